//! A path from elsewhere (another planner's, a student's, OMPL's) judged by the rule Planarium's own
//! planners keep: every state valid, every motion certified free all along by the scenario's
//! motion validator (at its resolution, exact where touching decides), from the start to the goal
//! within its tolerance. `planarium check-path` prints it; the benchmark suite counts how many of
//! OMPL's solutions it refuses (OMPL checks the states of a motion a resolution apart, and nothing
//! between them).

use crate::math::Real;
use crate::motion::MotionValidator;
use crate::problem::Problem;
use crate::robot::Verdict;
use serde::Serialize;

/// At most this many refusals are described one by one (the rest are counted).
pub const MAX_DESCRIBED: usize = 20;

/// One refused part of a path.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Refusal {
    /// The state's index (`path[k]`) or the motion's (`k`: from `path[k]` to `path[k + 1]`), as
    /// `what` says.
    pub at: usize,
    /// `"state"`, `"motion"`, `"start"` or `"goal"`.
    pub what: &'static str,
    /// Why, in the core's words (what collides with what, where the state fails).
    pub why: String,
}

/// What [`check_path`] found.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PathCheck {
    /// Whether the path is a valid solution: no refusal.
    pub valid: bool,
    /// States in the path.
    pub states: usize,
    /// Motions in the path (one fewer than its states).
    pub motions: usize,
    /// How many motions the motion validator refused.
    pub motions_refused: usize,
    /// The first [`MAX_DESCRIBED`] refusals, in the path's order.
    pub refusals: Vec<Refusal>,
}

/// Judge `path` (scenario states) against `problem`: see the module documentation. An inspection
/// task (no goal) needs the start only. States in bounds and free; motions certified by the
/// problem's motion validator from each state to the next (states that are not valid make their
/// motions unjudged and are refused themselves).
pub fn check_path(problem: &Problem, path: &[Vec<Real>]) -> PathCheck {
    let mut out = PathCheck { states: path.len(), motions: path.len().saturating_sub(1), ..PathCheck::default() };
    let refuse = |out: &mut PathCheck, at, what, why: String| {
        if out.refusals.len() < MAX_DESCRIBED {
            out.refusals.push(Refusal { at, what, why });
        }
    };
    if path.is_empty() {
        refuse(&mut out, 0, "state", "the path has no state".into());
        return out;
    }
    // Each state as a planning state (encoded, in bounds, free), or why not.
    let states: Vec<Option<Vec<Real>>> = path
        .iter()
        .enumerate()
        .map(|(k, q)| match problem.check_state(&format!("path[{k}]"), q) {
            Ok(q) => Some(q),
            Err(e) => {
                refuse(&mut out, k, "state", e.to_string());
                None
            }
        })
        .collect();
    let si = &problem.si;
    if let Some(first) = &states[0] {
        if si.distance(first, &problem.start) > 1e-9 {
            refuse(
                &mut out,
                0,
                "start",
                format!("path[0] is {:?}, not the start {:?}", path[0], problem.scenario.start),
            );
        }
    }
    if let (Some(goal), Some(Some(last))) = (&problem.goal, states.last()) {
        let d = si.distance(last, goal);
        if d > problem.goal_tolerance + 1e-9 {
            refuse(
                &mut out,
                path.len() - 1,
                "goal",
                format!("the last state is {d} from the goal, more than its tolerance {}", problem.goal_tolerance),
            );
        }
    }
    let mut scratch = vec![0.0; si.dims()];
    for (k, w) in states.windows(2).enumerate() {
        let (Some(a), Some(b)) = (&w[0], &w[1]) else { continue };
        if si.check_motion(a, b, &mut scratch).is_ok() {
            continue;
        }
        out.motions_refused += 1;
        let ws = si.workspace();
        // What blocked it, as the explain panel says it (`SpaceInfo::blocked_at`: the obstacle at
        // the state the validator stopped at, or the one an exact sweep meets); when neither is
        // known (a clearance too small to certify), the first state of the motion that is not
        // free, a quarter of the resolution apart.
        let mut blocked = si.blocked_at(a, b, &scratch).0;
        if blocked == -1 && first_invalid(problem, a, b, &mut scratch) {
            blocked = si.blocked_at(a, b, &scratch).0;
        }
        let named = |i: i64| match problem.scenario.obstacles3d.is_empty() {
            true => format!("it meets obstacles[{i}]"),
            false => format!("it meets obstacles3d[{i}]"),
        };
        let why = match (blocked, problem.robot.verdict(ws, &scratch)) {
            (-1, _) => {
                "it passes too near an obstacle, or touches one, between its states: it cannot be certified free"
                    .to_string()
            }
            // A free state, and the sweep between the states meets obstacle `i`.
            (i, Verdict::Valid) => format!("between its states {}", named(i)),
            (i, verdict) => {
                let what = problem.robot.describe_collision(ws, &scratch).unwrap_or_else(|| match verdict {
                    Verdict::Invalid(why) => why.into(),
                    _ if i == -2 => "it leaves the bounds".into(),
                    _ => named(i),
                });
                format!("at {:?}: {what}", problem.robot.decode(&scratch))
            }
        };
        refuse(&mut out, k, "motion", why);
    }
    out.valid = out.refusals.is_empty() && out.motions_refused == 0;
    out
}

/// Into `out`, the first state of the motion `a → b`, a quarter of the resolution apart, that is
/// not valid, and `true`; `false` (and `out` as it was) when there is none or the motion is too
/// long to walk.
fn first_invalid(problem: &Problem, a: &[Real], b: &[Real], out: &mut [Real]) -> bool {
    let si = &problem.si;
    let Some(n) = crate::limits::steps(si.distance(a, b), si.resolution / 4.0, crate::limits::MAX_MOTION_STEPS) else {
        return false;
    };
    let mut q = a.to_vec();
    for i in 1..=n {
        si.interpolate(a, b, i as Real / n as Real, &mut q);
        if problem.robot.verdict(si.workspace(), &q) != Verdict::Valid {
            out.copy_from_slice(&q);
            return true;
        }
    }
    false
}

//! The path found, certified before it is reported, for robots whose walks test configurations
//! alone ([`MotionModel::walks_by_states`](crate::robot::MotionModel::walks_by_states): the
//! spatial arm in its course's `last-free` connect, which tests each configuration a resolution
//! apart and nothing between, as the Robotics Library does). Every motion of the raw path is
//! checked by the motion validator, which certifies it all along (clearances against how far the
//! arm can move); a motion that grazes an obstacle between two of the connect's steps (a link's
//! corner passing a millimetre into the lintel) is walked again in steps of the resolution, and
//! each step that fails is replaced by a detour through states found near where it failed, each
//! leg certified in turn.
//!
//! These checks come after planning: they are not the planner's (the course counts queries while
//! planning), like smoothing's.

use crate::math::Real;
use crate::motion::MotionValidator;
use crate::problem::Problem;
use crate::rng::Rng;
use crate::space_info::SpaceInfo;

/// Detours tried around one graze before giving up.
const ATTEMPTS: usize = 300;
/// How many detour states may be chained to replace one motion.
const DEPTH: usize = 3;

/// What certifying a path did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Certified {
    /// The path, every motion certified.
    pub path: Vec<Vec<Real>>,
    /// The motions of the raw path that grazed an obstacle between two checked states and were
    /// replaced by a detour.
    pub repaired: usize,
}

/// `path` with every motion certified by `si`'s motion validator, grazing ones replaced by
/// detours (drawn from `rng`); `Err` names the motion no detour was found for (or says the run's
/// time ran out while certifying).
pub fn certify(problem: &Problem, path: &[Vec<Real>], rng: &mut Rng) -> Result<Certified, String> {
    let si = &problem.si;
    let mut out = vec![path[0].clone()];
    let mut scratch = path[0].clone();
    let mut repaired = 0;
    for (k, w) in path.windows(2).enumerate() {
        let (a, b) = (&w[0], &w[1]);
        if si.check_motion(a, b, &mut scratch).is_err() {
            if si.stopped() {
                return Err("the time ran out while the path found was certified".into());
            }
            let legs = repair(si, a, b, rng).map_err(|at| {
                let what = problem.robot.describe_collision(si.workspace(), &at);
                format!(
                    "the path found passes {} between two checked configurations (motion {} of {}), \
                     and no detour around it was found",
                    what.map_or("too near an obstacle to certify".into(), |w| format!("through a collision ({w})")),
                    k + 1,
                    path.len() - 1
                )
            })?;
            out.extend(legs);
            repaired += 1;
        }
        out.push(b.clone());
    }
    Ok(Certified { path: out, repaired })
}

/// The states to put between `a` and `b`, whose motion failed certification, so that every motion
/// is certified: the motion walked again in steps of the resolution (each step a sub-motion of
/// it), and each step that fails replaced by its two ends and a [`detour`] between them. The
/// stretches kept straight are unions of certified steps along the same line, so certified too.
/// `Err` holds where the first step with no detour failed.
fn repair(si: &SpaceInfo, a: &[Real], b: &[Real], rng: &mut Rng) -> Result<Vec<Vec<Real>>, Vec<Real>> {
    let n =
        crate::limits::steps(si.distance(a, b), si.resolution, crate::limits::MAX_MOTION_STEPS).ok_or(a.to_vec())?;
    let (mut prev, mut q, mut scratch) = (a.to_vec(), a.to_vec(), a.to_vec());
    let mut legs: Vec<Vec<Real>> = Vec::new();
    for i in 1..=n {
        si.interpolate(a, b, i as Real / n as Real, &mut q);
        // A step onto a state in collision (the walk tested other states than these) is taken
        // together with the next.
        if i < n && !si.is_valid(&q) {
            continue;
        }
        if si.check_motion(&prev, &q, &mut scratch).is_err() {
            let around = detour(si, &prev, &q, &scratch, rng, DEPTH).ok_or(scratch.clone())?;
            if legs.last() != Some(&prev) && prev != a {
                legs.push(prev.clone());
            }
            legs.extend(around);
            if i < n {
                legs.push(q.clone());
            }
        }
        prev.copy_from_slice(&q);
    }
    Ok(legs)
}

/// States to pass through between `a` and `b` (whose motion failed at `at`) so that every leg is
/// certified: a state near where the last leg failed, drawn at a spread growing from a hundredth
/// of the resolution to some hundred resolutions, whose leg from the last state is certified;
/// then on from it, at most `depth` states in all (no backtracking: at most `depth` × `ATTEMPTS`
/// draws).
fn detour(si: &SpaceInfo, a: &[Real], b: &[Real], at: &[Real], rng: &mut Rng, depth: usize) -> Option<Vec<Vec<Real>>> {
    let space = &si.space;
    let (mut from, mut at) = (a.to_vec(), at.to_vec());
    let (mut w, mut scratch) = (at.clone(), at.clone());
    let mut legs = Vec::new();
    for _ in 0..depth {
        // The first state reached whose leg on fails, to go on from if no state gets through.
        let mut first: Option<(Vec<Real>, Vec<Real>)> = None;
        for i in 0..ATTEMPTS {
            if si.stopped() {
                return None;
            }
            let sigma = si.resolution * 0.01 * (1.0 + i as Real).powf(1.5);
            for (k, x) in w.iter_mut().enumerate() {
                let d = &space.dims[k];
                *x = (at[k] + sigma * rng.normal()).clamp(d.lo, d.hi);
            }
            if !si.is_valid(&w) || si.check_motion(&from, &w, &mut scratch).is_err() {
                continue;
            }
            if si.check_motion(&w, b, &mut scratch).is_ok() {
                legs.push(w);
                return Some(legs);
            }
            first.get_or_insert_with(|| (w.clone(), scratch.clone()));
        }
        let (next, failed) = first?;
        legs.push(next.clone());
        (from, at) = (next, failed);
    }
    None
}

//! Informed RRT*: RRT* that, once it has a solution, samples only where a shorter one can lie.
//!
//! J. D. Gammell, S. S. Srinivasa, T. D. Barfoot, "Informed RRT*: Optimal sampling-based path
//! planning focused via direct sampling of an admissible ellipsoidal heuristic", IROS 2014. Until
//! the first solution it is [RRT*](super::rrt_star) with the run's sampler. Once the best solution
//! costs `c`, only states `q` with `d(start, q) + d(q, goal) < c` can lie on a shorter path (the
//! metric's triangle inequality bounds any path through `q` from below), so every sample is drawn
//! from that *informed set*, with the goal itself at the goal bias:
//!
//! - in a Euclidean space (the point robot), directly: the set is the prolate hyperspheroid with
//!   foci the start and the goal, transverse diameter `c` and conjugate diameters
//!   `sqrt(c² − d²)` (`d`: the foci's distance), a uniform draw in the unit ball (a normal vector's
//!   direction, radius `u^(1/n)`) stretched to those axes, turned onto the start–goal line (a
//!   Householder reflection: no trigonometry, so the same bits everywhere) and moved to the foci's
//!   midpoint; draws outside the space's bounds are drawn again;
//! - for a rigid body (`|Δ(x, y)| + w·|Δθ|`), its position directly in the ellipse of its `x, y`
//!   (which holds every position the set allows), its heading uniformly, kept when in the set;
//! - in any other space (an arm's joint angles, a chain), by rejection: uniform draws over the
//!   space until one is in the set.
//!
//! Either way at most [`TRIES`] draws are made per iteration; when none is in the set (a set that
//! hardly meets the space) the iteration draws nothing. Every improvement logs an
//! [`Informed`](EventKind::Informed) event with the set's ellipse in the plane (for a rigid body
//! the ellipse bounds the positions the set allows; for robots whose states are not placed in the
//! plane, none is logged), so the page draws it shrinking. Unlike the paper, the tree is not
//! pruned of nodes outside the set. Parameters are RRT*'s.

use super::rrt_star::{self, RrtStar, PARAMS};
use crate::events::EventKind;
use crate::math::{Real, Vec2};
use crate::planners::caps::Capabilities;
use crate::planners::Checkpoint;
use crate::planners::{Context, Planner, PlannerData, PlannerSpec, TaskKind};
use crate::sampler::SAMPLER_GROUP;
use crate::space::Metric;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "informed-rrt-star",
    label: "Informed RRT*",
    summary: "RRT* that, once it has a path, samples only the ellipse that can still hold a shorter one.",
    iteration: "Draw a sample (inside the ellipse once a path exists), extend the tree toward it, rewire the neighbourhood.",
    checks: "State validity checks: the states along each extension and rewiring motion (each motion is checked state by state at the scenario's resolution), plus a sampler's own checks.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        events: rrt_star::SPEC.caps.events.with(&[EventKind::Informed]),
        pseudocode: "tree-informed-rrt-star",
        overlays: &["rewires", "best", "informed"],
        ..rrt_star::SPEC.caps
    },
    make: |si, task, params| {
        let star = RrtStar::new(si, task, params);
        let start = task.start.clone();
        let goal = task.goal().to_vec();
        let n = start.len();
        // The leading coordinates drawn directly in their hyperspheroid: all of a Euclidean space
        // over unwrapped coordinates, a rigid body's position; none otherwise.
        let direct = match si.space.metric {
            Metric::Euclidean if si.space.dims.iter().all(|d| !d.wraps) => n,
            Metric::TranslationRotation { .. } => 2,
            _ => 0,
        };
        let foci = start[..direct].iter().zip(&goal[..direct]).map(|(a, b)| (b - a) * (b - a)).sum::<Real>().sqrt();
        // The Householder vector turning the first axis onto the start–goal direction.
        let mut turn = vec![0.0; direct];
        if foci > 0.0 {
            for (i, t) in turn.iter_mut().enumerate() {
                *t = if i == 0 { 1.0 } else { 0.0 } - (goal[i] - start[i]) / foci;
            }
        }
        // The ellipse in the plane bounds the set's positions when the first two coordinates are
        // the robot's point and the metric is at least their distance.
        let (ps, pg) = (si.project(&start), si.project(&goal));
        let planar = n >= 2 && ps == Vec2::new(start[0], start[1]) && pg == Vec2::new(goal[0], goal[1]) && direct == 2;
        let turn_sq = turn.iter().map(|v| v * v).sum();
        let set = InformedSet { goal_bias: params.real("goal_bias"), start, goal, foci, direct, turn, turn_sq };
        Ok(Box::new(InformedRrtStar { star, set, planar: planar.then_some((ps, pg)), shown: None }))
    },
};

/// Draws per iteration before it gives up.
pub const TRIES: usize = 100;

/// The Informed RRT* planner.
#[derive(Clone)]
pub struct InformedRrtStar {
    star: RrtStar,
    set: InformedSet,
    /// The start's and goal's points, when the set is drawn as an ellipse in the plane.
    planar: Option<(Vec2, Vec2)>,
    /// The cost whose set was last logged.
    shown: Option<Real>,
}

/// How the informed set is drawn from.
#[derive(Clone)]
struct InformedSet {
    goal_bias: Real,
    start: Vec<Real>,
    goal: Vec<Real>,
    /// The distance between the foci: start and goal in the leading `direct` coordinates.
    foci: Real,
    /// The leading coordinates drawn directly (in their hyperspheroid of diameter `c`, which
    /// holds the set's points there); the others are drawn uniformly, and the state is kept when
    /// it is in the set (always, when all are direct).
    direct: usize,
    /// Householder vector `e₁ − (goal − start)/foci` over the direct coordinates (all 0 when the
    /// foci coincide).
    turn: Vec<Real>,
    /// `|turn|²`.
    turn_sq: Real,
}

impl InformedSet {
    /// Whether `q` can lie on a path cheaper than `c`.
    fn in_set(&self, cx: &Context, q: &[Real], c: Real) -> bool {
        cx.si.distance(&self.start, q) + cx.si.distance(q, &self.goal) < c
    }

    /// Draw a state of the set of paths cheaper than `c` into `out`; `false` after [`TRIES`] misses.
    fn draw(&self, cx: &mut Context, c: Real, out: &mut [Real]) -> bool {
        let (n, k) = (out.len(), self.direct);
        for _ in 0..TRIES {
            if k < n {
                // the coordinates not drawn directly: uniformly (then the whole state is tested)
                cx.si.space.sample_uniform(cx.rng, out);
            }
            if k > 0 && !self.draw_direct(cx, c, &mut out[..k]) {
                continue;
            }
            if out[..k].iter().zip(&cx.si.space.dims).all(|(x, d)| *x >= d.lo && *x <= d.hi)
                && (k == n || self.in_set(cx, out, c))
            {
                return true;
            }
        }
        false
    }

    /// A uniform draw in the hyperspheroid of the leading coordinates `out` (diameter `c`, foci
    /// start and goal); `false` when the normal draw was degenerate.
    fn draw_direct(&self, cx: &mut Context, c: Real, out: &mut [Real]) -> bool {
        // A uniform point of the unit ball…
        let mut norm = 0.0;
        for o in out.iter_mut() {
            *o = cx.rng.normal();
            norm += *o * *o;
        }
        let norm = norm.sqrt();
        if norm <= 0.0 {
            return false;
        }
        let r = libm::pow(cx.rng.uniform01(), 1.0 / out.len() as Real) / norm;
        // …stretched to the axes…
        let minor = (c * c - self.foci * self.foci).max(0.0).sqrt() / 2.0;
        for (i, o) in out.iter_mut().enumerate() {
            *o *= r * if i == 0 { c / 2.0 } else { minor };
        }
        // …reflected onto the start–goal line and moved to the midpoint.
        let vv = self.turn_sq;
        if vv > 0.0 {
            let vx: Real = self.turn.iter().zip(out.iter()).map(|(v, x)| v * x).sum();
            let k = 2.0 * vx / vv;
            for (o, v) in out.iter_mut().zip(&self.turn) {
                *o -= k * v;
            }
        }
        for (i, o) in out.iter_mut().enumerate() {
            *o += (self.start[i] + self.goal[i]) / 2.0;
        }
        true
    }

    /// A sample for a run whose best path costs `c`: the goal at the goal bias, else a state of
    /// the set; logged as the run's sampler's are.
    fn sample(&self, cx: &mut Context, c: Real, out: &mut [Real]) -> bool {
        let goal = self.goal_bias > 0.0 && cx.rng.uniform01() < self.goal_bias;
        if goal {
            out.copy_from_slice(&self.goal);
        } else if !self.draw(cx, c, out) {
            return false;
        }
        let p = cx.si.project(out);
        cx.events.push(EventKind::Sample, 0, i64::from(goal), -1, p, p, out, out);
        true
    }
}

impl InformedRrtStar {
    /// The best solution's cost so far.
    pub fn best_cost(&self) -> Option<Real> {
        self.star.best_cost()
    }

    /// Log the set of paths cheaper than `c` as its ellipse in the plane.
    fn show(&mut self, cx: &mut Context, c: Real) {
        self.shown = Some(c);
        let Some((ps, pg)) = self.planar else { return };
        let d = (pg - ps).norm();
        let u = if d > 0.0 { (pg - ps) / d } else { Vec2::new(1.0, 0.0) };
        let m = (ps + pg) / 2.0;
        let minor = (c * c - d * d).max(0.0).sqrt() / 2.0;
        cx.events.values(EventKind::Informed, 0, cx.iteration as i64, -1, [m.x, m.y, c / 2.0, minor, u.x, u.y, c, d]);
    }
}

impl Planner for InformedRrtStar {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let set = &self.set;
        let found = match self.star.best_cost() {
            None => self.star.iterate_with(cx, &mut |cx, out| cx.sample(0, out)),
            Some(c) => self.star.iterate_with(cx, &mut |cx, out| set.sample(cx, c, out)),
        };
        if let Some(c) = self.star.best_cost() {
            if self.shown.is_none_or(|s| c < s) {
                self.show(cx, c);
            }
        }
        found
    }
    fn node_count(&self) -> usize {
        self.star.node_count()
    }
    fn stored_bytes(&self) -> usize {
        self.star.stored_bytes()
    }
    fn data(&self) -> PlannerData {
        self.star.data()
    }
    fn best_so_far(&self) -> Option<Vec<Vec<Real>>> {
        self.star.best_so_far()
    }
}

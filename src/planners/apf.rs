//! Artificial potential field: gradient descent on an attractive plus a repulsive potential.
//!
//! O. Khatib, "Real-time obstacle avoidance for manipulators and mobile robots", IJRR 5(1), 1986;
//! the escape by random walks is the randomized potential planner of J. Barraquand and
//! J.-C. Latombe, "Robot motion planning: a distributed representation approach", IJRR 10(6),
//! 1991. Report 002 (Columbia W4733) builds its hexagonal decomposition on such a field.
//!
//! # The method
//!
//! Think of the robot as a ball rolling downhill on a landscape `U(q) = U_att(q) + U_rep(q)`:
//!
//! - **Attraction** pulls towards the goal `g`. With `d = d(q, g)` in the robot's own metric (so
//!   a rigid body's heading counts too), it is a bowl near the goal and a cone farther away, so
//!   the pull never grows without bound:
//!   `U_att = ½·k_att·d²` when `d ≤ d_star`, else `k_att·d_star·d − ½·k_att·d_star²`.
//! - **Repulsion** pushes away from obstacles, but only within `rho0` of them. With `ρ` the
//!   distance from the body to the nearest obstacle (a point robot: from the point; a rigid
//!   robot: from its outline polygon), `U_rep = ½·eta·(1/ρ − 1/rho0)²` when `ρ < rho0`, else 0;
//!   a state in collision or out of bounds (`ρ = 0`) has `U = +∞`.
//!
//! Each iteration takes one step of metric length `step` along `−∇U`. The gradient is estimated
//! by central finite differences, one coordinate at a time, `h` = the scenario's resolution apart
//! (the heading is scaled by the metric's rotation weight so every coordinate moves the body about
//! as far); when one side of a difference is in collision, the one-sided difference of the other
//! side and the current state is used. A step is a straight motion checked by the motion
//! validator; if it collides, the step is halved (down to the resolution) and tried again. Once
//! the goal is within `step` (or the goal tolerance), the straight motion to it is tried and, if
//! it is free, the path (start, every step, goal) is returned.
//!
//! # Local minima
//!
//! Where attraction and repulsion cancel (in a cup that opens towards the robot, say) the gradient
//! vanishes and the descent stalls or oscillates. The planner watches the distance to the goal:
//! if it has not dropped by at least `min_progress` over the last `window` steps, it is in a
//! local minimum (a [`Minimum`](EventKind::Minimum) event marks it). Then, by `escape`:
//!
//! - `give-up`: stop; [`Planner::gave_up`] says where, and the run ends with status `no_path`;
//! - `random-walk` (Barraquand–Latombe): take `walk_steps` steps of length `step` in random
//!   directions (drawn from the run's seeded generator; a step that collides is redrawn, a bounded
//!   number of times), then resume the descent, with a fresh progress window. After
//!   `max_escapes` walks the planner gives up at the next minimum.
//!
//! # What it records
//!
//! Every step is a node of one chain ([`Tree`] 0, each node the child of the previous one);
//! `NodeAdded` events carry tree index 0 for descent steps and 1 for random-walk steps, so the
//! page can colour them. In its first iteration (when events are recorded) the planner samples
//! the field on a `field_grid × field_grid` grid over the workspace bounds, one
//! [`Field`](EventKind::Field) event per tile centre: the value (`+∞` where the robot would
//! collide), its two terms (attraction, repulsion), the unit direction `−∇U` in the plane (0 0
//! when degenerate or in collision) and the tile's half-size; a rigid robot is placed with the
//! start's heading. The heat map is drawing, not planning: its evaluations are not counted as
//! state checks (so `checks` does not depend on whether events are recorded). Planning's
//! evaluations are: every potential evaluated (one clearance of the body) counts as one state
//! check, besides the checks of the motion validator.

use crate::events::EventKind;
use crate::journal::Entry;
use crate::math::Real;
use crate::motion::MotionValidator;
use crate::planners::caps::{Capabilities, Draws, EventSet, Family, LegendItem};
use crate::planners::Checkpoint;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree};
use crate::space::Metric;
use crate::space_info::SpaceInfo;
use std::collections::VecDeque;

/// The legend: descent and random walks.
const LEGEND: &[LegendItem] =
    &[LegendItem::line("descent steps", "tree0"), LegendItem::line("random-walk steps", "tree1")];
/// The field's marks.
const MARKS: &[LegendItem] = &[LegendItem::ring("local minimum", "minimum")];

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "potential-field",
    label: "Artificial potential field",
    summary: "Gradient descent on an attractive plus repulsive potential; random walks out of local minima.",
    iteration: "One step of metric length step down the potential's gradient (or one step of a random walk out of a local minimum).",
    checks: "State validity checks: the potential's evaluations (one each) and the states along each step's motion, checked at the scenario's resolution.",
    params: PARAMS,
    groups: &[],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Field,
        draws: Draws::Field,
        trees: 1,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: true,
        events: EventSet::of(&[EventKind::Field, EventKind::Minimum, EventKind::NodeAdded, EventKind::Solved]),
        pseudocode: "field-potential",
        legend: LEGEND,
        marks: MARKS,
        overlays: &["heat", "arrows"],
    },
    make: |si, task, params| Ok(Box::new(PotentialField::new(si, task, params)?)),
};

/// The potential field's parameters.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec::real("k_att", "Attraction gain", 0.0, 1e6, 1.0, "k_att: scale of the attractive potential (½·k_att·d² near the goal, conic beyond d_star)."),
    ParamSpec::real("d_star", "Bowl radius", 0.0, 1e6, 0.3, "d_star: distance to the goal (robot's metric) where the attraction turns from a quadratic bowl into a cone."),
    ParamSpec::real("eta", "Repulsion gain", 0.0, 1e6, 0.0005, "eta: scale of the repulsive potential ½·eta·(1/ρ − 1/rho0)²."),
    ParamSpec::real("rho0", "Repulsion range", 1e-6, 1e6, 0.08, "rho0: obstacles farther than this from the body do not repel."),
    ParamSpec::real("step", "Step", 1e-6, 1e6, 0.01, "Length of one descent or random-walk step, in the robot's metric (halved, down to the resolution, when it collides)."),
    ParamSpec::int("window", "Progress window", 1.0, 1e6, 40.0, "Steps over which the distance to the goal must drop by min_progress; otherwise the robot is in a local minimum."),
    ParamSpec::real("min_progress", "Least progress", 0.0, 1e6, 0.01, "How much closer to the goal the robot must get within the window."),
    ParamSpec::choice(
        "escape",
        "Escape",
        &["random-walk", "give-up"],
        0,
        "random-walk: take walk_steps random steps, then descend again (Barraquand–Latombe); give-up: stop at the first local minimum.",
    ),
    ParamSpec::int("walk_steps", "Walk steps", 1.0, 1e6, 100.0, "Random steps of one escape.")
        .only_when("escape", &["random-walk"]),
    ParamSpec::int("max_escapes", "Most escapes", 0.0, 1e6, 40.0, "Random walks before the planner gives up at a local minimum.")
        .only_when("escape", &["random-walk"]),
    ParamSpec::int("field_grid", "Heat-map grid", 0.0, 400.0, 40.0, "The heat map samples the field on this many × this many points over the workspace (0: none)."),
];

/// Tries of a random-walk step before it is skipped (each direction that collides is redrawn).
const WALK_TRIES: usize = 20;

/// The parameter values, read once.
#[derive(Clone, Copy, Debug)]
struct Gains {
    k_att: Real,
    d_star: Real,
    eta: Real,
    rho0: Real,
}

/// The value of the potential at a state, with its two terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Potential {
    /// `U_att`.
    pub attraction: Real,
    /// `U_rep` (`+∞` in collision).
    pub repulsion: Real,
}

impl Potential {
    /// `U = U_att + U_rep`.
    pub fn total(&self) -> Real {
        self.attraction + self.repulsion
    }
}

/// What the planner is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// Descending the gradient.
    Descent,
    /// Escaping a local minimum by a random walk: steps left.
    Walk(usize),
}

/// The artificial potential field planner.
#[derive(Clone)]
pub struct PotentialField {
    goal: Vec<Real>,
    start: Vec<Real>,
    goal_tolerance: Real,
    gains: Gains,
    step: Real,
    window: usize,
    min_progress: Real,
    give_up_at_first: bool,
    walk_steps: usize,
    max_escapes: usize,
    field_grid: usize,
    /// Per coordinate: how far the body moves per unit (1 for x, y; the rotation weight for θ).
    scale: Vec<Real>,
    tree: Option<Tree>,
    /// The chain's last node.
    current: u32,
    mode: Mode,
    /// Distances to the goal after the last descent steps (at most `window + 1`).
    history: VecDeque<Real>,
    escapes: usize,
    reason: Option<String>,
    // Scratch states (reused so a step does not allocate).
    grad: Vec<Real>,
    probe: Vec<Real>,
    next: Vec<Real>,
    scratch: Vec<Real>,
}

/// The error of `make` for a robot that is not a body in the plane (it has no
/// [`WorkspaceBody`](crate::robot::WorkspaceBody)).
fn not_a_body(si: &SpaceInfo) -> String {
    let (kind, n) = (si.robot_kind(), si.dims());
    let a = if kind.starts_with(['a', 'e', 'i', 'o', 'u']) { "an" } else { "a" };
    format!("needs a point or rigid robot (this is {a} {kind} robot, whose state is {n} numbers, not a body moving in the plane)")
}

impl PotentialField {
    /// A potential-field planner for `task` with `params`; an error for robots that are not a
    /// point or a rigid body in a workspace.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Result<Self, String> {
        if si.body().is_none() {
            return Err(not_a_body(si));
        }
        let n = si.dims();
        let scale = (0..n)
            .map(|i| match si.space.metric {
                Metric::TranslationRotation { weight } if si.space.dims[i].wraps && weight > 0.0 => weight,
                _ => 1.0,
            })
            .collect();
        Ok(PotentialField {
            goal: task.goal().to_vec(),
            start: task.start.clone(),
            goal_tolerance: task.goal_tolerance,
            gains: Gains {
                k_att: params.real("k_att"),
                d_star: params.real("d_star"),
                eta: params.real("eta"),
                rho0: params.real("rho0"),
            },
            step: params.real("step"),
            window: params.real("window") as usize,
            min_progress: params.real("min_progress"),
            give_up_at_first: params.choice("escape") == "give-up",
            walk_steps: params.real("walk_steps") as usize,
            max_escapes: params.real("max_escapes") as usize,
            field_grid: params.real("field_grid") as usize,
            scale,
            tree: None,
            current: 0,
            mode: Mode::Descent,
            history: VecDeque::new(),
            escapes: 0,
            reason: None,
            grad: vec![0.0; n],
            probe: vec![0.0; n],
            next: vec![0.0; n],
            scratch: vec![0.0; n],
        })
    }

    /// The potential at `q` and its terms (not counted as a check: callers count).
    pub fn potential(&self, si: &SpaceInfo, q: &[Real]) -> Potential {
        let Gains { k_att, d_star, eta, rho0 } = self.gains;
        let d = si.distance(q, &self.goal);
        let attraction =
            if d <= d_star { 0.5 * k_att * d * d } else { k_att * d_star * d - 0.5 * k_att * d_star * d_star };
        let rho = clearance(si, q, rho0);
        let repulsion = if rho <= 0.0 {
            Real::INFINITY
        } else if rho < rho0 {
            let d = 1.0 / rho - 1.0 / rho0;
            0.5 * eta * d * d
        } else {
            0.0
        };
        Potential { attraction, repulsion }
    }

    /// Write into `self.grad` the finite-difference gradient of `U` at `q` over its first `dims`
    /// coordinates (in scaled units: per unit of body motion), the others 0; returns the number
    /// of potentials evaluated.
    fn gradient(&mut self, si: &SpaceInfo, q: &[Real], dims: usize) -> u64 {
        let h = si.resolution;
        let centre = self.potential(si, q).total();
        let mut evaluations = 1;
        let mut probe = std::mem::take(&mut self.probe);
        for i in 0..q.len() {
            self.grad[i] = 0.0;
            if i >= dims {
                continue;
            }
            let dq = h / self.scale[i];
            let mut side = |sign: Real| {
                probe.copy_from_slice(q);
                probe[i] += sign * dq;
                si.space.enforce(&mut probe);
                self.potential(si, &probe).total()
            };
            let (up, down) = (side(1.0), side(-1.0));
            evaluations += 2;
            self.grad[i] = match (up.is_finite(), down.is_finite(), centre.is_finite()) {
                (true, true, _) => (up - down) / (2.0 * h),
                (false, true, true) => (centre - down) / h,
                (true, false, true) => (up - centre) / h,
                _ => 0.0,
            };
        }
        self.probe = probe;
        evaluations
    }

    /// Write into `self.next` the state `len` (metric) from `q` along the scaled direction `dir`
    /// (any length); `false` when the direction is degenerate.
    fn advance(&mut self, si: &SpaceInfo, q: &[Real], dir: &[Real], len: Real) -> bool {
        let norm = dir.iter().map(|v| v * v).sum::<Real>().sqrt();
        if !norm.is_finite() || norm == 0.0 {
            return false;
        }
        for i in 0..q.len() {
            self.next[i] = q[i] + dir[i] / norm / self.scale[i];
        }
        si.space.enforce(&mut self.next);
        let unit = si.distance(q, &self.next);
        if unit == 0.0 || !unit.is_finite() {
            return false;
        }
        for i in 0..q.len() {
            self.next[i] = q[i] + len / unit * dir[i] / norm / self.scale[i];
        }
        si.space.enforce(&mut self.next);
        true
    }

    /// Add `self.next` to the chain after the current node, with its event (`tree`: 0 descent, 1
    /// random walk).
    fn add_step(&mut self, cx: &mut Context, tree_index: usize) {
        let tree = self.tree.as_mut().expect("the chain exists once iterating");
        let parent = self.current;
        let id = tree.add(cx, &self.next, parent);
        cx.nodes_left = cx.nodes_left.saturating_sub(1);
        let (p, pp) = (cx.si.project(&self.next), cx.si.project(tree.state(parent)));
        cx.events.push(
            EventKind::NodeAdded,
            tree_index,
            id as i64,
            parent as i64,
            p,
            pp,
            &self.next,
            tree.state(parent),
        );
        self.current = id;
    }

    /// The heat map's events (see the module documentation); not counted as checks.
    fn emit_field(&self, cx: &mut Context) {
        let n = self.field_grid;
        let ws = cx.si.workspace();
        if n == 0 || !cx.events.enabled {
            return;
        }
        let b = ws.bounds;
        let (dx, dy) = ((b.max.x - b.min.x) / n as Real, (b.max.y - b.min.y) / n as Real);
        let half = 0.5 * dx.max(dy);
        let h = cx.si.resolution;
        let mut q = self.start.clone();
        for j in 0..n {
            // A row costs n potentials and their gradients: past the time limit, stop drawing.
            if cx.si.out_of_time() {
                return;
            }
            for i in 0..n {
                let (x, y) = (b.min.x + (i as Real + 0.5) * dx, b.min.y + (j as Real + 0.5) * dy);
                q[0] = x;
                q[1] = y;
                let here = self.potential(cx.si, &q);
                let value = here.total();
                let mut dir = [0.0, 0.0];
                if value.is_finite() {
                    let mut g = [0.0; 2];
                    for (k, gk) in g.iter_mut().enumerate() {
                        let side = |sign: Real| {
                            let mut p = q.clone();
                            p[k] += sign * h;
                            self.potential(cx.si, &p).total()
                        };
                        let (up, down) = (side(1.0), side(-1.0));
                        *gk = match (up.is_finite(), down.is_finite()) {
                            (true, true) => (up - down) / (2.0 * h),
                            (false, true) => (value - down) / h,
                            (true, false) => (up - value) / h,
                            _ => 0.0,
                        };
                    }
                    let norm = (g[0] * g[0] + g[1] * g[1]).sqrt(); // not hypot: std's differs between native and wasm
                    if norm > 0.0 && norm.is_finite() {
                        dir = [-g[0] / norm, -g[1] / norm];
                    }
                }
                let index = (j * n + i) as i64;
                let (att, rep) = (here.attraction, if value.is_finite() { here.repulsion } else { Real::INFINITY });
                cx.events.values(EventKind::Field, 0, index, -1, [x, y, value, att, rep, dir[0], dir[1], half]);
            }
        }
    }

    /// The two forces at `q` in the plane: the pull `−∇U_att` and the push `−∇U_rep`, by central
    /// differences `h` = the resolution apart in x and y (one-sided next to a collision). For
    /// drawing only (the `Minimum` event): not counted as checks, like the heat map.
    fn forces(&self, si: &SpaceInfo, q: &[Real]) -> ([Real; 2], [Real; 2]) {
        let h = si.resolution;
        let here = self.potential(si, q);
        let (mut pull, mut push) = ([0.0; 2], [0.0; 2]);
        let mut p = q.to_vec();
        for k in 0..2 {
            p.copy_from_slice(q);
            p[k] = q[k] + h;
            let up = self.potential(si, &p);
            p[k] = q[k] - h;
            let down = self.potential(si, &p);
            pull[k] = -(up.attraction - down.attraction) / (2.0 * h);
            push[k] = match (up.repulsion.is_finite(), down.repulsion.is_finite(), here.repulsion.is_finite()) {
                (true, true, _) => -(up.repulsion - down.repulsion) / (2.0 * h),
                (false, true, true) => -(here.repulsion - down.repulsion) / h,
                (true, false, true) => -(up.repulsion - here.repulsion) / h,
                _ => 0.0,
            };
        }
        (pull, push)
    }

    /// A local minimum at the current node: record it, then give up or start a random walk.
    fn at_minimum(&mut self, cx: &mut Context) {
        let tree = self.tree.as_ref().expect("the chain exists once iterating");
        let q = tree.state(self.current).to_vec();
        let u = self.potential(cx.si, &q).total();
        cx.si.count_checks(1);
        let d = cx.si.distance(&q, &self.goal);
        let at = cx.si.project(&q);
        if cx.events.enabled {
            let (pull, push) = self.forces(cx.si, &q);
            let v = [at.x, at.y, u, d, pull[0], pull[1], push[0], push[1]];
            cx.events.values(EventKind::Minimum, 0, self.escapes as i64, self.current as i64, v);
        }
        self.history.clear();
        if self.give_up_at_first {
            self.reason = Some(format!(
                "local minimum at ({:.2}, {:.2}): the robot stopped getting closer to the goal, and with escape give-up the run ends there",
                at.x, at.y
            ));
        } else if self.escapes >= self.max_escapes {
            self.reason = Some(format!(
                "local minimum at ({:.2}, {:.2}): still trapped after {} random-walk escapes",
                at.x, at.y, self.escapes
            ));
        } else {
            self.escapes += 1;
            self.mode = Mode::Walk(self.walk_steps);
        }
    }

    /// One descent step; `Some(path)` when the goal was reached.
    fn descend(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let si = cx.si;
        let q = self.tree.as_ref().expect("the chain exists").state(self.current).to_vec();
        let d = si.distance(&q, &self.goal);
        if d <= self.goal_tolerance {
            return Some(self.solved(cx, false));
        }
        if d <= self.step.max(self.goal_tolerance) && si.check_motion(&q, &self.goal, &mut self.scratch).is_ok() {
            return Some(self.solved(cx, true));
        }
        let evaluations = self.gradient(si, &q, q.len());
        si.count_checks(evaluations);
        let down: Vec<Real> = self.grad.iter().map(|g| -g).collect();
        let mut len = self.step;
        let moved = loop {
            if !self.advance(si, &q, &down, len) {
                break false;
            }
            if si.check_motion(&q, &self.next, &mut self.scratch).is_ok() {
                break true;
            }
            if len <= si.resolution {
                break false;
            }
            len = (0.5 * len).max(si.resolution);
        };
        if !moved {
            // A vanishing gradient, or every step down collides: no progress is possible.
            self.at_minimum(cx);
            return None;
        }
        self.add_step(cx, 0);
        self.history.push_back(si.distance(&self.next, &self.goal));
        if self.history.len() > self.window {
            let old = self.history.pop_front().expect("non-empty");
            let best = self.history.iter().copied().fold(Real::INFINITY, Real::min);
            if old - best < self.min_progress {
                self.at_minimum(cx);
            }
        }
        None
    }

    /// One random-walk step (skipped when `WALK_TRIES` directions all collide).
    fn walk(&mut self, cx: &mut Context, left: usize) {
        let q = self.tree.as_ref().expect("the chain exists").state(self.current).to_vec();
        let mut dir = vec![0.0; q.len()];
        for _ in 0..WALK_TRIES {
            dir.iter_mut().for_each(|v| *v = cx.rng.normal());
            if self.advance(cx.si, &q, &dir, self.step) && cx.si.check_motion(&q, &self.next, &mut self.scratch).is_ok()
            {
                self.add_step(cx, 1);
                break;
            }
        }
        self.mode = if left > 1 { Mode::Walk(left - 1) } else { Mode::Descent };
    }

    /// The path to the goal (adding the goal as a node when `connect`), with its event.
    fn solved(&mut self, cx: &mut Context, connect: bool) -> Vec<Vec<Real>> {
        if connect {
            self.next.copy_from_slice(&self.goal);
            self.add_step(cx, 0);
        }
        // Within the goal tolerance the path ends where the robot is (a jump to the goal would be
        // a motion nobody checked).
        let path = self.tree.as_ref().expect("the chain exists").path_to(self.current);
        cx.events.at(EventKind::Solved, 0, cx.si.project(&self.goal), &self.goal);
        path
    }
}

/// The distance from the body at `q` to the nearest obstacle, capped at `cap`
/// ([`WorkspaceBody::obstacle_clearance`](crate::robot::WorkspaceBody::obstacle_clearance)); 0
/// when `q` is invalid (in collision or out of bounds). Not counted as a check (the descent counts
/// its evaluations itself).
/// (One answer of the batch journal: a bounded batch replays it rather than compute it again.)
fn clearance(si: &SpaceInfo, q: &[Real], cap: Real) -> Real {
    si.journalled(
        |e| if let Entry::Clear(c) = e { Some(*c) } else { None },
        Entry::Clear,
        0.0,
        || {
            let Some(body) = si.body() else { return 0.0 };
            if !si.is_valid_uncounted(q) {
                return 0.0;
            }
            body.obstacle_clearance(si.workspace(), q, cap)
        },
    )
}

impl Planner for PotentialField {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.reason.is_some() {
            return None;
        }
        if self.tree.is_none() {
            self.tree = Some(Tree::new(cx, &self.start, 0));
            self.current = 0;
            self.emit_field(cx);
        }
        if cx.nodes_left == 0 {
            return None;
        }
        match self.mode {
            Mode::Descent => self.descend(cx),
            Mode::Walk(left) => {
                self.walk(cx, left);
                None
            }
        }
    }

    fn node_count(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::len)
    }
    fn stored_bytes(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::bytes) + self.history.len() * std::mem::size_of::<Real>()
    }

    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.tree.iter().cloned().collect())
    }

    fn gave_up(&self) -> Option<String> {
        self.reason.clone()
    }
}

//! Inspection planning: a tree that grows until one branch has seen enough points of interest.
//!
//! The Technion course's inspection RRT (report 004, `docs/sources.md`; cf. G. Papadopoulos,
//! H. Kurniawati, N. M. Patrikalakis, "Asymptotically optimal inspection planning using systems with
//! differential constraints", ICRA 2013, whose tree nodes also carry what their branch has seen). One
//! tree from the start. Every node carries the set of points seen **along its branch**: its parent's
//! set and what the sensor sees at every state of the edge into it, checked at the motion
//! resolution (the course checks edges every 0.05 rad). The coverage of a node is the fraction of
//! the points in its set; the run ends when a node's coverage reaches the target (the `coverage`
//! parameter, by default the scenario's), and the path is its branch. With the task's
//! `at_vertices` (the scenario's `"coverage_mode": "vertices"`, set for the Technion maps) a node's
//! set is its parent's and what the sensor sees at the node itself, the handout's
//! `I_i = I_{i−1} ∪ S(v_i)`; with `touch_hides`, a sight line that touches an obstacle hides the
//! point (the course's test).
//!
//! Each iteration:
//! 1. chooses where to grow: with probability `focus`, from a node of the branch that sees most (a
//!    random one among those that see as many points as the best, so the walk spreads along the tip
//!    of the best branch), toward a sample; otherwise from the node nearest a sample (plain RRT). The
//!    sample comes from the run's sampler.
//! 2. steps at most `range` toward the sample (refused when it makes no progress, as `Tree::grow`)
//!    and checks the motion; a collision ends the iteration.
//! 3. chooses the new node's parent among its `k` nearest nodes and the node it grew from: the one
//!    through which it sees most, ties broken by the lesser cost (the sum of C-space distances).
//! 4. rewires each of the `k` nearest through the new node when that makes its branch see a superset
//!    of what it saw and either more points or the same at less cost; the change is propagated to its
//!    descendants. Requiring a superset keeps every node's set growing, so no branch (and never the
//!    best one) loses a point it saw, and an edge's stored set may omit what its parent's branch had
//!    already seen.
//!
//! What the sensor sees is the robot's business (its [`Sensor`](crate::robot::Sensor) capability,
//! through [`SpaceInfo::sensor`], and [`SpaceInfo::sees`]): an arm's end effector looking along its
//! last link, a rigid body's origin looking along its x axis, a point seeing all around; sight
//! lines are blocked by obstacle interiors only, unless `touch_hides`. Robots without a sensor are
//! refused.
//!
//! The parts: `visibility` (what the sensor sees at a state and along a motion), `coverage`
//! (what a path sees, and smoothing that keeps it), `grow` (one iteration: steps 1–4) and `bits`
//! (sets of points).
//!
//! Events: `NodeAdded`, `Collision`, `Rewire`, `Coverage` (whenever the best branch sees more),
//! `PointSeen` (the first time any node sees a point) and `Solved`.

mod bits;
mod coverage;
mod grow;
mod visibility;

pub use coverage::{continuous_coverage, course_coverage, path_coverage, seen_along, shortcut};

use super::rrt::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::Real;
use crate::planners::caps::{self, Capabilities, Draws, EventSet, Family};
use crate::planners::Checkpoint;
use crate::planners::{
    Context, InspectionTask, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree,
};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;
use bits::{count, Bits};
use visibility::Visibility;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "inspection",
    label: "Inspection RRT",
    summary: "A tree that grows to see the points of interest, until one branch sees enough of them.",
    iteration: "Choose a node to grow from, step toward a sample, check the motion, pick the parent that sees most.",
    checks: "State validity checks: the states along each motion tried (each motion is checked state by state at the scenario's resolution), plus a sampler's own checks.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Inspection,
    caps: Capabilities {
        family: Family::Tree,
        draws: Draws::Tree,
        trees: 1,
        improves: true,
        chart: Some("coverage"),
        queries: false,
        proves_no_path: false,
        events: EventSet::of(&[
            EventKind::Sample,
            EventKind::SampleTry,
            EventKind::NodeAdded,
            EventKind::Collision,
            EventKind::Nearest,
            EventKind::Steer,
            EventKind::Solved,
            EventKind::Rewire,
            EventKind::Coverage,
            EventKind::PointSeen,
        ]),
        pseudocode: "tree-inspection",
        legend: caps::ONE_TREE,
        marks: &[],
        overlays: &["rewires", "best", "seen", "fov"],
    },
    make: |si, task, params| {
        si.sensor().ok_or_else(|| format!("needs a robot with a sensor (a {} robot has none)", si.robot_kind()))?;
        Ok(Box::new(Inspection::new(si, task, params)))
    },
};

/// The inspection planner's parameters.
pub const PARAMS: &[ParamSpec] = &[
    RANGE,
    ParamSpec::real("coverage", "Coverage", 0.0, 1.0, 0.0, "Fraction of the inspection points one branch must see (0: the scenario's target)."),
    ParamSpec::int("k", "Neighbours", 0.0, 1000.0, 5.0, "Nearest nodes considered as a new node's parent and rewired through it (0: no rewiring)."),
    ParamSpec::real(
        "focus",
        "Focus",
        0.0,
        1.0,
        0.75,
        "Probability of growing from the tip of the branch that sees most, rather than from the node nearest the sample.",
    ),
];

/// The inspection planner.
#[derive(Clone)]
pub struct Inspection {
    start: Vec<Real>,
    /// The points to see, and how the robot's sensor sees them.
    view: Visibility,
    /// Target coverage (fraction of the points).
    target: Real,
    range: Real,
    k: usize,
    focus: Real,
    /// Words per bit set.
    words: usize,
    tree: Option<Tree>,
    /// Per node (`words` each): the points seen along its branch.
    seen: Vec<u64>,
    /// Per node: the points seen along the edge into it (its own state included) that its parent's
    /// branch had not seen when the edge was made.
    edge: Vec<u64>,
    /// Per node: points in `seen`.
    counts: Vec<u32>,
    /// Per node: the branch's cost (sum of C-space distances).
    cost: Vec<Real>,
    /// Per node: the length of the edge into it.
    len: Vec<Real>,
    children: Vec<Vec<u32>>,
    /// Points seen by any node.
    ever: Vec<u64>,
    /// The node whose branch sees most (ties: the least cost).
    best: u32,
    /// Nodes that see as many points as the best, and whether each node is among them.
    top: Vec<u32>,
    in_top: Vec<bool>,
    sample: Vec<Real>,
    new: Vec<Real>,
    scratch: Vec<Real>,
}

impl Inspection {
    /// An inspection planner for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Self {
        let insp = task.inspection.clone().unwrap_or(InspectionTask {
            points: Vec::new(),
            fov: 0.0,
            range: 0.0,
            coverage: 0.0,
            at_vertices: false,
            touch_hides: false,
        });
        let own = params.real("coverage");
        let n = si.dims();
        Inspection {
            start: task.start.clone(),
            words: insp.points.len().div_ceil(64).max(1),
            target: if own > 0.0 { own } else { insp.coverage },
            view: Visibility::of(insp),
            range: resolve_range(si, params.real("range")),
            k: params.real("k") as usize,
            focus: params.real("focus"),
            tree: None,
            seen: Vec::new(),
            edge: Vec::new(),
            counts: Vec::new(),
            cost: Vec::new(),
            len: Vec::new(),
            children: Vec::new(),
            ever: Vec::new(),
            best: 0,
            top: Vec::new(),
            in_top: Vec::new(),
            sample: vec![0.0; n],
            new: vec![0.0; n],
            scratch: vec![0.0; n],
        }
    }

    /// The coverage of the branch that sees most (0 before the first iteration).
    pub fn best_coverage(&self) -> Real {
        match self.counts.get(self.best as usize) {
            Some(&c) => self.fraction(c),
            None => 0.0,
        }
    }

    fn fraction(&self, c: u32) -> Real {
        let n = self.view.points.len();
        if n == 0 {
            1.0
        } else {
            c as Real / n as Real
        }
    }

    fn reached(&self, c: u32) -> bool {
        self.fraction(c) >= self.target
    }

    fn seen_of(&self, i: u32) -> &Bits {
        let i = i as usize;
        &self.seen[i * self.words..(i + 1) * self.words]
    }

    /// Append a node's records (the tree node itself is added by the caller).
    fn push_node(&mut self, seen: &Bits, edge: &Bits, cost: Real, len: Real) {
        self.seen.extend_from_slice(seen);
        self.edge.extend_from_slice(edge);
        self.counts.push(count(seen));
        self.cost.push(cost);
        self.len.push(len);
        self.children.push(Vec::new());
        self.in_top.push(false);
    }
}

impl Planner for Inspection {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let mut tree = match self.tree.take() {
            Some(t) => t,
            None => {
                let t = self.init(cx);
                if self.reached(self.counts[0]) {
                    let path = self.solved(cx, &t);
                    self.tree = Some(t);
                    return Some(path);
                }
                t
            }
        };
        let out = self.grow(cx, &mut tree);
        self.tree = Some(tree);
        out
    }

    fn node_count(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::len)
    }
    /// Each node keeps the points its branch has seen (a bit a point) besides its state.
    fn stored_bytes(&self) -> usize {
        use crate::planners::{bytes_of, nested_bytes};
        let n = self.node_count();
        self.tree.as_ref().map_or(0, Tree::bytes)
            + bytes_of(&self.seen)
            + bytes_of(&self.edge)
            + bytes_of(&self.counts)
            + bytes_of(&self.cost)
            + bytes_of(&self.len)
            + nested_bytes::<u32>(self.children.len(), n.saturating_sub(1))
            + bytes_of(&self.ever)
            + bytes_of(&self.top)
            + bytes_of(&self.in_top)
    }
    fn memory_advice(&self) -> &'static str {
        "lower max_nodes, or inspect fewer points (each node keeps a bit per point)"
    }

    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.tree.iter().cloned().collect())
    }

    fn best_so_far(&self) -> Option<Vec<Vec<Real>>> {
        let tree = self.tree.as_ref()?;
        self.reached(self.counts[self.best as usize]).then(|| tree.path_to(self.best))
    }

    fn coverage(&self) -> Option<Real> {
        Some(self.best_coverage())
    }
}

//! RRT-Connect: two trees, one from the start and one from the goal, grown toward each other.
//!
//! J. J. Kuffner and S. M. LaValle, "RRT-Connect: An efficient approach to single-query path
//! planning", ICRA 2000. Each iteration extends one tree a step of `range` toward a uniform sample,
//! then grows the other tree step after step toward the new node (CONNECT) until it reaches it or a
//! motion collides; the trees alternate every iteration. Seeded by the run's [`Rng`]. The goal is
//! reached exactly (goal tolerance plays no part: the goal is a tree's root).
//!
//! With `connect` = `last-free` it is the Robotics Library's `RrtConCon` (rl's
//! `rl/plan/RrtConCon.cpp` in its repository's `src`, the planner of report 001's course): both
//! trees CONNECT, tree A toward the sample and tree B toward the node tree A added, each stepping
//! by the scenario's resolution and keeping only the last free configuration
//! ([`Tree::connect_last_free`]: each step's motion is checked, one state check per configuration
//! for a robot checked by discrete states alone, as rl counts, more for a body whose steps are
//! certified by clearances); solved when tree B's last configuration is within
//! `epsilon` of tree A's new node (rl's `areEqual`: distance ≤ epsilon); the trees swap every
//! iteration. The path is rl's `RrtDual::getPath`: the start tree's branch to its meeting node,
//! then the goal tree's from the parent of its own meeting node (the two are within `epsilon`) to
//! the goal. Start and goal are tested once each, counted, in the first iteration (rl's
//! `Planner::verify` before `solve`), so `checks` and `free_checks` are the course's collision and
//! free queries (for the course's robot, the spatial arm, and a point robot; see
//! [`Tree::connect_last_free`] for a body's). Ladder steps are range steps: `ladder` does nothing
//! with `last-free`, and `range` nothing (as a sampler's `sigma` does nothing with the uniform
//! sampler): their declarations say so ([`ParamSpec::only_when`]), so the page hides them and the
//! CLI notes them.
//!
//! [`Rng`]: crate::rng::Rng

use super::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::Real;
use crate::planners::caps::{self, Capabilities, Draws, Family};
use crate::planners::tree::{TreeMark, TreeOptions, CONNECT_TREE_GROUP};
use crate::planners::{
    Checkpoint, Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree,
};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;
use crate::status::Grow;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "rrt-connect",
    label: "RRT-Connect",
    summary: "Two trees, from start and goal, taking turns to grow toward each other.",
    iteration: "One tree steps toward a sample, the other tries to connect to the new node; the trees swap roles.",
    checks: "State validity checks: the states along each extension and connection (each motion is checked state by state at the scenario's resolution), plus a sampler's own checks.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP, CONNECT_TREE_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Tree,
        draws: Draws::Tree,
        trees: 2,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: false,
        events: caps::SAMPLING_TREE.with(&[EventKind::Domain, EventKind::Exhausted, EventKind::TreesConnected]),
        pseudocode: "tree-rrt-connect",
        legend: caps::TWO_TREES,
        marks: &[],
        overlays: &[],
    },
    make: |si, task, params| Ok(Box::new(RrtConnect::new(si, task, params))),
};

/// How a CONNECT grows: in steps of `range`, each motion checked and added (Kuffner and LaValle),
/// or the Robotics Library's last free configuration at the resolution.
pub const CONNECT: ParamSpec = ParamSpec::choice(
    "connect",
    "Connect",
    &["range", "last-free"],
    0,
    "range: both growths step by range, each motion checked and added as a node (Kuffner & LaValle); last-free: the Robotics Library's RrtConCon (report 001's course): both trees step along the line by the resolution, each step's motion checked (one state check per configuration for the course's spatial arm and a point), and only the last free configuration becomes a node.",
);

/// How close the two trees' last configurations must be to meet, in `last-free` mode.
pub const EPSILON: ParamSpec = ParamSpec::real(
    "epsilon",
    "Meeting distance",
    1e-12,
    1e-3,
    1e-8,
    "last-free: the trees meet when the other tree's last configuration is within this distance of the new node (the Robotics Library's epsilon; the gap between them is not checked, so keep it far below the resolution).",
)
.only_when("connect", &["last-free"]);

/// RRT-Connect's parameters: `range` steps the `range` connect only (last-free steps by the
/// scenario's resolution), `epsilon` is last-free's alone.
pub const PARAMS: &[ParamSpec] = &[RANGE.only_when("connect", &["range"]), CONNECT, EPSILON];

/// The RRT-Connect planner.
#[derive(Clone)]
pub struct RrtConnect {
    task: Task,
    range: Real,
    /// The Robotics Library's connect (last free configuration), stepping by `delta`, meeting
    /// within `epsilon`.
    last_free: bool,
    delta: Real,
    epsilon: Real,
    opts: TreeOptions,
    trees: Vec<Tree>,
    /// The tree that extends toward the sample this iteration.
    turn: usize,
    sample: Vec<Real>,
    target: Vec<Real>,
    scratch: Vec<Real>,
    new: Vec<Real>,
    /// Where a last-free step's motion was found not free.
    found: Vec<Real>,
}

impl RrtConnect {
    /// An RRT-Connect for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Self {
        let n = si.dims();
        RrtConnect {
            task: task.clone(),
            range: resolve_range(si, params.real("range")),
            last_free: params.choice("connect") == "last-free",
            delta: si.resolution,
            epsilon: params.real("epsilon"),
            opts: TreeOptions::from_params(params, si.resolution),
            trees: Vec::new(),
            turn: 0,
            sample: vec![0.0; n],
            target: vec![0.0; n],
            scratch: vec![0.0; n],
            new: vec![0.0; n],
            found: vec![0.0; n],
        }
    }
}

impl Planner for RrtConnect {
    /// Its few numbers copied, its trees marked (they only grow: [`Tree::mark`]).
    fn checkpoint(&mut self) -> Checkpoint {
        let trees = std::mem::take(&mut self.trees);
        let rest = self.clone();
        self.trees = trees;
        let marks: Vec<TreeMark> = self.trees.iter_mut().map(Tree::mark).collect();
        Checkpoint::Mark(Box::new((rest, marks)))
    }
    fn rewind(&mut self, mark: Box<dyn std::any::Any>) {
        let (rest, marks) = *mark.downcast::<(RrtConnect, Vec<TreeMark>)>().expect("RRT-Connect's own mark");
        let mut trees = std::mem::take(&mut self.trees);
        trees.truncate(marks.len());
        for (tree, mark) in trees.iter_mut().zip(marks) {
            tree.rewind(mark);
        }
        *self = RrtConnect { trees, ..rest };
    }
    fn release(&mut self) {
        self.trees.iter_mut().for_each(Tree::release);
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.trees.is_empty() {
            let o = self.opts;
            self.trees =
                vec![Tree::with_options(cx, &self.task.start, 0, o), Tree::with_options(cx, self.task.goal(), 1, o)];
            if self.last_free {
                // rl's `Planner::verify`: start and goal tested once each (both valid: the problem
                // checked them), so the counts are the course's.
                cx.si.is_valid(&self.task.start);
                cx.si.is_valid(self.task.goal());
            }
        }
        if self.last_free {
            return self.iterate_last_free(cx);
        }
        let (a, b) = (self.turn, 1 - self.turn);
        self.turn = b;
        if !cx.sample(a, &mut self.sample) {
            return None;
        }
        let (grow, added) = self.trees[a].extend_sample(cx, &self.sample, self.range, &mut self.scratch, &mut self.new);
        if matches!(grow, Grow::Trapped | Grow::Rejected) {
            cx.events.at(EventKind::SampleRejected, a, cx.si.project(&self.sample), &self.sample);
            return None;
        }
        self.target.copy_from_slice(self.trees[a].state(added));
        let (g, reached) = self.trees[b].connect(cx, &self.target, self.range, &mut self.scratch, &mut self.new);
        match g {
            Grow::Trapped | Grow::Advanced | Grow::Rejected => None,
            Grow::Reached => {
                let p = cx.si.project(&self.target);
                cx.events.push(
                    EventKind::TreesConnected,
                    a,
                    added as i64,
                    reached as i64,
                    p,
                    p,
                    &self.target,
                    &self.target,
                );
                let goal = self.task.goal();
                cx.events.at(EventKind::Solved, a, cx.si.project(goal), goal);
                let (from_start, from_goal) = if a == 0 { (added, reached) } else { (reached, added) };
                Some(self.path(from_start, from_goal))
            }
        }
    }

    fn stored_bytes(&self) -> usize {
        self.trees.iter().map(Tree::bytes).sum()
    }
    fn node_count(&self) -> usize {
        self.trees.iter().map(Tree::len).sum()
    }

    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.trees.clone())
    }
}

impl RrtConnect {
    /// The path through the start tree's node `from_start` and the goal tree's `from_goal`, which
    /// are the same state or (last-free) within `epsilon`: the start tree's branch, then the goal
    /// tree's from the parent of `from_goal` (rl's `RrtDual::getPath` drops it too).
    fn path(&self, from_start: u32, from_goal: u32) -> Vec<Vec<Real>> {
        let mut path = self.trees[0].path_to(from_start);
        let mut tail = self.trees[1].path_to(from_goal);
        tail.reverse();
        path.extend(tail.into_iter().skip(1));
        path
    }

    /// One iteration of rl's `RrtConCon::solve` loop (see the module documentation).
    fn iterate_last_free(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let (a, b) = (self.turn, 1 - self.turn);
        self.turn = b;
        if !cx.sample(a, &mut self.sample) {
            return None;
        }
        let (delta, n, found) = (self.delta, &mut self.new, &mut self.found);
        let (grow, added) = self.trees[a].connect_last_free(cx, &self.sample, delta, true, &mut self.scratch, n, found);
        if matches!(grow, Grow::Trapped | Grow::Rejected) {
            cx.events.at(EventKind::SampleRejected, a, cx.si.project(&self.sample), &self.sample);
            return None;
        }
        self.target.copy_from_slice(self.trees[a].state(added));
        let (n, found) = (&mut self.new, &mut self.found);
        let (g, reached) = self.trees[b].connect_last_free(cx, &self.target, delta, false, &mut self.scratch, n, found);
        if matches!(g, Grow::Trapped | Grow::Rejected)
            || cx.si.distance(self.trees[b].state(reached), &self.target) > self.epsilon
        {
            return None;
        }
        let p = cx.si.project(&self.target);
        cx.events.push(EventKind::TreesConnected, a, added as i64, reached as i64, p, p, &self.target, &self.target);
        let goal = self.task.goal();
        cx.events.at(EventKind::Solved, a, cx.si.project(goal), goal);
        let (from_start, from_goal) = if a == 0 { (added, reached) } else { (reached, added) };
        Some(self.path(from_start, from_goal))
    }
}

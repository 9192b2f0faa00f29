//! RRT-Connect: two trees, one from the start and one from the goal, grown toward each other.
//!
//! J. J. Kuffner and S. M. LaValle, "RRT-Connect: An efficient approach to single-query path
//! planning", ICRA 2000. Each iteration extends one tree a step of `range` toward a uniform sample,
//! then grows the other tree step after step toward the new node (CONNECT) until it reaches it or a
//! motion collides; the trees alternate every iteration. Seeded by the run's [`Rng`]. The goal is
//! reached exactly (goal tolerance plays no part: the goal is a tree's root).
//!
//! [`Rng`]: crate::rng::Rng

use super::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::Real;
use crate::planners::caps::{self, Capabilities, Draws, Family};
use crate::planners::tree::{TreeOptions, TREE_GROUP};
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;
use crate::status::Grow;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "rrt-connect",
    label: "RRT-Connect",
    summary: "Two trees, from start and goal, taking turns to grow toward each other.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP, TREE_GROUP],
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

/// RRT-Connect's parameters.
pub const PARAMS: &[ParamSpec] = &[RANGE];

/// The RRT-Connect planner.
#[derive(Clone)]
pub struct RrtConnect {
    task: Task,
    range: Real,
    opts: TreeOptions,
    trees: Vec<Tree>,
    /// The tree that extends toward the sample this iteration.
    turn: usize,
    sample: Vec<Real>,
    target: Vec<Real>,
    scratch: Vec<Real>,
    new: Vec<Real>,
}

impl RrtConnect {
    /// An RRT-Connect for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Self {
        let n = si.dims();
        RrtConnect {
            task: task.clone(),
            range: resolve_range(si, params.real("range")),
            opts: TreeOptions::from_params(params, si.resolution),
            trees: Vec::new(),
            turn: 0,
            sample: vec![0.0; n],
            target: vec![0.0; n],
            scratch: vec![0.0; n],
            new: vec![0.0; n],
        }
    }
}

impl Planner for RrtConnect {
    fn snapshot(&self) -> Box<dyn Planner> {
        Box::new(self.clone())
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.trees.is_empty() {
            let o = self.opts;
            self.trees =
                vec![Tree::with_options(cx, &self.task.start, 0, o), Tree::with_options(cx, self.task.goal(), 1, o)];
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
                let mut path = self.trees[0].path_to(from_start);
                let mut tail = self.trees[1].path_to(from_goal);
                tail.reverse();
                path.extend(tail.into_iter().skip(1)); // the meeting state is in both
                Some(path)
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

//! RRT: Rapidly-exploring Random Trees.
//!
//! S. M. LaValle, "Rapidly-exploring random trees: a new tool for path planning", TR 98-11, Iowa
//! State University, 1998. One tree from the start; each iteration draws a sample (the goal itself
//! with probability `goal_bias`) and grows the tree toward it, either one step of `range`
//! (`extend`) or step after step until the sample is reached or a motion collides (`connect`,
//! "extend all the way", as the Technion course's E1 and report 003). Seeded by the run's [`Rng`].
//!
//! [`Rng`]: crate::rng::Rng

use super::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::Real;
use crate::planners::caps::{self, Capabilities, Draws, Family};
use crate::planners::tree::MAX_CONNECT_STEPS;
use crate::planners::tree::{TreeMark, TreeOptions, TREE_GROUP};
use crate::planners::{
    Checkpoint, Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree,
};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;
use crate::status::Grow;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "rrt",
    label: "RRT",
    summary: "One tree from the start, grown toward random samples, biased to the goal.",
    iteration: "Draw a sample (sometimes the goal), extend the nearest node one step toward it if the motion is free.",
    checks: "State validity checks: the states along each extension (each motion is checked state by state at the scenario's resolution), plus a sampler's own checks.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP, TREE_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Tree,
        draws: Draws::Tree,
        trees: 1,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: false,
        events: caps::SAMPLING_TREE.with(&[EventKind::Domain, EventKind::Exhausted]),
        pseudocode: "tree-rrt",
        legend: caps::ONE_TREE,
        marks: &[],
        overlays: &[],
    },
    make: |si, task, params| Ok(Box::new(Rrt::new(si, task, params))),
};

/// RRT's parameters.
pub const PARAMS: &[ParamSpec] = &[
    RANGE,
    ParamSpec::real("goal_bias", "Goal bias", 0.0, 1.0, 0.05, "Probability of sampling the goal itself (any sampler)."),
    ParamSpec::choice(
        "extend",
        "Growth",
        &["extend", "connect"],
        0,
        "extend: one step of range toward the sample; connect: step after step until the sample is reached or blocked.",
    ),
];

/// The RRT planner.
#[derive(Clone)]
pub struct Rrt {
    task: Task,
    range: Real,
    connect: bool,
    opts: TreeOptions,
    tree: Option<Tree>,
    sample: Vec<Real>,
    scratch: Vec<Real>,
    new: Vec<Real>,
}

impl Rrt {
    /// An RRT for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Self {
        let n = si.dims();
        Rrt {
            task: task.clone(),
            range: resolve_range(si, params.real("range")),
            connect: params.choice("extend") == "connect",
            opts: TreeOptions::from_params(params, si.resolution),
            tree: None,
            sample: vec![0.0; n],
            scratch: vec![0.0; n],
            new: vec![0.0; n],
        }
    }
}

impl Planner for Rrt {
    /// Its few numbers copied, its tree marked (it only grows: [`Tree::mark`]).
    fn checkpoint(&mut self) -> Checkpoint {
        let tree = self.tree.take();
        let rest = self.clone();
        self.tree = tree;
        Checkpoint::Mark(Box::new((rest, self.tree.as_mut().map(Tree::mark))))
    }
    fn rewind(&mut self, mark: Box<dyn std::any::Any>) {
        let (rest, mark) = *mark.downcast::<(Rrt, Option<TreeMark>)>().expect("RRT's own mark");
        let tree = match (self.tree.take(), mark) {
            (Some(mut tree), Some(mark)) => {
                tree.rewind(mark);
                Some(tree)
            }
            _ => None, // made in the batch: not there at its start
        };
        *self = Rrt { tree, ..rest };
    }
    fn release(&mut self) {
        self.tree.iter_mut().for_each(Tree::release);
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let opts = self.opts;
        let tree = self.tree.get_or_insert_with(|| Tree::with_options(cx, &self.task.start, 0, opts));
        if !cx.sample(0, &mut self.sample) {
            return None;
        }
        let goal = self.task.goal();
        let mut first = true;
        for _ in 0..MAX_CONNECT_STEPS {
            let (grow, id) = if first {
                tree.extend_sample(cx, &self.sample, self.range, &mut self.scratch, &mut self.new)
            } else {
                tree.extend(cx, &self.sample, self.range, &mut self.scratch, &mut self.new)
            };
            if matches!(grow, Grow::Trapped | Grow::Rejected) {
                if first {
                    cx.events.at(EventKind::SampleRejected, 0, cx.si.project(&self.sample), &self.sample);
                }
                return None;
            }
            first = false;
            let to_goal = cx.si.distance(tree.state(id), goal);
            if to_goal <= self.task.goal_tolerance {
                // Within the tolerance, the path ends at the node: the goal region is reached, and
                // a jump to the goal itself would be a motion nobody checked.
                let path = tree.path_to(id);
                cx.events.at(EventKind::Solved, 0, cx.si.project(goal), goal);
                return Some(path);
            }
            if grow == Grow::Reached || !self.connect || tree.slid() {
                return None;
            }
        }
        None
    }

    fn stored_bytes(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::bytes)
    }
    fn node_count(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::len)
    }

    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.tree.iter().cloned().collect())
    }
}

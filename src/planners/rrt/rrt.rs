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
use crate::planners::tree::MAX_CONNECT_STEPS;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, Tree};
use crate::space_info::SpaceInfo;
use crate::status::Grow;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "rrt",
    label: "RRT",
    summary: "One tree from the start, grown toward random samples, biased to the goal.",
    params: PARAMS,
    make: |si, task, params| Box::new(Rrt::new(si, task, params)),
};

/// RRT's parameters.
pub const PARAMS: &[ParamSpec] = &[
    RANGE,
    ParamSpec::real("goal_bias", "Goal bias", 0.0, 1.0, 0.05, "Probability of sampling the goal itself."),
    ParamSpec::choice(
        "extend",
        "Growth",
        &["extend", "connect"],
        0,
        "extend: one step of range toward the sample; connect: step after step until the sample is reached or blocked.",
    ),
];

/// The RRT planner.
pub struct Rrt {
    task: Task,
    range: Real,
    goal_bias: Real,
    connect: bool,
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
            goal_bias: params.real("goal_bias"),
            connect: params.choice("extend") == "connect",
            tree: None,
            sample: vec![0.0; n],
            scratch: vec![0.0; n],
            new: vec![0.0; n],
        }
    }
}

impl Planner for Rrt {
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let tree = self.tree.get_or_insert_with(|| Tree::new(cx, &self.task.start, 0));
        if cx.rng.uniform01() < self.goal_bias {
            self.sample.copy_from_slice(&self.task.goal);
        } else {
            cx.si.sample(cx.rng, &mut self.sample);
        }
        cx.events.at(EventKind::Sample, 0, cx.si.project(&self.sample), &self.sample);
        let mut first = true;
        for _ in 0..MAX_CONNECT_STEPS {
            let (grow, id) = tree.extend(cx, &self.sample, self.range, &mut self.scratch, &mut self.new);
            if grow == Grow::Trapped {
                if first {
                    cx.events.at(EventKind::SampleRejected, 0, cx.si.project(&self.sample), &self.sample);
                }
                return None;
            }
            first = false;
            let to_goal = cx.si.distance(tree.state(id), &self.task.goal);
            if to_goal <= self.task.goal_tolerance {
                let mut path = tree.path_to(id);
                if to_goal > 0.0 {
                    path.push(self.task.goal.clone());
                }
                cx.events.at(EventKind::Solved, 0, cx.si.project(&self.task.goal), &self.task.goal);
                return Some(path);
            }
            if grow == Grow::Reached || !self.connect {
                return None;
            }
        }
        None
    }

    fn node_count(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::len)
    }

    fn data(&self) -> PlannerData {
        PlannerData { trees: self.tree.iter().cloned().collect() }
    }
}

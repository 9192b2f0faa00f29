//! RRT*: asymptotically optimal RRT (S. Karaman, E. Frazzoli, "Sampling-based algorithms for
//! optimal motion planning", IJRR 2011). Work in progress: registered so the registry, page and CLI
//! see it.

use crate::math::Real;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "rrt-star",
    label: "RRT*",
    summary: "One tree that rewires its neighbourhood so paths keep getting shorter.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Goal,
    make: |si, task, params| Box::new(RrtStar::new(si, task, params)),
};

/// RRT*'s parameters.
pub const PARAMS: &[ParamSpec] = &[super::RANGE];

/// The RRT* planner.
pub struct RrtStar {}

impl RrtStar {
    /// An RRT* for `task` with `params`.
    pub fn new(_si: &SpaceInfo, _task: &Task, _params: &Params) -> Self {
        RrtStar {}
    }
}

impl Planner for RrtStar {
    fn iterate(&mut self, _cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        None
    }
    fn node_count(&self) -> usize {
        0
    }
    fn data(&self) -> PlannerData {
        PlannerData::default()
    }
}

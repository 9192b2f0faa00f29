//! Inspection planning (report 004): a tree that grows to see points of interest. Work in
//! progress: registered so the registry, page and CLI see it.

use crate::math::Real;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "inspection",
    label: "Inspection RRT",
    summary: "A tree that grows to see the points of interest, until one branch sees enough of them.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Inspection,
    make: |si, task, params| Box::new(Inspection::new(si, task, params)),
};

/// The inspection planner's parameters.
pub const PARAMS: &[ParamSpec] = &[super::rrt::RANGE];

/// The inspection planner.
pub struct Inspection {}

impl Inspection {
    /// An inspection planner for `task` with `params`.
    pub fn new(_si: &SpaceInfo, _task: &Task, _params: &Params) -> Self {
        Inspection {}
    }
}

impl Planner for Inspection {
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

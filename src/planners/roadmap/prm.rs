//! PRM: the probabilistic roadmap.
//!
//! L. E. Kavraki, P. Švestka, J.-C. Latombe, M. H. Overmars, "Probabilistic roadmaps for path
//! planning in high-dimensional configuration spaces", IEEE Trans. Robotics and Automation 12(4),
//! 1996; stepped as OMPL's `PRM` (growth and queries alternate). Each iteration adds one valid
//! sample as a milestone and connects it to its `k` nearest vertices (or those within `radius`)
//! by checked motions; once start and goal share a component, A* over the roadmap gives the path.
//! Seeded by the run's [`Rng`] only. See [`super::common`] for the steps.
//!
//! [`Rng`]: crate::rng::Rng

use super::{fixed_rule, RoadmapPlanner, CONNECT, K, RADIUS};
use crate::events::EventKind;
use crate::planners::caps::{self, Capabilities, Draws, EventSet, Family};
use crate::planners::{ParamSpec, PlannerSpec, TaskKind};
use crate::sampler::SAMPLER_GROUP;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "prm",
    label: "PRM",
    summary: "A roadmap of random milestones joined by checked motions, searched for the path.",
    iteration: "Add one milestone, check the motions to its neighbours, then search the roadmap if it changed.",
    checks: "State validity checks: the milestones and the states along every candidate edge (each motion is checked state by state at the scenario's resolution).",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Roadmap,
        draws: Draws::Roadmap,
        trees: 0,
        improves: false,
        chart: None,
        queries: true,
        proves_no_path: false,
        events: EventSet::of(&[
            EventKind::Sample,
            EventKind::SampleRejected,
            EventKind::SampleTry,
            EventKind::NodeAdded,
            EventKind::Collision,
            EventKind::RoadmapEdge,
            EventKind::QueryPath,
            EventKind::Solved,
        ]),
        pseudocode: "roadmap-prm",
        legend: caps::ROADMAP,
        marks: &[],
        overlays: &[],
    },
    make: |si, task, params| Ok(Box::new(RoadmapPlanner::new(si.dims(), task, fixed_rule(si, params), false))),
};

/// PRM's parameters.
pub const PARAMS: &[ParamSpec] = &[CONNECT, K, RADIUS];

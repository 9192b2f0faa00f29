//! Lazy PRM: a roadmap whose edges are checked only when a query's path uses them.
//!
//! R. Bohlin, L. E. Kavraki, "Path planning using Lazy PRM", ICRA 2000; stepped as OMPL's
//! `LazyPRM` (growth and queries alternate). Milestones are checked when sampled (one state
//! check each) but edges are added unchecked. When start and goal share a component, A* finds the
//! shortest path; its unchecked edges are checked from the start on, the first invalid one is
//! removed and the search runs again, until a path of valid edges is found or start and goal come
//! apart (then the roadmap grows). Seeded by the run's [`Rng`] only. See [`super::common`].
//!
//! [`Rng`]: crate::rng::Rng

use super::{fixed_rule, RoadmapPlanner, CONNECT, K, RADIUS};
use crate::events::EventKind;
use crate::planners::caps::{Capabilities, LegendItem};
use crate::planners::{ParamSpec, PlannerSpec, TaskKind};
use crate::sampler::SAMPLER_GROUP;

/// Lazy PRM's legend: edges unchecked, checked valid or blocked.
const LEGEND: &[LegendItem] = &[
    LegendItem::line("milestones, edges checked valid", "tree0"),
    LegendItem::line("unchecked edge", "roadmapUnchecked"),
    LegendItem::line("edge checked: blocked", "roadmapInvalid"),
    LegendItem::line("search's latest path", "queryPath"),
];

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "lazy-prm",
    label: "Lazy PRM",
    summary: "A roadmap whose edges are checked only when the shortest path uses them.",
    iteration: "Add one milestone joined to its neighbours by unchecked edges; when start and goal connect, check the shortest path's edges.",
    checks: "State validity checks: one per milestone, and the states along the edges a query's path used (unchecked edges cost nothing).",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        events: super::prm::SPEC.caps.events.with(&[EventKind::EdgeChecked]),
        pseudocode: "roadmap-lazy-prm",
        legend: LEGEND,
        ..super::prm::SPEC.caps
    },

    make: |si, task, params| Ok(Box::new(RoadmapPlanner::new(si.dims(), task, fixed_rule(si, params), true))),
};

/// Lazy PRM's parameters.
pub const PARAMS: &[ParamSpec] = &[CONNECT, K, RADIUS];

//! Planners, one per file, and the registry that lists them with their parameters as data.
//!
//! The generic entry is the [`Planner`] trait: a planner is advanced one iteration at a time by
//! the run loop (`run::Session`), which owns limits, timing and batching. Planners see only a
//! [`SpaceInfo`] bundle, a seeded [`Rng`] and the [`EventLog`]: no scenario or robot types.
//! [`REGISTRY`] lists every planner with its [`ParamSpec`]s; the page builds its parameter panel
//! from that list.

mod params;
pub mod rrt;
pub mod smoothing;
pub mod tree;

pub use params::{ParamKind, ParamSpec, Params};
pub use tree::{PlannerData, Tree};

use crate::events::EventLog;
use crate::math::Real;
use crate::rng::Rng;
use crate::space_info::SpaceInfo;

/// What a planner is asked to solve.
#[derive(Clone, Debug)]
pub struct Task {
    /// Start state.
    pub start: Vec<Real>,
    /// Goal state.
    pub goal: Vec<Real>,
    /// Distance within which the goal counts as reached (0: exactly).
    pub goal_tolerance: Real,
}

/// What an iteration may touch.
pub struct Context<'a> {
    /// The space bundle.
    pub si: &'a SpaceInfo,
    /// The run's seeded generator.
    pub rng: &'a mut Rng,
    /// Where events go.
    pub events: &'a mut EventLog,
    /// Nodes the planner may still add (the run's node limit, honoured inside an iteration too).
    pub nodes_left: usize,
}

/// A planner, advanced one iteration at a time.
pub trait Planner {
    /// Run one iteration; `Some(path)` when it found a solution (start first, goal last).
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>>;
    /// Nodes in all trees.
    fn node_count(&self) -> usize;
    /// The trees, for drawing and checking.
    fn data(&self) -> PlannerData;
}

/// A registered planner: its name, what it is, its parameters, and how to make one.
pub struct PlannerSpec {
    /// The name used by the CLI, the scenario format and the page.
    pub name: &'static str,
    /// A human title.
    pub label: &'static str,
    /// One line on what it does.
    pub summary: &'static str,
    /// Its parameters.
    pub params: &'static [ParamSpec],
    /// Construct it for a task.
    pub make: fn(&SpaceInfo, &Task, &Params) -> Box<dyn Planner>,
}

/// Every planner.
pub static REGISTRY: &[PlannerSpec] = &[rrt::rrt::SPEC, rrt::rrt_connect::SPEC];

/// A planner by name.
pub fn find(name: &str) -> Option<&'static PlannerSpec> {
    REGISTRY.iter().find(|p| p.name == name)
}

/// The names of every planner.
pub fn names() -> Vec<&'static str> {
    REGISTRY.iter().map(|p| p.name).collect()
}

/// The registry as JSON (for the page's planner picker and parameter panel).
pub fn registry_json() -> String {
    let list: Vec<serde_json::Value> = REGISTRY
        .iter()
        .map(|p| {
            serde_json::json!({
                "name": p.name, "label": p.label, "summary": p.summary,
                "params": p.params.iter().map(ParamSpec::to_json).collect::<Vec<_>>(),
            })
        })
        .collect();
    serde_json::to_string(&list).expect("registry serialises")
}

/// Parameters every run loop understands, beside the planner's own: smoothing and limits.
pub static RUN_PARAMS: &[ParamSpec] = &[
    ParamSpec::int("shortcut_attempts", "Shortcut attempts", 0.0, 10000.0, 100.0, "Random shortcut smoothing attempts on the found path (0: no smoothing)."),
    ParamSpec::real("time_limit", "Time limit (s)", 0.01, 3600.0, 30.0, "Stop after this much planning time."),
    ParamSpec::int("max_iterations", "Iteration limit", 1.0, 1e9, 1e7, "Stop after this many iterations."),
    ParamSpec::int("max_nodes", "Node limit", 2.0, 1e8, 1e6, "Stop when the trees hold this many nodes."),
];

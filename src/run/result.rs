use crate::math::Real;
pub use crate::planners::RoadmapCounts;
use serde::Serialize;

/// Statistics of one run (the contract's `stats`).
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct Stats {
    /// Planning time, milliseconds (smoothing excluded).
    pub time_ms: f64,
    /// Planner iterations.
    pub iterations: u64,
    /// Nodes in all trees.
    pub nodes: u64,
    /// State validity checks, including those inside motion checks (the Robotics Library's
    /// collision queries).
    pub checks: u64,
    /// Of `checks`, those that found the state valid (the Robotics Library's free queries; the
    /// workspace planners' geometric tests and a robot's own sampler's checks are never counted
    /// here: see [`SpaceInfo::free_checks`](crate::space_info::SpaceInfo::free_checks)).
    pub free_checks: u64,
    /// Raw path cost in the robot's metric (`null` when unsolved).
    pub cost: Option<Real>,
    /// Smoothed path cost (`null` when unsolved).
    pub smoothed_cost: Option<Real>,
    /// Time after planning, milliseconds: smoothing, and certifying the path first where the planner
    /// tested configurations alone (`repaired`).
    pub smoothing_ms: f64,
    /// Inspection: the fraction of points the raw path sees (before a path exists: the best
    /// branch's so far); `null` for other tasks.
    pub coverage: Option<Real>,
    /// Inspection: the fraction of points the smoothed path sees.
    pub smoothed_coverage: Option<Real>,
    /// Inspection, once solved: the raw path's coverage by the Technion course's definition
    /// (vertices only, touching hides), whatever the scenario counts; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub course_coverage: Option<Real>,
    /// Inspection, once solved: the raw path's coverage by Planarium's continuous definition
    /// (along the edges, only interiors hide); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub continuous_coverage: Option<Real>,
    /// Arm robots, once solved: the raw path's cost in report 004's unit (the sum of the norms of
    /// the stacked link-end differences, the `fk` metric); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cost_fk: Option<Real>,
    /// The smoothed path's cost in the same unit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smoothed_cost_fk: Option<Real>,
    /// For a path whose motions the planner tested only at their configurations (the spatial
    /// arm's course connect): how many of its motions met an obstacle between two of them when it
    /// was certified, and were replaced by a detour.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repaired: Option<u64>,
    /// Roadmap planners (PRM, PRM*, Lazy PRM): the edges checked and those in the roadmap; absent
    /// for the others.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roadmap: Option<RoadmapCounts>,
    /// What the sampler spent.
    pub sampler: SamplerSummary,
}

/// What the sampler spent (the contract's `stats.sampler`).
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct SamplerSummary {
    /// The sampler's name.
    pub name: &'static str,
    /// Whether the planner draws its samples through it (`false` for EST, grid and cell searches,
    /// the potential field and the visibility graph, whose counts then stay 0).
    pub used: bool,
    /// Samples handed to the planner.
    pub accepted: u64,
    /// Samples given up after `sampler_tries` raw draws.
    pub failed: u64,
    /// Raw states drawn.
    pub draws: u64,
    /// State checks the sampler spent (part of `checks`).
    pub checks: u64,
    /// Raw draws per accepted sample.
    pub draws_per_sample: Real,
    /// State checks per accepted sample.
    pub checks_per_sample: Real,
}

impl SamplerSummary {
    /// The summary of a sampler's statistics.
    pub fn of(name: &'static str, used: bool, s: crate::sampler::SamplerStats) -> SamplerSummary {
        SamplerSummary {
            name,
            used,
            accepted: s.accepted,
            failed: s.failed,
            draws: s.draws,
            checks: s.checks,
            draws_per_sample: s.draws_per_sample(),
            checks_per_sample: s.checks_per_sample(),
        }
    }
}

/// A planning result, as the CLI prints it with `--json` and the worker posts it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PlanResult {
    /// Whether a path was found.
    pub solved: bool,
    /// How the run ended.
    pub status: &'static str,
    /// The seed.
    pub seed: u64,
    /// The planner's name.
    pub planner: String,
    /// The parameters set explicitly.
    pub params: serde_json::Map<String, serde_json::Value>,
    /// The raw path, start first (empty when unsolved).
    pub path: Vec<Vec<Real>>,
    /// The smoothed path (empty when unsolved).
    pub smoothed: Vec<Vec<Real>>,
    /// The statistics.
    pub stats: Stats,
    /// Why the run ended where the status alone does not say: why the planner gave up (status
    /// `no_path`), or what holds the memory and what to change (status `memory_limit`); absent
    /// otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl PlanResult {
    /// The result as compact JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a result always serialises")
    }
}

//! How a run stands (OMPL's `PlannerStatus`).

use serde::Serialize;

/// The state of a planning run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Not finished: call `step` again.
    Running,
    /// A path from start to goal was found.
    Solved,
    /// The time limit was reached first.
    TimeLimit,
    /// The iteration limit was reached first.
    IterationLimit,
    /// The node limit was reached first.
    NodeLimit,
    /// The planner holds as many bytes as a run may ([`crate::limits::MAX_RUN_BYTES`]): the run's
    /// `reason` says what holds them and what to change.
    MemoryLimit,
    /// The run was cancelled.
    Cancelled,
    /// The planner gave up: it can say no path exists by its method (a region of influence that
    /// can grow no further, a potential field's local minimum with no escape left).
    NoPath,
}

impl Status {
    /// Whether the run is over.
    pub fn is_finished(self) -> bool {
        self != Status::Running
    }
    /// The status as its JSON name.
    pub fn name(self) -> &'static str {
        match self {
            Status::Running => "running",
            Status::Solved => "solved",
            Status::TimeLimit => "time_limit",
            Status::IterationLimit => "iteration_limit",
            Status::NodeLimit => "node_limit",
            Status::MemoryLimit => "memory_limit",
            Status::Cancelled => "cancelled",
            Status::NoPath => "no_path",
        }
    }
}

/// The outcome of growing a tree toward a state (RRT's extend).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Grow {
    /// No progress: the first step collides.
    Trapped,
    /// A new node was added, short of the target.
    Advanced,
    /// The target itself was added.
    Reached,
    /// Nothing was tried: the sample lay outside its nearest node's dynamic domain.
    Rejected,
}

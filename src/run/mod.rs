//! Running planners: the stepped [`Session`] (limits, timing, batching, events, smoothing), its
//! [`PlanResult`] in the contract's JSON form, and [`bench`](mod@bench) over seeds with its
//! [`report`](mod@report) (CSV, JSON, OMPL benchmark log, the courses' table). The benchmark's
//! modules depend one way: [`summary`](mod@summary) (rows and their summaries) ← `bench` ← `report`.
//!
//! The generic entry is [`Session::new`] followed by [`Session::step`] (the worker, a page that
//! single-steps) or [`Session::run_to_end`] (the CLI, tests, benchmarks).

pub mod bench;
mod certify;
mod check_path;
pub mod course_grade;
mod fingerprint;
mod optimum;
pub mod report;
mod result;
pub mod scaling;
mod session;
pub mod summary;

pub use check_path::{check_path, PathCheck, Refusal, MAX_DESCRIBED};
pub use fingerprint::{fingerprint, fingerprint_in_batches, fnv1a, Fingerprint, FNV_OFFSET};
pub use optimum::{optimum, optimum_within, Optimum};
pub use report::{BenchReport, SetupReport};
pub use result::{PlanResult, RoadmapCounts, SamplerSummary, Stats};
pub use session::{QueryAnswer, RunConfig, Session, SUSPEND_AFTER};
pub use summary::{RunRow, SetupSummary};

#[cfg(test)]
mod tests;

//! Running planners: the stepped [`Session`] (limits, timing, batching, events, smoothing), its
//! [`PlanResult`] in the contract's JSON form, and [`bench`](mod@bench) over seeds with its
//! [`export`](mod@export)s (CSV, JSON, OMPL benchmark log, the courses' table).
//!
//! The generic entry is [`Session::new`] followed by [`Session::step`] (the worker, a page that
//! single-steps) or [`Session::run_to_end`] (the CLI, tests, benchmarks).

pub mod bench;
pub mod export;
mod fingerprint;
mod result;
pub mod scaling;
mod session;

pub use export::{BenchReport, RunRow, SetupReport, SetupSummary};
pub use fingerprint::{fingerprint, fingerprint_in_batches, fnv1a, Fingerprint, FNV_OFFSET};
pub use result::{PlanResult, SamplerSummary, Stats};
pub use session::{RunConfig, Session};

#[cfg(test)]
mod tests;

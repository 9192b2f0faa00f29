//! # Planarium's planning core
//!
//! The data flows one way, and the modules follow it:
//!
//! 1. [`scenario`]: the JSON contract, parsed and validated, errors with their JSON path;
//! 2. [`problem`]: the scenario as a [`geometry::Workspace`], a [`robot::Robot`], a
//!    [`space::StateSpace`], start and goal, bundled for planners as a [`space_info::SpaceInfo`]
//!    with [`validity`] and [`motion`] checking;
//! 3. [`planners`]: stepped planners (RRT, RRT-Connect) over that bundle, using [`nn`] for nearest
//!    neighbours and a seeded [`rng`], emitting [`events`];
//! 4. [`run`]: the session that steps a planner in batches under limits, smooths, and reports a
//!    [`run::PlanResult`]; benchmarks over seeds;
//! 5. `wasm` (only on `wasm32`): the thin binding the Web Worker drives.
//!
//! ```
//! use planarium::{problem::Problem, run::{RunConfig, Session}, scenario, planners::Params};
//! let sc = scenario::builtin("narrow").unwrap();
//! let config = RunConfig { planner: "rrt-connect".into(), params: Params::default(), seed: 7, record_events: false };
//! let mut s = Session::new(Problem::from_scenario(&sc).unwrap(), config).unwrap();
//! s.run_to_end();
//! assert!(s.result().solved);
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod events;
pub mod geometry;
pub mod io;
pub mod journal;
pub mod limits;
pub mod math;
pub mod motion;
pub mod nn;
pub mod params;
pub mod planners;
pub mod problem;
pub mod rng;
pub mod robot;
pub mod run;
pub mod sampler;
pub mod scenario;
pub mod space;
pub mod space_info;
pub mod status;
pub mod validity;

#[cfg(target_arch = "wasm32")]
mod wasm;

//! # Planarium's planning core
//!
//! The data flows one way, and the modules follow it (in this order below):
//!
//! 1. [`scenario`]: the JSON contract, parsed and validated, errors with their JSON path; [`io`]
//!    reads the course formats (Technion maps, ASV problems) into scenarios;
//! 2. [`problem`]: the scenario as a [`geometry::Workspace`], a [`robot::Robot`], a
//!    [`space::StateSpace`], start and goal, bundled for planners as a [`space_info::SpaceInfo`]
//!    with [`validity`] and [`motion`] checking;
//! 3. what planners draw with: parameters declared as data ([`params`]), the [`sampler`]s, [`nn`]
//!    for nearest neighbours;
//! 4. [`planners`]: stepped planners over that bundle, each in the registry
//!    ([`planners::REGISTRY`]) with its parameters: RRT and RRT-Connect (the tree variants,
//!    Dynamic-Domain RRT and exhausted nodes, are their parameters), RRT*, inspection RRT, the
//!    hexagonal decomposition with a potential (`hex-potential`) and the artificial potential field
//!    (`potential-field`); every sampling planner takes any [`sampler`]; they emit [`events`];
//! 5. [`run`]: the session that steps a planner in batches under limits (a batch that stops
//!    mid-iteration resumes through the [`journal`]), smooths, and reports a
//!    [`run::PlanResult`]; benchmarks over seeds and their reports;
//! 6. `wasm` (only on `wasm32`): the thin binding the Web Worker drives.
//!
//! Used throughout: [`math`] (nalgebra's vectors and poses), the seeded [`rng`], input [`limits`], the
//! run [`status`], the [`clock`].
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

// 1. Input: the scenario contract; the course formats read into it.
pub mod scenario;
// Technion maps, ASV problems and solutions.
pub mod io;

// 2. The problem, and what it is made of: the workspace, the robot, its space, and the checks.
pub mod problem;
// What the page may do with a loaded scenario (the robot kind's record, views, downloads).
pub mod scene_caps;
// Exact 2-D shapes and predicates; convex polygons.
pub mod geometry;
// Point, rigid body, arm, ASV chain.
pub mod robot;
// State spaces: distance, interpolation, sampling.
pub mod space;
// State validity, counted.
pub mod validity;
// Motion validation.
pub mod motion;
// The bundle planners see.
pub mod space_info;

// 3. What planners draw with: parameters as data, samplers, nearest neighbours.
pub mod params;
// Uniform, Gaussian, bridge, obstacle-based, near-collision.
pub mod sampler;
// The k-d tree.
pub mod nn;

// 4. The planners and the events they emit.
pub mod planners;
// Fixed-stride records for the page.
pub mod events;

// 5. Running them: the batch journal, then sessions, benchmarks and their reports.
pub mod journal;
// Session, results, fingerprints, benchmarks, reports.
pub mod run;

// Used throughout.
pub mod limits;
// Scalars, points, vectors and poses (nalgebra).
pub mod math;
// The seeded generator, and fresh seeds.
pub mod rng;
// The clock time limits read.
pub mod clock;
// How a run stands.
pub mod status;

// 6. The binding the Web Worker drives.
#[cfg(target_arch = "wasm32")]
mod wasm;

//! # Planarium's planning core
//!
//! The modules import one way, each only from those below it (`tests/module_graph.rs` fails on a
//! cycle; `docs/architecture.md` draws the graph). From the bottom:
//!
//! 1. used throughout: [`math`] (nalgebra's vectors and poses), the seeded [`rng`], input
//!    [`limits`], the run [`status`], the [`clock`];
//! 2. what everything stands on: [`geometry`] (exact 2-D shapes and predicates), [`space`] (state
//!    spaces, the discrete motion loop), the flat [`events`] records, the batch [`journal`],
//!    parameters declared as data ([`params`]);
//! 3. [`scenario`]: the JSON contract, parsed and validated, errors with their JSON path;
//! 4. [`robot`]: what a state means, and what a robot can do; the checks on it: state
//!    [`validity`] and [`motion`] validation;
//! 5. [`space_info`]: the bundle planners see ([`space_info::SpaceInfo`]: the space, counted
//!    validity and motion checks, the deadline, the batch journal, sight);
//! 6. what planners draw with: the [`sampler`]s, [`nn`] for nearest neighbours;
//! 7. [`planners`]: stepped planners over that bundle, each in the registry
//!    ([`planners::REGISTRY`]) with its parameters: RRT and RRT-Connect (the tree variants,
//!    Dynamic-Domain RRT and exhausted nodes, are their parameters), RRT*, Informed RRT*, inspection RRT, the
//!    roadmaps, EST, grid search, the visibility graph, the hexagonal decomposition with a
//!    potential (`hex-potential`) and the artificial potential field (`potential-field`); every
//!    sampling planner takes any [`sampler`]; they emit [`events`];
//! 8. [`problem`]: a scenario made into a [`geometry::Workspace`], a [`robot::Robot`], a
//!    [`space::StateSpace`], start and goal, bundled as a [`space_info::SpaceInfo`]; its planner
//!    block is checked against the registry here; [`scene_caps`]: what the page may do with it
//!    (the robot kind's record, a configuration-space view, the optimum, a solution file);
//! 9. [`io`]: the course formats (Technion maps, ASV problems, occupancy maps) read into scenarios,
//!    and course solutions checked on a problem;
//! 10. [`run`]: the session that steps a planner in batches under limits (a batch that stops
//!     mid-iteration resumes through the [`journal`]), smooths, and reports a
//!     [`run::PlanResult`]; benchmarks over seeds and their reports; the exact optimum
//!     ([`run::optimum`], a run of the visibility graph);
//! 11. `wasm` (only on `wasm32`): the thin binding the Web Worker drives.
//!
//! The data itself flows scenario → problem → planner → events and result → run → page.
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

// 1. Used throughout. Scalars, points, vectors and poses (nalgebra).
pub mod math;
// Input limits.
pub mod limits;
// The seeded generator, and fresh seeds.
pub mod rng;
// The clock time limits read.
pub mod clock;
// How a run stands.
pub mod status;

// 2. What everything stands on.
// Exact 2-D shapes and predicates; convex polygons.
pub mod geometry;
// State spaces: distance, interpolation, sampling; the discrete motion loop.
pub mod space;
// Fixed-stride records for the page.
pub mod events;
// The bounded batch's recorded answers.
pub mod journal;
// Parameters as data.
pub mod params;

// 3. The scenario contract.
pub mod scenario;

// 4. Point, rigid body, arm, ASV chain; state validity; motion validation.
pub mod motion;
pub mod robot;
pub mod validity;

// 5. The bundle planners see.
pub mod space_info;

// 6. Uniform, Gaussian, bridge, obstacle-based, near-collision samplers; the k-d tree.
pub mod nn;
pub mod sampler;

// 7. The planners.
pub mod planners;

// 8. The problem: a scenario made into what planners plan on; what the page may do with it.
pub mod problem;
pub mod scene_caps;

// 9. Technion maps, ASV problems and solutions, occupancy maps.
pub mod io;

// 10. Running them: sessions, results, fingerprints, benchmarks, reports, the exact optimum.
pub mod run;

// 11. The binding the Web Worker drives.
#[cfg(target_arch = "wasm32")]
mod wasm;

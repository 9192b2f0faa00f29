//! The exact optimum of a problem, from a run of the visibility-graph planner
//! ([`crate::planners::visibility`]) to its end: the reference cost other planners' paths are
//! measured against (the CLI's `--optimum`, the page's optimum line, the optimality tests). It runs
//! a [`Session`], so it lives with the sessions, above the planners.

use super::{RunConfig, Session};
use crate::math::Real;
use crate::planners::visibility::{body_of, SPEC};
use crate::planners::Params;
use crate::problem::Problem;

/// The shortest path's cost for a problem, from a run of the planner to its end: `Ok(None)` when no
/// path exists; an error for a robot it does not apply to. `exact` says whether the cost is the
/// robot's optimum (a point, or a round footprint: see
/// [`Body`](crate::planners::visibility::Body)) or only a valid path's cost.
#[derive(Clone, Debug, PartialEq)]
pub struct Optimum {
    /// The shortest path's cost in the robot's metric (`None`: start and goal not connected).
    pub cost: Option<Real>,
    /// Whether that is the robot's optimum (up to the approximations in
    /// [`crate::planners::visibility`]'s doc).
    pub exact: bool,
    /// The path (planning states).
    pub path: Vec<Vec<Real>>,
}

/// The optimum of `problem` by the visibility graph (default parameters, no events, an hour at
/// most: see [`optimum_within`]).
pub fn optimum(problem: Problem) -> Result<Optimum, String> {
    optimum_within(problem, 3600.0)
}

/// [`optimum`] within `seconds`; an error when the graph takes longer (a map of many obstacles).
pub fn optimum_within(problem: Problem, seconds: Real) -> Result<Optimum, String> {
    let exact = body_of(&problem.si)?.round;
    let spec = crate::planners::find(SPEC.name).expect("registered");
    let mut params = Params::defaults(spec);
    params.set_text(spec, "time_limit", &format!("{}", seconds.clamp(0.01, 3600.0)))?;
    params.set_text(spec, "batch", "1000000")?;
    let config = RunConfig { planner: spec.name.into(), params, seed: 1, record_events: false };
    let mut s = Session::new(problem, config)?;
    s.run_to_end();
    let r = s.result();
    if r.solved {
        Ok(Optimum { cost: r.stats.cost, exact, path: s.planning_path(true).to_vec() })
    } else if s.status() == crate::status::Status::NoPath {
        Ok(Optimum { cost: None, exact, path: Vec::new() })
    } else {
        Err(format!("the visibility graph stopped: {}", r.status))
    }
}

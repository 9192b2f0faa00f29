//! The RRT family: [`rrt`] (single tree, goal bias, extend or connect growth),
//! [`rrt_connect`] (two trees, alternating) and [`rrt_star`] (rewiring toward shorter paths).

pub mod informed_rrt_star;
#[allow(clippy::module_inception)] // planners/rrt/rrt.rs, one planner per file
pub mod rrt;
pub mod rrt_connect;
pub mod rrt_star;

use crate::planners::ParamSpec;

/// The step range: 0 means OMPL's default, 0.2 × the space's largest extent.
pub const RANGE: ParamSpec = ParamSpec::real(
    "range",
    "Range",
    0.0,
    1e6,
    0.0,
    "Longest motion added in one step, in the robot's metric (0: 0.2 × the space's extent, as OMPL; a spatial arm's own default, 0.2 rad).",
);

/// The range a planner uses, resolving 0 to the robot kind's default, else OMPL's.
pub fn resolve_range(si: &crate::space_info::SpaceInfo, range: f64) -> f64 {
    if range > 0.0 {
        range
    } else {
        si.robot_caps().default_range.unwrap_or_else(|| 0.2 * si.space.max_extent())
    }
}

//! Roadmaps: [`prm`] (k-nearest or radius neighbours), [`prm_star`] (PRM*'s shrinking rule) and
//! [`lazy_prm`] (edges checked only when a query's path uses them), all built on one
//! [`RoadmapPlanner`] over one [`Roadmap`] graph.
//!
//! The generic entry is [`RoadmapPlanner`]: stepped one milestone at a time by the run loop like
//! every planner, and reusable for further queries on the same map through
//! [`RoadmapPlanner::query`].

pub mod common;
pub mod graph;
pub mod lazy_prm;
pub mod prm;
pub mod prm_star;

pub use common::{k_star, Neighbours, RoadmapPlanner, RoadmapStats};
pub use graph::{Edge, EdgeState, Roadmap};

use crate::params::ParamSpec;
use crate::planners::Params;
use crate::space_info::SpaceInfo;

/// PRM's and Lazy PRM's neighbour rule.
pub const CONNECT: ParamSpec = ParamSpec::choice(
    "connect",
    "Neighbours",
    &["k-nearest", "radius"],
    0,
    "k-nearest: connect a new milestone to its k nearest vertices; radius: to every vertex within the radius.",
);

/// The `k` of the k-nearest rule (OMPL's PRM default, 10).
pub const K: ParamSpec =
    ParamSpec::int("k", "k", 1.0, 1000.0, 10.0, "k-nearest: vertices a new milestone is connected to.")
        .only_when("connect", &["k-nearest"]);

/// The radius of the radius rule.
pub const RADIUS: ParamSpec = ParamSpec::real(
    "radius",
    "Radius",
    0.0,
    1e6,
    0.0,
    "radius: connect to the vertices within this distance, in the robot's metric (0: 0.2 × the space's extent).",
)
.only_when("connect", &["radius"]);

/// The rule `params` choose among [`CONNECT`], [`K`] and [`RADIUS`].
pub fn fixed_rule(si: &SpaceInfo, params: &Params) -> Neighbours {
    if params.choice("connect") == "radius" {
        let r = params.real("radius");
        Neighbours::Radius(if r > 0.0 { r } else { 0.2 * si.space.max_extent() })
    } else {
        Neighbours::Nearest(params.real("k") as usize)
    }
}

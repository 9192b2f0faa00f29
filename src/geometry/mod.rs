//! Exact 2-D geometry: obstacle shapes and the predicates that test them.
//!
//! The generic entry is [`Workspace`]: bounds plus obstacles, asked whether a point, a segment or a
//! polygon meets any obstacle. Below it, one file per pair of shapes, parry-style:
//! [`segment`] (segment/segment, point/segment), [`polygon`] (point/polygon, segment/polygon),
//! [`circle`] (segment/circle). All obstacles are closed sets: touching is a collision.
//! [`convex`] holds the floating-point constructions on convex polygons (clipping, centroid,
//! hexagons) that the hexagonal decomposition builds its cells with. [`solid`] holds the 3-D
//! convex solids (parry3d shapes) of a spatial arm's scene and links, [`mesh`] their triangle meshes
//! for the page's 3-D view.

mod aabb;
pub mod circle;
pub mod convex;
pub mod exact;
mod grid;
pub mod hull;
pub mod mesh;
pub mod polygon;
pub mod segment;
mod shape;
pub mod sight;
pub mod solid;
mod workspace;

pub use aabb::Aabb;
pub use shape::Shape;
pub use sight::SensorPose;
pub(crate) use workspace::add_tests;
pub use workspace::{cell_blocked, take_tests, Workspace, BVH_FROM, GRID_FROM};

#[cfg(test)]
mod tests;

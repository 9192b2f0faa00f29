//! Convex solids in 3-D: a spatial arm's scene (`obstacles3d`) and its links' parts, as parry3d
//! shapes (boxes as `Cuboid`, hulls as `ConvexPolyhedron` from points) with their own-frame boxes
//! for the broad phase. The queries themselves (GJK through parry's `intersection_test`) are the
//! arm's (`robot::spatial`); this file holds what is built once, when the scenario is read.

use super::hull::Hull;
use crate::math::Real;
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::shape::Cuboid;

/// A convex shape in its own frame.
#[derive(Clone, Debug)]
pub enum Convex {
    /// A box centred on its frame's origin, by half extents.
    Cuboid(Cuboid),
    /// The convex hull of points (its support map climbs the hull: `geometry::hull`).
    Hull(Box<Hull>),
}

/// An axis-aligned box in 3-D, closed: `lo ..= hi`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Box3 {
    /// The low corner.
    pub lo: [Real; 3],
    /// The high corner.
    pub hi: [Real; 3],
}

impl Box3 {
    /// Whether the two closed boxes meet (touching counts).
    #[inline]
    pub fn meets(&self, o: &Box3) -> bool {
        (0..3).all(|k| self.lo[k] <= o.hi[k] && o.lo[k] <= self.hi[k])
    }

    /// The box around `pts`.
    pub fn of_points(pts: &[[Real; 3]]) -> Box3 {
        let mut b = Box3 { lo: [Real::INFINITY; 3], hi: [Real::NEG_INFINITY; 3] };
        for p in pts {
            for (k, x) in p.iter().enumerate() {
                b.lo[k] = b.lo[k].min(*x);
                b.hi[k] = b.hi[k].max(*x);
            }
        }
        b
    }

    /// Its centre and half extents.
    pub fn centre_half(&self) -> ([Real; 3], [Real; 3]) {
        let c = [0, 1, 2].map(|k| 0.5 * (self.lo[k] + self.hi[k]));
        let h = [0, 1, 2].map(|k| 0.5 * (self.hi[k] - self.lo[k]));
        (c, h)
    }
}

/// A convex solid placed in a frame: its shape, where the shape sits in the frame (a box's
/// centre), and its box in that frame.
#[derive(Clone, Debug)]
pub struct Solid {
    /// Its name, for explanations ("" when it has none).
    pub name: String,
    /// The shape.
    pub convex: Convex,
    /// The shape's placement in the frame.
    pub placement: Pose,
    /// The shape's box in the frame.
    pub bounds: Box3,
}

impl Solid {
    /// A box by centre and full size.
    pub fn cuboid(name: &str, center: [Real; 3], size: [Real; 3]) -> Solid {
        let half = size.map(|s| 0.5 * s);
        Solid {
            name: name.to_string(),
            convex: Convex::Cuboid(Cuboid::new(Vector::new(half[0], half[1], half[2]))),
            placement: Pose::from_translation(Vector::new(center[0], center[1], center[2])),
            bounds: Box3 { lo: [0, 1, 2].map(|k| center[k] - half[k]), hi: [0, 1, 2].map(|k| center[k] + half[k]) },
        }
    }

    /// The convex hull of `pts` (at least 4 points, not in one plane); an error when parry cannot
    /// build it.
    pub fn hull(name: &str, pts: &[[Real; 3]]) -> Result<Solid, String> {
        let vs: Vec<Vector> = pts.iter().map(|p| Vector::new(p[0], p[1], p[2])).collect();
        let hull =
            Hull::of_points(&vs).map(Box::new).ok_or("its convex hull could not be built (degenerate points)")?;
        Ok(Solid {
            name: name.to_string(),
            convex: Convex::Hull(hull),
            placement: Pose::IDENTITY,
            bounds: Box3::of_points(pts),
        })
    }
}

use std::cmp::Ordering;

use super::circle::{interior_meets_segment_circle, intersect_segment_circle, point_disc_cmp};
use super::polygon::{contains_polygon_point, interior_meets_segment_polygon, intersect_segment_polygon};
use super::segment::{
    contains_segment_point, distance2_point_segment, distance_segment_segment_apart, intersect_segment_segment,
    orient_sign,
};
use super::Aabb;
use crate::math::{MinMax, Real, Vec2};

/// A closed obstacle shape in world coordinates.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Axis-aligned rectangle (its corners normalised: `min <= max`).
    Rect(Aabb),
    /// Simple polygon, convex or not, either winding.
    Polygon(Vec<Vec2>),
    /// Disc: centre and radius.
    Circle(Vec2, Real),
    /// A wall of zero thickness.
    Segment(Vec2, Vec2),
}

impl Shape {
    /// The shape's bounding box.
    pub fn aabb(&self) -> Aabb {
        match self {
            Shape::Rect(b) => *b,
            Shape::Polygon(p) => Aabb::of_points(p),
            Shape::Circle(c, r) => Aabb { min: *c, max: *c }.grown(*r),
            Shape::Segment(a, b) => Aabb::of_points(&[*a, *b]),
        }
    }

    /// One point of the shape (used to detect a shape wholly inside another).
    pub fn some_point(&self) -> Vec2 {
        match self {
            Shape::Rect(b) => b.min,
            Shape::Polygon(p) => p[0],
            Shape::Circle(c, _) => *c,
            Shape::Segment(a, _) => *a,
        }
    }

    /// The first point of the segment `a b` (from `a`) in the shape, within 2⁻⁵² of the
    /// segment's length, or `None` when they do not meet. `open`: the shape as an open set (its
    /// boundary not counted, as [`Shape::interior_meets_segment`]). A bisection on how much of
    /// the segment from `a` meets the shape, which only grows with it. For drawing where a body
    /// meets an obstacle; no validity depends on it.
    pub fn first_point_on(&self, a: Vec2, b: Vec2, open: bool) -> Option<Vec2> {
        let meets = |t: Real| {
            let p = a + (b - a) * t;
            if open {
                self.interior_meets_segment(a, p)
            } else {
                self.intersects_segment(a, p)
            }
        };
        if !meets(1.0) {
            return None;
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..52 {
            let mid = 0.5 * (lo + hi);
            if meets(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(a + (b - a) * hi)
    }

    /// Whether the closed shape contains `p`.
    #[inline(always)]
    pub fn contains_point(&self, p: Vec2) -> bool {
        match self {
            Shape::Rect(b) => b.contains(p),
            Shape::Polygon(poly) => contains_polygon_point(poly, p),
            Shape::Circle(c, r) => point_disc_cmp(p, *c, *r) != Ordering::Greater,
            Shape::Segment(a, b) => contains_segment_point(*a, *b, p),
        }
    }

    /// Whether the closed segment `a b` meets the shape.
    pub fn intersects_segment(&self, a: Vec2, b: Vec2) -> bool {
        match self {
            Shape::Rect(r) => {
                if r.contains(a) || r.contains(b) {
                    return true;
                }
                let c = [r.min, Vec2::new(r.max.x, r.min.y), r.max, Vec2::new(r.min.x, r.max.y)];
                (0..4).any(|i| intersect_segment_segment(a, b, c[i], c[(i + 1) % 4]))
            }
            Shape::Polygon(poly) => intersect_segment_polygon(a, b, poly),
            Shape::Circle(c, r) => intersect_segment_circle(a, b, *c, *r),
            Shape::Segment(p, q) => intersect_segment_segment(a, b, *p, *q),
        }
    }

    /// The distance from the closed segment `a b` to the shape, or `cap` if that is smaller
    /// (0 when they meet).
    pub fn distance_to_segment(&self, a: Vec2, b: Vec2, cap: Real) -> Real {
        if !Aabb::of_points(&[a, b]).grown(cap).intersects(&self.aabb()) {
            return cap;
        }
        if self.intersects_segment(a, b) {
            return 0.0;
        }
        let mut best = cap;
        match self {
            Shape::Rect(r) => {
                let c = [r.min, Vec2::new(r.max.x, r.min.y), r.max, Vec2::new(r.min.x, r.max.y)];
                (0..4).for_each(|i| best = best.at_most(distance_segment_segment_apart(a, b, c[i], c[(i + 1) % 4])));
            }
            Shape::Polygon(p) => (0..p.len())
                .for_each(|i| best = best.at_most(distance_segment_segment_apart(a, b, p[i], p[(i + 1) % p.len()]))),
            Shape::Segment(c, d) => best = best.at_most(distance_segment_segment_apart(a, b, *c, *d)),
            Shape::Circle(c, r) => best = best.at_most(distance2_point_segment(*c, a, b).sqrt() - r),
        }
        best.at_least(0.0)
    }

    /// Whether the segment `a b` meets the shape's *interior* (the shape as an open set: touching
    /// its boundary is allowed). A segment obstacle has no interior; it is met only by a proper
    /// crossing.
    pub fn interior_meets_segment(&self, a: Vec2, b: Vec2) -> bool {
        match self {
            Shape::Rect(r) => {
                if !(r.min.x < r.max.x && r.min.y < r.max.y) {
                    return false; // a flat rectangle has no interior
                }
                let c = [r.min, Vec2::new(r.max.x, r.min.y), r.max, Vec2::new(r.min.x, r.max.y)];
                interior_meets_segment_polygon(&c, a, b)
            }
            Shape::Polygon(poly) => interior_meets_segment_polygon(poly, a, b),
            Shape::Circle(c, r) => interior_meets_segment_circle(a, b, *c, *r),
            Shape::Segment(c, d) => {
                let (d1, d2) = (orient_sign(*c, *d, a), orient_sign(*c, *d, b));
                let (d3, d4) = (orient_sign(a, b, *c), orient_sign(a, b, *d));
                d1 * d2 < 0 && d3 * d4 < 0
            }
        }
    }

    /// The distance from the closed polygon `poly` (bounding box `bb`) to the shape, or `cap` if
    /// that is smaller (0 when they meet).
    pub fn distance_to_polygon(&self, poly: &[Vec2], bb: &Aabb, cap: Real) -> Real {
        if !bb.grown(cap).intersects(&self.aabb()) {
            return cap;
        }
        if self.intersects_polygon(poly, bb) {
            return 0.0;
        }
        let n = poly.len();
        let mut best = cap;
        let mut edge = |a: Vec2, b: Vec2| {
            for i in 0..n {
                best = best.at_most(distance_segment_segment_apart(a, b, poly[i], poly[(i + 1) % n]));
            }
        };
        match self {
            Shape::Rect(r) => {
                let c = [r.min, Vec2::new(r.max.x, r.min.y), r.max, Vec2::new(r.min.x, r.max.y)];
                (0..4).for_each(|i| edge(c[i], c[(i + 1) % 4]));
            }
            Shape::Polygon(p) => (0..p.len()).for_each(|i| edge(p[i], p[(i + 1) % p.len()])),
            Shape::Segment(a, b) => edge(*a, *b),
            Shape::Circle(c, r) => {
                for i in 0..n {
                    best = best.at_most(distance2_point_segment(*c, poly[i], poly[(i + 1) % n]).sqrt() - r);
                }
            }
        }
        best.at_least(0.0)
    }

    /// Whether the closed polygon `poly` (with bounding box `bb`) meets the shape.
    pub fn intersects_polygon(&self, poly: &[Vec2], bb: &Aabb) -> bool {
        if !bb.intersects(&self.aabb()) {
            return false;
        }
        let n = poly.len();
        let mut j = n - 1;
        for i in 0..n {
            if self.intersects_segment(poly[j], poly[i]) {
                return true;
            }
            j = i;
        }
        // No edge of `poly` meets the shape: either disjoint, or the shape is wholly inside `poly`.
        contains_polygon_point(poly, self.some_point())
    }
}

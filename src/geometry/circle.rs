//! Predicates with a closed disc.

use super::segment::distance2_point_segment;
use crate::math::{Real, Vec2};

/// Whether the closed segment `a b` meets the closed disc of centre `c` and radius `r`.
#[inline]
pub fn intersect_segment_circle(a: Vec2, b: Vec2, c: Vec2, r: Real) -> bool {
    distance2_point_segment(c, a, b) <= r * r
}

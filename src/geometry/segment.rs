//! Segment/segment and point/segment predicates.
//!
//! Every decision here rests on [`orient`], the sign of `(b − a) × (c − a)` computed **exactly**
//! (Shewchuk's adaptive predicate from the `robust` crate: an `f64` evaluation with an error bound,
//! and exact expansion arithmetic only when the bound cannot decide; IEEE operations only, so
//! native and wasm agree bit for bit). The naive `f64` formula returned 0 for about a fifth of
//! rounded near-collinear triples whose true sign is not 0 (`tests.rs`,
//! `orientation_is_exact_on_near_collinear_triples`). Distances are not exact: see
//! [`distance2_point_segment`].

use crate::math::{MinMax, Real, Vec2};

/// The orientation of `a, b, c`: > 0 when counter-clockwise, < 0 when clockwise, 0 exactly when the
/// three points are collinear (as `f64` values, with no rounding). Only the sign is meaningful:
/// the magnitude approximates twice the triangle's signed area.
///
/// Exact provided no intermediate product overflows or underflows (coordinates and their
/// differences between about `1e-140` and `1e140` in magnitude, or 0).
#[inline(always)]
pub fn orient(a: Vec2, b: Vec2, c: Vec2) -> Real {
    robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    )
}

/// The sign of [`orient`] as -1, 0 or 1.
#[inline(always)]
pub fn orient_sign(a: Vec2, b: Vec2, c: Vec2) -> i8 {
    let d = orient(a, b, c);
    (d > 0.0) as i8 - (d < 0.0) as i8
}

/// Whether `p`, known to be collinear with `a, b`, lies within their bounding box.
#[inline]
fn within(a: Vec2, b: Vec2, p: Vec2) -> bool {
    p.x >= a.x.at_most(b.x) && p.x <= a.x.at_least(b.x) && p.y >= a.y.at_most(b.y) && p.y <= a.y.at_least(b.y)
}

/// Whether point `p` lies on the closed segment `a b`.
#[inline]
pub fn contains_segment_point(a: Vec2, b: Vec2, p: Vec2) -> bool {
    orient(a, b, p) == 0.0 && within(a, b, p)
}

/// Whether closed segments `p1 p2` and `q1 q2` share a point (touching and overlap count).
///
/// Both ends of one strictly on the same side of the other's line is the common answer and
/// returns after two orientation tests (exact signs make the early exits agree with the full test).
#[inline(always)]
pub fn intersect_segment_segment(p1: Vec2, p2: Vec2, q1: Vec2, q2: Vec2) -> bool {
    let d1 = orient(q1, q2, p1);
    let d2 = orient(q1, q2, p2);
    if (d1 > 0.0 && d2 > 0.0) || (d1 < 0.0 && d2 < 0.0) {
        return false;
    }
    let d3 = orient(p1, p2, q1);
    let d4 = orient(p1, p2, q2);
    if (d3 > 0.0 && d4 > 0.0) || (d3 < 0.0 && d4 < 0.0) {
        return false;
    }
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return true;
    }
    (d1 == 0.0 && within(q1, q2, p1))
        || (d2 == 0.0 && within(q1, q2, p2))
        || (d3 == 0.0 && within(p1, p2, q1))
        || (d4 == 0.0 && within(p1, p2, q2))
}

/// Distance between closed segments `a b` and `c d` (0 when they meet).
#[inline(always)]
pub fn distance_segment_segment(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> Real {
    if intersect_segment_segment(a, b, c, d) {
        return 0.0;
    }
    distance_segment_segment_apart(a, b, c, d)
}

/// Distance between closed segments `a b` and `c d` known not to meet (the nearest points are
/// then an end of one and a point of the other): [`distance_segment_segment`] without its
/// intersection test.
#[inline(always)]
pub fn distance_segment_segment_apart(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> Real {
    distance2_point_segment(a, c, d)
        .at_most(distance2_point_segment(b, c, d))
        .at_most(distance2_point_segment(c, a, b))
        .at_most(distance2_point_segment(d, a, b))
        .sqrt()
}

/// Squared distance from `p` to the closed segment `a b`.
///
/// Not exact: the projection and the differences are rounded (an error of about ten ulps of the
/// largest coordinate). The disc predicates use it only as a filter before an exact comparison
/// ([`super::circle`]); clearances (motion certification) use it as it is, see
/// `docs/architecture.md`.
#[inline(always)]
pub fn distance2_point_segment(p: Vec2, a: Vec2, b: Vec2) -> Real {
    let ab = b - a;
    let l2 = ab.norm_squared();
    if l2 == 0.0 {
        return (p - a).norm_squared();
    }
    let t = ((p - a).dot(&ab) / l2).clamp(0.0, 1.0);
    (p - (a + ab.scale(t))).norm_squared()
}

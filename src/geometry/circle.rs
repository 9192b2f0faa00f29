//! Predicates with a closed disc.
//!
//! A distance cannot be computed exactly in `f64`, but its comparison with a radius can be decided
//! exactly: the `f64` distance is used as a filter, and only when it lies within a generous bound
//! of the radius (64 ulps of the largest coordinate) is the comparison redone in exact dyadic
//! arithmetic ([`super::exact`]). The answer is therefore exact, whatever the rounding.

use std::cmp::Ordering;

use super::exact::segment_disc_cmp_exact;
use super::segment::distance2_point_segment;
use crate::math::{MinMax, Real, Vec2};

/// How the distance from the closed segment `a b` to the point `c` compares with `r` (`r ≥ 0`),
/// exactly.
#[inline]
pub fn segment_disc_cmp(a: Vec2, b: Vec2, c: Vec2, r: Real) -> Ordering {
    let d2 = distance2_point_segment(c, a, b);
    // The computed distance is within about 10 ulps of the largest coordinate of the exact one;
    // outside 64 ulps the filter decides.
    let s =
        a.x.abs()
            .at_least(a.y.abs())
            .at_least(b.x.abs())
            .at_least(b.y.abs())
            .at_least(c.x.abs())
            .at_least(c.y.abs())
            .at_least(r);
    let m = 64.0 * Real::EPSILON * s;
    let hi = r + m;
    if d2 > hi * hi {
        return Ordering::Greater;
    }
    let lo = r - m;
    if lo > 0.0 && d2 < lo * lo {
        return Ordering::Less;
    }
    segment_disc_cmp_exact((a.x, a.y), (b.x, b.y), (c.x, c.y), r)
}

/// How the distance from the point `p` to the point `c` compares with `r` (`r ≥ 0`), exactly.
///
/// `|p − c|²` takes four roundings and `r²` one, so each is within `2ε` (relative) of its exact
/// value unless something underflows; a relative filter of `8ε` then decides, and the rest (and
/// anything below `1e-280`) is compared exactly.
#[inline]
pub fn point_disc_cmp(p: Vec2, c: Vec2, r: Real) -> Ordering {
    const REL: Real = 8.0 * Real::EPSILON;
    const TINY: Real = 1e-280;
    let d2 = (p - c).norm_squared();
    let r2 = r * r;
    if r2 > TINY && d2 > TINY {
        if d2 > r2 * (1.0 + REL) {
            return Ordering::Greater;
        }
        if d2 < r2 * (1.0 - REL) {
            return Ordering::Less;
        }
    }
    segment_disc_cmp_exact((p.x, p.y), (p.x, p.y), (c.x, c.y), r)
}

/// Whether the closed segment `a b` meets the closed disc of centre `c` and radius `r` (exact).
#[inline]
pub fn intersect_segment_circle(a: Vec2, b: Vec2, c: Vec2, r: Real) -> bool {
    segment_disc_cmp(a, b, c, r) != Ordering::Greater
}

/// Whether the closed segment `a b` meets the open disc of centre `c` and radius `r` (exact).
#[inline]
pub fn interior_meets_segment_circle(a: Vec2, b: Vec2, c: Vec2, r: Real) -> bool {
    segment_disc_cmp(a, b, c, r) == Ordering::Less
}

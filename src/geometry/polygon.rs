//! Point/polygon and segment/polygon predicates for simple polygons, convex or not, either winding.
//!
//! Exact: every decision is the sign of an [`orient`] test (no intersection point is ever
//! constructed), so a point on an edge is on it, and a segment that grazes a vertex grazes it.

use super::segment::{contains_segment_point, intersect_segment_segment, orient, orient_sign};
use crate::math::Vec2;

/// Where a point lies with respect to a closed polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Location {
    /// Outside the closed polygon.
    Outside,
    /// On an edge or a vertex.
    Boundary,
    /// Strictly inside.
    Inside,
}

/// Where `p` lies with respect to the polygon `poly` (exact; crossing number with orientation
/// tests instead of constructed crossings).
pub fn locate_polygon_point(poly: &[Vec2], p: Vec2) -> Location {
    let n = poly.len();
    let mut inside = false;
    let mut j = n - 1;
    for i in 0..n {
        let (a, b) = (poly[j], poly[i]);
        if (b.y > p.y) != (a.y > p.y) {
            // The edge spans `p`'s horizontal line (half-open in y): `p` is on it, or left of
            // where it crosses (the ray to +x crosses it), or right of it.
            let o = orient(a, b, p);
            if o == 0.0 {
                return Location::Boundary;
            }
            if (o > 0.0) == (b.y > a.y) {
                inside = !inside;
            }
        } else if (a.y == p.y || b.y == p.y) && contains_segment_point(a, b, p) {
            // A horizontal edge, or an end point on `p`'s line: the only other ways to hold `p`.
            return Location::Boundary;
        }
        j = i;
    }
    if inside {
        Location::Inside
    } else {
        Location::Outside
    }
}

/// Whether `p` lies in the closed polygon `poly` (boundary included).
pub fn contains_polygon_point(poly: &[Vec2], p: Vec2) -> bool {
    locate_polygon_point(poly, p) != Location::Outside
}

/// Whether the closed segment `a b` meets the closed polygon `poly`.
pub fn intersect_segment_polygon(a: Vec2, b: Vec2, poly: &[Vec2]) -> bool {
    let n = poly.len();
    let mut j = n - 1;
    for i in 0..n {
        if intersect_segment_segment(a, b, poly[j], poly[i]) {
            return true;
        }
        j = i;
    }
    // No boundary crossing: the segment is wholly inside or wholly outside.
    contains_polygon_point(poly, a)
}

/// Whether `p` lies strictly inside the polygon (not on its boundary).
pub fn strictly_contains_polygon_point(poly: &[Vec2], p: Vec2) -> bool {
    locate_polygon_point(poly, p) == Location::Inside
}

/// The polygon's winding, exactly: 1 counter-clockwise, -1 clockwise (0 only for a degenerate
/// polygon). The turn at the lowest-leftmost vertex has the polygon's orientation.
pub fn winding(poly: &[Vec2]) -> i8 {
    let n = poly.len();
    let k = (0..n).min_by(|&i, &j| poly[i].x.total_cmp(&poly[j].x).then(poly[i].y.total_cmp(&poly[j].y))).unwrap_or(0);
    orient_sign(poly[(k + n - 1) % n], poly[k], poly[(k + 1) % n])
}

/// Whether the direction from vertex `v` (edges `p → v → q`, polygon winding `w`) toward `t`
/// points strictly into the polygon's interior.
#[inline]
fn enters_at_vertex(p: Vec2, v: Vec2, q: Vec2, t: Vec2, w: i8) -> bool {
    // orient(p, v, t) has the sign of (v − p) × (t − v): the direction against the incoming edge.
    let left_in = w * orient_sign(p, v, t) > 0;
    let left_out = w * orient_sign(v, q, t) > 0;
    match w * orient_sign(p, v, q) {
        1 => left_in && left_out,
        -1 => left_in || left_out,
        _ => left_in,
    }
}

/// Whether the closed segment `a b` meets the polygon's interior (touching the boundary allowed),
/// exactly. A proper crossing of an edge meets it. Otherwise the boundary meets the segment only
/// at *contact points* (a vertex on the segment, or an end of the segment on an edge) and along
/// collinear overlaps; every piece of the segment between them starts at a contact point, and it
/// lies in the interior exactly when its direction there points into the interior (the wedge
/// between the vertex's edges, or the inner side of the edge). With no contact at all, the
/// segment is wholly inside or wholly outside.
pub fn interior_meets_segment_polygon(poly: &[Vec2], a: Vec2, b: Vec2) -> bool {
    if a == b {
        return strictly_contains_polygon_point(poly, a);
    }
    let n = poly.len();
    let w = winding(poly);
    let mut contact = false;
    for i in 0..n {
        let (c, e, f) = (poly[i], poly[(i + 1) % n], poly[(i + 2) % n]);
        let (d1, d2) = (orient_sign(c, e, a), orient_sign(c, e, b));
        let (d3, d4) = (orient_sign(a, b, c), orient_sign(a, b, e));
        if d1 * d2 < 0 && d3 * d4 < 0 {
            return true;
        }
        // An end of the segment inside the edge `c e` (not at a vertex): the segment leaves it
        // toward the other end, into the interior when that end is on the inner side.
        if d1 == 0 && a != c && a != e && contains_segment_point(c, e, a) {
            contact = true;
            if w * d2 > 0 {
                return true;
            }
        }
        if d2 == 0 && b != c && b != e && contains_segment_point(c, e, b) {
            contact = true;
            if w * d1 > 0 {
                return true;
            }
        }
        // The vertex `e` on the segment: the segment leaves it toward either end.
        if d4 == 0 && contains_segment_point(a, b, e) {
            contact = true;
            if (e != a && enters_at_vertex(c, e, f, a, w)) || (e != b && enters_at_vertex(c, e, f, b, w)) {
                return true;
            }
        }
    }
    !contact && strictly_contains_polygon_point(poly, a)
}

/// Whether the closed polygons `p` and `q` share a point.
pub fn intersect_polygon_polygon(p: &[Vec2], q: &[Vec2]) -> bool {
    let n = p.len();
    let mut j = n - 1;
    for i in 0..n {
        let m = q.len();
        let mut l = m - 1;
        for k in 0..m {
            if intersect_segment_segment(p[j], p[i], q[l], q[k]) {
                return true;
            }
            l = k;
        }
        j = i;
    }
    contains_polygon_point(q, p[0]) || contains_polygon_point(p, q[0])
}

/// Whether the polygon is convex (either winding; collinear vertices allowed).
pub fn is_convex(poly: &[Vec2]) -> bool {
    let n = poly.len();
    let (mut pos, mut neg) = (false, false);
    for i in 0..n {
        let c = super::segment::orient(poly[i], poly[(i + 1) % n], poly[(i + 2) % n]);
        pos |= c > 0.0;
        neg |= c < 0.0;
    }
    !(pos && neg)
}

/// Whether the polygon is simple: no two non-adjacent edges meet, and adjacent edges meet only at
/// their shared vertex.
pub fn is_simple(poly: &[Vec2]) -> bool {
    let n = poly.len();
    if n < 3 {
        return false;
    }
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if a == b {
            return false;
        }
        for j in i + 1..n {
            let (c, d) = (poly[j], poly[(j + 1) % n]);
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if adjacent {
                // Adjacent edges must not fold back over each other.
                let shared = if j == i + 1 { b } else { a };
                let other_i = if j == i + 1 { a } else { b };
                let other_j = if j == i + 1 { d } else { c };
                if super::segment::orient(other_i, shared, other_j) == 0.0
                    && (other_i - shared).dot(&(other_j - shared)) > 0.0
                {
                    return false;
                }
            } else if intersect_segment_segment(a, b, c, d) {
                return false;
            }
        }
    }
    true
}

/// Twice the signed area (shoelace; > 0 for counter-clockwise).
pub fn signed_area2(poly: &[Vec2]) -> f64 {
    let n = poly.len();
    (0..n).map(|i| poly[i].perp(&poly[(i + 1) % n])).sum()
}

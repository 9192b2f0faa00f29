//! Point/polygon and segment/polygon predicates for simple polygons, convex or not, either winding.

use super::segment::{contains_segment_point, intersect_segment_segment};
use crate::math::Vec2;

/// Whether `p` lies in the closed polygon `poly` (boundary included).
pub fn contains_polygon_point(poly: &[Vec2], p: Vec2) -> bool {
    let n = poly.len();
    let mut inside = false;
    let mut j = n - 1;
    for i in 0..n {
        let (a, b) = (poly[j], poly[i]);
        if contains_segment_point(a, b, p) {
            return true;
        }
        if (b.y > p.y) != (a.y > p.y) {
            let x = b.x + (p.y - b.y) * (a.x - b.x) / (a.y - b.y);
            if p.x < x {
                inside = !inside;
            }
        }
        j = i;
    }
    inside
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
    let n = poly.len();
    (0..n).all(|i| !contains_segment_point(poly[i], poly[(i + 1) % n], p)) && contains_polygon_point(poly, p)
}

/// Whether the segment `a b` meets the polygon's interior (touching the boundary allowed): the
/// segment is cut where it meets the boundary, and each piece's midpoint is tested.
pub fn interior_meets_segment_polygon(poly: &[Vec2], a: Vec2, b: Vec2) -> bool {
    let n = poly.len();
    let d = b - a;
    let mut ts = vec![0.0, 1.0];
    for i in 0..n {
        let (c, e) = (poly[i], poly[(i + 1) % n]);
        if !intersect_segment_segment(a, b, c, e) {
            continue;
        }
        let s = e - c;
        let den = d.cross(s);
        if den != 0.0 {
            ts.push(((c - a).cross(s) / den).clamp(0.0, 1.0));
        } else {
            // Collinear overlap: cut at the edge's end points, projected on the segment.
            let l2 = d.norm2();
            for p in [c, e] {
                ts.push(((p - a).dot(d) / l2).clamp(0.0, 1.0));
            }
        }
    }
    ts.sort_by(f64::total_cmp);
    ts.windows(2).any(|w| w[1] > w[0] && strictly_contains_polygon_point(poly, a + d.scale(0.5 * (w[0] + w[1]))))
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
                    && (other_i - shared).dot(other_j - shared) > 0.0
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
    (0..n).map(|i| poly[i].cross(poly[(i + 1) % n])).sum()
}

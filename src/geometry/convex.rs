//! Convex polygons in floating point: the constructions (clipping, centroid, a regular hexagon) and
//! the tolerant tests (containment, shared edges) that a cell decomposition needs.
//!
//! Unlike [`polygon`](super::polygon)'s exact predicates, these build new points, so their results
//! carry rounding; the tests allow for it with small tolerances (stated on each function). Rings
//! are slices of vertices, the last joined to the first; "counter-clockwise" is the orientation of
//! positive [`signed_area2`](super::polygon::signed_area2).

use crate::math::{Real, Vec2};

/// The corners of the pointy-top regular hexagon of circumradius `s` centred at `c` (the first at
/// 30°), counter-clockwise.
pub fn hexagon(c: Vec2, s: Real) -> [Vec2; 6] {
    let mut out = [Vec2::new(0.0, 0.0); 6];
    for (i, o) in out.iter_mut().enumerate() {
        let a = (30.0 + 60.0 * i as Real).to_radians();
        *o = Vec2::new(c.x + s * libm::cos(a), c.y + s * libm::sin(a));
    }
    out
}

/// Clip the convex polygon `subject` to the convex counter-clockwise polygon `clip`
/// (Sutherland–Hodgman). The result may be empty; consecutive vertices closer than `1e-12` times
/// the largest coordinate (at least 1) are merged, since clipping at a vertex repeats it.
pub fn clip_convex(subject: &[Vec2], clip: &[Vec2]) -> Vec<Vec2> {
    let mut out: Vec<Vec2> = subject.to_vec();
    let n = clip.len();
    for i in 0..n {
        if out.is_empty() {
            break;
        }
        let (a, b) = (clip[i], clip[(i + 1) % n]);
        let inside = |p: Vec2| (b - a).perp(&(p - a)) >= 0.0;
        let input = std::mem::take(&mut out);
        let m = input.len();
        for j in 0..m {
            let (p, q) = (input[j], input[(j + 1) % m]);
            let (pi, qi) = (inside(p), inside(q));
            if pi {
                out.push(p);
            }
            if pi != qi {
                // The edge p→q crosses the clip line a→b.
                let (dp, dq) = ((b - a).perp(&(p - a)), (b - a).perp(&(q - a)));
                let t = dp / (dp - dq);
                out.push(p + (q - p).scale(t));
            }
        }
    }
    dedup_ring(&mut out);
    out
}

/// Drop consecutive vertices closer than a tiny tolerance (clipping at a vertex repeats it).
fn dedup_ring(ring: &mut Vec<Vec2>) {
    let scale = ring.iter().fold(0.0, |m: Real, p| m.max(p.x.abs()).max(p.y.abs())).max(1.0);
    let eps = 1e-12 * scale;
    let mut i = 0;
    while ring.len() > 1 && i < ring.len() {
        let j = (i + 1) % ring.len();
        if (ring[i] - ring[j]).norm() <= eps {
            ring.remove(j);
        } else {
            i += 1;
        }
    }
}

/// Whether the convex counter-clockwise polygon `poly` contains `p`, boundary included: no edge
/// has `p` on its right by more than `1e-12` (the cross product of the edge and `p`'s offset).
pub fn convex_contains(poly: &[Vec2], p: Vec2) -> bool {
    let n = poly.len();
    (0..n).all(|i| (poly[(i + 1) % n] - poly[i]).perp(&(p - poly[i])) >= -1e-12)
}

/// Whether the convex counter-clockwise polygon `poly` holds `p` strictly inside: every edge has
/// `p` on its left by more than `1e-12` (the same cross product as [`convex_contains`]).
pub fn convex_strictly_contains(poly: &[Vec2], p: Vec2) -> bool {
    let n = poly.len();
    (0..n).all(|i| (poly[(i + 1) % n] - poly[i]).perp(&(p - poly[i])) > 1e-12)
}

/// The centroid of the area of a ring (non-zero area; either winding).
pub fn centroid(ring: &[Vec2]) -> Vec2 {
    let n = ring.len();
    let (mut cx, mut cy, mut a) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (p, q) = (ring[i], ring[(i + 1) % n]);
        let w = p.perp(&q);
        a += w;
        cx += (p.x + q.x) * w;
        cy += (p.y + q.y) * w;
    }
    Vec2::new(cx / (3.0 * a), cy / (3.0 * a))
}

/// Whether two polygons share a piece of boundary of positive length: an edge of each, on one line,
/// overlapping. "On one line" allows `1e-9` times the edge's length (at least `1e-3`) of distance,
/// and the overlap must be a thousand times that.
pub fn share_edge(a: &[Vec2], b: &[Vec2]) -> bool {
    let (n, m) = (a.len(), b.len());
    for i in 0..n {
        let (p, q) = (a[i], a[(i + 1) % n]);
        let d = q - p;
        let len = d.norm();
        if len == 0.0 {
            continue;
        }
        let eps = 1e-9 * len.max(1e-3);
        for j in 0..m {
            let (r, s) = (b[j], b[(j + 1) % m]);
            // Both ends of r s on the line p q?
            if (d.perp(&(r - p)) / len).abs() > eps || (d.perp(&(s - p)) / len).abs() > eps {
                continue;
            }
            let (t0, t1) = (d.dot(&(r - p)) / len, d.dot(&(s - p)) / len);
            let (lo, hi) = (t0.min(t1).max(0.0), t0.max(t1).min(len));
            if hi - lo > 1e3 * eps {
                return true;
            }
        }
    }
    false
}

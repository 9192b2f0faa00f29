//! An exhaustive reference for the spatial checker's GJK (tests/common/spatial.rs), sharing no code
//! with it: the distance between the convex hulls of two point sets from every feature pair the
//! points can form. Hulls meet when a point of one lies in a tetrahedron of the other's points, or
//! a segment of one crosses a triangle of the other's; else their distance is the least distance
//! between a point and a triangle, or two segments (every facet, edge and vertex of a hull is one
//! of those, and every such feature lies in the hull). Polynomial of degree four in the points:
//! for small sets and a few pairs.

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn at(a: V3, d: V3, t: f64) -> V3 {
    [a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]]
}

fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// The signed volume (×6) of `a, b, c, d`.
fn orient(a: V3, b: V3, c: V3, d: V3) -> f64 {
    dot(sub(b, a), cross(sub(c, a), sub(d, a)))
}

/// The distance from `p` to the segment `a b`.
fn point_segment(p: V3, a: V3, b: V3) -> f64 {
    let e = sub(b, a);
    let ee = dot(e, e);
    let t = if ee > 0.0 { (dot(sub(p, a), e) / ee).clamp(0.0, 1.0) } else { 0.0 };
    norm(sub(p, at(a, e, t)))
}

/// The distance from `p` to the triangle `a b c`: to its plane when `p` projects inside it, else
/// to its nearest edge.
fn point_triangle(p: V3, a: V3, b: V3, c: V3) -> f64 {
    let n = cross(sub(b, a), sub(c, a));
    let nn = dot(n, n);
    let edges = point_segment(p, a, b).min(point_segment(p, b, c)).min(point_segment(p, c, a));
    if nn == 0.0 {
        return edges;
    }
    let inside = [(a, b), (b, c), (c, a)].iter().all(|(u, v)| dot(cross(sub(*v, *u), sub(p, *u)), n) >= 0.0);
    if inside {
        dot(sub(p, a), n).abs() / nn.sqrt()
    } else {
        edges
    }
}

/// The distance between segments `p q` and `r s`: where the infinite lines are nearest, when that
/// is inside both, else from an end to the other segment.
fn segment_segment(p: V3, q: V3, r: V3, s: V3) -> f64 {
    let ends =
        point_segment(p, r, s).min(point_segment(q, r, s)).min(point_segment(r, p, q)).min(point_segment(s, p, q));
    let (d1, d2, w) = (sub(q, p), sub(s, r), sub(p, r));
    let (a, b, c, d, e) = (dot(d1, d1), dot(d1, d2), dot(d2, d2), dot(d1, w), dot(d2, w));
    let den = a * c - b * b;
    if den <= 1e-15 * a * c {
        return ends;
    }
    let (t, u) = ((b * e - c * d) / den, (a * e - b * d) / den);
    if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
        ends.min(norm(sub(at(p, d1, t), at(r, d2, u))))
    } else {
        ends
    }
}

/// Whether segment `p q` properly crosses triangle `a b c` (its ends strictly on either side).
fn crosses(p: V3, q: V3, a: V3, b: V3, c: V3) -> bool {
    let (sp, sq) = (orient(a, b, c, p), orient(a, b, c, q));
    if sp * sq >= 0.0 {
        return false;
    }
    let s = [orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a)];
    s.iter().all(|x| *x >= 0.0) || s.iter().all(|x| *x <= 0.0)
}

/// Whether `p` lies in the tetrahedron `a b c d` (closed).
fn in_tetrahedron(p: V3, a: V3, b: V3, c: V3, d: V3) -> bool {
    let v = orient(a, b, c, d);
    v != 0.0
        && [orient(p, b, c, d), orient(a, p, c, d), orient(a, b, p, d), orient(a, b, c, p)].iter().all(|x| x * v >= 0.0)
}

fn triples(n: usize) -> impl Iterator<Item = (usize, usize, usize)> {
    (0..n).flat_map(move |i| (i + 1..n).flat_map(move |j| (j + 1..n).map(move |k| (i, j, k))))
}

fn pairs(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n).flat_map(move |i| (i + 1..n).map(move |j| (i, j)))
}

/// Whether a point of `x` lies in a tetrahedron of `y`'s points, or a segment of `x` crosses a
/// triangle of `y`'s.
fn reaches_into(x: &[V3], y: &[V3]) -> bool {
    let quads = triples(y.len()).flat_map(|(i, j, k)| (k + 1..y.len()).map(move |l| (i, j, k, l)));
    for (i, j, k, l) in quads {
        if x.iter().any(|p| in_tetrahedron(*p, y[i], y[j], y[k], y[l])) {
            return true;
        }
    }
    triples(y.len()).any(|(i, j, k)| pairs(x.len()).any(|(m, n)| crosses(x[m], x[n], y[i], y[j], y[k])))
}

/// The distance between the convex hulls of `a` and `b` (0 when they meet).
pub fn distance(a: &[V3], b: &[V3]) -> f64 {
    if reaches_into(a, b) || reaches_into(b, a) {
        return 0.0;
    }
    let mut best = f64::INFINITY;
    for (x, y) in [(a, b), (b, a)] {
        for (i, j, k) in triples(y.len()) {
            for p in x {
                best = best.min(point_triangle(*p, y[i], y[j], y[k]));
            }
        }
    }
    for (i, j) in pairs(a.len()) {
        for (k, l) in pairs(b.len()) {
            best = best.min(segment_segment(a[i], a[j], b[k], b[l]));
        }
    }
    best
}

//! The independent checker's spatial arm (report 001's Puma 560 in 3-D), written apart from the
//! crate's geometry: forward kinematics with plain 4×4 matrices and `f64::sin_cos` (not nalgebra's
//! isometries, not the crate's `Chain`), and the distance between two convex sets by GJK over the
//! support function of their points, `max_i p_i·d` (a box is its eight corners, a hull its points:
//! no hull is built; not parry). Two sets meet when their distance is at most [`TOUCH`]: obstacles
//! are closed, touching is a collision.
//!
//! The rules, from docs/scenario-format.md: every joint within its limits; every part (the hull,
//! each box) of a link outside `exempt` against every obstacle of `obstacles3d`; every part of
//! link `i` against every part of link `j` (`i < j`) unless `[i, j]` is in `ignore`; never two
//! parts of one link; a link with neither hull nor box is never tested. The bounds are not a rule
//! (for a spatial arm they are only the view's extent). Link `k`'s frame is link `k − 1`'s times
//! `Rz(theta + q_k)·Tz(d)·Tx(a)·Rx(alpha)`, link 0's the base pose `T·Rz(rz)·Ry(ry)·Rx(rx)`.

use planarium::scenario::{RobotSpec, Scenario, SolidShape, SpatialArmSpec};

/// A point or vector in 3-D.
pub type V3 = [f64; 3];
/// A homogeneous transform, row-major.
pub type M4 = [[f64; 4]; 4];

/// Two sets this close or closer meet (metres).
pub const TOUCH: f64 = 1e-9;

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn neg(a: V3) -> V3 {
    [-a[0], -a[1], -a[2]]
}

fn identity() -> M4 {
    let mut m = [[0.0; 4]; 4];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    m
}

/// The product `a·b`.
pub fn mul(a: &M4, b: &M4) -> M4 {
    let mut c = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            c[i][j] = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

/// A rotation by `t` about axis 0 (x), 1 (y) or 2 (z).
pub fn rot(axis: usize, t: f64) -> M4 {
    let (s, c) = t.sin_cos();
    let (i, j) = [(1, 2), (2, 0), (0, 1)][axis];
    let mut m = identity();
    m[i][i] = c;
    m[i][j] = -s;
    m[j][i] = s;
    m[j][j] = c;
    m
}

/// A translation.
pub fn trans(v: V3) -> M4 {
    let mut m = identity();
    for k in 0..3 {
        m[k][3] = v[k];
    }
    m
}

/// `m` applied to the point `p`.
pub fn apply(m: &M4, p: V3) -> V3 {
    [0, 1, 2].map(|i| m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3])
}

/// The spatial-arm block of `sc` (panics for another robot).
pub fn spec(sc: &Scenario) -> &SpatialArmSpec {
    let RobotSpec::SpatialArm(s) = &sc.robot else { panic!("{} is not a spatial arm", sc.name) };
    s
}

/// A uniform state within the joint limits.
pub fn random_state(sc: &Scenario, rng: &mut planarium::rng::Rng) -> Vec<f64> {
    spec(sc).joints.iter().map(|j| rng.uniform(j.limits[0], j.limits[1])).collect()
}

/// The state `t` of the way from `a` to `b` in joint space; `b` itself at `t = 1` (where
/// `a + (b − a)` can round a few ulps past `b`, and so past a joint limit `b` sits on).
pub fn lerp(a: &[f64], b: &[f64], t: f64) -> Vec<f64> {
    if t == 1.0 {
        return b.to_vec();
    }
    a.iter().zip(b).map(|(x, y)| x + t * (y - x)).collect()
}

/// Every link's frame in the world at `q`, link 0 (the base) first.
pub fn frames(arm: &SpatialArmSpec, q: &[f64]) -> Vec<M4> {
    let [rx, ry, rz] = arm.base.rotation;
    let mut f = mul(&mul(&mul(&trans(arm.base.translation), &rot(2, rz)), &rot(1, ry)), &rot(0, rx));
    let mut out = vec![f];
    for (j, qk) in arm.joints.iter().zip(q) {
        let step =
            mul(&mul(&mul(&rot(2, j.theta + qk), &trans([0.0, 0.0, j.d])), &trans([j.a, 0.0, 0.0])), &rot(0, j.alpha));
        f = mul(&f, &step);
        out.push(f);
    }
    out
}

/// The tool centre point in the world at `q`.
pub fn tool_point(arm: &SpatialArmSpec, q: &[f64]) -> V3 {
    apply(frames(arm, q).last().unwrap(), arm.tool)
}

/// The eight corners of the axis-aligned box of centre `c` and full size `s`.
pub fn corners(c: V3, s: V3) -> Vec<V3> {
    (0..8).map(|k| [0, 1, 2].map(|i| c[i] + if k >> i & 1 == 1 { 0.5 } else { -0.5 } * s[i])).collect()
}

/// The support point of `pts` in direction `d`: the one with the largest `p·d`.
fn support(pts: &[V3], d: V3) -> V3 {
    let mut best = pts[0];
    let mut m = dot(best, d);
    for p in &pts[1..] {
        let x = dot(*p, d);
        if x > m {
            (m, best) = (x, *p);
        }
    }
    best
}

fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The point nearest the origin of the simplex `s` (1 to 4 points) when it lies strictly inside
/// it (every barycentric weight positive; the faces are other subsets), and the simplex is not
/// degenerate. Weights come from cross products and signed volumes, not normal equations (whose
/// squared condition number called flat tetrahedra holding the origin).
fn interior_closest(s: &[V3]) -> Option<V3> {
    let scale = || s.iter().flat_map(|p| s.iter().map(move |q| dot(sub(*p, *q), sub(*p, *q)))).fold(0.0, f64::max);
    match *s {
        [p] => Some(p),
        [a, b] => {
            let e = sub(b, a);
            let ee = dot(e, e);
            let t = -dot(a, e) / ee;
            (ee > 0.0 && t > 0.0 && t < 1.0).then(|| [0, 1, 2].map(|k| a[k] + t * e[k]))
        }
        [a, b, c] => {
            let n = cross(sub(b, a), sub(c, a));
            let nn = dot(n, n);
            if nn <= 1e-24 * scale() * scale() {
                return None;
            }
            let p = n.map(|x| x * dot(n, a) / nn);
            let w = [
                dot(n, cross(sub(b, p), sub(c, p))),
                dot(n, cross(sub(c, p), sub(a, p))),
                dot(n, cross(sub(a, p), sub(b, p))),
            ];
            w.iter().all(|x| *x > 0.0).then_some(p)
        }
        [a, b, c, d] => {
            let (ab, ac, ad) = (sub(b, a), sub(c, a), sub(d, a));
            let v = dot(ab, cross(ac, ad));
            if v.abs() <= 1e-18 * scale() * scale().sqrt() {
                return None;
            }
            let w =
                [dot(b, cross(c, d)), -dot(a, cross(ac, ad)), dot(ab, cross(neg(a), ad)), dot(ab, cross(ac, neg(a)))];
            w.iter().all(|x| *x / v > 0.0).then_some([0.0; 3])
        }
        _ => unreachable!("a simplex in 3-D has 1 to 4 points"),
    }
}

/// The subsets of a simplex's (up to) four points as bit masks, the smallest first.
const SUBSETS: [u8; 15] = [1, 2, 4, 8, 3, 5, 6, 9, 10, 12, 7, 11, 13, 14, 15];

/// A simplex: up to four points, on the stack.
#[derive(Clone, Copy)]
struct Simplex {
    p: [V3; 4],
    n: usize,
}

impl Simplex {
    fn points(&self) -> &[V3] {
        &self.p[..self.n]
    }

    fn subset(&self, mask: u8) -> Simplex {
        let mut out = Simplex { p: [[0.0; 3]; 4], n: 0 };
        for i in (0..self.n).filter(|i| mask >> i & 1 == 1) {
            out.p[out.n] = self.p[i];
            out.n += 1;
        }
        out
    }
}

/// The point of the simplex `s` nearest the origin and the smallest subset of `s` whose hull
/// holds it: the interior of every subset that holds the newest point (the last: the nearest
/// point of the others was the last answer, which the newest point improves on) is tried, the
/// smallest first.
fn closest_on_simplex(s: &Simplex) -> (V3, Simplex) {
    let mut best: Option<(f64, V3, Simplex)> = None;
    let newest = 1u8 << (s.n - 1);
    for mask in SUBSETS.into_iter().filter(|m| (*m as usize) < 1 << s.n && m & newest != 0) {
        let sub = s.subset(mask);
        if let Some(p) = interior_closest(sub.points()) {
            let d = dot(p, p);
            if best.as_ref().is_none_or(|(b, _, _)| d < *b) {
                best = Some((d, p, sub));
            }
        }
    }
    let (_, p, sub) = best.expect("a vertex is always a candidate");
    (p, sub)
}

/// The distance between the convex hulls of `a` and `b` (0 when they meet), by GJK on the
/// Minkowski difference `a − b`: `|v|` bounds it from above, `v·w/|v|` from below, and the loop
/// ends when the two are within 1e-13 m (or the simplex holds the origin). It starts from the
/// point of `a − b` farthest along the direction from `a`'s centroid to `b`'s (where the two
/// sets face each other), which saves iterations, not correctness.
pub fn distance(a: &[V3], b: &[V3]) -> f64 {
    let centroid = |s: &[V3]| [0, 1, 2].map(|k| s.iter().map(|p| p[k]).sum::<f64>() / s.len() as f64);
    let d = sub(centroid(b), centroid(a));
    let start = if dot(d, d) > 0.0 { sub(support(a, d), support(b, neg(d))) } else { sub(a[0], b[0]) };
    let mut simplex = Simplex { p: [start, [0.0; 3], [0.0; 3], [0.0; 3]], n: 1 };
    let mut v = simplex.p[0];
    for _ in 0..200 {
        let vv = dot(v, v);
        let vn = vv.sqrt();
        if vn <= 1e-15 {
            return 0.0;
        }
        let w = sub(support(a, neg(v)), support(b, v));
        if vn - dot(v, w) / vn <= 1e-13 || simplex.points().contains(&w) {
            return vn;
        }
        simplex.p[simplex.n] = w;
        simplex.n += 1;
        let (p, kept) = closest_on_simplex(&simplex);
        if kept.n == 4 {
            return 0.0;
        }
        if dot(p, p) >= vv {
            return vn;
        }
        (v, simplex) = (p, kept);
    }
    dot(v, v).sqrt()
}

/// `min_d h_a(d) + h_b(−d)` (`h` the support function) over the directions that can be normal to
/// a facet of the Minkowski difference `a − b`: the normal of every triple of points of either
/// set, and every difference of two points of `a` crossed with every difference of two points of
/// `b`, both signs. When the sets meet, this is the penetration depth (the shortest translation
/// that parts them), exactly but for rounding: the depth is reached at a facet normal, and every
/// direction bounds it from above. When they are apart, it is minus a separating plane's gap (a
/// lower bound of the distance). Brute force, cubic in the points: for reports and self-tests.
pub fn overlap(a: &[V3], b: &[V3]) -> f64 {
    let h = |d: V3| dot(support(a, d), d) - dot(support(b, neg(d)), d);
    let mut best = f64::INFINITY;
    let mut try_dir = |d: V3| {
        let n = dot(d, d).sqrt();
        if n > 1e-12 {
            let u = d.map(|x| x / n);
            best = best.min(h(u)).min(h(neg(u)));
        }
    };
    for set in [a, b] {
        for i in 0..set.len() {
            for j in i + 1..set.len() {
                for k in j + 1..set.len() {
                    try_dir(cross(sub(set[j], set[i]), sub(set[k], set[i])));
                }
            }
        }
    }
    let edges = |set: &[V3]| -> Vec<V3> {
        (0..set.len()).flat_map(|i| (i + 1..set.len()).map(move |j| (i, j))).map(|(i, j)| sub(set[j], set[i])).collect()
    };
    let eb = edges(b);
    for ea in edges(a) {
        for e in &eb {
            try_dir(cross(ea, *e));
        }
    }
    best
}

/// One convex part of the arm: the link it moves with, its name, its points in the link's frame.
pub struct Part {
    pub link: usize,
    pub name: String,
    pub local: Vec<V3>,
}

/// A pair the rules test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pair {
    /// Part `part` against obstacle `obstacle` of `obstacles3d`.
    Scene { part: usize, obstacle: usize },
    /// Parts `a` and `b` of two different links.
    Links { a: usize, b: usize },
}

/// The checker for one spatial-arm scenario.
pub struct Arm<'a> {
    pub sc: &'a Scenario,
    pub spec: &'a SpatialArmSpec,
    pub parts: Vec<Part>,
    pub obstacles: Vec<Vec<V3>>,
    /// Every pair tested, the scene's first.
    pub pairs: Vec<Pair>,
}

impl<'a> Arm<'a> {
    /// The checker of `sc`, or `None` when its robot is not a spatial arm.
    pub fn new(sc: &'a Scenario) -> Option<Arm<'a>> {
        let RobotSpec::SpatialArm(spec) = &sc.robot else { return None };
        let mut parts = Vec::new();
        for (k, l) in spec.links.iter().enumerate() {
            if !l.hull.is_empty() {
                parts.push(Part { link: k, name: l.name.clone(), local: l.hull.clone() });
            }
            for (i, b) in l.boxes.iter().enumerate() {
                let name = if b.name.is_empty() {
                    format!("{}'s box {i}", l.name)
                } else {
                    format!("{}'s {}", l.name, b.name)
                };
                parts.push(Part { link: k, name, local: corners(b.center, b.size) });
            }
        }
        let obstacles: Vec<Vec<V3>> = sc
            .obstacles3d
            .iter()
            .map(|o| match &o.shape {
                SolidShape::Box { center, size } => corners(*center, *size),
                SolidShape::Hull(pts) => pts.clone(),
            })
            .collect();
        let mut pairs = Vec::new();
        for (part, p) in parts.iter().enumerate() {
            if !spec.exempt.contains(&p.link) {
                pairs.extend((0..obstacles.len()).map(|obstacle| Pair::Scene { part, obstacle }));
            }
        }
        for (a, pa) in parts.iter().enumerate() {
            for (b, pb) in parts.iter().enumerate() {
                if pa.link < pb.link && !spec.ignore.contains(&[pa.link, pb.link]) {
                    pairs.push(Pair::Links { a, b });
                }
            }
        }
        Some(Arm { sc, spec, parts, obstacles, pairs })
    }

    /// Every part's points in the world at `q`.
    pub fn world(&self, q: &[f64]) -> Vec<Vec<V3>> {
        let f = frames(self.spec, q);
        self.parts.iter().map(|p| p.local.iter().map(|x| apply(&f[p.link], *x)).collect()).collect()
    }

    /// The two point sets of `pair` (parts placed as in `world`).
    pub fn sets<'w>(&'w self, world: &'w [Vec<V3>], pair: Pair) -> (&'w [V3], &'w [V3]) {
        match pair {
            Pair::Scene { part, obstacle } => (&world[part], &self.obstacles[obstacle]),
            Pair::Links { a, b } => (&world[a], &world[b]),
        }
    }

    /// What meets what, in words: "link6's bar meets obstacles3d[3] (lintel)", "link2 meets link5".
    pub fn describe(&self, pair: Pair) -> String {
        match pair {
            Pair::Scene { part, obstacle } => {
                let name = &self.sc.obstacles3d[obstacle].name;
                let named = if name.is_empty() { String::new() } else { format!(" ({name})") };
                format!("{} meets obstacles3d[{obstacle}]{named}", self.parts[part].name)
            }
            Pair::Links { a, b } => format!("{} meets {}", self.parts[a].name, self.parts[b].name),
        }
    }

    /// The joint outside its limits, if any.
    pub fn limit_problem(&self, q: &[f64]) -> Option<String> {
        let (k, [lo, hi]) = self
            .spec
            .joints
            .iter()
            .map(|j| j.limits)
            .enumerate()
            .zip(q)
            .find(|((_, [lo, hi]), x)| *x < lo || *x > hi)?
            .0;
        Some(format!("joint {k} outside [{lo}, {hi}]"))
    }

    /// Every tested pair that meets at `q` (all of them, or only the first), with its distance
    /// (at most [`TOUCH`]). Boxes around the world points that are more than `TOUCH` apart on an
    /// axis are apart (a lower bound of the distance), and skip GJK.
    pub fn contacts(&self, q: &[f64], all: bool) -> Vec<(Pair, f64)> {
        let world = self.world(q);
        let bound = |pts: &[V3]| {
            let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
            for p in pts {
                for k in 0..3 {
                    b[0][k] = b[0][k].min(p[k]);
                    b[1][k] = b[1][k].max(p[k]);
                }
            }
            b
        };
        let parts: Vec<[V3; 2]> = world.iter().map(|p| bound(p)).collect();
        let obstacles: Vec<[V3; 2]> = self.obstacles.iter().map(|p| bound(p)).collect();
        let mut out = Vec::new();
        for &pair in &self.pairs {
            let (ba, bb) = match pair {
                Pair::Scene { part, obstacle } => (parts[part], obstacles[obstacle]),
                Pair::Links { a, b } => (parts[a], parts[b]),
            };
            if (0..3).any(|k| ba[0][k] - bb[1][k] > TOUCH || bb[0][k] - ba[1][k] > TOUCH) {
                continue;
            }
            let (a, b) = self.sets(&world, pair);
            let d = distance(a, b);
            if d <= TOUCH {
                out.push((pair, d));
                if !all {
                    break;
                }
            }
        }
        out
    }

    /// The smallest signed clearance over every tested pair at `q`, and that pair: a pair's
    /// distance, or minus its penetration depth ([`overlap`]) when GJK finds it intersecting.
    pub fn clearance(&self, q: &[f64]) -> (f64, Pair) {
        self.clearance_of(q, |_| true)
    }

    /// [`Arm::clearance`] over the tested pairs `keep` accepts (infinite when none).
    pub fn clearance_of(&self, q: &[f64], keep: impl Fn(Pair) -> bool) -> (f64, Pair) {
        let world = self.world(q);
        let mut best = (f64::INFINITY, self.pairs[0]);
        for &pair in self.pairs.iter().filter(|p| keep(**p)) {
            let (a, b) = self.sets(&world, pair);
            let d = distance(a, b);
            let c = if d > 0.0 { d } else { -overlap(a, b) };
            if c < best.0 {
                best = (c, pair);
            }
        }
        best
    }

    /// How deep `pair` overlaps at `q` (at most; metres).
    pub fn depth(&self, q: &[f64], pair: Pair) -> f64 {
        let world = self.world(q);
        let (a, b) = self.sets(&world, pair);
        overlap(a, b)
    }

    /// Why `q` is invalid, or `None`.
    pub fn problem(&self, q: &[f64]) -> Option<String> {
        if q.len() != self.spec.joints.len() {
            return Some(format!("{q:?}: {} joint values for {} joints", q.len(), self.spec.joints.len()));
        }
        if let Some(e) = self.limit_problem(q) {
            return Some(format!("{q:?}: {e}"));
        }
        let (pair, d) = *self.contacts(q, false).first()?;
        Some(format!("{q:?}: {} (distance {d:.3e})", self.describe(pair)))
    }
}

//! A spatial arm's collision query at one state: forward kinematics, each link part's world box
//! (the broad phase), then parry's GJK intersection tests: every part of a link that may touch the
//! scene against every 3-D obstacle whose box meets it, then the link pairs that are tested, in
//! that order, stopping at the first hit (as the Robotics Library's `SimpleModel` does).
//!
//! nalgebra's isometries become parry's poses once per link per state (`to_pose`), never per
//! primitive; a part's own placement (a box's centre) is composed on parry's side.

use super::kinematics::Chain;
use crate::geometry::hull::Climber;
use crate::geometry::solid::{Box3, Convex, Solid};
use crate::math::Real;
use nalgebra::{Isometry3, Matrix3};
use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::query::details::intersection_test_support_map_support_map_with_params;
use parry3d_f64::query::gjk::{closest_points, CsoPoint, GJKResult, VoronoiSimplex};
use parry3d_f64::shape::SupportMap;
use std::cell::Cell;

/// One convex part of a link (its hull, or a box fixed to it).
#[derive(Clone, Debug)]
pub struct Part {
    /// The link it belongs to.
    pub link: usize,
    /// The part in the link's frame.
    pub solid: Solid,
}

/// What a query found first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    /// Part `part` meets obstacle `solid` of the scene.
    Scene { part: usize, solid: usize },
    /// Parts `a` and `b` of two different links meet.
    Links { a: usize, b: usize },
}

/// Scratch reused across queries: the frames and their rotation matrices, each part's pose,
/// world box and oriented box's centre; the state they were placed at, and the query's answer
/// there once known.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    /// The state last placed, as given (compared bit for bit): its first `placed_len` coordinates
    /// (none before the first placement).
    placed: [Real; crate::limits::MAX_SPATIAL_JOINTS],
    placed_len: usize,
    /// The first hit at `placed`, once asked, with the scene it was asked against (its address and
    /// length): an explanation asking again about the state a check just found blocked (a
    /// recorded run's collision events) reads it here instead of testing every pair again.
    answer: Option<((usize, usize), Option<Hit>)>,
    frames: Vec<Isometry3<Real>>,
    rots: Vec<Matrix3<Real>>,
    poses: Vec<Pose>,
    boxes: Vec<Box3>,
    centres: Vec<[Real; 3]>,
    /// Where each scene pair (part × obstacle), then each link pair, left its last test.
    warm: Vec<Warm>,
}

/// Where a pair's last GJK test ended, to start the next one there.
#[derive(Clone, Copy, Debug, Default)]
struct Warm {
    /// The separating direction it found (none after a hit).
    dir: Option<Vector>,
    /// The hull vertices each side's last support climb ended on.
    hints: [u32; 2],
}

/// An oriented box: centre, axes (the columns), half extents.
struct Obb<'a> {
    c: &'a [Real; 3],
    axes: &'a Matrix3<Real>,
    h: &'a [Real; 3],
}

/// Whether two oriented boxes are separated along one of the 15 axes of the separating-axis test
/// (Gottschalk's OBB test, as in Ericson's "Real-Time Collision Detection" §4.4.1). Only a cull
/// before GJK: a small margin on the cross-product axes keeps it from calling nearly parallel
/// boxes separated when they are not, so "separated" is always true, "not separated" may not be.
fn obb_separated(a: &Obb, b: &Obb) -> bool {
    const MARGIN: Real = 1e-9;
    let d = [b.c[0] - a.c[0], b.c[1] - a.c[1], b.c[2] - a.c[2]];
    let col = |m: &Matrix3<Real>, i: usize| [m[(0, i)], m[(1, i)], m[(2, i)]];
    let dot = |u: [Real; 3], v: [Real; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let (ax, bx) = ([0, 1, 2].map(|i| col(a.axes, i)), [0, 1, 2].map(|i| col(b.axes, i)));
    let mut r = [[0.0; 3]; 3];
    let mut abs = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = dot(ax[i], bx[j]);
            abs[i][j] = r[i][j].abs() + MARGIN;
        }
    }
    let t = [dot(ax[0], d), dot(ax[1], d), dot(ax[2], d)];
    let (ha, hb) = (a.h, b.h);
    for i in 0..3 {
        if t[i].abs() > ha[i] + hb[0] * abs[i][0] + hb[1] * abs[i][1] + hb[2] * abs[i][2] {
            return true;
        }
    }
    for j in 0..3 {
        let tj = t[0] * r[0][j] + t[1] * r[1][j] + t[2] * r[2][j];
        if tj.abs() > ha[0] * abs[0][j] + ha[1] * abs[1][j] + ha[2] * abs[2][j] + hb[j] {
            return true;
        }
    }
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            let ra = ha[i1] * abs[i2][j] + ha[i2] * abs[i1][j];
            let rb = hb[j1] * abs[i][j2] + hb[j2] * abs[i][j1];
            if (t[i2] * r[i1][j] - t[i1] * r[i2][j]).abs() > ra + rb {
                return true;
            }
        }
    }
    false
}

/// The arm's collision geometry: its parts, which links meet the scene, which pairs are tested.
#[derive(Clone, Debug)]
pub struct Body {
    /// Every part, grouped by link in link order.
    pub parts: Vec<Part>,
    /// Per link, the range of its parts.
    pub link_parts: Vec<std::ops::Range<usize>>,
    /// The parts of links tested against the scene.
    pub scene_parts: Vec<usize>,
    /// The part pairs of the link pairs tested against each other.
    pub pairs: Vec<(usize, usize)>,
    /// Each part's half extents in its link's frame (its oriented box's).
    pub halves: Vec<[Real; 3]>,
    /// Each part's box centre in its link's frame.
    pub centres: Vec<[Real; 3]>,
    /// Whether a part sits at its link's frame (a hull) rather than placed in it (a box).
    pub at_frame: Vec<bool>,
}

/// An isometry as parry's pose.
#[inline]
fn to_pose(f: &Isometry3<Real>) -> Pose {
    let (q, t) = (f.rotation.quaternion(), f.translation.vector);
    Pose::from_parts(Vector::new(t.x, t.y, t.z), Rotation::from_xyzw(q.i, q.j, q.k, q.w))
}

/// The world box of a part whose own box has centre `c` and half extents `h` in a frame at `t`
/// rotated by `m`: its centre moved, its half extents through the absolute rotation matrix.
#[inline]
fn world_box(t: &nalgebra::Vector3<Real>, m: &Matrix3<Real>, c: &[Real; 3], h: &[Real; 3]) -> (Box3, [Real; 3]) {
    let mut out = Box3 { lo: [0.0; 3], hi: [0.0; 3] };
    let mut wc = [0.0; 3];
    for r in 0..3 {
        wc[r] = m[(r, 0)] * c[0] + m[(r, 1)] * c[1] + m[(r, 2)] * c[2] + t[r];
        let e = m[(r, 0)].abs() * h[0] + m[(r, 1)].abs() * h[1] + m[(r, 2)].abs() * h[2];
        out.lo[r] = wc[r] - e;
        out.hi[r] = wc[r] + e;
    }
    (out, wc)
}

/// The gap a separating direction must leave for it to stand as GJK's answer: far above GJK's own
/// tolerance (about 1e-13 here), so that where it stands GJK would have found the pair apart too.
const CLEAR_GAP: Real = 1e-9;

/// Whether `g2` (placed at `pos12` in `g1`'s frame) meets `g1`, and the direction to start the
/// next test from. First the pair's last separating direction `warm`, when there is one: if `g2`
/// lies more than [`CLEAR_GAP`] beyond `g1` along it (two support points), they are apart and that
/// direction stands; else parry's GJK, started along `start`. The plane test proves what GJK would
/// answer, in two support points where GJK needs at least four; GJK's own warm start only picks
/// its first simplex point.
#[inline]
fn gjk<G1: SupportMap, G2: SupportMap>(
    pos12: &Pose,
    g1: &G1,
    g2: &G2,
    warm: Option<Vector>,
    start: Option<Vector>,
) -> (bool, Vector) {
    if let Some(d) = warm {
        let far_a = d.dot(g1.local_support_point(d));
        let near_b = d.dot(g2.support_point(pos12, -d));
        if near_b - far_a > CLEAR_GAP {
            return (false, d);
        }
    }
    intersection_test_support_map_support_map_with_params(pos12, g1, g2, &mut VoronoiSimplex::new(), start)
}

/// `v` scaled to length 1, or `None` for a zero or non-finite vector: glam's `try_normalize`, the
/// same operations in the same order, with the processor's square root. IEEE 754 rounds a square
/// root exactly, so the bits are the same as libm's, which glam calls when built with `libm` (as
/// parry's `enhanced-determinism` builds it); in wasm that is a software root (all its calls took 7%
/// of a Puma run's time in chromium, these about a third), where `f64::sqrt` is one `f64.sqrt`.
#[inline(always)]
fn unit(v: Vector) -> Option<Vector> {
    let rcp = 1.0 / v.dot(v).sqrt();
    if rcp.is_finite() && rcp > 0.0 {
        Some(v * rcp)
    } else {
        None
    }
}

/// Whether two placed solids meet: GJK on their support maps, started along `warm`'s direction (in
/// the first solid's frame) when there is one, else along the direction from the first's box
/// centre to the second's (`ca`, `cb`, in the world), each hull's climbs from `warm`'s vertices;
/// where GJK ended is written back to `warm`.
/// Started from the last query's separating direction, GJK on a pair that stays apart ends in one
/// or two iterations (SOLID's and Bullet's frame coherence). The start changes how fast GJK ends,
/// not its answer, except within GJK's tolerance of touching.
#[inline]
fn intersects(p1: &Pose, s1: &Solid, p2: &Pose, s2: &Solid, ca: &[Real; 3], cb: &[Real; 3], warm: &mut Warm) -> bool {
    let pos12 = p1.inv_mul(p2);
    let Warm { dir, hints } = warm;
    let start = dir.or_else(|| {
        let world = Vector::new(cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]);
        unit(p1.rotation.inverse() * world)
    });
    let [h1, h2] = hints;
    let climber = |hull, hint| Climber { hull, hint: Cell::from_mut(hint) };
    let warm = *dir;
    // Each pair of kinds by its own types, so that the support maps are inlined into GJK.
    let (hit, end) = match (&s1.convex, &s2.convex) {
        (Convex::Hull(a), Convex::Hull(b)) => gjk(&pos12, &climber(a, h1), &climber(b, h2), warm, start),
        (Convex::Hull(a), Convex::Cuboid(b)) => gjk(&pos12, &climber(a, h1), b, warm, start),
        (Convex::Cuboid(a), Convex::Hull(b)) => gjk(&pos12, a, &climber(b, h2), warm, start),
        (Convex::Cuboid(a), Convex::Cuboid(b)) => gjk(&pos12, a, b, warm, start),
    };
    *dir = if hit { None } else { unit(end) };
    hit
}

/// What a lower bound on a distance gives away to rounding: the plane test's two support points
/// are exact, their dot products err by some ulps of a metre.
const GAP_SLACK: Real = 1e-12;

/// A lower bound on the distance between `g1` and `g2` (placed at `pos12` in `g1`'s frame), capped
/// at `cap`: the gap between the two along a direction (how far `g2`'s nearest support point lies
/// beyond `g1`'s farthest), which no direction overstates. First along the pair's last
/// separating direction `warm`; when that leaves less than `cap`, along the direction between
/// the closest points GJK finds, which gives the distance itself up to GJK's tolerance. 0 when
/// GJK finds them meeting.
fn gap<G1: SupportMap, G2: SupportMap>(pos12: &Pose, g1: &G1, g2: &G2, warm: Option<Vector>, cap: Real) -> Real {
    let along = |d: Vector| d.dot(g2.support_point(pos12, -d)) - d.dot(g1.local_support_point(d)) - GAP_SLACK;
    if let Some(d) = warm {
        if along(d) >= cap {
            return cap;
        }
    }
    let start = warm.or_else(|| unit(pos12.translation)).unwrap_or(Vector::X);
    let mut simplex = VoronoiSimplex::new();
    simplex.reset(CsoPoint::from_shapes(pos12, g1, g2, start));
    match closest_points(pos12, g1, g2, Real::MAX, true, &mut simplex) {
        GJKResult::ClosestPoints(p1, p2, _) => unit(p2 - p1).map_or(0.0, |n| along(n).clamp(0.0, cap)),
        _ => 0.0,
    }
}

/// [`gap`] between two placed solids, each pair of kinds by its own types; the hulls' climbs
/// start from `warm`'s vertices, which are left as they were (so that a clearance never changes
/// what the next validity query does).
fn solid_gap(p1: &Pose, s1: &Solid, p2: &Pose, s2: &Solid, warm: &Warm, cap: Real) -> Real {
    let pos12 = p1.inv_mul(p2);
    let [mut h1, mut h2] = warm.hints;
    let climber = |hull, hint| Climber { hull, hint: Cell::from_mut(hint) };
    let w = warm.dir;
    match (&s1.convex, &s2.convex) {
        (Convex::Hull(a), Convex::Hull(b)) => gap(&pos12, &climber(a, &mut h1), &climber(b, &mut h2), w, cap),
        (Convex::Hull(a), Convex::Cuboid(b)) => gap(&pos12, &climber(a, &mut h1), b, w, cap),
        (Convex::Cuboid(a), Convex::Hull(b)) => gap(&pos12, a, &climber(b, &mut h2), w, cap),
        (Convex::Cuboid(a), Convex::Cuboid(b)) => gap(&pos12, a, b, w, cap),
    }
}

/// The distance between two boxes (0 when they meet): never more than between what they hold.
fn box_gap(a: &Box3, b: &Box3) -> Real {
    let mut sq = 0.0;
    for k in 0..3 {
        let g = (a.lo[k] - b.hi[k]).max(b.lo[k] - a.hi[k]).max(0.0);
        sq += g * g;
    }
    sq.sqrt()
}

impl Scratch {
    /// Whether the parts are placed at `q`, bit for bit.
    fn holds(&self, q: &[Real]) -> bool {
        self.placed_len == q.len() && self.placed.iter().zip(q).all(|(a, b)| a.to_bits() == b.to_bits())
    }

    /// Link `k`'s frame when the parts are placed at `q` (the same bits [`Chain::frames`] gives
    /// for `q`), else `None`.
    pub fn frame_at(&self, q: &[Real], k: usize) -> Option<&Isometry3<Real>> {
        if self.holds(q) {
            self.frames.get(k)
        } else {
            None
        }
    }

    /// Each part's pose at the state last placed (tests: what the 3-D view's frames must agree with).
    #[cfg(test)]
    pub fn poses(&self) -> &[Pose] {
        &self.poses
    }
}

impl Body {
    /// The first hit at `q` (scene first, then link pairs), or `None` when the arm is free: the
    /// parts placed at `q` (unless they are there already) and tested, or the answer already
    /// found for `q` against the same scene. Either way the same answer: a pair's test does not
    /// depend on where earlier tests started.
    pub fn hit_at(&self, chain: &Chain, scene: &[Solid], q: &[Real], s: &mut Scratch) -> Option<Hit> {
        if s.holds(q) {
            if let Some((k, hit)) = s.answer {
                if k == (scene.as_ptr() as usize, scene.len()) {
                    return hit;
                }
            }
        } else {
            self.place(chain, q, s);
        }
        self.answer(scene, s)
    }

    /// The first hit at `q`, the parts placed there and tested whatever `s` holds: a state check
    /// (a planner never asks about the same state twice in a row), kept for [`Body::hit_at`].
    pub fn test(&self, chain: &Chain, scene: &[Solid], q: &[Real], s: &mut Scratch) -> Option<Hit> {
        self.place(chain, q, s);
        self.answer(scene, s)
    }

    fn answer(&self, scene: &[Solid], s: &mut Scratch) -> Option<Hit> {
        let hit = self.first_hit(scene, s);
        s.answer = Some(((scene.as_ptr() as usize, scene.len()), hit));
        hit
    }

    /// Place every part at state `q` (frames, poses, world boxes) into `s`.
    // Not inlined into `hit_at`: the two apart take 1% fewer instructions (callgrind, Puma run).
    #[inline(never)]
    pub fn place(&self, chain: &Chain, q: &[Real], s: &mut Scratch) {
        // a state longer than any arm's (never placed) is not remembered
        s.placed_len = if q.len() <= s.placed.len() { q.len() } else { usize::MAX };
        for (p, x) in s.placed.iter_mut().zip(q) {
            *p = *x;
        }
        s.answer = None;
        let links = self.link_parts.len();
        s.frames.resize(links, Isometry3::identity());
        chain.frames(q, &mut s.frames);
        s.poses.resize(self.parts.len(), Pose::IDENTITY);
        s.boxes.resize(self.parts.len(), Box3 { lo: [0.0; 3], hi: [0.0; 3] });
        s.centres.resize(self.parts.len(), [0.0; 3]);
        s.rots.resize(links, Matrix3::identity());
        for (k, range) in self.link_parts.iter().enumerate() {
            if range.is_empty() {
                continue;
            }
            let f = &s.frames[k];
            let pose = to_pose(f);
            let m = f.rotation.to_rotation_matrix().into_inner();
            for i in range.clone() {
                s.poses[i] = if self.at_frame[i] { pose } else { pose * self.parts[i].solid.placement };
                (s.boxes[i], s.centres[i]) = world_box(&f.translation.vector, &m, &self.centres[i], &self.halves[i]);
            }
            s.rots[k] = m;
        }
    }

    /// The first hit at the state last placed in `s`, scene first, or `None` when the arm is free.
    #[inline(never)]
    pub fn first_hit(&self, scene: &[Solid], s: &mut Scratch) -> Option<Hit> {
        let (m, n) = (scene.len(), self.scene_parts.len());
        s.warm.resize(m * n + self.pairs.len(), Warm::default());
        let Scratch { boxes, poses, centres, rots, warm, .. } = s;
        let identity = Matrix3::identity();
        let obb = |i: usize| Obb { c: &centres[i], axes: &rots[self.parts[i].link], h: &self.halves[i] };
        for (k, &i) in self.scene_parts.iter().enumerate() {
            let (b, p, part) = (&boxes[i], &poses[i], &self.parts[i].solid);
            for (j, o) in scene.iter().enumerate() {
                if !b.meets(&o.bounds) {
                    continue;
                }
                let (c, h) = o.bounds.centre_half();
                if !obb_separated(&obb(i), &Obb { c: &c, axes: &identity, h: &h })
                    && intersects(p, part, &o.placement, o, &centres[i], &c, &mut warm[k * m + j])
                {
                    return Some(Hit::Scene { part: i, solid: j });
                }
            }
        }
        for (k, &(a, b)) in self.pairs.iter().enumerate() {
            if boxes[a].meets(&boxes[b])
                && !obb_separated(&obb(a), &obb(b))
                && intersects(
                    &poses[a],
                    &self.parts[a].solid,
                    &poses[b],
                    &self.parts[b].solid,
                    &centres[a],
                    &centres[b],
                    &mut warm[m * n + k],
                )
            {
                return Some(Hit::Links { a, b });
            }
        }
        None
    }

    /// Where `hit` happened at the state last placed in `s` (after [`first_hit`](Body::first_hit)
    /// found it): a point of the world between the two shapes' deepest points (GJK and EPA's
    /// penetrating contact), or, when EPA gives none (touching within GJK's tolerance), the centre
    /// of the overlap of the two shapes' world boxes. For drawing and explaining only.
    pub fn contact_point(&self, scene: &[Solid], s: &Scratch, hit: Hit) -> [Real; 3] {
        let (p1, s1, b1, p2, s2, b2) = match hit {
            Hit::Scene { part, solid } => {
                let o = &scene[solid];
                (&s.poses[part], &self.parts[part].solid, s.boxes[part], &o.placement, o, o.bounds)
            }
            Hit::Links { a, b } => {
                (&s.poses[a], &self.parts[a].solid, s.boxes[a], &s.poses[b], &self.parts[b].solid, s.boxes[b])
            }
        };
        let pos12 = p1.inv_mul(p2);
        let (h1, h2) = (Cell::new(0u32), Cell::new(0u32));
        let climber = |hull, hint| Climber { hull, hint };
        use parry3d_f64::query::contact::contact_support_map_support_map as epa;
        let c = match (&s1.convex, &s2.convex) {
            (Convex::Hull(a), Convex::Hull(b)) => epa(&pos12, &climber(a, &h1), &climber(b, &h2), 0.0),
            (Convex::Hull(a), Convex::Cuboid(b)) => epa(&pos12, &climber(a, &h1), b, 0.0),
            (Convex::Cuboid(a), Convex::Hull(b)) => epa(&pos12, a, &climber(b, &h2), 0.0),
            (Convex::Cuboid(a), Convex::Cuboid(b)) => epa(&pos12, a, b, 0.0),
        };
        match c {
            Some(c) if c.point1.is_finite() && c.point2.is_finite() => {
                let mid = (c.point1 + pos12.transform_point(c.point2)) * 0.5;
                let w = p1.transform_point(mid);
                [w.x, w.y, w.z]
            }
            _ => std::array::from_fn(|i| 0.5 * (b1.lo[i].max(b2.lo[i]) + b1.hi[i].min(b2.hi[i]))),
        }
    }

    /// A lower bound on the arm's clearance at the state last placed in `s`, found free by
    /// [`first_hit`](Body::first_hit), capped at `cap`: the least gap between a part that may
    /// touch the scene and an obstacle, and half the least gap between two parts of a tested
    /// link pair (both may move, each at most as far as any point of the arm). Pairs whose
    /// boxes lie `cap` apart are not looked at further.
    pub fn clearance(&self, scene: &[Solid], s: &Scratch, cap: Real) -> Real {
        let (m, n) = (scene.len(), self.scene_parts.len());
        let mut least = cap;
        for (k, &i) in self.scene_parts.iter().enumerate() {
            for (j, o) in scene.iter().enumerate() {
                if box_gap(&s.boxes[i], &o.bounds) >= least {
                    continue;
                }
                let warm = s.warm.get(k * m + j).copied().unwrap_or_default();
                least = least.min(solid_gap(&s.poses[i], &self.parts[i].solid, &o.placement, o, &warm, least));
            }
        }
        for (k, &(a, b)) in self.pairs.iter().enumerate() {
            if box_gap(&s.boxes[a], &s.boxes[b]) >= 2.0 * least {
                continue;
            }
            let warm = s.warm.get(m * n + k).copied().unwrap_or_default();
            let (pa, pb) = (&self.parts[a].solid, &self.parts[b].solid);
            least = least.min(0.5 * solid_gap(&s.poses[a], pa, &s.poses[b], pb, &warm, 2.0 * least));
        }
        least
    }
}

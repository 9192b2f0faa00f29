//! A spatial arm's collision query at one state: forward kinematics, each link part's world box
//! (the broad phase), then parry's GJK intersection tests: every part of a link that may touch the
//! scene against every 3-D obstacle whose box meets it, then the link pairs that are tested, in
//! that order, stopping at the first hit (as the Robotics Library's `SimpleModel` does).
//!
//! nalgebra's isometries become parry's poses once per link per state (`to_pose`), never per
//! primitive; a part's own placement (a box's centre) is composed on parry's side.

use super::kinematics::Chain;
use crate::geometry::solid::{Box3, Solid};
use crate::math::Real;
use nalgebra::Isometry3;
use parry3d_f64::math::{Pose, Rotation, Vector};

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

/// Scratch reused across queries: the frames, each part's pose and world box.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    frames: Vec<Isometry3<Real>>,
    poses: Vec<Pose>,
    boxes: Vec<Box3>,
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
}

/// An isometry as parry's pose.
#[inline]
fn to_pose(f: &Isometry3<Real>) -> Pose {
    let (q, t) = (f.rotation.quaternion(), f.translation.vector);
    Pose::from_parts(Vector::new(t.x, t.y, t.z), Rotation::from_xyzw(q.i, q.j, q.k, q.w))
}

/// The world box of a box `local` given in frame `f`: its centre moved, its half extents through
/// the absolute rotation matrix.
#[inline]
fn world_box(f: &Isometry3<Real>, m: &nalgebra::Matrix3<Real>, local: &Box3) -> Box3 {
    let (c, h) = local.centre_half();
    let wc = f * nalgebra::Point3::new(c[0], c[1], c[2]);
    let mut out = Box3 { lo: [0.0; 3], hi: [0.0; 3] };
    for r in 0..3 {
        let e = m[(r, 0)].abs() * h[0] + m[(r, 1)].abs() * h[1] + m[(r, 2)].abs() * h[2];
        out.lo[r] = wc[r] - e;
        out.hi[r] = wc[r] + e;
    }
    out
}

#[inline]
fn intersects(p1: &Pose, s1: &Solid, p2: &Pose, s2: &Solid) -> bool {
    parry3d_f64::query::intersection_test(p1, s1.convex.shape(), p2, s2.convex.shape())
        .map(|i| i.intersecting)
        // Every pair of convex shapes here is supported; an unsupported pair would be a bug, and
        // counting it as a collision keeps a path from passing through it.
        .unwrap_or(true)
}

impl Body {
    /// Place every part at state `q` (frames, poses, world boxes) into `s`.
    pub fn place(&self, chain: &Chain, q: &[Real], s: &mut Scratch) {
        let links = self.link_parts.len();
        s.frames.resize(links, Isometry3::identity());
        chain.frames(q, &mut s.frames);
        s.poses.resize(self.parts.len(), Pose::IDENTITY);
        s.boxes.resize(self.parts.len(), Box3 { lo: [0.0; 3], hi: [0.0; 3] });
        for (k, range) in self.link_parts.iter().enumerate() {
            if range.is_empty() {
                continue;
            }
            let f = &s.frames[k];
            let pose = to_pose(f);
            let m = f.rotation.to_rotation_matrix().into_inner();
            for i in range.clone() {
                let solid = &self.parts[i].solid;
                s.poses[i] = if solid.placement == Pose::IDENTITY { pose } else { pose * solid.placement };
                s.boxes[i] = world_box(f, &m, &solid.bounds);
            }
        }
    }

    /// The first hit at the state last placed in `s`, scene first, or `None` when the arm is free.
    pub fn first_hit(&self, scene: &[Solid], s: &Scratch) -> Option<Hit> {
        for &i in &self.scene_parts {
            let (b, p, part) = (&s.boxes[i], &s.poses[i], &self.parts[i].solid);
            for (j, o) in scene.iter().enumerate() {
                if b.meets(&o.bounds) && intersects(p, part, &o.placement, o) {
                    return Some(Hit::Scene { part: i, solid: j });
                }
            }
        }
        for &(a, b) in &self.pairs {
            if s.boxes[a].meets(&s.boxes[b])
                && intersects(&s.poses[a], &self.parts[a].solid, &s.poses[b], &self.parts[b].solid)
            {
                return Some(Hit::Links { a, b });
            }
        }
        None
    }
}

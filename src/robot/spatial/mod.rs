//! A spatial serial arm (report 001's Unimation Puma 560, `docs/sources.md`): revolute joints in
//! classic Denavit–Hartenberg form on a base pose, each link colliding as its convex hull and the
//! boxes fixed to it (a tool), in a scene of 3-D boxes and hulls (`obstacles3d`).
//!
//! Its state is the joint angles in radians, each within its limits (no wrapping); its metric is
//! Euclidean over them, the course's. Valid when every joint is within its limits, no link that
//! may touch the scene meets a 3-D obstacle, and no tested pair of links meets (the scenario lists
//! the pairs never tested, and the links exempt from the scene). Obstacles are closed: touching
//! is a collision, up to GJK's tolerance. Motions are certified between states checked at the
//! scenario's resolution: a lower bound on the clearance against a bound on how far any point of
//! the arm moves ([`MotionModel`]); the course's connect tests its `delta` steps' configurations
//! alone, and its path is certified after planning (`run::certify`).
//!
//! The kinematics ([`kinematics`]) is nalgebra's; the collision query ([`collide`]) parry3d's,
//! with the same bits natively, in Node and in the browser.

mod collide;
mod kinematics;

use super::{Contact, MotionModel, PartMesh, Robot, Spatial, Verdict};
use crate::geometry::mesh::Mesh;
use crate::geometry::solid::Solid;
use crate::geometry::Workspace;
use crate::math::{Real, Vec2};
use crate::robot::kinds::{Drawn, Pose, RobotKind};
use crate::scenario::{RobotSpec, SpatialArmSpec};
use crate::space::{Dim, Metric, StateSpace};
use collide::{Body, Hit, Part, Scratch};
pub use kinematics::Chain;
use std::cell::RefCell;

/// The kind's record ([`super::kinds`]).
pub const KIND: RobotKind = RobotKind {
    name: "spatial-arm",
    label: "Spatial arm (3-D)",
    drawn: Drawn::SpatialArm,
    body: false,
    sensor: false,
    cspace: false,
    course_cost: None,
    pose: Pose::Joints,
    solution_file: false,
    // OMPL's default, 0.2 × the joints' extent, is about 2.8 rad on the Puma: RRT-Connect with
    // range steps did not thread the course's window in 20 s at it (seeds 1–3), and did in 2–4 s
    // at 0.2 rad (about 11° of the six-joint norm).
    default_range: Some(0.2),
};

/// A spatial serial arm.
#[derive(Clone, Debug)]
pub struct SpatialArmRobot {
    chain: Chain,
    limits: Vec<[Real; 2]>,
    body: Body,
    tool: [Real; 3],
    /// Per joint, a bound on how far any point of the arm lies from the joint's axis (at any
    /// state): how fast it can move, in metres per radian of that joint.
    reach: Vec<Real>,
    scratch: RefCell<Scratch>,
    tool_memo: RefCell<ToolMemo>,
}

/// The last few tool points computed, their states compared bit for bit: a recorded run projects
/// the same node again and again (nearest, steer, collision, node added), and each projection is
/// the chain's forward kinematics. What it returns is what the kinematics gives, so runs and
/// their events are the same bits with it or without it.
#[derive(Clone, Debug, Default)]
struct ToolMemo {
    states: Vec<Real>,
    points: Vec<[Real; 3]>,
    next: usize,
}

/// States the tool memo keeps.
const TOOL_MEMO: usize = 4;

impl SpatialArmRobot {
    /// The robot a scenario's `spatial-arm` block describes; an error names the part whose hull
    /// could not be built.
    pub fn from_spec(spec: &RobotSpec) -> Result<Self, String> {
        let RobotSpec::SpatialArm(s) = spec else {
            return Err("not a spatial arm".into());
        };
        let SpatialArmSpec { base, joints, links, ignore, exempt, tool, .. } = s.as_ref();
        let mut parts = Vec::new();
        let mut link_parts = Vec::new();
        for (k, l) in links.iter().enumerate() {
            let from = parts.len();
            if !l.hull.is_empty() {
                let solid = Solid::hull(&l.name, &l.hull).map_err(|e| format!("robot.links[{k}].hull: {e}"))?;
                parts.push(Part { link: k, solid });
            }
            for b in &l.boxes {
                let name = if b.name.is_empty() { l.name.clone() } else { format!("{}'s {}", l.name, b.name) };
                parts.push(Part { link: k, solid: Solid::cuboid(&name, b.center, b.size) });
            }
            link_parts.push(from..parts.len());
        }
        let scene_parts = (0..parts.len()).filter(|&i| !exempt.contains(&parts[i].link)).collect();
        let mut pairs = Vec::new();
        for i in 0..links.len() {
            for j in i + 1..links.len() {
                if ignore.contains(&[i, j]) {
                    continue;
                }
                for a in link_parts[i].clone() {
                    for b in link_parts[j].clone() {
                        pairs.push((a, b));
                    }
                }
            }
        }
        let reach = reach(joints, &link_parts, &parts);
        Ok(SpatialArmRobot {
            reach,
            chain: Chain::new(base, joints),
            limits: joints.iter().map(|j| j.limits).collect(),
            body: Body {
                halves: parts.iter().map(|p| p.solid.bounds.centre_half().1).collect(),
                centres: parts.iter().map(|p| p.solid.bounds.centre_half().0).collect(),
                at_frame: parts.iter().map(|p| p.solid.placement == parry3d_f64::math::Pose::IDENTITY).collect(),
                parts,
                link_parts,
                scene_parts,
                pairs,
            },
            tool: *tool,
            scratch: RefCell::new(Scratch::default()),
            tool_memo: RefCell::new(ToolMemo::default()),
        })
    }

    /// The tool centre point at `q` ([`Chain::point_on_last`]), from the memo when `q` is one of
    /// the last states asked for, else from the last link's frame when the collision query's
    /// parts are placed at `q`.
    fn tool_at(&self, q: &[Real]) -> [Real; 3] {
        let mut m = self.tool_memo.borrow_mut();
        let n = q.len();
        let same = |k: usize| m.states[k * n..(k + 1) * n].iter().zip(q).all(|(a, b)| a.to_bits() == b.to_bits());
        if let Some(k) = (0..m.points.len()).find(|&k| same(k)) {
            return m.points[k];
        }
        // The parts placed at `q` (the state a check just tested): the last link's frame is there,
        // the same bits `point_on_last` computes.
        let placed = self.scratch.try_borrow().ok().and_then(|s| {
            let [x, y, z] = self.tool;
            s.frame_at(q, self.chain.joints()).map(|f| f * nalgebra::Point3::new(x, y, z)).map(|w| [w.x, w.y, w.z])
        });
        let p = placed.unwrap_or_else(|| self.chain.point_on_last(q, &self.tool));
        if m.points.len() < TOOL_MEMO {
            m.states.extend_from_slice(q);
            m.points.push(p);
        } else {
            let k = m.next;
            m.states[k * n..(k + 1) * n].copy_from_slice(q);
            m.points[k] = p;
            m.next = (k + 1) % TOOL_MEMO;
        }
        p
    }

    fn within_limits(&self, q: &[Real]) -> bool {
        q.iter().zip(&self.limits).all(|(x, [lo, hi])| *lo <= *x && *x <= *hi)
    }

    /// The first hit at `q` (scene first, then link pairs), or `None` when the arm is free; the
    /// joint limits are not checked.
    pub fn first_hit(&self, ws: &Workspace, q: &[Real]) -> Option<Hit> {
        let mut s = self.scratch.borrow_mut();
        self.body.hit_at(&self.chain, &ws.solids, q, &mut s)
    }

    /// What a hit is, in words: "link6's bar meets the lintel", "link2 meets link5".
    pub fn describe(&self, ws: &Workspace, hit: Hit) -> String {
        let part = |i: usize| &self.body.parts[i].solid.name;
        match hit {
            Hit::Scene { part: p, solid } => {
                let o = &ws.solids[solid].name;
                // a numbered name ("box2") is a label, said without "the"
                let o = if o.is_empty() {
                    format!("obstacles3d[{solid}]")
                } else if o.ends_with(|c: char| c.is_ascii_digit()) {
                    o.clone()
                } else {
                    format!("the {o}")
                };
                format!("{} meets {o}", part(p))
            }
            Hit::Links { a, b } => format!("{} meets {}", part(a), part(b)),
        }
    }

    /// Every link frame's origin and the tool centre point at `q`, in the world (`joints + 2`
    /// points): what a 3-D view draws the arm's skeleton and its tool through.
    pub fn skeleton_points(&self, q: &[Real]) -> Vec<[Real; 3]> {
        let mut frames = vec![nalgebra::Isometry3::identity(); self.chain.joints() + 1];
        self.chain.frames(q, &mut frames);
        let mut pts: Vec<[Real; 3]> = frames.iter().map(|f| f.translation.vector.into()).collect();
        let [x, y, z] = self.tool;
        let t = frames[self.chain.joints()] * nalgebra::Point3::new(x, y, z);
        pts.push([t.x, t.y, t.z]);
        pts
    }
}

/// Per joint `j`, a bound on the distance from joint `j`'s axis to any point of the links it
/// moves, whatever the state: a point of link `k ≥ j` lies within the sum of the DH steps'
/// lengths `√(a² + d²)` from joint `j` to link `k`, plus its part's farthest corner from link
/// `k`'s origin (by the triangle inequality along the chain).
fn reach(joints: &[crate::scenario::DhJoint], link_parts: &[std::ops::Range<usize>], parts: &[Part]) -> Vec<Real> {
    let radius = |k: usize| {
        link_parts.get(k).map_or(0.0, |r| {
            parts[r.clone()].iter().fold(0.0, |m: Real, p| {
                let (c, h) = p.solid.bounds.centre_half();
                let far = (0..3).map(|i| (c[i].abs() + h[i]).powi(2)).sum::<Real>().sqrt();
                m.max(far)
            })
        })
    };
    (0..joints.len())
        .map(|j| {
            // Joint j (0-based) turns about link j's z axis and moves links j + 1 ...
            let mut along = 0.0;
            let mut most: Real = 0.0;
            for k in j + 1..=joints.len() {
                let row = &joints[k - 1];
                along += (row.a * row.a + row.d * row.d).sqrt();
                most = most.max(along + radius(k));
            }
            most
        })
        .collect()
}

impl MotionModel for SpatialArmRobot {
    /// The least gap between the arm and the scene, or half the least between two tested links,
    /// capped at `cap`; 0 when a joint is outside its limits or the arm collides (by the same
    /// query as validity). A lower bound: each gap is measured along a separating direction.
    fn clearance(&self, ws: &Workspace, q: &[Real], cap: Real) -> Option<Real> {
        if !self.within_limits(q) {
            return Some(0.0);
        }
        let mut s = self.scratch.borrow_mut();
        // placed and tested anew: the gaps are measured from where this test's GJK ended
        if self.body.test(&self.chain, &ws.solids, q, &mut s).is_some() {
            return Some(0.0);
        }
        Some(self.body.clearance(&ws.solids, &s, cap))
    }
    /// `Σ_j reach_j · |b_j − a_j|`: along a straight motion in joint space no point of the arm
    /// travels farther (its speed is at most the sum of each joint's rate times the point's
    /// distance from that joint's axis).
    fn displacement_bound(&self, a: &[Real], b: &[Real]) -> Option<Real> {
        Some(self.reach.iter().zip(a.iter().zip(b)).map(|(r, (x, y))| r * (y - x).abs()).sum())
    }
    fn walks_by_states(&self) -> bool {
        true
    }
}

#[cfg(test)]
impl SpatialArmRobot {
    /// Each part's world vertices at `q` as the collision query places them (a hull's points, a
    /// box's corners): what a drawn mesh must agree with.
    fn placed_vertices(&self, q: &[Real]) -> Vec<Vec<[Real; 3]>> {
        use crate::geometry::solid::Convex;
        use parry3d_f64::math::Vector;
        let mut s = self.scratch.borrow_mut();
        self.body.place(&self.chain, q, &mut s);
        let poses = s.poses();
        self.body
            .parts
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let local: Vec<Vector> = match &p.solid.convex {
                    Convex::Hull(h) => h.poly.points().to_vec(),
                    Convex::Cuboid(c) => (0..8)
                        .map(|k| {
                            let h = c.half_extents;
                            let sign = |b: usize| if k & (1 << b) != 0 { 1.0 } else { -1.0 };
                            Vector::new(sign(0) * h.x, sign(1) * h.y, sign(2) * h.z)
                        })
                        .collect(),
                };
                local.iter().map(|v| poses[i].transform_point(*v)).map(|w| [w.x, w.y, w.z]).collect()
            })
            .collect()
    }
}

impl Robot for SpatialArmRobot {
    fn caps(&self) -> &'static RobotKind {
        &KIND
    }
    fn external_dims(&self) -> usize {
        self.chain.joints()
    }
    fn space(&self, _ws: &Workspace) -> StateSpace {
        StateSpace {
            dims: self.limits.iter().map(|[lo, hi]| Dim { lo: *lo, hi: *hi, wraps: false }).collect(),
            metric: Metric::Euclidean,
        }
    }
    fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict {
        if !self.within_limits(q) {
            return Verdict::Invalid("a joint is outside its limits");
        }
        match self.first_hit(ws, q) {
            None => Verdict::Valid,
            Some(Hit::Scene { solid, .. }) => Verdict::Collision(solid),
            Some(Hit::Links { .. }) => Verdict::Invalid("two links of the arm meet"),
        }
    }
    fn is_valid(&self, ws: &Workspace, q: &[Real]) -> bool {
        self.within_limits(q) && self.body.test(&self.chain, &ws.solids, q, &mut self.scratch.borrow_mut()).is_none()
    }
    fn describe_collision(&self, ws: &Workspace, q: &[Real]) -> Option<String> {
        self.first_hit(ws, q).map(|h| self.describe(ws, h))
    }
    /// The tool centre point seen from above.
    fn project(&self, q: &[Real]) -> Vec2 {
        let [x, y, _] = self.tool_at(q);
        Vec2::new(x, y)
    }
    /// The skeleton seen from above: the link frames' origins and the tool centre point.
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        vec![self.skeleton_points(q).iter().map(|p| Vec2::new(p[0], p[1])).collect()]
    }
    fn spatial(&self) -> Option<&dyn Spatial> {
        Some(self)
    }
    fn motion(&self) -> Option<&dyn MotionModel> {
        Some(self)
    }
}

impl Spatial for SpatialArmRobot {
    /// What collides at `q` and where, for a 3-D view's collision mark: the link of the part hit,
    /// the other link (`None`: a scene obstacle), the obstacle's index in the scene (`None`: two
    /// links), and a world point where they meet ([`Body::contact_point`](collide::Body)); `None`
    /// when the arm is free (joint limits are not checked).
    fn contact(&self, ws: &Workspace, q: &[Real]) -> Option<Contact> {
        let mut s = self.scratch.borrow_mut();
        let hit = self.body.hit_at(&self.chain, &ws.solids, q, &mut s)?;
        let at = self.body.contact_point(&ws.solids, &s, hit);
        Some(match hit {
            Hit::Scene { part, solid } => {
                Contact { link: self.body.parts[part].link, other: None, solid: Some(solid), at }
            }
            Hit::Links { a, b } => {
                Contact { link: self.body.parts[a].link, other: Some(self.body.parts[b].link), solid: None, at }
            }
        })
    }

    fn skeleton(&self, q: &[Real]) -> Vec<[Real; 3]> {
        self.skeleton_points(q)
    }
    fn tool_point(&self, q: &[Real]) -> [Real; 3] {
        self.tool_at(q)
    }
    fn tool_sweep(&self, a: &[Real], delta: &[Real], points: usize) -> Vec<[Real; 3]> {
        self.chain.sweep(a, delta, points, &self.tool)
    }
    fn tool(&self) -> [Real; 3] {
        self.tool
    }
    fn part_meshes(&self) -> Vec<PartMesh> {
        self.body
            .parts
            .iter()
            .map(|p| PartMesh { link: p.link, name: p.solid.name.clone(), mesh: Mesh::of_solid(&p.solid) })
            .collect()
    }
    fn link_frames(&self, q: &[Real]) -> Vec<[Real; 16]> {
        let mut frames = vec![nalgebra::Isometry3::identity(); self.chain.joints() + 1];
        self.chain.frames(q, &mut frames);
        frames
            .iter()
            .map(|f| {
                let mut m = [0.0; 16];
                m.copy_from_slice(f.to_homogeneous().as_slice());
                m
            })
            .collect()
    }
}

#[cfg(test)]
mod explain_tests;
#[cfg(test)]
mod tests;

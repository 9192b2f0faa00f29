use super::capability::{MotionModel, Sensor, WorkspaceBody};
use super::{xy_dims, xy_in_bounds, Robot, Verdict};
use crate::geometry::{SensorPose, Workspace};
use crate::math::{self, MinMax, Real, Vec2, PI};
use crate::robot::kinds::{Drawn, Pose, RobotKind};
use crate::space::{Dim, Metric, StateSpace};

/// The most footprint vertices transformed on the stack; larger footprints use the heap.
const STACK_VERTICES: usize = 16;

/// A rigid polygon robot; state `[x, y, θ]`, the footprint rotating about the body origin.
#[derive(Clone, Debug)]
pub struct RigidRobot {
    pub(crate) footprint: Vec<Vec2>,
    radius: Real,
    rotation_weight: Real,
    body_in_bounds: bool,
}

impl RigidRobot {
    /// A rigid robot with this body-frame footprint; the rotation weight of the metric defaults to
    /// the footprint's radius (its farthest vertex from the origin).
    pub fn new(footprint: Vec<Vec2>, rotation_weight: Option<Real>, body_in_bounds: bool) -> Self {
        let radius = footprint.iter().map(|p| p.norm()).fold(0.0, Real::max);
        RigidRobot { footprint, radius, rotation_weight: rotation_weight.unwrap_or(radius), body_in_bounds }
    }

    /// The footprint's radius.
    pub fn radius(&self) -> Real {
        self.radius
    }

    /// The verdict at `q` (`any`: see [`RigidRobot::verdict_of`]).
    fn verdict_at(&self, ws: &Workspace, q: &[Real], any: bool) -> Verdict {
        if let Some(v) = xy_in_bounds(ws, q) {
            return v;
        }
        let n = self.footprint.len();
        if n <= STACK_VERTICES {
            let mut buf = [Vec2::default(); STACK_VERTICES];
            self.place(q, &mut buf[..n]);
            self.verdict_of(ws, &buf[..n], any)
        } else {
            let mut buf = vec![Vec2::default(); n];
            self.place(q, &mut buf);
            self.verdict_of(ws, &buf, any)
        }
    }

    /// Write the footprint at state `q` into `out`.
    #[inline]
    fn place(&self, q: &[Real], out: &mut [Vec2]) {
        let body = math::pose(q[0], q[1], q[2]);
        for (o, p) in out.iter_mut().zip(&self.footprint) {
            *o = math::place(&body, *p);
        }
    }

    /// The verdict of the body placed at `body`; `any`: a collision names any obstacle met, not
    /// the first (for validity alone, where the search can stop at the first found).
    fn verdict_of(&self, ws: &Workspace, body: &[Vec2], any: bool) -> Verdict {
        if self.body_in_bounds {
            if let Some(p) = body.iter().find(|p| !ws.bounds.contains(**p)) {
                return Verdict::OutOfBounds(if p.x < ws.bounds.min.x || p.x > ws.bounds.max.x { 0 } else { 1 });
            }
        }
        match if any { ws.any_obstacle_in_polygon(body) } else { ws.first_obstacle_in_polygon(body) } {
            Some(i) => Verdict::Collision(i),
            None => Verdict::Valid,
        }
    }
}

/// The kind's record ([`super::kinds`]).
pub const KIND: RobotKind = RobotKind {
    name: "rigid",
    label: "Rigid body",
    drawn: Drawn::Polygon,
    body: true,
    sensor: true,
    cspace: false,
    course_cost: None,
    pose: Pose::PositionHeading,
    solution_file: false,
    default_range: None,
};

impl Robot for RigidRobot {
    fn caps(&self) -> &'static RobotKind {
        &KIND
    }
    fn external_dims(&self) -> usize {
        3
    }
    fn space(&self, ws: &Workspace) -> StateSpace {
        let [x, y] = xy_dims(ws);
        StateSpace {
            dims: vec![x, y, Dim { lo: -PI, hi: PI, wraps: true }],
            metric: Metric::TranslationRotation { weight: self.rotation_weight },
        }
    }
    fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict {
        self.verdict_at(ws, q, false)
    }
    fn is_valid(&self, ws: &Workspace, q: &[Real]) -> bool {
        self.verdict_at(ws, q, true) == Verdict::Valid
    }
    fn project(&self, q: &[Real]) -> Vec2 {
        Vec2::new(q[0], q[1])
    }
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        let mut body = vec![Vec2::default(); self.footprint.len()];
        self.place(q, &mut body);
        vec![body]
    }
    fn motion(&self) -> Option<&dyn MotionModel> {
        Some(self)
    }
    fn body(&self) -> Option<&dyn WorkspaceBody> {
        Some(self)
    }
    fn sensor(&self) -> Option<&dyn Sensor> {
        Some(self)
    }
}

/// Motions are certified by clearances and a bound on how far a body point moves.
impl MotionModel for RigidRobot {
    fn clearance(&self, ws: &Workspace, q: &[Real], cap: Real) -> Option<Real> {
        if xy_in_bounds(ws, q).is_some() {
            return Some(0.0);
        }
        let n = self.footprint.len();
        let mut heap;
        let mut stack = [Vec2::default(); STACK_VERTICES];
        let body: &mut [Vec2] = if n <= STACK_VERTICES {
            &mut stack[..n]
        } else {
            heap = vec![Vec2::default(); n];
            &mut heap
        };
        self.place(q, body);
        let mut cap = cap;
        if self.body_in_bounds {
            let b = ws.bounds;
            for p in body.iter() {
                let inside = (p.x - b.min.x).at_most(b.max.x - p.x).at_most(p.y - b.min.y).at_most(b.max.y - p.y);
                cap = cap.at_most(inside.at_least(0.0));
            }
        }
        Some(if cap == 0.0 { 0.0 } else { ws.polygon_clearance(body, cap) })
    }
    fn displacement_bound(&self, a: &[Real], b: &[Real]) -> Option<Real> {
        // A body point at distance ≤ radius from the origin moves at most |Δxy| + radius·|Δθ|.
        Some(
            ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
                + self.radius * crate::math::angle_diff(a[2], b[2]).abs(),
        )
    }
}

impl WorkspaceBody for RigidRobot {
    fn size(&self) -> (Real, Real) {
        let l = self.footprint.iter().map(|p| p.x.abs()).fold(0.0, Real::max);
        let w = self.footprint.iter().map(|p| p.y.abs()).fold(0.0, Real::max);
        (2.0 * l, 2.0 * w)
    }
    fn obstacle_clearance(&self, ws: &Workspace, q: &[Real], cap: Real) -> Real {
        self.outline(q).iter().map(|poly| ws.polygon_clearance(poly, cap)).fold(cap, Real::min)
    }
}

/// At the body origin, looking along the body's x axis (heading θ).
impl Sensor for RigidRobot {
    fn pose(&self, q: &[Real]) -> SensorPose {
        SensorPose { at: Vec2::new(q[0], q[1]), heading: Some(q[2]) }
    }
}

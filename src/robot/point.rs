use super::capability::{all_around, MotionModel, Sensor, WorkspaceBody};
use super::{xy_dims, xy_in_bounds, Robot, Verdict};
use crate::geometry::{SensorPose, Workspace};
use crate::math::{Real, Vec2};
use crate::robot::kinds::{Drawn, Pose, RobotKind};
use crate::space::{Metric, StateSpace};

/// A point robot; state `[x, y]`.
#[derive(Clone, Copy, Debug, Default)]
pub struct PointRobot;

/// The kind's record ([`super::kinds`]).
pub const KIND: RobotKind = RobotKind {
    name: "point",
    label: "Point robot",
    drawn: Drawn::Point,
    body: true,
    sensor: true,
    cspace: false,
    course_cost: None,
    pose: Pose::Position,
    solution_file: false,
    default_range: None,
};

impl Robot for PointRobot {
    fn caps(&self) -> &'static RobotKind {
        &KIND
    }
    fn external_dims(&self) -> usize {
        2
    }
    fn space(&self, ws: &Workspace) -> StateSpace {
        StateSpace { dims: xy_dims(ws).to_vec(), metric: Metric::Euclidean }
    }
    fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict {
        if let Some(v) = xy_in_bounds(ws, q) {
            return v;
        }
        match ws.first_obstacle_at(Vec2::new(q[0], q[1])) {
            Some(i) => Verdict::Collision(i),
            None => Verdict::Valid,
        }
    }
    fn is_valid(&self, ws: &Workspace, q: &[Real]) -> bool {
        xy_in_bounds(ws, q).is_none() && !ws.point_blocked(Vec2::new(q[0], q[1]))
    }
    fn project(&self, q: &[Real]) -> Vec2 {
        Vec2::new(q[0], q[1])
    }
    fn outline(&self, _q: &[Real]) -> Vec<Vec<Vec2>> {
        Vec::new()
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

/// A motion is a segment, tested exactly.
impl MotionModel for PointRobot {
    fn sweep_hits(&self, ws: &Workspace, a: &[Real], b: &[Real]) -> Option<bool> {
        Some(ws.segment_blocked(Vec2::new(a[0], a[1]), Vec2::new(b[0], b[1])))
    }
}

impl WorkspaceBody for PointRobot {
    fn size(&self) -> (Real, Real) {
        (0.0, 0.0)
    }
    fn obstacle_clearance(&self, ws: &Workspace, q: &[Real], cap: Real) -> Real {
        let p = self.project(q);
        ws.segment_clearance(p, p, cap)
    }
}

/// At the point, seeing all around.
impl Sensor for PointRobot {
    fn pose(&self, q: &[Real]) -> SensorPose {
        all_around(self.project(q))
    }
}

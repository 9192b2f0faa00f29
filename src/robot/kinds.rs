//! The robot kinds as data: what the page may do with each (how it is drawn, whether it has a body
//! for workspace planners, a sensor, a configuration-space view, a course cost unit, a pose to
//! drag), published to the page (`wasm::robot_kinds`), so the page never compares kind names.
//! Each robot's [`Robot::caps`](super::Robot::caps) returns its record; [`KINDS`] lists them all.

/// How a robot is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Drawn {
    /// A dot at its reference point.
    Point,
    /// Closed polygons (a rigid body's footprint).
    Polygon,
    /// One open polyline with joints (an arm: base, joints, end).
    OpenChain,
    /// A chain whose ends are joined (a vehicle chain: vehicles joined by brooms, the closing
    /// edge dashed).
    ClosedChain,
    /// A chain of convex solids in 3-D (a spatial arm); seen from above, its skeleton.
    SpatialArm,
}

impl Drawn {
    /// The name the page reads.
    pub fn as_str(self) -> &'static str {
        match self {
            Drawn::Point => "point",
            Drawn::Polygon => "polygon",
            Drawn::OpenChain => "open-chain",
            Drawn::ClosedChain => "closed-chain",
            Drawn::SpatialArm => "spatial-arm",
        }
    }
}

/// What the page may drag of a start or goal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pose {
    /// Nothing: the state is edited another way (a vehicle chain's).
    None,
    /// Its position `[x, y]`.
    Position,
    /// Its position `[x, y]` and heading (the third coordinate, turned by a handle).
    PositionHeading,
    /// Its joint angles (sliders), seen by its end effector.
    Joints,
}

impl Pose {
    /// The name the page reads.
    pub fn as_str(self) -> &'static str {
        match self {
            Pose::None => "none",
            Pose::Position => "position",
            Pose::PositionHeading => "position-heading",
            Pose::Joints => "joints",
        }
    }
}

/// A robot kind's record.
#[derive(Clone, Copy, Debug)]
pub struct RobotKind {
    /// The `robot.kind` of the scenario format.
    pub name: &'static str,
    /// A human title.
    pub label: &'static str,
    /// How it is drawn.
    pub drawn: Drawn,
    /// It has a body in the plane, for workspace planners ([`super::WorkspaceBody`]); its paths
    /// are polylines in the plane (the visibility graph's optimum applies).
    pub body: bool,
    /// It has a sensor, for inspection ([`super::Sensor`]).
    pub sensor: bool,
    /// Its first two planning coordinates are joint angles worth a configuration-space view,
    /// when it has exactly two.
    pub cspace: bool,
    /// The course's own unit of path cost, reported beside the metric's (`fk`: report 004's).
    pub course_cost: Option<&'static str>,
    /// What the page may drag of a start or goal.
    pub pose: Pose,
    /// Its solved paths can be written as the course's solution file, and are animated in that
    /// file's primitive steps.
    pub solution_file: bool,
    /// The range-step planners' default step when a run leaves `range` at 0, where OMPL's (0.2 ×
    /// the space's extent) does not serve the robot; `None`: OMPL's.
    pub default_range: Option<crate::math::Real>,
}

impl RobotKind {
    /// As JSON for the page.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "name": self.name, "label": self.label, "drawn": self.drawn.as_str(), "body": self.body,
            "sensor": self.sensor, "cspace": self.cspace, "course_cost": self.course_cost,
            "pose": self.pose.as_str(), "solution_file": self.solution_file,
            "default_range": self.default_range,
        })
    }
}

/// Every robot kind.
pub static KINDS: &[RobotKind] =
    &[super::point::KIND, super::rigid::KIND, super::arm::KIND, super::asv::KIND, super::spatial::KIND];

/// A kind by name.
pub fn find(name: &str) -> Option<&'static RobotKind> {
    KINDS.iter().find(|k| k.name == name)
}

/// The kinds as JSON (`[{name, label, drawn, body, sensor, cspace, course_cost, pose,
/// solution_file}]`).
pub fn kinds_json() -> String {
    serde_json::to_string(&KINDS.iter().map(RobotKind::to_json).collect::<Vec<_>>()).expect("kinds serialise")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kind's record agrees with its robot's capabilities.
    #[test]
    fn records_agree_with_the_robots() {
        let robots: Vec<_> = ["narrow", "hex-open", "arm-2", "asv-3", "puma-boxes"]
            .iter()
            .map(|id| super::super::from_spec(&crate::scenario::builtin(id).unwrap().robot, true).unwrap())
            .collect();
        for r in &robots {
            let k = r.caps();
            assert_eq!(k.name, r.kind());
            assert_eq!(k.body, r.body().is_some(), "{}", k.name);
            assert_eq!(k.sensor, r.sensor().is_some(), "{}", k.name);
            assert!(std::ptr::eq(find(k.name).unwrap(), find(r.kind()).unwrap()));
        }
        let names: Vec<_> = KINDS.iter().map(|k| k.name).collect();
        assert_eq!(names, ["point", "rigid", "arm", "asv", "spatial-arm"]);
        let drawn: Vec<_> = robots.iter().map(|r| r.caps().drawn).collect();
        assert_eq!(drawn, [Drawn::Point, Drawn::Polygon, Drawn::OpenChain, Drawn::ClosedChain, Drawn::SpatialArm]);
        assert_eq!(robots.iter().filter(|r| r.spatial().is_some()).count(), 1, "only the spatial arm is drawn in 3-D");
    }
}

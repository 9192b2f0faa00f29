//! The fixed-base planar arm (courses.md §4–§6). Work in progress: see issue 3.

use super::{Robot, Verdict};
use crate::geometry::Workspace;
use crate::math::{Real, Vec2};
use crate::scenario::RobotSpec;
use crate::space::StateSpace;

/// A fixed-base planar arm.
#[derive(Clone, Debug)]
pub struct ArmRobot {
    count: usize,
}

impl ArmRobot {
    /// The robot a scenario's `asv` block describes.
    pub fn from_spec(spec: &RobotSpec) -> Result<Self, String> {
        match spec {
            RobotSpec::Arm { .. } => Err("robot kind \"arm\" is not supported by this build yet".into()),
            _ => Err("not an arm".into()),
        }
    }
}

impl Robot for ArmRobot {
    fn kind(&self) -> &'static str {
        "arm"
    }
    fn external_dims(&self) -> usize {
        self.count
    }
    fn space(&self, _ws: &Workspace) -> StateSpace {
        unreachable!("ArmRobot cannot be built yet")
    }
    fn verdict(&self, _ws: &Workspace, _q: &[Real]) -> Verdict {
        Verdict::Invalid("not supported yet")
    }
    fn project(&self, q: &[Real]) -> Vec2 {
        Vec2::new(q[0], q[1])
    }
    fn outline(&self, _q: &[Real]) -> Vec<Vec<Vec2>> {
        Vec::new()
    }
}

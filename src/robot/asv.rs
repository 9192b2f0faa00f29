//! The broom-joined vehicle chain (courses.md §1). Work in progress: see issue 3.

use super::{Robot, Verdict};
use crate::geometry::Workspace;
use crate::math::{Real, Vec2};
use crate::scenario::RobotSpec;
use crate::space::StateSpace;

/// A chain of vehicles joined by brooms.
#[derive(Clone, Debug)]
pub struct AsvRobot {
    count: usize,
}

impl AsvRobot {
    /// The robot a scenario's `asv` block describes.
    pub fn from_spec(spec: &RobotSpec) -> Result<Self, String> {
        match spec {
            RobotSpec::Asv { .. } => Err("robot kind \"asv\" is not supported by this build yet".into()),
            _ => Err("not an asv robot".into()),
        }
    }
}

impl Robot for AsvRobot {
    fn kind(&self) -> &'static str {
        "asv"
    }
    fn external_dims(&self) -> usize {
        2 * self.count
    }
    fn space(&self, _ws: &Workspace) -> StateSpace {
        unreachable!("AsvRobot cannot be built yet")
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

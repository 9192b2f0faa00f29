//! State validity: a robot placed in a workspace (OMPL's `StateValidityChecker`).
//!
//! The checker is the robot's core ([`Robot::verdict`], [`Robot::is_valid`]) bound to the
//! workspace; it re-declares nothing else. What a robot can do beyond validity (its motion model,
//! sampler, body, sensor) is asked of the robot itself: see [`crate::robot::capability`], and the
//! accessors of [`SpaceInfo`](crate::space_info::SpaceInfo), which also count the checks.

use crate::geometry::Workspace;
use crate::math::Real;
use crate::robot::{Robot, Verdict};

/// A robot placed in a workspace: the problem's state validity checker.
#[derive(Debug)]
pub struct RobotInWorkspace {
    /// The robot (shared with the [`Problem`](crate::problem::Problem)).
    pub robot: std::rc::Rc<dyn Robot>,
    /// The workspace.
    pub workspace: Workspace,
}

impl RobotInWorkspace {
    /// Whether `q` is valid, and if not, why.
    #[inline]
    pub fn verdict(&self, q: &[Real]) -> Verdict {
        self.robot.verdict(&self.workspace, q)
    }
    /// Whether `q` is valid.
    #[inline]
    pub fn is_valid(&self, q: &[Real]) -> bool {
        self.robot.is_valid(&self.workspace, q)
    }
}

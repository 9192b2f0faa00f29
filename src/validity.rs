//! State validity: a robot in a workspace, and the counter of state checks.

use crate::geometry::{SensorPose, Workspace};
use crate::math::{Real, Vec2};
use crate::robot::{Robot, Verdict};

/// Answers whether states are valid (OMPL's `StateValidityChecker`).
pub trait StateValidity {
    /// Whether `q` is valid, and if not, why.
    fn verdict(&self, q: &[Real]) -> Verdict;
    /// Whether `q` is valid.
    fn is_valid(&self, q: &[Real]) -> bool {
        self.verdict(q) == Verdict::Valid
    }
    /// The discrete check of a motion, as [`Robot::check_discrete`] describes it.
    #[allow(clippy::too_many_arguments)]
    fn check_discrete(
        &self,
        space: &crate::space::StateSpace,
        a: &[Real],
        b: &[Real],
        n: usize,
        scratch: &mut [Real],
        skip: u64,
        stop: &dyn Fn(u64) -> bool,
    ) -> (crate::motion::Discrete, u64);
    /// Exact swept test of the straight motion `a → b`, when one exists (`Some(true)`: it hits).
    fn sweep_hits(&self, a: &[Real], b: &[Real]) -> Option<bool>;
    /// The workspace point a state is drawn at.
    fn project(&self, q: &[Real]) -> Vec2;
    /// A random state (the robot's sampler).
    fn sample(&self, space: &crate::space::StateSpace, rng: &mut crate::rng::Rng, out: &mut [Real]) -> u64;
    /// A Gaussian neighbour drawn the robot's own way, if it has one (`false`: it has none).
    fn sample_gaussian(
        &self,
        space: &crate::space::StateSpace,
        rng: &mut crate::rng::Rng,
        centre: &[Real],
        sigma: Real,
        out: &mut [Real],
    ) -> bool;
    /// Steps a motion of length `d` is checked in (`None`: more than can be checked; see
    /// [`Robot::motion_steps`]).
    fn motion_steps(&self, a: &[Real], b: &[Real], d: Real, resolution: Real) -> Option<usize>;
    /// Distance to the nearest obstacle capped at `cap` (0: invalid), when the robot has it.
    fn clearance(&self, q: &[Real], cap: Real) -> Option<Real>;
    /// Bound on how far any body point moves along `a → b`, for robots with a clearance.
    fn displacement_bound(&self, a: &[Real], b: &[Real]) -> Option<Real>;
    /// The robot's sensor at `q` (inspection tasks).
    fn sensor(&self, q: &[Real]) -> SensorPose;
    /// Whether the sight line `a → b` passes through no obstacle's interior (touching allowed; see
    /// [`crate::geometry::sight`]).
    fn sight_clear(&self, a: Vec2, b: Vec2) -> bool;
    /// The workspace, for planners that work in it (cell decomposition, potential fields).
    fn workspace(&self) -> Option<&Workspace> {
        None
    }
    /// The clearance of `q` on the motion `a → b` in units of the motion's parameter, when the
    /// robot bounds its parts' speeds per motion (see [`Robot::motion_clearance`]).
    fn motion_clearance(&self, _a: &[Real], _b: &[Real], _q: &[Real], _cap: Real) -> Option<Real> {
        None
    }
    /// Whether [`motion_clearance`](StateValidity::motion_clearance) is supported.
    fn has_motion_clearance(&self) -> bool {
        false
    }
    /// The body's outline at `q` (closed polygons; none for a point).
    fn outline(&self, _q: &[Real]) -> Vec<Vec<Vec2>> {
        Vec::new()
    }
    /// The body's length and width, for a mobile body (see [`Robot::body_size`]).
    fn body_size(&self) -> Option<(Real, Real)> {
        None
    }
}

/// A robot placed in a workspace.
#[derive(Debug)]
pub struct RobotInWorkspace {
    /// The robot (shared with the [`Problem`](crate::problem::Problem)).
    pub robot: std::rc::Rc<dyn Robot>,
    /// The workspace.
    pub workspace: Workspace,
}

impl StateValidity for RobotInWorkspace {
    fn verdict(&self, q: &[Real]) -> Verdict {
        self.robot.verdict(&self.workspace, q)
    }
    fn is_valid(&self, q: &[Real]) -> bool {
        self.robot.is_valid(&self.workspace, q)
    }
    fn check_discrete(
        &self,
        space: &crate::space::StateSpace,
        a: &[Real],
        b: &[Real],
        n: usize,
        scratch: &mut [Real],
        skip: u64,
        stop: &dyn Fn(u64) -> bool,
    ) -> (crate::motion::Discrete, u64) {
        self.robot.check_discrete(&self.workspace, space, a, b, n, scratch, skip, stop)
    }
    fn sweep_hits(&self, a: &[Real], b: &[Real]) -> Option<bool> {
        self.robot.sweep_hits(&self.workspace, a, b)
    }
    fn project(&self, q: &[Real]) -> Vec2 {
        self.robot.project(q)
    }
    fn sample(&self, space: &crate::space::StateSpace, rng: &mut crate::rng::Rng, out: &mut [Real]) -> u64 {
        self.robot.sample(space, rng, out)
    }
    fn sample_gaussian(
        &self,
        space: &crate::space::StateSpace,
        rng: &mut crate::rng::Rng,
        centre: &[Real],
        sigma: Real,
        out: &mut [Real],
    ) -> bool {
        self.robot.sample_gaussian(space, rng, centre, sigma, out)
    }
    fn motion_steps(&self, a: &[Real], b: &[Real], d: Real, resolution: Real) -> Option<usize> {
        self.robot.motion_steps(a, b, d, resolution)
    }
    fn clearance(&self, q: &[Real], cap: Real) -> Option<Real> {
        self.robot.clearance(&self.workspace, q, cap)
    }
    fn displacement_bound(&self, a: &[Real], b: &[Real]) -> Option<Real> {
        self.robot.displacement_bound(a, b)
    }
    fn sensor(&self, q: &[Real]) -> SensorPose {
        self.robot.sensor(q)
    }
    fn sight_clear(&self, a: Vec2, b: Vec2) -> bool {
        self.workspace.sight_clear(a, b)
    }
    fn workspace(&self) -> Option<&Workspace> {
        Some(&self.workspace)
    }
    fn motion_clearance(&self, a: &[Real], b: &[Real], q: &[Real], cap: Real) -> Option<Real> {
        self.robot.motion_clearance(&self.workspace, a, b, q, cap)
    }
    fn has_motion_clearance(&self) -> bool {
        self.robot.has_motion_clearance()
    }
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        self.robot.outline(q)
    }
    fn body_size(&self) -> Option<(Real, Real)> {
        self.robot.body_size()
    }
}

//! Robots: what a state means in the workspace.
//!
//! The generic entry is the [`Robot`] trait: a robot knows its state space, whether a state is
//! valid in a [`Workspace`], where to draw a state (its reference point), and, when it can, an exact
//! test for a straight motion. [`from_spec`] builds one from the scenario's robot block.

mod arm;
mod asv;
mod point;
mod rigid;

pub use arm::ArmRobot;
pub use asv::AsvRobot;
pub use point::PointRobot;
pub use rigid::RigidRobot;

use crate::geometry::{SensorPose, Workspace};
use crate::math::{Real, Vec2};
use crate::scenario::RobotSpec;
use crate::space::StateSpace;

/// Why a state is or is not valid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Free and in bounds.
    Valid,
    /// State dimension `0` (or a body point) is outside the bounds.
    OutOfBounds(usize),
    /// The robot meets obstacle `i` (index into the scenario's `obstacles`).
    Collision(usize),
    /// The robot breaks one of its own rules (self-collision, a joint limit, a broom's length…).
    Invalid(&'static str),
}

/// A robot in a planar workspace.
pub trait Robot: std::fmt::Debug {
    /// The `robot.kind` of the scenario format.
    fn kind(&self) -> &'static str;
    /// The robot's state space over the workspace's bounds.
    fn space(&self, ws: &Workspace) -> StateSpace;
    /// How many numbers a state has in the scenario format (start, goal, path points).
    fn external_dims(&self) -> usize;
    /// The planning state of a scenario state (identity unless the robot plans in another
    /// parameterisation, as the vehicle chain does); an error says why the state is not one.
    fn encode(&self, external: &[Real]) -> Result<Vec<Real>, String> {
        Ok(external.to_vec())
    }
    /// The scenario state of a planning state (the inverse of [`encode`](Robot::encode)).
    fn decode(&self, q: &[Real]) -> Vec<Real> {
        q.to_vec()
    }
    /// Whether state `q` is valid in `ws`, and if not, why.
    fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict;
    /// Whether state `q` is valid in `ws` (the verdict without its reason: robots whose check is a
    /// few comparisons answer it without building one).
    fn is_valid(&self, ws: &Workspace, q: &[Real]) -> bool {
        self.verdict(ws, q) == Verdict::Valid
    }
    /// The discrete check of the motion `a → b` in `n` steps ([`crate::motion::check_discrete`]).
    /// It is entered once per motion, so that the loop calls each robot's own `is_valid`
    /// directly (in wasm, a dynamic call per state cost more than the point robot's check itself).
    /// It resumes after `skip` states and calls `stop` as it goes (see the function).
    #[allow(clippy::too_many_arguments)]
    fn check_discrete(
        &self,
        ws: &Workspace,
        space: &StateSpace,
        a: &[Real],
        b: &[Real],
        n: usize,
        scratch: &mut [Real],
        skip: u64,
        stop: &dyn Fn(u64) -> bool,
    ) -> (crate::motion::Discrete, u64) {
        crate::motion::check_discrete(space, a, b, n, scratch, skip, stop, |q| self.is_valid(ws, q))
    }
    /// Write a random state into `out` (default: uniform over the space) and return the state
    /// checks it spent (counted like the planner's). Robots whose uniform samples are almost never
    /// valid (the vehicle chain) sample their own way.
    fn sample(&self, space: &StateSpace, rng: &mut crate::rng::Rng, out: &mut [Real]) -> u64 {
        space.sample_uniform(rng, out);
        0
    }
    /// Write into `out` a Gaussian neighbour of `centre` (spread `sigma` × each coordinate's range)
    /// drawn the robot's own way and return `true`; the default returns `false`, and samplers move
    /// every coordinate independently.
    fn sample_gaussian(
        &self,
        _space: &StateSpace,
        _rng: &mut crate::rng::Rng,
        _centre: &[Real],
        _sigma: Real,
        _out: &mut [Real],
    ) -> bool {
        false
    }
    /// How many steps a motion `a → b` of length `d` is checked in (default: `ceil(d / resolution)`);
    /// a robot with its own step rule (no vehicle moves more than `max_step`) overrides it. `None`
    /// when the count is not a number or exceeds [`crate::limits::MAX_MOTION_STEPS`] (the problem's
    /// checks make that unreachable for states in bounds; the motion is then refused, never
    /// checked more coarsely).
    fn motion_steps(&self, _a: &[Real], _b: &[Real], d: Real, resolution: Real) -> Option<usize> {
        crate::limits::steps(d, resolution, crate::limits::MAX_MOTION_STEPS)
    }
    /// The point of the workspace a state is drawn at (trees are projected onto it).
    fn project(&self, q: &[Real]) -> Vec2;
    /// An exact test of the straight motion `a → b`, when the robot has one: `Some(true)` if the
    /// swept body meets an obstacle. Used on top of the discrete checks so no motion cuts a corner.
    fn sweep_hits(&self, _ws: &Workspace, _a: &[Real], _b: &[Real]) -> Option<bool> {
        None
    }
    /// The distance from the body at `q` to the nearest obstacle (and, where the body must stay in
    /// bounds, to the bounds), capped at `cap`; 0 when `q` is invalid. `None` for robots whose
    /// motions are checked by [`sweep_hits`](Robot::sweep_hits) instead.
    fn clearance(&self, _ws: &Workspace, _q: &[Real], _cap: Real) -> Option<Real> {
        None
    }
    /// The clearance of state `q` on the straight motion `a → b`, in units of the motion's
    /// parameter `t ∈ [0, 1]` (each distance divided by a bound on how fast it can close along
    /// this motion), capped at `cap`; 0 when `q` is invalid. Robots that bound their parts' speeds
    /// separately (an arm: links near the base move less, neighbouring links barely move relative
    /// to each other) certify motions with it instead of [`clearance`](Robot::clearance) and one
    /// [`displacement_bound`](Robot::displacement_bound). `None`: not supported.
    fn motion_clearance(&self, _ws: &Workspace, _a: &[Real], _b: &[Real], _q: &[Real], _cap: Real) -> Option<Real> {
        None
    }
    /// Whether [`motion_clearance`](Robot::motion_clearance) is supported.
    fn has_motion_clearance(&self) -> bool {
        false
    }
    /// A bound on how far any point of the body moves along the straight motion `a → b` (linear
    /// in the fraction travelled), used with [`clearance`](Robot::clearance) to certify motions.
    /// `None` when the robot has no clearance.
    fn displacement_bound(&self, _a: &[Real], _b: &[Real]) -> Option<Real> {
        None
    }
    /// The body's outline at state `q`, as closed polygons in world coordinates (for drawing and
    /// exports); a point robot has none.
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>>;
    /// For a mobile body moving along its heading (workspace planners: hexagonal decomposition,
    /// potential fields): the length `l` (along the body's x axis) and width `w` of the smallest
    /// rectangle centred on the rotation point that holds the body. `None`: not a mobile body.
    fn body_size(&self) -> Option<(Real, Real)> {
        None
    }
    /// Where the robot's sensor is at state `q` and which way it looks (inspection tasks; see
    /// [`crate::geometry::sight`] for what it sees). Default: at the reference point
    /// ([`project`](Robot::project)), seeing all around.
    fn sensor(&self, q: &[Real]) -> SensorPose {
        SensorPose { at: self.project(q), heading: None }
    }
}

/// Build the robot a scenario describes; an error names a robot this build cannot plan for.
pub fn from_spec(spec: &RobotSpec, body_in_bounds: bool) -> Result<Box<dyn Robot>, String> {
    Ok(match spec {
        RobotSpec::Point => Box::new(PointRobot),
        RobotSpec::Rigid { footprint, rotation_weight } => Box::new(RigidRobot::new(
            footprint.iter().map(|p| Vec2::new(p[0], p[1])).collect(),
            *rotation_weight,
            body_in_bounds,
        )),
        RobotSpec::Arm { .. } => Box::new(ArmRobot::from_spec(spec)?),
        RobotSpec::Asv { .. } => Box::new(AsvRobot::from_spec(spec)?),
    })
}

/// The translation dimensions over the workspace bounds.
fn xy_dims(ws: &Workspace) -> [crate::space::Dim; 2] {
    let b = ws.bounds;
    [
        crate::space::Dim { lo: b.min.x, hi: b.max.x, wraps: false },
        crate::space::Dim { lo: b.min.y, hi: b.max.y, wraps: false },
    ]
}

/// Whether the reference point `[x, y]` is inside the bounds (`OutOfBounds` names the dimension).
fn xy_in_bounds(ws: &Workspace, q: &[Real]) -> Option<Verdict> {
    let b = ws.bounds;
    if q[0] < b.min.x || q[0] > b.max.x {
        Some(Verdict::OutOfBounds(0))
    } else if q[1] < b.min.y || q[1] > b.max.y {
        Some(Verdict::OutOfBounds(1))
    } else {
        None
    }
}

#[cfg(test)]
mod tests;

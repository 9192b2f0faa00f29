//! Robots: what a state means in the workspace.
//!
//! The core is the [`Robot`] trait: a robot knows its state space, whether a state is valid in a
//! [`Workspace`] (OMPL's state validity checker), how a state is written in the scenario format,
//! and how it is drawn (its reference point and outline). Everything else is a capability
//! ([`capability`]): a [`MotionModel`] (how its motions are checked), an [`OwnSampler`], a
//! [`WorkspaceBody`] for workspace planners, a [`Sensor`]; `Robot` hands each out through one
//! accessor, `None` when the robot lacks it. [`from_spec`] builds a robot from the scenario's
//! robot block.
//!
//! | robot | motion model | own sampler | workspace body | sensor |
//! |---|---|---|---|---|
//! | [`PointRobot`] | exact sweep | – | 0 × 0 | all around |
//! | [`RigidRobot`] | clearance + displacement bound | – | its footprint's box | along its x axis |
//! | [`ArmRobot`] | clearance per motion | – | – | along the last link |
//! | [`AsvRobot`] | own steps, clearance + bound | yes | – | all around, at the centroid |
//! | [`SpatialArmRobot`] | discrete steps | – | – | – |

mod arm;
mod asv;
pub mod capability;
pub mod kinds;
mod point;
mod rigid;
pub mod spatial;

pub use arm::{fk_path_cost, ArmRobot};
pub use asv::AsvRobot;
pub use capability::{Contact, DiscreteOnly, MotionModel, OwnSampler, PartMesh, Sensor, Spatial, WorkspaceBody};
pub use point::PointRobot;
pub use rigid::RigidRobot;
pub use spatial::SpatialArmRobot;

use crate::geometry::Workspace;
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

/// A robot in a planar workspace: what every robot has. Capabilities (see [`capability`]) are
/// handed out by the accessors at the end, `None` by default.
pub trait Robot: std::fmt::Debug {
    /// Its kind's record: what the page may do with it ([`kinds`]).
    fn caps(&self) -> &'static kinds::RobotKind;
    /// The `robot.kind` of the scenario format.
    fn kind(&self) -> &'static str {
        self.caps().name
    }
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
    /// The discrete check of the motion `a → b` in `n` steps ([`crate::space::check_discrete`]).
    /// Robots keep this default: it is entered once per motion, so that the loop calls each
    /// robot's own `is_valid` directly (in wasm, a dynamic call per state cost more than the point
    /// robot's check itself). It resumes after `skip` states and calls `stop` as it goes (see the
    /// function).
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
    ) -> (crate::space::Discrete, u64) {
        crate::space::check_discrete(space, a, b, n, scratch, skip, stop, |q| self.is_valid(ws, q))
    }
    /// What state `q` collides with, in words, when the robot can say more than its verdict does
    /// ("link6's bar meets the lintel"); `None` when it cannot or `q` is free.
    fn describe_collision(&self, _ws: &Workspace, _q: &[Real]) -> Option<String> {
        None
    }
    /// The point of the workspace a state is drawn at (trees are projected onto it).
    fn project(&self, q: &[Real]) -> Vec2;
    /// The body's outline at state `q` in world coordinates (for drawing and exports): closed
    /// polygons for a robot with a [`body`](Robot::body) (a rigid body), one open polyline for a
    /// chain of segments (an arm's base, joints and end; a vehicle chain's vehicles, joined by
    /// brooms); a point robot has none.
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>>;

    /// How its motions are checked; `None`: discrete checks only ([`DiscreteOnly`]).
    fn motion(&self) -> Option<&dyn MotionModel> {
        None
    }
    /// Its own state sampler; `None`: uniform samples, Gaussian neighbours per coordinate.
    fn sampler(&self) -> Option<&dyn OwnSampler> {
        None
    }
    /// Its body as a workspace planner sees it; `None`: not a mobile body in the plane.
    fn body(&self) -> Option<&dyn WorkspaceBody> {
        None
    }
    /// Its sensor (inspection tasks); `None`: it has none.
    fn sensor(&self) -> Option<&dyn Sensor> {
        None
    }
    /// Its 3-D geometry for drawing (a spatial arm); `None`: it moves in the plane.
    fn spatial(&self) -> Option<&dyn Spatial> {
        None
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
        RobotSpec::SpatialArm(_) => Box::new(SpatialArmRobot::from_spec(spec)?),
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

//! What a robot may have beyond the core [`Robot`](super::Robot): one trait per capability, each
//! asked for through one accessor of `Robot` (and of [`SpaceInfo`](crate::space_info::SpaceInfo)),
//! which answers `None` when the robot lacks it. The split follows OMPL's concepts where they fit:
//! the core is the state validity checker, [`MotionModel`] the robot's side of the motion
//! validator, [`OwnSampler`] a state sampler of its own.
//!
//! A new capability is one trait here and one accessor on `Robot` (defaulting to `None`), and one
//! on `SpaceInfo` for planners.

use crate::geometry::{SensorPose, Workspace};
use crate::math::{Real, Vec2};
use crate::space::StateSpace;

/// How the robot's straight motions are checked and certified (see [`crate::motion`]). Every
/// method has a default: discrete checks at the motion resolution, nothing more (OMPL's
/// `DiscreteMotionValidator`); [`DiscreteOnly`] is that model, for robots without one.
pub trait MotionModel {
    /// How many steps a motion `a → b` of length `d` is checked in (default: `ceil(d / resolution)`);
    /// a robot with its own step rule (no vehicle moves more than `max_step`) overrides it. `None`
    /// when the count is not a number or exceeds [`crate::limits::MAX_MOTION_STEPS`] (the problem's
    /// checks make that unreachable for states in bounds; the motion is then refused, never
    /// checked more coarsely).
    fn steps(&self, _a: &[Real], _b: &[Real], d: Real, resolution: Real) -> Option<usize> {
        crate::limits::steps(d, resolution, crate::limits::MAX_MOTION_STEPS)
    }
    /// Where the straight motion `a → b` passes through a state the robot refuses whatever the
    /// obstacles (the fraction of the motion), when the robot can tell without checking states:
    /// such a motion is refused at once (default: `None`, nothing known).
    fn refused_at(&self, _a: &[Real], _b: &[Real]) -> Option<Real> {
        None
    }
    /// An exact test of the straight motion `a → b`, when the robot has one: `Some(true)` if the
    /// swept body meets an obstacle. Used on top of the discrete checks so no motion cuts a corner.
    fn sweep_hits(&self, _ws: &Workspace, _a: &[Real], _b: &[Real]) -> Option<bool> {
        None
    }
    /// The distance from the body at `q` to the nearest obstacle (and, where the body must stay in
    /// bounds, to the bounds), capped at `cap`; 0 when `q` is invalid. `None` for robots whose
    /// motions are checked by [`sweep_hits`](MotionModel::sweep_hits) instead.
    fn clearance(&self, _ws: &Workspace, _q: &[Real], _cap: Real) -> Option<Real> {
        None
    }
    /// A bound on how far any point of the body moves along the straight motion `a → b` (linear
    /// in the fraction travelled), used with [`clearance`](MotionModel::clearance) to certify
    /// motions. `None` when the robot has no clearance.
    fn displacement_bound(&self, _a: &[Real], _b: &[Real]) -> Option<Real> {
        None
    }
    /// The clearance of state `q` on the straight motion `a → b`, in units of the motion's
    /// parameter `t ∈ [0, 1]` (each distance divided by a bound on how fast it can close along
    /// this motion), capped at `cap`; 0 when `q` is invalid. Robots that bound their parts' speeds
    /// separately (an arm: links near the base move less, neighbouring links barely move relative
    /// to each other) certify motions with it instead of [`clearance`](MotionModel::clearance) and
    /// one [`displacement_bound`](MotionModel::displacement_bound). `None`: not supported.
    fn motion_clearance(&self, _ws: &Workspace, _a: &[Real], _b: &[Real], _q: &[Real], _cap: Real) -> Option<Real> {
        None
    }
    /// Whether [`motion_clearance`](MotionModel::motion_clearance) is supported.
    fn has_motion_clearance(&self) -> bool {
        false
    }
    /// Whether a walk along a line in steps of the resolution (the Robotics Library's connect,
    /// RRT-Connect's `last-free`) tests each step's configuration alone, one query per
    /// configuration, as the robot's course counted (the spatial arm), rather than each step's
    /// motion. The motions between steps are then certified on the path found, after planning
    /// (`run::certify`).
    fn walks_by_states(&self) -> bool {
        false
    }
    /// A factor `μ` by which every constraint of [`motion_clearance`](MotionModel::motion_clearance)
    /// closes at most `μ` times as fast along the motion `a → b` as along `pa → pb`, so that a
    /// state's motion clearance `c` on `pa → pb` (a lower bound on each constraint's distance over
    /// its rate) is at least `c / μ` on `a → b`: a walk along a line carries its step's end
    /// clearance into the next step ([`SpaceInfo::check_step`](crate::space_info::SpaceInfo::check_step))
    /// rather than computing it again. Rounded up. `None` (the default): not known, the clearance
    /// is computed again.
    fn motion_rate_ratio(&self, _pa: &[Real], _pb: &[Real], _a: &[Real], _b: &[Real]) -> Option<Real> {
        None
    }
}

/// The motion model of a robot that has none of its own: discrete checks at the resolution.
#[derive(Clone, Copy, Debug, Default)]
pub struct DiscreteOnly;

impl MotionModel for DiscreteOnly {}

/// A robot that samples its own states (OMPL's `StateSampler`), for robots whose uniform samples
/// are almost never valid (the vehicle chain). Without one, samples are uniform over the space and
/// Gaussian neighbours move every coordinate independently.
pub trait OwnSampler {
    /// Write a random state into `out` and return the state checks it spent (counted like the
    /// planner's). `deadline_passed` reads the run's clock: a draw that takes many checks asks it
    /// between them and, once it says yes, gives up with what it has (the state written may be
    /// invalid; the run is ending).
    fn sample(
        &self,
        space: &StateSpace,
        rng: &mut crate::rng::Rng,
        out: &mut [Real],
        deadline_passed: &dyn Fn() -> bool,
    ) -> u64;
    /// Write into `out` a Gaussian neighbour of `centre` (spread `sigma` × each coordinate's
    /// range), drawn the robot's own way (OMPL's `StateSampler::sampleGaussian`).
    fn sample_gaussian(
        &self,
        space: &StateSpace,
        rng: &mut crate::rng::Rng,
        centre: &[Real],
        sigma: Real,
        out: &mut [Real],
    );
}

/// A mobile body in the workspace, moving along its heading, for the planners that plan in the
/// workspace rather than in configuration space (hexagonal decomposition, potential fields).
pub trait WorkspaceBody {
    /// The length `l` (along the body's x axis) and width `w` of the smallest rectangle centred on
    /// the rotation point that holds the body (a point: 0 × 0).
    fn size(&self) -> (Real, Real);
    /// The distance from the body at the valid state `q` to the nearest obstacle, capped at `cap`
    /// (the bounds do not count). For potential fields; not a motion certificate (see
    /// [`MotionModel::clearance`]).
    fn obstacle_clearance(&self, ws: &Workspace, q: &[Real], cap: Real) -> Real;
}

/// A sensor the robot carries (inspection tasks; see [`crate::geometry::sight`] for what it sees).
pub trait Sensor {
    /// Where the sensor is at state `q` and which way it looks.
    fn pose(&self, q: &[Real]) -> SensorPose;
}

/// A sensor at `at`, seeing all around.
pub(crate) fn all_around(at: Vec2) -> SensorPose {
    SensorPose { at, heading: None }
}

/// A robot in 3-D (a spatial arm): what a 3-D view draws, from the core's own kinematics.
pub trait Spatial {
    /// Every link frame's origin and the tool centre point at `q`, in the world.
    fn skeleton(&self, q: &[Real]) -> Vec<[Real; 3]>;
    /// The tool centre point at `q`, in the world.
    fn tool_point(&self, q: &[Real]) -> [Real; 3];
    /// The tool centre point at `points` evenly spread states of the straight motion from `a` by
    /// `delta` (per joint, as the space interpolates), both ends included (`a + delta` alone when
    /// `points` is 1): the curve the tool sweeps, for drawing (within 1e-12 m of
    /// [`tool_point`](Spatial::tool_point) at the same states, computed more cheaply).
    fn tool_sweep(&self, a: &[Real], delta: &[Real], points: usize) -> Vec<[Real; 3]>;
    /// The tool centre point in the last link's frame.
    fn tool(&self) -> [Real; 3];
    /// Every part the arm collides as (its links' hulls and boxes) as a triangle mesh in its
    /// link's frame: what a 3-D view draws, placed by [`link_frames`](Spatial::link_frames).
    fn part_meshes(&self) -> Vec<PartMesh>;
    /// Every link's frame in the world at `q` (link 0, the base, first; `joints + 1` of them),
    /// each a 4×4 homogeneous matrix, column-major (WebGL's order).
    fn link_frames(&self, q: &[Real]) -> Vec<[Real; 16]>;
    /// What collides at `q` and where ([`Contact`]); `None` when the arm is free (joint limits
    /// are not checked). For drawing and explaining.
    fn contact(&self, ws: &Workspace, q: &[Real]) -> Option<Contact>;
}

/// What collides at a state and where ([`Spatial::contact`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// The link (0: the base) of the part hit.
    pub link: usize,
    /// The other link, when two links meet.
    pub other: Option<usize>,
    /// The scene obstacle's index, when the arm meets the scene.
    pub solid: Option<usize>,
    /// A world point where they meet.
    pub at: [Real; 3],
}

/// One part of a spatial arm, for drawing.
#[derive(Clone, Debug)]
pub struct PartMesh {
    /// The link it is fixed to (0: the base).
    pub link: usize,
    /// Its name ("link6's bar").
    pub name: String,
    /// Its mesh, in the link's frame.
    pub mesh: crate::geometry::mesh::Mesh,
}

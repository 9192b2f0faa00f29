//! [`SpaceInfo`]: everything a planner may know about the problem's space, in one bundle
//! (OMPL's `SpaceInformation`). Planners import this, never scenario or robot types.
//!
//! One file per job: the bundle and the robot's capabilities (here); [`deadline`](Deadline) and
//! suspension (`deadline.rs`); the batch journal (`batch.rs`); the counted state questions and
//! their counters (`counters.rs`); motion checks, the [`MotionValidator`](crate::motion::MotionValidator)
//! (`motion.rs`); the explanation of a collision (`explain.rs`); sight (`sight.rs`).

use crate::clock::Instant;
use crate::journal::Journal;
use crate::math::{Real, Vec2};
use crate::robot::{DiscreteOnly, MotionModel, OwnSampler, Sensor, WorkspaceBody};
use crate::space::StateSpace;
use crate::validity::RobotInWorkspace;
use std::cell::{Cell, RefCell};

mod batch;
mod counters;
mod deadline;
mod explain;
mod motion;
mod sight;
#[cfg(test)]
mod tests;

pub use deadline::{Deadline, CLOCK_EVERY, SLOW_LOOK_MS};

/// The state space, validity checker and motion resolution, with the count of state checks.
///
/// The robot's capabilities are asked for here ([`motion_model`](SpaceInfo::motion_model),
/// [`own_sampler`](SpaceInfo::own_sampler), [`body`](SpaceInfo::body),
/// [`sensor`](SpaceInfo::sensor)): `None` when the robot lacks one (a robot without a motion model
/// has its motions checked discretely). Questions a planner decides by
/// go through the counted, journalled methods ([`is_valid`](SpaceInfo::is_valid),
/// [`sample`](SpaceInfo::sample), [`sees`](SpaceInfo::sees), motion checks); the capabilities'
/// own methods are neither counted nor journalled.
pub struct SpaceInfo {
    /// The state space.
    pub space: StateSpace,
    /// Largest step between two checked states along a motion, in the space's metric.
    pub resolution: Real,
    validity: RobotInWorkspace,
    /// State checks so far.
    checks: Cell<u64>,
    /// Of those, the ones that found the state valid (see [`SpaceInfo::free_checks`]).
    free: Cell<u64>,
    /// Scratch for the clearances along a motion (reused, so checking does not allocate).
    clearances: RefCell<Vec<Real>>,
    /// The last step of a walk along a line: its motion and the clearance at its end, carried
    /// into the next step (see [`SpaceInfo::check_step`]).
    carry: RefCell<motion::Carry>,
    /// The run's deadline (see [`Deadline`]), and whether work was cut short by it.
    deadline: Cell<Deadline>,
    interrupted: Cell<bool>,
    /// Units of work since the clock was last read, the units between two reads, and the last read.
    ticks: Cell<u64>,
    every: Cell<u64>,
    last_look: Cell<Option<Instant>>,
    /// The bounded batch's journal (see [`crate::journal`]), whether it is in use, when the batch
    /// is suspended, whether it was, and the units of new work done in the batch.
    journal: RefCell<Journal>,
    journal_on: Cell<bool>,
    suspend_at: Cell<Deadline>,
    suspended: Cell<bool>,
    fresh: Cell<u64>,
}

impl SpaceInfo {
    /// A bundle over a space and validity checker.
    pub fn new(space: StateSpace, validity: RobotInWorkspace, resolution: Real) -> Self {
        SpaceInfo {
            space,
            resolution,
            validity,
            checks: Cell::new(0),
            free: Cell::new(0),
            clearances: RefCell::new(Vec::new()),
            carry: RefCell::new(motion::Carry::default()),
            deadline: Cell::new(Deadline::NONE),
            interrupted: Cell::new(false),
            ticks: Cell::new(0),
            // From every unit, doubling while looks are quick: the first look comes after one
            // unit however long a unit takes.
            every: Cell::new(1),
            last_look: Cell::new(None),
            journal: RefCell::new(Journal::default()),
            journal_on: Cell::new(false),
            suspend_at: Cell::new(Deadline::NONE),
            suspended: Cell::new(false),
            fresh: Cell::new(0),
        }
    }
    /// Numbers per state.
    #[inline]
    pub fn dims(&self) -> usize {
        self.space.dim_count()
    }
    /// Distance between two states.
    #[inline]
    pub fn distance(&self, a: &[Real], b: &[Real]) -> Real {
        self.space.distance(a, b)
    }
    /// The state a fraction `t` from `a` to `b`.
    #[inline]
    pub fn interpolate(&self, a: &[Real], b: &[Real], t: Real, out: &mut [Real]) {
        self.space.interpolate(a, b, t, out)
    }
    /// The robot's own sampler (OMPL's `StateSampler`), when it has one; `None`: samples are
    /// uniform and Gaussian neighbours move each coordinate independently. Its draws are not
    /// counted: planners sample through [`SpaceInfo::sample`] (and the run's sampler).
    #[inline]
    pub fn own_sampler(&self) -> Option<&dyn OwnSampler> {
        self.validity.robot.sampler()
    }
    /// How the robot's motions are checked ([`DiscreteOnly`] when it has no model of its own).
    /// Planners check motions through [`MotionValidator`](crate::motion::MotionValidator).
    #[inline]
    pub fn motion_model(&self) -> &dyn MotionModel {
        self.validity.robot.motion().unwrap_or(&DiscreteOnly)
    }
    /// The robot as a mobile body in the workspace (workspace planners: hexagonal decomposition,
    /// potential fields); `None` for robots that are not one.
    #[inline]
    pub fn body(&self) -> Option<&dyn WorkspaceBody> {
        self.validity.robot.body()
    }
    /// The robot's sensor (inspection tasks), when it has one; what it sees is [`SpaceInfo::sees`].
    #[inline]
    pub fn sensor(&self) -> Option<&dyn Sensor> {
        self.validity.robot.sensor()
    }
    /// The `robot.kind` of the scenario format (for messages).
    pub fn robot_kind(&self) -> &'static str {
        self.validity.robot.kind()
    }
    /// The robot kind's record (what its kind can do, its defaults).
    pub fn robot_caps(&self) -> &'static crate::robot::kinds::RobotKind {
        self.validity.robot.caps()
    }
    /// Where a state is drawn in the workspace.
    #[inline]
    pub fn project(&self, q: &[Real]) -> Vec2 {
        self.validity.robot.project(q)
    }
    /// The body's outline at `q`, as closed polygons (none for a point robot).
    pub fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        self.validity.robot.outline(q)
    }
    /// The workspace (for planners that plan in it rather than in configuration space, and for
    /// the capabilities' methods that take it).
    #[inline]
    pub fn workspace(&self) -> &crate::geometry::Workspace {
        &self.validity.workspace
    }
}

//! [`SpaceInfo`]: everything a planner may know about the problem's space, in one bundle
//! (OMPL's `SpaceInformation`). Planners import this, never scenario or robot types.

use crate::geometry::SensorPose;
use crate::math::{Real, Vec2};
use crate::rng::Rng;
use crate::space::StateSpace;
use crate::validity::StateValidity;
use std::cell::{Cell, RefCell};
use web_time::Instant;

/// When long work must stop: the run's time limit, as an instant (none: no limit). Loops that can
/// run long inside one planner iteration (a motion check's states, smoothing, a heat map) look at
/// it every so often, so a time limit holds inside them too.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Deadline(pub Option<Instant>);

impl Deadline {
    /// No deadline.
    pub const NONE: Deadline = Deadline(None);
    /// `ms` milliseconds from now (none when `ms` is infinite or too large for the clock).
    pub fn in_ms(ms: f64) -> Deadline {
        if !(ms.is_finite() && ms < 1e12) {
            return Deadline::NONE;
        }
        Deadline(Instant::now().checked_add(std::time::Duration::from_secs_f64(ms.max(0.0) / 1000.0)))
    }
    /// Whether it has passed (reads the clock: call it every few hundred units of work).
    #[inline]
    pub fn passed(&self) -> bool {
        self.0.is_some_and(|t| Instant::now() >= t)
    }
}

/// Units of work (states checked, shortcuts tried) between two looks at the clock.
pub const CLOCK_EVERY: u64 = 256;

/// The state space, validity checker and motion resolution, with the count of state checks.
pub struct SpaceInfo {
    /// The state space.
    pub space: StateSpace,
    /// Largest step between two checked states along a motion, in the space's metric.
    pub resolution: Real,
    pub(crate) validity: Box<dyn StateValidity>,
    pub(crate) checks: Cell<u64>,
    /// Scratch for the clearances along a motion (reused, so checking does not allocate).
    pub(crate) clearances: RefCell<Vec<Real>>,
    /// The run's deadline (see [`Deadline`]), and whether work was cut short by it.
    deadline: Cell<Deadline>,
    interrupted: Cell<bool>,
    /// Units of work since the clock was last read.
    ticks: Cell<u64>,
}

impl SpaceInfo {
    /// A bundle over a space and validity checker.
    pub fn new(space: StateSpace, validity: Box<dyn StateValidity>, resolution: Real) -> Self {
        SpaceInfo {
            space,
            resolution,
            validity,
            checks: Cell::new(0),
            clearances: RefCell::new(Vec::new()),
            deadline: Cell::new(Deadline::NONE),
            interrupted: Cell::new(false),
            ticks: Cell::new(0),
        }
    }
    /// Set the deadline of the work that follows, and forget an earlier interruption.
    pub fn set_deadline(&self, deadline: Deadline) {
        self.deadline.set(deadline);
        self.interrupted.set(false);
    }
    /// The current deadline.
    pub fn deadline(&self) -> Deadline {
        self.deadline.get()
    }
    /// Whether the deadline has passed (reading the clock now). Once it has, work in progress
    /// is cut short: motion checks refuse at once, so nothing unchecked is ever accepted, and the
    /// run stops with its time limit.
    pub fn out_of_time(&self) -> bool {
        if !self.interrupted.get() && self.deadline.get().passed() {
            self.interrupted.set(true);
        }
        self.interrupted.get()
    }
    /// Whether work was cut short by the deadline (without reading the clock).
    pub fn interrupted(&self) -> bool {
        self.interrupted.get()
    }
    /// Count `units` of work; every [`CLOCK_EVERY`] of them, read the clock. Returns whether the
    /// deadline has passed.
    #[inline]
    pub fn tick(&self, units: u64) -> bool {
        let t = self.ticks.get() + units;
        if t >= CLOCK_EVERY {
            self.ticks.set(0);
            self.out_of_time()
        } else {
            self.ticks.set(t);
            self.interrupted.get()
        }
    }
    /// Numbers per state.
    #[inline]
    pub fn dims(&self) -> usize {
        self.space.dim_count()
    }
    /// Whether `q` is valid (counted as one state check).
    #[inline]
    pub fn is_valid(&self, q: &[Real]) -> bool {
        self.checks.set(self.checks.get() + 1);
        self.validity.is_valid(q)
    }
    /// State checks so far.
    pub fn checks(&self) -> u64 {
        self.checks.get()
    }
    /// Reset the check counter.
    pub fn reset_checks(&self) {
        self.checks.set(0)
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
    /// A random state from the robot's sampler (uniform over the space unless the robot knows
    /// better). The checks the robot's sampler spends count as state checks.
    #[inline]
    pub fn sample(&self, rng: &mut Rng, out: &mut [Real]) {
        let spent = self.validity.sample(&self.space, rng, out);
        self.checks.set(self.checks.get() + spent);
    }
    /// A Gaussian neighbour of `centre` (spread `sigma` × each coordinate's range) drawn the
    /// robot's own way, when it has one (OMPL's `StateSampler::sampleGaussian`); `false`: the
    /// generic per-coordinate neighbour applies.
    pub fn sample_gaussian(&self, rng: &mut Rng, centre: &[Real], sigma: Real, out: &mut [Real]) -> bool {
        self.validity.sample_gaussian(&self.space, rng, centre, sigma, out)
    }
    /// Where a state is drawn in the workspace.
    #[inline]
    pub fn project(&self, q: &[Real]) -> Vec2 {
        self.validity.project(q)
    }
    /// The robot's sensor at `q`: where it is and which way it looks (inspection tasks).
    #[inline]
    pub fn sensor(&self, q: &[Real]) -> SensorPose {
        self.validity.sensor(q)
    }
    /// The workspace, for planners that plan in it rather than in configuration space (cell
    /// decomposition, potential fields). `None` for a space with no workspace behind it.
    pub fn workspace(&self) -> Option<&crate::geometry::Workspace> {
        self.validity.workspace()
    }
    /// The body's outline at `q`, as closed polygons (none for a point robot).
    pub fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        self.validity.outline(q)
    }
    /// The length and width of a mobile body (point: 0 × 0); `None` for robots that are not one.
    pub fn body_size(&self) -> Option<(Real, Real)> {
        self.validity.body_size()
    }
    /// Count `n` geometric tests as state checks (workspace planners test cells and steps rather
    /// than states; their tests are counted here so `checks` compares work across planners).
    pub fn count_checks(&self, n: u64) {
        self.checks.set(self.checks.get() + n);
    }
    /// Whether a sensor at `pose` sees the workspace point `p`: within `range`, within `fov / 2`
    /// of its heading, and with a sight line through no obstacle's interior (touching an obstacle
    /// does not block; see [`crate::geometry::sight`]). Exact: no sampling along the sight line.
    /// Not counted as a state check.
    #[inline]
    pub fn sees(&self, pose: &SensorPose, p: Vec2, fov: Real, range: Real) -> bool {
        pose.in_view(p, fov, range) && self.validity.sight_clear(pose.at, p)
    }
}

//! [`SpaceInfo`]: everything a planner may know about the problem's space, in one bundle
//! (OMPL's `SpaceInformation`). Planners import this, never scenario or robot types.

use crate::geometry::SensorPose;
use crate::math::{Real, Vec2};
use crate::rng::Rng;
use crate::space::StateSpace;
use crate::validity::StateValidity;
use std::cell::{Cell, RefCell};

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
}

impl SpaceInfo {
    /// A bundle over a space and validity checker.
    pub fn new(space: StateSpace, validity: Box<dyn StateValidity>, resolution: Real) -> Self {
        SpaceInfo { space, resolution, validity, checks: Cell::new(0), clearances: RefCell::new(Vec::new()) }
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

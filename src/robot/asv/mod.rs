//! The broom-joined vehicle chain (UQ COMP3702's "ASV" problems, `docs/sources.md`).
//!
//! `n` vehicles (points) in chain order, each joined to the next by a broom of fixed length `L`.
//! A scenario state is `[x1, y1, ..., xn, yn]`. The planner works in
//! `[cx, cy, θ1, φ1, ..., φ(n−2)]` instead (report 000 used the first vehicle as base; the centroid
//! makes a turn of the whole chain one coordinate): `(cx, cy)` is the centroid of the vehicles, `θ1`
//! the heading of the first broom (wrapping), `φk` the turn from broom `k` to broom `k+1`. Every
//! broom then has its length by construction, and a straight motion keeps every chain turn between
//! its end values, so it never flips a turn's sign halfway.
//!
//! Validity is the course's, with half its tolerance `e = 1e-5` as a safety margin (so a state the
//! planner accepts passes the course's own checks, which [`crate::io::asv::check_solution`] repeats
//! independently): the closed polygon convex (every turn of one sign, turns within the tolerance
//! counted as straight, the absolute turns summing to at most 3π), its area at least the minimum,
//! every vehicle in bounds, and no broom meeting an obstacle shrunk by the tolerance when touching
//! is allowed (the closing edge is not a broom).
//!
//! Motions are checked so that no vehicle moves more than `max_step` between two checked states
//! (its [`MotionModel::steps`](super::MotionModel::steps), from a bound on every vehicle's speed
//! proved in [`motion_bound`]),
//! and then **certified** as the rigid body's are (`space_info/motion.rs`): each checked state's
//! clearance says how far every vehicle may move with the state staying valid, and intervals whose end
//! clearances do not cover the movement between them are bisected. So every state along an
//! accepted motion is valid, not only the checked ones: a part of a motion (the path smoother cuts
//! motions at arbitrary points) or a motion walked backwards (the goal tree's edges, in the final
//! path) is valid however it is cut into the solution file's primitive steps
//! ([`crate::io::asv::solution_text`]).

mod rules;
mod sampler;

use super::capability::{all_around, MotionModel, OwnSampler, Sensor};
use super::{Robot, Verdict};
use crate::geometry::{SensorPose, Workspace};
use crate::math::{angle_diff, wrap_angle, MinMax, Real, Vec2, PI};
use crate::robot::kinds::{Drawn, Pose, RobotKind};
use crate::scenario::RobotSpec;
use crate::space::{Dim, Metric, StateSpace};
use std::cell::{Cell, RefCell};

/// The course's tolerance `e` on every rule.
pub const TOLERANCE: Real = 1e-5;
/// The tolerance the planner uses: half the course's, so what it accepts the course accepts.
const MARGIN: Real = TOLERANCE / 2.0;
/// Vehicles placed on the stack; longer chains use the heap.
const STACK: usize = 32;

/// A chain of vehicles joined by brooms (see the module documentation).
#[derive(Clone, Debug)]
pub struct AsvRobot {
    n: usize,
    broom: Real,
    min_area: Real,
    convex: bool,
    max_step: Real,
    /// +1 counter-clockwise, −1 clockwise, 0 not known yet: the winding of the first state encoded.
    /// A convex chain whose area is bounded away from 0 cannot turn over, so every state of a path
    /// winds the same way, and the sampler draws only that way.
    orientation: Cell<Real>,
    /// The workspace, kept by [`Robot::space`] for the sampler (which places vehicles in gaps).
    workspace: RefCell<Option<Workspace>>,
    /// The workspace's narrow gaps, found at the first sample.
    gaps: RefCell<Option<sampler::Gaps>>,
}

impl AsvRobot {
    /// The robot a scenario's `asv` block describes.
    pub fn from_spec(spec: &RobotSpec) -> Result<Self, String> {
        match spec {
            RobotSpec::Asv { count, broom, min_area, convex, max_step } => {
                if *count < 3 && *convex {
                    return Err(format!("a convex chain needs 3 vehicles or more, found {count}"));
                }
                Ok(AsvRobot {
                    n: *count,
                    broom: *broom,
                    min_area: *min_area,
                    convex: *convex,
                    max_step: *max_step,
                    orientation: Cell::new(0.0),
                    workspace: RefCell::new(None),
                    gaps: RefCell::new(None),
                })
            }
            _ => Err("not an asv robot".into()),
        }
    }

    /// Number of vehicles.
    pub fn count(&self) -> usize {
        self.n
    }

    /// Run `f` on the vehicle positions of planning state `q`.
    #[inline]
    fn with_chain<T>(&self, q: &[Real], f: impl FnOnce(&[Vec2]) -> T) -> T {
        if self.n <= STACK {
            let mut buf = [Vec2::default(); STACK];
            self.place(q, &mut buf[..self.n]);
            f(&buf[..self.n])
        } else {
            let mut buf = vec![Vec2::default(); self.n];
            self.place(q, &mut buf);
            f(&buf)
        }
    }

    /// Write the vehicle positions of planning state `q` into `out` (`n` points).
    #[inline]
    fn place(&self, q: &[Real], out: &mut [Vec2]) {
        let n = self.n;
        offsets(self.broom, &q[2..], out);
        let mut sum = Vec2::default();
        for p in out.iter() {
            sum += *p;
        }
        let shift = Vec2::new(q[0] - sum.x / n as Real, q[1] - sum.y / n as Real);
        for p in out.iter_mut() {
            *p += shift;
        }
    }

    /// The winding the sampler draws: the first encoded state's, or either when none is known.
    fn orientation(&self) -> Real {
        self.orientation.get()
    }

    /// The weights of the metric: 1 on the centroid; on `θ1`, the radius of the regular polygon
    /// with the chain's sides (how far a vehicle moves per radian of turning the whole chain);
    /// on a turn `φk`, about how far the vehicles move when the chain bends there (the smaller part
    /// moves more; the weight falls toward the ends of the chain).
    fn weights(&self) -> Vec<Real> {
        let n = self.n as Real;
        let l = self.broom;
        let mut w = vec![1.0, 1.0, l / (2.0 * libm::sin(PI / n))];
        for k in 1..self.n - 1 {
            let (s1, s2) = ((k + 1) as Real, n - (k + 1) as Real);
            w.push(BEND_WEIGHT * l * (s1 * s2 / n).sqrt());
        }
        w
    }
}

/// Scale of a turn's weight in the metric (see [`AsvRobot::weights`]).
const BEND_WEIGHT: Real = 0.5;

/// The chain with its first vehicle at the origin: heading `angles[0]`, then turns `angles[1..]`.
#[inline]
fn offsets(l: Real, angles: &[Real], out: &mut [Vec2]) {
    let mut h = angles[0];
    let mut p = Vec2::default();
    out[0] = p;
    for k in 1..out.len() {
        let (s, c) = libm::sincos(h);
        p += Vec2::new(l * c, l * s);
        out[k] = p;
        if k < angles.len() {
            h += angles[k];
        }
    }
}

/// A bound on how far any vehicle moves along the straight motion `a → b` (in planning states).
///
/// Vehicle `m` sits at `c + r_m` with `r_m = L Σ_k a_mk u(h_k)`, `u(h) = (cos h, sin h)`, `h_k` the
/// heading of broom `k` and `a_mk = k/n` for `k < m`, `−(n−k)/n` otherwise (the centroid is the
/// mean of the vehicles). Along the motion every heading moves linearly by `Δh_k`; write
/// `Δh_k = δ + ε_k` for any common `δ`. Then `dr_m/dt = δ·J r_m + L Σ_k a_mk ε_k J u(h_k)` (`J` the
/// quarter turn), so `|dr_m/dt| ≤ |δ|·|r_m(t)| + E_m` with `E_m = L Σ_k |a_mk| |ε_k|`; the first
/// term is perpendicular to `r_m`, so `|r_m(t)| ≤ |r_m(0)| + E_m`. Every vehicle's speed (per unit
/// of the fraction `t` travelled) is therefore at most `|Δc| + max_m (|δ|·(|r_m(0)| + E_m) + E_m)`,
/// so over any part `[t0, t1]` of the motion it moves at most that times `t1 − t0` (one `N`th of
/// it in each of `N` equal steps). `δ = 0` and `δ` = the median `Δh_k` are both tried (the median
/// makes a pure turn of the chain cost only its real movement). `radii` are the vehicles'
/// distances from the centroid at `a`.
fn motion_bound(l: Real, a: &[Real], b: &[Real], radii: &[Real]) -> Real {
    let n = radii.len();
    let dc = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
    let mut dh = [0.0; STACK];
    let mut heap;
    let dh: &mut [Real] = if n <= STACK {
        &mut dh[..n - 1]
    } else {
        heap = vec![0.0; n - 1];
        &mut heap
    };
    dh[0] = angle_diff(a[2], b[2]);
    for k in 1..n - 1 {
        dh[k] = dh[k - 1] + (b[2 + k] - a[2 + k]);
    }
    // Sorted by the total order, stably: the same order as an unstable sort (equal keys are the
    // same number), and the same code as the run summaries' sort.
    let mut sorted = [0.0; STACK];
    let median = if n <= STACK {
        let s = &mut sorted[..n - 1];
        s.copy_from_slice(dh);
        s.sort_by(Real::total_cmp);
        s[(n - 1) / 2]
    } else {
        let mut s = dh.to_vec();
        s.sort_by(Real::total_cmp);
        s[(n - 1) / 2]
    };
    let nf = n as Real;
    let mut best = Real::INFINITY;
    for delta in [0.0, median] {
        // E_m = L/n · (Σ_{k<m} k|ε_k| + Σ_{k≥m} (n−k)|ε_k|), brooms k = 1..n−1, vehicles m = 1..n.
        let mut after: Real = (1..n).map(|k| (nf - k as Real) * (dh[k - 1] - delta).abs()).sum();
        let mut before = 0.0;
        let mut worst: Real = 0.0;
        for (m, r) in radii.iter().enumerate() {
            // Vehicle m+1: brooms 1..=m are before it.
            if m > 0 {
                let e = (dh[m - 1] - delta).abs();
                before += m as Real * e;
                after -= (nf - m as Real) * e;
            }
            let e_m = l * (before + after.at_least(0.0)) / nf;
            worst = worst.at_least(delta.abs() * (r + e_m) + e_m);
        }
        best = best.at_most(worst);
    }
    dc + best
}

/// The kind's record ([`super::kinds`]).
pub const KIND: RobotKind = RobotKind {
    name: "asv",
    label: "Vehicle chain (ASV)",
    drawn: Drawn::ClosedChain,
    body: false,
    sensor: true,
    cspace: false,
    course_cost: None,
    pose: Pose::None,
    solution_file: true,
    default_range: None,
};

impl Robot for AsvRobot {
    fn caps(&self) -> &'static RobotKind {
        &KIND
    }
    fn external_dims(&self) -> usize {
        2 * self.n
    }
    fn space(&self, ws: &Workspace) -> StateSpace {
        *self.workspace.borrow_mut() = Some(ws.clone());
        *self.gaps.borrow_mut() = None;
        let [x, y] = super::xy_dims(ws);
        let mut dims = vec![x, y, Dim { lo: -PI, hi: PI, wraps: true }];
        dims.extend((0..self.n - 2).map(|_| Dim { lo: -PI, hi: PI, wraps: false }));
        StateSpace { dims, metric: Metric::Weighted { weights: self.weights() } }
    }
    fn encode(&self, external: &[Real]) -> Result<Vec<Real>, String> {
        let n = self.n;
        if external.len() != 2 * n {
            return Err(format!("a chain of {n} vehicles has {} numbers (x y each), found {}", 2 * n, external.len()));
        }
        let p: Vec<Vec2> = external.chunks(2).map(|c| Vec2::new(c[0], c[1])).collect();
        let mut q = Vec::with_capacity(n + 1);
        let centroid = p.iter().fold(Vec2::default(), |s, v| s + *v).scale(1.0 / n as Real);
        q.extend([centroid.x, centroid.y]);
        let mut prev = 0.0;
        for k in 0..n - 1 {
            let d = p[k + 1] - p[k];
            let len = d.norm();
            if (len - self.broom).abs() > TOLERANCE {
                return Err(format!(
                    "broom {} (vehicles {} to {}) is {len} long, not {} (± {TOLERANCE})",
                    k + 1,
                    k + 1,
                    k + 2,
                    self.broom
                ));
            }
            let h = libm::atan2(d.y, d.x);
            q.push(if k == 0 { h } else { wrap_angle(h - prev) });
            prev = h;
        }
        let area2 = rules::signed_area2(&p);
        if self.min_area > TOLERANCE && area2 != 0.0 {
            let winding = area2.signum();
            let known = self.orientation.get();
            if known == 0.0 {
                self.orientation.set(winding);
            } else if known != winding {
                let name = |w: Real| if w > 0.0 { "counter-clockwise" } else { "clockwise" };
                return Err(format!(
                    "the chain winds {} here but {} in the state before: a chain that must keep an area cannot turn over, so no path joins them",
                    name(winding),
                    name(known)
                ));
            }
        }
        Ok(q)
    }
    fn decode(&self, q: &[Real]) -> Vec<Real> {
        self.with_chain(q, |pts| pts.iter().flat_map(|p| [p.x, p.y]).collect())
    }
    fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict {
        self.with_chain(q, |pts| self.verdict_of(ws, &q[3..], pts))
    }
    fn project(&self, q: &[Real]) -> Vec2 {
        Vec2::new(q[0], q[1])
    }
    fn outline(&self, q: &[Real]) -> Vec<Vec<Vec2>> {
        self.with_chain(q, |pts| vec![pts.to_vec()])
    }
    fn motion(&self) -> Option<&dyn MotionModel> {
        Some(self)
    }
    fn sampler(&self) -> Option<&dyn OwnSampler> {
        Some(self)
    }
    fn sensor(&self) -> Option<&dyn Sensor> {
        Some(self)
    }
}

/// No vehicle moves more than `max_step` between checked states; motions are certified by
/// clearances and a bound on how far a vehicle moves.
impl MotionModel for AsvRobot {
    fn steps(&self, a: &[Real], b: &[Real], _d: Real, _resolution: Real) -> Option<usize> {
        // A hair of slack for rounding in the bound.
        crate::limits::steps(self.bound(a, b) * (1.0 + 1e-9), self.max_step, crate::limits::MAX_MOTION_STEPS)
    }
    fn clearance(&self, ws: &Workspace, q: &[Real], cap: Real) -> Option<Real> {
        Some(self.with_chain(q, |pts| self.clearance_of(ws, &q[3..], pts, cap)))
    }
    fn displacement_bound(&self, a: &[Real], b: &[Real]) -> Option<Real> {
        Some(self.bound(a, b))
    }
}

/// Uniform chains are almost never valid: the chain draws its own (the `sampler` module).
impl OwnSampler for AsvRobot {
    fn sample(
        &self,
        space: &StateSpace,
        rng: &mut crate::rng::Rng,
        out: &mut [Real],
        deadline_passed: &dyn Fn() -> bool,
    ) -> u64 {
        sampler::sample(self, space, rng, out, deadline_passed)
    }
    fn sample_gaussian(
        &self,
        space: &StateSpace,
        rng: &mut crate::rng::Rng,
        centre: &[Real],
        sigma: Real,
        out: &mut [Real],
    ) {
        sampler::sample_gaussian(self, space, rng, centre, sigma, out);
    }
}

/// At the centroid, seeing all around.
impl Sensor for AsvRobot {
    fn pose(&self, q: &[Real]) -> SensorPose {
        all_around(self.project(q))
    }
}

impl AsvRobot {
    /// [`motion_bound`] for the motion `a → b` and for `b → a` (the same states walked back, so
    /// both bound it; the smaller), so a motion is cut into the same steps whichever way it is
    /// walked.
    fn bound(&self, a: &[Real], b: &[Real]) -> Real {
        self.one_way_bound(a, b).at_most(self.one_way_bound(b, a))
    }

    fn one_way_bound(&self, a: &[Real], b: &[Real]) -> Real {
        self.with_chain(a, |pts| {
            let c = Vec2::new(a[0], a[1]);
            let mut radii = [0.0; STACK];
            if pts.len() <= STACK {
                for (r, p) in radii.iter_mut().zip(pts) {
                    *r = (*p - c).norm();
                }
                motion_bound(self.broom, a, b, &radii[..pts.len()])
            } else {
                let radii: Vec<Real> = pts.iter().map(|p| (*p - c).norm()).collect();
                motion_bound(self.broom, a, b, &radii)
            }
        })
    }
}

#[cfg(test)]
mod tests;

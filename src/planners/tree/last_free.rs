//! The Robotics Library's CONNECT (`rl::plan::Rrt::connect`, used by `RrtConCon`, the planner of
//! report 001's course): step from the selected node along the straight line toward the target by
//! `delta`, testing each configuration, until the target is reached or a step is not free; only
//! the **last free configuration** becomes a node, with one edge from the node it started at;
//! nothing when the first step is not free.
//!
//! Followed from rl's `Rrt::connect` (`rl/plan/Rrt.cpp` in its repository's `src`):
//! - the first configuration is `interpolate(near, target, step / d)` with `step = d` when
//!   `d ≤ delta` (reached at once), else `step = delta`; when it collides, no vertex
//!   (`return nullptr`);
//! - then `step += delta` (a running sum, as rl adds it), and once `step ≥ d`, `step = d` and the
//!   target is reached: the last configuration is `interpolate(near, target, 1)`; the loop stops at
//!   the first colliding configuration or after the reached one;
//! - every configuration tested is one `isColliding` call, which `rl::plan::SimpleModel` counts as
//!   one query (`totalQueries`) and, when nothing was hit, one free query (`freeQueries`);
//! - the vertex added is the last free configuration, its edge from `near`.
//!
//! What Planarium adds, through the tree's machinery (not copies of it):
//! - **each step's motion is checked**, from the last free configuration (the node, at first) to
//!   the next, by [`SpaceInfo::check_step`](crate::space_info::SpaceInfo::check_step): rl tests
//!   the configurations alone, so a point could cut an obstacle's corner between two of them, or a
//!   planar arm's link graze one, and here a path through a corner is a bug. A step whose motion is not free ends the
//!   connect as a colliding configuration does. How a step counts:
//!   - a robot whose motions are checked by discrete states alone (no motion model of its own: the
//!     spatial arm, the course's Puma) tests the configuration alone, one state check, free when
//!     the configuration is: exactly rl's queries, one per configuration tested;
//!   - a point robot tests the configuration (one state check, free when it is) and the segment
//!     from the previous one exactly (a sweep, not a state check): still one query per
//!     configuration, but a free configuration at the end of a segment through an obstacle's
//!     corner ends the connect (its check counted free, as the configuration is; no check of the
//!     connect found a collision);
//!   - a body (planar arm, rigid body, vehicle chain) certifies the step's motion by clearances:
//!     the configuration's, the previous configuration's (computed on the first step only: a
//!     continuing step carries it from the step before), and those of the bisections that
//!     certify what lies between (and of the states a vehicle chain's own step rule puts there),
//!     each a state check, free when positive: `checks` is the collision work done, at least one
//!     per free step (two on the first), and `free_checks` counts the positive clearances, not the
//!     configurations kept; a step that is not free has one clearance of 0, the last computed, where the
//!     collision was found (unless the bisection's depth limit, 2⁻⁴⁰ of a step, refused it);
//! - the node is chosen by [`Tree::select`] (exhausted nodes and the weighted policy apply), and a
//!   sample beyond that node's dynamic domain is rejected before any check;
//! - **failure** (for the dynamic domain's radius and the exhausted nodes' count) means that no
//!   vertex came of it: the first step was not free, rl's `connect` returning `nullptr`.
//!   Report 001's DD-RRT pseudocode sets `q_near.radius = R` exactly when `CONNECT` does not
//!   return a new node, and Yershova et al. ("Dynamic-Domain RRTs", ICRA 2005) make a node a
//!   boundary node when its expansion fails, not when a long expansion that made progress ends
//!   against an obstacle (that node is interior; the new node at the end is the boundary one).
//!   The report counts an exhausted node's "failed expansions" the same way. A connect that made
//!   progress is a success for the node it started at (the adaptive domain grows);
//! - a **collision** (any, even after progress) is told to the sampler
//!   ([`Sampler::note_collision`](crate::sampler::Sampler::note_collision)) at the last connected
//!   configuration, as report 001's Algorithm 2 puts it (`lastCollisionPoint =
//!   lastConnectedNode`): the new node, or the start node when nothing was added;
//! - a target at distance 0 is reached at once, unchecked and without a node (rl would interpolate
//!   0/0);
//! - at most [`MAX_LAST_FREE_STEPS`] configurations (a problem's longest motion is at most
//!   [`MAX_MOTION_STEPS`](crate::limits::MAX_MOTION_STEPS) resolutions long); a connect cut short
//!   by the run's deadline or a suspended batch adds nothing (the run stops, or the iteration is
//!   done again from the journal).
//!
//! Events, as a range step's: `Nearest`; then `Steer` from the node to the farthest configuration
//! tested (the target when reached), `Collision` at the state where the last step was found not
//! free (the configuration, or a state of its motion), `NodeAdded` for the last free one.

use super::Tree;
use crate::math::Real;
use crate::planners::Context;
use crate::status::Grow;

/// The most configurations one last-free connect tests: a problem's longest motion in resolution
/// steps, plus the first.
pub const MAX_LAST_FREE_STEPS: usize = crate::limits::MAX_MOTION_STEPS as usize + 1;

/// The Robotics Library's schedule of a connect's steps over a distance `d` (> 0) in steps of
/// `delta`: each configuration's distance from the node along the line, and whether it is the
/// target (`step = d` when `d ≤ delta`, else `delta`; then `step += delta`, a running sum, until
/// `step ≥ d`, which is `d`: reached). The connect tests them in this order, stopping at the
/// first not free; the explain panel asks for the same ones ([`crate::problem::Problem::connect_configs`]).
#[derive(Clone, Debug)]
pub struct LastFreeSteps {
    d: Real,
    delta: Real,
    step: Real,
    reached: bool,
    done: bool,
}

impl LastFreeSteps {
    /// The steps over `d` by `delta`.
    pub fn new(d: Real, delta: Real) -> Self {
        let (step, reached) = if d <= delta { (d, true) } else { (delta, false) };
        LastFreeSteps { d, delta, step, reached, done: false }
    }
}

impl Iterator for LastFreeSteps {
    type Item = (Real, bool);
    fn next(&mut self) -> Option<(Real, bool)> {
        if self.done {
            return None;
        }
        let out = (self.step, self.reached);
        if self.reached {
            self.done = true;
        } else {
            self.step += self.delta;
            if self.step >= self.d {
                self.reached = true;
                self.step = self.d;
            }
        }
        Some(out)
    }
}

impl Tree {
    /// Connect toward `target` the Robotics Library's way (see the module documentation), in steps
    /// of `delta`; `sample`: the target is a sample (its node's dynamic domain applies). `scratch`
    /// holds the configuration tested, `new` the last free one, `found` where a step was found not
    /// free. Returns the outcome and the node added ([`Grow::Reached`] when it is the target,
    /// [`Grow::Advanced`] when a step was not free after progress), or the selected node
    /// ([`Grow::Trapped`]: the first step was not free, or no node may be added;
    /// [`Grow::Rejected`]: outside its domain; `Reached` at a distance of 0).
    #[allow(clippy::too_many_arguments)]
    pub fn connect_last_free(
        &mut self,
        cx: &mut Context,
        target: &[Real],
        delta: Real,
        sample: bool,
        scratch: &mut [Real],
        new: &mut [Real],
        found: &mut [Real],
    ) -> (Grow, u32) {
        let (near, d) = match self.begin_growth(cx, target, sample) {
            Ok(nd) => nd,
            Err(outcome) => return outcome,
        };
        let from = &self.states[near as usize * self.dims..(near as usize + 1) * self.dims];
        // rl: `step = distance`, reached when `step <= delta`, else `step = delta`; then by delta.
        let (mut step, mut reached) = (0.0, false);
        let (mut any_free, mut collided) = (false, false);
        let checks = cx.si.checks();
        for (s, r) in LastFreeSteps::new(d, delta).take(MAX_LAST_FREE_STEPS) {
            (step, reached) = (s, r);
            cx.si.interpolate(from, target, step / d, scratch);
            // The step's motion, from the last free configuration (the node, at first).
            // Past the first step, it continues from the previous step's end (its clearance is
            // carried).
            let free = cx.si.check_step(if any_free { &*new } else { from }, scratch, any_free, found).is_ok();
            if cx.si.stopped() {
                // Out of time, or the batch was suspended (its answers are refused): add nothing.
                return (Grow::Trapped, near);
            }
            if !free {
                collided = true;
                break;
            }
            new.copy_from_slice(scratch);
            any_free = true;
        }
        // The farthest configuration tested: the one whose step was not free, or the last free one.
        let tested = if collided { &*scratch } else { &*new };
        cx.note_steer(self.index, near, from, tested, step, d, reached && !collided);
        // The explain panel's query count of this connect (the state log only).
        cx.events.set_extra((cx.si.checks() - checks) as f64);
        if collided {
            cx.note_collision(self.index, near, from, target, found);
        }
        if !any_free {
            cx.sampler.note_collision(self.state(near));
            self.record(cx, near, true);
            return (Grow::Trapped, near);
        }
        if collided {
            cx.sampler.note_collision(new);
        }
        let id = self.append(cx, near, new);
        (if reached && !collided { Grow::Reached } else { Grow::Advanced }, id)
    }
}

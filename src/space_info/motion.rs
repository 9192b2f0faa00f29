//! Motion checks: the problem's [`MotionValidator`], counted and journalled (see
//! [`crate::motion`] for the method). How a motion is checked follows from the robot's motion
//! model ([`Mode`]).

use super::SpaceInfo;
use crate::journal::Entry;
use crate::math::Real;
use crate::motion::{Discrete, Invalid, MotionValidator};
use crate::robot::MotionModel;
use crate::space::in_bisection_order;

/// How a motion is checked on top of its discrete states, from the robot's motion model (asked in
/// this order: an exact sweep, clearances along the motion, a bound on any body point's travel).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    /// An exact swept test, which said whether the motion hits an obstacle: the discrete checks
    /// (the contract), then the sweep's answer.
    Swept {
        /// Whether the sweep hits.
        hit: bool,
    },
    /// Clearances in units of the motion's parameter, certified between checked states: every
    /// constraint closes at most at rate 1.
    AlongMotion,
    /// Clearances in workspace units, certified between checked states: no body point moves more
    /// than `disp` along the whole motion.
    InWorkspace {
        /// The bound on any body point's travel.
        disp: Real,
    },
    /// The discrete checks alone (a robot with no model of its own).
    Discrete,
}

impl Mode {
    /// How the motion `a → b` is checked, given what the robot's exact sweep (if any) said.
    /// Built where it is matched, so the enum costs nothing (callgrind: the same instructions as
    /// matching on the model's answers directly).
    #[inline]
    fn of(model: &dyn MotionModel, sweep: Option<bool>, a: &[Real], b: &[Real]) -> Mode {
        match sweep {
            Some(hit) => Mode::Swept { hit },
            None if model.has_motion_clearance() => Mode::AlongMotion,
            None => match model.displacement_bound(a, b) {
                Some(disp) => Mode::InWorkspace { disp },
                None => Mode::Discrete,
            },
        }
    }
}

/// Which clearance a certified check asks the motion model for.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Clearance<'m> {
    /// Along the motion `a → b`, in units of its parameter.
    Motion(&'m [Real], &'m [Real]),
    /// Of the state alone, in workspace units.
    Workspace,
}

/// The last step of a walk along a line ([`SpaceInfo::check_step`]) found free by clearances:
/// its motion `a → b` and the clearance computed at `b`, which is the next step's start.
#[derive(Debug, Default)]
pub(super) struct Carry {
    /// Whether the last step checked was certified free by clearances (else nothing is carried).
    valid: bool,
    a: Vec<Real>,
    b: Vec<Real>,
    /// The clearance at `b` on `a → b` (capped there), positive.
    clear: Real,
}

/// A motion checked as one step of a walk ([`SpaceInfo::check_step`]), with the clearance carried
/// into its start from the previous step, if any: a lower bound of the clearance at `a` in the
/// units the step is certified in, before the step's cap.
#[derive(Clone, Copy, Debug)]
struct Step {
    carried: Option<Real>,
}

/// Deepest bisection when certifying one interval (2^-40 of a resolution step).
const MAX_DEPTH: u32 = 40;

impl SpaceInfo {
    /// Clearance of `q` capped at `cap` by the robot's motion model `model`, counted as one state
    /// check: the clearance `kind` says (workspace units, or units of the motion's parameter).
    #[inline]
    fn clearance_checked(&self, model: &dyn MotionModel, kind: Clearance, q: &[Real], cap: Real) -> Real {
        self.checks.set(self.checks.get() + 1);
        // Past the deadline, a clearance of 0 refuses the motion (and the run stops).
        if self.interrupted() {
            return 0.0;
        }
        let clearance = self.journalled(
            |e| if let Entry::Clear(c) = e { Some(*c) } else { None },
            Entry::Clear,
            0.0,
            || {
                match kind {
                    Clearance::Motion(a, b) => model.motion_clearance(&self.validity.workspace, a, b, q, cap),
                    Clearance::Workspace => model.clearance(&self.validity.workspace, q, cap),
                }
                .unwrap_or(0.0)
            },
        );
        // A positive clearance: the state is valid (0: it is not, or the answer was refused).
        self.count_free((clearance > 0.0) as u64);
        clearance
    }

    fn check_discrete(&self, a: &[Real], b: &[Real], n: usize, scratch: &mut [Real]) -> Result<(), Invalid> {
        // A check cut short in an earlier batch resumes after the states it visited.
        let mark = self.journal_on().then(|| self.journal.borrow().mark());
        let skip = match self.journal_on().then(|| self.journal.borrow().peek().cloned()).flatten() {
            Some(Entry::Partial { visited }) => {
                self.journal.borrow_mut().take();
                visited
            }
            _ => 0,
        };
        let ws = &self.validity.workspace;
        let (outcome, checks) = self
            .validity
            .robot
            .check_discrete(ws, &self.space, a, b, n, scratch, skip, &|units| self.fresh_work(units));
        self.count_checks(checks);
        // Every state visited was valid but, for an invalid motion, the last.
        self.count_free(checks - matches!(outcome, Discrete::Invalid) as u64);
        match outcome {
            Discrete::Valid => Ok(()),
            Discrete::Invalid => Err(Invalid),
            Discrete::OutOfTime => {
                if let (Some(mark), true) = (mark, self.suspended() && !self.interrupted()) {
                    // Resumed at this state in the next batch (in place of where it resumed).
                    self.journal.borrow_mut().compact(mark, Entry::Partial { visited: checks }, None);
                }
                scratch.copy_from_slice(b);
                Err(Invalid)
            }
        }
    }

    /// Like the discrete check, but computing each state's clearance (capped at the per-step
    /// displacement) and then certifying every interval between checked states. `disp` bounds
    /// any body point's travel over the motion in the clearances' units (1 along the motion).
    /// A walk's `step` takes the clearance at `a` carried from the previous step, when there is
    /// one, rather than computing it, and carries the one at `b` into the next step when free.
    #[allow(clippy::too_many_arguments)]
    fn check_certified(
        &self,
        model: &dyn MotionModel,
        a: &[Real],
        b: &[Real],
        n: usize,
        disp: Real,
        m: Clearance,
        step: Option<Step>,
        scratch: &mut [Real],
    ) -> Result<(), Invalid> {
        let cap = disp / n as Real;
        let mut clear = self.clearances.take();
        clear.clear();
        clear.resize(n + 1, 0.0);
        let outcome = (|| {
            clear[n] = self.clearance_checked(model, m, b, cap);
            if clear[n] == 0.0 {
                scratch.copy_from_slice(b);
                return Err(Invalid);
            }
            in_bisection_order(n, |i| {
                self.interpolate(a, b, i as Real / n as Real, scratch);
                clear[i] = self.clearance_checked(model, m, scratch, cap);
                if clear[i] == 0.0 {
                    Err(Invalid)
                } else {
                    Ok(())
                }
            })?;
            // Carried: a lower bound of the clearance at `a`, capped as a computed one is.
            clear[0] = match step.and_then(|s| s.carried) {
                Some(c) => c.min(cap),
                None => self.clearance_checked(model, m, a, cap),
            };
            for i in 0..n {
                if clear[i] + clear[i + 1] <= cap {
                    let (t0, t1) = (i as Real / n as Real, (i + 1) as Real / n as Real);
                    self.certify(model, a, b, (t0, clear[i]), (t1, clear[i + 1]), disp, m, scratch, 0)?;
                }
            }
            Ok(())
        })();
        if step.is_some() && outcome.is_ok() {
            self.keep_carry(a, b, clear[n]);
        }
        self.clearances.replace(clear);
        outcome
    }

    #[allow(clippy::too_many_arguments)]
    fn certify(
        &self,
        model: &dyn MotionModel,
        a: &[Real],
        b: &[Real],
        lo: (Real, Real),
        hi: (Real, Real),
        disp: Real,
        m: Clearance,
        scratch: &mut [Real],
        depth: u32,
    ) -> Result<(), Invalid> {
        let span = disp * (hi.0 - lo.0);
        if lo.1 + hi.1 > span {
            return Ok(());
        }
        let tm = 0.5 * (lo.0 + hi.0);
        self.interpolate(a, b, tm, scratch);
        let cm = self.clearance_checked(model, m, scratch, span);
        if cm == 0.0 || depth >= MAX_DEPTH {
            return Err(Invalid);
        }
        self.certify(model, a, b, lo, (tm, cm), disp, m, scratch, depth + 1)?;
        self.certify(model, a, b, (tm, cm), hi, disp, m, scratch, depth + 1)
    }
}

/// The slack on the resolution for one step of a walk along a line ([`SpaceInfo::check_step`]):
/// the Robotics Library's running sum of steps puts two configurations a resolution apart up to
/// some ulps per step taken (at most 100,000 steps: about 1e-11 relative), which must not make the
/// step's check visit a second state (without it, a point on `narrow` made 55% more checks, seed 1:
/// 11,247 rather than 7,277, one per configuration).
const STEP_SLACK: Real = 1e-9;

impl MotionValidator for SpaceInfo {
    fn check_motion(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Invalid> {
        self.check_motion_at(a, b, self.resolution, None, scratch)
    }
}

impl SpaceInfo {
    /// One step of a walk along a line in steps of the resolution (RRT-Connect's `last-free`
    /// connect, the Robotics Library's): whether the motion `a → b` is free, `a` being free (the
    /// walk's start or its previous step's end) and `b` one resolution on (or less, the last step).
    /// On `Err`, `scratch` holds the invalid state found (`b`, or one between).
    ///
    /// - A robot whose walks test states alone ([`MotionModel::walks_by_states`]: the spatial
    ///   arm, whose course counted one query per configuration tested), or one with no motion
    ///   model, tests `b` alone, one state check (free when `b` is): the states between two steps
    ///   are not checked here, and the path found is certified after planning (`run::certify`).
    /// - Any other robot has the step's motion checked by the motion validator, as one motion at
    ///   the resolution (a hair of slack, `STEP_SLACK`, for the running sum's rounding), so
    ///   nothing between two steps goes unchecked: a point tests `b` (one state check) and the
    ///   segment exactly (the sweep is not a state check), so it still counts one check per
    ///   configuration; a body computes clearances at `b` and at the bisections that certify the
    ///   motion, each a state check, free when positive (a robot with its own step rule, the
    ///   vehicle chain, also at the states the rule puts between), and at `a` on the walk's first
    ///   step only.
    ///
    /// `continues`: `a` is the end of the step checked just before, by this method, in the same
    /// walk, and found free. Its clearance, computed by that step, is then carried rather than
    /// computed again: a workspace clearance (rigid body, vehicle chain) does not depend on the
    /// motion, and a clearance along the motion (planar arm) is divided by the motion model's
    /// [`motion_rate_ratio`](crate::robot::MotionModel::motion_rate_ratio) of the two steps (their
    /// lengths' ratio, along one line). A walk's first step has `continues` false, so nothing is
    /// carried from one walk into another (a batch replays each walk alone, see
    /// [`crate::journal`]).
    pub fn check_step(&self, a: &[Real], b: &[Real], continues: bool, scratch: &mut [Real]) -> Result<(), Invalid> {
        if self.validity.robot.motion().is_none_or(|m| m.walks_by_states()) {
            if self.is_valid(b) {
                return Ok(());
            }
            scratch.copy_from_slice(b);
            return Err(Invalid);
        }
        let carried = if continues { self.carried(a, b) } else { None };
        self.carry.borrow_mut().valid = false;
        let step = Some(Step { carried });
        self.check_motion_at(a, b, self.resolution * (1.0 + STEP_SLACK), step, scratch)
    }

    /// The clearance the last step carries into the step `a → b`, when that step ended at `a`
    /// (see [`SpaceInfo::check_step`]).
    fn carried(&self, a: &[Real], b: &[Real]) -> Option<Real> {
        let c = self.carry.borrow();
        if !c.valid || c.b != a {
            return None;
        }
        let model = self.motion_model();
        if model.has_motion_clearance() {
            model.motion_rate_ratio(&c.a, &c.b, a, b).map(|mu| c.clear / mu)
        } else {
            Some(c.clear)
        }
    }

    /// Keep the clearance `clear` at the end of the step `a → b`, found free, for the next step.
    fn keep_carry(&self, a: &[Real], b: &[Real], clear: Real) {
        let mut c = self.carry.borrow_mut();
        c.valid = clear > 0.0;
        c.clear = clear;
        c.a.clear();
        c.a.extend_from_slice(a);
        c.b.clear();
        c.b.extend_from_slice(b);
    }

    /// The motion check with states at most `resolution` apart, journalled in a bounded batch
    /// (a walk's `step` with the clearance it carries to the next: replayed with it).
    fn check_motion_at(
        &self,
        a: &[Real],
        b: &[Real],
        resolution: Real,
        step: Option<Step>,
        scratch: &mut [Real],
    ) -> Result<(), Invalid> {
        // Cut short by the deadline (or a suspended batch): refuse at once, accept nothing
        // unchecked.
        if self.stopped() {
            scratch.copy_from_slice(b);
            return Err(Invalid);
        }
        if !self.journal_on() {
            return self.check_motion_now(a, b, resolution, step, scratch);
        }
        // In a bounded batch: a finished check is answered from the journal, one cut short
        // resumes where it stopped, and a check that finishes is kept as one entry.
        let mark = self.journal.borrow().mark();
        let done = match self.journal.borrow().peek() {
            Some(&Entry::Motion { ok, checks, free, at, end }) => Some((ok, checks, free, at, end)),
            _ => None,
        };
        if let Some((ok, checks, free, at, end)) = done {
            self.journal.borrow_mut().take();
            self.count_checks(checks);
            self.count_free(free);
            if step.is_some() && end > 0.0 {
                // The clearance the step carried to the next, as when it was computed.
                self.keep_carry(a, b, end);
            }
            if ok {
                return Ok(());
            }
            self.journal.borrow().load(at, scratch);
            return Err(Invalid);
        }
        let (before, free_before) = (self.checks(), self.free_checks());
        let outcome = self.check_motion_now(a, b, resolution, step, scratch);
        if !self.stopped() {
            let (checks, free) = (self.checks() - before, self.free_checks() - free_before);
            let end = match (step, &*self.carry.borrow()) {
                (Some(_), c) if c.valid => c.clear,
                _ => 0.0,
            };
            let entry = Entry::Motion { ok: outcome.is_ok(), checks, free, at: 0, end };
            self.journal.borrow_mut().compact(mark, entry, outcome.is_err().then_some(&*scratch));
        }
        outcome
    }

    /// The motion check itself, with states at most `resolution` apart.
    fn check_motion_now(
        &self,
        a: &[Real],
        b: &[Real],
        resolution: Real,
        step: Option<Step>,
        scratch: &mut [Real],
    ) -> Result<(), Invalid> {
        let d = self.distance(a, b);
        let model = self.motion_model();
        // More steps than can be checked (unreachable for states in bounds: `Problem` refuses
        // such a resolution): refuse the motion rather than check it more coarsely.
        let Some(n) = model.steps(a, b, d, resolution) else {
            self.interpolate(a, b, 0.5, scratch);
            return Err(Invalid);
        };
        // A motion through a state the robot refuses whatever the obstacles (a folded arm):
        // refused as one state check, of that state.
        if let Some(t) = model.refused_at(a, b) {
            self.count_checks(1);
            self.interpolate(a, b, t, scratch);
            return Err(Invalid);
        }
        // The sweep is a question a planner decides by, so it is journalled (refused, as a hit,
        // once the batch is suspended).
        let sweep = self.journalled(
            |e| if let Entry::Hit(h) = e { Some(*h) } else { None },
            Entry::Hit,
            Some(true),
            || model.sweep_hits(&self.validity.workspace, a, b),
        );
        if self.stopped() {
            scratch.copy_from_slice(b);
            return Err(Invalid);
        }
        match Mode::of(model, sweep, a, b) {
            Mode::Swept { hit } => {
                self.check_discrete(a, b, n, scratch)?;
                if hit {
                    self.interpolate(a, b, 0.5, scratch);
                    return Err(Invalid);
                }
                Ok(())
            }
            Mode::AlongMotion => self.check_certified(model, a, b, n, 1.0, Clearance::Motion(a, b), step, scratch),
            Mode::InWorkspace { disp } => {
                self.check_certified(model, a, b, n, disp, Clearance::Workspace, step, scratch)
            }
            Mode::Discrete => self.check_discrete(a, b, n, scratch),
        }
    }
}

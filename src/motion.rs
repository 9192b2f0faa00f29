//! Motion validation. A straight motion in state space is checked at every state at most
//! [`SpaceInfo::resolution`] apart (OMPL's `DiscreteMotionValidator`: the end first, then in
//! bisection order, coarse to fine, so a collision is found after few checks). On top of that the
//! motion is *certified*, so no motion can cut an obstacle's corner between two checked states:
//!
//! - a point robot's motion is a segment, tested exactly against every obstacle;
//! - a body's motion uses clearances: the robot bounds how far any body point moves along the
//!   motion; if no body point moves more than `D` between two checked states and their clearances
//!   sum to more than `D`, every state between them is free
//!   (each body point stays within reach of one end); otherwise the interval is bisected, each new
//!   state counted as a check, until it is certified or a collision is found.

use crate::journal::Entry;
use crate::math::Real;
use crate::robot::MotionModel;
use crate::space::StateSpace;
use crate::space_info::SpaceInfo;

/// A motion was found invalid (the state found is in the caller's scratch buffer).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Invalid;

/// Checks straight motions between states.
pub trait MotionValidator {
    /// `Ok(())` if the motion `a → b` is valid (`a` is assumed valid). On `Err`, `scratch` (room for
    /// one state) holds the invalid state that was found.
    fn check_motion(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Invalid>;
}

/// How a discrete motion check ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Discrete {
    /// Every state checked was valid.
    Valid,
    /// An invalid state was found (it is in the caller's scratch).
    Invalid,
    /// The deadline passed before every state was checked: the motion is refused.
    OutOfTime,
}

/// Visit `1..n` coarse to fine (n/2 first, then n/4 and 3n/4, ...), each index once, stopping at
/// the first error. (`n` is at most [`crate::limits::MAX_MOTION_STEPS`]; the power of two is
/// computed checked all the same, since a wrapped one would visit nothing.)
fn in_bisection_order<E>(n: usize, mut visit: impl FnMut(usize) -> Result<(), E>) -> Result<(), E> {
    let mut step = n.checked_next_power_of_two().unwrap_or(1 << (usize::BITS - 1));
    while step > 1 {
        let half = step / 2;
        let mut i = half;
        while i < n {
            visit(i)?;
            i += step;
        }
        step = half;
    }
    Ok(())
}

/// The discrete check of the motion `a → b` in `n` steps: `b`, then the states `i/n` of the way,
/// coarse to fine, stopping at the first invalid one, which is left in `scratch`. Returns how it
/// ended and how many states it visited (all valid but the last, when one was invalid).
///
/// The first `skip` states in that order are taken as checked already (a check resumed by the
/// batch journal, [`crate::journal`]): they are counted but not computed. Every 8 new states it
/// calls `stop` with the units done; once that says so, it ends with [`Discrete::OutOfTime`],
/// having visited (all valid) the states counted.
#[allow(clippy::too_many_arguments)]
pub fn check_discrete(
    space: &StateSpace,
    a: &[Real],
    b: &[Real],
    n: usize,
    scratch: &mut [Real],
    skip: u64,
    stop: &dyn Fn(u64) -> bool,
    mut is_valid: impl FnMut(&[Real]) -> bool,
) -> (Discrete, u64) {
    const EVERY: u64 = 8;
    if skip == 0 && !is_valid(b) {
        scratch.copy_from_slice(b);
        return (Discrete::Invalid, 1);
    }
    let (mut visited, mut countdown, mut late) = (1u64, EVERY, false);
    let all = in_bisection_order(n, |i| {
        if visited < skip {
            visited += 1;
            return Ok(());
        }
        countdown -= 1;
        if countdown == 0 {
            countdown = EVERY;
            if stop(EVERY) {
                late = true;
                return Err(());
            }
        }
        space.interpolate(a, b, i as Real / n as Real, scratch);
        visited += 1;
        if is_valid(scratch) {
            Ok(())
        } else {
            Err(())
        }
    });
    (
        match (all, late) {
            (Ok(()), _) => Discrete::Valid,
            (Err(()), false) => Discrete::Invalid,
            (Err(()), true) => Discrete::OutOfTime,
        },
        visited,
    )
}

/// Deepest bisection when certifying one interval (2^-40 of a resolution step).
const MAX_DEPTH: u32 = 40;

impl SpaceInfo {
    /// Clearance of `q` capped at `cap` by the robot's motion model `model`, counted as one state
    /// check: in workspace units, or (when the robot supports it, `motion` given) in units of the
    /// motion's parameter.
    #[inline]
    fn clearance_checked(
        &self,
        model: &dyn MotionModel,
        motion: Option<(&[Real], &[Real])>,
        q: &[Real],
        cap: Real,
    ) -> Real {
        self.checks.set(self.checks.get() + 1);
        // Past the deadline, a clearance of 0 refuses the motion (and the run stops).
        if self.interrupted() {
            return 0.0;
        }
        self.journalled(
            |e| if let Entry::Clear(c) = e { Some(*c) } else { None },
            Entry::Clear,
            0.0,
            || {
                match motion {
                    Some((a, b)) => model.motion_clearance(&self.validity.workspace, a, b, q, cap),
                    None => model.clearance(&self.validity.workspace, q, cap),
                }
                .unwrap_or(0.0)
            },
        )
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
    /// displacement) and then certifying every interval between checked states.
    /// `motion`: clearances in units of the motion's parameter (then `disp` is 1).
    #[allow(clippy::too_many_arguments)]
    fn check_certified(
        &self,
        model: &dyn MotionModel,
        a: &[Real],
        b: &[Real],
        n: usize,
        disp: Real,
        motion: bool,
        scratch: &mut [Real],
    ) -> Result<(), Invalid> {
        let m = motion.then_some((a, b));
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
            clear[0] = self.clearance_checked(model, m, a, cap);
            for i in 0..n {
                if clear[i] + clear[i + 1] <= cap {
                    let (t0, t1) = (i as Real / n as Real, (i + 1) as Real / n as Real);
                    self.certify(model, a, b, (t0, clear[i]), (t1, clear[i + 1]), disp, m, scratch, 0)?;
                }
            }
            Ok(())
        })();
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
        m: Option<(&[Real], &[Real])>,
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

impl MotionValidator for SpaceInfo {
    fn check_motion(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Invalid> {
        // Cut short by the deadline (or a suspended batch): refuse at once, accept nothing
        // unchecked.
        if self.stopped() {
            scratch.copy_from_slice(b);
            return Err(Invalid);
        }
        if !self.journal_on() {
            return self.check_motion_now(a, b, scratch);
        }
        // In a bounded batch: a finished check is answered from the journal, one cut short
        // resumes where it stopped, and a check that finishes is kept as one entry.
        let mark = self.journal.borrow().mark();
        let done = match self.journal.borrow().peek() {
            Some(&Entry::Motion { ok, checks, at }) => Some((ok, checks, at)),
            _ => None,
        };
        if let Some((ok, checks, at)) = done {
            self.journal.borrow_mut().take();
            self.count_checks(checks);
            if ok {
                return Ok(());
            }
            self.journal.borrow().load(at, scratch);
            return Err(Invalid);
        }
        let before = self.checks();
        let outcome = self.check_motion_now(a, b, scratch);
        if !self.stopped() {
            let entry = Entry::Motion { ok: outcome.is_ok(), checks: self.checks() - before, at: 0 };
            self.journal.borrow_mut().compact(mark, entry, outcome.is_err().then_some(&*scratch));
        }
        outcome
    }
}

impl SpaceInfo {
    /// The motion check itself.
    fn check_motion_now(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Invalid> {
        let d = self.distance(a, b);
        let model = self.motion_model();
        // More steps than can be checked (unreachable for states in bounds: `Problem` refuses
        // such a resolution): refuse the motion rather than check it more coarsely.
        let Some(n) = model.steps(a, b, d, self.resolution) else {
            self.interpolate(a, b, 0.5, scratch);
            return Err(Invalid);
        };
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
        match sweep {
            // A robot with an exact swept test: discrete checks (the contract), then the sweep.
            Some(hit) => {
                self.check_discrete(a, b, n, scratch)?;
                if hit {
                    self.interpolate(a, b, 0.5, scratch);
                    return Err(Invalid);
                }
                Ok(())
            }
            // Clearances in units of the motion: every constraint closes at most at rate 1.
            None if model.has_motion_clearance() => self.check_certified(model, a, b, n, 1.0, true, scratch),
            None => match model.displacement_bound(a, b) {
                Some(disp) => self.check_certified(model, a, b, n, disp, false, scratch),
                None => self.check_discrete(a, b, n, scratch),
            },
        }
    }
}

#[cfg(test)]
mod tests;

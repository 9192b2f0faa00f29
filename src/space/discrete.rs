//! The discrete check of a straight motion: its states visited coarse to fine (OMPL's
//! `DiscreteMotionValidator`). Here, below the robots, so a robot's own motion check uses it as the
//! motion validator ([`crate::motion`]) does.

use crate::math::Real;

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
pub(crate) fn in_bisection_order<E>(n: usize, mut visit: impl FnMut(usize) -> Result<(), E>) -> Result<(), E> {
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
    space: &super::StateSpace,
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

//! The counted state questions and their counters: whether a state is valid and a random state,
//! each counted as state checks (and journalled in a bounded batch); the counts themselves: every
//! state check, and the *free* ones, those that found the state valid (the Robotics Library's
//! `SimpleModel` counts `totalQueries` and `freeQueries` so: one query per configuration tested,
//! a free query when nothing was hit).

use super::SpaceInfo;
use crate::journal::Entry;
use crate::math::Real;
use crate::rng::Rng;

impl SpaceInfo {
    /// Whether `q` is valid (counted as one state check).
    #[inline]
    pub fn is_valid(&self, q: &[Real]) -> bool {
        self.checks.set(self.checks.get() + 1);
        let valid = self.journalled(
            |e| if let Entry::Valid(v) = e { Some(*v) } else { None },
            Entry::Valid,
            false,
            || self.validity.is_valid(q),
        );
        self.free.set(self.free.get() + valid as u64);
        valid
    }
    /// Whether `q` is valid, **not** counted as a state check and not journalled: for work that
    /// counts its own checks (a potential field's clearances, inside one journalled answer) or that
    /// is not part of a run (a configuration-space picture). Planners deciding by a state use
    /// [`SpaceInfo::is_valid`].
    #[inline]
    pub fn is_valid_uncounted(&self, q: &[Real]) -> bool {
        self.validity.is_valid(q)
    }
    /// A random state from the robot's sampler (uniform over the space unless the robot knows
    /// better). The checks the robot's sampler spends count as state checks.
    #[inline]
    pub fn sample(&self, rng: &mut Rng, out: &mut [Real]) {
        let spent = if self.journal_on.get() { self.sample_journalled(rng, out) } else { self.sample_now(rng, out) };
        self.checks.set(self.checks.get() + spent);
    }
    /// A state from the robot's own sampler, else uniform; the checks it spent.
    #[inline]
    fn sample_now(&self, rng: &mut Rng, out: &mut [Real]) -> u64 {
        match self.own_sampler() {
            Some(own) => own.sample(&self.space, rng, out, &|| {
                self.look();
                self.interrupted.get()
            }),
            None => {
                self.space.sample_uniform(rng, out);
                0
            }
        }
    }
    fn sample_journalled(&self, rng: &mut Rng, out: &mut [Real]) -> u64 {
        let mut j = self.journal.borrow_mut();
        if let Some(e) = j.take() {
            if let Entry::Sample { spent, at, rng: after } = e {
                j.load(at, out);
                *rng = after;
                return spent;
            }
            drop(j);
            self.desync();
        } else {
            drop(j);
        }
        if self.suspended.get() {
            // Winding down: a uniform state, unchecked (the iteration is thrown away).
            self.space.sample_uniform(rng, out);
            return 0;
        }
        let spent = self.sample_now(rng, out);
        let mut j = self.journal.borrow_mut();
        let at = j.store(out);
        j.push(Entry::Sample { spent, at, rng: rng.clone() });
        drop(j);
        self.fresh_work(1);
        spent
    }
    /// State checks so far.
    #[inline]
    pub fn checks(&self) -> u64 {
        self.checks.get()
    }
    /// Of the state checks so far, those that found the state valid (the Robotics Library's free
    /// queries): a valid [`is_valid`](SpaceInfo::is_valid), each valid state of a motion check
    /// (and each positive clearance of a certified one). Not classified, so never free: the
    /// geometric tests the workspace planners count with [`count_checks`](SpaceInfo::count_checks)
    /// (cells, steps, potential evaluations), and the checks a robot's own sampler spends (a
    /// vehicle chain's: it reports how many, not which; at most one per sample was free).
    #[inline]
    pub fn free_checks(&self) -> u64 {
        self.free.get()
    }
    /// Reset both check counters.
    pub fn reset_checks(&self) {
        self.checks.set(0);
        self.free.set(0);
    }
    /// Restore the state-check counts, all and free (a suspended batch's checks are counted again
    /// when its iterations are replayed).
    #[inline]
    pub(crate) fn set_checks(&self, checks: u64, free: u64) {
        self.checks.set(checks);
        self.free.set(free);
    }
    /// Count `n` state checks that found their states valid (part of a motion check).
    #[inline]
    pub(super) fn count_free(&self, n: u64) {
        self.free.set(self.free.get() + n);
    }
    /// Count `n` geometric tests as state checks (workspace planners test cells and steps rather
    /// than states; their tests are counted here so `checks` compares work across planners).
    #[inline]
    pub fn count_checks(&self, n: u64) {
        self.checks.set(self.checks.get() + n);
    }
}

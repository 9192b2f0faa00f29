//! The batch journal: in a bounded batch, every question a planner decides by is recorded, and
//! after a suspension replayed (see [`crate::journal`]); outside one, each answer is still a unit of
//! work.

use super::{Deadline, SpaceInfo};
use crate::journal::Entry;

impl SpaceInfo {
    /// Start a bounded batch: questions are journalled, and past `suspend_at` (once the batch has
    /// done new work) the batch is suspended. See [`crate::journal`].
    pub fn begin_batch(&self, suspend_at: Deadline) {
        self.journal.borrow_mut().begin();
        self.journal_on.set(true);
        self.suspend_at.set(suspend_at);
        self.suspended.set(false);
        self.fresh.set(0);
    }
    /// End a bounded batch; returns whether it was suspended (its answers are then kept for the
    /// next batch, which replays them).
    pub fn end_batch(&self) -> bool {
        let suspended = self.suspended.get() && !self.interrupted.get();
        let mut j = self.journal.borrow_mut();
        if suspended {
            j.pause();
        } else {
            j.finish();
        }
        self.journal_on.set(false);
        self.suspended.set(false);
        self.suspend_at.set(Deadline::NONE);
        suspended
    }
    /// Whether questions go through the batch journal.
    #[inline]
    pub(crate) fn journal_on(&self) -> bool {
        self.journal_on.get()
    }
    /// Answer a question through the journal: replayed when recorded, else computed (and counted
    /// as a unit of new work), or `refuse` once the batch is suspended.
    #[inline]
    pub(crate) fn journalled<T: Copy>(
        &self,
        get: impl Fn(&Entry) -> Option<T>,
        make: impl Fn(T) -> Entry,
        refuse: T,
        compute: impl FnOnce() -> T,
    ) -> T {
        if !self.journal_on.get() {
            // Still a unit of work: the run's deadline is looked at inside long checks.
            let v = compute();
            self.fresh_work(1);
            return v;
        }
        let next = self.journal.borrow_mut().take();
        if let Some(e) = next {
            if let Some(v) = get(&e) {
                return v;
            }
            self.desync();
        }
        if self.suspended.get() {
            return refuse;
        }
        let v = compute();
        self.journal.borrow_mut().push(make(v));
        self.fresh_work(1);
        v
    }
    /// Journal a unit of work that fills `out` (a sensor's look, a sweep): replayed when recorded,
    /// else computed by `compute` and kept as one entry in place of the answers it asked for.
    /// `unit` tells its kind apart from the units it is made of.
    pub(crate) fn journalled_bits(&self, unit: u8, out: &mut [u64], compute: impl FnOnce(&mut [u64])) {
        if !self.journal_on.get() {
            return compute(out);
        }
        let at = match self.journal.borrow().peek() {
            Some(&Entry::Bits { unit: u, at }) if u == unit => Some(at),
            _ => None,
        };
        if let Some(at) = at {
            let mut j = self.journal.borrow_mut();
            j.take();
            j.load_bits(at, out);
            return;
        }
        let mark = self.journal.borrow().mark();
        compute(out);
        if !self.stopped() {
            self.journal.borrow_mut().compact_bits(mark, unit, out);
            // New work, even when it asked nothing the journal records (a look that sees nothing).
            self.fresh_work(1);
        }
    }
    /// Count `units` of new work in a bounded batch (answers computed, not replayed): a batch is
    /// suspended only after some, so every batch advances the run. Returns [`SpaceInfo::tick`]'s.
    #[inline]
    pub(crate) fn fresh_work(&self, units: u64) -> bool {
        // A query among many obstacles is more than one unit: one more per 16 exact tests.
        let units = units + crate::geometry::take_tests() / 16;
        self.fresh.set(self.fresh.get() + units);
        crate::clock::work_new(units);
        self.count_units(units)
    }
    /// A replayed answer was not the question asked: a planner is not deterministic. Stop
    /// replaying (answers are computed from here) and say so in debug builds.
    #[cold]
    pub(crate) fn desync(&self) {
        debug_assert!(false, "the journal's answers do not match the questions replayed");
        self.journal.borrow_mut().mode = crate::journal::Mode::Full;
    }
}

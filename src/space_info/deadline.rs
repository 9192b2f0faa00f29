//! The deadline and the suspension: when work in progress must wind down (the run's time limit,
//! or a bounded batch suspended), and how often the clock is read to know it.

use super::SpaceInfo;
use crate::clock::Instant;

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

/// Most units of work (states checked, shortcuts tried) between two looks at the clock. A run
/// looks first after one unit (again after its set-up), and the interval doubles while looks are
/// quick (less than an eighth of [`SLOW_LOOK_MS`] apart), up to this. When a unit is slow (a sight
/// line across 100,000 obstacles), the clock is read more often: when looks are more than
/// [`SLOW_LOOK_MS`] apart, the interval drops at once to the units that take about that long (at
/// least halving), down to every unit. So two looks are at most about `SLOW_LOOK_MS`, or one
/// call's units, apart.
pub const CLOCK_EVERY: u64 = 256;

/// Looks at the clock further apart than this make the interval between them shorter.
pub const SLOW_LOOK_MS: f64 = 0.5;

impl SpaceInfo {
    /// Set the deadline of the work that follows, and forget an earlier interruption.
    pub fn set_deadline(&self, deadline: Deadline) {
        self.deadline.set(deadline);
        self.interrupted.set(false);
    }
    /// Look at the clock again from the next unit of work on, and learn anew how often: what units
    /// cost may have changed (a set-up's quick tests, then a run's slow ones).
    pub fn look_again_soon(&self) {
        self.ticks.set(0);
        self.every.set(1);
        self.last_look.set(None);
    }
    /// The current deadline.
    pub fn deadline(&self) -> Deadline {
        self.deadline.get()
    }
    /// Whether work in progress must wind down, reading the clock now: the deadline has passed
    /// (or the bounded batch was suspended). Once it has, motion checks refuse at once, so nothing
    /// unchecked is ever accepted, and the run stops with its time limit.
    pub fn out_of_time(&self) -> bool {
        self.look();
        self.stopped()
    }
    /// Whether work was cut short by the deadline (without reading the clock).
    #[inline]
    pub fn interrupted(&self) -> bool {
        self.interrupted.get()
    }
    /// Whether work in progress must wind down: the run is out of time, or the batch was
    /// suspended (see [`crate::journal`]). Without reading the clock.
    #[inline]
    pub fn stopped(&self) -> bool {
        self.interrupted.get() || self.suspended.get()
    }
    /// Whether the bounded batch was suspended (its iteration is thrown away and done again).
    #[inline]
    pub fn suspended(&self) -> bool {
        self.suspended.get()
    }
    /// Count `units` of new work; every so often (see [`CLOCK_EVERY`]), read the clock. Returns
    /// whether work in progress must wind down ([`SpaceInfo::stopped`]).
    #[inline]
    pub fn tick(&self, units: u64) -> bool {
        crate::clock::work(units);
        self.count_units(units)
    }
    #[inline]
    pub(super) fn count_units(&self, units: u64) -> bool {
        let t = self.ticks.get() + units;
        if t >= self.every.get() {
            self.ticks.set(0);
            self.look();
        } else {
            self.ticks.set(t);
        }
        self.stopped()
    }
    /// Read the clock: the run's deadline, the batch's suspension, and how often to look again.
    pub(super) fn look(&self) {
        let now = Instant::now();
        if !self.interrupted.get() && self.deadline.get().0.is_some_and(|t| now >= t) {
            self.interrupted.set(true);
        }
        // A batch is suspended only once it has done new work, so every batch advances the run.
        if self.journal_on.get()
            && !self.suspended.get()
            && self.fresh.get() > 0
            && self.suspend_at.get().0.is_some_and(|t| now >= t)
            && self.journal.borrow().on()
        {
            self.suspended.set(true);
        }
        if let Some(last) = self.last_look.get() {
            let ms = now.saturating_duration_since(last).as_secs_f64() * 1000.0;
            let every = self.every.get();
            // Slow units: at once down to as many as take about SLOW_LOOK_MS (at least halved).
            self.every.set(if ms > SLOW_LOOK_MS {
                ((every as f64 * SLOW_LOOK_MS / ms) as u64).clamp(1, (every / 2).max(1))
            } else if ms < SLOW_LOOK_MS / 8.0 {
                (every * 2).min(CLOCK_EVERY)
            } else {
                every
            });
        }
        self.last_look.set(Some(now));
    }
}

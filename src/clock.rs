//! The monotonic clock that time limits and run times read, and a simulated clock for tests.
//!
//! Natively the real clock is `std::time::Instant`. In wasm (a Web Worker, or Node for tests) it is
//! the global `performance.now()`, reached through web-sys's typed `Performance`: the same clock
//! the page's frame times use, so a run's "planner finished in" and the page's measurements agree.
//! Only the methods the core uses are provided. Planner decisions never read the clock (only
//! whether to stop), so runs stay reproducible.
//!
//! # Simulated time
//!
//! The guarantees about time (a bounded batch returns within about twice its budget, a time
//! limit holds inside one long motion check or in smoothing) are statements about the mechanism:
//! how often the clock is read, in units of work, and what is done when it has passed a deadline.
//! [`simulate`] tests them exactly on a busy machine: it installs, for the calling thread, a clock
//! that moves only when work is done. Each unit of work the core counts ([`work`]: the units
//! `SpaceInfo::tick` counts, a state, a clearance, a sight line, plus one per 16 exact tests among
//! obstacles) advances it by a cost the test sets, and each read of the clock by a small fixed
//! cost, so a loop that only reads the clock still sees time pass. Dropping the returned guard
//! brings the real clock back. A run is the same, bit for bit, with or without simulation: only
//! when batches end and when a time limit stops the run depend on the clock.
//!
//! Without simulation the cost is one thread-local flag read per [`Instant::now`] and per
//! [`work`] call.

use std::cell::Cell;
use std::time::Duration;

#[cfg(not(target_arch = "wasm32"))]
pub use native::Instant;

#[cfg(target_arch = "wasm32")]
pub use performance::Instant;

thread_local! {
    /// Whether a simulated clock is installed on this thread (checked first, so the real clock's
    /// path reads one flag).
    static SIMULATED: Cell<bool> = const { Cell::new(false) };
    /// The simulated clock, when installed.
    static SIM: Cell<Sim> = const { Cell::new(Sim::OFF) };
}

/// A simulated clock's state: where it started (a real instant), how far it has moved, and what
/// a unit of work and a read cost.
#[derive(Clone, Copy, Debug)]
struct Sim {
    origin: Option<Instant>,
    /// Nanoseconds since `origin`.
    ns: f64,
    unit_ns: f64,
    read_ns: f64,
    units: u64,
    reads: u64,
    /// The most units counted in one call since [`Simulation::take_largest`].
    largest: u64,
    /// When the first new work was counted since [`Simulation::take_first_new`] (ns), if any.
    first_new: Option<f64>,
    /// When the first planner iteration ended since [`Simulation::take_first_iteration`] (ns).
    first_iteration: Option<f64>,
}

impl Sim {
    const OFF: Sim = Sim {
        origin: None,
        ns: 0.0,
        unit_ns: 0.0,
        read_ns: 0.0,
        units: 0,
        reads: 0,
        largest: 0,
        first_new: None,
        first_iteration: None,
    };
    fn now(&self) -> Instant {
        let origin = self.origin.expect("a simulated clock has its origin");
        origin.checked_add(Duration::from_nanos(self.ns as u64)).unwrap_or(origin)
    }
}

/// A simulated clock installed on this thread (see the module's doc); dropping it brings back the
/// clock that was there before (the real one, or an outer simulation).
#[must_use = "the simulation ends when this guard is dropped"]
pub struct Simulation {
    before: (bool, Sim),
    /// Not `Send`: the clock it installed is this thread's.
    _thread: std::marker::PhantomData<*const ()>,
}

/// Install a simulated clock on this thread, starting at the real clock's present: each unit of
/// work ([`work`]) advances it by `per_unit`, each read of it ([`Instant::now`]) by `per_read`.
/// For tests of the time mechanisms (see the module's doc).
pub fn simulate(per_unit: Duration, per_read: Duration) -> Simulation {
    let before = (SIMULATED.with(Cell::get), SIM.with(Cell::get));
    let origin = Some(if before.0 { before.1.now() } else { Instant::real_now() });
    let sim = Sim { unit_ns: nanos(per_unit), read_ns: nanos(per_read), origin, ..Sim::OFF };
    SIM.with(|s| s.set(sim));
    SIMULATED.with(|s| s.set(true));
    Simulation { before, _thread: std::marker::PhantomData }
}

fn nanos(d: Duration) -> f64 {
    d.as_secs_f64() * 1e9
}

impl Simulation {
    /// Move the clock on by `d` (as if the thread had been busy elsewhere: a paused run).
    pub fn advance(&self, d: Duration) {
        SIM.with(|s| {
            let mut sim = s.get();
            sim.ns += nanos(d);
            s.set(sim);
        });
    }
    /// The time simulated so far, without reading the clock (so without its cost).
    pub fn elapsed(&self) -> Duration {
        Duration::from_nanos(SIM.with(Cell::get).ns as u64)
    }
    /// Units of work counted so far.
    pub fn units(&self) -> u64 {
        SIM.with(Cell::get).units
    }
    /// Reads of the clock so far.
    pub fn reads(&self) -> u64 {
        SIM.with(Cell::get).reads
    }
    /// The most units counted by one [`work`] call since the last call of this (or since the
    /// simulation began): the core reads the clock between such calls, never inside one, so
    /// their cost bounds how late a look can come.
    pub fn take_largest(&self) -> u64 {
        SIM.with(|s| {
            let mut sim = s.get();
            let n = std::mem::take(&mut sim.largest);
            s.set(sim);
            n
        })
    }
    /// When (on this clock, since the simulation began) the first unit of new work was counted
    /// ([`work_new`]) since the last call of this, if one was: a bounded batch can be suspended only
    /// after it has done new work, so every batch advances its run.
    pub fn take_first_new(&self) -> Option<Duration> {
        SIM.with(|s| {
            let mut sim = s.get();
            let at = sim.first_new.take();
            s.set(sim);
            at.map(|ns| Duration::from_nanos(ns as u64))
        })
    }
    /// When (on this clock, since the simulation began) the first planner iteration ended
    /// ([`iteration_done`]) since the last call of this, if one did.
    pub fn take_first_iteration(&self) -> Option<Duration> {
        SIM.with(|s| {
            let mut sim = s.get();
            let at = sim.first_iteration.take();
            s.set(sim);
            at.map(|ns| Duration::from_nanos(ns as u64))
        })
    }
    /// Change what a unit of work costs from now on.
    pub fn set_unit_cost(&self, per_unit: Duration) {
        SIM.with(|s| {
            let mut sim = s.get();
            sim.unit_ns = nanos(per_unit);
            s.set(sim);
        });
    }
}

impl Drop for Simulation {
    fn drop(&mut self) {
        SIM.with(|s| s.set(self.before.1));
        SIMULATED.with(|s| s.set(self.before.0));
    }
}

/// Whether a simulated clock is installed on this thread.
#[inline]
pub fn is_simulated() -> bool {
    SIMULATED.with(Cell::get)
}

/// `units` units of work were done: a simulated clock moves on by their cost (the real clock
/// needs nothing).
#[inline]
pub fn work(units: u64) {
    if SIMULATED.with(Cell::get) {
        simulated_work(units, false);
    }
}

/// Like [`work`], for new work in a bounded batch (answers computed, not replayed: see
/// `SpaceInfo::fresh_work`).
#[inline]
pub fn work_new(units: u64) {
    if SIMULATED.with(Cell::get) {
        simulated_work(units, true);
    }
}

/// A planner iteration ended, after `units` units of its own work between the questions it asked
/// (which were counted as they were answered): a simulated clock moves on by their cost and notes
/// when (see [`Simulation::take_first_iteration`]). Only needed, and only called, when simulated.
pub fn iteration_done(units: u64) {
    if SIMULATED.with(Cell::get) {
        simulated_work(units, false);
        SIM.with(|s| {
            let mut sim = s.get();
            sim.first_iteration.get_or_insert(sim.ns);
            s.set(sim);
        });
    }
}

#[cold]
fn simulated_work(units: u64, new: bool) {
    SIM.with(|s| {
        let mut sim = s.get();
        sim.ns += units as f64 * sim.unit_ns;
        sim.units += units;
        sim.largest = sim.largest.max(units);
        if new && sim.first_new.is_none() {
            sim.first_new = Some(sim.ns);
        }
        s.set(sim);
    });
}

/// Now, on the simulated clock (which a read moves on by its cost).
#[cold]
fn simulated_now() -> Instant {
    SIM.with(|s| {
        let mut sim = s.get();
        sim.ns += sim.read_ns;
        sim.reads += 1;
        s.set(sim);
        sim.now()
    })
}

impl Instant {
    /// Now: the real clock, or the thread's simulated one (see [`simulate`]).
    #[inline]
    pub fn now() -> Instant {
        if SIMULATED.with(Cell::get) {
            simulated_now()
        } else {
            Instant::real_now()
        }
    }
    /// The time since `self`.
    pub fn elapsed(&self) -> Duration {
        Instant::now().saturating_duration_since(*self)
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::time::Duration;

    /// A point in time (`std::time::Instant`).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
    pub struct Instant(std::time::Instant);

    impl Instant {
        /// The real clock's now.
        #[inline]
        pub(super) fn real_now() -> Instant {
            Instant(std::time::Instant::now())
        }
        /// `self + d`, or `None` when not representable.
        pub fn checked_add(&self, d: Duration) -> Option<Instant> {
            self.0.checked_add(d).map(Instant)
        }
        /// The time from `earlier` to `self`, zero if `earlier` is later.
        pub fn saturating_duration_since(&self, earlier: Instant) -> Duration {
            self.0.saturating_duration_since(earlier.0)
        }
    }
}

#[cfg(target_arch = "wasm32")]
mod performance {
    use std::time::Duration;
    use wasm_bindgen::JsCast;

    thread_local! {
        /// `globalThis.performance` (a worker's, a window's or Node's), looked up once.
        static PERFORMANCE: Option<web_sys::Performance> =
            js_sys::Reflect::get(&js_sys::global(), &"performance".into())
                .ok()
                .and_then(|p| p.dyn_into::<web_sys::Performance>().ok());
    }

    /// A point in time: milliseconds since the time origin of `performance`.
    #[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
    pub struct Instant(f64);

    impl Instant {
        /// The real clock's now. Without a `performance` object (not in any host the project
        /// supports), 0: limits by time then never fire, and iteration and node limits still hold.
        pub(super) fn real_now() -> Instant {
            Instant(PERFORMANCE.with(|p| p.as_ref().map_or(0.0, |p| p.now())))
        }
        /// `self + d`, or `None` when not representable.
        pub fn checked_add(&self, d: Duration) -> Option<Instant> {
            let t = self.0 + d.as_secs_f64() * 1000.0;
            t.is_finite().then_some(Instant(t))
        }
        /// The time from `earlier` to `self`, zero if `earlier` is later.
        pub fn saturating_duration_since(&self, earlier: Instant) -> Duration {
            Duration::from_secs_f64(((self.0 - earlier.0) / 1000.0).max(0.0))
        }
    }
}

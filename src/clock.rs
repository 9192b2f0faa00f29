//! The monotonic clock that time limits and run times read.
//!
//! Natively it is `std::time::Instant`. In wasm (a Web Worker, or Node for tests) it is the
//! global `performance.now()`, reached through web-sys's typed `Performance`: the same clock the
//! page's frame times use, so a run's "planner finished in" and the page's measurements agree.
//! Only the methods the core uses are provided. Planner decisions never read the clock (only
//! whether to stop), so runs stay reproducible.

#[cfg(not(target_arch = "wasm32"))]
pub use std::time::Instant;

#[cfg(target_arch = "wasm32")]
pub use performance::Instant;

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
        /// Now. Without a `performance` object (not in any host the project supports), 0: limits
        /// by time then never fire, and iteration and node limits still hold.
        pub fn now() -> Instant {
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
        /// The time since `self`.
        pub fn elapsed(&self) -> Duration {
            Instant::now().saturating_duration_since(*self)
        }
    }
}

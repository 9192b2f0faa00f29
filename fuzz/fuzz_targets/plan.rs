//! (e) A plan with a small budget: the first 8 bytes choose the planner (any in the registry),
//! the seed, `max_iterations` (1..3000), `max_nodes` (2..3001), `shortcut_attempts` and whether
//! events are recorded; the rest is any document `io::import` reads. `time_limit` is 0.2 s. The
//! run goes to its end, then the result, the page's path frames and (ASV) the solution file are
//! made. A run past 0.2 s + `FUZZ_TIME_SLACK_S` is reported as a hang (and libFuzzer's
//! `-timeout=1` catches one that never returns).
#![no_main]
use libfuzzer_sys::fuzz_target;
use planarium_fuzz::{expect, harness, text, FUZZ_TIME_SLACK_S};

fuzz_target!(|data: &[u8]| {
    planarium_fuzz::timed("plan", data, || {
        if data.len() < 8 {
            return;
        }
        let budget = harness::Budget::from_bytes(&data[..8]);
        let doc = text(&data[8..]);
        if let harness::Outcome::Problem(p) = expect(harness::check_import(&doc)) {
            if let Some(r) = expect(harness::plan(*p, &budget)) {
                if r.wall_s > budget.time_s + FUZZ_TIME_SLACK_S {
                    panic!(
                        "hang: {} ran {:.3} s with a time limit of {} s ({:?})",
                        r.planner, r.wall_s, budget.time_s, r.status
                    );
                }
            }
        }
    });
});

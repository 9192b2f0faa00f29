//! (a) The scenario parser and validator: `Scenario::from_json`, then `Problem::from_scenario`.
#![no_main]
use libfuzzer_sys::fuzz_target;
use planarium_fuzz::{expect, harness, text};

fuzz_target!(|data: &[u8]| {
    planarium_fuzz::timed("scenario", data, || {
        expect(harness::check_scenario(&text(data)));
    });
});

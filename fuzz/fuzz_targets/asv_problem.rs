//! (c) The ASV problem file importer, then `Problem::from_scenario`.
#![no_main]
use libfuzzer_sys::fuzz_target;
use planarium_fuzz::{expect, harness, text};

fuzz_target!(|data: &[u8]| {
    planarium_fuzz::timed("asv_problem", data, || {
        expect(harness::check_asv_problem(&text(data)));
    });
});

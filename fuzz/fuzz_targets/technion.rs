//! (b) The Technion HW3 map importer, then `Problem::from_scenario`.
#![no_main]
use libfuzzer_sys::fuzz_target;
use planarium_fuzz::{expect, harness, text};

fuzz_target!(|data: &[u8]| {
    planarium_fuzz::timed("technion", data, || {
        expect(harness::check_technion(&text(data)));
    });
});

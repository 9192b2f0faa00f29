//! (f) An occupancy map: map_server YAML, `===`, the image's bytes (or a plain image), read by
//! `io::occupancy::import_image`, then `Problem::from_scenario`.
#![no_main]
use libfuzzer_sys::fuzz_target;
use planarium_fuzz::{expect, harness};

fuzz_target!(|data: &[u8]| {
    planarium_fuzz::timed("map", data, || {
        expect(harness::check_map(data));
    });
});

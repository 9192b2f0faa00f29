//! (d) The ASV solution reader and checker: the input is a problem (ASV problem file or scenario),
//! a line `===`, then a solution file; without that line, the whole input is a solution file for
//! the built-in `asv-3-easy`.
#![no_main]
use libfuzzer_sys::fuzz_target;
use planarium_fuzz::{expect, harness, text};

const SEPARATOR: &str = "\n===\n";

fuzz_target!(|data: &[u8]| {
    planarium_fuzz::timed("asv_solution", data, || {
        let t = text(data);
        let (problem, solution) = match t.split_once(SEPARATOR) {
            Some((p, s)) => (p.to_string(), s),
            None => (planarium::scenario::builtin("asv-3-easy").expect("built-in").to_json(), &*t),
        };
        expect(harness::check_asv_solution(&problem, solution));
    });
});

//! The same scenario, planner, parameters and seed give the same run: here natively, against the
//! fingerprints pinned in `tests/golden/runs.json`, which the wasm build (tests/wasm.rs, under
//! `wasm-pack test --node`), the Node tests and the browser test check too.
//! `PLANARIUM_BLESS=1 cargo test --test determinism` rewrites the file after a deliberate change.

use planarium::run::{fingerprint, Fingerprint};
use planarium::scenario::builtin;
use serde_json::Value;

fn cases() -> Vec<Value> {
    serde_json::from_str(include_str!("golden/cases.json")).unwrap()
}

fn run(case: &Value) -> Fingerprint {
    let sc = builtin(case["scenario"].as_str().unwrap()).unwrap();
    fingerprint(&sc, case["planner"].as_str().unwrap(), &case["params"], case["seed"].as_u64().unwrap()).unwrap()
}

#[test]
fn runs_match_the_pinned_fingerprints() {
    let got: Vec<Fingerprint> = cases().iter().map(run).collect();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/runs.json");
    if std::env::var("PLANARIUM_BLESS").is_ok() {
        std::fs::write(path, serde_json::to_string_pretty(&got).unwrap() + "\n").unwrap();
    }
    let want: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("tests/golden/runs.json")).unwrap();
    assert_eq!(serde_json::to_value(&got).unwrap(), want);
}

#[test]
fn a_second_run_is_identical() {
    for case in cases() {
        assert_eq!(run(&case), run(&case));
    }
}

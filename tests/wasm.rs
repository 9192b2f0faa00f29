//! The core compiled to wasm (run by `wasm-pack test --node`): a seeded run gives exactly the
//! fingerprint the native build pinned in `tests/golden/runs.json`.
#![cfg(target_arch = "wasm32")]

use planarium::run::fingerprint;
use planarium::scenario::builtin;
use serde_json::Value;
use wasm_bindgen_test::*;

#[wasm_bindgen_test]
fn seeded_runs_match_the_native_fingerprints() {
    let cases: Vec<Value> = serde_json::from_str(include_str!("golden/cases.json")).unwrap();
    let want: Value = serde_json::from_str(include_str!("golden/runs.json")).unwrap();
    for (i, case) in cases.iter().enumerate() {
        let sc = builtin(case["scenario"].as_str().unwrap()).unwrap();
        let got = fingerprint(&sc, case["planner"].as_str().unwrap(), &case["params"], case["seed"].as_u64().unwrap())
            .unwrap();
        assert_eq!(serde_json::to_value(&got).unwrap(), want[i], "case {i}: {case}");
    }
}

#[wasm_bindgen_test]
fn scenario_errors_cross_into_wasm_unchanged() {
    let e = planarium::scenario::Scenario::from_json(r#"{"bounds": [0,0,1,1], "obstacles": [{"polygon": [[0,0],[1,1]]}], "robot": {"kind": "point"}, "start": [0.1,0.1], "goal": [0.9,0.9]}"#).unwrap_err();
    assert_eq!(e.to_string(), "obstacles[0].polygon: needs at least 3 points, found 2");
}

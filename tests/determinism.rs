//! The same scenario, planner, parameters and seed give the same run: here natively, against the
//! fingerprints pinned in `tests/golden/runs.json`, which the wasm build (tests/wasm.rs, under
//! `wasm-pack test --node`), the Node tests and the browser test check too.
//! `PLANARIUM_BLESS=1 cargo test --test determinism` rewrites the file after a deliberate change.

use planarium::run::{fingerprint, fingerprint_in_batches, Fingerprint};
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

/// The page's worker plans in bounded batches; a batch that runs long is suspended in the middle
/// of an iteration and replayed by the next (src/journal.rs). With batches of a few microseconds
/// nearly every batch is suspended, and every pinned run must come out the same, bit for bit.
#[test]
fn runs_in_suspended_batches_match_the_pinned_fingerprints() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/runs.json");
    let want: Vec<Value> =
        serde_json::from_str(&std::fs::read_to_string(path).expect("tests/golden/runs.json")).unwrap();
    let mut suspended = 0;
    for (case, want) in cases().iter().zip(&want) {
        let sc = builtin(case["scenario"].as_str().unwrap()).unwrap();
        let (got, n) = fingerprint_in_batches(
            &sc,
            case["planner"].as_str().unwrap(),
            &case["params"],
            case["seed"].as_u64().unwrap(),
            0.002,
        )
        .unwrap();
        assert_eq!(&serde_json::to_value(&got).unwrap(), want, "{case}: {n} batches suspended");
        suspended += u64::from(n > 0);
    }
    assert!(
        suspended * 2 > want.len() as u64,
        "only {suspended} of {} runs had a batch suspended: the test does not exercise the journal",
        want.len()
    );
}

/// On a simulated clock (`planarium::clock::simulate`) the batches end at the same points on any
/// machine, and the clock is all a simulation changes: every pinned run, in one go and in 0.5 ms
/// batches, with units of work from cheap to dear, comes out the same, bit for bit.
#[test]
fn runs_on_a_simulated_clock_match_the_pinned_fingerprints() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/runs.json");
    let want: Vec<Value> =
        serde_json::from_str(&std::fs::read_to_string(path).expect("tests/golden/runs.json")).unwrap();
    for unit in [std::time::Duration::from_micros(1), std::time::Duration::from_micros(10)] {
        let _sim = planarium::clock::simulate(unit, std::time::Duration::from_nanos(50));
        let mut suspended = 0;
        for (case, want) in cases().iter().zip(&want) {
            assert_eq!(&serde_json::to_value(run(case)).unwrap(), want, "{case} in one go, units of {unit:?}");
            let sc = builtin(case["scenario"].as_str().unwrap()).unwrap();
            let (got, n) = fingerprint_in_batches(
                &sc,
                case["planner"].as_str().unwrap(),
                &case["params"],
                case["seed"].as_u64().unwrap(),
                0.5,
            )
            .unwrap();
            assert_eq!(&serde_json::to_value(&got).unwrap(), want, "{case}: {n} batches suspended, units of {unit:?}");
            suspended += u64::from(n > 0);
        }
        eprintln!("units of {unit:?}: {suspended} of {} runs had a batch suspended", want.len());
        assert!(suspended > 0, "units of {unit:?}: no batch was suspended");
    }
}

/// The same, beyond the pinned runs: every robot's way of checking motions (the point's exact
/// sweep, the arm's and the rigid body's clearances, the vehicle chain's own sampler), RRT*'s
/// rewiring, inspection's sensor sweeps, the samplers that check states, the tree variants, and
/// the last-free connect's walks on bodies, each compared with the same run in one go.
#[test]
fn every_robot_and_planner_gives_the_same_run_in_suspended_batches() {
    let cases = [
        ("arm-2", "rrt-connect", serde_json::json!({})),
        ("arm-3", "rrt", serde_json::json!({ "goal_bias": 0.2 })),
        ("ompl-rect", "rrt-connect", serde_json::json!({})),
        ("asv-3-easy", "rrt-connect", serde_json::json!({})),
        ("asv-7", "rrt-connect", serde_json::json!({ "ladder": 8, "range": 0.05 })),
        ("narrow", "rrt", serde_json::json!({ "ladder": 4, "extend": "connect" })),
        ("narrow", "rrt-star", serde_json::json!({ "max_iterations": 1500 })),
        ("technion-ip", "inspection", serde_json::json!({ "max_iterations": 300 })),
        ("narrow", "rrt", serde_json::json!({ "sampler": "bridge", "dd_radius": 0.3, "exhausted": 3 })),
        ("slot", "rrt-connect", serde_json::json!({ "sampler": "gaussian" })),
        (
            "slot",
            "rrt",
            serde_json::json!({ "sampler": "obstacle", "exhausted": 2, "exhausted_policy": "weighted", "max_iterations": 1000 }),
        ),
        ("hex-trap", "hex-potential", serde_json::json!({})),
        ("narrow", "est", serde_json::json!({})),
        ("zigzag", "bi-est", serde_json::json!({})),
        ("zigzag", "prm", serde_json::json!({})),
        ("slot", "lazy-prm", serde_json::json!({ "max_iterations": 1500 })),
        ("arm-2", "prm-star", serde_json::json!({ "connect": "radius" })),
        ("zigzag", "visibility-graph", serde_json::json!({ "batch": 8 })),
        // The last-free connect on bodies: each step carries its end's clearance into the next.
        ("arm-3", "rrt-connect", serde_json::json!({ "connect": "last-free" })),
        ("horn-10", "rrt-connect", serde_json::json!({ "connect": "last-free" })),
        ("slot", "rrt-connect", serde_json::json!({ "connect": "last-free" })),
        ("asv-3-easy", "rrt-connect", serde_json::json!({ "connect": "last-free" })),
    ];
    let mut suspended = 0;
    for (name, planner, params) in &cases {
        let sc = builtin(name).unwrap();
        let whole = fingerprint(&sc, planner, params, 3).unwrap();
        let (got, n) = fingerprint_in_batches(&sc, planner, params, 3, 0.002).unwrap();
        assert_eq!(got, whole, "{name} {planner} {params}: {n} batches suspended");
        suspended += u64::from(n > 0);
    }
    assert!(suspended as usize * 2 > cases.len(), "only {suspended} of {} runs had a batch suspended", cases.len());
}

/// `--seed random`: the CLI draws a fresh seed, says which on stderr, records it in the result, and
/// `--seed N` with that number replays the run exactly.
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn cli_fresh_seed_is_printed_and_replays() {
    let plan = |seed: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
            .args(["plan", "narrow", "--planner", "rrt", "--seed", seed, "--json"])
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        (json, String::from_utf8(out.stderr).unwrap())
    };
    let (a, said) = plan("random");
    let seed = a["seed"].as_u64().unwrap();
    assert!(seed < 1 << 53, "a fresh seed is exact as a JavaScript number: {seed}");
    assert!(said.contains(&format!("fresh seed {seed} (--seed {seed} replays this run)")), "{said}");
    let (b, _) = plan(&seed.to_string());
    assert_eq!(a["path"], b["path"], "the printed seed replays the path");
    assert_eq!(a["stats"]["checks"], b["stats"]["checks"]);
    let (c, _) = plan("random");
    assert_ne!(c["seed"], a["seed"], "two fresh seeds differ");
    let bad = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args(["plan", "narrow", "--seed", "dice"])
        .output()
        .unwrap();
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("\"dice\" is not a seed"));
}

/// The smoothing time a run reports is the time smoothing took, however the run was batched: a
/// bounded batch whose smoothing ran past its budget is suspended and done again (its checks then
/// answered from the journal, far faster), and the tries count. On a simulated clock (each unit
/// of work 10 µs), a run in 0.5 ms batches reports at least the smoothing time of the same run in
/// one go, and no more than twice it; the paths are the same.
#[test]
fn smoothing_time_counts_the_suspended_tries() {
    use planarium::planners::{self, Params};
    use planarium::problem::Problem;
    use planarium::run::{RunConfig, Session};
    let _sim = planarium::clock::simulate(std::time::Duration::from_micros(10), std::time::Duration::from_nanos(50));
    for (scenario, planner, seed) in [("narrow", "rrt-connect", 7), ("arm-3", "rrt", 2)] {
        let session = || {
            let spec = planners::find(planner).unwrap();
            let config = RunConfig {
                planner: planner.into(),
                params: Params::from_json(spec, &serde_json::json!({})).unwrap(),
                seed,
                record_events: true,
            };
            Session::new(Problem::from_scenario(&builtin(scenario).unwrap()).unwrap(), config).unwrap()
        };
        let mut one = session();
        one.run_to_end();
        let mut batched = session();
        while !batched.step(u64::MAX, 0.5).is_finished() {
            let _ = batched.drain_events();
        }
        let (a, b) = (one.result(), batched.result());
        assert_eq!(a.smoothed, b.smoothed, "{scenario}");
        let (whole, tried) = (a.stats.smoothing_ms, b.stats.smoothing_ms);
        eprintln!(
            "{scenario}: smoothing {whole:.2} ms in one go, {tried:.2} ms in batches ({} suspended)",
            batched.suspensions()
        );
        assert!(whole > 2.0, "{scenario}: smoothing took {whole} ms, within one batch: the test shows nothing");
        assert!(tried >= whole && tried <= 2.0 * whole, "{scenario}: {tried} ms in batches against {whole} in one go");
    }
}

//! Issue 13's reproductions from the command line and the core: each input that crashed, hung or
//! silently skipped work now gets a clear error naming where, or a normal, bounded run.

use planarium::io;
use planarium::limits;
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{RunConfig, Session};
use planarium::scenario::{self, Scenario, ScenarioError};
use serde_json::{json, Value};

#[path = "limits/time.rs"]
mod time;

#[path = "limits/hostile.rs"]
mod hostile;

#[path = "limits/bidi.rs"]
mod bidi;

fn builtin_value(id: &str) -> Value {
    serde_json::from_str(&scenario::builtin(id).unwrap().to_json()).unwrap()
}

/// Parse and build a problem; the first error.
fn problem_error(v: &Value) -> ScenarioError {
    match Scenario::from_value(v) {
        Err(e) => e,
        Ok(sc) => match Problem::from_scenario(&sc) {
            Err(e) => e,
            Ok(_) => panic!("accepted: {v}"),
        },
    }
}

fn session(v: &Value, planner: &str, params: Value, seed: u64) -> Result<Session, String> {
    let sc = Scenario::from_value(v).map_err(|e| e.to_string())?;
    let problem = Problem::from_scenario(&sc).map_err(|e| e.to_string())?;
    session_on(problem, planner, params, seed)
}

fn session_on(problem: Problem, planner: &str, params: Value, seed: u64) -> Result<Session, String> {
    let spec = planners::find(planner).unwrap();
    let params = Params::from_json(spec, &params).map_err(|(k, e)| format!("{k}: {e}"))?;
    Session::new(problem, RunConfig { planner: planner.into(), params, seed, record_events: false })
}

#[test]
fn a_goal_heading_of_1_8e19_with_a_resolution_of_2e_12_is_refused_where_it_is() {
    // Was: `memory allocation of 928867220336 bytes failed` in smoothing (an abort).
    let mut v = builtin_value("slot");
    v["goal"][2] = json!(1.8e19);
    let e = problem_error(&v);
    assert_eq!(e.path, "goal[2]");
    assert!(e.message.contains("between -1e9 and 1e9"), "{e}");
    // With the heading within range, the resolution is refused on its own.
    let mut v = builtin_value("slot");
    v["resolution"] = json!(2e-12);
    let e = problem_error(&v);
    assert_eq!(e.path, "resolution");
    assert!(e.message.contains("too fine") && e.message.contains("at least"), "{e}");
}

#[test]
fn bounds_of_minus_9_2e18_are_refused_where_they_are() {
    // Was: `index out of bounds` at src/motion.rs:101 (the step count saturated and `n + 1` wrapped).
    let mut v = builtin_value("slot");
    v["bounds"] = json!([-9.2e18, 0, 1, 1]);
    let e = problem_error(&v);
    assert_eq!(e.path, "bounds[0]");
    // Within the magnitude limit, a map so wide for its resolution is refused by the step count.
    v["bounds"] = json!([-9.0e8, 0, 1, 1]);
    let e = problem_error(&v);
    assert_eq!(e.path, "resolution", "{e}");
}

#[test]
fn a_footprint_vertex_at_1e308_or_a_rotation_weight_of_1e308_is_refused() {
    let mut v = builtin_value("slot");
    v["robot"]["footprint"][1][0] = json!(1e308);
    assert_eq!(problem_error(&v).path, "robot.footprint[1][0]");
    let mut v = builtin_value("slot");
    v["robot"]["rotation_weight"] = json!(1e308);
    assert_eq!(problem_error(&v).path, "robot.rotation_weight");
    // A weight within the magnitude limit but far too large for the resolution: the rotation
    // makes the longest motion 1e9·π long.
    v["robot"]["rotation_weight"] = json!(1e9);
    let e = problem_error(&v);
    assert_eq!(e.path, "resolution", "{e}");
}

#[test]
fn resolutions_of_1e_9_and_1e_12_are_refused_not_run_for_a_minute_or_skipped() {
    // Was: one motion check took a minute (1e-9), or past 2^31 steps the bisection's power of two
    // wrapped and the motion check visited nothing, "solved" with 50 checks (1e-12).
    for (id, r) in [("open-field", 1e-9), ("open-field", 1e-12), ("arm-2", 1e-12), ("narrow", 1e-9)] {
        let mut v = builtin_value(id);
        v["resolution"] = json!(r);
        let e = problem_error(&v);
        assert_eq!(e.path, "resolution", "{id} at {r}: {e}");
    }
    // The smallest resolution allowed is accepted, and its motions are checked state by state.
    let mut v = builtin_value("open-field");
    v["obstacles"] = json!([]);
    let sc = Scenario::from_value(&v).unwrap();
    let extent = Problem::from_scenario(&sc).unwrap().si.space.max_extent();
    v["resolution"] = json!(extent / limits::MAX_MOTION_STEPS * 1.0001);
    let mut s = session(&v, "rrt", json!({"range": 2.0, "goal_bias": 1.0, "max_iterations": 1}), 1).unwrap();
    s.run_to_end();
    let r = s.result();
    // One iteration straight to the goal, 1.19 long: checked at every step of the resolution.
    let d = 0.84 * std::f64::consts::SQRT_2;
    let expected = (d / v["resolution"].as_f64().unwrap()).ceil() as u64;
    assert_eq!(r.status, "solved");
    assert!(
        r.stats.checks >= expected,
        "a fine resolution checks every state: {} checks, {expected} steps",
        r.stats.checks
    );
}

#[test]
fn an_asv_file_with_a_huge_vehicle_or_obstacle_count_is_refused_before_any_allocation() {
    let e = io::import("123456789012\n0.1 0.1\n", "huge").unwrap_err();
    assert_eq!((e.line, e.column), (Some(1), Some(1)), "{e}");
    assert!(e.message.contains("limit"), "{e}");
    let e = io::import("99999999999999999999999\n", "huger").unwrap_err();
    assert_eq!(e.line, Some(1), "{e}");
    let good = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/asv/3ASV.txt")).unwrap();
    let lines: Vec<&str> = good.lines().collect();
    let mut text = lines[..3].join("\n");
    text.push_str("\n4000000000000\n");
    let e = io::import(&text, "many-obstacles").unwrap_err();
    assert_eq!(e.line, Some(4), "{e}");
    // A solution file that claims more steps than it could hold is refused by its first line.
    let e = io::asv::read_solution("18446744073709551615 1.0\n0.1 0.1 0.2 0.2\n").unwrap_err();
    assert!(e.starts_with("line 1"), "{e}");
}

#[test]
fn counts_are_capped_with_the_path_that_breaks_them() {
    let mut v = builtin_value("open-field");
    let rect = json!({"rect": [0.1, 0.1, 0.11, 0.11]});
    v["obstacles"] = Value::Array(vec![rect; limits::MAX_OBSTACLES + 1]);
    let e = problem_error(&v);
    assert_eq!(e.path, "obstacles");
    assert!(e.message.contains("100000"), "{e}");
    let ring: Vec<Value> = (0..=limits::MAX_POLYGON_VERTICES)
        .map(|i| {
            let a = i as f64 / (limits::MAX_POLYGON_VERTICES + 1) as f64 * std::f64::consts::TAU;
            json!([0.5 + 0.1 * a.cos(), 0.5 + 0.1 * a.sin()])
        })
        .collect();
    v["obstacles"] = json!([{ "polygon": ring }]);
    assert_eq!(problem_error(&v).path, "obstacles[0].polygon");
    let mut v = builtin_value("arm-3");
    v["robot"]["links"] = Value::Array(vec![json!(0.01); limits::MAX_LINKS + 1]);
    assert_eq!(problem_error(&v).path, "robot.links");
    let mut v = builtin_value("open-field");
    v["name"] = json!("n".repeat(limits::MAX_NAME_CHARS + 1));
    assert_eq!(problem_error(&v).path, "name");
    // A key a megabyte long is named, cut short.
    let mut v = builtin_value("open-field");
    v["k".repeat(1 << 20)] = json!(1);
    let e = problem_error(&v);
    assert!(e.path.chars().count() <= 100 && e.path.ends_with('…'), "{}", e.path.len());
    // More text than the limit is refused before it is parsed.
    let big = format!("{{\"notes\": \"{}\"}}", "x".repeat(limits::MAX_TEXT_BYTES));
    let e = Scenario::from_json(&big).unwrap_err();
    assert!(e.message.contains("limit"), "{e}");
    assert!(io::import(&big, "big").is_err());
}

#[test]
fn max_nodes_is_capped_at_a_million() {
    let v = builtin_value("narrow");
    let e = session(&v, "rrt", json!({"max_nodes": 1e8}), 1).err().expect("1e8 nodes refused");
    assert!(e.starts_with("max_nodes"), "{e}");
    assert!(session(&v, "rrt", json!({"max_nodes": limits::MAX_NODES}), 1).is_ok());
}

#[test]
fn a_hexagonal_tiling_too_fine_for_its_map_is_refused() {
    let v = builtin_value("hex-open");
    let e = session(&v, "hex-potential", json!({"cell_size": 1e-6}), 1).err().expect("refused");
    assert!(e.contains("cell_size") && e.contains("limit"), "{e}");
}

#[test]
fn the_cli_names_bad_input() {
    let dir = std::env::temp_dir().join(format!("planarium-limits-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.json");
    let mut v = builtin_value("slot");
    v["bounds"] = json!([-9.2e18, 0, 1, 1]);
    std::fs::write(&bad, v.to_string()).unwrap();
    for cmd in ["validate", "plan"] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
            .args([cmd, bad.to_str().unwrap()])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(matches!(out.status.code(), Some(1 | 2)), "{cmd}: an error exit, not a crash: {:?}", out.status);
        assert!(err.contains("bounds[0]") && !err.contains("panicked"), "{cmd}: {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_benchmark_pages_set_ups_are_capped_and_their_errors_cut() {
    let many: String = (0..17).map(|i| format!("s{i}: rrt\n")).collect();
    let e = planarium::run::bench::parse_setup_lines(&many).unwrap_err();
    assert!(e.starts_with("set-up line 17: more than 16"), "{e}");
    let e = planarium::run::bench::parse_setup_lines(&format!("rrt --{} 1", "x".repeat(100_000))).unwrap_err();
    assert!(e.chars().count() < 400, "{} characters", e.len());
}

#[test]
fn numbers_too_small_for_exact_predicates_are_refused() {
    let mut v = builtin_value("open-field");
    v["obstacles"][0]["rect"][1] = json!(5e-324);
    let e = problem_error(&v);
    assert_eq!(e.path, "obstacles[0].rect[1]");
    assert!(e.message.contains("too small"), "{e}");
    v["obstacles"][0]["rect"][1] = json!(0.0);
    assert!(Scenario::from_value(&v).is_ok(), "0 itself is fine");
}

#[test]
fn hex_potential_never_passes_max_nodes() {
    // The coarse tiling alone would pass a small node limit: refused up front, with the reason.
    let v = builtin_value("hex-open");
    let e = session(&v, "hex-potential", json!({"max_nodes": 5}), 1).err().expect("refused");
    assert!(e.contains("max_nodes"), "{e}");
    // Refinement stops at the limit: a split that may not fit ends the run at its node limit.
    let coarse = {
        let mut s = session(&v, "hex-potential", json!({"max_iterations": 1}), 1).unwrap();
        s.run_to_end();
        s.result().stats.nodes
    };
    for extra in [1, 3, 6, 7, 20] {
        let limit = coarse + extra;
        let mut s = session(&v, "hex-potential", json!({"max_nodes": limit}), 1).unwrap();
        s.run_to_end();
        let r = s.result();
        assert!(r.stats.nodes <= limit, "{} nodes past max_nodes {limit}", r.stats.nodes);
    }
}

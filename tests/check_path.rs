//! `planarium check-path` and `run::check_path`: a path from elsewhere judged by the rule the
//! planners keep. A motion that touches an obstacle's corner only is refused (closed sets), the
//! same path around the corner passes, a planner's own result file passes as it is, and the file
//! forms (one path, JSON lines with seeds) and bad input are answered as documented.

mod common;

use planarium::problem::Problem;
use planarium::run::check_path;
use planarium::scenario::Scenario;
use std::process::Command;

/// A box [0.25, 0.5]², start above its left side and goal right of it; every coordinate dyadic,
/// so that the motion start → goal passes exactly through the corner (0.5, 0.5).
const CORNER: &str = r#"{"bounds": [0, 0, 1, 1], "robot": {"kind": "point"}, "resolution": 0.01,
  "obstacles": [{"rect": [0.25, 0.25, 0.5, 0.5]}], "start": [0.375, 0.625], "goal": [0.625, 0.375]}"#;

fn planarium(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_planarium")).args(args).output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp(name: &str, text: &str) -> String {
    let f = std::env::temp_dir().join(format!("planarium-check-path-{}-{name}", std::process::id()));
    std::fs::write(&f, text).unwrap();
    f.to_str().unwrap().to_string()
}

#[test]
fn a_motion_through_a_corner_only_is_refused_and_the_way_around_passes() {
    let sc = Scenario::from_json(CORNER).unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let through = vec![vec![0.375, 0.625], vec![0.625, 0.375]];
    let c = check_path(&problem, &through);
    assert!(!c.valid);
    assert_eq!((c.motions, c.motions_refused), (1, 1));
    assert_eq!((c.refusals[0].what, c.refusals[0].at), ("motion", 0));
    // The obstacle is named (the corner itself, where the validator stopped).
    assert_eq!(c.refusals[0].why, "at [0.5, 0.5]: it meets obstacles[0]");
    // The independent checker's exact segment test agrees.
    assert!(common::path_problem(&sc, &through).is_some());
    let around = vec![vec![0.375, 0.625], vec![0.625, 0.625], vec![0.625, 0.375]];
    let c = check_path(&problem, &around);
    assert!(c.valid, "{:?}", c.refusals);
    assert_eq!((c.states, c.motions, c.motions_refused), (3, 2, 0));
    assert!(common::path_problem(&sc, &around).is_none());
    // Not from the start, not to the goal, a state inside the box: each named.
    let c = check_path(&problem, &[vec![0.375, 0.75], vec![0.375, 0.625], vec![0.3, 0.3], vec![0.625, 0.625]]);
    let what: Vec<(&str, usize)> = c.refusals.iter().map(|r| (r.what, r.at)).collect();
    assert_eq!(what, [("state", 2), ("start", 0), ("goal", 3)], "{:?}", c.refusals);
    assert!(c.refusals[0].why.contains("obstacles[0]"), "{}", c.refusals[0].why);
}

#[test]
fn the_command_reads_paths_as_files_give_them_and_says_which_it_refuses() {
    let scenario = temp("corner.json", CORNER);
    // JSON lines, as the OMPL harness writes them with --paths: seeds shown, status 1 on a refusal.
    let lines = temp(
        "lines.jsonl",
        "{\"seed\":4,\"path\":[[0.375,0.625],[0.625,0.625],[0.625,0.375]]}\n{\"seed\":7,\"path\":[[0.375,0.625],[0.625,0.375]]}\n",
    );
    let (code, out, err) = planarium(&["check-path", &scenario, &lines]);
    assert_eq!(code, Some(1), "{err}");
    assert!(out.contains("path 1 (seed 4): valid"), "{out}");
    assert!(out.contains("path 2 (seed 7): refused (1 of 1 motions refused)"), "{out}");
    assert!(out.contains("motion 1 (path[0] → path[1])"), "{out}");
    assert!(out.contains("1 of 2 paths valid"), "{out}");
    let (code, out, _) = planarium(&["check-path", &scenario, &lines, "--json"]);
    assert_eq!(code, Some(1));
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        (j["valid"].as_u64(), j["refused"].as_u64(), j["motions"].as_u64(), j["motions_refused"].as_u64()),
        (Some(1), Some(1), Some(3), Some(1))
    );
    assert_eq!(j["paths"][1]["seed"], 7);
    assert_eq!(j["paths"][1]["refusals"][0]["what"], "motion");
    // One path as an array of states: status 0 when valid.
    let one = temp("one.json", "[[0.375,0.625],[0.625,0.625],[0.625,0.375]]");
    let (code, out, err) = planarium(&["check-path", &scenario, &one]);
    assert_eq!(code, Some(0), "{out}{err}");
    // A planner's own result file, as `plan --json` writes it, passes as it is.
    let (code, result, err) = planarium(&["plan", "narrow", "--seed", "3", "--json"]);
    assert_eq!(code, Some(0), "{err}");
    let result = temp("result.json", &result);
    let (code, out, err) = planarium(&["check-path", "narrow", &result]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(out.contains("1 of 1 paths valid"), "{out}");
    // Bad input: an error naming where, status 2.
    for (text, says) in [
        ("{\"path\":[[0.375,0.625]]}\n{\"path\":[[0.375,\"x\"]]}\n", "line 2: state 0: \"x\" is not a number"),
        ("{\"states\":[]}", "an object without a \"path\" key"),
        ("[[0.375,0.625]] [", "not JSON"),
        ("", "no path in the file"),
        ("{\"path\":7}", "\"path\" must be an array of states"),
    ] {
        let bad = temp("bad.json", text);
        let (code, _, err) = planarium(&["check-path", &scenario, &bad]);
        assert_eq!(code, Some(2), "{text}: {err}");
        assert!(err.contains(says) && err.contains("bad.json"), "{text}: {err}");
    }
}

/// Hostile paths on every built-in (every robot kind, the Puma's included): states of the wrong
/// size, huge, tiny and out-of-bounds numbers, repeated states, a single state. `check_path` never
/// panics, refuses every path with a state out of bounds or of the wrong size, and a path it
/// accepts starts at the start.
#[test]
fn hostile_paths_are_refused_without_a_panic() {
    let mut rng = planarium::rng::Rng::new(7);
    for id in planarium::scenario::builtin_names() {
        let sc = planarium::scenario::builtin(id).unwrap();
        let problem = Problem::from_scenario(&sc).unwrap();
        let dims = sc.start.len();
        for case in 0..40 {
            let n = 1 + rng.below(4);
            let mut path: Vec<Vec<f64>> = Vec::new();
            let mut broken = false;
            for k in 0..n {
                let len = match rng.below(8) {
                    0 => dims + 1,
                    1 => dims.saturating_sub(1),
                    _ => dims,
                };
                let q: Vec<f64> = (0..len)
                    .map(|i| match rng.below(10) {
                        0 => 1e300,
                        1 => -1e300,
                        2 => 1e9,
                        3 => 1e-300,
                        4 => sc.bounds[2] + 1.0,
                        5..=6 => sc.start.get(i).copied().unwrap_or(0.0),
                        _ => sc.goal.as_ref().and_then(|g| g.get(i)).copied().unwrap_or(0.0),
                    })
                    .collect();
                broken |= len != dims || (k == 0 && q != sc.start);
                path.push(q);
            }
            let c = check_path(&problem, &path);
            assert_eq!((c.states, c.motions), (n, n - 1), "{id} case {case}");
            if broken {
                assert!(!c.valid, "{id} case {case}: accepted {path:?}");
            }
            assert!(c.refusals.len() <= planarium::run::MAX_DESCRIBED);
            if !c.valid {
                assert!(!c.refusals.is_empty(), "{id} case {case}: refused without a reason");
            }
        }
        // No state at all.
        assert!(!check_path(&problem, &[]).valid, "{id}: the empty path");
    }
}

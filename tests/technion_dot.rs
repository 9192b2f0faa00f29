//! Technion maps of the later offerings (only `WIDTH`, `HEIGHT`, `OBSTACLES`; start and goal given
//! beside them) and the course's point robot ("dot"): imported with default free corners, and
//! planned through the CLI with `--robot`, `--start`, `--goal`, whose errors name the flag. The
//! sample map `tests/data/technion-dot-400x300.json` is made up (400×300, 16 rectangles).

use serde_json::Value;
use std::process::Command;

const MAP: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/technion-dot-400x300.json");
const MAP_MP: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/fuzz/corpus/technion/map_mp.json");

/// The map's rectangles as `[x0, y0, x1, y1]`, read here from the file.
fn rects() -> Vec<[f64; 4]> {
    let v: Value = serde_json::from_str(&std::fs::read_to_string(MAP).unwrap()).unwrap();
    v["OBSTACLES"]
        .as_array()
        .unwrap()
        .iter()
        .map(|poly| {
            let xs: Vec<f64> = poly.as_array().unwrap().iter().map(|p| p[0].as_f64().unwrap()).collect();
            let ys: Vec<f64> = poly.as_array().unwrap().iter().map(|p| p[1].as_f64().unwrap()).collect();
            let (lo, hi) = (
                |v: &[f64]| v.iter().cloned().fold(f64::MAX, f64::min),
                |v: &[f64]| v.iter().cloned().fold(f64::MIN, f64::max),
            );
            [lo(&xs), lo(&ys), hi(&xs), hi(&ys)]
        })
        .collect()
}

/// Free for the dot: in the map and in or on no rectangle.
fn free(p: &[f64]) -> bool {
    (0.0..=399.0).contains(&p[0])
        && (0.0..=299.0).contains(&p[1])
        && !rects().iter().any(|r| p[0] >= r[0] && p[0] <= r[2] && p[1] >= r[1] && p[1] <= r[3])
}

fn planarium(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_planarium")).args(args).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into(), String::from_utf8_lossy(&out.stderr).into())
}

fn plan_json(args: &[&str]) -> Value {
    let (ok, out, err) = planarium(args);
    assert!(ok, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn the_sample_map_is_what_it_says() {
    let r = rects();
    assert_eq!(r.len(), 16);
    assert!(r.iter().all(|r| r[0] < r[2] && r[1] < r[3] && r[2] <= 399.0 && r[3] <= 299.0));
}

#[test]
fn a_map_without_start_and_goal_imports_with_the_dot_and_free_corners() {
    let text = std::fs::read_to_string(MAP).unwrap();
    let sc = planarium::io::import(&text, "technion-dot-400x300").unwrap();
    assert_eq!(sc.robot.kind(), "point");
    assert_eq!(sc.bounds, [0.0, 0.0, 399.0, 299.0]);
    let goal = sc.goal.clone().unwrap();
    assert!(free(&sc.start) && free(&goal), "{:?} {goal:?}", sc.start);
    assert!(sc.start[0] < 60.0 && sc.start[1] < 60.0, "start near the lower left: {:?}", sc.start);
    assert!(goal[0] > 340.0 && goal[1] > 240.0, "goal near the upper right: {goal:?}");
    // Deterministic: the same file gives the same scenario.
    assert_eq!(planarium::io::import(&text, "technion-dot-400x300").unwrap(), sc);
    // A rectangle over the lower left corner moves the start out of it, still free.
    let covered = text.replacen("\"OBSTACLES\": [", "\"OBSTACLES\": [[[0, 0], [35, 0], [35, 25], [0, 25]],", 1);
    let sc2 = planarium::io::import(&covered, "m").unwrap();
    assert!(sc2.start[0] > 35.0 || sc2.start[1] > 25.0, "{:?}", sc2.start);
    assert_ne!(sc2.start, sc.start);
}

#[test]
fn plan_with_start_and_goal_for_the_dot() {
    let r = plan_json(&["plan", MAP, "--robot", "dot", "--start", "10,10", "--goal", "390,290", "--json"]);
    assert_eq!(r["solved"], true, "{r}");
    let path: Vec<Vec<f64>> = serde_json::from_value(r["path"].clone()).unwrap();
    assert_eq!(path[0], [10.0, 10.0]);
    assert_eq!(*path.last().unwrap(), [390.0, 290.0]);
    assert!(path.iter().all(|p| free(p)), "{path:?}");
    // The dot is the default robot of such a map, and rrt-star runs on it too.
    let r = plan_json(&["plan", MAP, "--start", "10,290", "--goal", "390,10", "--planner", "rrt-star", "--json"]);
    assert_eq!(r["solved"], true, "{r}");
    assert!(r["stats"].get("cost_fk").is_none(), "no arm, no fk cost");
    // Without --start/--goal: the default corners.
    let r = plan_json(&["plan", MAP, "--json"]);
    assert_eq!(r["solved"], true, "{r}");
}

#[test]
fn start_and_goal_errors_name_the_flag() {
    for (args, want) in [
        (vec!["--start", "10,10,3", "--goal", "390,290"], "--start: a point robot's state has 2 numbers, found 3"),
        (vec!["--start", "50,40", "--goal", "390,290"], "--start: in collision with obstacles[0]"),
        (vec!["--start", "10,10", "--goal", "390,x"], "--goal 390,x: number 2 (\"x\") is not a finite number"),
        (vec!["--start", "10,10", "--goal", "450,290"], "--goal: out of bounds: x must stay within [0, 399]"),
        (vec!["--robot", "cat"], "--robot: \"cat\" is not a Technion robot (arm or dot)"),
        (vec!["--robot", "arm", "--goal", "0,0,0,0"], "START: is missing"),
    ] {
        let mut all = vec!["plan", MAP];
        all.extend(&args);
        let (ok, _, err) = planarium(&all);
        assert!(!ok, "{args:?} should fail");
        assert!(err.contains(want), "{args:?}: {err}");
    }
    // --robot on a scenario that is not a Technion map.
    let (ok, _, err) = planarium(&["plan", "narrow", "--robot", "dot"]);
    assert!(!ok && err.contains("--robot applies to Technion maps only"), "{err}");
}

#[test]
fn the_arm_takes_start_and_goal_from_the_command_line_too() {
    // map_mp's own START and GOAL, given on the command line: the same run.
    let own = plan_json(&["plan", MAP_MP, "--json"]);
    let given = plan_json(&["plan", MAP_MP, "--start", "0.78,-0.78,0.0,0.0", "--goal", "0.3,0.15,1.0,1.1", "--json"]);
    assert_eq!(own["path"], given["path"]);
    assert_eq!(given["solved"], true);
    assert!(given["stats"]["cost_fk"].as_f64().unwrap() > given["stats"]["cost"].as_f64().unwrap());
    // A goal of three joint angles, and a goal through the wall.
    let (ok, _, err) = planarium(&["plan", MAP_MP, "--goal", "0.3,0.15,1.0"]);
    assert!(!ok && err.contains("--goal: an arm robot's state has 4 numbers, found 3"), "{err}");
    let (ok, _, err) = planarium(&["plan", MAP_MP, "--goal", "0.7854,0,0,0"]);
    assert!(!ok && err.contains("--goal: in collision"), "{err}");
    // A scenario's start replaced: the narrow passage from a free place.
    let r = plan_json(&["plan", "narrow", "--start", "0.2,0.3", "--json"]);
    assert_eq!(r["path"][0], serde_json::json!([0.2, 0.3]));
}

use super::*;
use crate::problem::Problem;

fn err(text: &str) -> String {
    match Scenario::from_json(text) {
        Ok(sc) => match Problem::from_scenario(&sc) {
            Ok(_) => panic!("expected an error for {text}"),
            Err(e) => e.to_string(),
        },
        Err(e) => e.to_string(),
    }
}

const BASE: &str = r#""bounds": [0, 0, 1, 1], "robot": {"kind": "point"}, "start": [0.1, 0.1], "goal": [0.9, 0.9]"#;

fn with(extra: &str) -> String {
    format!("{{{BASE}{extra}}}")
}

#[test]
fn builtins_parse_and_build() {
    for name in builtin_names() {
        let sc = builtin(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        Problem::from_scenario(&sc).unwrap_or_else(|e| panic!("{name}: {e}"));
        // Round trip through the contract's JSON.
        assert_eq!(Scenario::from_json(&sc.to_json()).unwrap(), sc, "{name} round-trips");
    }
}

#[test]
fn errors_name_their_json_path() {
    assert_eq!(
        err(&with(
            r#", "obstacles": [{"rect": [0,0,0.1,0.1]}, {"rect": [0.3,0.3,0.4,0.4]}, {"circle": [0.5,0.5,0.01]}, {"polygon": [[0,0],[1,1]]}]"#
        )),
        "obstacles[3].polygon: needs at least 3 points, found 2"
    );
    assert_eq!(err(&with(r#", "obstacels": []"#)).split(' ').next().unwrap(), "obstacels:");
    assert!(err(&with(r#", "obstacels": []"#)).contains("unknown key"));
    assert_eq!(
        err(&with(r#", "obstacles": [{"rect": [0,0,0.1]}]"#)),
        "obstacles[0].rect: must be [x0, y0, x1, y1] (4 numbers), found 3 numbers"
    );
    assert_eq!(
        err(&with(r#", "obstacles": [{"box": [0,0,0.1,0.2]}]"#)),
        "obstacles[0].box: unknown obstacle kind (use rect, polygon, circle or segment)"
    );
    assert_eq!(
        err(&with(r#", "obstacles": [{"circle": [0.5,0.5,-1]}]"#)),
        "obstacles[0].circle[2]: radius must be positive"
    );
    assert!(err(&with(r#", "obstacles": [{"polygon": [[0,0],[1,1],[1,0],[0,1]]}]"#))
        .starts_with("obstacles[0].polygon: must be a simple polygon"));
    assert!(err(&with(r#", "robot2": 1"#)).starts_with("robot2: unknown key"));
    assert!(err(&with(r#", "": 1"#)).starts_with("\"\": unknown key"), "an empty key is named");
    assert_eq!(
        err(r#"{"bounds": [0,0,1,1], "robot": {"kind": "point", "size": 2}, "start": [0.1,0.1], "goal": [0.2,0.2]}"#)
            .split(':')
            .next()
            .unwrap(),
        "robot.size"
    );
    assert_eq!(
        err(r#"{"bounds": [0,0,1,1], "robot": {"kind": "tank"}, "start": [0.1,0.1], "goal": [0.2,0.2]}"#),
        "robot.kind: unknown robot kind \"tank\" (use point, rigid, arm, asv or spatial-arm)"
    );
    assert_eq!(
        err(r#"{"bounds": [1,0,0,1], "robot": {"kind": "point"}, "start": [0.1,0.1], "goal": [0.2,0.2]}"#),
        "bounds: needs xmin < xmax and ymin < ymax"
    );
    assert_eq!(
        err(r#"{"bounds": [0,0,1,1], "robot": {"kind": "point"}, "start": [0.1,0.1]}"#),
        "goal: is missing (only an inspection task may omit it)"
    );
    assert_eq!(
        err(&with(r#", "planner": {"name": "rrt", "goal_bias": 2}"#)),
        "planner.goal_bias: must be between 0 and 1"
    );
    assert!(err(&with(r#", "planner": {"name": "no-such-planner"}"#))
        .starts_with("planner.name: unknown planner \"no-such-planner\""));
}

#[test]
fn syntax_errors_give_line_and_column() {
    let e = Scenario::from_json(
        "{\n  \"bounds\": [0, 0, 1, 1],\n  \"robot\": {\"kind\": \"point\"}\n  \"start\": [0.1, 0.1]\n}",
    )
    .unwrap_err();
    assert_eq!((e.line, e.column), (Some(4), Some(3)));
    assert!(e.to_string().starts_with("line 4, column 3: invalid JSON"));
}

#[test]
fn start_and_goal_errors_say_which_and_why() {
    let obst = r#", "obstacles": [{"rect": [0.4,0.4,0.6,0.6]}]"#;
    let e = err(&format!(
        r#"{{"bounds": [0,0,1,1], "robot": {{"kind": "point"}}, "start": [0.5, 0.5], "goal": [0.9, 0.9]{obst}}}"#
    ));
    assert_eq!(e, "start: in collision with obstacles[0] (a rect)");
    let e = err(&format!(
        r#"{{"bounds": [0,0,1,1], "robot": {{"kind": "point"}}, "start": [0.1, 0.1], "goal": [0.9, 1.5]{obst}}}"#
    ));
    assert_eq!(e, "goal: out of bounds: y must stay within [0, 1]");
    let e = err(
        r#"{"bounds": [0,0,1,1], "robot": {"kind": "rigid", "footprint": [[0,0],[0.1,0],[0,0.1]]}, "start": [0.1, 0.1], "goal": [0.9, 0.9, 0]}"#,
    );
    assert_eq!(e, "start: a rigid robot's state has 3 numbers, found 2");
    // A rigid robot's start touching an obstacle (closed sets).
    let e = err(
        r#"{"bounds": [0,0,1,1], "obstacles": [{"segment": [0.2,0,0.2,1]}], "robot": {"kind": "rigid", "footprint": [[-0.1,-0.01],[0.1,-0.01],[0.1,0.01],[-0.1,0.01]]}, "start": [0.1, 0.5, 0], "goal": [0.9, 0.9, 0]}"#,
    );
    assert_eq!(e, "start: in collision with obstacles[0] (a segment)");
}

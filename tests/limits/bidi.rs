//! Bidirectional and format controls in what a user opens (a scenario's keys and values, a map's
//! YAML, the course files' words, parameter and planner names) are echoed in error messages as
//! `[U+202E]`, never raw: an override (U+202E) would turn the error box's line around.

use super::{builtin_value, problem_error, session};
use planarium::io;
use planarium::io::occupancy;
use planarium::scenario::Scenario;
use serde_json::json;

/// The raw controls a message must not hold (the page's list of bidirectional controls, the
/// invisible format characters these tests use, and control characters).
fn raw_control(text: &str) -> Option<char> {
    text.chars().find(|&c| {
        matches!(c, '\u{61c}' | '\u{200b}'..='\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
            || c.is_control()
    })
}

fn clean(what: &str, text: &str) {
    assert!(raw_control(text).is_none(), "{what}: a raw {:?} in {text:?}", raw_control(text));
}

#[test]
fn a_scenarios_keys_and_values_are_echoed_with_their_controls_shown() {
    // A key at the top, a key in an obstacle, a value (the robot's kind), the format.
    let mut v = builtin_value("open-field");
    v["\u{202E}evil"] = json!(1);
    let e = problem_error(&v);
    assert_eq!(e.path, "[U+202E]evil", "{e}");
    clean("top key", &e.to_string());
    let mut v = builtin_value("open-field");
    v["obstacles"][0] = json!({"re\u{2067}ct\u{200B}": [0, 0, 1, 1]});
    let e = problem_error(&v);
    assert!(e.path.contains("[U+2067]") && e.path.contains("[U+200B]"), "{e}");
    clean("obstacle key", &e.to_string());
    let mut v = builtin_value("open-field");
    v["robot"]["kind"] = json!("po\u{202E}int\u{0007}");
    let e = problem_error(&v);
    assert!(e.message.contains("po[U+202E]int[U+0007]"), "{e}");
    clean("value", &e.to_string());
    let e = Scenario::from_json("{\"format\": \"\u{202D}x\"}").unwrap_err();
    clean("format", &e.to_string());
    // Syntax errors say where; the text around is not echoed raw either.
    let e = Scenario::from_json("{\"\u{202E}\": }").unwrap_err();
    clean("syntax", &e.to_string());
}

#[test]
fn a_planner_name_or_parameter_from_a_scenario_is_echoed_with_its_controls_shown() {
    let v = builtin_value("narrow");
    let e = session(&v, "rrt", json!({"go\u{202E}al_bias": 0.1}), 1).err().expect("refused");
    assert!(e.contains("go[U+202E]al_bias"), "{e}");
    clean("parameter", &e);
    let sc = Scenario::from_value(&v).unwrap();
    let problem = planarium::problem::Problem::from_scenario(&sc).unwrap();
    let config = planarium::run::RunConfig {
        planner: "r\u{202E}rt".into(),
        params: planarium::planners::Params::defaults(planarium::planners::find("rrt").unwrap()),
        seed: 1,
        record_events: false,
    };
    let e = planarium::run::Session::new(problem, config).err().expect("unknown planner");
    assert!(e.contains("r[U+202E]rt"), "{e}");
    clean("planner", &e);
    let e = planarium::run::bench::parse_setup_lines("rrt --\u{202E}range 1").unwrap_err();
    clean("bench set-up", &e);
}

#[test]
fn the_course_files_and_a_maps_yaml_are_echoed_with_their_controls_shown() {
    // A map_server YAML: a key, and a value.
    let pgm = b"P5\n2 2\n255\n\xff\xff\xff\xff".to_vec();
    for yaml in [
        "image: m.pgm\nres\u{202E}olution: 0.05\n",
        "image: m.pgm\nresolution: 0.0\u{202E}5\n",
        "image: m.pgm\nmode: \u{2066}raw\n",
    ] {
        let e = occupancy::import_image(&pgm, "m.pgm", Some((yaml, "m\u{202E}.yaml"))).unwrap_err();
        clean(yaml, &e.to_string());
        clean(yaml, &e.path);
        assert!(e.to_string().contains("[U+"), "{e}");
    }
    // An ASV problem file: a word that is not a number.
    let e = io::import("3\n0.1 0.2 0.3 0.4\u{202E} 0.5 0.6\n", "p").unwrap_err();
    assert!(e.to_string().contains("[U+202E]"), "{e}");
    clean("asv", &e.to_string());
    let e = io::asv::read_solution("1 0.1\n0.1 0.\u{202E}2 0.3 0.4\n").unwrap_err();
    clean("asv solution", &e);
    // A Technion map: an unknown key.
    let e = io::technion::import_map("{\"WIDTH\": 10, \"HEIGHT\": 10, \"OBST\u{202E}ACLES\": []}", "t").unwrap_err();
    assert!(e.path.contains("[U+202E]"), "{e}");
    clean("technion", &e.to_string());
}

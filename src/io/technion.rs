//! The Technion "Algorithmic Motion Planning" HW3 maps (courses.md §5): `map_mp.json` (motion
//! planning, with a `GOAL`) and `map_ip.json` (inspection, with `INSPECTION_POINTS`).
//!
//! The course's robot is fixed: 4 links of lengths 80, 70, 40, 40 with the base at (0, 0), relative
//! joint angles wrapping around; every joint point stays in `[0, WIDTH−1] × [0, HEIGHT−1]`; a link
//! collides when it crosses an obstacle edge (touching is allowed, so the scenario sets
//! `touching_allowed`); the arm must not cross itself; edges are checked about 0.05 rad apart;
//! cost is the joint-space distance. The sensor sees 60 far within ±π/6 of the end effector's heading.
//! The map becomes an ordinary scenario, validated like any other.

use crate::scenario::{Scenario, ScenarioError};
use serde_json::{json, Value};

/// The course's link lengths.
pub const LINKS: [f64; 4] = [80.0, 70.0, 40.0, 40.0];

fn key<'a>(map: &'a serde_json::Map<String, Value>, k: &str) -> Result<&'a Value, ScenarioError> {
    map.get(k).ok_or_else(|| ScenarioError::at(k, "is missing (a Technion map needs it)"))
}

/// Read a Technion map as a scenario; `name` (the file's name) becomes part of its title.
pub fn import_map(text: &str, name: &str) -> Result<Scenario, ScenarioError> {
    let v: Value = serde_json::from_str(text).map_err(|e| ScenarioError::syntax(&e))?;
    let map = v.as_object().ok_or_else(|| ScenarioError::document("a Technion map is a JSON object"))?;
    for k in map.keys() {
        if !["WIDTH", "HEIGHT", "OBSTACLES", "START", "GOAL", "INSPECTION_POINTS"].contains(&k.as_str()) {
            return Err(ScenarioError::at(crate::limits::cut(k, 100), "unknown key in a Technion map"));
        }
    }
    let dim = |k: &str| -> Result<f64, ScenarioError> {
        key(map, k)?.as_f64().filter(|x| *x > 1.0).ok_or_else(|| ScenarioError::at(k, "must be a number above 1"))
    };
    let (w, h) = (dim("WIDTH")?, dim("HEIGHT")?);
    let obstacles: Vec<Value> = key(map, "OBSTACLES")?
        .as_array()
        .ok_or_else(|| ScenarioError::at("OBSTACLES", "must be a list of polygons"))?
        .iter()
        .map(|p| json!({ "polygon": p }))
        .collect();
    let inspection = map
        .get("INSPECTION_POINTS")
        .map(|pts| json!({"points": pts, "fov": std::f64::consts::FRAC_PI_3, "range": 60.0, "coverage": 0.5}));
    let task = if inspection.is_some() { "inspection" } else { "motion planning" };
    let mut sc = json!({
        "format": crate::scenario::FORMAT,
        "name": format!("Technion HW3 {task} map ({})", crate::limits::cut(name, 100)),
        "notes": format!("The manipulator of the Technion course's third homework: four links of 80, 70, 40 and 40 from a base at the corner, every joint wrapping around. Links may touch the obstacle but not cross it, and the arm may not cross itself. Cost is measured in joint space; edges are checked every 0.05 rad.{}",
            if inspection.is_some() { " The task is to see the inspection points with the end effector's sensor (60 far, ±30°)." } else { "" }),
        "bounds": [0.0, 0.0, w - 1.0, h - 1.0],
        "obstacles": obstacles,
        "robot": {"kind": "arm", "base": [0.0, 0.0], "links": LINKS, "limits": null, "self_collision": true, "metric": "joint"},
        "start": key(map, "START")?,
        "goal_tolerance": 0.0,
        "resolution": 0.05,
        "touching_allowed": true,
        "planner": {"name": "rrt", "seed": 1, "goal_bias": 0.05, "extend": "connect"}
    });
    let obj = sc.as_object_mut().expect("built as an object");
    if let Some(g) = map.get("GOAL") {
        obj.insert("goal".into(), g.clone());
    }
    if let Some(i) = inspection {
        obj.insert("inspection".into(), i);
        obj.remove("planner");
    }
    // Errors from the scenario checks name scenario paths; say which map key they came from.
    let rename = |mut e: ScenarioError| {
        for (from, to) in [
            ("obstacles", "OBSTACLES"),
            ("start", "START"),
            ("goal", "GOAL"),
            ("inspection.points", "INSPECTION_POINTS"),
        ] {
            if let Some(rest) = e.path.strip_prefix(from) {
                e.path = format!("{to}{rest}");
            }
        }
        e
    };
    let scenario = Scenario::from_value(&sc).map_err(rename)?;
    // Check START and GOAL now, so their errors name the map's keys too.
    crate::problem::Problem::from_scenario(&scenario).map_err(rename)?;
    Ok(scenario)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::Problem;

    const MP: &str = r#"{"HEIGHT": 300, "WIDTH": 300,
        "OBSTACLES": [[[130,80], [80,80], [80,220], [220,220], [220,80], [170,80], [170,100], [200,100], [200,200], [100,200], [100,100], [130,100]]],
        "START": [0.78, -0.78, 0.0, 0.0], "GOAL": [0.3, 0.15, 1.0, 1.1]}"#;

    #[test]
    fn the_goal_map_becomes_a_valid_problem() {
        let sc = crate::io::import(MP, "map_mp").unwrap();
        assert_eq!(sc.bounds, [0.0, 0.0, 299.0, 299.0]);
        assert!(sc.touching_allowed);
        let p = Problem::from_scenario(&sc).unwrap();
        assert_eq!(p.si.dims(), 4);
    }

    #[test]
    fn a_scenario_mentioning_the_map_keys_is_still_a_scenario() {
        let sc = crate::scenario::builtin("narrow").unwrap();
        let mut text = sc.to_json();
        text = text.replacen(
            "\"notes\": \"",
            "\"notes\": \"Unlike a Technion map it has no \\\"WIDTH\\\" or \\\"OBSTACLES\\\" key. ",
            1,
        );
        assert_eq!(crate::io::detect(&text), crate::io::Format::Scenario);
        assert_eq!(crate::io::detect(MP), crate::io::Format::TechnionMap);
        assert_eq!(crate::io::detect("3\n0.1 0.1 ..."), crate::io::Format::AsvProblem);
    }

    #[test]
    fn errors_name_the_map_key() {
        let e = import_map(&MP.replace(r#""START": [0.78, -0.78, 0.0, 0.0]"#, r#""START": [0.78, -0.78, 0.0]"#), "m")
            .unwrap_err();
        assert_eq!(e.to_string(), "START: an arm robot's state has 4 numbers, found 3");
        let e = import_map(&MP.replace("[[[130,80], [80,80]", "[[[130,80]"), "m").unwrap_err();
        assert!(e.path.starts_with("OBSTACLES[0]"), "{e}");
        let e = import_map(&MP.replace("\"HEIGHT\"", "\"HIGHT\""), "m").unwrap_err();
        assert_eq!(e.path, "HIGHT");
    }

    #[test]
    fn a_link_may_touch_the_obstacle_but_not_cross_it() {
        let sc = import_map(MP, "m").unwrap();
        let p = Problem::from_scenario(&sc).unwrap();
        // The first link (80 long) along the x axis stops short of the wall at x = 80.
        assert!(p.si.is_valid(&[0.0, 1.5, 1.0, 0.5]));
        // Bent up at the first joint, the third link cuts the wall's corner at (80, 80).
        assert!(!p.si.is_valid(&[0.0, 1.5, 0.5, 0.5]));
        // Straight along the diagonal, the arm runs through the room's wall (x, y in 80..100).
        assert!(!p.si.is_valid(&[std::f64::consts::FRAC_PI_4, 0.0, 0.0, 0.0]));
        // The course's start is valid.
        assert!(p.si.is_valid(&p.start));
    }
}

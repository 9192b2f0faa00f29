//! The Technion "Algorithmic Motion Planning" HW3 maps (`docs/sources.md`): `map_mp.json` (motion
//! planning, with a `GOAL`) and `map_ip.json` (inspection, with `INSPECTION_POINTS`).
//!
//! Later offerings give maps with only `WIDTH`, `HEIGHT` and `OBSTACLES` and a point robot
//! ("dot"): see [`import_map_with`] and [`MapOptions`].
//!
//! The course's robot is fixed: 4 links of lengths 80, 70, 40, 40 with the base at (0, 0), relative
//! joint angles wrapping around; every joint point stays in `[0, WIDTH−1] × [0, HEIGHT−1]`; a link
//! collides when it crosses an obstacle edge (touching is allowed, so the scenario sets
//! `touching_allowed`); the arm must not cross itself; edges are checked about 0.05 rad apart;
//! cost is the joint-space distance. The sensor sees 60 far within ±π/6 of the end effector's heading;
//! inspection is counted as the course does (`coverage_mode: vertices`, `touch_hides`).
//! The map becomes an ordinary scenario, validated like any other.

use crate::geometry::{Aabb, Workspace};
use crate::math::{Real, Vec2};
use crate::scenario::{Scenario, ScenarioError};
use serde_json::{json, Value};

/// The course's link lengths.
pub const LINKS: [f64; 4] = [80.0, 70.0, 40.0, 40.0];

/// Most candidate points looked at per ring when searching a free default start or goal for the
/// point robot, and most rings (so the search is bounded whatever the map's size).
const SEARCH_RINGS: usize = 200;

/// What to plan on a map beyond what the file says: the robot and, when the file has none or
/// they should be replaced, the start and goal (the later offerings give them beside the map).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MapOptions {
    /// `arm` (the course's manipulator) or `dot` (the course's point robot); default: `arm` when
    /// the map has a `START`, else `dot`.
    pub robot: Option<String>,
    /// The start state (4 joint angles for the arm, `[x, y]` for the dot); default: the map's
    /// `START`, else (dot only) a free point near the lower left corner.
    pub start: Option<Vec<Real>>,
    /// The goal state; default: the map's `GOAL`, else (dot only, on a map without inspection
    /// points) a free point near the upper right corner.
    pub goal: Option<Vec<Real>>,
}

fn key<'a>(map: &'a serde_json::Map<String, Value>, k: &str) -> Result<&'a Value, ScenarioError> {
    map.get(k).ok_or_else(|| ScenarioError::at(k, "is missing (a Technion map needs it)"))
}

/// Read a Technion map as a scenario; `name` (the file's name) becomes part of its title. A map
/// without `START` (the later offerings) imports with the point robot and default free start and
/// goal (see [`import_map_with`]).
pub fn import_map(text: &str, name: &str) -> Result<Scenario, ScenarioError> {
    import_map_with(text, name, &MapOptions::default())
}

/// The first free point (not in or on an obstacle, inside the bounds) on square rings around
/// `from`, nearest ring first, the ring's points in a fixed order, `step` apart, moving inward
/// by `dir` (±1 per axis): deterministic, bounded ([`SEARCH_RINGS`]² points at most).
fn free_point_near(ws: &Workspace, from: Vec2, dir: (Real, Real), step: Real) -> Option<[Real; 2]> {
    for r in 0..SEARCH_RINGS {
        for i in 0..=r {
            // The ring of Chebyshev radius r: (i, r) then (r, i), i from 0 outward.
            for (a, b) in [(i, r), (r, i)] {
                let p = Vec2::new(from.x + dir.0 * a as Real * step, from.y + dir.1 * b as Real * step);
                if ws.bounds.contains(p) && !ws.point_blocked(p) {
                    return Some([p.x, p.y]);
                }
            }
        }
    }
    None
}

/// [`import_map`] with the robot, start and goal chosen by `opts`.
///
/// For the point robot ("dot"), states are `[x, y]` in the map's bounds; without a start (the
/// map's `START` is the arm's, so the dot never uses it) the start is the first free point on
/// rings around the point 5% in from the lower left corner, the goal likewise from the upper
/// right corner (on a map of inspection points no goal is set). The search looks at points 1/400
/// of the map's larger side apart (at least 1), at most 200 rings out; a map whose corners are
/// buried that deep is refused, naming the state.
pub fn import_map_with(text: &str, name: &str, opts: &MapOptions) -> Result<Scenario, ScenarioError> {
    let v: Value = serde_json::from_str(text).map_err(|e| ScenarioError::syntax(&e))?;
    let map = v.as_object().ok_or_else(|| ScenarioError::document("a Technion map is a JSON object"))?;
    for k in map.keys() {
        if !["WIDTH", "HEIGHT", "OBSTACLES", "START", "GOAL", "INSPECTION_POINTS"].contains(&k.as_str()) {
            return Err(ScenarioError::at(
                crate::scenario::key_name(&crate::limits::cut(k, 100)),
                "unknown key in a Technion map",
            ));
        }
    }
    let dim = |k: &str| -> Result<f64, ScenarioError> {
        key(map, k)?.as_f64().filter(|x| *x > 1.0).ok_or_else(|| ScenarioError::at(k, "must be a number above 1"))
    };
    let (w, h) = (dim("WIDTH")?, dim("HEIGHT")?);
    let dot = match opts.robot.as_deref() {
        None => !map.contains_key("START"),
        Some("dot") => true,
        Some("arm") => false,
        Some(other) => {
            return Err(ScenarioError::at(
                "robot",
                format!("\"{}\" is not a Technion robot (arm or dot)", crate::limits::cut(other, 40)),
            ))
        }
    };
    let obstacles: Vec<Value> = key(map, "OBSTACLES")?
        .as_array()
        .ok_or_else(|| ScenarioError::at("OBSTACLES", "must be a list of polygons"))?
        .iter()
        .map(|p| json!({ "polygon": p }))
        .collect();
    // The course's inspection, exactly: coverage counted at the tree's vertices, a sight line
    // touching an obstacle edge hides the point (see docs/scenario-format.md).
    let inspection = map.get("INSPECTION_POINTS").map(|pts| {
        json!({"points": pts, "fov": std::f64::consts::FRAC_PI_3, "range": 60.0, "coverage": 0.5,
               "coverage_mode": "vertices", "touch_hides": true})
    });
    let task = if inspection.is_some() { "inspection" } else { "motion planning" };
    // Where each state came from, for error messages: the map's key or the caller's option.
    let (start, start_name) = match &opts.start {
        Some(s) => (json!(s), "start"),
        None if dot => (json!([0.0, 0.0]), "start"),
        None => (
            map.get("START").cloned().ok_or_else(|| {
                ScenarioError::at(
                    "START",
                    "is missing: this map has no start for the arm (give one, e.g. `planarium plan MAP --start q1,q2,q3,q4`, or plan for the point robot: --robot dot)",
                )
            })?,
            "START",
        ),
    };
    let goal = match &opts.goal {
        Some(g) => Some((json!(g), "goal")),
        None if dot => inspection.is_none().then(|| (json!([0.0, 0.0]), "goal")),
        None => map.get("GOAL").map(|g| (g.clone(), "GOAL")),
    };
    if goal.is_none() && inspection.is_none() {
        return Err(ScenarioError::at(
            "GOAL",
            "is missing: a map without inspection points needs a goal (give one, e.g. --goal q1,q2,q3,q4)",
        ));
    }
    let robot = if dot {
        json!({"kind": "point"})
    } else {
        json!({"kind": "arm", "base": [0.0, 0.0], "links": LINKS, "limits": null, "self_collision": true, "metric": "joint"})
    };
    let notes = if dot {
        "The point robot (\"dot\") of the Technion course's later offerings, on a map given without a start and goal: \
         unless they were given, the start is the free point nearest the lower left corner (5% in) and the goal the one \
         nearest the upper right corner; move them in the editor. The dot may touch an obstacle's boundary but not enter it."
            .to_string()
    } else {
        format!("The manipulator of the Technion course's third homework: four links of 80, 70, 40 and 40 from a base at the corner, every joint wrapping around. Links may touch the obstacle but not cross it, and the arm may not cross itself. Cost is measured in joint space (stats.cost_fk gives report 004's unit); edges are checked every 0.05 rad.{}",
            if inspection.is_some() { " The task is to see the inspection points with the end effector's sensor (60 far, ±30°), counted at the tree's vertices as the course does." } else { "" })
    };
    let mut sc = json!({
        "format": crate::scenario::FORMAT,
        "name": if dot { format!("Technion {task} map ({}), point robot", crate::limits::cut(name, 100)) } else { format!("Technion HW3 {task} map ({})", crate::limits::cut(name, 100)) },
        "notes": notes,
        "bounds": [0.0, 0.0, w - 1.0, h - 1.0],
        "obstacles": obstacles,
        "robot": robot,
        "start": start,
        "goal_tolerance": 0.0,
        "touching_allowed": true,
        "planner": {"name": "rrt", "seed": 1, "goal_bias": 0.05, "extend": "connect"}
    });
    let obj = sc.as_object_mut().expect("built as an object");
    if !dot {
        obj.insert("resolution".into(), json!(0.05));
    }
    if let Some((g, _)) = &goal {
        obj.insert("goal".into(), g.clone());
    }
    if let Some(i) = inspection {
        obj.insert("inspection".into(), i);
        if goal.is_none() {
            obj.remove("planner");
        } else {
            obj.insert("planner".into(), json!({"name": "inspection", "seed": 1}));
        }
    }
    // Errors from the scenario checks name scenario paths; say which map key (or option) they
    // came from.
    let goal_name = goal.as_ref().map_or("GOAL", |g| g.1);
    let rename = |mut e: ScenarioError| {
        for (from, to) in [
            ("obstacles", "OBSTACLES"),
            ("start", start_name),
            ("goal", goal_name),
            ("inspection.points", "INSPECTION_POINTS"),
        ] {
            if let Some(rest) = e.path.strip_prefix(from) {
                e.path = format!("{to}{rest}");
            }
        }
        e
    };
    let mut scenario = Scenario::from_value(&sc).map_err(rename)?;
    if dot && (opts.start.is_none() || (opts.goal.is_none() && scenario.goal.is_some())) {
        let b = scenario.bounds;
        let ws = Workspace::new(
            Aabb { min: Vec2::new(b[0], b[1]), max: Vec2::new(b[2], b[3]) },
            scenario.obstacles.iter().map(crate::problem::shape_of).collect(),
        );
        let (sx, sy) = (b[2] - b[0], b[3] - b[1]);
        let step = (sx.max(sy) / 400.0).max(1.0);
        let corner = |x: Real, y: Real, dir, what: &str, which: &str| {
            free_point_near(&ws, Vec2::new(x, y), dir, step).map(|p| p.to_vec()).ok_or_else(|| {
                ScenarioError::at(what, format!("no free point found near the {which} corner; give one"))
            })
        };
        if opts.start.is_none() {
            scenario.start = corner(b[0] + 0.05 * sx, b[1] + 0.05 * sy, (1.0, 1.0), "start", "lower left")?;
        }
        if opts.goal.is_none() && scenario.goal.is_some() {
            scenario.goal = Some(corner(b[2] - 0.05 * sx, b[3] - 0.05 * sy, (-1.0, -1.0), "goal", "upper right")?);
        }
    }
    // Check START and GOAL now, so their errors name the map's keys (or the options) too.
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
        // fuzz finding: an empty key is named too (an empty path would mean the whole document)
        let e = import_map(&MP.replace("\"HEIGHT\": 300,", "\"HEIGHT\": 300, \"\": 1,"), "m").unwrap_err();
        assert_eq!(e.to_string(), "\"\": unknown key in a Technion map");
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

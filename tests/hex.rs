//! The hexagonal decomposition planner (report 002) on its built-in scenarios: each behaves as
//! the report describes (the trap traps with the plain potential and the modified potential
//! escapes it; a gap narrower than t is impassable), every path passes the independent checker,
//! and the event stream is what the page draws (cells that partition their parents, a region of
//! influence that doubles and stops at d_maxOb + t).

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::{builtin, Scenario};
use serde_json::{json, Value};

/// Run hex-potential on `sc` with the scenario's planner block, then `over` on top.
fn run(sc: &Scenario, over: Value) -> (PlanResult, Vec<f64>) {
    let spec = planners::find("hex-potential").unwrap();
    let mut values = match &sc.planner {
        Some(p) if p.name == "hex-potential" => p.params.clone(),
        _ => serde_json::Map::new(),
    };
    for (k, v) in over.as_object().unwrap() {
        values.insert(k.clone(), v.clone());
    }
    let params = Params::from_json(spec, &Value::Object(values)).unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: spec.name.into(), params, seed: 1, record_events: true }).unwrap();
    s.run_to_end();
    (s.result(), s.drain_events())
}

fn records(ev: &[f64], kind: EventKind) -> impl Iterator<Item = &[f64]> {
    ev.chunks(STRIDE).filter(move |r| r[0] as u8 == kind as u8)
}

fn check_valid(sc: &Scenario, r: &PlanResult, what: &str) {
    assert!(r.solved, "{what}: {} {:?}", r.status, r.reason);
    for (name, path) in [("raw", &r.path), ("smoothed", &r.smoothed)] {
        if let Some(e) = common::path_problem(sc, path) {
            panic!("{what}, {name} path: {e}");
        }
    }
}

/// Where the path's straight pieces cross the vertical line `x` (the y values).
fn crossings_x(path: &[Vec<f64>], x: f64) -> Vec<f64> {
    path.windows(2)
        .filter(|w| (w[0][0] - x) * (w[1][0] - x) <= 0.0 && w[0][0] != w[1][0])
        .map(|w| w[0][1] + (x - w[0][0]) / (w[1][0] - w[0][0]) * (w[1][1] - w[0][1]))
        .collect()
}

#[test]
fn the_checker_rejects_what_is_wrong() {
    common::self_test();
}

#[test]
fn the_open_field_is_crossed_with_a_valid_path() {
    let sc = builtin("hex-open").unwrap();
    let (r, ev) = run(&sc, json!({}));
    check_valid(&sc, &r, "hex-open");
    // Cells were made at several levels, and only obstacles' cells were refined.
    let levels: std::collections::BTreeSet<u64> = records(&ev, EventKind::Cell).map(|c| c[1] as u64).collect();
    assert!(levels.len() >= 3, "levels {levels:?}");
    for c in records(&ev, EventKind::Cell).filter(|c| c[3] >= 0.0) {
        let parent = records(&ev, EventKind::Cell).find(|p| p[2] == c[3]).expect("the parent came first");
        assert_eq!(parent[6], 1.0, "cell {} was refined from a parent that is not mixed", c[2]);
    }
}

#[test]
fn the_corridor_goes_through_the_wide_gap() {
    let sc = builtin("hex-corridor").unwrap();
    let (r, ev) = run(&sc, json!({}));
    check_valid(&sc, &r, "hex-corridor");
    let ys = crossings_x(&r.path, 0.5);
    assert_eq!(ys.len(), 1, "one crossing of the wall: {ys:?}");
    assert!(ys[0] > 0.66 && ys[0] < 0.82, "through the wide gap, not the narrow one: y = {}", ys[0]);
    // The narrow gap was tried and refused by the step test.
    assert!(
        records(&ev, EventKind::CellState).any(|s| s[6] == 1.0 && s[5] > 0.5 && s[5] < 0.6 && s[4] < 0.45),
        "a blocked step at the narrow gap's mouth"
    );
    // A sampling planner drives through the narrow gap, which is wider than the robot.
    let problem = Problem::from_scenario(&sc).unwrap();
    let spec = planners::find("rrt-connect").unwrap();
    let mut s = Session::new(
        problem,
        RunConfig { planner: spec.name.into(), params: Params::defaults(spec), seed: 1, record_events: false },
    )
    .unwrap();
    s.run_to_end();
    assert!(s.result().solved);
}

/// The corridor with the wide gap closed, for a robot of footprint `l × w`.
fn closed_gap(l: f64, w: f64) -> Scenario {
    let mut v: Value = serde_json::to_value(builtin("hex-corridor").unwrap()).unwrap();
    v["obstacles"][2] = json!({"rect": [0.45, 0.66, 0.55, 1.0]});
    v["robot"]["footprint"] =
        json!([[-l / 2.0, -w / 2.0], [l / 2.0, -w / 2.0], [l / 2.0, w / 2.0], [-l / 2.0, w / 2.0]]);
    // Start and goal on the row of cell centres through the gap (y = 0.5625 at every level).
    v["start"] = json!([0.1, 0.5625, 0.0]);
    v["goal"] = json!([0.9, 0.5625, 0.0]);
    Scenario::from_json(&v.to_string()).unwrap()
}

#[test]
fn a_gap_narrower_than_t_is_impassable_and_one_wider_is_not() {
    // The gap is 0.045 wide. A weak repulsion, so the potential does not keep the robot out.
    let over = json!({"k1": 0.00001});
    // 0.05 × 0.025: t ≈ 0.056 > 0.045 although the robot is only 0.025 wide.
    let big = closed_gap(0.05, 0.025);
    let (r, ev) = run(&big, over.clone());
    assert_eq!(r.status, "no_path", "{:?}", r.reason);
    assert!(r.reason.as_deref().unwrap().contains("region of influence"), "{:?}", r.reason);
    assert!(
        records(&ev, EventKind::CellState)
            .any(|s| s[6] == 1.0 && (s[7] == 1.0 || s[7] == 2.0) && s[4] > 0.4 && s[4] < 0.6),
        "a step into the gap refused by the report's vertex tests"
    );
    // 0.03 × 0.015: t ≈ 0.034 < 0.045: straight through.
    let small = closed_gap(0.03, 0.015);
    let (r, _) = run(&small, over);
    check_valid(&small, &r, "small robot");
    let ys = crossings_x(&r.path, 0.5);
    assert!(ys.len() == 1 && (ys[0] - 0.5625).abs() < 0.0225, "through the narrow gap: {ys:?}");
}

#[test]
fn the_trap_traps_with_the_plain_potential() {
    let sc = builtin("hex-trap").unwrap();
    let (r, ev) = run(&sc, json!({}));
    assert_eq!(r.status, "no_path");
    assert!(!r.solved && r.path.is_empty());
    let reason = r.reason.expect("a reason");
    assert!(reason.contains("stuck") && reason.contains("region of influence"), "{reason}");
    // Every attempt walks into the dead-end corridor under the shelf (x < 0.6, 0.43 < y < 0.55).
    let regions: Vec<&[f64]> = records(&ev, EventKind::Region).collect();
    assert!(regions.len() >= 2, "the region grew at least once");
    for attempt in 0..regions.len() {
        let inside = records(&ev, EventKind::NodeAdded)
            .filter(|n| n[1] as usize == attempt)
            .any(|n| n[4] < 0.6 && n[5] > 0.43 && n[5] < 0.55);
        assert!(inside, "attempt {attempt} did not enter the dead end");
    }
    // The region doubled (or grew to d_maxOb + t) each time, and stopped there.
    for w in regions.windows(2) {
        let (r0, r1, limit) = (w[0][6], w[1][6], w[0][7]);
        assert!((r1 - (2.0 * r0).min(limit)).abs() < 1e-12, "grew {r0} → {r1} (limit {limit})");
    }
    let last = regions.last().unwrap();
    assert!((last[6] - last[7]).abs() < 1e-12, "the last region is at d_maxOb + t");
    // Obstacles counted grow with it.
    assert!(regions.first().unwrap()[8] <= last[8]);
}

#[test]
fn the_modified_potential_escapes_the_trap() {
    let sc = builtin("hex-trap-modified").unwrap();
    let (r, ev) = run(&sc, json!({}));
    check_valid(&sc, &r, "hex-trap-modified");
    // It goes around the shelf's right end (x > 0.75), never into the corridor.
    assert!(r.path.iter().all(|q| !(q[0] < 0.6 && q[1] > 0.43 && q[1] < 0.55)), "entered the dead end");
    let ys = crossings_x(&r.path, 0.8);
    assert!(!ys.is_empty(), "passes right of the shelf");
    // The trap term applies below the shelf (y < 0.55) and nowhere else.
    let pots: Vec<&[f64]> = records(&ev, EventKind::Potential).collect();
    assert!(pots.iter().any(|p| p[7] > 0.0), "some candidate got k3");
    for p in &pots {
        assert_eq!(p[7] > 0.0, p[5] < 0.55, "trap term at ({}, {}) = {}", p[4], p[5], p[7]);
    }
    // Without k3 the same map traps (the plain potential).
    let (plain, _) = run(&sc, json!({"k3": 0.0}));
    assert_eq!(plain.status, "no_path");
}

#[test]
fn cells_partition_their_parents_and_the_search_is_a_chain() {
    let sc = builtin("hex-trap-modified").unwrap();
    let (_, ev) = run(&sc, json!({}));
    // Outlines from the CELL_SHAPE records.
    let mut outline: std::collections::HashMap<i64, Vec<(f64, f64)>> = Default::default();
    for r in records(&ev, EventKind::CellShape) {
        let o = outline.entry(r[2] as i64).or_default();
        for j in 0..4 {
            if r[4 + 2 * j].is_finite() {
                o.push((r[4 + 2 * j], r[5 + 2 * j]));
            }
        }
    }
    let area = |p: &[(f64, f64)]| {
        (0..p.len()).map(|i| p[i].0 * p[(i + 1) % p.len()].1 - p[(i + 1) % p.len()].0 * p[i].1).sum::<f64>() / 2.0
    };
    let cells: Vec<&[f64]> = records(&ev, EventKind::Cell).collect();
    for c in &cells {
        assert_eq!(outline[&(c[2] as i64)].len(), c[8] as usize, "cell {}: vertex count", c[2]);
    }
    // Level 0 covers the map.
    let map: f64 = cells.iter().filter(|c| c[1] == 0.0).map(|c| area(&outline[&(c[2] as i64)])).sum();
    assert!((map - 1.0).abs() < 1e-9, "level 0 covers {map}");
    // Children cover their parent exactly.
    let mut kids: std::collections::HashMap<i64, f64> = Default::default();
    for c in cells.iter().filter(|c| c[3] >= 0.0) {
        *kids.entry(c[3] as i64).or_default() += area(&outline[&(c[2] as i64)]);
    }
    assert!(!kids.is_empty());
    for (p, a) in kids {
        assert!((a - area(&outline[&p])).abs() < 1e-12, "children of {p} cover {a}");
    }
    // Each step starts where the last one ended, at a visited free cell's centre.
    let steps: Vec<&[f64]> = records(&ev, EventKind::NodeAdded).collect();
    for w in steps.windows(2).filter(|w| w[0][1] == w[1][1]) {
        assert_eq!((w[1][6], w[1][7]), (w[0][4], w[0][5]));
    }
    let visited: Vec<&[f64]> = records(&ev, EventKind::CellState).filter(|s| s[6] == 2.0).collect();
    for v in &visited {
        let c = cells.iter().find(|c| c[2] == v[2]).unwrap();
        assert_eq!(c[6], 0.0, "visited cell {} is free", v[2]);
    }
}

#[test]
fn runs_are_deterministic() {
    let sc = builtin("hex-open").unwrap();
    let (a, ea) = run(&sc, json!({}));
    let (b, eb) = run(&sc, json!({}));
    assert_eq!(a.path, b.path);
    assert_eq!(ea.len(), eb.len());
    assert!(ea.iter().zip(&eb).all(|(x, y)| x == y || (x.is_nan() && y.is_nan())));
}

#[test]
fn a_point_robot_works_and_other_robots_are_refused() {
    let mut v: Value = serde_json::to_value(builtin("hex-open").unwrap()).unwrap();
    v["robot"] = json!({"kind": "point"});
    v["start"] = json!([0.08, 0.1]);
    v["goal"] = json!([0.9, 0.9]);
    let sc = Scenario::from_json(&v.to_string()).unwrap();
    let (r, _) = run(&sc, json!({}));
    check_valid(&sc, &r, "point robot");
    let arm = builtin("arm-2").unwrap();
    let err = Session::new(
        Problem::from_scenario(&arm).unwrap(),
        RunConfig {
            planner: "hex-potential".into(),
            params: Params::defaults(planners::find("hex-potential").unwrap()),
            seed: 1,
            record_events: false,
        },
    )
    .err()
    .expect("an arm is refused");
    assert!(err.contains("point or a rigid robot"), "{err}");
    // A trapping obstacle that does not exist is an error, not a panic.
    let spec = planners::find("hex-potential").unwrap();
    let params = Params::from_json(spec, &json!({"trap_obstacle": 9})).unwrap();
    let err = Session::new(
        Problem::from_scenario(&sc).unwrap(),
        RunConfig { planner: spec.name.into(), params, seed: 1, record_events: false },
    )
    .err()
    .unwrap();
    assert!(err.contains("trap_obstacle 9"), "{err}");
}

/// The complete search's closed cells (`CellState` verdict 2) in an event stream.
fn closed(ev: &[f64]) -> usize {
    records(ev, EventKind::CellState).filter(|r| r[6] == 2.0).count()
}

#[test]
fn the_complete_search_finds_the_zigzag_path_the_descent_cannot() {
    let sc = builtin("zigzag").unwrap();
    let (descent, _) = run(&sc, json!({}));
    assert_eq!(descent.status, "no_path", "the report's descent gets stuck in the zigzag");
    for search in ["astar", "dijkstra"] {
        let (r, ev) = run(&sc, json!({"search": search}));
        check_valid(&sc, &r, &format!("zigzag, {search}"));
        // Every wall is passed: the path crosses the zigzag's corridors, so it is far longer
        // than the straight start–goal line.
        let (s, g) = (&sc.start, sc.goal.as_ref().unwrap());
        let straight = ((g[0] - s[0]).powi(2) + (g[1] - s[1]).powi(2)).sqrt();
        assert!(r.stats.cost.unwrap() > 1.5 * straight, "{search}: cost {:?} vs {straight}", r.stats.cost);
        assert!(closed(&ev) > 0, "{search}: closed cells are evented");
    }
}

#[test]
fn astar_closes_no_more_cells_than_dijkstra_for_the_same_cost() {
    let mut fewer = 0;
    for (id, over) in [
        ("zigzag", json!({})),
        ("hex-trap", json!({})),
        ("apf-minimum", json!({})),
        ("narrow", json!({"levels": 5})),
        ("open-field", json!({})),
    ] {
        let sc = builtin(id).unwrap();
        let with = |search: &str| {
            let mut o = over.clone();
            o["search"] = json!(search);
            let (r, ev) = run(&sc, o);
            check_valid(&sc, &r, &format!("{id}, {search}"));
            (r.stats.cost.unwrap(), closed(&ev))
        };
        let (a_cost, a_closed) = with("astar");
        let (d_cost, d_closed) = with("dijkstra");
        assert!((a_cost - d_cost).abs() < 1e-9, "{id}: A* {a_cost} vs Dijkstra {d_cost}");
        assert!(a_closed <= d_closed, "{id}: A* closed {a_closed} cells, Dijkstra {d_closed}");
        fewer += usize::from(a_closed < d_closed);
    }
    // The heuristic does something: on the open field A* goes straight at the goal.
    assert!(fewer >= 1, "A* closed as many cells as Dijkstra everywhere");
}

#[test]
fn the_complete_search_is_never_longer_than_the_descent() {
    // The descent's steps are edges of the same graph, so a shortest way is at most as long.
    for id in ["hex-open", "hex-corridor", "hex-trap-modified", "open-field"] {
        let sc = builtin(id).unwrap();
        let (descent, _) = run(&sc, json!({}));
        let (astar, _) = run(&sc, json!({"search": "astar"}));
        check_valid(&sc, &astar, id);
        let (d, a) = (descent.stats.cost.unwrap(), astar.stats.cost.unwrap());
        assert!(a <= d + 1e-9, "{id}: A* {a} longer than the descent's {d}");
    }
    // Where the descent needs the modified potential to escape the trap, the complete search
    // finds a way with the plain one, shorter than the escape.
    let (escape, _) = run(&builtin("hex-trap-modified").unwrap(), json!({}));
    let (astar, _) = run(&builtin("hex-trap").unwrap(), json!({"search": "astar"}));
    assert!(astar.solved && astar.stats.cost.unwrap() < escape.stats.cost.unwrap());
}

#[test]
fn a_complete_search_without_a_way_says_so() {
    let (r, _) = run(&builtin("slot").unwrap(), json!({"search": "astar"}));
    assert_eq!(r.status, "no_path");
    let why = r.reason.unwrap_or_default();
    assert!(why.contains("complete search") && why.contains("resolution"), "{why}");
}

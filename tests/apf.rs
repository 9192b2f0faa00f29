//! The artificial potential field planner: it gets trapped in the cup of `apf-minimum` (and says
//! where), escapes it by random walks, solves open scenes for point and rigid robots with paths the
//! independent checker accepts, is deterministic per seed, draws its field as events, and refuses
//! robots that are not a body in the plane.

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::motion::MotionValidator;
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::{builtin, Scenario};
use serde_json::{json, Value};

/// The cup of `apf-minimum`: the arms start at x = 0.52, the back wall's inner face is at x = 0.6,
/// and the free space between the arms is 0.44 < y < 0.56.
const CUP_MOUTH: (f64, f64, f64, f64) = (0.52, 0.60, 0.44, 0.56);

/// Run the potential field on `sc` with `params` and `seed`; the result and the event records.
fn run(sc: &Scenario, params: Value, seed: u64) -> (PlanResult, Vec<f64>, Session) {
    let spec = planners::find("potential-field").unwrap();
    let params = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: "potential-field".into(), params, seed, record_events: true })
            .unwrap();
    s.run_to_end();
    let events = s.drain_events();
    (s.result(), events, s)
}

/// The records of one kind.
fn records(events: &[f64], kind: EventKind) -> Vec<&[f64]> {
    events.chunks(STRIDE).filter(|r| r[0] == kind as u8 as f64).collect()
}

/// Every edge of the chain is a valid motion (crate validator) and, independently checked, free.
fn check_chain(sc: &Scenario, s: &Session, what: &str) {
    let si = &s.problem().si;
    let mut scratch = vec![0.0; si.dims()];
    for tree in s.planner_data().trees.iter() {
        for (e, (a, b)) in tree.edges().enumerate() {
            assert!(si.check_motion(a, b, &mut scratch).is_ok(), "{what}: edge {e} invalid");
            if let Some(err) = common::motion_problem(sc, a, b) {
                panic!("{what}: edge {e}: {err}");
            }
        }
    }
}

fn solved_and_checked(sc: &Scenario, r: &PlanResult, what: &str) {
    assert!(r.solved, "{what}: {} {:?}", r.status, r.reason);
    if let Some(e) = common::path_problem(sc, &r.path) {
        panic!("{what}: raw path: {e}");
    }
    if let Some(e) = common::path_problem(sc, &r.smoothed) {
        panic!("{what}: smoothed path: {e}");
    }
}

#[test]
fn give_up_stops_in_the_cup_with_a_reason() {
    let sc = builtin("apf-minimum").unwrap();
    let (r, events, _) = run(&sc, json!({"escape": "give-up"}), 1);
    assert_eq!(r.status, "no_path");
    assert!(!r.solved && r.path.is_empty());
    let reason = r.reason.expect("a reason for no_path");
    assert!(reason.contains("local minimum"), "{reason}");
    assert!(reason.contains("give-up"), "{reason}");
    let minima = records(&events, EventKind::Minimum);
    assert_eq!(minima.len(), 1, "give-up stops at the first minimum");
    let m = minima[0];
    let (x, y) = (m[4], m[5]);
    let (x0, x1, y0, y1) = CUP_MOUTH;
    assert!(x > x0 && x < x1 && y > y0 && y < y1, "the minimum ({x}, {y}) is not between the cup's arms");
    assert_eq!(m[2], 0.0, "no escapes before it");
    assert!(m[6].is_finite() && m[6] > 0.0, "potential there: {}", m[6]);
    let to_goal = ((x - 0.9f64).powi(2) + (y - 0.5f64).powi(2)).sqrt();
    assert!((m[7] - to_goal).abs() < 1e-9, "distance to the goal: {} vs {to_goal}", m[7]);
    // The two forces there: the goal's pull towards +x (the cone's constant k_att·d_star = 0.3),
    // the cup's push back towards −x of the same order. They do not cancel exactly at the node:
    // the descent rocks by a step about the point where they do, and the push (from the nearest
    // obstacle only) jumps where the nearest obstacle changes.
    let (pull, push) = ((m[8], m[9]), (m[10], m[11]));
    assert!((pull.0 - 0.3).abs() < 0.01 && pull.1.abs() < 0.01, "pull {pull:?}");
    assert!(push.0 < -0.5 * pull.0 && push.0 > -2.0 * pull.0, "push {push:?} against pull {pull:?}");
    // Every step was a descent step (tree 0), and the robot never touched the cup.
    let nodes = records(&events, EventKind::NodeAdded);
    assert!(!nodes.is_empty() && nodes.iter().all(|n| n[1] == 0.0));
    assert!(r.stats.iterations < 500, "it took {} iterations to see the minimum", r.stats.iterations);
}

#[test]
fn random_walks_escape_the_cup_for_most_seeds() {
    let sc = builtin("apf-minimum").unwrap();
    let mut solved = 0;
    for seed in 1..=10 {
        let (r, events, s) = run(&sc, json!({"escape": "random-walk"}), seed);
        let what = format!("apf-minimum / random-walk / seed {seed}");
        check_chain(&sc, &s, &what);
        if !r.solved {
            assert_eq!(r.status, "no_path", "{what}");
            assert!(r.reason.as_deref().unwrap_or("").contains("local minimum"), "{what}: {:?}", r.reason);
            continue;
        }
        solved += 1;
        solved_and_checked(&sc, &r, &what);
        // It escaped: it met the minimum at least once and walked (tree index 1) out of it.
        assert!(!records(&events, EventKind::Minimum).is_empty(), "{what}: solved without meeting the cup's minimum");
        assert!(records(&events, EventKind::NodeAdded).iter().any(|n| n[1] == 1.0), "{what}: no random-walk step");
        assert_eq!(records(&events, EventKind::Solved).len(), 1, "{what}");
    }
    assert!(solved >= 7, "only {solved} of 10 seeds escaped");
}

#[test]
fn a_point_robot_solves_an_open_field() {
    let sc = builtin("open-field").unwrap();
    let (r, events, s) = run(&sc, json!({}), 1);
    solved_and_checked(&sc, &r, "open-field");
    check_chain(&sc, &s, "open-field");
    assert!(records(&events, EventKind::Minimum).is_empty(), "no local minimum on the open field");
    assert!(r.stats.checks > 0);
    // One node per step: the start plus every step (the last one at the goal).
    assert_eq!(r.stats.nodes as usize, r.path.len());
}

/// An open scene for a rectangle robot, 0.06 × 0.03 centred on its origin.
fn rigid_scene() -> Scenario {
    Scenario::from_json(
        &json!({
            "format": "planarium-scenario/1",
            "name": "rigid open",
            "bounds": [0, 0, 1, 1],
            "obstacles": [
                {"rect": [0.3, 0.15, 0.4, 0.4]},
                {"circle": [0.65, 0.6, 0.08]},
                {"rect": [0.2, 0.7, 0.35, 0.8]}
            ],
            "robot": {"kind": "rigid", "footprint": [[-0.03, -0.015], [0.03, -0.015], [0.03, 0.015], [-0.03, 0.015]]},
            "start": [0.1, 0.1, 0.0],
            "goal": [0.9, 0.9, 1.2],
            "goal_tolerance": 0.0,
            "resolution": 0.002
        })
        .to_string(),
    )
    .unwrap()
}

#[test]
fn a_rigid_rectangle_solves_an_open_scene() {
    let sc = rigid_scene();
    let (r, _, s) = run(&sc, json!({}), 1);
    solved_and_checked(&sc, &r, "rigid open");
    check_chain(&sc, &s, "rigid open");
    // The heading is planned too: the path turns from 0 to the goal's 1.2.
    assert!((r.path.last().unwrap()[2] - 1.2).abs() < 1e-9);
    assert!(r.path.iter().any(|q| q[2] > 0.3 && q[2] < 1.0), "the heading never turned on the way");
}

#[test]
fn the_same_seed_gives_the_same_path() {
    let sc = builtin("apf-minimum").unwrap();
    let a = run(&sc, json!({"escape": "random-walk"}), 3).0;
    let b = run(&sc, json!({"escape": "random-walk"}), 3).0;
    assert!(a.solved);
    assert_eq!(a.path, b.path);
    assert_eq!(a.stats.checks, b.stats.checks);
    // The walks do draw from the seed: another seed wanders another way.
    let c = run(&sc, json!({"escape": "random-walk"}), 4).0;
    assert_ne!(a.path, c.path);
}

#[test]
fn the_field_is_drawn_on_a_grid_and_points_to_the_goal_far_from_obstacles() {
    let sc = builtin("apf-minimum").unwrap();
    for grid in [40usize, 7] {
        let (_, events, _) = run(&sc, json!({"escape": "give-up", "field_grid": grid}), 1);
        let field = records(&events, EventKind::Field);
        assert_eq!(field.len(), grid * grid);
        // Field records come first, in the first iteration.
        assert_eq!(events[0], EventKind::Field as u8 as f64);
        let (goal, rho0) = ((0.9, 0.5), 0.08);
        let mut far = 0;
        let mut blocked = 0;
        for f in &field {
            let (x, y, value, att, rep, dx, dy, half) = (f[4], f[5], f[6], f[7], f[8], f[9], f[10], f[11]);
            assert!((half - 0.5 / grid as f64).abs() < 1e-12);
            assert!(x > 0.0 && x < 1.0 && y > 0.0 && y < 1.0);
            if !value.is_finite() {
                blocked += 1;
                assert_eq!((dx, dy), (0.0, 0.0));
                continue;
            }
            assert!((value - att - rep).abs() < 1e-12);
            // Farther than rho0 (plus the finite-difference step) from the cup's box: no repulsion,
            // and −∇U is the unit vector to the goal.
            let gap_x = (0.52 - x).max(x - 0.63).max(0.0);
            let gap_y = (0.41 - y).max(y - 0.59).max(0.0);
            if gap_x.hypot(gap_y) > rho0 + 0.01 {
                far += 1;
                assert_eq!(rep, 0.0);
                let (gx, gy) = (goal.0 - x, goal.1 - y);
                let n = gx.hypot(gy);
                let dot = (dx * gx + dy * gy) / n;
                assert!(dot > 0.999, "at ({x}, {y}) the field points ({dx}, {dy}), not to the goal");
                assert!((dx.hypot(dy) - 1.0).abs() < 1e-9);
            }
        }
        assert!(far > grid * grid / 2, "{far} tiles far from the cup");
        if grid == 40 {
            assert!(blocked > 0, "tile centres inside the cup's walls are infinite");
        }
    }
    // With events off, nothing is drawn and the checks are the same.
    let spec = planners::find("potential-field").unwrap();
    let checks = |record: bool| {
        let params = Params::from_json(spec, &json!({"escape": "give-up"})).unwrap();
        let mut s = Session::new(
            Problem::from_scenario(&sc).unwrap(),
            RunConfig { planner: spec.name.into(), params, seed: 1, record_events: record },
        )
        .unwrap();
        s.run_to_end();
        s.result().stats.checks
    };
    assert_eq!(checks(true), checks(false), "drawing the field is not counted as checks");
}

#[test]
fn arms_are_refused_with_a_clear_message() {
    for name in ["arm-3", "asv-3-easy"] {
        let sc = builtin(name).unwrap();
        let spec = planners::find("potential-field").unwrap();
        let err = Session::new(
            Problem::from_scenario(&sc).unwrap(),
            RunConfig { planner: spec.name.into(), params: Params::defaults(spec), seed: 1, record_events: false },
        )
        .err()
        .expect("the potential field cannot plan for this robot");
        assert!(err.contains("needs a point or rigid robot"), "{name}: {err}");
        let kind = if name.starts_with("arm") { "an arm" } else { "asv" };
        assert!(err.contains(kind), "{name}: {err}");
    }
}

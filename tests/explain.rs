//! The events the page's explain panel captions (`www/run/explain.js`) say what happened: each
//! growth step logs the node chosen (`Nearest`), the step taken (`Steer`), and then either the node
//! added or the blocked motion with what blocked it. Checked against the trees and, for a point
//! robot, against the independent checker in `tests/common`.

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{RunConfig, Session};
use planarium::scenario::builtin;
use serde_json::json;

/// The event records of a whole run.
fn run(
    scenario: &str,
    planner: &str,
    params: serde_json::Value,
    seed: u64,
) -> (planarium::scenario::Scenario, Vec<[f64; STRIDE]>) {
    let sc = builtin(scenario).unwrap();
    let spec = planners::find(planner).unwrap();
    let params = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: planner.into(), params, seed, record_events: true }).unwrap();
    s.run_to_end();
    let log = s.drain_events();
    let records = log.chunks_exact(STRIDE).map(|c| <[f64; STRIDE]>::try_from(c).unwrap()).collect();
    (sc, records)
}

/// A blocked motion: from, to (points) and its `Collision` record.
type Blocked = ([f64; 2], [f64; 2], [f64; STRIDE]);

const fn k(kind: EventKind) -> f64 {
    kind as u8 as f64
}

/// Walk a run's records as the explain panel does: every `Steer` follows the `Nearest` of the same
/// node, every `NodeAdded` of a growth step and every `Collision` follows a `Steer`, at the steered
/// point and from the steered node. Returns the (from, to, collision record) of every blocked motion.
fn check_steps(records: &[[f64; STRIDE]], same_parent: bool) -> (usize, Vec<Blocked>) {
    let (mut nearest, mut steer): (Option<[f64; STRIDE]>, Option<[f64; STRIDE]>) = (None, None);
    let (mut steps, mut blocked) = (0, Vec::new());
    let mut last_sample: Option<[f64; 2]> = None;
    for r in records {
        match r[0] {
            x if x == k(EventKind::Sample) => last_sample = Some([r[4], r[5]]),
            x if x == k(EventKind::Nearest) => {
                // a sample target is the last sample drawn
                if r[10] == 1.0 {
                    assert_eq!(Some([r[6], r[7]]), last_sample, "a Nearest toward a sample names the sample: {r:?}");
                }
                assert!(r[8] >= 0.0 && r[8].is_finite(), "distance {r:?}");
                nearest = Some(*r);
                steer = None;
            }
            x if x == k(EventKind::Steer) => {
                let n = nearest.expect("a Steer follows a Nearest");
                assert_eq!((r[1], r[2]), (n[1], n[2]), "Steer from the node chosen: {r:?} after {n:?}");
                assert_eq!([r[6], r[7]], [n[4], n[5]], "Steer starts at the node's point");
                assert!(r[8] <= r[9] * (1.0 + 1e-12), "a step is at most the range: {r:?}");
                if r[10] == 1.0 {
                    assert_eq!([r[4], r[5]], [n[6], n[7]], "a step that reaches the target ends on it");
                }
                steer = Some(*r);
                steps += 1;
            }
            x if x == k(EventKind::NodeAdded) && r[3] >= 0.0 => {
                if let Some(s) = steer.take() {
                    assert_eq!([r[4], r[5]], [s[4], s[5]], "the node added is the steered state: {r:?} after {s:?}");
                    if same_parent {
                        assert_eq!((r[1], r[3]), (s[1], s[2]), "the node's parent is the node steered from");
                    }
                }
            }
            x if x == k(EventKind::Collision) => {
                let s = steer.take().expect("a Collision follows a Steer");
                assert_eq!((r[1], r[3]), (s[1], s[2]), "a blocked motion starts at the node steered from: {r:?}");
                assert_eq!([r[6], r[7]], [s[6], s[7]]);
                blocked.push(([s[6], s[7]], [s[4], s[5]], *r));
            }
            _ => {}
        }
    }
    (steps, blocked)
}

/// For a point robot: the obstacle a blocked motion names blocks that motion on its own.
fn check_blockers(sc: &planarium::scenario::Scenario, blocked: &[Blocked]) {
    let mut named = 0;
    for (a, b, r) in blocked {
        let id = r[2];
        assert!(id >= -2.0, "a point meets an obstacle or the map's edge: {r:?}");
        if id < 0.0 {
            continue;
        }
        named += 1;
        let mut alone = sc.clone();
        alone.obstacles = vec![sc.obstacles[id as usize].clone()];
        assert!(common::motion_problem(&alone, a, b).is_some(), "obstacle {id} alone blocks {a:?} → {b:?}");
    }
    assert!(named > 0, "some motions were blocked by a named obstacle");
}

#[test]
fn rrt_steps_name_the_node_the_step_and_the_obstacle() {
    let (sc, records) = run("narrow", "rrt", json!({}), 7);
    let (steps, blocked) = check_steps(&records, true);
    assert!(steps > 100 && blocked.len() > 10, "{steps} steps, {} blocked", blocked.len());
    check_blockers(&sc, &blocked);
}

#[test]
fn rrt_connect_steps_toward_samples_and_the_other_tree() {
    let (sc, records) = run("narrow", "rrt-connect", json!({}), 7);
    let (steps, blocked) = check_steps(&records, true);
    assert!(steps > 100, "{steps} steps");
    let toward_tree = records.iter().filter(|r| r[0] == k(EventKind::Nearest) && r[10] == 0.0).count();
    assert!(toward_tree > 10, "CONNECT steps toward the other tree's node: {toward_tree}");
    check_blockers(&sc, &blocked);
}

/// The ladder move: after a blocked step, a step that moves only some coordinates, checked free
/// and added. For a point robot that is one coordinate (report 000's move along one axis), so the
/// node added differs from its parent in x or in y only; every such step follows a blocked one.
#[test]
fn ladder_steps_follow_a_blocked_step_and_move_one_axis_of_a_point() {
    for planner in ["rrt", "rrt-connect"] {
        let (sc, records) = run("narrow", planner, json!({"ladder": 8}), 7);
        let (steps, blocked) = check_steps(&records, true);
        assert!(steps > 30 && !blocked.is_empty(), "{planner}: {steps} steps");
        check_blockers(&sc, &blocked);
        let mut ladders = 0;
        for (i, r) in records.iter().enumerate() {
            if r[0] != k(EventKind::Steer) || r[3] < 0.0 {
                continue;
            }
            ladders += 1;
            assert_eq!(r[3], 1.0, "{planner}: a point's ladder step moves one coordinate: {r:?}");
            assert!(r[11] >= 1.0 && r[11] <= 8.0, "{planner}: the try's number: {r:?}");
            assert!((r[4] == r[6]) != (r[5] == r[7]), "{planner}: along x or along y only: {r:?}");
            let before =
                records[..i].iter().rev().find(|q| q[0] != k(EventKind::Exhausted) && q[0] != k(EventKind::Domain));
            assert_eq!(
                before.map(|q| q[0]),
                Some(k(EventKind::Collision)),
                "{planner}: a ladder step follows a blocked step"
            );
            let next = &records[i + 1];
            assert_eq!(next[0], k(EventKind::NodeAdded), "{planner}: the ladder step is added");
            assert!(common::motion_problem(&sc, &[r[6], r[7]], &[r[4], r[5]]).is_none(), "{planner}: {r:?} is free");
        }
        assert!(ladders >= 5, "{planner}: {ladders} ladder steps");
        // Off by default: the same run without it takes none.
        let (_, plain) = run("narrow", planner, json!({}), 7);
        assert!(plain.iter().all(|r| r[0] != k(EventKind::Steer) || r[3] < 0.0), "{planner}: no ladder step when off");
    }
}

#[test]
fn rrt_star_and_inspection_log_their_steps() {
    let (sc, records) = run("ompl-rect", "rrt-star", json!({}), 3);
    let (steps, blocked) = check_steps(&records, false);
    assert!(steps > 50, "{steps}");
    if matches!(sc.robot, planarium::scenario::RobotSpec::Point) {
        check_blockers(&sc, &blocked);
    }
    let (_, records) = run("technion-ip", "inspection", json!({}), 1);
    let (steps, _) = check_steps(&records, false);
    assert!(steps > 20, "{steps}");
}

#[test]
fn a_goal_sample_says_so() {
    let (sc, records) = run("open-field", "rrt", json!({"goal_bias": 0.3}), 2);
    let goal = sc.goal.clone().unwrap();
    let samples: Vec<_> = records.iter().filter(|r| r[0] == k(EventKind::Sample)).collect();
    let goals = samples.iter().filter(|r| r[2] == 1.0).count();
    assert!(goals > 0 && goals < samples.len(), "{goals} of {}", samples.len());
    for r in samples {
        assert_eq!(r[2] == 1.0, r[4] == goal[0] && r[5] == goal[1], "{r:?}");
    }
}

/// Nodes of `planner` (defaults) on `scenario` with `seed`.
fn nodes(scenario: &str, planner: &str, seed: u64) -> u64 {
    let sc = builtin(scenario).unwrap();
    let spec = planners::find(planner).unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let mut s = Session::new(
        problem,
        RunConfig { planner: planner.into(), params: Params::defaults(spec), seed, record_events: false },
    )
    .unwrap();
    s.run_to_end();
    s.result().stats.nodes
}

#[test]
fn the_narrow_passage_caption_holds_on_its_default_seed_and_over_101_seeds() {
    let sc = builtin("narrow").unwrap();
    let notes = sc.notes.clone();
    let seed = sc.planner.as_ref().and_then(|p| p.seed).unwrap();
    assert_eq!(seed, 7);
    let (rrt, connect) = (nodes("narrow", "rrt", seed), nodes("narrow", "rrt-connect", seed));
    assert!(notes.contains(&format!("on the default seed 7 RRT is the luckier ({rrt} nodes to {connect})")), "{notes}");
    assert!(rrt < connect);
    let median = |planner: &str| {
        let mut v: Vec<u64> = (1..=101).map(|s| nodes("narrow", planner, s)).collect();
        v.sort_unstable();
        v[50]
    };
    let (m_rrt, m_connect) = (median("rrt"), median("rrt-connect"));
    assert!(
        notes.contains(&format!("the median RRT-Connect run adds {m_connect} nodes to RRT's {m_rrt}")),
        "{m_connect} {m_rrt}: {notes}"
    );
}

/// Where a blocked motion is drawn: for a body (a rigid polygon, an arm, a vehicle chain), the
/// point where it meets the obstacle its record names, which lies in that obstacle; for a point,
/// the state itself. (Before, a body's collision was drawn at its reference point, which for the
/// chain lay far from the obstacle: "blocked by obstacle 1 at (0.146, 0.527)" with obstacle 1 at
/// x 0.25–0.35.)
#[test]
fn a_blocked_motion_is_drawn_where_the_robot_meets_the_obstacle() {
    for (scenario, planner, seed) in
        [("slot", "rrt-connect", 3), ("arm-2", "rrt-connect", 2), ("asv-7", "rrt-connect", 1), ("narrow", "rrt", 7)]
    {
        let (sc, records) = run(scenario, planner, json!({}), seed);
        let (mut named, mut moved) = (0, 0);
        for r in records.iter().filter(|r| r[0] == k(EventKind::Collision) && r[2] >= 0.0) {
            named += 1;
            let o = &sc.obstacles[r[2] as usize];
            let d = common::dist_to_obstacle(o, (r[4], r[5]));
            assert!(d <= 1e-9, "{scenario}: drawn at ({}, {}), {d} from obstacle {}", r[4], r[5], r[2]);
            moved += ([r[4], r[5]] != [r[8], r[9]]) as usize;
            if scenario == "arm-2" {
                // two joints: the record's c0, c1 are the whole state, so the point must lie on a
                // link of the arm there (its own forward kinematics)
                let pts = common::arm_points(&sc, &[r[8], r[9]]);
                let on = pts
                    .windows(2)
                    .map(|w| common::dist_point_segment((r[4], r[5]), w[0], w[1]))
                    .fold(f64::INFINITY, f64::min);
                assert!(on <= 1e-9, "arm-2: drawn at ({}, {}), {on} from the arm at {:?}", r[4], r[5], [r[8], r[9]]);
            }
        }
        assert!(named >= 5, "{scenario}: {named} collisions with a named obstacle");
        if scenario == "narrow" {
            assert_eq!(moved, 0, "a point's collision is drawn at the state");
        } else if scenario != "arm-2" {
            // (an arm's c0, c1 are angles, not a point: its contacts were checked on its links)
            assert!(moved * 2 > named, "{scenario}: {moved} of {named} drawn away from the reference point");
        }
    }
}

//! The explain panel's side channel for a spatial arm: the state log of a run (every growth-step
//! record's full states, in order) and where a collision happens (`Spatial::contact`).

use super::tests::problem;
use super::*;
use crate::events::{EventKind, EventLog, STRIDE};
use crate::problem::Problem;
use crate::run::{RunConfig, Session};
use crate::scenario::Scenario;
use serde_json::json;

fn last_free_session(log: bool) -> Session {
    let sc = crate::scenario::builtin("puma-rbo-wall").unwrap();
    let spec = crate::planners::find("rrt-connect").unwrap();
    let params = crate::planners::Params::from_json(spec, &json!({"connect": "last-free"})).unwrap();
    let config = RunConfig { planner: "rrt-connect".into(), params, seed: 3, record_events: true };
    let mut s = Session::new(Problem::from_scenario(&sc).unwrap(), config).unwrap();
    s.log_states(log);
    s
}

/// Every record of the growth step's kinds has exactly one entry, in order, of its kind; the
/// states are the record's (its first two coordinates, its drawn point); a last-free `Steer`
/// carries the state checks its connect took; a `Collision`'s state collides and the arm can say
/// where; and the log changes no record.
#[test]
fn the_state_log_gives_each_step_record_its_states_and_leaves_the_run_alone() {
    let (mut plain, mut logged) = (last_free_session(false), last_free_session(true));
    let (mut a, mut b, mut states) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..30 {
        let checks = logged.stats().checks;
        let (s1, s2) = (plain.step(10, f64::INFINITY), logged.step(10, f64::INFINITY));
        a.extend(plain.drain_events());
        let batch = logged.drain_events();
        let log = logged.drain_states();
        let flat = logged.problem().explain_states(&log);
        // The Steer entries' checks are the batch's checks but for the start's and goal's and
        // the samples' (none: the uniform sampler checks nothing).
        let steer_checks: f64 = flat[1..].chunks_exact(2 + 12).filter(|e| e[0] == 21.0).map(|e| e[1]).sum();
        let initial = if checks == 0 { 2.0 } else { 0.0 };
        assert_eq!(steer_checks + initial, (logged.stats().checks - checks) as f64, "the connects' queries");
        b.extend(batch);
        states.extend_from_slice(&flat[1..]);
        assert_eq!(flat[0], 6.0);
        assert_eq!(s1, s2);
        if s1.is_finished() {
            break;
        }
    }
    assert_eq!(a, b, "the state log changes no record");
    let p = logged.problem();
    let ws = p.si.workspace();
    let sp = p.robot.spatial().unwrap();
    let mut entries = states.chunks_exact(2 + 12);
    let (mut collisions, mut steers) = (0, 0);
    for r in b.chunks_exact(STRIDE) {
        let kind = r[0];
        if !EventLog::STATE_KINDS.iter().any(|k| *k as u8 as f64 == kind) {
            continue;
        }
        let e = entries.next().expect("an entry for each record");
        assert_eq!(e[0], kind);
        let (q, pq) = (&e[2..8], &e[8..14]);
        assert!(q.iter().chain(pq).all(|v| v.is_finite()), "{e:?}");
        if kind == EventKind::Sample as u8 as f64 || kind == EventKind::NodeAdded as u8 as f64 {
            assert_eq!((q[0], q[1]), (r[8], r[9]), "the record's first two coordinates");
            let at = p.si.project(q);
            assert_eq!((at.x, at.y), (r[4], r[5]));
        }
        if kind == EventKind::Nearest as u8 as f64 {
            assert_eq!(p.si.distance(q, pq), r[8], "the distance is the states'");
        }
        if kind == EventKind::Steer as u8 as f64 {
            steers += 1;
            assert!(e[1] >= 1.0 && e[1].fract() == 0.0, "the connect's queries: {}", e[1]);
            // the farthest configuration tested, `c0` from the node along the line
            assert!((p.si.distance(q, pq) - r[8]).abs() < 1e-9, "{} vs {}", p.si.distance(q, pq), r[8]);
        } else {
            assert!(e[1].is_nan());
        }
        if kind == EventKind::Collision as u8 as f64 {
            collisions += 1;
            assert!(!p.robot.is_valid(ws, q), "a collision's state collides");
            let c = sp.contact(ws, q).expect("the arm says where");
            assert!(c.at.iter().all(|v| v.is_finite()));
            assert!(p.robot.describe_collision(ws, q).is_some());
        }
    }
    assert!(entries.next().is_none(), "no entry without its record");
    assert!(collisions > 3 && steers > 10, "{collisions} collisions, {steers} steers");
}

/// Each last-free connect's configurations, asked for again (`Problem::connect_configs`, the
/// explain panel's steps through a connect), are the ones the connect tested: as many as its
/// queries, the last the farthest tested bit for bit, every one before it free, and the last free
/// unless the connect hit something.
#[test]
fn a_connects_configurations_asked_again_are_the_ones_it_tested() {
    let mut s = last_free_session(true);
    let (mut records, mut states) = (Vec::new(), Vec::new());
    for _ in 0..20 {
        let done = s.step(10, f64::INFINITY).is_finished();
        records.extend(s.drain_events());
        let log = s.drain_states();
        states.extend_from_slice(&s.problem().explain_states(&log)[1..]);
        if done {
            break;
        }
    }
    let p = s.problem();
    let ws = p.si.workspace();
    let entries: Vec<&[f64]> = states.chunks_exact(2 + 12).collect();
    let kinds: Vec<f64> = entries.iter().map(|e| e[0]).collect();
    let (steer, nearest, collision) =
        (EventKind::Steer as u8 as f64, EventKind::Nearest as u8 as f64, EventKind::Collision as u8 as f64);
    let mut checked = 0;
    for (i, e) in entries.iter().enumerate().filter(|(_, e)| e[0] == steer) {
        let n = kinds[..i].iter().rposition(|k| *k == nearest).expect("a nearest before each steer");
        let (from, target) = (&entries[n][2..8], &entries[n][8..14]);
        assert_eq!(&e[8..14], from, "the steer starts at the nearest node");
        let count = e[1] as usize;
        let configs = p.connect_configs(from, target, count);
        assert_eq!(configs.len(), count, "one configuration a query");
        assert_eq!(configs.last().unwrap().as_slice(), &e[2..8], "the last is the farthest tested");
        for q in &configs[..count - 1] {
            assert!(p.robot.is_valid(ws, q), "the connect went on past it: free");
        }
        let hit = kinds.get(i + 1) == Some(&collision);
        assert_eq!(p.robot.is_valid(ws, configs.last().unwrap()), !hit, "the last is free unless it hit");
        // asking for more gives the same first ones
        assert_eq!(&p.connect_configs(from, target, count + 3)[..count], &configs[..]);
        checked += 1;
    }
    assert!(checked > 10, "{checked} connects");
    assert!(p.connect_configs(&[0.0; 6], &[0.0; 6], 5).is_empty(), "no line: nothing");
}

/// A suspended batch's records go, and their state log entries with them.
#[test]
fn the_state_log_follows_truncation() {
    let mut log = EventLog::new(true);
    log.log_states(2);
    let p = crate::math::Vec2::new(0.0, 0.0);
    log.at(EventKind::Sample, 0, p, &[1.0, 2.0]);
    log.at(EventKind::Solved, 0, p, &[0.0, 0.0]); // not a step's kind: no entry
    assert_eq!(log.drain().len(), 2 * STRIDE);
    log.values(EventKind::Steer, 0, 0, -1, [0.0; 8]);
    log.attach(&[3.0, 4.0], &[5.0, 6.0], 7.0);
    log.values(EventKind::Nearest, 0, 0, -1, [0.0; 8]); // no states attached: NaN
    log.at(EventKind::Sample, 0, p, &[8.0, 9.0]);
    log.truncate(2); // record 4 (the last sample) goes
    let s = log.drain_states();
    let e: Vec<&[f64]> = s.data.chunks_exact(s.stride()).collect();
    assert_eq!(e.len(), 3);
    assert_eq!((e[0][0], e[0][1], e[0][3], e[0][4]), (0.0, 0.0, 1.0, 2.0));
    assert_eq!(&e[1][..2], &[2.0, EventKind::Steer as u8 as f64]);
    assert_eq!(&e[1][2..], &[7.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(&e[2][..2], &[3.0, EventKind::Nearest as u8 as f64]);
    assert!(e[2][2..].iter().all(|v| v.is_nan()));
}

/// Where the hand meets a wall, and where two links meet.
#[test]
fn a_contact_is_where_the_parts_meet() {
    // The test arm of `tests.rs`: the hand's hull spans x in [1, 1.5] at q = 0; the wall's face at 1.2.
    let mut sc = super::tests::scenario(1.2, json!({}));
    sc["obstacles3d"] = json!([{"name": "post", "box": {"center": [5, 5, 0], "size": [0.2, 0.2, 0.2]}},
                               {"name": "wall", "box": {"center": [1.7, 0, 0], "size": [1, 4, 4]}}]);
    let p = problem(&sc);
    let (ws, sp) = (p.si.workspace(), p.robot.spatial().unwrap());
    assert!(sp.contact(ws, &[1.5, 0.0]).is_none(), "free");
    let c = sp.contact(ws, &[0.0, 0.0]).unwrap();
    assert_eq!((c.link, c.other, c.solid), (2, None, Some(1)));
    // within the overlap x in [1.2, 1.5], on the hand's axis
    assert!((1.2 - 1e-9..=1.5 + 1e-9).contains(&c.at[0]), "{:?}", c.at);
    assert!(c.at[1].abs() <= 0.05 + 1e-9 && c.at[2].abs() <= 0.05 + 1e-9, "{:?}", c.at);
    // Tested against each other, folded back, the hand meets the bar.
    let mut sc2 = sc.clone();
    sc2["obstacles3d"] = json!([]);
    let ws = problem(&sc2).si.workspace().clone();
    sc2["robot"]["ignore"] = json!([]);
    let arm = SpatialArmRobot::from_spec(&Scenario::from_value(&sc2).unwrap().robot).unwrap();
    let c = arm.contact(&ws, &[0.0, 3.0]).unwrap();
    assert_eq!((c.link, c.other, c.solid), (1, Some(2), None));
    // the bar spans x in [0, 1], |y|, |z| ≤ 0.1
    assert!((-1e-9..=1.0 + 1e-9).contains(&c.at[0]) && c.at[1].abs() <= 0.1 + 1e-9, "{:?}", c.at);
}

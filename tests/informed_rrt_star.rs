//! Informed RRT* (Gammell et al. 2014): after the first solution every sample lies in the informed
//! set of the cost at the time; the ellipse logged with each improvement is that set's; paths are
//! valid by the independent checker; with the same iterations its median cost is below RRT*'s; it
//! is RRT* until the first solution.
//!
//! Each test says what it catches.

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::{builtin, Scenario};
use serde_json::{json, Value};

fn run(sc: &Scenario, planner: &str, v: &Value, seed: u64) -> (PlanResult, Vec<f64>, Problem) {
    let params = Params::from_json(planners::find(planner).unwrap(), v).unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    let config = RunConfig { planner: planner.into(), params, seed, record_events: true };
    let mut s = Session::new(Problem::from_scenario(sc).unwrap(), config).unwrap();
    s.run_to_end();
    (s.result(), s.drain_events(), problem)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Catches: samples drawn outside the informed set after a solution (the ellipse's axes, its
/// turn onto the start–goal line or its centre wrong; the rejection test's inequality reversed),
/// an ellipse logged that is not the set of the cost at the time, costs that do not fall, and
/// invalid paths. Point robots (direct draws: every coordinate is in the event) and the two-link
/// arm (angles that wrap: draws by rejection; its two angles are the event's state).
#[test]
fn samples_after_a_solution_lie_in_the_informed_set() {
    for (name, planar) in [("open-field", true), ("zigzag", true), ("narrow", true), ("arm-2", false)] {
        let sc = builtin(name).unwrap();
        for seed in 1..=6 {
            let (r, events, problem) = run(&sc, "informed-rrt-star", &json!({"improve_for": 800}), seed);
            assert!(r.solved, "{name} seed {seed}: {}", r.status);
            assert_eq!(common::path_problem(&sc, &r.path), None, "{name} seed {seed}: raw path");
            let (start, goal) = (problem.start.clone(), problem.goal.clone().unwrap());
            let foci = problem.si.distance(&start, &goal);
            let mut cost: Option<f64> = None;
            let (mut checked, mut ellipses) = (0, 0);
            for rec in events.chunks(STRIDE) {
                let kind = rec[0] as u8;
                if kind == EventKind::Cost as u8 {
                    let c = rec[6];
                    assert!(cost.is_none_or(|b| c < b), "{name} seed {seed}: cost {c} after {cost:?}");
                    cost = Some(c);
                } else if kind == EventKind::Informed as u8 {
                    ellipses += 1;
                    let c = cost.expect("an ellipse after a cost");
                    assert_eq!(rec[10], c, "{name} seed {seed}: the ellipse is the latest cost's");
                    assert_eq!(rec[6], c / 2.0);
                    assert!(
                        (rec[7] - (c * c - foci * foci).sqrt() / 2.0).abs() < 1e-12,
                        "{name}: minor axis {}",
                        rec[7]
                    );
                    assert!(
                        (rec[4] - (start[0] + goal[0]) / 2.0).abs() < 1e-12
                            && (rec[5] - (start[1] + goal[1]) / 2.0).abs() < 1e-12
                    );
                    assert!((rec[8] * rec[8] + rec[9] * rec[9] - 1.0).abs() < 1e-12);
                } else if kind == EventKind::Sample as u8 && rec[2] != 1.0 {
                    if let Some(c) = cost {
                        let q = [rec[8], rec[9]];
                        let h = problem.si.distance(&start, &q) + problem.si.distance(&q, &goal);
                        assert!(h < c, "{name} seed {seed}: sample {q:?} with d(s,q)+d(q,g) = {h} ≥ {c}");
                        checked += 1;
                    }
                }
            }
            assert!(checked > 100, "{name} seed {seed}: {checked} samples after the first solution");
            if planar {
                assert!(ellipses >= 1, "{name} seed {seed}: no ellipse logged");
            } else {
                assert_eq!(ellipses, 0, "{name}: an ellipse for a robot not placed in the plane");
            }
        }
    }
}

/// Catches: an informed sampler that does not focus the search (samples the whole space, or a set
/// too large). Raw costs, median over 15 seeds, the same iterations after the first solution.
/// Asserted on six built-ins; on `slot` (printed) the rigid body's heading is drawn uniformly
/// and Informed RRT*'s median is 0.9% above RRT*'s with these seeds.
#[test]
fn informed_sampling_lowers_the_median_cost() {
    for name in ["open-field", "narrow", "zigzag", "arm-2", "arm-3", "ompl-rect", "slot"] {
        let sc = builtin(name).unwrap();
        let cost = |planner| {
            median(
                (1..=15)
                    .map(|seed| run(&sc, planner, &json!({"improve_for": 1500}), seed).0.stats.cost.unwrap())
                    .collect(),
            )
        };
        let (star, informed) = (cost("rrt-star"), cost("informed-rrt-star"));
        println!("{name}: median cost RRT* {star:.4}, Informed RRT* {informed:.4}");
        assert!(name == "slot" || informed < star, "{name}: Informed RRT* {informed} against RRT* {star}");
    }
}

/// Catches: an Informed RRT* that differs from RRT* before its first solution (it must draw from
/// the run's sampler until then): the same seed gives the same first solution.
#[test]
fn before_a_solution_it_is_rrt_star() {
    for name in ["open-field", "zigzag", "arm-3"] {
        let sc = builtin(name).unwrap();
        for seed in 1..=5 {
            let first = |planner| {
                let (_, events, _) = run(&sc, planner, &json!({"improve_for": 0}), seed);
                events.chunks(STRIDE).find(|r| r[0] == EventKind::Cost as u8 as f64).map(|r| (r[2], r[6]))
            };
            assert_eq!(first("rrt-star"), first("informed-rrt-star"), "{name} seed {seed}");
        }
    }
}

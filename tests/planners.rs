//! Every registered planner, on every built-in scenario, for several seeds (OMPL's `2denvs`
//! harness): it must solve within an iteration limit, and every returned path, raw and smoothed,
//! must pass an independent checker; every tree edge must be a valid motion.

mod common;

use planarium::motion::MotionValidator;
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{RunConfig, Session};
use planarium::scenario::{builtin, builtin_names};
use serde_json::json;

fn setups() -> Vec<(&'static str, serde_json::Value)> {
    vec![
        ("rrt", json!({})),
        ("rrt", json!({"extend": "connect"})),
        ("rrt", json!({"goal_bias": 0.2, "range": 0.05})),
        ("rrt-connect", json!({})),
        ("rrt-connect", json!({"range": 0.05})),
    ]
}

#[test]
fn the_checker_rejects_bad_paths() {
    common::self_test();
}

#[test]
fn every_planner_solves_every_builtin_with_valid_paths() {
    for name in builtin_names() {
        let sc = builtin(name).unwrap();
        for (planner, params) in setups() {
            let spec = planners::find(planner).unwrap();
            for seed in 1..=4 {
                let mut p = Params::from_json(spec, &params).unwrap();
                p.set_text(spec, "max_iterations", "200000").unwrap();
                let problem = Problem::from_scenario(&sc).unwrap();
                let mut s = Session::new(problem, RunConfig { planner: planner.into(), params: p, seed, record_events: false }).unwrap();
                s.run_to_end();
                let r = s.result();
                let what = format!("{name} / {planner} {params} / seed {seed}");
                assert!(r.solved, "{what}: {}", r.status);
                if let Some(e) = common::path_problem(&sc, &r.path) {
                    panic!("{what}: raw path: {e}");
                }
                if let Some(e) = common::path_problem(&sc, &r.smoothed) {
                    panic!("{what}: smoothed path: {e}");
                }
                let (cost, smoothed) = (r.stats.cost.unwrap(), r.stats.smoothed_cost.unwrap());
                assert!(smoothed <= cost + 1e-9, "{what}: smoothing made it longer ({cost} → {smoothed})");
                assert!(r.stats.checks > 0 && r.stats.nodes >= 2);
                // Every edge of every tree was checked by the planner: re-check with the crate's
                // validator and, for a sample, independently.
                let si = &s.problem().si;
                let mut scratch = vec![0.0; si.dims()];
                for (k, tree) in s.planner_data().trees.iter().enumerate() {
                    for (e, (a, b)) in tree.edges().enumerate() {
                        assert!(si.check_motion(a, b, &mut scratch).is_ok(), "{what}: tree {k} edge {e} invalid");
                        if e % 7 == 0 {
                            if let Some(err) = common::motion_problem(&sc, a, b) {
                                panic!("{what}: tree {k} edge {e}: {err}");
                            }
                        }
                    }
                }
            }
        }
    }
}

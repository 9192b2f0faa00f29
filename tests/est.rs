//! EST and bidirectional EST (issue 17): each solves the built-ins it is meant for, the zigzag
//! included, with paths (raw and smoothed) and tree edges that pass the independent checker; runs
//! are reproducible; and every density pick the page draws is the rule's, recomputed here from the
//! nodes added (cell counts from the `NodeAdded` records, the probability 1/count over the sum).

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::builtin;
use std::collections::HashMap;

fn run(id: &str, planner: &str, seed: u64, events: bool) -> (PlanResult, Vec<f64>, Vec<Vec<Vec<f64>>>) {
    let sc = builtin(id).unwrap();
    let spec = planners::find(planner).unwrap();
    let mut p = Params::defaults(spec);
    p.set_text(spec, "max_iterations", "400000").unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: planner.into(), params: p, seed, record_events: events }).unwrap();
    s.run_to_end();
    let trees =
        s.planner_data().trees.iter().map(|t| (0..t.len() as u32).map(|i| t.state(i).to_vec()).collect()).collect();
    (s.result(), s.drain_events(), trees)
}

#[test]
fn both_solve_the_builtins_and_the_zigzag_with_valid_paths() {
    for id in ["open-field", "narrow", "zigzag", "arm-2", "ompl-rect"] {
        let sc = builtin(id).unwrap();
        for planner in ["est", "bi-est"] {
            for seed in 1..=3 {
                let what = format!("{id} / {planner} / seed {seed}");
                let (r, _, _) = run(id, planner, seed, false);
                assert!(r.solved, "{what}: {}", r.status);
                for (name, path) in [("raw", &r.path), ("smoothed", &r.smoothed)] {
                    if let Some(e) = common::path_problem(&sc, path) {
                        panic!("{what}, {name} path: {e}");
                    }
                }
                let far = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
                assert!(far(&r.path[0], &sc.start) < 1e-9, "{what}: the path starts at the start");
                assert!(far(r.path.last().unwrap(), sc.goal.as_ref().unwrap()) < 1e-9, "{what}: it ends at the goal");
            }
        }
    }
}

#[test]
fn the_same_seed_grows_the_same_trees() {
    for planner in ["est", "bi-est"] {
        let a = run("narrow", planner, 5, false);
        let b = run("narrow", planner, 5, false);
        assert_eq!(a.2, b.2, "{planner}: trees differ");
        assert_eq!(a.0.path, b.0.path);
        let c = run("narrow", planner, 6, false);
        assert_ne!(a.2, c.2, "{planner}: another seed, another tree");
    }
}

#[test]
fn every_pick_follows_the_density_rule() {
    for planner in ["est", "bi-est"] {
        let (r, ev, _) = run("narrow", planner, 2, true);
        assert!(r.solved);
        let sc = builtin("narrow").unwrap();
        let [x0, y0, x1, y1] = [sc.bounds[0], sc.bounds[1], sc.bounds[2], sc.bounds[3]];
        let grid = 20.0;
        let cell = |x: f64, y: f64| {
            let c = |v: f64, lo: f64, hi: f64| {
                (((v - lo) / (hi - lo)).clamp(0.0, 1.0) * grid).floor().min(grid - 1.0) as i64
            };
            (c(x, x0, x1), c(y, y0, y1))
        };
        // Cell counts per tree, from the roots (the start's and the goal's points) and every node
        // added.
        let mut counts: Vec<HashMap<(i64, i64), usize>> = vec![HashMap::new(), HashMap::new()];
        let g = sc.goal.clone().unwrap();
        counts[0].insert(cell(sc.start[0], sc.start[1]), 1);
        if planner == "bi-est" {
            counts[1].insert(cell(g[0], g[1]), 1);
        }
        let mut picks = 0;
        let mut sparse = 0;
        for rec in ev.chunks(STRIDE) {
            let (kind, tree) = (rec[0] as u8, rec[1] as usize);
            if kind == EventKind::NodeAdded as u8 {
                *counts[tree].entry(cell(rec[4], rec[5])).or_default() += 1;
            }
            if kind == EventKind::Select as u8 {
                let c = &counts[tree];
                let here = c[&cell(rec[4], rec[5])];
                assert_eq!(rec[6] as usize, here, "{planner}: the picked node's cell count");
                let total: f64 = c.values().map(|&n| 1.0 / n as f64).sum();
                let p = (1.0 / here as f64) / total;
                assert!((rec[7] - p).abs() < 1e-9, "{planner}: probability {} vs {p}", rec[7]);
                assert_eq!(rec[8] as usize, c.len(), "{planner}: cells in use");
                // A node picked at random (not by density) would sit in a cell of mean count
                // Σn²/Σn; the density rule picks cells below that mean more often.
                let (s1, s2) = c.values().fold((0.0, 0.0), |(a, b), &n| (a + n as f64, b + (n * n) as f64));
                sparse += usize::from((here as f64) < s2 / s1);
                picks += 1;
            }
        }
        assert!(picks > 100, "{planner}: {picks} picks");
        assert!(sparse * 2 > picks, "{planner}: only {sparse} of {picks} picks in a sparser-than-average cell");
    }
}

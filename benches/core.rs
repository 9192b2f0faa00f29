//! Micro-benchmarks of the core's parts on the OMPL comparison's problems (`cargo bench --bench core`).
//!
//! `npm run bench` times whole seeded runs natively and in wasm; these time the parts the profiles
//! name, one at a time, with criterion's statistics (useful on a noisy machine):
//!
//! - `nearest`: a query in a 10 000-state k-d tree, for each problem's metric (the plane, the bar's
//!   `|Δxy| + w·|Δθ|` with wrap-around, the 10-link chain's embedding);
//! - `state_check`: one state validity check;
//! - `motion_check`: one motion of at most OMPL's range from a valid state, at the scenario's
//!   resolution (discrete for the point, certified by clearance for the bar and the chain);
//! - `plan`: seeded RRT-Connect runs to the end (planning and smoothing), as in the suite;
//! - `scaling`: one state check among 10 to 100 000 obstacles (a grid of small blocks filling the
//!   right half of a 2 × 1 map), for the point, a small rectangle and a 3-link arm: the broad
//!   phase (parry's bounding-volume hierarchy from 32 obstacles on, a grid of candidate lists in
//!   front of it) keeps it nearly flat. The maps are `planarium::run::scaling`'s, which the suite
//!   times too (`planarium scaling`).
//!
//! - `spatial_query`: one collision query of report 001's Puma 560 on its course scene
//!   (`puma-rbo-wall`: forward kinematics, the scene's boxes, the 13 tested link pairs), on uniform
//!   states and on the states a connect tests (1° steps from a free state toward a uniform one,
//!   up to the first collision: the run's queries are these, neighbours of each other).
//!
//! Every input is drawn from a seeded generator, so each run of the benchmark measures the same work.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use planarium::motion::MotionValidator;
use planarium::nn::KdTree;
use planarium::planners::Params;
use planarium::problem::Problem;
use planarium::rng::Rng;
use planarium::run::bench::parse_setup;
use planarium::run::{scaling, RunConfig, Session};
use planarium::scenario;
use std::time::Duration;

/// The problems, with OMPL's step range for each.
const PROBLEMS: [(&str, f64); 3] = [("narrow", 0.2828), ("ompl-rect", 0.597), ("horn-10", 1.0)];

fn problem(id: &str) -> Problem {
    Problem::from_scenario(&scenario::builtin(id).expect("a built-in")).expect("a valid problem")
}

/// `n` uniform states (valid or not) from seed `seed`.
fn uniform_states(p: &Problem, n: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let mut q = vec![0.0; p.si.dims()];
            p.si.sample(&mut rng, &mut q);
            q
        })
        .collect()
}

/// `n` motions `(a, b)`: `a` a valid state, `b` a uniform state brought within `range` of `a`.
fn motions(p: &Problem, n: usize, range: f64) -> Vec<(Vec<f64>, Vec<f64>)> {
    let valid: Vec<Vec<f64>> = uniform_states(p, 50 * n, 11).into_iter().filter(|q| p.si.is_valid(q)).take(n).collect();
    assert_eq!(valid.len(), n, "enough valid states");
    let targets = uniform_states(p, n, 12);
    valid
        .into_iter()
        .zip(targets)
        .map(|(a, t)| {
            let d = p.si.distance(&a, &t);
            let mut b = t.clone();
            if d > range {
                p.si.interpolate(&a, &t, range / d, &mut b);
            }
            (a, b)
        })
        .collect()
}

fn nearest(c: &mut Criterion) {
    let mut g = c.benchmark_group("nearest");
    for (id, _) in PROBLEMS {
        let p = problem(id);
        let mut tree = KdTree::new(p.si.dims());
        for (i, q) in uniform_states(&p, 10_000, 1).iter().enumerate() {
            tree.add(&p.si.space, q, i as u32);
        }
        let queries = uniform_states(&p, 1024, 2);
        let mut k = 0;
        g.bench_function(BenchmarkId::new("10k", id), |b| {
            b.iter(|| {
                k = (k + 1) % queries.len();
                black_box(tree.nearest(&p.si.space, &queries[k]))
            })
        });
    }
    g.finish();
}

fn state_check(c: &mut Criterion) {
    let mut g = c.benchmark_group("state_check");
    for (id, _) in PROBLEMS {
        let p = problem(id);
        let states = uniform_states(&p, 1024, 3);
        let mut k = 0;
        g.bench_function(id, |b| {
            b.iter(|| {
                k = (k + 1) % states.len();
                black_box(p.si.is_valid(&states[k]))
            })
        });
    }
    g.finish();
}

fn motion_check(c: &mut Criterion) {
    let mut g = c.benchmark_group("motion_check");
    for (id, range) in PROBLEMS {
        let p = problem(id);
        let moves = motions(&p, 256, range);
        let mut scratch = vec![0.0; p.si.dims()];
        let mut k = 0;
        g.bench_function(id, |b| {
            b.iter(|| {
                k = (k + 1) % moves.len();
                let (a, m) = &moves[k];
                black_box(p.si.check_motion(a, m, &mut scratch).is_ok())
            })
        });
    }
    g.finish();
}

fn plan(c: &mut Criterion) {
    let mut g = c.benchmark_group("plan");
    g.sample_size(10);
    for (id, range) in PROBLEMS {
        let setup =
            parse_setup(&format!("rrt-connect --range {range}"), |spec| Ok(Params::defaults(spec))).expect("a set-up");
        let sc = scenario::builtin(id).expect("a built-in");
        // Seeds 1..=5 per iteration: one seed alone would time one tree.
        g.bench_function(BenchmarkId::new("rrt-connect seeds 1-5", id), |b| {
            b.iter(|| {
                for seed in 1..=5 {
                    let config = RunConfig {
                        planner: setup.spec.name.into(),
                        params: setup.params.clone(),
                        seed,
                        record_events: false,
                    };
                    let mut s =
                        Session::new(Problem::from_scenario(&sc).expect("a valid problem"), config).expect("a session");
                    assert!(s.run_to_end().is_finished());
                    black_box(s.stats());
                }
            })
        });
    }
    g.finish();
}

fn scaling(c: &mut Criterion) {
    let mut g = c.benchmark_group("scaling");
    for (robot, spec, start) in scaling::robots() {
        for n in scaling::SIZES {
            let p = scaling::blocks(n, spec.clone(), start.clone());
            let states = uniform_states(&p, 1024, 5);
            let mut k = 0;
            g.bench_function(BenchmarkId::new(robot, n), |b| {
                b.iter(|| {
                    k = (k + 1) % states.len();
                    black_box(p.si.is_valid(&states[k]))
                })
            });
        }
    }
    g.finish();
}

fn spatial_query(c: &mut Criterion) {
    let mut g = c.benchmark_group("spatial_query");
    let p = problem("puma-rbo-wall");
    let uniform = uniform_states(&p, 4096, 3);
    // Connect-like sequences: from a free state toward a uniform one in steps of the resolution.
    let mut steps = Vec::new();
    let targets = uniform_states(&p, 4096, 4);
    let mut q = vec![0.0; p.si.dims()];
    for (a, b) in uniform.iter().filter(|a| p.si.is_valid(a)).zip(&targets) {
        let d = p.si.distance(a, b);
        let n = (d / p.si.resolution).ceil() as usize;
        for k in 1..=n {
            p.si.interpolate(a, b, (k as f64 * p.si.resolution / d).min(1.0), &mut q);
            steps.push(q.clone());
            if !p.si.is_valid(&q) || steps.len() >= 100_000 {
                break;
            }
        }
        if steps.len() >= 100_000 {
            break;
        }
    }
    for (name, states) in [("uniform", &uniform), ("connect steps", &steps)] {
        let mut k = 0;
        g.bench_function(name, |b| {
            b.iter(|| {
                k = (k + 1) % states.len();
                black_box(p.si.is_valid(&states[k]))
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(2));
    targets = nearest, state_check, motion_check, plan, scaling, spatial_query
}
criterion_main!(benches);

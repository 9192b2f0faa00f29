//! Samplers inside whole runs and on every built-in robot: the statistics a run reports, the
//! narrow-passage samplers' effect on `narrow`, every sampler's bounds, validity and seeds, the vehicle
//! chain's own neighbours, and the hybrid form's uniform share (issue 16). Helpers are the parent's.

use super::*;
use planarium::run::{RunConfig, Session};

/// Catches: a sampler's statistics not reaching the run's result (`stats.sampler` in the
/// contract's JSON), or its checks not part of the run's.
#[test]
fn the_run_reports_the_samplers_statistics() {
    for sampler in NAMES {
        let sc = builtin("narrow").unwrap();
        let params = json!({"sampler": sampler, "max_iterations": 300, "goal_bias": 0.05});
        let params = Params::from_json(planners::find("rrt-connect").unwrap(), &params).unwrap();
        let config = RunConfig { planner: "rrt-connect".into(), params, seed: 2, record_events: true };
        let mut s = Session::new(Problem::from_scenario(&sc).unwrap(), config).unwrap();
        s.run_to_end();
        let events = s.drain_events();
        let count = |k: EventKind| events.chunks(STRIDE).filter(|r| r[0] == k as u8 as f64).count() as u64;
        let result = serde_json::to_value(s.result()).unwrap();
        let st = &result["stats"]["sampler"];
        assert_eq!(st["name"], json!(sampler));
        let accepted = st["accepted"].as_u64().unwrap();
        assert_eq!(accepted, count(EventKind::Sample), "{sampler}: one Sample event per accepted sample");
        assert_eq!(
            st["checks"].as_u64().unwrap(),
            count(EventKind::SampleTry),
            "{sampler}: one SampleTry event per check"
        );
        assert!(st["checks"].as_u64().unwrap() <= result["stats"]["checks"].as_u64().unwrap());
        let draws = st["draws"].as_u64().unwrap();
        assert!(draws >= accepted);
        assert_eq!(st["draws_per_sample"].as_f64().unwrap(), draws as f64 / accepted.max(1) as f64);
        assert!(accepted + st["failed"].as_u64().unwrap() > 0);
    }
}

/// On `narrow` (a wall with a 0.02 gap, `passage`), the share of samples that are free and near
/// the wall, and of those in the gap. Catches a narrow-passage sampler that does not favour obstacles or the passage over
/// uniform sampling (e.g. one that ignores its validity checks).
#[test]
fn narrow_passage_samplers_favour_the_obstacles_and_the_passage() {
    let share = |sampler: &str, near: Real| -> (Real, Real) {
        let mut b = Bench::new("narrow", json!({"sampler": sampler}), 14);
        let (mut n, mut close, mut passage) = (0, 0, 0);
        for _ in 0..3000 {
            if b.sample().0 {
                n += 1;
                close += near_wall(&b.out, near) as usize;
                passage += in_passage(&b.out) as usize;
            }
        }
        assert!(n > 100, "{sampler}: {n} samples");
        (close as Real / n as Real, passage as Real / n as Real)
    };
    let (uniform_near, uniform_passage) = share("uniform", 0.05);
    let (gaussian_near, _) = share("gaussian", 0.05);
    let (uniform_touching, _) = share("uniform", 0.003);
    let (obstacle_touching, _) = share("obstacle", 0.003);
    let (_, bridge_passage) = share("bridge", 0.05);
    eprintln!("near the wall: uniform {uniform_near:.3}, gaussian {gaussian_near:.3}; within 0.003: uniform {uniform_touching:.4}, obstacle {obstacle_touching:.3}; in the passage: uniform {uniform_passage:.4}, bridge {bridge_passage:.3}");
    assert!(gaussian_near > 0.5 && gaussian_near > 4.0 * uniform_near);
    assert!(obstacle_touching > 0.99 && uniform_touching < 0.02);
    assert!(bridge_passage == 1.0 && uniform_passage < 0.01);

    // Near-collision needs collisions: a whole RRT run, its Sample events. Its samples are not
    // checked, and a collision point is an occupied state the motion check found, inside the
    // wall: count samples within 0.05 of the wall's boundary on either side.
    let near_share = |sampler: &str| -> Real {
        let sc = builtin("narrow").unwrap();
        let params = json!({"sampler": sampler, "max_iterations": 1500, "goal_bias": 0.0});
        let params = Params::from_json(planners::find("rrt").unwrap(), &params).unwrap();
        let config = RunConfig { planner: "rrt".into(), params, seed: 3, record_events: true };
        let mut s = Session::new(Problem::from_scenario(&sc).unwrap(), config).unwrap();
        s.run_to_end();
        let events = s.drain_events();
        let samples: Vec<_> =
            events.chunks(STRIDE).filter(|r| r[0] == EventKind::Sample as u8 as f64).map(|r| [r[8], r[9]]).collect();
        assert!(samples.len() > 200, "{sampler}: {} samples", samples.len());
        samples.iter().filter(|q| wall_distance(&q[..]) <= 0.05).count() as Real / samples.len() as Real
    };
    let (u, nc) = (near_share("uniform"), near_share("near-collision"));
    eprintln!("within 0.05 of the wall's boundary in an RRT run: uniform {u:.3}, near-collision {nc:.3}");
    assert!(nc > 3.0 * u, "near-collision {nc}, uniform {u}");
}

/// Catches: a sample out of the space's bounds or an angle not wrapped, an occupied sample from a
/// sampler that checks validity, a sampler that gives up on every draw of a robot, and any
/// randomness besides the run's seeded generator (same seed, other results).
#[test]
fn every_sampler_on_every_builtin_stays_in_bounds_valid_and_reproducible() {
    for name in builtin_names() {
        for sampler in NAMES {
            let checks = matches!(*sampler, "gaussian" | "bridge" | "obstacle");
            let n = if *sampler == "bridge" { bridge_samples(name) } else { 60 };
            let run = |seed: u64| {
                let mut b = Bench::new(name, json!({"sampler": sampler}), seed);
                let mut got = Vec::new();
                let mut trace = Vec::new();
                for k in 0..n {
                    if k % 9 == 8 {
                        let q = b.out.clone();
                        b.s.note_collision(&q);
                    }
                    let (ok, events) = b.sample();
                    trace.extend(events);
                    if ok {
                        assert!(b.in_bounds(&b.out), "{name} {sampler}: {:?} out of bounds", b.out);
                        if checks {
                            assert!(b.valid(&b.out), "{name} {sampler}: {:?} is not valid", b.out);
                        }
                        got.push(b.out.clone());
                    }
                }
                (got, trace, b.s.stats())
            };
            let (first, trace, stats) = run(21);
            assert!(!first.is_empty(), "{name} {sampler}: gave up on all {n} samples");
            let (again, trace_again, stats_again) = run(21);
            assert!(
                first == again && trace == trace_again && stats == stats_again,
                "{name} {sampler}: same seed, other samples"
            );
            let (other, _, _) = run(22);
            assert_ne!(first, other, "{name} {sampler}: the seed changes nothing");
        }
    }
}

/// The vehicle chain's Gaussian neighbour keeps the chain a convex chain: around valid states, it
/// is valid more than twice as often (at the default sigma) as moving every coordinate independently (which is what Gaussian,
/// bridge and near-collision sampling would otherwise see: almost only invalid chains). Catches
/// the robot's own neighbour being ignored, or one that breaks the turns' winding or sum.
#[test]
fn the_vehicle_chain_draws_gaussian_neighbours_that_stay_chains() {
    let p = Problem::from_scenario(&builtin("asv-7").unwrap()).unwrap();
    let si = &p.si;
    let mut rng = Rng::new(11);
    let (mut q, mut own, mut generic) = (vec![0.0; si.dims()], vec![0.0; si.dims()], vec![0.0; si.dims()]);
    let (mut centres, mut own_valid, mut generic_valid) = (0, 0, 0);
    while centres < 300 {
        si.sample(&mut rng, &mut q);
        if !si.is_valid(&q) {
            continue;
        }
        centres += 1;
        let chain = si.own_sampler().expect("the chain has its own sampler");
        chain.sample_gaussian(&si.space, &mut rng, &q, 0.05, &mut own);
        planarium::sampler::gaussian_coordinates(&si.space, &mut rng, &q, 0.05, &mut generic);
        own_valid += si.is_valid(&own) as usize;
        generic_valid += si.is_valid(&generic) as usize;
        // Turns keep the winding of the centre's.
        let wind = |s: &[Real]| s[3..].iter().sum::<Real>().signum();
        assert!(own[3..].iter().all(|t| t * wind(&q) >= 0.0), "a turn changed side: {:?} → {:?}", &q[3..], &own[3..]);
    }
    assert!(
        own_valid > 2 * generic_valid && own_valid > 40,
        "own {own_valid}/300 valid, per-coordinate {generic_valid}/300"
    );
}

/// The hybrid form (issue 16): with `uniform_share` s, a fraction s of the samples (goal aside)
/// are plain uniform draws, told apart by `drew_uniform_share`, with no witnesses and no checked
/// tries of their own; the rest follow the rule. Catches a share ignored, applied to the
/// uniform sampler, or mixing its draws with the rule's.
#[test]
fn the_uniform_share_mixes_plain_uniform_samples_into_every_narrow_passage_sampler() {
    for sampler in ["gaussian", "bridge", "obstacle", "near-collision"] {
        let mut b = Bench::new("narrow", json!({"sampler": sampler, "uniform_share": 0.3}), 17);
        let (mut n, mut plain) = (0, 0);
        for _ in 0..2000 {
            let (ok, events) = b.sample();
            if !ok {
                continue; // the rule gave up after its tries (a plain draw never does)
            }
            n += 1;
            if b.s.drew_uniform_share() {
                plain += 1;
                assert!(b.s.witnesses().is_none() && tries(&events).is_empty(), "{sampler}: a plain draw was checked");
                assert_eq!(b.s.origin(), 2);
            } else {
                assert_eq!(b.s.origin(), 0);
            }
        }
        // 2000 draws at p = 0.3: the standard deviation is about 20, so ±100 is five of them.
        // 2000 draws at p = 0.3: the standard deviation is about 20, so ±100 is five of them.
        // The share is of the 2000 draws: a draw the rule gave up on was not a plain one.
        assert!((500..=700).contains(&plain), "{sampler}: {plain} plain draws of 2000 at 0.3 ({n} accepted)");
    }
    let mut b = Bench::new("narrow", json!({"sampler": "uniform", "uniform_share": 0.5}), 17);
    for _ in 0..200 {
        b.sample();
        assert!(!b.s.drew_uniform_share(), "the uniform sampler has no share to draw");
    }
}

/// What the share is for: on `zigzag` (corridors 0.15 wide, nothing narrow) the pure bridge test
/// almost never finds a bridge, so RRT-Connect finds no path in 40,000 iterations (each up to 100 tries); with the default
/// share it solves every seed tried. Paths pass the independent checker.
#[test]
fn the_default_uniform_share_lets_the_bridge_test_solve_open_corridors() {
    let sc = builtin("zigzag").unwrap();
    let run = |seed: u64, extra: Value| {
        let mut params = json!({"sampler": "bridge", "max_iterations": 40000});
        params.as_object_mut().unwrap().extend(extra.as_object().unwrap().clone());
        let params = Params::from_json(planners::find("rrt-connect").unwrap(), &params).unwrap();
        let config = RunConfig { planner: "rrt-connect".into(), params, seed, record_events: false };
        let mut s = Session::new(Problem::from_scenario(&sc).unwrap(), config).unwrap();
        s.run_to_end();
        s.result()
    };
    for seed in 1..=5 {
        let pure = run(seed, json!({"uniform_share": 0.0}));
        assert!(!pure.solved, "seed {seed}: the pure bridge test solved the zigzag");
        let hybrid = run(seed, json!({}));
        assert!(hybrid.solved, "seed {seed}: the hybrid bridge test did not solve it");
        assert_eq!(common::path_problem(&sc, &hybrid.path), None, "seed {seed}");
    }
}

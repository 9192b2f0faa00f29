//! Time limits and bounded batches, tested on a simulated clock (`planarium::clock::simulate`):
//! each unit of work the core counts (a state, a clearance, a sight line, plus one per 16 exact
//! tests among obstacles) moves the clock on by a cost the test sets, each read of the clock by
//! [`READ`]. The guarantees are statements about the mechanism (how often the clock is read, what
//! happens once a deadline has passed), so they are asserted exactly, for units far cheaper and far
//! dearer than this machine's, and hold however busy the machine is. One test, the CLI's, runs on
//! the real clock with a wide margin.

use super::session;
use planarium::clock::{self, Simulation};
use planarium::motion::MotionValidator;
use planarium::planners::smoothing;
use planarium::problem::Problem;
use planarium::rng::Rng;
use planarium::run::{Session, SUSPEND_AFTER};
use planarium::scenario::Scenario;
use planarium::space_info::{Deadline, SLOW_LOOK_MS};
use serde_json::{json, Value};
use std::time::{Duration, Instant};

/// What a unit of work costs in the simulations: cheap (the clock is read 256 units apart, and
/// a batch runs many iterations), dearer than [`SLOW_LOOK_MS`] (the clock is read after every
/// unit), and one unit longer than a whole batch's budget.
const UNIT_COSTS: [Duration; 5] = [
    Duration::from_nanos(20),
    Duration::from_micros(1),
    Duration::from_micros(50),
    Duration::from_millis(2),
    Duration::from_millis(30),
];

/// What one read of the clock costs in the simulations.
const READ: Duration = Duration::from_nanos(50);

/// The page's worker asks for batches of this many milliseconds.
const BATCH_MS: f64 = 12.0;

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

/// How late the clock can be looked at after a moment: the core reads it between calls that count
/// units of work, never inside one, at most about [`SLOW_LOOK_MS`] apart unless one call's units
/// take longer (see `space_info::CLOCK_EVERY`). `largest`: the most units one call counted.
fn look_gap_ms(largest: u64, unit: Duration) -> f64 {
    SLOW_LOOK_MS + largest as f64 * ms(unit)
}

/// How late a batch or a run can end after the moment it must stop: the look that sees it comes
/// at most [`look_gap_ms`] late, and winding the iteration down (every further question refused)
/// counts at most one more call (the work the iteration was doing).
fn stop_delay_ms(largest: u64, unit: Duration) -> f64 {
    look_gap_ms(largest, unit) + largest as f64 * ms(unit)
}

/// Past that, the reads' own cost and winding an iteration down (refused answers) may add this.
const SLACK_MS: f64 = 0.2;

/// A unit map whose every state check near the bottom edge is slow, even through the broad phase:
/// `n` discs centred at (1.5, 1.5) with radii from 1.5 down to 1.4996, whose boxes all reach below
/// y = 0.0005 and so hold the line from the start (0, 0.0005) to the goal (1, 0.0005), which the
/// discs themselves leave free. Each state on it is tested exactly against every disc.
pub fn cluttered(n: usize, resolution: f64) -> Value {
    let obstacles: Vec<Value> =
        (0..n).map(|i| json!({"circle": [1.5, 1.5, 1.5 - 0.0004 * i as f64 / n as f64]})).collect();
    json!({"bounds": [0, 0, 1, 1], "obstacles": obstacles, "robot": {"kind": "point"},
           "start": [0.0, 0.0005], "goal": [1.0, 0.0005], "resolution": resolution})
}

/// [`cluttered`] for a small square body, whose motions are certified by clearances.
fn cluttered_body(n: usize, resolution: f64) -> Value {
    let mut body = cluttered(n, resolution);
    body["robot"] = json!({"kind": "rigid", "footprint": [[-0.0001, -0.0001], [0.0001, -0.0001], [0.0001, 0.0001], [-0.0001, 0.0001]]});
    body["start"] = json!([0.0002, 0.0005, 0.0]);
    body["goal"] = json!([0.9998, 0.0005, 0.0]);
    body
}

/// What a run in bounded batches did.
#[derive(Debug, Default)]
struct Batches {
    batches: usize,
    longest_ms: f64,
    /// The largest of (a batch's time − its bound); negative while every batch kept to its bound.
    worst_ms: f64,
    /// Batches that advanced the run: did new work (answers computed, not replayed), or
    /// completed an iteration.
    advanced: usize,
}

/// Run `s` in [`BATCH_MS`] batches (as the page's worker does) on the simulated clock `sim`, at
/// most `max` batches; every batch must end within its bound: [`SUSPEND_AFTER`] × its budget, then
/// at most one look's delay ([`look_gap_ms`]) and [`SLACK_MS`].
fn in_batches(what: &str, s: &mut Session, sim: &Simulation, unit: Duration, max: usize) -> Batches {
    let mut b = Batches { worst_ms: f64::NEG_INFINITY, ..Batches::default() };
    while b.batches < max && !s.status().is_finished() {
        sim.take_largest();
        sim.take_first_new();
        sim.take_first_iteration();
        let t = sim.elapsed();
        let (units, reads, suspended, iterations) = (sim.units(), sim.reads(), s.suspensions(), s.stats().iterations);
        s.step(u64::MAX, BATCH_MS);
        s.drain_events();
        let took = ms(sim.elapsed() - t);
        let largest = sim.take_largest();
        // Suspended once past twice its budget, but only once it has done new work (answers
        // computed, not replayed), so every batch advances its run; a batch that does none (it
        // replays a suspended iteration, or does work the journal does not keep: a roadmap's graph
        // search, the hexagonal decomposition) ends after an iteration.
        let first_new = sim.take_first_new();
        let first_iteration = sim.take_first_iteration();
        let from = first_new.or(first_iteration).map_or(0.0, |at| ms(at.saturating_sub(t)));
        let bound = (SUSPEND_AFTER * BATCH_MS).max(from) + stop_delay_ms(largest, unit) + SLACK_MS;
        b.advanced += usize::from(first_new.is_some() || first_iteration.is_some());
        assert!(
            took <= bound,
            "{what}, units of {unit:?}: batch {} took {took:.3} ms (simulated); the bound is {bound:.3} ms (the largest call counted {largest} units; {} units, {} reads, {} suspended, {} iterations)",
            b.batches, sim.units() - units, sim.reads() - reads, s.suspensions() - suspended, s.stats().iterations as i64 - iterations as i64
        );
        b.batches += 1;
        b.longest_ms = b.longest_ms.max(took);
        b.worst_ms = b.worst_ms.max(took - bound);
    }
    b
}

#[test]
fn a_bounded_batch_keeps_to_its_bound_whatever_one_iteration_costs() {
    // One iteration is a motion checked at 66,667 states, each against 20,000 discs (1,251 units a
    // state), or smoothing's shortcuts of that size: however dear a unit, the batch is suspended
    // within one look of twice its budget, every batch does new work, and with the cheapest
    // units the first iteration (1.7 s of work) completes across some 70 suspended batches.
    let v = cluttered(20_000, 1.5e-5);
    for (k, unit) in UNIT_COSTS.into_iter().enumerate() {
        let sim = clock::simulate(unit, READ);
        for (planner, params) in [
            ("rrt", json!({"range": 2.0, "goal_bias": 1.0, "time_limit": 3600})),
            ("rrt-connect", json!({"range": 2.0, "time_limit": 3600})),
            ("rrt-star", json!({"range": 2.0, "goal_bias": 0.5, "time_limit": 3600})),
        ] {
            let mut s = session(&v, planner, params, 1).unwrap();
            // RRT's first iteration is the one motion to the goal (some 70 batches of the cheapest
            // units); the others' first iterations are longer.
            let cheap_rrt = k == 0 && planner == "rrt";
            let max = if cheap_rrt { 150 } else { 12 };
            let mut b = Batches { worst_ms: f64::NEG_INFINITY, ..Batches::default() };
            while b.batches < max && !s.status().is_finished() && !(cheap_rrt && s.stats().iterations > 0) {
                let more = in_batches(planner, &mut s, &sim, unit, 1);
                b.batches += more.batches;
                b.advanced += more.advanced;
                b.longest_ms = b.longest_ms.max(more.longest_ms);
                b.worst_ms = b.worst_ms.max(more.worst_ms);
            }
            let st = s.stats();
            eprintln!(
                "{planner}, units of {unit:?}: {} batches, the longest {:.3} ms (simulated), {:.3} ms within its bound; {} suspended, {} iterations",
                b.batches, b.longest_ms, -b.worst_ms, s.suspensions(), st.iterations
            );
            assert!(s.suspensions() > 0, "{planner}: no batch was suspended, so this input does not test it");
            assert_eq!(b.advanced, b.batches, "{planner}: every batch advances the run");
            if cheap_rrt {
                assert!(st.iterations > 0, "{planner}: the first iteration did not complete in {max} batches");
            }
        }
    }
}

/// `n` small blocks in a grid filling the right half of a 2 × 1 map.
fn right_half_blocks(n: usize) -> Vec<Value> {
    let side = (n as f64).sqrt().ceil() as usize;
    let cell = 1.0 / side as f64;
    let mut o = Vec::with_capacity(n);
    'grid: for i in 0..side {
        for j in 0..side {
            if o.len() == n {
                break 'grid;
            }
            let (x, y) = (1.0 + i as f64 * cell, j as f64 * cell);
            o.push(json!({"rect": [x + 0.3 * cell, y + 0.3 * cell, x + 0.7 * cell, y + 0.7 * cell]}));
        }
    }
    o
}

#[test]
fn at_the_limits_every_planners_batches_keep_to_their_bound() {
    // 100,000 obstacles (the cap) with the heaviest robot and task of each kind: a 64-link arm
    // (the cap) checked at 0.01 rad, inspection of 10,000 points (the cap), a point robot at a
    // resolution close to the finest allowed, the potential field's heat map, the hexagonal
    // decomposition, the roadmaps and the visibility graph. Each runs in 12 ms batches, as the
    // worker asks, with events recorded (the potential field draws its heat map).
    let pi = std::f64::consts::PI;
    let mut arm_start = vec![0.0; 64];
    arm_start[0] = pi;
    let limits: Vec<Value> = (0..64).map(|_| json!([-pi, pi])).collect();
    let blocks = right_half_blocks(100_000);
    let arm = json!({"bounds": [0, 0, 2, 1], "obstacles": blocks, "robot": {"kind": "arm", "base": [1.0, 0.5], "links": vec![0.9 / 64.0; 64], "limits": limits, "self_collision": true}, "start": arm_start, "goal": arm_start, "resolution": 0.01});
    let points: Vec<Value> =
        (0..10_000).map(|i| json!([0.05 + 0.009 * (i % 100) as f64, 0.05 + 0.009 * (i / 100) as f64])).collect();
    let inspect = json!({"bounds": [0, 0, 2, 1], "obstacles": blocks, "robot": {"kind": "rigid", "footprint": [[-0.01, -0.01], [0.01, -0.01], [0.01, 0.01], [-0.01, 0.01]]}, "start": [0.5, 0.5, 0.0], "resolution": 0.001, "inspection": {"points": points, "fov": 1.0, "range": 0.5, "coverage": 0.9}});
    let point = json!({"bounds": [0, 0, 2, 1], "obstacles": blocks, "robot": {"kind": "point"}, "start": [0.5, 0.5], "goal": [1.999, 0.999], "resolution": 3e-5});
    let cases = [
        (&arm, "rrt-connect", json!({})),
        (&arm, "rrt-star", json!({})),
        (&inspect, "inspection", json!({})),
        (&point, "rrt-connect", json!({"range": 3})),
        (&point, "hex-potential", json!({})),
        (&point, "potential-field", json!({})),
        (&arm, "prm", json!({})),
        (&point, "lazy-prm", json!({})),
        (&point, "prm-star", json!({"connect": "radius"})),
        (&point, "visibility-graph", json!({})),
    ];
    let scenarios: Vec<(&Value, Scenario)> =
        [&arm, &inspect, &point].into_iter().map(|v| (v, Scenario::from_value(v).unwrap())).collect();
    for unit in UNIT_COSTS[1..].iter().copied() {
        for (v, planner, params) in &cases {
            let robot = v["robot"]["kind"].as_str().unwrap();
            let what = format!("{robot} {planner}");
            let sc = &scenarios.iter().find(|(w, _)| std::ptr::eq(*w, *v)).unwrap().1;
            // Set up on the real clock (set-up is not a batch: with units of 30 ms, growing the
            // visibility graph's 400,000 corners would outlast any time limit), then batches on
            // the simulated one, with no time limit within the batches tested.
            let made = Instant::now();
            let problem = Problem::from_scenario(sc).unwrap();
            let mut params = params.clone();
            params["time_limit"] = json!(3600);
            let mut s = super::session_on(problem, planner, params, 1).unwrap();
            s.set_record_events(true);
            let sim = clock::simulate(unit, READ);
            let real = Instant::now();
            // The hexagonal decomposition's own work between questions is counted (its exact
            // distances) but far cheaper in units than in this machine's time: fewer batches.
            let b = in_batches(&what, &mut s, &sim, unit, if *planner == "hex-potential" { 3 } else { 16 });
            eprintln!(
                "{what}, units of {unit:?}: {} batches, the longest {:.3} ms (simulated), {:.3} ms within its bound; {} suspended, {} iterations, {}; set up in {:.0} ms, batches in {:.0} ms (real)",
                b.batches,
                b.longest_ms,
                -b.worst_ms,
                s.suspensions(),
                s.stats().iterations,
                s.status().name(),
                (real - made).as_secs_f64() * 1000.0,
                real.elapsed().as_secs_f64() * 1000.0,
            );
        }
    }
}

#[test]
fn the_time_limit_holds_inside_one_long_motion_check() {
    // 20,000 obstacles whose boxes all hold each state (so each state check tests them all) and the
    // finest resolution allowed: the free motion along the bottom edge to the goal is 66,667
    // states of 1,251 units each. The deadline is looked at inside the check, for a point (an exact
    // sweep and states) and for a body (certified by clearances: a different loop).
    let v = cluttered(20_000, 1.5e-5);
    let body = cluttered_body(20_000, 1.5e-5);
    for unit in UNIT_COSTS {
        let sim = clock::simulate(unit, READ);
        for (v, planner, params) in [
            (&v, "rrt", json!({"range": 2.0, "goal_bias": 1.0, "time_limit": 0.3})),
            (&v, "rrt-connect", json!({"range": 2.0, "time_limit": 0.3})),
            (&v, "rrt-star", json!({"range": 2.0, "goal_bias": 0.5, "time_limit": 0.3})),
            (&body, "rrt", json!({"range": 2.0, "goal_bias": 1.0, "time_limit": 0.3})),
        ] {
            let what = format!("{} {planner}", v["robot"]["kind"]);
            let mut s = session(v, planner, params, 1).unwrap();
            sim.take_largest();
            let t = sim.elapsed();
            s.run_to_end();
            let took = ms(sim.elapsed() - t);
            let bound = 300.0 + stop_delay_ms(sim.take_largest(), unit) + SLACK_MS;
            let r = s.result();
            eprintln!(
                "{what}, units of {unit:?}: {} after {took:.3} ms (simulated; the bound {bound:.3} ms), {} checks",
                r.status, r.stats.checks
            );
            assert_eq!(r.status, "time_limit", "{what}");
            assert!(
                took <= bound,
                "{what}, units of {unit:?}: ran {took:.3} ms against a 300 ms limit (bound {bound:.3} ms)"
            );
            assert!(r.stats.time_ms <= bound, "{what}: the run's own time {} ms", r.stats.time_ms);
        }
    }
}

#[test]
fn the_time_limit_holds_in_smoothing() {
    // A path in the free strip along the bottom edge: every shortcut between its two segments is
    // free and about half a map long, so each one checks some 30,000 states against 20,000
    // obstacles. Smoothing stops at the deadline with a shorter, still valid path.
    let mut v = cluttered(20_000, 1.5e-5);
    v["goal"] = json!([1.0, 0.0005]);
    let sc = Scenario::from_value(&v).unwrap();
    let path = vec![vec![0.0, 0.0005], vec![0.5, 0.0015], vec![1.0, 0.0005]];
    let mut checked: Vec<Vec<Vec<f64>>> = Vec::new();
    for unit in UNIT_COSTS {
        let p = Problem::from_scenario(&sc).unwrap();
        let sim = clock::simulate(unit, READ);
        sim.take_largest();
        let t = sim.elapsed();
        p.si.set_deadline(Deadline::in_ms(100.0));
        let out = smoothing::shortcut(&p.si, &path, 10_000, &mut Rng::new(1));
        let took = ms(sim.elapsed() - t);
        let bound = 100.0 + stop_delay_ms(sim.take_largest(), unit) + SLACK_MS;
        eprintln!(
            "smoothing, units of {unit:?}: {} states after {took:.3} ms (simulated; the bound {bound:.3} ms)",
            out.len()
        );
        assert!(
            took <= bound,
            "units of {unit:?}: smoothing ran {took:.3} ms against a 100 ms deadline (bound {bound:.3} ms)"
        );
        assert!(p.si.interrupted());
        assert_eq!((out.first(), out.last()), (path.first(), path.last()));
        drop(sim);
        // Every motion kept was checked (each distinct one checked here once: seconds each).
        let mut scratch = [0.0; 2];
        p.si.set_deadline(Deadline::NONE);
        for w in out.windows(2) {
            if !checked.iter().any(|c| c == w) {
                assert!(p.si.check_motion(&w[0], &w[1], &mut scratch).is_ok(), "an unchecked motion was kept: {w:?}");
                checked.push(w.to_vec());
            }
        }
    }
}

/// The one test on the real clock: the CLI wires `--time-limit` to the session. Without a limit
/// this run is one motion checked at 66,667 states against 60,000 discs whose boxes all hold each
/// state: about a minute here (20,000 discs took 19.8 s). With `--time-limit 0.3` the whole process
/// (start, reading 60,000 obstacles, the run, the JSON) must end within 15 s: a wide margin for a
/// busy machine that still fails if the limit were not honoured.
#[test]
fn the_cli_honours_its_time_limit() {
    let dir = std::env::temp_dir().join(format!("planarium-limits-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let slow = dir.join("slow.json");
    std::fs::write(&slow, cluttered(60_000, 1.5e-5).to_string()).unwrap();
    let t = Instant::now();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_planarium"))
        .args(["plan", slow.to_str().unwrap(), "--planner", "rrt", "--goal-bias", "1", "--range", "2"])
        .args(["--time-limit", "0.3", "--json"])
        .output()
        .unwrap();
    let took = t.elapsed().as_secs_f64();
    std::fs::remove_dir_all(&dir).ok();
    let r: Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|_| panic!("{}", String::from_utf8_lossy(&out.stderr)));
    eprintln!(
        "CLI: {} after {took:.3} s (limit 0.3 s; the planner's own time {} ms; process start and file parse included)",
        r["status"], r["stats"]["time_ms"]
    );
    assert_eq!(r["status"], "time_limit");
    assert!(took < 15.0, "the CLI ran {took:.3} s against a 0.3 s limit (the unlimited run takes about a minute)");
}

//! The spatial arm on report 001's robot: the Puma 560's kinematics against the Robotics Library's
//! own placement of its links, the course's scene, and the collision query's cost (printed). The
//! independent checker's spatial arm (tests/common/spatial.rs) is checked here against rl's link
//! frames and known states (its GJK and its agreement with the product in tests/spatial_checker.rs),
//! then re-checks the course planner's paths at a quarter of `delta`.

mod common;

use common::last_free::kept_configurations;
use common::spatial::{self, lerp, random_state, spec, Arm, Pair};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::rng::Rng;
use planarium::robot::{Spatial, SpatialArmRobot, Verdict};
use planarium::run::{RunConfig, Session};
use planarium::scenario::{builtin, Scenario};
use serde_json::Value;

fn puma(id: &str) -> (Scenario, Problem) {
    let sc = builtin(id).unwrap();
    let p = Problem::from_scenario(&sc).unwrap();
    (sc, p)
}

/// rl's translations of the Puma's link frames at q = 0, x y z, from its display file
/// (`data/rl-puma560/rlsg/unimation-puma560.convex/unimation-puma560.wrl`); the scenarios turn the
/// world by Rz(90°), which takes (x, y, z) to (−y, x, z).
const RL_AT_ZERO: [[f64; 3]; 7] = [
    [0.0, 0.0, 0.0],
    [0.0, 0.0, 0.6604],
    [0.4318, 0.1291, 0.6604],
    [0.4115, 0.1291, 0.6604],
    [0.4115, 0.1291, 1.0935],
    [0.4115, 0.1291, 1.0935],
    [0.4115, 0.1291, 1.13475],
];

/// At q = 0 every link frame is where rl's display file (`data/rl-puma560/rlsg/
/// unimation-puma560.convex/unimation-puma560.wrl`) puts it, turned by the world's Rz(90°).
#[test]
fn puma_frames_at_zero_are_rls() {
    let (sc, _) = puma("puma-rbo-wall");
    let arm = SpatialArmRobot::from_spec(&sc.robot).unwrap();
    let s = arm.skeleton_points(&[0.0; 6]);
    for (k, p) in RL_AT_ZERO.iter().enumerate() {
        let want = [-p[1], p[0], p[2]];
        assert!(s[k].iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-9), "link{k}: {:?} against {want:?}", s[k]);
    }
}

#[test]
fn the_course_scene_start_and_goal() {
    let (sc, p) = puma("puma-rbo-wall");
    let arm = SpatialArmRobot::from_spec(&sc.robot).unwrap();
    let ws = p.si.workspace();
    assert_eq!(ws.solids.len(), 4);
    let goal = sc.goal.clone().unwrap();
    assert!(p.robot.is_valid(ws, &sc.start) && p.robot.is_valid(ws, &goal));
    // The tool centre point is in front of the wall at the start and behind it at the goal.
    let (a, b) = (arm.tool_point(&sc.start), arm.tool_point(&goal));
    assert!(a[0] < 0.81 && b[0] > 0.89, "{a:?} {b:?}");
    // Straight from start to goal, the arm hits the wall somewhere.
    let hits = (0..=100)
        .map(|k| {
            let t = k as f64 / 100.0;
            sc.start.iter().zip(&goal).map(|(x, y)| x + t * (y - x)).collect::<Vec<_>>()
        })
        .filter(|q| !p.robot.is_valid(ws, q))
        .count();
    assert!(hits > 0, "the straight motion must collide");
    let (_, p) = puma("puma-boxes");
    assert_eq!(p.si.workspace().solids.len(), 8);
}

/// A collision query's cost on the course's problem: uniform states within the limits (printed,
/// never asserted).
#[test]
fn query_cost_is_printed() {
    let (sc, p) = puma("puma-rbo-wall");
    let ws = p.si.workspace();
    let mut rng = planarium::rng::Rng::new(1);
    let states: Vec<Vec<f64>> =
        (0..20_000).map(|_| p.si.space.dims.iter().map(|d| rng.uniform(d.lo, d.hi)).collect()).collect();
    let t = std::time::Instant::now();
    let free = states.iter().filter(|q| p.robot.is_valid(ws, q)).count();
    let ns = t.elapsed().as_nanos() as f64 / states.len() as f64;
    eprintln!("{}: {free} of {} uniform states free; {ns:.0} ns a query", sc.name, states.len());
    assert!(free > 0 && free < states.len());
}

/// The tool's curve along a motion, a point per `delta` step as the 3-D view's trees take it
/// (evenly spread, both ends the tool's own points), is fine enough that no chord between two
/// neighbours stands for much of the sweep.
#[test]
fn the_tool_sweep_follows_the_connect() {
    let (sc, p) = puma("puma-rbo-wall");
    let goal = sc.goal.clone().unwrap();
    let d = p.si.distance(&sc.start, &goal);
    let steps = (d / sc.resolution).ceil() as usize;
    let mut delta = vec![0.0; sc.start.len()];
    p.si.space.difference(&sc.start, &goal, &mut delta);
    let sp = p.robot.spatial().unwrap();
    let pts = sp.tool_sweep(&sc.start, &delta, steps + 1);
    let near = |a: [f64; 3], b: [f64; 3]| (0..3).all(|k| (a[k] - b[k]).abs() < 1e-12);
    assert!(near(pts[0], sp.tool_point(&sc.start)));
    assert!(near(*pts.last().unwrap(), sp.tool_point(&goal)));
    // Neighbouring steps are close: the tool is at most 1.3 m from the base axis, so it moves at
    // most about 1.3 × 6 × δ... far less in practice; a chord would cut through the wall.
    let longest =
        pts.windows(2).map(|w| (0..3).map(|k| (w[1][k] - w[0][k]).powi(2)).sum::<f64>().sqrt()).fold(0.0, f64::max);
    assert!(longest < 0.05, "{longest}");
    // A planar robot has no tool to sweep.
    let n = Problem::from_scenario(&builtin("narrow").unwrap()).unwrap();
    assert!(n.robot.spatial().is_none());
}

/// The 3-D view's edges are drawn through the tool's sweep: its points, stepped by one rotation
/// per joint from the last, are where the arm's own kinematics puts the tool at the same states
/// (to 1e-12 m, over motions of up to 3 rad a joint and 2,000 points), both ends included.
#[test]
fn the_tool_sweep_is_the_tools_own_curve() {
    let (sc, p) = puma("puma-rbo-wall");
    let goal = sc.goal.clone().unwrap();
    let sp = p.robot.spatial().unwrap();
    let mid: Vec<f64> = sc.start.iter().zip(&goal).map(|(a, b)| a + 0.013 * (b - a)).collect();
    let far: Vec<f64> = sc.start.iter().enumerate().map(|(k, a)| a + if k % 2 == 0 { 3.0 } else { -2.5 }).collect();
    let mut q = vec![0.0; sc.start.len()];
    let mut delta = vec![0.0; sc.start.len()];
    for (a, b) in [(&sc.start, &goal), (&sc.start, &mid), (&goal, &sc.start), (&goal, &far)] {
        p.si.space.difference(a, b, &mut delta);
        for points in [1, 2, 3, 7, 32, 2000] {
            let sweep = sp.tool_sweep(a, &delta, points);
            assert_eq!(sweep.len(), points);
            for (j, s) in sweep.iter().enumerate() {
                let t = if points == 1 { 1.0 } else { j as f64 / (points - 1) as f64 };
                p.si.interpolate(a, b, t, &mut q);
                let want = sp.tool_point(&q);
                let off = (0..3).map(|k| (s[k] - want[k]).abs()).fold(0.0, f64::max);
                assert!(off < 1e-12, "{points} points, point {j}: {s:?} against {want:?}");
            }
        }
    }
    // A motion that does not move: its one place, as often as asked.
    delta.fill(0.0);
    let here = sp.tool_point(&goal);
    for s in sp.tool_sweep(&goal, &delta, 5) {
        assert!((0..3).all(|k| (s[k] - here[k]).abs() < 1e-12));
    }
}

/// The checker's kinematics (its own 4×4 matrices) puts the Puma's link frames where rl's display
/// file does at q = 0, agrees with the product's skeleton at random states, and puts the course's
/// tool in front of the wall at the start and behind it at the goal; the checker calls both
/// courses' start and goal free, a joint past its limit invalid, and the straight motion through
/// the wall blocked.
#[test]
fn the_checkers_kinematics_and_known_states() {
    let (sc, p) = puma("puma-rbo-wall");
    let arm = spec(&sc);
    let f = spatial::frames(arm, &[0.0; 6]);
    for (k, rl) in RL_AT_ZERO.iter().enumerate() {
        let o = spatial::apply(&f[k], [0.0; 3]);
        let want = [-rl[1], rl[0], rl[2]];
        assert!(o.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-9), "link{k}: {o:?} against {want:?}");
    }
    let product = SpatialArmRobot::from_spec(&sc.robot).unwrap();
    let mut rng = Rng::new(7);
    let mut worst: f64 = 0.0;
    for _ in 0..500 {
        let q = random_state(&sc, &mut rng);
        let f = spatial::frames(arm, &q);
        let mut mine: Vec<[f64; 3]> = f.iter().map(|m| spatial::apply(m, [0.0; 3])).collect();
        mine.push(spatial::tool_point(arm, &q));
        for (a, b) in mine.iter().zip(product.skeleton_points(&q)) {
            worst = (0..3).map(|k| (a[k] - b[k]).abs()).fold(worst, f64::max);
        }
    }
    eprintln!("link origins and tool point against the product's skeleton: at most {worst:.1e} m apart");
    assert!(worst < 1e-12, "{worst}");
    let goal = sc.goal.clone().unwrap();
    let (a, b) = (spatial::tool_point(arm, &sc.start), spatial::tool_point(arm, &goal));
    assert!(a[0] < 0.81 && b[0] > 0.89, "{a:?} {b:?}");
    for id in ["puma-rbo-wall", "puma-boxes"] {
        let sc = builtin(id).unwrap();
        assert_eq!(common::state_problem(&sc, &sc.start), None, "{id}");
        assert_eq!(common::state_problem(&sc, sc.goal.as_ref().unwrap()), None, "{id}");
    }
    let mut past = sc.start.clone();
    past[1] = 0.8;
    assert!(common::state_problem(&sc, &past).unwrap().contains("joint 1 outside"));
    let e = common::motion_problem(&sc, &sc.start, &goal).expect("the straight motion meets the wall");
    assert!(e.contains("meets obstacles3d["), "{e}");
    // Where the product first calls the straight motion blocked, the checker names the same
    // obstacle among those it sees met.
    let ws = p.si.workspace();
    let t = (0..=1000).map(|k| k as f64 / 1000.0).find(|t| !p.robot.is_valid(ws, &lerp(&sc.start, &goal, *t))).unwrap();
    let q = lerp(&sc.start, &goal, t);
    let Verdict::Collision(o) = p.robot.verdict(ws, &q) else { panic!("the wall, not the arm itself") };
    let checker = Arm::new(&sc).unwrap();
    let met = checker.contacts(&q, true);
    eprintln!(
        "straight motion, first blocked at t = {t}: the product says {:?}; the checker {:?}",
        p.robot.describe_collision(ws, &q),
        met.iter().map(|(c, _)| checker.describe(*c)).collect::<Vec<_>>()
    );
    assert!(met.iter().any(|(c, _)| matches!(c, Pair::Scene { obstacle, .. } if *obstacle == o)));
}

/// The scenario's own planner block (RRT-Connect, `connect: last-free`, its `epsilon`) run with
/// `seed`, events recorded.
fn course_run(sc: &Scenario, seed: u64) -> Session {
    let block = sc.planner.as_ref().unwrap();
    let spec = planners::find(&block.name).unwrap();
    let params = Params::from_json(spec, &Value::Object(block.params.clone())).unwrap();
    let config = RunConfig { planner: block.name.clone(), params, seed, record_events: true };
    let mut s = Session::new(Problem::from_scenario(sc).unwrap(), config).unwrap();
    s.run_to_end();
    s
}

/// A motion of a path met between two checked states: its index and length, the stretch met
/// (from the motion's first state, both in `delta`s), what meets what, the deepest overlap seen.
#[derive(Debug)]
struct Graze {
    motion: usize,
    deltas: f64,
    from: f64,
    to: f64,
    what: Vec<String>,
    depth: f64,
}

/// Every motion of `path` whose states every `step` (joint space, ends included) meet something by
/// the checker, the stretch met then looked at 64 times finer (its ends and its deepest overlap,
/// [`spatial::overlap`], exact at each state looked at).
fn grazes(checker: &Arm, delta: f64, path: &[Vec<f64>], step: f64) -> Vec<Graze> {
    let mut out = Vec::new();
    for (k, w) in path.windows(2).enumerate() {
        let len = w[0].iter().zip(&w[1]).map(|(x, y)| (y - x).powi(2)).sum::<f64>().sqrt();
        let n = ((len / step).ceil() as usize).max(1);
        let met: Vec<usize> = (0..=n)
            .filter(|i| !checker.contacts(&lerp(&w[0], &w[1], *i as f64 / n as f64), false).is_empty())
            .collect();
        let (Some(first), Some(last)) = (met.first(), met.last()) else { continue };
        let (i0, i1) = (first.saturating_sub(1), (last + 1).min(n));
        let (lo, hi, m) = (i0 as f64 / n as f64, i1 as f64 / n as f64, 64 * (i1 - i0).max(1));
        let mut g = Graze { motion: k, deltas: len / delta, from: f64::INFINITY, to: 0.0, what: vec![], depth: 0.0 };
        for i in 0..=m {
            let t = lo + (hi - lo) * i as f64 / m as f64;
            let q = lerp(&w[0], &w[1], t);
            for (c, _) in checker.contacts(&q, true) {
                g.from = g.from.min(t * g.deltas);
                g.to = g.to.max(t * g.deltas);
                g.depth = g.depth.max(checker.depth(&q, c));
                let d = checker.describe(c);
                if !g.what.contains(&d) {
                    g.what.push(d);
                }
            }
        }
        out.push(g);
    }
    out
}

/// One course run re-checked by the independent checker at a quarter of `delta`. Asserted: solved,
/// from the start to within `epsilon` of the goal; every configuration the method kept free; the
/// raw path and the smoothed path free all along (both certified by the product); and, on the
/// path the trees gave before it was certified (the method tests configurations `delta` apart,
/// so it may meet the wall between two of them), the motions the checker finds met between
/// steps are as many as the product repaired. Returns those motions (printed, with where, what
/// and how deep), the smoothed path's, and the numbers of motions.
fn examine(id: &str, seed: u64) -> (Vec<Graze>, Vec<Graze>, usize, usize) {
    let sc = builtin(id).unwrap();
    let what = format!("{id} seed {seed}");
    let t = std::time::Instant::now();
    let mut s = course_run(&sc, seed);
    let ms = t.elapsed().as_secs_f64() * 1e3;
    let r = s.result();
    assert!(r.solved, "{what}: {}", r.status);
    let path = s.problem().decode_path(&r.path);
    let smoothed = s.problem().decode_path(&r.smoothed);
    assert_eq!(path[0], sc.start, "{what}");
    let goal = sc.goal.as_ref().unwrap();
    assert!(path.last().unwrap().iter().zip(goal).all(|(a, b)| (a - b).abs() <= 1e-8), "{what}");
    let events = s.drain_events();
    let kept = kept_configurations(&s, &events);
    assert_eq!(kept.len() as u64, r.stats.free_checks - 2, "{what}: every free configuration is kept");
    let checker = Arm::new(&sc).unwrap();
    for q in s.problem().decode_path(&kept) {
        if let Some(e) = checker.problem(&q) {
            panic!("{what}: a kept configuration: {e}");
        }
    }
    if let Some(e) = common::path_problem(&sc, &smoothed) {
        panic!("{what}: smoothed path, at a quarter of the resolution: {e}");
    }
    // The raw path is certified between its configurations (`run::certify`): the checker agrees
    // at a quarter of the resolution. The path the trees gave, before that (its states that are
    // tree nodes), is re-checked for the motions that were repaired.
    if let Some(e) = common::path_problem(&sc, &path) {
        panic!("{what}: raw path, at a quarter of the resolution: {e}");
    }
    let kept_states = s.problem().decode_path(&kept);
    let trees: Vec<Vec<f64>> = path
        .iter()
        .filter(|q| {
            **q == sc.start || kept_states.contains(q) || q.iter().zip(goal).all(|(a, b)| (a - b).abs() <= 1e-8)
        })
        .cloned()
        .collect();
    let raw = grazes(&checker, sc.resolution, &trees, sc.resolution / 4.0);
    assert_eq!(r.stats.repaired, Some(raw.len() as u64), "{what}: the motions repaired are the motions that grazed");
    let smooth = grazes(&checker, sc.resolution, &smoothed, sc.resolution / 4.0);
    eprintln!(
        "{what}: {ms:.0} ms, {} nodes, {} kept configurations free; raw path: {} motions, {} met between steps; \
         smoothed: {} motions, {} met between steps",
        r.stats.nodes,
        kept.len(),
        trees.len() - 1,
        raw.len(),
        smoothed.len() - 1,
        smooth.len()
    );
    for g in raw.iter().map(|g| ("raw", g)).chain(smooth.iter().map(|g| ("smoothed", g))) {
        eprintln!(
            "  {what}, {} motion {} ({:.2} δ long): met from {:.3} δ to {:.3} δ along it, {:.2e} m deep at most: {}",
            g.0,
            g.1.motion,
            g.1.deltas,
            g.1.from,
            g.1.to,
            g.1.depth,
            g.1.what.join("; ")
        );
    }
    (raw, smooth, trees.len() - 1, smoothed.len() - 1)
}

/// The course's planner on both Puma scenarios, seeds 1–3 (a puma-rbo-wall run takes about 2 s,
/// its re-check about 5 s): see [`examine`] for what is asserted. The re-check is shown not to be
/// vacuous on the trees' path before certification: puma-rbo-wall seed 2's motion 54 (27 steps
/// long) has link4 meet the block-left between its 20th and 21st steps, about 0.5 mm deep.
#[test]
fn course_paths_pass_the_independent_checker() {
    for id in ["puma-rbo-wall", "puma-boxes"] {
        for seed in 1..=3 {
            let (raw, _, _, _) = examine(id, seed);
            if (id, seed) == ("puma-rbo-wall", 2) {
                assert!(
                    raw.iter().any(|g| g.motion == 54
                        && g.what == ["link4 meets obstacles3d[1] (block-left)"]
                        && g.from > 20.0
                        && g.to < 21.0),
                    "the graze of seed 2's raw motion 54 is not found (if the run changed, re-measure: \
                     raw_path_grazes_over_seeds_1_to_20): {raw:?}"
                );
            }
        }
    }
}

/// The measurement behind the test above, seeds 1–20 (run by hand:
/// `cargo test --release --test spatial_arm -- --ignored --nocapture`), with what [`examine`]
/// asserts on every run: every graze of the trees' paths printed, each repaired. It
/// printed, on puma-rbo-wall, 4 of 1,660 trees' path motions met between steps (seed 2 motion 54, link4
/// and the block-left, 5.1e-4 m deep; seed 10 motion 99, link6 and the lintel, 6.0e-4 m; seed 16
/// motion 85, link4 and the lintel, 2.4e-4 m; seed 19 motion 10, one step long, link6's bar and
/// the lintel over 0.08–0.93 of it, 1.2e-3 m), none of the 130 smoothed motions; on puma-boxes
/// none of 81 raw and 20 smoothed motions.
#[test]
#[ignore]
fn raw_path_grazes_over_seeds_1_to_20() {
    for id in ["puma-rbo-wall", "puma-boxes"] {
        let (mut raw, mut smooth, mut motions, mut smoothed) = (0, 0, 0, 0);
        for seed in 1..=20 {
            let (r, s, m, n) = examine(id, seed);
            (raw, smooth, motions, smoothed) = (raw + r.len(), smooth + s.len(), motions + m, smoothed + n);
        }
        eprintln!("{id}, seeds 1-20: {raw} of {motions} raw motions and {smooth} of {smoothed} smoothed motions meet between steps");
    }
}

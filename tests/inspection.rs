//! The inspection planner (report 004, the Technion course's inspection RRT): its paths are valid
//! (re-checked by `common`'s independent checker) and see what they must, by a visibility
//! computation written here apart from the crate's: its own forward kinematics, its own
//! segment/polygon tests, states at most half the motion resolution (0.025 rad on the Technion map)
//! apart. Also the sensor rule by hand, determinism, events, a point robot, and smoothing that keeps
//! what a path sees.

mod common;

use planarium::events::{EventKind, STRIDE};
use planarium::geometry::SensorPose;
use planarium::math::Vec2;
use planarium::planners::{self, inspection, InspectionTask, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::{builtin, RobotSpec, Scenario};
use serde_json::{json, Value};
use std::f64::consts::PI;

use common::{cross, dist_point_segment, obstacle_polygon, P};

// ---- an independent visibility model ---------------------------------------------------------

/// Strictly inside: the common checker's winding number, the boundary (within 1e-9) excluded.
fn strictly_inside(poly: &[P], p: P) -> bool {
    let n = poly.len();
    !(0..n).any(|i| dist_point_segment(p, poly[i], poly[(i + 1) % n]) <= 1e-9) && common::in_polygon(poly, p)
}

/// Whether the sight line a → b passes through the polygon's interior: cut it where it meets the
/// boundary (parametric intersections; collinear overlaps cut at the edge's ends) and test the
/// middle of every piece.
fn crosses_interior(poly: &[P], a: P, b: P) -> bool {
    let r = (b.0 - a.0, b.1 - a.1);
    let l2 = r.0 * r.0 + r.1 * r.1;
    let mut ts = vec![0.0, 1.0];
    let n = poly.len();
    for i in 0..n {
        let (c, d) = (poly[i], poly[(i + 1) % n]);
        let s = (d.0 - c.0, d.1 - c.1);
        let den = r.0 * s.1 - r.1 * s.0;
        if den.abs() <= 1e-12 * (l2.sqrt() * (s.0 * s.0 + s.1 * s.1).sqrt()) {
            if cross(a, b, c).abs() <= 1e-9 * l2.sqrt().max(1.0) {
                for p in [c, d] {
                    ts.push((((p.0 - a.0) * r.0 + (p.1 - a.1) * r.1) / l2).clamp(0.0, 1.0));
                }
            }
            continue;
        }
        let t = ((c.0 - a.0) * s.1 - (c.1 - a.1) * s.0) / den;
        let u = ((c.0 - a.0) * r.1 - (c.1 - a.1) * r.0) / den;
        if (-1e-12..=1.0 + 1e-12).contains(&t) && (-1e-12..=1.0 + 1e-12).contains(&u) {
            ts.push(t.clamp(0.0, 1.0));
        }
    }
    ts.sort_by(f64::total_cmp);
    ts.windows(2).any(|w| {
        w[1] - w[0] > 1e-12 && strictly_inside(poly, (a.0 + 0.5 * (w[0] + w[1]) * r.0, a.1 + 0.5 * (w[0] + w[1]) * r.1))
    })
}

fn polygons(sc: &Scenario) -> Vec<Vec<P>> {
    sc.obstacles
        .iter()
        .map(|o| obstacle_polygon(o).unwrap_or_else(|| panic!("the test's visibility model has no {o:?}")))
        .collect()
}

/// The sensor at `q`: an arm's end effector and the sum of its joint angles; a point, all round.
fn sensor(sc: &Scenario, q: &[f64]) -> (P, Option<f64>) {
    match &sc.robot {
        RobotSpec::Arm { base, links, .. } => {
            let (mut x, mut y, mut th) = (base[0], base[1], 0.0);
            for (l, a) in links.iter().zip(q) {
                th += a;
                x += l * th.cos();
                y += l * th.sin();
            }
            ((x, y), Some(th))
        }
        RobotSpec::Point => ((q[0], q[1]), None),
        other => panic!("the test's visibility model has no {} robot", other.kind()),
    }
}

fn sees(sc: &Scenario, polys: &[Vec<P>], q: &[f64], p: P) -> bool {
    let insp = sc.inspection.as_ref().unwrap();
    let (at, heading) = sensor(sc, q);
    let (dx, dy) = (p.0 - at.0, p.1 - at.1);
    if (dx * dx + dy * dy).sqrt() > insp.range {
        return false;
    }
    if let Some(h) = heading {
        let off = ((dy.atan2(dx) - h + PI).rem_euclid(2.0 * PI) - PI).abs();
        if off > insp.fov / 2.0 {
            return false;
        }
    }
    !polys.iter().any(|poly| crosses_interior(poly, at, p))
}

fn angle_diff(a: f64, b: f64) -> f64 {
    (b - a + PI).rem_euclid(2.0 * PI) - PI
}

/// The points a path sees, states at most half the scenario's resolution apart.
fn seen_by_path(sc: &Scenario, path: &[Vec<f64>]) -> Vec<bool> {
    let polys = polygons(sc);
    let pts: Vec<P> = sc.inspection.as_ref().unwrap().points.iter().map(|p| (p[0], p[1])).collect();
    let arm = matches!(sc.robot, RobotSpec::Arm { .. });
    let mut seen = vec![false; pts.len()];
    let mut look = |q: &[f64]| {
        for (j, p) in pts.iter().enumerate() {
            if !seen[j] && sees(sc, &polys, q, *p) {
                seen[j] = true;
            }
        }
    };
    look(&path[0]);
    for w in path.windows(2) {
        let diff: Vec<f64> =
            w[0].iter().zip(&w[1]).map(|(a, b)| if arm { angle_diff(*a, *b) } else { b - a }).collect();
        let d = diff.iter().map(|x| x * x).sum::<f64>().sqrt();
        let n = 2 * ((d / sc.resolution).ceil() as usize).max(1);
        for i in 1..=n {
            let t = i as f64 / n as f64;
            let q: Vec<f64> = w[0].iter().zip(&diff).map(|(a, x)| a + t * x).collect();
            look(&q);
        }
    }
    seen
}

fn coverage(sc: &Scenario, path: &[Vec<f64>]) -> f64 {
    let seen = seen_by_path(sc, path);
    seen.iter().filter(|s| **s).count() as f64 / seen.len() as f64
}

/// Why the inspection path is not valid (`common`'s checker, its goal being the path's end).
fn path_problem(sc: &Scenario, path: &[Vec<f64>]) -> Option<String> {
    let mut sc = sc.clone();
    sc.goal = Some(path.last()?.clone());
    sc.goal_tolerance = 0.0;
    if path.len() == 1 {
        return common::state_problem(&sc, &path[0]);
    }
    common::path_problem(&sc, path)
}

// ---- runs ---------------------------------------------------------------------------------------

fn session(sc: &Scenario, params: Value, seed: u64, events: bool) -> Session {
    let spec = planners::find("inspection").unwrap();
    let params = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    Session::new(problem, RunConfig { planner: "inspection".into(), params, seed, record_events: events }).unwrap()
}

fn run(sc: &Scenario, params: Value, seed: u64) -> (PlanResult, Vec<f64>) {
    let mut s = session(sc, params, seed, true);
    s.run_to_end();
    (s.result(), s.drain_events())
}

fn task(sc: &Scenario) -> InspectionTask {
    let i = sc.inspection.as_ref().unwrap();
    InspectionTask {
        points: i.points.iter().map(|p| Vec2::new(p[0], p[1])).collect(),
        fov: i.fov,
        range: i.range,
        coverage: i.coverage,
        at_vertices: i.at_vertices(),
        touch_hides: i.touch_hides,
    }
}

/// Solved, valid, and seeing at least `target` by the independent model and by the crate's.
fn check_solution(sc: &Scenario, r: &PlanResult, target: f64, what: &str) {
    assert!(r.solved, "{what}: {}", r.status);
    if let Some(e) = path_problem(sc, &r.path) {
        panic!("{what}: {e}");
    }
    let c = coverage(sc, &r.path);
    assert!(c >= target, "{what}: the path sees {c}, below {target}");
    let problem = Problem::from_scenario(sc).unwrap();
    let own = inspection::path_coverage(&problem.si, &task(sc), &r.path);
    assert!(own >= target, "{what}: path_coverage {own}, below {target}");
    if matches!(sc.robot, RobotSpec::Arm { .. }) {
        // The cost: the sum of joint-space distances.
        let cost: f64 = r
            .path
            .windows(2)
            .map(|w| w[0].iter().zip(&w[1]).map(|(a, b)| angle_diff(*a, *b).powi(2)).sum::<f64>().sqrt())
            .sum();
        assert!((r.stats.cost.unwrap() - cost).abs() < 1e-9, "{what}: cost {:?} vs {cost}", r.stats.cost);
    }
}

/// The events of kind `k` as records.
fn events_of(ev: &[f64], k: EventKind) -> Vec<&[f64]> {
    ev.chunks(STRIDE).filter(|r| r[0] == k as u8 as f64).collect()
}

/// Coverage events grow, end at the target, and agree with the points seen; each point is
/// announced once; the run ends with `Solved`.
fn check_events(sc: &Scenario, ev: &[f64], target: f64, what: &str) {
    let n = sc.inspection.as_ref().unwrap().points.len();
    let cov = events_of(ev, EventKind::Coverage);
    assert!(!cov.is_empty(), "{what}: no coverage event");
    for w in cov.windows(2) {
        assert!(w[1][6] > w[0][6] && w[1][7] > w[0][7] && w[1][3] >= w[0][3], "{what}: coverage events must grow");
    }
    let last = cov.last().unwrap();
    assert!(last[6] >= target && (last[6] - last[7] / n as f64).abs() < 1e-12, "{what}: last coverage event {last:?}");
    let seen = events_of(ev, EventKind::PointSeen);
    let mut ids: Vec<i64> = seen.iter().map(|r| r[2] as i64).collect();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), seen.len(), "{what}: a point announced twice");
    assert!(ids.len() as f64 >= last[7], "{what}: fewer points announced than the best branch sees");
    for r in &seen {
        let p = sc.inspection.as_ref().unwrap().points[r[2] as usize];
        assert_eq!((r[4], r[5]), (p[0], p[1]), "{what}: PointSeen at the point");
    }
    let kinds: Vec<f64> = ev.chunks(STRIDE).map(|r| r[0]).collect();
    assert_eq!(*kinds.last().unwrap(), EventKind::Solved as u8 as f64, "{what}: ends with Solved");
    assert!(!events_of(ev, EventKind::NodeAdded).is_empty());
}

// ---- tests --------------------------------------------------------------------------------------

#[test]
fn the_checker_rejects_bad_paths() {
    common::self_test();
    // The test's own visibility model, on the Technion room (walls 80..220 around 100..200, the
    // opening x in 120..180 at the bottom).
    let sc = builtin("technion-ip").unwrap();
    let polys = polygons(&sc);
    assert!(crosses_interior(&polys[0], (110.0, 60.0), (105.0, 105.0)));
    assert!(!crosses_interior(&polys[0], (110.0, 60.0), (130.0, 100.0)), "grazing the vertex (120, 80)");
    assert!(!crosses_interior(&polys[0], (60.0, 80.0), (100.0, 80.0)), "along an edge");
    assert!(!crosses_interior(&polys[0], (150.0, 140.0), (145.0, 195.0)));
    assert!(crosses_interior(&polys[0], (150.0, 140.0), (150.0, 210.0)), "into the wall");
}

#[test]
fn the_sensor_by_hand() {
    let sc = builtin("technion-ip").unwrap();
    let p = Problem::from_scenario(&sc).unwrap();
    let si = &p.si;
    let (fov, range) = (PI / 3.0, 60.0);
    let v = Vec2::new;
    let up = Some(PI / 2.0);
    // The arm's sensor: the end effector, heading the sum of the joint angles. Links 80 along x,
    // 70 up, 40 along x, 40 up: the end effector at (120, 110), looking up.
    let s = si.sensor().unwrap().pose(&[0.0, PI / 2.0, -PI / 2.0, PI / 2.0]);
    assert!((s.at.x - 120.0).abs() < 1e-9 && (s.at.y - 110.0).abs() < 1e-9, "{s:?}");
    assert!((s.heading.unwrap() - PI / 2.0).abs() < 1e-12);
    let s = si.sensor().unwrap().pose(&sc.start);
    assert!((s.heading.unwrap() - (0.78 - 0.78)).abs() < 1e-12);

    // In the room, looking up: the top row's points 55 to 57 away, 5° and 15° off the heading.
    let inside = SensorPose { at: v(150.0, 140.0), heading: up };
    assert!(si.sees(&inside, v(145.0, 195.0), fov, range));
    assert!(si.sees(&inside, v(135.0, 195.0), fov, range));
    // 50 away but 37° off the heading: outside the field of view; seen when looking its way.
    assert!(!si.sees(&inside, v(120.0, 180.0), fov, range));
    assert!(si.sees(
        &SensorPose { at: v(150.0, 140.0), heading: Some(40f64.atan2(-30.0)) },
        v(120.0, 180.0),
        fov,
        range
    ));
    assert!(!si.sees(&inside, v(195.0, 145.0), fov, range), "84° off");
    assert!(si.sees(&SensorPose { at: v(150.0, 140.0), heading: Some(0.0) }, v(195.0, 145.0), fov, range));
    // Out of range: 65 away, straight ahead.
    assert!(!si.sees(&SensorPose { at: v(150.0, 130.0), heading: up }, v(150.0, 195.0), fov, range));
    // Exactly 60 away: the range is inclusive.
    assert!(si.sees(&SensorPose { at: v(150.0, 135.0), heading: up }, v(150.0, 195.0), fov, range));
    // Below the room, the point (105, 105) is 45 away and 6° off, but behind the wall.
    let below = SensorPose { at: v(110.0, 60.0), heading: up };
    assert!(below.in_view(v(105.0, 105.0), fov, range));
    assert!(!si.sees(&below, v(105.0, 105.0), fov, range));
    // A sight line that only touches the wall does not block (the documented rule): through the
    // vertex (120, 80) into the opening, and along the wall's bottom edge to its boundary.
    let diagonal = SensorPose { at: v(110.0, 60.0), heading: Some(2f64.atan2(1.0)) };
    assert!(si.sees(&diagonal, v(130.0, 100.0), fov, range));
    assert!(si.sees(&SensorPose { at: v(60.0, 80.0), heading: Some(0.0) }, v(100.0, 80.0), fov, range));
    // Past the touching point, into the wall: blocked.
    assert!(!si.sees(&SensorPose { at: v(60.0, 80.0), heading: Some(0.0) }, v(100.0, 81.0), fov, range));
    // A point robot's sensor sees all around.
    let pt = point_scenario();
    let pp = Problem::from_scenario(&pt).unwrap();
    let s = pp.si.sensor().unwrap().pose(&[0.1, 0.2]);
    assert_eq!(s, SensorPose { at: v(0.1, 0.2), heading: None });
    assert!(pp.si.sees(&s, v(0.1, 0.1), fov, 0.15));
    assert!(!pp.si.sees(&s, v(0.1, 0.2 + 0.16), fov, 0.15));
}

#[test]
fn technion_paths_are_valid_and_see_enough() {
    let sc = builtin("technion-ip").unwrap();
    // 0: the scenario's target (0.5). Each run takes milliseconds to a second natively.
    for (coverage, seeds) in [(0.0, 1..=5), (0.75, 1..=10), (1.0, 1..=2)] {
        let target = if coverage > 0.0 { coverage } else { sc.inspection.as_ref().unwrap().coverage };
        for seed in seeds {
            let what = format!("technion-ip coverage {target} seed {seed}");
            let (r, ev) = run(&sc, json!({"coverage": coverage, "time_limit": 60}), seed);
            check_solution(&sc, &r, target, &what);
            check_events(&sc, &ev, target, &what);
        }
    }
}

#[test]
fn every_tree_edge_is_a_valid_motion() {
    use planarium::motion::MotionValidator;
    let sc = builtin("technion-ip").unwrap();
    let mut s = session(&sc, json!({"coverage": 0.75}), 3, false);
    s.run_to_end();
    let si = &s.problem().si;
    let mut scratch = vec![0.0; si.dims()];
    let data = s.planner_data();
    assert_eq!(data.trees.len(), 1);
    for (e, (a, b)) in data.trees[0].edges().enumerate() {
        assert!(si.check_motion(a, b, &mut scratch).is_ok(), "edge {e}");
        if e % 5 == 0 {
            if let Some(err) = common::motion_problem(&sc, a, b) {
                panic!("edge {e}: {err}");
            }
        }
    }
}

#[test]
fn variants_solve_too() {
    let sc = builtin("technion-ip").unwrap();
    for params in
        [json!({"k": 0}), json!({"focus": 0.0}), json!({"k": 10, "focus": 1.0}), json!({"sampler": "gaussian"})]
    {
        let (r, _) = run(&sc, params.clone(), 5);
        check_solution(&sc, &r, 0.5, &format!("technion-ip {params}"));
    }
}

#[test]
fn the_same_seed_gives_the_same_run() {
    let sc = builtin("technion-ip").unwrap();
    let (a, ea) = run(&sc, json!({"coverage": 0.75}), 11);
    let (b, eb) = run(&sc, json!({"coverage": 0.75}), 11);
    assert_eq!(a.path, b.path);
    assert_eq!(a.smoothed, b.smoothed);
    assert_eq!(
        (a.stats.iterations, a.stats.nodes, a.stats.checks),
        (b.stats.iterations, b.stats.nodes, b.stats.checks)
    );
    assert_eq!(ea, eb);
    let (c, _) = run(&sc, json!({"coverage": 0.75}), 12);
    assert_ne!(a.path, c.path);
}

#[test]
fn a_run_stopped_short_of_the_target_is_not_solved() {
    let sc = builtin("technion-ip").unwrap();
    let mut s = session(&sc, json!({"coverage": 1.0, "max_iterations": 50}), 1, true);
    s.run_to_end();
    let r = s.result();
    assert!(!r.solved && r.path.is_empty(), "{}", r.status);
    assert_eq!(r.status, "iteration_limit");
    let ev = s.drain_events();
    assert!(events_of(&ev, EventKind::Solved).is_empty());
}

/// A point robot in a square with two walls; it sees 0.15 all around. One point lies inside a
/// wall (never seen), one on a wall's top edge (seen: touching does not block); 0.8 of 9 points
/// means every point but the buried one.
fn point_scenario() -> Scenario {
    Scenario::from_json(
        r#"{
        "format": "planarium-scenario/1",
        "name": "Inspect the S",
        "bounds": [0, 0, 1, 1],
        "obstacles": [{"rect": [0.3, 0.0, 0.35, 0.7]}, {"polygon": [[0.65, 0.3], [0.7, 0.3], [0.7, 1.0], [0.65, 1.0]]}],
        "robot": {"kind": "point"},
        "start": [0.1, 0.1],
        "resolution": 0.005,
        "inspection": {
            "points": [[0.1, 0.9], [0.15, 0.45], [0.5, 0.1], [0.5, 0.55], [0.5, 0.9], [0.85, 0.1], [0.85, 0.55], [0.325, 0.7], [0.32, 0.3]],
            "range": 0.15,
            "coverage": 0.8
        }
    }"#,
    )
    .unwrap()
}

#[test]
fn a_point_robot_inspects_too() {
    let sc = point_scenario();
    for seed in 1..=3 {
        let what = format!("point seed {seed}");
        let (r, ev) = run(&sc, json!({}), seed);
        check_solution(&sc, &r, 0.8, &what);
        check_events(&sc, &ev, 0.8, &what);
        let seen = seen_by_path(&sc, &r.path);
        assert!(seen[7] && !seen[8], "{what}: {seen:?}");
    }
}

#[test]
fn smoothing_keeps_what_the_path_sees() {
    for (sc, seed) in [(builtin("technion-ip").unwrap(), 2), (point_scenario(), 1)] {
        let (r, _) = run(&sc, json!({"shortcut_attempts": 0}), seed);
        let problem = Problem::from_scenario(&sc).unwrap();
        // Smoothing that keeps what the path sees continuously (technion-ip counts at vertices
        // as the course does; tests/technion_course.rs checks that count's smoothing).
        let t = task(&sc).counted(false, false);
        let mut rng = planarium::rng::Rng::new(99);
        let smooth = inspection::shortcut(&problem.si, &t, &r.path, 200, &mut rng);
        if let Some(e) = path_problem(&sc, &smooth) {
            panic!("{}: smoothed: {e}", sc.name);
        }
        let (before, after) = (seen_by_path(&sc, &r.path), seen_by_path(&sc, &smooth));
        assert!(before.iter().zip(&after).all(|(b, a)| !b || *a), "{}: smoothing lost a point", sc.name);
        let cost = |p: &[Vec<f64>]| planarium::planners::smoothing::path_cost(&problem.si, p);
        assert!(cost(&smooth) <= cost(&r.path) + 1e-9);
    }
}

//! The Technion course's definitions (report 004, `docs/sources.md`), recomputed here apart from the
//! crate: its own forward kinematics of the links 80, 70, 40, 40 from (0, 0), its own angle wrap,
//! its own segment-meets-segment predicate (touching counts as meeting, as the course's
//! `LineString.intersects`), and the course's count of what a path sees: at its vertices only.
//! The imported `map_ip.json` must report `stats.course_coverage` (and `stats.coverage`, its
//! active mode) equal to that count, meeting the target; `stats.cost_fk` must be report 004's cost.

use planarium::planners::{inspection, InspectionTask, Params};
use planarium::problem::Problem;
use planarium::run::{PlanResult, RunConfig, Session};
use planarium::scenario::Scenario;
use serde_json::{json, Value};
use std::f64::consts::PI;

const MAP_IP: &str = include_str!("../fuzz/corpus/technion/map_ip.json");
const LINKS: [f64; 4] = [80.0, 70.0, 40.0, 40.0];
const RANGE: f64 = 60.0;
const FOV: f64 = PI / 3.0;

type P = (f64, f64);

/// The course's forward kinematics: the four link ends (the 4×2 array), base (0, 0) excluded.
fn fk(q: &[f64]) -> [P; 4] {
    let (mut x, mut y, mut th) = (0.0, 0.0, 0.0);
    let mut out = [(0.0, 0.0); 4];
    for i in 0..4 {
        th += q[i];
        x += LINKS[i] * th.cos();
        y += LINKS[i] * th.sin();
        out[i] = (x, y);
    }
    out
}

/// An angle wrapped into [−π, π).
fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(2.0 * PI) - PI
}

fn orient(a: P, b: P, c: P) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// `p`, collinear with `a b`, lies on the closed segment.
fn within(a: P, b: P, p: P) -> bool {
    p.0 >= a.0.min(b.0) && p.0 <= a.0.max(b.0) && p.1 >= a.1.min(b.1) && p.1 <= a.1.max(b.1)
}

/// Whether the closed segments `a b` and `c d` meet (touching included).
fn meets(a: P, b: P, c: P, d: P) -> bool {
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    if ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)) {
        return true;
    }
    (o1 == 0.0 && within(a, b, c))
        || (o2 == 0.0 && within(a, b, d))
        || (o3 == 0.0 && within(c, d, a))
        || (o4 == 0.0 && within(c, d, b))
}

/// The map's obstacle edges (each polygon closed).
fn edges(map: &Value) -> Vec<(P, P)> {
    let mut out = Vec::new();
    for poly in map["OBSTACLES"].as_array().unwrap() {
        let pts: Vec<P> =
            poly.as_array().unwrap().iter().map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap())).collect();
        for i in 0..pts.len() {
            out.push((pts[i], pts[(i + 1) % pts.len()]));
        }
    }
    out
}

/// The course's `get_inspected_points` for one point: in range, within ±fov/2 of the heading
/// (the wrapped sum of the joint angles; the wrap-around handled), no obstacle edge met.
fn course_sees(edges: &[(P, P)], q: &[f64], p: P) -> bool {
    let ee = fk(q)[3];
    let heading = wrap(q.iter().sum());
    let (dx, dy) = (p.0 - ee.0, p.1 - ee.1);
    if (dx * dx + dy * dy).sqrt() > RANGE {
        return false;
    }
    if wrap(dy.atan2(dx) - heading).abs() > FOV / 2.0 {
        return false;
    }
    !edges.iter().any(|(c, d)| meets(ee, p, *c, *d))
}

/// The points a path sees at its vertices (the handout's I_i = I_{i−1} ∪ S(v_i)).
fn course_seen(edges: &[(P, P)], points: &[P], path: &[Vec<f64>]) -> Vec<bool> {
    let mut seen = vec![false; points.len()];
    for q in path {
        for (j, p) in points.iter().enumerate() {
            seen[j] |= course_sees(edges, q, *p);
        }
    }
    seen
}

fn fraction(seen: &[bool]) -> f64 {
    seen.iter().filter(|s| **s).count() as f64 / seen.len() as f64
}

/// Report 004's distance: the norm of the difference of the two 4×2 forward-kinematics arrays.
fn fk_cost(path: &[Vec<f64>]) -> f64 {
    path.windows(2)
        .map(|w| {
            let (a, b) = (fk(&w[0]), fk(&w[1]));
            a.iter().zip(&b).map(|(p, q)| (p.0 - q.0).powi(2) + (p.1 - q.1).powi(2)).sum::<f64>().sqrt()
        })
        .sum()
}

fn run(sc: &Scenario, params: Value, seed: u64) -> PlanResult {
    let spec = planarium::planners::find("inspection").unwrap();
    let params = Params::from_json(spec, &params).unwrap();
    let problem = Problem::from_scenario(sc).unwrap();
    let mut s =
        Session::new(problem, RunConfig { planner: "inspection".into(), params, seed, record_events: false }).unwrap();
    s.run_to_end();
    s.result()
}

#[test]
fn the_independent_predicates_are_right() {
    // Touching counts as meeting: at an end, at a vertex, collinear overlap; apart does not.
    assert!(meets((0.0, 0.0), (2.0, 2.0), (2.0, 2.0), (3.0, 0.0)), "end on end");
    assert!(meets((0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (1.0, 5.0)), "T");
    assert!(meets((0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (3.0, 0.0)), "overlap");
    assert!(meets((0.0, 0.0), (2.0, 2.0), (0.0, 2.0), (2.0, 0.0)), "cross");
    assert!(!meets((0.0, 0.0), (2.0, 0.0), (3.0, 0.0), (4.0, 0.0)), "collinear apart");
    assert!(!meets((0.0, 0.0), (2.0, 0.0), (1.0, 0.1), (1.0, 5.0)), "above");
    assert!((wrap(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-12 && (wrap(-0.1) + 0.1).abs() < 1e-15);
    let p = fk(&[0.0, PI / 2.0, -PI / 2.0, PI / 2.0]);
    assert!((p[3].0 - 120.0).abs() < 1e-9 && (p[3].1 - 110.0).abs() < 1e-9, "{p:?}");
}

/// The imported map counts as the course does; on seeds 1–5 at 0.5 and 0.75 the reported
/// coverage is the independent vertex count, it meets the target, the continuous count is at least
/// as high, smoothing keeps every point the raw path saw, and the fk cost is report 004's.
#[test]
fn map_ip_coverage_and_cost_by_the_course_definitions() {
    let sc = planarium::io::import(MAP_IP, "map_ip").unwrap();
    let insp = sc.inspection.as_ref().unwrap();
    assert!(insp.at_vertices() && insp.touch_hides, "the import sets the course's mode");
    let map: Value = serde_json::from_str(MAP_IP).unwrap();
    let edges = edges(&map);
    let points: Vec<P> = insp.points.iter().map(|p| (p[0], p[1])).collect();
    for target in [0.5, 0.75] {
        for seed in 1..=5 {
            let what = format!("map_ip coverage {target} seed {seed}");
            let r = run(&sc, json!({"coverage": target, "time_limit": 60}), seed);
            assert!(r.solved, "{what}: {}", r.status);
            let st = &r.stats;
            let seen = course_seen(&edges, &points, &r.path);
            let own = fraction(&seen);
            assert_eq!(st.course_coverage, Some(own), "{what}: reported vs recomputed course coverage");
            assert_eq!(st.coverage, Some(own), "{what}: the active mode is the course's");
            assert!(own >= target, "{what}: course coverage {own} below the target");
            let cont = st.continuous_coverage.unwrap();
            assert!(cont >= own, "{what}: continuous {cont} below the vertex count {own}");
            let smooth_seen = course_seen(&edges, &points, &r.smoothed);
            assert!(seen.iter().zip(&smooth_seen).all(|(a, b)| !a || *b), "{what}: smoothing lost a point");
            assert_eq!(st.smoothed_coverage, Some(fraction(&smooth_seen)), "{what}: smoothed coverage");
            let (c, sc_) = (fk_cost(&r.path), fk_cost(&r.smoothed));
            assert!((st.cost_fk.unwrap() - c).abs() <= 1e-9 * c, "{what}: cost_fk {:?} vs {c}", st.cost_fk);
            assert!((st.smoothed_cost_fk.unwrap() - sc_).abs() <= 1e-9 * sc_.max(1.0), "{what}: smoothed cost_fk");
            eprintln!(
                "{what}: course {own:.3} continuous {cont:.3}; cost joint {:.3} fk {c:.1}; smoothed joint {:.3} fk {sc_:.1}",
                st.cost.unwrap(),
                st.smoothed_cost.unwrap()
            );
        }
    }
}

/// The sight rule on hand-placed points: across the ±π seam of the heading, and a sight line that
/// only touches an obstacle's corner (hidden for the course, seen by Planarium's continuous rule).
#[test]
fn the_course_rule_by_hand_wrap_around_and_touching() {
    let sc = Scenario::from_value(&json!({
        "bounds": [-300, -300, 300, 300],
        "obstacles": [{"polygon": [[250, 10], [270, 10], [270, 30], [250, 30]]}],
        "robot": {"kind": "arm", "links": LINKS, "metric": "joint"},
        "start": [0, 0, 0, 0],
        "touching_allowed": true,
        "inspection": {"points": [
            // Looking along −x from (−230, 0): 0.4 rad off across the seam (seen), 0.6 rad off
            // on either side (not seen).
            [-230.0 + 30.0 * (-PI + 0.4).cos(), 30.0 * (-PI + 0.4).sin()],
            [-230.0 + 30.0 * (PI - 0.6).cos(), 30.0 * (PI - 0.6).sin()],
            [-230.0 + 30.0 * (-PI + 0.6).cos(), 30.0 * (-PI + 0.6).sin()],
            // Looking along +x from (230, 0): the sight line to (286, 14) touches the corner
            // (270, 10) only; (280, −10) is clear.
            [286, 14], [280, -10]
        ], "coverage_mode": "vertices", "touch_hides": true}
    }))
    .unwrap();
    let problem = Problem::from_scenario(&sc).unwrap();
    let i = sc.inspection.as_ref().unwrap();
    let task = InspectionTask {
        points: i.points.iter().map(|p| planarium::math::Vec2::new(p[0], p[1])).collect(),
        fov: i.fov,
        range: i.range,
        coverage: i.coverage,
        at_vertices: true,
        touch_hides: true,
    };
    let edges = edges(&json!({"OBSTACLES": [[[250, 10], [270, 10], [270, 30], [250, 30]]]}));
    let points: Vec<P> = i.points.iter().map(|p| (p[0], p[1])).collect();
    let left = vec![vec![PI, 0.0, 0.0, 0.0]];
    let right = vec![vec![0.0, 0.0, 0.0, 0.0]];
    let independent = |path: &[Vec<f64>]| course_seen(&edges, &points, path);
    assert_eq!(independent(&left), [true, false, false, false, false]);
    assert_eq!(independent(&right), [false, false, false, false, true]);
    let si = &problem.si;
    assert_eq!(inspection::course_coverage(si, &task, &left), 0.2);
    assert_eq!(inspection::course_coverage(si, &task, &right), 0.2);
    // Planarium's continuous rule sees the touched point too.
    assert_eq!(inspection::continuous_coverage(si, &task, &right), 0.4);
    let bits = inspection::seen_along(si, &task, &right);
    assert_eq!(bits[0], 0b10000);
}

/// The `fk` metric is report 004's distance, and a scenario may choose it.
#[test]
fn the_fk_metric_is_report_004s_distance() {
    let mut v: Value = serde_json::from_str(&planarium::io::import(MAP_IP, "m").unwrap().to_json()).unwrap();
    v["robot"]["metric"] = json!("fk");
    v["resolution"] = json!(2.0);
    let sc = Scenario::from_value(&v).unwrap();
    let p = Problem::from_scenario(&sc).unwrap();
    let mut rng = planarium::rng::Rng::new(4);
    for _ in 0..200 {
        let a: Vec<f64> = (0..4).map(|_| rng.uniform(-PI, PI)).collect();
        let b: Vec<f64> = (0..4).map(|_| rng.uniform(-PI, PI)).collect();
        let want = fk_cost(&[a.clone(), b.clone()]);
        assert!((p.si.distance(&a, &b) - want).abs() <= 1e-9 * want, "{a:?} {b:?}");
    }
    v["robot"]["metric"] = json!("fk2");
    let e = Scenario::from_value(&v).unwrap_err();
    assert_eq!(e.to_string(), "robot.metric: must be joint, chain, max or fk");
}

/// `bench --course-table` gives the cost in both units for an arm: its fk columns are the means of
/// report 004's distance over the same seeded runs, recomputed here from their paths; a point
/// robot's table has no such columns.
#[test]
fn the_course_table_gives_cost_in_both_units() {
    use planarium::run::{bench, report};
    let sc = planarium::io::import(include_str!("../fuzz/corpus/technion/map_mp.json"), "map_mp").unwrap();
    let spec = planarium::planners::find("rrt").unwrap();
    let params = Params::from_json(spec, &Value::Object(sc.planner.as_ref().unwrap().params.clone())).unwrap();
    let runs = 3;
    let b = bench::bench_planner(&sc, "rrt", &params, runs).unwrap();
    let table = report::course_table(&report::BenchReport::new(&sc.name, "map_mp", "", "", &[b]));
    let (mut raw, mut smooth) = (Vec::new(), Vec::new());
    for seed in 1..=runs {
        let problem = Problem::from_scenario(&sc).unwrap();
        let mut s = Session::new(
            problem,
            RunConfig { planner: "rrt".into(), params: params.clone(), seed, record_events: false },
        )
        .unwrap();
        s.run_to_end();
        let r = s.result();
        assert!(r.solved, "seed {seed}");
        raw.push(fk_cost(&r.path));
        smooth.push(fk_cost(&r.smoothed));
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let header = table.lines().next().unwrap();
    assert!(header.ends_with("| mean cost (fk) | mean smoothed cost (fk) |"), "{table}");
    let row: Vec<&str> = table.lines().nth(2).unwrap().split('|').map(str::trim).collect();
    let n = row.len();
    assert_eq!(row[n - 3], format!("{:.2}", mean(&raw)), "{table}");
    assert_eq!(row[n - 2], format!("{:.2}", mean(&smooth)), "{table}");
    let narrow = planarium::scenario::builtin("narrow").unwrap();
    let spec = planarium::planners::find("rrt").unwrap();
    let b = bench::bench_planner(&narrow, "rrt", &Params::defaults(spec), 2).unwrap();
    let t = report::course_table(&report::BenchReport::new(&narrow.name, "narrow", "", "", &[b]));
    assert!(!t.contains("(fk)"), "{t}");
}

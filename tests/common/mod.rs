//! An independent checker of paths, written apart from the crate's geometry: its own point and
//! polygon tests (winding numbers, orientation-sign intersections, a separating-axis box test) on
//! the scenario's numbers, and motions sampled twice as finely as the planner's resolution; point
//! robots' motions are also checked exactly. Its orientation signs come straight from
//! `robust::orient2d` (exact, as the crate's are, but not through the crate's code), so segment,
//! box and polygon decisions are exact; disc tests compare an `f64` distance and are not. The
//! spatial arm (3-D) has its own kinematics and GJK in [`spatial`], its motions sampled at a
//! quarter of the resolution.
#![allow(dead_code)]

pub mod brute3d;
pub mod last_free;
pub mod spatial;

use planarium::scenario::{ObstacleSpec, RobotSpec, Scenario};

/// A point.
pub type P = (f64, f64);

/// The exact orientation sign of `o, a, b` (> 0 counter-clockwise), as an `f64`.
pub fn cross(o: P, a: P, b: P) -> f64 {
    robust::orient2d(
        robust::Coord { x: o.0, y: o.1 },
        robust::Coord { x: a.0, y: a.1 },
        robust::Coord { x: b.0, y: b.1 },
    )
}

fn on_segment(a: P, b: P, p: P) -> bool {
    cross(a, b, p) == 0.0 && p.0 >= a.0.min(b.0) && p.0 <= a.0.max(b.0) && p.1 >= a.1.min(b.1) && p.1 <= a.1.max(b.1)
}

/// Winding number of `poly` around `p` (nonzero: inside), boundary counted as inside.
pub fn in_polygon(poly: &[P], p: P) -> bool {
    let n = poly.len();
    let mut w = 0i32;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        if on_segment(a, b, p) {
            return true;
        }
        if a.1 <= p.1 {
            if b.1 > p.1 && cross(a, b, p) > 0.0 {
                w += 1;
            }
        } else if b.1 <= p.1 && cross(a, b, p) < 0.0 {
            w -= 1;
        }
    }
    w != 0
}

/// Whether closed segments meet: each one's ends not strictly on one side of the other's line,
/// or (all four collinear) overlapping bounding boxes.
fn segments_meet(a: P, b: P, c: P, d: P) -> bool {
    let s = |x: f64| x.partial_cmp(&0.0).unwrap() as i8;
    let (d1, d2, d3, d4) = (s(cross(c, d, a)), s(cross(c, d, b)), s(cross(a, b, c)), s(cross(a, b, d)));
    if d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0 {
        return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
    }
    d1 * d2 <= 0 && d3 * d4 <= 0
}

pub fn dist_point_segment(p: P, a: P, b: P) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

pub fn obstacle_polygon(o: &ObstacleSpec) -> Option<Vec<P>> {
    match o {
        ObstacleSpec::Rect(r) => {
            let (x0, x1, y0, y1) = (r[0].min(r[2]), r[0].max(r[2]), r[1].min(r[3]), r[1].max(r[3]));
            Some(vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
        }
        ObstacleSpec::Polygon(p) => Some(p.iter().map(|q| (q[0], q[1])).collect()),
        _ => None,
    }
}

fn point_blocked(o: &ObstacleSpec, p: P) -> bool {
    match o {
        ObstacleSpec::Circle(c) => ((p.0 - c[0]).powi(2) + (p.1 - c[1]).powi(2)).sqrt() <= c[2],
        ObstacleSpec::Segment(s) => on_segment((s[0], s[1]), (s[2], s[3]), p),
        _ => in_polygon(&obstacle_polygon(o).unwrap(), p),
    }
}

/// The distance from `p` to the closed obstacle `o` (0 inside it).
pub fn dist_to_obstacle(o: &ObstacleSpec, p: P) -> f64 {
    if point_blocked(o, p) {
        return 0.0;
    }
    match o {
        ObstacleSpec::Circle(c) => ((p.0 - c[0]).powi(2) + (p.1 - c[1]).powi(2)).sqrt() - c[2],
        ObstacleSpec::Segment(s) => dist_point_segment(p, (s[0], s[1]), (s[2], s[3])),
        _ => {
            let poly = obstacle_polygon(o).unwrap();
            (0..poly.len())
                .map(|i| dist_point_segment(p, poly[i], poly[(i + 1) % poly.len()]))
                .fold(f64::INFINITY, f64::min)
        }
    }
}

/// Separating axes: does segment a-b meet the closed box? The x and y extents overlap, and the
/// box's corners are not all strictly on one side of the segment's line.
fn clip_box(a: P, b: P, x0: f64, y0: f64, x1: f64, y1: f64) -> bool {
    if a.0.max(b.0) < x0 || a.0.min(b.0) > x1 || a.1.max(b.1) < y0 || a.1.min(b.1) > y1 {
        return false;
    }
    let sides = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(|c| cross(a, b, c));
    !(sides.iter().all(|&v| v > 0.0) || sides.iter().all(|&v| v < 0.0))
}

fn segment_blocked(o: &ObstacleSpec, a: P, b: P) -> bool {
    match o {
        ObstacleSpec::Rect(r) => clip_box(a, b, r[0].min(r[2]), r[1].min(r[3]), r[0].max(r[2]), r[1].max(r[3])),
        ObstacleSpec::Circle(c) => dist_point_segment((c[0], c[1]), a, b) <= c[2],
        ObstacleSpec::Segment(s) => segments_meet(a, b, (s[0], s[1]), (s[2], s[3])),
        ObstacleSpec::Polygon(_) => {
            let poly = obstacle_polygon(o).unwrap();
            in_polygon(&poly, a) || (0..poly.len()).any(|i| segments_meet(a, b, poly[i], poly[(i + 1) % poly.len()]))
        }
    }
}

/// Whether a body polygon meets an obstacle.
fn body_hits(o: &ObstacleSpec, body: &[P]) -> bool {
    let n = body.len();
    (0..n).any(|i| segment_blocked(o, body[i], body[(i + 1) % n]))
        || match o {
            ObstacleSpec::Circle(c) => in_polygon(body, (c[0], c[1])),
            ObstacleSpec::Segment(s) => in_polygon(body, (s[0], s[1])),
            _ => obstacle_polygon(o).unwrap().iter().any(|&v| in_polygon(body, v)),
        }
}

fn body(sc: &Scenario, q: &[f64]) -> Option<Vec<P>> {
    match &sc.robot {
        RobotSpec::Point => None,
        RobotSpec::Rigid { footprint, .. } => {
            let (s, c) = q[2].sin_cos();
            Some(footprint.iter().map(|p| (q[0] + c * p[0] - s * p[1], q[1] + s * p[0] + c * p[1])).collect())
        }
        other => panic!("the independent checker has no {} robot", other.kind()),
    }
}

/// An arm's joint points (base first, tip end last), by its own forward kinematics.
pub fn arm_points(sc: &Scenario, q: &[f64]) -> Vec<P> {
    let RobotSpec::Arm { base, links, tip, .. } = &sc.robot else { unreachable!() };
    let mut pts = vec![(base[0], base[1])];
    let mut th = 0.0;
    for (l, a) in links.iter().zip(q) {
        th += a;
        let p = *pts.last().unwrap();
        pts.push((p.0 + l * th.cos(), p.1 + l * th.sin()));
    }
    if *tip > 0.0 {
        let p = *pts.last().unwrap();
        pts.push((p.0 + tip * th.cos(), p.1 + tip * th.sin()));
    }
    pts
}

fn arm_problem(sc: &Scenario, q: &[f64]) -> Option<String> {
    let RobotSpec::Arm { limits, self_collision, .. } = &sc.robot else { unreachable!() };
    for (i, (l, v)) in limits.iter().zip(q).enumerate() {
        if let Some([lo, hi]) = l {
            if v < lo || v > hi {
                return Some(format!("{q:?}: joint {i} outside [{lo}, {hi}]"));
            }
        }
    }
    let pts = arm_points(sc, q);
    let b = sc.bounds;
    if let Some(p) = pts.iter().find(|p| p.0 < b[0] || p.0 > b[2] || p.1 < b[1] || p.1 > b[3]) {
        return Some(format!("{q:?}: joint point {p:?} out of bounds"));
    }
    for w in pts.windows(2) {
        for (i, o) in sc.obstacles.iter().enumerate() {
            if segment_blocked(o, w[0], w[1]) {
                return Some(format!("{q:?}: link {:?}-{:?} meets obstacles[{i}]", w[0], w[1]));
            }
        }
    }
    if *self_collision {
        for i in 0..pts.len() - 1 {
            for j in i + 2..pts.len() - 1 {
                if segments_meet(pts[i], pts[i + 1], pts[j], pts[j + 1]) {
                    return Some(format!("{q:?}: links {i} and {j} cross"));
                }
            }
        }
    }
    None
}

/// Why state `q` is invalid, or `None`.
pub fn state_problem(sc: &Scenario, q: &[f64]) -> Option<String> {
    if matches!(sc.robot, RobotSpec::Arm { .. }) {
        return arm_problem(sc, q);
    }
    if let Some(arm) = spatial::Arm::new(sc) {
        return arm.problem(q);
    }
    let b = sc.bounds;
    if q[0] < b[0] || q[0] > b[2] || q[1] < b[1] || q[1] > b[3] {
        return Some(format!("{q:?} out of bounds"));
    }
    for (i, o) in sc.obstacles.iter().enumerate() {
        let hit = match body(sc, q) {
            None => point_blocked(o, (q[0], q[1])),
            Some(poly) => body_hits(o, &poly),
        };
        if hit {
            return Some(format!("{q:?} meets obstacles[{i}]"));
        }
    }
    None
}

fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (b - a).rem_euclid(2.0 * std::f64::consts::PI);
    if d > std::f64::consts::PI {
        d - 2.0 * std::f64::consts::PI
    } else {
        d
    }
}

fn metric(sc: &Scenario, a: &[f64], b: &[f64]) -> f64 {
    match &sc.robot {
        // For arms, the largest joint-space step (wrap-aware): paths must start and end within 1e-9.
        RobotSpec::Arm { .. } => a.iter().zip(b).map(|(x, y)| angle_diff(*x, *y).abs()).fold(0.0, f64::max),
        RobotSpec::Point => ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt(),
        // Euclidean over the joint angles (radians), the scenario format's `joint` metric.
        RobotSpec::SpatialArm(_) => a.iter().zip(b).map(|(x, y)| (y - x).powi(2)).sum::<f64>().sqrt(),
        RobotSpec::Rigid { footprint, rotation_weight } => {
            let r = rotation_weight.unwrap_or_else(|| footprint.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max));
            ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt() + r * angle_diff(a[2], b[2]).abs()
        }
        other => panic!("the independent checker has no {} robot", other.kind()),
    }
}

/// Why the path is not a valid solution from start to goal, or `None`. For an inspection task (no
/// goal) it must start at the start and every motion be valid; what it sees is checked by the
/// inspection tests.
pub fn path_problem(sc: &Scenario, path: &[Vec<f64>]) -> Option<String> {
    path_problem_by(sc, path, motion_problem)
}

/// Whether the scenario's robot is a spatial arm (its runs and re-checks cost seconds, not
/// milliseconds: the walks give it fewer seeds and iterations).
pub fn spatial(sc: &Scenario) -> bool {
    matches!(sc.robot, RobotSpec::SpatialArm(_))
}

fn path_problem_by(
    sc: &Scenario,
    path: &[Vec<f64>],
    motion_problem: fn(&Scenario, &[f64], &[f64]) -> Option<String>,
) -> Option<String> {
    if path.len() < 2 {
        return Some("fewer than two states".into());
    }
    if metric(sc, &path[0], &sc.start) > 1e-9 {
        return Some(format!("starts at {:?}, not at the start {:?}", path[0], sc.start));
    }
    if let Some(goal) = sc.goal.as_ref() {
        if metric(sc, path.last().unwrap(), goal) > sc.goal_tolerance + 1e-9 {
            return Some(format!("ends at {:?}, not at the goal {:?}", path.last().unwrap(), goal));
        }
    }
    for (k, w) in path.windows(2).enumerate() {
        if let Some(e) = motion_problem(sc, &w[0], &w[1]) {
            return Some(format!("motion {k}: {e}"));
        }
    }
    None
}

/// Why the motion a → b is invalid, or `None`: states every resolution/2 (a spatial arm's every
/// resolution/4, in joint space), and for a point an exact segment test.
pub fn motion_problem(sc: &Scenario, a: &[f64], b: &[f64]) -> Option<String> {
    let n = match &sc.robot {
        RobotSpec::Arm { links, limits, .. } => {
            // No arm point moves more than 1/1000 of the bounds' size between two checked states.
            let size = (sc.bounds[2] - sc.bounds[0]).max(sc.bounds[3] - sc.bounds[1]);
            let total: f64 = links.iter().sum();
            let moved: f64 = a
                .iter()
                .zip(b)
                .zip(limits)
                .map(|((x, y), l)| if l.is_some() { (y - x).abs() } else { angle_diff(*x, *y).abs() })
                .sum();
            ((moved * total) / (0.001 * size)).ceil() as usize
        }
        RobotSpec::SpatialArm(_) => (metric(sc, a, b) / (sc.resolution / 4.0)).ceil() as usize,
        _ => (metric(sc, a, b) / (sc.resolution / 2.0)).ceil() as usize,
    }
    .max(1);
    // A spatial arm's checker is built once per motion, not per state.
    let arm = spatial::Arm::new(sc);
    for i in 0..=n {
        let t = i as f64 / n as f64;
        let mut q: Vec<f64> = a.iter().zip(b).map(|(x, y)| x + t * (y - x)).collect();
        match &sc.robot {
            RobotSpec::Rigid { .. } => q[2] = a[2] + t * angle_diff(a[2], b[2]),
            RobotSpec::Arm { limits, .. } => {
                for (k, l) in limits.iter().enumerate() {
                    if l.is_none() {
                        q[k] = a[k] + t * angle_diff(a[k], b[k]);
                    }
                }
            }
            _ => {}
        }
        let e = match &arm {
            Some(arm) => arm.problem(&spatial::lerp(a, b, t)),
            None => state_problem(sc, &q),
        };
        if e.is_some() {
            return e;
        }
    }
    if matches!(sc.robot, RobotSpec::Point) {
        for (i, o) in sc.obstacles.iter().enumerate() {
            if segment_blocked(o, (a[0], a[1]), (b[0], b[1])) {
                return Some(format!("segment {a:?} → {b:?} meets obstacles[{i}]"));
            }
        }
    }
    None
}

/// Sanity checks of the checker itself: it must reject what is wrong.
pub fn self_test() {
    let sc = planarium::scenario::builtin("narrow").unwrap();
    assert!(state_problem(&sc, &[0.5, 0.2]).is_some());
    assert!(state_problem(&sc, &[0.5, 0.5]).is_none());
    assert!(motion_problem(&sc, &[0.1, 0.1], &[0.9, 0.1]).is_some());
    // Grazing the wall's corner (0.55, 0.49) exactly, both ends free.
    assert!(motion_problem(&sc, &[0.56, 0.48], &[0.54, 0.50]).is_some());
    assert!(path_problem(&sc, &[vec![0.1, 0.1], vec![0.9, 0.9]]).is_some());
    let arm = planarium::scenario::builtin("arm-3").unwrap();
    assert!(state_problem(&arm, &arm.start).is_none());
    assert!(state_problem(&arm, &[0.5, 0.0, 0.0]).is_some(), "straight through the block");
    assert!(state_problem(&arm, &[0.0, 2.0, 0.0]).is_some(), "joint limit");
    let horn = planarium::scenario::builtin("horn-10").unwrap();
    assert!(state_problem(&horn, &horn.start).is_none());
    assert!(
        state_problem(&horn, &[0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0]).is_some(),
        "curled into itself or the horn"
    );
    let puma = planarium::scenario::builtin("puma-rbo-wall").unwrap();
    let goal = puma.goal.clone().unwrap();
    assert!(state_problem(&puma, &puma.start).is_none() && state_problem(&puma, &goal).is_none());
    assert!(state_problem(&puma, &[0.0, 0.8, 0.0, 0.0, 0.0, 0.0]).is_some(), "joint limit");
    let through = motion_problem(&puma, &puma.start, &goal).expect("straight through the wall");
    assert!(through.contains("meets obstacles3d["), "{through}");
    let slot = planarium::scenario::builtin("slot").unwrap();
    assert!(state_problem(&slot, &[0.5, 0.5, std::f64::consts::FRAC_PI_2]).is_some());
    assert!(state_problem(&slot, &[0.5, 0.5, 0.0]).is_none());
}

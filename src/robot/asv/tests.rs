use super::*;
use crate::geometry::{Aabb, Shape};
use crate::rng::Rng;

/// 7ASV's start (a near-regular heptagon with one side open) and two walls with a 0.03 slot.
const START7: [Real; 14] =
    [0.193301, 0.238602, 0.15, 0.213602, 0.125, 0.170301, 0.150, 0.127, 0.200, 0.127, 0.225, 0.170301, 0.225, 0.220301];

fn robot(n: usize) -> AsvRobot {
    let min_area = PI * (0.007 * (n as Real - 1.0)).powi(2);
    AsvRobot::from_spec(&RobotSpec::Asv { count: n, broom: 0.05, min_area, convex: true, max_step: 0.001 }).unwrap()
}

fn slot() -> Workspace {
    let mut ws = Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![
            Shape::Rect(Aabb { min: Vec2::new(0.25, 0.0), max: Vec2::new(0.35, 0.3) }),
            Shape::Rect(Aabb { min: Vec2::new(0.25, 0.33), max: Vec2::new(0.35, 1.0) }),
        ],
    );
    ws.touching_allowed = true;
    ws
}

fn positions(r: &AsvRobot, q: &[Real]) -> Vec<Vec2> {
    r.decode(q).chunks(2).map(|c| Vec2::new(c[0], c[1])).collect()
}

fn max_move(r: &AsvRobot, a: &[Real], b: &[Real]) -> Real {
    positions(r, a).iter().zip(positions(r, b)).map(|(p, q)| (*p - q).norm()).fold(0.0, Real::max)
}

#[test]
fn encode_and_decode_round_trip() {
    let r = robot(7);
    let q = r.encode(&START7).unwrap();
    assert_eq!(q.len(), 8);
    let back = r.decode(&q);
    for (a, b) in back.iter().zip(START7) {
        assert!((a - b).abs() < 2e-6, "{back:?}");
    }
    let p = positions(&r, &q);
    for w in p.windows(2) {
        assert!(((w[1] - w[0]).norm() - 0.05).abs() < 1e-15, "brooms have their length by construction");
    }
    assert_eq!(r.orientation(), 1.0, "7ASV's start winds counter-clockwise");
    let mut bad = START7;
    bad[2] += 0.001;
    assert!(r.encode(&bad).unwrap_err().contains("broom 1"));
}

#[test]
fn the_start_is_valid_and_a_flattened_chain_is_not() {
    let (r, ws) = (robot(7), slot());
    let q = r.encode(&START7).unwrap();
    assert_eq!(r.verdict(&ws, &q), Verdict::Valid);
    let mut flat = q.clone();
    flat[3..].iter_mut().for_each(|t| *t = 0.01);
    assert!(matches!(r.verdict(&ws, &flat), Verdict::Invalid(_)), "a nearly straight chain has no area");
    let mut inside = q.clone();
    inside[0] = 0.3;
    assert_eq!(r.verdict(&ws, &inside), Verdict::Collision(0));
}

/// Random pairs of sampled states.
fn pairs(r: &AsvRobot, ws: &Workspace, count: usize) -> Vec<(Vec<Real>, Vec<Real>)> {
    let space = r.space(ws);
    let mut rng = Rng::new(7);
    let mut draw = || {
        let mut q = vec![0.0; space.dim_count()];
        r.sample(&space, &mut rng, &mut q, &|| false);
        q
    };
    (0..count).map(|_| (draw(), draw())).collect()
}

#[test]
fn no_vehicle_moves_more_than_max_step_between_checked_states() {
    let (r, ws) = (robot(7), slot());
    r.encode(&START7).unwrap();
    let space = r.space(&ws);
    let mut q = vec![0.0; 8];
    let mut prev = vec![0.0; 8];
    for (a, b) in pairs(&r, &ws, 60) {
        // Short motions too: a tenth of the way.
        let mut near = vec![0.0; 8];
        space.interpolate(&a, &b, 0.1, &mut near);
        for (a, b) in [(&a, &b), (&a, &near)] {
            let n = r.steps(a, b, 0.0, 0.0).expect("a motion in bounds has a step count");
            assert_eq!(Some(n), r.steps(b, a, 0.0, 0.0), "the same steps both ways");
            let bound = r.displacement_bound(a, b).unwrap();
            prev.copy_from_slice(a);
            // Every step, and every point within it (checked 4 times finer), moves no vehicle
            // more than its share of the bound, which is at most max_step.
            for i in 1..=4 * n {
                space.interpolate(a, b, i as Real / (4 * n) as Real, &mut q);
                assert!(max_move(&r, &prev, &q) <= bound / (4 * n) as Real + 1e-12);
                prev.copy_from_slice(&q);
            }
            assert!(bound / n as Real <= 0.001 + 1e-12);
        }
    }
}

#[test]
fn turning_the_whole_chain_costs_only_its_real_movement() {
    let r = robot(7);
    let a = r.encode(&START7).unwrap();
    let mut b = a.clone();
    b[2] += 0.1;
    let radius = positions(&r, &a).iter().map(|p| (*p - Vec2::new(a[0], a[1])).norm()).fold(0.0, Real::max);
    let bound = r.displacement_bound(&a, &b).unwrap();
    assert!((bound - 0.1 * radius).abs() < 1e-12, "{bound} vs {}", 0.1 * radius);
}

#[test]
fn clearance_is_a_radius_of_valid_states() {
    let (r, ws) = (robot(7), slot());
    r.encode(&START7).unwrap();
    let space = r.space(&ws);
    let mut q = vec![0.0; 8];
    let mut rng = Rng::new(11);
    let mut tested = 0;
    for (a, b) in pairs(&r, &ws, 400) {
        let c = r.clearance(&ws, &a, 0.01).unwrap();
        assert_eq!(c > 0.0, r.verdict(&ws, &a) == Verdict::Valid);
        if c == 0.0 {
            continue;
        }
        // States toward b (and toward a random state) whose vehicles stay within c are valid.
        for t in [rng.uniform01(), rng.uniform01() * 0.1, 0.01] {
            space.interpolate(&a, &b, t, &mut q);
            if max_move(&r, &a, &q) < c {
                tested += 1;
                assert_eq!(r.verdict(&ws, &q), Verdict::Valid, "within clearance {c} of a valid state");
            }
        }
    }
    assert!(tested > 50, "only {tested} states tested");
}

#[test]
fn samples_are_mostly_valid_and_wind_like_the_start() {
    let (r, ws) = (robot(7), slot());
    r.encode(&START7).unwrap();
    let space = r.space(&ws);
    let mut rng = Rng::new(3);
    let mut q = vec![0.0; 8];
    let mut valid = 0;
    for _ in 0..1000 {
        r.sample(&space, &mut rng, &mut q, &|| false);
        if r.verdict(&ws, &q) == Verdict::Valid {
            valid += 1;
            assert!(rules::signed_area2(&positions(&r, &q)) > 0.0);
        }
    }
    assert!(valid > 900, "{valid} of 1000 samples valid");
}

#[test]
fn the_bridge_test_finds_the_slot() {
    let gaps = sampler::Gaps::find(&slot(), &|| false).unwrap();
    let pts = gaps.points();
    assert!(pts.len() >= 20, "{} gap points", pts.len());
    // Most in the slot; a few in inner corners where a wall meets the bounds.
    let in_slot = pts.iter().filter(|(p, _)| p.x > 0.25 && p.x < 0.35 && p.y > 0.3 && p.y < 0.33).count();
    assert!(in_slot * 3 > pts.len() * 2, "{in_slot} of {} gap points in the slot", pts.len());
    for (p, along) in pts.iter().filter(|(p, _)| p.x > 0.26 && p.x < 0.34 && p.y > 0.3 && p.y < 0.33) {
        assert!(libm::sin(*along).abs() < 0.45, "the slot runs along x, found {along} at {p:?}");
    }
}

/// The middle of a gap, found for a thin chain: in a wall 0.33 thick with a gap 0.03 wide at
/// y 0.485 to 0.515, the centres of the gap points well inside it lie on y = 0.5.
#[test]
fn gap_centres_lie_in_the_middle_of_a_long_gap() {
    let mut ws = Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![
            Shape::Rect(Aabb { min: Vec2::new(0.335, 0.0), max: Vec2::new(0.665, 0.485) }),
            Shape::Rect(Aabb { min: Vec2::new(0.335, 0.515), max: Vec2::new(0.665, 1.0) }),
        ],
    );
    ws.touching_allowed = true;
    let gaps = sampler::Gaps::find(&ws, &|| false).unwrap();
    let inside: Vec<usize> =
        (0..gaps.points().len()).filter(|&i| gaps.points()[i].0.x > 0.36 && gaps.points()[i].0.x < 0.64).collect();
    assert!(inside.len() >= 20, "{} gap points inside the gap", inside.len());
    for i in inside {
        let c = gaps.centres()[i];
        assert!((c.y - 0.5).abs() < 0.002, "centre {c:?} of gap point {:?}", gaps.points()[i]);
    }
}

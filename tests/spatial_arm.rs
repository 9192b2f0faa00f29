//! The spatial arm on report 001's robot: the Puma 560's kinematics against the Robotics Library's
//! own placement of its links, the course's scene, and the collision query's cost (printed).

use planarium::problem::Problem;
use planarium::robot::{Spatial, SpatialArmRobot};
use planarium::scenario::{builtin, Scenario};

fn puma(id: &str) -> (Scenario, Problem) {
    let sc = builtin(id).unwrap();
    let p = Problem::from_scenario(&sc).unwrap();
    (sc, p)
}

/// At q = 0 every link frame is where rl's display file (`data/rl-puma560/rlsg/
/// unimation-puma560.convex/unimation-puma560.wrl`) puts it, turned by the world's Rz(90°).
#[test]
fn puma_frames_at_zero_are_rls() {
    let (sc, _) = puma("puma-rbo-wall");
    let arm = SpatialArmRobot::from_spec(&sc.robot).unwrap();
    let s = arm.skeleton_points(&[0.0; 6]);
    // rl's translations, x y z; Rz(90°) takes (x, y, z) to (−y, x, z).
    let rl = [
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 0.6604],
        [0.4318, 0.1291, 0.6604],
        [0.4115, 0.1291, 0.6604],
        [0.4115, 0.1291, 1.0935],
        [0.4115, 0.1291, 1.0935],
        [0.4115, 0.1291, 1.13475],
    ];
    for (k, p) in rl.iter().enumerate() {
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

/// The tool's curve along a motion: one point per `delta` step (then the end), on the arm's own
/// kinematics, ready for a 3-D view to draw an edge as the tool sweeps it.
#[test]
fn tool_steps_follow_the_connect() {
    let (sc, p) = puma("puma-rbo-wall");
    let goal = sc.goal.clone().unwrap();
    let pts = p.tool_steps(&sc.start, &goal);
    let d = p.si.distance(&sc.start, &goal);
    assert_eq!(pts.len(), (d / sc.resolution).ceil() as usize + 1);
    let sp = p.robot.spatial().unwrap();
    assert_eq!(pts[0], sp.tool_point(&sc.start));
    assert_eq!(*pts.last().unwrap(), sp.tool_point(&goal));
    // Neighbouring steps are close: the tool is at most 1.3 m from the base axis, so it moves at
    // most about 1.3 × 6 × δ... far less in practice; a chord would cut through the wall.
    let longest =
        pts.windows(2).map(|w| (0..3).map(|k| (w[1][k] - w[0][k]).powi(2)).sum::<f64>().sqrt()).fold(0.0, f64::max);
    assert!(longest < 0.05, "{longest}");
    // A planar robot has none.
    let n = Problem::from_scenario(&builtin("narrow").unwrap()).unwrap();
    assert!(n.tool_steps(&[0.1, 0.5], &[0.2, 0.5]).is_empty() && n.robot.spatial().is_none());
}

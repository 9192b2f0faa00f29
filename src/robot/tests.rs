use super::*;
use crate::geometry::{Aabb, Shape};
use crate::math::PI;

fn ws() -> Workspace {
    // A wall with a 0.06 slot at y = 0.5.
    Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![
            Shape::Rect(Aabb { min: Vec2::new(0.45, 0.0), max: Vec2::new(0.55, 0.47) }),
            Shape::Rect(Aabb { min: Vec2::new(0.45, 0.53), max: Vec2::new(0.55, 1.0) }),
        ],
    )
}

fn bar() -> RigidRobot {
    RigidRobot::new(
        vec![Vec2::new(-0.1, -0.015), Vec2::new(0.1, -0.015), Vec2::new(0.1, 0.015), Vec2::new(-0.1, 0.015)],
        None,
        false,
    )
}

#[test]
fn bar_fits_the_slot_only_when_flat() {
    let w = ws();
    assert_eq!(bar().verdict(&w, &[0.5, 0.5, 0.0]), Verdict::Valid);
    assert_eq!(bar().verdict(&w, &[0.5, 0.5, PI / 2.0]), Verdict::Collision(0));
    // Flat but too high: touches the upper wall's face exactly (closed sets).
    assert_eq!(bar().verdict(&w, &[0.5, 0.515, 0.0]), Verdict::Collision(1));
    assert_eq!(bar().verdict(&w, &[0.5, 0.5149, 0.0]), Verdict::Valid);
    // Rotation by a full turn is the same state.
    assert_eq!(bar().verdict(&w, &[0.5, 0.5, 2.0 * PI]), Verdict::Valid);
}

#[test]
fn reference_point_bounds_unless_body_in_bounds() {
    let w = ws();
    assert_eq!(bar().verdict(&w, &[0.05, 0.2, 0.0]), Verdict::Valid, "body may leave the bounds by default");
    let strict = RigidRobot::new(bar().footprint.clone(), None, true);
    assert_eq!(strict.verdict(&w, &[0.05, 0.2, 0.0]), Verdict::OutOfBounds(0));
    assert_eq!(bar().verdict(&w, &[1.01, 0.2, 0.0]), Verdict::OutOfBounds(0));
}

#[test]
fn point_sweep_catches_a_corner_between_samples() {
    // Dyadic coordinates, so the corner lies exactly on the segment.
    let w = Workspace::new(
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) },
        vec![Shape::Rect(Aabb { min: Vec2::new(0.375, 0.0), max: Vec2::new(0.625, 0.5) })],
    );
    let p = PointRobot;
    let (a, b) = ([0.75, 0.375], [0.5, 0.625]);
    assert_eq!(p.verdict(&w, &a), Verdict::Valid);
    assert_eq!(p.verdict(&w, &b), Verdict::Valid);
    assert_eq!(p.sweep_hits(&w, &a, &b), Some(true), "grazes the corner (0.625, 0.5)");
    assert_eq!(p.sweep_hits(&w, &[0.75, 0.376], &[0.5, 0.626]), Some(false));
}

mod arm {
    use super::super::*;
    use crate::math::PI;
    use crate::motion::MotionValidator;
    use crate::problem::Problem;
    use crate::scenario::Scenario;

    /// A 3-link arm (0.3, 0.2, 0.1) at (0.5, 0.5) beside a wall; `robot_extra` adds robot keys.
    pub(super) fn problem(robot_extra: &str) -> Problem {
        let text = format!(
            r#"{{"bounds": [0, 0, 1, 1], "obstacles": [{{"rect": [0.85, 0.0, 0.95, 0.4]}}],
                "robot": {{"kind": "arm", "base": [0.5, 0.5], "links": [0.3, 0.2, 0.1]{robot_extra}}},
                "start": [1.5, 1.5, 0], "goal": [1.5, 1.5, 0], "resolution": 0.01}}"#
        );
        Problem::from_scenario(&Scenario::from_json(&text).unwrap()).unwrap()
    }

    #[test]
    fn forward_kinematics_uses_relative_angles() {
        let arm = ArmRobot::from_spec(&problem("").scenario.robot).unwrap();
        let mut pts = [Vec2::default(); 4];
        arm.joint_points(&[PI / 2.0, -PI / 2.0, 0.0], &mut pts);
        let want = [(0.5, 0.5), (0.5, 0.8), (0.7, 0.8), (0.8, 0.8)];
        for (p, w) in pts.iter().zip(want) {
            assert!((p.x - w.0).abs() < 1e-12 && (p.y - w.1).abs() < 1e-12, "{pts:?}");
        }
    }

    #[test]
    fn every_rule_with_hand_made_states() {
        let p = problem("");
        let si = &p.si;
        assert!(!si.is_valid(&[0.0, 0.0, 0.0]), "straight right ends at x = 1.1: out of bounds");
        assert!(!si.is_valid(&[PI, 0.0, 0.0]), "straight left ends at x = -0.1: out of bounds");
        assert!(si.is_valid(&[PI / 2.0, PI / 2.0, 0.0]), "up, then left: inside and free");
        assert!(!si.is_valid(&[-0.6, 0.0, 0.0]), "down and right, into the wall");
        assert!(!si.is_valid(&[PI / 2.0, PI, 0.0]), "the second link folded back onto the first");
        assert!(!si.is_valid(&[PI / 2.0, 2.8, 2.5]), "the third link crosses the first");
        assert!(
            problem(r#", "self_collision": false"#).si.is_valid(&[PI / 2.0, 2.8, 2.5]),
            "allowed without self-collision"
        );
        let limited = problem(r#", "limits": [[-1, 2], [-1.5, 1.5], [-1.5, 1.5]]"#);
        assert!(limited.si.is_valid(&[PI / 2.0, 1.0, 0.5]));
        assert!(!limited.si.is_valid(&[PI / 2.0, 1.6, 0.0]), "second joint past its limit");
        assert!(!limited.si.is_valid(&[2.1, 0.0, 0.0]), "first joint past its limit");
    }

    #[test]
    fn touching_an_obstacle_is_allowed_only_when_the_scenario_says_so() {
        let text = |top: &str| {
            format!(
                r#"{{"bounds": [0, 0, 1, 1], "obstacles": [{{"rect": [0.0, 0.0, 1.0, 0.25]}}],
                    "robot": {{"kind": "arm", "base": [0.5, 0.5], "links": [0.25]}},
                    "start": [0], "goal": [0], "resolution": 0.01{top}}}"#
            )
        };
        let closed = Problem::from_scenario(&Scenario::from_json(&text("")).unwrap()).unwrap();
        let open =
            Problem::from_scenario(&Scenario::from_json(&text(r#", "touching_allowed": true"#)).unwrap()).unwrap();
        let down = [-PI / 2.0]; // the link's end at (0.5, 0.25), on the obstacle's top edge
        assert!(!closed.si.is_valid(&down), "closed obstacles: touching collides");
        assert!(open.si.is_valid(&down), "open obstacles: touching is allowed");
    }

    #[test]
    fn an_arm_cannot_sweep_through_a_thin_post_between_checked_states() {
        // One link of 0.4 from (0.5, 0.5); a post of radius 0.005 at angle 0.3. At a resolution of
        // 0.25 rad the checked states (0.2, 0.4, 0.6) all miss it; certification must not.
        let text = r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"circle": [0.8821, 0.6182, 0.005]}],
            "robot": {"kind": "arm", "base": [0.5, 0.5], "links": [0.4], "metric": "joint"},
            "start": [0], "goal": [0.6], "resolution": 0.25}"#;
        let p = Problem::from_scenario(&Scenario::from_json(text).unwrap()).unwrap();
        let mut s = [0.0];
        for q in [0.0, 0.2, 0.4, 0.6] {
            assert!(p.si.is_valid(&[q]), "checked state {q} is free");
        }
        assert!(p.si.check_motion(&[0.0], &[0.6], &mut s).is_err());
        assert!((s[0] - 0.3).abs() < 0.05, "found near the post: {s:?}");
        assert!(p.si.check_motion(&[0.0], &[0.2], &mut s).is_ok(), "stopping short of it is fine");
    }
}

/// The arm's motion clearance carried from one motion to another by
/// [`MotionModel::motion_rate_ratio`] never exceeds the clearance computed on the other motion
/// (it is a lower bound, so a walk's carried step stays certified), and for two steps along one
/// line it is that clearance but for rounding.
#[test]
fn an_arms_carried_motion_clearance_is_a_lower_bound() {
    let p = arm::problem("");
    let arm = ArmRobot::from_spec(&p.scenario.robot).unwrap();
    let ws = p.si.workspace();
    let mut rng = crate::rng::Rng::new(7);
    let state = |rng: &mut crate::rng::Rng| [0; 3].map(|_| rng.uniform(-crate::math::PI, crate::math::PI));
    let (mut compared, mut collinear) = (0, 0);
    for k in 0..4000 {
        let (pa, q) = (state(&mut rng), state(&mut rng));
        if !p.si.is_valid(&q) {
            continue;
        }
        let pb: Vec<Real> = pa.iter().map(|v| v + rng.uniform(-0.1, 0.1)).collect();
        // Half the time a motion along the same line (the walk's next step, shorter or longer),
        // else any other.
        let along = k % 2 == 0;
        let (a, b): (Vec<Real>, Vec<Real>) = if along {
            let s = rng.uniform(0.2, 1.5);
            (pb.clone(), pb.iter().zip(&pa).map(|(y, x)| y + s * (y - x)).collect())
        } else {
            let a: Vec<Real> = state(&mut rng).to_vec();
            let b = a.iter().map(|v| v + rng.uniform(-0.1, 0.1)).collect();
            (a, b)
        };
        let Some(mu) = arm.motion_rate_ratio(&pa, &pb, &a, &b) else { continue };
        let before = arm.motion_clearance(ws, &pa, &pb, &q, Real::INFINITY).unwrap();
        let now = arm.motion_clearance(ws, &a, &b, &q, Real::INFINITY).unwrap();
        assert!(before / mu <= now, "{pa:?} → {pb:?}, then {a:?} → {b:?} at {q:?}: {before} / {mu} > {now}");
        if along && now.is_finite() {
            assert!(before / mu >= now * (1.0 - 1e-9), "along a line: {before} / {mu} against {now}");
            collinear += 1;
        }
        compared += 1;
    }
    assert!(compared > 1000 && collinear > 500, "{compared} compared, {collinear} along a line");
}

mod capabilities {
    use super::super::*;
    use super::{bar, ws};
    use crate::motion::MotionValidator;
    use crate::planners::{self, Params, Task};
    use crate::space_info::SpaceInfo;
    use crate::validity::RobotInWorkspace;
    use std::rc::Rc;

    /// A point with only the core: no motion model, sampler, body or sensor.
    #[derive(Debug)]
    struct Bare;

    /// Its record: a kind no scenario names.
    static BARE: crate::robot::kinds::RobotKind =
        crate::robot::kinds::RobotKind { name: "bare", ..crate::robot::point::KIND };

    impl Robot for Bare {
        fn caps(&self) -> &'static crate::robot::kinds::RobotKind {
            &BARE
        }
        fn space(&self, ws: &Workspace) -> StateSpace {
            PointRobot.space(ws)
        }
        fn external_dims(&self) -> usize {
            2
        }
        fn verdict(&self, ws: &Workspace, q: &[Real]) -> Verdict {
            PointRobot.verdict(ws, q)
        }
        fn project(&self, q: &[Real]) -> Vec2 {
            Vec2::new(q[0], q[1])
        }
        fn outline(&self, _q: &[Real]) -> Vec<Vec<Vec2>> {
            Vec::new()
        }
    }

    fn si(robot: Rc<dyn Robot>) -> SpaceInfo {
        let workspace = ws();
        SpaceInfo::new(robot.space(&workspace), RobotInWorkspace { robot, workspace }, 0.01)
    }

    #[test]
    fn each_robot_has_what_the_table_says() {
        let has =
            |r: &dyn Robot| (r.motion().is_some(), r.sampler().is_some(), r.body().is_some(), r.sensor().is_some());
        assert_eq!(has(&PointRobot), (true, false, true, true));
        assert_eq!(has(&bar()), (true, false, true, true));
        let arm = ArmRobot::from_spec(&super::arm::problem("").scenario.robot).unwrap();
        assert_eq!(has(&arm), (true, false, false, true));
        let spec = RobotSpec::Asv { count: 3, broom: 0.05, min_area: 0.0, convex: true, max_step: 0.001 };
        assert_eq!(has(&AsvRobot::from_spec(&spec).unwrap()), (true, true, false, true));
        assert_eq!(has(&Bare), (false, false, false, false));
        assert_eq!(bar().size(), (0.2, 0.03));
    }

    #[test]
    fn a_robot_with_only_the_core_plans_with_discrete_checks_and_is_refused_where_it_lacks_a_capability() {
        let si = si(Rc::new(Bare));
        assert!(si.body().is_none() && si.sensor().is_none() && si.own_sampler().is_none());
        let mut s = [0.0; 2];
        // Discrete checks only: every state at the resolution counted, nothing more.
        let (a, b) = ([0.1, 0.5], [0.2, 0.5]);
        assert!(si.check_motion(&a, &b, &mut s).is_ok());
        assert_eq!(si.checks(), DiscreteOnly.steps(&a, &b, si.distance(&a, &b), 0.01).unwrap() as u64);
        assert!(si.check_motion(&[0.1, 0.5], &[0.9, 0.2], &mut s).is_err(), "through the wall");
        let task = Task { start: vec![0.1, 0.5], goal: Some(vec![0.9, 0.5]), goal_tolerance: 0.0, inspection: None };
        for name in ["potential-field", "hex-potential", "inspection"] {
            let spec = planners::find(name).unwrap();
            let err = (spec.make)(&si, &task, &Params::defaults(spec)).err().expect(name);
            assert!(err.contains("bare") || err.contains("needs a point"), "{name}: {err}");
        }
        let rrt = planners::find("rrt").unwrap();
        assert!((rrt.make)(&si, &task, &Params::defaults(rrt)).is_ok());
    }
}

use super::*;
use crate::problem::Problem;
use crate::scenario::{builtin, Scenario};
use crate::space::in_bisection_order;
use crate::space_info::SpaceInfo;

#[test]
fn bisection_order_checks_every_step_once() {
    let p = Problem::from_scenario(&builtin("narrow").unwrap()).unwrap();
    let si = &p.si;
    let (a, b) = ([0.1, 0.1], [0.4, 0.1]);
    let mut s = [0.0; 2];
    si.reset_checks();
    assert!(si.check_motion(&a, &b, &mut s).is_ok());
    let n = (0.3 / si.resolution).ceil() as u64;
    assert_eq!(si.checks(), n, "one check per step, end included");
    assert!(si.check_motion(&a, &[0.9, 0.1], &mut s).is_err());
    assert!(s[0] >= 0.45 && s[0] <= 0.55, "the state reported is inside the wall: {s:?}");
}

fn coarse_square_past_a_pin(resolution: f64) -> Problem {
    // A 0.02 square moving along y = 0.5 past a disc of radius 0.01 at (0.45, 0.5); with a coarse
    // resolution of 0.1 every checked state (x = 0.2, 0.3, ...) is free, the motion is not.
    let text = format!(
        r#"{{"bounds": [0,0,1,1], "obstacles": [{{"circle": [0.45, 0.5, 0.01]}}],
            "robot": {{"kind": "rigid", "footprint": [[-0.01,-0.01],[0.01,-0.01],[0.01,0.01],[-0.01,0.01]], "rotation_weight": 0.1}},
            "start": [0.2, 0.5, 0], "goal": [0.8, 0.5, 0], "resolution": {resolution}}}"#
    );
    Problem::from_scenario(&Scenario::from_json(&text).unwrap()).unwrap()
}

#[test]
fn a_body_cannot_jump_over_an_obstacle_between_checked_states() {
    let p = coarse_square_past_a_pin(0.1);
    let mut s = [0.0; 3];
    let (a, b) = ([0.2, 0.5, 0.0], [0.8, 0.5, 0.0]);
    for k in 0..=6 {
        assert!(p.si.is_valid(&[0.2 + 0.1 * k as f64, 0.5, 0.0]), "checked state {k} is free");
    }
    assert!(p.si.check_motion(&a, &b, &mut s).is_err());
    assert!((s[0] - 0.45).abs() < 0.03, "collision found near the pin, at {s:?}");
    // Passing above the pin with room to spare is certified.
    assert!(p.si.check_motion(&[0.2, 0.6, 0.0], &[0.8, 0.6, 0.0], &mut s).is_ok());
}

#[test]
fn certification_refines_close_to_an_obstacle_without_rejecting_a_free_motion() {
    let p = coarse_square_past_a_pin(0.1);
    let mut s = [0.0; 3];
    // 0.0005 of clearance above the pin: free, but far less than a step's displacement.
    let y = 0.5 + 0.01 + 0.01 + 0.0005;
    p.si.reset_checks();
    assert!(p.si.check_motion(&[0.2, y, 0.0], &[0.8, y, 0.0], &mut s).is_ok());
    assert!(p.si.checks() > 7, "refined near the pin: {} checks", p.si.checks());
    // Rotating in place next to the pin: the corners sweep into it.
    let near = [0.45, 0.5 + 0.01 + 0.0105, 0.0];
    assert!(p.si.is_valid(&near));
    assert!(p.si.check_motion(&near, &[0.45, near[1], 0.8], &mut s).is_err());
}

#[test]
fn bisection_order_visits_each_index_once_coarse_first() {
    for n in 1..70 {
        let mut seen = Vec::new();
        in_bisection_order::<()>(n, |i| {
            seen.push(i);
            Ok(())
        })
        .unwrap();
        let mut sorted = seen.clone();
        sorted.sort();
        assert_eq!(sorted, (1..n).collect::<Vec<_>>(), "n = {n}");
        if n >= 4 {
            assert_eq!(seen[0], n.next_power_of_two() / 2, "the middle first");
        }
    }
}

/// Whether the motion `a → b` is free by a dense check: states `step` apart in the motion's
/// parameter (an approximation for the differential test below).
fn dense_free(si: &SpaceInfo, a: &[Real], b: &[Real], steps: usize) -> bool {
    let mut q = vec![0.0; a.len()];
    (0..=steps).all(|i| {
        si.interpolate(a, b, i as Real / steps as Real, &mut q);
        si.is_valid(&q)
    })
}

/// The arm's certification (in units of the motion) against a dense check: every motion it
/// accepts is free at 20 000 states along it; every motion it refuses, it refuses at a state that
/// is really invalid (even where the dense check stepped over it), except at most 1% of the free
/// ones (a graze, where bisection reaches its depth).
/// Random short and long motions on the arm maps, valid starts.
#[test]
fn arm_certification_agrees_with_a_dense_check() {
    for name in ["technion-mp", "horn-10", "arm-3"] {
        let p = Problem::from_scenario(&builtin(name).unwrap()).unwrap();
        let si = &p.si;
        let mut rng = crate::rng::Rng::new(11);
        let n = si.dims();
        let (mut a, mut b, mut far, mut s) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let (mut tried, mut free, mut refused_free) = (0, 0, 0);
        while tried < 400 {
            si.sample(&mut rng, &mut a);
            si.sample(&mut rng, &mut far);
            if !si.is_valid(&a) {
                continue;
            }
            si.interpolate(&a, &far, rng.uniform01() * 0.3, &mut b);
            tried += 1;
            let certified = si.check_motion(&a, &b, &mut s).is_ok();
            let dense = dense_free(si, &a, &b, 20000);
            assert!(!certified || dense, "{name}: certified a motion the dense check finds blocked: {a:?} → {b:?}");
            free += usize::from(dense);
            // A refusal names the state it found invalid: if that state is invalid, the dense
            // check stepped over it (a wrapping joint passing a fold at ±π, a band of 1e-9).
            let found_invalid = !certified && !si.is_valid(&s);
            refused_free += usize::from(dense && !certified && !found_invalid);
        }
        assert!(free > 40, "{name}: only {free} free motions drawn");
        assert!(refused_free * 100 <= free, "{name}: {refused_free} of {free} free motions refused");
    }
}

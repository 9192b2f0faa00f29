use crate::math::Real;
use crate::motion::MotionValidator;
use crate::problem::Problem;
use crate::scenario::Scenario;

fn problem(text: &str) -> Problem {
    Problem::from_scenario(&Scenario::from_json(text).unwrap()).unwrap()
}

/// A 3-link planar arm (its motions certified by clearances along the motion).
fn arm() -> Problem {
    problem(
        r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"rect": [0.85, 0.0, 0.95, 0.4]}],
            "robot": {"kind": "arm", "base": [0.5, 0.5], "links": [0.2, 0.15, 0.1]},
            "start": [1.5, 1.5, 0], "goal": [1.5, 1.5, 0], "resolution": 0.01}"#,
    )
}

/// A small square (its motions certified by workspace clearances and a displacement bound).
fn square() -> Problem {
    problem(
        r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"circle": [0.5, 0.9, 0.05]}],
            "robot": {"kind": "rigid", "footprint": [[-0.01,-0.01],[0.01,-0.01],[0.01,0.01],[-0.01,0.01]], "rotation_weight": 0.1},
            "start": [0.2, 0.5, 0], "goal": [0.8, 0.5, 0], "resolution": 0.01}"#,
    )
}

/// Walk from `from` toward `to` in steps of the resolution as the last-free connect does (a
/// running sum of steps), each step checked by `check_step` (`carry`: continuing steps carry their
/// start's clearance). Returns each step's outcome and state checks, and the state found not free
/// (the walk's start when every step is free).
fn walk(p: &Problem, from: &[Real], to: &[Real], carry: bool) -> (Vec<(bool, u64)>, Vec<Real>) {
    let si = &p.si;
    let (d, delta) = (si.distance(from, to), si.resolution);
    let (mut prev, mut q, mut found) = (from.to_vec(), from.to_vec(), from.to_vec());
    let (mut step, mut out) = (delta.min(d), Vec::new());
    loop {
        si.interpolate(from, to, step / d, &mut q);
        let before = si.checks();
        let ok = si.check_step(&prev, &q, carry && !out.is_empty(), &mut found).is_ok();
        out.push((ok, si.checks() - before));
        if !ok || step >= d {
            return (out, found);
        }
        prev.copy_from_slice(&q);
        step = (step + delta).min(d);
    }
}

/// A long free walk certifies each step with the clearance at its start carried from the step
/// before: one clearance (a state check) fewer a step after the first, the same answers; in open
/// space the square's steps need no bisection, so it is one clearance a step, not two. (The arm's
/// steps here each need one bisection: three clearances a step before, two now.)
#[test]
fn a_free_walk_computes_one_clearance_per_step_after_the_first() {
    let cases: [(&str, Problem, Vec<Real>, Vec<Real>); 2] = [
        ("arm", arm(), vec![1.2, 0.3, -0.4], vec![2.6, -0.5, 0.6]),
        ("square", square(), vec![0.1, 0.3, 0.0], vec![0.9, 0.4, 1.0]),
    ];
    for (name, p, from, to) in &cases {
        let mut s = from.clone();
        assert!(p.si.check_motion(from, to, &mut s).is_ok(), "{name}: the whole motion is free");
        let (carried, _) = walk(p, from, to, true);
        let (again, _) = walk(p, from, to, false);
        assert!(carried.len() > 20, "{name}: a long walk ({} steps)", carried.len());
        assert_eq!(carried.len(), again.len());
        assert!(carried.iter().all(|(ok, _)| *ok), "{name}: every step free: {carried:?}");
        assert_eq!(carried[0], again[0], "{name}: the first step computes both ends' clearances");
        for (k, (c, a)) in carried.iter().zip(&again).enumerate().skip(1) {
            assert_eq!(c.1 + 1, a.1, "{name}: step {k}: one clearance fewer carried ({} against {})", c.1, a.1);
        }
        let (c, a): (u64, u64) = (carried.iter().map(|s| s.1).sum(), again.iter().map(|s| s.1).sum());
        eprintln!("{name}: {} steps, {c} state checks carrying, {a} not", carried.len());
    }
    let (carried, _) = walk(&cases[1].1, &cases[1].2, &cases[1].3, true);
    assert_eq!(carried[0].1, 2, "square: both ends' clearances on the first step");
    assert!(carried[1..].iter().all(|&(_, n)| n == 1), "square: one clearance a step after: {carried:?}");
}

/// Carrying changes how much is computed, never what is found: a walk into an obstacle stops at
/// the same step, found at the same state, and a walk that grazes one (its steps refined by
/// bisection) gives the same answers, with one clearance fewer a continuing step at most.
#[test]
fn a_walk_finds_the_same_collisions_with_and_without_carrying() {
    let cases: [(&str, Problem, Vec<Real>, Vec<Real>); 4] = [
        // Swinging down and right, the arm's hand runs into the wall.
        ("arm into the wall", arm(), vec![1.2, 0.3, -0.4], vec![-0.9, 0.1, 0.2]),
        // The square through the disc, and past it within a hair.
        ("square into the disc", square(), vec![0.1, 0.9, 0.0], vec![0.9, 0.9, 0.5]),
        ("square past the disc", square(), vec![0.1, 0.9 - 0.05 - 0.0103, 0.0], vec![0.9, 0.9 - 0.05 - 0.0103, 0.0]),
        ("arm near the wall", arm(), vec![0.0, 0.35, 0.0], vec![-0.3, 0.8, 0.0]),
    ];
    for (name, p, from, to) in &cases {
        let (carried, found) = walk(p, from, to, true);
        let (again, found_again) = walk(p, from, to, false);
        assert_eq!(carried.len(), again.len(), "{name}: the walk stops at the same step");
        assert_eq!(found, found_again, "{name}: the same state found");
        for (k, (c, a)) in carried.iter().zip(&again).enumerate() {
            assert_eq!(c.0, a.0, "{name}: step {k}'s answer");
            // A free continuing step saves its start's clearance; a step found not free saves it
            // when it was computed (the end was free), else nothing.
            let saved = a.1 - c.1;
            assert!(
                if k > 0 && c.0 { saved == 1 } else { saved <= u64::from(k > 0) },
                "{name}: step {k}: {} checks carried, {} not",
                c.1,
                a.1
            );
        }
        eprintln!("{name}: {} steps, last free: {}", carried.len(), carried.last().unwrap().0);
    }
}

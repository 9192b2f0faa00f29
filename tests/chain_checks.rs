//! The kinematic chain in the horn at OMPL's range: a motion that turns a joint through ±π folds
//! two links and is refused at once, rather than after its discrete states and 40 levels of
//! certifying bisection (`docs/performance.md`, "The chain's checks against OMPL's"). The trees
//! are the same as before; only the checks spent on refusing those motions went.

use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::run::{RunConfig, Session};
use planarium::scenario::builtin;
use serde_json::json;

/// Median checks and iterations of `planner` on horn-10 at range 6.2832 over seeds 1..=20; every
/// run must solve. The range is the one the comparison with OMPL passes (`--range 6.2832`, the
/// suite's rounding of 0.2 × the extent), not 2π.
#[allow(clippy::approx_constant)]
fn medians(planner: &str) -> (u64, u64) {
    let sc = builtin("horn-10").unwrap();
    let spec = planners::find(planner).unwrap();
    let (mut checks, mut iterations) = (Vec::new(), Vec::new());
    for seed in 1..=20 {
        let params = Params::from_json(spec, &json!({"range": 6.2832})).unwrap();
        let mut s = Session::new(
            Problem::from_scenario(&sc).unwrap(),
            RunConfig { planner: planner.into(), params, seed, record_events: false },
        )
        .unwrap();
        s.run_to_end();
        assert_eq!(s.status().name(), "solved", "{planner}, seed {seed}");
        checks.push(s.stats().checks);
        iterations.push(s.stats().iterations);
    }
    checks.sort_unstable();
    iterations.sort_unstable();
    (checks[10], iterations[10])
}

#[test]
fn horn_10_rrt_spends_no_certification_on_folds() {
    // Before the fold was refused up front: 5,655 checks (the upper middle of the 20 runs);
    // since: 4,031. The iterations did not move (the same trees).
    let (checks, iterations) = medians("rrt");
    eprintln!("rrt: median {checks} checks, {iterations} iterations");
    assert!(checks < 4_500, "rrt: median {checks} checks");
    assert_eq!(iterations, 2_350, "rrt: the same trees as before");
}

#[test]
fn horn_10_rrt_connect_spends_no_certification_on_folds() {
    // Before: 14,111 checks; since: 9,891.
    let (checks, iterations) = medians("rrt-connect");
    eprintln!("rrt-connect: median {checks} checks, {iterations} iterations");
    assert!(checks < 11_000, "rrt-connect: median {checks} checks");
    assert_eq!(iterations, 5_445, "rrt-connect: the same trees as before");
}

#[test]
fn a_motion_through_a_fold_is_refused_as_one_check_of_the_folded_state() {
    use planarium::motion::MotionValidator;
    let p = Problem::from_scenario(&builtin("horn-10").unwrap()).unwrap();
    let si = &p.si;
    // From the start, joint 5 turns from 3.0 the short way round to −3.0: through π, a fold.
    let a = p.start.clone();
    let (mut b, mut scratch) = (a.clone(), a.clone());
    b[5] = -3.0;
    let mut through = a.clone();
    through[5] = 3.0;
    let before = si.checks();
    assert!(si.check_motion(&through, &b, &mut scratch).is_err());
    assert_eq!(si.checks() - before, 1, "one check, of the folded state");
    assert!(
        (std::f64::consts::PI - scratch[5].abs()).abs() < 1e-9,
        "the state refused: joint 5 at ±π, not {}",
        scratch[5]
    );
    assert!(!si.is_valid(&scratch), "the folded state is invalid");
    // From the start (valid), joint 5 turning a little does not fold: checked by clearances at
    // its states (more than one check) and free.
    let mut c = a.clone();
    c[5] += 0.05;
    let before = si.checks();
    assert!(si.check_motion(&a, &c, &mut scratch).is_ok());
    assert!(si.checks() - before > 1, "a motion that does not fold is checked state by state");
}

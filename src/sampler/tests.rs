//! Tests of the samplers' private building blocks: the Gaussian neighbour (spread, wrapping,
//! reflection into the bounds) and the logging of checked draws. Each sampler's defining property
//! is tested through the public API in `tests/samplers.rs`.

use super::Draw;
use crate::events::{EventKind, EventLog, STRIDE};
use crate::math::{angle_diff, Real};
use crate::problem::Problem;
use crate::rng::Rng;
use crate::scenario::builtin;
use crate::space::reflect;

fn problem(name: &str) -> Problem {
    Problem::from_scenario(&builtin(name).unwrap()).unwrap()
}

/// Mean and standard deviation.
fn moments(xs: &[Real]) -> (Real, Real) {
    let n = xs.len() as Real;
    let mean = xs.iter().sum::<Real>() / n;
    (mean, (xs.iter().map(|x| (x - mean).powi(2)).sum::<Real>() / (n - 1.0)).sqrt())
}

/// `n` Gaussian neighbours of `centre` with `sigma`, on `p`'s space, seeded.
fn neighbours(p: &Problem, centre: &[Real], sigma: Real, n: usize) -> Vec<Vec<Real>> {
    let mut rng = Rng::new(11);
    let mut events = EventLog::new(false);
    let mut d = Draw { si: &p.si, rng: &mut rng, events: &mut events, tree: 0 };
    (0..n)
        .map(|_| {
            let mut out = vec![0.0; centre.len()];
            d.gaussian_near(centre, sigma, &mut out);
            out
        })
        .collect()
}

/// Catches: a reflection that leaves the bounds, is not the identity inside, mirrors about the
/// wrong point, or loses the periodicity of repeated folds.
#[test]
fn reflect_folds_into_the_bounds() {
    assert_eq!(reflect(0.3, 0.0, 1.0), 0.3);
    assert_eq!(reflect(0.0, 0.0, 1.0), 0.0);
    assert_eq!(reflect(1.0, 0.0, 1.0), 1.0);
    assert!((reflect(-0.25, 0.0, 1.0) - 0.25).abs() < 1e-15);
    assert!((reflect(1.25, 0.0, 1.0) - 0.75).abs() < 1e-15);
    assert!((reflect(2.25, 0.0, 1.0) - 0.25).abs() < 1e-15);
    assert!((reflect(-1.75, 0.0, 1.0) - 0.25).abs() < 1e-15);
    assert!((reflect(-3.0, -2.0, 2.0) - -1.0).abs() < 1e-15);
    for v in [-1e9, -7.3, -0.5, 0.999_999, 1e-300, 3.5, 1e12] {
        let r = reflect(v, -1.5, 2.0);
        assert!((-1.5..=2.0).contains(&r), "{v} → {r}");
    }
}

/// Catches: a spread not scaled by each coordinate's range (or scaled twice, or given as a
/// variance), a biased mean, and a bounded coordinate moved out of its bounds.
#[test]
fn gaussian_neighbour_has_sigma_times_the_range_per_coordinate() {
    // slot: x and y over the workspace bounds (ranges differ), θ wrapping over 2π.
    let p = problem("slot");
    let dims = p.si.space.dims.clone();
    let centre: Vec<Real> = dims.iter().map(|d| d.lo + 0.45 * (d.hi - d.lo)).collect();
    let sigma = 0.04;
    let xs = neighbours(&p, &centre, sigma, 6000);
    for (i, d) in dims.iter().enumerate() {
        let dev: Vec<Real> =
            xs.iter().map(|q| if d.wraps { angle_diff(centre[i], q[i]) } else { q[i] - centre[i] }).collect();
        let (mean, sd) = moments(&dev);
        let want = sigma * (d.hi - d.lo);
        assert!(mean.abs() < 4.0 * want / (dev.len() as Real).sqrt(), "coordinate {i}: mean deviation {mean}");
        assert!((sd / want - 1.0).abs() < 0.06, "coordinate {i}: sd {sd}, want {want}");
        assert!(xs.iter().all(|q| q[i] >= d.lo && q[i] <= d.hi), "coordinate {i} left its bounds");
    }
}

/// Catches: treating a wrapping angle as bounded (clamping or reflecting at ±π halves the spread
/// on one side and shifts the mean), and not wrapping the result into [−π, π).
#[test]
fn gaussian_neighbour_wraps_angles_across_pi() {
    let p = problem("arm-2");
    assert!(p.si.space.dims.iter().all(|d| d.wraps));
    let centre = [3.1, -3.1];
    let sigma = 0.03;
    let xs = neighbours(&p, &centre, sigma, 6000);
    let want = sigma * 2.0 * std::f64::consts::PI;
    for i in 0..2 {
        let dev: Vec<Real> = xs.iter().map(|q| angle_diff(centre[i], q[i])).collect();
        let (mean, sd) = moments(&dev);
        assert!(mean.abs() < 4.0 * want / (dev.len() as Real).sqrt(), "joint {i}: mean deviation {mean}");
        assert!((sd / want - 1.0).abs() < 0.06, "joint {i}: sd {sd}, want {want}");
        // About two fifths of them cross ±π, and come back wrapped.
        let crossed = xs.iter().filter(|q| q[i].signum() != centre[i].signum()).count();
        assert!(crossed > xs.len() / 5, "joint {i}: only {crossed} crossed ±π");
        assert!(xs.iter().all(|q| (-std::f64::consts::PI..std::f64::consts::PI).contains(&q[i])));
    }
}

/// Catches clamping: a neighbour of a state on a bound would sit exactly on the bound half the
/// time; reflected, none does, and the distance from the bound is a folded normal (mean
/// sigma·√(2/π)). A very wide spread must cover the range about uniformly, not pile up at the ends.
#[test]
fn gaussian_neighbour_is_reflected_at_the_bounds_not_clamped() {
    let p = problem("narrow");
    let (lo, hi) = (p.si.space.dims[0].lo, p.si.space.dims[0].hi);
    let sigma = 0.05;
    let xs = neighbours(&p, &[lo, 0.5], sigma, 6000);
    let on_bound = xs.iter().filter(|q| q[0] == lo).count();
    assert_eq!(on_bound, 0, "{on_bound} samples exactly on the bound");
    let dist: Vec<Real> = xs.iter().map(|q| q[0] - lo).collect();
    let (mean, _) = moments(&dist);
    let want = sigma * (hi - lo) * (2.0 / std::f64::consts::PI).sqrt();
    assert!((mean / want - 1.0).abs() < 0.05, "mean distance from the bound {mean}, want {want}");

    let wide = neighbours(&p, &[0.5, 0.5], 10.0, 6000);
    let at_ends = wide.iter().filter(|q| q[0] < 0.05 || q[0] > 0.95).count() as Real / wide.len() as Real;
    assert!((at_ends - 0.1).abs() < 0.03, "share within 0.05 of either end: {at_ends}");
    let (mean, sd) = moments(&wide.iter().map(|q| q[0]).collect::<Vec<_>>());
    assert!((mean - 0.5).abs() < 0.02 && (sd - (1.0 / 12.0 as Real).sqrt()).abs() < 0.02, "mean {mean}, sd {sd}");
}

/// Catches: a check that is not counted, a wrong verdict in the event's `id`, and an event without
/// the state's point and first two coordinates (`c0`, `c1`) that the configuration-space view uses.
#[test]
fn checked_draws_are_logged_with_the_state() {
    let p = problem("arm-2");
    let mut rng = Rng::new(1);
    let mut events = EventLog::new(true);
    let mut d = Draw { si: &p.si, rng: &mut rng, events: &mut events, tree: 1 };
    let mut q = [0.0; 2];
    let checks0 = p.si.checks();
    let mut verdicts = Vec::new();
    let mut states = Vec::new();
    for _ in 0..50 {
        d.uniform(&mut q);
        verdicts.push(d.check(&q));
        states.push(q);
    }
    assert_eq!(p.si.checks() - checks0, 50);
    let recs = events.records();
    assert_eq!(recs.len(), 50 * STRIDE);
    assert!(verdicts.iter().any(|v| *v) && verdicts.iter().any(|v| !*v));
    for (k, r) in recs.chunks(STRIDE).enumerate() {
        let pt = p.si.project(&states[k]);
        assert_eq!(r[0], EventKind::SampleTry as u8 as f64);
        assert_eq!(r[1], 1.0);
        assert_eq!(r[2], verdicts[k] as u8 as f64);
        assert_eq!(r[3], -1.0);
        assert_eq!((r[4], r[5]), (pt.x, pt.y));
        assert_eq!((r[8], r[9]), (states[k][0], states[k][1]));
    }
}

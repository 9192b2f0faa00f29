//! The samplers, each tested for its defining property through the public API: the states it
//! judged by ([`Sampler::witnesses`], [`Sampler::centre`]), the `SampleTry` events it logged for
//! every check (read back as a trace and replayed against the sampler's rule), and its statistics.
//! Then every sampler on every built-in robot: samples in bounds, valid where the sampler checks,
//! not all given up, and the same for the same seed. (The Gaussian neighbour itself, its wrapping
//! and its reflection at the bounds, is tested in `src/sampler/tests.rs`.)

mod common;

use planarium::events::{EventKind, EventLog, STRIDE};
use planarium::math::{angle_diff, Real, PI};
use planarium::planners::{self, Params};
use planarium::problem::Problem;
use planarium::rng::Rng;

use planarium::sampler::{Draw, Kind, Sampler, NAMES};
use planarium::scenario::{builtin, builtin_names};
use planarium::space::Metric;
use serde_json::{json, Value};

/// One robot of each kind, and the spaces that differ: a point, a rigid polygon, arms with wrapping
/// joints, joint limits, the chain metrics and long links, and the vehicle chain.
const ROBOTS: &[&str] = &["narrow", "slot", "arm-2", "arm-3", "horn-10", "technion-mp", "asv-3", "asv-7"];

/// A sampler on a built-in problem, with its own generator and an event log that records.
struct Bench {
    p: Problem,
    s: Sampler,
    rng: Rng,
    events: EventLog,
    out: Vec<Real>,
}

impl Bench {
    /// A sampler on `scenario` with `params`; in its pure form (no uniform share) unless `params`
    /// names `uniform_share`, since most tests here check one rule's own samples.
    fn new(scenario: &str, mut params: Value, seed: u64) -> Bench {
        let p = Problem::from_scenario(&builtin(scenario).unwrap()).unwrap();
        params.as_object_mut().unwrap().entry("uniform_share").or_insert(json!(0.0));
        let params = Params::from_json(planners::find("rrt-connect").unwrap(), &params).unwrap();
        let s = Sampler::from_params(&p.si, p.goal.as_deref(), &params);
        let out = vec![0.0; p.si.dims()];
        Bench { p, s, rng: Rng::new(seed), events: EventLog::new(true), out }
    }
    /// Draw one sample into `out`; whether it was accepted, and the events it logged.
    fn sample(&mut self) -> (bool, Vec<f64>) {
        self.events.drain();
        let mut d = Draw { si: &self.p.si, rng: &mut self.rng, events: &mut self.events, tree: 0 };
        let ok = self.s.sample(&mut d, &mut self.out);
        (ok, self.events.drain())
    }
    fn valid(&self, q: &[Real]) -> bool {
        self.p.si.is_valid(q)
    }
    /// `b − a` per coordinate as a fraction of its range (the short way round a wrapping angle).
    fn deviation(&self, a: &[Real], b: &[Real]) -> Vec<Real> {
        let dims = &self.p.si.space.dims;
        (0..a.len())
            .map(|i| if dims[i].wraps { angle_diff(a[i], b[i]) } else { b[i] - a[i] } / (dims[i].hi - dims[i].lo))
            .collect()
    }
    /// Whether `q` is inside the space's bounds, wrapping angles in [−π, π).
    fn in_bounds(&self, q: &[Real]) -> bool {
        self.p
            .si
            .space
            .dims
            .iter()
            .zip(q)
            .all(|(d, &v)| if d.wraps { (-PI..PI).contains(&v) } else { v >= d.lo && v <= d.hi })
    }
}

/// One `SampleTry` record: whether the state was free, and its first two coordinates.
#[derive(Clone, Copy, Debug)]
struct Try {
    free: bool,
    c: (f64, f64),
}

fn tries(events: &[f64]) -> Vec<Try> {
    events
        .chunks(STRIDE)
        .filter(|r| r[0] == EventKind::SampleTry as u8 as f64)
        .map(|r| {
            assert!(r[2] == 0.0 || r[2] == 1.0, "a SampleTry's id is 1 (free) or 0 (occupied), found {}", r[2]);
            Try { free: r[2] == 1.0, c: (r[8], r[9]) }
        })
        .collect()
}

/// Replay one sample's trace of checks against the rule of sampler `name` (`tries`: its
/// `sampler_tries`); returns the raw draws the trace shows. Panics where the trace breaks the rule:
/// a pair kept that is not one free and one occupied, a bridge kept whose ends are not both
/// occupied or whose midpoint is not free, a walk that goes on after an occupied state, giving up
/// before the tries are spent, or drawing on after they are.
fn replay(name: &str, trace: &[Try], accepted: bool, tries: usize) -> usize {
    match name {
        "gaussian" => {
            assert_eq!(trace.len() % 2, 0, "gaussian checks pairs");
            let pairs: Vec<_> = trace.chunks(2).collect();
            for (k, pair) in pairs.iter().enumerate() {
                let mixed = pair[0].free != pair[1].free;
                assert_eq!(mixed, accepted && k + 1 == pairs.len(), "pair {k} of {}: {pair:?}", pairs.len());
            }
            if accepted {
                assert!(!pairs.is_empty(), "an accepted gaussian sample checked its pair");
            } else {
                assert_eq!(pairs.len(), tries);
            }
            trace.len()
        }
        "bridge" => {
            let (mut k, mut attempts, mut draws, mut kept) = (0, 0, 0, false);
            while k < trace.len() {
                attempts += 1;
                draws += 1;
                if trace[k].free {
                    k += 1;
                    continue;
                }
                assert!(k + 1 < trace.len(), "an occupied first end is followed by its neighbour");
                draws += 1;
                if trace[k + 1].free {
                    k += 2;
                    continue;
                }
                assert!(k + 2 < trace.len(), "two occupied ends are followed by their midpoint");
                if trace[k + 2].free {
                    assert!(accepted && k + 3 == trace.len(), "a free midpoint ends the sample");
                    kept = true;
                } else {
                    assert!(k + 3 < trace.len() || !accepted);
                }
                k += 3;
            }
            assert_eq!(kept, accepted, "a bridge is kept exactly when its midpoint is free");
            assert!(attempts <= tries);
            if !accepted {
                assert_eq!(attempts, tries);
            }
            draws
        }
        "obstacle" => {
            let (mut free, mut occupied) = (false, false);
            let (mut k, mut attempts) = (0, 0);
            while k < trace.len() && !(free && occupied) {
                attempts += 1;
                if !free {
                    free = trace[k].free;
                    k += 1;
                }
                if !occupied {
                    assert!(k < trace.len(), "an attempt draws both missing witnesses");
                    occupied = !trace[k].free;
                    k += 1;
                }
            }
            assert!(attempts <= tries);
            assert_eq!(accepted, free && occupied);
            if !accepted {
                assert_eq!(attempts, tries);
            }
            let walk = &trace[k..];
            if let Some((_, before)) = walk.split_last() {
                assert!(before.iter().all(|t| t.free), "the walk stops at the first occupied state");
            }
            k
        }
        _ => {
            assert!(trace.is_empty(), "{name} checks nothing");
            0
        }
    }
}

/// The default `sampler_tries`.
const TRIES: usize = 100;

/// Catches: keeping the occupied one of a pair, keeping a pair whose states are both free or both
/// occupied, a partner that is not a Gaussian neighbour (drawn uniformly, or with the wrong
/// spread), and a kept state that is not one of the pair.
#[test]
fn gaussian_keeps_the_free_one_of_a_uniform_and_gaussian_pair() {
    let sigma = 0.05;
    for name in ROBOTS {
        let mut b = Bench::new(name, json!({"sampler": "gaussian", "sigma": sigma}), 3);
        let mut accepted = 0;
        for _ in 0..150 {
            let (ok, events) = b.sample();
            replay("gaussian", &tries(&events), ok, TRIES);
            if !ok {
                continue;
            }
            accepted += 1;
            let (a, n) =
                b.s.witnesses()
                    .map(|(a, n)| (a.to_vec(), n.to_vec()))
                    .expect("an accepted gaussian sample has its pair");
            let (fa, fn_) = (b.valid(&a), b.valid(&n));
            assert_ne!(fa, fn_, "{name}: exactly one of the pair is free");
            assert_eq!(b.out, if fa { a.clone() } else { n.clone() }, "{name}: the sample is the free one of the pair");
            // Kept pairs are biased toward longer ones (they must straddle a boundary), but a
            // Gaussian neighbour is never more than a few sigma away.
            for (i, dev) in b.deviation(&a, &n).iter().enumerate() {
                assert!(dev.abs() < 6.0 * sigma, "{name}: coordinate {i} of the pair is {dev} of its range apart");
            }
        }
        assert!(accepted > 100, "{name}: {accepted} of 150 accepted");
    }

    // Every pair drawn (kept or not): on `narrow`, a point's coordinates are the state, so the
    // events show the pairs; a neighbour is a normal deviate of sigma × range (1) per coordinate,
    // for uniform states far enough from the bounds that reflection never applies.
    let mut b = Bench::new("narrow", json!({"sampler": "gaussian", "sigma": sigma}), 4);
    let mut devs = [Vec::new(), Vec::new()];
    for _ in 0..1000 {
        let (_, events) = b.sample();
        for pair in tries(&events).chunks(2) {
            let (a, n) = (pair[0].c, pair[1].c);
            if [a.0, a.1].iter().all(|v| (0.3..0.7).contains(v)) {
                devs[0].push(n.0 - a.0);
                devs[1].push(n.1 - a.1);
            }
        }
    }
    for (i, d) in devs.iter().enumerate() {
        let (mean, sd) = moments(d);
        assert!(d.len() > 1000, "{} pairs", d.len());
        assert!(mean.abs() < 4.0 * sigma / (d.len() as Real).sqrt(), "coordinate {i}: mean {mean}");
        assert!((sd / sigma - 1.0).abs() < 0.08, "coordinate {i}: sd {sd}, want {sigma}");
    }
}

/// Catches: a bridge kept with a free end, a sample that is not the midpoint of its ends (or is
/// occupied), ends that are not a Gaussian distance apart (the second drawn uniformly, or with the
/// wrong spread), and a midpoint taken the long way round a wrapping angle.
#[test]
fn bridge_keeps_the_free_midpoint_of_two_occupied_ends_a_gaussian_distance_apart() {
    let sigma = 0.05;
    for name in ROBOTS {
        let mut b = Bench::new(name, json!({"sampler": "bridge", "sigma": sigma}), 5);
        let n = bridge_samples(name);
        let mut accepted = 0;
        for _ in 0..n {
            let (ok, events) = b.sample();
            replay("bridge", &tries(&events), ok, TRIES);
            if !ok {
                continue;
            }
            accepted += 1;
            let (e1, e2) =
                b.s.witnesses().map(|(a, n)| (a.to_vec(), n.to_vec())).expect("an accepted bridge has its ends");
            assert!(!b.valid(&e1) && !b.valid(&e2), "{name}: both ends of a bridge are occupied");
            assert!(b.valid(&b.out), "{name}: the midpoint is free");
            let mut mid = vec![0.0; e1.len()];
            b.p.si.interpolate(&e1, &e2, 0.5, &mut mid);
            assert_eq!(b.out, mid, "{name}: the sample is the ends' midpoint");
            let (d1, d2) = (b.p.si.distance(&e1, &b.out), b.p.si.distance(&e2, &b.out));
            let chain = matches!(b.p.si.space.metric, Metric::ChainSum { .. } | Metric::ChainMax { .. });
            assert!(chain || (d1 - d2).abs() <= 1e-9 * (1.0 + d1), "{name}: the midpoint is halfway ({d1} and {d2})");
            for (i, dev) in b.deviation(&e1, &e2).iter().enumerate() {
                assert!(dev.abs() < 6.0 * sigma, "{name}: coordinate {i} of the ends is {dev} of its range apart");
            }
        }
        eprintln!("bridge on {name}: {accepted} of {n} accepted");
        assert!(accepted > 0, "{name}: no bridge in {n} samples");
    }

    // Every pair of ends drawn: the second end is a normal deviate of sigma × range around the
    // first, whatever becomes of the bridge. On `narrow`, an occupied first end is in the wall
    // (x in [0.45, 0.55]); keep those far enough from the y bounds for reflection not to apply.
    let mut b = Bench::new("narrow", json!({"sampler": "bridge", "sigma": sigma}), 6);
    let mut devs = [Vec::new(), Vec::new()];
    let mut kept = Vec::new();
    for _ in 0..400 {
        let (ok, events) = b.sample();
        let trace = tries(&events);
        let mut k = 0;
        while k < trace.len() {
            if trace[k].free {
                k += 1;
                continue;
            }
            let (a, n) = (trace[k].c, trace[k + 1].c);
            if (0.3..0.7).contains(&a.1) {
                devs[0].push(n.0 - a.0);
                devs[1].push(n.1 - a.1);
            }
            k += if trace[k + 1].free { 2 } else { 3 };
        }
        if ok {
            kept.push(b.out.clone());
        }
    }
    for (i, d) in devs.iter().enumerate() {
        let (mean, sd) = moments(d);
        assert!(d.len() > 1000, "{} pairs", d.len());
        assert!(mean.abs() < 4.0 * sigma / (d.len() as Real).sqrt(), "coordinate {i}: mean {mean}");
        assert!((sd / sigma - 1.0).abs() < 0.08, "coordinate {i}: sd {sd}, want {sigma}");
    }
    // The walls are convex and the space around them open: a free midpoint between two
    // occupied points can only be in the passage.
    assert!(kept.len() > 10, "{} bridges kept", kept.len());
    assert!(kept.iter().all(|q| in_passage(q)), "every bridge on narrow is in the passage");
}

/// Catches: a walk that starts from the occupied end, keeps an occupied state, stops before the
/// first occupied state or walks past it, steps more than the resolution, or keeps a state that
/// is not on the way from the free witness to the occupied one.
#[test]
fn obstacle_based_keeps_the_last_free_state_walking_toward_the_occupied_one() {
    for name in ROBOTS {
        let mut b = Bench::new(name, json!({"sampler": "obstacle"}), 7);
        let chain = matches!(b.p.si.space.metric, Metric::ChainSum { .. } | Metric::ChainMax { .. });
        let res = b.p.si.resolution;
        let mut accepted = 0;
        for _ in 0..120 {
            let (ok, events) = b.sample();
            let trace = tries(&events);
            let start = replay("obstacle", &trace, ok, TRIES);
            if !ok {
                continue;
            }
            accepted += 1;
            let (free, occ) =
                b.s.witnesses()
                    .map(|(a, n)| (a.to_vec(), n.to_vec()))
                    .expect("an accepted obstacle sample has its witnesses");
            assert!(b.valid(&free) && !b.valid(&occ), "{name}: the walk goes from a free state to an occupied one");
            // Walk again, independently of the sampler's bookkeeping: states on the way at the
            // resolution; the sample must be the one before the first occupied.
            let si = &b.p.si;
            let steps = ((si.distance(&free, &occ) / res).ceil() as usize).max(1);
            let at = |k: usize| -> Vec<Real> {
                let mut q = vec![0.0; free.len()];
                si.interpolate(&free, &occ, k as Real / steps as Real, &mut q);
                if k == 0 {
                    free.clone()
                } else if k == steps {
                    occ.clone()
                } else {
                    q
                }
            };
            let first_occupied = (1..=steps).find(|&k| !si.is_valid(&at(k))).expect("the end is occupied");
            assert_eq!(b.out, at(first_occupied - 1), "{name}: the sample is the last free state of the walk");
            assert!(b.valid(&b.out), "{name}: the sample is free");
            // One step is one resolution, except under the chain metrics (equal joint steps are
            // not equal link moves), where only the step in joint space is bounded.
            let gap = si.distance(&b.out, &at(first_occupied));
            assert!(
                chain || gap <= res * (1.0 + 1e-9),
                "{name}: the occupied state beyond the sample is {gap} away (resolution {res})"
            );
            // The trace's walk: one check per state up to the first occupied (the end is not checked again).
            let walked = trace.len() - start;
            assert_eq!(walked, first_occupied.min(steps - 1), "{name}: checks on the walk");
        }
        assert!(accepted > 0, "{name}: none of 120 accepted");
    }
}

/// Catches: a spread that is not collision_sigma × range, samples not centred on the collision
/// point, a collision that does not move the centre, and a wrapping joint treated as bounded.
#[test]
fn near_collision_samples_gather_around_the_collision_point() {
    let cs = 0.03;
    for (name, centre) in [("narrow", vec![0.3, 0.6]), ("slot", vec![]), ("arm-2", vec![3.1, -3.1])] {
        let mut b = Bench::new(
            name,
            json!({"sampler": "near-collision", "collision_sigma": cs, "random_sigma": 0.5, "perseverance": 1e6}),
            8,
        );
        let dims = b.p.si.space.dims.clone();
        let c: Vec<Real> =
            if centre.is_empty() { dims.iter().map(|d| d.lo + 0.4 * (d.hi - d.lo)).collect() } else { centre };
        // A few samples around a random centre first, then the collision.
        for _ in 0..5 {
            b.sample();
        }
        b.s.note_collision(&c);
        let (cc, sigma, _) = b.s.centre().unwrap();
        assert_eq!((cc.to_vec(), sigma), (c.clone(), cs), "{name}: the centre is the collision point");
        let n = 4000;
        let mut devs = vec![Vec::new(); dims.len()];
        for _ in 0..n {
            let (ok, events) = b.sample();
            assert!(ok && events.is_empty(), "{name}: near-collision always succeeds and checks nothing");
            for (i, d) in b.deviation(&c, &b.out.clone()).into_iter().enumerate() {
                devs[i].push(d);
            }
        }
        for (i, d) in devs.iter().enumerate() {
            let (mean, sd) = moments(d);
            assert!(
                mean.abs() < 4.0 * cs / (n as Real).sqrt(),
                "{name}: coordinate {i}: mean deviation {mean} of the range"
            );
            assert!((sd / cs - 1.0).abs() < 0.06, "{name}: coordinate {i}: sd {sd} of the range, want {cs}");
        }
    }
}

/// Catches: re-centring on the wrong count, a collision that resets the count (report 001 does
/// not), re-centring that keeps the collision point or its sigma, and centres drawn but not
/// counted as draws.
#[test]
fn near_collision_recentres_at_random_every_perseverance_samples() {
    let mut b = Bench::new(
        "narrow",
        json!({"sampler": "near-collision", "collision_sigma": 0.01, "random_sigma": 0.4, "perseverance": 5}),
        9,
    );
    assert!(b.s.centre().is_none());
    b.sample();
    let (r1, sigma, count) = b.s.centre().map(|(c, s, n)| (c.to_vec(), s, n)).unwrap();
    assert_eq!((sigma, count), (0.4, 1), "the first sample re-centres at random");
    b.sample();
    b.sample();
    assert_eq!(b.s.centre().unwrap().0, &r1[..]);
    let c = [0.45, 0.3];
    b.s.note_collision(&c);
    assert_eq!(b.s.centre().unwrap(), (&c[..], 0.01, 3), "a collision moves the centre and keeps the count");
    b.sample();
    b.sample();
    assert_eq!(b.s.centre().unwrap(), (&c[..], 0.01, 5));
    assert!(b.out.iter().zip(&c).all(|(x, y)| (x - y).abs() < 0.01 * 6.0), "{:?} is not near the collision", b.out);
    b.sample();
    let (r2, sigma, count) = b.s.centre().map(|(c, s, n)| (c.to_vec(), s, n)).unwrap();
    assert_eq!((sigma, count), (0.4, 1), "the sixth sample re-centres at random");
    assert!(r2 != c && r2 != r1);
    assert_eq!(b.s.stats().draws, 6 + 2, "six samples and two random centres");
    // Without collisions: a new random centre every 5 samples.
    let mut centres = vec![r2];
    for _ in 0..20 {
        b.sample();
        let now = b.s.centre().unwrap().0.to_vec();
        if now != *centres.last().unwrap() {
            centres.push(now);
        }
    }
    assert_eq!(centres.len(), 1 + 4, "samples 7..26: new centres at 11, 16, 21, 26");
}

/// Catches: a goal bias ignored, inverted or applied twice; a goal sample that is not exactly the
/// goal, that spends checks, or that leaves the previous witnesses in place.
#[test]
fn goal_bias_returns_the_goal_with_its_probability() {
    for sampler in ["goal-biased", "obstacle", "near-collision"] {
        let mut b = Bench::new("narrow", json!({"sampler": sampler, "goal_bias": 0.3}), 10);
        let goal = b.p.goal.clone().unwrap();
        let n = 4000;
        let mut goals = 0;
        for _ in 0..n {
            let (ok, events) = b.sample();
            assert!(ok);
            if b.out == goal {
                goals += 1;
                assert!(events.is_empty(), "{sampler}: a goal sample checks nothing");
                assert!(b.s.witnesses().is_none(), "{sampler}: a goal sample has no witnesses");
            }
        }
        let f = goals as Real / n as Real;
        let sd = (0.3 * 0.7 / n as Real).sqrt();
        assert!((f - 0.3).abs() < 4.5 * sd, "{sampler}: the goal in {f} of the samples, want 0.3");
    }
    let mut b = Bench::new("narrow", json!({"sampler": "goal-biased", "goal_bias": 0.3}), 11);
    assert_eq!((b.s.name(), b.s.kind()), ("goal-biased", Kind::Uniform));
    for _ in 0..100 {
        b.sample();
    }
    assert_eq!(b.s.stats().draws, 100, "a goal sample is one draw, like a uniform one");
    assert_eq!(b.s.stats().checks, 0);

    let mut b = Bench::new("narrow", json!({"sampler": "goal-biased"}), 12);
    let goal = b.p.goal.clone().unwrap();
    assert!((0..2000).all(|_| b.sample().0 && b.out != goal), "no goal bias, no goal");
}

/// Catches: statistics that miss or double-count draws or checks (the goal, a near-collision
/// centre, a bridge's midpoint, the obstacle walk), count a failed sample as accepted, or
/// report per-sample ratios of something else.
#[test]
fn statistics_count_what_the_sampler_spent() {
    for name in ["narrow", "arm-2", "asv-3"] {
        for sampler in NAMES {
            let tries_ = 20;
            let mut b = Bench::new(
                name,
                json!({"sampler": sampler, "sampler_tries": tries_, "goal_bias": 0.1, "perseverance": 7}),
                13,
            );
            let goal = b.p.goal.clone().unwrap();
            let checks0 = b.p.si.checks();
            let (mut accepted, mut failed, mut draws, mut events_seen) = (0u64, 0u64, 0u64, 0u64);
            for k in 0..300 {
                if *sampler == "near-collision" && k % 11 == 10 {
                    let q = b.out.clone();
                    b.s.note_collision(&q);
                }
                let (ok, events) = b.sample();
                let trace = tries(&events);
                events_seen += trace.len() as u64;
                if ok {
                    accepted += 1;
                } else {
                    failed += 1;
                }
                draws += if ok && b.out == goal {
                    1
                } else {
                    match *sampler {
                        "uniform" | "goal-biased" => 1,
                        // One more when the centre moved to a random state (the count restarts at 1).
                        "near-collision" => 1 + (b.s.centre().unwrap().2 == 1) as u64,
                        _ => replay(sampler, &trace, ok, tries_) as u64,
                    }
                };
            }
            let st = b.s.stats();
            let spent = b.p.si.checks() - checks0;
            assert_eq!((st.accepted, st.failed), (accepted, failed), "{name} {sampler}");
            assert_eq!(st.checks, spent, "{name} {sampler}: checks, by the space's counter");
            // Every check of the sampler layer is a SampleTry event; the candidates a robot's own
            // sampler checks (the vehicle chain's), if it reports them, count but are not events.
            if robot_sampler_checks(&b.p) {
                assert!(events_seen <= st.checks, "{name} {sampler}: checks, by the events");
            } else {
                assert_eq!(st.checks, events_seen, "{name} {sampler}: checks, by the events");
            }
            assert_eq!(st.draws, draws, "{name} {sampler}: draws");
            assert_eq!(st.draws_per_sample(), draws as Real / accepted.max(1) as Real);
            assert_eq!(st.checks_per_sample(), spent as Real / accepted.max(1) as Real);
        }
    }
}

// ---- helpers ----

/// Whether the robot's own sampler spends state checks (counted by the space).
fn robot_sampler_checks(p: &Problem) -> bool {
    let checks0 = p.si.checks();
    let mut q = vec![0.0; p.si.dims()];
    for seed in 0..20 {
        p.si.sample(&mut Rng::new(seed), &mut q);
    }
    p.si.checks() > checks0
}

/// Samples to draw from the bridge sampler for a few bridges on scenario `name`. The vehicle
/// chain's sampler returns a valid chain almost every time (the first end of a bridge is occupied
/// in about 1 draw of 100 on `asv-7`), so a bridge is found there in about 1 sample of 100.
fn bridge_samples(name: &str) -> usize {
    // Bridges are rare where obstacles are few and the body small (the hexagon maps' robot).
    if name.starts_with("asv") || name.starts_with("hex-") {
        1000
    } else {
        300
    }
}

/// Mean and standard deviation.
fn moments(xs: &[Real]) -> (Real, Real) {
    let n = xs.len() as Real;
    let mean = xs.iter().sum::<Real>() / n;
    (mean, (xs.iter().map(|x| (x - mean).powi(2)).sum::<Real>() / (n - 1.0)).sqrt())
}

/// `narrow`'s two wall rectangles, `[x0, y0, x1, y1]`.
const WALLS: [[Real; 4]; 2] = [[0.45, 0.0, 0.55, 0.49], [0.45, 0.51, 0.55, 1.0]];

/// Distance from a point to `narrow`'s wall.
fn wall_distance(q: &[Real]) -> Real {
    WALLS
        .iter()
        .map(|r| {
            let dx = (r[0] - q[0]).max(q[0] - r[2]).max(0.0);
            let dy = (r[1] - q[1]).max(q[1] - r[3]).max(0.0);
            (dx * dx + dy * dy).sqrt()
        })
        .fold(Real::INFINITY, Real::min)
}

/// Whether a point is outside `narrow`'s wall but within `d` of it.
fn near_wall(q: &[Real], d: Real) -> bool {
    let w = wall_distance(q);
    w > 0.0 && w <= d
}

/// Whether a point is in `narrow`'s passage, the gap between the wall's two parts.
fn in_passage(q: &[Real]) -> bool {
    (0.45..=0.55).contains(&q[0]) && q[1] > 0.49 && q[1] < 0.51
}

#[path = "samplers/runs.rs"]
mod runs;

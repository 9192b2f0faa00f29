//! The independent checker's spatial arm (tests/common/spatial.rs) against known answers and the
//! product: its GJK on hand-built cubes and random point clouds (against an exhaustive reference,
//! tests/common/brute3d.rs), a hand-built arm a millionth from a box, and the product's verdicts
//! on uniform and boundary states of both Puma scenarios (the disagreements counted and printed).
//! Its kinematics is checked against rl's in tests/spatial_arm.rs.

mod common;

use common::brute3d;
use common::spatial::{self, lerp, random_state, Arm, Pair};
use planarium::problem::Problem;
use planarium::rng::Rng;
use planarium::robot::Verdict;
use planarium::scenario::{builtin, Scenario};
use serde_json::{json, Value};

fn puma(id: &str) -> (Scenario, Problem) {
    let sc = builtin(id).unwrap();
    let p = Problem::from_scenario(&sc).unwrap();
    (sc, p)
}

/// GJK on hand-built cubes, each answer known: unit cubes a millionth apart face to face, edge to
/// edge, corner to corner and edge to face (turned 45°) are apart by that much; touching or
/// overlapping, they meet, and the overlap is the shallowest axis's. On random point clouds, GJK's
/// distance is the exhaustive reference's (tests/common/brute3d.rs, to 1e-12), both call the same
/// clouds met, and the support-function bound ([`spatial::overlap`]) never claims more distance
/// than GJK finds (a separating plane's gap is a lower bound).
#[test]
fn the_checkers_gjk_on_hand_built_cubes_and_random_clouds() {
    let cube = |c: [f64; 3]| spatial::corners(c, [1.0; 3]);
    let a = cube([0.5; 3]);
    let cases = [
        ([1.5 + 1e-6, 0.5, 0.5], 1e-6),
        ([1.5 + 1e-6, 1.5 + 1e-6, 0.5], 2f64.sqrt() * 1e-6),
        ([1.5 + 1e-6, 1.5 + 1e-6, 1.5 + 1e-6], 3f64.sqrt() * 1e-6),
        ([1.5, 0.5, 0.5], 0.0),
        ([1.5, 1.5, 1.5], 0.0),
        ([1.0, 0.2, 0.7], 0.0),
        ([1.5 - 1e-6, 0.5, 0.5], 0.0),
    ];
    for (c, want) in cases {
        let d = spatial::distance(&a, &cube(c));
        assert!((d - want).abs() < 1e-12, "cube at {c:?}: {d} against {want}");
        assert_eq!(d <= spatial::TOUCH, want == 0.0, "cube at {c:?}");
        assert_eq!(brute3d::distance(&a, &cube(c)) == 0.0, want == 0.0, "the reference, cube at {c:?}");
    }
    assert!((spatial::overlap(&a, &cube([1.0, 0.5, 0.5])) - 0.5).abs() < 1e-12);
    assert!((spatial::overlap(&a, &cube([1.0, 1.25, 0.6])) - 0.25).abs() < 1e-12);
    // Turned 45° about z: its vertical edge 1e-6 from the first cube's face x = 1.
    let turned = |gap: f64| {
        let at = [1.0 + 0.5 * 2f64.sqrt() + gap, 0.5, 0.5];
        let m = spatial::mul(&spatial::trans(at), &spatial::rot(2, 0.25 * std::f64::consts::PI));
        spatial::corners([0.0; 3], [1.0; 3]).into_iter().map(|p| spatial::apply(&m, p)).collect::<Vec<_>>()
    };
    for (gap, want) in [(1e-6, 1e-6), (0.0, 0.0), (-1e-6, 0.0)] {
        let d = spatial::distance(&a, &turned(gap));
        assert!((d - want).abs() < 1e-12, "turned cube, gap {gap}: {d}");
    }
    let mut rng = Rng::new(3);
    let (mut apart, mut met, mut worst) = (0, 0, 0.0f64);
    for _ in 0..400 {
        let cloud = |rng: &mut Rng, c: [f64; 3]| -> Vec<[f64; 3]> {
            (0..8).map(|_| [0, 1, 2].map(|k| c[k] + rng.uniform(-0.5, 0.5))).collect()
        };
        let x = cloud(&mut rng, [0.0; 3]);
        let off = [0, 1, 2].map(|_| rng.uniform(-0.9, 0.9));
        let y = cloud(&mut rng, off);
        let (d, o, b) = (spatial::distance(&x, &y), spatial::overlap(&x, &y), brute3d::distance(&x, &y));
        worst = worst.max((d - b).abs());
        assert!((d - b).abs() < 1e-12, "clouds {off:?}: GJK {d}, the reference {b}");
        assert_eq!(d == 0.0, b == 0.0, "clouds {off:?}: GJK {d}, the reference {b}");
        if d > 0.0 {
            apart += 1;
            assert!(-o <= d + 1e-12, "clouds {off:?}: a plane {} apart, GJK {d}", -o);
        } else {
            met += 1;
            assert!(o > 0.0, "clouds {off:?}: met, overlap {o}");
        }
    }
    eprintln!("random clouds: {apart} apart, {met} met; GJK within {worst:.1e} of the reference");
    assert!(apart >= 50 && met >= 50, "{apart} {met}");
}

/// A one-joint arm whose link is a unit cube, turning about z at a corner, and a box whose near face
/// is `gap` beyond the cube's face at q = 0: the product and the checker agree where the answer is
/// known (a millionth apart: free; touching or turned into it: met, naming the box). A motion that
/// ends on the joint's limit stays within it: its last state is the end itself, not `a + (b − a)`,
/// which here rounds past the limit (the planners' walk met this on an EST edge of puma-rbo-wall).
#[test]
fn a_hand_built_arm_a_millionth_from_a_box() {
    let hi = std::f64::consts::FRAC_PI_4;
    let scene = |gap: f64| {
        let cube: Vec<Value> = spatial::corners([0.5; 3], [1.0; 3]).iter().map(|p| json!(p)).collect();
        Scenario::from_value(&json!({
            "bounds": [-3, -3, 3, 3],
            "robot": {"kind": "spatial-arm", "joints": [{"limits": [-3.9, hi]}], "links": [{}, {"name": "cube", "hull": cube}]},
            "obstacles3d": [{"name": "block", "box": {"center": [1.5 + gap, 0.5, 0.5], "size": [1, 1, 1]}}],
            "start": [0.5], "goal": [0.7], "resolution": 0.01
        }))
        .unwrap()
    };
    for (gap, q, met) in
        [(1e-6, 0.0, false), (1e-6, 0.3, false), (1e-6, -0.01, true), (0.0, 0.0, true), (0.0, 1e-3, false)]
    {
        let sc = scene(gap);
        let p = Problem::from_scenario(&sc).unwrap();
        let product = p.robot.verdict(p.si.workspace(), &[q]);
        let mine = common::state_problem(&sc, &[q]);
        assert_eq!(product != Verdict::Valid, met, "gap {gap}, q {q}: the product says {product:?}");
        assert_eq!(mine.is_some(), met, "gap {gap}, q {q}: {mine:?}");
        if let Some(e) = mine {
            assert!(e.contains("cube meets obstacles3d[0] (block)"), "{e}");
        }
    }
    let (sc, a) = (scene(5.0), -3.8901436703168017);
    assert!(a + (hi - a) > hi, "the naive last state is past the limit");
    assert_eq!(common::motion_problem(&sc, &[a], &[hi]), None);
    assert!(common::state_problem(&sc, &[a + (hi - a)]).unwrap().contains("joint 0 outside"));
}

/// Farther than this from touching (metres of clearance or depth), the checker and the product
/// must agree.
const MARGIN: f64 = 1e-6;

/// The product's verdict at `q` against the checker's: whether the product calls it free, and the
/// checker's signed clearance (and its pair) when the two disagree. When both call it blocked, the
/// hit the product names (an obstacle, or two links) must be met by the checker too, or lie within
/// `MARGIN` of it; a disagreement farther than `MARGIN` from touching fails.
fn compare(checker: &Arm, p: &Problem, q: &[f64]) -> (bool, Option<(f64, Pair)>) {
    let ws = p.si.workspace();
    let v = p.robot.verdict(ws, q);
    let met = checker.contacts(q, true);
    let what = || {
        format!("{q:?}: the product says {:?}, the checker {:?}", p.robot.describe_collision(ws, q), checker.problem(q))
    };
    if v == Verdict::Valid && met.is_empty() {
        return (true, None);
    }
    if v != Verdict::Valid && !met.is_empty() {
        let named: Box<dyn Fn(Pair) -> bool> = match v {
            Verdict::Collision(o) => Box::new(move |c| matches!(c, Pair::Scene { obstacle, .. } if obstacle == o)),
            Verdict::Invalid(why) => {
                assert_eq!(why, "two links of the arm meet", "{}", what());
                Box::new(|c| matches!(c, Pair::Links { .. }))
            }
            other => panic!("{other:?}: {}", what()),
        };
        if !met.iter().any(|(c, _)| named(*c)) {
            let (c, pair) = checker.clearance_of(q, named);
            assert!(c <= MARGIN, "the product's hit is {c:e} m from touching by the checker: {}", what());
            return (false, Some((c, pair)));
        }
        return (false, None);
    }
    let (c, pair) = checker.clearance(q);
    assert!(c.abs() <= MARGIN, "they disagree {c:e} m from touching: {}", what());
    (v == Verdict::Valid, Some((c, pair)))
}

/// The distance of `pair` at `q` by the exhaustive reference, which must be GJK's `gjk` (to 1e-12).
fn against_the_reference(checker: &Arm, q: &[f64], pair: Pair, gjk: f64) {
    let world = checker.world(q);
    let (x, y) = checker.sets(&world, pair);
    let r = brute3d::distance(x, y);
    assert!((gjk - r).abs() < 1e-12, "{q:?}: {}: GJK {gjk:e}, the reference {r:e}", checker.describe(pair));
}

/// The product's verdicts and the checker's agree on 2,000 uniform states of each Puma scenario,
/// and on 400 states within 1e-7 rad of the product's boundary (each end of a bisection between a
/// free and a blocked uniform state), except within `MARGIN` of touching: the disagreements are
/// counted and printed, with their clearance. Where both call a state blocked, the checker meets
/// the obstacle the product names (or two links, when it says so). The distances behind the first
/// disagreements and at the first free ends are GJK's and the exhaustive reference's alike, so the
/// product's tolerance read from them (it calls parts a few hundredths of a micrometre apart
/// blocked) is not the checker's error.
#[test]
fn the_checker_agrees_with_the_product_on_uniform_and_boundary_states() {
    for id in ["puma-rbo-wall", "puma-boxes"] {
        let (sc, p) = puma(id);
        let checker = Arm::new(&sc).unwrap();
        let mut rng = Rng::new(11);
        let (mut free, mut blocked, mut off) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..2000 {
            let q = random_state(&sc, &mut rng);
            let (ok, d) = compare(&checker, &p, &q);
            off.extend(d.map(|(c, _)| c));
            if ok {
                free.push(q);
            } else {
                blocked.push(q);
            }
        }
        let uniform_off = off.len();
        let (mut scene, mut links) = (0, 0);
        for q in &blocked {
            match p.robot.verdict(p.si.workspace(), q) {
                Verdict::Collision(_) => scene += 1,
                _ => links += 1,
            }
        }
        let (mut boundary_off, mut referenced) = (Vec::<f64>::new(), 0);
        for k in 0..200 {
            let (a, b) = (&free[k % free.len()], &blocked[(7 * k) % blocked.len()]);
            let len = a.iter().zip(b).map(|(x, y)| (y - x).powi(2)).sum::<f64>().sqrt();
            let (mut lo, mut hi) = (0.0, 1.0);
            while (hi - lo) * len > 1e-7 {
                let mid = 0.5 * (lo + hi);
                if p.robot.is_valid(p.si.workspace(), &lerp(a, b, mid)) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            for t in [lo, hi] {
                let q = lerp(a, b, t);
                if let (_, Some((c, pair))) = compare(&checker, &p, &q) {
                    // The first disagreements the checker calls free: GJK's distance is the
                    // exhaustive reference's.
                    if c > 0.0 && boundary_off.iter().filter(|c| **c > 0.0).count() < 5 {
                        against_the_reference(&checker, &q, pair, c);
                        referenced += 1;
                    }
                    boundary_off.push(c);
                }
            }
            // On the first ten free ends, the pair nearest to touching, likewise.
            let q = lerp(a, b, lo);
            if k < 10 && checker.contacts(&q, false).is_empty() {
                let (c, pair) = checker.clearance(&q);
                against_the_reference(&checker, &q, pair, c);
                referenced += 1;
            }
        }
        let apart: Vec<f64> = boundary_off.iter().copied().filter(|c| *c > spatial::TOUCH).collect();
        eprintln!(
            "{id}: 2,000 uniform states ({} free, {scene} meet the scene, {links} two links): {uniform_off} \
             disagreements; 400 boundary states: {} disagreements, {} the product calls blocked with the parts \
             apart (at most {:.2e} m), {} it calls free with the parts at most 1e-9 m apart; {referenced} pairs' \
             distances checked against the reference",
            free.len(),
            boundary_off.len(),
            apart.len(),
            apart.iter().fold(0.0, |m: f64, c| m.max(*c)),
            boundary_off.len() - apart.len(),
        );
        assert!(free.len() >= 50 && scene >= 50 && links >= 50, "{id}: too few of a kind to compare");
    }
}

use super::*;
use crate::math::PI;

fn se2(weight: Real) -> StateSpace {
    StateSpace {
        dims: vec![
            Dim { lo: 0.0, hi: 1.0, wraps: false },
            Dim { lo: 0.0, hi: 1.0, wraps: false },
            Dim { lo: -PI, hi: PI, wraps: true },
        ],
        metric: Metric::TranslationRotation { weight },
    }
}

#[test]
fn rotation_wraps_the_short_way() {
    let s = se2(0.5);
    let a = [0.0, 0.0, PI - 0.1];
    let b = [0.0, 0.0, -PI + 0.1];
    assert!((s.distance(&a, &b) - 0.5 * 0.2).abs() < 1e-12);
    let mut m = [0.0; 3];
    s.interpolate(&a, &b, 0.5, &mut m);
    assert!((m[2].abs() - PI).abs() < 1e-12, "midpoint crosses ±π, got {}", m[2]);
}

#[test]
fn box_bound_never_exceeds_true_distance() {
    let s = se2(0.3);
    let mut rng = crate::rng::Rng::new(5);
    for _ in 0..2000 {
        let mut q = [0.0; 3];
        let mut a = [0.0; 3];
        let mut b = [0.0; 3];
        s.sample_uniform(&mut rng, &mut q);
        s.sample_uniform(&mut rng, &mut a);
        s.sample_uniform(&mut rng, &mut b);
        let lo: Vec<Real> = (0..3).map(|i| a[i].min(b[i])).collect();
        let hi: Vec<Real> = (0..3).map(|i| a[i].max(b[i])).collect();
        let mut inside = [0.0; 3];
        for _ in 0..10 {
            for i in 0..3 {
                inside[i] = rng.uniform(lo[i], hi[i]);
            }
            assert!(s.box_lower_bound(&q, &lo, &hi) <= s.distance(&q, &inside) + 1e-12);
        }
    }
}

#[test]
fn max_extent_matches_ompl_ranges() {
    // OMPL's default range is 0.2 × extent: 0.2828 for the unit square, 0.597 for SE(2) with weight 0.5.
    let r2 = StateSpace { dims: se2(0.5).dims[..2].to_vec(), metric: Metric::Euclidean };
    assert!((0.2 * r2.max_extent() - 0.2828).abs() < 1e-4);
    assert!((0.2 * se2(0.5).max_extent() - 0.597).abs() < 1e-3);
}

#[test]
fn chain_embeddings_give_the_distance_bit_for_bit() {
    let links = vec![0.1, 0.25, 0.05, 0.3, 0.1];
    for metric in [
        Metric::ChainSum { links: links.clone() },
        Metric::ChainMax { links: links.clone() },
        Metric::ChainNorm { links: links.clone() },
    ] {
        let space = StateSpace { dims: vec![Dim { lo: -PI, hi: PI, wraps: true }; 5], metric };
        assert_eq!(space.embedding_len(), 10);
        let mut rng = crate::rng::Rng::new(3);
        let (mut a, mut b) = (vec![0.0; 5], vec![0.0; 5]);
        let (mut ea, mut eb) = (vec![0.0; 10], vec![0.0; 10]);
        for _ in 0..1000 {
            space.sample_uniform(&mut rng, &mut a);
            space.sample_uniform(&mut rng, &mut b);
            space.embed(&a, &mut ea);
            space.embed(&b, &mut eb);
            assert_eq!(space.embedded_distance(&ea, &eb).to_bits(), space.distance(&a, &b).to_bits());
        }
    }
    let plane = StateSpace { dims: vec![Dim { lo: 0.0, hi: 1.0, wraps: false }; 2], metric: Metric::Euclidean };
    assert_eq!(plane.embedding_len(), 0);
}

#[test]
fn plain_euclidean_distance_and_bound_are_the_general_ones_bit_for_bit() {
    let joints = |wraps: bool| StateSpace {
        dims: (0..6).map(|k| Dim { lo: -2.0 - k as Real, hi: 2.5 + k as Real, wraps: wraps && k == 3 }).collect(),
        metric: Metric::Euclidean,
    };
    let s = joints(false);
    assert!(s.plain_euclidean());
    assert!(!joints(true).plain_euclidean(), "a wrapping dimension is not plain");
    assert!(!se2(0.5).plain_euclidean());
    let mut rng = crate::rng::Rng::new(9);
    let mut draw = || -> Vec<Real> { s.dims.iter().map(|d| d.lo + (d.hi - d.lo) * rng.uniform01()).collect() };
    for _ in 0..5000 {
        let (a, b, c) = (draw(), draw(), draw());
        assert_eq!(plain_distance(&a, &b).to_bits(), s.distance(&a, &b).to_bits());
        let lo: Vec<Real> = b.iter().zip(&c).map(|(x, y)| x.min(*y)).collect();
        let hi: Vec<Real> = b.iter().zip(&c).map(|(x, y)| x.max(*y)).collect();
        assert_eq!(plain_box_lower_bound(&a, &lo, &hi).to_bits(), s.box_lower_bound(&a, &lo, &hi).to_bits());
        // a point inside its own box is at no distance from it
        assert_eq!(plain_box_lower_bound(&lo, &lo, &hi), 0.0);
    }
}

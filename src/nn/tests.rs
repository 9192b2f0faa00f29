use super::*;
use crate::math::{Real, PI};
use crate::rng::Rng;
use crate::space::{Dim, Metric, StateSpace};

fn brute(pts: &[Vec<Real>], s: &StateSpace, q: &[Real]) -> Real {
    pts.iter().map(|p| s.distance(q, p)).fold(Real::INFINITY, Real::min)
}

fn check_space(s: StateSpace, seed: u64) {
    let mut rng = Rng::new(seed);
    let mut t = KdTree::new(s.dim_count());
    let mut pts = Vec::new();
    for i in 0..3000u32 {
        let mut q = vec![0.0; s.dim_count()];
        // Clustered, RRT-like insertions: near the previous point most of the time.
        if i > 0 && rng.uniform01() < 0.7 {
            let prev: &Vec<Real> = &pts[rng.below(pts.len())];
            let mut r = vec![0.0; s.dim_count()];
            s.sample_uniform(&mut rng, &mut r);
            s.interpolate(prev, &r, 0.02, &mut q);
        } else {
            s.sample_uniform(&mut rng, &mut q);
        }
        t.add(&s, &q, i);
        pts.push(q);
        if i % 97 == 0 || i > 2900 {
            let mut query = vec![0.0; s.dim_count()];
            s.sample_uniform(&mut rng, &mut query);
            let (id, d) = t.nearest(&s, &query).unwrap();
            assert_eq!(d, brute(&pts, &s, &query));
            assert_eq!(d, s.distance(&query, &pts[id as usize]));
        }
    }
}

#[test]
fn matches_linear_scan_in_the_plane() {
    check_space(StateSpace { dims: vec![Dim { lo: 0.0, hi: 1.0, wraps: false }; 2], metric: Metric::Euclidean }, 1);
}

#[test]
fn matches_linear_scan_with_wrapping_angle() {
    let dims = vec![Dim { lo: 0.0, hi: 1.0, wraps: false }, Dim { lo: 0.0, hi: 1.0, wraps: false }, Dim { lo: -PI, hi: PI, wraps: true }];
    check_space(StateSpace { dims, metric: Metric::TranslationRotation { weight: 0.5 } }, 2);
}

#[test]
fn filtered_nearest_skips_excluded_ids() {
    let s = StateSpace { dims: vec![Dim { lo: 0.0, hi: 1.0, wraps: false }; 2], metric: Metric::Euclidean };
    let mut t = KdTree::new(2);
    for i in 0..100u32 {
        t.add(&s, &[i as Real / 100.0, 0.5], i);
    }
    assert_eq!(t.nearest(&s, &[0.5, 0.5]).unwrap().0, 50);
    assert_eq!(t.nearest_where(&s, &[0.5, 0.5], |id| id % 2 == 1).unwrap().0, 49);
}

#[test]
fn k_nearest_and_within_match_a_sorted_scan() {
    let dims = vec![Dim { lo: 0.0, hi: 1.0, wraps: false }, Dim { lo: 0.0, hi: 1.0, wraps: false }, Dim { lo: -PI, hi: PI, wraps: true }];
    let s = StateSpace { dims, metric: Metric::TranslationRotation { weight: 0.3 } };
    let mut rng = Rng::new(5);
    let mut t = KdTree::new(3);
    let mut pts = Vec::new();
    for i in 0..500u32 {
        let mut q = vec![0.0; 3];
        s.sample_uniform(&mut rng, &mut q);
        t.add(&s, &q, i);
        pts.push(q);
        if i % 50 == 0 || i == 499 {
            let mut query = vec![0.0; 3];
            s.sample_uniform(&mut rng, &mut query);
            let mut all: Vec<(u32, Real)> = pts.iter().enumerate().map(|(j, p)| (j as u32, s.distance(&query, p))).collect();
            all.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
            assert_eq!(t.k_nearest(&s, &query, 7), all.iter().take(7).copied().collect::<Vec<_>>());
            let r = 0.4;
            assert_eq!(t.within(&s, &query, r), all.iter().filter(|e| e.1 <= r).copied().collect::<Vec<_>>());
        }
    }
}

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
    let dims = vec![
        Dim { lo: 0.0, hi: 1.0, wraps: false },
        Dim { lo: 0.0, hi: 1.0, wraps: false },
        Dim { lo: -PI, hi: PI, wraps: true },
    ];
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

/// Grow a tree of `n` uniform states; after every `every`-th insertion and the last, compare
/// `k_nearest(k)` and `within(r)` for a random query with a sorted scan (`r` from the sorted
/// distances, so that it takes a fair share of points).
fn check_collect(s: &StateSpace, seed: u64, n: u32, every: u32, k: usize, r: impl Fn(&[(u32, Real)]) -> Real) {
    let d = s.dim_count();
    let mut rng = Rng::new(seed);
    let mut t = KdTree::new(d);
    let mut pts = Vec::new();
    for i in 0..n {
        let mut q = vec![0.0; d];
        s.sample_uniform(&mut rng, &mut q);
        t.add(s, &q, i);
        pts.push(q);
        if i % every == 0 || i == n - 1 {
            let mut query = vec![0.0; d];
            s.sample_uniform(&mut rng, &mut query);
            let mut all: Vec<(u32, Real)> =
                pts.iter().enumerate().map(|(j, p)| (j as u32, s.distance(&query, p))).collect();
            all.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
            assert_eq!(t.k_nearest(s, &query, k), all.iter().take(k).copied().collect::<Vec<_>>());
            let r = r(&all);
            assert_eq!(t.within(s, &query, r), all.iter().filter(|e| e.1 <= r).copied().collect::<Vec<_>>());
        }
    }
}

#[test]
fn k_nearest_and_within_match_a_sorted_scan() {
    let dims = vec![
        Dim { lo: 0.0, hi: 1.0, wraps: false },
        Dim { lo: 0.0, hi: 1.0, wraps: false },
        Dim { lo: -PI, hi: PI, wraps: true },
    ];
    let s = StateSpace { dims, metric: Metric::TranslationRotation { weight: 0.3 } };
    check_collect(&s, 5, 500, 50, 7, |_| 0.4);
}

/// A chain of `n` links with free joints (the horn's metric spaces).
fn chain_space(n: usize, metric: fn(Vec<Real>) -> Metric) -> StateSpace {
    let links: Vec<Real> = (0..n).map(|k| 0.1 + 0.01 * k as Real).collect();
    StateSpace { dims: vec![Dim { lo: -PI, hi: PI, wraps: true }; n], metric: metric(links) }
}

#[test]
fn matches_linear_scan_for_chain_metrics_over_embeddings() {
    // The tree is built over the link-end embeddings; the answers must be the scan's exactly.
    check_space(chain_space(10, |links| Metric::ChainSum { links }), 3);
    check_space(chain_space(10, |links| Metric::ChainMax { links }), 4);
    check_space(chain_space(3, |links| Metric::ChainSum { links }), 5);
    check_space(chain_space(4, |links| Metric::ChainNorm { links }), 6);
}

#[test]
fn chain_k_nearest_and_within_match_a_sorted_scan() {
    let s = chain_space(6, |links| Metric::ChainSum { links });
    check_collect(&s, 6, 400, 20, 5, |all| all[all.len().min(31) - 1].1);
}

#[test]
fn embedded_box_bound_never_exceeds_the_distance_to_a_point_inside() {
    for s in [
        chain_space(8, |links| Metric::ChainSum { links }),
        chain_space(8, |links| Metric::ChainMax { links }),
        chain_space(8, |links| Metric::ChainNorm { links }),
    ] {
        let mut rng = Rng::new(7);
        let (mut ea, mut eb, mut eq) = (vec![0.0; 16], vec![0.0; 16], vec![0.0; 16]);
        for _ in 0..2000 {
            let mut q = vec![0.0; 8];
            for e in [&mut ea, &mut eb, &mut eq] {
                s.sample_uniform(&mut rng, &mut q);
                s.embed(&q, e);
            }
            let lo: Vec<Real> = ea.iter().zip(&eb).map(|(a, b)| a.min(*b)).collect();
            let hi: Vec<Real> = ea.iter().zip(&eb).map(|(a, b)| a.max(*b)).collect();
            let bound = s.embedded_box_lower_bound(&eq, &lo, &hi);
            assert!(bound <= s.embedded_distance(&eq, &ea) && bound <= s.embedded_distance(&eq, &eb));
            assert_eq!(s.embedded_box_lower_bound(&ea, &lo, &hi), 0.0, "a point inside its box is at 0");
        }
    }
}

/// The plain search (squared sums, roots only where needed) gives the general search's answer
/// bit for bit: the same id and distance for every query, with and without a filter, on
/// clustered points, exact ties (points on a coarse grid, repeated) and distances so close that
/// their squares differ while their roots round alike; in each unrolled size and the run-time one.
#[test]
fn plain_search_is_the_general_search_bit_for_bit() {
    for (dims, seed) in [(2usize, 11u64), (3, 12), (6, 13), (4, 14), (1, 15)] {
        let s = StateSpace { dims: vec![Dim { lo: -1.0, hi: 1.0, wraps: false }; dims], metric: Metric::Euclidean };
        assert!(s.plain_euclidean());
        let mut rng = Rng::new(seed);
        let mut t = KdTree::new(dims);
        let draw = |rng: &mut Rng, grid: bool| -> Vec<Real> {
            (0..dims)
                .map(|_| {
                    let v = rng.uniform01() * 2.0 - 1.0;
                    if grid {
                        (v * 4.0).round() / 4.0
                    } else {
                        v
                    }
                })
                .collect()
        };
        let mut pts: Vec<Vec<Real>> = Vec::new();
        for i in 0..2500u32 {
            let p = match i % 5 {
                0 | 1 => draw(&mut rng, true),
                // A point whose distance to a grid point differs from another's by an ulp or so.
                2 if !pts.is_empty() => {
                    let mut p = pts[rng.below(pts.len())].clone();
                    p[0] = Real::from_bits(p[0].to_bits() + 1 + rng.below(3) as u64);
                    p
                }
                _ => draw(&mut rng, false),
            };
            t.add(&s, &p, i);
            pts.push(p);
            if i >= 40 && i % 7 == 0 {
                let q = draw(&mut rng, i % 2 == 0);
                for filtered in [false, true] {
                    let keep = |id: u32| !filtered || id % 3 != 1;
                    let fast = t.nearest_where(&s, &q, keep);
                    let mut stack = Vec::new();
                    let slow = t.search_nearest(&s, &q, keep, &mut stack);
                    let bits = |r: Option<(u32, Real)>| r.map(|(id, d)| (id, d.to_bits()));
                    assert_eq!(bits(fast), bits(slow), "{dims} dims, {i} points, query {q:?}");
                }
                // k nearest and within r, the plain traversal against the general one: r at a
                // grid step (exact ties at r), at a point's own distance, and at infinity
                let general = |t: &KdTree, k: usize, r: Real| {
                    let mut stack = Vec::new();
                    let found = t.search_collect(&s, &q, k, r, &mut stack);
                    found.into_iter().map(|(d, j)| (j as u32, d.to_bits())).collect::<Vec<_>>()
                };
                let bits = |v: Vec<(u32, Real)>| v.into_iter().map(|(id, d)| (id, d.to_bits())).collect::<Vec<_>>();
                let own = s.distance(&q, &pts[rng.below(pts.len())]);
                for k in [1, 2, 7, 40] {
                    let slow = general(&t, k, Real::INFINITY);
                    assert_eq!(bits(t.k_nearest(&s, &q, k)), slow, "{dims} dims, {i} points, {k} nearest");
                }
                for r in [0.25, 0.5, own, 0.0] {
                    let slow = general(&t, usize::MAX, r);
                    assert_eq!(bits(t.within(&s, &q, r)), slow, "{dims} dims, {i} points, within {r}");
                }
            }
        }
    }
}

#[test]
fn root_certainly_above_never_claims_what_rounding_undoes() {
    use crate::space::root_certainly_above;
    let mut rng = Rng::new(3);
    for _ in 0..200_000 {
        let y = match rng.below(4) {
            0 => rng.uniform01(),
            1 => rng.uniform01() * 1e-310,
            2 => rng.uniform01() * 1e300,
            _ => 0.0,
        };
        let x = match rng.below(3) {
            0 => Real::from_bits(y.to_bits() + rng.below(1 << 20) as u64),
            1 => y * (1.0 + rng.uniform01() * 1e-11),
            _ => y + rng.uniform01() * 1e-290,
        };
        if root_certainly_above(x, y) {
            assert!(x.sqrt() > y.sqrt(), "{x:e} over {y:e}");
        }
    }
    assert!(root_certainly_above(4.0, 1.0));
    assert!(!root_certainly_above(1.0, 1.0));
    assert!(!root_certainly_above(Real::NAN, 1.0));
}

/// A tree marked, grown past the mark (across rebuilds, or not), and rewound answers every query
/// as a tree of the points before the mark does: the same ids at the same distances, bit for bit,
/// and it goes on growing as that tree would.
#[test]
fn a_tree_rewound_to_its_mark_answers_as_the_tree_it_was() {
    let s = StateSpace { dims: vec![Dim { lo: 0.0, hi: 1.0, wraps: false }; 3], metric: Metric::Euclidean };
    let mut rng = Rng::new(7);
    let point = |rng: &mut Rng| {
        let mut q = vec![0.0; 3];
        s.sample_uniform(rng, &mut q);
        q
    };
    // marks before the first rebuild (scan mode), just before a rebuild, and in between
    for (before, after) in [(10, 100), (63, 2), (63, 300), (100, 5), (100, 1000), (1500, 1)] {
        let (mut t, mut fresh) = (KdTree::new(3), KdTree::new(3));
        for i in 0..before {
            let q = point(&mut rng);
            t.add(&s, &q, i);
            fresh.add(&s, &q, i);
        }
        let mark = t.mark();
        for i in 0..after {
            t.add(&s, &point(&mut rng), before + i);
        }
        t.rewind(mark);
        assert_eq!(t.len(), before as usize);
        // both grow on by the same points after the rewind; the same answers all along
        for i in 0..200u32 {
            let q = point(&mut rng);
            assert_eq!(t.nearest(&s, &q), fresh.nearest(&s, &q), "{before} + {after}: nearest");
            assert_eq!(t.k_nearest(&s, &q, 5), fresh.k_nearest(&s, &q, 5), "{before} + {after}: 5 nearest");
            assert_eq!(t.within(&s, &q, 0.2), fresh.within(&s, &q, 0.2), "{before} + {after}: within 0.2");
            if i % 2 == 0 {
                t.add(&s, &q, before + 10_000 + i);
                fresh.add(&s, &q, before + 10_000 + i);
            }
        }
    }
}

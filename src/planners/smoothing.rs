//! Random shortcut smoothing (OMPL's `PathSimplifier::shortcutPath`; report 003's "direct, random
//! shortcutting"): pick two random points along the path, and if the straight motion between them
//! is valid and shorter, replace the stretch between them with it. Seeded; `attempts` tries.

use crate::math::Real;
use crate::motion::MotionValidator;
use crate::rng::Rng;
use crate::space_info::SpaceInfo;

/// Length of a path in the space's metric.
pub fn path_cost(si: &SpaceInfo, path: &[Vec<Real>]) -> Real {
    path.windows(2).map(|w| si.distance(&w[0], &w[1])).sum()
}

/// The point at arc length `s` along `path` (with cumulative lengths `cum`): its segment index and state.
fn point_at(si: &SpaceInfo, path: &[Vec<Real>], cum: &[Real], s: Real) -> (usize, Vec<Real>) {
    let i = match cum.binary_search_by(|c| c.total_cmp(&s)) {
        Ok(i) => i.min(path.len() - 2),
        Err(i) => i.saturating_sub(1).min(path.len() - 2),
    };
    let len = cum[i + 1] - cum[i];
    let t = if len > 0.0 { ((s - cum[i]) / len).clamp(0.0, 1.0) } else { 0.0 };
    let mut q = vec![0.0; si.dims()];
    si.interpolate(&path[i], &path[i + 1], t, &mut q);
    (i, q)
}

/// Shorten `path` by random shortcuts; the result starts and ends where `path` does, and every
/// motion in it has been checked. Past the run's deadline ([`SpaceInfo::out_of_time`]) it stops
/// and returns what it has.
pub fn shortcut(si: &SpaceInfo, path: &[Vec<Real>], attempts: usize, rng: &mut Rng) -> Vec<Vec<Real>> {
    let mut scratch = vec![0.0; si.dims()];
    let path = shortcut_only(si, path, attempts, rng);
    reduce_vertices(si, &path, &mut scratch)
}

/// [`shortcut`] without its final [`reduce_vertices`] (for a path whose vertices matter in
/// themselves: an inspection path counted at its vertices).
pub fn shortcut_only(si: &SpaceInfo, path: &[Vec<Real>], attempts: usize, rng: &mut Rng) -> Vec<Vec<Real>> {
    let mut path = path.to_vec();
    let mut scratch = vec![0.0; si.dims()];
    for _ in 0..attempts {
        // The run's time limit holds here too: the path so far is valid, keep it.
        if path.len() < 3 || si.out_of_time() {
            break;
        }
        let mut cum = vec![0.0];
        for w in path.windows(2) {
            cum.push(cum.last().unwrap() + si.distance(&w[0], &w[1]));
        }
        let total = *cum.last().unwrap();
        let (mut s1, mut s2) = (rng.uniform(0.0, total), rng.uniform(0.0, total));
        if s1 > s2 {
            std::mem::swap(&mut s1, &mut s2);
        }
        let (i, a) = point_at(si, &path, &cum, s1);
        let (j, b) = point_at(si, &path, &cum, s2);
        if j <= i {
            continue; // same segment: already straight
        }
        // The stretch a → path[i+1] → ... → path[j] → b must be longer than the shortcut.
        let along = si.distance(&a, &path[i + 1]) + (cum[j] - cum[i + 1]) + si.distance(&path[j], &b);
        if si.distance(&a, &b) >= along - 1e-12 {
            continue;
        }
        if si.check_motion(&a, &b, &mut scratch).is_err() {
            continue;
        }
        let mut next: Vec<Vec<Real>> = path[..=i].to_vec();
        if si.distance(&a, &path[i]) > 0.0 {
            next.push(a);
        }
        if si.distance(&b, &path[j + 1]) > 0.0 {
            next.push(b);
        }
        next.extend_from_slice(&path[j + 1..]);
        path = next;
    }
    path
}

/// Drop the vertices that a straight valid motion can skip: from each kept vertex, jump to the
/// farthest later vertex reachable directly (OMPL's `reduceVertices`, done greedily). Never longer.
pub fn reduce_vertices(si: &SpaceInfo, path: &[Vec<Real>], scratch: &mut [Real]) -> Vec<Vec<Real>> {
    let mut out = vec![path[0].clone()];
    let mut i = 0;
    while i + 1 < path.len() {
        if si.out_of_time() {
            // Out of time: the rest of the path as it is (every motion in it was checked).
            out.extend_from_slice(&path[i + 1..]);
            break;
        }
        let mut next = i + 1;
        for j in (i + 2..path.len()).rev() {
            if si.check_motion(&path[i], &path[j], scratch).is_ok() {
                next = j;
                break;
            }
        }
        out.push(path[next].clone());
        i = next;
    }
    out
}

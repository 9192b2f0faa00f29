//! The chain's sampler. Uniform samples of `[cx, cy, θ1, φ...]` are almost never valid (report 000
//! found a handful in a million), so a sample is built the way a valid chain looks:
//!
//! - **shape**: the `n` exterior angles of a convex polygon are positive and sum to 2π, so the
//!   chain's turns are drawn as `n − 2` of `n` random shares of 2π, all of the chain's winding
//!   (each share a uniform number raised to a random power, so some shapes are round and some have
//!   long straight runs with sharp corners);
//! - **place**: a random vehicle (not always the first) is put at a random point, uniform over the
//!   bounds; or, most of the time when the workspace has narrow gaps, at a point of a gap (report
//!   000's "corridor" sampling, found here without knowing the map: see [`Gaps`]) with the broom
//!   leaving that vehicle turned along the gap and the turns next to it made small, the straight
//!   run that threads a gap (report 000's "enlarge the angles" to squeeze through passages);
//! - **keep**: the first valid candidate of a few tries, else the last one (RRT-Connect only needs
//!   a direction to grow in).

use super::{AsvRobot, STACK};
use crate::geometry::Workspace;
use crate::math::{wrap_angle, MinMax, Real, Vec2, PI};
use crate::rng::Rng;
use crate::robot::{Robot, Verdict};
use crate::space::StateSpace;

/// Candidates tried per sample before settling for an invalid one.
const TRIES: usize = 24;
/// Fraction of candidates placed in a narrow gap, when the workspace has one.
const GAP_FRACTION: Real = 0.7;
/// Turns next to the broom along a gap are scaled by a uniform factor below this…
const FLAT: Real = 0.3;
/// …for this many vehicles either side of it.
const FLAT_REACH: usize = 2;
/// How far (radians) the broom along a gap may deviate from the gap's direction.
const ALONG_SPREAD: Real = 0.15;
/// Fraction of the gap candidates drawn thin (see [`thin`]).
const THIN_FRACTION: Real = 0.5;
/// A thin chain's two bends, radians (each)…
const THIN_BEND: (Real, Real) = (0.2, 1.0);
/// …and the most its other turns bend.
const THIN_STRAIGHT: Real = 0.03;

/// Points in narrow gaps of a workspace, with each gap's direction.
///
/// Found once per workspace by a bridge test (Hsu et al., "The bridge test for sampling narrow
/// passages with probabilistic roadmap planners", ICRA 2003) done in the plane: the midpoint of a
/// short random segment whose two ends are blocked (in an obstacle or out of bounds) and which is
/// itself free lies in a gap narrower than the segment. The gap's direction at that point is
/// across the narrowest of several probed widths. Seeded on its own, so runs stay reproducible and
/// the run's generator is not disturbed.
#[derive(Clone, Debug, Default)]
pub(super) struct Gaps {
    points: Vec<(Vec2, Real)>,
    /// For each point, the middle of the gap across it (where a thin chain is centred).
    centres: Vec<Vec2>,
}

/// Bridge tests tried when building the gap list, and the most points kept.
const BRIDGE_TRIES: usize = 60_000;
const BRIDGE_KEEP: usize = 768;
/// Half the longest bridge, as a fraction of the workspace's size (gaps up to twice this wide).
const GAP_REACH: Real = 0.06;
/// Bridge tests between two looks at the run's deadline.
const LOOK_EVERY: usize = 256;
/// Directions probed for a gap's width.
const PROBES: usize = 16;

impl Gaps {
    /// The gaps of `ws`; `None` when `stop` said to give up first (asked every
    /// [`LOOK_EVERY`] bridge tests: on a map of many obstacles the search takes a while).
    pub(super) fn find(ws: &Workspace, stop: &dyn Fn() -> bool) -> Option<Gaps> {
        let mut rng = Rng::new(0xA5_6A95);
        let b = ws.bounds;
        let reach = GAP_REACH * (b.max.x - b.min.x).max(b.max.y - b.min.y);
        let (mut points, mut centres) = (Vec::new(), Vec::new());
        if ws.obstacles.is_empty() {
            return Some(Gaps { points, centres });
        }
        for i in 0..BRIDGE_TRIES {
            if i % LOOK_EVERY == LOOK_EVERY - 1 && stop() {
                return None;
            }
            let m = Vec2::new(rng.uniform(b.min.x, b.max.x), rng.uniform(b.min.y, b.max.y));
            let beta = rng.uniform(0.0, PI);
            let (s, c) = libm::sincos(beta);
            let d = Vec2::new(c, s).scale(rng.uniform(0.0, reach));
            if blocked(ws, m + d) && blocked(ws, m - d) && !blocked(ws, m) {
                let Some(beta) = across(ws, m, reach) else { continue };
                points.push((m, beta + 0.5 * PI));
                let (s, c) = libm::sincos(beta);
                let u = Vec2::new(c, s);
                let (a, b) = (edge(ws, m, u, 2.0 * reach), edge(ws, m, u.scale(-1.0), 2.0 * reach));
                centres.push(m + u.scale(0.5 * (a - b)));
                if points.len() == BRIDGE_KEEP {
                    break;
                }
            }
        }
        Some(Gaps { points, centres })
    }

    /// The gap points and directions found.
    #[cfg(test)]
    pub(super) fn points(&self) -> &[(Vec2, Real)] {
        &self.points
    }

    /// The middle of the gap across each point.
    #[cfg(test)]
    pub(super) fn centres(&self) -> &[Vec2] {
        &self.centres
    }

    /// A random gap point, its direction and the middle of the gap across it, if there are any.
    fn pick(&self, rng: &mut Rng) -> Option<(Vec2, Real, Vec2)> {
        if self.points.is_empty() {
            None
        } else {
            let i = rng.below(self.points.len());
            Some((self.points[i].0, self.points[i].1, self.centres[i]))
        }
    }
}

/// How far from free point `m` along unit `u` the first blocked point is (up to `reach`), to a
/// 1/1024 of `reach` (bisection after a coarse march).
fn edge(ws: &Workspace, m: Vec2, u: Vec2, reach: Real) -> Real {
    let step = reach / 64.0;
    let mut lo = 0.0;
    while lo + step <= reach && !blocked(ws, m + u.scale(lo + step)) {
        lo += step;
    }
    let mut hi = (lo + step).at_most(reach);
    for _ in 0..4 {
        let mid = 0.5 * (lo + hi);
        if blocked(ws, m + u.scale(mid)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// Whether `p` is blocked: outside the bounds or inside an obstacle.
fn blocked(ws: &Workspace, p: Vec2) -> bool {
    // Through the broad phase: the gap search makes up to 180,000 point tests, which a plain scan
    // of 20,000 obstacles turned into seconds past any time limit (found by tests/fuzz_props.rs).
    !ws.bounds.contains(p) || ws.point_blocked(p)
}

/// The direction (in `[0, π)`) across the gap at free point `m`: the narrowest of `PROBES`
/// widths, each found by marching both ways from `m` until blocked (up to `2·reach`). `None` when
/// the way along the gap (at right angles) is blocked close by on either side: `m` is then in an
/// inner corner of the free space (where a wall meets another or the bounds), not in a passage.
fn across(ws: &Workspace, m: Vec2, reach: Real) -> Option<Real> {
    let step = reach / 16.0;
    let free = |beta: Real, sign: Real| {
        let (s, c) = libm::sincos(beta);
        let u = Vec2::new(c, s).scale(sign);
        let mut t = step;
        while t < 2.0 * reach && !blocked(ws, m + u.scale(t)) {
            t += step;
        }
        t
    };
    let widths: Vec<(Real, Real)> =
        (0..PROBES).map(|i| PI * i as Real / PROBES as Real).map(|b| (b, free(b, 1.0) + free(b, -1.0))).collect();
    let (beta, _) = widths.iter().copied().fold((0.0, Real::INFINITY), |best, w| if w.1 < best.1 { w } else { best });
    let along = beta + 0.5 * PI;
    (free(along, 1.0) >= 0.5 * reach && free(along, -1.0) >= 0.5 * reach).then_some(beta)
}

/// Write a sample into `out` (see the module documentation); returns the state checks spent.
///
/// `stop` is asked between candidates and during the gap search: once the run's deadline has
/// passed, the sample ends with the candidate it has (and a gap search cut short is not kept, so
/// the next run on this robot searches again and finds the same gaps).
pub(super) fn sample(
    robot: &AsvRobot,
    space: &StateSpace,
    rng: &mut Rng,
    out: &mut [Real],
    stop: &dyn Fn() -> bool,
) -> u64 {
    let ws = robot.workspace.borrow();
    let mut cached = robot.gaps.borrow_mut();
    if cached.is_none() {
        *cached = match ws.as_ref() {
            Some(ws) => Gaps::find(ws, stop),
            None => Some(Gaps::default()),
        };
    }
    let none = Gaps::default();
    let gaps = cached.as_ref().unwrap_or(&none);
    let n = robot.n;
    let mut rel = [Vec2::default(); STACK];
    let mut heap;
    let rel: &mut [Vec2] = if n <= STACK {
        &mut rel[..n]
    } else {
        heap = vec![Vec2::default(); n];
        &mut heap
    };
    let (xd, yd) = (space.dims[0], space.dims[1]);
    let mut checks = 0;
    for t in 0..TRIES {
        if t > 0 && stop() {
            return checks;
        }
        let winding = match robot.orientation() {
            0.0 if rng.uniform01() < 0.5 => 1.0,
            0.0 => -1.0,
            w => w,
        };
        shape(robot, rng, winding, &mut out[2..]);
        let k = rng.below(n);
        let gap = if rng.uniform01() < GAP_FRACTION { gaps.pick(rng) } else { None };
        let (target, k) = match gap {
            Some((p, along, centre)) if n >= 4 && rng.uniform01() < THIN_FRACTION => {
                // The whole chain thin, its straight run exactly along the gap, centred across it.
                let broom = thin(rng, winding, &mut out[3..3 + n - 2]);
                let before: Real = out[3..3 + broom].iter().sum();
                let dir = along + if rng.uniform01() < 0.5 { 0.0 } else { PI };
                out[2] = wrap_angle(dir - before);
                super::offsets(robot.broom, &out[2..], rel);
                let (s, c) = libm::sincos(along);
                let (u, across) = (Vec2::new(c, s), Vec2::new(-s, c));
                let (lo, hi) = rel.iter().fold((Real::INFINITY, Real::NEG_INFINITY), |(lo, hi), r| {
                    let d = r.dot(&across);
                    (lo.at_most(d), hi.at_least(d))
                });
                let mid = 0.5 * (lo + hi);
                // Along the gap at p, across it at the middle.
                let at = centre + u.scale((p - centre).dot(&u)) + across.scale(rel[broom].dot(&across) - mid);
                (at, broom)
            }
            Some((p, along, _)) => {
                // Broom k (k−1 for the last vehicle) along the gap, the turns near it small.
                let broom = k.min(n - 2);
                for j in broom.saturating_sub(FLAT_REACH)..(broom + FLAT_REACH + 1).min(n - 2) {
                    out[3 + j] *= rng.uniform(0.0, FLAT);
                }
                let before: Real = out[3..3 + broom].iter().sum();
                let dir =
                    along + rng.uniform(-ALONG_SPREAD, ALONG_SPREAD) + if rng.uniform01() < 0.5 { 0.0 } else { PI };
                out[2] = wrap_angle(dir - before);
                (p, k)
            }
            None => (Vec2::new(rng.uniform(xd.lo, xd.hi), rng.uniform(yd.lo, yd.hi)), k),
        };
        super::offsets(robot.broom, &out[2..], rel);
        let mean = rel.iter().fold(Vec2::default(), |s, p| s + *p).scale(1.0 / n as Real);
        let c = target - (rel[k] - mean);
        out[0] = c.x;
        out[1] = c.y;
        match ws.as_ref() {
            Some(ws) => {
                checks += 1;
                if robot.verdict(ws, out) == Verdict::Valid {
                    return checks;
                }
            }
            None => return checks,
        }
    }
    checks
}

/// A Gaussian neighbour of `centre` that keeps the chain's shape a chain: the centroid and `θ1`
/// move as independent coordinates (spread `sigma` × their range), and each turn by a normal
/// deviate of `sigma` × 2π, kept on the winding's side and below π, the turns scaled back when
/// together they would leave no room to close the polygon. (Moving every coordinate
/// independently, as for other robots, almost always breaks convexity: Gaussian, bridge and
/// near-collision sampling would then only ever see invalid chains.)
pub(super) fn sample_gaussian(
    robot: &AsvRobot,
    space: &StateSpace,
    rng: &mut Rng,
    centre: &[Real],
    sigma: Real,
    out: &mut [Real],
) {
    let placement = StateSpace { dims: space.dims[..3].to_vec(), metric: crate::space::Metric::Euclidean };
    crate::space::gaussian_coordinates(&placement, rng, &centre[..3], sigma, &mut out[..3]);
    let winding = match robot.orientation() {
        0.0 => {
            let s: Real = centre[3..].iter().sum();
            if s < 0.0 {
                -1.0
            } else {
                1.0
            }
        }
        w => w,
    };
    let mut total = 0.0;
    for k in 3..out.len() {
        let t = (centre[k] * winding + rng.normal() * sigma * 2.0 * PI).clamp(0.0, PI - 1e-6);
        out[k] = t;
        total += t;
    }
    // The turns of a convex polygon sum to 2π: leave the closing turns a share.
    let room = 2.0 * PI * (1.0 - 1.0 / robot.n as Real);
    let scale = if total > room { room / total } else { 1.0 };
    for v in &mut out[3..] {
        *v *= scale * winding;
    }
}

/// Draw the chain's shape into `angles` (`θ1`, then the `n − 2` turns) with the given winding.
fn shape(robot: &AsvRobot, rng: &mut Rng, winding: Real, angles: &mut [Real]) {
    let n = robot.n;
    let power = [1.0, 2.0, 4.0][rng.below(3)];
    let mut shares = [0.0; STACK];
    let mut heap;
    let shares: &mut [Real] = if n <= STACK {
        &mut shares[..n]
    } else {
        heap = vec![0.0; n];
        &mut heap
    };
    let mut total = 0.0;
    for s in shares.iter_mut() {
        *s = libm::pow(rng.uniform01(), power) + 1e-9;
        total += *s;
    }
    angles[0] = rng.uniform(-PI, PI);
    for k in 0..n - 2 {
        let t = 2.0 * PI * shares[k] / total;
        angles[1 + k] = winding * t.min(PI - 1e-6);
    }
}

/// Draw a thin chain into `turns` (the `n − 2` turns, `n ≥ 4`): every turn almost straight (below
/// [`THIN_STRAIGHT`]) but two, at random places, bent by [`THIN_BEND`] each, all of the chain's
/// winding: a long flat trapezoid (with the closing edge as its base), the only kind of convex chain
/// that keeps its area inside a gap narrower than a broom and longer than the chain. Returns a
/// broom between the two bends (the straight run, which the caller turns along the gap).
fn thin(rng: &mut Rng, winding: Real, turns: &mut [Real]) -> usize {
    let m = turns.len();
    for t in turns.iter_mut() {
        *t = winding * rng.uniform(0.0, THIN_STRAIGHT);
    }
    // The bends near the ends (a long straight run between them), anywhere now and then.
    let (i, j) = if rng.uniform01() < 0.75 {
        let i = rng.below(2.min(m - 1));
        (i, (m - 1 - rng.below(2)).max(i + 1))
    } else {
        let i = rng.below(m - 1);
        (i, i + 1 + rng.below(m - 1 - i))
    };
    turns[i] = winding * rng.uniform(THIN_BEND.0, THIN_BEND.1);
    turns[j] = winding * rng.uniform(THIN_BEND.0, THIN_BEND.1);
    // Turn t joins broom t and broom t + 1: brooms i + 1 ..= j lie between the bends.
    i + 1 + rng.below(j - i)
}

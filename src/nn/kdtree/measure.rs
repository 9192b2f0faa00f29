//! How the k-d tree's traversals measure distances from their query ([`KdTree::traverse`],
//! [`KdTree::traverse_collect`]): the distance itself ([`Exact`]) or, in a plain Euclidean space,
//! its square ([`Squared`]), with the comparisons that keep both traversals' answers the same bit
//! for bit.

use super::KdTree;
use crate::math::Real;
use crate::space::StateSpace;

/// How [`KdTree::traverse`] measures distances from its query: by a measure monotone in the
/// distance (the distance itself, or its square), with the distance from a measure and a test
/// that decides a comparison of two distances from their measures when it can.
pub(super) trait Measure {
    /// The measure of the distance to point `i`.
    fn point(&self, i: usize) -> Real;
    /// The measure of the lower bound on the distance to any point under node `c`.
    fn node_box(&self, c: usize) -> Real;
    /// The distance whose measure is `m`.
    fn root(&self, m: Real) -> Real;
    /// Whether the distance of measure `x` is certainly past that of `y` (`false` decides nothing).
    /// It must also decide rightly against [`measure_of`](Self::measure_of) a distance, as a
    /// measure whose distance may differ from that distance in its last place.
    fn certainly_above(&self, x: Real, y: Real) -> bool;
    /// A measure for distance `d` (its distance is `d`, or `d` to within its last place).
    fn measure_of(&self, d: Real) -> Real;
}

/// Whether the distance of measure `x` is at most that of measure `b`, whose distance is
/// `bd()` (taken only when the measures do not decide it).
#[inline(always)]
pub(super) fn at_most<M: Measure>(m: &M, x: Real, b: Real, bd: impl FnOnce() -> Real) -> bool {
    !m.certainly_above(x, b) && (m.certainly_above(b, x) || m.root(x) <= bd())
}

/// Whether `(x, i)` comes before `(y, j)` in the order of `(distance, insertion index)`, for
/// measures `x` and `y`.
#[inline(always)]
fn before<M: Measure>(m: &M, (x, i): (Real, usize), (y, j): (Real, usize)) -> bool {
    if x == y {
        i < j
    } else if m.certainly_above(y, x) {
        true
    } else if m.certainly_above(x, y) {
        false
    } else {
        (m.root(x), i) < (m.root(y), j)
    }
}

/// Keep point `i` (at measure `x`) among the `k` nearest held in `found`, sorted, if its
/// distance is at most `r` (measure `r_m`) and it comes before the k-th.
#[inline(always)]
pub(super) fn offer<M: Measure>(
    m: &M,
    x: Real,
    i: usize,
    k: usize,
    r_m: Real,
    r: Real,
    found: &mut Vec<(Real, usize)>,
) {
    if at_most(m, x, r_m, || r) && (found.len() < k || before(m, (x, i), found[k - 1])) {
        let at = found.partition_point(|e| before(m, *e, (x, i)));
        found.insert(at, (x, i));
        found.truncate(k);
    }
}

/// The tree's own distances and box bounds, whatever its space: the measure is the distance.
pub(super) struct Exact<'a> {
    pub(super) tree: &'a KdTree,
    pub(super) space: &'a StateSpace,
    pub(super) qk: &'a [Real],
}

impl Measure for Exact<'_> {
    #[inline(always)]
    fn point(&self, i: usize) -> Real {
        self.tree.dist(self.space, self.qk, i)
    }
    #[inline(always)]
    fn node_box(&self, c: usize) -> Real {
        self.tree.box_bound(self.space, self.qk, c)
    }
    #[inline(always)]
    fn root(&self, m: Real) -> Real {
        m
    }
    #[inline(always)]
    fn certainly_above(&self, x: Real, y: Real) -> bool {
        x > y
    }
    #[inline(always)]
    fn measure_of(&self, d: Real) -> Real {
        d
    }
}

/// Squared Euclidean distances in a plain space, keys of `D` numbers (0: `kd`): a root is
/// monotone, so a sum at most another's never has the greater root, and two sums far enough
/// apart ([`root_certainly_above`](crate::space::root_certainly_above)) have roots in the same
/// order once rounded.
pub(super) struct Squared<'a, const D: usize> {
    pub(super) tree: &'a KdTree,
    pub(super) q: &'a [Real],
    pub(super) kd: usize,
}

impl<const D: usize> Measure for Squared<'_, D> {
    #[inline(always)]
    fn point(&self, i: usize) -> Real {
        let kd = if D > 0 { D } else { self.kd };
        crate::space::plain_distance_sq(self.q, &self.tree.keys[i * kd..i * kd + kd])
    }
    #[inline(always)]
    fn node_box(&self, c: usize) -> Real {
        let kd = if D > 0 { D } else { self.kd };
        crate::space::plain_box_lower_bound_sq(
            self.q,
            &self.tree.links.lo[c * kd..c * kd + kd],
            &self.tree.links.hi[c * kd..c * kd + kd],
        )
    }
    #[inline(always)]
    fn root(&self, m: Real) -> Real {
        m.sqrt()
    }
    #[inline(always)]
    fn certainly_above(&self, x: Real, y: Real) -> bool {
        crate::space::root_certainly_above(x, y)
    }
    /// The rounded square: its root is `d` to within a unit in the last place, and
    /// [`root_certainly_above`](crate::space::root_certainly_above)'s margin of 1e-12 holds
    /// against it in both directions (`d²` rounded is within 2⁻⁵³ of `d²`).
    #[inline(always)]
    fn measure_of(&self, d: Real) -> Real {
        d * d
    }
}

use crate::math::{MinMax, Real};
use crate::space::StateSpace;

mod mark;
mod measure;

use mark::Journal;
pub use mark::KdMark;
use measure::{at_most, offer, Exact, Measure, Squared};

const NONE: u32 = u32::MAX;
/// Below this many points, a linear scan is used and no tree is built.
const LEAF_SCAN: usize = 32;

/// An incremental k-d tree of states, each with a caller's id (`u32`).
///
/// Points are inserted down the tree; each time the size doubles past 32 points, the tree is
/// rebuilt balanced (median splits on the widest dimension), which keeps queries logarithmic on
/// RRT's spatially correlated insertions at amortised O(log n) per insert.
#[derive(Clone, Debug, Default)]
pub struct KdTree {
    dims: usize,
    /// Numbers per key (set by the first insertion): the embedding's length for metrics that
    /// have one (chain metrics, see [`StateSpace::embed`]), else the state's.
    kd: usize,
    /// Whether keys are embeddings. The tree is then built over the embeddings, whose boxes bound
    /// the chain metric far more tightly than joint-angle boxes do, and each stored state is
    /// embedded once instead of at every comparison.
    embedded: bool,
    /// Whether the space is Euclidean without wrapping dimensions (and keys are states): distances
    /// and box bounds then skip asking each dimension whether it wraps.
    plain: bool,
    /// Flat keys, `kd` per point, in insertion order.
    keys: Vec<Real>,
    ids: Vec<u32>,
    /// The tree over the points.
    links: Links,
    next_rebuild: usize,
    stack: Vec<(u32, Real)>,
    /// The query's embedding (when keys are embeddings).
    qemb: Vec<Real>,
    /// What changed since [`KdTree::mark`], while marked (to go back to it: `mark.rs`).
    journal: Option<Box<Journal>>,
}

/// The tree over a [`KdTree`]'s points: per point its split dimension, children, and the bounding
/// box of its subtree (in key coordinates, flat, `kd` per point); and the root.
#[derive(Clone, Debug, Default)]
struct Links {
    split: Vec<u8>,
    left: Vec<u32>,
    right: Vec<u32>,
    lo: Vec<Real>,
    hi: Vec<Real>,
    root: u32,
}

impl KdTree {
    /// The bytes its points take (keys, ids, links and boxes; see
    /// [`Planner::stored_bytes`](crate::planners::Planner::stored_bytes)).
    pub fn bytes(&self) -> usize {
        use crate::limits::bytes_of;
        let Links { split, left, right, lo, hi, .. } = &self.links;
        bytes_of(&self.keys)
            + bytes_of(&self.ids)
            + bytes_of(split)
            + bytes_of(left)
            + bytes_of(right)
            + bytes_of(lo)
            + bytes_of(hi)
    }
    /// An empty tree of `dims`-dimensional states.
    pub fn new(dims: usize) -> Self {
        KdTree {
            dims,
            links: Links { root: NONE, ..Default::default() },
            next_rebuild: LEAF_SCAN,
            ..Default::default()
        }
    }
    /// Number of points.
    pub fn len(&self) -> usize {
        self.ids.len()
    }
    /// Whether the tree is empty.
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }
    /// Remove every point.
    pub fn clear(&mut self) {
        *self = KdTree::new(self.dims);
    }

    /// Point `i`'s key.
    #[inline(always)]
    fn key(&self, i: usize) -> &[Real] {
        &self.keys[i * self.kd..(i + 1) * self.kd]
    }

    /// The query's key: its embedding (after [`Self::prepare`]), else the state itself.
    #[inline(always)]
    fn qkey<'a>(&'a self, q: &'a [Real]) -> &'a [Real] {
        if self.embedded {
            &self.qemb
        } else {
            q
        }
    }

    /// A lower bound on the distance from the query (key `qk`) to any point under node `c`.
    #[inline(always)]
    fn box_bound(&self, space: &StateSpace, qk: &[Real], c: usize) -> Real {
        let kd = self.kd;
        let (lo, hi) = (&self.links.lo[c * kd..(c + 1) * kd], &self.links.hi[c * kd..(c + 1) * kd]);
        if self.plain {
            crate::space::plain_box_lower_bound(qk, lo, hi)
        } else if self.embedded {
            space.embedded_box_lower_bound(qk, lo, hi)
        } else {
            space.box_lower_bound(qk, lo, hi)
        }
    }

    /// The distance from the query (key `qk`) to point `i`.
    #[inline(always)]
    fn dist(&self, space: &StateSpace, qk: &[Real], i: usize) -> Real {
        if self.plain {
            crate::space::plain_distance(qk, self.key(i))
        } else if self.embedded {
            space.embedded_distance(qk, self.key(i))
        } else {
            space.distance(qk, self.key(i))
        }
    }

    /// Embed the query, when keys are embeddings.
    fn prepare(&mut self, space: &StateSpace, q: &[Real]) {
        if self.embedded {
            self.qemb.resize(self.kd, 0.0);
            let mut e = std::mem::take(&mut self.qemb);
            space.embed(q, &mut e);
            self.qemb = e;
        }
    }

    /// Insert state `q` under `id`.
    pub fn add(&mut self, space: &StateSpace, q: &[Real], id: u32) {
        let n = self.ids.len();
        if n == 0 {
            let elen = space.embedding_len();
            self.embedded = elen > 0;
            self.plain = !self.embedded && space.plain_euclidean();
            self.kd = if self.embedded { elen } else { self.dims };
        }
        let at = self.keys.len();
        if self.embedded {
            self.keys.resize(at + self.kd, 0.0);
            space.embed(q, &mut self.keys[at..]);
        } else {
            self.keys.extend_from_slice(q);
        }
        self.ids.push(id);
        self.links.lo.extend_from_slice(&self.keys[at..]);
        self.links.hi.extend_from_slice(&self.keys[at..]);
        self.links.left.push(NONE);
        self.links.right.push(NONE);
        self.links.split.push(0);
        if n + 1 >= self.next_rebuild {
            self.keep_links_before_rebuild();
            self.rebuild(space);
            self.next_rebuild = (n + 1) * 2;
            return;
        }
        if self.links.root == NONE {
            return; // still in linear-scan mode
        }
        let d = self.kd;
        let mut cur = self.links.root as usize;
        loop {
            for k in 0..d {
                let v = self.keys[at + k];
                self.links.lo[cur * d + k] = self.links.lo[cur * d + k].at_most(v);
                self.links.hi[cur * d + k] = self.links.hi[cur * d + k].at_least(v);
            }
            let s = self.links.split[cur] as usize;
            let go_left = self.keys[at + s] < self.keys[cur * d + s];
            let child = if go_left { self.links.left[cur] } else { self.links.right[cur] };
            if child == NONE {
                if let Some(j) = &mut self.journal {
                    j.linked.push(cur as u32);
                }
                self.links.split[n] = ((s + 1) % d) as u8;
                if go_left {
                    self.links.left[cur] = n as u32;
                } else {
                    self.links.right[cur] = n as u32;
                }
                return;
            }
            cur = child as usize;
        }
    }

    fn rebuild(&mut self, space: &StateSpace) {
        let mut order: Vec<u32> = (0..self.ids.len() as u32).collect();
        self.links.root = self.build(space, &mut order);
    }

    fn build(&mut self, space: &StateSpace, idx: &mut [u32]) -> u32 {
        if idx.is_empty() {
            return NONE;
        }
        let d = self.kd;
        let mut lo = self.key(idx[0] as usize).to_vec();
        let mut hi = lo.clone();
        for &i in idx.iter() {
            for k in 0..d {
                let v = self.keys[i as usize * d + k];
                lo[k] = lo[k].at_most(v);
                hi[k] = hi[k].at_least(v);
            }
        }
        // Widest dimension, with the rotation weight of the metric applied to angles (embedding
        // coordinates are lengths already).
        let embedded = self.embedded;
        let weight = |k: usize| match &space.metric {
            _ if embedded => 1.0,
            crate::space::Metric::TranslationRotation { weight } if k == 2 => *weight,
            crate::space::Metric::Weighted { weights } => weights[k],
            _ => 1.0,
        };
        let s = (0..d)
            .max_by(|&a, &b| ((hi[a] - lo[a]) * weight(a)).total_cmp(&((hi[b] - lo[b]) * weight(b))))
            .unwrap_or(0);
        let mid = idx.len() / 2;
        let keys = &self.keys;
        idx.select_nth_unstable_by(mid, |&a, &b| {
            keys[a as usize * d + s].total_cmp(&keys[b as usize * d + s]).then(a.cmp(&b))
        });
        let m = idx[mid] as usize;
        let (left, rest) = idx.split_at_mut(mid);
        let l = self.build(space, left);
        let r = self.build(space, &mut rest[1..]);
        self.links.split[m] = s as u8;
        self.links.left[m] = l;
        self.links.right[m] = r;
        self.links.lo[m * d..(m + 1) * d].copy_from_slice(&lo);
        self.links.hi[m * d..(m + 1) * d].copy_from_slice(&hi);
        m as u32
    }

    /// The id and distance of the point nearest to `q` (ties: the earliest inserted in scan mode;
    /// deterministic in either mode), or `None` if empty.
    pub fn nearest(&mut self, space: &StateSpace, q: &[Real]) -> Option<(u32, Real)> {
        self.nearest_where(space, q, |_| true)
    }

    /// Like [`nearest`](Self::nearest), among the points whose id passes `keep`.
    pub fn nearest_where(&mut self, space: &StateSpace, q: &[Real], keep: impl Fn(u32) -> bool) -> Option<(u32, Real)> {
        self.prepare(space, q);
        let mut stack = std::mem::take(&mut self.stack);
        let best = match (self.plain && self.links.root != NONE, self.kd) {
            // The robots' usual sizes (a point, a rigid body, a six-joint arm) with their loops
            // unrolled; any other size by the same code with the size read at run time.
            (true, 2) => self.search_plain::<2>(q, keep, &mut stack),
            (true, 3) => self.search_plain::<3>(q, keep, &mut stack),
            (true, 6) => self.search_plain::<6>(q, keep, &mut stack),
            (true, _) => self.search_plain::<0>(q, keep, &mut stack),
            (false, _) => self.search_nearest(space, self.qkey(q), keep, &mut stack),
        };
        self.stack = stack;
        best
    }

    /// Keep point `i` at distance `dist` if it beats the best so far (ties: the earlier point).
    #[inline(always)]
    fn consider(&self, i: usize, dist: Real, best: &mut Option<(u32, Real)>, best_i: &mut usize) {
        let better = match best {
            None => true,
            Some((_, bd)) => dist < *bd || (dist == *bd && i < *best_i),
        };
        if better {
            *best = Some((self.ids[i], dist));
            *best_i = i;
        }
    }

    /// The nearest point passing `keep`, by the tree's own distances: a scan below
    /// [`LEAF_SCAN`] points, else the tree's traversal with [`Exact`].
    pub(super) fn search_nearest(
        &self,
        space: &StateSpace,
        qk: &[Real],
        keep: impl Fn(u32) -> bool,
        stack: &mut Vec<(u32, Real)>,
    ) -> Option<(u32, Real)> {
        if self.links.root == NONE {
            let mut best: Option<(u32, Real)> = None;
            let mut best_i = usize::MAX;
            for i in 0..self.ids.len() {
                if keep(self.ids[i]) {
                    self.consider(i, self.dist(space, qk, i), &mut best, &mut best_i);
                }
            }
            return best;
        }
        self.traverse(&Exact { tree: self, space, qk }, qk, self.kd, keep, stack)
    }

    /// [`search_nearest`](Self::search_nearest) in a plain Euclidean space with its tree built,
    /// keys of `D` numbers (0: `self.kd`, read at run time): the same traversal with
    /// [`Squared`] distances, so the same answer, bit for bit, by the same visits.
    fn search_plain<const D: usize>(
        &self,
        q: &[Real],
        keep: impl Fn(u32) -> bool,
        stack: &mut Vec<(u32, Real)>,
    ) -> Option<(u32, Real)> {
        let kd = if D > 0 { D } else { self.kd };
        let q = &q[..kd];
        self.traverse(&Squared::<D> { tree: self, q, kd }, q, kd, keep, stack)
    }

    /// The nearest-point traversal of the built tree, measuring with `m`: a node is visited
    /// when its bound is not past the best distance, the far side pushed first when its box's
    /// bound is not past it, the near side next with this node's bound (its box lies in this
    /// node's, so this bound bounds it too, and computing its own would rarely prune it). The
    /// stack holds measures; a root is taken only where [`Measure::certainly_above`] does not
    /// decide a comparison, or a new best is kept.
    #[inline(always)]
    fn traverse<M: Measure>(
        &self,
        m: &M,
        qk: &[Real],
        kd: usize,
        keep: impl Fn(u32) -> bool,
        stack: &mut Vec<(u32, Real)>,
    ) -> Option<(u32, Real)> {
        let mut best: Option<(u32, Real)> = None;
        let (mut best_i, mut best_m) = (usize::MAX, Real::INFINITY);
        stack.clear();
        stack.push((self.links.root, 0.0));
        while let Some((node, bound_m)) = stack.pop() {
            let i = node as usize;
            if let Some((_, bd)) = best {
                // `bound > bd`
                if bound_m > best_m && (m.certainly_above(bound_m, best_m) || m.root(bound_m) > bd) {
                    continue;
                }
            }
            if keep(self.ids[i]) {
                let d_m = m.point(i);
                if best.is_none() || !m.certainly_above(d_m, best_m) {
                    let before = best_i;
                    self.consider(i, m.root(d_m), &mut best, &mut best_i);
                    if best_i != before {
                        best_m = d_m;
                    }
                }
            }
            let s = self.links.split[i] as usize;
            let (near, far) = if qk[s] < self.keys[i * kd + s] {
                (self.links.left[i], self.links.right[i])
            } else {
                (self.links.right[i], self.links.left[i])
            };
            if far != NONE {
                let b_m = m.node_box(far as usize);
                // `b <= bd`
                let push = match best {
                    None => true,
                    Some((_, bd)) => b_m <= best_m || (!m.certainly_above(b_m, best_m) && m.root(b_m) <= bd),
                };
                if push {
                    stack.push((far, b_m));
                }
            }
            if near != NONE {
                stack.push((near, bound_m));
            }
        }
        best
    }

    /// The `k` points nearest to `q` as `(id, distance)`, nearest first (ties: insertion order).
    pub fn k_nearest(&mut self, space: &StateSpace, q: &[Real], k: usize) -> Vec<(u32, Real)> {
        self.collect(space, q, k, Real::INFINITY)
    }

    /// Every point within distance `r` of `q` (inclusive) as `(id, distance)`, nearest first.
    pub fn within(&mut self, space: &StateSpace, q: &[Real], r: Real) -> Vec<(u32, Real)> {
        self.collect(space, q, usize::MAX, r)
    }

    /// At most `k` points within `r`, nearest first; ties broken by insertion order.
    fn collect(&mut self, space: &StateSpace, q: &[Real], k: usize, r: Real) -> Vec<(u32, Real)> {
        if k == 0 {
            return Vec::new();
        }
        self.prepare(space, q);
        let mut stack = std::mem::take(&mut self.stack);
        let found = match (self.plain && self.links.root != NONE, self.kd) {
            (true, 2) => self.collect_plain::<2>(q, k, r, &mut stack),
            (true, 3) => self.collect_plain::<3>(q, k, r, &mut stack),
            (true, 6) => self.collect_plain::<6>(q, k, r, &mut stack),
            (true, _) => self.collect_plain::<0>(q, k, r, &mut stack),
            (false, _) => self.search_collect(space, self.qkey(q), k, r, &mut stack),
        };
        self.stack = stack;
        found.into_iter().map(|(dist, i)| (self.ids[i], dist)).collect()
    }

    /// At most `k` points within `r` by the tree's own distances, as `(distance, insertion
    /// index)`, nearest first: a scan below [`LEAF_SCAN`] points, else the tree's traversal with
    /// [`Exact`].
    pub(super) fn search_collect(
        &self,
        space: &StateSpace,
        qk: &[Real],
        k: usize,
        r: Real,
        stack: &mut Vec<(u32, Real)>,
    ) -> Vec<(Real, usize)> {
        let m = Exact { tree: self, space, qk };
        if self.links.root == NONE {
            let mut found = Vec::new();
            for i in 0..self.ids.len() {
                offer(&m, m.point(i), i, k, r, r, &mut found);
            }
            return found;
        }
        self.traverse_collect(&m, qk, self.kd, k, r, stack)
    }

    /// [`search_collect`](Self::search_collect) in a plain Euclidean space with its tree built,
    /// by [`Squared`] distances: the same points in the same order with the same distance bits.
    fn collect_plain<const D: usize>(
        &self,
        q: &[Real],
        k: usize,
        r: Real,
        stack: &mut Vec<(u32, Real)>,
    ) -> Vec<(Real, usize)> {
        let kd = if D > 0 { D } else { self.kd };
        let q = &q[..kd];
        let found = self.traverse_collect(&Squared::<D> { tree: self, q, kd }, q, kd, k, r, stack);
        found.into_iter().map(|(d_sq, i)| (d_sq.sqrt(), i)).collect()
    }

    /// The k-nearest traversal of the built tree, measuring with `m`: as
    /// [`traverse`](Self::traverse), the bound the k-th point's distance once `k` are held, else
    /// `r`. Returns `(measure, insertion index)` in the order of `(distance, insertion index)`.
    #[inline(always)]
    fn traverse_collect<M: Measure>(
        &self,
        m: &M,
        qk: &[Real],
        kd: usize,
        k: usize,
        r: Real,
        stack: &mut Vec<(u32, Real)>,
    ) -> Vec<(Real, usize)> {
        // Room for the k held and the one offered past them (a radius alone: a start).
        let mut found: Vec<(Real, usize)> = Vec::with_capacity(k.min(self.ids.len()).min(256) + 1);
        // `r` as a measure: not always one whose distance is `r` (a square is rounded), so it
        // only decides comparisons `at_most` can decide from measures past its margin.
        let r_m = m.measure_of(r);
        // Whether a measure's distance is at most the bound's.
        let within_bound = |x: Real, found: &Vec<(Real, usize)>| {
            if found.len() >= k {
                let b = found[k - 1].0;
                at_most(m, x, b, || m.root(b))
            } else {
                at_most(m, x, r_m, || r)
            }
        };
        stack.clear();
        stack.push((self.links.root, 0.0));
        while let Some((node, b)) = stack.pop() {
            if !within_bound(b, &found) {
                continue;
            }
            let i = node as usize;
            offer(m, m.point(i), i, k, r_m, r, &mut found);
            // Far side pushed first, so the near side is searched first and tightens the bound.
            let s = self.links.split[i] as usize;
            let (near, far) = if qk[s] < self.keys[i * kd + s] {
                (self.links.left[i], self.links.right[i])
            } else {
                (self.links.right[i], self.links.left[i])
            };
            if far != NONE {
                let cb = m.node_box(far as usize);
                if within_bound(cb, &found) {
                    stack.push((far, cb));
                }
            }
            // The near side, next, with this node's bound (as in `traverse`).
            if near != NONE {
                stack.push((near, b));
            }
        }
        found
    }
}

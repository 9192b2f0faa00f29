//! The search tree shared by the RRT family, and its one growth step, with the variants that
//! change how a node is chosen to grow ([`TreeOptions`]):
//!
//! - **Dynamic domain** (A. Yershova, L. Jaillet, T. Siméon, S. M. LaValle, "Dynamic-Domain RRTs",
//!   ICRA 2005): a node whose expansion fails gets a domain radius `dd_radius`; a sample farther
//!   from its nearest node than that node's radius is rejected before any check. The adaptive
//!   variant (L. Jaillet et al., IROS 2005) grows a radius by `1 + dd_adaptive` when the node
//!   expands and shrinks it by `1 − dd_adaptive` when it fails, never below `dd_min_radius`.
//! - **Exhausted nodes** (report 001): each node counts its failed expansions; with the `drop`
//!   policy a node that failed `exhausted` times leaves nearest-neighbour selection (until every
//!   node is exhausted: then the nearest grows again rather than the tree dying); with
//!   `weighted` every node stays and the lowest `H = (d − dmin)/(dmax − dmin) + (n − nmin)/(nmax −
//!   nmin)` is chosen (d: distance to the sample, n: failures).
//! - **Ladder steps** (report 000's "ladder" move, generalised): when a step collides, up to
//!   `ladder` steps that move only a random subset of the coordinates (each with probability 1/2,
//!   the others kept at the node's) are tried, and the first valid one that ends nearer the target
//!   is added. For a point robot that is the report's move along one axis; for a chain of vehicles
//!   it bends or shifts part of the chain while the rest holds still, which slides it along walls
//!   a full step would hit.
//!
//! Besides RRT's EXTEND and RRT-Connect's CONNECT in steps of `range` (motions checked by the
//! motion validator), the tree has the Robotics Library's connect, which keeps only the last free
//! configuration of a line stepped at the resolution ([`Tree::connect_last_free`], in
//! `tree/last_free.rs`); the dynamic domain, exhausted nodes and near-collision sampling act on it
//! through the same [`Tree::select`] and books.

mod last_free;
mod mark;

pub use last_free::{LastFreeSteps, MAX_LAST_FREE_STEPS};
pub use mark::TreeMark;

use super::{Context, ParamGroup, ParamSpec, Params};
use crate::events::EventKind;
use crate::math::{MinMax, Real};
use crate::motion::MotionValidator;
use crate::nn::KdTree;
use crate::status::Grow;

const DD_RADIUS: ParamSpec = ParamSpec::real("dd_radius", "Domain radius", 0.0, 1e6, 0.0, "Dynamic-Domain RRT: radius given to a node whose expansion fails; samples beyond their nearest node's radius are rejected unchecked (0: off).");
const DD_ADAPTIVE: ParamSpec = ParamSpec::real("dd_adaptive", "Domain adaptation", 0.0, 0.99, 0.0, "Adaptive Dynamic-Domain: a radius grows by this fraction on success and shrinks by it on failure (0: fixed radius).").only_when_positive("dd_radius");
const DD_MIN_RADIUS: ParamSpec = ParamSpec::real(
    "dd_min_radius",
    "Smallest domain",
    0.0,
    1e6,
    0.0,
    "Adaptive Dynamic-Domain: the smallest radius (0: the motion resolution).",
)
.only_when_positive("dd_radius");
const EXHAUSTED: ParamSpec = ParamSpec::int(
    "exhausted",
    "Exhausted after",
    0.0,
    1e6,
    0.0,
    "Exhausted nodes: failed expansions after which a node is exhausted (0: off).",
);
const EXHAUSTED_POLICY: ParamSpec = ParamSpec::choice("exhausted_policy", "Exhausted policy", &["drop", "weighted"], 0, "drop: exhausted nodes leave nearest-neighbour selection; weighted: pick the lowest distance-plus-failures score H.").only_when_positive("exhausted");
const LADDER: ParamSpec = ParamSpec::int("ladder", "Ladder steps", 0.0, 64.0, 0.0, "When a step collides, try up to this many steps that move only a random half of the coordinates (report 000's ladder move, generalised; 0: off; range steps only: nothing with RRT-Connect's last-free connect).");

/// The tree variants' parameters, shared by RRT and RRT-Connect.
pub static TREE_PARAMS: &[ParamSpec] = &[DD_RADIUS, DD_ADAPTIVE, DD_MIN_RADIUS, EXHAUSTED, EXHAUSTED_POLICY, LADDER];

/// The tree variants as a group of the page's parameter panel.
pub const TREE_GROUP: ParamGroup = ParamGroup { name: "tree", label: "Tree variants", params: TREE_PARAMS };

/// The same parameters for RRT-Connect, whose `connect` decides whether ladder steps are taken:
/// ladder steps are range steps, and the last-free connect takes none.
pub static CONNECT_TREE_PARAMS: &[ParamSpec] =
    &[DD_RADIUS, DD_ADAPTIVE, DD_MIN_RADIUS, EXHAUSTED, EXHAUSTED_POLICY, LADDER.only_when("connect", &["range"])];

/// The tree variants as RRT-Connect takes them: the group of the same name (values set in the page
/// are shared with RRT's), `ladder` applying with `connect` = `range` only.
pub const CONNECT_TREE_GROUP: ParamGroup =
    ParamGroup { name: TREE_GROUP.name, label: TREE_GROUP.label, params: CONNECT_TREE_PARAMS };

/// How a tree chooses the node to grow, from [`TREE_PARAMS`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TreeOptions {
    /// Dynamic-domain radius (0: off).
    pub dd_radius: Real,
    /// Adaptive factor (0: fixed).
    pub dd_adaptive: Real,
    /// Smallest adaptive radius.
    pub dd_min_radius: Real,
    /// Failures that exhaust a node (0: off).
    pub exhausted: u32,
    /// Weighted (history-based) selection instead of dropping.
    pub weighted: bool,
    /// Ladder steps tried after a step collides (0: off).
    pub ladder: u32,
}

impl TreeOptions {
    /// The options `params` set (resolution: the default smallest domain).
    pub fn from_params(params: &Params, resolution: Real) -> TreeOptions {
        let min = params.real("dd_min_radius");
        TreeOptions {
            dd_radius: params.real("dd_radius"),
            dd_adaptive: params.real("dd_adaptive"),
            dd_min_radius: if min > 0.0 { min } else { resolution },
            exhausted: params.real("exhausted") as u32,
            weighted: params.choice("exhausted_policy") == "weighted",
            ladder: params.real("ladder") as u32,
        }
    }
}

/// A tree of states: flat coordinates, parent links, and a nearest-neighbour index.
#[derive(Clone, Debug)]
pub struct Tree {
    dims: usize,
    states: Vec<Real>,
    parents: Vec<u32>,
    nn: KdTree,
    /// Which tree this is (0: rooted at the start, 1: at the goal), for events.
    pub index: usize,
    opts: TreeOptions,
    /// Dynamic-domain radius per node (∞: unbounded), when dynamic domains are on.
    radius: Vec<Real>,
    /// Failed expansions per node, when exhausted nodes are on.
    fails: Vec<u32>,
    /// Samples rejected by a dynamic domain.
    pub rejected: u64,
    /// Scratch for the weighted selection's distances (reused, so selection does not allocate).
    dist: Vec<Real>,
    /// Scratch for a ladder step: the node's state and the step (reused).
    ladder_buf: Vec<Real>,
    /// Whether the last growth step was a ladder step.
    slid: bool,
    /// While marked ([`Tree::mark`]): the parents re-attached since, with their parents before.
    reattached: Option<Vec<(u32, u32)>>,
}

/// The most steps one CONNECT takes (every step makes progress; this bounds an iteration's time).
pub const MAX_CONNECT_STEPS: usize = 10_000;

/// Parent of a root.
pub(crate) const ROOT: u32 = u32::MAX;

impl Tree {
    /// A tree rooted at `root`.
    pub fn new(cx: &mut Context, root: &[Real], index: usize) -> Tree {
        Tree::with_options(cx, root, index, TreeOptions::default())
    }
    /// A tree rooted at `root` that grows with the variants of `opts`.
    pub fn with_options(cx: &mut Context, root: &[Real], index: usize, opts: TreeOptions) -> Tree {
        let dims = root.len();
        let (radius, fails) = (Vec::new(), Vec::new());
        let mut t = Tree {
            dims,
            states: Vec::new(),
            parents: Vec::new(),
            nn: KdTree::new(dims),
            index,
            opts,
            radius,
            fails,
            rejected: 0,
            dist: Vec::new(),
            ladder_buf: Vec::new(),
            slid: false,
            reattached: None,
        };
        t.add(cx, root, ROOT);
        cx.nodes_left = cx.nodes_left.saturating_sub(1);
        t
    }
    /// The bytes its nodes take: states, parents, the nearest-neighbour index, per-node domains and
    /// failure counts (see [`Planner::stored_bytes`](crate::planners::Planner::stored_bytes)).
    pub fn bytes(&self) -> usize {
        use crate::planners::bytes_of;
        bytes_of(&self.states)
            + bytes_of(&self.parents)
            + self.nn.bytes()
            + bytes_of(&self.radius)
            + bytes_of(&self.fails)
    }
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.parents.len()
    }
    /// Whether the tree is empty (never, once built).
    pub fn is_empty(&self) -> bool {
        self.parents.is_empty()
    }
    /// A node's state.
    #[inline]
    pub fn state(&self, i: u32) -> &[Real] {
        let i = i as usize;
        &self.states[i * self.dims..(i + 1) * self.dims]
    }
    /// A node's parent (`u32::MAX` for the root).
    pub fn parent(&self, i: u32) -> u32 {
        self.parents[i as usize]
    }
    /// Add a node (the caller emits `NodeAdded`).
    pub fn add(&mut self, cx: &Context, q: &[Real], parent: u32) -> u32 {
        let id = self.parents.len() as u32;
        self.states.extend_from_slice(q);
        self.parents.push(parent);
        self.nn.add(&cx.si.space, q, id);
        if self.opts.dd_radius > 0.0 {
            self.radius.push(Real::INFINITY);
        }
        if self.opts.exhausted > 0 {
            self.fails.push(0);
        }
        id
    }
    /// The node nearest to `q`.
    pub fn nearest(&mut self, cx: &Context, q: &[Real]) -> (u32, Real) {
        self.nn.nearest(&cx.si.space, q).expect("a tree always has its root")
    }
    /// The node to grow toward `q` under the exhausted-node policy (the nearest when it is off, or
    /// when every node is exhausted).
    pub fn select(&mut self, cx: &Context, q: &[Real]) -> (u32, Real) {
        let limit = self.opts.exhausted;
        if limit == 0 {
            return self.nearest(cx, q);
        }
        if !self.opts.weighted {
            let fails = &self.fails;
            // When every node is exhausted the tree would be dead: the nearest grows again.
            return match self.nn.nearest_where(&cx.si.space, q, |i| fails[i as usize] < limit) {
                Some(found) => found,
                None => self.nearest(cx, q),
            };
        }
        // History-weighted: two passes, as report 001 describes (distances kept between calls).
        let mut dist = std::mem::take(&mut self.dist);
        dist.clear();
        dist.extend((0..self.len() as u32).map(|i| cx.si.distance(self.state(i), q)));
        let (mut dmin, mut dmax) = (Real::INFINITY, Real::NEG_INFINITY);
        for &d in &dist {
            dmin = dmin.at_most(d);
            dmax = dmax.at_least(d);
        }
        let nmin = *self.fails.iter().min().expect("a root") as Real;
        let nmax = *self.fails.iter().max().expect("a root") as Real;
        let norm = |v: Real, lo: Real, hi: Real| if hi > lo { (v - lo) / (hi - lo) } else { 0.0 };
        let mut best = (0u32, Real::INFINITY);
        for (i, &d) in dist.iter().enumerate() {
            let h = norm(d, dmin, dmax) + norm(self.fails[i] as Real, nmin, nmax);
            if h < best.1 {
                best = (i as u32, h);
            }
        }
        let found = (best.0, dist[best.0 as usize]);
        self.dist = dist;
        found
    }
    /// The `k` nodes nearest to `q` as `(id, distance)`, nearest first.
    pub fn k_nearest(&mut self, cx: &Context, q: &[Real], k: usize) -> Vec<(u32, Real)> {
        self.nn.k_nearest(&cx.si.space, q, k)
    }
    /// The nodes within `r` of `q` as `(id, distance)`, nearest first.
    pub fn within(&mut self, cx: &Context, q: &[Real], r: Real) -> Vec<(u32, Real)> {
        self.nn.within(&cx.si.space, q, r)
    }
    /// Re-attach node `i` under `parent` (rewiring; the caller keeps the tree acyclic).
    pub fn set_parent(&mut self, i: u32, parent: u32) {
        if let Some(log) = &mut self.reattached {
            log.push((i, self.parents[i as usize]));
        }
        self.parents[i as usize] = parent;
    }
    /// A node's dynamic-domain radius (∞ when it has none or domains are off).
    pub fn domain(&self, i: u32) -> Real {
        self.radius.get(i as usize).copied().unwrap_or(Real::INFINITY)
    }
    /// A node's failed expansions (0 when exhausted nodes are off).
    pub fn failures(&self, i: u32) -> u32 {
        self.fails.get(i as usize).copied().unwrap_or(0)
    }
    /// Whether a node is exhausted.
    pub fn is_exhausted(&self, i: u32) -> bool {
        self.opts.exhausted > 0 && self.failures(i) >= self.opts.exhausted
    }

    /// Book an expansion of `near`: its failure count and dynamic domain.
    fn record(&mut self, cx: &mut Context, near: u32, failed: bool) {
        let o = self.opts;
        let i = near as usize;
        if o.exhausted > 0 && failed {
            self.fails[i] += 1;
            if self.fails[i] == o.exhausted {
                cx.events.mark(
                    EventKind::Exhausted,
                    self.index,
                    near as i64,
                    -1.0,
                    cx.si.project(self.state(near)),
                    0.0,
                    0.0,
                );
            }
        }
        if o.dd_radius > 0.0 {
            let r = self.radius[i];
            let next = match (failed, r.is_finite()) {
                (true, false) => o.dd_radius,
                (true, true) if o.dd_adaptive > 0.0 => (r * (1.0 - o.dd_adaptive)).at_least(o.dd_min_radius),
                (false, true) if o.dd_adaptive > 0.0 => r * (1.0 + o.dd_adaptive),
                _ => r,
            };
            if next != r {
                self.radius[i] = next;
                cx.events.mark(
                    EventKind::Domain,
                    self.index,
                    near as i64,
                    -1.0,
                    cx.si.project(self.state(near)),
                    next,
                    0.0,
                );
            }
        }
    }
    /// States from the root to node `i`.
    pub fn path_to(&self, mut i: u32) -> Vec<Vec<Real>> {
        let mut out = Vec::new();
        while i != ROOT {
            out.push(self.state(i).to_vec());
            i = self.parent(i);
        }
        out.reverse();
        out
    }

    /// Grow one step of at most `range` toward a sample (RRT's EXTEND), from the node
    /// [`select`](Self::select) picks; a sample outside that node's dynamic domain is rejected
    /// unchecked. Returns the outcome and the node reached or added (the selected node when
    /// trapped or rejected).
    pub fn extend_sample(
        &mut self,
        cx: &mut Context,
        target: &[Real],
        range: Real,
        scratch: &mut [Real],
        new: &mut [Real],
    ) -> (Grow, u32) {
        self.grow(cx, target, range, scratch, new, true)
    }

    /// Grow one step of at most `range` toward `target` (a state of the other tree, or the next
    /// step of a CONNECT), from the node [`select`](Self::select) picks; no domain applies.
    pub fn extend(
        &mut self,
        cx: &mut Context,
        target: &[Real],
        range: Real,
        scratch: &mut [Real],
        new: &mut [Real],
    ) -> (Grow, u32) {
        self.grow(cx, target, range, scratch, new, false)
    }

    /// What every growth toward `target` does first (both connects): pick the node to grow from
    /// ([`select`](Self::select)) and say so; then `Err` with the outcome when there is nothing to
    /// grow (the target is that node, a sample outside its dynamic domain, no node may be added),
    /// else `Ok((near, distance))`.
    pub(super) fn begin_growth(
        &mut self,
        cx: &mut Context,
        target: &[Real],
        sample: bool,
    ) -> Result<(u32, Real), (Grow, u32)> {
        self.slid = false;
        let (near, d) = self.select(cx, target);
        cx.note_nearest(self.index, near, self.state(near), target, d, self.domain(near), sample);
        if d == 0.0 {
            return Err((Grow::Reached, near));
        }
        if sample && d > self.domain(near) {
            self.rejected += 1;
            return Err((Grow::Rejected, near));
        }
        if cx.nodes_left == 0 {
            return Err((Grow::Trapped, near));
        }
        Ok((near, d))
    }

    fn grow(
        &mut self,
        cx: &mut Context,
        target: &[Real],
        range: Real,
        scratch: &mut [Real],
        new: &mut [Real],
        sample: bool,
    ) -> (Grow, u32) {
        let (near, d) = match self.begin_growth(cx, target, sample) {
            Ok(nd) => nd,
            Err(outcome) => return outcome,
        };
        let reached = d <= range;
        if reached {
            new.copy_from_slice(target);
        } else {
            cx.si.interpolate(self.state(near), target, range / d, new);
        }
        // Growth must make progress: under a metric that is not convex along straight lines in
        // state space (the chain metrics), a step toward the target can end farther from it.
        if !reached && cx.si.distance(new, target) >= d {
            return (Grow::Trapped, near);
        }
        let near_state = &self.states[near as usize * self.dims..(near as usize + 1) * self.dims];
        cx.note_steer(self.index, near, near_state, new, if reached { d } else { range }, range, reached);
        if cx.si.check_motion(near_state, new, scratch).is_err() {
            cx.note_collision(self.index, near, near_state, new, scratch);
            cx.sampler.note_collision(self.state(near));
            if self.opts.ladder > 0 {
                if let Some(id) = self.ladder(cx, near, target, d, scratch, new) {
                    self.slid = true;
                    return (Grow::Advanced, id);
                }
            }
            self.record(cx, near, true);
            return (Grow::Trapped, near);
        }
        let id = self.append(cx, near, new);
        (if reached { Grow::Reached } else { Grow::Advanced }, id)
    }

    /// Add `new` as a child of `near` after its motion was found valid: the node's books, the
    /// run's node budget, the `NodeAdded` event.
    fn append(&mut self, cx: &mut Context, near: u32, new: &[Real]) -> u32 {
        self.record(cx, near, false);
        let id = self.add(cx, new, near);
        cx.nodes_left -= 1;
        let (p, q) = (cx.si.project(new), cx.si.project(self.state(near)));
        cx.events.push(EventKind::NodeAdded, self.index, id as i64, near as i64, p, q, new, self.state(near));
        id
    }

    /// Ladder steps after the step from `near` to `new` collided (see the module documentation):
    /// each moves every coordinate of that step with probability 1/2 (one random bit each) and
    /// keeps the others at `near`'s. A try that moves none of them, is the whole step again, or
    /// does not end nearer `target` than `d`, costs no check. The first valid one is added (its
    /// `Steer` event carries the coordinates moved and the try's number) and returned, in `new`
    /// too.
    fn ladder(
        &mut self,
        cx: &mut Context,
        near: u32,
        target: &[Real],
        d: Real,
        scratch: &mut [Real],
        new: &mut [Real],
    ) -> Option<u32> {
        let n = self.dims;
        let mut buf = std::mem::take(&mut self.ladder_buf);
        buf.clear();
        buf.extend_from_slice(self.state(near));
        buf.extend_from_slice(new);
        let (from, step) = buf.split_at_mut(n);
        let mut found = None;
        for attempt in 1..=self.opts.ladder {
            let mut moved = 0;
            let mut bits = 0u64;
            for k in 0..n {
                if k % 64 == 0 {
                    bits = cx.rng.next_u64();
                }
                let take = bits & 1 == 1;
                bits >>= 1;
                step[k] = if take { new[k] } else { from[k] };
                moved += (step[k] != from[k]) as usize;
            }
            if moved == 0 || step == new || cx.si.distance(step, target) >= d {
                continue;
            }
            if cx.si.check_motion(from, step, scratch).is_ok() {
                cx.note_ladder(self.index, near, from, step, moved, attempt);
                new.copy_from_slice(step);
                found = Some(self.append(cx, near, new));
                break;
            }
        }
        self.ladder_buf = buf;
        found
    }

    /// Whether the last growth step was a ladder step: a CONNECT ends after one, so one iteration
    /// never crawls along a wall in thousands of partial steps (its time and a suspended batch's
    /// replay stay those of one blocked CONNECT).
    pub fn slid(&self) -> bool {
        self.slid
    }

    /// Grow step after step toward `target` (RRT-Connect's CONNECT) until it is reached, a step is
    /// trapped or was a ladder step, or [`MAX_CONNECT_STEPS`] steps were taken. Returns the last
    /// outcome and the last node reached or added.
    pub fn connect(
        &mut self,
        cx: &mut Context,
        target: &[Real],
        range: Real,
        scratch: &mut [Real],
        new: &mut [Real],
    ) -> (Grow, u32) {
        let mut last = (Grow::Trapped, 0);
        for _ in 0..MAX_CONNECT_STEPS {
            last = self.extend(cx, target, range, scratch, new);
            if last.0 != Grow::Advanced || self.slid {
                break;
            }
        }
        last
    }

    /// Every edge as `(parent state, child state)`.
    pub fn edges(&self) -> impl Iterator<Item = (&[Real], &[Real])> {
        (0..self.len() as u32).filter(|&i| self.parent(i) != ROOT).map(|i| (self.state(self.parent(i)), self.state(i)))
    }
}

/// What a planner built (OMPL's `PlannerData`), for drawing and for re-checking in tests: its
/// trees, and a graph's vertices and edges. Every edge here, of a tree or of the graph, is a motion
/// the planner checked and kept ([`PlannerData::motions`]).
#[derive(Clone, Debug, Default)]
pub struct PlannerData {
    /// The trees (tree planners, EST, grid and hexagonal search, the potential field's descent,
    /// the visibility graph's search tree).
    pub trees: Vec<Tree>,
    /// A graph's vertices (a roadmap's milestones), `dims` numbers each, flat.
    pub vertices: Vec<Real>,
    /// Numbers per vertex.
    pub dims: usize,
    /// The graph's edges, as vertex pairs: those whose motion was checked and found valid (a Lazy
    /// PRM's edges that no path used are unchecked, so not here).
    pub edges: Vec<(u32, u32)>,
}

impl PlannerData {
    /// Trees only.
    pub fn of_trees(trees: Vec<Tree>) -> PlannerData {
        PlannerData { trees, ..PlannerData::default() }
    }
    /// Vertex `v` of the graph.
    pub fn vertex(&self, v: u32) -> &[Real] {
        let v = v as usize;
        &self.vertices[v * self.dims..(v + 1) * self.dims]
    }
    /// Vertices of the graph.
    pub fn vertex_count(&self) -> usize {
        self.vertices.len().checked_div(self.dims).unwrap_or(0)
    }
    /// Every motion the planner checked and kept: each tree's edges (parent → child), then the
    /// graph's.
    pub fn motions(&self) -> impl Iterator<Item = (&[Real], &[Real])> {
        self.trees.iter().flat_map(Tree::edges).chain(self.edges.iter().map(|&(a, b)| (self.vertex(a), self.vertex(b))))
    }
}

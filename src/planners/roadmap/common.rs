//! The roadmap planner the three roadmap methods share: how a milestone is added and connected,
//! and how a query is answered. The methods differ only in their neighbour rule ([`Neighbours`])
//! and in whether edges are checked when added or when a query's path uses them (`lazy`).
//!
//! One iteration is one construction step followed, when the roadmap changed, by one query:
//!
//! 1. draw a sample (the run's sampler, so PRM can use the Gaussian or bridge samplers of the
//!    literature); keep it as a milestone if it is valid;
//! 2. connect it to its neighbours: checked edges (PRM, PRM*) keep only valid motions; unchecked
//!    edges (Lazy PRM) are all kept;
//! 3. query: if start and goal are in one component, A* finds the shortest path over the roadmap;
//!    for Lazy PRM its unchecked edges are checked in order, an invalid one is removed and the
//!    search runs again, until a path of valid edges is found or start and goal come apart.
//!    Each search after an invalid edge is an iteration of its own, with no milestone added, so
//!    one iteration is at most one graph search: a batch suspended in the middle of a long
//!    query replays one search, not all those before it (see [`crate::journal`]). The runs are
//!    the same records, checks and path as one iteration per query; only the count differs.
//!
//! The start and the goal are the roadmap's first two vertices (terminals, not milestones), and
//! new milestones connect to them like to any vertex. [`RoadmapPlanner::query`] answers a further
//! query on the same roadmap: its start and goal join as terminals and the search runs again, with
//! no milestone added.

use super::graph::{EdgeState, Roadmap};
use crate::events::EventKind;
use crate::math::Real;
use crate::motion::MotionValidator;
use crate::planners::Checkpoint;
use crate::planners::{Context, Planner, PlannerData, Task};
use crate::space::StateSpace;

/// Which vertices a new vertex is connected to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Neighbours {
    /// The `k` nearest.
    Nearest(usize),
    /// Those within a radius.
    Radius(Real),
    /// PRM*'s k: the `⌈k_prm · ln n⌉` nearest (`n`: vertices before the new one).
    KStar(Real),
    /// PRM*'s radius: `r_prm · (ln n / n)^(1/d)`.
    RStar(Real),
}

impl Neighbours {
    /// The `k` of a k-nearest rule for a roadmap of `n` vertices (none for a radius rule).
    pub fn k(&self, n: usize) -> Option<usize> {
        match *self {
            Neighbours::Nearest(k) => Some(k),
            Neighbours::KStar(k_prm) => Some(k_star(k_prm, n)),
            _ => None,
        }
    }
    /// The radius of a radius rule for a roadmap of `n` vertices in `d` dimensions.
    pub fn radius(&self, n: usize, d: usize) -> Option<Real> {
        match *self {
            Neighbours::Radius(r) => Some(r),
            Neighbours::RStar(r_prm) => {
                let n = (n as Real).max(2.0);
                Some(r_prm * libm::pow(libm::log(n) / n, 1.0 / d as Real))
            }
            _ => None,
        }
    }
    fn find(&self, g: &mut Roadmap, space: &StateSpace, q: &[Real]) -> Vec<(u32, Real)> {
        let n = g.len();
        match (self.k(n), self.radius(n, space.dim_count())) {
            (Some(k), _) => g.k_nearest(space, q, k),
            (_, Some(r)) => g.within(space, q, r),
            _ => Vec::new(),
        }
    }
}

/// `⌈k_prm · ln n⌉` for a roadmap of `n` vertices, at least 1 (OMPL's `KStarStrategy`).
pub fn k_star(k_prm: Real, n: usize) -> usize {
    (libm::ceil(k_prm * libm::log(n.max(1) as Real)).max(1.0)) as usize
}

/// What a roadmap planner has done, for tests, the CLI and the page.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RoadmapStats {
    /// Milestones (sampled vertices; the terminals are not counted).
    pub milestones: usize,
    /// Edge motions checked (for PRM and PRM*: every candidate edge; for Lazy PRM: those a query
    /// path used).
    pub edges_checked: u64,
    /// Of those, found invalid.
    pub edges_invalid: u64,
    /// Graph searches run.
    pub searches: u64,
    /// Vertices the searches closed.
    pub expanded: u64,
}

/// A roadmap planner (PRM, PRM* or Lazy PRM: see the module doc).
#[derive(Clone)]
pub struct RoadmapPlanner {
    task: Task,
    rule: Neighbours,
    lazy: bool,
    graph: Roadmap,
    stats: RoadmapStats,
    sample: Vec<Real>,
    scratch: Vec<Real>,
    a: Vec<Real>,
    b: Vec<Real>,
    /// Iterations spent improving after the first solution (PRM*; 0: return the first).
    improve_for: u64,
    iterations: u64,
    solved_at: Option<u64>,
    /// The shortest path found so far and its cost (while improving).
    best: Option<(Vec<Vec<Real>>, Real)>,
    /// The last search's path had an invalid edge (Lazy PRM): the next iteration searches again
    /// without growing.
    search_again: bool,
    /// A milestone's edges stopped for want of bytes (`Context::bytes_left`): the run stops at
    /// its memory limit.
    out_of_memory: bool,
}

/// A search whose path had an invalid edge, now removed: search again.
#[derive(Debug)]
pub struct SearchAgain;

impl RoadmapPlanner {
    /// A roadmap planner for `task` (its start and goal become the first two vertices on the
    /// first iteration), connecting by `rule`, checking edges lazily or not.
    pub fn new(dims: usize, task: &Task, rule: Neighbours, lazy: bool) -> Self {
        RoadmapPlanner {
            task: task.clone(),
            rule,
            lazy,
            graph: Roadmap::new(dims),
            stats: RoadmapStats::default(),
            sample: vec![0.0; dims],
            scratch: vec![0.0; dims],
            a: vec![0.0; dims],
            b: vec![0.0; dims],
            improve_for: 0,
            iterations: 0,
            solved_at: None,
            best: None,
            search_again: false,
            out_of_memory: false,
        }
    }
    /// Keep growing the roadmap for `iterations` after the first solution, searching it again
    /// after each milestone: a shorter path is a `Cost` event (the page's cost chart), and the
    /// shortest is returned at the end (PRM*, whose paths approach the optimum as it grows).
    pub fn improving(mut self, iterations: u64) -> Self {
        self.improve_for = iterations;
        self
    }
    /// The roadmap.
    pub fn roadmap(&self) -> &Roadmap {
        &self.graph
    }
    /// The counts so far.
    pub fn stats(&self) -> RoadmapStats {
        self.stats
    }
    /// The neighbour rule.
    pub fn rule(&self) -> Neighbours {
        self.rule
    }
    /// Whether edges are checked only when a query's path uses them.
    pub fn is_lazy(&self) -> bool {
        self.lazy
    }

    /// Add the task's start and goal as vertices 0 and 1, once.
    pub fn init(&mut self, cx: &mut Context) {
        if self.graph.is_empty() {
            let (s, g) = (self.task.start.clone(), self.task.goal().to_vec());
            self.add_vertex(cx, &s);
            self.add_vertex(cx, &g);
        }
    }

    /// One construction step: sample, and add a milestone connected to its neighbours when the
    /// sample is valid. Returns whether a milestone was added.
    pub fn grow(&mut self, cx: &mut Context) -> bool {
        if cx.nodes_left == 0 || !cx.sample(0, &mut self.sample) {
            return false;
        }
        if !cx.si.is_valid(&self.sample) {
            cx.events.at(EventKind::SampleRejected, 0, cx.si.project(&self.sample), &self.sample);
            return false;
        }
        let q = self.sample.clone();
        if self.graph.k_nearest(&cx.si.space, &q, 1).first().is_some_and(|&(_, d)| d == 0.0) {
            return false; // already a vertex (the goal, drawn by a goal bias)
        }
        self.add_vertex(cx, &q);
        self.stats.milestones += 1;
        true
    }

    /// Add a vertex at the valid state `q` and connect it to its neighbours.
    fn add_vertex(&mut self, cx: &mut Context, q: &[Real]) -> u32 {
        let near = self.rule.find(&mut self.graph, &cx.si.space, q);
        let before = self.graph.bytes();
        let v = self.graph.add_vertex(&cx.si.space, q);
        cx.nodes_left = cx.nodes_left.saturating_sub(1);
        cx.bytes_left = cx.bytes_left.saturating_sub(self.graph.bytes() - before);
        let p = cx.si.project(q);
        cx.events.push(EventKind::NodeAdded, 0, v as i64, -1, p, p, q, q);
        for (u, d) in near {
            if cx.si.stopped() {
                break;
            }
            // A huge radius or k joins a milestone to every vertex: the edges count against the
            // run's memory, here where they are added.
            if cx.bytes_left < Roadmap::EDGE_BYTES {
                self.out_of_memory = true;
                break;
            }
            self.connect(cx, u, v, d);
        }
        v
    }

    /// Add the edge `u – v` of length `d`: unchecked (lazy), or checked and kept when valid.
    fn connect(&mut self, cx: &mut Context, u: u32, v: u32, d: Real) {
        self.a.copy_from_slice(self.graph.state(u));
        self.b.copy_from_slice(self.graph.state(v));
        let state = if self.lazy {
            EdgeState::Unchecked
        } else {
            self.stats.edges_checked += 1;
            if cx.si.check_motion(&self.a, &self.b, &mut self.scratch).is_err() {
                self.stats.edges_invalid += 1;
                cx.note_collision(0, u, &self.a, &self.b, &self.scratch);
                cx.sampler.note_collision(&self.a);
                return;
            }
            EdgeState::Valid
        };
        self.graph.add_edge(u, v, d, state);
        cx.bytes_left -= Roadmap::EDGE_BYTES;
        self.note_edge(cx, EventKind::RoadmapEdge, (state == EdgeState::Unchecked) as usize, u, v);
    }

    fn note_edge(&self, cx: &mut Context, kind: EventKind, tree: usize, u: u32, v: u32) {
        if cx.events.enabled {
            let (a, b) = (self.graph.state(u), self.graph.state(v));
            cx.events.push(kind, tree, u as i64, v as i64, cx.si.project(a), cx.si.project(b), a, b);
        }
    }

    /// The shortest path of valid edges from vertex `s` to vertex `g`, checking (lazy) the
    /// unchecked edges the search's paths use; `None` when there is none in the roadmap yet.
    pub fn query_vertices(&mut self, cx: &mut Context, s: u32, g: u32) -> Option<Vec<Vec<Real>>> {
        loop {
            if let Ok(path) = self.search(cx, s, g) {
                return path;
            }
        }
    }

    /// One search of [`RoadmapPlanner::query_vertices`]: the shortest path from `s` to `g`, its
    /// unchecked edges checked in order. `Ok(None)`: no path in the roadmap (or the run
    /// stopped); `Err`: the path had an invalid edge, removed, and another search may find one.
    pub fn search(&mut self, cx: &mut Context, s: u32, g: u32) -> Result<Option<Vec<Vec<Real>>>, SearchAgain> {
        if !self.graph.connected(s, g) || cx.si.stopped() {
            return Ok(None);
        }
        self.stats.searches += 1;
        let Some(path) = self.graph.shortest(cx.si, s, g, &mut self.stats.expanded) else {
            return Ok(None);
        };
        let verts = self.graph.walk(s, &path);
        for (i, w) in verts.windows(2).enumerate() {
            self.note_edge(cx, EventKind::QueryPath, (i > 0) as usize, w[0], w[1]);
        }
        let mut valid = true;
        for (i, &e) in path.iter().enumerate() {
            if self.graph.edges()[e as usize].state != EdgeState::Unchecked {
                continue;
            }
            let (u, v) = (verts[i], verts[i + 1]);
            self.a.copy_from_slice(self.graph.state(u));
            self.b.copy_from_slice(self.graph.state(v));
            self.stats.edges_checked += 1;
            if cx.si.check_motion(&self.a, &self.b, &mut self.scratch).is_ok() {
                self.graph.set_state(e, EdgeState::Valid);
                self.note_edge(cx, EventKind::EdgeChecked, 0, u, v);
            } else {
                self.stats.edges_invalid += 1;
                self.graph.set_state(e, EdgeState::Invalid);
                self.note_edge(cx, EventKind::EdgeChecked, 1, u, v);
                cx.note_collision(0, u, &self.a, &self.b, &self.scratch);
                valid = false;
                break;
            }
        }
        if cx.si.stopped() {
            return Ok(None); // a motion refused for want of time is not known invalid
        }
        if valid {
            return Ok(Some(verts.iter().map(|&v| self.graph.state(v).to_vec()).collect()));
        }
        Err(SearchAgain)
    }

    /// Answer a query on the roadmap as it stands: `start` and `goal` (valid states) join it as
    /// terminals, connected by the planner's rule, and the roadmap is searched; no milestone is
    /// added. `None` when the roadmap does not join them (yet).
    pub fn query(&mut self, cx: &mut Context, start: &[Real], goal: &[Real]) -> Option<Vec<Vec<Real>>> {
        self.init(cx);
        let s = self.add_vertex(cx, start);
        let g = self.add_vertex(cx, goal);
        self.query_vertices(cx, s, g)
    }
}

impl Planner for RoadmapPlanner {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let first = self.graph.is_empty();
        self.init(cx);
        let again = std::mem::take(&mut self.search_again);
        let grew = !again && self.grow(cx);
        if self.improve_for == 0 {
            if !grew && !first && !again {
                return None;
            }
            let Ok(found) = self.search(cx, 0, 1) else {
                self.search_again = true;
                return None;
            };
            let path = found?;
            let goal = self.task.goal();
            cx.events.at(EventKind::Solved, 0, cx.si.project(goal), goal);
            return Some(path);
        }
        // Anytime (PRM*): every milestone may shorten the path; the search runs again.
        let iteration = self.iterations;
        self.iterations += 1;
        if grew || first {
            if let Some(path) = self.query_vertices(cx, 0, 1) {
                let c = crate::planners::smoothing::path_cost(cx.si, &path);
                if self.best.as_ref().is_none_or(|(_, b)| c < *b) {
                    self.solved_at.get_or_insert(iteration);
                    let goal = self.task.goal();
                    cx.events.mark(EventKind::Cost, 0, 1, cx.iteration as Real, cx.si.project(goal), c, 0.0);
                    self.best = Some((path, c));
                }
            }
        }
        let solved = self.solved_at?;
        if iteration - solved < self.improve_for {
            return None;
        }
        let goal = self.task.goal();
        cx.events.at(EventKind::Solved, 0, cx.si.project(goal), goal);
        self.best_so_far()
    }
    fn best_so_far(&self) -> Option<Vec<Vec<Real>>> {
        self.best.as_ref().map(|(p, _)| p.clone())
    }
    fn node_count(&self) -> usize {
        self.graph.len()
    }
    fn roadmap_counts(&self) -> Option<crate::planners::RoadmapCounts> {
        Some(crate::planners::RoadmapCounts {
            edges_checked: self.stats.edges_checked,
            edges_invalid: self.stats.edges_invalid,
            edges: self.graph.edges().iter().filter(|e| e.state != EdgeState::Invalid).count() as u64,
        })
    }
    fn stored_bytes(&self) -> usize {
        self.graph.bytes()
    }
    fn out_of_memory(&self) -> bool {
        self.out_of_memory
    }
    fn memory_advice(&self) -> &'static str {
        match self.rule {
            Neighbours::Nearest(_) | Neighbours::KStar(_) => {
                "lower k (the neighbours each milestone is joined to), or max_nodes"
            }
            Neighbours::Radius(_) | Neighbours::RStar(_) => "lower the neighbour radius, or max_nodes",
        }
    }
    fn query(&mut self, cx: &mut Context, start: &[Real], goal: &[Real]) -> Option<Option<Vec<Vec<Real>>>> {
        Some(RoadmapPlanner::query(self, cx, start, goal))
    }
    /// No trees: the roadmap is read through [`RoadmapPlanner::roadmap`].
    fn data(&self) -> PlannerData {
        let g = &self.graph;
        PlannerData {
            trees: Vec::new(),
            vertices: g.states().to_vec(),
            dims: self.sample.len(),
            edges: g.edges().iter().filter(|e| e.state == EdgeState::Valid).map(|e| (e.a, e.b)).collect(),
        }
    }
}

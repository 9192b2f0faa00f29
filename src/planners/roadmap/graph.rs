//! The roadmap graph shared by PRM, PRM* and Lazy PRM: vertices (flat states with a k-d tree),
//! undirected edges that are either checked or still unchecked (Lazy PRM), connected components,
//! and A* over the usable edges.
//!
//! Nothing here checks a motion or draws a number: the planners decide which edges exist and in
//! which state; the graph keeps them and searches them. Ties in the search are broken by vertex
//! id, so a roadmap gives the same path every time.

use crate::math::Real;
use crate::nn::KdTree;
use crate::space::StateSpace;
use crate::space_info::SpaceInfo;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// What is known about an edge's motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EdgeState {
    /// Added without a motion check (Lazy PRM): usable by the search, checked when a path uses it.
    Unchecked,
    /// Checked: the motion is valid.
    Valid,
    /// Checked: the motion is invalid. The edge is out of the graph (kept so its id stays).
    Invalid,
}

/// An undirected edge between two vertices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge {
    /// One end (the older vertex).
    pub a: u32,
    /// The other end (the newer vertex).
    pub b: u32,
    /// The motion's length in the space's metric (the search's cost).
    pub len: Real,
    /// What is known about it.
    pub state: EdgeState,
}

/// A roadmap: vertices, edges and components.
#[derive(Clone, Debug)]
pub struct Roadmap {
    dims: usize,
    states: Vec<Real>,
    nn: KdTree,
    /// Edge ids at each vertex.
    adj: Vec<Vec<u32>>,
    edges: Vec<Edge>,
    /// Union-find over the usable edges (parent links).
    comp: Vec<u32>,
    /// An edge became invalid since the components were built: rebuild before asking.
    stale: bool,
}

/// A search entry: estimated total cost, vertex (min-heap by cost, then by id).
#[derive(Clone, Copy, PartialEq)]
struct Open(Real, u32);
impl Eq for Open {}
impl Ord for Open {
    fn cmp(&self, o: &Self) -> Ordering {
        o.0.total_cmp(&self.0).then_with(|| o.1.cmp(&self.1))
    }
}
impl PartialOrd for Open {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Roadmap {
    /// The bytes one more edge takes: the edge and its id at both ends.
    pub const EDGE_BYTES: usize = std::mem::size_of::<Edge>() + 2 * std::mem::size_of::<u32>();
    /// The bytes it holds: vertices (states, index, adjacency lists, components) and edges (see
    /// [`Planner::stored_bytes`](crate::planners::Planner::stored_bytes)).
    pub fn bytes(&self) -> usize {
        use crate::planners::{bytes_of, nested_bytes};
        bytes_of(&self.states)
            + self.nn.bytes()
            + nested_bytes::<u32>(self.adj.len(), 0)
            + bytes_of(&self.comp)
            + self.edges.len() * Self::EDGE_BYTES
    }
    /// An empty roadmap of `dims`-number states.
    pub fn new(dims: usize) -> Roadmap {
        Roadmap {
            dims,
            states: Vec::new(),
            nn: KdTree::new(dims),
            adj: Vec::new(),
            edges: Vec::new(),
            comp: Vec::new(),
            stale: false,
        }
    }
    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.adj.len()
    }
    /// Whether there is no vertex.
    pub fn is_empty(&self) -> bool {
        self.adj.is_empty()
    }
    /// A vertex's state.
    #[inline]
    pub fn state(&self, v: u32) -> &[Real] {
        let i = v as usize;
        &self.states[i * self.dims..(i + 1) * self.dims]
    }
    /// Every vertex's state, flat (`dims` numbers each, by id).
    pub fn states(&self) -> &[Real] {
        &self.states
    }
    /// Every edge, invalid ones included, by id.
    pub fn edges(&self) -> &[Edge] {
        &self.edges
    }
    /// The edges at vertex `v` (ids), invalid ones excluded.
    pub fn edges_at(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        self.adj[v as usize].iter().copied().filter(|&e| self.edges[e as usize].state != EdgeState::Invalid)
    }
    /// Add a vertex; returns its id.
    pub fn add_vertex(&mut self, space: &StateSpace, q: &[Real]) -> u32 {
        let id = self.adj.len() as u32;
        self.states.extend_from_slice(q);
        self.nn.add(space, q, id);
        self.adj.push(Vec::new());
        self.comp.push(id);
        id
    }
    /// The `k` vertices nearest to `q`, nearest first (ties by id).
    pub fn k_nearest(&mut self, space: &StateSpace, q: &[Real], k: usize) -> Vec<(u32, Real)> {
        self.nn.k_nearest(space, q, k)
    }
    /// The vertices within `r` of `q`, nearest first (ties by id).
    pub fn within(&mut self, space: &StateSpace, q: &[Real], r: Real) -> Vec<(u32, Real)> {
        self.nn.within(space, q, r)
    }
    /// Add an edge (`state`: checked valid, or unchecked); returns its id.
    pub fn add_edge(&mut self, a: u32, b: u32, len: Real, state: EdgeState) -> u32 {
        let id = self.edges.len() as u32;
        self.edges.push(Edge { a, b, len, state });
        self.adj[a as usize].push(id);
        self.adj[b as usize].push(id);
        if state != EdgeState::Invalid {
            self.union(a, b);
        }
        id
    }
    /// Set what is known about edge `e` (an invalid edge leaves the graph).
    pub fn set_state(&mut self, e: u32, state: EdgeState) {
        let edge = &mut self.edges[e as usize];
        if state == EdgeState::Invalid && edge.state != EdgeState::Invalid {
            self.stale = true;
        }
        edge.state = state;
    }
    fn find(&mut self, mut v: u32) -> u32 {
        while self.comp[v as usize] != v {
            let up = self.comp[self.comp[v as usize] as usize];
            self.comp[v as usize] = up;
            v = up;
        }
        v
    }
    fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        // The smaller id is the root: the same edges give the same forest, whatever the order.
        if ra != rb {
            let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
            self.comp[hi as usize] = lo;
        }
    }
    /// Whether `a` and `b` are joined by usable (valid or unchecked) edges.
    pub fn connected(&mut self, a: u32, b: u32) -> bool {
        if self.stale {
            self.stale = false;
            for v in 0..self.comp.len() {
                self.comp[v] = v as u32;
            }
            for e in 0..self.edges.len() {
                let Edge { a, b, state, .. } = self.edges[e];
                if state != EdgeState::Invalid {
                    self.union(a, b);
                }
            }
        }
        self.find(a) == self.find(b)
    }
    /// Number of connected components.
    pub fn components(&mut self) -> usize {
        let _ = self.connected(0, 0);
        (0..self.len() as u32).filter(|&v| self.find(v) == v).count()
    }
    /// The shortest path from `a` to `b` over usable edges, as edge ids in order, by A* with the
    /// space's distance as heuristic (admissible: an edge's cost is its length in that metric);
    /// `None` when they are not connected, or when the run must stop (`si.tick`, a unit a vertex
    /// closed). `expanded` counts the vertices the search closed.
    pub fn shortest(&self, si: &SpaceInfo, a: u32, b: u32, expanded: &mut u64) -> Option<Vec<u32>> {
        let space = &si.space;
        let n = self.len();
        let mut g = vec![Real::INFINITY; n];
        let mut via = vec![u32::MAX; n];
        let mut closed = vec![false; n];
        let goal = self.state(b);
        let mut open = BinaryHeap::new();
        g[a as usize] = 0.0;
        open.push(Open(space.distance(self.state(a), goal), a));
        while let Some(Open(_, v)) = open.pop() {
            if closed[v as usize] {
                continue;
            }
            closed[v as usize] = true;
            *expanded += 1;
            // A search over a large roadmap is long work: the run's time limit and a bounded
            // batch's suspension hold inside it (a stopped search finds nothing).
            if si.tick(1) {
                return None;
            }
            if v == b {
                let mut path = Vec::new();
                let mut at = b;
                while at != a {
                    let e = via[at as usize];
                    path.push(e);
                    let edge = &self.edges[e as usize];
                    at = if edge.a == at { edge.b } else { edge.a };
                }
                path.reverse();
                return Some(path);
            }
            for e in self.edges_at(v) {
                let edge = &self.edges[e as usize];
                let w = if edge.a == v { edge.b } else { edge.a };
                let c = g[v as usize] + edge.len;
                if c < g[w as usize] {
                    g[w as usize] = c;
                    via[w as usize] = e;
                    open.push(Open(c + space.distance(self.state(w), goal), w));
                }
            }
        }
        None
    }
    /// The vertices along a path of edge ids that starts at `from`.
    pub fn walk(&self, from: u32, path: &[u32]) -> Vec<u32> {
        let mut out = vec![from];
        let mut at = from;
        for &e in path {
            let edge = &self.edges[e as usize];
            at = if edge.a == at { edge.b } else { edge.a };
            out.push(at);
        }
        out
    }
}

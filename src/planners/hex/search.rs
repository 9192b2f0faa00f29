//! A complete search over the hexagonal cells: A* or Dijkstra on the decomposition's
//! adjacency, beside report 002's greedy descent.
//!
//! The graph is the descent's: the free leaves (and the start's and goal's leaves), each stood for
//! by its centre (the start's leaf by the start itself), joined where the cells touch and the step
//! between the two points passes the report's step test ([`step_test`](super::step::step_test)).
//! The goal point is one more node, reached from its own leaf or a neighbour of it by a step test,
//! as the descent reaches it. Edge costs are the step lengths; A*'s heuristic is the straight
//! distance to the goal (admissible, so both return a shortest path of this graph, of the same
//! cost). The region of influence plays no part: the search may use every cell.
//!
//! One iteration pops one node and judges its neighbours; every verdict is evented as a
//! `CellState` (0 opened or improved, 1 blocked by the step test with why, 2 closed), so the page
//! draws the open and closed cells as they change.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::step::{disc_blocked, step_test};
use super::{blocked_text, CellLabel, HexPotential};
use crate::events::EventKind;
use crate::math::{Real, Vec2};
use crate::planners::{Context, Tree};

/// Which complete search.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Search {
    /// A*, with the straight distance to the goal as the heuristic.
    AStar,
    /// Dijkstra (no heuristic).
    Dijkstra,
}

/// An entry of the open set: lower `f` first, then the lower node (so runs are deterministic).
#[derive(Clone, Copy, Debug)]
struct Open {
    f: Real,
    node: usize,
}

impl PartialEq for Open {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}
impl Eq for Open {}
impl PartialOrd for Open {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Open {
    fn cmp(&self, o: &Self) -> Ordering {
        // BinaryHeap is a max-heap: the smallest f (then node) is the greatest.
        o.f.total_cmp(&self.f).then(o.node.cmp(&self.node))
    }
}

/// The search's state between iterations. Nodes `0..n` are the decomposition's graph nodes; node
/// `n` is the goal point.
#[derive(Clone, Debug)]
pub struct Frontier {
    kind: Search,
    goal: Vec2,
    g: Vec<Real>,
    parent: Vec<Option<usize>>,
    closed: Vec<bool>,
    open: BinaryHeap<Open>,
    /// A*'s weight on the heuristic (1: a shortest path).
    weight: Real,
    /// Nodes closed so far (popped and expanded).
    pub expanded: usize,
}

impl Frontier {
    /// The bytes it holds per cell, and its queue (see [`Planner::stored_bytes`](crate::planners::Planner::stored_bytes)).
    pub fn bytes(&self) -> usize {
        use crate::planners::bytes_of;
        bytes_of(&self.g)
            + bytes_of(&self.parent)
            + bytes_of(&self.closed)
            + self.open.len() * std::mem::size_of::<Open>()
    }
    /// A search over `n` graph nodes (and the goal point) from node `start`.
    pub fn new(kind: Search, n: usize, start: usize, start_point: Vec2, goal: Vec2) -> Frontier {
        let mut f = Frontier {
            kind,
            goal,
            g: vec![Real::INFINITY; n + 1],
            parent: vec![None; n + 1],
            closed: vec![false; n + 1],
            open: BinaryHeap::new(),
            weight: 1.0,
            expanded: 0,
        };
        f.g[start] = 0.0;
        f.open.push(Open { f: f.h(start_point), node: start });
        f
    }

    /// The same search with A*'s heuristic weighted by `w` (the grid search's choice; the start's
    /// entry keeps its key, which orders nothing while it is alone).
    pub fn weighted(mut self, w: Real) -> Frontier {
        self.weight = w;
        self
    }

    /// The goal point's node.
    pub fn goal_node(&self) -> usize {
        self.g.len() - 1
    }

    fn h(&self, p: Vec2) -> Real {
        match self.kind {
            Search::AStar => self.weight * (self.goal - p).norm(),
            Search::Dijkstra => 0.0,
        }
    }

    /// The next node to expand (skipping stale entries), closed now; `None` when the open set is
    /// empty.
    pub fn pop(&mut self) -> Option<usize> {
        while let Some(Open { node, .. }) = self.open.pop() {
            if !self.closed[node] {
                self.closed[node] = true;
                self.expanded += 1;
                return Some(node);
            }
        }
        None
    }

    /// Whether `node` is closed.
    pub fn is_closed(&self, node: usize) -> bool {
        self.closed[node]
    }

    /// Offer the step `from → to` (at point `at`) of length `len`; whether it improved `to`.
    pub fn relax(&mut self, from: usize, to: usize, at: Vec2, len: Real) -> bool {
        let g = self.g[from] + len;
        if self.closed[to] || g >= self.g[to] {
            return false;
        }
        self.g[to] = g;
        self.parent[to] = Some(from);
        self.open.push(Open { f: g + self.h(at), node: to });
        true
    }

    /// The cost of the best way found to `node`.
    pub fn cost(&self, node: usize) -> Real {
        self.g[node]
    }

    /// The node `node` is reached from on its best way (none for the start).
    pub fn parent(&self, node: usize) -> Option<usize> {
        self.parent[node]
    }

    /// The nodes from the start to `node`, the start first.
    pub fn chain(&self, node: usize) -> Vec<usize> {
        let mut out = vec![node];
        let mut at = node;
        while let Some(p) = self.parent[at] {
            out.push(p);
            at = p;
        }
        out.reverse();
        out
    }
}

/// The complete search's side of the planner.
impl HexPotential {
    /// Start the complete search: its tree (for the final path) and its open set.
    pub(super) fn begin_complete(&mut self, cx: &mut Context, kind: Search) {
        let p0 = self.start_point();
        let q0 = self.start.clone();
        self.trees.push(Tree::new(cx, &q0, 0));
        self.frontier = Some(Frontier::new(kind, self.nodes.len(), self.start_node, p0, self.goal_point()));
        if self.t > 0.0 {
            if let Some(why) = disc_blocked(&self.ws, p0, self.t) {
                self.failure = Some(format!("the robot cannot turn at the start: {}", blocked_text(why as u8)));
            }
        }
    }

    /// Where graph node `k` stands: the start for the start's leaf, else its cell's centre.
    fn node_point(&self, k: usize) -> Vec2 {
        if k == self.start_node {
            self.start_point()
        } else {
            self.dec.cells[self.nodes[k]].centre
        }
    }

    /// One step of the complete search: close the best open node and judge its neighbours.
    pub(super) fn complete_one(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let mut f = self.frontier.take().expect("the search has begun");
        let out = self.expand(cx, &mut f);
        self.frontier = Some(f);
        out
    }

    fn expand(&mut self, cx: &mut Context, f: &mut Frontier) -> Option<Vec<Vec<Real>>> {
        let goal = f.goal_node();
        let g = self.goal_point();
        let Some(k) = f.pop() else {
            self.failure = Some(format!(
                "no path: the complete search closed all {} cells it could reach and none steps to the goal at this resolution",
                f.expanded
            ));
            return None;
        };
        if k == goal {
            // The goal point closed: its way is a shortest one. Step the robot along it.
            let chain = f.chain(goal);
            for &m in &chain[1..chain.len() - 1] {
                let c = self.node_point(m);
                self.advance(cx, c);
            }
            self.advance(cx, g);
            cx.events.at(EventKind::Solved, 0, g, &self.goal);
            return Some(self.path());
        }
        let p = self.node_point(k);
        let from = self.nodes[k] as i64;
        let parent = f.parent(k).map_or(-1, |m| self.nodes[m] as i64);
        cx.events.values(EventKind::CellState, 0, from, parent, [p.x, p.y, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        if k == self.goal_node || self.adj[k].contains(&self.goal_node) {
            cx.si.count_checks(1);
            let gc = self.nodes[self.goal_node] as i64;
            match step_test(&self.ws, p, g, self.t) {
                Ok(()) => {
                    if f.relax(k, goal, g, (g - p).norm()) {
                        cx.events.values(EventKind::CellState, 0, gc, from, [g.x, g.y, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
                    }
                }
                Err(why) => cx.events.values(
                    EventKind::CellState,
                    0,
                    gc,
                    from,
                    [g.x, g.y, 1.0, why as u8 as f64, 0.0, 0.0, 0.0, 0.0],
                ),
            }
        }
        for j in 0..self.adj[k].len() {
            let m = self.adj[k][j];
            let i = self.nodes[m];
            if f.is_closed(m) || self.dec.cells[i].label != CellLabel::Free {
                continue;
            }
            let c = self.node_point(m);
            cx.si.count_checks(1);
            match step_test(&self.ws, p, c, self.t) {
                Ok(()) => {
                    if f.relax(k, m, c, (c - p).norm()) {
                        cx.events.values(
                            EventKind::CellState,
                            0,
                            i as i64,
                            from,
                            [c.x, c.y, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                        );
                    }
                }
                Err(why) => cx.events.values(
                    EventKind::CellState,
                    0,
                    i as i64,
                    from,
                    [c.x, c.y, 1.0, why as u8 as f64, 0.0, 0.0, 0.0, 0.0],
                ),
            }
        }
        None
    }
}

//! Visibility graph: the exact shortest path of a point (or a disc) among polygons.
//!
//! T. Lozano-Pérez and M. A. Wesley, "An algorithm for planning collision-free paths among
//! polyhedral obstacles", CACM 22(10), 1979; M. de Berg et al., *Computational Geometry*, ch. 15.
//! It draws the reference line on RRT*'s cost chart.
//!
//! # The method
//!
//! A shortest path among polygonal obstacles is a polyline that bends only at convex obstacle
//! vertices. So the planner
//!
//! 1. **grows the obstacles** into polygons (see below) and takes as graph vertices the start, the
//!    goal and every convex vertex of the grown polygons that lies in bounds and strictly inside
//!    no grown polygon;
//! 2. **builds the graph**: every pair of vertices whose segment is tangent at both ends (a
//!    vertex's two polygon neighbours on one side of the line; other pairs can never be on a
//!    shortest path) is tested *exactly* ([`Workspace::sight_clear`](crate::geometry::Workspace::sight_clear): the segment may touch a
//!    grown polygon's boundary, slide along an edge, pass a vertex, but never cross an interior),
//!    a batch of pairs per iteration; each visible pair is a
//!    [`GraphEdge`](EventKind::GraphEdge) event;
//! 3. **searches** it by A* (Euclidean heuristic, exact since edges are straight), a batch of
//!    settled vertices per iteration, each a `NodeAdded` of tree 0 (the search tree);
//! 4. **checks** the path found with the run's motion validator (the scenario's resolution and the
//!    robot's exact sweep), as every planner's motions are, and returns it.
//!
//! # Growing the obstacles
//!
//! With `g` the growth, every obstacle is replaced by polygons containing the set of points within
//! `g` of it: a convex obstacle (rect, convex polygon, segment, circle) by the convex hull of its
//! vertices plus the vertices of a regular `sides`-gon of *apothem* `g` (so the polygon contains the
//! disc of radius `g`, and the grown polygon contains the true Minkowski sum: conservative); a
//! circle of radius `r` by the regular `sides`-gon of apothem `r + g` about its centre; a
//! non-convex polygon by itself plus, for each edge, the hull of the edge plus the `sides`-gon.
//! The growth is
//!
//! - for a **point robot**: a margin `ε = 1e-7 ×` the map's larger side, so the path stays off
//!   every boundary: a point (or rigid) robot's state on an obstacle's boundary is a collision
//!   whatever the scenario's `touching_allowed` says (that key opens obstacles only to the segment
//!   robots, arms: see [`Workspace::touching_allowed`](crate::geometry::Workspace::touching_allowed)). The shortest path would slide along
//!   boundaries; with the margin its cost is above that infimum (which no valid path attains) by a
//!   few `ε`;
//! - for a **rigid robot**: treated as its bounding disc (radius `R` = its footprint's farthest
//!   vertex from the rotation point) plus the margin `ε`; the heading turns from the start's to the
//!   goal's in proportion to the distance travelled (a disc may turn anywhere). For a footprint
//!   that is itself (nearly) a disc, a regular polygon centred on the rotation point, this is the
//!   optimum in the robot's metric (translation plus `weight·|Δθ|`) up to the approximations; for
//!   other footprints it is a valid path but not the optimum (see [`optimum`](crate::run::optimum)).
//!
//! Circles are approximated by `sides`-gons, so on maps with circles the path is the optimum among
//! the approximating polygons: longer than the true optimum by at most a factor
//! `1 / cos(π / sides)` on the arcs it wraps (0.5% with 32 sides).

mod grow;

pub use grow::{body_of, grow, grown_vertices, growth, Body, GrowError, Grown, MARGIN};

use crate::events::EventKind;
use crate::geometry::segment::orient_sign;
use crate::journal::Entry as Recorded;
use crate::math::{angle_diff, wrap_angle, Real, Vec2};
use crate::motion::MotionValidator;
use crate::planners::caps::{Capabilities, Draws, EventSet, Family, LegendItem};
use crate::planners::Checkpoint;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree};
use crate::space_info::SpaceInfo;
use std::cmp::Ordering;
use std::collections::BinaryHeap;
use std::rc::Rc;

/// The legend: the search and the graph.
const LEGEND: &[LegendItem] =
    &[LegendItem::line("A* search tree", "tree0"), LegendItem::line("visibility-graph edge", "graphEdge")];

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "visibility-graph",
    label: "Visibility graph (shortest path)",
    summary: "The exact shortest path of a point (or a disc, by growing the obstacles) among polygons: tangent visibility graph, then A*.",
    iteration: "A batch of vertex pairs tested for sight while building the graph, or a batch of vertices settled by A*.",
    checks: "State validity checks of the path found (the sight tests are exact geometry, not counted).",
    params: PARAMS,
    groups: &[],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Exact,
        draws: Draws::ExactGraph,
        trees: 1,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: true,
        events: EventSet::of(&[EventKind::GraphEdge, EventKind::NodeAdded, EventKind::Cost, EventKind::Solved]),
        pseudocode: "exact-visibility-graph",
        legend: LEGEND,
        marks: &[],
        overlays: &[],
    },
    make: |si, task, params| Ok(Box::new(VisibilityGraph::new(si, task, params)?)),
};

/// The visibility graph's parameters.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec::int(
        "sides",
        "Disc sides",
        4.0,
        1024.0,
        32.0,
        "Circles (circle obstacles, and the disc a robot's obstacles are grown by) are approximated by regular polygons of this many sides that contain them.",
    ),
    ParamSpec::int(
        "batch",
        "Work per iteration",
        1.0,
        1e6,
        64.0,
        "Vertex pairs tested (while building) or vertices settled (while searching) per iteration.",
    ),
];

/// The bytes one edge of the graph takes (an entry in each end's adjacency list).
const EDGE_BYTES: usize = 2 * std::mem::size_of::<(u32, Real)>();

/// Pairs visited (most skipped by the tangent test) per pair tested, in an iteration's budget.
const VISITS: usize = 32;

/// A queue entry: estimated total, cost so far, vertex (ties broken by the vertex: deterministic).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Entry(Real, Real, u32);

impl Eq for Entry {}
impl Ord for Entry {
    fn cmp(&self, o: &Self) -> Ordering {
        o.0.total_cmp(&self.0).then(o.2.cmp(&self.2))
    }
}
impl PartialOrd for Entry {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

/// What the planner is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Testing pairs: the next is `(i, j)`.
    Build(usize, usize),
    /// A* on the graph.
    Search,
}

/// The visibility-graph planner.
#[derive(Clone)]
pub struct VisibilityGraph {
    grown: Rc<Grown>,
    /// Vertex points: 0 the start, 1 the goal, then the corners.
    points: Vec<Vec2>,
    /// Each vertex's two polygon neighbours (the start and goal: itself, so every pair passes).
    sides: Vec<[Vec2; 2]>,
    adj: Vec<Vec<(u32, Real)>>,
    phase: Phase,
    batch: usize,
    start: Vec<Real>,
    goal: Vec<Real>,
    /// Rigid robots: the heading's total turn from start to goal.
    turn: Option<Real>,
    /// The robot's disc radius (0: a point).
    radius: Real,
    // A* state.
    open: BinaryHeap<Entry>,
    cost: Vec<Real>,
    parent: Vec<u32>,
    closed: Vec<bool>,
    /// Tree id of each settled vertex.
    tree_id: Vec<u32>,
    tree: Option<Tree>,
    edges: usize,
    reason: Option<String>,
    /// The build stopped for want of bytes (`Context::bytes_left`): the run stops at its memory
    /// limit.
    out_of_memory: bool,
}

impl VisibilityGraph {
    /// A visibility-graph planner for `task`; an error for robots it does not apply to, or a start
    /// or goal too close to an obstacle for the growth.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Result<Self, String> {
        let body = body_of(si)?;
        let k = params.real("sides") as usize;
        let max_nodes = params.real("max_nodes");
        // The graph's vertices are the grown polygons' convex corners outside every other grown
        // polygon. Growing is refused before anything is grown when it could make more corners
        // than any run may hold (the cap on max_nodes); growing (seconds on a big map) stops at
        // the run's deadline; the corners kept are then held to max_nodes itself, exactly (corners
        // inside other obstacles are dropped, so a bound made before growing would refuse graphs
        // within max_nodes).
        let g = growth(si, body);
        let cap = crate::limits::MAX_NODES as u64;
        let grown = grow(si, si.workspace(), g, k, body.radius > 0.0, cap - 2)
            .map_err(|e| match e {
                GrowError::TooMany(n) => format!(
                    "growing the obstacles by the {} would make up to {n} corners, more than the {cap} any run's max_nodes allows: lower sides (now {k}) or simplify the obstacles",
                    if body.radius > 0.0 { format!("robot's disc (radius {:.3e}, a {k}-sided polygon)", body.radius) } else { "margin".to_string() },
                ),
                GrowError::Stopped { done, of } => format!(
                    "the time limit ({} s) ran out while growing the obstacles ({}): raise time_limit, lower sides (now {k}) or simplify the obstacles",
                    params.real("time_limit"),
                    if done < of { format!("{done} of {of} grown") } else { format!("all {of} grown, their corners being tested") }
                ),
            })?;
        let (start, goal) = (task.start.clone(), task.goal().to_vec());
        let (s, g) = (si.project(&start), si.project(&goal));
        for (what, p) in [("start", s), ("goal", g)] {
            if !grown.ws.sight_clear(p, p) {
                return Err(format!(
                    "the {what} ({}, {}) is within {:.3e} of an obstacle (the robot's disc{}): the grown obstacles cover it",
                    p.x,
                    p.y,
                    grown.growth,
                    if body.radius > 0.0 { " and the margin" } else { ", the margin kept from obstacles" }
                ));
            }
        }
        let mut points = vec![s, g];
        let mut sides = vec![[s, s], [g, g]];
        for c in &grown.corners {
            points.push(c[0]);
            sides.push([c[1], c[2]]);
        }
        if points.len() as Real > max_nodes {
            return Err(format!(
                "the graph has {} vertices, more than max_nodes ({max_nodes}): raise max_nodes or lower sides",
                points.len()
            ));
        }
        let n = points.len();
        let turn = (start.len() == 3).then(|| angle_diff(start[2], goal[2]));
        Ok(VisibilityGraph {
            grown: Rc::new(grown),
            points,
            sides,
            adj: vec![Vec::new(); n],
            phase: Phase::Build(0, 1),
            batch: params.real("batch") as usize,
            start,
            goal,
            turn,
            radius: body.radius,
            open: BinaryHeap::new(),
            cost: vec![Real::INFINITY; n],
            parent: vec![u32::MAX; n],
            closed: vec![false; n],
            tree_id: vec![u32::MAX; n],
            tree: None,
            edges: 0,
            reason: None,
            out_of_memory: false,
        })
    }

    /// Edges of the graph so far.
    pub fn edge_count(&self) -> usize {
        self.edges
    }

    /// Whether segment `i j` may be on a shortest path: tangent to the polygon at both ends.
    fn tangent(&self, i: usize, j: usize) -> bool {
        let (a, b) = (self.points[i], self.points[j]);
        let ok = |v: Vec2, w: Vec2, s: [Vec2; 2]| orient_sign(v, w, s[0]) * orient_sign(v, w, s[1]) >= 0;
        ok(a, b, self.sides[i]) && ok(b, a, self.sides[j])
    }

    /// The state at vertex `v`, `along` of the way (rigid robots: the heading turned that far).
    fn state(&self, v: u32, along: Real) -> Vec<Real> {
        match v {
            0 => self.start.clone(),
            1 => self.goal.clone(),
            _ => {
                let p = self.points[v as usize];
                match self.turn {
                    Some(t) => vec![p.x, p.y, wrap_angle(self.start[2] + t * along)],
                    None => vec![p.x, p.y],
                }
            }
        }
    }

    fn build(&mut self, cx: &mut Context) {
        let Phase::Build(mut i, mut j) = self.phase else { return };
        let n = self.points.len();
        // Pairs that are not tangent are skipped cheaply, but on a large map there are many: they
        // count too (VISITS of them per test), so an iteration stays short.
        let (mut tests, mut visits) = (0, 0);
        while tests < self.batch && visits < self.batch * VISITS && i < n {
            if j >= n {
                i += 1;
                j = i + 1;
                continue;
            }
            visits += 1;
            if visits % VISITS == 0 && cx.si.tick(1) {
                break;
            }
            if self.points[i] != self.points[j] && self.tangent(i, j) {
                tests += 1;
                let (a, b) = (self.points[i], self.points[j]);
                // Through the batch journal, so a bounded batch can be suspended in the middle
                // of a long build and replay its answers (see `crate::journal`).
                let ws = &self.grown.ws;
                let clear = cx.si.journalled(
                    |e| if let Recorded::Sight(v) = e { Some(*v) } else { None },
                    Recorded::Sight,
                    false,
                    || ws.sight_clear(a, b),
                );
                // The graph's edges count against the run's memory (two adjacency entries each).
                if clear && cx.bytes_left < EDGE_BYTES {
                    self.out_of_memory = true;
                    break;
                }
                if clear {
                    cx.bytes_left -= EDGE_BYTES;
                    let d = (b - a).norm();
                    self.adj[i].push((j as u32, d));
                    self.adj[j].push((i as u32, d));
                    self.edges += 1;
                    cx.events.values(
                        EventKind::GraphEdge,
                        0,
                        i as i64,
                        j as i64,
                        [a.x, a.y, b.x, b.y, d, 1.0, 0.0, 0.0],
                    );
                }
                // The answer counted its work (and looked at the clock when due).
                if cx.si.stopped() {
                    break;
                }
            }
            j += 1;
        }
        cx.si.count_checks(tests as u64);
        self.phase = if i >= n { Phase::Search } else { Phase::Build(i, j) };
        if self.phase == Phase::Search {
            self.cost[0] = 0.0;
            self.open.push(Entry((self.points[1] - self.points[0]).norm(), 0.0, 0));
            self.tree = Some(Tree::new(cx, &self.start, 0));
            self.tree_id[0] = 0;
        }
    }

    /// Settle up to a batch of vertices; the path when the goal is settled.
    fn search(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let goal = self.points[1];
        for _ in 0..self.batch {
            let Some(Entry(_, c, v)) = self.open.pop() else {
                self.reason = Some(format!(
                    "the start and goal are not connected in the visibility graph ({} vertices, {} edges): no path exists for {}",
                    self.points.len(),
                    self.edges,
                    match self.radius {
                        r if r > 0.0 => format!("the robot's bounding disc (radius {r}); the robot itself may still pass by turning"),
                        _ => "a point".to_string(),
                    },
                ));
                return None;
            };
            let vi = v as usize;
            if self.closed[vi] || c > self.cost[vi] {
                continue;
            }
            self.closed[vi] = true;
            if vi != 0 {
                let p = self.parent[vi];
                let q = self.state(v, 0.0);
                let tree = self.tree.as_mut().expect("the search has its tree");
                let id = tree.add(cx, &q, self.tree_id[p as usize]);
                self.tree_id[vi] = id;
                let pq = tree.state(self.tree_id[p as usize]).to_vec();
                let (a, b) = (cx.si.project(&q), cx.si.project(&pq));
                cx.events.push(EventKind::NodeAdded, 0, id as i64, self.tree_id[p as usize] as i64, a, b, &q, &pq);
            }
            if vi == 1 {
                return self.finish(cx);
            }
            for &(w, d) in &self.adj[vi] {
                let wi = w as usize;
                let nc = c + d;
                if !self.closed[wi] && nc < self.cost[wi] {
                    self.cost[wi] = nc;
                    self.parent[wi] = v;
                    self.open.push(Entry(nc + (goal - self.points[wi]).norm(), nc, w));
                }
            }
        }
        None
    }

    /// The goal is settled: the path, checked by the run's motion validator.
    fn finish(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let mut chain = vec![1u32];
        while *chain.last().unwrap() != 0 {
            chain.push(self.parent[*chain.last().unwrap() as usize]);
        }
        chain.reverse();
        let total = self.cost[1];
        let mut along = 0.0;
        let mut path = Vec::with_capacity(chain.len());
        for (k, &v) in chain.iter().enumerate() {
            if k > 0 {
                along += (self.points[v as usize] - self.points[chain[k - 1] as usize]).norm();
            }
            path.push(self.state(v, if total > 0.0 { along / total } else { 1.0 }));
        }
        let mut scratch = vec![0.0; cx.si.dims()];
        for (k, w) in path.windows(2).enumerate() {
            if cx.si.check_motion(&w[0], &w[1], &mut scratch).is_err() {
                if !cx.si.stopped() {
                    self.reason = Some(format!(
                        "segment {k} of the visibility path ({:?} → {:?}) failed the run's motion check: a bug, or a robot the disc does not bound",
                        w[0], w[1]
                    ));
                }
                return None;
            }
        }
        let cost: Real = path.windows(2).map(|w| cx.si.distance(&w[0], &w[1])).sum();
        let at = cx.si.project(&self.goal);
        cx.events.mark(EventKind::Cost, 0, self.tree_id[1] as i64, cx.iteration as f64, at, cost, 0.0);
        cx.events.at(EventKind::Solved, 0, at, &self.goal);
        Some(path)
    }
}

impl Planner for VisibilityGraph {
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.reason.is_some() {
            return None;
        }
        match self.phase {
            Phase::Build(..) => {
                self.build(cx);
                None
            }
            Phase::Search => self.search(cx),
        }
    }
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn node_count(&self) -> usize {
        self.points.len()
    }
    fn stored_bytes(&self) -> usize {
        use crate::planners::{bytes_of, nested_bytes};
        bytes_of(&self.points)
            + bytes_of(&self.sides)
            + nested_bytes::<(u32, Real)>(self.adj.len(), 2 * self.edges)
            + bytes_of(&self.cost)
            + bytes_of(&self.parent)
            + bytes_of(&self.closed)
            + bytes_of(&self.tree_id)
            + self.open.len() * std::mem::size_of::<Entry>()
            + self.tree.as_ref().map_or(0, Tree::bytes)
    }
    fn out_of_memory(&self) -> bool {
        self.out_of_memory
    }
    fn memory_advice(&self) -> &'static str {
        "lower sides, or simplify the obstacles (fewer vertices see fewer of each other)"
    }
    /// Its nodes are the graph's vertices, all made when set up (which refuses more than
    /// `max_nodes`); the search settles them, and adds none.
    fn out_of_nodes(&self, _max_nodes: usize) -> bool {
        false
    }
    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.tree.iter().cloned().collect())
    }
    fn gave_up(&self) -> Option<String> {
        self.reason.clone()
    }
}

//! Hierarchical hexagonal decomposition with artificial potential fields (report 002).
//!
//! The method of "Mobile Robot Path Planning Based on Hierarchical Hexagonal Decomposition and
//! Artificial Potential Fields" (J. Robotic Systems, 1994), as report 002 describes it
//! (`docs/sources.md`). No public implementation existed; where the paper's numbers are
//! unknown (cell sizes, level count), they are parameters with the defaults documented below.
//!
//! 1. **Decompose** ([`cells`]): tile the map with hexagons (half hexagons at the borders) and
//!    refine, level by level, only the cells an obstacle meets without covering; a hexagon splits
//!    exactly into a hexagon of half its size and six half hexagons. Refinement stops at `levels`
//!    levels or at a circumradius of `min_cell · t`, `t = √(l² + w²)` being the robot's diagonal.
//!    A cell is free, full, or mixed (still mixed at the finest level: impassable).
//! 2. **Search** in the region of influence ([`potential`](mod@potential)): from the robot's cell, test the step
//!    to each neighbouring free cell ([`step`]: the report's semicircle and swept rectangle), and
//!    move to the passable one of lowest potential; the cell left behind is marked visited
//!    (impassable), so the search never cycles. The goal is reached by a step test to the goal
//!    itself from its cell or a neighbour.
//! 3. **Grow** the region when the search is stuck: restart from the start with the doubled
//!    radius (or `d_maxOb + t`); when it can grow no further, report "no path".
//!
//! One iteration does one unit of work (one cell examined, one step of the search), and each is
//! evented: `Cell`/`CellShape` as cells are made and labelled, `CellState` for every verdict,
//! `Potential` for each candidate's terms, `NodeAdded` for each step (tree = attempt), `Region`
//! and `Field` (the heat map) whenever the region changes. Cell labels and step tests count as
//! state checks; the heat map's look-ahead, drawn only, does not.
//!
//! The robot: a point (`t = 0`) or a rigid body, whose `l × w` is the smallest rectangle about
//! its rotation point holding the footprint. A rigid robot's path turns on the spot at each centre
//! and drives straight along its heading to the next.

pub mod cells;
pub mod potential;
pub mod search;
mod spec;
pub mod step;

pub use cells::CellLabel;
pub use spec::{PARAMS, SPEC};

use self::cells::{Decomposition, Refine};
use self::potential::{obstacle_terms, potential, Region, Side, Terms, Weights};
use self::search::{Frontier, Search};
use self::step::{disc_blocked, step_test};
use crate::events::EventKind;
use crate::geometry::Workspace;
use crate::math::{wrap_angle, Real, Vec2};
use crate::planners::Checkpoint;
use crate::planners::{Context, Params, Planner, PlannerData, Task, Tree};
use crate::space_info::SpaceInfo;
use std::collections::VecDeque;

/// Where the planner is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Examining and refining cells.
    Decompose,
    /// Searching the region of influence.
    Search,
}

/// The planner.
#[derive(Clone)]
pub struct HexPotential {
    ws: Workspace,
    t: Real,
    dims: usize,
    start: Vec<Real>,
    goal: Vec<Real>,
    weights: Weights,
    refine: Refine,
    max_level: u32,
    min_radius: Real,
    dec: Decomposition,
    queue: VecDeque<usize>,
    phase: Phase,
    /// The search graph's nodes (free leaves, and the start's and goal's leaves), by cell index.
    nodes: Vec<usize>,
    /// `node_of[cell]`: its index in `nodes`.
    node_of: Vec<Option<usize>>,
    adj: Vec<Vec<usize>>,
    start_node: usize,
    goal_node: usize,
    region: Region,
    counted: Vec<bool>,
    attempt: usize,
    visited: Vec<bool>,
    /// The robot's current node and position.
    at: (usize, Vec2),
    /// The centres stepped through in this attempt, the start first.
    waypoints: Vec<Vec2>,
    trees: Vec<Tree>,
    steps: usize,
    failure: Option<String>,
    /// A split would have passed `max_nodes` (the run ends at its node limit).
    out_of_nodes: bool,
    /// The complete search chosen instead of the descent, if any…
    complete: Option<Search>,
    /// …and its open and closed sets, once the cells are made.
    frontier: Option<Frontier>,
}

impl HexPotential {
    /// The planner for `task`; an error names a robot it cannot plan for.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Result<HexPotential, String> {
        let body = si.body().ok_or("needs a point or a rigid robot (a body that drives along its heading)")?;
        let (l, w) = body.size();
        let ws = si.workspace().clone();
        let t = (l * l + w * w).sqrt();
        let b = ws.bounds;
        let short = (b.max.x - b.min.x).min(b.max.y - b.min.y);
        let s0 = match params.real("cell_size") {
            s if s > 0.0 => s,
            _ => short / 8.0,
        };
        let start = task.start.clone();
        let goal = task.goal().to_vec();
        let (p0, g) = (Vec2::new(start[0], start[1]), Vec2::new(goal[0], goal[1]));
        let r0 = match params.real("influence") {
            r if r > 0.0 => r,
            _ => (g - p0).norm() + t,
        };
        let trap = params.real("trap_obstacle");
        if trap >= 0.0 && trap as usize >= ws.obstacles.len() {
            return Err(format!(
                "trap_obstacle {} does not exist (the scenario has {} obstacles, numbered from 0)",
                trap,
                ws.obstacles.len()
            ));
        }
        let side = match params.choice("trap_side") {
            "above" => Side::Above,
            "left" => Side::Left,
            "right" => Side::Right,
            _ => Side::Below,
        };
        let weights = Weights {
            k1: params.real("k1"),
            k2: params.real("k2"),
            c: params.real("c"),
            k3: params.real("k3"),
            trap: (trap >= 0.0).then_some((trap as usize, side)),
        };
        // The coarse tiling's size, computed before it is built.
        let coarse = ((b.max.x - b.min.x) / (cells::SQRT3 * s0) + 3.0) * ((b.max.y - b.min.y) / (1.5 * s0) + 2.0);
        if coarse.is_nan() || coarse > crate::limits::MAX_COARSE_CELLS as Real {
            return Err(format!(
                "cell_size {s0:e} is too small for this map: its coarse tiling would have about {coarse:.3e} hexagons; the limit is {}",
                crate::limits::MAX_COARSE_CELLS
            ));
        }
        let dec = Decomposition::tiling(&b, s0);
        // Cells count as nodes: the coarse tiling alone must fit under the node limit.
        let max_nodes = params.real("max_nodes");
        if dec.cells.len() as Real > max_nodes {
            return Err(format!(
                "the coarse tiling has {} cells, more than max_nodes ({max_nodes}): raise max_nodes or cell_size",
                dec.cells.len()
            ));
        }
        let queue = (0..dec.cells.len()).collect();
        let region = Region::new(p0, r0, &ws.obstacles, t, b, g);
        let counted = ws.obstacles.iter().map(|s| region.counts(s)).collect();
        Ok(HexPotential {
            t,
            dims: si.dims(),
            start,
            goal,
            weights,
            refine: if params.choice("refine") == "clearance" { Refine::Clearance } else { Refine::Mixed },
            max_level: (params.real("levels") as u32).max(1) - 1,
            min_radius: params.real("min_cell") * t,
            dec,
            queue,
            phase: Phase::Decompose,
            nodes: Vec::new(),
            node_of: Vec::new(),
            adj: Vec::new(),
            start_node: 0,
            goal_node: 0,
            region,
            counted,
            attempt: 0,
            visited: Vec::new(),
            at: (0, p0),
            waypoints: vec![p0],
            trees: Vec::new(),
            steps: 0,
            failure: None,
            out_of_nodes: false,
            complete: match params.choice("search") {
                "astar" => Some(Search::AStar),
                "dijkstra" => Some(Search::Dijkstra),
                _ => None,
            },
            frontier: None,
            ws,
        })
    }

    fn start_point(&self) -> Vec2 {
        Vec2::new(self.start[0], self.start[1])
    }
    fn goal_point(&self) -> Vec2 {
        Vec2::new(self.goal[0], self.goal[1])
    }

    /// Examine the next cell: label it, event it, refine it if the rule says so.
    fn decompose_one(&mut self, cx: &mut Context) {
        let Some(i) = self.queue.pop_front() else {
            self.finish_decomposition(cx);
            return;
        };
        cx.si.count_checks(1);
        let cell = &self.dec.cells[i];
        let mut label = cells::label_of(&self.ws, &cell.outline, &cell.bbox);
        let split_free = self.refine == Refine::Clearance
            && label == CellLabel::Free
            && self.ws.polygon_clearance(&cell.outline, self.t / 2.0) < self.t / 2.0;
        let can_split = cell.level < self.max_level && cell.radius / 2.0 >= self.min_radius;
        if split_free && can_split {
            label = CellLabel::Mixed;
        }
        // A split adds up to 7 cells, which count as nodes: when they may not fit under
        // `max_nodes`, the cell goes back and the run ends at its node limit.
        if label == CellLabel::Mixed && can_split && cx.nodes_left < 7 {
            self.queue.push_front(i);
            self.out_of_nodes = true;
            return;
        }
        self.dec.cells[i].label = label;
        emit_cell(cx, &self.dec, i);
        if label == CellLabel::Mixed && can_split {
            let children = self.dec.refine(i);
            self.queue.extend(children);
        }
    }

    /// Build the search graph, place the robot, draw the region and the field.
    fn finish_decomposition(&mut self, cx: &mut Context) {
        let (p0, g) = (self.start_point(), self.goal_point());
        let start_leaf = self.dec.leaf_at(p0);
        let goal_leaf = self.dec.leaf_at(g);
        let (Some(sl), Some(gl)) = (start_leaf, goal_leaf) else {
            self.failure = Some("the start or the goal lies outside every cell".into());
            return;
        };
        let c = &self.dec.cells;
        self.nodes =
            (0..c.len()).filter(|&i| c[i].is_leaf() && (c[i].label == CellLabel::Free || i == sl || i == gl)).collect();
        self.node_of = vec![None; c.len()];
        for (k, &i) in self.nodes.iter().enumerate() {
            self.node_of[i] = Some(k);
        }
        self.adj = self.dec.adjacency(&self.nodes);
        self.start_node = self.node_of[sl].expect("the start's leaf is a node");
        self.goal_node = self.node_of[gl].expect("the goal's leaf is a node");
        self.phase = Phase::Search;
        match self.complete {
            Some(kind) => self.begin_complete(cx, kind),
            None => self.begin_attempt(cx),
        }
    }

    /// Start (or restart) the search from the start in the current region.
    fn begin_attempt(&mut self, cx: &mut Context) {
        let p0 = self.start_point();
        self.visited = vec![false; self.nodes.len()];
        self.visited[self.start_node] = true;
        self.at = (self.start_node, p0);
        self.waypoints = vec![p0];
        let q0 = self.start.clone();
        self.trees.push(Tree::new(cx, &q0, self.attempt));
        let r = self.region;
        let inside = self.counted.iter().filter(|&&b| b).count();
        cx.events.values(
            EventKind::Region,
            0,
            self.attempt as i64,
            -1,
            [r.centre.x, r.centre.y, r.radius, r.limit, inside as f64, self.t, 0.0, 0.0],
        );
        self.emit_field(cx);
        if self.t > 0.0 {
            if let Some(why) = disc_blocked(&self.ws, p0, self.t) {
                self.failure = Some(format!("the robot cannot turn at the start: {}", blocked_text(why as u8)));
            }
        }
    }

    /// The heat map: for every node in the region, its obstacle terms and the step the search
    /// would take from it (ignoring visited marks).
    fn emit_field(&self, cx: &mut Context) {
        if !cx.events.enabled {
            return;
        }
        let g = self.goal_point();
        for (k, &i) in self.nodes.iter().enumerate() {
            let c = self.dec.cells[i].centre;
            if !self.region.holds(c) || self.dec.cells[i].label != CellLabel::Free {
                continue;
            }
            let (rep, trap) = obstacle_terms(&self.weights, &self.ws.obstacles, &self.counted, c);
            let best = self.adj[k]
                .iter()
                .map(|&m| self.dec.cells[self.nodes[m]].centre)
                .filter(|&n| self.region.holds(n) && step_test(&self.ws, c, n, self.t).is_ok())
                .map(|n| (potential(&self.weights, &self.ws.obstacles, &self.counted, c, n, g).total, n))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let dir = best.map(|(_, n)| (n - c).scale(1.0 / (n - c).norm().max(1e-12))).unwrap_or(Vec2::new(0.0, 0.0));
            cx.events.values(
                EventKind::Field,
                0,
                i as i64,
                -1,
                [c.x, c.y, rep + trap, rep, trap, dir.x, dir.y, self.dec.cells[i].radius],
            );
        }
    }

    /// One step of the search.
    fn search_one(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let (k, p) = self.at;
        let g = self.goal_point();
        // The goal's cell in reach: try the step to the goal itself.
        if k == self.goal_node || self.adj[k].contains(&self.goal_node) {
            cx.si.count_checks(1);
            let gc = self.nodes[self.goal_node] as i64;
            match step_test(&self.ws, p, g, self.t) {
                Ok(()) => {
                    cx.events.values(
                        EventKind::CellState,
                        0,
                        gc,
                        self.nodes[k] as i64,
                        [g.x, g.y, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                    );
                    self.advance(cx, g);
                    let path = self.path();
                    cx.events.at(EventKind::Solved, self.attempt, g, &self.goal);
                    return Some(path);
                }
                Err(why) => cx.events.values(
                    EventKind::CellState,
                    0,
                    gc,
                    self.nodes[k] as i64,
                    [g.x, g.y, 1.0, why as u8 as f64, 0.0, 0.0, 0.0, 0.0],
                ),
            }
        }
        // Judge every neighbour: visited, outside the region, blocked, or a candidate.
        let from = self.nodes[k] as i64;
        let mut candidates: Vec<(usize, Terms)> = Vec::new();
        for &m in &self.adj[k] {
            let i = self.nodes[m];
            let c = self.dec.cells[i].centre;
            if self.visited[m] || self.dec.cells[i].label != CellLabel::Free {
                continue;
            }
            if !self.region.holds(c) {
                cx.events.values(EventKind::CellState, 0, i as i64, from, [c.x, c.y, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
                continue;
            }
            cx.si.count_checks(1);
            match step_test(&self.ws, p, c, self.t) {
                Err(why) => cx.events.values(
                    EventKind::CellState,
                    0,
                    i as i64,
                    from,
                    [c.x, c.y, 1.0, why as u8 as f64, 0.0, 0.0, 0.0, 0.0],
                ),
                Ok(()) => candidates.push((m, potential(&self.weights, &self.ws.obstacles, &self.counted, p, c, g))),
            }
        }
        let best = candidates.iter().min_by(|a, b| a.1.total.total_cmp(&b.1.total)).map(|c| c.0);
        for (m, t) in &candidates {
            let i = self.nodes[*m];
            let c = self.dec.cells[i].centre;
            let chosen = if Some(*m) == best { 1.0 } else { 0.0 };
            cx.events.values(
                EventKind::Potential,
                0,
                i as i64,
                from,
                [c.x, c.y, t.repulsion, t.trap, t.goal, t.total, t.alpha, chosen],
            );
        }
        match best {
            Some(m) => {
                let i = self.nodes[m];
                let c = self.dec.cells[i].centre;
                self.visited[m] = true;
                cx.events.values(EventKind::CellState, 0, i as i64, from, [c.x, c.y, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
                self.at = (m, c);
                self.advance(cx, c);
            }
            None => self.stuck(cx),
        }
        None
    }

    /// Step the robot to `to`: a waypoint and, in the tree, its states.
    fn advance(&mut self, cx: &mut Context, to: Vec2) {
        self.steps += 1;
        let q = self.states_between(*self.waypoints.last().expect("a start"), to);
        let tree = self.trees.last_mut().expect("an attempt has a tree");
        let parent = tree.len() as u32 - 1;
        let state = q.last().expect("a state").clone();
        let id = tree.add(cx, &state, parent);
        let (pp, p) = (cx.si.project(tree.state(parent)), cx.si.project(&state));
        cx.events.push(EventKind::NodeAdded, self.attempt, id as i64, parent as i64, p, pp, &state, tree.state(parent));
        self.waypoints.push(to);
    }

    /// The robot's states for the step `a → b`: for a point, `b`; for a rigid body, the turn on
    /// the spot at `a` and the drive to `b` along the heading.
    fn states_between(&self, a: Vec2, b: Vec2) -> Vec<Vec<Real>> {
        if self.dims < 3 {
            return vec![vec![b.x, b.y]];
        }
        let h = if (b - a).norm_squared() > 0.0 { libm::atan2(b.y - a.y, b.x - a.x) } else { self.goal[2] };
        vec![vec![a.x, a.y, wrap_angle(h)], vec![b.x, b.y, wrap_angle(h)]]
    }

    /// The path of the current attempt, as robot states.
    fn path(&self) -> Vec<Vec<Real>> {
        let mut path = vec![self.start.clone()];
        for w in self.waypoints.windows(2) {
            for q in self.states_between(w[0], w[1]) {
                if path.last() != Some(&q) {
                    path.push(q);
                }
            }
        }
        // End in the goal state (the turn on the spot to the goal's heading).
        if path.last() != Some(&self.goal) {
            path.push(self.goal.clone());
        }
        path
    }

    /// No passable neighbour: grow the region and start again, or give up.
    fn stuck(&mut self, cx: &mut Context) {
        let p = self.at.1;
        match self.region.grown() {
            Some(r) => {
                self.region = r;
                self.counted = self.ws.obstacles.iter().map(|s| r.counts(s)).collect();
                self.attempt += 1;
                self.begin_attempt(cx);
            }
            None => {
                let why = if self.region.covers_map() { "covers the whole map" } else { "has reached d_maxOb + t" };
                self.failure = Some(format!(
                    "no path: the search is stuck at ({:.3}, {:.3}) and the region of influence (radius {:.3}) {why}",
                    p.x, p.y, self.region.radius
                ));
            }
        }
    }
}

/// The words for a step-test verdict.
fn blocked_text(reason: u8) -> &'static str {
    match reason {
        1 => "an obstacle vertex within t/2",
        2 => "an obstacle vertex in the swept rectangle",
        3 => "an obstacle edge crosses the swept region",
        _ => "the map's edge is within t/2",
    }
}

/// The `Cell` record of cell `i` and the `CellShape` records of its outline.
fn emit_cell(cx: &mut Context, dec: &Decomposition, i: usize) {
    if !cx.events.enabled {
        return;
    }
    let c = &dec.cells[i];
    let parent = c.parent.map_or(-1, |p| p as i64);
    let n = c.outline.len();
    cx.events.values(
        EventKind::Cell,
        c.level as usize,
        i as i64,
        parent,
        [c.centre.x, c.centre.y, c.label as u8 as f64, c.radius, n as f64, 0.0, 0.0, 0.0],
    );
    for chunk in c.outline.chunks(4) {
        let mut v = [f64::NAN; 8];
        for (j, p) in chunk.iter().enumerate() {
            v[2 * j] = p.x;
            v[2 * j + 1] = p.y;
        }
        cx.events.values(EventKind::CellShape, 0, i as i64, -1, v);
    }
}

impl Planner for HexPotential {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.failure.is_some() {
            return None;
        }
        match self.phase {
            Phase::Decompose => {
                self.decompose_one(cx);
                None
            }
            Phase::Search if self.complete.is_some() => self.complete_one(cx),
            Phase::Search => self.search_one(cx),
        }
    }
    fn node_count(&self) -> usize {
        self.dec.cells.len() + self.steps
    }
    fn stored_bytes(&self) -> usize {
        use crate::planners::{bytes_of, nested_bytes};
        // A cell's outline has at most 7 vertices (a hexagon clipped to its parent), and a
        // node at most 6 neighbours.
        let cells = self.dec.cells.len() * (std::mem::size_of::<cells::Cell>() + 7 * std::mem::size_of::<Vec2>());
        cells
            + bytes_of(&self.nodes)
            + bytes_of(&self.node_of)
            + nested_bytes::<usize>(self.adj.len(), 6 * self.adj.len())
            + bytes_of(&self.counted)
            + bytes_of(&self.visited)
            + bytes_of(&self.waypoints)
            + self.trees.iter().map(Tree::bytes).sum::<usize>()
            + self.frontier.as_ref().map_or(0, Frontier::bytes)
    }
    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.trees.clone())
    }
    fn gave_up(&self) -> Option<String> {
        self.failure.clone()
    }
    fn out_of_nodes(&self, max_nodes: usize) -> bool {
        // A split that may not fit, or no room for the search's next step.
        self.out_of_nodes || self.node_count() >= max_nodes
    }
}

#[cfg(test)]
mod tests;

//! Grid search for a point robot: A*, Dijkstra, breadth-first search and the wavefront
//! planner on an occupancy grid made from the scenario, with PathFinding.js's choices.
//!
//! **The grid.** Square cells of side `cell` over the map (0: a fortieth of its shorter side); a
//! cell is blocked when an obstacle touches it (the hexagons' exact cell test,
//! [`label_of`](super::hex::cells::label_of)), so a move between the centres of free cells never
//! meets an obstacle. On an occupancy map (the scenario's `map` block, `io::occupancy`) the default
//! cell is one pixel and the grid starts on a pixel corner; a cell is then blocked when an
//! obstacle meets its interior ([`cell_blocked`]: a rectangle that only shares a side with it does
//! not), so the blocked cells are exactly the image's occupied pixels. A move between free cells'
//! centres still meets no obstacle: a rectangle of positive size that contains a point of a shared
//! side or corner enters one of the cells around it. The cells are labelled a row per iteration, each evented as a `Cell` with
//! its square outline (label 0 free, 2 blocked), so the page draws the grid as it is made.
//!
//! **The search.** Nodes are the cells (the start's cell stands at the start itself) and the goal
//! point, reached from its own cell or a neighbour by a checked motion. Moves go to the 4 side
//! neighbours, or to the 8 with `diagonal`: `yes` takes a diagonal only when both cells beside it
//! are free (PathFinding.js's "don't cross corners"), `cross-corners` takes it whenever the motion
//! itself is free. `astar` orders the open set by g + weight·h (h the straight distance to the
//! goal; weight 1 keeps it a shortest path), `dijkstra` by g, `bfs` counts moves (every move costs
//! 1), and `wavefront` numbers the cells by moves from the goal outward (a breadth-first wave) and
//! then walks from the start down the numbers. One iteration closes one cell; each verdict is a
//! `CellState` (0 opened, 1 the motion is blocked, 2 closed), as for the hexagonal search.

use super::hex::cells::label_of;
use super::hex::search::{Frontier, Search};
use super::hex::CellLabel;
use crate::events::EventKind;
use crate::geometry::{cell_blocked, Aabb, Workspace};
use crate::math::{Real, Vec2};
use crate::motion::MotionValidator;
use crate::planners::caps::{self, Capabilities, Draws, EventSet, Family, LegendItem};
use crate::planners::Checkpoint;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree};
use crate::space_info::SpaceInfo;

/// The cells' marks.
const MARKS: &[LegendItem] = &[
    LegendItem::boxed("closed cell", "cellVisited"),
    LegendItem::boxed("open cell", "cellOpen"),
    LegendItem::boxed("blocked cell", "cellFull"),
];

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "grid-search",
    label: "Grid search (A*, Dijkstra, BFS, wavefront)",
    summary: "A point robot on an occupancy grid made from the map: cells touching an obstacle blocked, searched cell by cell.",
    iteration: "One grid row labelled while the grid is made, then one cell closed by the search.",
    checks: "State validity checks: the cells' obstacle tests and the motions between cells and to the goal.",
    params: PARAMS,
    groups: &[],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Cells,
        draws: Draws::Grid,
        trees: 1,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: true,
        events: EventSet::of(&[EventKind::Cell, EventKind::CellShape, EventKind::CellState, EventKind::NodeAdded, EventKind::Solved]),
        pseudocode: "cells-grid-search",
        legend: caps::TWO_TREES,
        marks: MARKS,
        overlays: &["cells"],
    },
    make: |si, task, params| Ok(Box::new(GridSearch::new(si, task, params)?)),
};

/// The planner's parameters.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec::real("cell", "Cell size", 0.0, 1e6, 0.0, "Side of the grid's square cells (0: a fortieth of the map's shorter side; on an occupancy map, one pixel, the cells aligned with the image's). A cell an obstacle touches is blocked (on an occupancy map's pixels, one a rectangle overlaps)."),
    ParamSpec::choice(
        "search",
        "Search",
        &["astar", "dijkstra", "bfs", "wavefront"],
        0,
        "astar: by g + weight·h (h the distance to the goal); dijkstra: by g; bfs: by moves; wavefront: number the cells by moves from the goal, then walk down the numbers from the start.",
    ),
    ParamSpec::choice(
        "diagonal",
        "Diagonal moves",
        &["yes", "no", "cross-corners"],
        0,
        "yes: 8 neighbours, a diagonal only when both cells beside it are free (don't cross corners); no: 4 neighbours; cross-corners: a diagonal whenever the motion itself is free.",
    ),
    ParamSpec::real("weight", "Heuristic weight", 0.0, 100.0, 1.0, "A*: the weight of h (1: a shortest path; more: faster, possibly longer).")
        .only_when("search", &["astar"]),
];

/// The most cells a grid may have.
pub const MAX_GRID_CELLS: usize = 4_000_000;

/// The grid search.
#[derive(Clone)]
pub struct GridSearch {
    ws: Workspace,
    start: Vec<Real>,
    goal: Vec<Real>,
    origin: Vec2,
    side: Real,
    /// The cells are an occupancy map's pixels: a cell is blocked when an obstacle meets its
    /// interior ([`cell_blocked`]), so a pixel beside an occupied one stays free.
    aligned: bool,
    nx: usize,
    ny: usize,
    free: Vec<bool>,
    /// Rows labelled so far.
    rows: usize,
    search: Search,
    unit: bool,
    wave: bool,
    diagonal: u8,
    weight: Real,
    frontier: Option<Frontier>,
    tree: Option<Tree>,
    failure: Option<String>,
}

impl GridSearch {
    /// The planner for `task`; an error names a robot or a grid it cannot plan on.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Result<GridSearch, String> {
        match si.body() {
            Some(b) if b.size() == (0.0, 0.0) && si.dims() == 2 => {}
            _ => return Err("needs a point robot (x, y): the grid's cells are the robot's states".into()),
        }
        let ws = si.workspace().clone();
        let b = ws.bounds;
        let (w, h) = (b.max.x - b.min.x, b.max.y - b.min.y);
        // On an occupancy map (the scenario's `map` block) the default cell is one pixel, and the
        // grid starts on a pixel corner, so its cells are the image's pixels.
        let map = ws.map_grid.filter(|(o, r)| *r > 0.0 && o.x.is_finite() && o.y.is_finite());
        let side = match params.real("cell") {
            s if s > 0.0 => s,
            _ => map.map_or(w.min(h) / 40.0, |(_, r)| r),
        };
        let origin = match map {
            Some((o, r)) if side == r => {
                let snap = |lo: Real, o: Real| o + ((lo - o) / r).floor() * r;
                let s = Vec2::new(snap(b.min.x, o.x), snap(b.min.y, o.y));
                if s.x.is_finite() && s.y.is_finite() {
                    s
                } else {
                    b.min
                }
            }
            _ => b.min,
        };
        let aligned = map.is_some_and(|(_, r)| side == r);
        let (w, h) = (b.max.x - origin.x, b.max.y - origin.y);
        let (fx, fy) = ((w / side).ceil(), (h / side).ceil());
        let cells = fx * fy;
        if !cells.is_finite() || cells > MAX_GRID_CELLS as Real {
            return Err(format!(
                "cell {side:e} is too small for this map: the grid would have {cells:.3e} cells; the limit is {MAX_GRID_CELLS}"
            ));
        }
        let (nx, ny) = ((fx as usize).max(1), (fy as usize).max(1));
        let max_nodes = params.real("max_nodes");
        if (nx * ny) as Real > max_nodes {
            return Err(format!(
                "the grid has {} cells, more than max_nodes ({max_nodes}): raise max_nodes or cell",
                nx * ny
            ));
        }
        let choice = params.choice("search");
        Ok(GridSearch {
            start: task.start.clone(),
            goal: task.goal().to_vec(),
            origin,
            side,
            aligned,
            nx,
            ny,
            free: vec![false; nx * ny],
            rows: 0,
            search: if choice == "astar" { Search::AStar } else { Search::Dijkstra },
            unit: choice == "bfs" || choice == "wavefront",
            wave: choice == "wavefront",
            diagonal: match params.choice("diagonal") {
                "no" => 0,
                "cross-corners" => 2,
                _ => 1,
            },
            weight: params.real("weight"),
            frontier: None,
            tree: None,
            failure: None,
            ws,
        })
    }

    fn cell_of(&self, p: Vec2) -> usize {
        let c = |v: Real, n: usize| ((v / self.side).floor().max(0.0) as usize).min(n - 1);
        c(p.y - self.origin.y, self.ny) * self.nx + c(p.x - self.origin.x, self.nx)
    }

    fn centre(&self, k: usize) -> Vec2 {
        let (i, j) = (k % self.nx, k / self.nx);
        self.origin + Vec2::new((i as Real + 0.5) * self.side, (j as Real + 0.5) * self.side)
    }

    /// The search runs from `from` to `to`: start to goal, or goal to start for the wavefront.
    fn ends(&self) -> (Vec2, Vec2) {
        let (s, g) = (Vec2::new(self.start[0], self.start[1]), Vec2::new(self.goal[0], self.goal[1]));
        if self.wave {
            (g, s)
        } else {
            (s, g)
        }
    }

    /// Where node `k` stands: the search's first point for its own cell, else the cell's centre.
    fn point(&self, k: usize) -> Vec2 {
        let from = self.ends().0;
        if k == self.cell_of(from) {
            from
        } else {
            self.centre(k)
        }
    }

    /// Label row `self.rows` and event its cells.
    fn label_row(&mut self, cx: &mut Context) {
        let j = self.rows;
        for i in 0..self.nx {
            let k = j * self.nx + i;
            let c = self.centre(k);
            let h = 0.5 * self.side;
            let outline = [c + Vec2::new(-h, -h), c + Vec2::new(h, -h), c + Vec2::new(h, h), c + Vec2::new(-h, h)];
            let bbox = Aabb { min: outline[0], max: outline[2] };
            cx.si.count_checks(1);
            let clear = if self.aligned {
                // The pixel's sides as the importer computed them: origin + index · side.
                let at = |o: Real, n: usize| o + n as Real * self.side;
                let min = Vec2::new(at(self.origin.x, i), at(self.origin.y, j));
                let max = Vec2::new(at(self.origin.x, i + 1), at(self.origin.y, j + 1));
                !cell_blocked(&self.ws, min, max)
            } else {
                label_of(&self.ws, &outline, &bbox) == CellLabel::Free
            };
            self.free[k] = clear && self.ws.bounds.contains(c);
            if cx.events.enabled {
                let label = if self.free[k] { 0.0 } else { 2.0 };
                cx.events.values(
                    EventKind::Cell,
                    0,
                    k as i64,
                    -1,
                    [c.x, c.y, label, h * 2f64.sqrt(), 4.0, 0.0, 0.0, 0.0],
                );
                let mut v = [0.0; 8];
                for (n, p) in outline.iter().enumerate() {
                    v[2 * n] = p.x;
                    v[2 * n + 1] = p.y;
                }
                cx.events.values(EventKind::CellShape, 0, k as i64, -1, v);
            }
        }
        self.rows += 1;
    }

    /// The neighbours of cell `k` a move may go to: (cell, whether the move must be checked), the
    /// first `n` of the 8 (no allocation: this runs once per cell closed).
    fn neighbours(&self, k: usize) -> ([(usize, bool); 8], usize) {
        let (i, j) = ((k % self.nx) as i64, (k / self.nx) as i64);
        let at = |di: i64, dj: i64| {
            let (a, b) = (i + di, j + dj);
            (a >= 0 && b >= 0 && a < self.nx as i64 && b < self.ny as i64).then(|| b as usize * self.nx + a as usize)
        };
        let (mut out, mut n) = ([(0, false); 8], 0);
        let mut push = |m: usize, check: bool| {
            out[n] = (m, check);
            n += 1;
        };
        for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
            if let Some(m) = at(di, dj) {
                push(m, false);
            }
        }
        if self.diagonal > 0 {
            for (di, dj) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
                let Some(m) = at(di, dj) else { continue };
                let beside = [at(di, 0), at(0, dj)];
                let clear = beside.iter().all(|c| c.is_some_and(|c| self.free[c]));
                if clear {
                    push(m, false);
                } else if self.diagonal == 2 {
                    push(m, true);
                }
            }
        }
        (out, n)
    }

    /// Whether the straight motion between two points is valid (a check counted).
    fn motion(&self, cx: &mut Context, a: Vec2, b: Vec2) -> bool {
        let mut scratch = [0.0; 2];
        cx.si.check_motion(&[a.x, a.y], &[b.x, b.y], &mut scratch).is_ok()
    }

    fn state(&self, cx: &mut Context, k: usize, from: i64, verdict: Real, p: Vec2) {
        cx.events.values(EventKind::CellState, 0, k as i64, from, [p.x, p.y, verdict, 0.0, 0.0, 0.0, 0.0, 0.0]);
    }

    /// Close the best open node, judge its neighbours; the path once the far end is closed.
    fn step(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let (from_pt, to_pt) = self.ends();
        let mut f = match self.frontier.take() {
            Some(f) => f,
            None => {
                let s = self.cell_of(from_pt);
                let f = Frontier::new(self.search, self.nx * self.ny, s, from_pt, to_pt).weighted(self.weight);
                self.tree = Some(Tree::new(cx, &self.start, 0));
                f
            }
        };
        let end = f.goal_node();
        let Some(k) = f.pop() else {
            self.failure = Some(format!(
                "no path: the search closed all {} cells it could reach and none reaches the {} at this cell size",
                f.expanded,
                if self.wave { "start" } else { "goal" }
            ));
            return None;
        };
        if k == end {
            let mut chain: Vec<Vec2> =
                f.chain(end).iter().map(|&m| if m == end { to_pt } else { self.point(m) }).collect();
            if self.wave {
                chain.reverse();
            }
            return Some(self.walk(cx, &chain));
        }
        let p = self.point(k);
        let parent = f.parent(k).map_or(-1, |m| m as i64);
        self.state(cx, k, parent, 2.0, p);
        let len = |a: Vec2, b: Vec2, unit: bool| if unit { 1.0 } else { (b - a).norm() };
        let to_cell = self.cell_of(to_pt);
        let (nb, count) = self.neighbours(k);
        let nb = &nb[..count];
        if k == to_cell || nb.iter().any(|&(m, _)| m == to_cell) {
            cx.si.count_checks(1);
            if self.motion(cx, p, to_pt) {
                if f.relax(k, end, to_pt, len(p, to_pt, self.unit)) {
                    self.state(cx, to_cell, k as i64, 0.0, to_pt);
                }
            } else {
                self.state(cx, to_cell, k as i64, 1.0, to_pt);
            }
        }
        let own = k == self.cell_of(from_pt);
        for &(m, check) in nb {
            if f.is_closed(m) || !self.free[m] {
                continue;
            }
            let c = self.centre(m);
            // A move between free cells' centres is free by construction; the start's own point
            // and a corner-crossing diagonal are checked.
            if check || own {
                cx.si.count_checks(1);
                if !self.motion(cx, p, c) {
                    self.state(cx, m, k as i64, 1.0, c);
                    continue;
                }
            }
            if f.relax(k, m, c, len(p, c, self.unit)) {
                self.state(cx, m, k as i64, 0.0, c);
            }
        }
        self.frontier = Some(f);
        None
    }

    /// The robot's path through `points` (start first), evented as steps of the tree.
    fn walk(&mut self, cx: &mut Context, points: &[Vec2]) -> Vec<Vec<Real>> {
        let tree = self.tree.as_mut().expect("the search has begun");
        let mut path = vec![self.start.clone()];
        for p in &points[1..] {
            let q = vec![p.x, p.y];
            if path.last() == Some(&q) {
                continue;
            }
            let parent = tree.len() as u32 - 1;
            let id = tree.add(cx, &q, parent);
            let pp = cx.si.project(tree.state(parent));
            cx.events.push(EventKind::NodeAdded, 0, id as i64, parent as i64, *p, pp, &q, tree.state(parent));
            path.push(q);
        }
        let g = &self.goal;
        cx.events.at(EventKind::Solved, 0, Vec2::new(g[0], g[1]), g);
        path
    }
}

impl Planner for GridSearch {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.failure.is_some() {
            return None;
        }
        if self.rows < self.ny {
            self.label_row(cx);
            return None;
        }
        self.step(cx)
    }
    fn node_count(&self) -> usize {
        self.nx * self.ny
    }
    fn stored_bytes(&self) -> usize {
        crate::planners::bytes_of(&self.free)
            + self.frontier.as_ref().map_or(0, Frontier::bytes)
            + self.tree.as_ref().map_or(0, Tree::bytes)
    }
    /// Its nodes are the grid's cells, all made when set up (which refuses more than `max_nodes`).
    fn out_of_nodes(&self, _max_nodes: usize) -> bool {
        false
    }
    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.tree.iter().cloned().collect())
    }
    fn gave_up(&self) -> Option<String> {
        self.failure.clone()
    }
}

//! EST and bidirectional EST: trees grown from the nodes where they are thinnest.
//!
//! D. Hsu, J.-C. Latombe and R. Motwani, "Path planning in expansive configuration spaces",
//! ICRA 1997; the grid form of OMPL's `EST`. Each node is filed in a cell of a grid laid over the
//! workspace (the node's projection, the point the page draws), `grid` cells a side. An iteration
//!
//! 1. picks a cell with probability proportional to 1 / (the nodes in it), then a node of that
//!    cell at random: sparse regions grow first (a `Select` event: the node, its cell's count and
//!    the cell's probability);
//! 2. draws a state uniformly in the box of half-width `range` about the node (each coordinate,
//!    clamped to its bounds, angles wrapped), or, with probability `goal_bias` (EST only), the goal;
//! 3. adds it if the straight motion to it is valid (`NodeAdded`, else `Collision`).
//!
//! EST then tries the motion from the new node to the goal when the goal is within `range`. The
//! bidirectional form (`bi-est`, after OMPL's `BiEST`) grows a tree from the start and one from the
//! goal in turn, and joins them when the new node is within `range` of the other tree's nearest
//! node and the motion between them is valid. Seeded by the run's generator only.

use super::rrt::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::Real;
use crate::motion::MotionValidator;
use crate::planners::caps::{self, Capabilities, Draws, EventSet, Family};
use crate::planners::Checkpoint;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree};
use crate::space_info::SpaceInfo;
use std::collections::HashMap;

/// The registry entry of EST.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "est",
    label: "EST",
    summary: "One tree, grown from where it is sparsest: a node of a thin grid cell, a random state near it.",
    iteration: "Pick a node where the tree is sparsest, draw a state near it, add it if the motion to it is free.",
    checks: "State validity checks: the drawn state and the states along the motion to it (each motion is checked state by state at the scenario's resolution).",
    params: PARAMS,
    groups: &[],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Tree,
        draws: Draws::Tree,
        trees: 1,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: false,
        events: EventSet::of(&[
            EventKind::Sample,
            EventKind::NodeAdded,
            EventKind::Collision,
            EventKind::Select,
            EventKind::Solved,
        ]),
        pseudocode: "tree-est",
        legend: caps::ONE_TREE,
        marks: &[],
        overlays: &["density"],
    },
    make: |si, task, params| Ok(Box::new(Est::new(si, task, params, false))),
};

/// The registry entry of bidirectional EST.
pub const BI_SPEC: PlannerSpec = PlannerSpec {
    name: "bi-est",
    label: "Bidirectional EST",
    summary: "Two ESTs, from start and goal, taking turns, joined when a new node sees the other tree.",
    iteration: "One tree (they take turns) picks a node where it is sparsest, draws a state near it and adds it if the motion is free; a new node then tries to join the other tree.",
    checks: "State validity checks: the drawn states and the states along every motion tried, joins included (each motion is checked state by state at the scenario's resolution).",
    params: BI_PARAMS,
    groups: &[],
    task: TaskKind::Goal,
    caps: Capabilities {
        trees: 2,
        events: SPEC.caps.events.with(&[EventKind::TreesConnected]),
        pseudocode: "tree-bi-est",
        legend: caps::TWO_TREES,
        ..SPEC.caps
    },

    make: |si, task, params| Ok(Box::new(Est::new(si, task, params, true))),
};

const GRID: ParamSpec = ParamSpec::int(
    "grid",
    "Density grid",
    1.0,
    1000.0,
    20.0,
    "Cells a side of the grid over the workspace that counts nodes: a node is picked from a cell with probability 1 / its count.",
);

/// EST's parameters.
pub const PARAMS: &[ParamSpec] = &[
    RANGE,
    ParamSpec::real(
        "goal_bias",
        "Goal bias",
        0.0,
        1.0,
        0.05,
        "Probability of trying the goal itself instead of a state near the picked node.",
    ),
    GRID,
];

/// Bidirectional EST's parameters.
pub const BI_PARAMS: &[ParamSpec] = &[RANGE, GRID];

/// A tree and its density grid: node ids by cell.
#[derive(Clone, Debug)]
struct Grown {
    tree: Tree,
    cells: Vec<Vec<u32>>,
    /// Cell key → index in `cells`, in order of first use (so picks are deterministic).
    index: HashMap<(i64, i64), usize>,
    keys: Vec<(i64, i64)>,
}

impl Grown {
    /// File node `id` in its cell of a `grid`-a-side grid over the workspace.
    fn file(&mut self, si: &SpaceInfo, grid: Real, id: u32) {
        let b = si.workspace().bounds;
        let p = si.project(self.tree.state(id));
        let (w, h) = ((b.max.x - b.min.x).max(1e-12), (b.max.y - b.min.y).max(1e-12));
        let cell = |v: Real| (v.clamp(0.0, 1.0) * grid).floor().min(grid - 1.0) as i64;
        let key = (cell((p.x - b.min.x) / w), cell((p.y - b.min.y) / h));
        let k = *self.index.entry(key).or_insert_with(|| {
            self.cells.push(Vec::new());
            self.keys.push(key);
            self.cells.len() - 1
        });
        self.cells[k].push(id);
    }
}

/// EST or bidirectional EST.
#[derive(Clone)]
pub struct Est {
    task: Task,
    range: Real,
    goal_bias: Real,
    grid: Real,
    bi: bool,
    trees: Vec<Grown>,
    turn: usize,
    new: Vec<Real>,
    scratch: Vec<Real>,
    /// The picked node's state (a buffer: an iteration allocates nothing until it adds a node).
    from: Vec<Real>,
    goal: Vec<Real>,
}

impl Est {
    /// An EST (`bi`: bidirectional) for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params, bi: bool) -> Est {
        let n = si.dims();
        Est {
            task: task.clone(),
            range: resolve_range(si, params.real("range")),
            goal_bias: if bi { 0.0 } else { params.real("goal_bias") },
            grid: params.real("grid").max(1.0),
            bi,
            trees: Vec::new(),
            turn: 0,
            new: vec![0.0; n],
            scratch: vec![0.0; n],
            from: vec![0.0; n],
            goal: task.goal().to_vec(),
        }
    }

    fn root(&self, cx: &mut Context, q: &[Real], index: usize) -> Grown {
        let mut g = Grown { tree: Tree::new(cx, q, index), cells: Vec::new(), index: HashMap::new(), keys: Vec::new() };
        g.file(cx.si, self.grid, 0);
        g
    }

    /// Pick a node of tree `t`: a cell with probability ∝ 1/count, then one of its nodes.
    fn select(&self, cx: &mut Context, t: usize) -> u32 {
        let g = &self.trees[t];
        let total: Real = g.cells.iter().map(|c| 1.0 / c.len() as Real).sum();
        let mut r = cx.rng.uniform01() * total;
        let mut k = g.cells.len() - 1;
        for (i, c) in g.cells.iter().enumerate() {
            r -= 1.0 / c.len() as Real;
            if r < 0.0 {
                k = i;
                break;
            }
        }
        let cell = &g.cells[k];
        let id = cell[cx.rng.below(cell.len())];
        if cx.events.enabled {
            let q = g.tree.state(id);
            let p = cx.si.project(q);
            let share = (1.0 / cell.len() as Real) / total;
            let (gx, gy) = g.keys[k];
            cx.events.values(
                EventKind::Select,
                t,
                id as i64,
                -1,
                [p.x, p.y, cell.len() as Real, share, g.cells.len() as Real, gx as Real, gy as Real, self.grid],
            );
        }
        id
    }

    /// A state in the box of half-width `range` about `q`, into `out`.
    fn near(&self, cx: &mut Context, q: &[Real], out: &mut [Real]) {
        for (k, d) in cx.si.space.dims.iter().enumerate() {
            let v = q[k] + cx.rng.uniform(-self.range, self.range);
            out[k] = if d.wraps { crate::math::wrap_angle(v) } else { v.clamp(d.lo, d.hi) };
        }
    }

    /// Add the motion `from → q` to tree `t` if it is valid; the new node's id.
    fn try_add(&mut self, cx: &mut Context, t: usize, from: u32, q: &[Real]) -> Option<u32> {
        if cx.nodes_left == 0 {
            return None;
        }
        self.from.copy_from_slice(self.trees[t].tree.state(from));
        let a = &self.from;
        if cx.si.check_motion(a, q, &mut self.scratch).is_err() {
            cx.note_collision(t, from, a, q, &self.scratch);
            return None;
        }
        let g = &mut self.trees[t];
        let id = g.tree.add(cx, q, from);
        cx.nodes_left -= 1;
        let (p, pp) = (cx.si.project(q), cx.si.project(a));
        cx.events.push(EventKind::NodeAdded, t, id as i64, from as i64, p, pp, q, a);
        g.file(cx.si, self.grid, id);
        Some(id)
    }

    fn path(&self, t: usize, id: u32, other: Option<u32>) -> Vec<Vec<Real>> {
        let mut path = self.trees[t].tree.path_to(id);
        if let Some(o) = other {
            let mut tail = self.trees[1 - t].tree.path_to(o);
            tail.reverse();
            path.extend(tail);
            if t == 1 {
                path.reverse();
            }
        }
        path
    }
}

impl Planner for Est {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }

    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        if self.trees.is_empty() {
            let start = self.task.start.clone();
            self.trees.push(self.root(cx, &start, 0));
            if self.bi {
                let goal = self.task.goal().to_vec();
                self.trees.push(self.root(cx, &goal, 1));
            }
        }
        let t = self.turn;
        if self.bi {
            self.turn = 1 - t;
        }
        let from = self.select(cx, t);
        let mut q = std::mem::take(&mut self.new);
        if !self.bi && cx.rng.uniform01() < self.goal_bias {
            q.copy_from_slice(&self.goal);
            let p = cx.si.project(&q);
            cx.events.push(EventKind::Sample, t, 1, -1, p, p, &q, &q);
        } else {
            self.near(cx, self.trees[t].tree.state(from), &mut q);
            let p = cx.si.project(&q);
            cx.events.push(EventKind::Sample, t, 0, -1, p, p, &q, &q);
        }
        let added = self.try_add(cx, t, from, &q);
        self.new = q;
        let id = added?;
        let state = self.trees[t].tree.state(id).to_vec();
        let goal = self.goal.clone();
        if !self.bi {
            let d = cx.si.distance(&state, &goal);
            if d <= self.task.goal_tolerance {
                cx.events.at(EventKind::Solved, 0, cx.si.project(&goal), &goal);
                return Some(self.path(0, id, None));
            }
            if d <= self.range && d > 0.0 {
                if let Some(g) = self.try_add(cx, 0, id, &goal) {
                    cx.events.at(EventKind::Solved, 0, cx.si.project(&goal), &goal);
                    return Some(self.path(0, g, None));
                }
            }
            return None;
        }
        // Bidirectional: join the other tree's nearest node if it is within range and seen.
        let o = 1 - t;
        let (near, d) = self.trees[o].tree.nearest(cx, &state);
        if d > self.range {
            return None;
        }
        let other = self.trees[o].tree.state(near).to_vec();
        if cx.si.check_motion(&state, &other, &mut self.scratch).is_err() {
            cx.note_collision(t, id, &state, &other, &self.scratch);
            return None;
        }
        let p = cx.si.project(&other);
        cx.events.push(EventKind::TreesConnected, t, id as i64, near as i64, p, p, &other, &other);
        cx.events.at(EventKind::Solved, t, cx.si.project(&goal), &goal);
        Some(self.path(t, id, Some(near)))
    }

    fn node_count(&self) -> usize {
        self.trees.iter().map(|g| g.tree.len()).sum()
    }
    fn stored_bytes(&self) -> usize {
        use crate::planners::{bytes_of, nested_bytes};
        self.trees
            .iter()
            .map(|g| {
                // The grid's cells hold each node once; the index a key, a cell and a hash.
                g.tree.bytes()
                    + nested_bytes::<u32>(g.cells.len(), g.tree.len())
                    + bytes_of(&g.keys) * 2
                    + g.index.len() * (std::mem::size_of::<((i64, i64), usize)>() + 8)
            })
            .sum()
    }

    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.trees.iter().map(|g| g.tree.clone()).collect())
    }
}

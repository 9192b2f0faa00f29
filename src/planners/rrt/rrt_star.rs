//! RRT*: asymptotically optimal RRT.
//!
//! S. Karaman, E. Frazzoli, "Sampling-based algorithms for optimal motion planning", IJRR 30(7),
//! 2011; structured as OMPL's `RRTstar`. One tree from the start. Each iteration draws a sample
//! (the goal itself with probability `goal_bias`), steps at most `range` from its nearest node
//! toward it and, if that motion is valid:
//!
//! 1. finds the near set of the new state: its `k` nearest nodes, `k = ⌈f·e·(1 + 1/d)·ln n⌉`, or
//!    the nodes within `r = min(range, f·γ·(ln n / n)^(1/d))`, `γ = 2·(1 + 1/d)^(1/d)·(μ/ζ_d)^(1/d)`
//!    (`f`: `rewire_factor`, `n`: nodes after insertion, `d`: dimensions, `μ`: the space's measure,
//!    the product of its coordinate ranges, `ζ_d`: the volume of the unit `d`-ball);
//! 2. chooses as parent the node of the near set (or the nearest) that reaches the new state with
//!    the least cost-to-come through a valid motion (candidates in order of cost, so only the
//!    motions that could win are checked, OMPL's delayed collision checking);
//! 3. rewires: every near node that the new node reaches more cheaply, through a valid motion,
//!    gets the new node as parent, and the cost change propagates to its descendants.
//!
//! Cost is path length in the robot's metric (as `planners::smoothing::path_cost`). A node within
//! `goal_tolerance` of the goal is a goal node; the best solution is the goal node of least cost
//! (plus the last step to the goal itself when it is not exactly there). After the first solution
//! the planner keeps improving for `improve_for` iterations and then returns the best path; when a
//! run limit stops it first, [`Planner::best_so_far`] hands the session the best path so far.
//! Every improvement is logged as a `Cost` event, every re-parenting as a `Rewire` event.
//! Seeded by the run's [`Rng`] only; ties are broken by node id.
//!
//! [`Rng`]: crate::rng::Rng

use super::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::Real;
use crate::motion::MotionValidator;
use crate::planners::caps::{self, Capabilities, Draws, Family};
use crate::planners::Checkpoint;
use crate::planners::{Context, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "rrt-star",
    label: "RRT*",
    summary: "One tree that rewires its neighbourhood so paths keep getting shorter.",
    iteration: "Draw a sample, extend the tree toward it through the cheapest neighbour, rewire the neighbourhood.",
    checks: "State validity checks: the states along each extension and rewiring motion (each motion is checked state by state at the scenario's resolution), plus a sampler's own checks.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Tree,
        draws: Draws::Tree,
        trees: 1,
        improves: true,
        chart: Some("cost"),
        queries: false,
        proves_no_path: false,
        events: caps::SAMPLING_TREE.with(&[EventKind::Rewire, EventKind::Cost]),
        pseudocode: "tree-rrt-star",
        legend: caps::ONE_TREE,
        marks: &[],
        overlays: &["rewires", "best"],
    },
    make: |si, task, params| Ok(Box::new(RrtStar::new(si, task, params))),
};

/// RRT*'s parameters.
pub const PARAMS: &[ParamSpec] = &[
    RANGE,
    ParamSpec::real("goal_bias", "Goal bias", 0.0, 1.0, 0.05, "Probability of sampling the goal itself (any sampler)."),
    ParamSpec::choice(
        "rewire",
        "Near set",
        &["k-nearest", "radius"],
        0,
        "k-nearest: the ⌈f·e·(1 + 1/d)·ln n⌉ nearest nodes; radius: the nodes within min(range, f·γ·(ln n / n)^(1/d)).",
    ),
    ParamSpec::real("rewire_factor", "Rewire factor", 0.0, 100.0, 1.1, "f: scales the near set's k or radius above the bound that makes RRT* asymptotically optimal (0: no near set, plain RRT)."),
    ParamSpec::int("improve_for", "Improve for", 0.0, 1e9, 2000.0, "Iterations spent improving the path after the first solution (0: return the first solution)."),
];

/// Parent of the root.
const NO_PARENT: u32 = u32::MAX;

/// The RRT* planner.
#[derive(Clone)]
pub struct RrtStar {
    task: Task,
    range: Real,
    /// k-nearest near sets (else radius).
    k_nearest: bool,
    /// `f·e·(1 + 1/d)`: k = ⌈k_rrg · ln n⌉.
    k_rrg: Real,
    /// `f·γ`: r = min(range, r_rrg · (ln n / n)^(1/d)).
    r_rrg: Real,
    dims: usize,
    improve_for: u64,
    tree: Option<Tree>,
    /// Cost-to-come of each node (by id).
    cost: Vec<Real>,
    /// Length of the edge from each node's parent (0 for the root).
    edge: Vec<Real>,
    /// Children of each node, for propagating cost changes.
    children: Vec<Vec<u32>>,
    /// Goal nodes with their distance to the goal.
    goals: Vec<(u32, Real)>,
    /// The best goal node, its solution cost and its distance to the goal.
    best: Option<(u32, Real, Real)>,
    /// The iteration (own count) of the first solution.
    solved_at: Option<u64>,
    /// Iterations run so far.
    iterations: u64,
    /// Rewirings so far.
    rewires: u64,
    sample: Vec<Real>,
    new: Vec<Real>,
    scratch: Vec<Real>,
    /// Scratch for the descendants of a rewired node.
    stack: Vec<u32>,
}

/// Volume of the unit ball in `d` dimensions (ζ_0 = 1, ζ_1 = 2, ζ_d = ζ_{d−2} · 2π/d).
fn unit_ball_volume(d: usize) -> Real {
    match d {
        0 => 1.0,
        1 => 2.0,
        _ => unit_ball_volume(d - 2) * 2.0 * std::f64::consts::PI / d as Real,
    }
}

impl RrtStar {
    /// An RRT* for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Self {
        let n = si.dims();
        let d = n as Real;
        let factor = params.real("rewire_factor");
        let measure: Real = si.space.dims.iter().map(|dim| dim.hi - dim.lo).product();
        let gamma = 2.0 * libm::pow(1.0 + 1.0 / d, 1.0 / d) * libm::pow(measure / unit_ball_volume(n), 1.0 / d);
        RrtStar {
            task: task.clone(),
            range: resolve_range(si, params.real("range")),
            k_nearest: params.choice("rewire") != "radius",
            k_rrg: factor * std::f64::consts::E * (1.0 + 1.0 / d),
            r_rrg: factor * gamma,
            dims: n,
            improve_for: params.real("improve_for") as u64,
            tree: None,
            cost: Vec::new(),
            edge: Vec::new(),
            children: Vec::new(),
            goals: Vec::new(),
            best: None,
            solved_at: None,
            iterations: 0,
            rewires: 0,
            sample: vec![0.0; n],
            new: vec![0.0; n],
            scratch: vec![0.0; n],
            stack: Vec::new(),
        }
    }

    /// Cost-to-come of every node, by node id (the tree's invariant: a node's cost is its parent's
    /// plus the length of the edge between them).
    pub fn costs(&self) -> &[Real] {
        &self.cost
    }

    /// The cost of the best solution so far.
    pub fn best_cost(&self) -> Option<Real> {
        self.best.map(|(_, c, _)| c)
    }

    /// Rewirings so far.
    pub fn rewire_count(&self) -> u64 {
        self.rewires
    }

    /// The near set's size `k` (k-nearest) for a tree that will hold `n` nodes.
    pub fn near_k(&self, n: usize) -> usize {
        libm::ceil(self.k_rrg * libm::log(n as Real)).max(0.0) as usize
    }

    /// The near set's radius (radius rule) for a tree that will hold `n` nodes.
    pub fn near_radius(&self, n: usize) -> Real {
        let n = n as Real;
        self.range.min(self.r_rrg * libm::pow(libm::log(n) / n, 1.0 / self.dims as Real))
    }

    /// Book a node the tree just added (`id` under `parent`, edge length `len`).
    fn book(&mut self, cx: &Context, id: u32, parent: u32, len: Real) {
        let c = if parent == NO_PARENT { 0.0 } else { self.cost[parent as usize] + len };
        self.cost.push(c);
        self.edge.push(len);
        self.children.push(Vec::new());
        if parent != NO_PARENT {
            self.children[parent as usize].push(id);
        }
        let tree = self.tree.as_ref().expect("a tree");
        let to_goal = cx.si.distance(tree.state(id), self.task.goal());
        if to_goal <= self.task.goal_tolerance {
            self.goals.push((id, to_goal));
        }
    }

    /// One RRT* step: sample (by `draw`), steer, choose a parent, insert, rewire.
    fn grow(&mut self, cx: &mut Context, draw: &mut dyn FnMut(&mut Context, &mut [Real]) -> bool) {
        if !draw(cx, &mut self.sample) {
            return;
        }
        // The near set's size, for a tree of n nodes once the new one is in.
        let n = self.node_count() + 1;
        let (k, r) = (self.near_k(n), self.near_radius(n));
        let tree = self.tree.as_mut().expect("a tree");
        let (near, d) = tree.nearest(cx, &self.sample);
        cx.note_nearest(0, near, tree.state(near), &self.sample, d, Real::INFINITY, true);
        if d == 0.0 {
            return; // already in the tree
        }
        if cx.nodes_left == 0 {
            cx.events.at(EventKind::SampleRejected, 0, cx.si.project(&self.sample), &self.sample);
            return;
        }
        if d <= self.range {
            self.new.copy_from_slice(&self.sample);
        } else {
            cx.si.interpolate(tree.state(near), &self.sample, self.range / d, &mut self.new);
            // Under the chain metrics a straight step can end no closer to the sample (see
            // Tree::grow): refuse it.
            if cx.si.distance(&self.new, &self.sample) >= d {
                cx.events.at(EventKind::SampleRejected, 0, cx.si.project(&self.sample), &self.sample);
                return;
            }
        }
        cx.note_steer(0, near, tree.state(near), &self.new, d.min(self.range), self.range, d <= self.range);
        if cx.si.check_motion(tree.state(near), &self.new, &mut self.scratch).is_err() {
            cx.note_collision(0, near, tree.state(near), &self.new, &self.scratch);
            cx.sampler.note_collision(tree.state(near));
            cx.events.at(EventKind::SampleRejected, 0, cx.si.project(&self.sample), &self.sample);
            return;
        }

        let neighbours = if self.k_nearest { tree.k_nearest(cx, &self.new, k) } else { tree.within(cx, &self.new, r) };

        // Choose the parent: the nearest (its motion is valid) unless a neighbour reaches the new
        // state more cheaply through a valid motion. Candidates by cost (ties by id), checked in
        // that order: the first valid one wins.
        let near_len = cx.si.distance(tree.state(near), &self.new);
        let mut parent = (near, self.cost[near as usize] + near_len);
        let mut candidates: Vec<(Real, u32)> = neighbours
            .iter()
            .filter(|&&(i, _)| i != near)
            .map(|&(i, di)| (self.cost[i as usize] + di, i))
            .filter(|&(c, _)| c < parent.1)
            .collect();
        candidates.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for &(c, i) in &candidates {
            if cx.si.check_motion(tree.state(i), &self.new, &mut self.scratch).is_ok() {
                parent = (i, c);
                break;
            }
        }
        let (p, _) = parent;
        let len = if p == near { near_len } else { cx.si.distance(tree.state(p), &self.new) };
        let id = tree.add(cx, &self.new, p);
        cx.nodes_left -= 1;
        let (pq, pp) = (cx.si.project(&self.new), cx.si.project(tree.state(p)));
        cx.events.push(EventKind::NodeAdded, 0, id as i64, p as i64, pq, pp, &self.new, tree.state(p));
        self.book(cx, id, p, len);

        // Rewire: near nodes the new node reaches more cheaply, through a valid motion.
        let tree = self.tree.as_mut().expect("a tree");
        let base = self.cost[id as usize];
        for &(j, dj) in &neighbours {
            if j == p || base + dj >= self.cost[j as usize] {
                continue;
            }
            if cx.si.check_motion(&self.new, tree.state(j), &mut self.scratch).is_err() {
                continue;
            }
            let old = tree.parent(j);
            let len = dj; // the near-set query measured distance(new, j), the edge's own order
                          // Acyclic: j cannot be an ancestor of the new node, whose cost is at least j's then.
            tree.set_parent(j, id);
            let (pj, pn) = (cx.si.project(tree.state(j)), cx.si.project(&self.new));
            cx.events.push(EventKind::Rewire, 0, j as i64, id as i64, pj, pn, tree.state(j), &self.new);
            self.rewires += 1;
            if old != NO_PARENT {
                let siblings = &mut self.children[old as usize];
                if let Some(at) = siblings.iter().position(|&c| c == j) {
                    siblings.remove(at);
                }
            }
            self.children[id as usize].push(j);
            self.edge[j as usize] = len;
            self.cost[j as usize] = base + len;
            // Propagate to the descendants.
            self.stack.clear();
            self.stack.extend_from_slice(&self.children[j as usize]);
            while let Some(c) = self.stack.pop() {
                let ci = c as usize;
                self.cost[ci] = self.cost[tree.parent(c) as usize] + self.edge[ci];
                self.stack.extend_from_slice(&self.children[ci]);
            }
        }
    }

    /// Re-evaluate the best goal node; log a `Cost` event when the solution improved.
    fn update_best(&mut self, cx: &mut Context, iteration: u64) {
        let mut best: Option<(u32, Real, Real)> = None;
        for &(g, to_goal) in &self.goals {
            let c = self.cost[g as usize] + to_goal;
            if best.is_none_or(|(_, b, _)| c < b) {
                best = Some((g, c, to_goal));
            }
        }
        let Some((g, c, to_goal)) = best else { return };
        let improved = self.best.is_none_or(|(_, b, _)| c < b);
        self.best = Some((g, c, to_goal));
        if improved {
            self.solved_at.get_or_insert(iteration);
            let goal = self.task.goal();
            cx.events.mark(EventKind::Cost, 0, g as i64, cx.iteration as f64, cx.si.project(goal), c, 0.0);
        }
    }

    /// The path to the best goal node (within the goal tolerance; never a jump to the goal itself,
    /// which would be a motion nobody checked).
    fn best_path(&self) -> Option<Vec<Vec<Real>>> {
        let (g, _, _) = self.best?;
        Some(self.tree.as_ref()?.path_to(g))
    }
}

impl RrtStar {
    /// One iteration whose sample is drawn by `draw` (which writes a state and returns `false`
    /// when it gave up): the run's sampler for RRT*, another rule for its variants (Informed
    /// RRT*). A `dyn` rule, so that the iteration's code is built once, not once a rule.
    pub fn iterate_with(
        &mut self,
        cx: &mut Context,
        draw: &mut dyn FnMut(&mut Context, &mut [Real]) -> bool,
    ) -> Option<Vec<Vec<Real>>> {
        if self.tree.is_none() {
            let tree = Tree::new(cx, &self.task.start, 0);
            self.tree = Some(tree);
            self.book(cx, 0, NO_PARENT, 0.0);
        }
        let iteration = self.iterations;
        self.iterations += 1;
        self.grow(cx, draw);
        self.update_best(cx, iteration);
        let first = self.solved_at?;
        if iteration - first < self.improve_for {
            return None;
        }
        let goal = self.task.goal();
        cx.events.at(EventKind::Solved, 0, cx.si.project(goal), goal);
        self.best_path()
    }
}

impl Planner for RrtStar {
    fn checkpoint(&mut self) -> Checkpoint {
        Checkpoint::copy_of(self)
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        self.iterate_with(cx, &mut |cx, out| cx.sample(0, out))
    }

    fn node_count(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::len)
    }
    fn stored_bytes(&self) -> usize {
        use crate::planners::{bytes_of, nested_bytes};
        let n = self.node_count();
        self.tree.as_ref().map_or(0, Tree::bytes)
            + bytes_of(&self.cost)
            + bytes_of(&self.edge)
            + nested_bytes::<u32>(self.children.len(), n.saturating_sub(1))
            + bytes_of(&self.goals)
    }

    fn data(&self) -> PlannerData {
        PlannerData::of_trees(self.tree.iter().cloned().collect())
    }

    fn best_so_far(&self) -> Option<Vec<Vec<Real>>> {
        self.best_path()
    }
}

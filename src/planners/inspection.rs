//! Inspection planning: a tree that grows until one branch has seen enough points of interest.
//!
//! The Technion course's inspection RRT (courses.md §5, report 004; cf. G. Papadopoulos,
//! H. Kurniawati, N. M. Patrikalakis, "Asymptotically optimal inspection planning using systems with
//! differential constraints", ICRA 2013, whose tree nodes also carry what their branch has seen). One
//! tree from the start. Every node carries the set of points seen **along its branch**: its parent's
//! set and what the sensor sees at every state of the edge into it, checked at the motion
//! resolution (the course checks edges every 0.05 rad). The coverage of a node is the fraction of
//! the points in its set; the run ends when a node's coverage reaches the target (the `coverage`
//! parameter, by default the scenario's), and the path is its branch.
//!
//! Each iteration:
//! 1. chooses where to grow: with probability `focus`, from a node of the branch that sees most (a
//!    random one among those that see as many points as the best, so the walk spreads along the tip
//!    of the best branch), toward a sample; otherwise from the node nearest a sample (plain RRT). The
//!    sample comes from the run's sampler.
//! 2. steps at most `range` toward the sample (refused when it makes no progress, as `Tree::grow`)
//!    and checks the motion; a collision ends the iteration.
//! 3. chooses the new node's parent among its `k` nearest nodes and the node it grew from: the one
//!    through which it sees most, ties broken by the lesser cost (the sum of C-space distances).
//! 4. rewires each of the `k` nearest through the new node when that makes its branch see a superset
//!    of what it saw and either more points or the same at less cost; the change is propagated to its
//!    descendants. Requiring a superset keeps every node's set growing, so no branch (and never the
//!    best one) loses a point it saw, and an edge's stored set may omit what its parent's branch had
//!    already seen.
//!
//! What the sensor sees is the robot's business (its [`Sensor`](crate::robot::Sensor) capability,
//! through [`SpaceInfo::sensor`], and [`SpaceInfo::sees`]): an arm's end effector looking along its
//! last link, a rigid body's origin looking along its x axis, a point seeing all around; sight
//! lines are blocked by obstacle interiors only. Robots without a sensor are refused.
//!
//! Events: `NodeAdded`, `Collision`, `Rewire`, `Coverage` (whenever the best branch sees more),
//! `PointSeen` (the first time any node sees a point) and `Solved`.

use super::rrt::{resolve_range, RANGE};
use crate::events::EventKind;
use crate::math::{Real, Vec2};
use crate::motion::MotionValidator;
use crate::planners::tree::ROOT;
use crate::planners::{
    Context, InspectionTask, ParamSpec, Params, Planner, PlannerData, PlannerSpec, Task, TaskKind, Tree,
};
use crate::sampler::SAMPLER_GROUP;
use crate::space_info::SpaceInfo;

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "inspection",
    label: "Inspection RRT",
    summary: "A tree that grows to see the points of interest, until one branch sees enough of them.",
    params: PARAMS,
    groups: &[SAMPLER_GROUP],
    task: TaskKind::Inspection,
    make: |si, task, params| {
        si.sensor().ok_or_else(|| format!("needs a robot with a sensor (a {} robot has none)", si.robot_kind()))?;
        Ok(Box::new(Inspection::new(si, task, params)))
    },
};

/// The inspection planner's parameters.
pub const PARAMS: &[ParamSpec] = &[
    RANGE,
    ParamSpec::real("coverage", "Coverage", 0.0, 1.0, 0.0, "Fraction of the inspection points one branch must see (0: the scenario's target)."),
    ParamSpec::int("k", "Neighbours", 0.0, 1000.0, 5.0, "Nearest nodes considered as a new node's parent and rewired through it (0: no rewiring)."),
    ParamSpec::real(
        "focus",
        "Focus",
        0.0,
        1.0,
        0.75,
        "Probability of growing from the tip of the branch that sees most, rather than from the node nearest the sample.",
    ),
];

/// Points seen, one bit per inspection point.
type Bits = [u64];

fn count(b: &Bits) -> u32 {
    b.iter().map(|w| w.count_ones()).sum()
}

fn has(b: &Bits, i: usize) -> bool {
    b[i / 64] >> (i % 64) & 1 == 1
}

fn set(b: &mut Bits, i: usize) {
    b[i / 64] |= 1 << (i % 64);
}

/// Whether `a` ⊇ `b`.
fn covers(a: &Bits, b: &Bits) -> bool {
    a.iter().zip(b).all(|(x, y)| y & !x == 0)
}

/// The sensor's model for one task: the points, the field of view and the range.
#[derive(Clone, Debug)]
struct Sensor {
    points: Vec<Vec2>,
    fov: Real,
    range: Real,
}

impl Sensor {
    /// Set in `out` every point not in `skip` or `out` that the sensor sees at `q`.
    /// (One unit of the batch journal: a bounded batch replays it without looking again.)
    fn look(&self, si: &SpaceInfo, q: &[Real], skip: &Bits, out: &mut Bits) {
        si.journalled_bits(0, out, |out| {
            // A robot without a sensor sees nothing (the planner refuses it).
            let Some(sensor) = si.sensor() else { return };
            let pose = sensor.pose(q);
            for (j, p) in self.points.iter().enumerate() {
                if !has(skip, j) && !has(out, j) && si.sees(&pose, *p, self.fov, self.range) {
                    set(out, j);
                }
            }
        })
    }

    /// Set in `out` (cleared first) every point not in `skip` that the sensor sees along the motion
    /// `a → b`, at every state at most the motion resolution apart, `b` included and `a` excluded
    /// (its own are its branch's).
    /// (One unit of the batch journal, like [`Sensor::look`].)
    fn sweep(&self, si: &SpaceInfo, a: &[Real], b: &[Real], skip: &Bits, out: &mut Bits, buf: &mut [Real]) {
        si.journalled_bits(1, out, |out| self.sweep_now(si, a, b, skip, out, buf))
    }

    fn sweep_now(&self, si: &SpaceInfo, a: &[Real], b: &[Real], skip: &Bits, out: &mut Bits, buf: &mut [Real]) {
        out.fill(0);
        let n = self.points.len();
        if count(skip) as usize == n {
            return;
        }
        // At most `MAX_MOTION_STEPS` (the problem's resolution check), each looking at every
        // point: the run's deadline is looked at as it goes.
        let Some(steps) = crate::limits::steps(si.distance(a, b), si.resolution, crate::limits::MAX_MOTION_STEPS)
        else {
            return;
        };
        for i in 1..=steps {
            if si.tick(n as u64 + 1) {
                return;
            }
            if i == steps {
                buf.copy_from_slice(b);
            } else {
                si.interpolate(a, b, i as Real / steps as Real, buf);
            }
            self.look(si, buf, skip, out);
        }
    }
}

/// The points `task`'s sensor sees along `path` (one bit per point), at every state of each motion
/// at most the motion resolution apart, as the planner checks its edges.
pub fn seen_along(si: &SpaceInfo, task: &InspectionTask, path: &[Vec<Real>]) -> Vec<u64> {
    let sensor = Sensor { points: task.points.clone(), fov: task.fov, range: task.range };
    let words = task.points.len().div_ceil(64).max(1);
    let (mut seen, mut edge) = (vec![0u64; words], vec![0u64; words]);
    let mut buf = vec![0.0; si.dims()];
    if let Some(first) = path.first() {
        sensor.look(si, first, &vec![0u64; words], &mut seen);
    }
    for w in path.windows(2) {
        sensor.sweep(si, &w[0], &w[1], &seen, &mut edge, &mut buf);
        seen.iter_mut().zip(&edge).for_each(|(s, e)| *s |= e);
    }
    seen
}

/// The coverage `path` reaches: the fraction of `task`'s points it sees ([`seen_along`]); 1 when
/// the task has no points.
pub fn path_coverage(si: &SpaceInfo, task: &InspectionTask, path: &[Vec<Real>]) -> Real {
    match task.points.len() {
        0 => 1.0,
        n => count(&seen_along(si, task, path)) as Real / n as Real,
    }
}

/// Random shortcut smoothing that keeps what the path sees: each attempt of
/// [`smoothing::shortcut`](super::smoothing::shortcut) is kept only if the shortened path still
/// sees every point the original saw (plain shortcutting cuts the detours an inspection path takes
/// to look at things).
pub fn shortcut(
    si: &SpaceInfo,
    task: &InspectionTask,
    path: &[Vec<Real>],
    attempts: usize,
    rng: &mut crate::rng::Rng,
) -> Vec<Vec<Real>> {
    let must = seen_along(si, task, path);
    let mut path = path.to_vec();
    for _ in 0..attempts {
        if path.len() < 3 || si.out_of_time() {
            break;
        }
        let next = super::smoothing::shortcut(si, &path, 1, rng);
        if next != path && covers(&seen_along(si, task, &next), &must) {
            path = next;
        }
    }
    path
}

/// The inspection planner.
#[derive(Clone)]
pub struct Inspection {
    start: Vec<Real>,
    sensor: Sensor,
    /// Target coverage (fraction of the points).
    target: Real,
    range: Real,
    k: usize,
    focus: Real,
    /// Words per bit set.
    words: usize,
    tree: Option<Tree>,
    /// Per node (`words` each): the points seen along its branch.
    seen: Vec<u64>,
    /// Per node: the points seen along the edge into it (its own state included) that its parent's
    /// branch had not seen when the edge was made.
    edge: Vec<u64>,
    /// Per node: points in `seen`.
    counts: Vec<u32>,
    /// Per node: the branch's cost (sum of C-space distances).
    cost: Vec<Real>,
    /// Per node: the length of the edge into it.
    len: Vec<Real>,
    children: Vec<Vec<u32>>,
    /// Points seen by any node.
    ever: Vec<u64>,
    /// The node whose branch sees most (ties: the least cost).
    best: u32,
    /// Nodes that see as many points as the best, and whether each node is among them.
    top: Vec<u32>,
    in_top: Vec<bool>,
    sample: Vec<Real>,
    new: Vec<Real>,
    scratch: Vec<Real>,
}

impl Inspection {
    /// An inspection planner for `task` with `params`.
    pub fn new(si: &SpaceInfo, task: &Task, params: &Params) -> Self {
        let insp = task.inspection.clone().unwrap_or(InspectionTask {
            points: Vec::new(),
            fov: 0.0,
            range: 0.0,
            coverage: 0.0,
        });
        let own = params.real("coverage");
        let n = si.dims();
        Inspection {
            start: task.start.clone(),
            words: insp.points.len().div_ceil(64).max(1),
            target: if own > 0.0 { own } else { insp.coverage },
            sensor: Sensor { points: insp.points, fov: insp.fov, range: insp.range },
            range: resolve_range(si, params.real("range")),
            k: params.real("k") as usize,
            focus: params.real("focus"),
            tree: None,
            seen: Vec::new(),
            edge: Vec::new(),
            counts: Vec::new(),
            cost: Vec::new(),
            len: Vec::new(),
            children: Vec::new(),
            ever: Vec::new(),
            best: 0,
            top: Vec::new(),
            in_top: Vec::new(),
            sample: vec![0.0; n],
            new: vec![0.0; n],
            scratch: vec![0.0; n],
        }
    }

    /// The coverage of the branch that sees most (0 before the first iteration).
    pub fn best_coverage(&self) -> Real {
        match self.counts.get(self.best as usize) {
            Some(&c) => self.fraction(c),
            None => 0.0,
        }
    }

    fn fraction(&self, c: u32) -> Real {
        let n = self.sensor.points.len();
        if n == 0 {
            1.0
        } else {
            c as Real / n as Real
        }
    }

    fn reached(&self, c: u32) -> bool {
        self.fraction(c) >= self.target
    }

    fn seen_of(&self, i: u32) -> &Bits {
        let i = i as usize;
        &self.seen[i * self.words..(i + 1) * self.words]
    }

    /// Append a node's records (the tree node itself is added by the caller).
    fn push_node(&mut self, seen: &Bits, edge: &Bits, cost: Real, len: Real) {
        self.seen.extend_from_slice(seen);
        self.edge.extend_from_slice(edge);
        self.counts.push(count(seen));
        self.cost.push(cost);
        self.len.push(len);
        self.children.push(Vec::new());
        self.in_top.push(false);
    }

    /// Log the points node `i` sees that no node saw before.
    fn note_points(&mut self, cx: &mut Context, i: u32) {
        let w = self.words;
        for j in 0..self.sensor.points.len() {
            if has(&self.seen[i as usize * w..(i as usize + 1) * w], j) && !has(&self.ever, j) {
                set(&mut self.ever, j);
                cx.events.mark(EventKind::PointSeen, 0, j as i64, -1.0, self.sensor.points[j], 0.0, 0.0);
            }
        }
    }

    /// Consider node `i` for the best branch (after its set or cost changed).
    fn offer(&mut self, cx: &mut Context, tree: &Tree, i: u32) {
        let (c, b) = (self.counts[i as usize], self.counts[self.best as usize]);
        if c > b {
            self.best = i;
            for t in self.top.drain(..) {
                self.in_top[t as usize] = false;
            }
            self.top.push(i);
            self.in_top[i as usize] = true;
            cx.events.mark(
                EventKind::Coverage,
                0,
                i as i64,
                cx.iteration as f64,
                cx.si.project(tree.state(i)),
                self.fraction(c),
                c as f64,
            );
        } else if c == b {
            if !self.in_top[i as usize] {
                self.in_top[i as usize] = true;
                self.top.push(i);
            }
            if self.cost[i as usize] < self.cost[self.best as usize] {
                self.best = i;
            }
        }
    }

    /// Whether `a` is an ancestor of `i` (or `i` itself).
    fn is_ancestor(tree: &Tree, a: u32, mut i: u32) -> bool {
        while i != ROOT {
            if i == a {
                return true;
            }
            i = tree.parent(i);
        }
        false
    }

    fn init(&mut self, cx: &mut Context) -> Tree {
        let tree = Tree::new(cx, &self.start, 0);
        self.ever = vec![0; self.words];
        let mut seen = vec![0; self.words];
        self.sensor.look(cx.si, &self.start, &vec![0; self.words], &mut seen);
        self.push_node(&seen, &seen, 0.0, 0.0);
        self.note_points(cx, 0);
        self.best = 0;
        self.top = vec![0];
        self.in_top[0] = true;
        let c = self.counts[0];
        cx.events.mark(
            EventKind::Coverage,
            0,
            0,
            cx.iteration as f64,
            cx.si.project(&self.start),
            self.fraction(c),
            c as f64,
        );
        tree
    }

    fn solved(&self, cx: &mut Context, tree: &Tree) -> Vec<Vec<Real>> {
        let q = tree.state(self.best);
        cx.events.at(EventKind::Solved, 0, cx.si.project(q), q);
        tree.path_to(self.best)
    }

    /// Re-attach `i` under `parent` with the edge set `edge` and length `d`, and bring its
    /// descendants' sets and costs up to date.
    fn rewire(&mut self, cx: &mut Context, tree: &mut Tree, i: u32, parent: u32, edge: &Bits, d: Real) {
        let old = tree.parent(i);
        self.children[old as usize].retain(|&c| c != i);
        self.children[parent as usize].push(i);
        tree.set_parent(i, parent);
        let w = self.words;
        self.edge[i as usize * w..(i as usize + 1) * w].copy_from_slice(edge);
        self.len[i as usize] = d;
        let (p, q) = (cx.si.project(tree.state(i)), cx.si.project(tree.state(parent)));
        cx.events.push(EventKind::Rewire, 0, i as i64, parent as i64, p, q, tree.state(i), tree.state(parent));
        let mut stack = vec![i];
        while let Some(c) = stack.pop() {
            let (c, p) = (c as usize, tree.parent(c) as usize);
            for k in 0..w {
                self.seen[c * w + k] = self.seen[p * w + k] | self.edge[c * w + k];
            }
            self.counts[c] = count(&self.seen[c * w..(c + 1) * w]);
            self.cost[c] = self.cost[p] + self.len[c];
            if c == i as usize {
                // Its new edge may see what no node saw; below it, sets only gain those.
                self.note_points(cx, i);
            }
            self.offer(cx, tree, c as u32);
            stack.extend_from_slice(&self.children[c]);
        }
    }

    /// Pick the node to grow from and the sample to grow toward (in `self.sample`); `None` when the
    /// sampler gave up.
    fn choose(&mut self, cx: &mut Context, tree: &mut Tree) -> Option<u32> {
        let focused = self.focus > 0.0 && cx.rng.uniform01() < self.focus;
        if !cx.sample(0, &mut self.sample) {
            return None;
        }
        if focused {
            Some(self.top[cx.rng.below(self.top.len())])
        } else {
            Some(tree.nearest(cx, &self.sample).0)
        }
    }
}

impl Planner for Inspection {
    fn snapshot(&self) -> Box<dyn Planner> {
        Box::new(self.clone())
    }
    fn iterate(&mut self, cx: &mut Context) -> Option<Vec<Vec<Real>>> {
        let mut tree = match self.tree.take() {
            Some(t) => t,
            None => {
                let t = self.init(cx);
                if self.reached(self.counts[0]) {
                    let path = self.solved(cx, &t);
                    self.tree = Some(t);
                    return Some(path);
                }
                t
            }
        };
        let out = self.grow(cx, &mut tree);
        self.tree = Some(tree);
        out
    }

    fn node_count(&self) -> usize {
        self.tree.as_ref().map_or(0, Tree::len)
    }

    fn data(&self) -> PlannerData {
        PlannerData { trees: self.tree.iter().cloned().collect() }
    }

    fn best_so_far(&self) -> Option<Vec<Vec<Real>>> {
        let tree = self.tree.as_ref()?;
        self.reached(self.counts[self.best as usize]).then(|| tree.path_to(self.best))
    }

    fn coverage(&self) -> Option<Real> {
        Some(self.best_coverage())
    }
}

impl Inspection {
    fn grow(&mut self, cx: &mut Context, tree: &mut Tree) -> Option<Vec<Vec<Real>>> {
        let source = self.choose(cx, tree)?;
        if cx.nodes_left == 0 {
            return None;
        }
        let d = cx.si.distance(tree.state(source), &self.sample);
        cx.note_nearest(0, source, tree.state(source), &self.sample, d, Real::INFINITY, true);
        if d == 0.0 {
            return None;
        }
        let reached = d <= self.range;
        if reached {
            self.new.copy_from_slice(&self.sample);
        } else {
            cx.si.interpolate(tree.state(source), &self.sample, self.range / d, &mut self.new);
            // Progress, as in `Tree::grow`: under the chain metrics a step can end farther away.
            if cx.si.distance(&self.new, &self.sample) >= d {
                return None;
            }
        }
        cx.note_steer(0, source, tree.state(source), &self.new, d.min(self.range), self.range, reached);
        if cx.si.check_motion(tree.state(source), &self.new, &mut self.scratch).is_err() {
            cx.note_collision(0, source, tree.state(source), &self.new, &self.scratch);
            cx.sampler.note_collision(tree.state(source));
            return None;
        }
        let new = self.new.clone();
        let w = self.words;
        let mut buf = vec![0.0; new.len()];

        // The parent: the candidate through which the new node sees most, then the cheapest.
        let mut near = if self.k > 0 { tree.k_nearest(cx, &new, self.k) } else { Vec::new() };
        if !near.iter().any(|&(i, _)| i == source) {
            near.push((source, cx.si.distance(tree.state(source), &new)));
        }
        // (node, points seen, cost, edge set, motion known valid)
        let mut cands: Vec<(u32, u32, Real, Vec<u64>, bool)> = Vec::with_capacity(near.len());
        for &(i, di) in &near {
            let mut e = vec![0u64; w];
            self.sensor.sweep(cx.si, tree.state(i), &new, self.seen_of(i), &mut e, &mut buf);
            let c = self.counts[i as usize] + count(&e);
            cands.push((i, c, self.cost[i as usize] + di, e, i == source));
        }
        cands.sort_by(|a, b| b.1.cmp(&a.1).then(a.2.total_cmp(&b.2)).then(a.0.cmp(&b.0)));
        let mut valid: Vec<(u32, bool)> = Vec::new();
        let mut chosen = None;
        for (ci, c) in cands.iter().enumerate() {
            let ok = c.4 || cx.si.check_motion(tree.state(c.0), &new, &mut self.scratch).is_ok();
            valid.push((c.0, ok));
            if ok {
                chosen = Some(ci);
                break;
            }
        }
        let ci = chosen?;
        let (parent, _, cost, edge, _) = cands.swap_remove(ci);
        let mut seen = self.seen_of(parent).to_vec();
        seen.iter_mut().zip(&edge).for_each(|(s, e)| *s |= e);
        let id = tree.add(cx, &new, parent);
        cx.nodes_left -= 1;
        let dp = cx.si.distance(tree.state(parent), &new);
        self.push_node(&seen, &edge, cost, dp);
        self.children[parent as usize].push(id);
        let (p, q) = (cx.si.project(&new), cx.si.project(tree.state(parent)));
        cx.events.push(EventKind::NodeAdded, 0, id as i64, parent as i64, p, q, &new, tree.state(parent));
        self.note_points(cx, id);
        self.offer(cx, tree, id);

        // Rewire the neighbours through the new node.
        let mut e = vec![0u64; w];
        let mut through = vec![0u64; w];
        for &(i, di) in &near {
            if i == parent || Self::is_ancestor(tree, i, id) {
                continue;
            }
            let new_seen = self.seen_of(id).to_vec();
            self.sensor.sweep(cx.si, &new, tree.state(i), &new_seen, &mut e, &mut buf);
            through.iter_mut().zip(new_seen.iter().zip(&e)).for_each(|(t, (s, x))| *t = s | x);
            let (c_old, c_new) = (self.counts[i as usize], count(&through));
            let cost_new = self.cost[id as usize] + di;
            let better = c_new > c_old || (c_new == c_old && cost_new < self.cost[i as usize]);
            if !better || !covers(&through, self.seen_of(i)) {
                continue;
            }
            let ok = match valid.iter().find(|v| v.0 == i) {
                // Motions are certified in either direction: checked one way is checked.
                Some(v) => v.1,
                None => cx.si.check_motion(&new, tree.state(i), &mut self.scratch).is_ok(),
            };
            if ok {
                self.rewire(cx, tree, i, id, &e, di);
            }
        }
        if self.reached(self.counts[self.best as usize]) {
            return Some(self.solved(cx, tree));
        }
        None
    }
}

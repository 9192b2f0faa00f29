//! The tree's growth: choosing where to grow, the new node's parent, rewiring, and the best branch
//! (steps 1–4 of the module documentation).

use super::bits::{count, covers, has, set, Bits};
use super::Inspection;
use crate::events::EventKind;
use crate::math::Real;
use crate::motion::MotionValidator;
use crate::planners::tree::ROOT;
use crate::planners::{Context, Tree};

impl Inspection {
    /// Log the points node `i` sees that no node saw before.
    fn note_points(&mut self, cx: &mut Context, i: u32) {
        let w = self.words;
        for j in 0..self.view.points.len() {
            if has(&self.seen[i as usize * w..(i as usize + 1) * w], j) && !has(&self.ever, j) {
                set(&mut self.ever, j);
                cx.events.mark(EventKind::PointSeen, 0, j as i64, -1.0, self.view.points[j], 0.0, 0.0);
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

    pub(super) fn init(&mut self, cx: &mut Context) -> Tree {
        let tree = Tree::new(cx, &self.start, 0);
        self.ever = vec![0; self.words];
        let mut seen = vec![0; self.words];
        self.view.look(cx.si, &self.start, &vec![0; self.words], &mut seen);
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

    pub(super) fn solved(&self, cx: &mut Context, tree: &Tree) -> Vec<Vec<Real>> {
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

impl Inspection {
    pub(super) fn grow(&mut self, cx: &mut Context, tree: &mut Tree) -> Option<Vec<Vec<Real>>> {
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
            self.view.sweep(cx.si, tree.state(i), &new, self.seen_of(i), &mut e, &mut buf);
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
            self.view.sweep(cx.si, &new, tree.state(i), &new_seen, &mut e, &mut buf);
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

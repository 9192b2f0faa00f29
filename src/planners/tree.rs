//! The search tree shared by the RRT family, and its one growth step.

use super::Context;
use crate::events::EventKind;
use crate::math::Real;
use crate::motion::MotionValidator;
use crate::nn::KdTree;
use crate::status::Grow;

/// A tree of states: flat coordinates, parent links, and a nearest-neighbour index.
#[derive(Clone, Debug)]
pub struct Tree {
    dims: usize,
    states: Vec<Real>,
    parents: Vec<u32>,
    nn: KdTree,
    /// Which tree this is (0: rooted at the start, 1: at the goal), for events.
    pub index: usize,
}

/// The most steps one CONNECT takes (every step makes progress; this bounds an iteration's time).
pub const MAX_CONNECT_STEPS: usize = 10_000;

/// Parent of a root.
pub(crate) const ROOT: u32 = u32::MAX;

impl Tree {
    /// A tree rooted at `root`.
    pub fn new(cx: &mut Context, root: &[Real], index: usize) -> Tree {
        let dims = root.len();
        let mut t = Tree { dims, states: Vec::new(), parents: Vec::new(), nn: KdTree::new(dims), index };
        t.add(cx, root, ROOT);
        cx.nodes_left = cx.nodes_left.saturating_sub(1);
        t
    }
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.parents.len()
    }
    /// Whether the tree is empty (never, once built).
    pub fn is_empty(&self) -> bool {
        self.parents.is_empty()
    }
    /// A node's state.
    #[inline]
    pub fn state(&self, i: u32) -> &[Real] {
        let i = i as usize;
        &self.states[i * self.dims..(i + 1) * self.dims]
    }
    /// A node's parent (`u32::MAX` for the root).
    pub fn parent(&self, i: u32) -> u32 {
        self.parents[i as usize]
    }
    /// Add a node; emits `NodeAdded`.
    pub fn add(&mut self, cx: &Context, q: &[Real], parent: u32) -> u32 {
        let id = self.parents.len() as u32;
        self.states.extend_from_slice(q);
        self.parents.push(parent);
        self.nn.add(&cx.si.space, q, id);
        id
    }
    /// The node nearest to `q`.
    pub fn nearest(&mut self, cx: &Context, q: &[Real]) -> (u32, Real) {
        self.nn.nearest(&cx.si.space, q).expect("a tree always has its root")
    }
    /// States from the root to node `i`.
    pub fn path_to(&self, mut i: u32) -> Vec<Vec<Real>> {
        let mut out = Vec::new();
        while i != ROOT {
            out.push(self.state(i).to_vec());
            i = self.parent(i);
        }
        out.reverse();
        out
    }

    /// Grow one step of at most `range` from the node nearest `target` toward it (RRT's EXTEND).
    /// Returns the outcome and the node reached or added (the nearest node when trapped).
    pub fn extend(&mut self, cx: &mut Context, target: &[Real], range: Real, scratch: &mut [Real], new: &mut [Real]) -> (Grow, u32) {
        let (near, d) = self.nearest(cx, target);
        if d == 0.0 {
            return (Grow::Reached, near);
        }
        if cx.nodes_left == 0 {
            return (Grow::Trapped, near);
        }
        let reached = d <= range;
        if reached {
            new.copy_from_slice(target);
        } else {
            cx.si.interpolate(self.state(near), target, range / d, new);
        }
        // Growth must make progress: under a metric that is not convex along straight lines in
        // state space (the chain metrics), a step toward the target can end farther from it.
        if !reached && cx.si.distance(new, target) >= d {
            return (Grow::Trapped, near);
        }
        let near_state = &self.states[near as usize * self.dims..(near as usize + 1) * self.dims];
        if cx.si.check_motion(near_state, new, scratch).is_err() {
            cx.events.at(EventKind::Collision, self.index, cx.si.project(scratch), scratch);
            return (Grow::Trapped, near);
        }
        let id = self.add(cx, new, near);
        cx.nodes_left -= 1;
        let (p, q) = (cx.si.project(new), cx.si.project(self.state(near)));
        cx.events.push(EventKind::NodeAdded, self.index, id as i64, near as i64, p, q, new, self.state(near));
        (if reached { Grow::Reached } else { Grow::Advanced }, id)
    }

    /// Grow step after step toward `target` (RRT-Connect's CONNECT) until it is reached, a step is
    /// trapped, or [`MAX_CONNECT_STEPS`] steps were taken. Returns the last outcome and the last
    /// node reached or added.
    pub fn connect(&mut self, cx: &mut Context, target: &[Real], range: Real, scratch: &mut [Real], new: &mut [Real]) -> (Grow, u32) {
        let mut last = (Grow::Trapped, 0);
        for _ in 0..MAX_CONNECT_STEPS {
            last = self.extend(cx, target, range, scratch, new);
            if last.0 != Grow::Advanced {
                break;
            }
        }
        last
    }

    /// Every edge as `(parent state, child state)`.
    pub fn edges(&self) -> impl Iterator<Item = (&[Real], &[Real])> {
        (0..self.len() as u32).filter(|&i| self.parent(i) != ROOT).map(|i| (self.state(self.parent(i)), self.state(i)))
    }
}

/// A planner's trees, for drawing and for re-checking in tests.
#[derive(Clone, Debug, Default)]
pub struct PlannerData {
    /// The trees.
    pub trees: Vec<Tree>,
}

//! Going back to an earlier state of a [`Tree`] without copying its nodes (a bounded batch's
//! mark, see [`crate::journal`] and [`crate::nn::KdMark`]): since a mark a tree appends nodes and
//! may re-attach older ones (noted); its per-node domains and failure counts, when the variants
//! that keep them are on, are copied at the mark (a number a node).

use super::Tree;
use crate::math::Real;
use crate::nn::KdMark;

/// Where a [`Tree`] stood when marked ([`Tree::mark`]).
#[derive(Clone, Debug)]
pub struct TreeMark {
    len: usize,
    nn: KdMark,
    radius: Vec<Real>,
    fails: Vec<u32>,
    rejected: u64,
    slid: bool,
}

impl Tree {
    /// Mark the tree as it stands, to [`rewind`](Self::rewind) to it later.
    pub fn mark(&mut self) -> TreeMark {
        self.reattached = Some(Vec::new());
        TreeMark {
            len: self.len(),
            nn: self.nn.mark(),
            radius: self.radius.clone(),
            fails: self.fails.clone(),
            rejected: self.rejected,
            slid: self.slid,
        }
    }

    /// Forget the mark.
    pub fn release(&mut self) {
        self.reattached = None;
        self.nn.release();
    }

    /// Back to the tree as it stood at `mark` (its last mark), node for node.
    pub fn rewind(&mut self, mark: TreeMark) {
        for (i, parent) in self.reattached.take().unwrap_or_default().into_iter().rev() {
            self.parents[i as usize] = parent;
        }
        self.states.truncate(mark.len * self.dims);
        self.parents.truncate(mark.len);
        self.nn.rewind(mark.nn);
        (self.radius, self.fails, self.rejected, self.slid) = (mark.radius, mark.fails, mark.rejected, mark.slid);
    }
}

#[cfg(test)]
mod tests {
    use crate::events::EventLog;
    use crate::planners::{find, Context, Params, Tree};
    use crate::problem::Problem;
    use crate::rng::Rng;
    use crate::sampler::Sampler;
    use crate::scenario::builtin;

    /// A tree marked, grown past the mark (across the k-d tree's rebuilds), with older nodes
    /// re-attached, then rewound, is the tree it was: its states and parents, and its nearest
    /// answers, bit for bit.
    #[test]
    fn a_tree_rewound_to_its_mark_is_the_tree_it_was() {
        let p = Problem::from_scenario(&builtin("narrow").unwrap()).unwrap();
        let params = Params::from_json(find("rrt").unwrap(), &serde_json::json!({})).unwrap();
        let mut sampler = Sampler::from_params(&p.si, None, &params);
        let (mut rng, mut events) = (Rng::new(5), EventLog::default());
        let mut cx = Context {
            si: &p.si,
            rng: &mut rng,
            events: &mut events,
            nodes_left: 10_000,
            bytes_left: usize::MAX,
            sampler: &mut sampler,
            iteration: 0,
        };
        let point = |cx: &mut Context| {
            let mut q = vec![0.0; 2];
            cx.si.space.sample_uniform(cx.rng, &mut q);
            q
        };
        let mut t = Tree::new(&mut cx, &[0.1, 0.1], 0);
        for i in 0..100u32 {
            let q = point(&mut cx);
            t.add(&cx, &q, i / 2);
        }
        let before = t.clone();
        let mark = t.mark();
        for i in 0..300u32 {
            let q = point(&mut cx);
            t.add(&cx, &q, i);
        }
        for (i, parent) in [(5, 90), (5, 250), (7, 150), (250, 3)] {
            t.set_parent(i, parent);
        }
        t.rewind(mark);
        assert_eq!((t.len(), &t.states, &t.parents), (before.len(), &before.states, &before.parents));
        let mut before = before;
        for _ in 0..200 {
            let q = point(&mut cx);
            assert_eq!(t.nearest(&cx, &q), before.nearest(&cx, &q));
        }
    }
}

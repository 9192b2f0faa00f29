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

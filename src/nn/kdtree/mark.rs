//! Going back to an earlier state of a [`KdTree`] without copying it: a bounded batch of planning
//! marks the tree at its start and, when the batch is suspended ([`crate::journal`]), rewinds it
//! there, where a copy of every point's links and box cost a `memcpy` of the whole tree per batch.
//!
//! Since a mark the tree only grows: points are appended, a child link of an older point is set
//! from none to a newer point (each is noted), the boxes of older points only widen, and a rebuild
//! rewrites every link and box (the first one keeps them, as they were, beforehand). Rewinding
//! truncates the points, unsets the links noted, or puts back the links kept at a rebuild. Boxes
//! widened since are left wide: a box is only a lower bound for pruning, and every query's answer
//! is the nearest by (distance, insertion order), whatever the tree's shape or boxes, so the run
//! after a rewind is the same, bit for bit (`tests/determinism.rs`, runs in suspended batches).

use super::{KdTree, Links, NONE};

/// Where a [`KdTree`] stood when marked ([`KdTree::mark`]).
#[derive(Clone, Debug)]
pub struct KdMark {
    len: usize,
    root: u32,
    next_rebuild: usize,
}

/// What changed since the mark.
#[derive(Clone, Debug, Default)]
pub(super) struct Journal {
    /// Points whose child link was set (to a point added since the mark), in order.
    pub(super) linked: Vec<u32>,
    /// The links and boxes as they were before the first rebuild since the mark, and how many
    /// links had been noted then.
    before_rebuild: Option<(Links, usize)>,
}

impl KdTree {
    /// Mark the tree as it stands, to [`rewind`](Self::rewind) to it later; until then (or
    /// [`release`](Self::release)) what insertions change is noted.
    pub fn mark(&mut self) -> KdMark {
        self.journal = Some(Box::default());
        KdMark { len: self.ids.len(), root: self.links.root, next_rebuild: self.next_rebuild }
    }

    /// Forget the mark (nothing is noted any more).
    pub fn release(&mut self) {
        self.journal = None;
    }

    /// Back to the tree as it stood at `mark` (its last mark): the same points, and the same
    /// answers to every query.
    pub fn rewind(&mut self, mark: KdMark) {
        let journal = self.journal.take().unwrap_or_default();
        let mut noted = &journal.linked[..];
        if let Some((links, linked)) = journal.before_rebuild {
            noted = &journal.linked[..linked];
            self.links = links;
        }
        let n = mark.len;
        for &p in noted {
            let p = p as usize;
            if p < n {
                // a link to a point past the mark (NONE is past it too, and stays NONE)
                for child in [&mut self.links.left[p], &mut self.links.right[p]] {
                    if *child as usize >= n {
                        *child = NONE;
                    }
                }
            }
        }
        self.keys.truncate(n * self.kd);
        self.ids.truncate(n);
        let links = &mut self.links;
        links.split.truncate(n);
        links.left.truncate(n);
        links.right.truncate(n);
        links.lo.truncate(n * self.kd);
        links.hi.truncate(n * self.kd);
        links.root = mark.root;
        self.next_rebuild = mark.next_rebuild;
    }

    /// Before a rebuild, while marked: keep the links and boxes, the first time since the mark.
    pub(super) fn keep_links_before_rebuild(&mut self) {
        if let Some(j) = &mut self.journal {
            if j.before_rebuild.is_none() {
                j.before_rebuild = Some((self.links.clone(), j.linked.len()));
            }
        }
    }
}

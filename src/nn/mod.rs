//! Nearest-neighbour structures over a [`StateSpace`](crate::space::StateSpace)'s metric.
//!
//! The generic entry is [`KdTree`]: an incremental k-d tree whose nodes keep the bounding box of
//! their subtree, pruned with the space's `box_lower_bound`, which knows about wrapping angles and
//! weighted metrics. Exact (never approximate), and compared against a linear scan in the tests.

mod kdtree;

pub use kdtree::KdTree;

#[cfg(test)]
mod tests;

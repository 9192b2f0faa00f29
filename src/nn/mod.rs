//! Nearest-neighbour structures over a [`StateSpace`](crate::space::StateSpace)'s metric.
//!
//! The generic entry is [`KdTree`]: an incremental k-d tree whose nodes keep the bounding box of
//! their subtree, pruned with the space's `box_lower_bound`, which knows about wrapping angles and
//! weighted metrics. For the chain metrics the tree is built over each state's link-end points
//! (`StateSpace::embed`) and pruned with `embedded_box_lower_bound`: a box of joint angles says
//! little about where a 10-link chain's links are, a box of link ends says a lot (3.3× faster
//! queries among 10 000 random 10-link states, `cargo bench --bench core -- nearest`). Exact
//! (never approximate), and compared against a linear scan in the tests.

mod kdtree;

pub use kdtree::{KdMark, KdTree};

#[cfg(test)]
mod tests;

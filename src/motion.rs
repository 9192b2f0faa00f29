//! Motion validation. A straight motion in state space is checked at every state at most
//! [`SpaceInfo::resolution`](crate::space_info::SpaceInfo::resolution) apart (OMPL's
//! `DiscreteMotionValidator`: the end first, then in bisection order, coarse to fine, so a
//! collision is found after few checks). On top of that the
//! motion is *certified*, so no motion can cut an obstacle's corner between two checked states:
//!
//! - a point robot's motion is a segment, tested exactly against every obstacle;
//! - a body's motion uses clearances: the robot bounds how far any body point moves along the
//!   motion; if no body point moves more than `D` between two checked states and their clearances
//!   sum to more than `D`, every state between them is free
//!   (each body point stays within reach of one end); otherwise the interval is bisected, each new
//!   state counted as a check, until it is certified or a collision is found.
//!
//! This module declares the validator ([`MotionValidator`]) and its outcome; the problem's
//! validator is [`SpaceInfo`](crate::space_info::SpaceInfo), whose motion checks (counted and
//! journalled) are in `space_info/motion.rs`. The discrete loop itself is [`check_discrete`], in
//! [`crate::space`] so robots use it too.

use crate::math::Real;
pub use crate::space::{check_discrete, Discrete};

/// A motion was found invalid (the state found is in the caller's scratch buffer).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Invalid;

/// Checks straight motions between states.
pub trait MotionValidator {
    /// `Ok(())` if the motion `a → b` is valid (`a` is assumed valid). On `Err`, `scratch` (room for
    /// one state) holds the invalid state that was found.
    fn check_motion(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Invalid>;
}

#[cfg(test)]
mod tests;

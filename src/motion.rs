//! Motion validation: a straight motion in state space is valid when every state along it, at most
//! [`SpaceInfo::resolution`] apart, is valid (OMPL's `DiscreteMotionValidator`), and, for robots with
//! an exact swept test (the point), when that test finds nothing either.
//!
//! States are checked end first, then in bisection order (coarse to fine), so that a collision is
//! found after few checks.

use crate::math::{Real, Vec2};
use crate::space_info::SpaceInfo;

/// Checks straight motions between states.
pub trait MotionValidator {
    /// `Ok(())` if the motion `a → b` is valid (`a` is assumed valid); otherwise the workspace point
    /// of the collision found. `scratch` holds one state.
    fn check_motion(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Vec2>;
}

impl MotionValidator for SpaceInfo {
    fn check_motion(&self, a: &[Real], b: &[Real], scratch: &mut [Real]) -> Result<(), Vec2> {
        let d = self.distance(a, b);
        let n = ((d / self.resolution).ceil() as usize).max(1);
        if !self.is_valid(b) {
            return Err(self.project(b));
        }
        let mut step = n.next_power_of_two();
        while step > 1 {
            let half = step / 2;
            let mut i = half;
            while i < n {
                self.interpolate(a, b, i as Real / n as Real, scratch);
                if !self.is_valid(scratch) {
                    return Err(self.project(scratch));
                }
                i += step;
            }
            step = half;
        }
        if self.validity.sweep_hits(a, b) == Some(true) {
            self.interpolate(a, b, 0.5, scratch);
            return Err(self.project(scratch));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::Problem;
    use crate::scenario::builtin;

    #[test]
    fn bisection_order_checks_every_step_once() {
        let p = Problem::from_scenario(&builtin("narrow").unwrap()).unwrap();
        let si = &p.si;
        let (a, b) = ([0.1, 0.1], [0.4, 0.1]);
        let mut s = [0.0; 2];
        si.reset_checks();
        assert!(si.check_motion(&a, &b, &mut s).is_ok());
        let n = (0.3 / si.resolution).ceil() as u64;
        assert_eq!(si.checks(), n, "one check per step, end included");
        // Through the wall: found, and the point reported is inside the wall.
        let hit = si.check_motion(&a, &[0.9, 0.1], &mut s).unwrap_err();
        assert!(hit.x >= 0.45 && hit.x <= 0.55);
    }
}

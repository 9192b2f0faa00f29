//! Sampling near collisions (report 001, "Extension 2"): Gaussian samples around the last point
//! where a motion collided, with `collision_sigma`: as in the report's algorithm 2, the tree node
//! the colliding motion started from (free, and beside the obstacle; the colliding state itself
//! would lie inside it); in RRT-Connect's `last-free` connect, the last free configuration, the
//! node that connect added (or the node it started from when it added none). A counter holds the samples drawn since the
//! centre was last chosen at random; once it reaches `perseverance`, the centre moves to a random
//! state (one raw draw from the robot's sampler), the spread becomes `random_sigma` and the counter
//! starts again, so a fruitless obstacle is given up. A collision moves the centre to the
//! collision point and the spread to `collision_sigma` but does not reset the counter. No validity
//! check is spent: the planner's own motion checks judge the sample.

use super::{Draw, Sampler};
use crate::math::Real;

pub(super) fn draw(s: &mut Sampler, d: &mut Draw, out: &mut [Real]) -> bool {
    if s.centre.is_none() || s.around_centre >= s.perseverance {
        let c = s.centre.get_or_insert_with(|| vec![0.0; out.len()]);
        d.uniform(c);
        s.stats.draws += 1;
        s.centre_sigma = s.random_sigma;
        s.around_centre = 0;
    }
    s.around_centre += 1;
    let centre = s.centre.as_deref().expect("set above");
    d.gaussian_near(centre, s.centre_sigma, out);
    s.stats.draws += 1;
    true
}

pub(super) fn note_collision(s: &mut Sampler, q: &[Real]) {
    match &mut s.centre {
        Some(c) => c.copy_from_slice(q),
        None => s.centre = Some(q.to_vec()),
    }
    s.centre_sigma = s.collision_sigma;
}

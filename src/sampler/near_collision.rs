//! Sampling near collisions (report 001, "Extension 2"): Gaussian samples around the last point
//! where a motion collided, with `collision_sigma`; every `perseverance` samples the centre moves
//! to a uniform random state and the spread becomes `random_sigma`, so a fruitless obstacle is
//! given up. No validity check is spent: the planner's own motion checks judge the sample.

use super::{Draw, Sampler};
use crate::math::Real;

pub(super) fn draw(s: &mut Sampler, d: &mut Draw, out: &mut [Real]) -> bool {
    if s.centre.is_none() || s.around_centre >= s.perseverance {
        let mut c = vec![0.0; out.len()];
        d.uniform(&mut c);
        s.stats.draws += 1;
        s.centre = Some(c);
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

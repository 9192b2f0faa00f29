//! The generic Gaussian neighbour of a state. Here, below the samplers and the robots, since both
//! draw with it (the vehicle chain moves its placement this way).

use crate::math::Real;
use crate::rng::Rng;

/// The generic Gaussian neighbour: every coordinate moved independently (what a sampler's
/// Gaussian neighbour falls back to). Public for robots that move some coordinates this way.
pub fn gaussian_coordinates(space: &super::StateSpace, rng: &mut Rng, centre: &[Real], sigma: Real, out: &mut [Real]) {
    for (i, d) in space.dims.iter().enumerate() {
        let v = centre[i] + rng.normal() * sigma * (d.hi - d.lo);
        out[i] = if d.wraps { v } else { reflect(v, d.lo, d.hi) };
    }
    space.enforce(out);
}

/// `v` folded into `[lo, hi]` by reflection at the bounds (as often as needed): the identity
/// inside, a mirror image just outside, and uniform in the limit of a wide spread. Plain IEEE
/// arithmetic (`rem_euclid`), so the result is the same on every platform.
pub(crate) fn reflect(v: Real, lo: Real, hi: Real) -> Real {
    let w = hi - lo;
    if w <= 0.0 {
        return lo;
    }
    let t = (v - lo).rem_euclid(2.0 * w);
    (lo + if t > w { 2.0 * w - t } else { t }).clamp(lo, hi)
}

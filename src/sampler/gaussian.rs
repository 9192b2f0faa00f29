//! Gaussian sampling: V. Boor, M. H. Overmars, A. F. van der Stappen, "The Gaussian sampling
//! strategy for probabilistic roadmap planners", ICRA 1999. Draw a uniform state and a Gaussian
//! neighbour of it (`sigma`); when exactly one of the two is free, keep that one. Samples gather
//! along the boundary of the obstacles, within a few `sigma` of it. One attempt: one pair, two
//! draws and two checks.

use super::{Draw, Sampler};
use crate::math::Real;

pub(super) fn draw(s: &mut Sampler, d: &mut Draw, out: &mut [Real]) -> bool {
    for _ in 0..s.tries {
        d.uniform(&mut s.a);
        d.gaussian_near(&s.a, s.sigma, &mut s.b);
        s.stats.draws += 2;
        let (fa, fb) = (d.check(&s.a), d.check(&s.b));
        if fa != fb {
            out.copy_from_slice(if fa { &s.a } else { &s.b });
            s.witnessed = true;
            return true;
        }
    }
    false
}

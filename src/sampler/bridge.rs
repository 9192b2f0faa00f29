//! The bridge test: D. Hsu, T. Jiang, J. Reif, Z. Sun, "The bridge test for sampling narrow
//! passages with probabilistic roadmap planners", ICRA 2003. Draw an occupied state and a Gaussian
//! neighbour of it (`sigma`) that is occupied too; when the midpoint of the two (in the space's
//! interpolation, so the short way round an angle) is free, keep it. Samples gather in narrow
//! passages, where a short "bridge" between two obstacles has a free middle. One attempt: one or
//! two draws, and up to three checks.

use super::{Draw, Sampler};
use crate::math::Real;

pub(super) fn draw(s: &mut Sampler, d: &mut Draw, out: &mut [Real]) -> bool {
    for _ in 0..s.tries {
        d.uniform(&mut s.a);
        s.stats.draws += 1;
        if d.check(&s.a) {
            continue;
        }
        d.gaussian_near(&s.a, s.sigma, &mut s.b);
        s.stats.draws += 1;
        if d.check(&s.b) {
            continue;
        }
        d.si.interpolate(&s.a, &s.b, 0.5, out);
        if d.check(out) {
            s.witnessed = true;
            return true;
        }
    }
    false
}

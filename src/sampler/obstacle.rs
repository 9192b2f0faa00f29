//! Obstacle-based sampling (OMPL's `ObstacleBasedValidStateSampler`, after N. M. Amato et al.,
//! "OBPRM", WAFR 1996): draw a free state and an occupied one, then walk from the free one toward
//! the occupied one at the motion resolution and keep the last free state before the obstacle.

use super::{Draw, Sampler};
use crate::math::Real;

pub(super) fn draw(s: &mut Sampler, d: &mut Draw, out: &mut [Real]) -> bool {
    let mut free = false;
    let mut occupied = false;
    for _ in 0..s.tries {
        if !free {
            d.uniform(&mut s.a);
            s.stats.draws += 1;
            free = d.check(&s.a);
        }
        if !occupied {
            d.uniform(&mut s.b);
            s.stats.draws += 1;
            occupied = !d.check(&s.b);
        }
        if free && occupied {
            break;
        }
    }
    if !(free && occupied) {
        return false;
    }
    // Walk a → b; `out` keeps the last free state seen.
    let dist = d.si.distance(&s.a, &s.b);
    let steps = ((dist / d.si.resolution).ceil() as usize).max(1);
    out.copy_from_slice(&s.a);
    let mut q = s.a.clone();
    for k in 1..=steps {
        d.si.interpolate(&s.a, &s.b, k as Real / steps as Real, &mut q);
        if !d.check(&q) {
            break;
        }
        out.copy_from_slice(&q);
    }
    true
}

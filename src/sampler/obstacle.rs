//! Obstacle-based sampling (OMPL's `ObstacleBasedValidStateSampler`, after N. M. Amato,
//! O. B. Bayazit, L. K. Dale, C. Jones, D. Vallejo, "OBPRM: an obstacle-based PRM for 3D
//! workspaces", WAFR 1998): draw a free state and an occupied one (an attempt draws whichever is
//! still missing), then walk from the free one toward the occupied one along the space's
//! interpolation, in ⌈distance / resolution⌉ equal steps, and keep the last free state before the
//! first occupied one. Samples lie within one step of an obstacle: at most one resolution apart
//! under every metric but the chain metrics (under which equal steps of the joints are not equal
//! moves of the links, as motion checking also knows). The walk checks fewer than
//! ⌈distance / resolution⌉ states (the occupied end is known, and not checked again), so at most
//! the space's extent over its resolution.

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
    // Walk a → b over the states a + k/steps·(b − a), 0 < k < steps; `out` keeps the last free one.
    let dist = d.si.distance(&s.a, &s.b);
    // At most `MAX_MOTION_STEPS` (the problem's resolution check); the run's deadline holds.
    let steps = crate::limits::steps(dist, d.si.resolution, crate::limits::MAX_MOTION_STEPS).unwrap_or(1);
    out.copy_from_slice(&s.a);
    for k in 1..steps {
        if d.si.tick(1) {
            break;
        }
        d.si.interpolate(&s.a, &s.b, k as Real / steps as Real, &mut s.c);
        if !d.check(&s.c) {
            break;
        }
        out.copy_from_slice(&s.c);
    }
    s.witnessed = true;
    true
}

//! Sensing (inspection tasks): a sensor pose, its field of view, and the rule for a sight line.
//!
//! A sensor at `at` with heading `h` sees a point `p` when
//! - `|p − at| ≤ range` (the range is inclusive),
//! - the direction of `p` is within `fov / 2` of `h` (inclusive; a sensor with no heading, or with
//!   `fov ≥ 2π`, sees all around; a point exactly at the sensor has no direction and is seen), and
//! - the sight line `at → p` passes through no obstacle's **interior**
//!   ([`Workspace::sight_clear`](super::Workspace::sight_clear)).
//!
//! With the inspection block's `touch_hides` (the Technion course's rule, whose checker asks
//! whether the sight line `intersects` an obstacle edge), any contact hides the point instead:
//! [`Workspace::sight_untouched`](super::Workspace::sight_untouched).
//!
//! By default, a sight line that only touches an obstacle (grazes a vertex, runs along an edge, ends on the
//! boundary) is not blocked, in every workspace, whether or not the robot's body may touch
//! obstacles: light passes a corner. Crossing an interior blocks, and so does a point strictly
//! inside an obstacle. Every test is exact `f64` arithmetic on the segment, with no sampling along
//! the sight line; the direction uses `libm::atan2` so native and wasm agree to the bit.

use crate::math::{angle_diff, Real, Vec2, PI};

/// Where a robot's sensor is and which way it looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorPose {
    /// The sensor's position in the workspace.
    pub at: Vec2,
    /// Its heading, radians (`None`: it sees all around).
    pub heading: Option<Real>,
}

impl SensorPose {
    /// Whether `p` is within `range` of the sensor and inside its field of view `fov` (centred on
    /// the heading). Obstacles are not considered: see
    /// [`Workspace::sight_clear`](super::Workspace::sight_clear).
    #[inline]
    pub fn in_view(&self, p: Vec2, fov: Real, range: Real) -> bool {
        let d = p - self.at;
        let d2 = d.norm_squared();
        if d2 > range * range {
            return false;
        }
        match self.heading {
            Some(h) if fov < 2.0 * PI && d2 > 0.0 => angle_diff(h, libm::atan2(d.y, d.x)).abs() <= 0.5 * fov,
            _ => true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Aabb, Shape, Workspace};

    fn v(x: f64, y: f64) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn range_and_field_of_view() {
        let s = SensorPose { at: v(0.0, 0.0), heading: Some(0.0) };
        let fov = PI / 3.0;
        assert!(s.in_view(v(10.0, 0.0), fov, 60.0));
        assert!(s.in_view(v(60.0, 0.0), fov, 60.0), "the range is inclusive");
        assert!(!s.in_view(v(60.000001, 0.0), fov, 60.0));
        assert!(s.in_view(v(10.0, 5.0), fov, 60.0), "26.6° off the heading");
        assert!(!s.in_view(v(10.0, 6.0), fov, 60.0), "31° off the heading");
        assert!(!s.in_view(v(-10.0, 0.0), fov, 60.0), "behind");
        assert!(s.in_view(v(0.0, 0.0), fov, 60.0), "at the sensor");
        // Headings wrap: looking along −x with heading π or −π.
        for h in [PI, -PI, 3.0 * PI] {
            let s = SensorPose { at: v(0.0, 0.0), heading: Some(h) };
            assert!(s.in_view(v(-10.0, 1.0), fov, 60.0) && s.in_view(v(-10.0, -1.0), fov, 60.0), "heading {h}");
        }
        let all_round = SensorPose { at: v(0.0, 0.0), heading: None };
        assert!(all_round.in_view(v(-10.0, 0.0), fov, 60.0));
        assert!(!all_round.in_view(v(-61.0, 0.0), fov, 60.0));
    }

    #[test]
    fn sight_lines_are_blocked_by_interiors_only() {
        let b = Aabb { min: v(-10.0, -10.0), max: v(10.0, 10.0) };
        let square = Shape::Polygon(vec![v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)]);
        for ws in [
            Workspace::new(b, vec![square.clone()]),
            Workspace::new(b, vec![Shape::Rect(Aabb { min: v(0.0, 0.0), max: v(1.0, 1.0) })]),
        ] {
            assert!(!ws.sight_clear(v(-1.0, 0.5), v(2.0, 0.5)), "through");
            assert!(!ws.sight_clear(v(-1.0, -1.0), v(2.0, 2.0)), "along the diagonal, through the inside");
            assert!(ws.sight_clear(v(-1.0, 1.0), v(1.0, -1.0)), "grazing the vertex (0, 0)");
            assert!(ws.sight_clear(v(-1.0, 0.0), v(3.0, 0.0)), "along an edge");
            assert!(ws.sight_clear(v(-1.0, 0.5), v(0.0, 0.5)), "ending on the boundary");
            assert!(!ws.sight_clear(v(-1.0, 0.5), v(0.5, 0.5)), "ending inside");
            assert!(ws.sight_clear(v(-1.0, 2.0), v(3.0, 2.0)), "clear");
        }
    }
}

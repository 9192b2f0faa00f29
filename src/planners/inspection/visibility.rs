//! What the robot's sensor sees: at a state, and along a motion at the motion resolution. Each
//! is one unit of the batch journal.

use super::bits::{count, has, set, Bits};
use crate::math::{Real, Vec2};
use crate::planners::InspectionTask;
use crate::space_info::SpaceInfo;

/// Points looked at between two counts of the work done (see `SpaceInfo::tick`).
const POINTS_PER_TICK: u64 = 64;

/// What the robot's sensor must see for one task: the points, the field of view and the range.
#[derive(Clone, Debug)]
pub(super) struct Visibility {
    pub(super) points: Vec<Vec2>,
    pub(super) fov: Real,
    pub(super) range: Real,
    /// Look at the end of a motion only (the course's vertex-only coverage), not along it.
    pub(super) at_vertices: bool,
    /// Any contact with an obstacle hides a point (the course's sight test).
    pub(super) touch_hides: bool,
}

impl Visibility {
    pub(super) fn of(t: InspectionTask) -> Visibility {
        Visibility {
            points: t.points,
            fov: t.fov,
            range: t.range,
            at_vertices: t.at_vertices,
            touch_hides: t.touch_hides,
        }
    }

    /// Set in `out` every point not in `skip` or `out` that the sensor sees at `q`.
    /// (One unit of the batch journal: a bounded batch replays it without looking again.)
    pub(super) fn look(&self, si: &SpaceInfo, q: &[Real], skip: &Bits, out: &mut Bits) {
        si.journalled_bits(0, out, |out| {
            // A robot without a sensor sees nothing (the planner refuses it).
            let Some(sensor) = si.sensor() else { return };
            let pose = sensor.pose(q);
            // A unit of work per point, counted as the points are looked at (a replayed look is
            // not work: a simulated clock does not move on for it, nor does the interval between
            // looks at the clock shrink).
            let mut pending = 0;
            for (j, p) in self.points.iter().enumerate() {
                // Winding down: the look is thrown away (the journal keeps finished ones).
                if pending == POINTS_PER_TICK {
                    pending = 0;
                    if si.tick(POINTS_PER_TICK) {
                        break;
                    }
                } else if j == 0 && si.stopped() {
                    break;
                }
                pending += 1;
                if !has(skip, j) && !has(out, j) && si.sees_by(&pose, *p, self.fov, self.range, self.touch_hides) {
                    set(out, j);
                }
            }
            si.tick(pending + 1);
        })
    }

    /// Set in `out` (cleared first) every point not in `skip` that the sensor sees along the motion
    /// `a → b`, at every state at most the motion resolution apart, `b` included and `a` excluded
    /// (its own are its branch's); with `at_vertices`, at `b` only.
    /// (One unit of the batch journal, like [`Visibility::look`].)
    pub(super) fn sweep(&self, si: &SpaceInfo, a: &[Real], b: &[Real], skip: &Bits, out: &mut Bits, buf: &mut [Real]) {
        si.journalled_bits(1, out, |out| self.sweep_now(si, a, b, skip, out, buf))
    }

    fn sweep_now(&self, si: &SpaceInfo, a: &[Real], b: &[Real], skip: &Bits, out: &mut Bits, buf: &mut [Real]) {
        out.fill(0);
        let n = self.points.len();
        if count(skip) as usize == n {
            return;
        }
        // Each look counts its work (see `look`); the sweep stops when the run must wind down.
        if self.at_vertices {
            if !si.stopped() {
                self.look(si, b, skip, out);
            }
            return;
        }
        // At most `MAX_MOTION_STEPS` (the problem's resolution check), each looking at every
        // point: the run's deadline is looked at as it goes.
        let Some(steps) = crate::limits::steps(si.distance(a, b), si.resolution, crate::limits::MAX_MOTION_STEPS)
        else {
            return;
        };
        for i in 1..=steps {
            if si.stopped() {
                return;
            }
            if i == steps {
                buf.copy_from_slice(b);
            } else {
                si.interpolate(a, b, i as Real / steps as Real, buf);
            }
            self.look(si, buf, skip, out);
        }
    }
}

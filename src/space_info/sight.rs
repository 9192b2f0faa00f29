//! Sight: whether a sensor sees a workspace point (inspection tasks), exact and journalled.

use super::SpaceInfo;
use crate::geometry::SensorPose;
use crate::journal::Entry;
use crate::math::{Real, Vec2};

impl SpaceInfo {
    /// Whether a sensor at `pose` sees the workspace point `p`: within `range`, within `fov / 2`
    /// of its heading, and with a sight line through no obstacle's interior (touching an obstacle
    /// does not block; see [`crate::geometry::sight`]). Exact: no sampling along the sight line.
    /// Not counted as a state check.
    #[inline]
    pub fn sees(&self, pose: &SensorPose, p: Vec2, fov: Real, range: Real) -> bool {
        self.sees_by(pose, p, fov, range, false)
    }
    /// [`SpaceInfo::sees`] with the sight rule chosen: `touch_hides` (the Technion course's test),
    /// a sight line that meets an obstacle at all, its boundary included, hides the point; else
    /// only one through an obstacle's interior does.
    #[inline]
    pub fn sees_by(&self, pose: &SensorPose, p: Vec2, fov: Real, range: Real, touch_hides: bool) -> bool {
        pose.in_view(p, fov, range)
            && self.journalled(
                |e| if let Entry::Sight(v) = e { Some(*v) } else { None },
                Entry::Sight,
                false,
                || {
                    let ws = &self.validity.workspace;
                    if touch_hides {
                        ws.sight_untouched(pose.at, p)
                    } else {
                        ws.sight_clear(pose.at, p)
                    }
                },
            )
    }
}

//! The explanation of a collision: why a state is invalid, what blocked a motion and where the
//! robot met it. Neither counted nor journalled: it decides nothing in a run.

use super::SpaceInfo;
use crate::math::{Real, Vec2};
use crate::robot::Verdict;

impl SpaceInfo {
    /// Whether `q` is valid, and if not, why: **not** counted as a state check, not journalled
    /// (for explanations and checks of a finished path, which decide nothing in the run).
    pub fn verdict(&self, q: &[Real]) -> Verdict {
        self.validity.verdict(q)
    }
    /// What blocked the motion `a → b`, found invalid at `at`, for the explanation of a
    /// [`Collision`](crate::events::EventKind::Collision) event, and the workspace point to show
    /// it at. What: the index of the obstacle the robot meets at `at` (the first in scenario
    /// order; for a robot with an exact sweep whose state `at` is free, the first obstacle the
    /// sweep meets), -2 the map's edge, -3 one of the robot's own rules (self-collision, a joint
    /// limit), -1 not known (a motion refused unchecked: out of time, or too long to check).
    /// Where: for a body meeting an obstacle at `at`, where they meet ([`SpaceInfo::contact`]);
    /// else the state's reference point. Not counted as a state check, not journalled: it asks
    /// nothing a planner decides by.
    pub fn blocked_at(&self, a: &[Real], b: &[Real], at: &[Real]) -> (i64, Vec2) {
        let reference = self.project(at);
        match self.validity.verdict(at) {
            Verdict::Collision(i) => (i as i64, self.contact(at, i).unwrap_or(reference)),
            Verdict::OutOfBounds(_) => (-2, reference),
            Verdict::Invalid(_) => (-3, reference),
            Verdict::Valid => match self.motion_model().sweep_hits(self.workspace(), a, b) {
                Some(true) => {
                    let hit = self.workspace().first_obstacle_on_segment(self.project(a), self.project(b));
                    (hit.map_or(-1, |i| i as i64), reference)
                }
                _ => (-1, reference),
            },
        }
    }
    /// Where the robot's body at `q` meets obstacle `i`: the first point, along its outline's
    /// edges in order (a rigid body's polygon, an arm's links, a vehicle chain's brooms), that lies
    /// in the obstacle; else (the obstacle wholly inside a rigid body) a point of the obstacle.
    /// `None` for a point robot (no outline). For drawing and captions only: the verdict is the
    /// robot's.
    pub fn contact(&self, q: &[Real], i: usize) -> Option<Vec2> {
        let shape = self.validity.workspace.obstacles.get(i)?;
        let open = self.validity.workspace.touching_allowed;
        let closed = self.validity.robot.body().is_some(); // see `Robot::outline`
        let outline = self.outline(q);
        for poly in &outline {
            let n = poly.len();
            let edges = if closed && n > 2 { n } else { n.saturating_sub(1) };
            if let Some(p) = (0..edges).find_map(|k| shape.first_point_on(poly[k], poly[(k + 1) % n], open)) {
                return Some(p);
            }
        }
        (closed && !outline.is_empty()).then(|| shape.some_point())
    }
}

//! The chain's validity rules on vehicle positions (the vehicle-chain course, `docs/sources.md`), with the planner's margin.

use super::{AsvRobot, MARGIN};
use crate::geometry::segment::distance2_point_segment;
use crate::geometry::{Aabb, Shape, Workspace};
use crate::math::{wrap_angle, MinMax, Real, Vec2, PI};
use crate::robot::Verdict;

/// Twice the signed area of the closed polygon (shoelace; > 0 counter-clockwise).
pub(super) fn signed_area2(p: &[Vec2]) -> Real {
    let n = p.len();
    (0..n).map(|i| p[i].perp(&p[(i + 1) % n])).sum()
}

/// The signed turn from direction `d` to direction `e`, in `[−π, π]`.
#[inline]
fn turn(d: Vec2, e: Vec2) -> Real {
    libm::atan2(d.perp(&e), d.dot(&e))
}

/// Whether the closed segment `a b` meets the closed box `[lo, hi]`: the boxes overlap and the
/// box's corners are not all strictly on one side of the segment's line.
#[inline]
pub(super) fn segment_meets_box(a: Vec2, b: Vec2, lo: Vec2, hi: Vec2) -> bool {
    if a.x.at_least(b.x) < lo.x || a.x.at_most(b.x) > hi.x || a.y.at_least(b.y) < lo.y || a.y.at_most(b.y) > hi.y {
        return false;
    }
    let side = |c: Vec2| crate::geometry::segment::orient(a, b, c);
    let s = [side(lo), side(Vec2::new(hi.x, lo.y)), side(hi), side(Vec2::new(lo.x, hi.y))];
    !(s.iter().all(|&v| v > 0.0) || s.iter().all(|&v| v < 0.0))
}

/// Whether closed segments `a b` and `c d` share a point.
fn segments_meet(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> bool {
    crate::geometry::segment::intersect_segment_segment(a, b, c, d)
}

/// The obstacle a broom `a b` meets, if any: a rectangle shrunk by the margin when touching is
/// allowed (the course's rule), any other shape as a closed set.
#[inline]
pub(super) fn broom_hit(ws: &Workspace, a: Vec2, b: Vec2) -> Option<usize> {
    let shrink = if ws.touching_allowed { MARGIN } else { 0.0 };
    ws.first_hit(&Aabb::of_points(&[a, b]), |i| match &ws.obstacles[i] {
        Shape::Rect(r) => {
            let (lo, hi) =
                (Vec2::new(r.min.x + shrink, r.min.y + shrink), Vec2::new(r.max.x - shrink, r.max.y - shrink));
            lo.x <= hi.x && lo.y <= hi.y && segment_meets_box(a, b, lo, hi)
        }
        other => other.intersects_segment(a, b),
    })
}

/// The distance from broom `a b` to the nearest obstacle (rectangles shrunk as in [`broom_hit`]),
/// or `cap` if that is smaller; 0 when it meets one. Through the workspace's broad phase (its
/// boxes are the unshrunk ones, so it skips only obstacles that cannot be nearer).
fn broom_distance(ws: &Workspace, a: Vec2, b: Vec2, cap: Real) -> Real {
    let shrink = if ws.touching_allowed { MARGIN } else { 0.0 };
    let bb = Aabb::of_points(&[a, b]);
    ws.nearest_by(&bb, cap, |i, best| match &ws.obstacles[i] {
        Shape::Rect(r) => {
            let (lo, hi) =
                (Vec2::new(r.min.x + shrink, r.min.y + shrink), Vec2::new(r.max.x - shrink, r.max.y - shrink));
            if lo.x > hi.x || lo.y > hi.y {
                return best;
            }
            // Box-to-box gap first: most rectangles are farther than `best`.
            if (Aabb { min: lo, max: hi }).gap(&bb).norm_squared() >= best * best {
                return best;
            }
            if segment_meets_box(a, b, lo, hi) {
                return 0.0;
            }
            // Apart: the nearest points are an end of the broom or a corner of the box.
            let to_box = |p: Vec2| {
                let dx = (lo.x - p.x).at_least(p.x - hi.x).at_least(0.0);
                let dy = (lo.y - p.y).at_least(p.y - hi.y).at_least(0.0);
                dx * dx + dy * dy
            };
            let mut d2 = to_box(a).at_most(to_box(b));
            for corner in [lo, Vec2::new(hi.x, lo.y), hi, Vec2::new(lo.x, hi.y)] {
                d2 = d2.at_most(distance2_point_segment(corner, a, b));
            }
            best.at_most(d2.sqrt())
        }
        other => best.at_most(other.distance_to_polygon(&[a, b], &bb, best)),
    })
}

impl AsvRobot {
    /// The verdict on vehicle positions `pts` whose chain turns are `turns` (`n − 2` of them).
    pub(super) fn verdict_of(&self, ws: &Workspace, turns: &[Real], pts: &[Vec2]) -> Verdict {
        let v = self.shape_verdict(ws, turns, pts);
        if v != Verdict::Valid {
            return v;
        }
        for k in 0..pts.len() - 1 {
            if let Some(i) = broom_hit(ws, pts[k], pts[k + 1]) {
                return Verdict::Collision(i);
            }
        }
        Verdict::Valid
    }

    /// Every rule but the obstacles: bounds, area, convexity (or simplicity).
    fn shape_verdict(&self, ws: &Workspace, turns: &[Real], pts: &[Vec2]) -> Verdict {
        let b = ws.bounds;
        for p in pts {
            if p.x < b.min.x - MARGIN || p.x > b.max.x + MARGIN {
                return Verdict::OutOfBounds(0);
            }
            if p.y < b.min.y - MARGIN || p.y > b.max.y + MARGIN {
                return Verdict::OutOfBounds(1);
            }
        }
        if signed_area2(pts).abs() < 2.0 * (self.min_area - MARGIN) {
            return Verdict::Invalid("the polygon closed by the chain is too small (area)");
        }
        if self.convex {
            if let Some(why) = self.convexity(turns, pts) {
                return Verdict::Invalid(why);
            }
        } else if !simple(pts) {
            return Verdict::Invalid("the polygon closed by the chain crosses itself");
        }
        Verdict::Valid
    }

    /// How far every vehicle may move (each by at most this much, brooms keeping their length,
    /// chain turns keeping within their rules) with the state staying valid, capped at `cap`;
    /// 0 when the state is invalid. The parts:
    /// - bounds and obstacles: the distance of each vehicle to the (grown) bounds' edges and of
    ///   each broom to each (shrunk) obstacle, since a broom whose ends move `δ` stays within `δ`;
    /// - area: moving every vertex `δ` changes the shoelace area by at most `δ·P + n·δ²/2` (`P` the
    ///   perimeter);
    /// - the two turns at the closing edge: a vector of length `ℓ` whose ends move `δ ≤ ℓ/2` turns
    ///   by at most `π·δ/ℓ`, so each turn moves at most `π·δ·(1/|closing| + 1/L)`, and must keep
    ///   its sign (within the margin) and stay short of π.
    ///
    /// The chain's own turns are not part of it: along a straight motion each moves linearly
    /// between its end values, so it keeps its rules when both ends do.
    pub(super) fn clearance_of(&self, ws: &Workspace, turns: &[Real], pts: &[Vec2], cap: Real) -> Real {
        if self.shape_verdict(ws, turns, pts) != Verdict::Valid {
            return 0.0;
        }
        let n = pts.len();
        let b = ws.bounds;
        let mut c = cap.at_most(0.5 * self.broom);
        for p in pts {
            c = c
                .at_most(p.x - b.min.x + MARGIN)
                .at_most(b.max.x + MARGIN - p.x)
                .at_most(p.y - b.min.y + MARGIN)
                .at_most(b.max.y + MARGIN - p.y);
        }
        let area2 = signed_area2(pts);
        let closing = pts[0] - pts[n - 1];
        let perimeter = self.broom * (n - 1) as Real + closing.norm();
        c = c.at_most((0.5 * area2.abs() - (self.min_area - MARGIN)) / (perimeter + n as Real * cap));
        if self.convex {
            let len = closing.norm();
            let sigma = if area2 != 0.0 { area2.signum() } else { 0.0 };
            let k = PI * (1.0 / len + 1.0 / self.broom);
            c = c.at_most(0.5 * len);
            for t in [turn(pts[n - 1] - pts[n - 2], closing), turn(closing, pts[1] - pts[0])] {
                c = c.at_most((sigma * t + MARGIN) / k).at_most((PI - t.abs()) / k);
            }
        } else {
            for i in 0..n {
                for j in i + 2..n {
                    if i == 0 && j == n - 1 {
                        continue;
                    }
                    let d = crate::geometry::segment::distance_segment_segment(
                        pts[i],
                        pts[(i + 1) % n],
                        pts[j],
                        pts[(j + 1) % n],
                    );
                    c = c.at_most(0.5 * d);
                }
            }
        }
        for k in 0..n - 1 {
            if c <= 0.0 {
                return 0.0;
            }
            c = c.at_most(broom_distance(ws, pts[k], pts[k + 1], c));
        }
        c.at_least(0.0)
    }

    /// Why the closed polygon is not convex in the course's sense, if it is not: every turn (walking
    /// it) has one sign, turns within the margin counting as straight; no turn is a full reversal;
    /// the absolute turns sum to at most 3π.
    fn convexity(&self, turns: &[Real], pts: &[Vec2]) -> Option<&'static str> {
        let n = pts.len();
        let closing = pts[0] - pts[n - 1];
        let first = pts[1] - pts[0];
        let last = pts[n - 1] - pts[n - 2];
        let (mut sign, mut total) = (0.0, 0.0);
        let mut visit = |t: Real| -> Option<&'static str> {
            if t.abs() >= PI {
                return Some("the chain folds back on itself");
            }
            total += t.abs();
            if !(-MARGIN..=MARGIN).contains(&t) {
                let s = t.signum();
                if sign * s < 0.0 {
                    return Some("the polygon closed by the chain is not convex");
                }
                sign = s;
            }
            None
        };
        let chain = turns.iter().map(|&t| if t.abs() > PI { wrap_angle(t) } else { t });
        for t in chain.chain([turn(last, closing), turn(closing, first)]) {
            if let Some(why) = visit(t) {
                return Some(why);
            }
        }
        if total > 3.0 * PI {
            return Some("the polygon closed by the chain crosses itself");
        }
        None
    }
}

/// Whether the closed polygon is simple: no two non-adjacent edges meet.
fn simple(p: &[Vec2]) -> bool {
    let n = p.len();
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            if segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]) {
                return false;
            }
        }
    }
    true
}

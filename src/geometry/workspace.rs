use super::{Aabb, Shape};
use crate::math::{MinMax, Real, Vec2};

/// The world a robot moves in: rectangular bounds and closed obstacles.
#[derive(Clone, Debug)]
pub struct Workspace {
    /// The bounds `[xmin, ymin] .. [xmax, ymax]`.
    pub bounds: Aabb,
    /// Obstacles are open sets: touching their boundary is allowed (`touching_allowed`). Only
    /// [`Workspace::segment_hit`] reads it; robots made of segments (arms) use that.
    pub open: bool,
    /// The obstacles, in scenario order.
    pub obstacles: Vec<Shape>,
    boxes: Vec<Aabb>,
}

impl Workspace {
    /// A workspace from its bounds and obstacles.
    pub fn new(bounds: Aabb, obstacles: Vec<Shape>) -> Self {
        let boxes = obstacles.iter().map(Shape::aabb).collect();
        Workspace { bounds, obstacles, boxes, open: false }
    }

    /// The index of the first obstacle that contains `p`, if any.
    pub fn point_hit(&self, p: Vec2) -> Option<usize> {
        self.boxes.iter().zip(&self.obstacles).position(|(bx, shape)| bx.contains(p) && shape.contains_point(p))
    }

    /// Whether the point `p` lies in (or on) an obstacle.
    pub fn point_hits(&self, p: Vec2) -> bool {
        self.boxes.iter().zip(&self.obstacles).any(|(bx, shape)| bx.contains(p) && shape.contains_point(p))
    }

    /// Whether the closed segment `a b` meets an obstacle.
    pub fn segment_hits(&self, a: Vec2, b: Vec2) -> bool {
        let bb = Aabb::of_points(&[a, b]);
        self.boxes.iter().zip(&self.obstacles).any(|(bx, shape)| bx.intersects(&bb) && shape.intersects_segment(a, b))
    }

    /// The distance from the closed polygon `poly` to the nearest obstacle, capped at `cap`
    /// (0 when it meets one).
    pub fn polygon_clearance(&self, poly: &[Vec2], cap: Real) -> Real {
        let bb = Aabb::of_points(poly);
        let mut best = cap;
        for (shape, bx) in self.obstacles.iter().zip(&self.boxes) {
            if bx.intersects(&bb.grown(best)) {
                best = best.at_most(shape.distance_to_polygon(poly, &bb, best));
                if best == 0.0 {
                    break;
                }
            }
        }
        best
    }

    /// The index of the first obstacle that the segment `a b` meets (its interior only when the
    /// workspace is [`open`](Workspace::open)), if any.
    pub fn segment_hit(&self, a: Vec2, b: Vec2) -> Option<usize> {
        let bb = Aabb::of_points(&[a, b]);
        (0..self.obstacles.len()).find(|&i| {
            self.boxes[i].intersects(&bb)
                && if self.open { self.obstacles[i].interior_meets_segment(a, b) } else { self.obstacles[i].intersects_segment(a, b) }
        })
    }

    /// The distance from the segment `a b` to the nearest obstacle, capped at `cap` (0 when it
    /// meets or touches one).
    pub fn segment_clearance(&self, a: Vec2, b: Vec2, cap: Real) -> Real {
        let bb = Aabb::of_points(&[a, b]);
        let mut best = cap;
        for (shape, bx) in self.obstacles.iter().zip(&self.boxes) {
            if bx.intersects(&bb.grown(best)) {
                best = best.at_most(shape.distance_to_segment(a, b, best));
                if best == 0.0 {
                    break;
                }
            }
        }
        best
    }

    /// Whether a sensor at `a` has a clear sight line to `b`: the segment `a b` passes through no
    /// obstacle's interior. Touching (grazing a vertex, running along an edge, ending on the
    /// boundary) does not block, whatever [`open`](Workspace::open) says (see [`super::sight`]).
    pub fn sight_clear(&self, a: Vec2, b: Vec2) -> bool {
        let bb = Aabb::of_points(&[a, b]);
        !(0..self.obstacles.len()).any(|i| self.boxes[i].intersects(&bb) && self.obstacles[i].interior_meets_segment(a, b))
    }

    /// The index of the first obstacle that the closed polygon `poly` meets, if any.
    pub fn polygon_hit(&self, poly: &[Vec2]) -> Option<usize> {
        let bb = Aabb::of_points(poly);
        (0..self.obstacles.len()).find(|&i| self.boxes[i].intersects(&bb) && self.obstacles[i].intersects_polygon(poly, &bb))
    }
}

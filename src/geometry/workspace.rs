use super::{Aabb, Shape};
use crate::math::{MinMax, Real, Vec2};
use parry2d_f64::bounding_volume::Aabb as ParryAabb;
use parry2d_f64::math::Vector;
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy, BvhNode};
use std::cell::Cell;

/// From this many obstacles on, queries go through a bounding-volume hierarchy (parry's `Bvh`)
/// rather than a scan of every obstacle's box. Below it, the scan is as fast.
pub const BVH_FROM: usize = 32;

/// The world a robot moves in: rectangular bounds and closed obstacles.
///
/// Every query is a broad phase over the obstacles' boxes (a scan, or from [`BVH_FROM`] obstacles
/// on parry's bounding-volume hierarchy, built once here), then the exact test on the obstacles
/// whose boxes meet the query's. Both broad phases find the same obstacles, and the queries that
/// name one name the first in scenario order, so results do not depend on which is used.
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
    bvh: Option<Bvh>,
}

/// Whether a hierarchy node's box meets `bb` (closed boxes: touching counts, as [`Aabb::intersects`]).
#[inline]
fn node_meets(node: &BvhNode, bb: &Aabb) -> bool {
    let (lo, hi) = (node.mins(), node.maxs());
    lo.x <= bb.max.x && bb.min.x <= hi.x && lo.y <= bb.max.y && bb.min.y <= hi.y
}

impl Workspace {
    /// A workspace from its bounds and obstacles.
    pub fn new(bounds: Aabb, obstacles: Vec<Shape>) -> Self {
        let boxes: Vec<Aabb> = obstacles.iter().map(Shape::aabb).collect();
        let bvh = (boxes.len() >= BVH_FROM).then(|| {
            let leaves: Vec<ParryAabb> = boxes.iter().map(|b| ParryAabb::new(Vector::new(b.min.x, b.min.y), Vector::new(b.max.x, b.max.y))).collect();
            Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves)
        });
        Workspace { bounds, obstacles, boxes, bvh, open: false }
    }

    /// The same workspace with the broad phase a scan of every box (for tests and benchmarks
    /// that compare the two).
    pub fn scanned(&self) -> Workspace {
        Workspace { bvh: None, ..self.clone() }
    }

    /// Whether queries use the bounding-volume hierarchy.
    pub fn has_bvh(&self) -> bool {
        self.bvh.is_some()
    }

    /// Call `f` with each obstacle whose box meets `bb` (in no particular order) until it returns
    /// `true`; returns whether it did.
    #[inline]
    fn near(&self, bb: &Aabb, mut f: impl FnMut(usize) -> bool) -> bool {
        match &self.bvh {
            None => self.boxes.iter().enumerate().any(|(i, bx)| bx.intersects(bb) && f(i)),
            Some(t) => t.leaves(|n| node_meets(n, bb)).any(|i| f(i as usize)),
        }
    }

    /// The first obstacle (in scenario order) whose box meets `bb` and that passes `hit`.
    #[inline]
    fn first(&self, bb: &Aabb, hit: impl Fn(usize) -> bool) -> Option<usize> {
        match &self.bvh {
            None => (0..self.obstacles.len()).find(|&i| self.boxes[i].intersects(bb) && hit(i)),
            Some(_) => {
                let mut first: Option<usize> = None;
                self.near(bb, |i| {
                    if first.is_none_or(|f| i < f) && hit(i) {
                        first = Some(i);
                    }
                    false
                });
                first
            }
        }
    }

    /// The smallest of `cap` and `dist(i, best so far)` over the obstacles whose boxes come within
    /// the best so far of `bb` (stopping at 0).
    #[inline]
    fn nearest(&self, bb: &Aabb, cap: Real, dist: impl Fn(usize, Real) -> Real) -> Real {
        match &self.bvh {
            None => {
                let mut best = cap;
                for (i, bx) in self.boxes.iter().enumerate() {
                    if bx.intersects(&bb.grown(best)) {
                        best = best.at_most(dist(i, best));
                        if best == 0.0 {
                            break;
                        }
                    }
                }
                best
            }
            Some(t) => {
                // The search box shrinks as closer obstacles are found.
                let best = Cell::new(cap);
                for i in t.leaves(|n| node_meets(n, &bb.grown(best.get()))) {
                    let b = best.get();
                    if self.boxes[i as usize].intersects(&bb.grown(b)) {
                        best.set(b.at_most(dist(i as usize, b)));
                        if best.get() == 0.0 {
                            break;
                        }
                    }
                }
                best.get()
            }
        }
    }

    /// The index of the first obstacle that contains `p`, if any.
    pub fn point_hit(&self, p: Vec2) -> Option<usize> {
        self.first(&Aabb { min: p, max: p }, |i| self.obstacles[i].contains_point(p))
    }

    /// Whether the point `p` lies in (or on) an obstacle.
    pub fn point_hits(&self, p: Vec2) -> bool {
        self.near(&Aabb { min: p, max: p }, |i| self.obstacles[i].contains_point(p))
    }

    /// Whether the closed segment `a b` meets an obstacle.
    pub fn segment_hits(&self, a: Vec2, b: Vec2) -> bool {
        self.near(&Aabb::of_points(&[a, b]), |i| self.obstacles[i].intersects_segment(a, b))
    }

    /// The distance from the closed polygon `poly` to the nearest obstacle, capped at `cap`
    /// (0 when it meets one).
    pub fn polygon_clearance(&self, poly: &[Vec2], cap: Real) -> Real {
        let bb = Aabb::of_points(poly);
        self.nearest(&bb, cap, |i, best| self.obstacles[i].distance_to_polygon(poly, &bb, best))
    }

    /// The index of the first obstacle that the segment `a b` meets (its interior only when the
    /// workspace is [`open`](Workspace::open)), if any.
    pub fn segment_hit(&self, a: Vec2, b: Vec2) -> Option<usize> {
        self.first(&Aabb::of_points(&[a, b]), |i| if self.open { self.obstacles[i].interior_meets_segment(a, b) } else { self.obstacles[i].intersects_segment(a, b) })
    }

    /// The distance from the segment `a b` to the nearest obstacle, capped at `cap` (0 when it
    /// meets or touches one).
    pub fn segment_clearance(&self, a: Vec2, b: Vec2, cap: Real) -> Real {
        self.nearest(&Aabb::of_points(&[a, b]), cap, |i, best| self.obstacles[i].distance_to_segment(a, b, best))
    }

    /// Whether a sensor at `a` has a clear sight line to `b`: the segment `a b` passes through no
    /// obstacle's interior. Touching (grazing a vertex, running along an edge, ending on the
    /// boundary) does not block, whatever [`open`](Workspace::open) says (see [`super::sight`]).
    pub fn sight_clear(&self, a: Vec2, b: Vec2) -> bool {
        !self.near(&Aabb::of_points(&[a, b]), |i| self.obstacles[i].interior_meets_segment(a, b))
    }

    /// The index of the first obstacle that the closed polygon `poly` meets, if any.
    pub fn polygon_hit(&self, poly: &[Vec2]) -> Option<usize> {
        let bb = Aabb::of_points(poly);
        self.first(&bb, |i| self.obstacles[i].intersects_polygon(poly, &bb))
    }

    /// An obstacle (the first found, not necessarily the first in scenario order) that the closed
    /// polygon `poly` meets, if any: for validity, where any will do and the search stops at it.
    pub fn polygon_hit_any(&self, poly: &[Vec2]) -> Option<usize> {
        let bb = Aabb::of_points(poly);
        self.any(&bb, |i| self.obstacles[i].intersects_polygon(poly, &bb))
    }

    /// Like [`Workspace::segment_hit`], but any obstacle met (see [`Workspace::polygon_hit_any`]).
    pub fn segment_hit_any(&self, a: Vec2, b: Vec2) -> Option<usize> {
        self.any(&Aabb::of_points(&[a, b]), |i| if self.open { self.obstacles[i].interior_meets_segment(a, b) } else { self.obstacles[i].intersects_segment(a, b) })
    }

    /// An obstacle whose box meets `bb` and that passes `hit`, the first the broad phase finds.
    #[inline]
    fn any(&self, bb: &Aabb, hit: impl Fn(usize) -> bool) -> Option<usize> {
        let mut found = None;
        self.near(bb, |i| {
            let h = hit(i);
            if h {
                found = Some(i);
            }
            h
        });
        found
    }
}

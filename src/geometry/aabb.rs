use crate::math::{MinMax, Real, Vec2};

/// An axis-aligned bounding box, the broad phase of every test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub min: Vec2,
    /// Upper corner.
    pub max: Vec2,
}

impl Aabb {
    /// The box of a set of points (`pts` non-empty).
    pub fn of_points(pts: &[Vec2]) -> Aabb {
        let mut b = Aabb { min: pts[0], max: pts[0] };
        for p in &pts[1..] {
            b.min.x = b.min.x.at_most(p.x);
            b.min.y = b.min.y.at_most(p.y);
            b.max.x = b.max.x.at_least(p.x);
            b.max.y = b.max.y.at_least(p.y);
        }
        b
    }
    /// Whether two closed boxes overlap (touching counts).
    #[inline]
    pub fn intersects(&self, o: &Aabb) -> bool {
        self.min.x <= o.max.x && o.min.x <= self.max.x && self.min.y <= o.max.y && o.min.y <= self.max.y
    }
    /// Whether the closed box contains `p`.
    #[inline]
    pub fn contains(&self, p: Vec2) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }
    /// How far apart two boxes are along x and along y (0 along an axis where they overlap):
    /// their distance is at least `√(gx² + gy²)`.
    #[inline]
    pub fn gap(&self, o: &Aabb) -> Vec2 {
        Vec2::new(
            (self.min.x - o.max.x).at_least(o.min.x - self.max.x).at_least(0.0),
            (self.min.y - o.max.y).at_least(o.min.y - self.max.y).at_least(0.0),
        )
    }
    /// The box grown by `r` on every side.
    pub fn grown(&self, r: Real) -> Aabb {
        Aabb { min: Vec2::new(self.min.x - r, self.min.y - r), max: Vec2::new(self.max.x + r, self.max.y + r) }
    }
}

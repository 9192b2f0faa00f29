//! Scalar and 2-D point types used everywhere in the core.
//!
//! The hot path (collision checks, distances, nearest neighbours) runs on plain `f64` and this small
//! [`Vec2`]; see `docs/architecture.md` for why the core does not use nalgebra or parry types here.

/// The scalar type of every coordinate, angle and distance.
pub type Real = f64;

/// π as a [`Real`].
pub const PI: Real = std::f64::consts::PI;

/// A 2-D point or vector.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec2 {
    /// x coordinate.
    pub x: Real,
    /// y coordinate.
    pub y: Real,
}

/// A 2-D point (alias of [`Vec2`], as parry names them).
pub type Point2 = Vec2;

impl Vec2 {
    /// A new vector.
    #[inline]
    pub const fn new(x: Real, y: Real) -> Self {
        Vec2 { x, y }
    }
    /// `self * s`.
    #[inline]
    pub fn scale(self, s: Real) -> Vec2 {
        Vec2::new(self.x * s, self.y * s)
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: Vec2) -> Real {
        self.x * o.x + self.y * o.y
    }
    /// z component of the cross product.
    #[inline]
    pub fn cross(self, o: Vec2) -> Real {
        self.x * o.y - self.y * o.x
    }
    /// Squared length.
    #[inline]
    pub fn norm2(self) -> Real {
        self.dot(self)
    }
    /// Length.
    #[inline]
    pub fn norm(self) -> Real {
        self.norm2().sqrt()
    }
    /// Rotate by an angle given as its cosine and sine.
    #[inline]
    pub fn rotate(self, c: Real, s: Real) -> Vec2 {
        Vec2::new(c * self.x - s * self.y, s * self.x + c * self.y)
    }
}

impl std::ops::Sub for Vec2 {
    type Output = Vec2;
    #[inline]
    fn sub(self, o: Vec2) -> Vec2 {
        Vec2::new(self.x - o.x, self.y - o.y)
    }
}

impl std::ops::Add for Vec2 {
    type Output = Vec2;
    #[inline]
    fn add(self, o: Vec2) -> Vec2 {
        Vec2::new(self.x + o.x, self.y + o.y)
    }
}

/// Wrap an angle to `[-π, π)`.
#[inline]
pub fn wrap_angle(a: Real) -> Real {
    let t = (a + PI).rem_euclid(2.0 * PI) - PI;
    if t >= PI {
        t - 2.0 * PI
    } else {
        t
    }
}

/// The signed shortest rotation from `a` to `b`, in `[-π, π)`.
#[inline]
pub fn angle_diff(a: Real, b: Real) -> Real {
    wrap_angle(b - a)
}

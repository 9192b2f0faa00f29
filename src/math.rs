//! Scalar, vector and pose types used everywhere in the core.
//!
//! Points and vectors are nalgebra's ([`Vec2`] is `nalgebra::Vector2<f64>`), and a placed body is
//! an [`Pose2`] (`nalgebra::Isometry2`), so code reads as Rust robotics code does. Angles become
//! rotations only through [`pose`] and [`rotation`], from libm's `sincos`: nalgebra's own
//! `Rotation2::new(angle)` calls the platform's `sin`/`cos`, which may differ in the last bit
//! between native code and wasm, and runs must be identical everywhere.

/// The scalar type of every coordinate, angle and distance.
pub type Real = f64;

/// π as a [`Real`].
pub const PI: Real = std::f64::consts::PI;

/// A 2-D point or vector (nalgebra's `Vector2`; `x`, `y`, `dot`, `perp`, `norm`, `scale`).
pub type Vec2 = nalgebra::Vector2<Real>;

/// A 2-D point (alias of [`Vec2`], as parry names them).
pub type Point2 = Vec2;

/// A planar rotation (nalgebra's unit complex number).
pub type Rot2 = nalgebra::UnitComplex<Real>;

/// A planar pose: a rotation, then a translation (nalgebra's `Isometry2`).
pub type Pose2 = nalgebra::Isometry2<Real>;

/// The rotation by `theta`, its cosine and sine from libm (value-stable on every platform).
#[inline]
pub fn rotation(theta: Real) -> Rot2 {
    let (s, c) = libm::sincos(theta);
    Rot2::from_cos_sin_unchecked(c, s)
}

/// The pose at `(x, y)` with heading `theta`.
#[inline]
pub fn pose(x: Real, y: Real, theta: Real) -> Pose2 {
    Pose2::from_parts(nalgebra::Translation2::new(x, y), rotation(theta))
}

/// `pose` applied to the body-frame point `p`: `R p + t`.
#[inline]
pub fn place(pose: &Pose2, p: Vec2) -> Vec2 {
    pose.transform_point(&nalgebra::Point2::from(p)).coords
}

/// Minimum and maximum of two [`Real`]s as one comparison each, for the hot loops.
///
/// std's `f64::min`/`max` must return the other operand when one is NaN. WebAssembly has no
/// instruction for that (its `f64.min` propagates NaN), so in wasm they become calls to `fmin` and
/// `fmax`, which took a third of the time of the arm's collision checks there (the OMPL comparison's profile).
/// These compare and select; when `self` is NaN they return `other`, as std does.
pub trait MinMax: Copy {
    /// The smaller of `self` and `other` (`self.min(other)`).
    fn at_most(self, other: Self) -> Self;
    /// The larger of `self` and `other` (`self.max(other)`).
    fn at_least(self, other: Self) -> Self;
}

impl MinMax for Real {
    #[inline(always)]
    fn at_most(self, other: Real) -> Real {
        if self < other {
            self
        } else {
            other
        }
    }
    #[inline(always)]
    fn at_least(self, other: Real) -> Real {
        if self > other {
            self
        } else {
            other
        }
    }
}

/// Wrap an angle to `[-π, π)`.
///
/// Angles within a turn of the range are wrapped by one addition (exact there, and equal to what
/// `rem_euclid` gives): `rem_euclid` is a call to `fmod` in wasm.
#[inline]
pub fn wrap_angle(a: Real) -> Real {
    const TWO_PI: Real = 2.0 * PI;
    let s = a + PI;
    let r = if (0.0..TWO_PI).contains(&s) {
        s
    } else if (-TWO_PI..0.0).contains(&s) {
        s + TWO_PI
    } else {
        s.rem_euclid(TWO_PI)
    };
    let t = r - PI;
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

/// Sort a short list (at most a few hundred items: the keys an error names, an arm's link pairs, a
/// cell's neighbours) by insertion, in ascending order; equal items keep their order. The standard
/// library's sorts are some 4–10 kB of wasm each per item type and order, for lists this short.
pub fn sort_short<T: Ord>(v: &mut [T]) {
    for i in 1..v.len() {
        let mut j = i;
        while j > 0 && v[j - 1] > v[j] {
            v.swap(j - 1, j);
            j -= 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `sort_short` orders as the standard library's stable sort does, equal keys included.
    #[test]
    fn sort_short_is_a_stable_sort() {
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        for len in 0..60 {
            let items: Vec<(u8, usize)> = (0..len)
                .map(|i| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    ((x % 7) as u8, i)
                })
                .collect();
            // Ordered by the key only, so equal keys must keep their order.
            let mut keyed: Vec<Key> = items.iter().map(|&(k, i)| Key(k, i)).collect();
            sort_short(&mut keyed);
            let mut want = items.clone();
            want.sort_by_key(|&(k, _)| k);
            assert_eq!(keyed.iter().map(|k| (k.0, k.1)).collect::<Vec<_>>(), want, "{len} items");
        }
    }

    /// An item ordered by its first field only.
    #[derive(Debug)]
    struct Key(u8, usize);
    impl PartialEq for Key {
        fn eq(&self, o: &Self) -> bool {
            self.0 == o.0
        }
    }
    impl Eq for Key {}
    impl PartialOrd for Key {
        fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
            Some(self.cmp(o))
        }
    }
    impl Ord for Key {
        fn cmp(&self, o: &Self) -> std::cmp::Ordering {
            self.0.cmp(&o.0)
        }
    }

    /// The definition `wrap_angle` had before its fast paths.
    fn wrap_by_rem(a: Real) -> Real {
        let t = (a + PI).rem_euclid(2.0 * PI) - PI;
        if t >= PI {
            t - 2.0 * PI
        } else {
            t
        }
    }

    #[test]
    fn wrap_angle_is_bit_identical_to_rem_euclid() {
        let mut rng = crate::rng::Rng::new(7);
        let edges = [-3.0 * PI, -2.0 * PI - PI, -PI, -0.0, 0.0, PI, 2.0 * PI, 3.0 * PI, 1e-300, -1e-300, 40.0, -40.0];
        let near = edges
            .iter()
            .flat_map(|&e| [e, f64::from_bits(e.to_bits() + 1), f64::from_bits(e.to_bits().saturating_sub(1))])
            .filter(|a: &Real| a.is_finite());
        let random = (0..200_000).map(|_| rng.uniform(-30.0, 30.0));
        for a in near.chain(random) {
            let (w, r) = (wrap_angle(a), wrap_by_rem(a));
            assert_eq!(w.to_bits(), r.to_bits(), "wrap_angle({a:e}) = {w:e}, rem_euclid gives {r:e}");
            assert!((-PI..PI).contains(&w), "wrap_angle({a:e}) = {w:e} is outside [-π, π)");
        }
    }

    #[test]
    fn at_most_and_at_least_agree_with_min_and_max() {
        let vals = [-2.5, -0.0, 0.0, 1e-300, 3.0, Real::INFINITY, Real::NEG_INFINITY];
        for &a in &vals {
            for &b in &vals {
                assert_eq!(a.at_most(b), a.min(b), "{a} at_most {b}");
                assert_eq!(a.at_least(b), a.max(b), "{a} at_least {b}");
            }
        }
        // A NaN in `self` gives `other`, as std does (a NaN distance never wins a minimum).
        assert_eq!(Real::NAN.at_most(1.0), 1.0);
        assert_eq!(Real::NAN.at_least(1.0), 1.0);
    }
}

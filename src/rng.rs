//! The seeded, portable random number generator every planner uses.
//!
//! xoshiro256++ seeded through SplitMix64: a few lines of integer arithmetic, so the same seed gives
//! the same stream natively, in Node and in the browser, whatever crate versions are in use. (The
//! `rand` crate does not promise value stability of its distributions across versions; a planner's
//! tree must not change because a dependency was upgraded.) No planner code may use a thread or OS RNG.

use crate::math::Real;

/// A seeded xoshiro256++ generator.
#[derive(Clone, Debug)]
pub struct Rng {
    s: [u64; 4],
}

impl Rng {
    /// A generator whose whole stream is fixed by `seed`.
    pub fn new(seed: u64) -> Self {
        let mut z = seed;
        let mut next = || {
            z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut x = z;
            x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            x ^ (x >> 31)
        };
        Rng { s: [next(), next(), next(), next()] }
    }

    /// The next 64 random bits.
    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        let s = &mut self.s;
        let result = s[0].wrapping_add(s[3]).rotate_left(23).wrapping_add(s[0]);
        let t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = s[3].rotate_left(45);
        result
    }

    /// Uniform in `[0, 1)`, with 53 random bits.
    #[inline]
    pub fn uniform01(&mut self) -> Real {
        (self.next_u64() >> 11) as Real * (1.0 / (1u64 << 53) as Real)
    }

    /// Uniform in `[lo, hi)`.
    #[inline]
    pub fn uniform(&mut self, lo: Real, hi: Real) -> Real {
        lo + (hi - lo) * self.uniform01()
    }

    /// Uniform integer in `0..n` (`n > 0`), without modulo bias worth noticing for planner use.
    #[inline]
    pub fn below(&mut self, n: usize) -> usize {
        (((self.next_u64() >> 11) as u128 * n as u128) >> 53) as usize
    }

    /// A standard normal sample (Box–Muller; deterministic, uses two uniforms). `libm`'s log and
    /// cos, not std's: std's come from the platform's C library natively and from Rust's own port
    /// in wasm, and may differ in the last bit, so a Gaussian sampler's tree would differ.
    pub fn normal(&mut self) -> Real {
        let u1 = 1.0 - self.uniform01();
        let u2 = self.uniform01();
        (-2.0 * libm::log(u1)).sqrt() * libm::cos(2.0 * crate::math::PI * u2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_stream_and_known_values() {
        let mut a = Rng::new(7);
        let mut b = Rng::new(7);
        for _ in 0..100 {
            assert_eq!(a.next_u64(), b.next_u64());
        }
        // Pinned values: the stream must never change, or every saved figure changes with it.
        let mut r = Rng::new(1);
        let first: Vec<u64> = (0..3).map(|_| r.next_u64()).collect();
        assert_eq!(first, PINNED_SEED1);
    }

    // Computed independently (a Python transcription of xoshiro256++ and SplitMix64).
    const PINNED_SEED1: [u64; 3] = [14971601782005023387, 13781649495232077965, 1847458086238483744];

    #[test]
    fn uniform_in_range() {
        let mut r = Rng::new(3);
        for _ in 0..10_000 {
            let u = r.uniform(-2.0, 5.0);
            assert!((-2.0..5.0).contains(&u));
            assert!(r.below(7) < 7);
        }
    }
}

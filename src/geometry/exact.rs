//! Exact arithmetic on `f64` values, for the rare cases a floating-point filter cannot decide.
//!
//! Every finite `f64` is an integer times a power of two, so sums, differences and products of
//! them are exact in [`Dyadic`] (a sign, a magnitude in 64-bit limbs and a binary exponent). It is
//! slow (allocating, quadratic multiplication) and meant only as a fallback: the disc predicates
//! use it when their `f64` value lies within its error bound of the threshold, and the tests use
//! it as an independent oracle for [`orient`](super::segment::orient).

use std::cmp::Ordering;

/// An exact dyadic rational `±mag · 2^exp` (`mag` little-endian 64-bit limbs, no trailing zero
/// limbs; zero has no limbs).
#[derive(Clone, Debug)]
pub struct Dyadic {
    neg: bool,
    mag: Vec<u64>,
    exp: i32,
}

fn trim(m: &mut Vec<u64>) {
    while m.last() == Some(&0) {
        m.pop();
    }
}

fn cmp_mag(a: &[u64], b: &[u64]) -> Ordering {
    a.len().cmp(&b.len()).then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

fn add_mag(a: &[u64], b: &[u64]) -> Vec<u64> {
    let (long, short) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    let mut out = Vec::with_capacity(long.len() + 1);
    let mut carry = 0u64;
    for (i, &x) in long.iter().enumerate() {
        let y = short.get(i).copied().unwrap_or(0);
        let s = x as u128 + y as u128 + carry as u128;
        out.push(s as u64);
        carry = (s >> 64) as u64;
    }
    out.push(carry);
    trim(&mut out);
    out
}

/// `a − b`, given `a ≥ b`.
fn sub_mag(a: &[u64], b: &[u64]) -> Vec<u64> {
    let mut out = Vec::with_capacity(a.len());
    let mut borrow = 0u64;
    for (i, &x) in a.iter().enumerate() {
        let y = b.get(i).copied().unwrap_or(0);
        let (d1, o1) = x.overflowing_sub(y);
        let (d2, o2) = d1.overflowing_sub(borrow);
        out.push(d2);
        borrow = (o1 || o2) as u64;
    }
    debug_assert_eq!(borrow, 0);
    trim(&mut out);
    out
}

fn mul_mag(a: &[u64], b: &[u64]) -> Vec<u64> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![0u64; a.len() + b.len()];
    for (i, &x) in a.iter().enumerate() {
        let mut carry = 0u128;
        for (j, &y) in b.iter().enumerate() {
            let t = out[i + j] as u128 + x as u128 * y as u128 + carry;
            out[i + j] = t as u64;
            carry = t >> 64;
        }
        out[i + b.len()] = carry as u64;
    }
    trim(&mut out);
    out
}

fn shl_mag(a: &[u64], bits: u32) -> Vec<u64> {
    let (limbs, rem) = ((bits / 64) as usize, bits % 64);
    let mut out = vec![0u64; limbs];
    if rem == 0 {
        out.extend_from_slice(a);
    } else {
        let mut carry = 0u64;
        for &x in a {
            out.push((x << rem) | carry);
            carry = x >> (64 - rem);
        }
        out.push(carry);
    }
    trim(&mut out);
    out
}

impl Dyadic {
    /// The exact value of a finite `f64` (panics on NaN or an infinity).
    pub fn from_f64(v: f64) -> Dyadic {
        assert!(v.is_finite(), "Dyadic::from_f64({v})");
        let bits = v.to_bits();
        let neg = bits >> 63 == 1;
        let e = ((bits >> 52) & 0x7ff) as i32;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, exp) = if e == 0 { (frac, -1074) } else { (frac | (1u64 << 52), e - 1075) };
        let mut mag = vec![m];
        trim(&mut mag);
        Dyadic { neg, mag, exp }
    }

    /// -1, 0 or 1.
    pub fn signum(&self) -> i8 {
        if self.mag.is_empty() {
            0
        } else if self.neg {
            -1
        } else {
            1
        }
    }

    /// `self · o`, exactly.
    pub fn mul(&self, o: &Dyadic) -> Dyadic {
        Dyadic { neg: self.neg != o.neg, mag: mul_mag(&self.mag, &o.mag), exp: self.exp + o.exp }
    }

    /// `self + o`, exactly.
    pub fn add(&self, o: &Dyadic) -> Dyadic {
        if o.mag.is_empty() {
            return self.clone();
        }
        if self.mag.is_empty() {
            return o.clone();
        }
        let exp = self.exp.min(o.exp);
        let a = shl_mag(&self.mag, (self.exp - exp) as u32);
        let b = shl_mag(&o.mag, (o.exp - exp) as u32);
        let (neg, mag) = if self.neg == o.neg {
            (self.neg, add_mag(&a, &b))
        } else {
            match cmp_mag(&a, &b) {
                Ordering::Less => (o.neg, sub_mag(&b, &a)),
                _ => (self.neg, sub_mag(&a, &b)),
            }
        };
        Dyadic { neg, mag, exp }
    }

    /// `−self`.
    pub fn neg(&self) -> Dyadic {
        Dyadic { neg: !self.neg, ..self.clone() }
    }

    /// `self − o`, exactly.
    pub fn sub(&self, o: &Dyadic) -> Dyadic {
        self.add(&o.neg())
    }
}

/// The exact sign of `(b − a) × (c − a)` for `f64` points given as `(x, y)`.
pub fn orient_sign_exact(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> i8 {
    let d = |p: f64, q: f64| Dyadic::from_f64(p).sub(&Dyadic::from_f64(q));
    let (bx, by, cx, cy) = (d(b.0, a.0), d(b.1, a.1), d(c.0, a.0), d(c.1, a.1));
    bx.mul(&cy).sub(&by.mul(&cx)).signum()
}

/// The exact comparison of the squared distance from `p` to the closed segment `a b` with `r²`:
/// `Less`, `Equal` or `Greater`, for `f64` points given as `(x, y)` and `r ≥ 0`.
#[cold]
#[inline(never)]
pub fn segment_disc_cmp_exact(a: (f64, f64), b: (f64, f64), p: (f64, f64), r: f64) -> Ordering {
    let f = Dyadic::from_f64;
    let d = |u: f64, v: f64| f(u).sub(&f(v));
    let dot = |ux: &Dyadic, uy: &Dyadic, vx: &Dyadic, vy: &Dyadic| ux.mul(vx).add(&uy.mul(vy));
    let r2 = f(r).mul(&f(r));
    let sign_cmp = |x: &Dyadic| match x.signum() {
        -1 => Ordering::Less,
        0 => Ordering::Equal,
        _ => Ordering::Greater,
    };
    let (abx, aby) = (d(b.0, a.0), d(b.1, a.1));
    let (apx, apy) = (d(p.0, a.0), d(p.1, a.1));
    let l2 = dot(&abx, &aby, &abx, &aby);
    let t = dot(&apx, &apy, &abx, &aby);
    if l2.signum() == 0 || t.signum() <= 0 {
        // The nearest point is `a`.
        return sign_cmp(&dot(&apx, &apy, &apx, &apy).sub(&r2));
    }
    let (bpx, bpy) = (d(p.0, b.0), d(p.1, b.1));
    if t.sub(&l2).signum() >= 0 {
        // The nearest point is `b`.
        return sign_cmp(&dot(&bpx, &bpy, &bpx, &bpy).sub(&r2));
    }
    // The nearest point is inside the segment: distance² = cross² / l2; compare cross² with r²·l2.
    let cross = abx.mul(&apy).sub(&aby.mul(&apx));
    sign_cmp(&cross.mul(&cross).sub(&r2.mul(&l2)))
}

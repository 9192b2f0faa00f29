//! Sets of inspection points, one bit per point.

/// Points seen, one bit per inspection point.
pub(super) type Bits = [u64];

pub(super) fn count(b: &Bits) -> u32 {
    b.iter().map(|w| w.count_ones()).sum()
}

pub(super) fn has(b: &Bits, i: usize) -> bool {
    b[i / 64] >> (i % 64) & 1 == 1
}

pub(super) fn set(b: &mut Bits, i: usize) {
    b[i / 64] |= 1 << (i % 64);
}

/// Whether `a` ⊇ `b`.
pub(super) fn covers(a: &Bits, b: &Bits) -> bool {
    a.iter().zip(b).all(|(x, y)| y & !x == 0)
}

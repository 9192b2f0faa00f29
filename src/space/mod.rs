//! State spaces: the dimensions of a robot's configuration, its metric and its interpolation.
//!
//! The generic entry is [`StateSpace`]. Planners see states only as `&[Real]` slices of
//! [`StateSpace::dims`] numbers; the space says how far apart two of them are, how to move between
//! them, and which dimensions wrap around (angles).

use crate::math::{angle_diff, wrap_angle, MinMax, Real};
use crate::rng::Rng;

mod discrete;
mod gaussian;
pub(crate) use discrete::in_bisection_order;
pub use discrete::{check_discrete, Discrete};
pub use gaussian::gaussian_coordinates;
#[cfg(test)]
pub(crate) use gaussian::reflect;

/// One dimension of a state space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dim {
    /// Lower bound (for a wrapping dimension: −π).
    pub lo: Real,
    /// Upper bound (for a wrapping dimension: π).
    pub hi: Real,
    /// Whether the dimension is an angle that wraps around.
    pub wraps: bool,
}

/// How distances are measured.
#[derive(Clone, Debug, PartialEq)]
pub enum Metric {
    /// Euclidean over all dimensions (wrapped dimensions by their shortest angle).
    Euclidean,
    /// Euclidean with a weight per dimension: `sqrt(Σ (wᵢ·Δᵢ)²)`.
    Weighted {
        /// One weight per dimension.
        weights: Vec<Real>,
    },
    /// For a planar chain of relative joint angles: the sum over links of the distance moved by
    /// each link's end point (OMPL's kinematic chain metric).
    ChainSum {
        /// Link lengths.
        links: Vec<Real>,
    },
    /// For a planar chain: the largest distance any joint point (link end) moves.
    ChainMax {
        /// Link lengths.
        links: Vec<Real>,
    },
    /// For a planar chain: the Euclidean norm of the difference of the stacked link-end points,
    /// `sqrt(Σ |Δpₖ|²)` (report 004's distance: the norm of the difference of the two n×2
    /// forward-kinematics arrays).
    ChainNorm {
        /// Link lengths.
        links: Vec<Real>,
    },
    /// `|Δ(x, y)| + weight · |Δθ|` for states `[x, y, θ]` (rigid bodies).
    TranslationRotation {
        /// Weight of the rotation, usually the body's radius.
        weight: Real,
    },
}

/// A state space: its dimensions and metric.
#[derive(Clone, Debug, PartialEq)]
pub struct StateSpace {
    /// The dimensions, in state order.
    pub dims: Vec<Dim>,
    /// The metric.
    pub metric: Metric,
}

impl StateSpace {
    /// The number of numbers in a state.
    #[inline]
    pub fn dim_count(&self) -> usize {
        self.dims.len()
    }

    /// Write `b − a` per dimension into `out` (the shortest way round for wrapping dimensions):
    /// [`interpolate`](Self::interpolate) moves along it.
    pub fn difference(&self, a: &[Real], b: &[Real], out: &mut [Real]) {
        for (((o, x), y), d) in out.iter_mut().zip(a).zip(b).zip(&self.dims) {
            *o = Self::delta_in(d, *x, *y);
        }
    }

    /// Per-dimension difference `b − a` (the shortest way round for wrapping dimensions).
    #[inline]
    fn delta(&self, i: usize, a: Real, b: Real) -> Real {
        Self::delta_in(&self.dims[i], a, b)
    }

    /// `b − a` along dimension `d`.
    #[inline(always)]
    fn delta_in(d: &Dim, a: Real, b: Real) -> Real {
        if d.wraps {
            angle_diff(a, b)
        } else {
            b - a
        }
    }

    /// The distance between two states.
    #[inline(always)]
    pub fn distance(&self, a: &[Real], b: &[Real]) -> Real {
        match &self.metric {
            // Zipped rather than indexed: no bounds checks in the nearest-neighbour hot loop.
            Metric::Euclidean => a
                .iter()
                .zip(b)
                .zip(&self.dims)
                .map(|((x, y), d)| Self::delta_in(d, *x, *y).powi(2))
                .sum::<Real>()
                .sqrt(),
            Metric::Weighted { weights } => {
                (0..a.len()).map(|i| (weights[i] * self.delta(i, a[i], b[i])).powi(2)).sum::<Real>().sqrt()
            }
            Metric::TranslationRotation { weight } => {
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                (dx * dx + dy * dy).sqrt() + weight * angle_diff(a[2], b[2]).abs()
            }
            Metric::ChainSum { links } => chain_moves(links, a, b).sum(),
            Metric::ChainMax { links } => chain_moves(links, a, b).fold(0.0, Real::max),
            Metric::ChainNorm { links } => chain_moves(links, a, b).map(|m| m * m).sum::<Real>().sqrt(),
        }
    }

    /// Whether the metric is Euclidean and no dimension wraps: then [`plain_distance`] and
    /// [`plain_box_lower_bound`] give [`distance`](Self::distance) and
    /// [`box_lower_bound`](Self::box_lower_bound), bit for bit, without asking each dimension.
    pub fn plain_euclidean(&self) -> bool {
        matches!(self.metric, Metric::Euclidean) && !self.dims.iter().any(|d| d.wraps)
    }

    /// Numbers in a state's embedding (see [`embed`](Self::embed)): the chain metrics' link-end
    /// points; 0 for metrics computed from the states directly.
    pub fn embedding_len(&self) -> usize {
        match &self.metric {
            Metric::ChainSum { links } | Metric::ChainMax { links } | Metric::ChainNorm { links } => 2 * links.len(),
            _ => 0,
        }
    }

    /// Write `q`'s embedding into `out`: for a chain metric, the link-end points relative to the
    /// base, computed exactly as [`chain_moves`] does, so that
    /// [`embedded_distance`](Self::embedded_distance) of two embeddings equals
    /// [`distance`](Self::distance) of the states bit for bit. Nearest-neighbour search embeds each
    /// stored state once instead of redoing its forward kinematics at every comparison.
    pub fn embed(&self, q: &[Real], out: &mut [Real]) {
        if let Metric::ChainSum { links } | Metric::ChainMax { links } | Metric::ChainNorm { links } = &self.metric {
            let (mut t, mut p) = (0.0, (0.0, 0.0));
            for (i, l) in links.iter().enumerate() {
                t += q[i];
                let (s, c) = libm::sincos(t);
                p = (p.0 + l * c, p.1 + l * s);
                out[2 * i] = p.0;
                out[2 * i + 1] = p.1;
            }
        }
    }

    /// The distance between two states from their embeddings (chain metrics only).
    #[inline]
    pub fn embedded_distance(&self, ea: &[Real], eb: &[Real]) -> Real {
        let moves = (0..ea.len() / 2)
            .map(|k| ((ea[2 * k] - eb[2 * k]).powi(2) + (ea[2 * k + 1] - eb[2 * k + 1]).powi(2)).sqrt());
        match &self.metric {
            Metric::ChainMax { .. } => moves.fold(0.0, Real::max),
            Metric::ChainNorm { .. } => moves.map(|m| m * m).sum::<Real>().sqrt(),
            _ => moves.sum(),
        }
    }

    /// A lower bound on the distance from the embedding `eq` to any embedding in the box
    /// `lo..=hi` (chain metrics only): each link end moves at least its 2-D distance to its part
    /// of the box. Computed in the same order as [`embedded_distance`](Self::embedded_distance),
    /// so in floating point too it never exceeds the distance to a point of the box.
    #[inline(always)]
    pub fn embedded_box_lower_bound(&self, eq: &[Real], lo: &[Real], hi: &[Real]) -> Real {
        let gap = |v: Real, l: Real, h: Real| {
            if v < l {
                l - v
            } else if v > h {
                v - h
            } else {
                0.0
            }
        };
        let moves = eq
            .chunks_exact(2)
            .zip(lo.chunks_exact(2))
            .zip(hi.chunks_exact(2))
            .map(|((e, l), h)| (gap(e[0], l[0], h[0]).powi(2) + gap(e[1], l[1], h[1]).powi(2)).sqrt());
        match &self.metric {
            Metric::ChainMax { .. } => moves.fold(0.0, Real::max),
            Metric::ChainNorm { .. } => moves.map(|m| m * m).sum::<Real>().sqrt(),
            _ => moves.sum(),
        }
    }

    /// Write into `out` the state a fraction `t` of the way from `a` to `b`.
    #[inline]
    pub fn interpolate(&self, a: &[Real], b: &[Real], t: Real, out: &mut [Real]) {
        for (((o, x), y), d) in out.iter_mut().zip(a).zip(b).zip(&self.dims) {
            let v = x + t * Self::delta_in(d, *x, *y);
            *o = if d.wraps { wrap_angle(v) } else { v };
        }
    }

    /// Write a uniform random state into `out`.
    pub fn sample_uniform(&self, rng: &mut Rng, out: &mut [Real]) {
        for (o, d) in out.iter_mut().zip(&self.dims) {
            *o = rng.uniform(d.lo, d.hi);
        }
    }

    /// Bring a state into canonical form (wrap angles).
    pub fn enforce(&self, q: &mut [Real]) {
        for (v, d) in q.iter_mut().zip(&self.dims) {
            if d.wraps {
                *v = wrap_angle(*v);
            }
        }
    }

    /// The largest distance between two states of the space (OMPL's `getMaximumExtent`, used to
    /// derive the default step range as in OMPL: 0.2 × extent).
    pub fn max_extent(&self) -> Real {
        let ext = |d: &Dim| if d.wraps { std::f64::consts::PI } else { d.hi - d.lo };
        let reach = |links: &[Real], k: usize| -> Real { links[..=k].iter().sum() };
        match &self.metric {
            Metric::Euclidean => self.dims.iter().map(|d| ext(d).powi(2)).sum::<Real>().sqrt(),
            Metric::Weighted { weights } => {
                self.dims.iter().zip(weights).map(|(d, w)| (w * ext(d)).powi(2)).sum::<Real>().sqrt()
            }
            Metric::ChainSum { links } => (0..links.len()).map(|k| 2.0 * reach(links, k)).sum(),
            Metric::ChainMax { links } => 2.0 * links.iter().sum::<Real>(),
            Metric::ChainNorm { links } => {
                (0..links.len()).map(|k| (2.0 * reach(links, k)).powi(2)).sum::<Real>().sqrt()
            }
            Metric::TranslationRotation { weight } => {
                (ext(&self.dims[0]).powi(2) + ext(&self.dims[1]).powi(2)).sqrt() + weight * ext(&self.dims[2])
            }
        }
    }

    /// A lower bound on the distance from `q` to any state in the box `lo..=hi` (per dimension,
    /// with `lo`, `hi` canonical). Used by the nearest-neighbour tree to prune.
    #[inline(always)]
    pub fn box_lower_bound(&self, q: &[Real], lo: &[Real], hi: &[Real]) -> Real {
        #[inline(always)]
        fn gap_in(d: &Dim, v: Real, lo: Real, hi: Real) -> Real {
            if d.wraps && !(v >= lo && v <= hi) {
                angle_diff(v, lo).abs().at_most(angle_diff(v, hi).abs())
            } else {
                gap_outside(v, lo, hi)
            }
        }
        let gap = |i: usize| gap_in(&self.dims[i], q[i], lo[i], hi[i]);
        match &self.metric {
            Metric::Euclidean => q
                .iter()
                .zip(lo)
                .zip(hi)
                .zip(&self.dims)
                .map(|(((v, l), h), d)| gap_in(d, *v, *l, *h).powi(2))
                .sum::<Real>()
                .sqrt(),
            Metric::Weighted { weights } => (0..q.len()).map(|i| (weights[i] * gap(i)).powi(2)).sum::<Real>().sqrt(),
            Metric::TranslationRotation { weight } => (gap(0).powi(2) + gap(1).powi(2)).sqrt() + weight * gap(2),
            // A box of joint angles bounds a chain's moves poorly: the tree bounds the chain metrics
            // over link-end boxes instead (`embedded_box_lower_bound`).
            Metric::ChainSum { .. } | Metric::ChainMax { .. } | Metric::ChainNorm { .. } => 0.0,
        }
    }
}

/// For each link of a planar chain (relative angles, base at the origin), the distance its end
/// point moves between configurations `a` and `b`.
#[inline]
pub fn chain_moves<'a>(links: &'a [Real], a: &'a [Real], b: &'a [Real]) -> impl Iterator<Item = Real> + 'a {
    let (mut ta, mut tb) = (0.0, 0.0);
    let (mut pa, mut pb) = ((0.0, 0.0), (0.0, 0.0));
    links.iter().enumerate().map(move |(i, l)| {
        ta += a[i];
        tb += b[i];
        let ((sa, ca), (sb, cb)) = (libm::sincos(ta), libm::sincos(tb));
        pa = (pa.0 + l * ca, pa.1 + l * sa);
        pb = (pb.0 + l * cb, pb.1 + l * sb);
        ((pa.0 - pb.0).powi(2) + (pa.1 - pb.1).powi(2)).sqrt()
    })
}

/// The Euclidean distance between `a` and `b` in a space whose dimensions do not wrap
/// ([`StateSpace::plain_euclidean`]): the same operations in the same order as
/// [`StateSpace::distance`], so the same bits. The nearest-neighbour search's inner loop.
#[inline(always)]
pub fn plain_distance(a: &[Real], b: &[Real]) -> Real {
    plain_distance_sq(a, b).sqrt()
}

/// The sum under [`plain_distance`]'s square root (the squared distance), the same bits.
#[inline(always)]
pub fn plain_distance_sq(a: &[Real], b: &[Real]) -> Real {
    a.iter().zip(b).map(|(x, y)| (y - x).powi(2)).sum::<Real>()
}

/// [`StateSpace::box_lower_bound`] in a space whose dimensions do not wrap, the same bits.
#[inline(always)]
pub fn plain_box_lower_bound(q: &[Real], lo: &[Real], hi: &[Real]) -> Real {
    plain_box_lower_bound_sq(q, lo, hi).sqrt()
}

/// The sum under [`plain_box_lower_bound`]'s square root, the same bits.
#[inline(always)]
pub fn plain_box_lower_bound_sq(q: &[Real], lo: &[Real], hi: &[Real]) -> Real {
    q.iter().zip(lo).zip(hi).map(|((v, l), h)| gap_outside(*v, *l, *h).powi(2)).sum::<Real>()
}

/// Whether the square root of `x` certainly exceeds the square root of `y` once both are
/// rounded: `x` is past `y` by far more than the four units in the last place two correctly
/// rounded roots can close (and past 1e-300, so that a subnormal `y`'s coarse spacing does not
/// matter). A `false` decides nothing: the caller takes the roots and compares them.
#[inline(always)]
pub fn root_certainly_above(x: Real, y: Real) -> bool {
    x > y * (1.0 + 1e-12) + 1e-300
}

/// How far `v` lies outside `[lo, hi]` on a line that does not wrap (0 inside).
#[inline(always)]
fn gap_outside(v: Real, lo: Real, hi: Real) -> Real {
    if v >= lo && v <= hi {
        0.0
    } else if v < lo {
        lo - v
    } else {
        v - hi
    }
}

#[cfg(test)]
mod tests;

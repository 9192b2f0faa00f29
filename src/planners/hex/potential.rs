//! The potential of a cell and the region of influence that decides which obstacles count.
//!
//! Seen from the robot's current position `p`, a candidate cell centred at `c` has the potential
//!
//! ```text
//! P(c) = Σ_i k1 / r_i²  −  C · (1 − k2 · α)
//! ```
//!
//! where `r_i` is the distance from `c` to obstacle `i`, the sum runs over the obstacles in the
//! region of influence, and `α ∈ [0, π]` is the angle between the step `p → c` and the direction
//! from `p` to the goal. The first term repels from obstacles; the second favours the cell that
//! keeps the robot heading for the goal. The report's modified potential (its Q5) replaces the
//! term of one chosen obstacle `j` by the stronger `k3 / r_j²` on one side of it (below its lower
//! edge, for the report's horizontal obstacle), so the field no longer leads into the dead end
//! that obstacle closes.
//!
//! The region of influence is a circle about the start. When the search is stuck it grows (the
//! report's Q2): to `2R`, or to `d_maxOb + t` if that is smaller, `d_maxOb` being the farthest
//! obstacle vertex from the centre. Once it has that radius, or covers the whole map, every
//! obstacle counts and a ring of width `t` around them all is inside: if the search is still
//! stuck, there is no path by this method.

use crate::geometry::{Aabb, Shape};
use crate::math::{Real, Vec2, PI};

/// The circle of obstacles that count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region {
    /// Its centre (the start).
    pub centre: Vec2,
    /// Its radius.
    pub radius: Real,
    /// The radius it grows to at most: `d_maxOb + t`.
    pub limit: Real,
    /// The map, whose corners all inside the region also end the growth.
    pub bounds: Aabb,
}

/// The farthest point of any obstacle from `o` (a vertex, or a disc's far side): `d_maxOb`.
pub fn d_max_ob(o: Vec2, obstacles: &[Shape]) -> Real {
    let far = |p: Vec2| (p - o).norm();
    obstacles
        .iter()
        .map(|s| match s {
            Shape::Rect(r) => [r.min, Vec2::new(r.max.x, r.min.y), r.max, Vec2::new(r.min.x, r.max.y)]
                .into_iter()
                .map(far)
                .fold(0.0, Real::max),
            Shape::Polygon(p) => p.iter().map(|&v| far(v)).fold(0.0, Real::max),
            Shape::Segment(a, b) => far(*a).max(far(*b)),
            Shape::Circle(c, r) => far(*c) + r,
        })
        .fold(0.0, Real::max)
}

impl Region {
    /// A region about `centre` of `radius` (capped at its limit) among `obstacles`, for a robot of
    /// diagonal `t` going to `goal`. The limit is `d_maxOb + t`, or the goal's distance plus `t`
    /// if the goal is farther than every obstacle (the report's rule takes the target to lie
    /// among the obstacles; a region that cannot reach the goal could never succeed).
    pub fn new(centre: Vec2, radius: Real, obstacles: &[Shape], t: Real, bounds: Aabb, goal: Vec2) -> Region {
        let limit = d_max_ob(centre, obstacles).max((goal - centre).norm()) + t;
        Region { centre, radius: radius.min(limit).max(0.0), limit, bounds }
    }
    /// Whether the region covers the whole map.
    pub fn covers_map(&self) -> bool {
        let b = self.bounds;
        [b.min, Vec2::new(b.max.x, b.min.y), b.max, Vec2::new(b.min.x, b.max.y)]
            .iter()
            .all(|&p| (p - self.centre).norm() <= self.radius)
    }
    /// Whether it can grow no further: it has reached `d_maxOb + t`, or covers the map.
    pub fn is_final(&self) -> bool {
        self.radius >= self.limit || self.covers_map()
    }
    /// The next region after a failed search: radius `min(2R, d_maxOb + t)`; `None` when it is
    /// final ("no path").
    pub fn grown(&self) -> Option<Region> {
        if self.is_final() {
            return None;
        }
        // A region of radius 0 (start on top of every obstacle's farthest point) still grows.
        let next = if self.radius > 0.0 { 2.0 * self.radius } else { self.limit };
        Some(Region { radius: next.min(self.limit), ..*self })
    }
    /// Whether point `p` is inside.
    pub fn holds(&self, p: Vec2) -> bool {
        (p - self.centre).norm() <= self.radius
    }
    /// Whether an obstacle counts: some point of it lies inside.
    pub fn counts(&self, s: &Shape) -> bool {
        s.distance_to_segment(self.centre, self.centre, self.radius + 1.0) <= self.radius
    }
}

/// Which side of the trapping obstacle gets the stronger term.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Below its lower edge (the report's case).
    Below,
    /// Above its upper edge.
    Above,
    /// Left of its left edge.
    Left,
    /// Right of its right edge.
    Right,
}

impl Side {
    /// Whether `p` lies on this side of the box `b`.
    pub fn holds(self, b: &Aabb, p: Vec2) -> bool {
        match self {
            Side::Below => p.y < b.min.y,
            Side::Above => p.y > b.max.y,
            Side::Left => p.x < b.min.x,
            Side::Right => p.x > b.max.x,
        }
    }
}

/// The potential's constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Weights {
    /// Repulsion gain `k1`.
    pub k1: Real,
    /// Heading weight `k2` (1/π: the goal term falls from `−C` to 0 as α goes 0 → π).
    pub k2: Real,
    /// Attraction `C`.
    pub c: Real,
    /// The trap term's gain `k3` (0: the plain potential).
    pub k3: Real,
    /// The trapping obstacle and the side where `k3` replaces `k1`.
    pub trap: Option<(usize, Side)>,
}

/// A candidate's potential, term by term (what the page shows on hover).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Terms {
    /// `Σ k1 / r_i²` over the counted obstacles (the trap obstacle's term excluded when `k3` applies).
    pub repulsion: Real,
    /// `k3 / r_j²` when it applies, else 0.
    pub trap: Real,
    /// `−C (1 − k2 α)`.
    pub goal: Real,
    /// α, radians.
    pub alpha: Real,
    /// The sum.
    pub total: Real,
}

/// The angle between `u` and `v` in `[0, π]` (0 if either is zero).
pub fn angle_between(u: Vec2, v: Vec2) -> Real {
    if u.norm_squared() == 0.0 || v.norm_squared() == 0.0 {
        return 0.0;
    }
    libm::atan2(u.perp(&v).abs(), u.dot(&v)).clamp(0.0, PI)
}

/// The obstacle part of the potential at `c`: `(repulsion, trap term)`. `counted[i]`: whether
/// obstacle `i` is in the region of influence.
pub fn obstacle_terms(w: &Weights, obstacles: &[Shape], counted: &[bool], c: Vec2) -> (Real, Real) {
    let (mut rep, mut trap) = (0.0, 0.0);
    let mut tests = 0;
    for (i, s) in obstacles.iter().enumerate() {
        if !counted[i] {
            continue;
        }
        tests += 1;
        let r = s.distance_to_segment(c, c, Real::INFINITY).max(1e-9);
        match w.trap {
            Some((j, side)) if j == i && w.k3 > 0.0 && side.holds(&s.aabb(), c) => trap += w.k3 / (r * r),
            _ => rep += w.k1 / (r * r),
        }
    }
    // Exact distances, counted as the workspace's queries count theirs (the work a run does),
    // and the scan over every obstacle as one test per 16.
    crate::geometry::add_tests(tests + obstacles.len() as u64 / 16);
    (rep, trap)
}

/// The potential of the cell centred at `c` seen from the robot at `p`, with goal `g`.
pub fn potential(w: &Weights, obstacles: &[Shape], counted: &[bool], p: Vec2, c: Vec2, g: Vec2) -> Terms {
    let (repulsion, trap) = obstacle_terms(w, obstacles, counted, c);
    let alpha = angle_between(c - p, g - p);
    let goal = -w.c * (1.0 - w.k2 * alpha);
    Terms { repulsion, trap, goal, alpha, total: repulsion + trap + goal }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Aabb {
        Aabb { min: Vec2::new(0.0, 0.0), max: Vec2::new(1.0, 1.0) }
    }
    fn rect(x0: Real, y0: Real, x1: Real, y1: Real) -> Shape {
        Shape::Rect(Aabb { min: Vec2::new(x0, y0), max: Vec2::new(x1, y1) })
    }

    #[test]
    fn d_max_ob_is_the_farthest_vertex() {
        let o = Vec2::new(0.0, 0.0);
        let obs = [
            rect(0.1, 0.1, 0.2, 0.3),
            Shape::Circle(Vec2::new(0.5, 0.0), 0.1),
            Shape::Segment(Vec2::new(0.0, 0.2), Vec2::new(0.0, 0.55)),
        ];
        assert!((d_max_ob(o, &obs) - 0.6).abs() < 1e-12);
        assert_eq!(d_max_ob(o, &[]), 0.0);
    }

    #[test]
    fn the_region_doubles_then_stops_at_d_max_ob_plus_t() {
        // Obstacles up to 0.5 from the centre, t = 0.1: limit 0.6. A big map, so it is not covered.
        let big = Aabb { min: Vec2::new(-5.0, -5.0), max: Vec2::new(5.0, 5.0) };
        let obs = [rect(0.3, -0.1, 0.4, 0.3)]; // farthest vertex (0.4, 0.3): 0.5
        let r0 = Region::new(Vec2::new(0.0, 0.0), 0.1, &obs, 0.1, big, Vec2::new(0.2, 0.2));
        assert!((r0.limit - 0.6).abs() < 1e-12);
        let r1 = r0.grown().expect("grows");
        assert!((r1.radius - 0.2).abs() < 1e-12, "doubled: {}", r1.radius);
        let r2 = r1.grown().expect("grows");
        assert!((r2.radius - 0.4).abs() < 1e-12, "doubled: {}", r2.radius);
        // 2R = 0.8 > 0.6: grown to d_maxOb + t exactly, and no further.
        let r3 = r2.grown().expect("grows");
        assert!((r3.radius - 0.6).abs() < 1e-12, "capped: {}", r3.radius);
        assert!(r3.is_final());
        assert_eq!(r3.grown(), None, "no path once the region is at d_maxOb + t");
    }

    #[test]
    fn the_region_reaches_a_goal_beyond_every_obstacle() {
        let obs = [rect(0.1, 0.0, 0.2, 0.1)];
        let r = Region::new(Vec2::new(0.0, 0.0), 0.1, &obs, 0.05, unit(), Vec2::new(0.9, 0.0));
        assert!((r.limit - 0.95).abs() < 1e-12, "{}", r.limit);
    }

    #[test]
    fn the_region_stops_when_it_covers_the_map() {
        // Centre at the map's middle; corners at √0.5 ≈ 0.707; obstacles far smaller.
        let obs = [rect(0.45, 0.45, 0.46, 0.46)];
        let r = Region { centre: Vec2::new(0.5, 0.5), radius: 0.75, limit: 10.0, bounds: unit() };
        assert!(r.covers_map());
        assert_eq!(r.grown(), None);
        let r = Region::new(Vec2::new(0.5, 0.5), 0.01, &obs, 0.0, unit(), Vec2::new(0.6, 0.6));
        assert!(!r.is_final());
    }

    #[test]
    fn a_region_starts_capped_at_its_limit() {
        let r = Region::new(Vec2::new(0.0, 0.0), 5.0, &[rect(0.1, 0.0, 0.2, 0.1)], 0.05, unit(), Vec2::new(0.1, 0.1));
        assert!((r.radius - r.limit).abs() < 1e-12);
        assert!(r.is_final());
    }

    #[test]
    fn obstacles_count_when_any_part_is_inside() {
        let r = Region { centre: Vec2::new(0.0, 0.0), radius: 0.3, limit: 1.0, bounds: unit() };
        assert!(r.counts(&rect(0.25, -0.1, 0.9, 0.1)));
        assert!(!r.counts(&rect(0.35, -0.1, 0.9, 0.1)));
        assert!(r.counts(&Shape::Circle(Vec2::new(0.0, 0.5), 0.21)));
    }

    #[test]
    fn the_potential_adds_its_terms() {
        let w = Weights { k1: 0.01, k2: 1.0 / PI, c: 1.0, k3: 0.0, trap: None };
        let obs = [rect(0.5, 0.0, 0.6, 1.0)];
        // Cell 0.1 left of the wall, stepping straight at the goal: α = 0.
        let t = potential(&w, &obs, &[true], Vec2::new(0.3, 0.5), Vec2::new(0.4, 0.5), Vec2::new(0.9, 0.5));
        assert!((t.repulsion - 1.0).abs() < 1e-9, "{t:?}");
        assert!((t.goal + 1.0).abs() < 1e-12 && t.alpha == 0.0);
        assert!((t.total - 0.0).abs() < 1e-9);
        // Stepping away from the goal: α = π, the goal term vanishes.
        let t = potential(&w, &obs, &[true], Vec2::new(0.3, 0.5), Vec2::new(0.2, 0.5), Vec2::new(0.9, 0.5));
        assert!((t.alpha - PI).abs() < 1e-12 && t.goal.abs() < 1e-12);
        // An obstacle outside the region does not count.
        let t = potential(&w, &obs, &[false], Vec2::new(0.3, 0.5), Vec2::new(0.4, 0.5), Vec2::new(0.9, 0.5));
        assert_eq!(t.repulsion, 0.0);
    }

    #[test]
    fn the_trap_term_replaces_k1_on_its_side_only() {
        let w = Weights { k1: 0.01, k2: 0.0, c: 0.0, k3: 0.04, trap: Some((0, Side::Below)) };
        let obs = [rect(0.2, 0.5, 0.8, 0.6)];
        let below = obstacle_terms(&w, &obs, &[true], Vec2::new(0.5, 0.4));
        assert!(below.0 == 0.0 && (below.1 - 4.0).abs() < 1e-9, "{below:?}");
        let above = obstacle_terms(&w, &obs, &[true], Vec2::new(0.5, 0.7));
        assert!((above.0 - 1.0).abs() < 1e-9 && above.1 == 0.0, "{above:?}");
        // k3 = 0 is the plain potential.
        let plain = obstacle_terms(&Weights { k3: 0.0, ..w }, &obs, &[true], Vec2::new(0.5, 0.4));
        assert!((plain.0 - 1.0).abs() < 1e-9 && plain.1 == 0.0);
    }
}

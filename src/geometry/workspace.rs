use super::grid::{Grid, Query};
use super::{Aabb, Shape};
use crate::math::{MinMax, Real, Vec2};
use parry2d_f64::bounding_volume::Aabb as ParryAabb;
use parry2d_f64::math::Vector;
use parry2d_f64::partitioning::{Bvh, BvhBuildStrategy, BvhNode};
use std::cell::{Cell, OnceCell};

thread_local! {
    /// Exact tests done by workspace queries since [`take_tests`] was last called: how long a
    /// time-bounded loop has been working (a query among many obstacles weighs more than one).
    static TESTS: Cell<u64> = const { Cell::new(0) };
}

/// The exact tests workspace queries did since the last call (see `SpaceInfo::tick`).
pub fn take_tests() -> u64 {
    TESTS.with(|t| t.replace(0))
}

/// Count `n` exact tests (workspace queries do; so do loops of exact tests over the obstacles
/// outside them, like the hexagonal decomposition's potential).
#[inline]
pub(crate) fn add_tests(n: u64) {
    TESTS.with(|t| t.set(t.get() + n));
}

/// From this many obstacles on, queries go through a bounding-volume hierarchy (parry's `Bvh`)
/// rather than a scan of every obstacle's box. Below it, the scan is as fast.
pub const BVH_FROM: usize = 32;

/// From this many obstacles on, a grid of candidate lists stands in front of the hierarchy (see
/// `geometry/grid.rs`). Below it the hierarchy is shallow, and alone it is as fast or faster for
/// segments and bodies (`planarium scaling --sizes 100,1000`).
pub const GRID_FROM: usize = 1000;

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
    /// The scenario's `touching_allowed`: obstacles are open sets, so touching their boundary is
    /// allowed. Only [`Workspace::first_obstacle_on_segment`] reads it; robots made of segments
    /// (arms) use that.
    pub touching_allowed: bool,
    /// The obstacles, in scenario order.
    pub obstacles: Vec<Shape>,
    /// The pixel grid of the occupancy map the scenario came from (its `map` block): `(origin,
    /// side)`. Only grid-search reads it (its default cell, aligned with the pixels).
    pub map_grid: Option<(Vec2, Real)>,
    /// The 3-D obstacles (`obstacles3d`), in scenario order, for a spatial arm; empty otherwise.
    pub solids: Vec<super::solid::Solid>,
    boxes: Vec<Aabb>,
    bvh: Option<Bvh>,
    /// With the hierarchy, a grid of candidate lists in front of it (see `geometry/grid.rs`).
    grid: Option<Grid>,
}

/// Whether a hierarchy node's box meets `bb` (closed boxes: touching counts, as [`Aabb::intersects`]).
#[inline]
fn node_meets(node: &BvhNode, bb: &Aabb) -> bool {
    let (lo, hi) = (node.mins(), node.maxs());
    lo.x <= bb.max.x && bb.min.x <= hi.x && lo.y <= bb.max.y && bb.min.y <= hi.y
}

/// A query's shape for pruning the hierarchy: its box, and the axes (normals) along which it may be
/// separated from a node's box (the segment's normal; a convex polygon's edge normals), each with
/// the shape's extent along it.
struct Probe {
    bb: Aabb,
    axes: [(Vec2, Real, Real); 8],
    n: usize,
    /// Whether the axes are a convex polygon's edge normals (the polygon is where the shape's
    /// extents along them all hold), set by [`Probe::with_holds`].
    convex: bool,
}

impl Probe {
    /// The probe of a query's shape, its box `bb`. (Inlined: built in place, as a segment's
    /// probe was before the grid; a polygon's is a call, as it was.)
    #[inline(always)]
    fn of(q: &Query, bb: Aabb) -> Probe {
        match *q {
            Query::Point(_) => Probe::of_box(bb),
            Query::Segment(a, b) => Probe::of_segment(a, b),
            Query::Polygon(poly) => Probe::of_polygon(poly),
        }
    }
    /// Only the box.
    fn of_box(bb: Aabb) -> Probe {
        Probe { bb, axes: [(Vec2::default(), 0.0, 0.0); 8], n: 0, convex: false }
    }
    /// A segment: its box and its normal.
    fn of_segment(a: Vec2, b: Vec2) -> Probe {
        let mut p = Probe::of_box(Aabb::of_points(&[a, b]));
        let n = Vec2::new(a.y - b.y, b.x - a.x);
        let d = n.x * a.x + n.y * a.y;
        p.axes[0] = (n, d, d);
        p.n = 1;
        p
    }
    /// A polygon: its box, and its edge normals when it is convex with at most 8 edges.
    #[inline(never)]
    fn of_polygon(poly: &[Vec2]) -> Probe {
        let mut p = Probe::of_box(Aabb::of_points(poly));
        let m = poly.len();
        if !(3..=8).contains(&m) {
            return p;
        }
        let turn = |i: usize| {
            let (a, b, c) = (poly[i], poly[(i + 1) % m], poly[(i + 2) % m]);
            (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x)
        };
        let first = turn(0);
        if first == 0.0 || (1..m).any(|i| turn(i) * first <= 0.0) {
            return p;
        }
        for i in 0..m {
            let (a, b) = (poly[i], poly[(i + 1) % m]);
            let n = Vec2::new(a.y - b.y, b.x - a.x);
            let (mut lo, mut hi) = (Real::INFINITY, Real::NEG_INFINITY);
            for q in poly {
                let d = n.x * q.x + n.y * q.y;
                lo = lo.at_most(d);
                hi = hi.at_least(d);
            }
            p.axes[i] = (n, lo, hi);
        }
        p.n = m;
        p
    }
    /// The probe, told whether it may answer [`Probe::holds`]: its axes are a convex polygon's, and
    /// the polygon is no star (its edges turn once around: their y components change sign twice).
    fn with_holds(mut self, q: &Query) -> Probe {
        if let Query::Polygon(poly) = *q {
            let m = poly.len();
            let dy = |i: usize| poly[if i + 1 == m { 0 } else { i + 1 }].y - poly[i].y;
            let mut ups = (0..m).map(dy).filter(|&d| d != 0.0).map(|d| d > 0.0);
            let start = ups.next();
            let (mut last, mut flips) = (start, 0);
            for up in ups {
                flips += usize::from(last != Some(up));
                last = Some(up);
            }
            self.convex = self.n == m && flips + usize::from(last != start) == 2;
        }
        self
    }
    /// Whether the box `lo .. hi` lies inside the shape, a convex polygon: never `true` for one that
    /// does not (the same margin, the other way). An obstacle has a point in its box (a corner, a
    /// vertex, an end, the centre), so one whose box the polygon holds meets the polygon: what the
    /// exact test would answer, without its cost (among many small obstacles, a body
    /// often covers some whole).
    #[inline]
    fn holds(&self, lo: Vec2, hi: Vec2) -> bool {
        if !self.convex {
            return false;
        }
        self.box_on_axes(lo, hi).all(|(d, r, dlo, dhi, margin)| d - r >= dlo + margin && d + r <= dhi - margin)
    }
    /// Whether the box `lo .. hi` may meet the shape: never `false` for one that does (a margin
    /// far above rounding keeps the test conservative; the exact test decides).
    #[inline]
    fn may_meet(&self, lo: Vec2, hi: Vec2) -> bool {
        let bb = &self.bb;
        if !(lo.x <= bb.max.x && bb.min.x <= hi.x && lo.y <= bb.max.y && bb.min.y <= hi.y) {
            return false;
        }
        if self.n == 0 {
            return true;
        }
        self.box_on_axes(lo, hi).all(|(d, r, dlo, dhi, margin)| d + r >= dlo - margin && d - r <= dhi + margin)
    }
    /// The box `lo .. hi` on each of the shape's axes: `(d, r, dlo, dhi, margin)`, the box's centre
    /// `d` and half-width `r` along the axis, the shape's extent `dlo .. dhi` on it, and a margin far
    /// above the rounding of `d ± r` (what [`Probe::holds`] and [`Probe::may_meet`] compare).
    #[inline]
    fn box_on_axes(&self, lo: Vec2, hi: Vec2) -> impl Iterator<Item = (Real, Real, Real, Real, Real)> + '_ {
        let scale = 1.0 + lo.x.abs().at_least(lo.y.abs()).at_least(hi.x.abs()).at_least(hi.y.abs());
        let c = Vec2::new((lo.x + hi.x) * 0.5, (lo.y + hi.y) * 0.5);
        self.axes[..self.n].iter().map(move |&(n, dlo, dhi)| {
            let r = 0.5 * ((hi.x - lo.x) * n.x.abs() + (hi.y - lo.y) * n.y.abs());
            let d = n.x * c.x + n.y * c.y;
            (d, r, dlo, dhi, 1e-9 * (n.x.abs() + n.y.abs()) * scale)
        })
    }
}

impl Workspace {
    /// A workspace from its bounds and obstacles.
    pub fn new(bounds: Aabb, obstacles: Vec<Shape>) -> Self {
        let boxes: Vec<Aabb> = obstacles.iter().map(Shape::aabb).collect();
        let bvh = (boxes.len() >= BVH_FROM).then(|| {
            let leaves: Vec<ParryAabb> = boxes
                .iter()
                .map(|b| ParryAabb::new(Vector::new(b.min.x, b.min.y), Vector::new(b.max.x, b.max.y)))
                .collect();
            Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves)
        });
        let grid = (boxes.len() >= GRID_FROM).then(|| Grid::new(&boxes)).flatten();
        Workspace { bounds, obstacles, boxes, bvh, grid, touching_allowed: false, map_grid: None, solids: Vec::new() }
    }

    /// The same workspace with the broad phase a scan of every box (for tests and benchmarks
    /// that compare the two).
    pub fn scanned(&self) -> Workspace {
        Workspace { bvh: None, grid: None, ..self.clone() }
    }

    /// The same workspace with the hierarchy alone, no grid in front of it (for tests and
    /// benchmarks that compare the two).
    pub fn without_grid(&self) -> Workspace {
        Workspace { grid: None, ..self.clone() }
    }

    /// The same workspace with a grid in front of its hierarchy whatever its size (for tests that
    /// compare the broad phases on small maps).
    pub fn with_grid(&self) -> Workspace {
        Workspace { grid: self.bvh.as_ref().and_then(|_| Grid::new(&self.boxes)), ..self.clone() }
    }

    /// Whether small queries go through the grid of candidate lists first.
    pub fn has_grid(&self) -> bool {
        self.grid.is_some()
    }

    /// The grid's cells, list entries and crowded cells.
    #[cfg(test)]
    pub(super) fn grid_stats(&self) -> Option<(usize, usize, usize)> {
        self.grid.as_ref().map(Grid::stats)
    }

    /// The bytes the broad phase uses beyond the obstacles: their boxes, the hierarchy and the grid.
    pub fn broad_phase_bytes(&self) -> usize {
        std::mem::size_of_val(&self.boxes[..])
            + self.bvh.as_ref().map_or(0, Bvh::heap_memory_size)
            + self.grid.as_ref().map_or(0, Grid::heap_bytes)
    }

    /// Whether queries use the bounding-volume hierarchy.
    pub fn has_bvh(&self) -> bool {
        self.bvh.is_some()
    }

    /// Call `f` with each obstacle whose box meets `bb`, the box of the query `q` (in no particular
    /// order), until it returns `true`; returns whether it did. The grid and the hierarchy skip
    /// obstacles by the query's shape too (only when there is a hierarchy: a scan of a few boxes
    /// tests `bb` alone).
    #[inline]
    ///
    /// `f` is told too whether the obstacle surely meets the query, its box inside the query's
    /// convex polygon (see `Probe::holds`; never for other queries, nor by the scan).
    fn near_by(&self, bb: &Aabb, q: Query, mut f: impl FnMut(usize, bool) -> bool) -> bool {
        // (Exact tests are counted only through the hierarchy: a scan has fewer than BVH_FROM.)
        match &self.bvh {
            None => self.boxes.iter().enumerate().any(|(i, bx)| bx.intersects(bb) && f(i, false)),
            Some(t) => {
                let mut tests = 0;
                if let Some(g) = &self.grid {
                    if let Some(found) = self.near_in_grid(g, bb, q, &mut f) {
                        return found;
                    }
                }
                // (Built in place: a probe is a few hundred bytes, and small maps query often. The
                // hierarchy serves maps of 32 to 1,000 obstacles mostly, where a body seldom holds
                // one whole: the exact test decides, as it always did.)
                let probe = Probe::of(&q, *bb);
                let found = t
                    .leaves(|n| probe.may_meet(Vec2::new(n.mins().x, n.mins().y), Vec2::new(n.maxs().x, n.maxs().y)))
                    .any(|i| {
                        tests += 1;
                        f(i as usize, false)
                    });
                if tests > 0 {
                    add_tests(tests);
                }
                found
            }
        }
    }

    /// [`Workspace::near_by`] through the grid: `None` when it gives way to the hierarchy. (Apart,
    /// and not inlined: the hierarchy's path stays as small as it was for the maps below
    /// [`GRID_FROM`].)
    #[inline(never)]
    fn near_in_grid(&self, g: &Grid, bb: &Aabb, q: Query, f: &mut impl FnMut(usize, bool) -> bool) -> Option<bool> {
        let mut tests = 0;
        // Made when first needed: a query beside every obstacle needs none.
        let probe = OnceCell::new();
        let probe = || probe.get_or_init(|| Probe::of(&q, *bb).with_holds(&q));
        let polygon = matches!(q, Query::Polygon(_));
        let sure = |i: usize| polygon && probe().holds(self.boxes[i].min, self.boxes[i].max);
        // A body among many small obstacles often holds some whole: those listed at the
        // centre of its box first, where they are likeliest (then the walk, which may
        // hand them over again: `f` answers the same).
        if let Query::Polygon(_) = q {
            let centre = Vec2::new(0.5 * (bb.min.x + bb.max.x), 0.5 * (bb.min.y + bb.max.y));
            for &i in g.at(centre).unwrap_or(&[]) {
                let bx = &self.boxes[i as usize];
                if probe().holds(bx.min, bx.max) {
                    tests += 1;
                    if f(i as usize, true) {
                        add_tests(tests);
                        return Some(true);
                    }
                }
            }
        }
        // Obstacles whose boxes the shape misses are not handed to the exact test.
        let meets = |bx: &Aabb| match q {
            Query::Point(p) => bx.contains(p),
            _ => bx.intersects(bb) && probe().may_meet(bx.min, bx.max),
        };
        let walked = g.walk(&self.boxes, bb, &q, meets, |i| {
            tests += 1;
            f(i, sure(i))
        });
        if tests > 0 {
            add_tests(tests);
        }
        walked
    }

    /// The first obstacle (in scenario order) whose box meets `bb` and that passes `hit`.
    #[inline]
    fn first(&self, bb: &Aabb, q: Query, hit: impl Fn(usize) -> bool) -> Option<usize> {
        match &self.bvh {
            None => (0..self.obstacles.len()).find(|&i| self.boxes[i].intersects(bb) && hit(i)),
            Some(_) => {
                let mut first: Option<usize> = None;
                self.near_by(bb, q, |i, sure| {
                    if first.is_none_or(|f| i < f) && (sure || hit(i)) {
                        first = Some(i);
                    }
                    false
                });
                first
            }
        }
    }

    /// The smallest index `i` of an obstacle whose box meets `bb` and for which `hit(i)` holds (the
    /// exact test is the caller's, e.g. a robot's own rule), through the hierarchy when the map
    /// has one: the answer a scan of every obstacle in order gives.
    pub fn first_hit(&self, bb: &Aabb, hit: impl Fn(usize) -> bool) -> Option<usize> {
        match &self.bvh {
            None => (0..self.obstacles.len()).find(|&i| self.boxes[i].intersects(bb) && hit(i)),
            Some(t) => t
                .leaves(|n| node_meets(n, bb))
                .map(|i| i as usize)
                .filter(|&i| self.boxes[i].intersects(bb))
                .inspect(|_| add_tests(1))
                .filter(|&i| hit(i))
                .min(),
        }
    }

    /// The smallest of `cap` and `dist(i, best so far)` over the obstacles whose boxes come within
    /// the best so far of `bb` (stopping at 0): a robot's own distance rule, through the hierarchy.
    #[inline]
    pub fn nearest_by(&self, bb: &Aabb, cap: Real, dist: impl Fn(usize, Real) -> Real) -> Real {
        self.nearest(bb, cap, dist)
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
                        add_tests(1);
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
    pub fn first_obstacle_at(&self, p: Vec2) -> Option<usize> {
        let bb = Aabb { min: p, max: p };
        self.first(&bb, Query::Point(p), |i| self.obstacles[i].contains_point(p))
    }

    /// Whether the point `p` lies in (or on) an obstacle.
    pub fn point_blocked(&self, p: Vec2) -> bool {
        // The common small map (no hierarchy) first, as a plain scan: the hottest query of all.
        if self.bvh.is_none() {
            return self.boxes.iter().zip(&self.obstacles).any(|(bx, o)| bx.contains(p) && o.contains_point(p));
        }
        self.near_by(&Aabb { min: p, max: p }, Query::Point(p), |i, _| self.obstacles[i].contains_point(p))
    }

    /// Whether the closed segment `a b` meets an obstacle.
    pub fn segment_blocked(&self, a: Vec2, b: Vec2) -> bool {
        self.near_by(&Aabb::of_points(&[a, b]), Query::Segment(a, b), |i, _| self.obstacles[i].intersects_segment(a, b))
    }

    /// The distance from the closed polygon `poly` to the nearest obstacle, capped at `cap`
    /// (0 when it meets one).
    pub fn polygon_clearance(&self, poly: &[Vec2], cap: Real) -> Real {
        let bb = Aabb::of_points(poly);
        self.nearest(&bb, cap, |i, best| self.obstacles[i].distance_to_polygon(poly, &bb, best))
    }

    /// The index of the first obstacle that the segment `a b` meets (its interior only when the
    /// workspace is [`touching_allowed`](Workspace::touching_allowed)), if any.
    pub fn first_obstacle_on_segment(&self, a: Vec2, b: Vec2) -> Option<usize> {
        self.first(&Aabb::of_points(&[a, b]), Query::Segment(a, b), |i| {
            if self.touching_allowed {
                self.obstacles[i].interior_meets_segment(a, b)
            } else {
                self.obstacles[i].intersects_segment(a, b)
            }
        })
    }

    /// The distance from the segment `a b` to the nearest obstacle, capped at `cap` (0 when it
    /// meets or touches one).
    pub fn segment_clearance(&self, a: Vec2, b: Vec2, cap: Real) -> Real {
        self.nearest(&Aabb::of_points(&[a, b]), cap, |i, best| self.obstacles[i].distance_to_segment(a, b, best))
    }

    /// Whether a sensor at `a` has a clear sight line to `b`: the segment `a b` passes through no
    /// obstacle's interior. Touching (grazing a vertex, running along an edge, ending on the
    /// boundary) does not block, whatever [`touching_allowed`](Workspace::touching_allowed) says (see [`super::sight`]).
    pub fn sight_clear(&self, a: Vec2, b: Vec2) -> bool {
        !self.near_by(&Aabb::of_points(&[a, b]), Query::Segment(a, b), |i, _| {
            self.obstacles[i].interior_meets_segment(a, b)
        })
    }

    /// Whether the closed segment `a → b` meets no obstacle at all, boundaries included (the
    /// Technion course's sight rule, where a sight line that touches an obstacle edge hides the
    /// point; see [`crate::geometry::sight`]). Exact, whatever `touching_allowed` says.
    pub fn sight_untouched(&self, a: Vec2, b: Vec2) -> bool {
        !self
            .near_by(&Aabb::of_points(&[a, b]), Query::Segment(a, b), |i, _| self.obstacles[i].intersects_segment(a, b))
    }

    /// The index of the first obstacle that the closed polygon `poly` meets, if any.
    pub fn first_obstacle_in_polygon(&self, poly: &[Vec2]) -> Option<usize> {
        let bb = Aabb::of_points(poly);
        self.first(&bb, Query::Polygon(poly), |i| self.obstacles[i].intersects_polygon(poly, &bb))
    }

    /// An obstacle (the first found, not necessarily the first in scenario order) that the closed
    /// polygon `poly` meets, if any: for validity, where any will do and the search stops at it.
    pub fn any_obstacle_in_polygon(&self, poly: &[Vec2]) -> Option<usize> {
        let bb = Aabb::of_points(poly);
        self.any(&bb, Query::Polygon(poly), |i| self.obstacles[i].intersects_polygon(poly, &bb))
    }

    /// Like [`Workspace::first_obstacle_on_segment`], but any obstacle met (see [`Workspace::any_obstacle_in_polygon`]).
    pub fn any_obstacle_on_segment(&self, a: Vec2, b: Vec2) -> Option<usize> {
        self.any(&Aabb::of_points(&[a, b]), Query::Segment(a, b), |i| {
            if self.touching_allowed {
                self.obstacles[i].interior_meets_segment(a, b)
            } else {
                self.obstacles[i].intersects_segment(a, b)
            }
        })
    }

    /// An obstacle whose box meets `bb` and that passes `hit`, the first the broad phase finds.
    #[inline]
    fn any(&self, bb: &Aabb, q: Query, hit: impl Fn(usize) -> bool) -> Option<usize> {
        let mut found = None;
        self.near_by(bb, q, |i, sure| {
            let h = sure || hit(i);
            if h {
                found = Some(i);
            }
            h
        });
        found
    }
}

/// Whether an obstacle meets the interior of the cell `[min, max]`: a rectangle when their open
/// interiors overlap (so a rectangle that only shares a side does not block, and a map's pixels
/// come back exactly); other shapes when they touch the cell at all (the closed test, which is
/// safe for moves between cell centres). Grid search's cells and an occupancy map's pixels.
pub fn cell_blocked(ws: &Workspace, min: Vec2, max: Vec2) -> bool {
    let bbox = Aabb { min, max };
    let outline = [min, Vec2::new(max.x, min.y), max, Vec2::new(min.x, max.y)];
    ws.first_hit(&bbox, |i| match &ws.obstacles[i] {
        Shape::Rect(r) => r.min.x < max.x && min.x < r.max.x && r.min.y < max.y && min.y < r.max.y,
        s => s.intersects_polygon(&outline, &bbox),
    })
    .is_some()
}

//! A uniform grid of candidate lists in front of the obstacle hierarchy (see [`super::Workspace`]).
//!
//! Among many obstacles, a query of parry's `Bvh` descends some twenty levels, testing two boxes at
//! each, before it reaches the one or two obstacles near a point. The grid answers a
//! small query in one or a few steps instead: it covers the union of the obstacles' boxes with
//! about as many cells as obstacles, and each cell lists, in scenario order, the obstacles whose
//! boxes meet it. A query walks the cells its shape may meet, row by row, and hands each listed
//! obstacle whose box meets the query's box to the exact test once. It gives way to the hierarchy
//! for long queries and crowded cells, so the hierarchy stays the broad phase of record.
//!
//! Both sides map a coordinate to a cell with the same monotone function ([`Grid::col`],
//! [`Grid::row`]), so a point of an obstacle's box always falls in a cell that lists it: the grid
//! finds every obstacle the scan finds, and the exact tests decide as before.

use super::Aabb;
use crate::math::{MinMax, Real, Vec2};

/// At most about this many cells (three times it at worst, from rounding up along each axis).
const MAX_CELLS: usize = 1 << 20;
/// A cell listing more obstacles than this sends the queries that reach it to the hierarchy.
const MAX_LIST: usize = 48;
/// A query whose box spans more rows or columns than this goes to the hierarchy.
const MAX_SPAN: usize = 32;
/// The grid is given up (the hierarchy alone answers) when the lists would hold more than this
/// many entries per obstacle, even at a coarser resolution: big obstacles over many cells.
const ENTRIES_PER_OBSTACLE: usize = 8;

/// A query's shape: what the grid walks.
#[derive(Clone, Copy)]
pub(super) enum Query<'a> {
    Point(Vec2),
    Segment(Vec2, Vec2),
    /// A closed polygon (its boundary and inside), convex or not.
    Polygon(&'a [Vec2]),
}

impl Query<'_> {
    /// A range of x that holds every point of the shape whose y lies in `lo ..= hi`, widened by
    /// `margin` (`None` when the shape has none there). Every point of the shape in the band is in
    /// its boundary's span there (a horizontal line through a point inside meets the boundary on
    /// both sides), so a polygon's span is the union of its edges'.
    #[inline]
    fn span(&self, lo: Real, hi: Real, margin: Real) -> Option<(Real, Real)> {
        let (a, b) = match *self {
            Query::Point(p) => (p.x, p.x),
            Query::Segment(p, q) => segment_span(p, q, lo, hi)?,
            Query::Polygon(poly) => {
                let mut span: Option<(Real, Real)> = None;
                for (i, &p) in poly.iter().enumerate() {
                    if let Some((a, b)) = segment_span(p, poly[(i + 1) % poly.len()], lo, hi) {
                        span = Some(span.map_or((a, b), |(x, y)| (x.at_most(a), y.at_least(b))));
                    }
                }
                span?
            }
        };
        Some((a - margin, b + margin))
    }
}

/// The x range of the segment `p q` where its y lies in `lo ..= hi`, if it reaches the band.
#[inline]
fn segment_span(p: Vec2, q: Vec2, lo: Real, hi: Real) -> Option<(Real, Real)> {
    let (ylo, yhi) = (p.y.at_most(q.y), p.y.at_least(q.y));
    if yhi < lo || ylo > hi {
        return None;
    }
    let (xlo, xhi) = (p.x.at_most(q.x), p.x.at_least(q.x));
    if p.y == q.y {
        return Some((xlo, xhi));
    }
    // Where the segment crosses the band's lines (clamped to its ends); the caller's margin covers
    // the rounding, and the segment's own x range bounds the answer.
    let at = |y: Real| {
        let t = ((y - p.y) / (q.y - p.y)).at_least(0.0).at_most(1.0);
        p.x + t * (q.x - p.x)
    };
    let (a, b) = (at(lo), at(hi));
    Some((a.at_most(b).at_least(xlo), a.at_least(b).at_most(xhi)))
}

/// The grid: cells over the union of the obstacles' boxes, each with its list of obstacles.
#[derive(Clone, Debug)]
pub(super) struct Grid {
    /// The union of the obstacles' boxes: no obstacle box meets anything outside it.
    bounds: Aabb,
    /// Cells per unit length along x and y (0 along an axis of zero extent: one cell).
    inv: Vec2,
    /// A cell's size along x and y.
    size: Vec2,
    nx: usize,
    ny: usize,
    /// Cell `c` (row-major, `c = row · nx + col`) lists `items[start[c] .. start[c + 1]]`.
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Grid {
    /// The grid over these boxes (obstacle `i`'s box is `boxes[i]`), or `None` when it would not
    /// pay: boxes not finite, or too many list entries even when coarsened.
    pub(super) fn new(boxes: &[Aabb]) -> Option<Grid> {
        let n = boxes.len();
        let first = *boxes.first()?;
        if u32::try_from(n).is_err() {
            return None;
        }
        let mut bounds = first;
        for b in boxes {
            bounds.min.x = bounds.min.x.at_most(b.min.x);
            bounds.min.y = bounds.min.y.at_most(b.min.y);
            bounds.max.x = bounds.max.x.at_least(b.max.x);
            bounds.max.y = bounds.max.y.at_least(b.max.y);
        }
        let (w, h) = (bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y);
        if !(w.is_finite() && h.is_finite() && boxes.iter().all(|b| b.min.x <= b.max.x && b.min.y <= b.max.y)) {
            return None;
        }
        let mut target = n.clamp(1, MAX_CELLS);
        let budget = (ENTRIES_PER_OBSTACLE as u64).checked_mul(n as u64)?;
        // Coarsened three times at most: fewer cells than that would list too many obstacles each.
        while target >= (n / 64).max(1) {
            let (nx, ny) = dims(w, h, target);
            let cells = nx.checked_mul(ny)?;
            let grid = Grid {
                bounds,
                inv: Vec2::new(if w > 0.0 { nx as Real / w } else { 0.0 }, if h > 0.0 { ny as Real / h } else { 0.0 }),
                size: Vec2::new(w / nx as Real, h / ny as Real),
                nx,
                ny,
                start: Vec::new(),
                items: Vec::new(),
            };
            // Count the entries before allocating them (each term is at most `cells`, so the sum of
            // `n` of them fits in a u64).
            let entries: u64 = boxes
                .iter()
                .map(|b| grid.cells_of(b))
                .map(|(c, r)| (c.end() - c.start() + 1) as u64 * (r.end() - r.start() + 1) as u64)
                .sum();
            if entries <= budget.max(cells as u64) && u32::try_from(entries).is_ok() {
                return Some(grid.filled(boxes, cells, entries as usize));
            }
            target /= 4;
        }
        None
    }

    /// The grid with its lists: a count per cell, then the lists filled in scenario order.
    fn filled(mut self, boxes: &[Aabb], cells: usize, entries: usize) -> Grid {
        let mut start = vec![0u32; cells + 1];
        for b in boxes {
            let (cols, rows) = self.cells_of(b);
            for r in rows {
                for c in cols.clone() {
                    start[r * self.nx + c + 1] += 1;
                }
            }
        }
        for c in 0..cells {
            start[c + 1] += start[c];
        }
        let mut next: Vec<u32> = start[..cells].to_vec();
        let mut items = vec![0u32; entries];
        for (i, b) in boxes.iter().enumerate() {
            let (cols, rows) = self.cells_of(b);
            for r in rows {
                for c in cols.clone() {
                    let k = &mut next[r * self.nx + c];
                    items[*k as usize] = i as u32;
                    *k += 1;
                }
            }
        }
        self.start = start;
        self.items = items;
        self
    }

    /// Its cells, list entries and crowded cells (whose queries go to the hierarchy).
    #[cfg(test)]
    pub(super) fn stats(&self) -> (usize, usize, usize) {
        let crowded = self.start.windows(2).filter(|w| (w[1] - w[0]) as usize > MAX_LIST).count();
        (self.nx * self.ny, self.items.len(), crowded)
    }

    /// The bytes the grid's lists use.
    pub(super) fn heap_bytes(&self) -> usize {
        4 * (self.start.len() + self.items.len())
    }

    /// The column holding `x` (monotone in `x`; clamped to the grid).
    #[inline(always)]
    fn col(&self, x: Real) -> usize {
        ((x - self.bounds.min.x) * self.inv.x).at_least(0.0).at_most((self.nx - 1) as Real) as usize
    }

    /// The row holding `y` (as [`Grid::col`]).
    #[inline(always)]
    fn row(&self, y: Real) -> usize {
        ((y - self.bounds.min.y) * self.inv.y).at_least(0.0).at_most((self.ny - 1) as Real) as usize
    }

    /// The columns and rows of the cells a box meets.
    #[inline]
    fn cells_of(&self, b: &Aabb) -> (std::ops::RangeInclusive<usize>, std::ops::RangeInclusive<usize>) {
        (self.col(b.min.x)..=self.col(b.max.x), self.row(b.min.y)..=self.row(b.max.y))
    }

    #[inline(always)]
    fn list(&self, cell: usize) -> &[u32] {
        &self.items[self.start[cell] as usize..self.start[cell + 1] as usize]
    }

    /// The obstacles listed in the cell holding `p` (`None` outside every obstacle's box).
    #[inline]
    pub(super) fn at(&self, p: Vec2) -> Option<&[u32]> {
        self.bounds.contains(p).then(|| self.list(self.row(p.y) * self.nx + self.col(p.x)))
    }

    /// Call `f` once with each obstacle whose box (`boxes[i]`) passes `meets` (at least: meets `bb`,
    /// the query's box) and lies in a cell the query's shape may meet, until it returns `true`. `Some(whether it did)`;
    /// `None` when the query is long or reaches a crowded cell (some obstacles may have been
    /// handed to `f` already): ask the hierarchy.
    #[inline]
    pub(super) fn walk(
        &self,
        boxes: &[Aabb],
        bb: &Aabb,
        q: &Query,
        meets: impl Fn(&Aabb) -> bool,
        mut f: impl FnMut(usize) -> bool,
    ) -> Option<bool> {
        if !self.bounds.intersects(bb) {
            return Some(false);
        }
        if let Query::Point(p) = *q {
            let list = self.list(self.row(p.y) * self.nx + self.col(p.x));
            if list.len() > MAX_LIST {
                return None;
            }
            return Some(list.iter().any(|&i| meets(&boxes[i as usize]) && f(i as usize)));
        }
        let (c0, c1) = (self.col(bb.min.x), self.col(bb.max.x));
        let (r0, r1) = (self.row(bb.min.y), self.row(bb.max.y));
        if c1 - c0 >= MAX_SPAN || r1 - r0 >= MAX_SPAN {
            return None;
        }
        // A row's band, widened by a hundredth of a cell and far more than rounding, and as much
        // along x: every point of the shape that `row` puts in the row is in the band.
        let scale = [self.bounds.min, self.bounds.max, bb.min, bb.max]
            .iter()
            .fold(1.0, |s: Real, p| s.at_least(p.x.abs()).at_least(p.y.abs()));
        let (my, mx) = (0.01 * self.size.y + 1e-9 * scale, 0.01 * self.size.x + 1e-9 * scale);
        let y0 = self.bounds.min.y;
        // The previous row's columns: an obstacle listed there as well was handed over there.
        let mut prev: Option<(usize, usize)> = None;
        for r in r0..=r1 {
            let (lo, hi) = (y0 + r as Real * self.size.y - my, y0 + (r + 1) as Real * self.size.y + my);
            // (No obstacle box meets the shape in a row where it lies beside them all.)
            let span = q.span(lo.at_least(bb.min.y), hi.at_most(bb.max.y), mx);
            let Some((xa, xb)) = span.filter(|&(xa, xb)| xa <= self.bounds.max.x && xb >= self.bounds.min.x) else {
                prev = None;
                continue;
            };
            let (a, b) = (self.col(xa).max(c0), self.col(xb).min(c1));
            for c in a..=b {
                let list = self.list(r * self.nx + c);
                if list.len() > MAX_LIST {
                    return None;
                }
                for &i in list {
                    let bx = &boxes[i as usize];
                    if !meets(bx) {
                        continue;
                    }
                    // Handed over already: in this row's previous cell, or in the previous row.
                    let (oc0, oc1) = (self.col(bx.min.x), self.col(bx.max.x));
                    if c > a && oc0 < c {
                        continue;
                    }
                    if let Some((pa, pb)) = prev {
                        if self.row(bx.min.y) < r && oc0.max(pa) <= oc1.min(pb) {
                            continue;
                        }
                    }
                    if f(i as usize) {
                        return Some(true);
                    }
                }
            }
            prev = Some((a, b));
        }
        Some(false)
    }
}

/// Columns and rows for about `target` square cells over a `w × h` box (at least one of each).
fn dims(w: Real, h: Real, target: usize) -> (usize, usize) {
    let t = target as Real;
    let mut s = (w * h / t).sqrt();
    if !(s > 0.0 && s.is_finite() && s >= w.at_least(h) / t) {
        s = w.at_least(h) / t;
    }
    if s.is_nan() || s <= 0.0 {
        return (1, 1);
    }
    let n = |len: Real| ((len / s).ceil() as usize).clamp(1, target);
    (n(w), n(h))
}

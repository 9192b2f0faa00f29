//! The hierarchical hexagonal decomposition: a coarse tiling of the workspace by pointy-top
//! hexagons, each refined on demand into seven children.
//!
//! A hexagon of circumradius `s` splits *exactly* into one hexagon of circumradius `s/2` at its
//! centre and six half hexagons, one straddling each edge: the hexagon of radius `s/2` centred on
//! an edge's midpoint has that edge as its long diagonal, so the parent cuts it in half. Every
//! cell is therefore a hexagon clipped to its parent (and, at level 0, to the workspace bounds):
//! the half hexagons at the borders the report describes, and at every level the cells of a
//! parent cover it with no gap and no overlap. The lattice of level `k + 1` contains the one of
//! level `k`, so neighbouring parents' edge children are the same hexagon cut in two halves.

use crate::geometry::convex::{centroid, clip_convex, convex_contains, convex_strictly_contains, hexagon, share_edge};
use crate::geometry::polygon::signed_area2;
use crate::geometry::{Aabb, Shape, Workspace};
use crate::math::{Real, Vec2};

/// √3.
pub(super) const SQRT3: Real = 1.732_050_807_568_877_2;

/// What a cell holds, from the workspace's obstacles alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellLabel {
    /// No obstacle meets the cell.
    Free = 0,
    /// The cell is partly covered: refined, or impassable at the finest level.
    Mixed = 1,
    /// The cell lies inside an obstacle.
    Full = 2,
}

/// One cell of the decomposition.
#[derive(Clone, Debug)]
pub struct Cell {
    /// Level (0: the coarse tiling).
    pub level: u32,
    /// Its centre: the centroid of its outline (the hexagon's centre for a whole hexagon; inside
    /// a half hexagon, so the two halves of a hexagon have distinct centres). The robot steps
    /// from centre to centre.
    pub centre: Vec2,
    /// Circumradius of its hexagon.
    pub radius: Real,
    /// Its outline: the hexagon clipped to its parent (convex, counter-clockwise).
    pub outline: Vec<Vec2>,
    /// Bounding box of the outline.
    pub bbox: Aabb,
    /// Its parent (`None` at level 0).
    pub parent: Option<usize>,
    /// Its children (empty: a leaf).
    pub children: Vec<usize>,
    /// Its label (set when it is examined).
    pub label: CellLabel,
}

impl Cell {
    /// Whether the cell has not been refined.
    pub fn is_leaf(&self) -> bool {
        self.children.is_empty()
    }
}

/// The centres of the seven children of a hexagon of circumradius `s` at `c`: its own centre,
/// then one on each edge's midpoint (at the inradius `√3 s / 2`, perpendicular to the edge).
pub fn child_centres(c: Vec2, s: Real) -> [Vec2; 7] {
    let mut out = [c; 7];
    let d = SQRT3 * s / 2.0;
    for (i, o) in out[1..].iter_mut().enumerate() {
        let a = (60.0 * i as Real).to_radians();
        *o = Vec2::new(c.x + d * libm::cos(a), c.y + d * libm::sin(a));
    }
    out
}

/// The cell label of a convex outline among the workspace's obstacles.
pub fn label_of(ws: &Workspace, outline: &[Vec2], bbox: &Aabb) -> CellLabel {
    let mut meets = false;
    for shape in &ws.obstacles {
        if !shape.intersects_polygon(outline, bbox) {
            continue;
        }
        if contains_outline(shape, outline) {
            return CellLabel::Full;
        }
        meets = true;
    }
    if meets {
        CellLabel::Mixed
    } else {
        CellLabel::Free
    }
}

/// Whether `shape` holds the whole convex outline: every corner inside it, and (for a polygon
/// that need not be convex) none of its corners strictly inside the outline.
fn contains_outline(shape: &Shape, outline: &[Vec2]) -> bool {
    if !outline.iter().all(|&p| shape.contains_point(p)) {
        return false;
    }
    match shape {
        Shape::Rect(_) | Shape::Circle(..) => true,
        Shape::Segment(..) => false,
        Shape::Polygon(poly) => !poly.iter().any(|&v| convex_strictly_contains(outline, v)),
    }
}

/// How refinement decides which cells to split.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Refine {
    /// Split the cells an obstacle meets without covering them (the report's rule).
    Mixed,
    /// Also split free cells that an obstacle comes within t/2 of, so cells near walls are
    /// small enough to step between.
    Clearance,
}

/// The decomposition: every cell made so far, in the order they were made.
#[derive(Clone, Debug, Default)]
pub struct Decomposition {
    /// The cells; children follow their parents.
    pub cells: Vec<Cell>,
    /// Circumradius of level 0.
    pub base_radius: Real,
}

impl Decomposition {
    /// The coarse tiling of `bounds` by hexagons of circumradius `s`, rows centred on the bottom
    /// edge (so the bottom row is half hexagons), each clipped to the bounds. Labels start `Free`.
    pub fn tiling(bounds: &Aabb, s: Real) -> Decomposition {
        let (dx, dy) = (SQRT3 * s, 1.5 * s);
        let rows = ((bounds.max.y - bounds.min.y) / dy).ceil() as i64 + 1;
        let rect =
            [bounds.min, Vec2::new(bounds.max.x, bounds.min.y), bounds.max, Vec2::new(bounds.min.x, bounds.max.y)];
        let mut cells = Vec::new();
        for r in 0..=rows {
            let y = bounds.min.y + r as Real * dy;
            let shift = if r % 2 == 0 { 0.0 } else { dx / 2.0 };
            let cols = ((bounds.max.x - bounds.min.x) / dx).ceil() as i64 + 1;
            for q in -1..=cols {
                let c = Vec2::new(bounds.min.x + q as Real * dx + shift, y);
                let outline = clip_convex(&hexagon(c, s), &rect);
                if outline.len() < 3 || signed_area2(&outline) <= 1e-9 * s * s {
                    continue;
                }
                let bbox = Aabb::of_points(&outline);
                cells.push(Cell {
                    level: 0,
                    centre: centroid(&outline),
                    radius: s,
                    outline,
                    bbox,
                    parent: None,
                    children: Vec::new(),
                    label: CellLabel::Free,
                });
            }
        }
        Decomposition { cells, base_radius: s }
    }

    /// Split cell `i` into its children (hexagons of half its radius clipped to it) and return
    /// their indices. Children whose clipped outline is empty or a sliver are dropped.
    pub fn refine(&mut self, i: usize) -> std::ops::Range<usize> {
        let first = self.cells.len();
        let (c, s, level) = (self.cells[i].centre, self.cells[i].radius, self.cells[i].level);
        for cc in child_centres(c, s) {
            let outline = clip_convex(&hexagon(cc, s / 2.0), &self.cells[i].outline);
            if outline.len() < 3 || signed_area2(&outline) <= 1e-9 * s * s {
                continue;
            }
            let centre = centroid(&outline);
            let bbox = Aabb::of_points(&outline);
            self.cells.push(Cell {
                level: level + 1,
                centre,
                radius: s / 2.0,
                outline,
                bbox,
                parent: Some(i),
                children: Vec::new(),
                label: CellLabel::Free,
            });
        }
        let range = first..self.cells.len();
        self.cells[i].children = range.clone().collect();
        range
    }

    /// The leaf that contains `p` (descending from the level-0 cell that holds it), if any.
    pub fn leaf_at(&self, p: Vec2) -> Option<usize> {
        let mut at = (0..self.cells.len()).take_while(|&i| self.cells[i].level == 0).find(|&i| self.contains(i, p))?;
        while !self.cells[at].is_leaf() {
            at = *self.cells[at].children.iter().find(|&&c| self.contains(c, p))?;
        }
        Some(at)
    }

    fn contains(&self, i: usize, p: Vec2) -> bool {
        self.cells[i].bbox.grown(1e-12).contains(p) && convex_contains(&self.cells[i].outline, p)
    }

    /// For each cell in `cells`, the others in `cells` it shares a piece of boundary with
    /// (positive length). Cells of every size meet this way, since each lies on its parent's
    /// edges.
    pub fn adjacency(&self, cells: &[usize]) -> Vec<Vec<usize>> {
        // Bucket the cells by their boxes on a grid of the smallest cell's size (a big cell sits in
        // many buckets; a bucket holds few small ones).
        let smallest = cells.iter().map(|&i| self.cells[i].radius).fold(self.base_radius, Real::min);
        let bucket = (2.0 * smallest).max(1e-9);
        let key = |x: Real, y: Real| ((x / bucket).floor() as i64, (y / bucket).floor() as i64);
        let mut grid: std::collections::HashMap<(i64, i64), Vec<usize>> = std::collections::HashMap::new();
        for (k, &i) in cells.iter().enumerate() {
            let b = self.cells[i].bbox;
            let (x0, y0) = key(b.min.x, b.min.y);
            let (x1, y1) = key(b.max.x, b.max.y);
            for gx in x0..=x1 {
                for gy in y0..=y1 {
                    grid.entry((gx, gy)).or_default().push(k);
                }
            }
        }
        let mut out = vec![Vec::new(); cells.len()];
        for (k, &i) in cells.iter().enumerate() {
            let b = self.cells[i].bbox.grown(1e-9);
            let (x0, y0) = key(b.min.x, b.min.y);
            let (x1, y1) = key(b.max.x, b.max.y);
            let mut seen: Vec<usize> = Vec::new();
            for gx in x0..=x1 {
                for gy in y0..=y1 {
                    for &m in grid.get(&(gx, gy)).map(|v| v.as_slice()).unwrap_or(&[]) {
                        if m != k && !seen.contains(&m) {
                            seen.push(m);
                        }
                    }
                }
            }
            crate::math::sort_short(&mut seen);
            for m in seen {
                let j = cells[m];
                if self.cells[j].bbox.intersects(&b) && share_edge(&self.cells[i].outline, &self.cells[j].outline) {
                    out[k].push(m);
                }
            }
        }
        out
    }
}

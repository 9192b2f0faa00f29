//! Occupancy maps as people have them: ROS map_server's form (a PGM or PNG image and its
//! YAML: `image`, `resolution`, `origin`, `negate`, `occupied_thresh`, `free_thresh`, `mode`) and a
//! plain image (dark = occupied), read into an [`OccupancyGrid`] and from there into a scenario;
//! and back: a scenario rasterised at a cell size, written as PGM (P5) + YAML or PNG.
//!
//! **Semantics (map_server's).** A pixel's value `v` of `maxval` gives `p = (maxval − v)/maxval`
//! (`v/maxval` with `negate`; colour pixels are the mean of their channels, alpha is ignored);
//! `p > occupied_thresh` is occupied, `p < free_thresh` free, anything between unknown. Planning
//! treats unknown as occupied. `mode: raw` reads `v` (8-bit) as the occupancy in percent (above 100:
//! unknown). Row 0 of the image is the top: pixel (column c, row r) covers
//! `x ∈ [ox + c·res, ox + (c+1)·res]`, `y ∈ [oy + (h−1−r)·res, oy + (h−r)·res]`. A nonzero yaw in
//! `origin` is refused (the scenario's obstacles are axis-aligned boxes).
//!
//! **A plain image** (no YAML) reads with map_server's defaults (thresholds 0.65 and 0.196, no
//! negate) at [`PLAIN_RESOLUTION`] (0.05, map_server's usual 5 cm) per pixel, origin (0, 0).
//!
//! **To a scenario.** Occupied (and unknown) pixels merge into axis-aligned rectangles (maximal
//! runs along each row, then runs with the same columns on consecutive rows), so the broad phase
//! gets few boxes; the bounds are the image's extent; the robot is a point; start and goal are the
//! free pixels' centres nearest the lower left and upper right corners within the largest
//! 4-connected free region (so the grid planners can always reach one from the other). The optional
//! scenario key `map` (`{"resolution", "origin"}`) remembers the pixel grid, so grid-search's
//! default cell is one pixel, aligned with the image.
//!
//! Every size is checked before anything is allocated ([`MAX_MAP_SIDE`], [`MAX_MAP_PIXELS`], the
//! scenario's obstacle limit); every error names the file and where in it (byte offset, line and
//! column, or key).
//!
//! Here: the grid, map_server's classification, grid → scenario. The image decoders are in
//! `decode.rs`, the YAML reader in `yaml.rs`, scenario → grid → files in `export.rs`.

use crate::limits;
use crate::math::Real;
use crate::scenario::{Scenario, ScenarioError};
use serde_json::json;

pub use crate::geometry::cell_blocked;
pub use crate::limits::{MAX_MAP_PIXELS, MAX_MAP_SIDE};

mod decode;
mod export;
mod yaml;

pub use decode::{decode_image, is_map_name, is_yaml_name, sniff};
pub use export::{scenario_to_grid, to_pgm_yaml, to_png};
pub use yaml::{parse_yaml, MAX_YAML_BYTES};

/// Metres (scenario units) per pixel of a plain image without a YAML.
pub const PLAIN_RESOLUTION: Real = 0.05;

/// map_server's default thresholds.
pub const OCCUPIED_THRESH: Real = 0.65;
/// map_server's default free threshold.
pub const FREE_THRESH: Real = 0.196;

/// One cell of an occupancy grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Occupancy {
    /// Free.
    Free,
    /// Occupied.
    Occupied,
    /// Neither threshold met (planned as occupied).
    Unknown,
}

/// An occupancy grid: `cells[row * width + col]`, row 0 the top (largest y), as in the image.
#[derive(Clone, Debug, PartialEq)]
pub struct OccupancyGrid {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// The cells, row 0 the top.
    pub cells: Vec<Occupancy>,
    /// Side of a cell in scenario units.
    pub resolution: Real,
    /// World position of the lower left corner of the lower left cell.
    pub origin: [Real; 2],
}

impl OccupancyGrid {
    /// Whether the cell at (col, row) blocks the robot (occupied or unknown).
    pub fn blocked(&self, col: usize, row: usize) -> bool {
        self.cells[row * self.width + col] != Occupancy::Free
    }
    /// The blocked cells as booleans, row 0 the top.
    pub fn blocked_mask(&self) -> Vec<bool> {
        self.cells.iter().map(|c| *c != Occupancy::Free).collect()
    }
    /// The x of the cell boundary `i` (0 = the left edge).
    fn x(&self, i: usize) -> Real {
        self.origin[0] + i as Real * self.resolution
    }
    /// The y of the cell boundary `j` counted from the bottom (0 = the lower edge).
    fn y(&self, j: usize) -> Real {
        self.origin[1] + j as Real * self.resolution
    }
}

/// A decoded image: grey values `0..=maxval`, row 0 the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Columns.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// The largest value (255 for 8-bit, up to 65535).
    pub maxval: u16,
    /// Grey values, row-major.
    pub values: Vec<u16>,
}

/// How map_server reads the image (its YAML's keys).
#[derive(Clone, Debug, PartialEq)]
pub struct MapMeta {
    /// The image's file name, relative to the YAML's folder.
    pub image: String,
    /// Scenario units per pixel.
    pub resolution: Real,
    /// The lower left pixel's lower left corner `[x, y]` (yaw 0 only).
    pub origin: [Real; 2],
    /// Light is occupied.
    pub negate: bool,
    /// Above: occupied.
    pub occupied_thresh: Real,
    /// Below: free.
    pub free_thresh: Real,
    /// `trinary` (default), `scale` or `raw`.
    pub mode: String,
}

impl MapMeta {
    /// map_server's defaults, for a plain image.
    pub fn plain(image: &str) -> MapMeta {
        MapMeta {
            image: image.to_string(),
            resolution: PLAIN_RESOLUTION,
            origin: [0.0, 0.0],
            negate: false,
            occupied_thresh: OCCUPIED_THRESH,
            free_thresh: FREE_THRESH,
            mode: "trinary".into(),
        }
    }
}

fn file_err(file: &str, message: impl Into<String>) -> ScenarioError {
    ScenarioError::at(limits::cut(file, 100), message)
}

fn check_size(file: &str, width: u64, height: u64) -> Result<(usize, usize), ScenarioError> {
    if width == 0 || height == 0 {
        return Err(file_err(file, format!("the image is {width}×{height} pixels: it has no pixels")));
    }
    let side = MAX_MAP_SIDE as u64;
    let pixels = width.checked_mul(height);
    if width > side || height > side || pixels.is_none_or(|p| p > MAX_MAP_PIXELS as u64) {
        return Err(file_err(
            file,
            format!(
                "the image is {width}×{height} pixels; the limits are {MAX_MAP_SIDE} pixels a side and {MAX_MAP_PIXELS} pixels in all"
            ),
        ));
    }
    Ok((width as usize, height as usize))
}

/// The grid map_server makes of `image` with `meta`'s thresholds.
pub fn classify(image: &Image, meta: &MapMeta) -> OccupancyGrid {
    let max = Real::from(image.maxval);
    let cells = image
        .values
        .iter()
        .map(|&v| {
            let v = Real::from(v);
            if meta.mode == "raw" {
                // The value is the occupancy in percent; above 100 unknown.
                if v > 100.0 {
                    return Occupancy::Unknown;
                }
                let p = v / 100.0;
                return if p > meta.occupied_thresh {
                    Occupancy::Occupied
                } else if p < meta.free_thresh {
                    Occupancy::Free
                } else {
                    Occupancy::Unknown
                };
            }
            let p = if meta.negate { v / max } else { (max - v) / max };
            if p > meta.occupied_thresh {
                Occupancy::Occupied
            } else if p < meta.free_thresh {
                Occupancy::Free
            } else {
                Occupancy::Unknown
            }
        })
        .collect();
    OccupancyGrid { width: image.width, height: image.height, cells, resolution: meta.resolution, origin: meta.origin }
}

// ---------------------------------------------------------------------------------------------
// Grid → scenario

/// The grid's blocked cells as rectangles `[x0, y0, x1, y1]`: maximal runs along each row, merged
/// with the same run on the rows below. Deterministic (ordered by top row, then column).
pub fn rectangles(grid: &OccupancyGrid) -> Vec<[Real; 4]> {
    use std::collections::BTreeMap;
    // Open runs: (c0, c1) → the top row where they began.
    let mut open: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    let mut out: Vec<(usize, usize, [Real; 4])> = Vec::new();
    let close = |c0: usize, c1: usize, top: usize, bottom: usize, out: &mut Vec<_>| {
        // rows top..=bottom (row 0 the top); y counts boundaries from the bottom.
        let y0 = grid.y(grid.height - 1 - bottom);
        let y1 = grid.y(grid.height - top);
        out.push((top, c0, [grid.x(c0), y0, grid.x(c1), y1]));
    };
    for row in 0..=grid.height {
        let mut runs = Vec::new();
        if row < grid.height {
            let mut c = 0;
            while c < grid.width {
                if grid.blocked(c, row) {
                    let c0 = c;
                    while c < grid.width && grid.blocked(c, row) {
                        c += 1;
                    }
                    runs.push((c0, c));
                } else {
                    c += 1;
                }
            }
        }
        let here: std::collections::BTreeSet<(usize, usize)> = runs.iter().copied().collect();
        let ended: Vec<(usize, usize)> = open.keys().filter(|k| !here.contains(k)).copied().collect();
        for k in ended {
            let top = open.remove(&k).expect("an open run");
            close(k.0, k.1, top, row - 1, &mut out);
        }
        for r in runs {
            open.entry(r).or_insert(row);
        }
    }
    out.sort_by_key(|a| (a.0, a.1));
    out.into_iter().map(|(_, _, r)| r).collect()
}

/// Cells in ring order around (c, r) moving inward by `dir`: the first for which `ok` holds.
fn nearest(grid: &OccupancyGrid, from: (usize, usize), dir: (i64, i64), ok: impl Fn(usize) -> bool) -> Option<usize> {
    let (w, h) = (grid.width as i64, grid.height as i64);
    for d in 0..w.max(h) {
        for i in 0..=d {
            for (a, b) in [(i, d), (d, i)] {
                let (c, r) = (from.0 as i64 + dir.0 * a, from.1 as i64 + dir.1 * b);
                if c >= 0 && r >= 0 && c < w && r < h {
                    let k = (r * w + c) as usize;
                    if ok(k) {
                        return Some(k);
                    }
                }
            }
        }
    }
    None
}

/// The largest 4-connected region of free cells (ties: the first found in row order), as a mask.
fn largest_free_region(grid: &OccupancyGrid) -> Vec<bool> {
    let (w, h) = (grid.width, grid.height);
    let mut label = vec![u32::MAX; w * h];
    let mut best = (0usize, u32::MAX);
    let mut next = 0u32;
    let mut stack = Vec::new();
    for s in 0..w * h {
        if label[s] != u32::MAX || grid.cells[s] != Occupancy::Free {
            continue;
        }
        let mut size = 0;
        label[s] = next;
        stack.push(s);
        while let Some(k) = stack.pop() {
            size += 1;
            let (c, r) = (k % w, k / w);
            let mut visit = |m: usize| {
                if label[m] == u32::MAX && grid.cells[m] == Occupancy::Free {
                    label[m] = next;
                    stack.push(m);
                }
            };
            if c > 0 {
                visit(k - 1);
            }
            if c + 1 < w {
                visit(k + 1);
            }
            if r > 0 {
                visit(k - w);
            }
            if r + 1 < h {
                visit(k + w);
            }
        }
        if size > best.0 {
            best = (size, next);
        }
        next += 1;
    }
    label.iter().map(|&l| l == best.1 && l != u32::MAX).collect()
}

/// The scenario of an occupancy grid; `name` titles it.
pub fn grid_to_scenario(grid: &OccupancyGrid, name: &str) -> Result<Scenario, ScenarioError> {
    let rects = rectangles(grid);
    let max = limits::MAX_OBSTACLES.min(limits::MAX_TOTAL_VERTICES / 4);
    if rects.len() > max {
        return Err(file_err(
            name,
            format!(
                "the map's occupied pixels make {} rectangles; the limit is {max} obstacles (a coarser or simpler map is needed)",
                rects.len()
            ),
        ));
    }
    let region = largest_free_region(grid);
    let centre = |k: usize| {
        let (c, r) = (k % grid.width, k / grid.width);
        let j = grid.height - 1 - r;
        vec![grid.origin[0] + (c as Real + 0.5) * grid.resolution, grid.origin[1] + (j as Real + 0.5) * grid.resolution]
    };
    let free = |k: usize| region[k];
    let start = nearest(grid, (0, grid.height - 1), (1, -1), free)
        .ok_or_else(|| file_err(name, "the map has no free pixel (nothing below free_thresh) to start from"))?;
    let goal = nearest(grid, (grid.width - 1, 0), (-1, 1), free).unwrap_or(start);
    if goal == start {
        return Err(file_err(name, "the map's largest free region is a single pixel: there is nowhere to go"));
    }
    let (w, h) = (grid.width as Real * grid.resolution, grid.height as Real * grid.resolution);
    let bounds = [grid.origin[0], grid.origin[1], grid.x(grid.width), grid.y(grid.height)];
    let unknown = grid.cells.iter().filter(|c| **c == Occupancy::Unknown).count();
    let notes = format!(
        "An occupancy map of {}×{} pixels, {} units a pixel ({w}×{h}): occupied pixels (and the {unknown} unknown ones, which planning treats as occupied) \
         merged into {} rectangles. The point robot starts at the free pixel nearest the lower left corner and goes to the one nearest the upper right, \
         both in the largest connected free region; move them in the editor. Grid search's default cell is one pixel (on maps of at most a million pixels it is the default planner).",
        grid.width,
        grid.height,
        grid.resolution,
        rects.len()
    );
    let obstacles: Vec<_> = rects.iter().map(|r| json!({"rect": r})).collect();
    let v = json!({
        "format": crate::scenario::FORMAT,
        "name": format!("Occupancy map ({})", limits::cut(name, 100)),
        "notes": notes,
        "bounds": bounds,
        "obstacles": obstacles,
        "robot": {"kind": "point"},
        "start": centre(start),
        "goal": centre(goal),
        "resolution": grid.resolution * 0.5,
        "map": {"resolution": grid.resolution, "origin": grid.origin},
        // Grid-search a cell a pixel needs max_nodes ≥ the pixels (at most MAX_NODES).
        "planner": {"name": if (grid.width * grid.height) as f64 <= limits::MAX_NODES { "grid-search" } else { "rrt-connect" }, "seed": 1},
    });
    Scenario::from_value(&v).map_err(|e| file_err(name, e.to_string()))
}

/// Read a map: `bytes` are the image (PGM or PNG) named `name`; `yaml` is its map_server YAML
/// `(text, file name)`, if any (else the image reads as a plain image).
pub fn import_image(bytes: &[u8], name: &str, yaml: Option<(&str, &str)>) -> Result<Scenario, ScenarioError> {
    let meta = match yaml {
        Some((text, file)) => parse_yaml(text, file)?,
        None => MapMeta::plain(name),
    };
    let image = decode_image(bytes, name)?;
    let grid = classify(&image, &meta);
    let title = yaml.map_or(name, |(_, f)| f);
    grid_to_scenario(&grid, title)
}

// ---------------------------------------------------------------------------------------------
// Scenario → grid → files

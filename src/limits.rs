//! Input limits: every number and count a user can type, open or link is bounded, so that every
//! size derived from them fits, no step count wraps, and one planner iteration stays short.
//! `docs/limits.md` lists each limit, why it has its value, and the message a user gets; the page
//! reads them through the wasm export `limits()`.
//!
//! What cannot be represented is refused up front, with the JSON path (or line and column) of the
//! value that asks for it: a scenario within these limits never makes a motion check skip states,
//! an allocation fail or an index wrap.

use crate::math::Real;

/// Bytes of one scenario or course file's text (the page's editor, "Open file…", a link's
/// decompressed scenario, the CLI's file argument). 100,000 rectangles written compactly take
/// about 4 MB; pretty-printed about 12 MB.
pub const MAX_TEXT_BYTES: usize = 16 << 20;

/// Largest magnitude of any number in a scenario: coordinates, sizes, lengths, angles, gains.
/// Squares and cross products of such numbers (1e18) stay far inside `f64`, and a distance never
/// overflows to infinity.
pub const MAX_MAGNITUDE: Real = 1e9;

/// Smallest size of a number other than 0: the exact predicates (`robust::orient2d`) are exact
/// as long as products of coordinate differences do not underflow, which holds for numbers between
/// 1e-100 and 1e9 (the smallest difference of two such is about 1e-116).
pub const MIN_MAGNITUDE: Real = 1e-100;

/// Obstacles in one scenario (the broad phase keeps state checks with this many fast).
pub const MAX_OBSTACLES: usize = 100_000;

/// Vertices of one polygon (an obstacle or a rigid robot's footprint). Checking that a polygon is
/// simple costs `n²/2` segment tests: 500,000 at this limit.
pub const MAX_POLYGON_VERTICES: usize = 1_000;

/// Vertices of all polygon obstacles together (a rectangle counts 4): bounds the memory of the
/// workspace and the time to validate it (at most 400 polygons of the largest size).
pub const MAX_TOTAL_VERTICES: usize = 400_000;

/// Links of an arm (OMPL's hardest kinematic chain benchmark has 20).
pub const MAX_LINKS: usize = 64;

/// Vehicles of a vehicle chain (the ASV course's top band asks for more than 15).
pub const MAX_VEHICLES: usize = 64;

/// Inspection points.
pub const MAX_INSPECTION_POINTS: usize = 10_000;

/// Joints of a spatial arm (industrial arms have 6 or 7; a state check does forward kinematics
/// and up to `joints²/2` self pairs).
pub const MAX_SPATIAL_JOINTS: usize = 12;

/// Points of one convex hull (a link's or a 3-D obstacle's); rl's Puma links have 29 to 95.
pub const MAX_HULL_POINTS: usize = 1_024;

/// Boxes fixed to one link of a spatial arm (a tool).
pub const MAX_LINK_BOXES: usize = 16;

/// 3-D obstacles (`obstacles3d`): each state check tests the arm's links against every one whose
/// box meets theirs, so this bounds a check's cost.
pub const MAX_SOLIDS: usize = 10_000;

/// Hull points in all of a scenario's 3-D obstacles together.
pub const MAX_TOTAL_HULL_POINTS: usize = 200_000;

/// Characters of a scenario's name.
pub const MAX_NAME_CHARS: usize = 500;

/// Characters of a scenario's notes.
pub const MAX_NOTES_CHARS: usize = 20_000;

/// The most states one motion check may visit: the longest motion in the robot's space (its
/// extent, `StateSpace::max_extent`) divided by the scenario's `resolution` (a vehicle chain's
/// `max_step`) must stay at or below this. The finest built-in needs 1,486 (the ASV chains); a
/// point robot among a few obstacles checks 100,000 states in about 1 ms, among 20,000 (a linear
/// scan before the broad phase) in about 3 s.
pub const MAX_MOTION_STEPS: Real = 100_000.0;

/// The largest `max_nodes` a run accepts: a tree of a million nodes holds about 200 MB in the
/// core and in the page's record store together; 1e8 took 5.2 GB and minutes.
pub const MAX_NODES: f64 = 1e6;

/// Bytes a run's planner may hold (its trees, roadmap, cells, counted from what they hold:
/// [`Planner::stored_bytes`](crate::planners::Planner::stored_bytes)); past it the run stops with
/// status `memory_limit` and a reason naming what to change. A million-node tree of a point robot
/// holds about 80 MB; a roadmap's edge about 40 bytes, so a roadmap stops at some 6 million edges
/// (the page keeps a 96-byte record for each); PRM with a huge radius held 772 MB in the page after
/// 4 minutes at 4,011 nodes and kept growing.
pub const MAX_RUN_BYTES: usize = 256 << 20;

/// Cells of a hexagonal decomposition's coarse tiling (`cell_size` against the map's size).
pub const MAX_COARSE_CELLS: usize = 100_000;

/// States in a vehicle chain's solution file (its primitive steps), read or written.
pub const MAX_SOLUTION_STEPS: usize = 5_000_000;

/// Pixels along either side of an occupancy map's image (`io::occupancy`), checked from its header
/// before anything is allocated.
pub const MAX_MAP_SIDE: usize = 4096;

/// Pixels of an occupancy map's image: grid-search's own grid limit
/// ([`MAX_GRID_CELLS`](crate::planners::grid::MAX_GRID_CELLS)). At one cell a pixel grid-search
/// also needs `max_nodes` ≥ the pixels, so it plans on maps of up to [`MAX_NODES`] pixels; larger
/// maps open with rrt-connect as their planner (grid-search then needs a larger `cell`).
pub const MAX_MAP_PIXELS: usize = 4_000_000;

/// Animation frames the worker sends for one path (the spacing grows to stay within it).
pub const MAX_PATH_FRAMES: usize = 100_000;

/// Tool points drawn along one tree edge in the 3-D view (`Problem::tool_tree`): an edge is drawn
/// through as many evenly spread points as it has steps (and its end), at most this many, ends kept. The Puma's course edges take a few
/// dozen steps; a node then sends at most 99 numbers.
pub const MAX_TOOL_POINTS_PER_EDGE: usize = 32;

/// The limits as JSON, for the page (`limits()` in the wasm binding) and `docs/limits.md`.
pub fn to_json() -> serde_json::Value {
    serde_json::json!({
        "max_text_bytes": MAX_TEXT_BYTES,
        "max_magnitude": MAX_MAGNITUDE,
        "min_magnitude": MIN_MAGNITUDE,
        "max_obstacles": MAX_OBSTACLES,
        "max_polygon_vertices": MAX_POLYGON_VERTICES,
        "max_total_vertices": MAX_TOTAL_VERTICES,
        "max_links": MAX_LINKS,
        "max_vehicles": MAX_VEHICLES,
        "max_inspection_points": MAX_INSPECTION_POINTS,
        "max_spatial_joints": MAX_SPATIAL_JOINTS,
        "max_hull_points": MAX_HULL_POINTS,
        "max_link_boxes": MAX_LINK_BOXES,
        "max_solids": MAX_SOLIDS,
        "max_total_hull_points": MAX_TOTAL_HULL_POINTS,
        "max_name_chars": MAX_NAME_CHARS,
        "max_notes_chars": MAX_NOTES_CHARS,
        "max_motion_steps": MAX_MOTION_STEPS,
        "max_nodes": MAX_NODES,
        "max_run_bytes": MAX_RUN_BYTES,
        "max_coarse_cells": MAX_COARSE_CELLS,
        "max_solution_steps": MAX_SOLUTION_STEPS,
        "max_map_side": MAX_MAP_SIDE,
        "max_map_pixels": MAX_MAP_PIXELS,
        "max_path_frames": MAX_PATH_FRAMES,
    })
}

/// The error for a text over [`MAX_TEXT_BYTES`], or `None`.
pub fn text_too_large(text: &str) -> Option<String> {
    (text.len() > MAX_TEXT_BYTES)
        .then(|| format!("the file is {} bytes; the limit is {} bytes (16 MiB)", text.len(), MAX_TEXT_BYTES))
}

/// `(x / step).ceil()` as a step count, or `None` when it is not a finite number at most `max`
/// (NaN, infinite, or too many): callers refuse what they cannot count instead of wrapping.
pub fn steps(x: Real, step: Real, max: Real) -> Option<usize> {
    let n = (x / step).ceil();
    (n.is_finite() && n <= max).then(|| (n as usize).max(1))
}

/// Whether `c` is written as its code point (`[U+202E]`) when user text is echoed in a message:
/// control characters (C0, DEL, C1), bidirectional controls (an override would turn the rest of
/// the message's line around: the page's share links show them the same way) and the other
/// invisible format characters (zero-width spaces and joiners, word joiners, the byte order mark,
/// line and paragraph separators, interlinear annotations).
pub fn hidden(c: char) -> bool {
    matches!(
        c,
        '\u{0}'..='\u{1f}'
            | '\u{7f}'..='\u{9f}'
            | '\u{61c}'
            | '\u{180e}'
            | '\u{200b}'..='\u{200f}'
            | '\u{2028}'..='\u{202e}'
            | '\u{2060}'..='\u{2064}'
            | '\u{2066}'..='\u{206f}'
            | '\u{feff}'
            | '\u{fff9}'..='\u{fffb}'
    )
}

/// `text` as a message may echo it: every [`hidden`] character written as its code point,
/// `[U+202E]`. Every error the core builds from user input (JSON paths and keys, YAML keys and
/// values, the course files' words, parameter names) goes through this (through [`cut`], and
/// [`ScenarioError`](crate::scenario::ScenarioError)'s constructors).
pub fn echo(text: &str) -> String {
    if !text.chars().any(hidden) {
        return text.to_string();
    }
    let mut s = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        if hidden(c) {
            s.push_str(&format!("[U+{:04X}]", c as u32));
        } else {
            s.push(c);
        }
    }
    s
}

/// `text` [`echo`]ed and cut to at most `max` characters (an ellipsis marks the cut): keys, names
/// and words echoed in titles and error messages, so a hostile file cannot make an error
/// megabytes long, nor turn it around.
pub fn cut(text: &str, max: usize) -> String {
    let text = echo(text);
    if text.chars().count() <= max {
        text
    } else {
        let mut s: String = text.chars().take(max.saturating_sub(1)).collect();
        s.push('…');
        s
    }
}

/// The bytes `v`'s items take (its length, not its capacity: see
/// [`Planner::stored_bytes`](crate::planners::Planner::stored_bytes)); what a run's memory limit
/// counts.
#[inline]
pub fn bytes_of<T>(v: &[T]) -> usize {
    std::mem::size_of_val(v)
}

/// The bytes a vector of vectors takes: each inner vector's header, and `items` items of `T` in
/// all (counted by the caller, so this is quick).
#[inline]
pub fn nested_bytes<T>(outer: usize, items: usize) -> usize {
    outer * std::mem::size_of::<Vec<T>>() + items * std::mem::size_of::<T>()
}

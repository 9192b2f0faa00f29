//! Scenario → grid → files: a scenario rasterised at a cell size, written as map_server writes a
//! map (a P5 PGM and its YAML) or as an 8-bit grey PNG.

use super::{cell_blocked, Occupancy, OccupancyGrid, FREE_THRESH, MAX_MAP_PIXELS, MAX_MAP_SIDE, OCCUPIED_THRESH};
use crate::geometry::{Aabb, Workspace};
use crate::limits;
use crate::math::{Real, Vec2};
use crate::scenario::{Scenario, ScenarioError};

/// The scenario rasterised at `cell` from its bounds' lower left corner: a cell is occupied when an
/// obstacle meets it ([`cell_blocked`]) or its centre is out of bounds.
pub fn scenario_to_grid(sc: &Scenario, cell: Real) -> Result<OccupancyGrid, ScenarioError> {
    let b = sc.bounds;
    if !(cell.is_finite() && cell >= limits::MIN_MAGNITUDE) {
        return Err(ScenarioError::at("cell", "must be a positive number"));
    }
    let (fx, fy) = (((b[2] - b[0]) / cell).ceil(), ((b[3] - b[1]) / cell).ceil());
    if !(fx.is_finite() && fy.is_finite())
        || fx > MAX_MAP_SIDE as Real
        || fy > MAX_MAP_SIDE as Real
        || fx * fy > MAX_MAP_PIXELS as Real
    {
        return Err(ScenarioError::at(
            "cell",
            format!(
                "{cell} makes a grid of {fx}×{fy} cells; the limits are {MAX_MAP_SIDE} a side and {MAX_MAP_PIXELS} in all"
            ),
        ));
    }
    let (w, h) = ((fx as usize).max(1), (fy as usize).max(1));
    let ws = Workspace::new(
        Aabb { min: Vec2::new(b[0], b[1]), max: Vec2::new(b[2], b[3]) },
        sc.obstacles.iter().map(crate::problem::shape_of).collect(),
    );
    let grid0 = OccupancyGrid { width: w, height: h, cells: Vec::new(), resolution: cell, origin: [b[0], b[1]] };
    let mut cells = Vec::with_capacity(w * h);
    for row in 0..h {
        let j = h - 1 - row;
        for c in 0..w {
            let (min, max) = (Vec2::new(grid0.x(c), grid0.y(j)), Vec2::new(grid0.x(c + 1), grid0.y(j + 1)));
            let centre = (min + max) * 0.5;
            let blocked = !ws.bounds.contains(centre) || cell_blocked(&ws, min, max);
            cells.push(if blocked { Occupancy::Occupied } else { Occupancy::Free });
        }
    }
    Ok(OccupancyGrid { cells, ..grid0 })
}

/// The grid as map_server writes it: a P5 PGM (occupied 0, free 254, unknown 205, as map_saver
/// does) and its YAML naming `image_name`.
pub fn to_pgm_yaml(grid: &OccupancyGrid, image_name: &str) -> (Vec<u8>, String) {
    let mut pgm =
        format!("P5\n# planarium occupancy map, {} per pixel\n{} {}\n255\n", grid.resolution, grid.width, grid.height)
            .into_bytes();
    pgm.extend(grid.cells.iter().map(|c| grey(*c)));
    let yaml = format!(
        "image: {image_name}\nresolution: {}\norigin: [{}, {}, 0.0]\nnegate: 0\noccupied_thresh: {OCCUPIED_THRESH}\nfree_thresh: {FREE_THRESH}\n",
        grid.resolution, grid.origin[0], grid.origin[1]
    );
    (pgm, yaml)
}

fn grey(c: Occupancy) -> u8 {
    match c {
        Occupancy::Free => 254,
        Occupancy::Occupied => 0,
        Occupancy::Unknown => 205,
    }
}

/// The grid as an 8-bit grey PNG (the same values as the PGM).
pub fn to_png(grid: &OccupancyGrid) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, grid.width as u32, grid.height as u32);
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(png::BitDepth::Eight);
        let data: Vec<u8> = grid.cells.iter().map(|c| grey(*c)).collect();
        let mut w = enc.write_header().expect("writing to a Vec does not fail");
        w.write_image_data(&data).expect("the data has the header's size");
    }
    out
}

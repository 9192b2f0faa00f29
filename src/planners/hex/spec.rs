//! The hexagonal decomposition's registry entry: what it is, its parameters, its capabilities (the
//! planner itself is in `mod.rs`).

use super::HexPotential;
use crate::events::EventKind;
use crate::planners::caps::{Capabilities, Draws, EventSet, Family, LegendItem};
use crate::planners::{ParamSpec, PlannerSpec, TaskKind};

/// The legend: the search's steps.
const LEGEND: &[LegendItem] = &[LegendItem::line("search steps, cell to cell", "tree0")];
/// The cells' marks.
const MARKS: &[LegendItem] = &[
    LegendItem::boxed("visited (closed) cell", "cellVisited"),
    LegendItem::boxed("open (A*, Dijkstra) or passable cell", "cellOpen"),
    LegendItem::boxed("step-blocked cell (×)", "cellBlocked"),
    LegendItem::line("later attempts: earlier trees faint", "tree0"),
];

/// The registry entry.
pub const SPEC: PlannerSpec = PlannerSpec {
    name: "hex-potential",
    label: "Hexagonal decomposition + potential",
    summary: "Report 002: hexagonal cells refined where obstacles are, searched by lowest potential, in a growing region of influence.",
    iteration: "One unit of work: one cell examined while the cells are made, or one step of the search.",
    checks: "State validity checks: the cells' labels and the step tests (the heat map's look-ahead, drawn only, is not counted).",
    params: PARAMS,
    groups: &[],
    task: TaskKind::Goal,
    caps: Capabilities {
        family: Family::Cells,
        draws: Draws::Cells,
        trees: 1,
        improves: false,
        chart: None,
        queries: false,
        proves_no_path: true,
        events: EventSet::of(&[EventKind::Cell, EventKind::CellShape, EventKind::CellState, EventKind::Potential, EventKind::Region, EventKind::Field, EventKind::NodeAdded, EventKind::Solved]),
        pseudocode: "cells-hex-potential",
        legend: LEGEND,
        marks: MARKS,
        overlays: &["cells", "region", "heat", "arrows"],
    },
    make: |si, task, params| Ok(Box::new(HexPotential::new(si, task, params)?)),
};

/// The planner's parameters.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec::real("cell_size", "Coarse cell size", 0.0, 1e6, 0.0, "Circumradius of the level-0 hexagons (0: an eighth of the map's shorter side)."),
    ParamSpec::int("levels", "Levels", 1.0, 10.0, 4.0, "Most levels of refinement, the coarse tiling included; each level halves the cell size."),
    ParamSpec::real("min_cell", "Smallest cell (× t)", 0.0, 100.0, 0.5, "Cells are not refined below this circumradius, as a multiple of the robot's diagonal t."),
    ParamSpec::choice(
        "refine",
        "Refine",
        &["mixed", "clearance"],
        0,
        "mixed: split cells an obstacle meets without covering (the report's rule); clearance: also split free cells within t/2 of an obstacle.",
    ),
    ParamSpec::real("k1", "k1 (repulsion)", 0.0, 1e6, 0.0005, "Gain of each obstacle's repulsion k1/r²."),
    ParamSpec::real("k2", "k2 (heading)", 0.0, 1e3, std::f64::consts::FRAC_1_PI, "Weight of the angle α between the step and the goal direction (1/π: the goal term falls to 0 at α = π)."),
    ParamSpec::real("c", "C (attraction)", 0.0, 1e6, 1.0, "Attraction toward the goal direction: the term −C(1 − k2·α)."),
    ParamSpec::real("k3", "k3 (trap)", 0.0, 1e6, 0.0, "The modified potential (report Q5): gain k3/r_j² of the trapping obstacle on its chosen side (0: the plain potential)."),
    ParamSpec::int("trap_obstacle", "Trapping obstacle", -1.0, 1e6, -1.0, "Index (from 0, in the scenario's order) of the obstacle j that gets k3 (-1: none)."),
    ParamSpec::choice("trap_side", "Trap side", &["below", "above", "left", "right"], 0, "Where k3 replaces k1: below obstacle j's lower edge (the report's case), above, left or right of it."),
    ParamSpec::real("influence", "Region of influence", 0.0, 1e6, 0.0, "Initial radius of the region of influence about the start (0: the start–goal distance plus t)."),
    ParamSpec::choice(
        "search",
        "Search",
        &["descent", "astar", "dijkstra"],
        0,
        "descent: the report's steps to the passable neighbour of lowest potential (it can get stuck); astar or dijkstra: a complete search of the same cells for the shortest way through their centres (it finds a way whenever the cells join start and goal).",
    ),
];

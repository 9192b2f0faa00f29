// What planners and robots can do, as the core says (its registry), and the one place that maps a
// capability to a drawing. The page learns the capabilities from the worker's `ready` message
// (`planners[].caps`, `robotKinds`; session.js calls `learn`) and keys overlays, legends, the
// explain panel, roadmap queries and the editor's modes on them, never on planner or robot names
// (scripts/check-names.mjs fails on a name in any other file of www/). A loaded scenario's own
// decisions (configuration-space view, optimum, solution file, draggable pose) come with the
// worker's `loaded` reply as `caps` (the core's `scene_caps`).
//
// Planner capabilities (registry_json, `caps`): {family, draws, trees, samples, tree_variants,
//   improves, chart, queries, proves_no_path, events: [EVENT_NAME], pseudocode, legend: [{label,
//   color, shape}], marks: [{label, color, shape}], overlays: [key]}; `color` is a PALETTE key.
// Robot kinds (robot_kinds): {name, label, drawn, body, sensor, cspace, course_cost, pose,
//   solution_file}.

import { PALETTE } from './palette.js';

/** @typedef {{label: string, color: string, shape: string}} LegendItem */
/**
 * @typedef {{family: string, draws: string, trees: number, samples: boolean, tree_variants: boolean,
 *   improves: boolean, chart: string | null, queries: boolean, proves_no_path: boolean, events: string[],
 *   pseudocode: string, legend: LegendItem[], marks: LegendItem[], overlays: string[]}} PlannerCaps
 */
/**
 * @typedef {{name: string, label: string, drawn: string, body: boolean, sensor: boolean, cspace: boolean,
 *   course_cost: string | null, pose: string, solution_file: boolean}} RobotCaps
 */

/** What a planner the page has not learnt about can do: nothing special, a tree drawn. */
const NO_PLANNER = Object.freeze(/** @type {PlannerCaps} */ ({
  family: '', draws: 'tree', trees: 2, samples: false, tree_variants: false, improves: false, chart: null,
  queries: false, proves_no_path: false, events: [], pseudocode: '', legend: [], marks: [], overlays: [],
}));
/** A robot kind the page has not learnt about: drawn as a dot, nothing to drag. */
const NO_ROBOT = Object.freeze(/** @type {RobotCaps} */ ({
  name: '', label: '', drawn: 'point', body: false, sensor: false, cspace: false, course_cost: null, pose: 'none',
  solution_file: false,
}));

/** @type {Map<string, PlannerCaps>} */
const planners = new Map();
/** @type {Map<string, RobotCaps>} */
const robots = new Map();

/**
 * Learn the core's registry: `planners` as the `ready` message's ({planners: [{name, caps}]} or the
 * list itself), `robotKinds` the robot kinds' records.
 * @param {{planners?: any, robotKinds?: any[]}} registry
 */
export function learn({ planners: list, robotKinds } = {}) {
  for (const p of (Array.isArray(list) ? list : list?.planners) || []) if (p?.caps) planners.set(p.name, Object.freeze(p.caps));
  for (const k of robotKinds || []) if (k?.name) robots.set(k.name, Object.freeze(k));
}

/** The capabilities of planner `name` (unknown: NO_PLANNER). @returns {PlannerCaps} */
export function plannerCaps(name) {
  return planners.get(name) ?? NO_PLANNER;
}

/** The record of a robot (a scenario's `robot` object) or robot kind name. @returns {RobotCaps} */
export function robotCaps(robot) {
  const kind = typeof robot === 'string' ? robot : robot?.kind;
  return robots.get(kind) ?? NO_ROBOT;
}

/** Whether the planner emits the event kind `name` (as events.js names it). */
export function emits(planner, name) {
  return plannerCaps(planner).events.includes(name);
}

// ---- Capabilities to drawings ----

/** A legend item of the registry with its colour taken from the palette. */
const painted = (/** @type {LegendItem} */ l) => ({ label: l.label, color: PALETTE[l.color] ?? PALETTE.tree0, shape: l.shape });

/** Two trees, when the page knows nothing of the planner. */
const DEFAULT_TREES = [
  { label: 'tree from the start (tree 0)', color: PALETTE.tree0, shape: 'line' },
  { label: 'tree from the goal (tree 1)', color: PALETTE.tree1, shape: 'line' },
];

/** The legend's lines for what planner `name` draws (trees, roadmap, graph). */
export function treeLegend(name) {
  const c = plannerCaps(name);
  return c.legend.length ? c.legend.map(painted) : DEFAULT_TREES;
}

/** The legend's marks of planner `name`'s cells and fields (after the robot). */
export function markLegend(name) {
  return plannerCaps(name).marks.map(painted);
}

/** Whether a missing palette colour or shape would leave a legend item undrawn (for tests). */
export const LEGEND_SHAPES = Object.freeze(['line', 'box', 'ring', 'dot', 'cross', 'dash', 'thick']);

/** The drawing of each `draws` capability: which of the view's layers its records fill. */
export const DRAWINGS = Object.freeze({
  tree: 'trees',
  roadmap: 'graphs',
  'exact-graph': 'graphs',
  cells: 'cells',
  grid: 'cells',
  field: 'cells',
});

/** The drawing of each robot `drawn` capability (robots.js, export-svg.js). */
export const ROBOT_DRAWINGS = Object.freeze({
  point: 'dot',
  polygon: 'polygons',
  'open-chain': 'linkage',
  'closed-chain': 'chain',
  // A spatial arm seen from above: its skeleton (the core's outline) ending at the tool; the page's
  // 3-D view draws it in full.
  'spatial-arm': 'skeleton',
});

/** How the robot of scenario `robot` is drawn: 'dot', 'polygons', 'linkage', 'chain' or 'skeleton'. */
export function robotDrawing(robot) {
  return ROBOT_DRAWINGS[robotCaps(robot).drawn] ?? 'dot';
}

/** Whether `robot`'s planning space is the workspace's plane (a point: distances and ranges drawn as they are). */
export function planeIsWorkspace(robot) {
  return robotCaps(robot).drawn === 'point';
}

/** Whether a start or goal of `robot` is dragged by its position (and, 'position-heading', turned). */
export function dragsPosition(robot) {
  const p = robotCaps(robot).pose;
  return p === 'position' || p === 'position-heading';
}

/** Whether a start or goal of `robot` has a heading to turn (a handle; its body to grab). */
export function dragsHeading(robot) {
  return robotCaps(robot).pose === 'position-heading';
}

/** Whether `robot`'s start and goal are joint angles (sliders; its end effector seen). */
export function posedByJoints(robot) {
  return robotCaps(robot).pose === 'joints';
}

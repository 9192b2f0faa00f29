// Event records streamed by the worker: fixed-stride Float64Array records
// [kind, tree, id, parent, x, y, px, py, c0, c1, pc0, pc1] (see src/events.rs). A test checks these
// constants against the wasm module's event_kinds().
export const STRIDE = 12;
export const EventKind = Object.freeze({
  SAMPLE: 0, // id: 1 the goal itself (goal bias)
  SAMPLE_REJECTED: 1,
  NODE_ADDED: 2,
  COLLISION: 3, // id: obstacle index (-2 map edge, -3 robot's own rule, -1 unknown), x y: where the body meets it (a point: the state), parent: node, px py: its point, c0 c1: the state's first numbers
  TREES_CONNECTED: 4,
  SOLVED: 5,
  SAMPLE_TRY: 6, // id: 1 free, 0 occupied
  DOMAIN: 7, // id: node, px: radius (Infinity: none)
  EXHAUSTED: 8, // id: node
  REWIRE: 9, // id: node, parent: its new parent (x, y; px, py)
  COST: 10, // id: best node, parent: iteration, px: cost
  COVERAGE: 11, // id: best node, parent: iteration, px: fraction, py: points seen
  POINT_SEEN: 12, // id: inspection point
  // Cell decomposition and potential fields (hex-potential, potential-field): see src/events.rs.
  CELL: 13, // tree: level, id, parent, x y: centre, px: label (0 free 1 mixed 2 full), py: radius, c0: vertex count
  CELL_SHAPE: 14, // id: cell, then up to 4 vertices (x y px py c0 c1 pc0 pc1; NaN unused)
  CELL_STATE: 15, // id: cell, parent: from cell, px: 0 passable 1 blocked 2 visited 3 outside region 4 obstacle, py: why blocked
  POTENTIAL: 16, // id: cell, parent: from, px: repulsion, py: trap term, c0: goal term, c1: total, pc0: alpha, pc1: chosen
  REGION: 17, // id: attempt, x y: centre, px: radius, py: final radius, c0: obstacles inside, c1: t
  FIELD: 18, // id, x y, px: value, py c0: terms, c1 pc0: direction, pc1: tile half-size
  MINIMUM: 19, // id: escapes so far, x y, px: potential, py: distance to goal
  // One growth step, for the explain panel: the node chosen, then the step steered from it.
  NEAREST: 20, // id: node, x y: its point, px py: the target, c0: distance, c1: domain radius, pc0: 1 target is a sample
  STEER: 21, // id: node, x y: the new state, px py: the node, c0: step, c1: range, pc0: 1 reaches the target
  // Roadmaps (prm, prm-star, lazy-prm): milestones are NODE_ADDED records with parent -1.
  ROADMAP_EDGE: 22, // id, parent: the two vertices (x y, px py); tree: 0 checked valid, 1 unchecked (lazy)
  EDGE_CHECKED: 23, // id, parent: the two vertices; tree: 0 valid, 1 invalid (removed)
  QUERY_PATH: 24, // id -> parent: one edge of a search's path; tree: 0 the path's first edge, 1 the others
  SELECT: 25, // EST: id: node picked, x y: its point, px: nodes in its cell, py: the cell's probability, c0: cells, c1 pc0: column, row, pc1: grid
  // The visibility graph: an edge between two graph vertices.
  GRAPH_EDGE: 26, // id, parent: the vertices, x y / px py: their points, c0: length, c1: 1 clear (kept), 0 blocked
  INFORMED: 27, // x y: the ellipse's centre, px py: its semi-axes, c0 c1: the major axis (unit), pc0: best cost, pc1: the foci's distance
});

/**
 * The set-up kinds (the core's EventKind::SETUP, checked against event_kinds().setup): what a
 * planner lays out before its decisions (cells and their outlines, a region of influence, a heat
 * map). A run of them is one step of the playback (pace.js).
 */
export const SETUP_KINDS = Object.freeze([EventKind.CELL, EventKind.CELL_SHAPE, EventKind.REGION, EventKind.FIELD]);

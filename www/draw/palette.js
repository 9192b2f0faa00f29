// Colours, how each event kind is drawn, and the switchable overlays: the tables the canvas
// views (view.js), the overlay box (overlays.js) and the browser tests share.
// Colours follow the Okabe–Ito palette where it matters (tree 0 / tree 1 / paths), so they stay
// distinguishable with the common colour-vision deficiencies (they also differ in lightness).

import { EventKind } from '../run/events.js';

export const PALETTE = Object.freeze({
  background: '#eef0f3',
  free: '#ffffff',
  bounds: '#30343b',
  obstacle: '#8c510a',  // brown: apart from the start (orange) and goal (green) for every colour-vision deficiency (tests/js/palette.test.mjs)
  obstacleEdge: '#543005',
  start: '#e67e00',
  goal: '#009e73',
  tree0: '#1f4e9a',
  tree1: '#cc79a7',
  rejected: '#8a8f98',
  collision: 'rgba(255, 236, 120, 0.85)', // pale yellow: seen on the brown obstacles where motions end
  sample: '#30343b',
  connect: '#111111',
  rawPath: '#ffb000',
  smoothPath: '#e0a800',
  pathCasing: '#3d2f00',
  robot: 'rgba(48, 52, 59, 0.55)',
  robotEdge: '#111111',
  inspection: '#56b4e9',
  handle: '#ffffff',
  accepted: '#2a9d8f',
  tryFree: '#4daf4a',
  tryOccupied: '#5e3c99',
  domain: '#b2182b',  // dark red rings: not the brown obstacles, not the purple occupied tries
  exhausted: '#b0b4ba',
  exhaustedEdge: '#4a4f57',
  rewire: '#e7298a',
  best: '#d55e00',
  bestCasing: '#ffffff',
  seen: '#ffd400',
  fov: '#9a7400',
  fovFill: 'rgba(255, 212, 0, 0.18)',
  chartLine: '#d55e00',
  chartTarget: '#009e73',
  chartAxis: '#5d6470',
  graphEdge: '#a9b4c2', // visibility-graph edges: light, under the search tree
  // cells and potential fields (cells.js): free cells light, darker by level; mixed amber; full grey;
  // visited (closed) blue, step-blocked pink (with a × mark) and, for A*/Dijkstra, open green, told
  // apart by lightness too
  cellFree: Object.freeze(['#f7f4ea', '#efe9d8', '#e6dec6', '#ddd3b4']),
  cellEdge: 'rgba(70, 60, 40, 0.32)',
  cellMixed: '#f6c86e',
  cellFull: '#8e949c',
  cellVisited: '#9cc2ea',
  cellOpen: '#b5e3a1',
  cellBlocked: '#f4b6d2',
  cellBlockedMark: '#a6165f',
  // the heat map: ColorBrewer YlGnBu (sequential, colour-blind safe), low potential light, high dark
  heat: Object.freeze(['#ffffd9', '#edf8b1', '#c7e9b4', '#7fcdbb', '#41b6c4', '#1d91c0', '#225ea8', '#253494', '#081d58']),
  arrow: 'rgba(29, 33, 39, 0.75)',
  region: '#7b3294',
  robotT: '#30343b',
  minimum: '#d01c8b',
  // the two forces at a local minimum (white halos keep them apart from the heat map)
  forcePull: '#d55e00',
  forcePush: '#1d2127',
  // roadmaps (prm, prm-star, lazy-prm): checked edges take tree0; Lazy PRM's unchecked edges are
  // dashed grey, an edge its check found blocked vermilion; the query's latest path dashed black
  roadmapUnchecked: '#9aa3ad',
  roadmapInvalid: 'rgba(213, 94, 0, 0.35)', // faint: on the zigzag most of Lazy PRM's checks find a wall
  queryPath: '#111111',
  queryAnswer: '#5e3c99', // another query on the finished roadmap: its path and its two clicks
  // EST's density grid: a cell shaded by its chance of being picked, the latest pick outlined
  density: '#cc79a7',
  // The informed set (Informed RRT*): its latest ellipse, the earlier ones faint
  informed: '#6a3d9a',
  densityPick: '#882255',
  // The 3-D view's arm posed by hand (www/ui/pose3d.js): blue when free, red when it collides (the
  // panel's text says which, for colour-blind users too)
  posed: '#0072b2',
  posedCollides: '#e8112d',
});

// How each event kind is drawn. `layer`: 'under', 'tree', 'over' (persistent, incremental),
// 'domain' (from the run model) or 'marker' (top layer, every frame). `toggle` names a view option
// that must be on for the kind to be drawn.
export const STYLE = Object.freeze({
  [EventKind.SAMPLE]: { layer: 'marker', shape: 'dot', color: PALETTE.sample, size: 3, label: 'latest sample' },
  [EventKind.SAMPLE_REJECTED]: { layer: 'under', shape: 'square', color: PALETTE.rejected, size: 2, toggle: 'showRejected', label: 'rejected sample' },
  [EventKind.NODE_ADDED]: { layer: 'tree', shape: 'edge', colors: [PALETTE.tree0, PALETTE.tree1], width: 1, size: 2, label: 'tree edge' },
  [EventKind.COLLISION]: { layer: 'over', shape: 'cross', color: PALETTE.collision, size: 2.5, width: 1, toggle: 'showCollisions', label: 'blocked motion' },
  [EventKind.TREES_CONNECTED]: { layer: 'marker', shape: 'ring', color: PALETTE.connect, size: 7, width: 2, label: 'trees connected' },
  [EventKind.SOLVED]: { layer: 'marker', shape: 'ring', color: PALETTE.goal, size: 10, width: 2, label: 'goal reached' },
  [EventKind.SAMPLE_TRY]: { layer: 'under', shape: 'square', colors: [PALETTE.tryOccupied, PALETTE.tryFree], size: 1.5, toggle: 'showTries', label: 'raw try of the sampler' },
  [EventKind.DOMAIN]: { layer: 'domain', shape: 'circle', color: PALETTE.domain, width: 1.5, toggle: 'showDomains', label: 'dynamic-domain radius' },
  [EventKind.EXHAUSTED]: { layer: 'tree', shape: 'square', color: PALETTE.exhausted, size: 5, toggle: 'showExhausted', label: 'exhausted node' },
  [EventKind.REWIRE]: { layer: 'marker', shape: 'edge', color: PALETTE.rewire, width: 2, size: 3, toggle: 'showRewires', label: 'rewired edge' },
  [EventKind.COST]: { layer: 'marker', shape: 'path', color: PALETTE.best, width: 3, toggle: 'showBest', label: 'best path so far' },
  [EventKind.POINT_SEEN]: { layer: 'marker', shape: 'diamond', color: PALETTE.seen, toggle: 'showSeen', label: 'inspection point seen' },
  // cells and fields (cells.js): the 'cells' layer, between the scene and the samples
  [EventKind.CELL]: { layer: 'cells', shape: 'polygon', colors: [PALETTE.cellFree, PALETTE.cellMixed, PALETTE.cellFull], widths: [1.6, 1.2, 0.9, 0.7], toggle: 'showCells', label: 'decomposition cell' },
  [EventKind.CELL_STATE]: { layer: 'cells', shape: 'polygon', colors: { 0: PALETTE.cellOpen, 1: PALETTE.cellBlocked, 2: PALETTE.cellVisited }, mark: PALETTE.cellBlockedMark, toggle: 'showCells', label: 'cell judged by the search' },
  [EventKind.FIELD]: { layer: 'cells', shape: 'tile', colors: PALETTE.heat, toggle: 'showHeat', label: 'potential heat map' },
  [EventKind.REGION]: { layer: 'marker', shape: 'circle', color: PALETTE.region, width: 2, toggle: 'showRegion', label: 'region of influence' },
  [EventKind.GRAPH_EDGE]: { layer: 'under', shape: 'edge', color: PALETTE.graphEdge, width: 1, label: 'graph edge' },
  [EventKind.MINIMUM]: { layer: 'marker', shape: 'ring', color: PALETTE.minimum, size: 11, width: 3, label: 'local minimum' },
  // roadmaps: edges on the tree layer (checked solid, unchecked dashed); the query's path on top
  [EventKind.ROADMAP_EDGE]: { layer: 'tree', shape: 'edge', colors: [PALETTE.tree0, PALETTE.roadmapUnchecked], width: 1, dash: [3, 3], label: 'roadmap edge: checked / unchecked' },
  [EventKind.EDGE_CHECKED]: { layer: 'tree', shape: 'edge', colors: [PALETTE.tree0, PALETTE.roadmapInvalid], width: 1.3, label: 'edge checked by a query: valid / blocked' },
  [EventKind.QUERY_PATH]: { layer: 'marker', shape: 'path', color: PALETTE.queryPath, width: 2, dash: [6, 4], label: "the graph search's latest path" },
});

// The switchable overlays, in the order of the overlay box: `option` is the view option, `swatches`
// the legend marks [{color, shape, label?}], `on` the default. `doc` is the box's tooltip.
export const OVERLAYS = Object.freeze([
  { option: 'showAccepted', id: 'show-accepted', label: 'accepted samples', on: false,
    swatches: [{ color: PALETTE.accepted, shape: 'dot' }],
    doc: 'Samples the planner grew toward (a sample not followed by a rejection).' },
  { option: 'showRejected', id: 'show-rejected', label: 'rejected samples', on: false,
    swatches: [{ color: PALETTE.rejected, shape: 'dot' }],
    doc: 'Samples that grew nothing: invalid, outside a dynamic domain, or their growth was blocked.' },
  { option: 'showTries', id: 'show-tries', label: "sampler's raw tries: free / occupied", on: false,
    swatches: [{ color: PALETTE.tryFree, shape: 'dot' }, { color: PALETTE.tryOccupied, shape: 'dot' }],
    doc: 'Every state a validity-checking sampler (gaussian, bridge, obstacle) drew and checked. After the first 50 000 of a run, the worker forwards a thinning share of them (see the stats).' },
  { option: 'showDomains', id: 'show-domains', label: 'dynamic-domain radii', on: true,
    swatches: [{ color: PALETTE.domain, shape: 'ring' }],
    doc: "Each node's latest dynamic-domain radius, drawn around its point. The radius is in the robot's metric: exact for a point robot; for other robots it is drawn in workspace units around the projected point, so only approximate." },
  { option: 'showExhausted', id: 'show-exhausted', label: 'exhausted nodes (greyed)', on: true,
    swatches: [{ color: PALETTE.exhausted, shape: 'box' }],
    doc: 'Nodes whose expansions failed too often (the tree variant "exhausted nodes").' },
  { option: 'showRewires', id: 'show-rewires', label: 'rewires (RRT*), flashing', on: true,
    swatches: [{ color: PALETTE.rewire, shape: 'line' }],
    doc: 'A node moved under a new parent: its new edge flashes for a moment (the tree is redrawn).' },
  { option: 'showBest', id: 'show-best', label: 'best path so far', on: true,
    swatches: [{ color: PALETTE.best, shape: 'thick' }],
    doc: 'The best solution (RRT*) or best inspection branch so far, back to the root, through projected points.' },
  { option: 'showSeen', id: 'show-seen', label: 'inspection points seen (lit)', on: true,
    swatches: [{ color: PALETTE.seen, shape: 'box' }],
    doc: 'Inspection points the planner has seen so far light up.' },
  { option: 'showFov', id: 'show-fov', label: "sensor's field of view", on: true,
    swatches: [{ color: PALETTE.fov, shape: 'box' }],
    doc: "The inspection sensor's wedge (range, ±fov/2) at the end effector of the robot shown: the start, then the animated robot along the path. During a run, a dashed ring of the range marks the best branch's tip (the events do not carry its heading)." },
  { option: 'showCollisions', id: 'show-collisions', label: 'blocked motions (×)', on: true,
    swatches: [{ color: PALETTE.collision, shape: 'cross' }],
    doc: 'Where a motion was found in collision.' },
  { option: 'showCells', id: 'show-cells', label: 'cells: free / mixed / full', on: true,
    swatches: [{ color: PALETTE.cellFree[0], shape: 'box' }, { color: PALETTE.cellMixed, shape: 'box' }, { color: PALETTE.cellFull, shape: 'box' }],
    doc: 'Hexagonal decomposition (hex-potential): each cell as it is made and labelled, free (lighter at coarser levels, thicker outline), mixed (an obstacle meets it: refined, or impassable at the finest level) or full; refined cells are covered by their children. During the search, visited cells turn blue and cells whose step test failed pink with a × (hover for why). Hover a cell for its level, state and potential terms.' },
  { option: 'showDensity', id: 'show-density', label: "EST's pick chance by cell", on: true,
    swatches: [{ color: '#cc79a7', shape: 'box' }, { color: '#882255', shape: 'ring' }],
    doc: "EST and bi-EST: the density grid over the map, each cell of the tree that picked last shaded by its chance of being picked next (darkest: the sparsest cell, 1 / its nodes, over the sum for all the tree's cells); the cell of the latest pick outlined. Empty cells hold no node, so they cannot be picked." },
  { option: 'showInformed', id: 'show-informed', label: 'informed set (ellipse), shrinking', on: true,
    swatches: [{ color: PALETTE.informed, shape: 'ring' }],
    doc: 'Once a path is found, only states whose distance from the start plus distance to the goal is below its cost can lie on a shorter path: in the plane, the ellipse with foci the start and the goal and major axis that cost. Informed RRT* samples only there; each better path shrinks it (the earlier ellipses stay, faint). For a rigid body the ellipse bounds the positions; the heading is free.' },
  { option: 'showHeat', id: 'show-heat', label: 'potential heat map (low → high)', on: false,
    swatches: [{ color: PALETTE.heat[1], shape: 'box' }, { color: PALETTE.heat[4], shape: 'box' }, { color: PALETTE.heat[8], shape: 'box' }],
    doc: "The potential field the planner reports, light where it is low, dark where it is high, by rank: each of the nine colours holds about a ninth of the samples, so the repulsion's blow-up near obstacles does not wash out the rest (hover a cell or tile for its numbers); where the robot would collide it takes the obstacle colour. hex-potential: each free cell in the region of influence, coloured by its obstacle terms (repulsion + trap term; the goal term depends on the step); potential-field: a grid of tiles, coloured by attraction + repulsion. A new region of influence replaces it." },
  { option: 'showArrows', id: 'show-arrows', label: 'descent directions (arrows)', on: false,
    swatches: [{ color: PALETTE.arrow, shape: 'line' }],
    doc: 'At each heat-map sample, the way the robot would move from there: hex-potential: toward the passable neighbour of lowest potential (visited marks ignored); potential-field: along the negative gradient. Thinned where the samples are tiny.' },
  { option: 'showRegion', id: 'show-region', label: 'region of influence, t/2 circle', on: true,
    swatches: [{ color: PALETTE.region, shape: 'ring' }, { color: PALETTE.robotT, shape: 'dash' }],
    doc: "hex-potential: the region of influence (dashed), the search's bounds; each time it grows the older radii stay, faint. Around the animated robot, a dashed circle of radius t/2, t being the robot's diagonal (the room it needs to turn on the spot)." },
]);

/** The overlays' default view options. */
export const OVERLAY_DEFAULTS = Object.freeze(Object.fromEntries(OVERLAYS.map((o) => [o.option, o.on])));

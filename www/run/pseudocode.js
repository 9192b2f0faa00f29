// Each planner's pseudocode, keyed by its registry entry's `caps.pseudocode` (src/planners/caps.rs):
// the lines the explain panel shows, each with an id the Explainer (explain.js) puts the panel on.
// A line with `when` is shown only for the set-ups it applies to (optionsOf). A new planner's entry
// goes here, under the key its registry entry names; tests/js/capabilities.test.mjs fails on a
// registered planner without one.

import { plannerCaps } from '../draw/capabilities.js';

/**
 * @typedef {{id: string, text: string, indent?: number, when?: (o: Options) => boolean}} Line
 * @typedef {{sampler?: string, goalBias?: number, share?: boolean, connect?: boolean, domain?: boolean, exhausted?: boolean,
 *   weighted?: boolean, ladder?: boolean, lastFree?: boolean, escape?: string, vertices?: boolean, search?: string}} Options
 * @typedef {{title: string, lines: Line[], choosesParent?: boolean}} Pseudocode  (choosesParent: what the Explainer says of a parent that is not the nearest node)
 */

const descent = (o) => !o.search || o.search === 'descent'; // hex-potential: the report's search
export const complete = (o) => !descent(o); // hex-potential: A* or Dijkstra over the same cells
const lastFree = (o) => !!o.lastFree; // RRT-Connect's `connect: last-free` (the Robotics Library's RrtConCon)
const range = (o) => !o.lastFree;
const sampled = (o) => o.goalBias === undefined || o.goalBias > 0; // unset: the planner's default, which may bias
const SAMPLER_LINES = /** @type {Line[]} */ ([
  { id: 'goal', text: 'with probability goal_bias: q_rand ← q_goal', indent: 2, when: sampled },
  { id: 'share', text: 'else with probability uniform_share: q_rand ← a plain uniform draw', indent: 2, when: (o) => !!o.share },
  { id: 'try', text: 'SAMPLE(): uniform draws, checked', indent: 2, when: (o) => !!o.sampler && o.sampler !== 'uniform' && o.sampler !== 'goal-biased' },
]);

// The ladder move's line, under a step's check (RRT and RRT-Connect's `ladder` parameter).
const LADDER = /** @type {Line} */ ({
  id: 'ladder',
  text: 'else try up to L steps moving a random half of the coordinates (ladder); the first free one becomes q_new',
  when: (o) => !!o.ladder,
});

// The tree variants' lines, under NEAREST (RRT and RRT-Connect grow with them).
const VARIANT_LINES = /** @type {Line[]} */ ([
  { id: 'exhausted', text: 'skip nodes that failed too often (exhausted)', indent: 2, when: (o) => !!o.exhausted },
  { id: 'domain', text: 'if d > r(q_near): reject (dynamic domain)', indent: 2, when: (o) => !!o.domain },
]);

/** @type {Record<string, Pseudocode>} */
export const PSEUDOCODE = {
  'tree-rrt': {
    title: 'RRT (LaValle 1998)',
    lines: [
      { id: 'init', text: 'T ← {q_start}' },
      { id: 'loop', text: 'repeat' },
      { id: 'sample', text: 'q_rand ← SAMPLE()', indent: 1 },
      ...SAMPLER_LINES,
      { id: 'nearest', text: 'q_near ← NEAREST(T, q_rand)', indent: 1 },
      ...VARIANT_LINES,
      { id: 'steer', text: 'q_new ← STEER(q_near, q_rand, range)', indent: 1 },
      { id: 'check', text: 'if not MOTION_FREE(q_near, q_new): reject', indent: 1 },
      { ...LADDER, indent: 2 },
      { id: 'add', text: 'T ← T ∪ {q_new}, parent(q_new) ← q_near', indent: 1 },
      { id: 'connect', text: 'connect: steer again toward q_rand until reached or blocked', indent: 2, when: (o) => !!o.connect },
      { id: 'goal-check', text: 'if dist(q_new, q_goal) ≤ tolerance: return PATH(q_new)', indent: 1 },
    ],
  },
  'tree-rrt-connect': {
    title: 'RRT-Connect (Kuffner & LaValle 2000)',
    // `connect: last-free`: the Robotics Library's RrtConCon (report 001's course), with its own lines
    lines: [
      { id: 'init', text: 'T_a ← {q_start}, T_b ← {q_goal}' },
      { id: 'loop', text: 'repeat' },
      { id: 'sample', text: 'q_rand ← SAMPLE()', indent: 1 },
      ...SAMPLER_LINES,
      { id: 'nearest', text: 'EXTEND(T_a, q_rand): q_near ← NEAREST(T_a, q_rand)', indent: 1, when: range },
      { id: 'nearest', text: 'CONNECT(T_a, q_rand): q_near ← NEAREST(T_a, q_rand)', indent: 1, when: lastFree },
      ...VARIANT_LINES,
      { id: 'steer', text: 'q_new ← STEER(q_near, q_rand, range)', indent: 2, when: range },
      { id: 'check', text: 'if not MOTION_FREE(q_near, q_new): reject', indent: 2, when: range },
      { id: 'steer', text: 'for q ← q_near + δ, q_near + 2δ, … along the line to q_rand (δ: the resolution):', indent: 2, when: lastFree },
      { id: 'check', text: 'if q collides (one query each): stop', indent: 3, when: lastFree },
      { ...LADDER, indent: 3, when: (o) => !!o.ladder && range(o) },
      { id: 'add', text: 'add q_new to T_a', indent: 2, when: range },
      { id: 'add', text: 'only the last free q becomes q_new, added to T_a under q_near (none free: next iteration)', indent: 2, when: lastFree },
      { id: 'c-nearest', text: 'CONNECT(T_b, q_new): q_near ← NEAREST(T_b, q_new)', indent: 1 },
      { id: 'c-steer', text: 'repeat: q ← STEER(q_near, q_new, range)', indent: 2, when: range },
      { id: 'c-check', text: 'until blocked: MOTION_FREE fails', indent: 2, when: range },
      { id: 'c-steer', text: 'for q ← q_near + δ, q_near + 2δ, … along the line to q_new:', indent: 2, when: lastFree },
      { id: 'c-check', text: 'if q collides (one query each): stop', indent: 3, when: lastFree },
      { ...LADDER, id: 'c-ladder', text: 'else try up to L steps moving a random half of the coordinates (ladder): add the first free one, and stop', indent: 3, when: (o) => !!o.ladder && range(o) },
      { id: 'c-add', text: 'add q to T_b', indent: 2, when: range },
      { id: 'c-add', text: 'only the last free q becomes a node of T_b, under q_near', indent: 2, when: lastFree },
      { id: 'met', text: 'if q = q_new: the trees meet: return PATH', indent: 1, when: range },
      { id: 'met', text: 'if |q − q_new| ≤ ε: the trees meet: return PATH', indent: 1, when: lastFree },
      { id: 'swap', text: 'swap T_a and T_b', indent: 1 },
    ],
  },
  'tree-rrt-star': {
    title: 'RRT* (Karaman & Frazzoli 2011)',
    choosesParent: true, // a node's parent is the cheapest of its neighbours, not always the nearest
    lines: [
      { id: 'init', text: 'T ← {q_start}' },
      { id: 'loop', text: 'repeat' },
      { id: 'sample', text: 'q_rand ← SAMPLE()', indent: 1 },
      ...SAMPLER_LINES,
      { id: 'nearest', text: 'q_near ← NEAREST(T, q_rand)', indent: 1 },
      { id: 'steer', text: 'q_new ← STEER(q_near, q_rand, range)', indent: 1 },
      { id: 'check', text: 'if not MOTION_FREE(q_near, q_new): reject', indent: 1 },
      { id: 'add', text: 'Q_near ← NEAR(T, q_new); parent ← cheapest valid in Q_near', indent: 1 },
      { id: 'rewire', text: 'REWIRE: for q in Q_near cheaper through q_new: parent(q) ← q_new', indent: 1 },
      { id: 'cost', text: 'if a goal node got cheaper: best ← its cost', indent: 1 },
      { id: 'goal-check', text: 'return the best path when time or iterations run out', indent: 1 },
    ],
  },
  'tree-inspection': {
    title: 'Inspection planning (IRIS-style tree, Technion course)',
    lines: [
      { id: 'init', text: 'T ← {q_start}, seen(q_start) ← S(q_start)' },
      { id: 'loop', text: 'repeat' },
      { id: 'sample', text: 'q_rand ← SAMPLE()', indent: 1 },
      ...SAMPLER_LINES,
      { id: 'nearest', text: 'q_src ← the node chosen to grow toward q_rand', indent: 1 },
      { id: 'steer', text: 'q_new ← STEER(q_src, q_rand, range)', indent: 1 },
      { id: 'check', text: 'if not MOTION_FREE(q_src, q_new): reject', indent: 1 },
      { id: 'add', text: 'parent ← the near node through which q_new sees most', indent: 1 },
      { id: 'seen', text: 'seen(q_new) ← seen(parent) ∪ points seen on the way', indent: 1, when: (o) => !o.vertices },
      { id: 'seen', text: 'seen(q_new) ← seen(parent) ∪ points seen at q_new (the course counts vertices only)', indent: 1, when: (o) => !!o.vertices },
      { id: 'rewire', text: 'rewire near nodes that see more (or as much, cheaper) through q_new', indent: 1 },
      { id: 'cost', text: 'if |seen(q_new)| beats the best branch: best ← q_new', indent: 1 },
      { id: 'goal-check', text: 'when coverage ≥ target: return PATH(best)', indent: 1 },
    ],
  },
  'cells-hex-potential': {
    title: 'Hexagonal decomposition + potential fields (report 002)',
    lines: [
      { id: 'cells', text: 'tile the map with hexagons; split mixed cells, level by level' },
      { id: 'region', text: 'region ← a disc of influence around the start', when: descent },
      { id: 'field', text: 'potential of each free cell in the region (heat map)', indent: 1, when: descent },
      { id: 'loop', text: 'repeat from the robot\'s cell', when: descent },
      { id: 'judge', text: 'test the step to each neighbouring free cell', indent: 1, when: descent },
      { id: 'potential', text: 'U = repulsion + trap term − C(1 − k2·α) for each passable one', indent: 1, when: descent },
      { id: 'add', text: 'step to the lowest U; mark the cell left visited', indent: 1, when: descent },
      { id: 'grow', text: 'stuck: double the region and start again', indent: 1, when: descent },
      { id: 'goal-check', text: 'goal cell in reach and its step is free: done', indent: 1, when: descent },
      { id: 'open', text: 'open ← {start}, g(start) = 0 (the region plays no part)', when: complete },
      { id: 'close', text: 'close the open cell of least g + h (A*: h = distance to the goal; Dijkstra: h = 0)', when: complete },
      { id: 'judge', text: 'test the step to each neighbouring free cell; open it if the way through here is shorter', indent: 1, when: complete },
      { id: 'goal-check', text: 'goal cell in reach and its step is free: open the goal', indent: 1, when: complete },
      { id: 'add', text: 'goal closed: step along its shortest way (none open: no path at this resolution)', when: complete },
    ],
  },
  'cells-grid-search': {
    title: 'Grid search: A*, Dijkstra, breadth-first, wavefront (PathFinding.js\'s choices)',
    lines: [
      { id: 'cells', text: 'cut the map into square cells; a cell an obstacle touches is blocked' },
      { id: 'open', text: 'open ← {start}, g(start) = 0', when: (o) => o.search !== 'wavefront' },
      { id: 'open', text: 'wave ← {goal}: number the cells by moves from the goal', when: (o) => o.search === 'wavefront' },
      { id: 'close', text: 'close the open cell of least key (A*: g + weight·h; Dijkstra: g; BFS and wave: moves)' },
      { id: 'judge', text: 'each neighbour (8 without crossing corners, or 4): open it if the way through here is shorter', indent: 1 },
      { id: 'goal-check', text: 'the far end in reach and the motion to it free: open it', indent: 1 },
      { id: 'add', text: 'far end closed: walk its way (the wave: down the numbers from the start)' },
    ],
  },
  'tree-est': {
    title: 'EST: expansive-space tree (Hsu, Latombe & Motwani 1997; the grid form of OMPL)',
    lines: [
      { id: 'init', text: 'T ← {q_start}; each node filed in a cell of a grid over the map' },
      { id: 'loop', text: 'repeat' },
      { id: 'select', text: 'pick a cell with probability ∝ 1 / (its nodes), then a node q of it', indent: 1 },
      { id: 'goal', text: 'with probability goal_bias: q_new ← q_goal', indent: 1, when: sampled },
      { id: 'sample', text: 'q_new ← a random state within range of q (each coordinate)', indent: 1 },
      { id: 'check', text: 'the motion q → q_new blocked: next iteration', indent: 1 },
      { id: 'add', text: 'add q_new under q; file it in its cell', indent: 1 },
      { id: 'goal-check', text: 'q_goal within range and the motion to it is free: done', indent: 1 },
    ],
  },
  'tree-bi-est': {
    title: 'Bidirectional EST (two ESTs taking turns, as OMPL\'s BiEST)',
    lines: [
      { id: 'init', text: 'T_a ← {q_start}, T_b ← {q_goal}; nodes filed in grid cells' },
      { id: 'loop', text: 'repeat, T_a and T_b taking turns' },
      { id: 'select', text: 'pick a cell of T_a with probability ∝ 1 / (its nodes), then a node q of it', indent: 1 },
      { id: 'sample', text: 'q_new ← a random state within range of q (each coordinate)', indent: 1 },
      { id: 'check', text: 'a motion blocked: next iteration', indent: 1 },
      { id: 'add', text: 'add q_new under q; file it in its cell', indent: 1 },
      { id: 'met', text: 'T_b\'s nearest node within range and the motion free: the trees meet, done', indent: 1 },
    ],
  },
  'exact-visibility-graph': {
    title: 'Visibility graph + A* (Lozano-Pérez & Wesley 1979)',
    lines: [
      { id: 'init', text: 'grow the obstacles by the robot\'s disc (and a margin); V ← {q_start, q_goal} ∪ convex corners' },
      { id: 'loop', text: 'for each pair (u, v) tangent at both ends' },
      { id: 'edge', text: 'if the segment u v crosses no grown interior: E ← E ∪ {u v}', indent: 1 },
      { id: 'add', text: 'A*: settle the open vertex of least g + |v − q_goal|, parent ← its best neighbour' },
      { id: 'cost', text: 'q_goal settled: its g is the shortest cost' },
      { id: 'goal-check', text: 'check the path with MOTION_FREE and return it' },
    ],
  },
  'field-potential': {
    title: 'Artificial potential field (Khatib 1986; escapes: Barraquand & Latombe 1991)',
    lines: [
      { id: 'field', text: 'U(q) = U_att(q) + U_rep(q) (heat map)' },
      { id: 'loop', text: 'repeat' },
      { id: 'add', text: 'q ← q − step · ∇U / |∇U| (halved while the motion collides)', indent: 1 },
      { id: 'minimum', text: 'not min_progress closer to the goal in the last window steps: stuck in a local minimum (the pull and the push cancel)', indent: 1 },
      { id: 'walk', text: 'escape: a random walk, then descend again', indent: 2, when: (o) => o.escape !== 'give-up' },
      { id: 'stop', text: 'stop there: no path (escape set to give-up)', indent: 2, when: (o) => o.escape === 'give-up' },
      { id: 'goal-check', text: 'goal within a step and the motion is free: done', indent: 1 },
    ],
  },
};

// Informed RRT* (Gammell, Srinivasa & Barfoot 2014) is RRT* whose samples, once it has a path, come
// from the informed set: RRT*'s lines, with its sampling and the set's shrinking said.
PSEUDOCODE['tree-informed-rrt-star'] = {
  title: 'Informed RRT* (Gammell, Srinivasa & Barfoot 2014)',
  choosesParent: true,
  lines: PSEUDOCODE['tree-rrt-star'].lines.flatMap((l) => {
    if (l.id === 'init') return [{ ...l, text: 'T ← {q_start}, c_best ← ∞' }];
    if (l.id === 'sample') return [{ ...l, text: 'q_rand ← SAMPLE() while c_best = ∞, else a uniform state of the informed set' }];
    if (l.id === 'cost') {
      return [{ ...l, text: 'if a goal node got cheaper: c_best ← its cost' },
        { id: 'informed', text: 'informed set ← {q : d(q_start, q) + d(q, q_goal) < c_best}: an ellipse, shrinking', indent: 2 }];
    }
    return [l];
  }),
};

// The roadmaps (src/planners/roadmap/): one milestone per iteration, then a query when it changed.
const ROADMAP_HEAD = /** @type {Line[]} */ ([
  { id: 'init', text: 'V ← {q_start, q_goal}, E ← ∅' },
  { id: 'loop', text: 'repeat' },
  { id: 'sample', text: 'q ← SAMPLE()', indent: 1 },
  ...SAMPLER_LINES,
  { id: 'valid', text: 'if not VALID(q): reject', indent: 1 },
  { id: 'add', text: 'V ← V ∪ {q} (a milestone)', indent: 1 },
]);
const EAGER_TAIL = /** @type {Line[]} */ ([
  { id: 'check', text: "if MOTION_FREE(q, q'): E ← E ∪ {(q, q')}", indent: 2 },
  { id: 'query', text: 'if q_start and q_goal share a component: return A*(q_start, q_goal) over (V, E)', indent: 1 },
]);
PSEUDOCODE['roadmap-prm'] = {
  title: 'PRM (Kavraki, Švestka, Latombe & Overmars 1996)',
  lines: [...ROADMAP_HEAD, { id: 'near', text: "for q' in the k nearest of q (or those within the radius):", indent: 1 }, ...EAGER_TAIL],
};
PSEUDOCODE['roadmap-prm-star'] = {
  title: 'PRM* (Karaman & Frazzoli 2011)',
  lines: [...ROADMAP_HEAD, { id: 'near', text: "for q' in the k(n) = ⌈e(1 + 1/d)·ln n⌉ nearest of q (or within r(n)):", indent: 1 },
    EAGER_TAIL[0],
    { id: 'query', text: 'if q_start and q_goal share a component: path ← A*(q_start, q_goal) over (V, E)', indent: 1 },
    { id: 'cost', text: 'if cost(path) < best: best ← path; improve_for milestones after the first, return best', indent: 2 }],
};
PSEUDOCODE['roadmap-lazy-prm'] = {
  title: 'Lazy PRM (Bohlin & Kavraki 2000)',
  lines: [
    ...ROADMAP_HEAD,
    { id: 'edge', text: "for q' in the k nearest of q: E ← E ∪ {(q, q')}, unchecked", indent: 1 },
    { id: 'query', text: 'while q_start and q_goal share a component:', indent: 1 },
    { id: 'search', text: 'path ← A*(q_start, q_goal) over (V, E)', indent: 2 },
    { id: 'lazy-check', text: 'check its unchecked edges in order; a blocked one leaves E: search again', indent: 2 },
    { id: 'goal-check', text: 'every edge free: return path', indent: 2 },
  ],
};

/** The pseudocode of `planner` (by its registry's `caps.pseudocode` key) with only the lines `options` apply (null for an unknown planner). */
export function pseudocode(planner, options = {}) {
  const p = PSEUDOCODE[plannerCaps(planner).pseudocode];
  if (!p) return null;
  return { title: p.title, lines: p.lines.filter((l) => !l.when || l.when(options)) };
}

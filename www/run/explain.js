// The explain panel's model: each planner's pseudocode, and a reader of the event stream that says,
// for every event, which line of it the planner was on and what happened, in words ("sample
// (0.31, 0.72) → nearest #52 at 0.41 → step 0.28 → blocked by obstacle 3"). Everything it says
// comes from the records the core emitted (src/events.rs), so it is true by construction: the
// numbers are the records' numbers, the node ids the core's. No DOM here (ui/explain-panel.js shows
// it, draw/actors.js draws the step's actors); tests/js/explain.test.mjs and the browser test step
// each planner and check line and caption against the events.

import { EventKind as K, STRIDE } from './events.js';
import { plannerCaps, planeIsWorkspace } from '../draw/capabilities.js';

/**
 * @typedef {{id: string, text: string, indent?: number, when?: (o: Options) => boolean}} Line
 * @typedef {{sampler?: string, goalBias?: number, share?: boolean, connect?: boolean, domain?: boolean, exhausted?: boolean,
 *   weighted?: boolean, ladder?: boolean, escape?: string, vertices?: boolean, search?: string}} Options
 * @typedef {{title: string, lines: Line[], choosesParent?: boolean}} Pseudocode  (choosesParent: what the Explainer says of a parent that is not the nearest node)
 */

const descent = (o) => !o.search || o.search === 'descent'; // hex-potential: the report's search
const complete = (o) => !descent(o); // hex-potential: A* or Dijkstra over the same cells
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
    lines: [
      { id: 'init', text: 'T_a ← {q_start}, T_b ← {q_goal}' },
      { id: 'loop', text: 'repeat' },
      { id: 'sample', text: 'q_rand ← SAMPLE()', indent: 1 },
      ...SAMPLER_LINES,
      { id: 'nearest', text: 'EXTEND(T_a, q_rand): q_near ← NEAREST(T_a, q_rand)', indent: 1 },
      ...VARIANT_LINES,
      { id: 'steer', text: 'q_new ← STEER(q_near, q_rand, range)', indent: 2 },
      { id: 'check', text: 'if not MOTION_FREE(q_near, q_new): reject', indent: 2 },
      { ...LADDER, indent: 3 },
      { id: 'add', text: 'add q_new to T_a', indent: 2 },
      { id: 'c-nearest', text: 'CONNECT(T_b, q_new): q_near ← NEAREST(T_b, q_new)', indent: 1 },
      { id: 'c-steer', text: 'repeat: q ← STEER(q_near, q_new, range)', indent: 2 },
      { id: 'c-check', text: 'until blocked: MOTION_FREE fails', indent: 2 },
      { ...LADDER, id: 'c-ladder', text: 'else try up to L steps moving a random half of the coordinates (ladder): add the first free one, and stop', indent: 3 },
      { id: 'c-add', text: 'add q to T_b', indent: 2 },
      { id: 'met', text: 'if q = q_new: the trees meet: return PATH', indent: 1 },
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
      { id: 'minimum', text: 'no progress over the window: a local minimum', indent: 1 },
      { id: 'walk', text: 'escape: a random walk, then descend again', indent: 2, when: (o) => o.escape !== 'give-up' },
      { id: 'goal-check', text: 'goal within a step and the motion is free: done', indent: 1 },
    ],
  },
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

const NARROW_SAMPLERS = ['gaussian', 'bridge', 'obstacle', 'near-collision'];

/** The options the pseudocode shows, from a planner set-up {planner, params}. */
export function optionsOf(config) {
  const p = config?.params || {};
  return {
    sampler: p.sampler,
    // the narrow-passage samplers draw a share of plain uniform samples unless it is 0 (default 0.1)
    share: NARROW_SAMPLERS.includes(p.sampler) && (p.uniform_share === undefined || Number(p.uniform_share) > 0),
    goalBias: p.goal_bias === undefined ? undefined : Number(p.goal_bias),
    connect: p.extend === 'connect',
    domain: Number(p.dd_radius) > 0,
    exhausted: Number(p.exhausted) > 0,
    ladder: Number(p.ladder) > 0,
    weighted: p.exhausted_policy === 'weighted',
    escape: p.escape,
    search: p.search,
  };
}

/** A number as the captions write it: 3 significant digits, no exponent for ordinary values. */
export function num(v) {
  if (!Number.isFinite(v)) return v > 0 ? '∞' : v < 0 ? '−∞' : '?';
  const a = Math.abs(v);
  if (a !== 0 && (a < 1e-3 || a >= 1e5)) return v.toExponential(2).replace('-', '−');
  const s = Number(v.toPrecision(3)).toString();
  return s.replace('-', '−');
}
const pt = (x, y) => `(${num(x)}, ${num(y)})`;

/** What blocked a motion, from a COLLISION record's id (src/space_info.rs, SpaceInfo::blocked_at). */
export function blockerText(id) {
  if (id >= 0) return `blocked by obstacle ${id}`;
  if (id === -2) return 'blocked by the map\'s edge';
  if (id === -3) return 'blocked by the robot\'s own rule (self-collision, a joint limit, or a chain\'s area or convexity)';
  return 'refused (not checked in time)';
}

const HEX_WHY = ['', 'an obstacle vertex in the t/2 circle', 'a vertex in the swept rectangle', 'an obstacle edge crossing the region', 'the map\'s edge'];
const TREE_NAME = (planner, tree) => (plannerCaps(planner).trees === 2 ? (tree === 0 ? 'start tree' : 'goal tree') : 'tree');

/**
 * Reads records one at a time and keeps what the current step has said: the line, the caption
 * (the step's parts joined by " → "), and the step's actors for the canvas (sample, nearest node,
 * target, range, new edge, collision).
 */
export class Explainer {
  /**
   * `planner`: the registry name; `robot`: the scenario's robot kind (one whose planning space is
   * the plane has its range drawn); `options`: what `optionsOf` reads from the set-up (hex-potential's
   * search). What the planner does is read from its capabilities (capabilities.js) and the lines of
   * its pseudocode, never from its name.
   */
  constructor(planner = '', robot = '', options = /** @type {Options} */ ({})) {
    this.planner = planner;
    this.robot = robot;
    const caps = plannerCaps(planner);
    const code = PSEUDOCODE[caps.pseudocode];
    const has = (id) => !!code?.lines.some((l) => l.id === id);
    this.twoTrees = caps.trees === 2;
    this.roadmap = caps.draws === 'roadmap';
    this.density = caps.events.includes('SELECT');      // EST: a step starts by picking a node
    this.connects = has('c-nearest');                    // RRT-Connect's CONNECT
    this.extendConnects = has('connect');                // RRT's extend = connect
    this.lazy = has('lazy-check');                       // Lazy PRM: edges checked on the path
    this.choosesParent = !!code?.choosesParent;          // RRT*: the cheapest neighbour is the parent
    this.grid = caps.draws === 'grid';
    this.cells = caps.family === 'cells';
    this.exact = caps.draws === 'exact-graph';
    this.field = caps.family === 'field';
    this.stepStart = caps.samples || this.density;       // readStore: steps begin at a SAMPLE or SELECT
    this.rangeDrawn = planeIsWorkspace(robot);
    this.complete = (caps.draws === 'cells' && complete(options)) || this.grid;
    this.reset();
  }

  reset() {
    this.line = 'init';
    this.parts = [];
    this.actors = {};
    this.events = 0;
    this.connecting = false; // RRT-Connect: in CONNECT (growing the other tree toward q_new)
    this.pathEdges = 0;      // roadmaps: edges of the search's path read so far
  }

  /** Start a new step's caption. */
  begin(text) {
    this.parts = [text];
    this.actors = {};
  }

  /** Add to the step's caption (a long CONNECT keeps its first parts and the last few). */
  then(text) {
    this.parts.push(text);
    if (this.parts.length > 8) this.parts.splice(2, this.parts.length - 7, '…');
  }

  /**
   * Read one record: STRIDE numbers of `r` from offset `o` (an array, or a chunk of the record
   * store: no copy is made). Then `line` is the pseudocode line's id and `caption` the step's
   * words.
   */
  read(r, o = 0) {
    this.events++;
    const kind = r[o], tree = r[o + 1], id = r[o + 2], parent = r[o + 3];
    const x = r[o + 4], y = r[o + 5], px = r[o + 6], py = r[o + 7], c0 = r[o + 8], c1 = r[o + 9], pc0 = r[o + 10], pc1 = r[o + 11];
    const A = this.actors;
    switch (kind) {
      case K.SAMPLE_TRY:
        if (!this.parts.length || this.line !== 'try') this.begin(`sampler tries ${pt(x, y)}: ${id === 1 ? 'free' : 'occupied'}`);
        else this.then(`tries ${pt(x, y)}: ${id === 1 ? 'free' : 'occupied'}`);
        this.line = 'try';
        (A.tries ||= []).push([x, y, id === 1]);
        break;
      case K.SELECT:
        this.begin(`the ${TREE_NAME(this.planner, tree)} picks #${id}: its cell holds ${px} node${px === 1 ? '' : 's'} (probability ${num(py)} of ${c0} cells)`);
        A.near = [x, y];
        A.nearId = id;
        this.line = 'select';
        break;
      case K.SAMPLE: {
        if (this.density) {
          this.then(id === 1 ? `sample q_goal ${pt(x, y)} (goal bias)` : `sample ${pt(x, y)} within range of it`);
          A.sample = [x, y];
          this.line = id === 1 ? 'goal' : 'sample';
          break;
        }
        const tries = this.line === 'try' ? A.tries : undefined;
        this.connecting = false;
        this.begin(id === 1 ? `sample q_goal ${pt(x, y)} (goal bias)` : id === 2 ? `sample ${pt(x, y)} (uniform share)` : `sample ${pt(x, y)}`);
        if (tries) this.actors.tries = tries;
        this.actors.sample = [x, y];
        this.line = id === 1 ? 'goal' : id === 2 ? 'share' : 'sample';
        if (this.connects) this.parts[0] += ` for the ${TREE_NAME(this.planner, tree)}`;
        break;
      }
      case K.NEAREST: {
        const toSample = pc0 === 1;
        if (!toSample && this.connects) {
          if (!this.connecting) {
            const sample = A.sample;
            this.begin(`CONNECT the ${TREE_NAME(this.planner, tree)} toward ${pt(px, py)}`);
            if (sample) this.actors.sample = sample;
          }
          this.connecting = true;
        }
        this.then(`nearest #${id} at ${num(c0)}`);
        const N = this.actors;
        N.near = [x, y];
        N.target = [px, py];
        N.nearId = id;
        N.domain = Number.isFinite(c1) ? c1 : null;
        N.edge = undefined;
        N.range = undefined;
        N.collision = undefined;
        N.blocked = false;
        if (!toSample) N.sample ||= [px, py];
        this.line = this.connecting ? 'c-nearest' : toSample || !this.extendConnects ? 'nearest' : 'connect';
        break;
      }
      case K.STEER:
        if (parent > 0) { // a ladder step, checked free: its NODE_ADDED follows
          this.then(`ladder try ${pc1}: a step ${num(c0)} moving ${parent} coordinate${parent === 1 ? '' : 's'}, free`);
          A.edge = [px, py, x, y];
          A.collision = undefined;
          A.blocked = false;
          this.line = this.connecting ? 'c-ladder' : 'ladder';
          break;
        }
        this.then(`step ${num(c0)}${pc0 === 1 ? ' (reaches it)' : ''}`);
        A.edge = [px, py, x, y];
        if (this.rangeDrawn) A.range = [px, py, c1];
        this.line = this.connecting ? 'c-steer' : 'steer';
        break;
      case K.COLLISION:
        this.then(`${blockerText(id)} at ${pt(x, y)}`);
        A.collision = [x, y];
        A.blocked = true;
        this.line = this.lazy ? 'lazy-check' : this.connecting ? 'c-check' : 'check';
        if (this.twoTrees && this.density && this.line === 'check' && A.added) this.line = 'met'; // the join was blocked
        break;
      case K.NODE_ADDED:
        if (parent < 0 && this.roadmap) {
          if (this.line === 'init' && id <= 1) {
            this.begin(`${id === 0 ? 'q_start' : 'q_goal'} ${pt(x, y)} is vertex #${id}`);
            this.line = 'init';
          } else {
            this.then(`milestone #${id} at ${pt(x, y)}`);
            A.milestone = [x, y];
            this.line = 'add';
          }
          break;
        }
        if (parent < 0) { this.begin(`the ${TREE_NAME(this.planner, tree)} starts at ${pt(x, y)}`); this.line = 'init'; break; }
        if (this.cells) {
          this.begin(`${this.complete ? 'along the shortest way: step to' : 'step to cell centre'} ${pt(x, y)} (node #${id})`);
          A.edge = [px, py, x, y];
          this.line = 'add';
          break;
        }
        if (this.exact) {
          this.begin(`A* settles ${pt(x, y)} (node #${id}, parent #${parent})`);
          A.edge = [px, py, x, y];
          this.line = 'add';
          break;
        }
        if (this.field) {
          this.begin(`${tree === 1 ? 'random-walk step' : 'step down the gradient'} to ${pt(x, y)} (node #${id})`);
          A.edge = [px, py, x, y];
          this.line = tree === 1 ? 'walk' : 'add';
          break;
        }
        if (this.choosesParent && A.nearId !== undefined && parent !== A.nearId) {
          this.then(`add #${id} under #${parent} (cheaper than #${A.nearId})`);
        } else {
          this.then(`add #${id} under #${parent}`);
        }
        A.edge = [px, py, x, y];
        A.added = true;
        this.line = this.connecting ? 'c-add' : 'add';
        break;
      case K.SAMPLE_REJECTED:
        if (this.line === 'nearest' && A.domain !== null && A.domain !== undefined) {
          this.then(`outside its domain r = ${num(A.domain)}: rejected unchecked`);
          this.line = 'domain';
        } else if (this.roadmap) {
          this.then('invalid: rejected');
          this.line = 'valid';
        } else {
          this.then('sample dropped');
          if (this.line !== 'check') this.line = 'sample';
        }
        break;
      case K.ROADMAP_EDGE:
        this.then(`edge #${parent}–#${id} ${tree === 1 ? 'added unchecked' : 'free: added'}`);
        A.edge = [px, py, x, y];
        this.line = tree === 1 ? 'edge' : 'check';
        break;
      case K.QUERY_PATH:
        if (tree === 0 || this.line !== (this.lazy ? 'search' : 'query')) {
          this.begin('A* over the roadmap: a path of 1 edge');
          this.pathEdges = 0;
        }
        this.pathEdges++;
        this.parts[0] = `A* over the roadmap: a path of ${this.pathEdges} edge${this.pathEdges > 1 ? 's' : ''}`;
        A.edge = [x, y, px, py];
        this.line = this.lazy ? 'search' : 'query';
        break;
      case K.EDGE_CHECKED:
        this.then(`edge #${id}–#${parent} ${tree === 1 ? 'blocked: removed' : 'checked: free'}`);
        A.edge = [x, y, px, py];
        this.line = 'lazy-check';
        break;
      case K.DOMAIN:
        this.then(`#${id}'s domain ${Number.isFinite(px) ? `r = ${num(px)}` : 'removed'}`);
        this.line = 'domain';
        break;
      case K.EXHAUSTED:
        this.then(`#${id} is exhausted`);
        this.line = 'exhausted';
        break;
      case K.TREES_CONNECTED:
        this.then(`the trees meet at ${pt(x, y)}`);
        A.met = [x, y];
        this.line = 'met';
        break;
      case K.SOLVED:
        this.then('solved: the path is returned');
        this.line = this.twoTrees ? 'met' : this.roadmap && !this.lazy ? 'query' : 'goal-check';
        break;
      case K.GRAPH_EDGE:
        this.begin(`edge ${pt(x, y)} – ${pt(px, py)}: ${c1 > 0 ? 'clear' : 'blocked'}, length ${num(c0)}`);
        A.edge = [px, py, x, y];
        this.line = 'edge';
        break;
      case K.REWIRE:
        this.begin(`rewire #${id}: its parent is now #${parent}, cheaper`);
        A.edge = [px, py, x, y];
        this.line = 'rewire';
        break;
      case K.COST:
        this.begin(`best cost now ${num(px)} (goal node #${id}, iteration ${parent})`);
        this.line = 'cost';
        break;
      case K.COVERAGE:
        this.begin(`best branch now sees ${num(100 * px)}% (${py} points; node #${id})`);
        this.line = 'cost';
        break;
      case K.POINT_SEEN:
        this.then(`point ${id} seen at ${pt(x, y)}`);
        this.line = 'seen';
        break;
      case K.CELL:
        if (this.grid) this.begin(`cell #${id} at ${pt(x, y)}: ${px === 0 ? 'free' : 'blocked (an obstacle touches it)'}`);
        else this.begin(`cell #${id} at level ${tree}: ${['free', 'mixed', 'full'][px] || 'cell'}`);
        A.cell = [x, y];
        this.line = 'cells';
        break;
      case K.CELL_SHAPE:
        break; // the outline of the cell just captioned
      case K.REGION:
        this.begin(`region of influence: radius ${num(px)} around ${pt(x, y)} (${c0} obstacles inside)`);
        A.region = [x, y, px];
        this.line = id > 0 ? 'grow' : 'region';
        break;
      case K.FIELD:
        if (this.line !== 'field') this.begin('the potential of each free cell, for the heat map');
        this.line = 'field';
        break;
      case K.CELL_STATE: {
        if (this.complete && px === 2) {
          this.begin(`close cell #${id} (the open cell of least g + h)`);
          A.cell = [x, y];
          this.line = 'close';
          break;
        }
        const verdict = [this.complete ? 'opened (a shorter way)' : 'passable', `blocked: ${this.grid ? 'the motion collides' : HEX_WHY[py] || 'the step test failed'}`, 'visited already', 'outside the region', 'an obstacle cell'][px] || 'judged';
        if (this.line !== 'judge') this.begin(`from cell #${parent}: cell #${id} ${verdict}`);
        else this.then(`#${id} ${verdict}`);
        A.cell = [x, y];
        this.line = 'judge';
        break;
      }
      case K.POTENTIAL:
        if (this.line !== 'potential') this.begin(`U(#${id}) = ${num(c1)}${pc1 === 1 ? ' (lowest: step there)' : ''}`);
        else this.then(`U(#${id}) = ${num(c1)}${pc1 === 1 ? ' (lowest)' : ''}`);
        A.cell = [x, y];
        this.line = 'potential';
        break;
      case K.MINIMUM:
        this.begin(`local minimum at ${pt(x, y)}: U = ${num(px)}, ${num(py)} from the goal`);
        A.collision = [x, y];
        this.line = 'minimum';
        break;
      default:
        break;
    }
  }

  /** The caption of the step so far (joined when asked for: a bulk reveal reads thousands of records). */
  get caption() { return this.parts.join(' → '); }

  /**
   * Read records [from, to) of `store` (a RecordStore). A long reveal (Instant, a step of many
   * iterations) is read from the start of its last step only: the caption and line depend on the
   * current step, which begins at a SAMPLE for the sampling planners (CONNECT included) and at a
   * SELECT for EST; it counts
   * the records skipped. Returns whether records were skipped.
   */
  readStore(store, from, to) {
    let start = from;
    if (to - from > LONG_REVEAL) {
      start = Math.max(from, to - LONG_REVEAL);
      if (this.stepStart) {
        const first = this.density ? K.SELECT : K.SAMPLE;
        for (let i = to - 1, n = 0; i >= from && n < MAX_LOOK_BACK; i--, n++) {
          if (store.record(i)[0] === first) { start = i; break; }
        }
      }
      this.reset();
      this.events = start;
    }
    for (const [d, o0, o1] of store.spans(start, to)) {
      for (let o = o0; o < o1; o += STRIDE) this.read(d, o);
    }
    return start > from;
  }
}

/** Reveals longer than this many records are read from their last step only (readStore). */
const LONG_REVEAL = 256;
/** How far back readStore looks for the last step's SAMPLE. */
const MAX_LOOK_BACK = 1 << 17;

// The explain panel's model: each planner's pseudocode (pseudocode.js), and a reader of the event stream that says,
// for every event, which line of it the planner was on and what happened, in words ("sample
// (0.31, 0.72) → nearest #52 at 0.41 → step 0.28 → blocked by obstacle 3"). Everything it says
// comes from the records the core emitted (src/events.rs), so it is true by construction: the
// numbers are the records' numbers, the node ids the core's. No DOM here (ui/explain-panel.js shows
// it, draw/actors.js draws the step's actors); tests/js/explain.test.mjs and the browser test step
// each planner and check line and caption against the events.

import { EventKind as K, STRIDE } from './events.js';
import { plannerCaps, planeIsWorkspace } from '../draw/capabilities.js';
import { PSEUDOCODE, complete } from './pseudocode.js';

/**
 * @typedef {import('./pseudocode.js').Options} Options
 */

export { pseudocode, PSEUDOCODE } from './pseudocode.js';

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
    // RRT-Connect's `connect` choice: the Robotics Library's RrtConCon (step by the resolution, only
    // the last free configuration added) rather than range steps
    lastFree: p.connect === 'last-free',
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

/** An angle in whole degrees, as the captions write a joint: "−40°". */
export const deg = (rad) => `${Math.round((rad * 180) / Math.PI) || 0}°`.replace('-', '−');
/** A configuration of joint angles: "q = (12°, −40°, 95°, 0°, 30°, −10°)". */
export const joints = (q) => `q = (${Array.from(q, deg).join(', ')})`;

/** What blocked a motion, from a COLLISION record's id (src/space_info/explain.rs, SpaceInfo::blocked_at). */
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
    this.lastFree = this.connects && !!options.lastFree; // RRT-Connect's last-free connect
    /** @type {{get: (i: number) => ({q: ArrayLike<number>, pq: ArrayLike<number>, extra: number} | undefined)} | null} full states by record index (run/arm-states.js) */
    this.states = null;
    /** @type {{collision: (q: ArrayLike<number>) => string} | null} the core's words for what collides at a state */
    this.describe = null;
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
  read(r, o = 0, st = undefined) {
    this.events++;
    // A robot of more than two coordinates (a spatial arm) is told in its joints, from the core's
    // state log (`st`: this record's full states, when the panel has them).
    const arm = st && st.q.length > 2 && Number.isFinite(st.q[0]) ? st : null;
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
        const at = arm ? joints(arm.q) : pt(x, y);
        this.begin(id === 1 ? `sample q_goal ${at} (goal bias)` : id === 2 ? `sample ${at} (uniform share)` : `sample ${at}`);
        if (tries) this.actors.tries = tries;
        this.actors.sample = [x, y];
        if (arm) this.actors.sampleQ = arm.q;
        this.line = id === 1 ? 'goal' : id === 2 ? 'share' : 'sample';
        if (this.connects) this.parts[0] += ` for the ${TREE_NAME(this.planner, tree)}`;
        break;
      }
      case K.NEAREST: {
        const toSample = pc0 === 1;
        if (!toSample && this.connects) {
          if (!this.connecting) {
            const sample = A.sample;
            const sampleQ = A.sampleQ;
            this.begin(`CONNECT the ${TREE_NAME(this.planner, tree)} toward ${arm ? `the new node's ${joints(arm.pq)}` : pt(px, py)}`);
            if (sample) this.actors.sample = sample;
            if (sampleQ) this.actors.sampleQ = sampleQ;
          }
          this.connecting = true;
        }
        this.then(`nearest #${id} at ${num(c0)}${arm ? ' rad' : ''}`);
        const N = this.actors;
        N.stepQ = undefined;
        N.collisionQ = undefined;
        N.connect = undefined;
        // the connect's target, in full (the state log's: a last-free STEER walks toward it)
        N.targetQ = arm ? arm.pq : undefined;
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
        if (arm && this.lastFree) {
          // The Robotics Library's connect: configurations a resolution apart along the line, each
          // one query (`extra`: the state checks the connect took), up to the farthest tested.
          const n = Number.isFinite(arm.extra) ? arm.extra : NaN;
          this.then(`step along the line by the resolution: ${Number.isFinite(n) ? `${n} configuration${n === 1 ? '' : 's'} checked (${n} quer${n === 1 ? 'y' : 'ies'})` : 'configurations checked'}, ${num(c0)} of ${num(c1)} rad${pc0 === 1 ? ' (reaches it)' : ''}, the farthest ${joints(arm.q)}`);
          A.stepQ = arm.q;
          // its configurations one by one (ui/connect-steps.js asks the core for them): from the
          // node toward the target, as many as its queries (one a configuration)
          if (A.targetQ && Number.isInteger(n) && n >= 1) A.connect = { from: arm.pq, target: A.targetQ, count: n };
        } else {
          this.then(`step ${num(c0)}${arm ? ` rad to ${joints(arm.q)}` : ''}${pc0 === 1 ? ' (reaches it)' : ''}`);
          if (arm) A.stepQ = arm.q;
        }
        A.edge = [px, py, x, y];
        if (this.rangeDrawn) A.range = [px, py, c1];
        this.line = this.connecting ? 'c-steer' : 'steer';
        break;
      case K.COLLISION:
        if (arm) {
          const q = arm.q;
          const describe = this.describe;
          let words = null;
          const lead = `${this.lastFree ? 'the configuration ' : ''}${joints(q)} collides`;
          // The core's words ("link4 meets the slab"), asked for only when the caption is shown.
          this.then(describe ? () => {
            words ??= describe.collision(q) || blockerText(id);
            return `${lead}: ${words}`;
          } : `${lead}: ${blockerText(id)}`);
          A.collisionQ = q;
          A.stepQ = q;
        } else {
          this.then(`${blockerText(id)} at ${pt(x, y)}`);
        }
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
        if (parent < 0) { this.begin(`the ${TREE_NAME(this.planner, tree)} starts at ${arm ? joints(arm.q) : pt(x, y)}`); this.line = 'init'; break; }
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
        if (arm && this.lastFree) {
          this.then(`only the last free configuration ${joints(arm.q)} becomes a node: #${id} under #${parent}`);
        } else if (arm) {
          this.then(`add #${id} under #${parent} at ${joints(arm.q)}`);
        } else if (this.choosesParent && A.nearId !== undefined && parent !== A.nearId) {
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
          this.then(this.lastFree ? 'not even the first configuration is free: no node, the sample is dropped' : 'sample dropped');
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
        this.then(arm ? `the trees join: #${id} of the ${TREE_NAME(this.planner, tree)} and #${parent} of the other${this.lastFree ? ' (within ε)' : ''}, at ${joints(arm.q)}` : `the trees meet at ${pt(x, y)}`);
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
      case K.INFORMED:
        this.then(`samples now only where d(start, q) + d(q, goal) < ${num(pc0)}: an ellipse ${num(2 * px)} × ${num(2 * py)} around the foci ${num(pc1)} apart`);
        this.line = 'informed';
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
      case K.MINIMUM: {
        this.begin(`local minimum at ${pt(x, y)}: U = ${num(px)}, ${num(py)} from the goal`);
        const pull = Math.sqrt(c0 * c0 + c1 * c1), push = Math.sqrt(pc0 * pc0 + pc1 * pc1);
        if (pull > 0 && push > 0) { // the core's forces there (see EventKind::Minimum)
          // their sum, from the core's two vectors: near 0 they cancel at this very step; else the
          // descent rocks by a step about the point where they do
          const net = Math.sqrt((c0 + pc0) ** 2 + (c1 + pc1) ** 2);
          this.then(net <= 0.2 * Math.max(pull, push)
            ? `pull ${num(pull)} and push ${num(push)} cancel here: the goal pulls the robot on, the nearest obstacle pushes it back, and it gets no closer`
            : `pull ${num(pull)} and push ${num(push)} (sum ${num(net)}): they cancel within a step of here, so the robot rocks back and forth and gets no closer`);
        }
        A.collision = [x, y];
        this.line = 'minimum';
        break;
      }
      default:
        break;
    }
  }

  /** The caption of the step so far (joined when asked for: a bulk reveal reads thousands of records). */
  get caption() { return this.parts.map((p) => (typeof p === 'function' ? p() : p)).join(' → '); }

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
    let i = start;
    for (const [d, o0, o1] of store.spans(start, to)) {
      for (let o = o0; o < o1; o += STRIDE, i++) this.read(d, o, this.states?.get(i));
    }
    return start > from;
  }
}

/** Reveals longer than this many records are read from their last step only (readStore). */
const LONG_REVEAL = 256;
/** How far back readStore looks for the last step's SAMPLE. */
const MAX_LOOK_BACK = 1 << 17;

// The explain panel's model (www/run/explain.js) against the events the core emits: every planner
// is run under Node (the wasm build) and its records fed to the Explainer one at a time; each
// record must put the panel on a line of that planner's pseudocode, and the caption must say what
// the record says (its node ids, its numbers, the obstacle that blocked it), so the captions are
// true by construction. Runs on real built-ins with their default seeds.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { scenarios, runRecords } from './core-runs.mjs';
import { EventKind as K, STRIDE } from '../../www/run/events.js';
import { Explainer, pseudocode, optionsOf, num, blockerText } from '../../www/run/explain.js';
import { learn } from '../../www/draw/capabilities.js';
import { planners, robot_kinds } from '../../www/pkg/planarium.js';

// The page learns the registry's capabilities from the worker's ready message; here, from the core.
learn({ planners: JSON.parse(planners()), robotKinds: JSON.parse(robot_kinds()) });

function records(scenario, planner, params, seed) {
  const { out } = runRecords(scenario, planner, params, seed);
  const recs = [];
  for (let o = 0; o < out.length; o += STRIDE) recs.push(out.slice(o, o + STRIDE));
  return recs;
}

/** What the caption must end with (or contain) after record `r`; null: no check for that kind. */
function expected(planner, r) {
  const [kind, , id, parent, x, y, px, py, c0, , , pc1] = r;
  switch (kind) {
    case K.SAMPLE: return id === 1 ? `sample q_goal (${num(x)}, ${num(y)}) (goal bias)` : id === 2 ? `sample (${num(x)}, ${num(y)}) (uniform share)` : `sample (${num(x)}, ${num(y)})`;
    case K.NEAREST: return `nearest #${id} at ${num(c0)}`;
    case K.STEER: return parent > 0 ? `ladder try ${pc1}: a step ${num(c0)} moving ${parent} coordinate` : `step ${num(c0)}`;
    case K.COLLISION: return `${blockerText(id)} at (${num(x)}, ${num(y)})`;
    case K.NODE_ADDED:
      if (parent < 0 || planner === 'hex-potential' || planner === 'grid-search' || planner === 'potential-field') return `(${num(x)}, ${num(y)})`;
      if (planner === 'visibility-graph') return `(${num(x)}, ${num(y)}) (node #${id}, parent #${parent})`;
      return `add #${id} under #${parent}`;
    case K.REWIRE: return `rewire #${id}: its parent is now #${parent}`;
    case K.COST: return `best cost now ${num(px)}`;
    case K.INFORMED: return `d(start, q) + d(q, goal) < ${num(r[10])}: an ellipse ${num(2 * px)} × ${num(2 * py)}`;
    case K.TREES_CONNECTED: return 'the trees meet';
    case K.SOLVED: return 'solved';
    case K.MINIMUM: return `local minimum at (${num(x)}, ${num(y)})`;
    case K.CELL_STATE: return `#${id}`;
    case K.REGION: return `radius ${num(px)}`;
    case K.SELECT: return `picks #${id}: its cell holds ${px} node`;
    case K.ROADMAP_EDGE: return `edge #${parent}–#${id}`;
    case K.EDGE_CHECKED: return `edge #${id}–#${parent} ${r[1] === 1 ? 'blocked' : 'checked: free'}`;
    case K.QUERY_PATH: return 'A* over the roadmap';
    case K.GRAPH_EDGE: return `edge (${num(x)}, ${num(y)}) – (${num(px)}, ${num(py)}): clear, length ${num(c0)}`;
    default: return null;
  }
}

const RUNS = [
  ['narrow', 'rrt', {}, 7],
  ['narrow', 'rrt', { extend: 'connect', dd_radius: 0.05, exhausted: 3 }, 7],
  ['narrow', 'rrt-connect', {}, 7],
  ['narrow', 'rrt-connect', { ladder: 8 }, 7],
  ['zigzag', 'rrt', { ladder: 4 }, 1],
  ['ompl-rect', 'rrt-star', { max_iterations: 400 }, 1],
  ['open-field', 'informed-rrt-star', { improve_for: 300 }, 1],
  ['technion-ip', 'inspection', { max_iterations: 300 }, 1],
  ['hex-trap', 'hex-potential', {}, 1],
  ['apf-minimum', 'potential-field', {}, 1],
  ['open-field', 'rrt', { sampler: 'bridge', goal_bias: 0.2 }, 2],
  ['zigzag', 'rrt-connect', { sampler: 'bridge', max_iterations: 3000 }, 2],
  ['zigzag', 'hex-potential', { search: 'astar' }, 1],
  ['hex-trap', 'hex-potential', { search: 'dijkstra' }, 1],
  ['narrow', 'est', {}, 3],
  ['zigzag', 'grid-search', {}, 1],
  ['apf-minimum', 'grid-search', { search: 'wavefront', diagonal: 'cross-corners' }, 1],
  ['zigzag', 'bi-est', {}, 2],
  ['zigzag', 'prm', {}, 1],
  ['narrow', 'prm-star', { connect: 'radius' }, 2],
  ['zigzag', 'lazy-prm', {}, 1],
  ['open-field', 'visibility-graph', {}, 1],
];

for (const [scenario, planner, params, seed] of RUNS) {
  test(`explain: ${planner} ${JSON.stringify(params)} on ${scenario}: every event lands on a line of its pseudocode with its own words`, () => {
    const code = pseudocode(planner, optionsOf({ planner, params }));
    assert.ok(code, `pseudocode for ${planner}`);
    const ids = new Set(code.lines.map((l) => l.id));
    const x = new Explainer(planner, scenarios[scenario].robot.kind, optionsOf({ planner, params }));
    const recs = records(scenario, planner, params, seed);
    assert.ok(recs.length > 50, `${recs.length} records`);
    if (params.ladder) assert.ok(recs.filter((r) => r[0] === K.STEER && r[3] > 0).length > 3, 'ladder steps were taken and captioned');
    const linesSeen = new Set();
    let checked = 0;
    for (const r of recs) {
      x.read(r);
      const { line, caption } = x;
      if (r[0] === K.CELL_SHAPE || r[0] === K.FIELD || r[0] === K.SAMPLE_TRY || r[0] === K.CELL || r[0] === K.POTENTIAL) continue;
      assert.ok(ids.has(line), `${planner}: kind ${r[0]} put the panel on line "${line}", not in its pseudocode`);
      linesSeen.add(line);
      const want = expected(planner, r);
      if (want !== null) {
        assert.ok(caption.includes(want), `${planner}: after kind ${r[0]} [${[...r].join(', ')}] the caption "${caption}" should say "${want}"`);
        checked++;
      }
    }
    assert.ok(checked > 20, `${checked} captions checked`);
    assert.ok(linesSeen.size >= 3, `lines reached: ${[...linesSeen]}`);
    if (recs.some((r) => r[0] === K.INFORMED)) assert.ok(linesSeen.has('informed'), 'the informed set was captioned');
    if (planner === 'informed-rrt-star') assert.ok(recs.some((r) => r[0] === K.INFORMED), 'the run logged its informed set');
  });
}

test('explain: a growth step reads sample → nearest → step → added or blocked, in that order', () => {
  const x = new Explainer('rrt', 'point');
  const recs = records('narrow', 'rrt', {}, 7);
  let blocked = 0, added = 0;
  for (const r of recs) {
    x.read(r);
    const { caption } = x;
    if (r[0] === K.COLLISION) {
      blocked++;
      assert.match(caption, /^sample (q_goal )?\(.*\)( \(goal bias\))? → nearest #\d+ at [\d.]+ → step [\d.]+( \(reaches it\))? → (blocked by obstacle \d+|blocked by the map's edge) at /);
      assert.ok(x.actors.collision && x.actors.near && x.actors.edge && x.actors.range, 'the actors of a blocked step');
    }
    if (r[0] === K.NODE_ADDED && r[3] >= 0) {
      added++;
      assert.match(caption, /^sample (q_goal )?\(.*\)( \(goal bias\))? → nearest #\d+ at [\d.]+ → step [\d.]+( \(reaches it\))? → add #\d+ under #\d+$/);
    }
  }
  assert.ok(blocked > 10 && added > 50, `${blocked} blocked, ${added} added`);
});

test('explain: the pseudocode shows the lines of the options chosen', () => {
  const plain = pseudocode('rrt', optionsOf({ planner: 'rrt', params: { goal_bias: 0 } })).lines.map((l) => l.id);
  assert.ok(!plain.includes('goal') && !plain.includes('domain') && !plain.includes('exhausted') && !plain.includes('connect'));
  const all = pseudocode('rrt', optionsOf({ planner: 'rrt', params: { goal_bias: 0.1, dd_radius: 0.1, exhausted: 3, extend: 'connect', sampler: 'bridge' } })).lines.map((l) => l.id);
  for (const id of ['goal', 'domain', 'exhausted', 'connect', 'try']) assert.ok(all.includes(id), id);
  assert.equal(pseudocode('no-such-planner'), null);
  // the ladder's lines (after a step's check, and CONNECT's) only when it is on
  const ladder = (planner, params) => pseudocode(planner, optionsOf({ planner, params })).lines.map((l) => l.id);
  assert.ok(ladder('rrt', { ladder: 8 }).includes('ladder') && !ladder('rrt', {}).includes('ladder') && !ladder('rrt', { ladder: 0 }).includes('ladder'));
  assert.ok(ladder('rrt-connect', { ladder: 2 }).includes('c-ladder') && !ladder('rrt-connect', {}).includes('c-ladder'));
  // the uniform share's line shows for the narrow-passage samplers unless the share is 0
  const ids = (params) => pseudocode('rrt-connect', optionsOf({ planner: 'rrt-connect', params })).lines.map((l) => l.id);
  assert.ok(ids({ sampler: 'bridge' }).includes('share') && ids({ sampler: 'near-collision', uniform_share: 0.3 }).includes('share'));
  assert.ok(!ids({ sampler: 'bridge', uniform_share: 0 }).includes('share') && !ids({ sampler: 'uniform' }).includes('share'));
  // inspection: what a new node sees, as the scenario counts it
  const seen = (o) => pseudocode('inspection', o).lines.filter((l) => l.id === 'seen').map((l) => l.text);
  assert.deepEqual(seen({}), ['seen(q_new) ← seen(parent) ∪ points seen on the way']);
  assert.deepEqual(seen({ vertices: true }), ['seen(q_new) ← seen(parent) ∪ points seen at q_new (the course counts vertices only)']);
  // hexagonal cells: the report's descent, or a complete search with its own lines
  const hex = (search) => pseudocode('hex-potential', optionsOf({ planner: 'hex-potential', params: { search } })).lines.map((l) => l.id);
  assert.ok(hex(undefined).includes('potential') && hex('descent').includes('grow') && !hex('descent').includes('close'));
  assert.ok(hex('astar').includes('close') && hex('dijkstra').includes('open') && !hex('astar').includes('potential'));
});

test('explain: A* over the hexagonal cells closes cells, opens shorter ways and steps along the shortest', () => {
  const params = { search: 'astar' };
  const x = new Explainer('hex-potential', 'point', optionsOf({ planner: 'hex-potential', params }));
  const said = { close: 0, opened: 0, along: 0 };
  for (const r of records('zigzag', 'hex-potential', params, 1)) {
    x.read(r);
    if (r[0] === K.CELL_STATE && r[6] === 2) { assert.equal(x.line, 'close'); assert.match(x.caption, /^close cell #\d+/); said.close++; }
    if (r[0] === K.CELL_STATE && r[6] === 0) { assert.match(x.caption, /opened \(a shorter way\)/); said.opened++; }
    if (r[0] === K.NODE_ADDED && r[3] >= 0) { assert.match(x.caption, /^along the shortest way: step to/); said.along++; }
  }
  assert.ok(said.close > 100 && said.opened > 100 && said.along > 5, JSON.stringify(said));
});

test('explain: a long reveal read at once says what reading every record one by one says', () => {
  for (const [scenario, planner, params, seed] of [['narrow', 'rrt-connect', {}, 7], ['narrow', 'rrt', { extend: 'connect' }, 3], ['hex-trap', 'hex-potential', {}, 1]]) {
    const recs = records(scenario, planner, params, seed);
    const flat = new Float64Array(recs.length * STRIDE);
    recs.forEach((r, i) => flat.set(r, i * STRIDE));
    const store = { spans: function* (a, b) { yield [flat, a * STRIDE, b * STRIDE]; }, record: (i) => flat.subarray(i * STRIDE, (i + 1) * STRIDE) };
    for (const end of [recs.length, Math.floor(recs.length / 2), Math.floor(recs.length / 3) + 7]) {
      const one = new Explainer(planner, 'point');
      for (let i = 0; i < end; i++) one.read(flat, i * STRIDE);
      const bulk = new Explainer(planner, 'point');
      const skipped = bulk.readStore(store, 0, end);
      assert.ok(skipped, 'the long reveal was read from its last step');
      assert.equal(bulk.line, one.line, `${planner} at ${end}: line`);
      if (planner !== 'hex-potential') assert.equal(bulk.caption, one.caption, `${planner} at ${end}: caption`);
      assert.deepEqual(bulk.actors, one.actors, `${planner} at ${end}: actors`);
    }
  }
});

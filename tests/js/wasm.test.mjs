// The wasm build (www/pkg, --target web) under Node: stepped in batches exactly as the worker
// does, it reproduces the native runs bit for bit (event-log fingerprints pinned in
// tests/golden/runs.json, paths equal to the native CLI's JSON), and its constants match www/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { initSync, Run, Scene, builtins, planners, event_kinds } from '../../www/pkg/planarium.js';
import { EventKind, SETUP_KINDS, STRIDE } from '../../www/run/events.js';
import { smallQuads } from './seeded.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
initSync({ module: readFileSync(join(root, 'www/pkg/planarium_bg.wasm')) });
const cases = JSON.parse(readFileSync(join(root, 'tests/golden/cases.json'), 'utf8'));
const golden = JSON.parse(readFileSync(join(root, 'tests/golden/runs.json'), 'utf8'));
const builtinText = Object.fromEntries(JSON.parse(builtins()).map((b) => [b.id, JSON.stringify(b.scenario)]));

// FNV-1a 64 over the little-endian bytes of the f64s, as src/run/fingerprint.rs.
function fnv1a(h, f64s) {
  const bytes = new Uint8Array(f64s.buffer, f64s.byteOffset, f64s.byteLength);
  for (const b of bytes) {
    h ^= BigInt(b);
    h = (h * 0x100000001b3n) & 0xffffffffffffffffn;
  }
  return h;
}
const OFFSET = 0xcbf29ce484222325n;
const hex = (h) => h.toString(16).padStart(16, '0');

function runInBatches(c, batch) {
  const run = new Run(builtinText[c.scenario], c.planner, JSON.stringify(c.params), c.seed);
  let h = OFFSET;
  let status;
  do {
    status = run.step(batch, 1e9);
    h = fnv1a(h, run.drain_events());
  } while (status === 'running');
  const result = JSON.parse(run.result_json());
  run.free();
  return { events: hex(h), result };
}

test('seeded runs in wasm match the native fingerprints, in any batch size', () => {
  cases.forEach((c, i) => {
    for (const batch of [1, 37, 1e9]) {
      const { events, result } = runInBatches(c, batch);
      assert.equal(events, golden[i].events, `case ${i} (${c.scenario}/${c.planner}) batch ${batch}`);
      assert.equal(result.stats.iterations, golden[i].iterations);
      assert.equal(result.stats.nodes, golden[i].nodes);
      assert.equal(result.stats.checks, golden[i].checks);
    }
  });
});

test('wasm paths equal the native CLI paths number for number', () => {
  const cli = join(root, 'target/release/planarium');
  cases.forEach((c) => {
    const flags = Object.entries(c.params).flatMap(([k, v]) => [`--${k.replaceAll('_', '-')}`, String(v)]);
    const native = JSON.parse(execFileSync(cli, ['plan', c.scenario, '--planner', c.planner, '--seed', String(c.seed), '--json', ...flags], { encoding: 'utf8' }));
    const { result } = runInBatches(c, 1e9);
    assert.equal(result.solved, true);
    assert.deepEqual(result.path, native.path);
    assert.deepEqual(result.smoothed, native.smoothed);
    assert.equal(result.stats.cost, native.stats.cost);
  });
});

test('event constants in www/run/events.js match the core', () => {
  const k = JSON.parse(event_kinds());
  assert.equal(k.stride, STRIDE);
  assert.deepEqual(k.kinds, { ...EventKind });
  assert.deepEqual(k.setup, [...SETUP_KINDS], 'the set-up kinds (one step of the playback each run of them)');
});

test('events stream what the page needs: nodes with parents, collisions, a solution', () => {
  const run = new Run(builtinText.narrow, 'rrt-connect', '{}', 7);
  while (run.step(100, 1e9) === 'running');
  const ev = run.drain_events();
  const count = (kind) => { let n = 0; for (let i = 0; i < ev.length; i += STRIDE) if (ev[i] === kind) n++; return n; };
  const stats = JSON.parse(run.stats_json());
  assert.equal(count(EventKind.NODE_ADDED), stats.nodes - 2, 'one NODE_ADDED per non-root node');
  assert.ok(count(EventKind.COLLISION) > 0);
  assert.equal(count(EventKind.TREES_CONNECTED), 1);
  assert.equal(count(EventKind.SOLVED), 1);
  // Every node event's parent point is an earlier node of the same tree (or its root).
  for (let i = 0; i < ev.length; i += STRIDE) {
    if (ev[i] === EventKind.NODE_ADDED) assert.ok(ev[i + 3] < ev[i + 2], 'parent id precedes the node');
  }
  const frames = run.path_frames(false, 0.01);
  assert.equal(frames[0], 2, 'point states have 2 numbers');
  assert.ok(frames[1] > 10, 'enough frames to animate');
  run.free();
});

test('path_lengths: the length along the path at each animation frame and waypoint, the last the cost', () => {
  const run = new Run(builtinText.narrow, 'rrt-connect', '{}', 7);
  while (run.step(100, 1e9) === 'running');
  const result = JSON.parse(run.result_json());
  for (const [raw, cost, way] of [[false, result.stats.smoothed_cost, result.smoothed], [true, result.stats.cost, result.path]]) {
    const frames = run.path_frames(raw, 0.01);
    const lengths = run.path_lengths(raw, 0.01);
    const n = frames[1];
    assert.equal(lengths[0], n, 'a length for each frame');
    assert.equal(lengths[n + 1], way.length, 'then one for each waypoint');
    assert.equal(lengths.length, n + 2 + way.length);
    // the frames' states (a point's outline is a polygon count of 0 or a point: skipped)
    const states = [];
    let o = 2;
    for (let k = 0; k < n; k++) {
      states.push([frames[o], frames[o + 1]]);
      o += 2;
      const polys = frames[o++];
      for (let q = 0; q < polys; q++) o += 1 + 2 * frames[o];
    }
    let sum = 0;
    for (let k = 0; k < n; k++) {
      if (k > 0) sum += Math.hypot(states[k][0] - states[k - 1][0], states[k][1] - states[k - 1][1]);
      assert.ok(Math.abs(lengths[1 + k] - sum) <= 1e-9 * cost, `${raw ? 'raw' : 'smoothed'} frame ${k}: ${lengths[1 + k]} vs ${sum}`);
    }
    assert.equal(lengths[n], cost, 'the last frame is at the cost the stats give, exactly');
    let w = 0;
    for (let i = 0; i < way.length; i++) {
      if (i > 0) w += Math.hypot(way[i][0] - way[i - 1][0], way[i][1] - way[i - 1][1]);
      assert.ok(Math.abs(lengths[n + 2 + i] - w) <= 1e-9 * cost, `waypoint ${i}`);
    }
    assert.equal(lengths[lengths.length - 1], cost, 'the last waypoint is at the cost');
  }
  run.free();
});

test("Scene.tool_points: a path's tool curve in one call, where each state's link frames put the tool; bad input gives none", () => {
  const scene = new Scene(builtinText['puma-rbo-wall']);
  const { tool } = JSON.parse(scene.spatial_json());
  const sc = JSON.parse(builtinText['puma-rbo-wall']);
  const dims = sc.start.length;
  const states = [];
  for (let k = 0; k <= 10; k++) for (let j = 0; j < dims; j++) states.push(sc.start[j] + (k / 10) * (sc.goal[j] - sc.start[j]));
  const pts = scene.tool_points(Float64Array.from(states));
  assert.equal(pts.length, 3 * 11);
  for (let k = 0; k <= 10; k++) {
    const lf = scene.link_frames(Float64Array.from(states.slice(k * dims, (k + 1) * dims)));
    const m = lf.subarray(lf.length - 16);
    for (let r = 0; r < 3; r++) {
      const want = m[r] * tool[0] + m[4 + r] * tool[1] + m[8 + r] * tool[2] + m[12 + r];
      assert.ok(Math.abs(pts[3 * k + r] - want) < 1e-12, `state ${k}, axis ${r}: ${pts[3 * k + r]} vs ${want}`);
    }
  }
  // not a whole number of states, a number that is not finite, a plane robot: nothing
  assert.equal(scene.tool_points(Float64Array.from(states.slice(0, dims + 1))).length, 0);
  assert.equal(scene.tool_points(Float64Array.from([...states.slice(0, dims - 1), NaN])).length, 0);
  assert.equal(scene.tool_points(new Float64Array(0)).length, 0);
  const plane = new Scene(builtinText.narrow);
  assert.equal(plane.tool_points(Float64Array.from([0.1, 0.5])).length, 0);
  scene.free();
  plane.free();
});

test('a file is read into a Scene as the user gave it: the text limit is on the file, and runs are made from the Scene', () => {
  // 70,000 quadrilaterals with 12-digit corners: 8.3 MB as written, 21 MB pretty-printed
  const obstacles = smallQuads(70000);
  const sc = { bounds: [0, 0, 1, 1], obstacles, robot: { kind: 'point' }, start: [0.01, 0.01], goal: [0.99, 0.99] };
  const text = JSON.stringify(sc);
  assert.ok(text.length < 16 * 1024 * 1024 && JSON.stringify(sc, null, 2).length > 16 * 1024 * 1024);
  const scene = Scene.from_file(text, 'large.json');
  const json = scene.scenario_json();
  assert.ok(json.length < 16 * 1024 * 1024, `the scenario's JSON is compact: ${json.length} bytes`);
  assert.equal(JSON.parse(json).obstacles.length, 70000);
  const run = scene.run('rrt-connect', JSON.stringify({ max_iterations: 5 }), 1);
  while (run.step(1e9, 50) === 'running');
  assert.equal(JSON.parse(run.stats_json()).iterations, 5);
  run.free();
  // over the limit as written: refused, naming the size
  assert.throws(() => Scene.from_file(' '.repeat(16 * 1024 * 1024 + 1), 'big.json'), (e) => /16777217 bytes; the limit is 16777216/.test(JSON.parse(e.message).text));
  scene.free();
});

test('bad input is an error naming what and where, never a crash', () => {
  assert.throws(() => new Scene('{"bounds": [0,0,1,1], "obstacles": [{"polygon": [[0,0],[1,1]]}], "robot": {"kind": "point"}, "start": [0.1,0.1], "goal": [0.9,0.9]}'),
    (e) => JSON.parse(e.message).path === 'obstacles[0].polygon');
  assert.throws(() => new Scene('{\n"bounds": [0,0,1,1],\n}'), (e) => JSON.parse(e.message).line === 3);
  assert.throws(() => new Run(builtinText.narrow, 'rrt', '{"goal_bias": 7}', 1), /goal_bias: must be between 0 and 1/);
  assert.throws(() => new Run(builtinText.narrow, 'no-such-planner', '{}', 1), /unknown planner/);
  assert.throws(() => new Run(builtinText.narrow, 'rrt', '{}', -1), /seed/);
  const s = new Scene(builtinText.slot);
  const outline = s.outline(new Float64Array([0.5, 0.5, 0]));
  assert.deepEqual([...outline.slice(0, 2)], [1, 4], 'one polygon of four corners');
  assert.ok(JSON.parse(planners()).planners.some((p) => p.name === 'rrt-connect'));
});

test('a bidirectional control in a scenario key, a parameter or a planner name is echoed as [U+202E], never raw', () => {
  const bidi = /[\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]/;
  const scenario = JSON.parse(builtinText.narrow);
  scenario['\u202eevil'] = 1;
  assert.throws(() => new Scene(JSON.stringify(scenario)), (e) => {
    assert.equal(JSON.parse(e.message).path, '[U+202E]evil');
    assert.ok(!bidi.test(e.message), e.message);
    return true;
  });
  for (const [planner, params] of [['rrt', '{"go\u202eal_bias": 0.1}'], ['r\u202ert', '{}']]) {
    assert.throws(() => new Run(builtinText.narrow, planner, params, 1), (e) => {
      assert.ok(e.message.includes('[U+202E]') && !bidi.test(e.message), e.message);
      return true;
    });
  }
});

test('time and iteration limits are honoured in wasm', () => {
  const run = new Run(builtinText.narrow, 'rrt', JSON.stringify({ goal_bias: 0, range: 0.0005, time_limit: 0.2 }), 1);
  const t0 = performance.now();
  let status;
  do status = run.step(1e9, 50); while (status === 'running');
  console.log(`a 0.2 s time limit ended the run after ${(performance.now() - t0).toFixed(0)} ms`);
  assert.equal(status, 'time_limit');
  const r2 = new Run(builtinText.narrow, 'rrt', JSON.stringify({ goal_bias: 0, max_iterations: 123 }), 1);
  while (r2.step(50, 1e9) === 'running');
  assert.equal(JSON.parse(r2.stats_json()).iterations, 123);
});

test('a vehicle chain is animated in primitive steps, from the exact start to the exact goal', () => {
  const sc = JSON.parse(builtinText['asv-3-easy']);
  const run = new Run(builtinText['asv-3-easy'], 'rrt-connect', '{}', 1);
  while (run.step(1e9, 1e9) === 'running');
  const frames = run.path_frames(false, 0.004);
  const dims = frames[0], count = frames[1];
  assert.equal(dims, 2 * sc.robot.count);
  const states = [];
  let o = 2;
  for (let k = 0; k < count; k++) {
    states.push(Array.from(frames.subarray(o, o + dims)));
    o += dims;
    const polys = frames[o++];
    for (let p = 0; p < polys; p++) o += 1 + 2 * frames[o];
  }
  assert.equal(o, frames.length, 'the frame layout is consistent');
  assert.deepEqual(states[0], sc.start);
  assert.deepEqual(states[states.length - 1], sc.goal);
  for (let k = 1; k < states.length; k++) {
    for (let v = 0; v < dims; v += 2) {
      const d = Math.hypot(states[k][v] - states[k - 1][v], states[k][v + 1] - states[k - 1][v + 1]);
      assert.ok(d <= 0.001 + 1e-5, `step ${k}, vehicle ${v / 2} moves ${d}`);
    }
  }
  const text = run.asv_solution();
  assert.equal(Number(text.split(/\s+/)[0]), count - 1, 'the solution file has the same steps');
  run.free();
});

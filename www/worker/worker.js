// The planning worker: one stateful session per worker (wasm-in-web-worker style).
//
// Messages in  {type, ...}:
//   load      {text}                         validate a scenario (JSON text) and keep it
//   import    {text, name}                   read any supported file (scenario, Technion map, ASV
//                                            problem .txt) and proceed as `load` with the scenario
//   import    {text: '', name, bytes, yaml, yamlName}   an occupancy map: `bytes` (an
//                                            ArrayBuffer, transferred) the image (PGM or PNG) named
//                                            `name`, `yaml` (text or null) its map_server YAML named
//                                            `yamlName`; no YAML: a plain image (dark is occupied);
//                                            a YAML without `bytes` is `invalid`, naming the image
//                                            it needs. Then as `load` with the scenario
//   configure {planner, params, seed}        choose the planner set-up for the next run
//   run       {}                             start (or resume) planning; streams events
//   pause     {}                             stop stepping, keep the run
//   step      {iterations}                   run exactly that many iterations, then pause
//   reset     {}                             drop the run (the next run starts from the seed)
//   cancel    {}                             stop the run now; it is finished
//   asv-solution {}                          the finished run's path as an ASV solution file
//   query     {start, goal}                  after a roadmap run (prm, prm-star, lazy-prm): another
//                                            query on its roadmap, scenario states (arrays)
//   ping      {}                             nothing (with `ack`: shows the worker reads messages)
//   fresh-seed {}                            a fresh seed from the core's entropy (a `seed` reply)
//   debug-panic  {message}                   tests only: make the core panic (a `crashed` reply)
//   debug-hang   {ms}                        tests only: stay busy for `ms` milliseconds without
//                                            reading messages (a batch that never ends)
// Any message may carry `ack: n`: the worker then replies {type: 'ack', ack: n} as soon as it reads
// it, before doing the work (the page's watchdog, session.js, replaces a worker that does not
// acknowledge cancel, reset, configure or load within a second).
// Messages out {type, run, ...}:
//   ready     {builtins, planners, eventKinds, robotKinds}   planners: the registry (each with `caps`,
//                                            its capabilities); robotKinds: the robot kinds' records
//   loaded    {scenario, start, goal, space, caps, cspace?, optimum?, spatial?}  normalised scenario; start/goal
//                                            outlines (flat Float64Arrays); space: the planning space [{lo, hi, wraps}];
//                                            caps: what the core decided (scene_caps: {robot, cspace,
//                                            optimum, solution_file, pose});
//                                            cspace {n, grid: Uint8Array (transferred), dims} for a
//                                            2-D arm: n×n validity, rows from the lowest 2nd coordinate;
//                                            optimum {cost, exact} | {error}: the visibility graph's,
//                                            when caps.optimum; spatial {links, tool, parts, obstacles,
//                                            start, goal} when caps.view3d: the 3-D view's meshes
//                                            (Scene.spatial_json) and the start's and goal's link frames
//   invalid   {error: {path, message, line, column, text}}
//   events    {data: Float64Array, stats, status, tries: {seen, sent}, tree3d?, states?}   transferred, once per batch;
//                                            tree3d (caps.view3d): the batch's nodes as the tool sweeps
//                                            their edges (Run.drain_tool_tree: [tree, id, n, x, y, z…]);
//                                            states (caps.view3d): the full states of the batch's
//                                            growth-step records for the explain panel
//                                            (Run.drain_states; run/arm-states.js);
//                                            the sampler's raw tries (SAMPLE_TRY) are all sent up to
//                                            TRY_KEEP a run, then thinned (one in 2, 4, 8… as their
//                                            number doubles), so a validity-checking sampler's
//                                            millions of draws cannot swamp the page
//   result    {result, frames: Float64Array, rawFrames: Float64Array, path3d?, rawPath3d?}   path3d
//                                            (caps.view3d, solved): {tool, frames, count, links,
//                                            stride, lengths}: the tool's curve and the link frames of at most
//                                            PATH_POSES_3D poses (every stride-th frame and the last),
//                                            the core's lengths along the path (Run.path_lengths);
//                                            rawPath3d the same for the raw path
//   status    {status}
//   ack       {ack}                          the message carrying `ack` was read
//   asv-solution {text}
//   query     {data: Float64Array, answer: {path, points, cost} | {error}, states?}   the query's events
//                                            (transferred) and its answer; `path` empty when the
//                                            roadmap does not join the two states
//   seed      {seed}                         a fresh seed (asked for by fresh-seed), ≤ 2^53 − 1
//   error     {message}                      a bad request; the worker stays usable
//   crashed   {message}                      the core panicked; the page must replace this worker
// `run` is a counter bumped on every run/reset/load, so the page can drop stale replies.
// The messages' types, both directions, are in ../run/messages.js (checked by tsc --checkJs).

import init, { Scene, builtins, map_image_name, planners, robot_kinds, event_kinds, install_panic_hook, last_panic, debug_panic, fresh_seed }
  from '../pkg/planarium.js';
import { thinTries } from './thin.js';

/** @typedef {import('../run/messages.js').WorkerIn} WorkerIn */
/** @typedef {import('../run/messages.js').WorkerOut} WorkerOut */

const BATCH_MS = 12;          // one batch of planning, then yield to the message queue
const FRAME_SPACING = 0.004;  // animation frames along the path, in the robot's metric
const CSPACE_N = 128;         // cells per side of the configuration-space grid
const OPTIMUM_S = 0.5;        // the visibility graph's time for the cost chart's reference line…
const OPTIMUM_MAX = 500;
const PATH_POSES_3D = 2000;   // the 3-D view's arm animation: at most this many poses of a path      // …on maps of at most this many obstacles (its graph is quadratic: 1,000 rects take 1.3 s natively)

let scene = null;       // current Scene (runs are made from it: the scenario is never re-read as text)
let setup = { planner: 'rrt-connect', params: {}, seed: 1 };
let run = null;         // current Run
let runId = 0;
let running = false;
let dead = false;
let tries = { seen: 0, sent: 0 }; // the current run's raw tries: drawn by the core, sent to the page
let view3d = false;     // the scene has a 3-D view (caps.view3d): runs log their nodes for its trees
let stepping = null;    // a `step` in progress: {token, target} (it runs in bounded batches too)
let stepToken = 0;

const ready = init().then(() => {
  install_panic_hook();
  post({ type: 'ready', builtins: JSON.parse(builtins()), planners: JSON.parse(planners()),
         eventKinds: JSON.parse(event_kinds()), robotKinds: JSON.parse(robot_kinds()) });
});

/**
 * Run `f` as the worker's next task, once it has read the messages already queued: a message on a
 * channel of its own, not `setTimeout(f, 0)`, which browsers clamp to 4 ms once timers nest five
 * deep, so every 12 ms batch of a run waited 4 ms idle (measured in headless chromium: 100 batches
 * of 12 ms took 1.6 s by timers, 1.21 s by the channel; a page's message still waits at most one
 * batch, both being message tasks).
 * @type {(f: () => void) => void}
 */
const nextTask = (() => {
  const channel = new MessageChannel();
  /** @type {Array<() => void>} */
  const queue = [];
  channel.port1.onmessage = () => { queue.shift()?.(); };
  return (f) => { queue.push(f); channel.port2.postMessage(null); };
})();

/** @param {WorkerOut} msg @param {Transferable[]} [transfer] */
function post(msg, transfer = []) {
  self.postMessage(msg, transfer);
}

function freeRun() {
  if (run) { run.free(); run = null; }
  running = false;
  tries = { seen: 0, sent: 0 };
}

function ensureRun() {
  if (!run) {
    if (!scene) throw new Error('no scenario loaded');
    run = scene.run(setup.planner, JSON.stringify(setup.params), setup.seed);
    if (view3d) { run.log_nodes(true); run.log_states(true); }
  }
  return run;
}

function flush(status) {
  const data = thinTries(run.drain_events(), tries);
  /** @type {WorkerOut} */
  const events = { type: 'events', run: runId, data, stats: JSON.parse(run.stats_json()), status, tries: { ...tries } };
  const transfer = [data.buffer];
  if (view3d) {
    events.tree3d = run.drain_tool_tree();
    events.states = run.drain_states();
    transfer.push(events.tree3d.buffer, events.states.buffer);
  }
  post(events, transfer);
  if (status !== 'running') {
    running = false;
    const result = JSON.parse(run.result_json());
    const frames = result.solved ? run.path_frames(false, FRAME_SPACING) : new Float64Array(0);
    const rawFrames = result.solved ? run.path_frames(true, FRAME_SPACING) : new Float64Array(0);
    const path3d = view3d && result.solved ? pathIn3d(frames, run.path_lengths(false, FRAME_SPACING)) : undefined;
    const rawPath3d = view3d && result.solved ? pathIn3d(rawFrames, run.path_lengths(true, FRAME_SPACING)) : undefined;
    const moved = [path3d, rawPath3d].flatMap((p) => (p ? [p.tool.buffer, p.frames.buffer, p.lengths.buffer] : []));
    post({ type: 'result', run: runId, result, frames, rawFrames, path3d, rawPath3d }, [...moved, frames.buffer, rawFrames.buffer]);
  }
}

/**
 * For the 3-D view, a solved path from its animation frames (`Run.path_frames`: dims, count, then
 * each frame's state and outline): the tool's curve through every frame, and the link frames of at
 * most PATH_POSES_3D of them, evenly spread, for the arm's animation; and the core's lengths along
 * the path at each frame and waypoint (`Run.path_lengths`, for the path panel: it shows the core's
 * numbers, never its own sums).
 * @param {Float64Array} frames
 * @param {Float64Array} lengths
 * @returns {import('../run/messages.js').Path3d}
 */
function pathIn3d(frames, lengths) {
  const dims = frames[0] | 0;
  const count = frames[1] | 0;
  const stride = Math.max(1, Math.ceil(count / PATH_POSES_3D));
  const states = new Float64Array(count * dims);
  let n = 0;
  let at = 2;
  for (; n < count && at + dims <= frames.length; n++) {
    states.set(frames.subarray(at, at + dims), n * dims);
    at += dims;
    const polys = frames[at++] | 0; // the outline: [n_polygons, n_1, x, y…, …]
    for (let p = 0; p < polys; p++) at += 1 + 2 * (frames[at] | 0);
  }
  const poses = [];
  for (let f = 0; f < n; f++) {
    if (f % stride === 0 || f === n - 1) poses.push(scene.link_frames(states.subarray(f * dims, (f + 1) * dims)));
  }
  const links = poses.length ? poses[0].length / 16 : 0;
  const flat = new Float64Array(poses.length * links * 16);
  poses.forEach((p, i) => flat.set(p, i * links * 16));
  // The tool's curve through every frame, from the core in one call.
  const tool = scene.tool_points(states.subarray(0, n * dims));
  return { tool, frames: flat, count: poses.length, links, stride, lengths };
}

function loop(id) {
  if (!running || id !== runId || dead) return;
  guarded(() => {
    const status = run.step(1e9, BATCH_MS);
    flush(status);
    if (status === 'running') nextTask(() => loop(id));
  });
}

/**
 * A `step` of n iterations runs in bounded batches like a run, so a slow iteration never keeps
 * the worker from reading its messages (a batch the core suspends mid-iteration is replayed by
 * the next: src/journal.rs). It flushes once, when the iterations are done or the run ends.
 */
function stepLoop(token) {
  if (!stepping || stepping.token !== token || dead || !run) return;
  guarded(() => {
    const before = JSON.parse(run.stats_json()).iterations;
    const status = run.step(Math.max(0, stepping.target - before), BATCH_MS);
    const after = JSON.parse(run.stats_json()).iterations;
    if (status === 'running' && after < stepping.target) {
      nextTask(() => stepLoop(token));
      return;
    }
    stepping = null;
    flush(status);
  });
}

/** A panic (or a trap) must reach guarded() as a crash, not be answered as a refused request. */
function rethrowPanic(e) {
  if (last_panic() || e instanceof WebAssembly.RuntimeError) throw e;
}

function parseError(e) {
  try { return JSON.parse(e.message); } catch { return { message: String(e.message || e), text: String(e.message || e) }; }
}

/**
 * Make the scene `make()` returns current (a `load` or an `import`): the limit on a file's size is
 * the core's, on the text the user gave; an imported file is read straight into a scene, never
 * written out as JSON and read again (a pretty-printed copy was nearly three times the file).
 */
function load(make) {
  freeRun();
  runId++;
  let next;
  try {
    next = make();
  } catch (e) {
    rethrowPanic(e);
    post({ type: 'invalid', run: runId, error: parseError(e) });
    return;
  }
  if (scene) scene.free();
  scene = next;
  const sc = JSON.parse(scene.scenario_json());
  const start = scene.outline(new Float64Array(sc.start));
  const goal = sc.goal ? scene.outline(new Float64Array(sc.goal)) : new Float64Array(0);
  const space = JSON.parse(scene.space_json());
  // What the core decided for this scene (scene_caps): the robot kind's record, the c-space view,
  // the optimum, the solution file, the draggable pose.
  const caps = JSON.parse(scene.caps_json(OPTIMUM_MAX));
  /** @type {import('../run/messages.js').LoadedReply & {run: number}} */
  const msg = { type: 'loaded', run: runId, scenario: sc, start, goal, space, caps };
  const transfer = [];
  if (caps.cspace) {
    const grid = scene.cspace_grid(CSPACE_N);
    if (grid.length === CSPACE_N * CSPACE_N) {
      msg.cspace = { n: CSPACE_N, grid, dims: space };
      transfer.push(grid.buffer);
    }
  }
  // The shortest path's cost (visibility graph), for a robot whose paths are polylines in the plane
  // (a point or a rigid body): {cost, exact} or {error}. The cost chart draws it as its reference
  // line when it is the robot's optimum.
  if (caps.optimum) {
    try { msg.optimum = JSON.parse(scene.optimum_json(OPTIMUM_S)); } catch (e) { rethrowPanic(e); }
  }
  // A robot in 3-D (caps.view3d): its parts' meshes and the scene's solids, once, and the link
  // frames at the start and goal, for the page's 3-D view.
  view3d = !!caps.view3d;
  if (view3d) {
    const goalFrames = sc.goal ? scene.link_frames(new Float64Array(sc.goal)) : new Float64Array(0);
    const startFrames = scene.link_frames(new Float64Array(sc.start));
    msg.spatial = { ...JSON.parse(scene.spatial_json()), start: startFrames, goal: goalFrames };
    transfer.push(startFrames.buffer, goalFrames.buffer);
  }
  post(msg, transfer);
}

/**
 * An occupancy map's scene (see `import` above); throws what the core throws.
 * @param {Extract<WorkerIn, {type: 'import'}>} msg
 */
function importMap(msg) {
  const yamlName = String(msg.yamlName || 'map.yaml');
  if (!msg.bytes) {
    const image = map_image_name(String(msg.yaml), yamlName); // throws the YAML's own errors first
    const message = `${yamlName} names its image "${image}": open the YAML and that image together (choose both files)`;
    throw new Error(JSON.stringify({ path: 'image', message, line: null, column: null, text: message }));
  }
  const yaml = msg.yaml == null ? undefined : String(msg.yaml);
  return Scene.from_map(new Uint8Array(msg.bytes), String(msg.name || 'map'), yaml, yaml === undefined ? undefined : yamlName);
}

/** @param {WorkerIn} msg */
function handle(msg) {
  // Any request but another step ends a step in progress.
  if (msg.type !== 'step' && msg.type !== 'asv-solution' && msg.type !== 'query' && msg.type !== 'ping' && msg.type !== 'fresh-seed') stepping = null;
  switch (msg.type) {
    case 'load':
      load(() => new Scene(String(msg.text)));
      return;
    case 'import':
      load(() => (msg.bytes || msg.yaml != null ? importMap(msg) : Scene.from_file(String(msg.text), String(msg.name || ''))));
      return;
    case 'configure':
      setup = { planner: msg.planner, params: msg.params || {}, seed: msg.seed };
      freeRun();
      runId++;
      post({ type: 'status', run: runId, status: 'idle' });
      return;
    case 'run':
      try { ensureRun(); } catch (e) { rethrowPanic(e); post({ type: 'error', run: runId, message: parseError(e).text }); return; }
      if (!running) {
        running = true;
        const id = runId;
        nextTask(() => loop(id));
      }
      return;
    case 'pause':
      running = false;
      post({ type: 'status', run: runId, status: 'paused' });
      return;
    case 'step': {
      running = false;
      try { ensureRun(); } catch (e) { rethrowPanic(e); post({ type: 'error', run: runId, message: parseError(e).text }); return; }
      // A step asked for while one is under way adds to it.
      const start = stepping ? stepping.target : JSON.parse(run.stats_json()).iterations;
      stepping = { token: ++stepToken, target: start + Math.max(1, msg.iterations | 0) };
      stepLoop(stepping.token);
      return;
    }
    case 'reset':
      freeRun();
      runId++;
      post({ type: 'status', run: runId, status: 'idle' });
      return;
    case 'cancel':
      if (run) { run.cancel(); running = false; flush('cancelled'); }
      return;
    case 'asv-solution':
      if (!run) {
        post({ type: 'error', run: runId, message: 'no run to write a solution file for' });
        return;
      }
      post({ type: 'asv-solution', run: runId, text: run.asv_solution() });
      return;
    case 'query': {
      if (!run) {
        post({ type: 'query', run: runId, data: new Float64Array(0), answer: { error: 'no run: the roadmap is built by a run first' } });
        return;
      }
      const state = (v) => Float64Array.from(Array.isArray(v) ? v.slice(0, 64).map(Number) : []);
      let answer;
      try { answer = JSON.parse(run.query(state(msg.start), state(msg.goal))); } catch (e) { rethrowPanic(e); answer = { error: parseError(e).text }; }
      const data = run.drain_events();
      const states = view3d ? run.drain_states() : undefined;
      post({ type: 'query', run: runId, data, answer, states }, states ? [data.buffer, states.buffer] : [data.buffer]);
      return;
    }
    case 'debug-panic':
      debug_panic(msg.message || 'debug panic requested');
      return;
    case 'debug-hang': { // a busy loop: the worker reads no message until it ends
      const end = performance.now() + Math.max(0, Number(msg.ms) || 0);
      while (performance.now() < end) { /* busy */ }
      return;
    }
    case 'ping':
      return;
    case 'fresh-seed': // entropy from the core (getrandom → Web Crypto); the page shows and records it
      post({ type: 'seed', seed: fresh_seed() });
      return;
    default:
      post({ type: 'error', run: runId, message: `unknown message type ${/** @type {any} */ (msg).type}` });
  }
}

function guarded(fn) {
  try {
    fn();
  } catch (e) {
    const panic = last_panic();
    if (panic || e instanceof WebAssembly.RuntimeError) {
      dead = true;
      running = false;
      post({ type: 'crashed', message: panic || String(e) });
    } else {
      post({ type: 'error', run: runId, message: String(e && e.message || e) });
    }
  }
}

/** @param {MessageEvent<WorkerIn>} e */
self.onmessage = async (e) => {
  if (e.data?.ack != null) post({ type: 'ack', ack: e.data.ack }); // read, even before the core is ready
  try {
    await ready;
  } catch (err) {
    post({ type: 'crashed', message: `the planning core failed to load: ${err}` });
    return;
  }
  if (dead) { post({ type: 'crashed', message: 'the planning core stopped after an earlier error' }); return; }
  guarded(() => handle(e.data));
};

// The planning worker: one stateful session per worker (wasm-in-web-worker style).
//
// Messages in  {type, ...}:
//   load      {text}                         validate a scenario (JSON text) and keep it
//   configure {planner, params, seed}        choose the planner set-up for the next run
//   run       {}                             start (or resume) planning; streams events
//   pause     {}                             stop stepping, keep the run
//   step      {iterations}                   run exactly that many iterations, then pause
//   reset     {}                             drop the run (the next run starts from the seed)
//   cancel    {}                             stop the run now; it is finished
// Messages out {type, run, ...}:
//   ready     {builtins, planners, eventKinds}
//   loaded    {scenario, start, goal}        normalised scenario; start/goal outlines (flat)
//   invalid   {error: {path, message, line, column, text}}
//   events    {data: Float64Array, stats, status}   transferred, once per batch
//   result    {result, frames: Float64Array, rawFrames: Float64Array}
//   status    {status}
//   error     {message}                      a bad request; the worker stays usable
//   crashed   {message}                      the core panicked; the page must replace this worker
// `run` is a counter bumped on every run/reset/load, so the page can drop stale replies.

import init, { Scene, Run, builtins, planners, event_kinds, install_panic_hook, last_panic, debug_panic }
  from './pkg/planarium.js';

const BATCH_MS = 12;          // one batch of planning, then yield to the message queue
const FRAME_SPACING = 0.004;  // animation frames along the path, in the robot's metric

let scene = null;       // current Scene
let scenarioText = null;
let setup = { planner: 'rrt-connect', params: {}, seed: 1 };
let run = null;         // current Run
let runId = 0;
let running = false;
let dead = false;

const ready = init().then(() => {
  install_panic_hook();
  post({ type: 'ready', builtins: JSON.parse(builtins()), planners: JSON.parse(planners()),
         eventKinds: JSON.parse(event_kinds()) });
});

function post(msg, transfer = []) {
  self.postMessage(msg, transfer);
}

function freeRun() {
  if (run) { run.free(); run = null; }
  running = false;
}

function ensureRun() {
  if (!run) {
    if (!scenarioText) throw new Error('no scenario loaded');
    run = new Run(scenarioText, setup.planner, JSON.stringify(setup.params), setup.seed);
  }
  return run;
}

function flush(status) {
  const data = run.drain_events();
  post({ type: 'events', run: runId, data, stats: JSON.parse(run.stats_json()), status }, [data.buffer]);
  if (status !== 'running') {
    running = false;
    const result = JSON.parse(run.result_json());
    const frames = result.solved ? run.path_frames(false, FRAME_SPACING) : new Float64Array(0);
    const rawFrames = result.solved ? run.path_frames(true, FRAME_SPACING) : new Float64Array(0);
    post({ type: 'result', run: runId, result, frames, rawFrames }, [frames.buffer, rawFrames.buffer]);
  }
}

function loop(id) {
  if (!running || id !== runId || dead) return;
  guarded(() => {
    const status = run.step(1e9, BATCH_MS);
    flush(status);
    if (status === 'running') setTimeout(() => loop(id), 0);
  });
}

function parseError(e) {
  try { return JSON.parse(e.message); } catch { return { message: String(e.message || e), text: String(e.message || e) }; }
}

function handle(msg) {
  switch (msg.type) {
    case 'load': {
      freeRun();
      runId++;
      let next;
      try {
        next = new Scene(msg.text);
      } catch (e) {
        post({ type: 'invalid', run: runId, error: parseError(e) });
        return;
      }
      if (scene) scene.free();
      scene = next;
      scenarioText = scene.scenario_json();
      const sc = JSON.parse(scenarioText);
      const start = scene.outline(new Float64Array(sc.start));
      const goal = sc.goal ? scene.outline(new Float64Array(sc.goal)) : new Float64Array(0);
      post({ type: 'loaded', run: runId, scenario: sc, start, goal });
      return;
    }
    case 'configure':
      setup = { planner: msg.planner, params: msg.params || {}, seed: msg.seed };
      freeRun();
      runId++;
      post({ type: 'status', run: runId, status: 'idle' });
      return;
    case 'run':
      try { ensureRun(); } catch (e) { post({ type: 'error', run: runId, message: parseError(e).text }); return; }
      if (!running) {
        running = true;
        const id = runId;
        setTimeout(() => loop(id), 0);
      }
      return;
    case 'pause':
      running = false;
      post({ type: 'status', run: runId, status: 'paused' });
      return;
    case 'step': {
      running = false;
      try { ensureRun(); } catch (e) { post({ type: 'error', run: runId, message: parseError(e).text }); return; }
      const status = run.step(Math.max(1, msg.iterations | 0), 1e9);
      flush(status);
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
    case 'debug-panic':
      debug_panic(msg.message || 'debug panic requested');
      return;
    default:
      post({ type: 'error', run: runId, message: `unknown message type ${msg.type}` });
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

self.onmessage = async (e) => {
  try {
    await ready;
  } catch (err) {
    post({ type: 'crashed', message: `the planning core failed to load: ${err}` });
    return;
  }
  if (dead) { post({ type: 'crashed', message: 'the planning core stopped after an earlier error' }); return; }
  guarded(() => handle(e.data));
};

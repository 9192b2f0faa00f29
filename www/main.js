// Wiring: the worker session, the controller's table, the panel, playback and the view.
// Read-only state for tests is exposed as window.planarium (nothing else is global).

import { Controller, BUTTONS } from './controller.js';
import { View, PALETTE } from './view.js';
import { CSpaceView } from './cspace.js';
import { Editor } from './editor.js';
import { fitViews, downloadText } from './stage.js';
import { createPanel } from './panel.js';
import { Playback } from './playback.js';

const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), file: $('file'), error: $('error'), errorText: $('error-text'), errorClose: $('error-close'),
  stage: $('stage'), canvas: $('canvas'), cspace: $('cspace'), course: $('scenario-course'), name: $('scenario-name'),
  notes: $('scenario-notes'), legend: $('legend'), endpoints: $('endpoints'), download: $('download-solution'),
  panel: $('panel'), stepSize: $('step-size'), speed: $('speed'), speedOut: $('speed-out'),
  animSpeed: $('anim-speed'), animOut: $('anim-speed-out'), showRejected: $('show-rejected'),
  showCollisions: $('show-collisions'), animRaw: $('anim-raw'), status: $('status'), stats: $('stats'),
};

const controller = new Controller('loading');
const playback = new Playback();
const view = new View(ui.canvas, playback.store);
const cspace = new CSpaceView(ui.cspace, playback.store, PALETTE);

// Worker session
let worker = null;
let latestRun = -1;      // `run` of the latest status/loaded/invalid message
let bumpsPending = 0;    // load/configure/reset sent, not yet answered: drop events until answered
let loadsPending = 0;
let registry = null;     // {planners, run_params} from the first `ready`
let panel = null;
let builtins = [];
let scenarioText = null; // the last valid scenario (reloaded after a crash)
let sentEdit = false;    // the latest `load` is a start/goal edit
let course = '';         // the course of the scenario being loaded
let loaded = null;       // the latest `loaded` message's scenario
let applyDefaults = false;
let crashes = [];

// The current run, as the page sees it
let workerStats = null;
let finalStatus = null;  // the planner's terminal status word
let result = null;
let workerDone = false;  // the `result` message arrived
let stepPending = false; // reveal the answer to a step at once
let revealOnePending = false;
let lastFrame = 0;

function send(msg) { worker.postMessage(msg); }

function startWorker() {
  const w = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  worker = w;
  latestRun = -1;
  bumpsPending = 0;
  loadsPending = 0;
  w.onmessage = (e) => { if (w === worker) onMessage(e.data); };
  w.onerror = (e) => {
    e.preventDefault();
    if (w === worker) recover(e.message || 'the worker failed to start');
  };
  w.onmessageerror = () => { if (w === worker) recover('a message from the worker could not be read'); };
}

function recover(message) {
  showError(`The planning worker stopped: ${message}`);
  worker.terminate();
  worker = null;
  const now = performance.now();
  crashes = crashes.filter((t) => now - t < 10000).concat(now);
  clearRun();
  if (crashes.length > 3) {
    showError(`The planning worker keeps stopping (${message}). Reload the page to try again.`);
    return;
  }
  controller.fire('load');
  startWorker(); // its `ready` reloads the current scenario and configuration
}

function onMessage(msg) {
  switch (msg.type) {
    case 'ready': return onReady(msg);
    case 'loaded': {
      latestRun = msg.run;
      bumpsPending = Math.max(0, bumpsPending - 1);
      if (--loadsPending > 0) return; // a newer load is on its way
      scenarioText = JSON.stringify(msg.scenario);
      showScenario(msg);
      if (applyDefaults) panel.apply(msg.scenario.planner);
      applyDefaults = false;
      configure(); // fires 'configure' only from states that allow it; then 'loaded' below
      controller.fire('loaded');
      return;
    }
    case 'invalid': {
      latestRun = msg.run;
      bumpsPending = Math.max(0, bumpsPending - 1);
      if (--loadsPending > 0) return;
      showInvalid(msg.error, sentEdit);
      return;
    }
    case 'status':
      latestRun = msg.run;
      if (msg.status === 'idle') bumpsPending = Math.max(0, bumpsPending - 1);
      return;
    case 'events':
      // one run, one result: drop replies for other runs and anything after the result
      if (msg.run !== latestRun || bumpsPending || workerDone) return;
      playback.push(msg.data);
      workerStats = msg.stats;
      if (msg.status !== 'running') finalStatus = msg.status;
      if (stepPending || controller.state === 'finished') { stepPending = false; reveal(playback.revealAll()); }
      if (revealOnePending) { revealOnePending = false; reveal(playback.reveal(1)); }
      updateStats();
      return;
    case 'result':
      if (msg.run !== latestRun || bumpsPending || workerDone) return;
      result = msg.result;
      workerDone = true;
      view.setResult(msg.result, msg.frames, msg.rawFrames);
      cspace.setResult(msg.result);
      maybeFinish();
      updateStats();
      return;
    case 'error':
      showError(msg.message);
      stepPending = revealOnePending = false;
      if (!workerDone && controller.fire('fail')) clearRun();
      return;
    case 'asv-solution':
      if (msg.run === latestRun) downloadText(msg.text, `${(loaded?.name || 'solution').replace(/[^\w.-]+/g, '_')}-solution.txt`);
      return;
    case 'crashed':
      recover(msg.message);
      return;
    default:
      console.warn('unknown message from the worker', msg.type);
  }
}

function onReady(msg) {
  if (!registry) {
    registry = msg.planners;
    builtins = msg.builtins;
    panel = createPanel(ui.panel, registry, () => { configure(); clearError(); });
    const groups = new Map(); // course → optgroup, in the order given
    for (const b of builtins) {
      if (!groups.has(b.course)) {
        const g = document.createElement('optgroup');
        g.label = b.course || 'Other';
        groups.set(b.course, g);
        ui.scenario.append(g);
      }
      groups.get(b.course).append(new Option(b.name, b.id));
    }
    const first = builtins.find((b) => b.id === new URLSearchParams(location.search).get('scenario')) || builtins[0];
    ui.scenario.value = first.id;
    load(JSON.stringify(first.scenario), true, { course: first.course });
  } else if (scenarioText) {
    load(scenarioText, false, { course }); // after a crash: same scenario, same configuration
  }
}

// Requests

/** Send a scenario (or, with `file`, any file the core imports) to the worker. */
function load(text, defaults, { course: c = course, edit = false, file = null } = {}) {
  sentEdit = edit;
  course = c;
  applyDefaults = defaults;
  loadsPending++;
  bumpsPending++;
  if (!edit) editor.loading();
  clearRun();
  controller.fire('load');
  send(file ? { type: 'import', text, name: file } : { type: 'load', text });
}

function configure() {
  if (!panel || !worker) return;
  bumpsPending++;
  send({ type: 'configure', ...panel.config() });
  clearRun();
  controller.fire('configure');
}

const actions = {
  run() {
    if (!controller.can('run')) return;
    clearError();
    if (controller.state === 'finished') resetRun();
    controller.fire('run');
    if (!workerDone) send({ type: 'run' });
  },
  pause() {
    if (!controller.fire('pause')) return;
    if (!workerDone) send({ type: 'pause' });
  },
  step() {
    if (!controller.fire('step')) return;
    if (workerDone) { reveal(playback.revealAll()); return; }
    stepPending = true;
    send({ type: 'step', iterations: Math.max(1, Math.floor(Number(ui.stepSize.value)) || 1) });
  },
  stepEvent() {
    if (!controller.fire('stepEvent')) return;
    if (playback.pending > 0) reveal(playback.reveal(1));
    else if (!workerDone) { revealOnePending = true; send({ type: 'step', iterations: 1 }); }
  },
  reset() {
    if (!controller.can('reset')) return;
    resetRun();
    controller.fire('reset');
  },
  cancel() {
    if (!controller.can('cancel')) return;
    if (workerDone) { // the planner already stopped: show the rest now
      reveal(playback.revealAll());
      maybeFinish();
      return;
    }
    send({ type: 'cancel' });
    finalStatus = 'cancelled';
    reveal(playback.revealAll());
    controller.fire('cancel');
  },
};

function resetRun() {
  bumpsPending++;
  send({ type: 'reset' });
  clearRun();
}

// Run state and playback

function clearRun() {
  playback.clear();
  view.clearRun();
  cspace.clearRun();
  workerStats = null;
  finalStatus = null;
  result = null;
  workerDone = false;
  stepPending = false;
  revealOnePending = false;
  updateStats();
  syncDownload();
}

function reveal([from, to]) {
  if (to > from) { view.drawRecords(from, to); cspace.drawRecords(from, to); }
  maybeFinish();
}

function maybeFinish() {
  if (workerDone && playback.pending === 0 && controller.fire('finish')) updateStats();
  if (controller.state === 'finished' && result && !view.showResult) {
    view.showResult = cspace.showResult = true;
    view.dirty = cspace.dirty = true;
    syncDownload();
  }
}

function speedRate() {
  const v = Number(ui.speed.value);
  return v >= Number(ui.speed.max) ? Infinity : Math.round(10 ** (1 + (4 * v) / 100));
}
function animFps() { return 10 ** (0.5 + (2.5 * Number(ui.animSpeed.value)) / 100); }

function frame(time) {
  const dt = Math.min(0.25, (time - (lastFrame || time)) / 1000);
  lastFrame = time;
  if (controller.state === 'running' && playback.pending > 0) reveal(playback.tick(speedRate(), dt));
  else if (controller.state === 'running') maybeFinish();
  view.render(time, animFps());
  cspace.render(view.robotState);
  requestAnimationFrame(frame);
}

// Display

function showScenario({ scenario, start, goal, space, cspace: grid }) {
  loaded = scenario;
  ui.course.textContent = course;
  ui.name.textContent = scenario.name || 'Untitled scenario';
  ui.notes.textContent = scenario.notes || '';
  view.setScenario(scenario, start, goal);
  cspace.setSpace(grid || null, scenario.start, scenario.goal);
  editor.setScenario(scenario, space, sentEdit);
  ui.cspace.hidden = !cspace.active;
  ui.stage.classList.toggle('dual', cspace.active);
  buildLegend();
  onResize();
}

function showInvalid(error, edit) {
  const where = [error.path, error.line != null ? `line ${error.line}` : null,
    error.column != null ? `column ${error.column}` : null].filter(Boolean).join(', ');
  if (edit) {
    const which = /^(start|goal)\b/.exec(error.path || '')?.[1] || 'start or goal';
    showError(`The new ${which} is not valid${/^(start|goal)$/.test(error.path) ? '' : ` at ${where}`}: ` +
      `${error.message || error.text}\nMove it back to a free place, restore it, or pick another scenario.`);
  } else {
    showError(`This scenario has an error${where ? ` at ${where}` : ''}: ${error.message || error.text}`);
  }
  clearRun();
  if (!edit) { // an edit keeps the scene on screen, so the start or goal can be dragged back
    loaded = null;
    ui.course.textContent = '';
    ui.name.textContent = 'No valid scenario';
    ui.notes.textContent = 'Fix the file and open it again, or pick a built-in scenario.';
    view.setScenario(null);
    cspace.setSpace(null);
    editor.setScenario(null, null, false);
    ui.cspace.hidden = true;
    ui.stage.classList.remove('dual');
    onResize();
  }
  controller.fire('invalid');
}

function showError(text) {
  ui.errorText.textContent = text;
  ui.error.hidden = false;
}
function clearError() {
  ui.error.hidden = true;
  ui.errorText.textContent = '';
}

const STAT_FIELDS = [
  ['time', (s) => s.time_ms?.toFixed(1)],
  ['iterations', (s) => s.iterations],
  ['nodes', (s) => s.nodes],
  ['checks', (s) => s.checks],
  ['cost', (s) => s.cost?.toFixed(4)],
  ['smoothed-cost', (s) => s.smoothed_cost?.toFixed(4)],
];

function statusWord() {
  return controller.state === 'finished' ? (finalStatus || (result?.solved ? 'solved' : 'finished')) : controller.state;
}

function currentStats() {
  const s = (controller.state === 'finished' && result?.stats) || workerStats || {};
  return { ...s, status: statusWord(), shown_nodes: playback.nodeCount, shown_events: playback.store.length, queued_events: playback.pending };
}

function updateStats() {
  const s = currentStats();
  ui.status.textContent = s.status;
  ui.status.dataset.status = s.status;
  for (const [key, fmt] of STAT_FIELDS) {
    const v = fmt(s);
    $(`stat-${key}`).textContent = v === undefined || v === null || Number.isNaN(v) ? '–' : String(v);
  }
  $('stat-shown').textContent = `${s.shown_nodes} (${s.queued_events} events queued)`;
}

function syncButtons() {
  const enabled = controller.buttons();
  for (const id of Object.keys(BUTTONS)) $(id).disabled = !enabled[id];
  const busy = controller.state === 'loading';
  ui.scenario.disabled = busy;
  ui.file.disabled = busy;
  panel?.setDisabled(busy);
  document.body.dataset.state = controller.state;
}

controller.onChange(() => { syncButtons(); updateStats(); });

function buildLegend() {
  ui.legend.replaceChildren(...view.legend().map(({ label, color, shape }) => {
    const li = document.createElement('li');
    const sw = document.createElement('span');
    sw.className = `swatch ${shape}`;
    sw.style.setProperty('--c', color);
    sw.setAttribute('aria-hidden', 'true');
    li.append(sw, document.createTextNode(label));
    return li;
  }));
}

// Start / goal editing and the solution file

const editor = new Editor({
  canvas: ui.canvas, view, root: ui.endpoints, palette: PALETTE,
  onPreview(which, state) {
    view.preview[which] = state.slice();
    view.dirty = true;
    cspace.setStartGoal(view.stateOf('start'), view.stateOf('goal'));
  },
  onCommit(scenario) {
    clearError();
    load(JSON.stringify(scenario), false, { edit: true });
  },
});

function syncDownload() {
  ui.download.hidden = !(loaded?.robot?.kind === 'asv' && result?.solved && controller.state === 'finished');
}

ui.download.addEventListener('click', () => { if (worker && result?.solved) send({ type: 'asv-solution' }); });

// Inputs

for (const [id, event] of Object.entries(BUTTONS)) $(id).addEventListener('click', () => actions[event]());
ui.errorClose.addEventListener('click', clearError);

ui.scenario.addEventListener('change', () => {
  const b = builtins.find((x) => x.id === ui.scenario.value);
  if (!b) return;
  clearError();
  for (const o of [...ui.scenario.options]) if (o.dataset.file) o.remove();
  load(JSON.stringify(b.scenario), true, { course: b.course });
});

ui.file.addEventListener('change', async () => {
  const file = ui.file.files[0];
  ui.file.value = ''; // the same file can be opened again
  if (!file) return;
  clearError();
  let text;
  try { text = await file.text(); } catch (e) { showError(`Could not read ${file.name}: ${e.message}`); return; }
  for (const o of [...ui.scenario.options]) if (o.dataset.file) o.remove();
  const opt = new Option(`File: ${file.name}`, '', true, true);
  opt.dataset.file = 'yes';
  opt.disabled = true;
  ui.scenario.append(opt);
  ui.scenario.value = '';
  opt.selected = true;
  load(text, true, { course: 'Opened file', file: file.name });
});

function updateOutputs() {
  const r = speedRate();
  ui.speedOut.textContent = Number.isFinite(r) ? `${r.toLocaleString('en')} events/s` : 'all at once';
  ui.animOut.textContent = `${Math.round(animFps())} frames/s`;
}
ui.speed.addEventListener('input', updateOutputs);
ui.animSpeed.addEventListener('input', updateOutputs);
const syncOptions = () => {
  view.setOptions({ showRejected: ui.showRejected.checked, showCollisions: ui.showCollisions.checked, animateRaw: ui.animRaw.checked });
  cspace.setOptions({ showRejected: ui.showRejected.checked, showCollisions: ui.showCollisions.checked });
};
for (const box of [ui.showRejected, ui.showCollisions, ui.animRaw]) box.addEventListener('change', syncOptions);

document.addEventListener('keydown', (e) => {
  if (e.ctrlKey || e.metaKey || e.altKey || e.repeat && e.key !== 'ArrowRight') return;
  const t = e.target;
  if (t instanceof Element && t.closest('input, select, textarea, [contenteditable]')) return;
  if (e.key === ' ') {
    e.preventDefault(); // also keeps a focused button from being clicked by the same key
    if (controller.state === 'running') actions.pause(); else actions.run();
  } else if (e.key === 'ArrowRight') {
    e.preventDefault();
    actions.step();
  } else if (e.key === 'r' || e.key === 'R') {
    actions.reset();
  }
});

// Size: the views follow the stage (and the device pixel ratio).
const onResize = fitViews(ui.stage, view, cspace);

Object.defineProperty(window, 'planarium', {
  value: Object.freeze({
    state: () => controller.state,
    stats: () => currentStats(),
    result: () => (result ? structuredClone(result) : null),
    scenario: () => (editor.scenario ? structuredClone(editor.scenario) : null),
    nodeCount: () => playback.nodeCount,
  }),
  writable: false,
  configurable: false,
});

buildLegend();
updateOutputs();
syncOptions();
syncButtons();
updateStats();
startWorker();
requestAnimationFrame(frame);

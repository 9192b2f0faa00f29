// Wiring: one lane (the worker session, its playback, the views and the chart: lane.js), the
// controller's table, the panel, the overlay box and the stats; the hover text of cells and
// potential fields (cells.js), and the note under the canvas when a planner finds no path.
// Read-only state for tests is exposed as window.planarium (nothing else is global).

import { Controller, BUTTONS } from './controller.js';
import { View } from './view.js';
import { PALETTE } from './palette.js';
import { CSpaceView } from './cspace.js';
import { Editor } from './editor.js';
import { fitViews, downloadText } from './stage.js';
import { createPanel, taskOf } from './panel.js';
import { Playback } from './playback.js';
import { Chart } from './chart.js';
import { Lane } from './lane.js';
import { createStats } from './stats.js';
import { createOverlays } from './overlays.js';
import { cellLegend, cellSummary } from './cells.js';
import { chartKind, speedRate, animFps, describeSpeed, modelSummary, fillScenarioPicker, errorBox } from './shared.js';

const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), file: $('file'), error: $('error'), errorText: $('error-text'), errorClose: $('error-close'),
  stage: $('stage'), canvas: $('canvas'), cspace: $('cspace'), course: $('scenario-course'), name: $('scenario-name'),
  notes: $('scenario-notes'), legend: $('legend'), endpoints: $('endpoints'), download: $('download-solution'),
  panel: $('panel'), stepSize: $('step-size'), speed: $('speed'), speedOut: $('speed-out'),
  animSpeed: $('anim-speed'), animOut: $('anim-speed-out'), animRaw: $('anim-raw'), overlays: $('overlays'),
  stats: $('stats'), chartBox: $('chart-box'), chart: $('chart'), chartTitle: $('chart-title'), compare: $('to-compare'),
  tip: $('cell-tip'), runNote: $('run-note'),
};
const { show: showError, clear: clearError } = errorBox(ui.error, ui.errorText);

const controller = new Controller('loading');
const playback = new Playback();
const view = new View(ui.canvas, playback.store, playback.model);
const cspace = new CSpaceView(ui.cspace, playback.store, PALETTE, playback.model);
const chart = new Chart(ui.chart, playback.model, PALETTE);
const updateStatsList = createStats(ui.stats);

let registry = null;     // {planners, run_params} from the first `ready`
let panel = null;
let builtins = [];
let scenarioText = null; // the last valid scenario (reloaded after a crash)
let sentEdit = false;    // the latest `load` is a start/goal edit
let course = '';         // the course of the scenario being loaded
let loaded = null;       // the latest `loaded` message's scenario
let applyDefaults = false;
let lastFrame = 0;

const lane = new Lane({
  playback,
  views: [view, cspace],
  chart,
  hooks: {
    ready: onReady,
    loaded(msg) {
      scenarioText = JSON.stringify(msg.scenario);
      showScenario(msg);
      panel.setTask(taskOf(msg.scenario));
      if (applyDefaults) panel.apply(msg.scenario.planner);
      applyDefaults = false;
      configure(); // fires 'configure' only from states that allow it; then 'loaded' below
      controller.fire('loaded');
    },
    invalid(error) { showInvalid(error, sentEdit); },
    error(message) {
      showError(message);
      if (!lane.done && controller.fire('fail')) lane.clearRun();
    },
    asv(text) { downloadText(text, `${(loaded?.name || 'solution').replace(/[^\w.-]+/g, '_')}-solution.txt`); },
    stopped(message, fatal) {
      showError(fatal ? `The planning worker keeps stopping (${message}). Reload the page to try again.`
        : `The planning worker stopped: ${message}`);
      if (!fatal) controller.fire('load');
    },
    revealed: () => maybeFinish(),
    finished: () => controller.state === 'finished',
    changed: () => { updateStats(); syncDownload(); },
  },
});

function onReady(msg) {
  if (!registry) {
    registry = msg.planners;
    builtins = msg.builtins;
    panel = createPanel(ui.panel, registry, () => { configure(); clearError(); syncChart(); });
    const first = fillScenarioPicker(ui.scenario, builtins);
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
  if (!edit) editor.loading();
  lane.load(text, file);
  controller.fire('load');
}

function configure() {
  if (!panel || !lane.session.alive) return;
  lane.configure(panel.config());
  syncChart();
  syncOptions();
  buildLegend();
  controller.fire('configure');
}

const actions = {
  run() {
    if (!controller.can('run')) return;
    clearError();
    if (controller.state === 'finished') lane.resetRun();
    controller.fire('run');
    lane.run();
  },
  pause() {
    if (!controller.fire('pause')) return;
    lane.pause();
  },
  step() {
    if (!controller.fire('step')) return;
    lane.step(Math.max(1, Math.floor(Number(ui.stepSize.value)) || 1));
  },
  stepEvent() {
    if (!controller.fire('stepEvent')) return;
    lane.stepEvent();
  },
  reset() {
    if (!controller.can('reset')) return;
    lane.resetRun();
    controller.fire('reset');
  },
  cancel() {
    if (!controller.can('cancel')) return;
    const stopped = lane.done; // the planner already stopped: show the rest now
    lane.cancel();
    if (!stopped) controller.fire('cancel');
  },
};

// Run state and playback

function maybeFinish() {
  if (lane.caughtUp && controller.fire('finish')) updateStats();
  if (controller.state === 'finished' && lane.showResult()) syncDownload();
}

function frame(time) {
  const dt = Math.min(0.25, (time - (lastFrame || time)) / 1000);
  lastFrame = time;
  if (controller.state === 'running' && playback.pending > 0) lane.tick(speedRate(ui.speed), dt);
  else if (controller.state === 'running') maybeFinish();
  if (!chart.kind && playback.model.costs.length) syncChart(); // a planner that reports costs
  view.render(time, animFps(ui.animSpeed));
  cspace.render(view.robotState);
  chart.render(lane.iterationNow);
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
  lane.clearRun();
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

function statusWord() {
  return controller.state === 'finished'
    ? (lane.finalStatus || (lane.result?.solved ? 'solved' : 'finished')) : controller.state;
}

function currentStats() { return lane.statsFor(statusWord(), controller.state === 'finished'); }

function updateStats() {
  const s = currentStats();
  updateStatsList(s);
  // a planner that gave up says why: under the canvas too, where it is seen
  const why = s.status === 'no_path' ? (lane.result?.reason || 'the planner gave up') : '';
  ui.runNote.textContent = why ? `No path: ${why.replace(/^no path:\s*/i, '')}` : '';
  ui.runNote.hidden = !why;
}

/** The chart that fits the chosen planner: best cost, coverage, or none. */
function syncChart() {
  const kind = panel ? chartKind(panel.planner(), playback.model) : null;
  chart.setKind(kind, { target: loaded?.inspection?.coverage ?? null });
  ui.chartBox.hidden = !kind;
  ui.chartTitle.textContent = kind === 'cost' ? 'Best cost against iterations'
    : kind === 'coverage' ? 'Coverage of the best branch against iterations' : '';
  ui.chart.setAttribute('aria-label', ui.chartTitle.textContent);
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
  const name = panel?.planner()?.name;
  const items = [...view.legend(name), ...cellLegend(name)];
  ui.legend.replaceChildren(...items.map(({ label, color, shape }) => {
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
  ui.download.hidden = !(loaded?.robot?.kind === 'asv' && lane.result?.solved && controller.state === 'finished');
}

ui.download.addEventListener('click', () => { if (lane.session.alive && lane.result?.solved) lane.session.send({ type: 'asv-solution' }); });

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

// the compare page opens on the scenario shown here
ui.compare.addEventListener('click', () => {
  const b = builtins.find((x) => x.id === ui.scenario.value);
  ui.compare.href = b ? `compare.html?scenario=${encodeURIComponent(b.id)}` : 'compare.html';
});

function updateOutputs() {
  ui.speedOut.textContent = describeSpeed(ui.speed);
  ui.animOut.textContent = `${Math.round(animFps(ui.animSpeed))} frames/s`;
}
ui.speed.addEventListener('input', updateOutputs);
ui.animSpeed.addEventListener('input', updateOutputs);
const overlayOptions = createOverlays(ui.overlays, () => syncOptions());
// An inspection planner's smoothed path need not see what its branch saw: its robot follows the raw path.
const syncOptions = () => {
  const o = overlayOptions();
  view.setOptions({ ...o, animateRaw: ui.animRaw.checked || panel?.planner().task === 'inspection' });
  cspace.setOptions({ showRejected: o.showRejected, showCollisions: o.showCollisions });
};
ui.animRaw.addEventListener('change', syncOptions);

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

// Hover: the cell or field tile under the pointer, described in a small box (text only).
function hideTip() { ui.tip.hidden = true; }
ui.canvas.addEventListener('pointermove', (e) => {
  const L = view.layout;
  const lines = L && !e.buttons ? view.cells.describe(L.wx(e.offsetX * L.dpr), L.wy(e.offsetY * L.dpr), view.options) : null;
  if (!lines) { hideTip(); return; }
  ui.tip.textContent = lines.join('\n');
  ui.tip.hidden = false;
  const stage = ui.stage.getBoundingClientRect();
  const x = e.clientX - stage.left + 14, y = e.clientY - stage.top + 14;
  const w = ui.tip.offsetWidth, h = ui.tip.offsetHeight;
  ui.tip.style.left = `${Math.max(0, x + w > stage.width ? x - w - 28 : x)}px`;
  ui.tip.style.top = `${Math.max(0, y + h > stage.height ? y - h - 28 : y)}px`;
});
ui.canvas.addEventListener('pointerleave', hideTip);
ui.canvas.addEventListener('pointerdown', hideTip);

// Size: the views follow the stage (and the device pixel ratio).
const onResize = fitViews(ui.stage, view, cspace);

Object.defineProperty(window, 'planarium', {
  value: Object.freeze({
    state: () => controller.state,
    stats: () => currentStats(),
    result: () => (lane.result ? structuredClone(lane.result) : null),
    scenario: () => (editor.scenario ? structuredClone(editor.scenario) : null),
    nodeCount: () => playback.nodeCount,
    model: () => modelSummary(playback.model, chart),
    cells: () => cellSummary(playback.model.cells),
    /** Css px within the workspace canvas of the world point (x, y), or null. */
    toCanvas: (x, y) => (view.layout ? [view.layout.sx(x) / view.layout.dpr, view.layout.sy(y) / view.layout.dpr] : null),
  }),
  writable: false,
  configurable: false,
});

buildLegend();
updateOutputs();
syncOptions();
syncButtons();
updateStats();
lane.start();
requestAnimationFrame(frame);

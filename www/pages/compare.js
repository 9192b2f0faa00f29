// The compare page: two planner set-ups (planner and parameters) on the same scenario and seed,
// side by side. Each set-up is a lane (lane.js: its own worker, playback, view, chart and stats);
// one controller (controller.js, the playground's table) drives both, so they load, run, pause and
// reset together, and the page is finished when both lanes are.
// Read-only state for tests is exposed as window.planarium (lane-aware: stats('a'), result('b')).

import { Controller } from '../run/controller.js';
import { View } from '../draw/view.js';
import { PALETTE } from '../draw/palette.js';
import { createPanel, taskOf } from '../ui/panel.js';
import { Playback } from '../run/playback.js';
import { Chart } from '../draw/chart.js';
import { Lane } from '../run/lane.js';
import { createStats } from '../ui/stats.js';
import { createOverlays } from '../draw/overlays.js';
import { chartKind, speedRate, animFps, describeSpeed, modelSummary, fillScenarioPicker, errorBox, fillLegend } from '../ui/controls.js';
import { applyPageLimits } from '../run/limits.js';

const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), seed: $('seed'), seedHint: $('seed-hint'), error: $('error'), errorText: $('error-text'),
  errorClose: $('error-close'), course: $('scenario-course'), name: $('scenario-name'), notes: $('scenario-notes'),
  legend: $('legend'), speed: $('speed'), speedOut: $('speed-out'), animSpeed: $('anim-speed'),
  animOut: $('anim-speed-out'), overlays: $('overlays'), playground: $('to-playground'),
};
const { show: showError, clear: clearError } = errorBox(ui.error, ui.errorText);
const BUTTONS = { run: 'run', pause: 'pause', reset: 'reset' };

const controller = new Controller('loading');
let registry = null;
let builtins = [];
let scenario = null;     // the scenario both lanes show
let scenarioText = null;
let seed = 1;
let loadGen = 0;         // bumped by every load; a lane is loaded when its answer is for the latest
let applyDefaults = false;
let lastFrame = 0;

/** One side of the page: a lane, its panel, its stats, its chart. */
function makeSide(key) {
  const playback = new Playback();
  const view = new View($(`${key}-canvas`), playback.store, playback.model);
  const chart = new Chart($(`${key}-chart`), playback.model, PALETTE);
  const side = {
    key, playback, view, chart, panel: null, loadedGen: -1, ready: false,
    stats: createStats($(`${key}-stats`), `${key}-`),
    title: $(`${key}-title`), chartBox: $(`${key}-chart-box`), chartTitle: $(`${key}-chart-title`),
  };
  side.lane = new Lane({
    playback,
    views: [view],
    chart,
    hooks: {
      ready: (msg) => onReady(side, msg),
      loaded: (msg) => onLoaded(side, msg),
      invalid: (error) => onInvalid(side, error),
      error(message) {
        showError(`Set-up ${key.toUpperCase()}: ${message}`);
        if (!side.lane.done && controller.fire('fail')) for (const s of sides) s.lane.resetRun();
      },
      stopped(message, fatal, why) {
        const what = why === 'hung' ? `Set-up ${key.toUpperCase()}: ${message}`
          : `The planning worker of set-up ${key.toUpperCase()} stopped: ${message}`;
        showError(fatal ? `The planning worker of set-up ${key.toUpperCase()} keeps stopping (${message}). Pick a scenario to start it again.`
          : what);
        side.ready = false;
        controller.fire(fatal ? 'stop' : 'load');
      },
      revealed: () => maybeFinish(),
      finished: () => controller.state === 'finished',
      changed: () => updateStats(side),
    },
  });
  // the canvas follows its box
  const stage = $(`${key}-stage`);
  const fit = () => {
    const r = stage.getBoundingClientRect();
    view.resize(Math.max(40, r.width), Math.max(40, r.height), window.devicePixelRatio || 1);
  };
  new ResizeObserver(fit).observe(stage);
  fit();
  return side;
}

const sides = [makeSide('a'), makeSide('b')];

function onReady(side, msg) {
  side.ready = true;
  if (!registry) {
    registry = applyPageLimits(msg.planners);
    builtins = msg.builtins;
    for (const s of sides) {
      s.panel = createPanel($(`${s.key}-panel`), registry, () => { configure([s]); clearError(); },
        { prefix: `${s.key}-`, seed: false, title: 'Planner' });
    }
    fillScenarioPicker(ui.scenario, builtins);
  }
  // load once every worker is ready (again, after a crash: same scenario, same set-ups)
  if (!sides.every((s) => s.ready)) return;
  if (sides.some((s) => s.lane.session.loadsPending > 0)) return; // the user's load is on its way
  if (scenarioText) load(scenarioText, false);
  else {
    const b = builtins.find((x) => x.id === ui.scenario.value) || builtins[0];
    load(JSON.stringify(b.scenario), true);
  }
}

function load(text, defaults) {
  applyDefaults = defaults;
  loadGen++;
  for (const s of sides) s.lane.load(text);
  controller.fire('load');
}

function onLoaded(side, msg) {
  side.loadedGen = loadGen;
  side.loaded = msg;
  if (!sides.every((s) => s.loadedGen === loadGen)) return;
  scenario = msg.scenario;
  scenarioText = JSON.stringify(scenario);
  ui.name.textContent = scenario.name || 'Untitled scenario';
  ui.notes.textContent = scenario.notes || '';
  ui.course.textContent = builtins.find((b) => b.id === ui.scenario.value)?.course || '';
  for (const s of sides) {
    s.view.setScenario(s.loaded.scenario, s.loaded.start, s.loaded.goal);
    s.panel.setTask(taskOf(scenario));
    if (applyDefaults) s.panel.apply(scenario.planner);
  }
  if (applyDefaults && Number.isSafeInteger(scenario.planner?.seed)) {
    seed = scenario.planner.seed;
    ui.seed.value = String(seed);
  }
  applyDefaults = false;
  buildLegend();
  configure(sides);
  controller.fire('loaded');
}

function onInvalid(side, error) {
  showError(`This scenario has an error${error.path ? ` at ${error.path}` : ''}: ${error.message || error.text}`);
  for (const s of sides) s.lane.clearRun();
  controller.fire('invalid');
}

/** A side's set-up: its panel's planner and parameters, the shared seed. */
function setupOf(s) { return { ...s.panel.config(), seed }; }

/** Send the set-ups of `which` sides; the others are reset, so both runs start together. */
function configure(which) {
  if (!registry || !sides.every((s) => s.lane.session.alive)) return;
  for (const s of sides) {
    if (which.includes(s)) s.lane.configure(setupOf(s));
    else s.lane.resetRun();
    syncSide(s);
  }
  syncOptions();
  controller.fire('configure');
}

const actions = {
  run() {
    if (!controller.can('run')) return;
    clearError();
    if (controller.state === 'finished') for (const s of sides) s.lane.resetRun();
    controller.fire('run');
    for (const s of sides) s.lane.run();
  },
  pause() {
    if (!controller.fire('pause')) return;
    for (const s of sides) s.lane.pause();
  },
  reset() {
    if (!controller.can('reset')) return;
    for (const s of sides) s.lane.resetRun();
    controller.fire('reset');
  },
};

function maybeFinish() {
  if (sides.every((s) => s.lane.caughtUp) && controller.fire('finish')) sides.forEach(updateStats);
  if (controller.state === 'finished') for (const s of sides) s.lane.showResult();
}

function frame(time) {
  const dt = Math.min(0.25, (time - (lastFrame || time)) / 1000);
  lastFrame = time;
  if (controller.state === 'running') {
    for (const s of sides) s.lane.tick(speedRate(ui.speed), dt);
    maybeFinish();
  }
  for (const s of sides) {
    if (!s.chart.kind && s.playback.model.costs.length) syncSide(s);
    s.view.render(time, animFps(ui.animSpeed));
    s.chart.render(s.lane.iterationNow);
  }
  requestAnimationFrame(frame);
}

// Display

/** A side's title (planner and sampler) and chart. */
function syncSide(s) {
  if (!s.panel) return;
  const p = s.panel.planner();
  const cfg = s.panel.config();
  const sampler = cfg.params.sampler || p.groups?.find((g) => g.name === 'sampler')?.params.find((x) => x.name === 'sampler')?.default;
  const extras = Object.entries(cfg.params).filter(([k]) => k !== 'sampler').map(([k, v]) => `${k} ${v}`);
  s.title.textContent = [p.label, sampler ? `${sampler} sampler` : null, ...extras].filter(Boolean).join(' · ');
  const kind = chartKind(p, s.playback.model);
  s.chart.setKind(kind, { target: scenario?.inspection?.coverage ?? null });
  s.chartBox.hidden = !kind;
  s.chartTitle.textContent = kind === 'cost' ? 'Best cost against iterations'
    : kind === 'coverage' ? 'Coverage of the best branch against iterations' : '';
}

function statusOf(s) {
  if (controller.state === 'finished' || (s.lane.caughtUp && controller.state === 'running')) {
    return s.lane.finalStatus || (s.lane.result?.solved ? 'solved' : 'finished');
  }
  return controller.state;
}

function statsOf(s) { return s.lane.statsFor(statusOf(s), s.lane.caughtUp); }

function updateStats(s) { s.stats(statsOf(s)); }

function syncButtons() {
  for (const [id, event] of Object.entries(BUTTONS)) $(id).disabled = !controller.can(event);
  const busy = controller.state === 'loading';
  ui.scenario.disabled = busy;
  ui.seed.disabled = busy;
  for (const s of sides) s.panel?.setDisabled(busy);
  document.body.dataset.state = controller.state;
}

controller.onChange(() => { syncButtons(); sides.forEach(updateStats); });

function buildLegend() {
  fillLegend(ui.legend, sides[0].view.legend());
}

// Inputs

for (const [id, event] of Object.entries(BUTTONS)) $(id).addEventListener('click', () => actions[event]());
ui.errorClose.addEventListener('click', clearError);

ui.scenario.addEventListener('change', () => {
  const b = builtins.find((x) => x.id === ui.scenario.value);
  if (!b) return;
  clearError();
  scenarioText = null;
  load(JSON.stringify(b.scenario), true);
});

ui.seed.addEventListener('change', () => {
  const v = Number(ui.seed.value);
  if (ui.seed.value.trim() === '' || !Number.isSafeInteger(v) || v < 0) {
    ui.seed.setAttribute('aria-invalid', 'true');
    ui.seedHint.textContent = 'The seed must be a whole number ≥ 0.';
    return;
  }
  ui.seed.removeAttribute('aria-invalid');
  ui.seedHint.textContent = '';
  seed = v;
  configure(sides);
});

ui.playground.addEventListener('click', () => {
  const id = ui.scenario.value;
  ui.playground.href = id ? `./?scenario=${encodeURIComponent(id)}` : './';
});

function updateOutputs() {
  ui.speedOut.textContent = describeSpeed(ui.speed);
  ui.animOut.textContent = `${Math.round(animFps(ui.animSpeed))} frames/s`;
}
ui.speed.addEventListener('input', updateOutputs);
ui.animSpeed.addEventListener('input', updateOutputs);
const overlayOptions = createOverlays(ui.overlays, () => syncOptions());
function syncOptions() {
  const o = overlayOptions();
  // an inspection planner's smoothed path need not see what its branch saw: follow the raw path
  for (const s of sides) s.view.setOptions({ ...o, animateRaw: s.panel?.planner().task === 'inspection' });
}

document.addEventListener('keydown', (e) => {
  if (e.ctrlKey || e.metaKey || e.altKey || e.repeat) return;
  const t = e.target;
  if (t instanceof Element && t.closest('input, select, textarea, [contenteditable]')) return;
  if (e.key === ' ') {
    e.preventDefault();
    if (controller.state === 'running') actions.pause(); else actions.run();
  } else if (e.key === 'r' || e.key === 'R') {
    actions.reset();
  }
});

const laneOf = (key) => sides.find((s) => s.key === key) || sides[0];
Object.defineProperty(window, 'planarium', {
  value: Object.freeze({
    state: () => controller.state,
    lanes: () => sides.map((s) => s.key),
    stats: (key = 'a') => statsOf(laneOf(key)),
    result: (key = 'a') => (laneOf(key).lane.result ? structuredClone(laneOf(key).lane.result) : null),
    model: (key = 'a') => modelSummary(laneOf(key).playback.model, laneOf(key).chart),
    config: (key = 'a') => (laneOf(key).panel ? structuredClone(setupOf(laneOf(key))) : null),
    scenario: () => (scenario ? structuredClone(scenario) : null),
  }),
  writable: false,
  configurable: false,
});

updateOutputs();
syncOptions();
syncButtons();
sides.forEach(updateStats);
for (const s of sides) s.lane.start();
requestAnimationFrame(frame);

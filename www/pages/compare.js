// The compare page: two planner set-ups (planner and parameters) on the same scenario and seed,
// side by side. Each set-up is a lane (lane.js: its own worker, playback, view, chart and stats);
// one controller (controller.js, the playground's table) drives both, so they load, run, pause and
// reset together, and the page is finished when both lanes are.
// The scenario is a built-in, an opened file (the lanes' workers import it as the playground's
// does) or a link's. Scenario, both set-ups and the seed are kept in the URL hash (ui/setups.js:
// the playground's share grammar plus `a` and `b`, a set-up line each), so a reload, or a
// playground link's `#…` opened here, restores them; bad values are named and defaults used.
// "Run 20 seeds" runs both set-ups to the end on seeds seed … seed+19 over a pool of benchmark
// workers (ui/seed-pool.js, as the playground's) and shows success and medians, the better set-up marked per row.
// On a phone the two lanes are tabs.
// Read-only state for tests is exposed as window.planarium (lane-aware: stats('a'), result('b')).

import { Controller } from '../run/controller.js';
import { View } from '../draw/view.js';
import { PALETTE } from '../draw/palette.js';
import { createPanel, taskOf } from '../ui/panel.js';
import { Playback } from '../run/playback.js';
import { Chart } from '../draw/chart.js';
import { Lane } from '../run/lane.js';
import { View3dSlot } from '../draw/view3d-slot.js';
import { createStats } from '../ui/stats.js';
import { createOverlays } from '../draw/overlays.js';
import { chartKind, speedSeconds, animFps, describeSpeed, modelSummary, fillScenarioPicker, errorBox, fillLegend, removeCustomScenarios, markCustomScenario } from '../ui/controls.js';
import { applyPageLimits } from '../run/limits.js';
import init, { parse_setups as parseSetups } from '../pkg/planarium.js';
import { setupFor } from '../ui/links.js';
import { fillSeedsTable } from '../ui/seeds-table.js';
import { wireCompareExport, wireChartDownloads, KEY_NUMBERS } from '../ui/compare-export.js';
import { wireLanesAnimations } from '../ui/compare-anim.js';
import { wireSpeedButtons } from '../ui/speed-buttons.js';
import { runPool } from '../ui/seed-pool.js';
import { setupLine, readPageState, checkSetups, pageHash, playgroundLink, readChosenFile, differingParams } from '../ui/setups.js';
import { shown } from '../ui/text.js';
import { MAX_SEED, readSeed, blockSeedProblem } from '../ui/seed.js';
import { ScenarioSource } from '../run/scenario-source.js';
import { wireLinkedZoom, wireLaneTabs } from '../ui/lanes.js';

/**
 * The page's element `id`. Its kind is the HTML's (input, select, button, canvas, dialog…), so it
 * is typed loosely here and checked by the browser tests.
 * @param {string} id
 * @returns {any}
 */
const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), seed: $('seed'), seedHint: $('seed-hint'), error: $('error'), errorText: $('error-text'),
  errorClose: $('error-close'), course: $('scenario-course'), name: $('scenario-name'), notes: $('scenario-notes'),
  legend: $('legend'), speed: $('speed'), speedOut: $('speed-out'), animSpeed: $('anim-speed'),
  animOut: $('anim-speed-out'), overlays: $('overlays'), playground: $('to-playground'), file: $('file'),
  runSeeds: $('run-seeds'), seedsCancel: $('seeds-cancel'), seedsProgress: $('seeds-progress'), seedsStatus: $('seeds-status'),
  seedsTable: $('seeds-table'), seedsCaption: $('seeds-caption'), seedsRange: $('seeds-range'), toBench: $('to-bench'),
  lanes: $('lanes'), tabA: $('tab-a'), tabB: $('tab-b'),
};
const SEEDS = 20; // "Run 20 seeds"
const wasm = init(); // the core on this thread too: a link's set-up lines go through its parser
const { show: showError, clear: clearError } = errorBox(ui.error, ui.errorText);
const BUTTONS = { run: 'run', pause: 'pause', reset: 'reset' };

const controller = new Controller('loading');
let registry = null;
let builtins = [];
// The scenario both lanes show, why it was loaded and where it came from, and the hash's state
// {share, own} waiting for its scenario (run/scenario-source.js). A lane is loaded when its
// answer is for the latest load (`src.generation`).
const src = new ScenarioSource();
let seed = 1;
let lastFrame = 0;
let hashRead = null;     // the promise of reading the hash's state
const encoded = new Map();
let keepSetups = false;  // a scenario the user picked or opened: both set-ups are kept, not the scenario's

/** One side of the page: a lane, its panel, its stats, its chart. */
function makeSide(key) {
  const playback = new Playback();
  const view = new View($(`${key}-canvas`), playback.store, playback.model);
  const chart = new Chart($(`${key}-chart`), playback.model, PALETTE);
  // a spatial arm (the core's caps.view3d): the lane shows it in 3-D instead of the top view
  const view3d = new View3dSlot($(`${key}-view3d`), playback.store, PALETTE, () => fit());
  const side = {
    key, playback, view, view3d, chart, panel: null, loadedGen: -1, ready: false,
    stats: createStats($(`${key}-stats`), `${key}-`),
    title: $(`${key}-title`), chartBox: $(`${key}-chart-box`), chartTitle: $(`${key}-chart-title`),
  };
  side.lane = new Lane({
    playback,
    views: [view, view3d],
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
    $(`${key}-canvas`).hidden = view3d.active;
    (view3d.active ? view3d : view).resize(Math.max(40, r.width), Math.max(40, r.height), window.devicePixelRatio || 1);
  };
  wireChartDownloads({
    chart, title: () => `${key.toUpperCase()} · ${side.title.textContent}: ${side.chartTitle.textContent}`, now: () => side.lane.iterationNow,
    png: $(`${key}-chart-png`), svg: $(`${key}-chart-svg`), name: `planarium-compare-${key}-chart`, onError: showError,
  });
  new ResizeObserver(fit).observe(stage);
  fit();
  return side;
}

const sides = [makeSide('a'), makeSide('b')];

// Zoom and pan on the plane, both lanes together, in the link (ui/lanes.js)
wireLinkedZoom(sides.map((s) => ({ canvas: $(`${s.key}-canvas`), view: s.view, stage: $(`${s.key}-stage`) })), () => writeHash());

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
    src.read();
    hashRead = wasm.then(() => readPageState(location.hash, { builtins, keys: ['a', 'b'] }))
      .then((state) => { src.restore(state); }, (e) => { src.restore(null); showError(`The link could not be read: ${e?.message ?? e}`); });
  }
  // load once every worker is ready (again, after a crash: same scenario, same set-ups)
  if (!sides.every((s) => s.ready)) return;
  if (sides.some((s) => s.lane.session.loadsPending > 0)) return; // the user's load is on its way
  hashRead.then(loadFirst);
}

/** Load the scenario shown (after a crash), else the link's, else the picker's built-in. */
function loadFirst() {
  if (sides.some((s) => s.lane.session.loadsPending > 0)) return;
  if (src.text) { load('reload', src.text); return; }
  const sc = src.pending?.share.scenario;
  if (sc?.text) {
    markCustom('Scenario from a link');
    load('link', sc.text, { defaults: true });
    return;
  }
  const b = builtins.find((x) => x.id === sc?.id) || builtins.find((x) => x.id === ui.scenario.value) || builtins[0];
  ui.scenario.value = b.id;
  load('builtin', JSON.stringify(b.scenario), { id: b.id, defaults: true });
}

/**
 * Send a scenario (or, with `file`, any file the core imports) to both lanes, saying why
 * (run/scenario-source.js). `defaults`: apply the scenario's planner block and seed.
 * @param {import('../run/scenario-source.js').LoadReason} reason @param {string} text
 * @param {{id?: string, defaults?: boolean, file?: string | null}} [options]
 */
function load(reason, text, { id, defaults = false, file = null } = {}) {
  src.sent(reason, { id, defaults, file });
  for (const s of sides) s.lane.load(text, file);
  controller.fire('load');
}

const removeCustom = () => removeCustomScenarios(ui.scenario);
const markCustom = (label) => markCustomScenario(ui.scenario, label);

/** @param {any} side @param {import('../run/messages.js').LoadedReply} msg */
function onLoaded(side, msg) {
  side.loadedGen = src.generation;
  side.loaded = msg;
  if (!sides.every((s) => s.loadedGen === src.generation)) return;
  const scenario = msg.scenario;
  const { restore, defaults: applyDefaults } = src.loaded(scenario);
  ui.name.textContent = shown(scenario.name || 'Untitled scenario');
  ui.notes.textContent = shown(scenario.notes || '');
  ui.course.textContent = builtins.find((b) => b.id === ui.scenario.value)?.course || '';
  for (const s of sides) {
    s.view.setScenario(s.loaded.scenario, s.loaded.start, s.loaded.goal);
    s.view3d.setScene(s.loaded.spatial || null, !!s.loaded.caps?.view3d);
    s.panel.setTask(taskOf(scenario));
    if (applyDefaults && !keepSetups) s.panel.apply(scenario.planner);
  }
  keepSetups = false;
  if (applyDefaults && blockSeedProblem(scenario.planner?.seed)) {
    ui.seedHint.textContent = `${blockSeedProblem(scenario.planner.seed)}; the seed stays ${seed}.`;
  } else if (applyDefaults && Number.isSafeInteger(scenario.planner?.seed)) {
    seed = scenario.planner.seed;
    ui.seed.value = String(seed);
    ui.seedHint.textContent = '';
  }
  if (restore) applyRestore(restore, scenario);
  buildLegend();
  configure(sides);
  controller.fire('loaded');
}

/**
 * The link's set-ups and seed, on the scenario just loaded: `a` / `b` (a set-up line each, read
 * by the core's parser), else a playground link's planner set-up for A; bad values are named and
 * the scenario's defaults kept.
 */
function applyRestore({ share, own }, scenario) {
  const problems = [...share.problems];
  for (const s of sides) {
    const K = s.key.toUpperCase();
    if (!own.has(s.key)) continue;
    const got = checkSetups(s.key, own.get(s.key) ?? '', parseSetups, 1);
    if (got.problem) { problems.push(`${got.problem}; set-up ${K} keeps its default.`); continue; }
    const [st] = got.setups;
    s.panel.apply({ ...st.params, name: st.planner });
    if (s.panel.planner().name !== st.planner) {
      problems.push(`${s.key}: ${st.planner} does not fit this scenario; set-up ${K} uses ${s.panel.planner().label}.`);
    }
  }
  if (!own.has('a') && (share.planner !== null || share.params.length)) {
    const { block, problems: more } = setupFor(share, scenario, registry, sides[0].panel.planner().name);
    problems.push(...more);
    sides[0].panel.apply(block);
  }
  if (share.seed !== null) {
    seed = share.seed;
    ui.seed.value = String(seed);
  }
  if (share.view.zoom) sides[0].view.setViewport(share.view.zoom); // the other lane follows
  if (problems.length) showError(`This link has problems:\n${problems.join('\n')}`);
}

function onInvalid(side, error) {
  const what = src.file ? `${src.file}: this file has an error` : 'This scenario has an error';
  showError(`${what}${error.path ? ` at ${error.path}` : ''}: ${error.message || error.text}`);
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
  if (seedJob) stopSeeds('Stopped: a set-up, the seed or the scenario changed.');
  showSeedRange();
  writeHash();
}

// The URL: scenario, both set-ups, the seed; and the links to the playground and the benchmark

/** A side's set-up as a line (only the values that differ from the defaults). */
function lineOf(s) {
  const { planner, params } = s.panel.config();
  return setupLine({ planner, params: differingParams(s.panel.planner(), params, registry) });
}

let hashGen = 0;
async function writeHash() {
  if (!registry || !src.text || src.pending || sides.some((s) => !s.panel)) return;
  const gen = ++hashGen;
  const from = src.linkSource();
  const [a, b] = sides.map(lineOf);
  const hash = await pageHash(from, [['a', a], ['b', b], ['seed', seed]], registry, encoded, { zoom: sides[0].view.viewport });
  const bench = await pageHash(from, [['setups', `A: ${a}\nB: ${b}`], ['runs', SEEDS]], registry, encoded);
  const play = await playgroundLink(from, setupOf(sides[0]), registry, encoded);
  if (gen !== hashGen) return;
  if (location.hash !== `#${hash}`) history.replaceState(history.state, '', `${location.pathname}${location.search}#${hash}`);
  ui.toBench.href = `bench.html#${bench}`;
  ui.playground.href = play || './';
  // the views' links carry the state too: this page's own, and the benchmark's
  $('nav-bench').href = `bench.html#${bench}`;
  $('nav-compare').href = `compare.html#${hash}`;
}

// Run 20 seeds: both set-ups to the end on seeds seed … seed+19, over benchmark workers

let seedJob = null;  // {lines, first, rows: [[row], [row]], done, total, pool}
let seedSummary = null;

function showSeedRange() {
  ui.seedsRange.textContent = `${seed} … ${seed + SEEDS - 1}`;
}

function runSeeds() {
  if (seedJob || !src.text || sides.some((s) => !s.panel)) return;
  clearError();
  if (seed > MAX_SEED - (SEEDS - 1)) {
    showError(`Seeds ${seed} … ${seed} + ${SEEDS - 1} would pass ${MAX_SEED} (2^53 − 1), the largest seed the page carries exactly: choose a seed of at most ${MAX_SEED - (SEEDS - 1)}.`);
    return;
  }
  const setups = sides.map((s) => s.panel.config());
  const jobs = [];
  for (let k = 0; k < SEEDS; k++) setups.forEach((st, i) => jobs.push({ i, text: src.text, planner: st.planner, params: st.params, seed: seed + k }));
  seedJob = { lines: sides.map(lineOf), first: seed, rows: [[], []], done: 0, total: jobs.length, pool: null };
  const job = seedJob;
  seedJob.pool = runPool(jobs, {
    onResult(j, msg) {
      if (msg.type !== 'done') {
        stopSeeds(`Stopped: set-up ${'AB'[j.i]}, seed ${j.seed}: ${msg.type === 'crashed' ? 'the core crashed' : 'the run was refused'}: ${msg.message}`);
        return;
      }
      const s = msg.result.stats;
      job.rows[j.i].push({ seed: j.seed, solved: msg.result.solved, time_ms: s.time_ms, nodes: s.nodes, checks: s.checks, cost: s.cost });
      job.done++;
      seedProgress();
    },
    onEnd(why) {
      if (why === 'done') finishSeeds();
      else stopSeeds('Stopped: the seed workers stopped.');
    },
  });
  seedSummary = null;
  ui.seedsTable.hidden = true;
  ui.seedsProgress.hidden = false;
  syncSeedButtons();
  seedProgress();
}

function seedProgress() {
  ui.seedsProgress.max = seedJob.total;
  ui.seedsProgress.value = seedJob.done;
  ui.seedsStatus.textContent = `${seedJob.done} / ${seedJob.total} runs`;
}

function syncSeedButtons() {
  ui.runSeeds.disabled = !!seedJob || !src.text;
  ui.seedsCancel.disabled = !seedJob;
}

function stopSeeds(why) {
  if (!seedJob) return;
  seedJob.pool?.stop();
  seedJob = null;
  ui.seedsProgress.hidden = true;
  ui.seedsStatus.textContent = shown(why);
  syncSeedButtons();
}

function finishSeeds() {
  const j = seedJob;
  j.pool?.stop();
  seedJob = null;
  ui.seedsProgress.hidden = true;
  syncSeedButtons();
  const { per, better } = fillSeedsTable(ui.seedsTable, j.rows);
  seedSummary = { first: j.first, last: j.first + SEEDS - 1, lines: j.lines, a: per[0], b: per[1], better, rows: j.rows };
  ui.seedsCaption.textContent = `Seeds ${j.first} … ${j.first + SEEDS - 1}; ★ the better set-up`;
  ui.seedsTable.hidden = false;
  ui.seedsStatus.textContent = `${j.total} runs done`;
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
    for (const s of sides) s.lane.tick(speedSeconds(ui.speed), dt);
    maybeFinish();
  }
  for (const s of sides) {
    if (!s.chart.kind && s.playback.model.costs.length) syncSide(s);
    s.view.render(time, animFps(ui.animSpeed));
    s.view3d.render(time, animFps(ui.animSpeed));
    s.chart.render(s.lane.iterationNow);
  }
  requestAnimationFrame(frame);
}

// Display

/** A side's title (planner and sampler), its stats' hover text (the registry's words) and chart. */
function syncSide(s) {
  if (!s.panel) return;
  const p = s.panel.planner();
  s.stats.setPlanner(p);
  const cfg = s.panel.config();
  const sampler = cfg.params.sampler || p.groups?.find((g) => g.name === 'sampler')?.params.find((x) => x.name === 'sampler')?.default;
  const extras = Object.entries(cfg.params).filter(([k]) => k !== 'sampler').map(([k, v]) => `${k} ${v}`);
  s.title.textContent = [p.label, sampler ? `${sampler} sampler` : null, ...extras].filter(Boolean).join(' · ');
  const kind = chartKind(p, s.playback.model);
  s.chart.setKind(kind, { target: src.scenario?.inspection?.coverage ?? null, optimum: optimumOf(s) });
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

/** A side's stats, with its scenario's optimum (the visibility graph's, for a point or a disc robot: the Optimum row). */
function statsOf(s) { return { ...s.lane.statsFor(statusOf(s), s.lane.caughtUp), optimum: optimumOf(s) }; }

function optimumOf(s) {
  const best = s.loaded?.optimum;
  return best && best.exact && Number.isFinite(best.cost) ? best.cost : null;
}

function updateStats(s) { s.stats(statsOf(s)); }

function syncButtons() {
  for (const [id, event] of Object.entries(BUTTONS)) $(id).disabled = !controller.can(event);
  const busy = controller.state === 'loading';
  ui.scenario.disabled = busy;
  ui.seed.disabled = busy;
  ui.file.disabled = busy;
  syncSeedButtons();
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
  removeCustom();
  src.clear();
  keepSetups = true; // the user's set-ups stay: only the scenario (and its seed) changes
  load('builtin', JSON.stringify(b.scenario), { id: b.id, defaults: true });
});

ui.file.addEventListener('change', async () => {
  const file = ui.file.files[0];
  ui.file.value = ''; // the same file can be opened again
  if (!file) return;
  clearError();
  let text;
  try { text = await readChosenFile(file); } catch (e) { showError(e.message); return; }
  markCustom(`File: ${file.name}`);
  src.clear();
  keepSetups = true;
  load('file', text, { defaults: true, file: file.name });
});

// another link pasted into this tab's address bar (the page's own writes use replaceState, which
// fires no hashchange): start again from it
window.addEventListener('hashchange', () => location.reload());

ui.runSeeds.addEventListener('click', runSeeds);

// Export for a slide: both lanes in one PNG, GIF or WebM, with their titles and key numbers
const numbersOf = (s) => KEY_NUMBERS.map(([label, id, short = (t) => t]) => [label, short($(`${s.key}-${id}`)?.textContent ?? '')]);
wireCompareExport({
  button: $('export-lanes'), status: $('export-status'), onError: showError,
  lanes: () => sides.map((s) => ({ key: s.key, title: s.title.textContent, canvas: $(`${s.key}-${s.view3d.active ? 'view3d' : 'canvas'}`), numbers: numbersOf(s) })),
});
wireLanesAnimations({
  gif: $('export-lanes-gif'), webm: $('export-lanes-webm'), lapse: $('export-lapse'), status: $('export-status'), animFps: () => animFps(ui.animSpeed),
  lanes: () => sides.map((s) => ({ key: s.key, title: s.title.textContent, view: s.view, view3d: s.view3d.active, numbers: () => numbersOf(s) })),
});
ui.seedsCancel.addEventListener('click', () => stopSeeds('Cancelled.'));

// A phone: the lanes as tabs A / B (ui/lanes.js)
wireLaneTabs({ lanes: ui.lanes, tabA: ui.tabA, tabB: ui.tabB });

ui.seed.addEventListener('change', () => {
  const r = readSeed(ui.seed.value);
  if (r.why) { // refused: the field shows the seed the runs use (Run 20 seeds too), the hint why
    ui.seedHint.textContent = `Seed: ${r.why}; the seed stays ${seed}.`;
    ui.seed.value = String(seed);
    return;
  }
  ui.seed.removeAttribute('aria-invalid');
  ui.seedHint.textContent = '';
  seed = r.seed;
  configure(sides);
});


// Slow / Normal / Fast / Instant: the playground's presets of the slider, for both lanes
const syncSpeedButtons = wireSpeedButtons(ui.speed, () => updateOutputs());
function updateOutputs() {
  syncSpeedButtons();
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
    scenario: () => (src.scenario ? structuredClone(src.scenario) : null),
    seed: () => seed,
    /** The replay's pace: the slider's seconds for a whole run, and a lane's pace as its last frame used it (run/pace.js). */
    duration: () => speedSeconds(ui.speed),
    pace: (key = 'a') => { const p = laneOf(key).playback.pace; return { duration: p.duration, clock: p.clock, frames: p.frames }; },
    /** The last "Run 20 seeds": {first, last, lines, a, b (success, medians), better: {metric: 'a' | 'b' | null}, rows}. */
    seeds: () => (seedSummary ? structuredClone(seedSummary) : null),
    seedsRunning: () => !!seedJob,
    /** A lane's 3-D view: {active, ready, error}; how many of its pixels are near each colour. */
    view3d: (key = 'a') => { const v = laneOf(key).view3d; return { active: v.active, ready: !!v.view?.matrices, error: v.error }; },
    view3dColours: (key, colours, tol) => laneOf(key).view3d.view?.countColours(colours, tol) ?? null,
    /** Css px within a lane's canvas of the world point (x, y), or null. */
    toCanvas: (x, y, key = 'a') => { const L = laneOf(key).view.layout; return L ? [L.sx(x) / L.dpr, L.sy(y) / L.dpr] : null; },
    /** A lane's plane zoom and centre (null: fitted), and whether its layers are drawn at what it shows. */
    viewport: (key = 'a') => { const v = laneOf(key).view; return { zoom: v.zoom, viewport: v.viewport && { ...v.viewport }, settled: v.settled }; },
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

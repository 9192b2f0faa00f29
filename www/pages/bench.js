// The benchmark page: several planner set-ups × seeds 1..N on one scenario, spread over a pool of
// workers (bench-worker.js, one per core; the pages' one pool, ui/seed-pool.js), with progress, an
// estimate of the time left and cancel.
// The results go through the core's own report code (bench_export: the same code as the CLI's
// `bench --csv/--json-file/--ompl-log`), so the table and the exports match the CLI's numbers.
// Set-ups are built from menus (the playground's planner panel, ui/panel.js) or typed as the CLI's
// set-up lines (the "advanced" text, the single source of what runs: the menus add a line to it).
// The scenario is a built-in, an opened file (the core's import_file: the playground's formats)
// or a link's; scenario, set-ups and runs are kept in the URL hash (ui/setups.js) and restored on
// load. A click on a dot of "cost against time" offers that run in the playground.
// Read-only state for tests is exposed as window.planarium.

import init, { builtins as builtinsJson, planners as plannersJson, bench_export as benchExport, parse_setups as parseSetups, import_file as importFile } from '../pkg/planarium.js';
import { fillScenarioPicker, removeCustomScenarios, markCustomScenario } from '../ui/controls.js';
import { createPanel, taskOf } from '../ui/panel.js';
import { setupFor, configOf } from '../ui/links.js';
import { applyPageLimits } from '../run/limits.js';
import { boxPlot, successBars, scatter, stepLines, hitDot } from '../draw/plots.js';
import { downloadText } from '../draw/stage.js';
import { plotOn, addPlotDownloads } from '../ui/plot-downloads.js';
import { withProgress } from '../run/ompl-progress.js';
import { resultRows, fillTable, toMarkdown, toLatex, FK_NOTE } from '../ui/results-table.js';
import { el } from '../ui/dom.js';
import { runPool } from '../ui/seed-pool.js';
import { setupLine, setupLines, readPageState, wholeIn, checkSetups, coreError, pageHash, playgroundLink, readChosenFile, differingParams, MAX_SETUPS } from '../ui/setups.js';
import { shown } from '../ui/text.js';
import { ScenarioSource } from '../run/scenario-source.js';

/**
 * The page's element `id`. Its kind is the HTML's (input, select, button, canvas, dialog…), so it
 * is typed loosely here and checked by the browser tests.
 * @param {string} id
 * @returns {any}
 */
const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), setups: $('setups'), runs: $('runs'), workers: $('workers'),
  run: $('bench-run'), cancel: $('bench-cancel'), progress: $('bench-progress'), status: $('bench-status'),
  error: $('bench-error'), table: $('bench-table'), caption: $('bench-caption'), plots: $('plots'),
  csv: $('export-csv'), json: $('export-json'), ompl: $('export-ompl'), course: $('export-course'), courseTable: $('course-table'), copyBar: $('copy-bar'), copyMd: $('copy-md'), copyTex: $('copy-tex'), copyStatus: $('copy-status'), file: $('file'), list: $('setup-list'),
  buildLabel: $('build-label'), buildPanel: $('build-panel'), add: $('add-setup'), buildNote: $('build-note'),
  advanced: $('advanced'), logAxes: $('log-axes'), plotOptions: $('plot-options'), pop: $('run-pop'),
};
const DEFAULT_SETUPS = 'rrt-connect\nrrt';
const DEFAULT_RUNS = 20;
const MAX_RUNS = 10000;

/** @type {{head: string[], rows: string[][], caption?: string} | null} the results table shown, for its copies */
let tableText = null;
let builtins = [];
let registry = null;
let pool = null;  // the benchmark's workers (ui/seed-pool.js): {stop}
let job = null;   // the benchmark being run: {text, scenario, setups, runs, rows, curves, done, total, started}
let report = null; // the last finished (or cancelled) report
let runProgress = []; // per set-up, seed → RRT*'s best cost against time, for the OMPL log's progress
let curves = [];   // per set-up, RRT*'s best cost against time per run: [[[ms, cost], ...], ...]
let asked = null;  // the last report's {runs: seeds asked per set-up, total: runs asked, done: runs done}
// The scenario and why it was chosen (a built-in, a file, a link): run/scenario-source.js, as the
// other pages; read on this thread, so it is loaded as soon as it is sent.
const src = new ScenarioSource();
// The scenario benchmarked, as a report names it: {id, name, text (its JSON), scenario (parsed),
// source: what a link carries ({id} for a built-in as shipped, else {text})}.
let current = null;
let reportScenario = null; // `current` as the last report ran it (its dots open on it)
let builder = null;        // the set-up builder's planner panel
let dots = [];             // the cost-against-time plot's dots: [{x, y, series, index}]
let dotRows = [];          // per set-up, the solved rows, in the order the dots were drawn
const encoded = new Map(); // scenario text → its link encoding

function showError(text) {
  ui.error.textContent = shown(text);
  ui.error.hidden = !text;
}

function rowOf(seed, result) {
  const s = result.stats;
  return { seed, solved: result.solved, status: result.status, time_ms: s.time_ms, iterations: s.iterations, nodes: s.nodes,
    checks: s.checks, free_checks: s.free_checks ?? 0, cost: s.cost, smoothed_cost: s.smoothed_cost, smoothing_ms: s.smoothing_ms,
    ...(s.cost_fk != null ? { cost_fk: s.cost_fk } : {}), ...(s.smoothed_cost_fk != null ? { smoothed_cost_fk: s.smoothed_cost_fk } : {}) };
}

/**
 * A run's answer from the pool (ui/seed-pool.js): `j` the job {k, setup, seed, …}.
 * @param {{k: number, setup: {label: string}, seed: number}} j
 * @param {Exclude<import('../run/messages.js').BenchReply, {type: 'ready'}>} msg
 */
function onRunAnswer(j, msg) {
  if (!job) return;
  if (msg.type === 'done') {
    job.rows[j.k].push(rowOf(j.seed, msg.result));
    if (msg.curve) { job.curves[j.k].push(msg.curve); job.progress[j.k].set(j.seed, msg.curve); }
  } else {
    // A bad set-up or a crash: stop, say which run, keep the page usable.
    const what = msg.type === 'crashed' ? 'the core crashed' : 'the run was refused';
    finish(`Stopped: ${what} on "${j.setup.label}", seed ${j.seed}: ${msg.message}`);
    return;
  }
  job.done++;
  progress();
  if (job.done === job.total) finish(null);
}

function progress() {
  const { done, total, started } = job;
  ui.progress.max = total;
  ui.progress.value = done;
  const elapsed = (performance.now() - started) / 1000;
  const left = done ? (elapsed / done) * (total - done) : NaN;
  ui.status.textContent = `${done} / ${total} runs` + (done && done < total ? `, about ${left < 1 ? '<1' : Math.round(left)} s left` : '');
}

function setRunning(on) {
  document.body.dataset.state = on ? 'running' : 'idle';
  ui.run.disabled = on;
  ui.cancel.disabled = !on;
  ui.scenario.disabled = on;
  ui.file.disabled = on;
  for (const b of [ui.csv, ui.json, ui.ompl, ui.course]) b.disabled = on || !report;
}

function start() {
  showError('');
  let setups;
  try {
    // The core's parser, the CLI's --setup syntax: errors name the line.
    setups = JSON.parse(parseSetups(ui.setups.value));
  } catch (e) {
    showError(String(e?.message ?? e));
    return;
  }
  const runs = Math.max(1, Math.min(10000, Math.floor(Number(ui.runs.value) || 1)));
  if (setups.length > MAX_SETUPS) { showError(`${setups.length} set-ups: at most ${MAX_SETUPS} run at once.`); return; }
  const b = current;
  const jobs = [];
  // Seed-major order, so every set-up's first seeds finish early and partial results are fair.
  for (let seed = 1; seed <= runs; seed++) {
    setups.forEach((setup, k) => jobs.push({ k, setup, seed, text: b.text, planner: setup.planner, params: setup.params }));
  }
  job = { text: b.text, scenario: b, setups, runs, rows: setups.map(() => []), curves: setups.map(() => []), progress: setups.map(() => new Map()), done: 0, total: jobs.length, started: performance.now() };
  pool?.stop();
  const size = Math.max(1, Math.min(64, Math.floor(Number(ui.workers.value) || navigator.hardwareConcurrency || 2)));
  report = null;
  reportScenario = b;
  writeHash();
  setRunning(true);
  progress();
  pool = runPool(jobs, {
    size,
    onResult: onRunAnswer,
    onEnd(why) { if (why !== 'done' && job) finish('Stopped: the benchmark workers stopped.'); },
  });
}

function finish(problem) {
  pool?.stop();
  pool = null;
  const j = job;
  job = null;
  setRunning(false);
  const limit = j.setups[0]?.params.time_limit ?? registry.run_params.find((p) => p.name === 'time_limit').default;
  const rows = j.rows.map((r) => r.sort((a, b) => a.seed - b.seed));
  report = {
    scenario: j.scenario.name, scenario_id: j.scenario.id, date: new Date().toISOString().replace('T', ' ').slice(0, 19),
    // the seeds that really ran (a cancelled benchmark ran fewer than asked): the exports' "runs per set-up"
    host: 'browser', time_limit_s: limit, runs: Math.max(0, ...rows.map((r) => r.length)),
    setups: j.setups.map((s, k) => ({ label: s.label, planner: s.planner, params: s.params, rows: rows[k] })),
  };
  asked = { runs: j.runs, total: j.total, done: j.done };
  curves = j.curves;
  runProgress = j.progress;
  const secs = ((performance.now() - j.started) / 1000).toFixed(1);
  if (problem) showError(problem);
  ui.status.textContent = problem ? `${j.done} of ${j.total} runs done` : `${j.total} runs in ${secs} s`;
  for (const b of [ui.csv, ui.json, ui.ompl, ui.course]) b.disabled = false;
  show(report);
}

function cancel() {
  if (!job) return;
  const { done, total } = job;
  finish(null);
  ui.status.textContent = `Cancelled after ${done} of ${total} runs`;
}

/** A table number: whole numbers as they are, large ones to 0.1, small ones to 4 significant digits. */
function num(v) {
  if (v === null || v === undefined || !Number.isFinite(v)) return '—';
  if (Number.isInteger(v)) return String(v);
  return Math.abs(v) >= 100 ? v.toFixed(1) : Number(v.toPrecision(4)).toString();
}

/** Runs per set-up as they really ran, short (plot titles): "40 runs each", or "439–440 runs each". */
function runsShort(r) {
  const counts = r.setups.map((s) => s.rows.length);
  const lo = Math.min(...counts), hi = Math.max(...counts);
  return lo === hi ? `${lo} runs each` : `${lo}–${hi} runs each`;
}

/** The seeds that really ran, in words: "2000 seeds per set-up (1 … 2000)" when whole, else per set-up. */
function seedsRun(r) {
  const whole = (s) => s.rows.every((row, i) => row.seed === i + 1);
  const counts = r.setups.map((s) => s.rows.length);
  if (r.setups.every(whole) && counts.every((c) => c === counts[0])) {
    return `${counts[0]} seeds per set-up (1 … ${counts[0]})`;
  }
  return `seeds run per set-up: ${r.setups.map((s) => `${s.label} ${s.rows.length}`).join(', ')}`;
}

/** The table in the courses' form and the plots, from the core's summaries. */
function show(r) {
  const full = JSON.parse(benchExport(JSON.stringify(r), 'json'));
  tableText = resultRows(full.setups);
  fillTable(ui.table, tableText);
  // report 001's table: solved, avgT, stdT, avgNodes, avgQueries (means over all runs, as the CLI's)
  ui.courseTable.tBodies[0].replaceChildren(...full.setups.map((s) => {
    const m = s.summary;
    const tr = document.createElement('tr');
    [s.label, `${(100 * m.success_rate).toFixed(0)}%`, num(m.time_ms.mean), num(m.time_ms.std), num(m.nodes.mean), num(m.checks.mean)].forEach((c, i) => {
      const td = document.createElement(i ? 'td' : 'th');
      if (!i) td.scope = 'row';
      td.textContent = c;
      tr.append(td);
    });
    return tr;
  }));
  ui.courseTable.hidden = false;
  const ran = seedsRun(r);
  const partial = asked && asked.done < asked.total ? ` (stopped after ${asked.done} of ${asked.total} runs)` : '';
  ui.caption.textContent = shown(`${r.scenario}: ${ran}${partial}; means ± standard deviations and medians over all runs, costs over solved runs${tableText.head.some((h) => h.includes('(fk)')) ? `; ${FK_NOTE}` : ''}`);
  tableText.caption = ui.caption.textContent;
  ui.table.hidden = false;
  ui.copyBar.hidden = false;
  ui.copyStatus.textContent = '';
  ui.plots.hidden = false;
  ui.plotOptions.hidden = false;
  drawPlots(r);
}

/** The plots of report `r`, on log axes where the values span decades unless the box is unticked. */
function drawPlots(r) {
  /** @type {{scale: 'auto' | 'linear'}} */
  const opt = { scale: ui.logAxes.checked ? 'auto' : 'linear' };
  closePop();
  const groups = (f, solvedOnly = false) => r.setups.map((s) => ({ label: s.label, values: s.rows.filter((x) => !solvedOnly || x.solved).map(f) }));
  const bars = r.setups.map((s) => ({ label: s.label, solved: s.rows.filter((x) => x.solved).length, runs: s.rows.length }));
  plotOn($('plot-success'), (c) => successBars(c, `Success (${runsShort(r)})`, bars));
  const n = runsShort(r);
  const box = (id, title, unit, f, solvedOnly = false) => {
    const g = groups(f, solvedOnly);
    plotOn($(id), (c) => boxPlot(c, title, unit, g, opt));
  };
  box('plot-time', `Planning time (${n})`, 'ms', (x) => x.time_ms);
  box('plot-nodes', `Nodes (${n})`, 'nodes', (x) => x.nodes);
  box('plot-checks', `State checks (${n})`, 'checks', (x) => x.checks);
  box('plot-cost', `Path cost, solved (${n})`, 'cost', (x) => x.cost, true);
  dotRows = r.setups.map((s) => s.rows.filter((x) => x.solved));
  const dotSeries = r.setups.map((s, k) => ({ label: s.label, points: dotRows[k].map((x) => [x.time_ms, x.cost]) }));
  dots = plotOn($('plot-cost-time'), (c) => scatter(c, `Cost against time, a dot per solved run (${n})`, 'time (ms)', 'cost', dotSeries, opt));
  const anytime = r.setups.map((s, k) => ({ label: s.label, lines: curves[k] ?? [] })).filter((s) => s.lines.length);
  $('plot-curves').hidden = !anytime.length;
  if (anytime.length) plotOn($('plot-curves'), (c) => stepLines(c, 'RRT*: best cost against time, median and interquartile band (a faint line per run)', 'time (ms)', 'cost', anytime, { ...opt, band: true }));
}

// A click on a run's dot: that run (scenario, set-up, seed) in the playground

function closePop() {
  ui.pop.hidden = true;
  ui.pop.replaceChildren();
}

async function onPlotClick(e) {
  if (!report || !reportScenario) return;
  const canvas = e.currentTarget;
  const box = canvas.getBoundingClientRect();
  const hit = hitDot(dots, e.clientX - box.left, e.clientY - box.top);
  if (!hit) { closePop(); return; }
  const setup = report.setups[hit.series];
  const row = dotRows[hit.series]?.[hit.index];
  if (!setup || !row) return;
  const href = await playgroundLink(reportScenario.source, { planner: setup.planner, params: setup.params, seed: row.seed }, registry, encoded);
  const what = `${setup.label}, seed ${row.seed}: cost ${num(row.cost)}, ${num(row.time_ms)} ms`;
  const close = el('button', { type: 'button', className: 'close', text: '×', ariaLabel: 'Close' });
  close.addEventListener('click', closePop);
  const links = href
    ? [el('a', { id: 'run-open', href, text: 'Open in the playground' }),
      el('a', { id: 'run-open-tab', href, target: '_blank', rel: 'noopener', text: 'in a new tab' })]
    : [el('span', { className: 'hint', text: 'This scenario is too large for a link: open its file in the playground and pick this seed.' })];
  ui.pop.replaceChildren(el('p', { className: 'run-what', text: what }), el('p', { className: 'run-links' }, ...links), close);
  ui.pop.dataset.seed = String(row.seed);
  // beside the dot, inside the plots' box
  const plots = ui.plots.getBoundingClientRect();
  ui.pop.hidden = false;
  const w = ui.pop.offsetWidth;
  ui.pop.style.left = `${Math.max(0, Math.min(plots.width - w, box.left - plots.left + hit.x + 10))}px`;
  ui.pop.style.top = `${box.top - plots.top + hit.y + 10}px`;
  (href ? $('run-open') : close).focus();
}

function onPlotMove(e) {
  const box = e.currentTarget.getBoundingClientRect();
  e.currentTarget.classList.toggle('pointing', !!hitDot(dots, e.clientX - box.left, e.clientY - box.top));
}

/** The report in `format`; the OMPL log with RRT*'s progress (run/ompl-progress.js). */
function exported(format) {
  const text = benchExport(JSON.stringify(report), format);
  return format === 'ompl' ? withProgress(text, report, runProgress) : text;
}

function exportAs(format, ext, kind = 'bench') {
  if (!report) return;
  try {
    downloadText(exported(format), `${report.scenario_id}-${kind}.${ext}`);
  } catch (e) {
    showError(String(e.message ?? e));
  }
}

// The scenario

/** Benchmark built-in `b` as shipped. */
function useBuiltin(b) {
  removeCustom();
  ui.scenario.value = b.id;
  src.sent('builtin', { id: b.id });
  src.loaded(b.scenario);
  current = { id: b.id, name: b.name, text: src.text, scenario: src.scenario, source: src.linkSource() };
  builder?.setTask(taskOf(current.scenario));
}

/**
 * Benchmark a scenario given as text (an opened file, or a link's JSON: `reason`): read by the
 * core's import_file, as the playground reads files. `name`: the file's name (its extension picks
 * the format). Returns the problem in words, or null.
 * @param {string} text @param {string} name @param {string} label
 * @param {import('../run/scenario-source.js').LoadReason} reason
 */
function useText(text, name, label, reason) {
  let json;
  try {
    json = importFile(text, name);
  } catch (e) {
    return `${name}: ${coreError(e)}`;
  }
  const scenario = JSON.parse(json);
  const id = (scenario.name || name).replace(/\.[a-z]+$/i, '').replace(/[^\w.-]+/g, '-').toLowerCase().slice(0, 60) || 'scenario';
  src.sent(reason, { file: name });
  src.loaded(scenario, json);
  current = { id, name: scenario.name || name, text: src.text, scenario: src.scenario, source: src.linkSource() };
  markCustom(label);
  builder?.setTask(taskOf(scenario));
  return null;
}

const removeCustom = () => removeCustomScenarios(ui.scenario);
const markCustom = (label) => markCustomScenario(ui.scenario, label);

// The set-ups: the text is what runs; the list shows it, the builder adds to it

/** The list of set-ups the text holds, each with a Remove button; or what is wrong with the text. */
function renderList() {
  const lines = setupLines(ui.setups.value);
  let setups = null;
  let problem = null;
  try {
    setups = JSON.parse(parseSetups(ui.setups.value));
  } catch (e) {
    problem = String(e?.message ?? e);
  }
  if (!setups) {
    ui.list.replaceChildren(el('li', { className: 'bad', text: lines.length ? problem : 'No set-up yet: build one below, or type lines under "Advanced".' }));
    return;
  }
  ui.list.replaceChildren(...setups.map((s, k) => {
    const remove = el('button', { type: 'button', className: 'remove', text: 'Remove', ariaLabel: `Remove set-up ${s.label}` });
    remove.addEventListener('click', () => removeSetup(k));
    const params = Object.entries(s.params).map(([p, v]) => `${p} ${v}`).join(', ');
    return el('li', { className: 'setup-item' },
      el('span', { className: 'setup-label', text: s.label }),
      el('span', { className: 'setup-what', text: [s.planner, params].filter(Boolean).join(' · ') }),
      remove);
  }));
}

function removeSetup(k) {
  const all = ui.setups.value.split('\n');
  const at = setupLines(ui.setups.value)[k]?.at;
  if (at === undefined) return;
  all.splice(at, 1);
  ui.setups.value = all.join('\n');
  setupsChanged();
}

function setupsChanged() {
  renderList();
  writeHash();
}

/** "Add set-up": the builder's planner and parameters as one more line (checked by the core's parser). */
function addSetup() {
  const { planner, params } = builder.config();
  // values at their defaults are left out: the line says what differs
  const line = setupLine({ label: ui.buildLabel.value, planner, params: differingParams(builder.planner(), params, registry) });
  try {
    parseSetups(line);
  } catch (e) {
    ui.buildNote.textContent = shown(String(e?.message ?? e));
    ui.buildNote.classList.add('bad');
    return;
  }
  if (setupLines(ui.setups.value).length >= MAX_SETUPS) {
    ui.buildNote.textContent = `At most ${MAX_SETUPS} set-ups: remove one first.`;
    ui.buildNote.classList.add('bad');
    return;
  }
  const text = ui.setups.value.replace(/\s+$/, '');
  ui.setups.value = text ? `${text}\n${line}` : line;
  ui.buildNote.classList.remove('bad');
  ui.buildNote.textContent = `Added: ${line}`;
  ui.buildLabel.value = '';
  setupsChanged();
}

// The URL: scenario, set-ups and runs

let hashGen = 0;
async function writeHash() {
  if (!current || !registry) return;
  const gen = ++hashGen;
  const runs = wholeIn(ui.runs.value, 1, MAX_RUNS) ?? DEFAULT_RUNS;
  const hash = await pageHash(current.source, [['setups', ui.setups.value.trim()], ['runs', runs]], registry, encoded);
  if (gen !== hashGen) return;
  if (location.hash !== `#${hash}`) history.replaceState(history.state, '', `${location.pathname}${location.search}#${hash}`);
}

/**
 * Restore scenario, set-ups and runs from the hash; bad values are named in the error box and
 * their defaults used. A playground link's planner set-up becomes the one set-up.
 */
async function restoreHash(hash) {
  const { share, own } = await readPageState(hash, { builtins, keys: ['setups', 'runs'] });
  const problems = [...share.problems];
  if (share.scenario?.text) {
    const why = useText(share.scenario.text, 'link.json', 'Scenario from a link', 'link');
    if (why) { problems.push(`The link's scenario: ${why.replace(/^link\.json: /, '')}; the first built-in is used.`); useBuiltin(builtins[0]); }
  } else {
    const b = builtins.find((x) => x.id === share.scenario?.id) || builtins.find((x) => x.id === ui.scenario.value) || builtins[0];
    useBuiltin(b);
  }
  let text = DEFAULT_SETUPS;
  if (own.has('setups')) {
    const got = checkSetups('setups', own.get('setups') ?? '', parseSetups);
    if (got.problem) problems.push(`${got.problem}; the default set-ups are used.`);
    else text = got.text;
  } else if (share.planner !== null || share.params.length) {
    // a playground link: its set-up (planner, parameters) is the one to run
    const { block, problems: more } = setupFor(share, current.scenario, registry);
    problems.push(...more);
    const { planner, params } = configOf(block);
    text = setupLine({ planner, params });
  }
  ui.setups.value = text;
  if (own.has('runs')) {
    const v = wholeIn(own.get('runs'), 1, MAX_RUNS);
    if (v === null) problems.push(`runs=${String(own.get('runs')).slice(0, 40)}: the number of runs must be a whole number from 1 to ${MAX_RUNS}; ${DEFAULT_RUNS} is used.`);
    ui.runs.value = String(v ?? DEFAULT_RUNS);
  }
  showError(problems.length ? `This link has problems:\n${problems.join('\n')}` : '');
  renderList();
}

await init();
builtins = JSON.parse(builtinsJson());
registry = applyPageLimits(JSON.parse(plannersJson()));
fillScenarioPicker(ui.scenario, builtins);
ui.workers.value = String(navigator.hardwareConcurrency || 2);
builder = createPanel(ui.buildPanel, registry, () => { ui.buildNote.textContent = ''; }, { prefix: 'build-', seed: false, title: 'Planner' });
await restoreHash(location.hash);
writeHash();
ui.run.addEventListener('click', start);
ui.cancel.addEventListener('click', cancel);
ui.csv.addEventListener('click', () => exportAs('csv', 'csv'));
ui.json.addEventListener('click', () => exportAs('json', 'json'));
ui.ompl.addEventListener('click', () => exportAs('ompl', 'log'));
ui.course.addEventListener('click', () => exportAs('course', 'csv', 'course'));
ui.add.addEventListener('click', addSetup);
ui.setups.addEventListener('input', setupsChanged);
ui.runs.addEventListener('change', () => writeHash());
ui.scenario.addEventListener('change', () => {
  const b = builtins.find((x) => x.id === ui.scenario.value);
  if (!b) return;
  showError('');
  useBuiltin(b);
  writeHash();
});
ui.file.addEventListener('change', async () => {
  const file = ui.file.files[0];
  ui.file.value = ''; // the same file can be opened again
  if (!file) return;
  showError('');
  let text;
  try { text = await readChosenFile(file); } catch (e) { showError(e.message); return; }
  const why = useText(text, file.name, `File: ${file.name}`, 'file');
  if (why) { showError(`This file is not a scenario the core reads: ${why}`); return; }
  writeHash();
});
ui.logAxes.addEventListener('change', () => { if (report) drawPlots(report); });
addPlotDownloads([...ui.plots.querySelectorAll('canvas.plot')], showError);

// The results table for a report: Markdown or LaTeX on the clipboard
async function copyTable(as, what) {
  if (!tableText) return;
  const text = as(tableText, tableText.caption);
  try {
    await navigator.clipboard.writeText(text);
    ui.copyStatus.textContent = `Copied as ${what}.`;
  } catch (e) {
    ui.copyStatus.textContent = '';
    showError(`The table could not be copied as ${what}: ${e?.message ?? e}`);
  }
}
ui.copyMd.addEventListener('click', () => copyTable(toMarkdown, 'Markdown'));
ui.copyTex.addEventListener('click', () => copyTable(toLatex, 'LaTeX'));
$('plot-cost-time').addEventListener('click', onPlotClick);
$('plot-cost-time').addEventListener('mousemove', onPlotMove);
document.addEventListener('keydown', (e) => { if (e.key === 'Escape' && !ui.pop.hidden) closePop(); });
window.addEventListener('hashchange', () => { if (!job) restoreHash(location.hash).then(() => writeHash()); });
setRunning(false);
ui.status.textContent = 'Ready';
document.body.dataset.state = 'idle';

Object.defineProperty(window, 'planarium', { value: Object.freeze({
  state: () => document.body.dataset.state,
  report: () => report && JSON.parse(JSON.stringify(report)),
  curves: () => JSON.parse(JSON.stringify(curves)),
  exported: (format) => report && exported(format),
  scenario: () => current && { id: current.id, name: current.name, builtin: !!current.source.id },
  setups: () => { try { return JSON.parse(parseSetups(ui.setups.value)); } catch { return null; } },
  dots: () => dots.map((d) => ({ ...d, seed: dotRows[d.series]?.[d.index]?.seed })),
}), writable: false, configurable: false });

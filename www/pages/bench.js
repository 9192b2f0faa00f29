// The benchmark page: several planner set-ups × seeds 1..N on one scenario, spread over a pool of
// workers (bench-worker.js, one per core), with progress, an estimate of the time left and cancel.
// The results go through the core's own report code (bench_export: the same code as the CLI's
// `bench --csv/--json-file/--ompl-log`), so the table and the exports match the CLI's numbers.
// Read-only state for tests is exposed as window.planarium.

import init, { builtins as builtinsJson, planners as plannersJson, bench_export as benchExport, parse_setups as parseSetups } from '../pkg/planarium.js';
import { fillScenarioPicker } from '../ui/controls.js';
import { boxPlot, successBars, scatter, stepLines } from '../draw/plots.js';
import { downloadText } from '../draw/stage.js';

const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), setups: $('setups'), runs: $('runs'), workers: $('workers'),
  run: $('bench-run'), cancel: $('bench-cancel'), progress: $('bench-progress'), status: $('bench-status'),
  error: $('bench-error'), table: $('bench-table'), caption: $('bench-caption'), plots: $('plots'),
  csv: $('export-csv'), json: $('export-json'), ompl: $('export-ompl'),
};

let builtins = [];
let registry = null;
let pool = [];
let job = null;   // the benchmark being run: {report, queue, done, total, started}
let report = null; // the last finished (or cancelled) report
let curves = [];   // per set-up, RRT*'s best cost against time per run: [[[ms, cost], ...], ...]
let asked = null;  // the last report's {runs: seeds asked per set-up, total: runs asked, done: runs done}

function showError(text) {
  ui.error.textContent = text;
  ui.error.hidden = !text;
}

function newWorker() {
  const w = new Worker(new URL('../worker/bench-worker.js', import.meta.url), { type: 'module' });
  w.busy = null;
  w.onmessage = (e) => onWorkerMessage(w, e.data);
  w.onerror = (e) => { e.preventDefault(); onWorkerMessage(w, { type: 'crashed', id: w.busy?.id, message: e.message || 'worker error' }); };
  return w;
}

function stopPool() {
  for (const w of pool) w.terminate();
  pool = [];
}

function dispatch() {
  for (const w of pool) {
    if (w.busy || !job.queue.length) continue;
    const j = job.queue.shift();
    w.busy = j;
    w.postMessage({ id: j.id, text: job.text, planner: j.setup.planner, params: j.setup.params, seed: j.seed });
  }
}

function rowOf(seed, result) {
  const s = result.stats;
  return { seed, solved: result.solved, status: result.status, time_ms: s.time_ms, iterations: s.iterations, nodes: s.nodes,
    checks: s.checks, cost: s.cost, smoothed_cost: s.smoothed_cost, smoothing_ms: s.smoothing_ms };
}

function onWorkerMessage(w, msg) {
  if (!job || msg.type === 'ready') return;
  const j = w.busy;
  w.busy = null;
  if (msg.type === 'done' && j) {
    job.rows[j.k].push(rowOf(j.seed, msg.result));
    if (msg.curve) job.curves[j.k].push(msg.curve);
  } else if (j) {
    // A bad set-up or a crash: stop, say which run, keep the page usable.
    const what = msg.type === 'crashed' ? 'the core crashed' : 'the run was refused';
    finish(`Stopped: ${what} on "${j.setup.label}", seed ${j.seed}: ${msg.message}`);
    return;
  }
  job.done++;
  progress();
  if (job.done === job.total) finish(null);
  else dispatch();
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
  for (const b of [ui.csv, ui.json, ui.ompl]) b.disabled = on || !report;
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
  const b = builtins.find((x) => x.id === ui.scenario.value);
  const queue = [];
  // Seed-major order, so every set-up's first seeds finish early and partial results are fair.
  for (let seed = 1; seed <= runs; seed++) setups.forEach((setup, k) => queue.push({ id: queue.length, k, setup, seed }));
  job = { text: JSON.stringify(b.scenario), scenario: b, setups, runs, rows: setups.map(() => []), curves: setups.map(() => []), queue, done: 0, total: queue.length, started: performance.now() };
  stopPool();
  const n = Math.max(1, Math.min(64, Math.floor(Number(ui.workers.value) || navigator.hardwareConcurrency || 2)));
  for (let i = 0; i < n; i++) pool.push(newWorker());
  report = null;
  setRunning(true);
  progress();
  dispatch();
}

function finish(problem) {
  stopPool();
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
  const secs = ((performance.now() - j.started) / 1000).toFixed(1);
  if (problem) showError(problem);
  ui.status.textContent = problem ? `${j.done} of ${j.total} runs done` : `${j.total} runs in ${secs} s`;
  for (const b of [ui.csv, ui.json, ui.ompl]) b.disabled = false;
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
  const body = ui.table.tBodies[0];
  body.replaceChildren(...full.setups.map((s) => {
    const m = s.summary;
    const tr = document.createElement('tr');
    const cells = [s.label, `${(100 * m.success_rate).toFixed(0)}% (${m.solved}/${m.runs})`, num(m.time_ms.mean), num(m.time_ms.std),
      num(m.time_ms.median), num(m.nodes.median), num(m.checks.median), num(m.cost.median), num(m.smoothed_cost.median)];
    cells.forEach((c, i) => {
      const td = document.createElement(i ? 'td' : 'th');
      if (!i) td.scope = 'row';
      td.textContent = c;
      tr.append(td);
    });
    return tr;
  }));
  const ran = seedsRun(r);
  const partial = asked && asked.done < asked.total ? ` (stopped after ${asked.done} of ${asked.total} runs)` : '';
  ui.caption.textContent = `${r.scenario}: ${ran}${partial}; medians over all runs, costs over solved runs`;
  ui.table.hidden = false;
  ui.plots.hidden = false;
  const groups = (f, solvedOnly = false) => r.setups.map((s) => ({ label: s.label, values: s.rows.filter((x) => !solvedOnly || x.solved).map(f) }));
  successBars($('plot-success'), `Success (${runsShort(r)})`, r.setups.map((s) => ({ label: s.label, solved: s.rows.filter((x) => x.solved).length, runs: s.rows.length })));
  const n = runsShort(r);
  boxPlot($('plot-time'), `Planning time (${n})`, 'ms', groups((x) => x.time_ms));
  boxPlot($('plot-nodes'), `Nodes (${n})`, 'nodes', groups((x) => x.nodes));
  boxPlot($('plot-checks'), `State checks (${n})`, 'checks', groups((x) => x.checks));
  boxPlot($('plot-cost'), `Path cost, solved (${n})`, 'cost', groups((x) => x.cost, true));
  scatter($('plot-cost-time'), `Cost against time, a dot per solved run (${n})`, 'time (ms)', 'cost',
    r.setups.map((s) => ({ label: s.label, points: s.rows.filter((x) => x.solved).map((x) => [x.time_ms, x.cost]) })));
  const anytime = r.setups.map((s, k) => ({ label: s.label, lines: curves[k] ?? [] })).filter((s) => s.lines.length);
  $('plot-curves').hidden = !anytime.length;
  if (anytime.length) stepLines($('plot-curves'), "RRT*: best cost against time (one line per run)", 'time (ms)', 'cost', anytime);
}

function exportAs(format, ext) {
  if (!report) return;
  try {
    downloadText(benchExport(JSON.stringify(report), format), `${report.scenario_id}-bench.${ext}`);
  } catch (e) {
    showError(String(e.message ?? e));
  }
}

await init();
builtins = JSON.parse(builtinsJson());
registry = JSON.parse(plannersJson());
fillScenarioPicker(ui.scenario, builtins);
ui.workers.value = String(navigator.hardwareConcurrency || 2);
ui.run.addEventListener('click', start);
ui.cancel.addEventListener('click', cancel);
ui.csv.addEventListener('click', () => exportAs('csv', 'csv'));
ui.json.addEventListener('click', () => exportAs('json', 'json'));
ui.ompl.addEventListener('click', () => exportAs('ompl', 'log'));
setRunning(false);
ui.status.textContent = 'Ready';
document.body.dataset.state = 'idle';

window.planarium = Object.freeze({
  state: () => document.body.dataset.state,
  report: () => report && JSON.parse(JSON.stringify(report)),
  curves: () => JSON.parse(JSON.stringify(curves)),
  exported: (format) => report && benchExport(JSON.stringify(report), format),
});

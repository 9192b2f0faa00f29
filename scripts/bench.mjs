// The benchmark suite (`npm run bench`): the OMPL comparison problems run natively (the CLI's
// `bench`, seeds 1..N), by OMPL 1.5's own RRT and RRT-Connect through the project's harness
// (bench/ompl/harness.cpp, scripts/ompl.mjs; the same set-ups and seeds, alternated with the native
// runs) when OMPL is installed (Debian's libompl-dev; else the suite says "OMPL not measured" and
// goes on), and, for the problems OMPL is compared on, with the wasm build in Node (the same
// set-ups and seeds; the counts must equal the native ones, bit for bit).
// Then the scaling benchmark: one state check among 10 to 100,000 obstacles for the
// point, a rectangle and an arm (the CLI's `scaling`, and `scaling_json` in wasm).
// Writes bench/results/suite-<UTC stamp>.json (everything) and .md (the tables).
//
//   node scripts/bench.mjs [--runs N] [--rounds K] [--only id,id] [--quick] [--out DIR]
//
// --out DIR: write the results there instead of bench/results/. PLANARIUM_OMPL=0 in the
// environment leaves OMPL out, as on a machine without it.
//
// --only scaling: the scaling benchmark alone; --only rrt-star-budget: RRT* at a fixed time budget
// (1 s and 5 s on narrow and ompl-rect, natively and by OMPL's RRT*) alone.
// --quick: 5 runs and no horn-20 (a smoke run). Times are wall-clock medians of planning only.
// The problems compared between native and wasm or OMPL are run in K rounds (default 3) on each
// side, and each seed's time is its best round: the machine's noise (±15% between identical runs
// here) is larger than the differences measured. Every round must give the same runs, count for count.
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir, cpus } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildHarness, detectOmpl, problemText, runHarness } from './ompl.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const opt = (name, fallback) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : fallback; };
const quick = args.includes('--quick');
const runsArg = Number(opt('--runs', quick ? 5 : 20));
const roundsArg = Math.max(1, Number(opt('--rounds', quick ? 1 : 3)));
const sameRun = (x, y) => x.checks === y.checks && x.nodes === y.nodes && x.cost === y.cost && x.solved === y.solved;
// Each seed's best time over the rounds (rounds: arrays of rows, seed by seed).
const bestOf = (rounds) => rounds[0].map((_, j) => Math.min(...rounds.map((rows) => rows[j].time_ms)));
const only = opt('--only', null)?.split(',');
const ASV = join(root, 'tests', 'data', 'asv');

// ompl: measured by OMPL's planners too (scenarios/<id>.json through the harness) when installed.
const SUITE = [
  { id: 'narrow', what: 'point, wall with a 0.02 gap', wasm: true, ompl: true,
    setups: ['rrt: rrt --range 0.2828', 'rrt-connect: rrt-connect --range 0.2828'] },
  { id: 'ompl-rect', what: 'rigid 0.1 × 0.02 bar, 0.04 gap', wasm: true, ompl: true,
    setups: ['rrt: rrt --range 0.597', 'rrt-connect: rrt-connect --range 0.597'] },
  { id: 'horn-10', what: 'kinematic chain in the horn, 10 links', wasm: true, ompl: true,
    setups: ['rrt: rrt', 'rrt-connect: rrt-connect'] },
  { id: 'horn-20', what: 'kinematic chain in the horn, 20 links (10 s limit)', slow: true, ompl: true,
    setups: ['rrt-connect: rrt-connect --time-limit 10', 'rrt: rrt --time-limit 10'] },
  { id: 'asv-7', what: 'seven vehicles and brooms (7ASV)', runs: 10, setups: ['rrt-connect: rrt-connect --time-limit 10'] },
  ...['3ASV-easy', '3ASV', '7ASV-easy', '7ASV'].map((f) => ({ id: join(ASV, `${f}.txt`), name: f, what: `official ASV file ${f}.txt`, runs: 10,
    setups: ['rrt-connect: rrt-connect --time-limit 10'], optional: true })),
  { id: 'puma-rbo-wall', what: "Puma 560 through the window (report 001's course: RRT-Connect, last free configuration)", wasm: true, runs: 10,
    setups: ['rrt-connect: rrt-connect'] },
  { id: 'technion-mp', what: 'Technion HW3 goal map (4-link arm)', setups: ['rrt-connect: rrt-connect', 'rrt: rrt --goal-bias 0.2'] },
  { id: 'arm-3', what: '3-link arm of report 003', setups: ['rrt-connect: rrt-connect', 'rrt: rrt'] },
];

const cli = join(root, 'target', 'release', 'planarium');
console.log('[bench] cargo build --release');
execFileSync('cargo', ['build', '--release', '--quiet'], { cwd: root, stdio: 'inherit' });

const tmp = mkdtempSync(join(tmpdir(), 'planarium-suite-'));

// OMPL through the project's harness, when installed (rebuilt only when its source is newer).
const selected = (p) => (!only || only.includes(p.name ?? p.id)) && !(quick && p.slow);
let omplBin = null;
let omplStatus = null;
if (SUITE.some((p) => p.ompl && selected(p)) || !only || only.includes('rrt-star-budget')) {
  const found = detectOmpl();
  omplStatus = found.message;
  console.log(`[bench] ${found.message}`);
  if (found.installed) {
    console.log('[bench] g++ -O3 bench/ompl/harness.cpp (when newer than target/ompl/harness)');
    omplBin = buildHarness(root);
  }
}
// A suite problem's scenario, and the harness's problem file for each of its set-ups (or why not).
const omplProblems = (p, name, setups) => {
  const scenario = JSON.parse(readFileSync(join(root, 'scenarios', `${p.id}.json`), 'utf8'));
  return setups.map((s, i) => {
    const made = problemText(scenario, s.planner, s.params ?? {});
    if ('skip' in made) {
      console.log(`[bench] ${name} ${s.label}: OMPL not measured (${made.skip})`);
      return { skip: made.skip };
    }
    const file = join(tmp, `${name}-ompl-${i}.txt`);
    writeFileSync(file, made.text);
    return { file };
  });
};
const sameOmplRun = (x, y) => x.checks === y.checks && x.nodes === y.nodes && x.solved === y.solved;
// OMPL's runs of one set-up in one round. A set-up that solves none of its first OMPL_PROBE seeds
// (each then costs its whole time limit, e.g. OMPL's RRT-Connect on the horn) stops there, and is
// run in the first round only: its times are time limits, not planning times.
const OMPL_PROBE = 5;
const omplSeeds = (file, planner, runs, limitS, first) => {
  if (first?.stopped) return first;
  // The first round keeps OMPL's solution paths, for check-path (below).
  const opts = { paths: !first };
  const head = runHarness(omplBin, file, planner, 1, Math.min(OMPL_PROBE, runs), limitS, opts);
  if (runs <= OMPL_PROBE) return { rows: head, stopped: false };
  if (!head.some((x) => x.solved)) return { rows: head, stopped: true };
  return { rows: head.concat(runHarness(omplBin, file, planner, OMPL_PROBE + 1, runs, limitS, opts)), stopped: false };
};
// OMPL's solution paths judged by Planarium's rule (`planarium check-path`: every motion certified
// free all along at the scenario's resolution; OMPL checks a motion's states a resolution apart and
// nothing between them). The paths are dropped from the rows after.
const omplPathsChecked = (scenarioFile, rows, name) => {
  const solved = rows.filter((x) => x.path);
  if (!solved.length) return null;
  const file = join(tmp, `${name}-ompl-paths.jsonl`);
  writeFileSync(file, solved.map((x) => JSON.stringify({ seed: x.seed, path: x.path })).join('\n') + '\n');
  const out = spawnSync(cli, ['check-path', scenarioFile, file, '--json'], { encoding: 'utf8', maxBuffer: 64 << 20 });
  if (out.status !== 0 && out.status !== 1) throw new Error(`check-path ${scenarioFile}: ${out.stderr}`);
  const j = JSON.parse(out.stdout);
  for (const x of rows) delete x.path;
  return { paths: solved.length, refused: j.refused, motions: j.motions, motions_refused: j.motions_refused,
    refused_seeds: j.paths.filter((x) => !x.valid).map((x) => x.seed) };
};

// The wasm build in Node: the same set-ups and seeds, events off, as the page's benchmark workers.
const wasmFile = join(root, 'www', 'pkg', 'planarium_bg.wasm');
let wasm = null;
if (SUITE.some((p) => p.wasm && (!only || only.includes(p.id))) || !only || only.includes('scaling')) {
  if (existsSync(wasmFile)) {
    const { initSync, Run, builtins, scaling_json: scalingJson } = await import(join(root, 'www', 'pkg', 'planarium.js'));
    initSync({ module: readFileSync(wasmFile) });
    wasm = { Run, scalingJson, texts: Object.fromEntries(JSON.parse(builtins()).map((b) => [b.id, JSON.stringify(b.scenario)])) };
  } else {
    console.log('[bench] www/pkg is not built (node scripts/build.mjs): wasm skipped');
  }
}
const wasmRun = (text, s, seed) => {
  const run = new wasm.Run(text, s.planner, JSON.stringify(s.params), seed);
  run.record_events(false);
  while (run.step(1e9, 1e9) === 'running');
  const res = JSON.parse(run.result_json());
  run.free();
  return { seed, solved: res.solved, time_ms: res.stats.time_ms, nodes: res.stats.nodes, checks: res.stats.checks, cost: res.stats.cost };
};

const results = [];
for (const p of SUITE) {
  const name = p.name ?? p.id;
  if (only && !only.includes(name)) continue;
  if (quick && p.slow) continue;
  if (p.optional && !existsSync(p.id)) { console.log(`[bench] ${name}: ${p.id} not found, skipped`); continue; }
  const runs = Math.min(p.runs ?? runsArg, runsArg);
  const withWasm = p.wasm && wasm;
  const withOmpl = p.ompl && omplBin;
  if (withWasm && !wasm.texts[p.id]) throw new Error(`www/pkg has no built-in "${p.id}": rebuild it (node scripts/build.mjs)`);
  const rounds = withWasm || withOmpl ? roundsArg : 1;
  const started = Date.now();
  // Rounds alternate native, OMPL and wasm, so that all sides see the machine in the same state.
  const reports = [];
  const wasmRounds = [];
  const omplRounds = [];
  let problems = null;
  for (let k = 0; k < rounds; k++) {
    const file = join(tmp, `${name}-${k}.json`);
    execFileSync(cli, ['bench', p.id, '--runs', String(runs), ...p.setups.flatMap((s) => ['--setup', s]), '--json-file', file], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
    reports.push(JSON.parse(readFileSync(file, 'utf8')));
    if (withOmpl) {
      problems ??= omplProblems(p, name, reports[0].setups);
      omplRounds.push(reports[0].setups.map((s, i) => (problems[i].file
        ? omplSeeds(problems[i].file, s.planner, runs, Number(s.params?.time_limit ?? reports[0].time_limit_s), omplRounds[0]?.[i])
        : null)));
    }
    if (!withWasm) continue;
    wasmRounds.push(reports[0].setups.map((s) => {
      // One untimed run first: the engine compiles the module's hot code on first use.
      if (k === 0) wasmRun(wasm.texts[p.id], s, 1);
      return Array.from({ length: runs }, (_, j) => wasmRun(wasm.texts[p.id], s, j + 1));
    }));
  }
  const report = reports[0];
  report.setups.forEach((s, i) => {
    const all = reports.map((r) => r.setups[i].rows);
    s.rounds = rounds;
    s.best_ms = bestOf(all);
    s.rounds_agree = all.every((rows) => rows.every((x, j) => sameRun(x, s.rows[j])));
    if (!s.rounds_agree) console.log(`[bench] ${name} ${s.label}: the native rounds DIFFER`);
  });
  const wasmResult = withWasm ? report.setups.map((s, i) => {
    const all = wasmRounds.map((r) => r[i]);
    return { label: s.label, rows: all[0], best_ms: bestOf(all), same_as_native: all.every((rows) => rows.every((x, j) => sameRun(x, s.rows[j]))) };
  }) : null;
  const omplResult = withOmpl ? report.setups.map((s, i) => {
    if (problems[i].skip) return { label: s.label, skip: problems[i].skip };
    const all = omplRounds.map((r) => r[i].rows);
    const agree = all.every((rows) => rows.every((x, j) => sameOmplRun(x, all[0][j])));
    if (!agree) console.log(`[bench] ${name} ${s.label}: the OMPL rounds DIFFER`);
    const stopped = omplRounds[0][i].stopped;
    if (stopped) console.log(`[bench] ${name} ${s.label}: OMPL solved none of seeds 1..${OMPL_PROBE}; its other seeds and rounds not run`);
    const paths_checked = omplPathsChecked(join(root, 'scenarios', `${p.id}.json`), all[0], `${name}-${i}`);
    if (paths_checked) console.log(`[bench] ${name} ${s.label}: check-path refuses ${paths_checked.refused} of OMPL's ${paths_checked.paths} paths (${paths_checked.motions_refused} of ${paths_checked.motions} motions)`);
    return { label: s.label, planner: s.planner, rows: all[0], best_ms: bestOf(all), rounds_agree: agree, stopped, paths_checked };
  }) : null;
  const sides = ['natively', withOmpl && 'by OMPL', withWasm && 'in wasm'].filter(Boolean).join(', ');
  console.log(`[bench] ${name}: ${runs} seeds × ${p.setups.length} set-ups × ${rounds} round(s) ${sides} in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  if (wasmResult) console.log(`[bench] ${name}: wasm in Node ${wasmResult.every((w) => w.same_as_native) ? 'gives the native runs exactly' : 'DIFFERS from the native runs'}`);
  results.push({ problem: name, what: p.what, runs, omplCompared: Boolean(p.ompl), ompl: omplResult, native: report, wasm: wasmResult, wasmScenario: withWasm ? p.id : null });
}

// RRT* at a fixed time budget: the best path's cost when the time is up, natively and by OMPL's
// RRT* (the same range, goal bias and near set; both improve until the limit), seeds 1..N each.
// Budgets 1 s and 5 s (--quick: 0.2 s); selected by default or by --only rrt-star-budget.
const BUDGET_PROBLEMS = [{ id: 'narrow', range: 0.2828 }, { id: 'ompl-rect', range: 0.597 }];
const budgets = quick ? [0.2] : [1, 5];
const budgetRows = [];
if (!only || only.includes('rrt-star-budget')) {
  for (const b of BUDGET_PROBLEMS) {
    for (const limit of budgets) {
      const started = Date.now();
      const runs = Math.min(runsArg, quick ? 3 : runsArg);
      const setup = `rrt-star: rrt-star --range ${b.range} --improve-for 100000000 --max-nodes 1000000 --time-limit ${limit}`;
      const file = join(tmp, `${b.id}-star-${limit}.json`);
      execFileSync(cli, ['bench', b.id, '--runs', String(runs), '--setup', setup, '--json-file', file], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
      const s = JSON.parse(readFileSync(file, 'utf8')).setups[0];
      let ompl = null;
      if (omplBin) {
        const [problem] = omplProblems(b, `${b.id}-star-${limit}`, [s]);
        ompl = problem.skip ? { skip: problem.skip } : { rows: runHarness(omplBin, problem.file, 'rrt-star', 1, runs, limit) };
        if (problem.skip) console.log(`[bench] ${b.id} RRT* ${limit} s: OMPL not measured (${problem.skip})`);
      }
      console.log(`[bench] ${b.id} RRT* at ${limit} s: ${runs} seeds ${ompl?.rows ? 'natively and by OMPL' : 'natively'} in ${((Date.now() - started) / 1000).toFixed(1)} s`);
      budgetRows.push({ problem: b.id, budget_s: limit, runs, params: s.params, native: s.rows, ompl });
    }
  }
}

// The scaling benchmark: natively, then in wasm (the same states: the valid counts must agree).
let scaling = null;
if (!only || only.includes('scaling')) {
  const started = Date.now();
  const checks = quick ? 20000 : 200000;
  const file = join(tmp, 'scaling.json');
  execFileSync(cli, ['scaling', '--checks', String(checks), '--rounds', String(roundsArg), '--json-file', file], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
  const native = JSON.parse(readFileSync(file, 'utf8'));
  const inWasm = wasm?.scalingJson ? JSON.parse(wasm.scalingJson(checks, roundsArg)) : null;
  const sameValid = inWasm ? inWasm.every((w, i) => w.valid === native[i].valid) : null;
  console.log(`[bench] scaling: ${native.length} rows, ${checks} checks each, ${inWasm ? 'natively and in wasm' : 'natively'} in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  if (inWasm) console.log(`[bench] scaling: wasm in Node ${sameValid ? 'finds the native valid counts' : 'DIFFERS from the native valid counts'}`);
  scaling = { checks, native, wasm: inWasm, same_valid: sameValid };
}

const median = (xs) => { const v = xs.filter(Number.isFinite).sort((a, b) => a - b); const n = v.length; return n ? (n % 2 ? v[(n - 1) / 2] : (v[n / 2 - 1] + v[n / 2]) / 2) : NaN; };
const mean = (xs) => xs.reduce((a, b) => a + b, 0) / xs.length;
// The sample standard deviation, as the CLI's summaries give it.
const std = (xs) => (xs.length > 1 ? Math.sqrt(xs.reduce((a, x) => a + (x - mean(xs)) ** 2, 0) / (xs.length - 1)) : 0);
const f = (v, d = 2) => (Number.isFinite(v) ? (Math.abs(v) >= 1000 ? Math.round(v).toString() : v.toFixed(d)) : '—');
const stamp = new Date().toISOString().replace(/[-:]/g, '').replace(/\..*/, '').replace('T', '-');
const host = `${cpus().length} × ${cpus()[0]?.model ?? 'cpu'}`;
const lines = [
  `# Benchmark suite, ${new Date().toISOString().slice(0, 16).replace('T', ' ')} UTC`,
  '',
  `Machine: ${host}, Node ${process.version}. Seeds 1..N per set-up; times are medians of planning time (smoothing excluded). `
  + `Where wasm or OMPL is measured, every side ran ${roundsArg} round(s), alternated, and each seed's time is its best round. `
  + (omplBin ? 'OMPL: OMPL 1.5\'s RRT, RRT-Connect and RRT* (Debian\'s libompl-dev) in the project\'s harness, bench/ompl/harness.cpp, g++ -O3, the same set-ups and seeds; '
    + 'its checks count its state validity checker\'s calls; native / OMPL is the ratio of the median times (below 1: Planarium is faster); '
    + 'OMPL paths refused: its solutions that `planarium check-path` refuses (a motion not free all along at the scenario\'s resolution: OMPL checks a motion\'s states a resolution apart, Planarium certifies the whole motion). '
    : `${omplStatus ?? 'OMPL not measured'}. `)
  + 'Made by `npm run bench`.',
  '',
  '| problem | set-up | solved | median ms (native) | mean ± std ms (native) | median ms (wasm, Node) | wasm / native | solved (OMPL) | median ms (OMPL) | native / OMPL | median checks (OMPL) | OMPL paths refused | median nodes | median checks | median cost |',
  '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|',
];
for (const r of results) {
  r.native.setups.forEach((s, k) => {
    const m = s.summary;
    const w = r.wasm?.[k];
    const wms = w ? median(w.best_ms) : NaN;
    const nms = s.rounds > 1 ? median(s.best_ms) : m.time_ms.median;
    const agree = (w ? w.same_as_native : true) && s.rounds_agree;
    const o = r.ompl?.[k];
    const oms = o?.rows ? median(o.best_ms) : NaN;
    const notMeasured = r.omplCompared ? 'not measured' : '—';
    // A median over runs of which half or more failed is a time limit, not a planning time.
    const oSolved = o?.rows ? o.rows.filter((x) => x.solved).length : 0;
    const ratio = 2 * oSolved > (o?.rows?.length ?? 0) && 2 * m.solved > m.runs ? `${f(nms / oms)}×` : '— (half or more unsolved)';
    const omplCells = o?.rows
      ? [`${oSolved}/${o.rows.length}${o.stopped ? ' (stopped)' : ''}`, f(oms), `${ratio}${o.rounds_agree ? '' : ' (rounds differ!)'}`, f(median(o.rows.map((x) => x.checks)), 0),
        o.paths_checked ? `${o.paths_checked.refused}/${o.paths_checked.paths} (${o.paths_checked.motions_refused} of ${o.paths_checked.motions} motions)` : '—']
      : [notMeasured, notMeasured, '—', '—', '—'];
    lines.push(`| ${r.problem} | ${s.label} | ${m.solved}/${m.runs} | ${f(nms)} | ${s.rounds > 1 ? `${f(mean(s.best_ms))} ± ${f(std(s.best_ms))}` : `${f(m.time_ms.mean)} ± ${f(m.time_ms.std)}`} | ${w ? f(wms) : '—'} | ${w ? `${f(wms / nms)}×` : '—'}${agree ? '' : ' (runs differ!)'} | ${omplCells.join(' | ')} | ${f(m.nodes.median, 1)} | ${f(m.checks.median, 0)} | ${f(m.cost.median, 4)} |`);
  });
}
if (results.length) {
  lines.push('', 'Problems:', '');
  for (const r of results) lines.push(`- **${r.problem}**: ${r.what}.`);
} else {
  lines.splice(lines.length - 2, 2); // no problem run: no table
}
if (budgetRows.length) {
  // the quartiles of the solved runs' costs: the spread
  const quartiles = (xs) => {
    const v = xs.filter(Number.isFinite).sort((a, b) => a - b);
    const q = (t) => v[Math.min(v.length - 1, Math.floor(t * (v.length - 1) + 0.5))];
    return v.length ? `${f(q(0.25), 4)}–${f(q(0.75), 4)}` : '—';
  };
  const side = (rows) => {
    const solved = rows.filter((x) => x.solved && x.cost >= 0);
    const costs = solved.map((x) => x.cost);
    return { solved: `${solved.length}/${rows.length}`, median: median(costs), spread: quartiles(costs), nodes: median(rows.map((x) => x.nodes)) };
  };
  lines.push('', '## RRT* at a fixed time budget', '',
    'The best path\'s cost (its length in the robot\'s metric, unsmoothed) when the time is up, seeds 1..N; both planners improve until the limit, '
    + 'with the same range, goal bias (0.05) and near set (k-nearest, rewire factor 1.1). Spread: the quartiles of the solved runs\' costs. '
    + 'Planarium / OMPL below 1: Planarium\'s paths are shorter.', '',
    '| problem | budget | solved | median cost | spread | median nodes | solved (OMPL) | median cost (OMPL) | spread (OMPL) | median nodes (OMPL) | Planarium / OMPL cost |',
    '|---|---|---|---|---|---|---|---|---|---|---|');
  for (const r of budgetRows) {
    const n = side(r.native);
    const o = r.ompl?.rows ? side(r.ompl.rows) : null;
    const oCells = o ? [o.solved, f(o.median, 4), o.spread, f(o.nodes, 0), `${f(n.median / o.median, 3)}×`] : [r.ompl?.skip ? `not measured (${r.ompl.skip})` : 'not measured', '—', '—', '—', '—'];
    lines.push(`| ${r.problem} | ${r.budget_s} s | ${n.solved} | ${f(n.median, 4)} | ${n.spread} | ${f(n.nodes, 0)} | ${oCells.join(' | ')} |`);
  }
}
if (scaling) {
  lines.push('', '## Scaling: one state check among n obstacles', '',
    `A 2 × 1 map whose right half holds n small blocks in a grid; ${scaling.checks} checks of uniform states per row, best of ${roundsArg} round(s). `
    + '× 10: the time over the 10-obstacle time (the target: at most 3 at 100,000). Build: the broad phase (boxes, BVH, grid) from the obstacles.', '',
    '| robot | obstacles | ns / check (native) | × 10 | ns / check (wasm, Node) | × 10 (wasm) | valid | build ms | broad phase kB |',
    '|---|---|---|---|---|---|---|---|---|');
  scaling.native.forEach((r, i) => {
    const w = scaling.wasm?.[i];
    lines.push(`| ${r.robot} | ${r.obstacles} | ${f(r.ns_per_check, 1)} | ${f(r.ratio_to_10)} | ${w ? f(w.ns_per_check, 1) : '—'} | ${w ? f(w.ratio_to_10) : '—'} | ${r.valid}${w && w.valid !== r.valid ? ' (wasm differs!)' : ''} | ${f(r.build_ms)} | ${f(r.broad_phase_bytes / 1024, 0)} |`);
  });
}
const outDir = opt('--out', join(root, 'bench', 'results'));
mkdirSync(outDir, { recursive: true });
const base = join(outDir, `suite-${stamp}`);
writeFileSync(`${base}.json`, `${JSON.stringify({ date: new Date().toISOString(), host, node: process.version, runs: runsArg, results, rrt_star_budget: budgetRows, scaling }, null, 1)}\n`);
writeFileSync(`${base}.md`, `${lines.join('\n')}\n`);
console.log(lines.join('\n'));
console.log(`[bench] wrote ${base}.json and ${base}.md`);

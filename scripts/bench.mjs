// The benchmark suite (`npm run bench`): issue 7's problems beside OMPL 1.5.2's figures, run
// natively (the CLI's `bench`, seeds 1..N) and, for the problems OMPL was timed on, with the wasm
// build in Node (the same set-ups and seeds; the counts must equal the native ones, bit for bit).
// Writes bench/results/suite-<UTC stamp>.json (everything) and .md (the tables).
//
//   node scripts/bench.mjs [--runs N] [--only id,id] [--quick]
//
// --quick: 5 runs and no horn-20 (a smoke run). Times are wall-clock medians of planning only.
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir, cpus } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const opt = (name, fallback) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : fallback; };
const quick = args.includes('--quick');
const runsArg = Number(opt('--runs', quick ? 5 : 20));
const only = opt('--only', null)?.split(',');
const ASV = join(root, '..', 'shared', 'data', 'asv');

// OMPL 1.5.2 (Debian's libompl-dev, -O3), medians over 20 seeds on this machine kind (issue 7).
const SUITE = [
  { id: 'narrow', what: 'point, wall with a 0.02 gap', wasm: true,
    setups: ['rrt: rrt --range 0.2828', 'rrt-connect: rrt-connect --range 0.2828'],
    ompl: { rrt: '0.6 ms, 8.4k checks', 'rrt-connect': '2.4 ms, 17k checks' }, omplMs: { rrt: 0.6, 'rrt-connect': 2.4 } },
  { id: 'ompl-rect', what: 'rigid 0.1 × 0.02 bar, 0.04 gap', wasm: true,
    setups: ['rrt: rrt --range 0.597', 'rrt-connect: rrt-connect --range 0.597'],
    ompl: { rrt: '23 ms, 123k checks', 'rrt-connect': '36 ms, 159k checks' }, omplMs: { rrt: 23, 'rrt-connect': 36 } },
  { id: 'horn-10', what: 'kinematic chain in the horn, 10 links', wasm: true,
    setups: ['rrt: rrt', 'rrt-connect: rrt-connect'],
    ompl: { rrt: '7.3 ms', 'rrt-connect': '9.9 ms' }, omplMs: { rrt: 7.3, 'rrt-connect': 9.9 } },
  { id: 'horn-20', what: 'kinematic chain in the horn, 20 links (10 s limit)', slow: true,
    setups: ['rrt-connect: rrt-connect --time-limit 10', 'rrt: rrt --time-limit 10'],
    ompl: { rrt: '83% solved in 30 s', 'rrt-connect': '33% solved in 30 s' } },
  { id: 'asv-7', what: 'seven vehicles and brooms (7ASV)', runs: 10, setups: ['rrt-connect: rrt-connect --time-limit 10'] },
  ...['3ASV-easy', '3ASV', '7ASV-easy', '7ASV'].map((f) => ({ id: join(ASV, `${f}.txt`), name: f, what: `official ASV file ${f}.txt`, runs: 10,
    setups: ['rrt-connect: rrt-connect --time-limit 10'], optional: true })),
  { id: 'technion-mp', what: 'Technion HW3 goal map (4-link arm)', setups: ['rrt-connect: rrt-connect', 'rrt: rrt --goal-bias 0.2'] },
  { id: 'arm-3', what: '3-link arm of report 003', setups: ['rrt-connect: rrt-connect', 'rrt: rrt'] },
];

const cli = join(root, 'target', 'release', 'planarium');
console.log('[bench] cargo build --release');
execFileSync('cargo', ['build', '--release', '--quiet'], { cwd: root, stdio: 'inherit' });

const tmp = mkdtempSync(join(tmpdir(), 'planarium-suite-'));
const results = [];
for (const p of SUITE) {
  const name = p.name ?? p.id;
  if (only && !only.includes(name)) continue;
  if (quick && p.slow) continue;
  if (p.optional && !existsSync(p.id)) { console.log(`[bench] ${name}: ${p.id} not found, skipped`); continue; }
  const runs = Math.min(p.runs ?? runsArg, runsArg);
  const file = join(tmp, `${name}.json`);
  const started = Date.now();
  execFileSync(cli, ['bench', p.id, '--runs', String(runs), ...p.setups.flatMap((s) => ['--setup', s]), '--json-file', file], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
  const report = JSON.parse(readFileSync(file, 'utf8'));
  console.log(`[bench] ${name}: ${runs} seeds × ${p.setups.length} set-ups natively in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  results.push({ problem: name, what: p.what, runs, ompl: p.ompl ?? null, omplMs: p.omplMs ?? null, native: report, wasm: null, wasmScenario: p.wasm ? p.id : null });
}

// The wasm build in Node: the same set-ups and seeds, events off, as the page's benchmark workers.
const wasmFile = join(root, 'www', 'pkg', 'planarium_bg.wasm');
if (results.some((r) => r.wasmScenario) && existsSync(wasmFile)) {
  const { initSync, Run, builtins } = await import(join(root, 'www', 'pkg', 'planarium.js'));
  initSync({ module: readFileSync(wasmFile) });
  const texts = Object.fromEntries(JSON.parse(builtins()).map((b) => [b.id, JSON.stringify(b.scenario)]));
  for (const r of results.filter((x) => x.wasmScenario)) {
    if (!texts[r.wasmScenario]) throw new Error(`www/pkg has no built-in "${r.wasmScenario}": rebuild it (node scripts/build.mjs)`);
    r.wasm = r.native.setups.map((s) => {
      // One untimed run first: the engine compiles the module's hot code on first use.
      const warm = new Run(texts[r.wasmScenario], s.planner, JSON.stringify(s.params), 1);
      warm.record_events(false);
      while (warm.step(1e9, 1e9) === 'running');
      warm.free();
      const rows = [];
      for (let seed = 1; seed <= r.runs; seed++) {
        const run = new Run(texts[r.wasmScenario], s.planner, JSON.stringify(s.params), seed);
        run.record_events(false);
        while (run.step(1e9, 1e9) === 'running');
        const res = JSON.parse(run.result_json());
        run.free();
        rows.push({ seed, solved: res.solved, time_ms: res.stats.time_ms, nodes: res.stats.nodes, checks: res.stats.checks, cost: res.stats.cost });
      }
      const same = rows.every((x, i) => x.checks === s.rows[i].checks && x.nodes === s.rows[i].nodes && x.cost === s.rows[i].cost);
      return { label: s.label, rows, same_as_native: same };
    });
    console.log(`[bench] ${r.problem}: wasm in Node ${r.wasm.every((w) => w.same_as_native) ? 'gives the native runs exactly' : 'DIFFERS from the native runs'}`);
  }
} else if (results.some((r) => r.wasmScenario)) {
  console.log('[bench] www/pkg is not built (node scripts/build.mjs): wasm skipped');
}

const median = (xs) => { const v = xs.filter(Number.isFinite).sort((a, b) => a - b); const n = v.length; return n ? (n % 2 ? v[(n - 1) / 2] : (v[n / 2 - 1] + v[n / 2]) / 2) : NaN; };
const f = (v, d = 2) => (Number.isFinite(v) ? (Math.abs(v) >= 1000 ? Math.round(v).toString() : v.toFixed(d)) : '—');
const stamp = new Date().toISOString().replace(/[-:]/g, '').replace(/\..*/, '').replace('T', '-');
const host = `${cpus().length} × ${cpus()[0]?.model ?? 'cpu'}`;
const lines = [
  `# Benchmark suite, ${new Date().toISOString().slice(0, 16).replace('T', ' ')} UTC`,
  '',
  `Machine: ${host}, Node ${process.version}. Seeds 1..N per set-up; times are medians of planning time (smoothing excluded). `
  + 'OMPL 1.5.2 figures are issue 7\'s (medians over 20 seeds, same machine kind). Made by `npm run bench`.',
  '',
  '| problem | set-up | solved | median ms (native) | median ms (wasm, Node) | wasm / native | OMPL | median nodes | median checks | median cost |',
  '|---|---|---|---|---|---|---|---|---|---|',
];
for (const r of results) {
  r.native.setups.forEach((s, k) => {
    const m = s.summary;
    const w = r.wasm?.[k];
    const wms = w ? median(w.rows.map((x) => x.time_ms)) : NaN;
    const plannerKey = s.planner;
    lines.push(`| ${r.problem} | ${s.label} | ${m.solved}/${m.runs} | ${f(m.time_ms.median)} | ${w ? f(wms) : '—'} | ${w ? `${f(wms / m.time_ms.median)}×${w.same_as_native ? '' : ' (runs differ!)'}` : '—'} | ${r.ompl?.[plannerKey] ?? '—'} | ${f(m.nodes.median, 1)} | ${f(m.checks.median, 0)} | ${f(m.cost.median, 4)} |`);
  });
}
lines.push('', 'Problems:', '');
for (const r of results) lines.push(`- **${r.problem}**: ${r.what}.`);
const outDir = join(root, 'bench', 'results');
mkdirSync(outDir, { recursive: true });
const base = join(outDir, `suite-${stamp}`);
writeFileSync(`${base}.json`, `${JSON.stringify({ date: new Date().toISOString(), host, node: process.version, runs: runsArg, results }, null, 1)}\n`);
writeFileSync(`${base}.md`, `${lines.join('\n')}\n`);
console.log(lines.join('\n'));
console.log(`[bench] wrote ${base}.json and ${base}.md`);

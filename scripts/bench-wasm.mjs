// The benchmark of the wasm build under Node: `node scripts/bench-wasm.mjs SCENARIO_ID PLANNER RUNS`
// runs seeds 1..RUNS exactly as `planarium bench` does natively (events off is not possible in the
// binding, so the worker's real cost, events included, is what is measured) and prints the medians.
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { initSync, Run, builtins } from '../www/pkg/planarium.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
initSync({ module: readFileSync(join(root, 'www/pkg/planarium_bg.wasm')) });
const [id = 'narrow', planner = 'rrt-connect', runsText = '20'] = process.argv.slice(2);
const scenario = JSON.parse(builtins()).find((b) => b.id === id);
if (!scenario) throw new Error(`no built-in scenario ${id}`);
const text = JSON.stringify(scenario.scenario);
const median = (xs) => { const v = [...xs].sort((a, b) => a - b); const n = v.length; return n % 2 ? v[(n - 1) / 2] : (v[n / 2 - 1] + v[n / 2]) / 2; };
const rows = [];
for (let seed = 1; seed <= Number(runsText); seed++) {
  const run = new Run(text, planner, '{}', seed);
  while (run.step(1e9, 1e9) === 'running');
  rows.push(JSON.parse(run.result_json()));
  run.free();
}
const solved = rows.filter((r) => r.solved).length;
console.log(`wasm (Node ${process.version}) ${planner} on ${id}, seeds 1..${rows.length}: ${solved}/${rows.length} solved`);
for (const k of ['time_ms', 'nodes', 'checks', 'cost']) {
  console.log(`  median ${k}: ${median(rows.map((r) => r.stats[k] ?? NaN)).toFixed(k === 'time_ms' ? 3 : 1)}`);
}

// Shared by the Node tests that run the core itself (the wasm build, no browser): the module
// initialised once, the built-in scenarios by id, and a planner run's event records.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { initSync, Run, builtins } from '../../www/pkg/planarium.js';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
initSync({ module: readFileSync(join(ROOT, 'www/pkg/planarium_bg.wasm')) });

/** The built-in scenarios, by id. */
export const scenarios = Object.fromEntries(JSON.parse(builtins()).map((b) => [b.id, b.scenario]));

/**
 * Run `planner` with `params` and `seed` on built-in `scenario` to its end (or 3 M numbers of
 * records): {out: the flat records, status}.
 */
export function runRecords(scenario, planner, params, seed) {
  const run = new Run(JSON.stringify(scenarios[scenario]), planner, JSON.stringify(params), seed);
  const out = [];
  let status;
  do {
    status = run.step(200, 1e9);
    for (const v of run.drain_events()) out.push(v);
  } while (status === 'running' && out.length < 3e6);
  run.free();
  return { out, status };
}

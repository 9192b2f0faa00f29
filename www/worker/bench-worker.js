// A benchmark worker: runs one seeded planning run at a time, to the end, and posts its result.
// The page keeps a pool of these (one per core) and hands out (set-up, seed) jobs.
//
// Message in  {id, text, planner, params, seed}: the scenario's JSON text, the set-up and seed.
// Messages out {type: 'ready'}; {type: 'done', id, result} (the contract's result JSON, parsed);
//              (for RRT*: `curve`, the best cost against planning time, [[ms, cost], ...], read
//              from its COST events after each 10 ms batch)
//              {type: 'failed', id, message}: a bad set-up (the worker stays usable);
//              {type: 'crashed', id, message}: the core panicked; the page replaces this worker.
// Their types, BenchJob and BenchReply, are in ../run/messages.js (checked by tsc --checkJs).

import init, { Run, install_panic_hook, last_panic, planners } from '../pkg/planarium.js';
import { EventKind, STRIDE } from '../run/events.js';

// The run goes to its end in one loop (the page cancels by terminating the worker); batches of this
// many ms only bound each wasm call. An RRT* cost curve reads its COST events every 10 ms instead.
const BATCH_MS = 50;

/** @param {import('../run/messages.js').BenchReply} msg */
const post = (msg) => self.postMessage(msg);

/** @type {Map<string, string | null>} each planner's chart (the registry's `caps.chart`) */
let charts = new Map();

const ready = init().then(() => {
  install_panic_hook();
  charts = new Map(JSON.parse(planners()).planners.map((p) => [p.name, p.caps?.chart ?? null]));
  post({ type: 'ready' });
});

/** @param {MessageEvent<import('../run/messages.js').BenchJob>} e */
self.onmessage = async (e) => {
  await ready;
  const { id, text, planner, params, seed } = e.data;
  let run = null;
  try {
    run = new Run(text, planner, JSON.stringify(params), seed);
    // An anytime planner's cost curve (a planner whose chart is its cost) needs its COST events;
    // other runs record nothing.
    /** @type {Array<[number, number]> | null} */
    const curve = charts.get(planner) === 'cost' ? [] : null;
    run.record_events(!!curve);
    let status;
    do {
      status = run.step(1e9, curve ? 10 : BATCH_MS);
      if (curve) {
        const ev = run.drain_events();
        let best = null;
        for (let o = 0; o < ev.length; o += STRIDE) if (ev[o] === EventKind.COST) best = ev[o + 6];
        if (best !== null) curve.push([JSON.parse(run.stats_json()).time_ms, best]);
      }
    } while (status === 'running');
    const result = JSON.parse(run.result_json());
    post({ type: 'done', id, result, curve });
  } catch (err) {
    const panic = last_panic();
    if (panic) post({ type: 'crashed', id, message: panic });
    else post({ type: 'failed', id, message: String(err?.message ?? err) });
  } finally {
    try { run?.free(); } catch { /* a poisoned module: the page replaces the worker */ }
  }
};

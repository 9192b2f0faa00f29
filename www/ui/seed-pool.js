// The page's one pool of background benchmark workers (worker/bench-worker.js) that runs a list of
// jobs {text, planner, params, seed} to the end, each on a fresh run: what "Run 20 seeds" uses in
// the playground (ui/trials.js) and in Compare (pages/compare.js), two workers at most, and the
// benchmark page (pages/bench.js), as many as it asks for. The page's own run is not touched.

/** @typedef {import('../run/messages.js').BenchJob} BenchJob */
/** @typedef {import('../run/messages.js').BenchReply} BenchReply */

/**
 * Start `jobs`. `onResult(job, message)` gets each job (with its index as `id`) and the worker's
 * answer ({type: 'done', result} | {type: 'failed' | 'crashed', message}); a worker that crashed takes
 * no more jobs. `onEnd(why)` is called once when every job has answered ('done') or no worker is
 * left ('workers lost'); not after `stop()`. `size`: the number of workers (default: one per core,
 * at most two; never more than the jobs). Jobs are handed out in order. Returns {stop}: terminates
 * the workers at once.
 * The messages are the benchmark worker's (run/messages.js: BenchJob, BenchReply).
 * @template {Omit<BenchJob, 'id'>} J
 * @param {J[]} jobs
 * @param {{onResult: (job: J & {id: number}, message: Exclude<BenchReply, {type: 'ready'}>) => void,
 *   onEnd?: (why: 'done' | 'workers lost') => void, size?: number}} handlers
 * @returns {{stop: () => void}}
 */
export function runPool(jobs, { onResult, onEnd = () => {}, size: asked = Math.min(2, navigator.hardwareConcurrency || 2) }) {
  const queue = jobs.map((j, id) => ({ ...j, id }));
  /** @type {Array<Worker & {busy: (J & {id: number}) | null}>} */
  let workers = [];
  let answered = 0;
  let stopped = false;
  const stop = () => {
    stopped = true;
    for (const w of workers) w.terminate();
    workers = [];
  };
  /** @param {'done' | 'workers lost'} why */
  const end = (why) => { if (!stopped) { stop(); onEnd(why); } };
  const give = (w) => {
    const j = queue.shift();
    w.busy = j ?? null;
    /** @type {BenchJob} */
    const msg = j && { id: j.id, text: j.text, planner: j.planner, params: j.params, seed: j.seed };
    if (j) w.postMessage(msg);
  };
  /** @param {Worker & {busy: (J & {id: number}) | null}} w @param {BenchReply} m */
  const answer = (w, m) => {
    if (stopped) return;
    if (m.type === 'ready') { give(w); return; }
    const j = w.busy;
    w.busy = null;
    if (!j) return;
    answered++;
    onResult(j, m);
    if (stopped) return; // the handler stopped the pool
    if (m.type === 'crashed') { // a poisoned module: this worker takes no more jobs
      w.terminate();
      workers = workers.filter((x) => x !== w);
    }
    if (answered === jobs.length) end('done');
    else if (!workers.length) end('workers lost');
    else if (m.type !== 'crashed') give(w);
  };
  const size = Math.max(1, Math.min(asked, jobs.length));
  for (let k = 0; k < size; k++) {
    const w = Object.assign(new Worker(new URL('../worker/bench-worker.js', import.meta.url), { type: 'module' }), { busy: null });
    w.onmessage = (e) => answer(w, e.data);
    w.onerror = (e) => {
      e.preventDefault();
      if (stopped) return;
      if (w.busy) { answer(w, { type: 'crashed', id: w.busy.id, message: e.message || 'the worker stopped' }); return; }
      w.terminate(); // it failed before taking a job
      workers = workers.filter((x) => x !== w);
      if (!workers.length) end('workers lost');
    };
    workers.push(w);
  }
  if (!jobs.length) end('done');
  return { stop };
}

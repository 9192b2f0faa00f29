// "Run 20 seeds": the playground's set-up run on 20 consecutive seeds in background benchmark
// workers (ui/seed-pool.js), so a student sees how much one seed
// says: the share solved and the medians (time, iterations, nodes, checks, path cost; run/summary.js), and one dot
// per seed, coloured by outcome, that opens that seed in the playground when clicked. The page's own
// run is not touched. Built with DOM calls and textContent.

import { el } from './dom.js';
import { runPool } from './seed-pool.js';
import { MAX_SEED } from './seed.js';
import { summarise } from '../run/summary.js';

export const SEEDS = 20;

const METRICS = ['time_ms', 'iterations', 'nodes', 'checks', 'cost'];

/**
 * {runs, solved, success, medians: {time_ms, iterations, nodes, checks, cost}} of result JSONs:
 * the medians over the solved runs (run/summary.js), the cost the smoothed path's when there is one.
 */
export function summariseResults(results) {
  const rows = results.map((r) => ({
    solved: !!r.solved, time_ms: r.stats?.time_ms, iterations: r.stats?.iterations, nodes: r.stats?.nodes,
    checks: r.stats?.checks, cost: r.stats?.smoothed_cost ?? r.stats?.cost,
  }));
  return summarise(rows, { overSolved: METRICS });
}

const fmt = (v, d = 0) => (v === null || v === undefined ? '–' : Number(v).toLocaleString('en', { maximumFractionDigits: d }));

/**
 * Wire the trials box: `button` starts, `cancel` stops (the workers are terminated), `status`,
 * `table` and `dots` show the outcome; `setup()` gives {text, planner, params, seed} or null;
 * `open(seed)` opens a seed in the playground.
 */
export function createTrials({ button, cancel, status, table, dots, setup, open }) {
  let pool = null;

  function stop() {
    pool?.stop();
    pool = null;
    button.disabled = false;
    cancel.hidden = true;
  }

  function show(s, results, first) {
    table.hidden = false;
    const row = (k, v) => el('tr', {}, el('th', { scope: 'row', text: k }), el('td', { text: v }));
    const m = s.medians;
    table.replaceChildren(el('tbody', {},
      row('Solved', `${s.solved} of ${s.runs}`),
      row('Median time', `${fmt(m.time_ms, 1)} ms`),
      row('Median iterations', fmt(m.iterations)),
      row('Median nodes', fmt(m.nodes)),
      row('Median checks', fmt(m.checks)),
      row('Median path cost', fmt(m.cost, 3))));
    dots.replaceChildren(...results.map((r, i) => {
      if (!r) return el('span', { className: 'trial-dot pending', text: '·' });
      const seed = first + i;
      const b = el('button', {
        className: `trial-dot ${r.solved ? 'solved' : 'failed'}`, type: 'button', text: String(seed),
        title: `seed ${seed}: ${r.status}, ${fmt(r.stats?.time_ms, 1)} ms, ${fmt(r.stats?.nodes)} nodes — click to open it`,
      });
      b.dataset.seed = String(seed);
      b.addEventListener('click', () => open(seed));
      return b;
    }));
  }

  button.addEventListener('click', () => {
    const s = setup();
    if (!s) { status.textContent = 'Load a valid scenario first.'; return; }
    if (s.seed > MAX_SEED - (SEEDS - 1)) {
      status.textContent = `Seeds ${s.seed} … ${s.seed} + ${SEEDS - 1} would pass ${MAX_SEED} (2^53 − 1), the largest seed the page carries exactly: choose a seed of at most ${MAX_SEED - (SEEDS - 1)}.`;
      return;
    }
    stop();
    const first = s.seed;
    const results = new Array(SEEDS).fill(null);
    let done = 0;
    button.disabled = true;
    cancel.hidden = false;
    status.textContent = `Running ${s.planner} on seeds ${first}–${first + SEEDS - 1}…`;
    const jobs = Array.from({ length: SEEDS }, (_, i) => ({ text: s.text, planner: s.planner, params: s.params, seed: first + i }));
    pool = runPool(jobs, {
      onResult(j, m) {
        results[j.id] = m.type === 'done' ? m.result : { solved: false, status: m.type === 'failed' ? `failed: ${m.message}` : 'crashed', stats: {} };
        done++;
        status.textContent = `Running seeds: ${done} of ${SEEDS} done…`;
        show(summariseResults(results.filter(Boolean)), results, first);
      },
      onEnd() {
        stop();
        const sum = summariseResults(results.filter(Boolean));
        status.textContent = `${s.planner}, seeds ${first}–${first + SEEDS - 1}: solved ${sum.solved} of ${sum.runs}. Click a seed to open it.`;
        show(sum, results, first);
      },
    });
  });
  cancel.addEventListener('click', () => { stop(); status.textContent = 'Stopped.'; });
}

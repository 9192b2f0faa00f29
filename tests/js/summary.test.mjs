// The page's summary over seeds (www/run/summary.js) against known values: numpy's quantiles
// (linear interpolation), the sample standard deviation, and the core's own summary of the same
// numbers (the benchmark page's table and the CLI print the core's; the page's Run 20 seeds must agree).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { median, mean, std, quantile, quartiles, successRate, summarise } from '../../www/run/summary.js';
import './core-runs.mjs'; // initialises the wasm build
import { bench_export as benchExport } from '../../www/pkg/planarium.js';

test('median: the middle value, or the mean of the middle two; non-finite values are left out', () => {
  assert.equal(median([3, 1, 2]), 2);
  assert.equal(median([3, 1, 2, 10]), 2.5);
  assert.equal(median([7]), 7);
  assert.equal(median([]), null);
  assert.equal(median([null, undefined, NaN, Infinity]), null);
  assert.equal(median([5, null, 1, NaN, 3, undefined]), 3);
  // the mean of the middle two as (a + b) / 2, as the core computes it (not a + (b − a) / 2)
  assert.equal(median([0.1, 0.2]), (0.1 + 0.2) / 2);
  // numbers, not strings: 10 sorts after 9
  assert.equal(median([10, 9, 100]), 10);
});

test('mean and sample standard deviation (n − 1)', () => {
  assert.equal(mean([1, 2, 3, 4]), 2.5);
  assert.equal(mean([]), null);
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, squared deviations sum to 32, so std = sqrt(32 / 7)
  assert.equal(std([2, 4, 4, 4, 5, 5, 7, 9]), Math.sqrt(32 / 7));
  assert.equal(std([42]), 0);
  assert.equal(std([]), null);
  assert.equal(std([1, NaN, 3]), Math.SQRT2);
});

test('quantiles by linear interpolation, as numpy.quantile', () => {
  // numpy.quantile([1, 2, 3, 4], [0, .25, .5, .75, 1]) = [1, 1.75, 2.5, 3.25, 4]
  const v = [4, 1, 3, 2];
  assert.deepEqual([0, 0.25, 0.5, 0.75, 1].map((p) => quantile(v, p)), [1, 1.75, 2.5, 3.25, 4]);
  // numpy.quantile([1, 2, 3, 4, 5, 6, 7, 8, 9, 10], .9) = 9.1
  assert.ok(Math.abs(quantile([1, 2, 3, 4, 5, 6, 7, 8, 9, 10], 0.9) - 9.1) < 1e-12);
  assert.equal(quantile([], 0.5), null);
  assert.equal(quantile([5, 1], 2), 5, 'p is clamped to 1');
  assert.deepEqual(quartiles([10, 1, 7, 3, 5]), { min: 1, q1: 3, median: 5, q3: 7, max: 10, n: 5 });
  assert.deepEqual(quartiles([1, 2, 3, 4]), { min: 1, q1: 1.75, median: 2.5, q3: 3.25, max: 4, n: 4 });
  const empty = quartiles([]);
  assert.equal(empty.n, 0);
  assert.ok(Number.isNaN(empty.median) && Number.isNaN(empty.min) && Number.isNaN(empty.q1));
});

test('success rate', () => {
  assert.equal(successRate(3, 4), 0.75);
  assert.equal(successRate(0, 0), 0);
  assert.equal(successRate(20, 20), 1);
});

test('summarise: medians over every run or over the solved ones, success', () => {
  const rows = [
    { solved: true, time_ms: 10, nodes: 100, cost: 2 },
    { solved: false, time_ms: 50, nodes: 900, cost: null },
    { solved: true, time_ms: 20, nodes: 300, cost: 4 },
    { solved: false, time_ms: 40, nodes: 700 },
  ];
  const s = summarise(rows, { overAll: ['time_ms', 'nodes'], overSolved: ['cost'] });
  assert.deepEqual(s, { runs: 4, solved: 2, success: 0.5, medians: { time_ms: 30, nodes: 500, cost: 3 } });
  const solvedOnly = summarise(rows, { overSolved: ['time_ms', 'nodes', 'missing'] });
  assert.deepEqual(solvedOnly.medians, { time_ms: 15, nodes: 200, missing: null });
  assert.deepEqual(summarise([], { overAll: ['time_ms'] }), { runs: 0, solved: 0, success: 0, medians: { time_ms: null } });
});

test('the page\'s summary agrees with the core\'s on the same rows (median, mean, std, success)', () => {
  // odd and even counts, values that round differently, an unsolved run
  const times = [12.5, 3.25, 7.125, 100.0625, 0.1, 0.2];
  const costs = [1.5, null, 2.75, 0.3, 0.1, 0.2];
  const rows = times.map((t, i) => ({
    seed: i + 1, solved: costs[i] !== null, status: costs[i] !== null ? 'solved' : 'time_limit', time_ms: t,
    iterations: 10 * (i + 1), nodes: 7 * (i + 1) + (i % 2), checks: 31 * (i + 3), cost: costs[i], smoothed_cost: costs[i],
    smoothing_ms: 0,
  }));
  const report = { scenario: 's', scenario_id: 's', date: '', host: 'test', time_limit_s: 1, runs: rows.length,
    setups: [{ label: 'a', planner: 'rrt', params: {}, rows }] };
  const core = JSON.parse(benchExport(JSON.stringify(report), 'json')).setups[0].summary;
  assert.equal(median(times), core.time_ms.median);
  assert.equal(mean(times), core.time_ms.mean);
  assert.ok(Math.abs(std(times) - core.time_ms.std) <= 1e-12 * core.time_ms.std, `std ${std(times)} vs ${core.time_ms.std}`);
  assert.equal(median(rows.map((r) => r.nodes)), core.nodes.median);
  assert.equal(median(rows.filter((r) => r.solved).map((r) => r.cost)), core.cost.median);
  const s = summarise(rows, { overAll: ['checks'], overSolved: ['cost'] });
  assert.equal(s.success, core.success_rate);
  assert.equal(s.solved, core.solved);
  assert.equal(s.runs, core.runs);
  assert.equal(s.medians.checks, core.checks.median);
});

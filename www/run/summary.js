// Summaries over seeds, the page's one copy (as the core's src/run/summary.rs): the median (the
// mean of the middle two for an even count), mean, sample standard deviation (n − 1), quantiles by
// linear interpolation (numpy's default) and the success rate. "Run 20 seeds" (ui/trials.js, the
// playground), Compare's Run 20 seeds (pages/compare.js) and the benchmark's plots (draw/plots.js)
// use it; the benchmark's table is the core's own summary (bench_export), as the CLI prints it.
// Pure: no DOM, so a Node test checks it against known values.

/** The finite numbers of `xs`, ascending. @param {Array<number | null | undefined>} xs @returns {number[]} */
function finiteSorted(xs) {
  return /** @type {number[]} */ (xs.filter(Number.isFinite)).sort((a, b) => a - b);
}

/** The median of sorted values (the mean of the middle two for an even count; NaN when empty). @param {number[]} v */
function medianOfSorted(v) {
  if (!v.length) return NaN;
  const m = v.length >> 1;
  return v.length % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

/**
 * The `p`-quantile (0 ≤ p ≤ 1) of sorted values by linear interpolation between the closest
 * ranks (numpy's default); NaN when empty. @param {number[]} v @param {number} p
 */
function quantileOfSorted(v, p) {
  if (!v.length) return NaN;
  const i = (v.length - 1) * p;
  const lo = Math.floor(i), hi = Math.ceil(i);
  return v[lo] + (v[hi] - v[lo]) * (i - lo);
}

/** The median of the finite numbers in `xs`, or null when there are none. @param {Array<number | null | undefined>} xs */
export function median(xs) {
  const v = finiteSorted(xs);
  return v.length ? medianOfSorted(v) : null;
}

/** The mean of the finite numbers in `xs`, or null when there are none. @param {Array<number | null | undefined>} xs */
export function mean(xs) {
  const v = /** @type {number[]} */ (xs.filter(Number.isFinite));
  return v.length ? v.reduce((a, b) => a + b, 0) / v.length : null;
}

/**
 * The sample standard deviation (n − 1) of the finite numbers in `xs`: 0 for one value, null for
 * none (as the core's). @param {Array<number | null | undefined>} xs
 */
export function std(xs) {
  const v = /** @type {number[]} */ (xs.filter(Number.isFinite));
  if (!v.length) return null;
  if (v.length === 1) return 0;
  const m = v.reduce((a, b) => a + b, 0) / v.length;
  return Math.sqrt(v.reduce((a, x) => a + (x - m) ** 2, 0) / (v.length - 1));
}

/** The `p`-quantile (0 … 1, linear interpolation) of the finite numbers in `xs`, or null. @param {Array<number | null | undefined>} xs @param {number} p */
export function quantile(xs, p) {
  const v = finiteSorted(xs);
  return v.length ? quantileOfSorted(v, Math.min(1, Math.max(0, p))) : null;
}

/**
 * A box plot's five numbers of `values` (all of them; NaN for an empty list): min, quartiles by
 * linear interpolation, the median as `median` gives it, max, and n.
 * @param {number[]} values
 * @returns {{min: number, q1: number, median: number, q3: number, max: number, n: number}}
 */
export function quartiles(values) {
  const v = [...values].sort((a, b) => a - b);
  return { min: v.length ? v[0] : NaN, q1: quantileOfSorted(v, 0.25), median: medianOfSorted(v), q3: quantileOfSorted(v, 0.75),
    max: v.length ? v[v.length - 1] : NaN, n: v.length };
}

/** The share of runs solved, 0 … 1 (0 for no runs). @param {number} solved @param {number} runs */
export function successRate(solved, runs) {
  return runs > 0 ? solved / runs : 0;
}

/**
 * @typedef {{solved: boolean} & Record<string, any>} SeedRow  one run: solved, and its metrics by name
 * @typedef {{runs: number, solved: number, success: number, medians: Record<string, number | null>}} SeedSummary
 */

/**
 * The summary of some runs: how many, how many solved, the success rate, and the median of each
 * metric: those named in `overAll` over every run, those in `overSolved` over the solved runs
 * (a path's cost means nothing without a path). A metric a run lacks (not a finite number) is left
 * out of its median; a metric no run has is null.
 * @param {SeedRow[]} rows
 * @param {{overAll?: string[], overSolved?: string[]}} metrics
 * @returns {SeedSummary}
 */
export function summarise(rows, { overAll = [], overSolved = [] }) {
  const ok = rows.filter((r) => r.solved);
  /** @type {Record<string, number | null>} */
  const medians = {};
  for (const k of overAll) medians[k] = median(rows.map((r) => r[k]));
  for (const k of overSolved) medians[k] = median(ok.map((r) => r[k]));
  return { runs: rows.length, solved: ok.length, success: successRate(ok.length, rows.length), medians };
}

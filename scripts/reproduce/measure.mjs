// Statistics and the report 004 cost unit, recomputed from paths outside the core.

/** The mean of `xs` (NaN when empty). */
export const mean = (xs) => (xs.length ? xs.reduce((a, b) => a + b, 0) / xs.length : NaN);

/** The sample standard deviation (n − 1) of `xs` (0 for one value, NaN when empty). */
export function std(xs) {
  if (!xs.length) return NaN;
  if (xs.length === 1) return 0;
  const m = mean(xs);
  return Math.sqrt(xs.reduce((a, x) => a + (x - m) ** 2, 0) / (xs.length - 1));
}

/** The median of `xs` (the mean of the middle two for an even count; NaN when empty). */
export function median(xs) {
  if (!xs.length) return NaN;
  const s = [...xs].sort((a, b) => a - b);
  const k = s.length >> 1;
  return s.length % 2 ? s[k] : (s[k - 1] + s[k]) / 2;
}

/** The Technion course's arm: link lengths, base at (0, 0). */
export const TECHNION_LINKS = [80, 70, 40, 40];

/** Forward kinematics of the course's arm at joint angles `q` (relative): the 4 link ends, as report 004's 4×2 array. */
export function linkEnds(q, links = TECHNION_LINKS) {
  let x = 0, y = 0, a = 0;
  return links.map((l, i) => {
    a += q[i];
    x += l * Math.cos(a);
    y += l * Math.sin(a);
    return [x, y];
  });
}

/** Report 004's distance: the Euclidean norm of the difference of the two stacked link-end arrays. */
export function fkDistance(p, q) {
  const a = linkEnds(p), b = linkEnds(q);
  let s = 0;
  for (let i = 0; i < a.length; i++) s += (a[i][0] - b[i][0]) ** 2 + (a[i][1] - b[i][1]) ** 2;
  return Math.sqrt(s);
}

/** A path's cost in report 004's unit: the sum of `fkDistance` over consecutive configurations. */
export function fkCost(path) {
  let c = 0;
  for (let i = 1; i < path.length; i++) c += fkDistance(path[i - 1], path[i]);
  return c;
}

/** Student's t two-sided 95% critical values for 1..30 degrees of freedom. */
const T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.16, 2.145, 2.131,
  2.12, 2.11, 2.101, 2.093, 2.086, 2.08, 2.074, 2.069, 2.064, 2.06, 2.056, 2.052, 2.048, 2.045, 2.042];

/** The 97.5% quantile of Student's t with `df` degrees of freedom (a table to 30, then the Cornish–Fisher series; ±0.001). */
export function t975(df) {
  if (!(df >= 1)) return NaN;
  if (df <= 30) return T975[Math.floor(df) - 1];
  const z = 1.959964;
  return z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df * df);
}

/** The mean of `xs` and the half-width of its 95% t-interval (mean ± t·s/√n; NaN half-width below 2 values). */
export function ci95(xs) {
  const m = mean(xs);
  return { mean: m, half: xs.length > 1 ? t975(xs.length - 1) * std(xs) / Math.sqrt(xs.length) : NaN };
}

/** Welch's t-test of two samples' means at the 5% level: t, the Welch–Satterthwaite df, and whether the gap is significant. */
export function welch(a, b) {
  const va = std(a) ** 2 / a.length, vb = std(b) ** 2 / b.length;
  if (va + vb === 0) return { t: NaN, df: NaN, significant: mean(a) !== mean(b) };
  const t = (mean(a) - mean(b)) / Math.sqrt(va + vb);
  const df = (va + vb) ** 2 / (va ** 2 / (a.length - 1) + vb ** 2 / (b.length - 1));
  return { t, df, significant: Number.isFinite(t) && Math.abs(t) > t975(df) };
}

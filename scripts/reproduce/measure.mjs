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

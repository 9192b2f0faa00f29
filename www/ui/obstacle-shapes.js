// The obstacle editor's geometry (obstacle-editor.js): the snapping grid's steps and rounding, an
// obstacle's handles, whether a point is inside it, and the obstacle moved or reshaped by a drag. Obstacles are the scenario's JSON
// objects ({rect}, {circle}, {polygon}, {segment}); each function returns a new one.

import { pointInPolygon } from '../draw/transform.js';

/** A "nice" grid step near `v` (1, 2 or 5 times a power of ten). */
export function niceStep(v) {
  if (!(v > 0) || !Number.isFinite(v)) return 1;
  const p = 10 ** Math.floor(Math.log10(v));
  const best = [1, 2, 5, 10].map((m) => m * p).reduce((a, b) => (Math.abs(Math.log(b / v)) < Math.abs(Math.log(a / v)) ? b : a));
  return Number(best.toPrecision(1));
}

/** How many decimals the values on a grid of `step` need (as written, at most 12). */
export function stepDecimals(step) {
  const text = String(step);
  if (!/e/i.test(text)) return Math.min(12, (text.split('.')[1] || '').length);
  return Math.min(12, Math.max(0, 2 - Math.floor(Math.log10(step))));
}

/** `v` on the grid of `step` (anchored at 0), written with the step's decimals: no float noise. */
export function snapTo(v, step) {
  return Number((Math.round(v / step) * step).toFixed(stepDecimals(step)));
}

/** `v` rounded to about four digits below `extent` (the map's size): 0.46999998929207787 → 0.47. */
export function tidy(v, extent) {
  const step = 10 ** (Math.floor(Math.log10(Math.max(extent, 1e-9))) - 4);
  return Number((Math.round(v / step) * step).toFixed(Math.max(0, Math.min(12, Math.round(-Math.log10(step))))));
}

/** Decimals for showing coordinates on a map of size `extent` (a pixel is about 1/1000 of it). */
export function readoutDecimals(extent) {
  return Math.max(0, Math.min(8, 3 - Math.floor(Math.log10(Math.max(extent, 1e-9)))));
}

/** The point an obstacle is moved by when snapping: a circle's centre, else its first handle. */
export function anchor(ob) {
  return ob.circle ? [ob.circle[0], ob.circle[1]] : handles(ob)[0] || [0, 0];
}

/** The handles of obstacle `ob`: [[x, y], ...] in world units. */
export function handles(ob) {
  if (ob.rect) { const [a, b, c, d] = ob.rect; return [[a, b], [c, b], [c, d], [a, d]]; }
  if (ob.circle) { const [x, y, r] = ob.circle; return [[x + r, y]]; }
  if (ob.polygon) return ob.polygon.map((p) => [...p]);
  if (ob.segment) { const [a, b, c, d] = ob.segment; return [[a, b], [c, d]]; }
  return [];
}

/** Whether world point (x, y) is inside obstacle `ob` (a segment: within `tol`). */
export function inside(ob, x, y, tol) {
  if (ob.rect) { const [a, b, c, d] = ob.rect; return x >= Math.min(a, c) && x <= Math.max(a, c) && y >= Math.min(b, d) && y <= Math.max(b, d); }
  if (ob.circle) { const [cx, cy, r] = ob.circle; return Math.hypot(x - cx, y - cy) <= r; }
  if (ob.polygon) return pointInPolygon(x, y, ob.polygon.flat());
  if (ob.segment) {
    const [a, b, c, d] = ob.segment;
    const dx = c - a, dy = d - b, len2 = dx * dx + dy * dy || 1;
    const t = Math.max(0, Math.min(1, ((x - a) * dx + (y - b) * dy) / len2));
    return Math.hypot(x - a - t * dx, y - b - t * dy) <= tol;
  }
  return false;
}

export function moved(ob, dx, dy) {
  if (ob.rect) { const [a, b, c, d] = ob.rect; return { rect: [a + dx, b + dy, c + dx, d + dy] }; }
  if (ob.circle) { const [x, y, r] = ob.circle; return { circle: [x + dx, y + dy, r] }; }
  if (ob.polygon) return { polygon: ob.polygon.map(([x, y]) => [x + dx, y + dy]) };
  if (ob.segment) { const [a, b, c, d] = ob.segment; return { segment: [a + dx, b + dy, c + dx, d + dy] }; }
  return ob;
}

/** Obstacle `ob` with handle `k` dragged to (x, y). */
export function reshaped(ob, k, x, y) {
  if (ob.rect) {
    const [a, b, c, d] = ob.rect;
    const opp = [[c, d], [a, d], [a, b], [c, b]][k]; // the corner across from handle k stays
    return { rect: [opp[0], opp[1], x, y] };
  }
  if (ob.circle) { const [cx, cy] = ob.circle; return { circle: [cx, cy, Math.hypot(x - cx, y - cy)] }; }
  if (ob.polygon) return { polygon: ob.polygon.map((p, i) => (i === k ? [x, y] : [...p])) };
  if (ob.segment) { const s = [...ob.segment]; s[2 * k] = x; s[2 * k + 1] = y; return { segment: s }; }
  return ob;
}

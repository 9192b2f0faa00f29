// EST's density grid, as its records say (DensityMirror, fed by playback.js's RunModel) and drawn
// (drawDensity, from view.js over the cells layer, under the trees).
//
// EST and bi-EST file every node in a cell of a `grid`-a-side grid over the map's bounds, by the
// node's projected point, and pick a cell with probability ∝ 1 / (the nodes in it). The mirror files
// the same points (the NODE_ADDED records' x y, the root's from its first child's record or its
// first SELECT) by the same rule as src/planners/est.rs (`Grown::file`), with the grid size from the
// latest SELECT record; each SELECT also carries the picked cell's count and probability, so a test
// can check the mirror against the planner pick by pick.
//
// Drawn: the tree that picked last, each of its cells shaded by the probability of being picked
// next (darkest: the likeliest, the sparsest cell); the cell of the latest pick outlined.

import { EventKind } from '../run/events.js';
import { PALETTE } from './palette.js';

/** The cell index of `v` in [lo, hi] on a `grid`-a-side grid, as `Grown::file` computes it. */
export function densityCell(v, lo, hi, grid) {
  const w = Math.max(hi - lo, 1e-12);
  const t = Math.min(Math.max((v - lo) / w, 0), 1);
  return Math.min(Math.floor(t * grid), grid - 1);
}

/** One tree's filed points and counts. */
class DensityTree {
  constructor() {
    this.xs = [];
    this.ys = [];
    this.rooted = false;
    this.filed = 0;            // points filed into `counts` so far
    this.counts = new Map();   // column · grid + row → nodes
  }

  add(x, y) { this.xs.push(x); this.ys.push(y); }
}

export class DensityMirror {
  constructor() {
    this.trees = [];
    this.grid = 0;       // cells a side (from the latest SELECT; 0 before one)
    this.latest = null;  // the latest SELECT: {tree, id, count, share, cells, column, row}
    this.key = '';       // the bounds and grid the counts were filed for
  }

  get empty() { return !this.latest; }

  tree(t) {
    const i = t > 0 ? t | 0 : 0;
    while (this.trees.length <= i) this.trees.push(new DensityTree());
    return this.trees[i];
  }

  /** The record at offset `o` of `d` was revealed (NODE_ADDED or SELECT). */
  apply(d, o) {
    const t = this.tree(d[o + 1]);
    if (d[o] === EventKind.NODE_ADDED) {
      if (!t.rooted && d[o + 3] === 0) { t.add(d[o + 6], d[o + 7]); t.rooted = true; }
      if (d[o + 3] >= 0) t.add(d[o + 4], d[o + 5]);
      return;
    }
    if (!t.rooted && d[o + 2] === 0) { t.add(d[o + 4], d[o + 5]); t.rooted = true; }
    const grid = d[o + 11];
    if (Number.isFinite(grid) && grid >= 1 && grid <= 1000) this.grid = Math.floor(grid);
    this.latest = { tree: d[o + 1] > 0 ? d[o + 1] | 0 : 0, id: d[o + 2], count: d[o + 6], share: d[o + 7],
      cells: d[o + 8], column: d[o + 9], row: d[o + 10] };
  }

  /**
   * Tree `t`'s node counts by cell over `bounds` = [x0, y0, x1, y1], keyed column · grid + row
   * (filed incrementally).
   */
  counts(t, bounds) {
    const key = `${bounds.join(',')}/${this.grid}`;
    if (key !== this.key) {
      for (const tr of this.trees) { tr.filed = 0; tr.counts.clear(); }
      this.key = key;
    }
    const tr = this.tree(t);
    const [x0, y0, x1, y1] = bounds;
    for (; tr.filed < tr.xs.length; tr.filed++) {
      const c = densityCell(tr.xs[tr.filed], x0, x1, this.grid) * this.grid + densityCell(tr.ys[tr.filed], y0, y1, this.grid);
      tr.counts.set(c, (tr.counts.get(c) || 0) + 1);
    }
    return tr.counts;
  }
}

/** Shade the picking tree's cells by their chance of being picked; outline the latest pick's cell. */
export function drawDensity(ctx, L, mirror, bounds) {
  if (!mirror || mirror.empty || !mirror.grid) return;
  const { tree, column, row } = mirror.latest;
  const counts = mirror.counts(tree, bounds);
  let total = 0;
  for (const n of counts.values()) total += 1 / n;
  if (!(total > 0)) return;
  const [x0, y0, x1, y1] = bounds;
  const cw = (x1 - x0) / mirror.grid, ch = (y1 - y0) / mirror.grid;
  const maxShare = 1 / total; // a cell of one node
  ctx.save();
  ctx.fillStyle = PALETTE.density;
  for (const [c, n] of counts) {
    const i = Math.floor(c / mirror.grid), j = c % mirror.grid;
    ctx.globalAlpha = 0.08 + 0.5 * ((1 / n) / total) / maxShare;
    ctx.fillRect(L.sx(x0 + i * cw), L.sy(y0 + (j + 1) * ch), cw * L.scale, ch * L.scale);
  }
  ctx.globalAlpha = 1;
  ctx.strokeStyle = PALETTE.densityPick;
  ctx.lineWidth = L.px(2);
  ctx.strokeRect(L.sx(x0 + column * cw), L.sy(y0 + (row + 1) * ch), cw * L.scale, ch * L.scale);
  ctx.restore();
}

// What the cell and field records say so far (cells.js's CellMirror, one per run, fed by
// playback.js's RunModel): the cells of the hexagonal decomposition and of grid search, their
// verdicts, the regions of influence, the potential field and its local minima. The records'
// meanings are in cells.js's header.

import { EventKind } from '../run/events.js';
import { pointInPolygon } from './transform.js';

/** What the cell and field records say so far (one per run; RunModel.cells). */
export class CellMirror {
  constructor() {
    this.cells = new Map(); // id → {id, level, parent, x, y, label, radius, n, pts, done, state, why, from, terms, ...}
    this.split = new Set(); // ids of cells refined into children (a child's CELL has come)
    this.order = [];        // ids of complete cells, in arrival order
    this.orderCells = [];   // the same cells (drawn without a lookup each)
    // the same cells as a table, row k for orderCells[k]: what drawing a million small ones reads,
    // in typed arrays (one object each would be a cache miss each): box [x0, y0, x1, y1], drawing
    // level (0–3), label, state, and whether an axis-aligned rectangle
    this.table = { box: new Float64Array(0), level: new Int8Array(0), label: new Int8Array(0), state: new Int8Array(0), rect: new Uint8Array(0) };
    this.changed = [];      // ids whose verdict changed since the latest REGION, in order
    this.regions = [];      // [{attempt, x, y, radius, limit, inside, t}]
    this.field = [];        // the current field: [{id, x, y, v, a, b, dx, dy, half}]
    this.minima = [];       // [{escapes, x, y, u, dist, pull: [x, y], push: [x, y]}]
    this.index = null;      // cellAt's buckets of complete cells (bucketIndex)
    this.fieldVersion = 0;  // bumped by every FIELD and REGION: the layer is redrawn
    this.regionVersion = 0;
  }

  /** The robot's diagonal t from the latest REGION (0 when there is none). */
  get t() { return this.regions.length ? this.regions[this.regions.length - 1].t : 0; }
  /** The latest attempt (REGION id), or -1. */
  get attempt() { return this.regions.length ? this.regions[this.regions.length - 1].attempt : -1; }
  get empty() { return !this.cells.size && !this.field.length && !this.regions.length && !this.minima.length; }

  /** The record at offset `o` of `d` was revealed (kinds CELL to MINIMUM). */
  apply(d, o) {
    const id = d[o + 2];
    switch (d[o]) {
      case EventKind.CELL: {
        const n = d[o + 8] | 0;
        this.cells.set(id, { id, level: d[o + 1], parent: d[o + 3], x: d[o + 4], y: d[o + 5], label: d[o + 6],
          radius: d[o + 7], n, pts: [], done: false, state: -1, why: 0, from: -1, attempt: -1, terms: null, box: null, rect: false, k: -1 });
        if (d[o + 3] >= 0) this.split.add(d[o + 3]);
        return;
      }
      case EventKind.CELL_SHAPE: {
        const c = this.cells.get(id);
        if (!c || c.done) return;
        for (let j = 0; j < 4 && c.pts.length < 2 * c.n; j++) {
          const x = d[o + 4 + 2 * j], y = d[o + 5 + 2 * j];
          if (Number.isNaN(x) || Number.isNaN(y)) break;
          c.pts.push(x, y);
        }
        if (c.pts.length >= 2 * c.n && c.n >= 3) {
          c.done = true;
          let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
          for (let i = 0; i < c.pts.length; i += 2) {
            x0 = Math.min(x0, c.pts[i]); x1 = Math.max(x1, c.pts[i]);
            y0 = Math.min(y0, c.pts[i + 1]); y1 = Math.max(y1, c.pts[i + 1]);
          }
          c.box = [x0, y0, x1, y1];
          const p = c.pts; // an axis-aligned rectangle (grid search's cells): no polygon test for its pixels
          c.rect = c.n === 4 && ((p[0] === p[2] && p[4] === p[6] && p[1] === p[7] && p[3] === p[5])
            || (p[1] === p[3] && p[5] === p[7] && p[0] === p[6] && p[2] === p[4]));
          c.k = this.order.length;
          this.order.push(id);
          this.orderCells.push(c);
          this.tableRow(c);
        }
        return;
      }
      case EventKind.CELL_STATE: {
        const c = this.cells.get(id);
        if (!c) return;
        // A* and Dijkstra may find a step into an open or closed cell blocked from another cell:
        // the cell stays open (closed); the blocked step is in the explain panel's caption.
        if (d[o + 6] === 1 && (c.state === 0 || c.state === 2)) return;
        c.state = d[o + 6];
        if (c.k >= 0) this.table.state[c.k] = c.state;
        c.why = d[o + 7];
        c.from = d[o + 3];
        c.attempt = this.attempt;
        this.changed.push(id);
        return;
      }
      case EventKind.POTENTIAL: {
        const c = this.cells.get(id);
        if (!c) return;
        c.terms = { from: d[o + 3], repulsion: d[o + 6], trap: d[o + 7], goal: d[o + 8], total: d[o + 9],
          alpha: d[o + 10], chosen: d[o + 11] > 0, attempt: this.attempt };
        return;
      }
      case EventKind.REGION:
        // a new attempt: the search starts again from the start, its verdicts and field with it
        for (const k of this.changed) {
          const c = this.cells.get(k);
          if (c) c.state = -1;
          if (c?.k >= 0) this.table.state[c.k] = -1;
        }
        this.changed = [];
        this.field = [];
        this.regions.push({ attempt: id, x: d[o + 4], y: d[o + 5], radius: d[o + 6], limit: d[o + 7], inside: d[o + 8], t: d[o + 9] });
        this.fieldVersion++;
        this.regionVersion++;
        return;
      case EventKind.FIELD:
        this.field.push({ id, x: d[o + 4], y: d[o + 5], v: d[o + 6], a: d[o + 7], b: d[o + 8], dx: d[o + 9], dy: d[o + 10], half: d[o + 11] });
        this.fieldVersion++;
        return;
      case EventKind.MINIMUM:
        this.minima.push({ escapes: id, x: d[o + 4], y: d[o + 5], u: d[o + 6], dist: d[o + 7], pull: [d[o + 8], d[o + 9]], push: [d[o + 10], d[o + 11]] });
        return;
      default:
    }
  }

  /** Row c.k of the table: complete cell `c` (the arrays grow by doubling). */
  tableRow(c) {
    const t = this.table, k = c.k;
    if (k >= t.level.length) {
      const cap = Math.max(1024, 2 * t.level.length);
      const grow = (a, n) => { const b = new a.constructor(n); b.set(a); return b; };
      t.box = grow(t.box, 4 * cap);
      t.level = grow(t.level, cap); t.label = grow(t.label, cap); t.state = grow(t.state, cap); t.rect = grow(t.rect, cap);
    }
    t.box.set(c.box, 4 * k);
    t.level[k] = Math.min(3, Math.max(0, c.level | 0));
    t.label[k] = c.label;
    t.state[k] = c.state;
    t.rect[k] = c.rect ? 1 : 0;
  }

  /**
   * The complete cell holding (x, y): the latest made (a child comes after its parent), or null.
   * The cells are filed in buckets the size of the first cell (a hover over a million cells looks
   * at a handful, not at every one).
   */
  cellAt(x, y) {
    const ix = this.bucketIndex();
    if (!ix) return null;
    const list = ix.buckets.get(bucketKey(Math.floor((x - ix.ox) / ix.side), Math.floor((y - ix.oy) / ix.side))) ?? [];
    let best = null;
    for (const ks of [list, ix.big]) { // each in arrival order: the last that holds the point is the latest
      for (let n = ks.length - 1; n >= 0; n--) {
        const c = this.cells.get(this.order[ks[n]]);
        if (best && c.k < best.k) break;
        const [x0, y0, x1, y1] = c.box;
        if (x < x0 || x > x1 || y < y0 || y > y1 || !pointInPolygon(x, y, c.pts)) continue;
        best = c;
        break;
      }
    }
    return best;
  }

  /** The bucket index over the complete cells, brought up to date (null before the first cell). */
  bucketIndex() {
    if (!this.order.length) return null;
    if (!this.index) {
      const [x0, y0, x1, y1] = this.cells.get(this.order[0]).box;
      this.index = { ox: x0, oy: y0, side: Math.max(x1 - x0, y1 - y0) || 1, buckets: new Map(), big: [], filed: 0 };
    }
    const ix = this.index;
    for (; ix.filed < this.order.length; ix.filed++) {
      const [x0, y0, x1, y1] = this.cells.get(this.order[ix.filed]).box;
      const i0 = Math.floor((x0 - ix.ox) / ix.side), i1 = Math.floor((x1 - ix.ox) / ix.side);
      const j0 = Math.floor((y0 - ix.oy) / ix.side), j1 = Math.floor((y1 - ix.oy) / ix.side);
      if (!((i1 - i0 + 1) * (j1 - j0 + 1) <= 64)) { ix.big.push(ix.filed); continue; } // far larger than the first: looked at always
      for (let j = j0; j <= j1; j++) {
        for (let i = i0; i <= i1; i++) {
          const key = bucketKey(i, j);
          const list = ix.buckets.get(key);
          if (list) list.push(ix.filed); else ix.buckets.set(key, [ix.filed]);
        }
      }
    }
    return ix;
  }

  /** The field sample nearest (x, y) whose tile holds it, or null. */
  sampleAt(x, y) {
    let best = null, bd = Infinity;
    for (const s of this.field) {
      const dd = (s.x - x) ** 2 + (s.y - y) ** 2;
      if (dd < bd && Math.abs(s.x - x) <= s.half * 1.01 && Math.abs(s.y - y) <= s.half * 1.01) { best = s; bd = dd; }
    }
    return best;
  }
}

/** A bucket's key in CellMirror's index. */
const bucketKey = (i, j) => `${i},${j}`;

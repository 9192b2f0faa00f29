// Event playback: batches from the worker are queued, then revealed at the page's pace
// (PathFinding.js style: pausing is playback-only, the records stay). Revealed records are kept in
// a chunked store (RecordStore), so the view can redraw everything from them after a resize.
//
// Every revealed record also goes through a RunModel: what the records say so far, kept so the
// views need not re-read the whole log: a mirror of each tree (node points and parents: a REWIRE
// moves a node's edge, so the tree layer is redrawn from the mirror, not from the records), the
// dynamic-domain radius and exhausted flag of each node, the best solution's node with the cost or
// coverage series, and the inspection points seen; and the cells and potential fields of the
// hex-potential and potential-field planners (cell-mirror.js CellMirror).

import { EventKind, STRIDE } from './events.js';
import { CellMirror } from '../draw/cell-mirror.js';
import { DensityMirror } from '../draw/density.js';
import { REVEAL_PER_FRAME, STORE_CHUNK_RECORDS } from './limits.js';
import { Pace, StepScanner } from './pace.js';

/**
 * The revealed records, in chunks of STORE_CHUNK_RECORDS (limits.js): growing adds a chunk and
 * never copies what is held (a doubling array froze the page for seconds per doubling past a few
 * million records). Read them with spans(from, to).
 */
export class RecordStore {
  constructor(chunkRecords = STORE_CHUNK_RECORDS) {
    this.chunkRecords = chunkRecords;
    this.chunkSize = chunkRecords * STRIDE; // numbers per chunk
    this.chunks = [];
    this.length = 0; // records
  }

  /** Forget the records; the first chunk is kept for the next run, the rest are let go. */
  clear() {
    this.length = 0;
    this.chunks.length = Math.min(this.chunks.length, 1);
  }

  append(src, from, count) {
    let at = this.length * STRIDE;
    let s = from * STRIDE;
    const end = (from + count) * STRIDE;
    while (s < end) {
      const c = Math.floor(at / this.chunkSize);
      if (c === this.chunks.length) this.chunks.push(new Float64Array(this.chunkSize));
      const o = at - c * this.chunkSize;
      const n = Math.min(end - s, this.chunkSize - o);
      this.chunks[c].set(src.subarray(s, s + n), o);
      s += n;
      at += n;
    }
    this.length += count;
  }

  /**
   * Records [from, to) as spans [data, start, end]: offsets into one chunk's numbers, a record
   * every STRIDE numbers (for (const [d, o0, o1] of store.spans(a, b)) for (let o = o0; o < o1; o += STRIDE) …).
   */
  *spans(from, to) {
    const hi = Math.min(to, this.length);
    for (let r = Math.max(0, from); r < hi;) {
      const c = Math.floor(r / this.chunkRecords);
      const first = r - c * this.chunkRecords;
      const last = Math.min(this.chunkRecords, hi - c * this.chunkRecords);
      yield [this.chunks[c], first * STRIDE, last * STRIDE];
      r = c * this.chunkRecords + last;
    }
  }

  /** Record `i`'s numbers (a view, no copy). */
  record(i) {
    const c = Math.floor(i / this.chunkRecords);
    const o = (i - c * this.chunkRecords) * STRIDE;
    return this.chunks[c].subarray(o, o + STRIDE);
  }

  /** Bytes held. */
  get bytes() { return this.chunks.length * this.chunkSize * 8; }
}

const KNOWN = 1;     // the node's point is known
const EXHAUSTED = 2; // the node is exhausted

/** One tree as the records describe it: per node id, its point (x, y; c0, c1) and parent. */
export class TreeMirror {
  constructor() {
    this.n = 0; // ids 0..n-1 have a slot (some may be unknown)
    this.alloc(256);
    this.domains = 0;   // nodes with a finite dynamic-domain radius
    this.exhausted = 0; // exhausted nodes
  }

  alloc(cap) {
    const grow = (Type, old, fill) => {
      const a = new Type(cap);
      if (fill !== undefined) a.fill(fill);
      if (old) a.set(old.subarray(0, this.n));
      return a;
    };
    this.x = grow(Float64Array, this.x);
    this.y = grow(Float64Array, this.y);
    this.c0 = grow(Float64Array, this.c0);
    this.c1 = grow(Float64Array, this.c1);
    this.parent = grow(Int32Array, this.parent, -1);
    this.radius = grow(Float64Array, this.radius, Infinity);
    this.flags = grow(Uint8Array, this.flags);
    this.cap = cap;
  }

  /** Make room for node `id`. */
  slot(id) {
    if (id >= this.cap) {
      let cap = this.cap;
      while (cap <= id) cap *= 2;
      this.alloc(cap);
    }
    if (id >= this.n) this.n = id + 1;
  }

  known(id) { return id >= 0 && id < this.n && (this.flags[id] & KNOWN) !== 0; }
  isExhausted(id) { return (this.flags[id] & EXHAUSTED) !== 0; }

  /** Set node `id`'s point (and its parent, unless `parent` is undefined). */
  place(id, x, y, c0, c1, parent) {
    if (!(id >= 0)) return;
    this.slot(id);
    this.x[id] = x; this.y[id] = y; this.c0[id] = c0; this.c1[id] = c1;
    this.flags[id] |= KNOWN;
    if (parent !== undefined) this.parent[id] = parent;
  }

  /** Place node `id` at (x, y) only if nothing better is known (events that carry no c0, c1). */
  placeIfUnknown(id, x, y, c0 = 0, c1 = 0) {
    if (!(id >= 0)) return;
    this.slot(id);
    if (!(this.flags[id] & KNOWN)) this.place(id, x, y, c0, c1);
  }

  /** Node ids from the root to `id` (following the mirror's parents), or [] when `id` is unknown. */
  branch(id) {
    const out = [];
    let i = id;
    for (let guard = 0; this.known(i) && guard <= this.n; guard++) {
      out.push(i);
      i = this.parent[i];
    }
    return out.reverse();
  }
}

export class RunModel {
  constructor() { this.clear(); }

  clear() {
    this.trees = [];
    this.best = null;      // {tree, id, kind}: the latest COST or COVERAGE node
    this.costs = [];       // [iteration, cost] per COST event
    this.coverage = [];    // [iteration, fraction, points seen] per COVERAGE event
    this.informed = [];    // the informed set's ellipses, oldest first: [cx, cy, a, b, ux, uy, cost] per INFORMED event
    this.seen = new Set(); // inspection point numbers seen
    this.counts = new Float64Array(32); // records per kind
    this.cells = new CellMirror(); // cells, verdicts, regions, fields, minima
    this.density = new DensityMirror(); // EST's density grid (after its first SELECT)
    this.treeVersion = 0;     // bumped when an edge moves (REWIRE): the tree layer is redrawn
    this.domainVersion = 0;   // bumped when a radius changes
  }

  tree(t) {
    const i = t > 0 ? t | 0 : 0;
    while (this.trees.length <= i) this.trees.push(new TreeMirror());
    return this.trees[i];
  }

  /** The record at offset `o` of `d` was revealed. */
  apply(d, o) {
    const kind = d[o];
    if (kind >= 0 && kind < this.counts.length) this.counts[kind]++;
    switch (kind) {
      case EventKind.NODE_ADDED: {
        if (!this.density.empty) this.density.apply(d, o);
        const t = this.tree(d[o + 1]);
        const parent = d[o + 3];
        // the root has no record of its own: its first child's record says where it is
        if (parent >= 0) t.placeIfUnknown(parent, d[o + 6], d[o + 7], d[o + 10], d[o + 11]);
        t.place(d[o + 2], d[o + 4], d[o + 5], d[o + 8], d[o + 9], parent >= 0 ? parent : -1);
        return;
      }
      case EventKind.REWIRE: {
        const t = this.tree(d[o + 1]);
        const id = d[o + 2], parent = d[o + 3];
        t.placeIfUnknown(id, d[o + 4], d[o + 5], d[o + 8], d[o + 9]);
        t.placeIfUnknown(parent, d[o + 6], d[o + 7], d[o + 10], d[o + 11]);
        if (id >= 0 && parent >= 0 && parent !== id) t.parent[id] = parent;
        this.treeVersion++;
        return;
      }
      case EventKind.DOMAIN: {
        const t = this.tree(d[o + 1]);
        const id = d[o + 2];
        if (!(id >= 0)) return;
        t.placeIfUnknown(id, d[o + 4], d[o + 5]);
        const before = Number.isFinite(t.radius[id]) && t.radius[id] > 0;
        const r = d[o + 6];
        t.radius[id] = Number.isFinite(r) && r > 0 ? r : Infinity;
        t.domains += (Number.isFinite(t.radius[id]) ? 1 : 0) - (before ? 1 : 0);
        this.domainVersion++;
        return;
      }
      case EventKind.EXHAUSTED: {
        const t = this.tree(d[o + 1]);
        const id = d[o + 2];
        if (!(id >= 0)) return;
        t.placeIfUnknown(id, d[o + 4], d[o + 5]);
        if (!t.isExhausted(id)) { t.flags[id] |= EXHAUSTED; t.exhausted++; }
        return;
      }
      case EventKind.COST:
        this.tree(d[o + 1]).placeIfUnknown(d[o + 2], d[o + 4], d[o + 5]);
        this.best = { tree: d[o + 1] > 0 ? d[o + 1] | 0 : 0, id: d[o + 2], kind: 'cost' };
        this.costs.push([d[o + 3], d[o + 6]]);
        return;
      case EventKind.COVERAGE:
        this.tree(d[o + 1]).placeIfUnknown(d[o + 2], d[o + 4], d[o + 5]);
        this.best = { tree: d[o + 1] > 0 ? d[o + 1] | 0 : 0, id: d[o + 2], kind: 'coverage' };
        this.coverage.push([d[o + 3], d[o + 6], d[o + 7]]);
        return;
      case EventKind.POINT_SEEN:
        this.seen.add(d[o + 2]);
        return;
      case EventKind.INFORMED:
        this.informed.push([d[o + 4], d[o + 5], d[o + 6], d[o + 7], d[o + 8], d[o + 9], d[o + 10]]);
        return;
      case EventKind.SELECT:
        this.tree(d[o + 1]).placeIfUnknown(d[o + 2], d[o + 4], d[o + 5]);
        this.density.apply(d, o);
        return;
      case EventKind.CELL: case EventKind.CELL_SHAPE: case EventKind.CELL_STATE: case EventKind.POTENTIAL:
      case EventKind.REGION: case EventKind.FIELD: case EventKind.MINIMUM:
        this.cells.apply(d, o);
        return;
      default:
    }
  }

  /** The latest best cost, or null. */
  get bestCost() { return this.costs.length ? this.costs[this.costs.length - 1][1] : null; }
  /** The latest coverage {fraction, seen}, or null. */
  get bestCoverage() {
    if (!this.coverage.length) return null;
    const [, fraction, seen] = this.coverage[this.coverage.length - 1];
    return { fraction, seen };
  }

  /** The best branch, root first, as workspace points [[x, y], ...] (empty when there is none). */
  bestBranch() {
    if (!this.best) return [];
    const t = this.trees[this.best.tree];
    if (!t) return [];
    return t.branch(this.best.id).map((i) => [t.x[i], t.y[i]]);
  }
}

export class Playback {
  constructor() {
    this.store = new RecordStore();
    this.model = new RunModel();
    this.scanner = new StepScanner(); // which pushed records start a step (pace.js)
    this.pace = new Pace();
    this.clear();
  }

  clear() {
    this.store.clear();
    this.model.clear();
    this.scanner.clear();
    this.pace.clear();
    this.queue = [];        // [{data: Float64Array, starts: Uint8Array, next: record index}]
    this.pending = 0;       // records queued, not yet revealed
    this.pendingSteps = 0;  // steps queued (a run of set-up records is one: pace.js)
    this.steps = 0;         // steps revealed
    this.nodeCount = 0;     // NODE_ADDED records revealed
  }

  push(data) {
    const n = Math.floor(data.length / STRIDE);
    if (n === 0) return;
    const { starts, steps } = this.scanner.scan(data, STRIDE);
    this.queue.push({ data, starts, next: 0 });
    this.pending += n;
    this.pendingSteps += steps;
  }

  /**
   * Reveal up to `records` records, stopping before the step after `steps` more steps (records
   * that continue the step being shown come first, free); returns [from, to) as record indices
   * into the store.
   */
  revealUpTo(records, steps) {
    const from = this.store.length;
    let left = Math.min(records, this.pending);
    let taken = 0;
    while (left > 0) {
      const chunk = this.queue[0];
      const size = chunk.data.length / STRIDE;
      let end = chunk.next;
      const last = Math.min(size, chunk.next + left);
      for (; end < last; end++) {
        if (chunk.starts[end]) {
          if (taken === steps) break;
          taken++;
        }
        const o = end * STRIDE;
        if (chunk.data[o] === EventKind.NODE_ADDED) this.nodeCount++;
        this.model.apply(chunk.data, o);
      }
      const take = end - chunk.next;
      this.store.append(chunk.data, chunk.next, take);
      chunk.next = end;
      left -= take;
      this.pending -= take;
      if (chunk.next >= size) this.queue.shift();
      else if (take === 0 || end < last) break; // the next step is not owed
    }
    this.steps += taken;
    this.pendingSteps -= taken;
    return [from, this.store.length];
  }

  /** Reveal up to `n` records; returns [from, to) as record indices into the store. */
  reveal(n) { return this.revealUpTo(n, Infinity); }

  /** Reveal the next `n` steps (a run of set-up records is one step). */
  revealSteps(n) { return this.revealUpTo(Infinity, n); }

  /** Reveal the records that continue the step last shown (a set-up run still arriving). */
  revealContinuation() { return this.revealUpTo(Infinity, 0); }

  /** Whether the next queued record continues the step last shown. */
  get continues() {
    const q = this.queue[0];
    return !!q && !q.starts[q.next];
  }

  revealAll() { return this.reveal(this.pending); }

  /** Bytes the page holds for the run: {records, trees, queued} (typed arrays, by capacity). */
  bytes() {
    const perNode = 4 * 8 + 4 + 8 + 1; // x, y, c0, c1, parent, radius, flags
    return {
      records: this.store.bytes,
      trees: this.model.trees.reduce((s, t) => s + t.cap * perNode, 0),
      queued: this.queue.reduce((s, q) => s + q.data.byteLength + q.starts.byteLength, 0),
    };
  }

  /**
   * Reveal what the pace owes after `dt` seconds when the whole run should take `duration`
   * seconds (0: everything queued), at most `cap` and REVEAL_PER_FRAME (limits.js) records in one
   * call: the page calls it once a frame.
   */
  tick(duration, dt, cap = REVEAL_PER_FRAME) {
    const n = this.pace.owe(this.pendingSteps, duration, dt);
    return this.revealUpTo(Math.min(cap, REVEAL_PER_FRAME), n);
  }

  /** The pacing plan so far, for tests and the console (window.planarium.pace()). */
  plan() {
    const p = this.pace;
    return {
      duration: p.duration, clock: p.clock, frames: p.frames, lastSteps: p.lastSteps,
      steps: this.steps, pendingSteps: this.pendingSteps, records: this.store.length, pending: this.pending,
    };
  }
}

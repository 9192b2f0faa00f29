// Event playback: batches from the worker are queued, then revealed at the page's pace
// (PathFinding.js style: pausing is playback-only, the records stay). Revealed records are kept in
// one growable Float64Array, so the view can redraw everything from them after a resize.

import { EventKind, STRIDE } from './events.js';

export class RecordStore {
  constructor() {
    this.data = new Float64Array(STRIDE * 4096);
    this.length = 0; // records
  }

  clear() { this.length = 0; }

  append(src, from, count) {
    const need = (this.length + count) * STRIDE;
    if (need > this.data.length) {
      let size = this.data.length;
      while (size < need) size *= 2;
      const next = new Float64Array(size);
      next.set(this.data.subarray(0, this.length * STRIDE));
      this.data = next;
    }
    this.data.set(src.subarray(from * STRIDE, (from + count) * STRIDE), this.length * STRIDE);
    this.length += count;
  }
}

export class Playback {
  constructor() {
    this.store = new RecordStore();
    this.queue = [];        // [{data: Float64Array, next: record index}]
    this.pending = 0;       // records queued, not yet revealed
    this.nodeCount = 0;     // NODE_ADDED records revealed
    this.budget = 0;        // fractional records owed by the rate
  }

  clear() {
    this.store.clear();
    this.queue = [];
    this.pending = 0;
    this.nodeCount = 0;
    this.budget = 0;
  }

  push(data) {
    const n = Math.floor(data.length / STRIDE);
    if (n === 0) return;
    this.queue.push({ data, next: 0 });
    this.pending += n;
  }

  /** Reveal up to `n` records; returns [from, to) as record indices into the store. */
  reveal(n) {
    const from = this.store.length;
    let left = Math.min(n, this.pending);
    while (left > 0) {
      const chunk = this.queue[0];
      const size = chunk.data.length / STRIDE;
      const take = Math.min(left, size - chunk.next);
      this.store.append(chunk.data, chunk.next, take);
      for (let i = chunk.next; i < chunk.next + take; i++) {
        if (chunk.data[i * STRIDE] === EventKind.NODE_ADDED) this.nodeCount++;
      }
      chunk.next += take;
      left -= take;
      this.pending -= take;
      if (chunk.next >= size) this.queue.shift();
    }
    return [from, this.store.length];
  }

  revealAll() { return this.reveal(this.pending); }

  /** Reveal what `rate` records per second owes after `dt` seconds (Infinity: everything). */
  tick(rate, dt) {
    if (!Number.isFinite(rate)) { this.budget = 0; return this.revealAll(); }
    this.budget = Math.min(this.budget + rate * dt, Math.max(1, rate)); // no burst after a stall
    const n = Math.floor(this.budget);
    this.budget -= n;
    return this.reveal(n);
  }
}

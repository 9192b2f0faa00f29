// The full states of a growth step's records, for the explain panel of a robot with more than the
// two coordinates a record carries (a spatial arm's six joints): the worker sends, with each events
// batch, the core's state log (`Run.drain_states`: [dims, then per record of the kinds below, in
// order: kind, extra, q…, pq…]; src/events.rs, StateLog). Every record of those kinds has exactly
// one entry, in order, and the worker's thinning drops only SAMPLE_TRY records, so the k-th entry
// belongs to the k-th such record the page reveals: entries are matched to records as they are
// revealed, and each entry's kind is checked against its record's.
//
// Bounded: the entries not yet revealed wait with their batches (as the records do), and of those
// revealed only the last KEEP are kept, each copied out of its batch (about 250 bytes for six joints) (a step's records are the last few: the panel reads a long
// reveal from its last step only, run/explain.js).

import { EventKind as K } from './events.js';

/** The kinds with an entry (EventLog::STATE_KINDS in src/events.rs). */
export const STATE_KINDS = new Set([K.SAMPLE, K.SAMPLE_REJECTED, K.NEAREST, K.STEER, K.COLLISION, K.NODE_ADDED, K.TREES_CONNECTED]);

/** Revealed entries kept. */
export const KEEP = 4096;

/**
 * @typedef {{q: Float64Array, pq: Float64Array, extra: number}} StateEntry
 */

export class StateMirror {
  constructor(keep = KEEP) {
    this.keep = keep;
    this.clear();
  }

  clear() {
    this.queue = [];        // [{data, at}]: batches not fully matched, `at` the next entry's offset
    this.byRecord = new Map(); // record index → StateEntry (the last `keep` revealed)
    this.matched = 0;       // records looked at so far (records [0, matched) are matched)
    this.mismatches = 0;    // entries whose kind was not their record's (the log was dropped from then on)
  }

  /** A batch's state log (`Run.drain_states`), or nothing. */
  push(flat) {
    if (!flat || flat.length < 1) return;
    const dims = flat[0] | 0;
    if (dims < 1 || dims > 64) return;
    this.queue.push({ data: flat, at: 1, dims });
  }

  /** Match the entries to records [from, to) of `store` (revealed in order; each record once). */
  assign(store, from, to) {
    // A batch's entries arrive with its records, before they are revealed: none queued, none due.
    if (!this.queue.length) { this.matched = Math.max(this.matched, to); return; }
    for (let i = Math.max(from, this.matched); i < to; i++) {
      const kind = store.record(i)[0];
      if (!STATE_KINDS.has(kind)) continue;
      const e = this.next();
      if (!e) continue;
      if (e.kind !== kind) { this.mismatches++; this.queue = []; continue; }
      this.byRecord.set(i, e.entry);
      if (this.byRecord.size > this.keep) this.byRecord.delete(this.byRecord.keys().next().value);
    }
    this.matched = Math.max(this.matched, to);
  }

  next() {
    while (this.queue.length) {
      const b = this.queue[0];
      const stride = 2 + 2 * b.dims;
      if (b.at + stride > b.data.length) { this.queue.shift(); continue; }
      const o = b.at;
      b.at += stride;
      const d = b.data;
      return {
        kind: d[o],
        // copies (not views), so that an entry kept does not keep its whole batch alive
        entry: { q: d.slice(o + 2, o + 2 + b.dims), pq: d.slice(o + 2 + b.dims, o + stride), extra: d[o + 1] },
      };
    }
    return null;
  }

  /** Record `i`'s states, if kept. @returns {StateEntry | undefined} */
  get(i) {
    return this.byRecord.get(i);
  }
}

// Thinning the sampler's raw tries before they leave the worker. A validity-checking sampler
// (bridge, gaussian, obstacle) can draw millions of states a second; every one is a SAMPLE_TRY
// record, and the page keeps every record it is sent. So each run's first TRY_KEEP tries are sent
// in full, then one in 2, 4, 8, … as their count doubles (try number k of the run is kept when k is
// a multiple of the smallest power of two p with p·TRY_KEEP > k): the page still sees tries all
// over the run, about TRY_KEEP more for every doubling. Other records are never touched.

import { EventKind, STRIDE } from '../run/events.js';

export const TRY_KEEP = 50000;

/** `data` with its raw tries thinned; `counter` {seen, sent} counts the run's tries (updated). */
export function thinTries(data, counter, keep = TRY_KEEP) {
  const n = data.length / STRIDE;
  let count = 0;
  for (let i = 0; i < n; i++) if (data[i * STRIDE] === EventKind.SAMPLE_TRY) count++;
  if (count === 0) return data;
  if (counter.seen + count <= keep) {
    counter.seen += count;
    counter.sent += count;
    return data;
  }
  const out = new Float64Array(data.length);
  let w = 0;
  for (let i = 0; i < n; i++) {
    const o = i * STRIDE;
    if (data[o] === EventKind.SAMPLE_TRY) {
      const k = counter.seen++;
      let stride = 1;
      while (stride * keep <= k) stride *= 2;
      if (k % stride !== 0) continue;
      counter.sent++;
    }
    out.set(data.subarray(o, o + STRIDE), w);
    w += STRIDE;
  }
  return out.slice(0, w);
}

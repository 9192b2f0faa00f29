// The page's record store (playback.js RecordStore) grows by chunks, never by copying what it
// holds (issue 13, reproduction 7: the doubling array froze the page for 8.5 s per doubling at
// millions of records): records read back the same across chunk seams, and appending 3 million
// records keeps every earlier chunk where it was. Prints the longest single append (not asserted).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { RecordStore } from '../../www/run/playback.js';
import { STRIDE } from '../../www/run/events.js';

const batch = (from, n) => {
  const d = new Float64Array(n * STRIDE);
  for (let i = 0; i < n; i++) d.fill(from + i, i * STRIDE, (i + 1) * STRIDE);
  return d;
};

test('records cross chunk seams intact; spans cover exactly [from, to)', () => {
  const s = new RecordStore(7);
  let n = 0;
  for (const size of [3, 5, 7, 1, 13, 2]) { s.append(batch(n, size), 0, size); n += size; }
  s.append(batch(n, 10), 4, 3); // part of a batch: records n+4 .. n+6
  assert.equal(s.length, n + 3);
  const seen = [];
  for (const [d, o0, o1] of s.spans(5, s.length)) for (let o = o0; o < o1; o += STRIDE) seen.push(d[o]);
  assert.deepEqual(seen, [...Array.from({ length: n - 5 }, (_, i) => i + 5), n + 4, n + 5, n + 6]);
  assert.equal(s.record(9)[STRIDE - 1], 9);
  s.clear();
  assert.equal(s.length, 0);
  assert.deepEqual([...s.spans(0, 10)], []);
});

test('3 million records: earlier chunks are never copied', () => {
  const s = new RecordStore();
  const b = batch(0, 4096);
  s.append(b, 0, 4096);
  const first = s.chunks[0];
  let worst = 0;
  for (let i = 0; i < 3e6 / 4096; i++) {
    const t = performance.now();
    s.append(b, 0, 4096);
    worst = Math.max(worst, performance.now() - t);
  }
  assert.equal(s.chunks[0], first, 'the first chunk is the same array');
  assert.ok(s.length > 3e6);
  console.log(`# ${s.length} records in ${s.chunks.length} chunks (${(s.bytes / 2 ** 20).toFixed(0)} MiB); longest append ${worst.toFixed(1)} ms`);
  // the longest append is printed, not asserted: on a shared 2-core machine a GC pause lands anywhere
});

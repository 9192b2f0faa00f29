// The 3-D path panel's pure parts (www/ui/path3d.js), in Node: the frames' states and lengths read
// from `Run.path_frames`' layout (each frame's outline skipped), and the ghost spacing's bounds.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseStates, readSpacing, GHOSTS } from '../../www/ui/path3d.js';

test('parseStates reads each frame\'s state past its outline and sums the joint-space distance', () => {
  // dims 2, 3 frames; outlines: none, one triangle, two polygons (a point and a segment)
  const frames = Float64Array.from([
    2, 3,
    0, 0, 0,
    3, 4, 1, 3, 9, 9, 8, 8, 7, 7,
    3, 4, 2, 1, 5, 5, 2, 6, 6, 4, 4,
  ]);
  const p = parseStates(frames);
  assert.equal(p.dims, 2);
  assert.deepEqual(Array.from(p.states), [0, 0, 3, 4, 3, 4]);
  assert.deepEqual(Array.from(p.s), [0, 5, 5]);
  assert.equal(parseStates(new Float64Array(0)), null);
  assert.equal(parseStates(Float64Array.from([2, 0])), null);
  // a truncated array keeps the frames it holds
  assert.deepEqual(Array.from(parseStates(Float64Array.from([2, 3, 0, 0, 0, 3, 4])).states), [0, 0, 3, 4]);
});

test('readSpacing: 0 or within the bounds; anything else refused, naming the field and the bounds', () => {
  assert.deepEqual(readSpacing('0'), { value: 0 });
  assert.deepEqual(readSpacing(' 0.5 '), { value: 0.5 });
  assert.deepEqual(readSpacing(String(GHOSTS.max)), { value: GHOSTS.max });
  assert.deepEqual(readSpacing(String(GHOSTS.min)), { value: GHOSTS.min });
  for (const [text, why] of [['', /type a number/], ['abc', /"abc" is not a number/], ['NaN', /not a number/], ['Infinity', /not a number/],
    ['-0.5', /below 0/], ['1e300', /above 10/], ['0.01', /below 0\.05/]]) {
    const r = readSpacing(text);
    assert.ok('error' in r, `"${text}" refused`);
    assert.match(r.error, /^Ghost spacing: /);
    assert.match(r.error, why);
    assert.match(r.error, /0 \(no ghosts\) or from 0\.05 to 10 rad/);
  }
  assert.ok(readSpacing('x'.repeat(1000)).error.length < 200, 'a long text is not echoed whole');
});

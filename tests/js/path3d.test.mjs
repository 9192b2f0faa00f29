// The 3-D path panel's pure parts (www/ui/path3d.js), in Node: the frames' states read from
// `Run.path_frames`' layout (each frame's outline skipped) with the core's lengths (`Run.path_lengths`),
// and the ghost spacing's bounds.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseStates } from '../../www/ui/path3d.js';
import { readSpacing, GHOSTS } from '../../www/ui/ghost-spacing.js';

test('parseStates reads each frame\'s state past its outline, and takes the lengths from the core\'s array', () => {
  // dims 2, 3 frames; outlines: none, one triangle, two polygons (a point and a segment)
  const frames = Float64Array.from([
    2, 3,
    0, 0, 0,
    3, 4, 1, 3, 9, 9, 8, 8, 7, 7,
    3, 4, 2, 1, 5, 5, 2, 6, 6, 4, 4,
  ]);
  // the core's lengths ([frames, s…, waypoints, w…]): not what the states' distances would sum to,
  // so a page that summed them would be caught
  const lengths = Float64Array.from([3, 0, 2.5, 7, 2, 0, 7]);
  const p = parseStates(frames, lengths);
  assert.equal(p.dims, 2);
  assert.deepEqual(Array.from(p.states), [0, 0, 3, 4, 3, 4]);
  assert.deepEqual(Array.from(p.s), [0, 2.5, 7], 'the core\'s lengths, not the page\'s sums (0, 5, 5)');
  assert.deepEqual(p.waypoints, [0, 7]);
  assert.equal(parseStates(new Float64Array(0), lengths), null);
  assert.equal(parseStates(Float64Array.from([2, 0]), lengths), null);
  // lengths that do not belong to these frames: refused
  assert.equal(parseStates(frames, undefined), null, 'no lengths');
  assert.equal(parseStates(frames, Float64Array.from([2, 0, 7, 2, 0, 7])), null, 'another frame count');
  assert.equal(parseStates(frames, Float64Array.from([3, 0, 2.5, 7, 3, 0, 7])), null, 'a waypoint count the array does not hold');
  assert.equal(parseStates(frames, Float64Array.from([3, 0, 8, 7, 2, 0, 7])), null, 'a length going back');
  assert.equal(parseStates(frames, Float64Array.from([3, 0, NaN, 7, 2, 0, 7])), null, 'a length not a number');
  // a truncated frame array keeps the frames it holds (and needs lengths for those)
  assert.deepEqual(Array.from(parseStates(Float64Array.from([2, 3, 0, 0, 0, 3, 4]), Float64Array.from([2, 0, 5, 2, 0, 5])).states), [0, 0, 3, 4]);
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

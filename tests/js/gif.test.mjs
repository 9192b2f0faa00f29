// www/ui/gif.js in Node: frames encoded, then decoded by an independent decoder (gif-decode.mjs):
// size, palette, loop, delays and every pixel's index come back; the palette keeps fixed colours
// exact; odd inputs give errors that name what.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { encodeGif, buildPalette, indexPixels, GifWriter, hexRgb } from '../../www/ui/gif.js';
import { decodeGif } from './gif-decode.mjs';

/** Deterministic pseudo-random bytes. */
function rand(seed) {
  let s = seed >>> 0;
  return () => { s = (s * 1664525 + 1013904223) >>> 0; return s >>> 24; };
}

test('LZW round trip: noisy, flat and long frames, every palette size', () => {
  const r = rand(7);
  for (const colours of [2, 3, 4, 16, 200, 256]) {
    const w = 97, h = 61;
    const palette = Uint8Array.from({ length: colours * 3 }, () => r());
    const noisy = Uint8Array.from({ length: w * h }, () => r() % colours);
    const flat = new Uint8Array(w * h).fill(colours - 1);
    const stripes = Uint8Array.from({ length: w * h }, (_, i) => (i >> 5) % colours); // long runs: the table fills and clears
    const gif = encodeGif({ width: w, height: h, palette, frames: [{ indices: noisy, delay: 7 }, { indices: flat, delay: 10 }, { indices: stripes }] });
    const d = decodeGif(gif);
    assert.equal(d.version, 'GIF89a');
    assert.equal(d.width, w);
    assert.equal(d.height, h);
    assert.equal(d.loop, 0, 'loops forever');
    assert.deepEqual(d.frames.map((f) => f.delay), [7, 10, 10]);
    assert.deepEqual(d.frames.map((f) => [f.left, f.top, f.width, f.height]), [[0, 0, w, h], [0, 0, w, h], [0, 0, w, h]]);
    assert.deepEqual([...d.frames[0].indices], [...noisy], `noisy frame, ${colours} colours`);
    assert.deepEqual([...d.frames[1].indices], [...flat]);
    assert.deepEqual([...d.frames[2].indices], [...stripes]);
    assert.deepEqual([...d.palette.subarray(0, colours * 3)], [...palette]);
  }
  // a big frame with little noise: thousands of table resets
  const big = Uint8Array.from({ length: 640 * 480 }, (_, i) => (i % 640 < 320 ? (i >> 3) & 255 : rand(i)() ));
  const d = decodeGif(encodeGif({ width: 640, height: 480, palette: new Uint8Array(768), frames: [{ indices: big }] }));
  assert.deepEqual(d.frames[0].indices, big);
});

test('the palette keeps fixed colours exact; pixels map to the nearest colour', () => {
  const fixed = ['#eef0f3', '#8c510a', '#1f4e9a'].map(hexRgb);
  const w = 50, h = 20;
  const rgba = new Uint8Array(w * h * 4);
  const r = rand(3);
  for (let i = 0; i < w * h; i++) {
    const c = i < 400 ? fixed[i % 3] : [r(), r(), r()];
    rgba.set([...c, 255], 4 * i);
  }
  const pal = buildPalette(rgba, fixed, 256);
  assert.ok(pal.length / 3 <= 256);
  assert.deepEqual([...pal.subarray(0, 9)], fixed.flat(), 'fixed colours first, exact');
  const idx = indexPixels(rgba, pal);
  for (let i = 0; i < 400; i++) assert.equal(idx[i], i % 3);
  // every other pixel maps to a colour no farther than any palette colour
  for (let i = 400; i < w * h; i += 37) {
    const px = rgba.subarray(4 * i, 4 * i + 3);
    const d = (c) => (pal[3 * c] - px[0]) ** 2 + (pal[3 * c + 1] - px[1]) ** 2 + (pal[3 * c + 2] - px[2]) ** 2;
    for (let c = 0; c < pal.length / 3; c++) assert.ok(d(idx[i]) <= d(c));
  }
  assert.equal(hexRgb('rgba(1, 2, 3, 0.5)'), null);
});

test('GifWriter: frames as they come, one palette; errors name what', () => {
  const w = 8, h = 4;
  const frame = (c) => ({ width: w, height: h, data: Uint8Array.from({ length: w * h * 4 }, (_, i) => (i % 4 === 3 ? 255 : c)) });
  const g = new GifWriter(w, h, [[0, 0, 0], [255, 255, 255]]);
  g.add(frame(0), 5);
  g.add(frame(255), 5);
  g.add(frame(250), 5); // near white
  const d = decodeGif(g.finish());
  assert.equal(d.frames.length, 3);
  assert.deepEqual(d.frames.map((f) => f.indices[0]), [0, 1, 1]);
  assert.throws(() => g.add({ width: 9, height: 4, data: new Uint8Array(144) }), /9 × 4 frame/);
  assert.throws(() => new GifWriter(2, 2).finish(), /no frames/);
  assert.throws(() => encodeGif({ width: 0, height: 5, palette: new Uint8Array(6), frames: [] }), /size 0 × 5/);
  assert.throws(() => encodeGif({ width: 2, height: 2, palette: new Uint8Array(6), frames: [{ indices: new Uint8Array(3) }] }), /frame 1 has 3 pixels/);
});

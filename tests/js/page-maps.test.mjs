// Occupancy maps in the page (issue 17): a map_server YAML and its PGM chosen together in "Open
// file…" are decoded by the core in the worker, drawn (obstacle-coloured pixels where the image is
// occupied, none where it is free), and grid-search (the map's default planner) solves it; a YAML
// alone says which image it needs; a PNG alone opens as a plain image. Screenshot: target/page-maps.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, ROOT as root, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, waitStatus, nextFrames } = fx;

const data = (name) => readFileSync(join(root, 'tests', 'data', 'maps', name));

/** Pixels of the obstacle colour, and all pixels, in the world box [x0, y0, x1, y1] of the canvas. */
function obstaclePixels(box) {
  return page.evaluate(({ box, colour }) => {
    const c = /** @type {HTMLCanvasElement} */ (document.getElementById('canvas'));
    const k = c.width / c.clientWidth;
    const [ax, ay] = window.planarium.toCanvas(box[0], box[1]);
    const [bx, by] = window.planarium.toCanvas(box[2], box[3]);
    const [x0, x1] = [Math.min(ax, bx) * k, Math.max(ax, bx) * k].map(Math.round);
    const [y0, y1] = [Math.min(ay, by) * k, Math.max(ay, by) * k].map(Math.round);
    const px = c.getContext('2d').getImageData(x0, y0, x1 - x0, y1 - y0).data;
    const rgb = [1, 3, 5].map((i) => parseInt(colour.slice(i, i + 2), 16));
    let hits = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (rgb.every((v, j) => Math.abs(px[i + j] - v) <= 8)) hits++;
    }
    return { hits, all: px.length / 4 };
  }, { box, colour: PALETTE.obstacle });
}

test('a map_server PGM and its YAML open together, are drawn as the image, and grid-search solves them', async () => {
  await page.setInputFiles('#file', [
    { name: 'sample.yaml', mimeType: 'application/x-yaml', buffer: data('sample.yaml') },
    { name: 'sample.pgm', mimeType: 'image/x-portable-graymap', buffer: data('sample.pgm') },
  ]);
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Occupancy map (sample.yaml)');
  await waitState('idle');
  const sc = await page.evaluate(() => window.planarium.scenario());
  assert.deepEqual(sc.bounds, [-1, -0.5, 3, 2.5]);
  assert.equal(sc.obstacles.length, 6);
  assert.deepEqual(sc.map, { resolution: 0.1, origin: [-1, -0.5] });
  assert.equal(await page.inputValue('#planner'), 'grid-search');
  await nextFrames();
  // The wall hanging from the top: image columns 12–13, rows 0–19 (x 0.2…0.4, y 0.5…2.5).
  const wall = await obstaclePixels([0.22, 0.6, 0.38, 2.4]);
  // A free stretch: columns 5–7, rows 13–28 (x −0.5…−0.3, y −0.4…1.1).
  const free = await obstaclePixels([-0.48, -0.38, -0.32, 1.05]);
  console.log(`obstacle-coloured pixels: wall ${wall.hits}/${wall.all}, free ${free.hits}/${free.all}`);
  assert.ok(wall.all > 50 && wall.hits > 0.8 * wall.all, `the wall is drawn: ${JSON.stringify(wall)}`);
  assert.ok(free.all > 50 && free.hits === 0, `the free stretch is empty: ${JSON.stringify(free)}`);
  await fx.fastPlayback();
  await page.click('#run');
  await waitStatus('solved');
  const result = await page.evaluate(() => window.planarium.result());
  assert.equal(result.solved, true);
  assert.equal(result.planner, 'grid-search');
  await nextFrames();
  await page.screenshot({ path: join(shots, 'page-maps.png') });
});

test('a YAML alone names the image it needs; a PNG alone opens as a plain image', async () => {
  await page.setInputFiles('#file', { name: 'sample.yaml', mimeType: 'application/x-yaml', buffer: data('sample.yaml') });
  await waitState('invalid');
  await page.waitForSelector('#error', { state: 'visible' });
  assert.match(await page.textContent('#error'), /sample\.yaml names its image "sample\.pgm"/);
  // A YAML error names the line, the column and the key.
  const bad = Buffer.from('image: sample.pgm\nresolution: 0.o5\n');
  await page.setInputFiles('#file', [
    { name: 'bad.yaml', mimeType: 'application/x-yaml', buffer: bad },
    { name: 'sample.pgm', mimeType: 'image/x-portable-graymap', buffer: data('sample.pgm') },
  ]);
  await page.waitForFunction(() => /resolution/.test(document.getElementById('error').textContent));
  assert.match(await page.textContent('#error'), /line 2.*column 13|2:13/);
  await page.setInputFiles('#file', { name: 'sample.png', mimeType: 'image/png', buffer: data('sample.png') });
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Occupancy map (sample.png)');
  await waitState('idle');
  const sc = await page.evaluate(() => window.planarium.scenario());
  assert.deepEqual(sc.bounds, [0, 0, 2, 1.5]);
  assert.equal(await page.isVisible('#error'), false, 'a good load clears the error');
});

test('a file over 16 MiB is refused before it is read, by name and size; the map shown stays', async () => {
  const before = await page.evaluate(() => window.planarium.scenario());
  await page.setInputFiles('#file', { name: 'huge.png', mimeType: 'image/png', buffer: Buffer.alloc(16 * 1024 * 1024 + 1) });
  await page.waitForSelector('#error', { state: 'visible' });
  assert.match(await page.textContent('#error'), /huge\.png is 16,777,217 bytes; the limit is 16,777,216 bytes/);
  assert.deepEqual(await page.evaluate(() => window.planarium.scenario()), before);
  assert.equal(await page.evaluate(() => window.planarium.state()), 'idle');
});

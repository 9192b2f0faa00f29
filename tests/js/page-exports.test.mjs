// Exports for slides, in headless chromium: a PNG at a chosen width (its size read from the file),
// an SVG of the picture (parsed: obstacles, tree edges, the smoothed path; cells for a hexagon run),
// and a WebM recording of a run (the file starts with WebM's EBML magic number).
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { pageFixture } from './browser.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

async function download(click) {
  const [d] = await Promise.all([page.waitForEvent('download'), click()]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}

async function solve(id, name) {
  await fx.pickScenario(id, name);
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
}

test('PNG at a chosen width, SVG of the picture', async () => {
  await solve('narrow', 'Narrow passage');
  await page.fill('#png-width', '1600');
  const png = await download(() => page.click('#export-png'));
  assert.match(png.name, /\.png$/);
  assert.equal(png.bytes.subarray(1, 4).toString(), 'PNG');
  const width = png.bytes.readUInt32BE(16), height = png.bytes.readUInt32BE(20);
  assert.equal(width, 1600);
  assert.equal(height, 1600, 'the narrow scene is square');
  // The page's canvas is back at its own size.
  const cw = await page.$eval('#canvas', (c) => c.width);
  assert.ok(cw < 1600, `canvas restored (${cw})`);

  const svg = await download(() => page.click('#export-svg'));
  const text = svg.bytes.toString('utf8');
  const counts = await page.evaluate((t) => {
    const doc = new DOMParser().parseFromString(t, 'image/svg+xml');
    if (doc.querySelector('parsererror')) return null;
    const q = (s) => doc.querySelectorAll(s).length;
    const edges = [...doc.querySelectorAll('[id^="tree-"] path')].map((p) => (p.getAttribute('d').match(/M/g) || []).length);
    return { obstacles: q('#obstacles > *'), edges: edges.reduce((a, b) => a + b, 0), smoothed: q('#smoothed-path'), start: q('.start'), goal: q('.goal') };
  }, text);
  assert.ok(counts, 'the SVG parses');
  const model = await page.evaluate(() => window.planarium.model());
  assert.equal(counts.obstacles, (await page.evaluate(() => window.planarium.scenario())).obstacles.length);
  assert.ok(counts.edges > 50, `tree edges ${counts.edges}`);
  assert.equal(counts.smoothed, 1);
  assert.ok(counts.start >= 1 && counts.goal >= 1);
  assert.ok(model, 'the model is exposed');
});

test('SVG of a hexagon run has its cells', async () => {
  await solve('hex-trap-modified', 'Hexagons: the trap, modified potential');
  const svg = (await download(() => page.click('#export-svg'))).bytes.toString('utf8');
  const cells = await page.evaluate((t) => new DOMParser().parseFromString(t, 'image/svg+xml').querySelectorAll('#cells polygon').length, svg);
  const want = await page.evaluate(() => window.planarium.cells().cells);
  assert.ok(cells > 100 && cells === want, `${cells} cells in the SVG, ${want} in the run`);
});

test('a WebM recording of a run', async () => {
  await fx.pickScenario('narrow', 'Narrow passage');
  await page.click('#record');
  assert.match(await page.textContent('#record'), /Stop/);
  await page.click('#run');
  await fx.waitStatus('solved', 60000);
  await page.waitForTimeout(800);
  const webm = await download(() => page.click('#record'));
  assert.match(webm.name, /\.webm$/);
  assert.deepEqual([...webm.bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML magic');
  assert.ok(webm.bytes.length > 2000, `${webm.bytes.length} bytes`);
});

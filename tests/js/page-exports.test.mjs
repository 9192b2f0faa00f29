// Exports for slides, in headless chromium: a PNG at a chosen width (its size read from the file;
// the visible canvas not resized), an SVG of the picture (parsed: obstacles, tree edges, the
// smoothed path; cells for a hexagon run, a subpath each; rasterised, it matches the PNG pixel for pixel within a
// small mean difference, in four scenarios), a WebM at a chosen width (its EBML read: size,
// Duration, cues; a <video> plays it with a finite duration and seeks), an animated GIF (decoded
// by tests/js/gif-decode.mjs and by the browser: size, frames, loop, exact palette colours), the
// legend and transparent-background options, and out-of-range sizes typed into the fields.
// Pictures are saved in target/exports-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';
import { webmInfo } from '../../www/ui/webm.js';
import { decodeGif } from './gif-decode.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

async function download(click) {
  const [d] = await Promise.all([page.waitForEvent('download'), click()]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}

/** Start counting changes to the visible canvas's size (width/height/style attributes). */
const watchCanvas = () => page.evaluate(() => {
  window.canvasChanges = 0;
  // its size only (its text, `aria-label`, follows the run: ui/a11y.js)
  new MutationObserver((m) => { window.canvasChanges += m.length; }).observe(document.getElementById('canvas'), { attributes: true, attributeFilter: ['width', 'height', 'style'] });
});
const canvasChanges = () => page.evaluate(() => new Promise((r) => setTimeout(() => r(window.canvasChanges), 0)));

async function solve(id, name) {
  await fx.pickScenario(id, name);
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
}

test('PNG at a chosen width, SVG of the picture', async () => {
  await solve('narrow', 'Narrow passage');
  await page.fill('#png-width', '1600');
  await watchCanvas();
  const png = await download(() => page.click('#export-png'));
  assert.equal(await canvasChanges(), 0, 'the visible canvas was not resized for the export');
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
  // the cells as the canvas draws them: a few filled paths (one a level and colour), a subpath a cell
  const cells = await page.evaluate((t) => [...new DOMParser().parseFromString(t, 'image/svg+xml').querySelectorAll('#cells path:not([fill="none"])')]
    .reduce((n, p) => n + (p.getAttribute('d').match(/M/g) || []).length, 0), svg);
  const want = await page.evaluate(() => window.planarium.cells().cells);
  // cells under 4 px on screen are painted as pixels (draw/cell-raster.js): an embedded image
  const images = await page.evaluate((t) => new DOMParser().parseFromString(t, 'image/svg+xml').querySelectorAll('[id="cells"] image, image#cells').length, svg);
  assert.ok(cells > 100 && cells <= want && (cells === want || (images > 0 && cells >= 0.95 * want)), `${cells} cells as paths in the SVG (and ${images} images), ${want} in the run`);
});

test('SVG of a visibility-graph run has its graph edges', async () => {
  await fx.pickScenario('open-field', 'Open field');
  await page.selectOption('#planner', 'visibility-graph');
  await fx.waitState('idle');
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
  const svg = (await download(() => page.click('#export-svg'))).bytes.toString('utf8');
  const d = await page.evaluate((t) => new DOMParser().parseFromString(t, 'image/svg+xml').querySelector('#graph')?.getAttribute('d') ?? '', svg);
  const edges = (d.match(/M/g) || []).length;
  assert.ok(edges >= 50, `${edges} graph edges in the SVG`);
  await page.selectOption('#planner', 'rrt-connect');
  await fx.waitState('idle');
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

// ---- Issue 14's exports for slides: WebM at a size with a duration, GIF, SVG like the canvas, options ----

/** In the page: decode images (base64 bytes with their MIME types) at `w` × `h`: RGBA arrays. */
async function pixelsOf(images, w, h) {
  return page.evaluate(async ({ images, w, h }) => {
    const out = [];
    for (const { b64, type } of images) {
      const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const url = URL.createObjectURL(new Blob([bytes], { type }));
      const img = new Image();
      img.src = url;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = w; c.height = h;
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0, w, h);
      // the pixels as base64: an array of numbers this size takes seconds to carry out of the page
      const px = ctx.getImageData(0, 0, w, h).data;
      let bin = '';
      for (let i = 0; i < px.length; i += 0x8000) bin += String.fromCharCode.apply(null, Array.from(px.subarray(i, i + 0x8000)));
      out.push({ natural: [img.naturalWidth, img.naturalHeight], b64: btoa(bin) });
      URL.revokeObjectURL(url);
    }
    return out;
  }, { images: images.map(({ bytes, type }) => ({ b64: Buffer.from(bytes).toString('base64'), type })), w, h })
    .then((out) => out.map(({ natural, b64 }) => ({ natural, data: new Uint8Array(Buffer.from(b64, 'base64')) })));
}

const rgb = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
/** Pixels of RGBA `data` within `tol` of `#rrggbb` (opaque ones). */
function countColour(data, hex, tol = 4) {
  const [r, g, b] = rgb(hex);
  let n = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (data[i + 3] > 250 && Math.abs(data[i] - r) <= tol && Math.abs(data[i + 1] - g) <= tol && Math.abs(data[i + 2] - b) <= tol) n++;
  }
  return n;
}

/** Write RGBA pictures side by side (with a 4-px gap) as a PNG in target/ (drawn by the page). */
async function saveSideBySide(name, pics, w, h) {
  const b64 = await page.evaluate(({ pics, w, h }) => {
    const c = document.createElement('canvas');
    c.width = pics.length * (w + 4); c.height = h;
    const ctx = c.getContext('2d');
    pics.forEach((p, k) => ctx.putImageData(new ImageData(Uint8ClampedArray.from(atob(p), (ch) => ch.charCodeAt(0)), w, h), k * (w + 4), 0));
    return c.toDataURL('image/png').split(',')[1];
  }, { pics: pics.map((p) => Buffer.from(Uint8Array.from(p)).toString('base64')), w, h });
  writeFileSync(join(SHOTS, name), Buffer.from(b64, 'base64'));
}

test('SVG looks like the canvas: rasterised, it matches the PNG drawn at the same size', async () => {
  const cases = [['narrow', 'Narrow passage'], ['slot', 'Turn to pass the slot'], ['arm-2', 'Two-link arm and its configuration space'],
    ['hex-trap-modified', 'Hexagons: the trap, modified potential'],
    ['hex-trap-modified', 'Hexagons: the trap, modified potential', ['show-heat', 'show-arrows']]];
  const P = await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE);
  for (const [id, name, overlays] of cases) {
    await solve(id, name);
    for (const box of overlays ?? []) await page.check(`#${box}`);
    // the robot stops where it is: both exports draw the frame the canvas shows, which must not change between them
    await page.$eval('#anim-speed', (el) => { el.value = el.min; el.dispatchEvent(new Event('input', { bubbles: true })); });
    const w = await page.$eval('#canvas', (c) => Math.round(parseFloat(c.style.width)));
    const h = await page.$eval('#canvas', (c) => Math.round(parseFloat(c.style.height)));
    await page.fill('#png-width', String(w));
    const png = await download(() => page.click('#export-png'));
    const svg = await download(() => page.click('#export-svg'));
    const [a, b] = await pixelsOf([{ bytes: png.bytes, type: 'image/png' }, { bytes: svg.bytes, type: 'image/svg+xml' }], w, h);
    assert.deepEqual(a.natural, [w, h], `${id}: the PNG is ${w} × ${h}`);
    assert.deepEqual(b.natural, [w, h], `${id}: the SVG is ${w} × ${h}`);
    let diff = 0, far = 0;
    const d = new Array(a.data.length);
    for (let i = 0; i < a.data.length; i += 4) {
      const e = Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) + Math.abs(a.data[i + 2] - b.data[i + 2]);
      diff += e;
      if (e > 90) far++;
      d[i] = d[i + 1] = d[i + 2] = 255 - Math.min(255, e * 2); d[i + 3] = 255;
    }
    const mean = diff / (a.data.length / 4) / 3;
    await saveSideBySide(`exports-svg-vs-png-${id}${overlays ? '-heat' : ''}.png`, [a.data, b.data, d], w, h);
    assert.ok(mean < 4, `${id}: mean colour difference ${mean.toFixed(2)} per channel`);
    assert.ok(far / (w * h) < 0.01, `${id}: ${far} pixels differ a lot`);
    // the same colours, in about the same amounts
    for (const key of ['background', 'free', 'obstacle', 'tree0', 'tree1', 'smoothPath', 'start', 'goal', 'cellMixed', 'cellVisited']) {
      const ca = countColour(a.data, P[key]), cb = countColour(b.data, P[key]);
      if (ca < 30) continue; // not in this picture (or only as antialiased edges)
      assert.ok(Math.abs(ca - cb) <= Math.max(40, 0.2 * ca), `${id}: ${key} ${P[key]}: ${ca} pixels on the canvas, ${cb} in the SVG`);
    }
    assert.ok(countColour(b.data, P.smoothPath) > 20, `${id}: the path drawn in the SVG`);
    if (!id.startsWith('hex')) assert.ok(countColour(b.data, P.obstacle) > 100, `${id}: obstacles drawn in the SVG`); // (veiled under cells)
  }
});

test('a WebM at the chosen width with a real duration: it seeks', async () => {
  await solve('narrow', 'Narrow passage');
  await page.fill('#video-width', '640');
  await watchCanvas();
  await page.click('#record'); // the run so far is drawn first (in steps), then recording starts
  await page.waitForFunction(() => /Recording 640 × 640/.test(document.getElementById('export-status').textContent));
  await page.waitForTimeout(1500); // a clip of about 1.5 s (no assertion rests on how long)
  const webm = await download(() => page.click('#record'));
  assert.match(webm.name, /-640\.webm$/);
  assert.equal(await canvasChanges(), 0, 'the visible canvas was not resized while recording');
  const info = webmInfo(webm.bytes);
  assert.equal(info.width, 640, 'the video is as wide as asked');
  assert.equal(info.height, 640, 'and as high as the (square) scene');
  assert.equal(info.segmentKnown, true, 'the Segment has a known size');
  assert.ok(info.clusters.length >= 1 && info.clusters.every((c) => c.known), 'clusters of known size');
  assert.ok(info.cues.length >= 1, 'cues');
  for (const c of info.cues) assert.ok(info.clusters.some((k) => k.position === c.position), 'each cue points at a cluster');
  assert.ok(info.duration > info.lastBlock && info.duration < info.lastBlock + 500, `duration ${info.duration} ms, last frame at ${info.lastBlock} ms`);
  console.log(`a clip of ${info.duration} ms`);
  assert.ok(info.lastBlock > 0, 'more than one frame');
  const played = await page.evaluate(async (b64) => {
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const v = document.createElement('video');
    v.muted = true;
    v.src = URL.createObjectURL(new Blob([bytes], { type: 'video/webm' }));
    await new Promise((resolve, reject) => { v.onloadedmetadata = resolve; v.onerror = () => reject(new Error('the video does not load')); });
    const duration = v.duration;
    v.currentTime = duration / 2;
    await new Promise((resolve) => { v.onseeked = resolve; });
    return { duration, size: [v.videoWidth, v.videoHeight], at: v.currentTime, seekable: v.seekable.length ? v.seekable.end(0) : 0 };
  }, webm.bytes.toString('base64'));
  assert.ok(Number.isFinite(played.duration), `the player's duration is ${played.duration}`);
  assert.ok(Math.abs(played.duration * 1000 - info.duration) < 100, `player ${played.duration} s, header ${info.duration} ms`);
  assert.deepEqual(played.size, [640, 640]);
  assert.ok(Math.abs(played.at - played.duration / 2) < 0.1, `seeked to ${played.at} s`);
  assert.ok(played.seekable > 0, 'the player can seek it');
});

test('an animated GIF of the playback: its size, frames, loop and pixels', async () => {
  await solve('narrow', 'Narrow passage');
  await page.fill('#gif-width', '320');
  await page.fill('#gif-frames', '12');
  const gif = await download(() => page.click('#export-gif'));
  assert.match(gif.name, /\.gif$/);
  const g = decodeGif(gif.bytes);
  assert.equal(g.version, 'GIF89a');
  assert.deepEqual([g.width, g.height], [320, 320], 'logical screen: the chosen width, the square scene');
  assert.equal(g.frames.length, 12);
  assert.equal(g.loop, 0, 'loops forever');
  assert.ok(g.frames.every((f) => f.delay === 10 && f.width === 320 && f.height === 320));
  const rgba = (f) => {
    const out = new Uint8Array(f.indices.length * 4);
    f.indices.forEach((k, i) => out.set([g.palette[3 * k], g.palette[3 * k + 1], g.palette[3 * k + 2], 255], 4 * i));
    return out;
  };
  const first = rgba(g.frames[0]);
  const P = await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE);
  for (const key of ['background', 'free', 'obstacle', 'tree0', 'tree1', 'smoothPath']) {
    assert.ok(countColour(first, P[key], 0) > 20, `${key} ${P[key]} kept exact in the GIF (${countColour(first, P[key], 0)} pixels)`);
  }
  const distinct = new Set(g.frames.map((f) => Buffer.from(f.indices).toString('base64')));
  assert.ok(distinct.size >= 2, `the robot moves: ${distinct.size} different frames`);
  // the browser's own GIF decoder shows the same first frame as ours
  const [mine] = [first];
  const [theirs] = await pixelsOf([{ bytes: gif.bytes, type: 'image/gif' }], 320, 320);
  let same = 0;
  for (let i = 0; i < mine.length; i += 4) if (mine[i] === theirs.data[i] && mine[i + 1] === theirs.data[i + 1] && mine[i + 2] === theirs.data[i + 2]) same++;
  assert.equal(same, 320 * 320, 'the browser decodes the first frame to the same pixels');
  // and it is the picture: close to a PNG at the same width
  await page.fill('#png-width', '320');
  const png = await download(() => page.click('#export-png'));
  const [p] = await pixelsOf([{ bytes: png.bytes, type: 'image/png' }], 320, 320);
  let diff = 0;
  for (let i = 0; i < mine.length; i += 4) diff += Math.abs(mine[i] - p.data[i]) + Math.abs(mine[i + 1] - p.data[i + 1]) + Math.abs(mine[i + 2] - p.data[i + 2]);
  assert.ok(diff / (320 * 320 * 3) < 4, `GIF frame vs PNG: mean difference ${(diff / (320 * 320 * 3)).toFixed(2)}`);
  writeFileSync(join(SHOTS, 'exports-gif.gif'), gif.bytes);
  await saveSideBySide('exports-gif-frames.png', [first, rgba(g.frames[6]), p.data], 320, 320);
});

test('options: transparent background and legend (PNG, SVG, GIF)', async () => {
  await solve('narrow', 'Narrow passage');
  await page.check('#export-transparent');
  await page.fill('#png-width', '400');
  const png = await download(() => page.click('#export-png'));
  assert.equal(png.bytes.readUInt32BE(16), 400);
  assert.equal(png.bytes.readUInt32BE(20), 400, 'no legend: as high as the scene');
  writeFileSync(join(SHOTS, 'exports-transparent.png'), png.bytes);
  const [t] = await pixelsOf([{ bytes: png.bytes, type: 'image/png' }], 400, 400);
  const alpha = (x, y) => t.data[4 * (y * 400 + x) + 3];
  assert.equal(alpha(1, 1), 0, 'the margin is transparent');
  assert.equal(alpha(398, 398), 0);
  let clear = 0, opaque = 0;
  for (let i = 3; i < t.data.length; i += 4) { if (t.data[i] === 0) clear++; else if (t.data[i] === 255) opaque++; }
  assert.ok(clear > 0.3 * 400 * 400, `the free space is transparent too (${clear} clear pixels)`);
  assert.ok(opaque > 5000, `the scene is opaque (${opaque} pixels)`);
  assert.ok(countColour(t.data, (await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE)).obstacle) > 1000, 'obstacles opaque');
  const svgT = (await download(() => page.click('#export-svg'))).bytes.toString('utf8');
  assert.ok(!/id="background"|id="free"/.test(svgT), 'the SVG has no background rectangles');
  const sw = Number(/<svg[^>]* width="(\d+)"/.exec(svgT)[1]);
  const [st] = await pixelsOf([{ bytes: Buffer.from(svgT), type: 'image/svg+xml' }], sw, sw);
  assert.equal(st.data[3], 0, 'the rasterised SVG is transparent in the corner');
  let clearSvg = 0;
  for (let i = 3; i < st.data.length; i += 4) if (st.data[i] === 0) clearSvg++;
  assert.ok(clearSvg > 0.3 * sw * sw, `and in the free space (${clearSvg} clear pixels)`);

  await page.uncheck('#export-transparent');
  await page.check('#export-legend');
  const labels = await page.$$eval('#legend li', (lis) => lis.map((li) => li.textContent));
  assert.ok(labels.length >= 5, `the page's legend: ${labels.join(', ')}`);
  const pngL = await download(() => page.click('#export-png'));
  const H = pngL.bytes.readUInt32BE(20);
  assert.ok(H > 440, `a legend band under the picture (${H} px high)`);
  const [l] = await pixelsOf([{ bytes: pngL.bytes, type: 'image/png' }], 400, H);
  const band = Uint8Array.from(l.data.slice(400 * 400 * 4));
  const P = await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE);
  await saveSideBySide('exports-legend.png', [l.data], 400, H);
  // boxes are solid; the lines are 2 css px, here 1.4 px: antialiased, so a looser match
  for (const key of ['obstacle', 'start', 'goal']) assert.ok(countColour(band, P[key], 2) >= 20, `${key}'s box in the legend band`);
  for (const key of ['tree0', 'tree1', 'smoothPath']) assert.ok(countColour(band, P[key], 40) >= 8, `${key}'s line in the legend band (${countColour(band, P[key], 40)})`);
  let dark = 0;
  for (let i = 0; i < band.length; i += 4) if (band[i] + band[i + 1] + band[i + 2] < 300) dark++;
  assert.ok(dark > 300, `the labels: ${dark} dark pixels`);
  const svgL = (await download(() => page.click('#export-svg'))).bytes.toString('utf8');
  const texts = await page.evaluate((s) => [...new DOMParser().parseFromString(s, 'image/svg+xml').querySelectorAll('#legend text')].map((t) => t.textContent), svgL);
  assert.deepEqual(texts, labels, 'the SVG legend has the page legend labels');
  await page.fill('#gif-width', '200');
  await page.fill('#gif-frames', '2');
  const gif = decodeGif((await download(() => page.click('#export-gif'))).bytes);
  assert.equal(gif.width, 200);
  assert.ok(gif.height > 250, `the GIF has the legend too (${gif.height} px high), at a size one can read`);
  assert.match(await page.textContent('#export-status'), /GIF, 200 × \d+, 2 frames/);
});

test('odd sizes typed into the export fields are bounded, and the status says so', async () => {
  await solve('narrow', 'Narrow passage');
  await page.fill('#png-width', '50');
  const png = await download(() => page.click('#export-png'));
  assert.equal(png.bytes.readUInt32BE(16), 100);
  assert.match(await page.textContent('#export-status'), /PNG width is 100 to 8000: 100 used/);
  assert.equal(await page.inputValue('#png-width'), '100');
  await page.fill('#gif-width', '');
  await page.fill('#gif-frames', '-3');
  const gif = decodeGif((await download(() => page.click('#export-gif'))).bytes);
  assert.deepEqual([gif.width, gif.frames.length], [480, 2]);
  const said = await page.textContent('#export-status');
  assert.match(said, /GIF width: not a number, 480 used/);
  assert.match(said, /GIF frames is 2 to 150: 2 used/);
  await page.fill('#video-width', '12');
  await page.click('#record'); // the run is drawn first, then recording starts
  await page.waitForFunction(() => /^Recording/.test(document.getElementById('export-status').textContent));
  assert.match(await page.textContent('#export-status'), /Recording 320 × 320.*Video width is 320 to 3840: 320 used/);
  // let the recorder write its first cluster: stopped at once, a recording can hold only the EBML
  // header (the page then saves it raw and says so; this test is about the size)
  await page.waitForTimeout(700);
  const webm = await download(() => page.click('#record'));
  assert.equal(webmInfo(webm.bytes).width, 320);
  await page.screenshot({ path: join(SHOTS, 'exports-section.png') });
  await page.locator('#h-export').scrollIntoViewIfNeeded();
  await page.locator('#sec-export').screenshot({ path: join(SHOTS, 'exports-controls.png') });
});

test('a GIF taken while a run grows follows it (the export view draws the records as they come)', async () => {
  await fx.pickScenario('narrow', 'Narrow passage');
  await page.fill('#gif-width', '240');
  await page.fill('#gif-frames', '25');
  await page.click('#speed-instant'); // the run's batches shown as they come
  await watchCanvas();
  const [d] = await Promise.all([page.waitForEvent('download', { timeout: 120000 }), (async () => {
    await page.click('#export-gif'); // the first frame is taken at once: before the run
    await page.click('#run');
  })()]);
  const g = decodeGif(readFileSync(await d.path()));
  assert.equal(g.frames.length, 25);
  const P = await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE);
  const tree = (f) => {
    const [r, gg, b] = rgb(P.tree0);
    let n = 0;
    for (const k of f.indices) if (g.palette[3 * k] === r && g.palette[3 * k + 1] === gg && g.palette[3 * k + 2] === b) n++;
    return n;
  };
  const counts = g.frames.map(tree);
  assert.equal(counts[0], 0, 'no tree before the run');
  assert.ok(counts[24] > 50, `the tree grows in the GIF: ${counts.join(' ')}`);
  assert.equal(await canvasChanges(), 0, 'the visible canvas was not resized');
});

test('time-lapse: a GIF and a WebM of the whole run in 5 s, the tree growing frame by frame, the path at the end', async () => {
  await solve('narrow', 'Narrow passage');
  await page.fill('#gif-width', '200');
  await page.selectOption('#export-lapse', '5');
  const gif = await download(() => page.click('#export-gif'));
  const g = decodeGif(gif.bytes);
  const status = await page.textContent('#export-status');
  console.log(`time-lapse GIF: ${status}`);
  assert.match(status, /50 frames at 10 fps, the whole run in 5 s/);
  assert.equal(g.frames.length, 50, '5 s at 10 frames a second');
  assert.ok(g.frames.every((f) => f.delay === 10));
  const P = await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE);
  const rgba = (f) => {
    const out = new Uint8Array(f.indices.length * 4);
    f.indices.forEach((k, i) => out.set([g.palette[3 * k], g.palette[3 * k + 1], g.palette[3 * k + 2], 255], 4 * i));
    return out;
  };
  const tree = [0, 24, 49].map((k) => countColour(rgba(g.frames[k]), P.tree0, 0) + countColour(rgba(g.frames[k]), P.tree1, 0));
  const path = [0, 24, 49].map((k) => countColour(rgba(g.frames[k]), P.smoothPath, 0));
  console.log(`tree pixels at frames 1, 25, 50: ${tree}; smoothed path pixels: ${path}`);
  assert.ok(tree[0] < tree[1] && tree[1] < tree[2], `the tree grows over the time-lapse: ${tree}`);
  assert.equal(path[0], 0, 'no path before the end');
  assert.ok(path[2] > 20, `the path at the end (${path[2]} pixels)`);
  // the page's own picture is not replayed: it still shows the finished run
  assert.equal(await page.evaluate(() => window.planarium.state()), 'finished');

  // WebM: it records the run in 5 s and saves by itself
  const webm = await download(async () => {
    await page.click('#record');
    await page.waitForFunction(() => /the whole run in 5 s \(it saves by itself\)/.test(document.getElementById('export-status').textContent));
  });
  const w = webmInfo(webm.bytes);
  console.log(`time-lapse WebM: ${w.duration} ms, ${w.width} × ${w.height}; ${await page.textContent('#export-status')}`);
  assert.match(webm.name, /\.webm$/);
  // one click: it stopped and saved by itself (its length is the machine's: logged, not asserted)
  assert.ok(w.duration > 0 && Number.isFinite(w.duration), `a real duration (${w.duration} ms)`);
});

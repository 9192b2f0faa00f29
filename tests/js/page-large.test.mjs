// Large inputs in the page, each within the documented limits, end cleanly: a scenario file of
// 8.3 MB opens and runs (the size limit is checked on the file, not on a pretty-printed copy);
// grid search on a 998×998 map draws its million cells with a handful of canvas calls (small cells
// as pixels) and exports a bounded SVG; a big run's PNG and GIF are drawn in steps (the page keeps
// drawing frames, shows progress, and Cancel stops it); the Cells tool on a map of about 90,000
// rectangles looks at a bounded number of obstacles per pointer move. Times are printed, not
// asserted: what is asserted is counted (canvas calls, frames, function calls), so a busy machine
// cannot fail it and a regression to per-cell or per-obstacle work does.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, statSync } from 'node:fs';
import { pageFixture, walledIn } from './browser.mjs';
import { smallQuads } from './seeded.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

/** A binary PGM (P5) of `w` × `h` pixels, `occupied(x, y)` black (row 0 at the top), else free. */
function pgm(w, h, occupied) {
  const head = Buffer.from(`P5\n${w} ${h}\n255\n`);
  const px = Buffer.alloc(w * h, 254);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) if (occupied(x, y)) px[y * w + x] = 0;
  return Buffer.concat([head, px]);
}

/** Open a plain image (dark is occupied) and wait until it is loaded. */
async function openImage(name, bytes) {
  await page.setInputFiles('#file', { name, mimeType: 'image/x-portable-graymap', buffer: bytes });
  await page.waitForFunction((n) => document.getElementById('scenario-name').textContent === `Occupancy map (${n})`, name, { timeout: 60000 });
  await fx.waitState('idle', 60000);
}

/** Count calls of the 2-D context's drawing methods from now on (window.__calls()). */
const countCanvasCalls = () => page.evaluate(() => {
  const counts = {};
  const P = CanvasRenderingContext2D.prototype;
  for (const name of ['fill', 'stroke', 'fillRect', 'putImageData', 'drawImage']) {
    const f = P[name];
    counts[name] = 0;
    P[name] = function (...args) { counts[name]++; return f.apply(this, args); };
  }
  window.__calls = () => ({ ...counts });
  window.__resetCalls = () => { for (const k of Object.keys(counts)) counts[k] = 0; };
});

/** Record long tasks (PerformanceObserver) from now on: window.__long() is their durations. */
const watchLongTasks = () => page.evaluate(() => {
  const long = [];
  new PerformanceObserver((l) => { for (const e of l.getEntries()) long.push(e.duration); }).observe({ type: 'longtask' });
  window.__long = () => long.splice(0);
});
const longest = async () => Math.max(0, ...(await page.evaluate(() => window.__long())));

test('Open file: a scenario of 8.3 MB within every limit opens and runs (the limit is on the file, not on a re-serialised copy)', async () => {
  // 70,000 small quadrilaterals whose corners have 12 digits: compact, 8.3 MB; pretty-printed
  // (as the core wrote its copy: serde's two-space indent, a number a line), 21 MB.
  const obstacles = smallQuads(70000);
  const sc = { format: 'planarium-scenario/1', name: 'Large file', bounds: [0, 0, 1, 1], obstacles, robot: { kind: 'point' },
    start: [0.01, 0.01], goal: [0.99, 0.99], resolution: 0.001, planner: { name: 'rrt-connect', seed: 1 } };
  const text = JSON.stringify(sc);
  const pretty = JSON.stringify(sc, null, 2);
  console.log(`the file: ${text.length.toLocaleString('en')} bytes (pretty-printed ${pretty.length.toLocaleString('en')})`);
  assert.ok(text.length > 8e6 && text.length < 16 * 1024 * 1024 && pretty.length > 20e6);
  await page.setInputFiles('#file', { name: 'large.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Large file'
    || !document.getElementById('error').hidden, null, { timeout: 120000 });
  assert.equal(await page.isVisible('#error'), false, `no error: ${await page.textContent('#error')}`);
  await fx.waitState('idle', 60000);
  assert.equal((await page.evaluate(() => window.planarium.scenario())).obstacles.length, 70000);
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitState('finished', 120000);
  assert.equal(await page.isVisible('#error'), false, `the run was not refused: ${await page.textContent('#error')}`);
  assert.ok((await page.evaluate(() => window.planarium.stats())).iterations > 0);
});

test('grid search on a 998×998 map: its million cells redraw in a handful of canvas calls, and its SVG is bounded', async () => {
  // Two long walls; the rest free (a 3 kB PNG of this map is what the report was about).
  const map = pgm(998, 998, (x, y) => (x >= 300 && x < 306 && y < 800) || (x >= 700 && x < 706 && y > 200));
  await openImage('walls.pgm', map);
  assert.equal(await page.inputValue('#planner'), 'grid-search');
  await fx.setField('run-max_nodes', 1000000);
  await fx.setField('run-time_limit', 600);
  await watchLongTasks();
  await fx.fastPlayback();
  const t0 = Date.now();
  await page.click('#run');
  await fx.waitState('finished', 300000);
  await fx.nextFrames();
  const ran = Date.now() - t0;
  const cells = await page.evaluate(() => window.planarium.cells().cells);
  assert.ok(cells > 990000, `${cells} cells`);
  const heap = await page.evaluate(() => (performance.memory ? Math.round(performance.memory.usedJSHeapSize / 1e6) : null));
  console.log(`grid search, ${cells.toLocaleString('en')} cells at Instant: ${ran} ms to the end, longest task ${(await longest()).toFixed(0)} ms, JS heap ${heap} MB`);
  // The cells are drawn: mostly the free cells' colour, and the walls' grey.
  const [free] = await fx.countColours('canvas', ['#f7f4ea'], 6);
  assert.ok(free > 10000, `free cells drawn (${free} px)`);

  // An overlay toggle and a resize redraw the layer: a handful of canvas calls, not two a cell.
  await countCanvasCalls();
  await page.click('#show-cells');
  await fx.nextFrames();
  await page.click('#show-cells');
  await fx.nextFrames();
  const toggle = await page.evaluate(() => window.__calls());
  const toggled = await longest();
  await page.evaluate(() => window.__resetCalls());
  await page.setViewportSize({ width: 1100, height: 760 });
  await fx.nextFrames();
  await fx.nextFrames();
  const resize = await page.evaluate(() => window.__calls());
  console.log(`overlay off and on: ${JSON.stringify(toggle)}, longest task ${toggled.toFixed(0)} ms; resize: ${JSON.stringify(resize)}, longest task ${(await longest()).toFixed(0)} ms`);
  for (const [what, c] of [['toggle', toggle], ['resize', resize]]) {
    assert.ok(c.fill + c.stroke < 2000, `${what}: ${c.fill} fills and ${c.stroke} strokes for ${cells} cells`);
  }
  const [after] = await fx.countColours('canvas', ['#f7f4ea'], 6);
  assert.ok(after > 10000, `free cells drawn after the resize (${after} px)`);

  // The SVG: the cells as one embedded image, not a million polygons.
  const s0 = Date.now();
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 120000 }), page.click('#export-svg')]);
  const path = await download.path();
  const bytes = statSync(path).size;
  const svg = readFileSync(path, 'utf8');
  console.log(`SVG: ${(bytes / 1e6).toFixed(2)} MB in ${Date.now() - s0} ms; status "${await page.textContent('#export-status')}"`);
  assert.ok(bytes < 8e6, `the SVG is ${bytes} bytes`);
  assert.match(svg, /<image[^>]+href="data:image\/png;base64,/);
  assert.ok((svg.match(/<polygon/g) ?? []).length < 100, 'no polygon a cell');
  assert.match(await page.textContent('#export-status'), /cells .*image/);
});

// RRT grows until its node limit: the goal is walled in.
const WALLED = walledIn({ max_nodes: 150000, time_limit: 600 });

/** Count animation frames from now on (window.__frames()). */
const countFrames = () => page.evaluate(() => {
  let n = 0;
  const tick = () => { n++; requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
  window.__frames = () => n;
});

test('a big run\'s PNG and GIF are drawn in steps: frames keep coming, progress is shown, Cancel stops it', async () => {
  await page.setInputFiles('#file', { name: 'walled.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(WALLED)) });
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Walled-in goal');
  await fx.waitState('idle');
  await fx.fastPlayback();
  const t0 = Date.now();
  await page.click('#run');
  await fx.waitState('finished', 600000);
  const stats = await page.evaluate(() => window.planarium.stats());
  console.log(`${stats.nodes.toLocaleString('en')} nodes, ${stats.shown_events.toLocaleString('en')} records in ${Date.now() - t0} ms`);
  assert.equal(stats.nodes, 150000);
  await countFrames();
  await watchLongTasks();
  // Progress: every status line the export writes while it draws, with the frames drawn so far.
  await page.evaluate(() => {
    window.__said = [];
    new MutationObserver(() => window.__said.push([document.getElementById('export-status').textContent, window.__frames()]))
      .observe(document.getElementById('export-status'), { childList: true, characterData: true, subtree: true });
  });
  /** The progress lines said since the last call that match `re`, and the frames drawn between the first and the last. */
  const progress = async (re) => {
    const lines = (await page.evaluate(() => window.__said.splice(0))).filter(([t]) => re.test(t));
    return { lines: lines.length, frames: lines.length ? lines.at(-1)[1] - lines[0][1] : 0 };
  };
  await page.fill('#png-width', '4000');

  // A PNG 4000 px wide: the page draws frames while the export draws the run, and says how far it got.
  const p0 = Date.now();
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: 300000 }), page.click('#export-png')]);
  const png = await progress(/^Drawing the PNG: \d+%/);
  console.log(`PNG 4000 px: ${Date.now() - p0} ms, longest task ${(await longest()).toFixed(0)} ms; ${png.lines} progress lines `
    + `over ${png.frames} frames, then "${await page.textContent('#export-status')}"`);
  assert.ok((await download.path()) && statSync(await download.path()).size > 10000);
  assert.ok(png.lines >= 5, `${png.lines} progress lines`);
  assert.ok(png.frames >= 3, `${png.frames} frames drawn while the PNG was drawn`);
  assert.match(await page.textContent('#export-status'), /^PNG, 4000 px wide/);

  // Cancel: a second press while it draws; nothing is saved, and the status says so.
  let saved = false;
  page.on('download', () => { saved = true; });
  await page.click('#export-png');
  await page.waitForFunction(() => /^Drawing the PNG/.test(document.getElementById('export-status').textContent));
  assert.equal(await page.textContent('#export-png'), 'Cancel PNG');
  await page.click('#export-png');
  await page.waitForFunction(() => /cancelled/.test(document.getElementById('export-status').textContent));
  assert.match(await page.textContent('#export-status'), /^The PNG cancelled: nothing was saved\.$/);
  assert.equal(await page.textContent('#export-png'), 'PNG');

  // A GIF of two frames: the run is drawn in steps first, then the frames.
  await page.fill('#gif-frames', '2');
  await page.evaluate(() => window.__said.splice(0));
  const q0 = Date.now();
  await page.click('#export-gif');
  await page.waitForFunction(() => /^GIF, /.test(document.getElementById('export-status').textContent), null, { timeout: 300000 });
  const gif = await progress(/^Drawing the run for the GIF: \d+%/);
  console.log(`GIF: ${Date.now() - q0} ms, longest task ${(await longest()).toFixed(0)} ms; ${gif.lines} progress lines over ${gif.frames} frames`);
  assert.ok(gif.lines >= 5 && gif.frames >= 3, `${gif.lines} progress lines over ${gif.frames} frames`);
  assert.ok(saved, 'the GIF was saved');
});

test('the Cells tool on a map of about 90,000 rectangles: a pointer move looks at a bounded number of obstacles', async () => {
  // 900 × 300 pixels: a free frame 3 pixels wide; inside, two occupied pixels in three along each
  // row, shifted a pixel a row (rows never merge): a rectangle of two cells per pair.
  const W = 900, H = 300, F = 3;
  const wall = (x, y) => x >= F && y >= F && x < W - F && y < H - F && (x + y) % 3 !== 2;
  // Calls counted by V8's precise coverage, on from the page's start (code compiled before it was
  // on would not be counted): each take returns the counts since the last and resets them.
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.startPreciseCoverage', { callCount: true, detailed: true });
  await page.reload();
  await fx.waitState('idle', 30000);
  await openImage('dominoes.pgm', pgm(W, H, wall));
  const sc = await page.evaluate(() => window.planarium.scenario());
  console.log(`${sc.obstacles.length.toLocaleString('en')} rectangles`);
  assert.ok(sc.obstacles.length > 85000, `${sc.obstacles.length} rectangles`);
  assert.equal(await page.inputValue('#planner'), 'grid-search');
  const { resolution: r, origin: [ox, oy] } = sc.map;
  const at = (x, y) => fx.toPage(ox + (x + 0.5) * r, oy + (H - y - 0.5) * r); // pixel (x, row y from the top)
  await page.click('#tool-cells');
  await fx.nextFrames();
  await countCanvasCalls();
  // Each pointer move's handling time (a listener before the canvas's and one after it).
  await page.evaluate(() => {
    window.__moves = [];
    let t0 = 0;
    window.addEventListener('pointermove', () => { t0 = performance.now(); }, true);
    window.addEventListener('pointermove', () => { if (t0) window.__moves.push(performance.now() - t0); t0 = 0; });
  });
  /** Calls of the functions that test an obstacle against a cell (by name, in their modules) while `act()` runs. */
  const calls = async (act) => {
    await cdp.send('Profiler.takePreciseCoverage');
    await act();
    const { result } = await cdp.send('Profiler.takePreciseCoverage');
    const out = { inside: 0, meets: 0 };
    const home = { inside: '/ui/obstacle-shapes.js', meets: '/ui/cell-grid.js' };
    for (const script of result) {
      for (const f of script.functions) {
        if (f.functionName in out && script.url.endsWith(home[f.functionName]) && f.ranges.length) out[f.functionName] += f.ranges[0].count;
      }
    }
    return out;
  };
  const moves = 12;
  const drag = async (x0, y, mode) => {
    await page.mouse.move(...(await at(x0, y)));
    await page.mouse.down();
    await page.evaluate(() => { window.__moves.splice(0); window.__resetCalls(); });
    const n = await calls(async () => {
      for (let k = 1; k <= moves; k++) await page.mouse.move(...(await at(x0 + 2 * k, y)));
    });
    n.fill = (await page.evaluate(() => window.__calls())).fill; // the canvas's fills: an obstacle drawn is one
    await page.mouse.up();
    const ms = (await page.evaluate(() => window.__moves.splice(0))).sort((a, b) => a - b);
    console.log(`${mode}: ${moves} moves, median ${ms[ms.length >> 1].toFixed(1)} ms, longest ${ms.at(-1).toFixed(1)} ms; calls ${JSON.stringify(n)}`);
    // a move crosses 2 cells: what it looks at and redraws is what lies near them, not the map's 90,000
    for (const [name, c] of Object.entries(n)) assert.ok(c <= 1000 * moves, `${mode}: ${name} ran ${c} times in ${moves} moves`);
  };
  // Paint: from a free pixel of the middle row, along it (walls are skipped, free cells painted).
  const y = 150, x = 450 + ((2 - ((450 + y) % 3)) + 3) % 3;
  assert.equal(wall(x, y), false);
  const before = sc.obstacles.length;
  await drag(x, y, 'paint');
  await page.waitForFunction((n) => window.planarium.state() === 'idle' && window.planarium.scenario().obstacles.length > n, before, { timeout: 60000 });
  const painted = (await page.evaluate(() => window.planarium.scenario())).obstacles.length;
  // Erase: from a wall pixel a few rows down, along its row.
  await drag(x + 1, y + 6, 'erase');
  await page.waitForFunction((n) => window.planarium.state() === 'idle' && window.planarium.scenario().obstacles.length !== n, painted, { timeout: 60000 });
  const after = (await page.evaluate(() => window.planarium.scenario())).obstacles.length;
  console.log(`obstacles: ${before} → ${painted} painted → ${after} erased`);
  assert.ok(painted > before && after !== painted);
  await cdp.send('Profiler.stopPreciseCoverage');
});

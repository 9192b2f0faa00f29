// Grid search's editor (issue 17, PathFinding.js's conventions) in headless chromium, used like a
// person with the mouse: the Cells tool paints walls on grid search's own cells (the saved JSON has
// one rect per cell, a hundredth of a cell inside where the neighbour is free), grid search then
// blocks exactly the painted cells, a drag from a wall erases (the walls beside it draw back, so
// grid search frees exactly the erased cells), one undo takes back a whole drag, a drag through the
// start leaves its cell free and says so, a press on the start still drags it, circles are not
// erased (said), and Clear walls removes the painted cells but keeps drawn shapes.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { pageFixture } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const scenario = () => page.evaluate(() => window.planarium.scenario());
const settled = (n) => page.waitForFunction((k) => window.planarium.state() === 'idle' && window.planarium.scenario()?.obstacles.length === k, n);
async function saveJson() {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-scenario')]);
  return JSON.parse(readFileSync(await download.path(), 'utf8'));
}

// The unit map's default grid: 40 × 40 cells of 0.025; a wall a hundredth of a cell inside.
const SIDE = 0.025, N = 40, M = SIDE / 100;
const clean = (v) => Number(v.toPrecision(12));
const centre = (i) => (i + 0.5) * SIDE;
/** The rects of a painted run of cells i0..i1 in row j, alone on the map. */
const run = (i0, i1, j) => Array.from({ length: i1 - i0 + 1 }, (_, n) => {
  const i = i0 + n;
  return { rect: [clean(i * SIDE + (i === i0 ? M : 0)), clean(j * SIDE + M), clean((i + 1) * SIDE - (i === i1 ? M : 0)), clean((j + 1) * SIDE - M)] };
});
const ids = (i0, i1, j) => Array.from({ length: i1 - i0 + 1 }, (_, n) => j * N + i0 + n);
const sortRects = (obs) => obs.map((o) => o.rect).sort((a, b) => a[1] - b[1] || a[0] - b[0]);

/** Press at world point `from`, move to `to` in `steps` jumps (few: a fast drag), release. */
async function drag(from, to, steps = 3, during = null) {
  await page.mouse.move(...(await fx.toPage(...from)));
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(...(await fx.toPage(from[0] + ((to[0] - from[0]) * k) / steps, from[1] + ((to[1] - from[1]) * k) / steps)));
  }
  if (during) await during();
  await page.mouse.up();
}

/** Run grid search to the end: the cells it labelled blocked (ids j·40 + i). */
async function blockedCells() {
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitState('finished', 60000);
  await fx.nextFrames();
  const cells = await page.evaluate(() => window.planarium.cells());
  assert.equal(cells.cells, N * N);
  await page.click('#reset');
  await fx.waitState('idle');
  return cells.full.sort((a, b) => a - b);
}

test('Cells: paint a row of walls on grid search\'s cells, grid search blocks exactly those; erase part of it; one undo per drag', async () => {
  await fx.pickScenario('open-field', 'Open field');
  await page.click('#new-map');
  await settled(0);
  await page.selectOption('#planner', 'grid-search');
  await fx.waitState('idle');
  await page.click('#tool-cells');
  assert.equal(await page.getAttribute('#tool-cells', 'aria-pressed'), 'true');
  await fx.nextFrames();
  const [lattice] = await fx.countColours('canvas', ['#ced8e9'], 4);
  assert.ok(lattice > 3000, `the lattice is drawn faintly (${lattice} px)`);

  // Count the scenarios sent to the worker: one per drag, on release.
  await page.evaluate(() => {
    const post = Worker.prototype.postMessage;
    window.loadsSent = 0;
    Worker.prototype.postMessage = function (msg, ...rest) {
      if (msg?.type === 'load') window.loadsSent++;
      return post.call(this, msg, ...rest);
    };
  });
  // A fast drag along row 20 (three jumps of five cells): no gap, the canvas shows it live.
  const y = centre(20);
  let live = 0;
  await drag([centre(12), y], [centre(27), y], 3, async () => {
    await fx.nextFrames();
    live = (await fx.countColours('canvas', [PALETTE.obstacle], 4))[0];
    await page.screenshot({ path: '/tmp/page-grid-editor-paint.png' });
    assert.equal(await page.evaluate(() => window.loadsSent), 0, 'nothing sent to the worker during the drag');
  });
  assert.ok(live > 1500, `painted cells drawn during the drag (${live} px)`);
  await settled(16);
  assert.equal(await page.evaluate(() => window.loadsSent), 1, 'one load for the whole drag');
  const saved = await saveJson();
  assert.deepEqual(sortRects(saved.obstacles), sortRects(run(12, 27, 20)), 'one rect per cell, on grid search\'s cells');
  assert.deepEqual(await blockedCells(), ids(12, 27, 20), 'grid search blocks exactly the painted cells');

  // One undo takes back the whole drag; redo brings it again.
  await page.click('#undo');
  await settled(0);
  await page.click('#redo');
  await settled(16);

  // A drag from a wall erases: cells 16..21 go, their neighbours draw back from them.
  await drag([centre(16), y], [centre(21), y], 2);
  await settled(10);
  assert.deepEqual(sortRects((await scenario()).obstacles), sortRects([...run(12, 15, 20), ...run(22, 27, 20)]));
  assert.deepEqual(await blockedCells(), [...ids(12, 15, 20), ...ids(22, 27, 20)], 'grid search frees exactly the erased cells');
  await page.click('#undo');
  await settled(16);

  // A diagonal drag: a staircase of cells, each sharing a side with the one before (no leak).
  // (a wall cell with walls on two sides and a free cell between them is an L of two rects)
  await drag([centre(5), centre(30)], [centre(10), centre(35)], 1);
  await fx.waitState('idle');
  const diag = (await scenario()).obstacles.length - 16;
  const stair = new Set((await scenario()).obstacles.slice(16).map(({ rect: r }) => `${Math.floor((r[0] + r[2]) / 2 / SIDE)},${Math.floor((r[1] + r[3]) / 2 / SIDE)}`));
  assert.equal(stair.size, 11, `a staircase of 11 cells from (5, 30) to (10, 35), not 6: ${[...stair]}`);
  assert.ok(stair.has('5,30') && stair.has('10,35'));
  assert.deepEqual((await blockedCells()).filter((k) => k >= 30 * N).map((k) => `${k % N},${Math.floor(k / N)}`).sort(), [...stair].sort(), 'grid search blocks the staircase, not its corners');

  // Clear walls: the painted cells go.
  await page.click('#clear-walls');
  await settled(0);
  await page.click('#undo');
  await settled(16 + diag);
});

test('Cells: the start\'s cell stays free (said), a press on the start drags it, circles are not erased (said), Clear walls keeps drawn shapes', async () => {
  await fx.pickScenario('open-field', 'Open field');
  await page.click('#new-map');
  await settled(0);
  await page.selectOption('#planner', 'grid-search');
  await fx.waitState('idle');
  // a circle, drawn first
  await page.click('#tool-circle');
  await fx.drag(await fx.toPage(0.7, 0.3), await fx.toPage(0.76, 0.3));
  await settled(1);

  // Row 4 holds the start (0.1, 0.1), on the corner of cells 3 and 4: both stay free.
  await page.click('#tool-cells');
  await drag([centre(0), centre(4)], [centre(9), centre(4)], 4);
  await settled(1 + 8);
  assert.match(await page.textContent('#edit-status'), /never covers the start/);
  const s = await scenario();
  const covers = (o, [x, y]) => o.rect && x >= Math.min(o.rect[0], o.rect[2]) && x <= Math.max(o.rect[0], o.rect[2]) && y >= Math.min(o.rect[1], o.rect[3]) && y <= Math.max(o.rect[1], o.rect[3]);
  assert.ok(!s.obstacles.some((o) => covers(o, s.start)), 'no wall covers the start');
  assert.equal(await page.isVisible('#error'), false, 'the core accepts the map');

  // A press on the start drags it (no wall painted).
  await drag([0.1, 0.1], [0.2, 0.2], 4);
  await page.waitForFunction(() => window.planarium.scenario().start[0] > 0.15);
  await fx.waitState('idle');
  assert.equal((await scenario()).obstacles.length, 9);

  // A drag from the circle's centre (a wall) erases: the circle stays, and the status says why.
  await drag([centre(28), centre(12)], [centre(30), centre(12)], 2);
  assert.match(await page.textContent('#edit-status'), /under a circle or polygon are not erased/);
  assert.equal((await scenario()).obstacles.filter((o) => o.circle).length, 1);

  // Clear walls keeps the circle; Clear obstacles removes it too.
  await page.click('#clear-walls');
  await settled(1);
  assert.ok((await scenario()).obstacles[0].circle);
  assert.equal(await page.isDisabled('#clear-walls'), true, 'no walls left');
  await page.click('#clear-obstacles');
  await settled(0);
});

test('Cells on another planner: the snapping grid\'s cells when snapping, grid search\'s default otherwise', async () => {
  await fx.pickScenario('open-field', 'Open field');
  await page.click('#new-map');
  await settled(0);
  await page.check('#snap-grid'); // step 0.05
  await page.click('#tool-cells');
  await drag([0.125, 0.525], [0.225, 0.525], 2);
  await settled(3);
  const rects = sortRects((await scenario()).obstacles);
  assert.deepEqual(rects, [[0.1005, 0.5005, 0.15, 0.5495], [0.15, 0.5005, 0.2, 0.5495], [0.2, 0.5005, 0.2495, 0.5495]]);
});

test('Cells: erasing a cell of a drawn rectangle splits it around the cell, which grid search then leaves free; Escape drops a drag', async () => {
  await fx.pickScenario('open-field', 'Open field');
  await page.click('#new-map');
  await settled(0);
  await page.selectOption('#planner', 'grid-search');
  await fx.waitState('idle');
  await page.click('#tool-rect');
  await fx.drag(await fx.toPage(0.3, 0.7), await fx.toPage(0.5, 0.9));
  await settled(1);
  const [rect] = (await scenario()).obstacles;
  const cell = 32 * N + 16; // (0.4125, 0.8125), in the middle of it
  assert.ok((await blockedCells()).includes(cell));

  // A click (no move) on a wall cell erases that one cell: four rects around it.
  await page.click('#tool-cells');
  await drag([centre(16), centre(32)], [centre(16), centre(32)], 1);
  await settled(4);
  const parts = (await scenario()).obstacles.map((o) => o.rect);
  const area = (r) => Math.abs((r[2] - r[0]) * (r[3] - r[1]));
  const hole = (SIDE + 2 * M) ** 2;
  assert.ok(Math.abs(parts.reduce((a, r) => a + area(r), 0) - (area(rect.rect) - hole)) < 1e-12, 'the rectangle minus the cell (and its hair)');
  const blocked = await blockedCells();
  assert.ok(!blocked.includes(cell), 'the erased cell is free');
  for (const k of [cell - 1, cell + 1, cell - N, cell + N]) assert.ok(blocked.includes(k), `its neighbour ${k} stays blocked`);

  // Escape in the middle of a drag: the map as before it, nothing sent.
  await page.mouse.move(...(await fx.toPage(centre(2), centre(2))));
  await page.mouse.down();
  await page.mouse.move(...(await fx.toPage(centre(9), centre(2))));
  await page.keyboard.press('Escape');
  await page.mouse.up();
  await fx.nextFrames();
  await fx.waitState('idle');
  assert.equal((await scenario()).obstacles.length, 4);
});

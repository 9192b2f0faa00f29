// Cells and potential fields in the page (headless chromium): the hexagonal decomposition of
// hex-potential drawn by label and verdict, a run that ends without a path and says why, the heat
// map switched on and off, the hover box over a visited cell, and the classic potential field's
// local minimum. Screenshots go to /tmp/page-hex-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, waitStatus, pickScenario, countColours, nextFrames, fastPlayback } = fx;

const SCENARIOS = {
  'hex-trap-modified': 'Hexagons: the trap, modified potential',
  'hex-trap': 'Hexagons: the dead-end trap',
  'apf-minimum': 'Potential field: a local minimum',
};

/** Pick a built-in scenario, make sure `planner` is chosen, run it to the end at full speed. */
async function runToEnd(id, planner) {
  await pickScenario(id, SCENARIOS[id]);
  if (await page.$eval('#planner', (s) => s.value) !== planner) {
    await page.selectOption('#planner', planner);
    await waitState('idle');
  }
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
}

async function toggle(id) {
  await page.click(`#${id}`);
  await nextFrames();
}

const sum = (a) => a.reduce((s, v) => s + v, 0);

test('hex-trap-modified: the cells are drawn free, mixed and visited, and the run solves', async () => {
  await runToEnd('hex-trap-modified', 'hex-potential');
  await waitStatus('solved');
  const cells = await page.evaluate(() => window.planarium.cells());
  console.log(`cells ${cells.cells} (free, mixed, full: ${cells.labels}), visited ${cells.visited.length}, field ${cells.field}, t ${cells.t}`);
  assert.ok(cells.cells > 100, `cells: ${cells.cells}`);
  assert.ok(cells.labels[0] > 0 && cells.labels[1] > 0 && cells.labels[2] > 0, `labels: ${cells.labels}`);
  assert.ok(cells.visited.length >= 5, `visited cells: ${cells.visited.length}`);
  assert.equal(cells.regions.length, 1, 'the modified potential solves in the first region');
  assert.ok(cells.t > 0, 'a rigid robot has a diagonal t');
  const [free, mixed, visited] = await countColours('canvas', [PALETTE.cellFree[0], PALETTE.cellMixed, PALETTE.cellVisited], 3);
  console.log(`pixels: free level-0 cells ${free}, mixed ${mixed}, visited ${visited}`);
  assert.ok(free > 5000, `free-cell pixels: ${free}`);
  assert.ok(mixed > 300, `mixed-cell pixels: ${mixed}`);
  assert.ok(visited > 300, `visited-cell pixels: ${visited}`);
  // Looked at: the ivory hexagons (coarse ones lighter, with thicker outlines) tile the map, the
  // amber finest-level cells hug the shelf and the floor (obstacles veiled on top), the blue
  // visited cells lead round the shelf's right end under the tree, the dashed region of
  // influence, and the robot with its dashed t/2 circle along the path.
  await page.screenshot({ path: '/tmp/page-hex-modified.png' });
});

test('hex-trap with A*: the complete search over the same cells solves where the descent is trapped; open and closed cells drawn', async () => {
  await pickScenario('hex-trap', SCENARIOS['hex-trap']);
  if (await page.$eval('#planner', (s) => s.value) !== 'hex-potential') {
    await page.selectOption('#planner', 'hex-potential');
    await waitState('idle');
  }
  assert.ok(await page.isVisible('#param-search'), 'the search is a choice in the panel');
  await page.selectOption('#param-search', 'astar');
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
  await waitStatus('solved');
  const cells = await page.evaluate(() => window.planarium.cells());
  console.log(`A*: closed ${cells.visited.length}, open ${cells.open}, blocked ${cells.blocked}, regions ${cells.regions.length}`);
  assert.ok(cells.visited.length > 20 && cells.open > 5, `closed ${cells.visited.length}, open ${cells.open}`);
  assert.equal(cells.regions.length, 0, 'no region of influence: the search may use every cell');
  const [open, closed] = await countColours('canvas', [PALETTE.cellOpen, PALETTE.cellVisited], 3);
  console.log(`pixels: open ${open}, closed ${closed}`);
  assert.ok(open > 200 && closed > 1000, `open ${open}, closed ${closed} pixels`);
  const note = await page.textContent('#explain-code');
  assert.match(note, /close the open cell of least g \+ h/);
  await page.screenshot({ path: '/tmp/page-hex-astar.png' });
  await page.selectOption('#param-search', 'descent');
});

test('zigzag with grid search: the grid drawn blocked and free, A*\'s open and closed cells, and it solves', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'grid-search');
  await waitState('idle');
  assert.ok(await page.isVisible('#param-diagonal') && await page.isVisible('#param-weight'), 'PathFinding.js\'s choices in the panel');
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
  await waitStatus('solved');
  const cells = await page.evaluate(() => window.planarium.cells());
  console.log(`grid: ${cells.cells} cells (free, -, blocked: ${cells.labels}), closed ${cells.visited.length}, open ${cells.open}`);
  assert.equal(cells.cells, 1600, 'a 40 × 40 grid');
  assert.ok(cells.labels[2] > 100 && cells.visited.length > 100 && cells.open > 10, JSON.stringify({ labels: cells.labels, open: cells.open }));
  const [open, closed, blocked] = await countColours('canvas', [PALETTE.cellOpen, PALETTE.cellVisited, PALETTE.cellFull], 3);
  console.log(`pixels: open ${open}, closed ${closed}, blocked ${blocked}`);
  assert.ok(open > 200 && closed > 5000 && blocked > 2000, `open ${open}, closed ${closed}, blocked ${blocked}`);
  assert.match(await page.textContent('#explain-code'), /a cell an obstacle touches is blocked/);
  await page.screenshot({ path: '/tmp/page-grid-astar.png' });
});

test('hex-trap: no path, the status and the note say why; the heat map switches on and off', async () => {
  await runToEnd('hex-trap', 'hex-potential');
  await waitStatus('no path');
  assert.equal(await page.evaluate(() => window.planarium.state()), 'finished');
  assert.equal(await page.isHidden('#error'), true, 'no error is shown');
  assert.equal(await page.getAttribute('#status', 'data-status'), 'no_path');
  const result = await page.evaluate(() => window.planarium.result());
  assert.equal(result.solved, false);
  assert.match(result.reason, /region of influence/);
  assert.match(await page.textContent('#stat-reason'), /region of influence/);
  assert.equal(await page.isVisible('#run-note'), true, 'the note under the canvas is shown');
  assert.match(await page.textContent('#run-note'), /^No path: .*region of influence/);
  const cells = await page.evaluate(() => window.planarium.cells());
  assert.ok(cells.regions.length >= 2, `the region grew: ${cells.regions.map((r) => r.radius.toFixed(3))}`);
  assert.ok(cells.regions[1].radius > cells.regions[0].radius);
  assert.ok(cells.field > 20, `field samples: ${cells.field}`);

  const heat = async () => sum(await countColours('canvas', [...PALETTE.heat], 2));
  assert.equal(await page.isChecked('#show-heat'), false, 'the heat map is off by default');
  const off = await heat();
  await toggle('show-heat');
  const on = await heat();
  console.log(`heat-map pixels: off ${off}, on ${on}`);
  assert.ok(on > 20000, `heat-map pixels when on: ${on}`);
  await toggle('show-arrows');
  // Looked at: the heat map over the free cells inside the region (dark next to the shelf and the
  // floor, light in the open), the descent arrows, the faint first region and the final one.
  await page.screenshot({ path: '/tmp/page-hex-trap-heat.png' });
  await toggle('show-arrows');
  await toggle('show-heat');
  const again = await heat();
  assert.ok(again <= off + 50 && again < on / 20, `heat-map pixels gone: ${again} (off ${off}, on ${on})`);
  await page.screenshot({ path: '/tmp/page-hex-trap.png' });

  // a new run clears the note
  await page.click('#reset');
  await waitState('idle');
  assert.equal(await page.isHidden('#run-note'), true, 'the note goes with the run');
});

test('hovering a visited cell shows its level, verdict and potential terms', async () => {
  await runToEnd('hex-trap-modified', 'hex-potential');
  await waitStatus('solved');
  const cells = await page.evaluate(() => window.planarium.cells());
  // a visited cell in the middle of the path (its centre is its record's centre, inside it)
  const cell = cells.visited[Math.floor(cells.visited.length / 2)];
  const [cx, cy] = await page.evaluate(([x, y]) => window.planarium.toCanvas(x, y), [cell.x, cell.y]);
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + cx + 3, box.y + cy + 3);
  await page.waitForSelector('#cell-tip:not([hidden])');
  const text = await page.textContent('#cell-tip');
  console.log(`hover text over cell ${cell.id}:\n${text}`);
  assert.match(text, new RegExp(`cell ${cell.id} · level \\d`));
  assert.match(text, /visited/);
  assert.match(text, /repulsion[^\n]*\d/);
  assert.match(text, /goal term[^\n]*α [−\d.]+°/);
  assert.match(text, /total [−\d]/);
  await page.screenshot({ path: '/tmp/page-hex-hover.png' });
  await page.mouse.move(2, 2); // off the canvas
  await page.waitForSelector('#cell-tip', { state: 'hidden' });
});

test('apf-minimum: the potential field stops at a local minimum, marked on the canvas', async () => {
  await runToEnd('apf-minimum', 'potential-field');
  await waitStatus('no path');
  const result = await page.evaluate(() => window.planarium.result());
  assert.match(result.reason, /local minimum/);
  assert.match(await page.textContent('#run-note'), /local minimum/);
  const cells = await page.evaluate(() => window.planarium.cells());
  assert.equal(cells.minima.length, 1, 'one local minimum');
  assert.ok(cells.field > 100, `field tiles: ${cells.field}`);
  const [ring] = await countColours('canvas', [PALETTE.minimum], 8);
  console.log(`local-minimum marker pixels: ${ring}`);
  assert.ok(ring > 60, `local-minimum marker pixels: ${ring}`);
  // hovering a tile (the heat map is on from the start for a field) gives the field's terms
  assert.equal(await page.isChecked('#show-heat'), true, 'a potential field shows its heat map from the start');
  await toggle('show-arrows');
  const [cx, cy] = await page.evaluate(() => window.planarium.toCanvas(0.3, 0.7));
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + cx, box.y + cy);
  await page.waitForSelector('#cell-tip:not([hidden])');
  const text = await page.textContent('#cell-tip');
  assert.match(text, /attraction [\d.]/);
  assert.match(text, /repulsion/);
  await page.mouse.move(2, 2);
  await page.waitForSelector('#cell-tip', { state: 'hidden' });
  // Looked at: the heat map (the goal's basin light, the cup's inside dark up to its walls),
  // the arrows turning into the cup, the chain of steps stopping in it, and the magenta ring
  // labelled "local minimum".
  await page.screenshot({ path: '/tmp/page-hex-apf.png' });
});

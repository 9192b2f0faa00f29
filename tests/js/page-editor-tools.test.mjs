// The scenario editor's map tools in headless chromium, used like a person: New map and Clear
// obstacles (the canvas shows none, undo brings them back), snapping to a grid (a dragged
// rectangle, a circle, a moved rectangle and the start land exactly on it, as the saved file
// shows), the coordinate read-out under the pointer, and the name and notes (saved in the JSON,
// carried by the copied link, bounded).
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const scenario = () => page.evaluate(() => window.planarium.scenario());
/** Wait until the worker has accepted the edit and the scenario holds `n` obstacles. */
const settled = (n) => page.waitForFunction((k) => window.planarium.state() === 'idle' && window.planarium.scenario()?.obstacles.length === k, n);
/**
 * Obstacle-coloured pixels on the workspace canvas, once it has been redrawn. A map without
 * obstacles still has a few: the start dot's anti-aliased rim (orange into its dark edge) passes
 * for brown (NONE); the narrow passage's walls are thousands.
 */
const NONE = 20;
const obstaclePixels = async () => { await fx.nextFrames(); return (await fx.countColours('canvas', [PALETTE.obstacle], 4))[0]; };
/** Click Save JSON and parse the downloaded file: [scenario, file name]. */
async function saveJson() {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-scenario')]);
  return [JSON.parse(readFileSync(await download.path(), 'utf8')), download.suggestedFilename()];
}
/** Faint grid-line pixels (the grid's blue at 16% over the white free space). */
const gridPixels = async () => { await fx.nextFrames(); return (await fx.countColours('canvas', ['#dbe3ef'], 3))[0]; };

test('New map: an empty map with the same bounds and robot, start and goal in corners; undo brings the old map back', async () => {
  await fx.pickScenario('narrow', 'Narrow passage');
  const before = await scenario();
  assert.ok(before.obstacles.length > 0 && await obstaclePixels() > 1000, 'the built-in shows its obstacles');

  await page.click('#new-map');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Untitled map');
  await settled(0);
  const s = await scenario();
  assert.deepEqual(s.bounds, before.bounds);
  assert.equal(s.robot.kind, 'point');
  assert.deepEqual([s.start, s.goal], [[0.1, 0.1], [0.9, 0.9]]);
  assert.ok(await obstaclePixels() <= NONE, 'no obstacle drawn');
  assert.equal(await page.isDisabled('#clear-obstacles'), true, 'nothing to clear');
  assert.equal(await page.inputValue('#edit-name'), 'Untitled map');
  await page.screenshot({ path: join(SHOTS, 'page-editor-tools-newmap.png') });

  // It plans (the empty map is valid), and undo gives the built-in back, obstacles and name.
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
  await page.click('#undo');
  await settled(before.obstacles.length);
  assert.deepEqual((await scenario()).obstacles, before.obstacles);
  assert.equal(await page.textContent('#scenario-name'), 'Narrow passage');
  assert.ok(await obstaclePixels() > 1000);

  // A rigid body stays a rigid body, placed clear of the bounds with its heading 0.
  await fx.pickScenario('hex-open', 'Hexagons: open field');
  const rigid = await scenario();
  await page.click('#new-map');
  await settled(0);
  const r = await scenario();
  assert.equal(r.robot.kind, 'rigid');
  assert.deepEqual(r.robot.footprint, rigid.robot.footprint);
  assert.equal(r.start.length, 3);
  assert.equal(r.start[2], 0);
  assert.ok(r.start[0] < r.goal[0] && r.start[1] < r.goal[1], JSON.stringify([r.start, r.goal]));
  assert.equal(await page.isVisible('#error'), false, 'the core accepts it');

  // An arm and a vehicle chain keep their robot, start and goal (valid in the same bounds).
  for (const [id, name] of [['arm-2', 'Two-link arm and its configuration space'], ['asv-3-easy', 'Three vehicles, one wide gap (ASV 3-easy)']]) {
    await fx.pickScenario(id, name);
    const was = await scenario();
    await page.click('#new-map');
    await settled(0);
    const now = await scenario();
    assert.deepEqual([now.robot, now.start, now.goal, now.bounds], [was.robot, was.start, was.goal, was.bounds], id);
    assert.equal(await page.isVisible('#error'), false, `${id}: the core accepts it`);
  }
});

test('Clear obstacles, then undo brings every one back', async () => {
  await fx.pickScenario('narrow', 'Narrow passage');
  const before = (await scenario()).obstacles;
  await page.click('#clear-obstacles');
  await settled(0);
  assert.ok(await obstaclePixels() <= NONE, 'no obstacle drawn');
  assert.equal(await page.textContent('#scenario-name'), 'Narrow passage', 'only the obstacles go');
  await page.click('#undo');
  await settled(before.length);
  assert.deepEqual((await scenario()).obstacles, before);
  assert.ok(await obstaclePixels() > 1000);
  await page.click('#redo');
  await settled(0);

  // Bounds that cross are refused here, named, and the field shows the bound kept.
  await page.fill('#bounds-2', '-1');
  await page.press('#bounds-2', 'Enter');
  assert.match(await page.textContent('#bounds-error'), /X max must be above x min \(0\); it stays 1\./);
  assert.equal(await page.inputValue('#bounds-2'), '1');
  assert.deepEqual((await scenario()).bounds, [0, 0, 1, 1]);
});

test('Snap to grid: drawn, resized and moved shapes and the start land exactly on the grid', async () => {
  await fx.pickScenario('open-field', 'Open field');
  await page.click('#new-map');
  await settled(0);
  assert.deepEqual([(await scenario()).start, (await scenario()).goal], [[0.1, 0.1], [0.9, 0.9]], 'start and goal in the corners');
  assert.equal(await page.inputValue('#grid-step'), '0.05', 'the default step: 1/20 of the width');
  assert.equal(await gridPixels(), 0, 'no grid while snapping is off');
  await page.check('#snap-grid');
  const lines = await gridPixels();
  assert.ok(lines > 5000, `the grid is drawn (${lines} px)`);

  // A rectangle dragged between off-grid points.
  await page.click('#tool-rect');
  await fx.drag(await fx.toPage(0.312, 0.287), await fx.toPage(0.538, 0.611));
  await settled(1);
  let [saved] = await saveJson();
  assert.deepEqual(saved.obstacles, [{ rect: [0.3, 0.3, 0.55, 0.6] }], 'exactly on the 0.05 grid, no float noise');

  // Resize its top-right corner, then move it by its inside: still on the grid.
  await page.click('#tool-select');
  await page.mouse.click(...(await fx.toPage(0.4, 0.4)));
  await fx.drag(await fx.toPage(0.55, 0.6), await fx.toPage(0.641, 0.683));
  await page.waitForFunction(() => window.planarium.scenario().obstacles[0].rect[2] === 0.65);
  await fx.drag(await fx.toPage(0.4, 0.4), await fx.toPage(0.433, 0.372));
  await page.waitForFunction(() => window.planarium.scenario().obstacles[0].rect[0] !== 0.3);
  await fx.waitState('idle');

  // A coarser grid: a circle from an off-grid centre, and the start dragged to an off-grid point.
  await page.fill('#grid-step', '0.1');
  await page.press('#grid-step', 'Enter');
  await page.click('#tool-circle');
  await fx.drag(await fx.toPage(0.79, 0.21), await fx.toPage(0.91, 0.23));
  await settled(2);
  await page.click('#tool-select');
  await fx.drag(await fx.toPage(0.1, 0.1), await fx.toPage(0.23, 0.17));
  await page.waitForFunction(() => window.planarium.scenario().start[0] === 0.2);
  await fx.waitState('idle');
  await page.mouse.move(...(await fx.toPage(0.437, 0.862)));
  await page.screenshot({ path: join(SHOTS, 'page-editor-tools-snap.png') });
  await page.locator('#obstacle-tools').screenshot({ path: join(SHOTS, 'page-editor-tools-panel.png') });

  [saved] = await saveJson();
  assert.deepEqual(saved.obstacles, [{ rect: [0.35, 0.25, 0.7, 0.65] }, { circle: [0.8, 0.2, 0.1] }]);
  assert.deepEqual(saved.start, [0.2, 0.2]);

  // A step out of bounds is refused, named, and the grid stays as it was.
  await page.fill('#grid-step', '1e9');
  await page.press('#grid-step', 'Enter');
  assert.match(await page.textContent('#grid-error'), /grid step must be a number from 0\.001 to 0\.5.*stays 0\.1/);
  assert.equal(await page.isVisible('#grid-error'), true);
  await page.fill('#grid-step', '0.25');
  await page.press('#grid-step', 'Enter');
  assert.equal(await page.isVisible('#grid-error'), false);

  // Off: no grid, and a drawn corner is only tidied (about 4 digits), not snapped.
  await page.uncheck('#snap-grid');
  assert.equal(await gridPixels(), 0);
  await page.click('#tool-rect');
  await fx.drag(await fx.toPage(0.112, 0.712), await fx.toPage(0.213, 0.813));
  await settled(3);
  const rect = (await scenario()).obstacles[2].rect;
  for (const v of rect) assert.equal(v, Number(v.toFixed(4)), `tidied: ${rect}`);
  assert.ok(Math.abs(rect[0] - 0.112) < 0.003 && Math.abs(rect[3] - 0.813) < 0.003, `not snapped to the 0.25 grid: ${rect}`);
});

test('the read-out shows the world coordinates under the pointer, and the grid point when snapping', async () => {
  await fx.pickScenario('open-field', 'Open field');
  assert.equal(await page.isVisible('#pointer-coords'), false);
  await page.mouse.move(...(await fx.toPage(0.3, 0.7)));
  const text = await page.textContent('#pointer-coords');
  const m = /^x (-?\d+\.\d{3}), y (-?\d+\.\d{3})$/.exec(text);
  assert.ok(m, text);
  assert.ok(Math.abs(Number(m[1]) - 0.3) <= 0.002 && Math.abs(Number(m[2]) - 0.7) <= 0.002, text);

  await page.check('#snap-grid');
  await page.mouse.move(...(await fx.toPage(0.312, 0.688)));
  assert.match(await page.textContent('#pointer-coords'), / · grid \(0\.3, 0\.7\)$/);

  // Leaving the canvas hides it.
  await page.mouse.move(5, 5);
  assert.equal(await page.isVisible('#pointer-coords'), false);

  // A large map: fewer decimals.
  await fx.pickScenario('technion-mp', 'Technion HW3: reach the goal');
  await page.uncheck('#snap-grid');
  await page.mouse.move(...(await fx.toPage(150.2, 80.7)));
  const big = /^x (\d+\.\d), y (\d+\.\d)$/.exec(await page.textContent('#pointer-coords'));
  assert.ok(big && Math.abs(Number(big[1]) - 150.2) <= 0.6 && Math.abs(Number(big[2]) - 80.7) <= 0.6, String(big));
});

test('name and notes: edited before saving, in the saved JSON and the copied link; too long is refused', async () => {
  await fx.pickScenario('open-field', 'Open field');
  assert.equal(await page.inputValue('#edit-name'), 'Open field', 'prefilled');
  assert.ok((await page.inputValue('#edit-notes')).length > 10, 'prefilled');

  await page.fill('#edit-name', 'Two rooms');
  await page.press('#edit-name', 'Tab');
  await page.fill('#edit-notes', 'Where does RRT get stuck?\nLook at the door.');
  // Save straight from the notes field: leaving it commits the notes first.
  const [saved, file] = await saveJson();
  assert.equal(saved.name, 'Two rooms');
  assert.equal(saved.notes, 'Where does RRT get stuck?\nLook at the door.');
  assert.equal(file, 'two-rooms.json');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Two rooms');
  await fx.waitState('idle');
  assert.equal(await page.textContent('#scenario-notes'), 'Where does RRT get stuck?\nLook at the door.');

  // Too long: named, refused, the scenario keeps its name.
  await page.fill('#edit-name', 'x'.repeat(121));
  assert.match(await page.textContent('#meta-error'), /name is 121 characters long \(at most 120\): shorten it/);
  await page.press('#edit-name', 'Tab');
  await page.fill('#edit-notes', 'y'.repeat(2001));
  assert.match(await page.textContent('#meta-error'), /notes are 2,001 characters long \(at most 2,000\): shorten them/);
  await page.press('#edit-notes', 'Tab');
  await page.locator('#obstacle-tools').screenshot({ path: join(SHOTS, 'page-editor-tools-meta-error.png') });
  assert.equal((await scenario()).name, 'Two rooms');
  assert.equal((await scenario()).notes, 'Where does RRT get stuck?\nLook at the door.');
  await page.fill('#edit-name', 'Two rooms');
  await page.fill('#edit-notes', 'Where does RRT get stuck?\nLook at the door.');
  await page.press('#edit-notes', 'Tab');
  assert.equal(await page.isVisible('#meta-error'), false);

  // The copied link opens the map with its name and notes in a fresh page.
  await page.click('#copy-link');
  await page.waitForFunction(() => document.getElementById('copy-status').textContent !== '');
  const link = await page.inputValue('#share-url');
  assert.ok(link.includes('#'), link);
  const other = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
  try {
    await other.goto(link);
    await other.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Two rooms');
    assert.equal(await other.textContent('#scenario-notes'), 'Where does RRT get stuck?\nLook at the door.');
    assert.equal(await other.inputValue('#edit-name'), 'Two rooms');
  } finally {
    await other.close();
  }

  // Undo takes the notes edit back, then the name edit.
  await page.click('#undo');
  await page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.scenario().notes !== 'Where does RRT get stuck?\nLook at the door.');
  await page.click('#undo');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Open field');
  assert.equal(await page.inputValue('#edit-name'), 'Open field');
});

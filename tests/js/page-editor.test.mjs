// The scenario editor in headless chromium, used like a person: draw a rectangle, a circle and a
// polygon on the canvas, move and resize, delete, undo and redo, set the bounds, cover the start
// (the core names it, the page stays usable, undo fixes it), save the scenario as JSON and read the
// file back, and plan on the edited scenario.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const scenario = () => page.evaluate(() => window.planarium.scenario());
const obstacles = async () => (await scenario()).obstacles;
const near = (a, b, tol = 0.01) => a.length === b.length && a.every((v, i) => Math.abs(v - b[i]) <= tol);
/** Wait until the worker has accepted the edit and the scenario holds `n` obstacles. */
const settled = (n) => page.waitForFunction((k) => window.planarium.state() === 'idle' && window.planarium.scenario()?.obstacles.length === k, n);

test('draw, move, resize, delete, undo and redo obstacles; bounds; save; plan', async () => {
  await fx.pickScenario('open-field', 'Open field');
  const n0 = (await obstacles()).length;

  // A rectangle, dragged out in a free corner.
  await page.click('#tool-rect');
  await fx.drag(await fx.toPage(0.85, 0.2), await fx.toPage(0.95, 0.35));
  await settled(n0 + 1);
  let last = (await obstacles()).at(-1);
  assert.ok(last.rect && near(last.rect, [0.85, 0.2, 0.95, 0.35]), JSON.stringify(last));

  // Undo removes it, redo brings it back.
  await page.click('#undo');
  await settled(n0);
  await page.click('#redo');
  await settled(n0 + 1);

  // Select it and move it by dragging its inside.
  await page.click('#tool-select');
  await fx.drag(await fx.toPage(0.9, 0.27), await fx.toPage(0.9, 0.12));
  await page.waitForFunction(() => window.planarium.scenario().obstacles.at(-1).rect[1] < 0.1);
  last = (await obstacles()).at(-1);
  assert.ok(near(last.rect, [0.85, 0.05, 0.95, 0.2]), `moved: ${last.rect}`);
  // Resize it by its top-right handle.
  await fx.drag(await fx.toPage(0.95, 0.2), await fx.toPage(0.98, 0.25));
  await page.waitForFunction(() => window.planarium.scenario().obstacles.at(-1).rect[3] > 0.22);
  last = (await obstacles()).at(-1);
  assert.ok(near(last.rect, [0.85, 0.05, 0.98, 0.25]), `resized: ${last.rect}`);

  // A circle from its centre, and a polygon by clicks closed with Enter.
  await page.click('#tool-circle');
  await fx.drag(await fx.toPage(0.12, 0.5), await fx.toPage(0.17, 0.5));
  await settled(n0 + 2);
  last = (await obstacles()).at(-1);
  assert.ok(last.circle && near(last.circle, [0.12, 0.5, 0.05]), JSON.stringify(last));
  await page.click('#tool-polygon');
  for (const [x, y] of [[0.6, 0.9], [0.7, 0.95], [0.65, 0.85]]) await page.mouse.click(...(await fx.toPage(x, y)));
  await page.keyboard.press('Enter');
  await settled(n0 + 3);
  last = (await obstacles()).at(-1);
  assert.ok(last.polygon?.length === 3 && near(last.polygon.flat(), [0.6, 0.9, 0.7, 0.95, 0.65, 0.85]), JSON.stringify(last));
  await page.screenshot({ path: join(SHOTS, 'page-editor.png') });

  // Select the circle and delete it with the Delete key.
  await page.click('#tool-select');
  await page.mouse.click(...(await fx.toPage(0.12, 0.5)));
  await page.keyboard.press('Delete');
  await settled(n0 + 2);
  assert.ok(!(await obstacles()).some((o) => o.circle && Math.abs(o.circle[0] - 0.12) < 1e-9));

  // Cover the start: the core names it, Run is refused, the page stays usable; undo fixes it.
  await page.click('#tool-rect');
  await fx.drag(await fx.toPage(0.03, 0.03), await fx.toPage(0.13, 0.13));
  await fx.waitState('invalid');
  assert.match(await page.textContent('#error-text'), /start/);
  assert.equal(await page.isDisabled('#run'), true);
  await page.click('#undo');
  await fx.waitState('idle');
  assert.equal(await page.isVisible('#error'), false);
  assert.equal((await obstacles()).length, n0 + 2);

  // The bounds: widen the map.
  await page.fill('#bounds-2', '1.2');
  await page.press('#bounds-2', 'Enter');
  await page.waitForFunction(() => window.planarium.scenario().bounds[2] === 1.2);

  // Save: the downloaded JSON is the scenario.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-scenario')]);
  const saved = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.deepEqual(saved, await scenario());

  // And it plans.
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
});

// The scene's 3-D boxes as numbers (www/ui/boxes3d.js), in headless chromium, typed like a person:
// the arm posed away from its start with the keyboard (a degree a press on joint 1), then the
// lintel shrunk to a 10 cm cube and its centre typed, a field at a time, to the posed tool point:
// the pose panel then says the arm collides, naming the lintel (the core's `collision` for the
// page's pose and the edited scene, computed here in Node too). An out-of-bounds centre (2e9) and a
// negative size are refused beside the field, naming the box and the field, with the core's own
// words, and leave the scenario as it was; a box moved into the start pose is refused naming the
// start (the box and the start's collision named). Remove and Add box change the list. Screenshot at 1280×800 to /tmp/boxes3d-1280.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, ROOT } from './browser.mjs';
import { initSync, Scene, builtins } from '../../www/pkg/planarium.js';

initSync({ module: readFileSync(join(ROOT, 'www/pkg/planarium_bg.wasm')) });
const puma = JSON.parse(builtins()).find((b) => b.id === 'puma-rbo-wall').scenario;
const core = new Scene(JSON.stringify(puma));
const PUMA_NAME = "Puma 560 through a window (report 001's course)";
const LINTEL = puma.obstacles3d.findIndex((o) => o.name === 'lintel');

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const pose = () => page.evaluate(() => window.planarium.view3d.pose());
const boxes = () => page.evaluate(() => window.planarium.view3d.boxes());
const scenario = () => page.evaluate(() => window.planarium.scenario());

/** Type `text` into field `id` of the boxes panel like a person: select it, type, press Enter. */
async function type(id, text) {
  const f = page.locator(`#${id}`);
  await f.click();
  await f.press('Control+A');
  await f.pressSequentially(String(text));
  await f.press('Enter');
}

/** Type into a field and wait until the edited scene is loaded (the status says it was applied). */
async function typeApplied(id, text) {
  const before = JSON.stringify(await scenario());
  await type(id, text);
  await page.waitForFunction((b) => JSON.stringify(window.planarium.scenario()) !== b
    && /^Applied/.test(window.planarium.view3d.boxes().status), before, { timeout: 20000 });
  await fx.waitState('idle');
}

async function openPuma() {
  await fx.pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await page.waitForFunction(() => window.planarium.view3d.pose().status.startsWith('Free'), null, { timeout: 20000 });
  await page.waitForSelector('#box3d-0-cx', { state: 'attached' });
  // the panel opens with a click on its title (closed at first; the test browser may have opened it)
  if (!(await page.$eval('#boxes3d details', (d) => d.open))) await page.click('#boxes3d summary');
  await page.waitForSelector('#box3d-0-cx');
}

test('puma-rbo-wall: the lintel typed into the posed arm makes the pose panel name it; out-of-bounds numbers are refused beside the field', async () => {
  assert.equal(await page.isHidden('#boxes3d'), true, 'no boxes panel for the first (2-D) scenario');
  await openPuma();
  assert.equal(await page.isVisible('#boxes3d'), true);
  const shown = await boxes();
  assert.equal(shown.rows.length, puma.obstacles3d.length, 'a row an obstacle');
  assert.deepEqual(shown.rows[LINTEL].values, {
    name: 'lintel', cx: '0.85', cy: '0', cz: '1.04', sx: '0.08', sy: '0.64', sz: '0.16',
  }, 'the lintel\'s numbers as in the file');

  // out of bounds: the core's words, beside the field, naming the box and the field; nothing changed
  const before = await scenario();
  await type(`box3d-${LINTEL}-cx`, '2e9');
  await page.waitForFunction((i) => window.planarium.view3d.boxes().rows[i].error !== '', LINTEL);
  let s = await boxes();
  console.log(`2e9: ${s.rows[LINTEL].error}`);
  assert.equal(s.rows[LINTEL].error, 'lintel, centre x: 2e9 is too large: numbers must lie between -1e9 and 1e9');
  assert.equal(await page.getAttribute(`#box3d-${LINTEL}-cx`, 'aria-invalid'), 'true');
  assert.equal(await page.getAttribute(`#box3d-${LINTEL}-cx`, 'aria-describedby'), `box3d-${LINTEL}-error`);
  assert.equal(await page.isVisible(`#box3d-${LINTEL}-error`), true, 'the error is shown under the box\'s row');
  assert.deepEqual(await scenario(), before, 'a refused edit leaves the scenario as it was');
  await type(`box3d-${LINTEL}-sy`, '-1');
  await page.waitForFunction((i) => /size y/.test(window.planarium.view3d.boxes().rows[i].error), LINTEL);
  s = await boxes();
  assert.equal(s.rows[LINTEL].error, "lintel, size y: a box's size must be positive");
  assert.equal(await page.getAttribute(`#box3d-${LINTEL}-cx`, 'aria-invalid'), 'false', 'only the field refused is marked');
  await type(`box3d-${LINTEL}-sz`, 'tall');
  await page.waitForFunction((i) => /size z/.test(window.planarium.view3d.boxes().rows[i].error), LINTEL);
  assert.equal((await boxes()).rows[LINTEL].error, 'lintel, size z: must be a number, found a string');
  assert.deepEqual(await scenario(), before);

  // a box moved into the arm at its start: the start would be refused, and it says so naming the box
  const startSk = core.skeleton(new Float64Array(puma.start));
  const startTool = [...startSk.slice(startSk.length - 3)];
  await typeApplied(`box3d-${LINTEL}-cz`, startTool[2].toFixed(3));
  await typeApplied(`box3d-${LINTEL}-cy`, startTool[1].toFixed(3));
  await type(`box3d-${LINTEL}-cx`, startTool[0].toFixed(3));
  await page.waitForFunction((i) => /start/.test(window.planarium.view3d.boxes().rows[i].error), LINTEL, { timeout: 20000 });
  s = await boxes();
  console.log(`into the start: ${s.rows[LINTEL].error}`);
  assert.match(s.rows[LINTEL].error, /^lintel, centre x: not applied, the start would be refused: in collision with obstacles3d\[3\], the lintel: /);
  assert.equal((await scenario()).obstacles3d[LINTEL].box.center[0], 0.85, 'the centre x refused is not in the scenario');

  // The arm posed 30° round the waist with the keyboard, then the lintel shrunk and typed onto its tool.
  await page.focus('#pose-q1');
  for (let i = 0; i < 30; i++) await page.keyboard.press('ArrowRight');
  const q = (await pose()).q;
  assert.equal((await pose()).collision, '', 'the posed arm is free');
  const sk = core.skeleton(new Float64Array(q));
  const tool = [...sk.slice(sk.length - 3)].map((v) => Number(v.toFixed(3)));
  for (const [id, v] of [['sx', 0.1], ['sy', 0.1], ['sz', 0.1], ['cz', 1.5], ['cx', tool[0]], ['cy', tool[1]]]) {
    await typeApplied(`box3d-${LINTEL}-${id}`, v);
    assert.equal((await pose()).collision, '', `the arm is still free after ${id} = ${v}`);
  }
  await typeApplied(`box3d-${LINTEL}-cz`, tool[2]);
  await page.waitForFunction(() => window.planarium.view3d.pose().collision !== '', null, { timeout: 20000 });
  const hit = await pose();
  console.log(`the lintel at the posed tool ${JSON.stringify(tool)}: ${hit.status}`);
  assert.deepEqual(hit.q, q, 'the pose stayed through the edits');
  const edited = await scenario();
  assert.deepEqual(edited.obstacles3d[LINTEL].box, { center: tool, size: [0.1, 0.1, 0.1] });
  const expected = new Scene(JSON.stringify(edited)).collision(new Float64Array(q));
  assert.equal(hit.collision, expected, 'the core\'s own answer for the edited scene');
  assert.match(hit.status, /^In collision .*meets the lintel/, 'the pose panel names the box');
  assert.match((await boxes()).status, /^Applied: lintel, centre z is now/);
  await page.locator('#boxes3d').scrollIntoViewIfNeeded();
  await page.screenshot({ path: '/tmp/boxes3d-1280.png' });

  // Remove it: the arm is free again; Add box: a new row
  await page.click(`#box3d-${LINTEL}-remove`);
  await page.waitForFunction((n) => window.planarium.scenario().obstacles3d.length === n - 1, puma.obstacles3d.length, { timeout: 20000 });
  await page.waitForFunction(() => window.planarium.view3d.pose().collision === '', null, { timeout: 20000 });
  assert.ok(!(await scenario()).obstacles3d.some((o) => o.name === 'lintel'));
  assert.equal((await boxes()).rows.length, puma.obstacles3d.length - 1);
  await page.click('#box3d-add');
  await page.waitForFunction((n) => window.planarium.scenario().obstacles3d.length === n, puma.obstacles3d.length, { timeout: 20000 });
  const added = (await scenario()).obstacles3d.at(-1);
  assert.deepEqual(added.box.size, [0.2, 0.2, 0.2]);
  await page.waitForFunction((n) => window.planarium.view3d.boxes().rows.length === n, puma.obstacles3d.length);
  assert.equal((await boxes()).rows.at(-1).values.name, added.name);
  assert.deepEqual(fx.errors, []);
});

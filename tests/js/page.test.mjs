// The page in headless chromium: built-in scenarios run to a solution and are drawn, invalid files
// are reported with their JSON path, playback controls and keys work, and a crashed worker is
// replaced. Screenshots go to target/page-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, ROOT as root, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { TRANSITIONS, toDot } from '../../www/run/controller.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, waitStatus, pickScenario, countColours, nextFrames } = fx;

async function setRange(id, value) {
  await page.$eval(`#${id}`, (el, v) => {
    el.value = String(v);
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
}

test('narrow passage: RRT-Connect solves and the canvas shows the trees and the smoothed path', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await page.selectOption('#planner', 'rrt-connect');
  await waitState('idle');
  await page.click('#run');
  await waitStatus('solved');
  assert.equal(await page.evaluate(() => window.planarium.state()), 'finished');
  const result = await page.evaluate(() => window.planarium.result());
  assert.equal(result.solved, true);
  assert.ok(result.smoothed.length >= 2);
  const drawn = await page.evaluate(() => window.planarium.nodeCount());
  assert.ok(drawn > 0, 'tree nodes were revealed');
  await nextFrames();
  const [path, tree0, tree1] = await countColours('canvas', [PALETTE.smoothPath, PALETTE.tree0, PALETTE.tree1], 6);
  console.log(`pixels: smoothed path ${path}, tree 0 ${tree0}, tree 1 ${tree1}; nodes shown ${drawn}`);
  assert.ok(path > 200, `smoothed path pixels: ${path}`);
  assert.ok(tree0 > 20, `tree 0 pixels: ${tree0}`);
  assert.ok(tree1 > 20, `tree 1 pixels: ${tree1}`);
  await page.screenshot({ path: join(shots, 'page-narrow.png') });
});

test('an invalid file is reported with its JSON path and the page stays usable', async () => {
  const bad = {
    format: 'planarium-scenario/1', name: 'Bad', bounds: [0, 0, 1, 1],
    obstacles: [{ polygon: [[0.2, 0.2], [0.3, 0.3]] }],
    robot: { kind: 'point' }, start: [0.1, 0.1], goal: [0.9, 0.9],
  };
  await page.setInputFiles('#file', { name: 'bad.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(bad, null, 2)) });
  await waitState('invalid');
  await page.waitForSelector('#error', { state: 'visible' });
  const message = await page.textContent('#error');
  assert.match(message, /obstacles\[0\]\.polygon/);
  assert.equal(await page.textContent('#status'), 'invalid');
  assert.equal(await page.isDisabled('#run'), true);

  // not even JSON: reported with a line and column
  await page.setInputFiles('#file', { name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from('{"format": ') });
  await page.waitForFunction(() => /line/.test(document.getElementById('error').textContent));

  await pickScenario('narrow', 'Narrow passage');
  await setRange('speed', 100);
  await page.click('#run');
  await waitStatus('solved');
  assert.equal(await page.isVisible('#error'), false, 'the error box is cleared by a good load');
});

test('slot: the rigid bar solves with RRT and the stats show iterations', async () => {
  await pickScenario('slot', 'Turn to pass the slot');
  await page.selectOption('#planner', 'rrt');
  await setRange('speed', 100);
  await waitState('idle');
  await page.click('#run');
  await waitStatus('solved');
  const iterations = Number((await page.textContent('#stat-iterations')).replace(/,/g, '')); // grouped: "1,234"
  assert.ok(iterations > 0, `iterations: ${iterations}`);
  const stats = await page.evaluate(() => window.planarium.stats());
  assert.equal(stats.iterations, iterations);
  assert.ok(stats.nodes > 0 && stats.checks > 0 && stats.cost > 0);
  await page.waitForTimeout(400); // let the bar move along the path for the picture
  await page.screenshot({ path: join(shots, 'page-slot.png') });
});

test('playback: pause, step one event, step iterations, reset and keys', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await setRange('speed', 0); // 10 events per second
  await page.click('#run');
  await page.waitForFunction(() => window.planarium.stats().shown_events > 2);
  await page.click('#pause');
  await waitState('paused');
  const before = await page.evaluate(() => window.planarium.stats().shown_events);
  await page.click('#step-event');
  await page.waitForFunction((n) => window.planarium.stats().shown_events === n + 1, before);

  await page.click('#reset');
  await waitState('idle');
  assert.equal(await page.evaluate(() => window.planarium.nodeCount()), 0);

  // Step from idle runs exactly that many iterations and shows them at once
  await page.fill('#step-size', '50');
  await page.click('#step');
  await page.waitForFunction(() => window.planarium.stats().iterations === 50 && window.planarium.stats().queued_events === 0);
  assert.equal(await page.evaluate(() => window.planarium.state()), 'paused');
  // with nothing buffered, "step one event" asks the planner for one more iteration and shows one event
  const shown = await page.evaluate(() => window.planarium.stats().shown_events);
  await page.click('#step-event');
  // (the stats' iterations are those drawn: 50 and one event of the 51st; the planner's are 51)
  await page.waitForFunction((n) => {
    const s = window.planarium.stats();
    return s.shown_events === n + 1 && (s.planner_iterations ?? s.iterations) === 51 && s.iterations === 50;
  }, shown);

  await page.click('#reset');
  await waitState('idle');

  // keys act when focus is not in an input
  await page.click('#canvas');
  await page.keyboard.press(' ');
  await waitState('running');
  await page.keyboard.press(' ');
  await waitState('paused');
  await page.keyboard.press('r');
  await waitState('idle');
  await page.keyboard.press('ArrowRight');
  await waitState('paused');
  await page.focus('#step-size');
  await page.keyboard.press('r');
  assert.equal(await page.evaluate(() => window.planarium.state()), 'paused', 'keys in an input are left alone');
});

test('a crashed worker is replaced and the page keeps working', async () => {
  await pickScenario('narrow', 'Narrow passage');
  const [worker] = page.workers();
  assert.ok(worker, 'the planning worker is running');
  await worker.evaluate(() => self.onmessage({ data: { type: 'debug-panic', message: 'test panic' } }));
  await page.waitForFunction(() => /test panic/.test(document.getElementById('error').textContent));
  await waitState('idle');
  assert.equal(await page.textContent('#scenario-name'), 'Narrow passage');
  await setRange('speed', 100);
  await page.click('#run');
  await waitStatus('solved');
});

test('docs/state-diagram.gv is the controller table', () => {
  assert.equal(readFileSync(join(root, 'docs', 'state-diagram.gv'), 'utf8'), toDot(TRANSITIONS));
  for (const edges of Object.values(TRANSITIONS)) {
    for (const to of Object.values(edges)) assert.ok(TRANSITIONS[to], `unknown state ${to}`);
  }
});

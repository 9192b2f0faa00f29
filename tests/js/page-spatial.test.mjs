// Report 001's Puma 560 in the page (headless chromium), until its 3-D view comes: the course's
// scene loads with the course's planner, the arm is drawn from above as its skeleton, its joints
// are sliders within their limits, and a run in the worker gives the native run's counts for the
// same seed (13,909 nodes, 695,733 collision queries for seed 1, `tests/golden/runs.json`).
// Screenshots go to target/page-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageFixture, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitStatus, pickScenario, countColours, nextFrames, fastPlayback } = fx;

test('puma-rbo-wall: the course planner, the arm from above, joint sliders within the limits', async () => {
  await pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
  await nextFrames();
  const sc = await page.evaluate(() => window.planarium.scenario());
  assert.equal(sc.robot.joints.length, 6);
  assert.equal(await page.inputValue('#planner'), 'rrt-connect');
  assert.equal(await page.inputValue('#param-connect'), 'last-free');
  assert.equal(await page.isVisible('#param-epsilon'), true, 'epsilon is shown for the last-free connect');
  // Six sliders per end, each within its joint's limits and at the scenario's angle.
  for (const which of ['start', 'goal']) {
    const sliders = await page.$$eval(`#${which}-joints input[type=range]`, (els) => els.map((e) => [Number(e.min), Number(e.max), Number(e.value)]));
    assert.equal(sliders.length, 6, which);
    sliders.forEach(([lo, hi, v], i) => {
      assert.ok(Math.abs(lo - sc.robot.joints[i].limits[0]) < 1e-9 && Math.abs(hi - sc.robot.joints[i].limits[1]) < 1e-9, `${which} joint ${i}: ${lo}..${hi}`);
      assert.ok(Math.abs(v - sc[which][i]) < 1e-9, `${which} joint ${i} at ${v}`);
    });
  }
  // The start and goal skeletons are drawn (seen from above).
  const [start, goal] = await countColours('canvas', [PALETTE.start, PALETTE.goal]);
  console.log(`skeletons from above: start ${start}, goal ${goal} pixels`);
  assert.ok(start > 100 && goal > 100, `start ${start}, goal ${goal}`);
  await page.screenshot({ path: join(shots, 'page-puma-loaded.png') });
  // A slider pushed to its limit keeps the joint within it (rounding 0.785398 to four places
  // would leave it: 0.7854).
  const k = sc.robot.joints.findIndex((j) => Math.abs(Number(j.limits[1].toFixed(4)) - j.limits[1]) > 0 && Number(j.limits[1].toFixed(4)) > j.limits[1]);
  assert.ok(k >= 0, 'a joint whose upper limit rounds up');
  await page.$eval(`#start-q${k + 1}`, (el) => {
    el.value = el.max;
    el.dispatchEvent(new Event('input', { bubbles: true }));
    el.dispatchEvent(new Event('change', { bubbles: true }));
  });
  const hi = sc.robot.joints[k].limits[1];
  await page.waitForFunction(([k, hi]) => Math.abs(window.planarium.scenario().start[k] - hi) < 1e-3, [k, hi]);
  const moved = await page.evaluate(() => window.planarium.scenario().start);
  assert.ok(moved[k] <= hi, `joint ${k + 1} at ${moved[k]}, past its limit ${hi}`);
});

test('puma-rbo-wall: a run in the worker gives the native counts for seed 1', async () => {
  await pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
  await fastPlayback();
  const t0 = Date.now();
  await page.click('#run');
  await waitStatus('solved', 240000);
  const r = await page.evaluate(() => window.planarium.result());
  console.log(`worker run: ${r.stats.nodes} nodes, ${r.stats.checks} queries (${r.stats.free_checks} free), ${r.stats.time_ms.toFixed(0)} ms planning, ${Date.now() - t0} ms to solved on the page`);
  assert.equal(r.seed, 1);
  assert.equal(r.stats.nodes, 13909);
  assert.equal(r.stats.checks, 695733);
  assert.equal(r.stats.free_checks, 668000);
  await nextFrames();
  await page.screenshot({ path: join(shots, 'page-puma-solved.png') });
});

test('puma-rbo-wall: range is not offered in last-free mode; switching connect shows it and hides epsilon, values kept', async () => {
  await pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
  assert.equal(await page.inputValue('#param-connect'), 'last-free');
  const shown = (name) => page.isVisible(`#param-${name}`);
  assert.equal(await shown('range'), false, 'range is not used by the last-free connect');
  assert.equal(await shown('ladder'), false, 'ladder steps are range steps');
  assert.equal(await shown('epsilon'), true);
  await page.selectOption('#param-connect', 'range');
  assert.equal(await shown('range'), true, 'range steps the range connect');
  assert.equal(await shown('ladder'), true);
  assert.equal(await shown('epsilon'), false, 'epsilon is the last-free connect\'s');
  await page.fill('#param-range', '0.3');
  await page.dispatchEvent('#param-range', 'change');
  await page.selectOption('#param-connect', 'last-free');
  assert.equal(await shown('range'), false);
  assert.equal(await shown('epsilon'), true);
  await page.selectOption('#param-connect', 'range');
  assert.equal(await page.inputValue('#param-range'), '0.3', 'the value is kept while hidden');
});

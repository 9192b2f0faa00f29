// The compare page in headless chromium: two set-ups (RRT-Connect with the uniform sampler and
// with the Gaussian sampler) on the narrow passage, same seed, two workers and two canvases,
// started, paused, reset and run to the end together; both finish, with different stats.
// Screenshot: target/page-compare.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageFixture, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, countColours } = fx;

async function setSpeed(v) {
  await page.$eval('#speed', (el, v) => {
    el.value = String(v === 'max' ? el.max : v);
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, v);
}

test('compare: uniform against Gaussian RRT-Connect on the same seed, run together, both finish with different stats', async () => {
  // from the playground's link, on the scenario shown there
  await page.selectOption('#scenario', 'narrow');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Narrow passage');
  await waitState('idle');
  await page.click('#to-compare');
  await page.waitForURL(/compare\.html\?scenario=narrow/);
  await page.waitForFunction(() => window.planarium?.state() === 'idle' && document.getElementById('scenario-name').textContent === 'Narrow passage', null, { timeout: 30000 });
  assert.equal(page.workers().length, 2, 'one worker per set-up');

  await page.selectOption('#a-planner', 'rrt-connect');
  await waitState('idle');
  await page.selectOption('#b-planner', 'rrt-connect');
  await waitState('idle');
  await page.selectOption('#b-param-sampler', 'gaussian');
  await waitState('idle');
  await page.fill('#seed', '3');
  await page.dispatchEvent('#seed', 'change');
  await waitState('idle');
  const [a, b] = await page.evaluate(() => [window.planarium.config('a'), window.planarium.config('b')]);
  assert.equal(a.seed, 3);
  assert.equal(b.seed, 3);
  assert.equal(a.params.sampler, undefined, 'A keeps the default (uniform) sampler');
  assert.equal(b.params.sampler, 'gaussian');
  assert.match(await page.textContent('#b-title'), /gaussian/);

  // started and paused together
  await setSpeed(0);
  await page.click('#run');
  await waitState('running');
  await page.waitForFunction(() => window.planarium.stats('a').shown_events > 0 && window.planarium.stats('b').shown_events > 0);
  await page.click('#pause');
  await waitState('paused');
  assert.equal(await page.textContent('#a-status'), 'paused');
  assert.equal(await page.textContent('#b-status'), 'paused');
  // reset together
  await page.click('#reset');
  await waitState('idle');
  const cleared = await page.evaluate(() => [window.planarium.stats('a').shown_events, window.planarium.stats('b').shown_events]);
  assert.deepEqual(cleared, [0, 0]);

  // run both to the end
  await setSpeed('max');
  await page.click('#run');
  await waitState('finished', 120000);
  const [sa, sb] = await page.evaluate(() => [window.planarium.stats('a'), window.planarium.stats('b')]);
  console.log(`A: ${sa.status}, ${sa.iterations} iterations, ${sa.nodes} nodes, ${sa.checks} checks, sampler ${sa.sampler.name} ` +
    `(${sa.sampler.draws_per_sample.toFixed(2)} draws/sample); B: ${sb.status}, ${sb.iterations} iterations, ${sb.nodes} nodes, ` +
    `${sb.checks} checks, sampler ${sb.sampler.name} (${sb.sampler.draws_per_sample.toFixed(2)} draws/sample)`);
  assert.equal(sa.status, 'solved');
  assert.equal(sb.status, 'solved');
  assert.equal(await page.textContent('#a-status'), 'solved');
  assert.equal(await page.textContent('#b-status'), 'solved');
  assert.equal(sa.sampler.name, 'uniform');
  assert.equal(sb.sampler.name, 'gaussian');
  assert.ok(sb.sampler.draws_per_sample > sa.sampler.draws_per_sample, 'the Gaussian sampler draws more per sample');
  assert.notEqual(sa.checks, sb.checks);
  assert.notDeepEqual([sa.iterations, sa.nodes], [sb.iterations, sb.nodes]);
  assert.equal(await page.textContent('#a-stat-sampler'), 'uniform');
  assert.equal(await page.textContent('#b-stat-sampler'), 'gaussian');
  assert.notEqual(await page.textContent('#a-stat-checks'), await page.textContent('#b-stat-checks'));
  const [ra, rb] = await page.evaluate(() => [window.planarium.result('a'), window.planarium.result('b')]);
  assert.equal(ra.seed, 3);
  assert.equal(rb.seed, 3);
  assert.notDeepEqual(ra.path, rb.path);

  // both canvases show their trees and their smoothed paths
  await page.waitForTimeout(300);
  for (const key of ['a', 'b']) {
    const [path, tree0, tree1] = await countColours(`${key}-canvas`, [PALETTE.smoothPath, PALETTE.tree0, PALETTE.tree1], 6);
    console.log(`${key}: smoothed path ${path}, tree 0 ${tree0}, tree 1 ${tree1} pixels`);
    assert.ok(path > 100, `${key}: smoothed path pixels ${path}`);
    assert.ok(tree0 + tree1 > 10, `${key}: tree pixels ${tree0} + ${tree1}`);
  }
  await page.screenshot({ path: join(shots, 'page-compare.png') });

  // Run again from finished: both start over together
  await page.click('#run');
  await waitState('finished', 120000);
  const again = await page.evaluate(() => [window.planarium.stats('a').checks, window.planarium.stats('b').checks]);
  assert.deepEqual(again, [sa.checks, sb.checks], 'the same seed replays the same runs');
});

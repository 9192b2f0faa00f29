// The per-iteration overlays in the page (headless chromium): the parameter panel's shared groups,
// the sampler's raw tries and the dynamic-domain circles on the narrow passage, each switched on
// and off by its checkbox (canvas pixels counted), and the overlay state kept across a scenario
// change. Screenshots go to target/page-overlays-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageFixture, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { thinTries, TRY_KEEP } from '../../www/worker/thin.js';
import { STRIDE, EventKind } from '../../www/run/events.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, waitStatus, pickScenario, countColours, nextFrames, fastPlayback, setField } = fx;

async function toggle(id) {
  await page.click(`#${id}`);
  await nextFrames();
}

test('the raw tries beyond the first TRY_KEEP are thinned, every other record kept', () => {
  const n = 3 * TRY_KEEP;
  const data = new Float64Array((n + 10) * STRIDE);
  for (let i = 0; i < n + 10; i++) data[i * STRIDE] = i < 10 ? EventKind.NODE_ADDED : EventKind.SAMPLE_TRY;
  const counter = { seen: 0, sent: 0 };
  const out = thinTries(data, counter);
  const kinds = [];
  for (let i = 0; i < out.length; i += STRIDE) kinds.push(out[i]);
  assert.equal(kinds.filter((k) => k === EventKind.NODE_ADDED).length, 10);
  assert.equal(counter.seen, n);
  // all of the first TRY_KEEP, half of the next TRY_KEEP, a quarter of the rest
  assert.equal(counter.sent, TRY_KEEP + TRY_KEEP / 2 + TRY_KEEP / 4);
  assert.equal(kinds.length, 10 + counter.sent);
  // below the cap nothing changes
  const small = new Float64Array(5 * STRIDE).fill(0);
  for (let i = 0; i < 5; i++) small[i * STRIDE] = EventKind.SAMPLE_TRY;
  assert.equal(thinTries(small, { seen: 0, sent: 0 }), small);
});

test('the panel shows the sampler and tree-variant groups as their own fieldsets', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  const groups = await page.$$eval('#param-groups fieldset', (fs) => fs.map((f) => ({
    group: f.dataset.group, legend: f.querySelector('legend').textContent,
    names: [...f.querySelectorAll('input, select')].map((i) => i.name),
  })));
  assert.deepEqual(groups.map((g) => g.group), ['sampler', 'tree']);
  assert.ok(groups[0].names.includes('sampler') && groups[0].names.includes('sigma'), groups[0].names.join());
  assert.ok(!groups[0].names.includes('goal_bias'), "RRT's own goal bias replaces the sampler group's");
  assert.deepEqual(groups[1].names, ['dd_radius', 'dd_adaptive', 'dd_min_radius', 'exhausted', 'exhausted_policy', 'ladder']);
  // RRT* has no tree variants
  await page.selectOption('#planner', 'rrt-star');
  await waitState('idle');
  assert.deepEqual(await page.$$eval('#param-groups fieldset', (fs) => fs.map((f) => f.dataset.group)), ['sampler']);
  // a group value is shared by the planners that have the group
  await page.selectOption('#param-sampler', 'gaussian');
  await waitState('idle');
  await page.selectOption('#planner', 'rrt-connect');
  await waitState('idle');
  assert.equal(await page.$eval('#param-sampler', (s) => s.value), 'gaussian');
});

test('narrow, bridge sampler and dynamic domains: raw tries and domain circles switch on and off', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  await page.selectOption('#param-sampler', 'bridge');
  await waitState('idle');
  await setField('param-sigma', 0.1);
  await setField('param-dd_radius', 0.1);
  await setField('run-max_iterations', 3000);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 90000); // solved or out of iterations: either draws tries and domains
  assert.match(await page.textContent('#status'), /^(solved|iteration_limit)$/);
  const stats = await page.evaluate(() => window.planarium.stats());
  assert.equal(stats.sampler.name, 'bridge');
  assert.ok(stats.sampler.draws_per_sample > 10, `bridge draws per sample: ${stats.sampler.draws_per_sample}`);
  assert.ok(Number(await page.textContent('#stat-draws')) > 10, 'the stats panel shows draws per sample');
  assert.ok(Number(await page.textContent('#stat-sampler-checks')) > 10, 'the stats panel shows checks per sample');
  const model = await page.evaluate(() => window.planarium.model());
  assert.ok(model.tries > 1000, `raw tries shown: ${model.tries}`);
  assert.ok(model.trees[0].domains > 0, `nodes with a domain: ${model.trees[0].domains}`);
  assert.match(await page.textContent('#stat-tries'), /of/);

  const tries = () => countColours('canvas', [PALETTE.tryFree, PALETTE.tryOccupied], 4);
  const domains = async () => (await countColours('canvas', [PALETTE.domain], 24))[0];
  await nextFrames();

  // raw tries: off by default, on, off
  assert.equal(await page.isChecked('#show-tries'), false);
  const [free0, occ0] = await tries();
  assert.equal(free0 + occ0, 0, `no raw tries drawn while the overlay is off (${free0}, ${occ0})`);
  await toggle('show-tries');
  const [free1, occ1] = await tries();
  console.log(`raw tries: free ${free1}, occupied ${occ1} pixels`);
  assert.ok(free1 > 200, `free tries pixels: ${free1}`);
  assert.ok(occ1 > 200, `occupied tries pixels: ${occ1}`);
  await page.screenshot({ path: join(shots, 'page-overlays-tries.png') });
  await toggle('show-tries');
  const [free2, occ2] = await tries();
  assert.equal(free2 + occ2, 0, `raw tries gone again (${free2}, ${occ2})`);

  // domain circles: on by default, off, on
  assert.equal(await page.isChecked('#show-domains'), true);
  const dd1 = await domains();
  console.log(`domain circle pixels: ${dd1}`);
  assert.ok(dd1 > 100, `domain circle pixels: ${dd1}`);
  await page.screenshot({ path: join(shots, 'page-overlays-dd.png') });
  await toggle('show-domains');
  const dd2 = await domains();
  assert.ok(dd2 < dd1 / 20, `domain circles gone: ${dd2} pixels left of ${dd1}`);
  await toggle('show-domains');
  assert.ok(await domains() > dd1 / 2, 'domain circles back');

  // the overlay choices stay when the scenario changes
  await toggle('show-tries');
  await pickScenario('open-field', 'Open field');
  assert.equal(await page.isChecked('#show-tries'), true);
  assert.equal(await page.isChecked('#show-domains'), true);
});

test('Informed RRT*: the informed set is drawn as an ellipse that shrinks with each better path, switched by its box', async () => {
  await pickScenario('open-field', 'Open field');
  await page.selectOption('#planner', 'rrt-star');
  await waitState('idle');
  assert.equal(await page.isHidden('label[data-option="showInformed"]'), true, 'RRT* offers no informed set');
  await page.selectOption('#planner', 'informed-rrt-star');
  await waitState('idle');
  assert.equal(await page.isVisible('label[data-option="showInformed"]'), true, 'Informed RRT* offers its informed set');
  await setField('param-improve_for', 600);
  await fastPlayback();
  await page.click('#run');
  await waitStatus('solved');
  await nextFrames();
  const model = await page.evaluate(() => window.planarium.model());
  assert.ok(model.informed.length >= 2, `ellipses: ${model.informed.length}`);
  // one ellipse per better cost, each the set of that cost: major axis = the cost, shrinking
  assert.equal(model.informed.length, model.costs.length);
  model.informed.forEach((e, i) => {
    assert.equal(e[6], model.costs[i][1]);
    assert.ok(Math.abs(2 * e[2] - e[6]) < 1e-12);
    if (i) assert.ok(e[2] < model.informed[i - 1][2], `ellipse ${i} smaller than the one before`);
  });
  const ink = async () => (await countColours('canvas', [PALETTE.informed], 6))[0];
  // The latest ellipse's own outline, in canvas pixels: 360 points of it, read where they fall.
  const [cx, cy, a, b, ux, uy] = model.informed[model.informed.length - 1];
  const outline = [];
  for (let k = 0; k < 360; k++) {
    const t = (k * Math.PI) / 180;
    const [ex, ey] = [a * Math.cos(t), b * Math.sin(t)];
    outline.push(await page.evaluate(([x, y]) => window.planarium.toCanvas(x, y), [cx + ex * ux - ey * uy, cy + ex * uy + ey * ux]));
  }
  // How many outline points have the informed colour within a pixel of them.
  const onOutline = () => page.evaluate(({ pts, hex }) => {
    const c = document.getElementById('canvas');
    const dpr = c.width / c.clientWidth;
    const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const rgb = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
    return pts.filter(([x, y]) => {
      for (let dy = -1; dy <= 1; dy++) {
        for (let dx = -1; dx <= 1; dx++) {
          const [i, j] = [Math.round(x * dpr) + dx, Math.round(y * dpr) + dy];
          if (i < 0 || j < 0 || i >= c.width || j >= c.height) continue;
          const o = 4 * (j * c.width + i);
          if (rgb.every((v, m) => Math.abs(px[o + m] - v) <= 24)) return true;
        }
      }
      return false;
    }).length;
  }, { pts: outline, hex: PALETTE.informed });
  const on = await ink();
  const onLine = await onOutline();
  console.log(`informed set: ${model.informed.length} ellipses, ${on} pixels; latest outline: ${onLine} of 360 points inked`);
  assert.ok(on > 300, `informed-set pixels: ${on}`);
  assert.ok(onLine > 300, `the latest ellipse is drawn where it is: ${onLine} of 360 outline points`);
  await page.screenshot({ path: join(shots, 'page-overlays-informed.png') });
  await toggle('show-informed');
  const offLine = await onOutline();
  console.log(`switched off: ${offLine} of 360 outline points in its colour`);
  // Tree edges crossing the outline may come near the colour at a few points; the ellipse itself is gone.
  assert.ok(offLine < 36, `ellipse gone: ${offLine} of 360 outline points still in its colour`);
  await toggle('show-informed');
  assert.ok((await onOutline()) > 300, 'and back when switched on again');
});

test('accepted and rejected samples are drawn in their own colours when switched on', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await fastPlayback();
  await page.click('#run');
  await waitStatus('solved');
  await nextFrames();
  const colours = () => countColours('canvas', [PALETTE.accepted, PALETTE.rejected], 4);
  // (a few anti-aliased pixels of the animated robot, grey at 55% over the scene, can match the
  // rejected grey by chance, depending on where it is: off means fewer than 10, on more than 20)
  const off = await colours();
  assert.ok(off[0] < 10 && off[1] < 10, `both off by default: ${off}`);
  await toggle('show-accepted');
  await toggle('show-rejected');
  const [accepted, rejected] = await colours();
  console.log(`samples: accepted ${accepted}, rejected ${rejected} pixels`);
  assert.ok(accepted > 40 && rejected > 20, `accepted ${accepted}, rejected ${rejected}`);
  await toggle('show-accepted');
  const [acceptedOff, rejectedOn] = await colours();
  assert.ok(acceptedOff < 10, `accepted off: ${acceptedOff}`);
  assert.ok(rejectedOn > 20);
});

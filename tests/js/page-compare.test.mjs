// The compare page in headless chromium: two set-ups (RRT-Connect with the uniform sampler and
// with the Gaussian sampler) on the narrow passage, same seed, two workers and two canvases,
// started, paused, reset and run to the end together; both finish, with different stats.
// Screenshot: target/page-compare.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { canvasPixels, pageFixture, ROOT, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { initSync, planners } from '../../www/pkg/planarium.js';

initSync({ module: readFileSync(join(ROOT, 'www/pkg/planarium_bg.wasm')) });
/** The core registry's entry for a planner (its label and its words for an iteration and a check). */
const specOf = (name) => JSON.parse(planners()).planners.find((p) => p.name === name);

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
  // the link carries the playground's state (its share hash), written a moment after each change
  await page.waitForFunction(() => /#.*scenario=narrow/.test(document.getElementById('to-compare').getAttribute('href')));
  await page.click('#to-compare');
  await page.waitForURL(/compare\.html#.*scenario=narrow/);
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
  // the counts grouped as the status strip groups them
  assert.equal(await page.textContent('#a-stat-nodes'), sa.nodes.toLocaleString('en'));
  assert.equal(await page.textContent('#b-stat-checks'), sb.checks.toLocaleString('en'));
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

// Issue 14: state in the URL, Open file…, Run 20 seeds, a phone's tabs.

/** Open compare.html with `hash` as a fresh page load, waiting until both lanes are loaded and idle. */
async function openCompare(hash = '') {
  await page.goto('about:blank');
  await page.goto(`${fx.env.base}compare.html${hash}`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle' && window.planarium.scenario(), null, { timeout: 30000 });
}

test('compare keeps scenario, both set-ups and the seed in the URL: a reload restores them; bad values are named', async () => {
  await openCompare('#scenario=slot&a=rrt%20--goal-bias%200.3&b=rrt-connect%20--sampler%20gaussian&seed=5');
  assert.equal(await page.$eval('#scenario', (s) => s.value), 'slot');
  assert.equal(await page.$eval('#seed', (s) => s.value), '5');
  assert.deepEqual(await page.evaluate(() => [window.planarium.config('a'), window.planarium.config('b')]), [
    { planner: 'rrt', params: { goal_bias: 0.3 }, seed: 5 }, { planner: 'rrt-connect', params: { sampler: 'gaussian' }, seed: 5 }]);
  assert.equal(await page.$eval('#a-planner', (s) => s.value), 'rrt');
  assert.equal(await page.$eval('#a-param-goal_bias', (s) => s.value), '0.3');
  assert.equal(await page.isVisible('#error'), false, 'a good link shows no error');
  // change B through its menus and the seed: the URL follows; a reload restores it
  await page.selectOption('#b-planner', 'rrt-star');
  await waitState('idle');
  await page.fill('#seed', '9');
  await page.dispatchEvent('#seed', 'change');
  await page.waitForFunction(() => /&b=rrt-star(%20|&)/.test(location.hash) && /seed=9$/.test(location.hash));
  await page.reload();
  await page.waitForFunction(() => window.planarium?.state() === 'idle' && window.planarium.scenario(), null, { timeout: 30000 });
  const b = await page.evaluate(() => window.planarium.config('b'));
  assert.equal(b.planner, 'rrt-star');
  assert.equal(b.seed, 9);
  // a seed above 2^53 − 1: refused by name, the field shows the seed both lanes and Run 20 seeds use
  await page.fill('#seed', '9007199254740993');
  await page.dispatchEvent('#seed', 'change');
  assert.equal(await page.inputValue('#seed'), '9');
  assert.equal(await page.textContent('#seed-hint'), 'Seed: 9007199254740993 is larger than 9007199254740991 (2^53 − 1), the largest seed the page carries exactly; the seed stays 9.');
  assert.equal((await page.evaluate(() => window.planarium.config('b'))).seed, 9);
  assert.equal(await page.textContent('#seeds-range'), '9 … 28');
  assert.equal((await page.evaluate(() => window.planarium.config('a'))).params.goal_bias, 0.3);
  assert.equal((await page.evaluate(() => window.planarium.scenario())).name, 'Turn to pass the slot');
  // bad values: each named, defaults used
  await openCompare('#scenario=narrow&a=nope&b=rrt%20--range%20-1&seed=abc');
  const error = await page.textContent('#error-text');
  assert.match(error, /seed=abc: the seed is not a whole number from 0 to 9007199254740991; the scenario's seed is used/);
  assert.match(error, /a=nope: set-up line 1: unknown planner "nope".*set-up A keeps its default/);
  assert.match(error, /b=rrt --range -1: set-up line 1: range: must be between 0 and 1000000; set-up B keeps its default/);
  assert.deepEqual(await page.evaluate(() => [window.planarium.config('a').planner, window.planarium.config('b').params]), ['rrt-connect', {}]);
  await page.screenshot({ path: join(shots, 'page-compare-bad-link.png') });
  // a playground link's state (planner and parameters) opens as set-up A
  await openCompare('#scenario=narrow&planner=rrt&seed=4&goal_bias=0.3');
  assert.deepEqual(await page.evaluate(() => window.planarium.config('a')), { planner: 'rrt', params: { goal_bias: 0.3 }, seed: 4 });
  assert.equal(await page.isVisible('#error'), false);
});

test('compare: the wheel over one lane zooms both about the same world point, a middle drag pans both, the link carries the zoom, Fit in the other lane fits both', async () => {
  await openCompare('#scenario=narrow&a=rrt&b=rrt-connect&seed=3');
  await setSpeed('max');
  await page.click('#run');
  await waitState('finished', 120000);
  await fx.nextFrames();
  const lanePoint = async (key, x, y) => {
    const box = await page.locator(`#${key}-canvas`).boundingBox();
    const [cx, cy] = await page.evaluate(([x, y, key]) => window.planarium.toCanvas(x, y, key), [x, y, key]);
    return [box.x + cx, box.y + cy];
  };
  const settled = () => page.waitForFunction(() => ['a', 'b'].every((k) => window.planarium.viewport(k).settled), null, { timeout: 30000 });
  const before = await canvasPixels(page, 'b-canvas');
  assert.equal(await page.isVisible('#a-stage .plane-zoom'), false, 'no bar over a fitted lane');

  // the wheel over the gap in lane A
  const at = await lanePoint('a', 0.5, 0.5);
  await page.mouse.move(...at);
  await page.mouse.wheel(0, -800); // exp(800 · 0.0015) = 3.3×
  await settled();
  const [va, vb] = await page.evaluate(() => [window.planarium.viewport('a'), window.planarium.viewport('b')]);
  assert.ok(va.zoom > 3 && va.zoom < 3.5, `lane A zoomed 3.3× (${va.zoom})`);
  assert.deepEqual(vb.viewport, va.viewport, 'lane B shows the same region');
  const [ax, ay] = await lanePoint('a', 0.5, 0.5);
  // within 1.5 px: the lane's canvas sits at a fractional page position, and a wheel event's
  // offsetX and offsetY are whole pixels
  assert.ok(Math.abs(ax - at[0]) < 1.5 && Math.abs(ay - at[1]) < 1.5, `the point under the pointer stays there: (${ax}, ${ay}) against (${at[0]}, ${at[1]})`);
  const inA = await page.evaluate(() => window.planarium.toCanvas(0.45, 0.55, 'a'));
  const inB = await page.evaluate(() => window.planarium.toCanvas(0.45, 0.55, 'b'));
  assert.ok(Math.hypot(inA[0] - inB[0], inA[1] - inB[1]) < 1e-6, `a world point sits at the same place in both lanes: ${inA} and ${inB}`);
  assert.equal(await page.isVisible('#a-stage .plane-zoom'), true);
  assert.match(await page.textContent('#b-stage [data-zoom="fit"]'), /^Fit \(3\.\d×\)$/);
  const zoomed = await canvasPixels(page, 'b-canvas');
  let changed = 0;
  for (let i = 0; i < zoomed.data.length; i += 4) if (Math.abs(zoomed.data[i] - before.data[i]) > 60) changed++;
  assert.ok(changed > zoomed.w * zoomed.h * 0.02, `lane B's picture is zoomed (${changed} pixels changed)`);
  await page.screenshot({ path: join(shots, 'page-compare-zoom.png') });

  // a middle drag in lane B pans both
  const from = await lanePoint('b', 0.5, 0.5);
  await page.mouse.move(...from);
  await page.mouse.down({ button: 'middle' });
  for (let i = 1; i <= 4; i++) await page.mouse.move(from[0] + 10 * i, from[1] + 5 * i);
  await page.mouse.up({ button: 'middle' });
  await settled();
  const [pa, pb] = await page.evaluate(() => [window.planarium.viewport('a'), window.planarium.viewport('b')]);
  assert.ok(pa.viewport.cx < va.viewport.cx && pa.viewport.cy > va.viewport.cy, 'dragged right and down, both look left and up');
  assert.deepEqual(pb.viewport, pa.viewport);

  // the link carries it: a fresh page opens both lanes at the same zoom and centre
  // (written 200 ms after the last move)
  await page.waitForFunction(() => {
    const m = /[#&]zoom=([^&]*)/.exec(location.hash);
    const v = window.planarium.viewport('a').viewport;
    return m && v && decodeURIComponent(m[1]).split(',').every((x, i) => Math.abs(Number(x) - [v.zoom, v.cx, v.cy][i]) < 1e-9);
  });
  const link = await page.evaluate(() => location.hash);
  await openCompare(link);
  await page.waitForFunction(() => window.planarium.viewport('b').viewport !== null);
  for (const key of ['a', 'b']) {
    const v = (await page.evaluate((k) => window.planarium.viewport(k), key)).viewport;
    for (const k of ['zoom', 'cx', 'cy']) assert.ok(Math.abs(v[k] - pa.viewport[k]) < 1e-9, `lane ${key} reopened at ${k} ${v[k]} (was ${pa.viewport[k]})`);
  }

  // Fit in lane B fits both
  await page.click('#b-stage [data-zoom="fit"]');
  assert.deepEqual(await page.evaluate(() => [window.planarium.viewport('a').viewport, window.planarium.viewport('b').viewport]), [null, null]);
  await page.waitForFunction(() => !/[#&]zoom=/.test(location.hash));
  assert.equal(await page.isVisible('#b-stage .plane-zoom'), false);
});

test('compare: the playground\'s link to an opened scenario opens here and in Benchmark; Open file… loads a file in both lanes, the link carries it, a reload keeps it; a bad file is named', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'planarium-compare-file-'));
  const mine = JSON.parse(readFileSync(join(ROOT, 'scenarios/narrow.json'), 'utf8'));
  mine.name = 'My narrow passage';
  const path = join(dir, 'my-narrow.json');
  writeFileSync(path, JSON.stringify(mine));
  const bad = join(dir, 'broken.json');
  writeFileSync(bad, '{"format": "planarium-scenario/1", "name": "x"}');
  // the playground's own link to an opened scenario (its `#…` state) opens here: scenario and set-up A
  await page.setInputFiles('#file', path);
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'My narrow passage');
  await waitState('idle');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  const shared = await page.evaluate(() => window.planarium.shareLink());
  assert.match(shared, /#scenario=deflate:.*planner=rrt/);
  await openCompare(shared.slice(shared.indexOf('#')));
  assert.equal(await page.textContent('#scenario-name'), 'My narrow passage');
  assert.equal((await page.evaluate(() => window.planarium.config('a'))).planner, 'rrt');
  assert.equal(await page.isVisible('#error'), false, `no problem: ${await page.textContent('#error-text')}`);
  // and in the benchmark
  await page.goto('about:blank');
  await page.goto(`${fx.env.base}bench.html${shared.slice(shared.indexOf('#'))}`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  assert.equal((await page.evaluate(() => window.planarium.scenario())).name, 'My narrow passage');
  assert.deepEqual((await page.evaluate(() => window.planarium.setups())).map((x) => x.planner), ['rrt']);

  await openCompare();
  await page.setInputFiles('#file', bad);
  await page.waitForFunction(() => !document.getElementById('error').hidden);
  assert.match(await page.textContent('#error-text'), /broken\.json: this file has an error at bounds/);
  await page.setInputFiles('#file', path);
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'My narrow passage');
  await waitState('idle');
  assert.equal(await page.$eval('#scenario', (s) => s.selectedOptions[0].textContent), 'File: my-narrow.json');
  await page.waitForFunction(() => /scenario=deflate:/.test(location.hash));
  await setSpeed('max');
  await page.click('#run');
  await waitState('finished', 120000);
  assert.deepEqual(await page.evaluate(() => [window.planarium.stats('a').status, window.planarium.stats('b').status]), ['solved', 'solved']);
  await page.reload();
  await page.waitForFunction(() => window.planarium?.state() === 'idle' && window.planarium.scenario(), null, { timeout: 30000 });
  assert.equal(await page.textContent('#scenario-name'), 'My narrow passage');
  assert.equal(await page.$eval('#scenario', (s) => s.selectedOptions[0].textContent), 'Scenario from a link');
  // the playground link carries the same scenario
  assert.match(await page.getAttribute('#to-playground', 'href'), /index\.html#scenario=deflate:/);
  // so do the other views' links in the header: this page's own and the benchmark's
  const hash = await page.evaluate(() => location.hash);
  assert.equal(await page.getAttribute('#nav-compare', 'href'), `compare.html${hash}`);
  assert.match(await page.getAttribute('#nav-bench', 'href'), /^bench\.html#scenario=deflate:.*setups=/);
  await page.click('#nav-bench');
  await page.waitForFunction(() => /bench\.html$/.test(location.pathname) && document.getElementById('setups')?.value.includes('A: '), null, { timeout: 30000 });
});

test('compare: Run 20 seeds gives success and medians per set-up, marks the better one, and opens the pair in Benchmark', async () => {
  await openCompare('#scenario=open-field&a=rrt-connect&b=rrt%20--range%200.02&seed=3');
  await page.click('#run-seeds');
  await page.waitForFunction(() => window.planarium.seeds(), null, { timeout: 120000 });
  const s = await page.evaluate(() => window.planarium.seeds());
  assert.equal(s.first, 3);
  assert.equal(s.last, 22);
  for (const k of ['a', 'b']) {
    assert.equal(s[k].runs, 20);
    assert.deepEqual(s.rows[k === 'a' ? 0 : 1].map((r) => r.seed).sort((x, y) => x - y), Array.from({ length: 20 }, (_, i) => 3 + i));
  }
  // the medians are those of the runs (recomputed here from the rows)
  const med = (v) => { const x = [...v].sort((p, q) => p - q); return (x[9] + x[10]) / 2; };
  assert.equal(s.a.nodes, med(s.rows[0].map((r) => r.nodes)));
  assert.equal(s.b.checks, med(s.rows[1].map((r) => r.checks)));
  // RRT with a short range grows far more nodes than RRT-Connect: A is marked better on nodes
  assert.ok(s.b.nodes > s.a.nodes, `nodes ${s.a.nodes} vs ${s.b.nodes}`);
  assert.equal(s.better.nodes, 'a');
  const rows = await page.$$eval('#seeds-table tbody tr', (trs) => trs.map((tr) => [...tr.children].map((c) => [c.textContent, c.className])));
  assert.deepEqual(rows.map((r) => r[0][0]), ['success', 'time (ms)', 'nodes', 'checks', 'path length (solved)']);
  const nodesRow = rows[2];
  assert.equal(nodesRow[1][0], `${s.a.nodes} ★`);
  assert.equal(nodesRow[1][1], 'better');
  assert.equal(nodesRow[2][0], String(s.b.nodes));
  assert.match(rows[0][1][0], /^\d+% \(\d+\/20\)/);
  // every metric with different values has exactly one mark
  for (const [i, key] of ['success', 'time_ms', 'nodes', 'checks', 'length'].entries()) {
    const marks = rows[i].slice(1).filter(([t]) => t.endsWith('★')).length;
    assert.equal(marks, s.better[key] ? 1 : 0, `${key}: ${marks} marks`);
  }
  assert.match(await page.textContent('#seeds-caption'), /Seeds 3 … 22/);
  await page.screenshot({ path: join(shots, 'page-compare-seeds.png') });
  // the same pair in Benchmark (URL state): scenario, both set-ups, 20 runs
  await page.click('#to-bench');
  await page.waitForURL(/bench\.html#/);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  assert.equal(await page.$eval('#scenario', (e) => e.value), 'open-field');
  assert.equal(await page.$eval('#runs', (e) => e.value), '20');
  assert.deepEqual(await page.evaluate(() => window.planarium.setups()), [
    { label: 'A', planner: 'rrt-connect', params: {} }, { label: 'B', planner: 'rrt', params: { range: 0.02 } }]);
});

test('compare on a phone (390×844): the two lanes are tabs A / B, one shown at a time', async () => {
  await page.setViewportSize({ width: 390, height: 844 });
  await openCompare('#scenario=narrow&a=rrt-connect&b=rrt&seed=2');
  assert.equal(await page.isVisible('#tab-a'), true);
  assert.equal(await page.isVisible('#tab-b'), true);
  assert.equal(await page.isVisible('#a-lane'), true);
  assert.equal(await page.isVisible('#b-lane'), false, 'B is behind its tab');
  assert.equal(await page.getAttribute('#tab-a', 'aria-selected'), 'true');
  await setSpeed('max');
  await page.click('#run');
  await waitState('finished', 120000);
  await page.locator('#tab-a').scrollIntoViewIfNeeded();
  await page.screenshot({ path: join(shots, 'page-compare-phone-a.png') });
  const [pathA] = await countColours('a-canvas', [PALETTE.smoothPath], 6);
  assert.ok(pathA > 50, `A's canvas shows its path (${pathA} px)`);
  await page.click('#tab-b');
  assert.equal(await page.isVisible('#a-lane'), false);
  assert.equal(await page.isVisible('#b-lane'), true);
  assert.equal(await page.getAttribute('#tab-b', 'aria-selected'), 'true');
  // B's canvas was sized when its tab opened, and is drawn
  await page.waitForFunction(() => document.getElementById('b-canvas').getBoundingClientRect().width > 200);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const [pathB] = await countColours('b-canvas', [PALETTE.smoothPath], 6);
  assert.ok(pathB > 50, `B's canvas shows its path (${pathB} px)`);
  const box = await page.locator('#b-canvas').boundingBox();
  assert.ok(box.x >= 0 && box.x + box.width <= 390, `B's canvas fits the screen: ${JSON.stringify(box)}`);
  await page.screenshot({ path: join(shots, 'page-compare-phone-b.png') });
  // at desktop width, both lanes side by side and no tabs
  await page.setViewportSize({ width: 1280, height: 800 });
  assert.equal(await page.isVisible('#tab-a'), false);
  assert.equal(await page.isVisible('#a-lane'), true);
  assert.equal(await page.isVisible('#b-lane'), true);
  await page.screenshot({ path: join(shots, 'page-compare-desktop.png') });
});

test('compare: RRT* against RRT-Connect on the open field: the RRT* lane\'s cost chart draws the optimum line', async () => {
  await openCompare('#scenario=open-field&a=rrt-star&b=rrt-connect&seed=1');
  assert.equal(await page.isVisible('#a-chart'), true, 'RRT* has its cost chart');
  // each lane's iteration and "Checks" rows say, on hover, what its planner counts (the registry's words)
  const tip = (key, stat) => page.$eval(`#${key}-stats [data-stat="${stat}"] dt`, (dt) => dt.title);
  for (const [key, name] of [['a', 'rrt-star'], ['b', 'rrt-connect']]) {
    const spec = specOf(name);
    assert.ok((await tip(key, 'iterations')).startsWith(`${spec.label}: ${spec.iteration}\n`), `${key}: ${await tip(key, 'iterations')}`);
    assert.equal(await tip(key, 'checks'), `${spec.label}: ${spec.checks}`);
  }
  assert.notEqual(await tip('a', 'iterations'), await tip('b', 'iterations'));
  assert.equal(await page.isVisible('#b-chart'), false, 'RRT-Connect has none before a cost');
  await page.waitForFunction(() => document.getElementById('a-chart').width > 0);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const [dashed] = await countColours('a-chart', [PALETTE.chartTarget], 8);
  assert.ok(dashed > 40, `optimum line pixels in lane A's chart: ${dashed}`);
  // the chart downloads: a PNG twice its size with the title on top, an SVG with the full title
  const box = await page.locator('#a-chart').boundingBox();
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#a-chart-png')]);
  assert.equal(d.suggestedFilename(), 'planarium-compare-a-chart.png');
  const bytes = readFileSync(await d.path());
  writeFileSync(join(shots, 'page-compare-chart-download.png'), bytes);
  const seen = await page.evaluate(async (b64) => {
    const img = await createImageBitmap(new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))], { type: 'image/png' }));
    const c = new OffscreenCanvas(img.width, img.height);
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, img.width, 40).data;
    let dark = 0;
    for (let i = 0; i < px.length; i += 4) if (px[i] < 80 && px[i + 1] < 80 && px[i + 2] < 80 && px[i + 3] > 200) dark++;
    return { w: img.width, h: img.height, dark };
  }, bytes.toString('base64'));
  assert.equal(seen.w, Math.round(box.width * 2));
  assert.ok(seen.h >= Math.round((box.height + 22) * 2), `the chart and its title's lines: ${seen.h}`);
  assert.ok(seen.dark > 150, `the title's dark pixels: ${seen.dark}`);
  const [s] = await Promise.all([page.waitForEvent('download'), page.click('#a-chart-svg')]);
  const svg = readFileSync(await s.path(), 'utf8');
  const title = `A · ${await page.textContent('#a-title')}: Best cost against iterations`;
  const doc = await page.evaluate((text) => {
    const x = new DOMParser().parseFromString(text, 'image/svg+xml');
    return { title: x.querySelector('svg > title')?.textContent, drawn: [...x.querySelectorAll('#title text')].map((t) => t.textContent).join(' '), paths: x.querySelectorAll('path').length };
  }, svg);
  assert.equal(doc.title, title);
  assert.equal(doc.drawn, title, 'the title drawn in full');
  assert.ok(doc.paths > 3, `the chart drawn in the SVG: ${doc.paths} paths`);
});

test('compare for a slide: both lanes\' canvases are the same size at 1280 and 1920 px with RRT*\'s chart shown, the chart inside its card, the page\'s width used; picking a scenario keeps both set-ups', async () => {
  for (const [width, height] of [[1280, 800], [1920, 1080]]) {
    await page.setViewportSize({ width, height });
    await openCompare('#scenario=open-field&a=rrt-star&b=rrt-connect%20--range%200.2&seed=1');
    await setSpeed('max');
    await page.click('#run');
    await waitState('finished', 120000);
    await fx.nextFrames();
    assert.equal(await page.isVisible('#a-chart'), true, 'RRT*\'s chart is shown');
    const box = (sel) => page.locator(sel).boundingBox();
    const [ca, cb, la, lb, chart, lanes] = await Promise.all(['#a-canvas', '#b-canvas', '#a-lane', '#b-lane', '#a-chart-box', '#lanes'].map(box));
    console.log(`${width}: A canvas ${ca.width}×${ca.height}, B canvas ${cb.width}×${cb.height}, lanes ${lanes.width} px wide`);
    assert.ok(Math.abs(ca.width - cb.width) <= 2 && Math.abs(ca.height - cb.height) <= 2, `${width}: canvases ${JSON.stringify([ca, cb])}`);
    assert.ok(Math.abs(la.width - lb.width) <= 2 && Math.abs(la.height - lb.height) <= 2, `${width}: lanes ${JSON.stringify([la, lb])}`);
    assert.ok(ca.width > 0.25 * width, `${width}: the canvases use the width (${ca.width} px)`);
    assert.ok(lanes.x + lanes.width > width - 40, `${width}: the lanes reach the page's right edge (${lanes.x + lanes.width})`);
    assert.ok(chart.x >= la.x && chart.x + chart.width <= la.x + la.width + 0.5 && chart.y >= la.y && chart.y + chart.height <= la.y + la.height + 0.5,
      `${width}: the chart ${JSON.stringify(chart)} inside its card ${JSON.stringify(la)}`);
    await page.screenshot({ path: join(shots, `page-compare-${width}.png`) });
  }
  // a scenario picked from the menu: both set-ups stay as they were
  const before = await page.evaluate(() => [window.planarium.config('a'), window.planarium.config('b')]);
  await page.selectOption('#scenario', 'narrow');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Narrow passage');
  await waitState('idle');
  const after = await page.evaluate(() => [window.planarium.config('a'), window.planarium.config('b')]);
  assert.deepEqual(after.map((c) => [c.planner, c.params]), before.map((c) => [c.planner, c.params]));
  assert.equal(await page.$eval('#b-planner', (s) => s.value), 'rrt-connect');
  assert.equal(await page.$eval('#b-param-range', (s) => s.value), '0.2');
});

test('compare: Export for a slide gives one PNG of both lanes, each under its title and above its key numbers', async () => {
  await openCompare('#scenario=open-field&a=rrt-star&b=rrt-connect&seed=1');
  await setSpeed('max');
  await page.click('#run');
  await waitState('finished', 120000);
  await fx.nextFrames();
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#export-lanes')]);
  assert.equal(d.suggestedFilename(), 'planarium-compare.png');
  const bytes = readFileSync(await d.path());
  writeFileSync(join(shots, 'page-compare-export.png'), bytes);
  const [wa, wb] = await page.evaluate(() => ['a-canvas', 'b-canvas'].map((id) => document.getElementById(id).width));
  const seen = await page.evaluate(async ({ b64, path }) => {
    const img = await createImageBitmap(new Blob([Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0))], { type: 'image/png' }));
    const c = new OffscreenCanvas(img.width, img.height);
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const rgb = [1, 3, 5].map((i) => parseInt(path.slice(i, i + 2), 16));
    const count = (x0, y0, x1, y1, test) => {
      const px = ctx.getImageData(x0, y0, x1 - x0, y1 - y0).data;
      let n = 0;
      for (let i = 0; i < px.length; i += 4) if (test(px[i], px[i + 1], px[i + 2])) n++;
      return n;
    };
    const dark = (r, g, b) => r < 80 && g < 80 && b < 80;
    const isPath = (r, g, b) => Math.abs(r - rgb[0]) <= 6 && Math.abs(g - rgb[1]) <= 6 && Math.abs(b - rgb[2]) <= 6;
    const half = img.width / 2;
    return {
      w: img.width, h: img.height,
      titles: [count(0, 0, half, 40, dark), count(half, 0, img.width, 40, dark)],
      paths: [count(0, 40, half, img.height - 30, isPath), count(half, 40, img.width, img.height - 30, isPath)],
      numbers: [count(0, img.height - 44, half, img.height, dark), count(half, img.height - 44, img.width, img.height, dark)],
    };
  }, { b64: bytes.toString('base64'), path: PALETTE.smoothPath });
  console.log(`export ${seen.w}×${seen.h}: titles ${seen.titles}, paths ${seen.paths}, numbers ${seen.numbers}`);
  assert.equal(seen.w, 12 + wa + 12 + wb + 12, 'both lanes side by side at their size');
  for (const k of [0, 1]) {
    assert.ok(seen.titles[k] > 150, `lane ${'AB'[k]}'s title: ${seen.titles[k]}`);
    assert.ok(seen.paths[k] > 100, `lane ${'AB'[k]}'s path: ${seen.paths[k]}`);
    assert.ok(seen.numbers[k] > 100, `lane ${'AB'[k]}'s numbers: ${seen.numbers[k]}`);
  }
  assert.match(await page.textContent('#export-status'), /Saved planarium-compare\.png/);
});

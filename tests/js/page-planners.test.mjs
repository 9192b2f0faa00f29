// The planners that keep improving, in the page (headless chromium): RRT* on the open field draws
// its best-cost chart and reports the best cost; the inspection planner on the Technion room draws
// its coverage chart, lights the points it sees and shows the sensor's field of view; planners are
// offered by the scenario's task. Screenshots go to target/page-rrt-star.png, page-inspection.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { execFileSync } from 'node:child_process';
import { canvasPixels, pageFixture, ROOT, SHOTS as shots } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, pickScenario, countColours, nextFrames, fastPlayback, setField } = fx;

/** Pixels of the chart canvas within `tol` of the chart's line colour. */
const chartLine = async (tol = 8) => (await countColours('chart', [PALETTE.chartLine], tol))[0];

/** Lazy PRM on the zigzag, seed 1, run to its end at full playback speed. */
async function finishLazyPrm() {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'lazy-prm');
  await waitState('idle');
  await setField('seed', 1);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 90000);
}

test('RRT* on the open field: the best-cost chart has a line and the stats show the best cost', async () => {
  await pickScenario('open-field', 'Open field');
  await page.selectOption('#planner', 'rrt-star');
  await waitState('idle');
  assert.equal(await page.isVisible('#chart'), true, 'the chart is shown for RRT*');
  assert.match(await page.textContent('#chart-title'), /cost/i);
  await nextFrames();
  assert.equal(await chartLine(), 0, 'no line before the run');
  // the optimum (visibility graph, issue 17) is the chart's dashed reference line from the start
  const [dashed] = await countColours('chart', [PALETTE.chartTarget], 8);
  assert.ok(dashed > 40, `optimum line pixels before the run: ${dashed}`);
  const optimum = (await page.evaluate(() => window.planarium.model())).optimum;
  assert.ok(Math.abs(optimum - 1.226427) < 1e-5, `open-field's optimum: ${optimum}`);
  await setField('seed', 1);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 90000);
  await nextFrames();
  const model = await page.evaluate(() => window.planarium.model());
  assert.ok(model.costs.length >= 2, `cost improvements shown: ${model.costs.length}`);
  assert.ok(model.costs.every(([, c], i) => i === 0 || c <= model.costs[i - 1][1]), 'the best cost never grows');
  assert.ok(model.costs.every(([, c]) => c >= optimum - 1e-6), `no cost below the optimum ${optimum}`);
  assert.ok(await page.evaluate(() => window.planarium.model().optimum) === optimum, 'the line stays');
  assert.ok(model.rewires > 0, `rewires: ${model.rewires}`);
  assert.ok(model.bestBranch >= 2, 'the best path walks back to the root');
  const line = await chartLine();
  console.log(`RRT*: ${model.costs.length} costs, ${model.rewires} rewires, chart line ${line} pixels`);
  assert.ok(line > 60, `chart line pixels: ${line}`);
  const best = Number(await page.textContent('#stat-best-cost'));
  const last = model.costs.at(-1)[1];
  assert.ok(Number.isFinite(best) && best > 0, `best cost shown: ${best}`);
  assert.ok(Math.abs(best - last) < 1e-4, `stats best cost ${best} = last COST event ${last}`);
  assert.equal(await page.isVisible('#stat-best-cost'), true);
  assert.equal(await page.isVisible('#stat-coverage'), false, 'no coverage row for a goal planner');
  await page.$eval('#chart-box', (el) => el.scrollIntoView());
  await page.screenshot({ path: join(shots, 'page-rrt-star.png') });

  // the best path so far is drawn, and goes when its overlay is switched off
  await page.click('#reset');
  await waitState('idle');
  await page.$eval('#speed', (el) => { el.value = 55; el.dispatchEvent(new Event('input', { bubbles: true })); });
  await page.click('#run');
  await page.waitForFunction(() => window.planarium.model().costs.length > 0, null, { timeout: 60000 });
  await page.click('#pause');
  await waitState('paused');
  await nextFrames();
  const [bestPath] = await countColours('canvas', [PALETTE.best], 6);
  assert.ok(bestPath > 100, `best path pixels: ${bestPath}`);
  await page.click('#show-best');
  await nextFrames();
  const [bestOff] = await countColours('canvas', [PALETTE.best], 6);
  assert.ok(bestOff < bestPath / 10, `best path gone: ${bestOff} of ${bestPath}`);
});

test('PRM* on the zigzag: its cost chart falls toward the optimum line as the roadmap grows', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'prm-star');
  await waitState('idle');
  assert.equal(await page.isVisible('#chart'), true, 'PRM* keeps improving: the cost chart is shown');
  const optimum = (await page.evaluate(() => window.planarium.model())).optimum;
  assert.ok(Math.abs(optimum - 3.85966) < 1e-4, `zigzag's optimum: ${optimum}`);
  await setField('seed', 1);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 90000);
  await nextFrames();
  const model = await page.evaluate(() => window.planarium.model());
  assert.ok(model.costs.length >= 5, `improvements shown: ${model.costs.length}`);
  assert.ok(model.costs.every(([, c], i) => c >= optimum - 1e-6 && (i === 0 || c < model.costs[i - 1][1])), JSON.stringify(model.costs));
  assert.ok(Math.abs(Number(await page.textContent('#stat-cost')) - model.costs.at(-1)[1]) < 1e-3, 'the path is the last improvement');
  const [line, dashed] = await countColours('chart', [PALETTE.chartLine, PALETTE.chartTarget], 8);
  assert.ok(line > 60 && dashed > 40, `chart line ${line} px, optimum line ${dashed} px`);
});

test('Lazy PRM on the zigzag: unchecked edges drawn dashed grey, checked ones in the tree colour; PRM draws only checked edges', async () => {
  await finishLazyPrm();
  assert.equal(await page.textContent('#status'), 'solved');
  await nextFrames();
  const lazy = (await page.evaluate(() => window.planarium.model())).roadmap;
  const [grey, checked] = await countColours('canvas', [PALETTE.roadmapUnchecked, PALETTE.tree0], 6);
  console.log(`lazy-prm: ${lazy.edges} edges, ${lazy.checked} checked, ${lazy.pathEdges} path edges; ${grey} grey px, ${checked} tree px`);
  assert.ok(lazy.edges > 50 && lazy.checked > 0 && lazy.checked < lazy.edges, JSON.stringify(lazy));
  assert.ok(lazy.pathEdges > 0, 'the searches\' paths are streamed');
  assert.ok(grey > 200, `unchecked edge pixels: ${grey}`);
  assert.ok(checked > 50, `checked edge pixels: ${checked}`);
  await page.screenshot({ path: join(shots, 'page-lazy-prm.png') });

  await page.selectOption('#planner', 'prm');
  await waitState('idle');
  await page.click('#run');
  await waitState('finished', 90000);
  assert.equal(await page.textContent('#status'), 'solved');
  await nextFrames();
  const eager = (await page.evaluate(() => window.planarium.model())).roadmap;
  const [grey2, checked2] = await countColours('canvas', [PALETTE.roadmapUnchecked, PALETTE.tree0], 6);
  console.log(`prm: ${eager.edges} edges; ${grey2} grey px, ${checked2} tree px`);
  assert.equal(eager.checked, 0, 'PRM checks edges as it adds them');
  assert.ok(eager.edges > 50 && checked2 > 200, `${eager.edges} edges, ${checked2} px`);
  assert.ok(grey2 < grey / 10, `no unchecked edges drawn: ${grey2} px`);
});

test('EST on the zigzag: the density grid shades the picking tree\'s cells and outlines the pick; no sampler rows', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'est');
  await waitState('idle');
  assert.equal(await page.isVisible('#show-density'), true, "EST's density overlay is offered");
  await setField('seed', 1);
  // a fixed number of iterations (not a pause at some moment), so the drawing is the same every run
  await page.fill('#step-size', '120');
  await page.click('#step');
  await waitState('paused');
  await nextFrames();
  const pixels = async () => (await canvasPixels(page)).data;
  const on = await pixels();
  const [outline] = await countColours('canvas', [PALETTE.densityPick], 10);
  await page.screenshot({ path: join(shots, 'page-est-density.png') });
  await page.click('#show-density');
  await nextFrames();
  const off = await pixels();
  const [outlineOff] = await countColours('canvas', [PALETTE.densityPick], 10);
  let changed = 0;
  for (let i = 0; i < on.length; i += 4) {
    if (Math.abs(on[i] - off[i]) + Math.abs(on[i + 1] - off[i + 1]) + Math.abs(on[i + 2] - off[i + 2]) > 24) changed++;
  }
  console.log(`EST density: outline ${outline} px (off: ${outlineOff}), ${changed} px shaded`);
  assert.ok(outline > 40 && outlineOff === 0, `the latest pick's cell outlined: ${outline} px, then ${outlineOff}`);
  assert.ok(changed > 2000, `cells shaded: ${changed} px change when the overlay is switched off`);
  assert.equal(await page.isVisible('#stat-sampler'), false, 'EST draws no samples through the sampler: no Sampler row');
  await page.click('#show-density');
  await page.selectOption('#planner', 'rrt-connect');
  await waitState('idle');
  assert.equal(await page.isVisible('#show-density'), false, 'not offered for RRT-Connect');
});

test('Lazy PRM on the zigzag: two clicks ask the finished roadmap another query, answered as the CLI answers it', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'lazy-prm');
  await waitState('idle');
  assert.equal(await page.isVisible('#query-button'), false, 'no query before the roadmap is built');
  await setField('seed', 1);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 90000);
  await nextFrames();
  const before = await page.evaluate(() => window.planarium.stats().nodes);
  const scenario = await page.evaluate(() => window.planarium.scenario());
  // Escape drops a query half asked; the map is not edited by the clicks, even with a drawing tool on
  await page.click('#tool-rect');
  await page.click('#query-button');
  await page.mouse.click(...(await fx.toPage(0.92, 0.1)));
  await page.keyboard.press('Escape');
  assert.match(await page.textContent('#query-status'), /cancelled/);
  await page.click('#query-button');
  await page.mouse.click(...(await fx.toPage(0.92, 0.1)));
  await page.mouse.click(...(await fx.toPage(0.08, 0.9)));
  await page.waitForFunction(() => /cost|does not join/.test(document.getElementById('query-status').textContent), null, { timeout: 30000 });
  const status = await page.textContent('#query-status');
  assert.match(status, /^Query 1: \d+ states, cost [\d.]+, on the same roadmap\.$/);
  assert.deepEqual(await page.evaluate(() => window.planarium.scenario()), scenario, 'the clicks edited nothing');
  assert.equal(await page.evaluate(() => window.planarium.state()), 'finished', 'still the same finished run');
  const { points, cost } = await page.evaluate(() => window.planarium.query());
  assert.ok(Math.hypot(points[0][0] - 0.92, points[0][1] - 0.1) < 0.01, `starts where clicked: ${points[0]}`);
  assert.equal(await page.evaluate(() => window.planarium.stats().nodes), before, "the stats stay the run's");
  // the native CLI, same roadmap (seed), same two states: the same answer
  const arg = `${points[0].join(',')}:${points.at(-1).join(',')}`;
  const out = execFileSync(join(ROOT, 'target/release/planarium'), ['plan', 'zigzag', '--planner', 'lazy-prm', '--seed', '1', '--query', arg], { encoding: 'utf8' });
  const m = out.match(/query 1: [^:]+:[^:]+: (\d+) states, cost ([\d.]+)/);
  assert.ok(m, out);
  assert.equal(`${points.length} states, cost ${cost.toFixed(4)}`, `${m[1]} states, cost ${m[2]}`, `the CLI: ${m[0]}`);
  await nextFrames();
  const [drawn] = await countColours('canvas', [PALETTE.queryAnswer], 8);
  assert.ok(drawn > 300, `the answer drawn: ${drawn} px`);
  // the legend names the purple path, in its colour
  const queryItem = () => page.$$eval('#legend li', (lis) => lis.filter((li) => /new query/.test(li.textContent)).length);
  assert.equal(await queryItem(), 1, 'a legend entry for the answer');
  await page.screenshot({ path: join(shots, 'page-roadmap-query.png') });
  // step back replays the run from its seed: the query goes with the finished state
  await page.click('#step-back');
  await page.waitForFunction(() => window.planarium.state() !== 'finished', null, { timeout: 30000 });
  assert.equal(await page.evaluate(() => window.planarium.query()), null, 'step back drops the answer');
  assert.equal(await queryItem(), 0, 'the legend drops the answer with it');
  assert.equal(await page.isVisible('#query-button'), false);
  // a new run (reset) forgets the query
  await page.click('#reset');
  await waitState('idle');
  assert.equal(await page.isVisible('#query-button'), false);
  assert.equal(await page.evaluate(() => window.planarium.query()), null);
});

test('a phone (390×844): the query status, last in the run bar (which wraps onto rows), is on screen', async () => {
  await page.setViewportSize({ width: 390, height: 844 });
  await finishLazyPrm();
  const onScreen = () => page.$eval('#query-status', (el) => {
    const r = el.getBoundingClientRect();
    return { left: r.left, right: r.right, width: innerWidth, text: el.textContent };
  });
  // the bar wraps onto rows on a phone: nothing in it, the status last, is off to the side
  assert.ok(await page.$eval('#run-bar', (b) => b.scrollWidth <= b.clientWidth + 1), 'the run bar does not scroll sideways');
  await page.click('#query-button');
  let s = await onScreen();
  assert.match(s.text, /Click the query's start/);
  assert.ok(s.left >= 0 && s.right <= s.width, `the prompt is on screen: ${JSON.stringify(s)}`);
  // the map in view to click on it (the run bar, sticky, floats at the screen's bottom edge)
  await page.$eval('#canvas', (c) => c.scrollIntoView({ block: 'start' }));
  await page.mouse.click(...(await fx.toPage(0.92, 0.1)));
  await page.mouse.click(...(await fx.toPage(0.08, 0.9)));
  await page.waitForFunction(() => /cost|does not join/.test(document.getElementById('query-status').textContent), null, { timeout: 30000 });
  s = await onScreen();
  assert.match(s.text, /^Query 1: \d+ states, cost [\d.]+, on the same roadmap\.$/);
  assert.ok(s.left >= 0 && s.right <= s.width, `the answer is on screen: ${JSON.stringify(s)}`);
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth), 'the page itself does not scroll sideways');
  await page.screenshot({ path: join(shots, 'page-roadmap-query-phone.png') });
});

test('technion-ip: only inspection planners are offered, with the reason; narrow offers no inspection, without a note', async () => {
  await pickScenario('technion-ip', 'Technion HW3: inspect the room');
  const offered = await page.$$eval('#planner option', (os) => os.map((o) => o.value));
  assert.deepEqual(offered, ['inspection']);
  assert.match(await page.textContent('#planner-note'), /need a goal/);
  await pickScenario('narrow', 'Narrow passage');
  const goalOnly = await page.$$eval('#planner option', (os) => os.map((o) => o.value));
  assert.ok(!goalOnly.includes('inspection') && goalOnly.includes('rrt-connect'), goalOnly.join());
  // every map without inspection points leaves the inspection planner out: no note for that
  assert.equal(await page.isVisible('#planner-note'), false, 'no note on a map with a goal');
});

test('inspection on technion-ip: the coverage chart grows and seen points light up', async () => {
  await pickScenario('technion-ip', 'Technion HW3: inspect the room');
  assert.equal(await page.$eval('#planner', (s) => s.value), 'inspection');
  assert.match(await page.textContent('#chart-title'), /coverage/i);
  await setField('param-coverage', 0.5);
  await setField('seed', 1);
  await setField('run-time_limit', 120);
  await nextFrames();
  const [litBefore] = await countColours('canvas', [PALETTE.seen], 6);
  assert.equal(litBefore, 0, 'nothing lit before the run');
  assert.equal(await chartLine(), 0, 'no line before the run');
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 150000);
  assert.equal(await page.textContent('#status'), 'solved');
  await page.waitForTimeout(300);
  const model = await page.evaluate(() => window.planarium.model());
  const coverage = model.coverage.at(-1);
  console.log(`inspection: ${model.coverage.length} coverage events, last ${coverage}, ${model.seen.length} points seen`);
  assert.ok(coverage[1] >= 0.5, `coverage reached: ${coverage[1]}`);
  assert.ok(model.seen.length >= coverage[2], 'every point the best branch sees was seen');
  assert.match(await page.textContent('#stat-coverage'), /^\d+(\.\d)?% \(\d+ seen\)$/);
  const shown = parseFloat(await page.textContent('#stat-coverage'));
  assert.ok(Math.abs(shown - 100 * coverage[1]) < 0.06, `stats coverage ${shown}% = ${100 * coverage[1]}%`);
  const line = await chartLine();
  assert.ok(line > 60, `coverage chart line pixels: ${line}`);
  // lit points: each seen point is a bright diamond (about 70 px at this size)
  const [lit, unlit] = await countColours('canvas', [PALETTE.seen, PALETTE.inspection], 6);
  console.log(`lit ${lit} px for ${model.seen.length} points; unlit ${unlit} px`);
  assert.ok(lit >= 25 * model.seen.length, `lit pixels ${lit} for ${model.seen.length} seen points`);
  // the sensor's wedge at the robot shown
  const [fov] = await countColours('canvas', [PALETTE.fov], 30);
  assert.ok(fov > 80, `field-of-view outline pixels: ${fov}`);
  await page.$eval('#chart-box', (el) => el.scrollIntoView());
  await page.screenshot({ path: join(shots, 'page-inspection.png') });
  // switched off, the points go back to their plain colour
  await page.click('#show-seen');
  await nextFrames();
  const [litOff] = await countColours('canvas', [PALETTE.seen], 6);
  assert.equal(litOff, 0, `lit pixels with the overlay off: ${litOff}`);
});

test('visibility graph on the open field: the graph is drawn, the path is the optimum the chart marks', async () => {
  await pickScenario('open-field', 'Open field');
  await page.selectOption('#planner', 'visibility-graph');
  await waitState('idle');
  await nextFrames();
  const [before] = await countColours('canvas', [PALETTE.graphEdge], 4);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
  await page.screenshot({ path: join(shots, 'page-visibility.png') });
  const [edges] = await countColours('canvas', [PALETTE.graphEdge], 4);
  console.log(`visibility graph: edge pixels ${before} → ${edges}`);
  assert.ok(edges > before + 200, `graph edge pixels: ${before} → ${edges}`);
  assert.equal(await page.getAttribute('#status', 'data-status'), 'solved');
  const model = await page.evaluate(() => window.planarium.model());
  assert.ok(Math.abs(model.optimum - 1.226427) < 1e-5, `open-field's optimum: ${model.optimum}`);
  assert.ok(model.trees[0].nodes >= 3, 'the A* search tree is drawn');
  const cost = Number(await page.textContent('#stat-cost'));
  assert.ok(Math.abs(cost - model.optimum) < 1e-4, `the run's cost ${cost} is the optimum ${model.optimum}`);
});

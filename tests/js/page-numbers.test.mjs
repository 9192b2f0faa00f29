// The numbers match the picture (headless chromium): paused mid-replay, the stats count what is
// drawn and mark the planner's own numbers "(final)"; finished, the status strip and the stats give
// the same node count, grouped alike ("1,500"); PRM shows its edges; the optimum row for a point robot, not for a rigid bar;
// rows that do not apply are hidden; the iteration and "Checks" rows say what the planner counts;
// the first click after typing a map's name is not lost; the editing marks leave a run's picture.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture, walledIn } from './browser.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, pickScenario, setField, fastPlayback, nextFrames } = fx;

const text = (id) => page.textContent(`#${id}`);
const num = (s) => Number(String(s).replace(/,/g, ''));

test('paused mid-replay: the stats count the nodes drawn and mark the rest final; finished, the strip and the stats agree', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  await setField('seed', 1);
  await page.click('#speed-slow');
  await page.click('#run');
  // the planner is far ahead of a slow replay: pause while the replay is behind
  await page.waitForFunction(() => /^replaying .* · planner finished/.test(document.getElementById('run-status').textContent)
    && window.planarium.nodeCount() > 3, null, { timeout: 60000 });
  await page.click('#pause');
  await waitState('paused');
  await nextFrames();
  const drawn = await page.evaluate(() => window.planarium.nodeCount());
  const nodes = await text('stat-nodes');
  const m = nodes.match(/^([\d,]+) of ([\d,]+)$/);
  assert.ok(m, `nodes: drawn of the planner's: ${nodes}`);
  assert.equal(num(m[1]), drawn, `the stats' nodes ${nodes} are those drawn (${drawn})`);
  assert.ok(num(m[1]) < num(m[2]), nodes);
  // the iteration shown is the strip's
  const strip = await text('run-status');
  const it = strip.match(/^paused at ≈?([\d,]+) of ([\d,]+) iterations/);
  assert.ok(it, strip);
  assert.equal(await text('stat-iterations'), `${it[1]} of ${it[2]}`, `the strip: ${strip}`);
  // what only the planner knows is marked as its final number
  assert.match(await text('stat-checks'), /^\d{1,3}(,\d{3})* \(final\)$/);
  assert.match(await text('stat-time'), /^[\d.]+ \(final\)$/);
  // the rest at once: the strip's node count is the stats'
  await page.click('#speed-instant');
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
  const final = await page.evaluate(() => window.planarium.stats());
  const done = await text('run-status');
  const strip2 = done.match(/^solved · ([\d,]+) iterations · ([\d,]+) nodes/);
  assert.ok(strip2, done);
  assert.equal(await text('stat-nodes'), strip2[2], `strip ${done}`);
  assert.equal(num(strip2[2]), final.nodes);
  assert.equal(await text('stat-iterations'), strip2[1]);
  assert.doesNotMatch(await text('stat-checks'), /final/, 'caught up: no mark');
});

test('a run of thousands of nodes: the stats group their counts as the strip does, times and costs stay plain', async () => {
  await page.setInputFiles('#file', { name: 'walled.json', mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify(walledIn({ max_nodes: 1500, time_limit: 60 }))) });
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Walled-in goal');
  await waitState('idle');
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
  const s = await page.evaluate(() => window.planarium.stats());
  assert.ok(s.nodes >= 1000, `a run of at least 1,000 nodes: ${s.nodes}`);
  const nodes = await text('stat-nodes');
  assert.match(nodes, /^\d{1,3}(,\d{3})+$/, `grouped: ${nodes}`);
  assert.equal(nodes, s.nodes.toLocaleString('en'));
  const strip = (await text('run-status')).match(/ · ([\d,]+) iterations · ([\d,]+) nodes/);
  assert.ok(strip, await text('run-status'));
  assert.equal(nodes, strip[2], 'the stats and the strip write the count alike');
  assert.equal(await text('stat-iterations'), strip[1]);
  assert.ok(s.checks >= 1000, `checks: ${s.checks}`);
  assert.equal(await text('stat-checks'), s.checks.toLocaleString('en'));
  assert.match(await text('stat-shown'), /^\d{1,3}(,\d{3})+ \([\d,]+ events queued\)$/);
  // a time is a decimal, not a count: never grouped
  assert.match(await text('stat-time'), /^\d+\.\d$/);
});

test('PRM shows the edges it checked and those in its roadmap; RRT has no such rows', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'prm');
  await waitState('idle');
  await setField('seed', 1);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 90000);
  const s = await page.evaluate(() => window.planarium.stats());
  assert.ok(s.roadmap && s.roadmap.edges_checked > 0, JSON.stringify(s.roadmap));
  const checked = (await text('stat-edges-checked')).match(/^([\d,]+) \(([\d,]+) blocked\)$/);
  assert.ok(checked, await text('stat-edges-checked'));
  assert.equal(checked[1], s.roadmap.edges_checked.toLocaleString('en'), 'grouped as the strip groups');
  const inMap = num(await text('stat-edges'));
  assert.equal(num(checked[1]), s.roadmap.edges_checked);
  // PRM checks every candidate edge and keeps those found free
  assert.equal(inMap, num(checked[1]) - num(checked[2]), 'edges in the roadmap: checked less blocked');
  assert.ok(num(checked[2]) > 0, 'the zigzag blocks some edges');
  assert.equal(await page.isVisible('#stat-edges-checked'), true);
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  assert.equal(await page.isVisible('#stat-edges-checked'), false);
  assert.equal(await page.isVisible('#stat-edges'), false);
});

test('the optimum row for a point robot says how far above it the path is; none for a rigid bar; rows that do not apply are hidden', async () => {
  await pickScenario('open-field', 'Open field');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  assert.match(await text('stat-optimum'), /^1\.23 \(visibility graph\)$/, 'the optimum before a path');
  // the registry says what an iteration and a check are for this planner
  const tip = await page.$eval('[data-stat="iterations"] dt', (dt) => dt.title);
  assert.match(tip, /^RRT: .*sample/, tip);
  assert.match(await page.$eval('[data-stat="checks"] dt', (dt) => dt.title), /^RRT: State validity checks/);
  await setField('seed', 1);
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  const s = await page.evaluate(() => window.planarium.stats());
  const row = await text('stat-optimum');
  const m = row.match(/^1\.23 \(visibility graph\): this path \+(\d+\.\d)%$/);
  assert.ok(m, row);
  assert.equal(m[1], (100 * (s.cost / s.optimum - 1)).toFixed(1));
  // uniform sampling spends no checks per sample: the row is hidden
  assert.equal(await page.isVisible('#stat-sampler-checks'), false, 'no "Checks / sample" on a uniform run');
  assert.equal(await page.isVisible('#stat-draws'), true);
  // PRM's words differ from RRT's
  await page.selectOption('#planner', 'prm');
  await waitState('idle');
  assert.match(await page.$eval('[data-stat="iterations"] dt', (dt) => dt.title), /^PRM: .*milestone/);
  // a rigid bar's optimum is not the visibility graph's: no row
  await pickScenario('slot', 'Turn to pass the slot');
  assert.equal(await page.isVisible('#stat-optimum'), false);
});

test('the first click after typing a map name is not lost', async () => {
  await pickScenario('open-field', 'Open field');
  await page.click('#edit-name');
  await page.keyboard.press('End');
  await page.keyboard.type(' two', { delay: 30 });
  await page.waitForTimeout(600); // a person moves the mouse to the next button
  await page.click('#run');
  await page.waitForFunction(() => window.planarium.state() !== 'idle', null, { timeout: 10000 });
  assert.notEqual(await page.evaluate(() => window.planarium.state()), 'loading');
  assert.equal(await text('scenario-name'), 'Open field two');
  assert.equal((await page.evaluate(() => window.planarium.scenario())).name, 'Open field two');
});

test('the snapping grid is not drawn over a run', async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.check('#snap-grid');
  await nextFrames();
  const grid = () => page.evaluate(() => {
    // the grid's faint blue over the white background: count near-white bluish pixels
    const c = document.getElementById('canvas');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 2] - d[i] > 12 && d[i] > 180 && d[i + 2] > 200) n++;
    return n;
  });
  const before = { grid: await grid() };
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
  const during = { grid: await grid() };
  assert.ok(before.grid > 200, `the grid drawn while editing: ${JSON.stringify(before)}`);
  assert.ok(during.grid < before.grid / 4, `no grid over the run: ${JSON.stringify(during)} (before ${JSON.stringify(before)})`);
  await page.click('#reset');
  await waitState('idle');
  await nextFrames();
  assert.ok((await grid()) > 200, 'back after a reset');
});

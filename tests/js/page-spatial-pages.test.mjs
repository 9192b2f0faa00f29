// The Puma 560 of report 001 on the other pages. Compare: each lane shows the arm in 3-D (the
// playground's 3-D view, one per lane), a 2-D scenario brings the top views back. Benchmark: a few
// runs of the course's scenario give report 001's columns (solved, avgT, stdT, avgNodes,
// avgQueries), the means of the rows, and the course CSV (the CLI's `bench --course-csv`) with
// the CLI's vertices, state checks and free checks for the same seeds. Times are logged, never
// asserted. Screenshots go to target/spatial-*.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pageFixture, ROOT, SHOTS } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();

test('compare on puma-rbo-wall: both lanes show the arm in 3-D', async () => {
  const page = fx.page;
  await page.goto(`${fx.env.base}compare.html`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  await page.selectOption('#scenario', 'puma-rbo-wall');
  await page.waitForFunction(() => window.planarium.state() === 'idle' && document.getElementById('scenario-name').textContent.startsWith('Puma'), null, { timeout: 30000 });
  await page.waitForFunction(() => ['a', 'b'].every((k) => window.planarium.view3d(k).ready), null, { timeout: 20000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  for (const k of ['a', 'b']) {
    assert.equal((await page.evaluate((k) => window.planarium.view3d(k), k)).error, '');
    assert.equal(await page.isVisible(`#${k}-view3d`), true, `lane ${k}: the 3-D view`);
    assert.equal(await page.isVisible(`#${k}-canvas`), false, `lane ${k}: instead of the top view`);
    const b = await page.locator(`#${k}-view3d`).boundingBox();
    const [arm, obstacle] = await page.evaluate(({ k, c }) => window.planarium.view3dColours(k, c, 40), { k, c: [PALETTE.start, PALETTE.obstacle] });
    console.log(`lane ${k}: 3-D view ${Math.round(b.width)}×${Math.round(b.height)}, ${arm} pixels near the arm's colour, ${obstacle} near the wall's`);
    assert.ok(b.width >= 200 && b.height >= 150, `lane ${k}: a real picture`);
    assert.ok(arm > 300, `lane ${k}: the arm is drawn`);
  }
  await page.screenshot({ path: join(SHOTS, 'spatial-compare-1280.png') });
  await page.setViewportSize({ width: 390, height: 844 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await page.screenshot({ path: join(SHOTS, 'spatial-compare-390.png') });
  await page.setViewportSize({ width: 1280, height: 800 });
  // a 2-D scenario: the top views again
  await page.selectOption('#scenario', 'narrow');
  await page.waitForFunction(() => window.planarium.state() === 'idle' && document.getElementById('scenario-name').textContent === 'Narrow passage', null, { timeout: 30000 });
  for (const k of ['a', 'b']) {
    assert.equal(await page.isVisible(`#${k}-canvas`), true);
    assert.equal(await page.isVisible(`#${k}-view3d`), false);
  }
  assert.deepEqual(fx.errors, []);
});

test('benchmark on puma-rbo-wall: report 001\'s columns and the course CSV, as the CLI\'s', async () => {
  const page = fx.page;
  const runs = 3;
  // the scenario's planner block written out: the CLI puts a set-up on that block, the page on the
  // registry's defaults (docs/benchmarks.md), so the same line gives the same runs only this way
  const setup = 'last-free: rrt-connect --connect last-free --epsilon 1e-8 --time-limit 1200';
  await page.goto(`${fx.env.base}bench.html`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  await page.fill('#workers', '2');
  await page.selectOption('#scenario', 'puma-rbo-wall');
  if (!(await page.$eval('#advanced', (d) => d.open))) await page.click('#advanced summary');
  await page.fill('#setups', setup);
  await page.fill('#runs', String(runs));
  await page.click('#bench-run');
  await page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report(), null, { timeout: 600000 });
  const report = await page.evaluate(() => window.planarium.report());
  const rows = report.setups[0].rows;
  console.log(`page: ${rows.map((r) => `seed ${r.seed} ${r.solved ? 'solved' : r.status} ${r.nodes} nodes ${r.checks} checks ${r.time_ms.toFixed(0)} ms`).join('; ')}`);
  const head = await page.$$eval('#course-table thead th', (ths) => ths.map((t) => t.textContent));
  assert.deepEqual(head, ['set-up', 'solved', 'avgT (ms)', 'stdT (ms)', 'avgNodes', 'avgQueries']);
  const cells = await page.$$eval('#course-table tbody tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  assert.equal(cells.length, 1);
  const mean = (f) => rows.reduce((s, r) => s + f(r), 0) / rows.length;
  const solved = rows.filter((r) => r.solved).length;
  assert.equal(cells[0][0], 'last-free');
  assert.equal(cells[0][1], `${((100 * solved) / runs).toFixed(0)}%`);
  assert.ok(Math.abs(Number(cells[0][4]) - mean((r) => r.nodes)) <= 0.01 * mean((r) => r.nodes) + 1e-9, 'avgNodes is the mean of the nodes');
  assert.ok(Math.abs(Number(cells[0][5]) - mean((r) => r.checks)) <= 0.01 * mean((r) => r.checks) + 1e-9, 'avgQueries is the mean of the state checks');
  assert.ok(Math.abs(Number(cells[0][2]) - mean((r) => r.time_ms)) <= 0.01 * mean((r) => r.time_ms) + 0.01, 'avgT is the mean time');
  console.log(`report 001's columns in the page: ${cells[0].join(' | ')}`);
  // the course CSV: its header, one line a run, the free checks carried (not 0)
  assert.equal(await page.isEnabled('#export-course'), true);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-course')]);
  assert.equal(download.suggestedFilename(), 'puma-rbo-wall-course.csv');
  const csv = readFileSync(await download.path(), 'utf8');
  const lines = csv.trim().split('\n');
  assert.equal(lines[0], 'date,time,solved,plannerName,#vertices,#totalCollisionQueries,#freeQueries,time_ms');
  assert.equal(lines.length, 1 + runs);
  const fields = lines.slice(1).map((l) => l.split(','));
  fields.forEach((f, i) => {
    assert.equal(f[2], String(rows[i].solved));
    assert.equal(f[3], 'last-free');
    assert.equal(Number(f[4]), rows[i].nodes);
    assert.equal(Number(f[5]), rows[i].checks);
    assert.ok(Number(f[6]) > 0 && Number(f[6]) <= rows[i].checks, 'the free checks are carried');
  });
  await page.screenshot({ path: join(SHOTS, 'spatial-bench-1280.png'), fullPage: true });
  // the CLI's course CSV for the same seeds: the same counts
  const cli = join(ROOT, 'target/release/planarium');
  if (!existsSync(cli)) { console.log('no native CLI built: the course CSV is not compared with the CLI\'s'); return; }
  const dir = mkdtempSync(join(tmpdir(), 'planarium-course-'));
  execFileSync(cli, ['bench', 'puma-rbo-wall', '--runs', String(runs), '--setup', setup, '--course-csv', join(dir, 'course.csv')], { encoding: 'utf8' });
  const native = readFileSync(join(dir, 'course.csv'), 'utf8').trim().split('\n').slice(1).map((l) => l.split(','));
  console.log(`CLI's course lines: ${native.map((f) => f.slice(2).join(',')).join(' / ')}`);
  assert.deepEqual(fields.map((f) => f.slice(2, 7)), native.map((f) => f.slice(2, 7)), 'solved, name, vertices, checks and free checks as the CLI\'s');
  assert.deepEqual(fx.errors, []);
});

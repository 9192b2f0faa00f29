// The benchmark page in headless chromium, driven like a person: choose a scenario, type set-ups
// and a number of runs, run them over a pool of workers, and check the table against the native
// CLI's `bench` for the same seeds; the plots are drawn; the OMPL log parses with a small reader;
// cancel stops at once and keeps the page usable; a bad set-up line is named; a cancelled run
// reports the runs that really ran (table, caption, plot titles, exports) and eight set-ups'
// labels do not overlap (each label's drawn box, recorded from fillText; target/page-bench-eight.png).
// The figures for a slide (plot downloads, the results table copied) are in page-bench-slides.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pageFixture, ROOT, SHOTS } from './browser.mjs';
import { benchPage } from './bench-page.mjs';

const fx = await pageFixture();

const { openBench, typeSetups, runBench, waitReport } = benchPage(fx);

/** A reader for OMPL's benchmark log, following ompl_benchmark_statistics.py's readBenchmarkLog. */
function readOmplLog(text) {
  const lines = text.split('\n');
  let i = 0;
  const next = () => lines[i++];
  const header = {};
  header.version = next();
  header.experiment = next();
  while (i < lines.length && !/planners? in this benchmark|planner count/i.test(lines[i]) && !/^\d+ planners?$/.test(lines[i].trim())) i++;
  const planners = [];
  const count = parseInt(next(), 10);
  assert.ok(count > 0, 'a planner count');
  for (let p = 0; p < count; p++) {
    const name = next().trim();
    const common = parseInt(next(), 10);
    for (let k = 0; k < common; k++) next();
    const nprops = parseInt(next(), 10);
    const props = [];
    for (let k = 0; k < nprops; k++) props.push(next().trim());
    const nruns = parseInt(next(), 10);
    const runs = [];
    for (let k = 0; k < nruns; k++) runs.push(next().split(';').map((s) => s.trim()));
    // Progress properties (none, or a block as readBenchmarkLog reads it), then the planner's closing ".".
    let progress = null;
    if (lines[i].trim() !== '.') {
      const np = parseInt(next(), 10);
      const names = [];
      for (let k = 0; k < np; k++) names.push(next().trim());
      const pruns = parseInt(next(), 10);
      const samples = [];
      for (let k = 0; k < pruns; k++) samples.push(next().split(';').slice(0, -1).map((x) => x.split(',').slice(0, -1).map(Number)));
      progress = { names, runs: samples };
    }
    assert.equal(next().trim(), '.', `${name}: the closing "."`);
    planners.push({ name, props, runs, progress });
  }
  return { header, planners };
}

test('a benchmark over two workers gives the CLI\'s numbers, plots and exports', async () => {
  await openBench();
  await fx.page.fill('#workers', '2');
  await runBench('narrow', 'connect: rrt-connect\nbiased: rrt --goal-bias 0.2', 4);
  await fx.page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report(), null, { timeout: 120000 });
  const status = await fx.page.textContent('#bench-status');
  assert.match(status, /^8 runs in /);
  assert.equal(await fx.page.$eval('#bench-progress', (p) => p.value), 8);
  const report = await fx.page.evaluate(() => window.planarium.report());
  // The native CLI, same scenario, set-ups and seeds.
  const dir = mkdtempSync(join(tmpdir(), 'planarium-bench-'));
  const cli = join(ROOT, 'target/release/planarium');
  execFileSync(cli, ['bench', 'narrow', '--runs', '4', '--setup', 'connect: rrt-connect', '--setup', 'biased: rrt --goal-bias 0.2',
    '--json-file', join(dir, 'cli.json')], { encoding: 'utf8' });
  const native = JSON.parse(readFileSync(join(dir, 'cli.json'), 'utf8'));
  assert.equal(report.setups.length, 2);
  report.setups.forEach((s, k) => {
    const n = native.setups[k];
    assert.equal(s.label, n.label);
    assert.deepEqual(s.rows.map((r) => r.seed), [1, 2, 3, 4]);
    for (const key of ['solved', 'status', 'iterations', 'nodes', 'checks', 'cost', 'smoothed_cost']) {
      assert.deepEqual(s.rows.map((r) => r[key]), n.rows.map((r) => r[key]), `${s.label}: ${key}`);
    }
  });
  // The table shows the same medians as the CLI's summary.
  const cells = await fx.page.$$eval('#bench-table tbody tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  assert.equal(cells.length, 2);
  assert.equal(cells[0][0], 'connect');
  assert.equal(Number(cells[0][7]), native.setups[0].summary.checks.median);
  assert.equal(Number(cells[1][5]), native.setups[1].summary.nodes.median);
  assert.match(cells[0][1], /^100% \(4\/4\)$/);
  // The plots are drawn: the box plot has both set-ups' colours.
  const painted = await fx.page.evaluate(() => {
    const c = document.getElementById('plot-checks');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const near = (r, g, b) => { let n = 0; for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - r) < 8 && Math.abs(d[i + 1] - g) < 8 && Math.abs(d[i + 2] - b) < 8) n++; return n; };
    return [near(0x00, 0x72, 0xb2), near(0xe6, 0x9f, 0x00)];
  });
  assert.ok(painted[0] > 20 && painted[1] > 20, `box plot colours ${painted}`);
  // Exports: CSV rows, and an OMPL log our reader parses, with the CLI's numbers.
  const csv = await fx.page.evaluate(() => window.planarium.exported('csv'));
  assert.equal(csv.trim().split(/\r?\n/).length, 1 + 8);
  // times to the microsecond, without the float noise of a binary sum (5.1, not 5.1000000000000005)
  const timeAt = csv.split(/\r?\n/)[0].split(',').indexOf('time_ms');
  for (const line of csv.trim().split(/\r?\n/).slice(1)) assert.match(line.split(',')[timeAt], /^\d+(\.\d{1,3})?$/, line);
  const log = readOmplLog(await fx.page.evaluate(() => window.planarium.exported('ompl')));
  assert.equal(log.planners.length, 2);
  const p0 = log.planners[0];
  assert.equal(p0.runs.length, 4);
  const nodesAt = p0.props.findIndex((p) => /^graph states/.test(p));
  assert.ok(nodesAt >= 0, `a graph states property in ${p0.props}`);
  assert.deepEqual(p0.runs.map((r) => Number(r[nodesAt])), native.setups[0].rows.map((r) => r.nodes));
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench.png'), fullPage: true });
});

test('issue 17: PRM, Lazy PRM, EST, RRT-Connect and grid A* side by side on the zigzag, as the CLI gives them', async () => {
  await openBench();
  await fx.page.fill('#workers', '2');
  const setups = ['prm: prm', 'lazy: lazy-prm', 'est: est', 'connect: rrt-connect', 'astar: grid-search --search astar'];
  await runBench('zigzag', setups.join('\n'), 10);
  await fx.page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report(), null, { timeout: 240000 });
  assert.match(await fx.page.textContent('#bench-status'), /^50 runs in /);
  const report = await fx.page.evaluate(() => window.planarium.report());
  const dir = mkdtempSync(join(tmpdir(), 'planarium-bench-'));
  execFileSync(join(ROOT, 'target/release/planarium'), ['bench', 'zigzag', '--runs', '10',
    ...setups.flatMap((x) => ['--setup', x]), '--json-file', join(dir, 'cli.json')], { encoding: 'utf8' });
  const native = JSON.parse(readFileSync(join(dir, 'cli.json'), 'utf8'));
  assert.deepEqual(report.setups.map((x) => x.label), ['prm', 'lazy', 'est', 'connect', 'astar']);
  report.setups.forEach((x, k) => {
    assert.ok(x.rows.every((r) => r.solved), `${x.label}: every run solved`);
    for (const key of ['status', 'iterations', 'nodes', 'checks', 'cost', 'smoothed_cost']) {
      assert.deepEqual(x.rows.map((r) => r[key]), native.setups[k].rows.map((r) => r[key]), `${x.label}: ${key} as the CLI`);
    }
  });
  const cells = await fx.page.$$eval('#bench-table tbody tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  assert.deepEqual(cells.map((c) => c[0]), ['prm', 'lazy', 'est', 'connect', 'astar']);
  for (const c of cells) assert.match(c[1], /^100% \(10\/10\)$/);
  // Lazy PRM checks fewer motions than PRM on the same seeds (its roadmap's edges wait for a query)
  const median = (label) => native.setups[setups.findIndex((x) => x.startsWith(`${label}:`))].summary.checks.median;
  assert.ok(median('lazy') < median('prm'), `checks: lazy ${median('lazy')}, prm ${median('prm')}`);
  const log = readOmplLog(await fx.page.evaluate(() => window.planarium.exported('ompl')));
  assert.equal(log.planners.length, 5);
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench-issue17.png'), fullPage: true });
});

test('cancel stops the pool at once and the page stays usable; a bad line is named', async () => {
  await openBench();
  await runBench('horn-20', 'rrt-connect --time-limit 30', 50);
  await fx.page.waitForFunction(() => window.planarium.state() === 'running');
  await fx.page.waitForTimeout(300);
  await fx.page.click('#bench-cancel');
  await fx.page.waitForFunction(() => window.planarium.state() === 'idle', null, { timeout: 5000 });
  assert.match(await fx.page.textContent('#bench-status'), /^Cancelled after \d+ of 50 runs$/);
  // A typo is named by line and the run does not start.
  await typeSetups('rrt-connect\nrrt --goal-bais 0.2');
  await fx.page.click('#bench-run');
  assert.match(await fx.page.textContent('#bench-error'), /set-up line 2: --goal-bais is not a parameter of rrt/);
  assert.equal(await fx.page.evaluate(() => window.planarium.state()), 'idle');
  // And a good one runs afterwards.
  await runBench('narrow', 'rrt-connect', 2);
  await fx.page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report()?.setups[0].rows.length === 2, null, { timeout: 60000 });
});

test('RRT*: the best cost against time, one falling line per run, ending at the run\'s cost', async () => {
  await openBench();
  await runBench('open-field', 'star: rrt-star --improve-for 3000\nplain: rrt', 3);
  await fx.page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report(), null, { timeout: 120000 });
  const [curves, report] = await fx.page.evaluate(() => [window.planarium.curves(), window.planarium.report()]);
  assert.equal(curves[0].length, 3, 'a curve per RRT* run');
  assert.equal(curves[1].length, 0, 'none for plain RRT');
  curves[0].forEach((line, i) => {
    assert.ok(line.length >= 1);
    for (let k = 1; k < line.length; k++) {
      assert.ok(line[k][0] >= line[k - 1][0] && line[k][1] <= line[k - 1][1], `run ${i}: time rises, cost falls`);
    }
    const row = report.setups[0].rows.find((r) => r.seed === i + 1) ?? report.setups[0].rows[i];
    assert.ok(row.solved);
  });
  // The last point of each line is that run's cost (the rows are in seed order, lines in finishing order).
  const finals = curves[0].map((l) => l.at(-1)[1]).sort((a, b) => a - b);
  const costs = report.setups[0].rows.map((r) => r.cost).sort((a, b) => a - b);
  assert.deepEqual(finals, costs);
  assert.equal(await fx.page.$eval('#plot-curves', (c) => c.hidden), false);
  // the same progress in the OMPL log, as Planner Arena reads it: time (s) and best cost per run, in the runs' order
  const log = readOmplLog(await fx.page.evaluate(() => window.planarium.exported('ompl')));
  assert.deepEqual(log.planners[0].progress.names, ['time REAL', 'best cost REAL']);
  assert.equal(log.planners[0].progress.runs.length, 3);
  log.planners[0].progress.runs.forEach((samples, k) => {
    const row = report.setups[0].rows[k];
    assert.ok(samples.length >= 1, `run ${k}: samples`);
    assert.equal(samples.at(-1)[1], row.cost, `run ${k} (seed ${row.seed}): the last best cost is the run's cost`);
    for (let m = 1; m < samples.length; m++) assert.ok(samples[m][0] >= samples[m - 1][0] && samples[m][1] <= samples[m - 1][1]);
    const line = curves[0].find((l) => l.at(-1)[1] === row.cost);
    assert.deepEqual(samples, line.map(([ms, c]) => [ms / 1000, c]), `run ${k}: the curve in seconds`);
  });
  assert.equal(log.planners[1].progress, null, 'plain RRT has no progress');
});

// Reproduction 8 of issue 13: a benchmark cancelled part-way reports the seeds that really ran
// (table, caption, plot titles, exports), and eight set-ups' labels do not overlap on the plots.
test('a cancelled benchmark reports the runs that really ran; eight set-ups\' labels do not overlap', async () => {
  // every label the plots draw: its text, the canvas, the transform and the measured width
  await fx.page.addInitScript(() => {
    const C = CanvasRenderingContext2D.prototype;
    const fill = C.fillText;
    const clear = C.clearRect;
    window.plotTexts = {};
    C.clearRect = function (...a) {
      if (this.canvas.classList.contains('plot')) window.plotTexts[this.canvas.id] = [];
      return clear.apply(this, a);
    };
    C.fillText = function (text, x, y, ...rest) {
      if (this.canvas.classList.contains('plot')) {
        const m = this.getTransform();
        (window.plotTexts[this.canvas.id] ||= []).push({ text, x, y, align: this.textAlign, width: this.measureText(text).width,
          m: [m.a, m.b, m.c, m.d, m.e, m.f] });
      }
      return fill.call(this, text, x, y, ...rest);
    };
  });
  await openBench();
  await fx.page.fill('#workers', '2');
  const labels = [0.02, 0.03, 0.05, 0.08, 0.1, 0.15, 0.2, 0.3].map((r, i) => [`${i % 2 ? 'connect' : 'plain rrt'} with range ${r}`, r]);
  const setups = labels.map(([l, r], i) => `${l}: ${i % 2 ? 'rrt-connect' : 'rrt'} --range ${r}`).join('\n');
  await runBench('narrow', setups, 400);
  await fx.page.waitForFunction(() => Number(document.getElementById('bench-progress').value) >= 40, null, { timeout: 120000 });
  await fx.page.click('#bench-cancel');
  await fx.page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report(), null, { timeout: 10000 });
  const report = await fx.page.evaluate(() => window.planarium.report());
  const counts = report.setups.map((s) => s.rows.length);
  const done = counts.reduce((a, b) => a + b, 0);
  assert.ok(done >= 40 && done < 3200, `${done} runs done`);
  assert.match(await fx.page.textContent('#bench-status'), new RegExp(`^Cancelled after ${done} of 3200 runs$`));
  assert.equal(report.runs, Math.max(...counts), 'the report says the runs that ran, not the 400 asked');
  const caption = await fx.page.textContent('#bench-caption');
  assert.doesNotMatch(caption, /400 seeds/);
  assert.match(caption, new RegExp(`stopped after ${done} of 3200 runs`));
  for (const [k, s] of report.setups.entries()) {
    if (!caption.includes('seeds per set-up')) assert.ok(caption.includes(`${s.label} ${counts[k]}`), `caption names ${s.label}'s ${counts[k]} runs`);
  }
  const table = await fx.page.$$eval('#bench-table tbody tr', (trs) => trs.map((tr) => tr.children[1].textContent));
  table.forEach((cell, k) => assert.match(cell, new RegExp(`/${counts[k]}\\)$`), `table row ${k}: ${cell}`));
  const lo = Math.min(...counts), hi = Math.max(...counts);
  const n = lo === hi ? `${lo} runs each` : `${lo}–${hi} runs each`;
  for (const id of ['plot-success', 'plot-time', 'plot-nodes', 'plot-checks']) {
    assert.ok((await fx.page.getAttribute(`#${id}`, 'aria-label')).includes(n), `${id}'s title says ${n}`);
  }
  const json = JSON.parse(await fx.page.evaluate(() => window.planarium.exported('json')));
  assert.equal(json.runs, hi);
  json.setups.forEach((s, k) => assert.equal(s.summary.runs, counts[k]));
  const ompl = await fx.page.evaluate(() => window.planarium.exported('ompl'));
  assert.match(ompl, new RegExp(`^${hi} runs per planner$`, 'm'));
  assert.doesNotMatch(ompl, /^400 runs per planner$/m);
  // The labels under each plot: none overlaps another (text boxes, as drawn, tilted or not).
  const texts = await fx.page.evaluate(() => window.plotTexts);
  const names = labels.map(([l]) => l);
  const isLabel = (t) => names.includes(t) || (t.endsWith('…') && names.some((l) => l.startsWith(t.slice(0, -1))));
  const box = ({ x, y, align, width, m: [a, b, c, d, e, f] }) => {
    const left = align === 'center' ? x - width / 2 : align === 'right' || align === 'end' ? x - width : x;
    return [[left, y - 9], [left + width, y - 9], [left + width, y + 2], [left, y + 2]]
      .map(([px, py]) => [a * px + c * py + e, b * px + d * py + f]);
  };
  const overlap = (p, q) => { // separating axis test for convex quads
    for (const poly of [p, q]) {
      for (let i = 0; i < 4; i++) {
        const [x1, y1] = poly[i], [x2, y2] = poly[(i + 1) % 4];
        const axis = [y2 - y1, x1 - x2];
        const proj = (r) => r.map(([x, y]) => x * axis[0] + y * axis[1]);
        const [pa, qa] = [proj(p), proj(q)];
        if (Math.max(...pa) <= Math.min(...qa) || Math.max(...qa) <= Math.min(...pa)) return false;
      }
    }
    return true;
  };
  for (const id of ['plot-success', 'plot-time', 'plot-nodes', 'plot-checks']) {
    const drawn = (texts[id] || []).filter((t) => isLabel(t.text));
    assert.equal(drawn.length, 8, `${id}: eight labels drawn`);
    const boxes = drawn.map(box);
    for (let i = 0; i < 8; i++) for (let j = i + 1; j < 8; j++) {
      assert.ok(!overlap(boxes[i], boxes[j]), `${id}: "${drawn[i].text}" and "${drawn[j].text}" overlap`);
    }
    assert.match(await fx.page.getAttribute(`#${id}`, 'title'), /1\. plain rrt with range 0\.02\n2\. connect with range 0\.03/);
  }
  await fx.page.locator('#plots').screenshot({ path: join(SHOTS, 'page-bench-eight.png') });
  console.log(`# reproduction 8: cancelled after ${done} of 3200 runs; runs per set-up ${counts.join(', ')}`);
});

// Issue 14: set-ups from menus, log axes, a dot opens its run, state in the URL, opened files,
// a phone's table.

/** Record every text the plots draw (window.plotTexts[canvas id] = [{text, ...}]), from the next load. */
async function recordPlotTexts() {
  await fx.page.addInitScript(() => {
    const C = CanvasRenderingContext2D.prototype;
    const fill = C.fillText;
    const clear = C.clearRect;
    window.plotTexts = {};
    C.clearRect = function (...a) {
      if (this.canvas.classList.contains('plot')) window.plotTexts[this.canvas.id] = [];
      return clear.apply(this, a);
    };
    C.fillText = function (text, x, y, ...rest) {
      if (this.canvas.classList.contains('plot')) (window.plotTexts[this.canvas.id] ||= []).push({ text, x, y });
      return fill.call(this, text, x, y, ...rest);
    };
  });
}

/** The set-ups' labels as the list shows them. */
const listed = () => fx.page.$$eval('#setup-list .setup-label', (els) => els.map((e) => e.textContent));

test('set-ups built from the menus are the set-ups the same typed lines give, and they run', async () => {
  await openBench();
  await fx.page.selectOption('#scenario', 'narrow');
  assert.deepEqual(await listed(), ['rrt-connect', 'rrt'], 'the default set-ups are listed');
  // remove both defaults with their buttons
  await fx.page.click('#setup-list button[aria-label="Remove set-up rrt"]');
  await fx.page.click('#setup-list button[aria-label="Remove set-up rrt-connect"]');
  assert.deepEqual(await listed(), []);
  assert.match(await fx.page.textContent('#setup-list'), /No set-up yet/);
  // A: RRT, goal bias 0.2, Gaussian sampler, labelled "biased"
  await fx.page.fill('#build-label', 'biased');
  await fx.page.selectOption('#build-planner', 'rrt');
  await fx.page.fill('#build-param-goal_bias', '0.2');
  await fx.page.press('#build-param-goal_bias', 'Tab');
  await fx.page.selectOption('#build-param-sampler', 'gaussian');
  await fx.page.click('#add-setup');
  // B: RRT-Connect, no label; the sampler menu is shared by the planners (as in the playground):
  // back to uniform, the default, which the line leaves out
  await fx.page.selectOption('#build-planner', 'rrt-connect');
  assert.equal(await fx.page.$eval('#build-param-sampler', (s) => s.value), 'gaussian');
  await fx.page.selectOption('#build-param-sampler', 'uniform');
  await fx.page.click('#add-setup');
  assert.equal(await fx.page.textContent('#build-note'), 'Added: rrt-connect');
  assert.deepEqual(await listed(), ['biased', 'rrt-connect']);
  assert.doesNotMatch(await fx.page.textContent('#build'), /null/, 'no stray "null" under the panel');
  const built = await fx.page.evaluate(() => window.planarium.setups());
  // The same set-ups typed in the advanced form
  await typeSetups('biased: rrt --goal-bias 0.2 --sampler gaussian\nrrt-connect');
  const typed = await fx.page.evaluate(() => window.planarium.setups());
  assert.deepEqual(built, typed);
  assert.deepEqual(built[0], { label: 'biased', planner: 'rrt', params: { goal_bias: 0.2, sampler: 'gaussian' } });
  // a bad value in the builder is refused there, not added
  await fx.page.fill('#build-param-goal_bias', '7');
  await fx.page.press('#build-param-goal_bias', 'Tab');
  assert.equal(await fx.page.getAttribute('#build-param-goal_bias', 'aria-invalid'), 'true');
  // and they run
  await fx.page.fill('#runs', '2');
  await fx.page.click('#bench-run');
  await waitReport(2);
  const report = await fx.page.evaluate(() => window.planarium.report());
  assert.deepEqual(report.setups.map((s) => [s.label, s.planner, s.params]), [['biased', 'rrt', { goal_bias: 0.2, sampler: 'gaussian' }], ['rrt-connect', 'rrt-connect', {}]]);
  assert.deepEqual(await fx.page.$$eval('#bench-table tbody th', (t) => t.map((e) => e.textContent)), ['biased', 'rrt-connect']);
});

test('nodes spanning decades get a log axis with labelled decades; the toggle draws it linear; checks stay linear', async () => {
  await recordPlotTexts();
  await openBench();
  await runBench('open-field', 'connect: rrt-connect\nsmall steps: rrt --range 0.004', 3);
  await waitReport(3);
  const report = await fx.page.evaluate(() => window.planarium.report());
  const nodes = report.setups.flatMap((s) => s.rows.map((r) => r.nodes));
  const checks = report.setups.flatMap((s) => s.rows.map((r) => r.checks));
  assert.ok(Math.max(...nodes) / Math.min(...nodes) > 100, `nodes span ${Math.min(...nodes)}…${Math.max(...nodes)}`);
  assert.ok(Math.max(...checks) / Math.min(...checks) < 100, `checks span ${Math.min(...checks)}…${Math.max(...checks)}`);
  assert.equal(await fx.page.getAttribute('#plot-nodes', 'data-y-scale'), 'log');
  assert.equal(await fx.page.getAttribute('#plot-checks', 'data-y-scale'), 'linear');
  const texts = async (id) => (await fx.page.evaluate((i) => window.plotTexts[i] || [], id)).map((t) => t.text);
  const logNodes = await texts('plot-nodes');
  for (const decade of ['10', '100', '1000']) assert.ok(logNodes.includes(decade), `decade ${decade} labelled: ${logNodes.join(' | ')}`);
  assert.ok(logNodes.includes('nodes (log)'), 'the axis says log');
  await fx.page.locator('#plots').screenshot({ path: join(SHOTS, 'page-bench-log.png') });
  const logPixels = await fx.page.$eval('#plot-nodes', (c) => c.toDataURL());
  // the toggle: linear axes everywhere
  await fx.page.uncheck('#log-axes');
  assert.equal(await fx.page.getAttribute('#plot-nodes', 'data-y-scale'), 'linear');
  const linNodes = await texts('plot-nodes');
  assert.ok(!linNodes.includes('nodes (log)') && linNodes.includes('nodes'));
  assert.ok(!linNodes.includes('10'), `no decade ticks on a linear axis: ${linNodes.join(' | ')}`);
  assert.notEqual(await fx.page.$eval('#plot-nodes', (c) => c.toDataURL()), logPixels, 'the plot is redrawn');
  await fx.page.check('#log-axes');
  assert.equal(await fx.page.getAttribute('#plot-nodes', 'data-y-scale'), 'log');
});

test('a click on a run\'s dot offers that run in the playground, which opens with its scenario, set-up and seed', async () => {
  await openBench();
  await runBench('narrow', 'connect: rrt-connect\nbiased: rrt --goal-bias 0.2 --range 0.1', 3);
  await waitReport(3);
  const dots = await fx.page.evaluate(() => window.planarium.dots());
  const dot = dots.find((d) => d.series === 1 && d.seed === 2) || dots.find((d) => d.series === 1);
  const benchRow = (await fx.page.evaluate(() => window.planarium.report())).setups[1].rows.find((r) => r.seed === dot?.seed);
  assert.ok(dot, `a dot of "biased": ${JSON.stringify(dots)}`);
  await fx.page.locator('#plot-cost-time').scrollIntoViewIfNeeded();
  const box = await fx.page.locator('#plot-cost-time').boundingBox();
  // a click away from every dot offers nothing
  await fx.page.mouse.click(box.x + 4, box.y + 4);
  assert.equal(await fx.page.isVisible('#run-pop'), false);
  await fx.page.mouse.click(box.x + dot.x, box.y + dot.y);
  await fx.page.waitForSelector('#run-pop:not([hidden])');
  assert.match(await fx.page.textContent('#run-pop'), new RegExp(`biased, seed ${dot.seed}`));
  assert.equal(await fx.page.getAttribute('#run-open-tab', 'target'), '_blank');
  const href = await fx.page.getAttribute('#run-open', 'href');
  assert.match(href, new RegExp(`/index\\.html#scenario=narrow&planner=rrt&seed=${dot.seed}&`));
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench-dot.png') });
  await fx.page.click('#run-open');
  await fx.page.waitForURL(/index\.html#/);
  await fx.waitState('idle', 30000);
  await fx.page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Narrow passage');
  assert.equal(await fx.page.$eval('#planner', (s) => s.value), 'rrt');
  assert.equal(await fx.page.$eval('#seed', (s) => s.value), String(dot.seed));
  assert.equal(await fx.page.$eval('#param-goal_bias', (s) => s.value), '0.2');
  assert.equal(await fx.page.$eval('#param-range', (s) => s.value), '0.1');
  // run there: the same cost as the benchmark's run of that seed
  await fx.fastPlayback();
  await fx.page.click('#run');
  await fx.waitStatus('solved', 60000);
  const stats = await fx.page.evaluate(() => window.planarium.result().stats);
  assert.equal(stats.cost, benchRow.cost, 'the playground replays the benchmark\'s run: same cost');
  assert.equal(stats.nodes, benchRow.nodes, 'same nodes');
});

test('scenario, set-ups and runs live in the URL: a reload restores them; bad values are named and defaults used', async () => {
  await openBench();
  await fx.page.selectOption('#scenario', 'slot');
  await typeSetups('quick: rrt-connect --range 0.3\nrrt --goal-bias 0.25');
  await fx.page.fill('#runs', '7');
  await fx.page.press('#runs', 'Tab');
  await fx.page.waitForFunction(() => /runs=7/.test(location.hash));
  const url = fx.page.url();
  assert.match(url, /#scenario=slot&setups=quick:%20rrt-connect%20--range%200\.3%0Arrt%20--goal-bias%200\.25&runs=7$/);
  await fx.page.reload();
  await fx.page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  assert.equal(await fx.page.$eval('#scenario', (s) => s.value), 'slot');
  assert.equal(await fx.page.$eval('#runs', (s) => s.value), '7');
  assert.deepEqual(await listed(), ['quick', 'rrt --goal-bias 0.25']);
  assert.equal(await fx.page.isVisible('#bench-error'), false, 'a good link shows no error');
  // bad values: each named, defaults used
  await fx.page.goto('about:blank');
  await fx.page.goto(`${fx.env.base}bench.html#scenario=nowhere&setups=rrt%20--goal-bias%207&runs=0`);
  await fx.page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  const error = await fx.page.textContent('#bench-error');
  assert.match(error, /There is no built-in scenario "nowhere"/);
  assert.match(error, /setups=rrt --goal-bias 7: set-up line 1: goal_bias: must be between 0 and 1; the default set-ups are used/);
  assert.match(error, /runs=0: the number of runs must be a whole number from 1 to 10000; 20 is used/);
  assert.deepEqual(await listed(), ['rrt-connect', 'rrt']);
  assert.equal(await fx.page.$eval('#runs', (s) => s.value), '20');
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench-bad-link.png') });
  // a playground link (its planner set-up) opens here as the one set-up
  await fx.page.goto('about:blank');
  await fx.page.goto(`${fx.env.base}bench.html#scenario=narrow&planner=rrt&seed=4&goal_bias=0.3&range=0.1`);
  await fx.page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  assert.deepEqual(await fx.page.evaluate(() => window.planarium.setups()), [{ label: 'rrt --goal-bias 0.3 --range 0.1', planner: 'rrt', params: { range: 0.1, goal_bias: 0.3 } }]);
  assert.equal(await fx.page.$eval('#scenario', (s) => s.value), 'narrow');
});

test('Open file…: a scenario file and an ASV problem are benchmarked and kept in the link; a bad file is named', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'planarium-bench-file-'));
  const mine = JSON.parse(readFileSync(join(ROOT, 'scenarios/open-field.json'), 'utf8'));
  mine.name = 'My own field';
  const path = join(dir, 'my-field.json');
  writeFileSync(path, JSON.stringify(mine));
  const bad = join(dir, 'broken.json');
  writeFileSync(bad, '{"format": "planarium-scenario/1", "name": "x"}');
  await openBench();
  await fx.page.setInputFiles('#file', bad);
  await fx.page.waitForSelector('#bench-error:not([hidden])'); // the file is read asynchronously
  assert.match(await fx.page.textContent('#bench-error'), /broken\.json: bounds: is missing/);
  await fx.page.setInputFiles('#file', path);
  await fx.page.waitForFunction(() => window.planarium.scenario().name === 'My own field');
  assert.equal(await fx.page.isVisible('#bench-error'), false);
  assert.deepEqual(await fx.page.evaluate(() => window.planarium.scenario()), { id: 'my-own-field', name: 'My own field', builtin: false });
  assert.equal(await fx.page.$eval('#scenario', (s) => s.selectedOptions[0].textContent), 'File: my-field.json');
  await runBench2('rrt-connect', 2);
  const report = await fx.page.evaluate(() => window.planarium.report());
  assert.equal(report.scenario, 'My own field');
  assert.ok(report.setups[0].rows.every((r) => r.solved));
  // the link carries the scenario itself; a reload benchmarks it again
  await fx.page.waitForFunction(() => /scenario=deflate:/.test(location.hash));
  await fx.page.reload();
  await fx.page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  assert.equal((await fx.page.evaluate(() => window.planarium.scenario())).name, 'My own field');
  assert.equal(await fx.page.$eval('#scenario', (s) => s.selectedOptions[0].textContent), 'Scenario from a link');
  // an ASV problem (.txt), as the playground opens it
  await fx.page.setInputFiles('#file', join(ROOT, 'fuzz/corpus/asv_problem/3ASV-easy.txt'));
  await fx.page.waitForFunction(() => document.getElementById('scenario').selectedOptions[0].textContent === 'File: 3ASV-easy.txt');
  const asv = await fx.page.evaluate(() => window.planarium.scenario());
  assert.equal(asv.builtin, false);
  assert.equal(await fx.page.$eval('#scenario', (s) => s.selectedOptions[0].textContent), 'File: 3ASV-easy.txt');
  assert.equal(await fx.page.isVisible('#bench-error'), false);
});

/** Set the set-ups and runs, run, and wait for the report (on the scenario shown). */
async function runBench2(setups, runs) {
  await typeSetups(setups);
  await fx.page.fill('#runs', String(runs));
  await fx.page.click('#bench-run');
  await waitReport(runs);
}

test('a phone (390×844): the results table scrolls sideways inside its box; the page itself does not', async () => {
  await fx.page.setViewportSize({ width: 390, height: 844 });
  await openBench();
  await runBench('open-field', 'a long set-up label: rrt-connect\nanother long label: rrt --goal-bias 0.2', 2);
  await waitReport(2);
  const m = await fx.page.$eval('#table-scroll', (b) => ({ sw: b.scrollWidth, cw: b.clientWidth, right: b.getBoundingClientRect().right,
    page: document.documentElement.scrollWidth, overflow: getComputedStyle(b).overflowX }));
  assert.ok(m.sw > m.cw + 50, `the table is wider than its box: ${JSON.stringify(m)}`);
  assert.equal(m.overflow, 'auto');
  assert.ok(m.right <= 390 && m.page <= 390, `the box and the page fit the screen: ${JSON.stringify(m)}`);
  // the last column can be scrolled into view inside the box
  const lastHeader = '#bench-table thead th:last-child';
  const before = await fx.page.$eval(lastHeader, (th) => th.getBoundingClientRect().left);
  assert.ok(before > 390, `the last column starts off screen (${before})`);
  await fx.page.locator('#bench-table').scrollIntoViewIfNeeded();
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench-phone.png') });
  await fx.page.$eval('#table-scroll', (b) => { b.scrollLeft = b.scrollWidth; });
  const after = await fx.page.$eval(lastHeader, (th) => th.getBoundingClientRect().right);
  assert.ok(after <= 390, `scrolled, the last column is on screen (${after})`);
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench-phone-scrolled.png') });
});

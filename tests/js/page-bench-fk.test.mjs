// The benchmark page on the Technion course's arm (report 004): the results table adds the cost in
// the course's own unit (the fk distance: the norm of the stacked link-end differences, summed),
// its mean ± std and median recomputed here from each run's `cost_fk`, and the caption says what
// the unit is; a point-robot benchmark keeps the table without those columns (page-bench-slides).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { benchPage } from './bench-page.mjs';

const fx = await pageFixture();
const { openBench, runBench, waitReport } = benchPage(fx);

const stats = (v) => {
  const mean = v.reduce((a, b) => a + b, 0) / v.length;
  const std = Math.sqrt(v.reduce((a, b) => a + (b - mean) ** 2, 0) / (v.length - 1));
  const s = [...v].sort((a, b) => a - b);
  const median = s.length % 2 ? s[s.length >> 1] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
  return { mean, std, median };
};
const close = (shown, v, what) => assert.ok(Math.abs(Number(shown) - v) <= 1e-3 * Math.abs(v) + 0.051, `${what}: ${shown} against ${v}`);

test("an arm course's benchmark gives the cost in report 004's unit beside the joint-space cost", async () => {
  await openBench();
  await runBench('technion-mp', 'e1: rrt --extend connect\ne2: rrt --extend extend', 4);
  await waitReport(4);
  const head = await fx.page.$$eval('#bench-table thead th', (ths) => ths.map((t) => t.textContent));
  const at = (h) => { const k = head.indexOf(h); assert.ok(k > 0, `a column "${h}" in ${JSON.stringify(head)}`); return k; };
  const [mk, dk, sk] = [at('cost (fk) mean ± std'), at('cost (fk) median'), at('smoothed cost (fk) median')];
  const cells = await fx.page.$$eval('#bench-table tbody tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  const report = await fx.page.evaluate(() => window.planarium.report());
  report.setups.forEach((s, k) => {
    const solved = s.rows.filter((r) => r.solved);
    assert.ok(solved.length >= 2, `${s.label}: two or more solved runs to summarise`);
    const fk = stats(solved.map((r) => r.cost_fk));
    const joint = stats(solved.map((r) => r.cost));
    // the course's unit is link-end pixels: tens to hundreds, where joint space gives a few radians
    assert.ok(fk.median > 10 * joint.median, `${s.label}: fk ${fk.median} against joint ${joint.median}`);
    const [m, sd] = cells[k][mk].split(' ± ');
    close(m, fk.mean, `${s.label}: fk mean`);
    close(sd, fk.std, `${s.label}: fk std`);
    close(cells[k][dk], fk.median, `${s.label}: fk median`);
    close(cells[k][sk], stats(solved.map((r) => r.smoothed_cost_fk)).median, `${s.label}: smoothed fk median`);
  });
  assert.match(await fx.page.textContent('#bench-caption'), /cost \(fk\): the Technion course's unit \(report 004\)/);
});

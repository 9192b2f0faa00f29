// `npm run reproduce` (scripts/reproduce.mjs, issue 16): in quick mode it writes the four reports'
// tables, and the figures it writes are the CLI's own, read back here from the Markdown and
// recomputed from independent runs; report 004's cost unit is checked against a closed form and
// against the core's own `stats.cost_fk`.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PUMA_QUICK_ITERATIONS } from '../../scripts/reproduce/reports.mjs';
import { ci95, fkCost, fkDistance, linkEnds, median, std, t975, welch } from '../../scripts/reproduce/measure.mjs';

const root = new URL('../..', import.meta.url).pathname;
const bin = join(root, 'target', 'release', 'planarium');

/** The rows of the Markdown table that follows `heading` (cells trimmed), header first. */
function tableAfter(md, heading) {
  const at = md.indexOf(heading);
  assert.ok(at >= 0, `no "${heading}" in the document`);
  const lines = md.slice(at).split('\n');
  const start = lines.findIndex((l) => l.startsWith('| '));
  const rows = [];
  for (let i = start; i < lines.length && lines[i].startsWith('|'); i++) rows.push(lines[i].split('|').slice(1, -1).map((c) => c.trim()));
  return rows.filter((r) => !r.every((c) => c === '---'));
}

test('report 004\'s distance is the norm of the stacked link-end differences', () => {
  // Straight arm along x; turning the first joint by d moves each link end at radius r by the chord 2 r sin(d/2).
  const d = 0.3;
  const radii = [80, 150, 190, 230];
  const want = 2 * Math.sin(d / 2) * Math.sqrt(radii.reduce((a, r) => a + r * r, 0));
  assert.ok(Math.abs(fkDistance([0, 0, 0, 0], [d, 0, 0, 0]) - want) < 1e-9);
  assert.deepEqual(linkEnds([0, 0, 0, 0]).map((p) => p[0]), radii);
  // Turning only the last joint moves only the last end, by 2·40·sin(d/2).
  assert.ok(Math.abs(fkDistance([0.1, 0.2, -0.3, 0], [0.1, 0.2, -0.3, d]) - 80 * Math.sin(d / 2)) < 1e-9);
  assert.equal(fkCost([[0, 0, 0, 0], [d, 0, 0, 0], [0, 0, 0, 0]]), 2 * fkDistance([0, 0, 0, 0], [d, 0, 0, 0]));
  assert.equal(median([3, 1, 2, 10]), 2.5);
  assert.ok(Math.abs(std([1, 2, 3, 4]) - Math.sqrt(5 / 3)) < 1e-12);
});

test('the 95% t-intervals and Welch\'s test of report 001\'s Puma table', () => {
  // Student's t quantiles: the table (df 1, 30) and the series beyond it (df 39: 2.0227; df 120: 1.9799).
  assert.equal(t975(1), 12.706);
  assert.equal(t975(30), 2.042);
  assert.ok(Math.abs(t975(39) - 2.0227) < 0.001, t975(39));
  assert.ok(Math.abs(t975(120) - 1.9799) < 0.001, t975(120));
  const c = ci95([1, 2, 3, 4]);
  assert.equal(c.mean, 2.5);
  assert.ok(Math.abs(c.half - 3.182 * Math.sqrt(5 / 3) / 2) < 1e-12);
  // Two samples 10 apart with std 1: significant; 0.5 apart: not.
  const a = [9, 10, 11, 9, 10, 11], b = a.map((x) => x + 10), d = a.map((x) => x + 0.5);
  assert.equal(welch(a, b).significant, true);
  assert.equal(welch(a, d).significant, false);
  assert.ok(Math.abs(welch(a, b).df - 10) < 1e-9, 'equal variances and sizes: df = 2n − 2');
});

test('npm run reproduce --quick writes the four reports\' tables with the CLI\'s figures', { timeout: 300_000 }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'planarium-reproduce-test-'));
  try {
    const out = join(dir, 'r.md');
    const r = spawnSync(process.execPath, [join(root, 'scripts', 'reproduce.mjs'), '--quick', '--bin', bin, '--out', out], { encoding: 'utf8' });
    assert.equal(r.status, 0, r.stderr);
    const md = readFileSync(out, 'utf8');
    for (const h of ['## Report 000', '## Report 001', '## Report 003', '## Report 004']) assert.ok(md.includes(h), h);

    // Report 000: the asv-3-easy row's median nodes and cost, recomputed from two runs of `plan`.
    const t0 = tableAfter(md, '## Report 000');
    const row = t0.find((c) => c[1] === '`asv-3-easy`');
    assert.ok(row, 'no asv-3-easy row');
    const plans = [1, 2].map((s) => JSON.parse(spawnSync(bin, ['plan', 'asv-3-easy', '--planner', 'rrt-connect', '--seed', String(s), '--json', '--time-limit', '10'], { encoding: 'utf8' }).stdout));
    assert.equal(row[3], '2/2');
    assert.equal(row[6], median(plans.map((p) => p.stats.nodes)).toFixed(0));
    assert.equal(row[8], median(plans.map((p) => p.stats.cost)).toFixed(3));
    assert.equal(row[2], '1795');
    assert.match(md, /4 of 4 problems pass/, 'the course grade of the four official files');

    // Report 001 on the Puma: ten set-ups, the default's ratio 1; its 2 runs' mean nodes and queries recomputed
    // from `plan` with the scenario's own planner block and quick mode's iteration cap.
    const tp = tableAfter(md, '### On the report\'s own robot');
    assert.equal(tp.length, 11);
    assert.equal(tp[1][0], 'default');
    assert.equal(tp[1][7], '1.00');
    const pumas = [1, 2].map((s) => JSON.parse(spawnSync(bin, ['plan', 'puma-rbo-wall', '--seed', String(s), '--json', '--max-iterations', String(PUMA_QUICK_ITERATIONS), '--time-limit', '10'], { encoding: 'utf8' }).stdout));
    assert.equal(tp[1][4].split(' ± ')[0], ((pumas[0].stats.nodes + pumas[1].stats.nodes) / 2).toFixed(0));
    assert.equal(tp[1][5].split(' ± ')[0], ((pumas[0].stats.checks + pumas[1].stats.checks) / 2).toFixed(0));
    const tc = tableAfter(md, 'Beside the report');
    assert.deepEqual(tc[1].slice(1, 7), ['22398.83', '11029.82', '12495.75', '578095', '1.00', '1.00']);
    assert.equal(tc.find((r) => r[0] === '3.1 Gaussian')[7], String(Math.ceil(1.96 ** 2 * (13054.23 ** 2 + 11029.82 ** 2) / (18994.21 - 22398.83) ** 2)));

    // Report 001 on the stand-ins: seven set-ups per scene, the default's ratio 1, the report's columns as printed.
    const t1 = tableAfter(md, '### Narrow passage');
    assert.equal(t1.length, 8);
    assert.deepEqual(t1[1].slice(6), ['1.00', '22398.83', '11029.82', '12495.75', '578095', '1.00']);

    // Report 004: the E1-0.05 row's cost in the report's unit, recomputed from the same runs.
    const t4 = tableAfter(md, '## Report 004');
    const e1 = t4.find((c) => c[0] === 'E1-0.05');
    const runs = [1, 2].map((s) => JSON.parse(spawnSync(bin, ['plan', 'technion-mp', '--planner', 'rrt', '--goal-bias', '0.05', '--extend', 'connect', '--time-limit', '5', '--seed', String(s), '--json'], { encoding: 'utf8' }).stdout));
    const ok = runs.filter((x) => x.solved);
    assert.equal(e1[1], `${ok.length}/2`);
    assert.equal(e1[2], (ok.reduce((a, x) => a + fkCost(x.path), 0) / ok.length).toFixed(2));
    assert.equal(e1[3], (ok.reduce((a, x) => a + x.stats.cost, 0) / ok.length).toFixed(3));
    assert.equal(e1[6], '344.694');
    // the core's own fk cost (stats.cost_fk) agrees with the script's recomputation
    for (const x of ok) assert.ok(Math.abs(x.stats.cost_fk - fkCost(x.path)) <= 1e-9 * x.stats.cost_fk, `${x.stats.cost_fk} vs ${fkCost(x.path)}`);

    // Report 004's inspection: every solved run meets its target by the course's count
    const ti = tableAfter(md, '### Inspection at coverage');
    for (const target of ['0.5', '0.75']) {
      const r = ti.find((c) => c[0] === target);
      assert.ok(r, `no row for ${target}`);
      assert.ok(Number(r[7]) >= Number(target) - 1e-12, `least course coverage ${r[7]} below ${target}`);
      assert.ok(Number(r[8]) >= Number(r[6]), 'the continuous count is never below the course\'s');
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

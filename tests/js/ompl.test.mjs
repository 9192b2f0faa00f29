// OMPL in the benchmark suite (scripts/ompl.mjs, bench/ompl/harness.cpp): the detection says
// plainly when OMPL is missing; the problem file carries the scenario's set-up; and, where OMPL 1.5
// is installed (Debian's libompl-dev), the harness builds, solves the narrow passage with OMPL's
// RRT-Connect, counts its state checks, repeats a seed exactly and fails a closed wall.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { NOT_INSTALLED, OMPL_INCLUDE, buildHarness, detectOmpl, problemText, runHarness } from '../../scripts/ompl.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const scenario = (id) => JSON.parse(readFileSync(join(root, 'scenarios', `${id}.json`), 'utf8'));
const found = detectOmpl();

test('without OMPL\'s headers the suite is told "not installed", and says so in those words', () => {
  const missing = detectOmpl({ include: join(tmpdir(), 'no-ompl-here') });
  assert.equal(missing.installed, false);
  assert.equal(missing.message, "OMPL not installed (Debian's libompl-dev): OMPL not measured");
  assert.equal(missing.message, NOT_INSTALLED);
  // On this machine, with the default paths: not installed exactly when the header is missing
  // (or, with the header, when no g++ can build the harness).
  if (!existsSync(join(OMPL_INCLUDE, 'ompl', 'geometric', 'SimpleSetup.h'))) assert.deepEqual(found, missing);
  else assert.ok(found.installed || /no g\+\+/.test(found.message), found.message);
});

test('the problem file carries the scenario\'s bounds, resolution, range, goal bias, robot and obstacles', () => {
  const narrow = problemText(scenario('narrow'), 'rrt', { range: 0.2828 });
  assert.ok('text' in narrow);
  const lines = narrow.text.trim().split('\n');
  assert.deepEqual(lines.slice(0, 8), [
    'robot point', 'bounds 0 0 1 1', 'resolution 0.0014', 'range 0.2828', 'goal_bias 0.05', 'goal_tolerance 0', 'start 2 0.1 0.1', 'goal 2 0.9 0.9',
  ]);
  assert.deepEqual(lines.slice(8), ['polygon 4 0.45 0 0.55 0 0.55 0.49 0.45 0.49', 'polygon 4 0.45 0.51 0.55 0.51 0.55 1 0.45 1']);
  const bar = problemText(scenario('ompl-rect'), 'rrt-connect', { range: 0.597 });
  assert.ok(bar.text.includes('\ngoal_bias 0\n'));
  assert.ok(bar.text.includes('\nfootprint 4 -0.05 -0.01 0.05 -0.01 0.05 0.01 -0.05 0.01\nrotation_weight 0.5\n'));
  const horn = problemText(scenario('horn-10'), 'rrt-connect', { range: 1 });
  assert.ok(horn.text.startsWith('robot chain\n'));
  assert.ok(horn.text.includes('\nlinks 10 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\ntip 0.001\nself_collision 1\n'));
  assert.equal(horn.text.split('\nsegment ').length - 1, 18);
  // What OMPL has no match for is named, not run.
  assert.match(problemText(scenario('narrow'), 'prm', {}).skip, /not prm/);
  assert.match(problemText(scenario('narrow'), 'rrt', { extend: 'connect' }).skip, /extend/);
  assert.match(problemText(scenario('narrow'), 'rrt-connect', { goal_bias: 0.1 }).skip, /no goal bias/);
  const round = { ...scenario('narrow'), obstacles: [{ circle: [0.5, 0.5, 0.1] }] };
  assert.match(problemText(round, 'rrt', {}).skip, /circle/);
});

test('OMPL installed: the harness solves the narrow passage with RRT-Connect, counts its checks, repeats a seed', { skip: !found.installed && found.message }, () => {
  const bin = buildHarness(root);
  const dir = mkdtempSync(join(tmpdir(), 'planarium-ompl-'));
  const file = join(dir, 'narrow.txt');
  writeFileSync(file, problemText(scenario('narrow'), 'rrt-connect', { range: 0.2828 }).text);
  const rows = runHarness(bin, file, 'rrt-connect', 1, 3, 10);
  assert.deepEqual(rows.map((r) => r.seed), [1, 2, 3]);
  for (const r of rows) {
    assert.equal(r.solved, true, `seed ${r.seed}`);
    assert.ok(r.checks > 0 && r.nodes >= 2 && r.time_ms > 0, JSON.stringify(r));
  }
  const again = runHarness(bin, file, 'rrt-connect', 2, 2, 10);
  assert.deepEqual([again[0].checks, again[0].nodes], [rows[1].checks, rows[1].nodes]);
  // Close the gap: the validity checker sees the wall, so nothing is found within the limit.
  const closed = { ...scenario('narrow'), obstacles: [{ rect: [0.45, 0, 0.55, 1] }] };
  writeFileSync(file, problemText(closed, 'rrt-connect', { range: 0.2828 }).text);
  const [blocked] = runHarness(bin, file, 'rrt-connect', 1, 1, 0.2);
  assert.equal(blocked.solved, false);
  assert.ok(blocked.checks > 0);
});

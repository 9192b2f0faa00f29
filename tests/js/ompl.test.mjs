// OMPL in the benchmark suite (scripts/ompl.mjs, bench/ompl/harness.cpp): the detection says
// plainly when OMPL is missing; the problem file carries the scenario's set-up; and, where OMPL 1.5
// is installed (Debian's libompl-dev), the harness builds, solves the narrow passage with OMPL's
// RRT-Connect, counts its state checks, repeats a seed exactly and fails a closed wall.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { NOT_INSTALLED, SWITCHED_OFF, OMPL_INCLUDE, buildHarness, detectOmpl, problemText, runHarness } from '../../scripts/ompl.mjs';

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

test('PLANARIUM_OMPL=0 leaves OMPL out: a whole suite run says so and measures Planarium alone', () => {
  assert.deepEqual(detectOmpl({ env: { PLANARIUM_OMPL: '0' } }), { installed: false, message: SWITCHED_OFF });
  assert.equal(detectOmpl({ include: join(tmpdir(), 'no-ompl-here'), env: { PLANARIUM_OMPL: '1' } }).message, NOT_INSTALLED);
  // the suite itself, on the narrow passage (a smoke run: 3 seeds, one round), into a folder of its own
  const out = mkdtempSync(join(tmpdir(), 'planarium-suite-off-'));
  const log = execFileSync(process.execPath, [join(root, 'scripts', 'bench.mjs'), '--quick', '--runs', '3', '--only', 'narrow', '--out', out],
    { cwd: root, encoding: 'utf8', env: { ...process.env, PLANARIUM_OMPL: '0' }, stdio: ['ignore', 'pipe', 'pipe'] });
  assert.match(log, /\[bench\] OMPL left out \(PLANARIUM_OMPL=0\): OMPL not measured/);
  assert.doesNotMatch(log, /g\+\+ -O3 bench\/ompl\/harness\.cpp/, 'no harness is built');
  const md = readdirSync(out).find((f) => f.endsWith('.md'));
  const text = readFileSync(join(out, md), 'utf8');
  assert.ok(text.includes(`${SWITCHED_OFF}. `), 'the table\'s preamble says why OMPL is missing');
  const rows = text.split('\n').filter((l) => l.startsWith('| narrow |'));
  assert.equal(rows.length, 2, 'RRT and RRT-Connect on the narrow passage');
  for (const row of rows) {
    const cells = row.split(' | ');
    assert.equal(cells[7], 'not measured', `OMPL's solved column: ${row}`);
    assert.equal(cells[8], 'not measured', `OMPL's time column: ${row}`);
    assert.match(cells[2], /^3\/3$/, `Planarium solved its 3 seeds: ${row}`);
  }
  const json = JSON.parse(readFileSync(join(out, md.replace(/\.md$/, '.json')), 'utf8'));
  assert.ok(json.results[0].ompl === null || json.results[0].ompl.every((o) => !o.rows), 'no OMPL rows in the results');
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
  // RRT*: only improving until the time limit, as OMPL's does; its default goal bias is RRT's.
  assert.match(problemText(scenario('narrow'), 'rrt-star', { range: 0.2828 }).skip, /improves until its time limit/);
  const star = problemText(scenario('narrow'), 'rrt-star', { range: 0.2828, improve_for: 1e8, max_nodes: 1e6, time_limit: 1 });
  assert.ok(star.text.includes('\nrange 0.2828\ngoal_bias 0.05\n'), star.text);
  assert.match(problemText(scenario('narrow'), 'rrt-star', { improve_for: 1e8, rewire: 'radius' }).skip, /rewire/);
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
  // With --paths: the same runs, each with its path from the start to the goal, which check-path
  // reads (every path judged, each one's seed given back).
  const withPaths = runHarness(bin, file, 'rrt-connect', 1, 3, 10, { paths: true });
  assert.deepEqual(withPaths.map((r) => [r.checks, r.nodes]), rows.map((r) => [r.checks, r.nodes]));
  for (const r of withPaths) assert.deepEqual([r.path[0], r.path.at(-1)], [[0.1, 0.1], [0.9, 0.9]], `seed ${r.seed}`);
  const paths = join(dir, 'paths.jsonl');
  writeFileSync(paths, withPaths.map((r) => JSON.stringify({ seed: r.seed, path: r.path })).join('\n'));
  const checked = spawnSync(join(root, 'target', 'release', 'planarium'), ['check-path', join(root, 'scenarios', 'narrow.json'), paths, '--json'], { encoding: 'utf8' });
  assert.ok(checked.status === 0 || checked.status === 1, checked.stderr);
  const verdicts = JSON.parse(checked.stdout);
  assert.deepEqual(verdicts.paths.map((v) => v.seed), [1, 2, 3]);
  assert.equal(verdicts.valid + verdicts.refused, 3);
  // Close the gap: the validity checker sees the wall, so nothing is found within the limit.
  const closed = { ...scenario('narrow'), obstacles: [{ rect: [0.45, 0, 0.55, 1] }] };
  writeFileSync(file, problemText(closed, 'rrt-connect', { range: 0.2828 }).text);
  const [blocked] = runHarness(bin, file, 'rrt-connect', 1, 1, 0.2);
  assert.equal(blocked.solved, false);
  assert.ok(blocked.checks > 0);
});

test('OMPL installed: its RRT* improves until the time limit, and its cost is the length of a path the gap allows', { skip: !found.installed && found.message }, () => {
  const bin = buildHarness(root);
  const dir = mkdtempSync(join(tmpdir(), 'planarium-ompl-star-'));
  const file = join(dir, 'narrow.txt');
  writeFileSync(file, problemText(scenario('narrow'), 'rrt-star', { range: 0.2828, improve_for: 1e8 }).text);
  const rows = runHarness(bin, file, 'rrt-star', 1, 2, 0.3);
  for (const r of rows) {
    assert.equal(r.solved, true, `seed ${r.seed}`);
    // it used its whole budget (a lower bound: a busy machine only makes it later)
    assert.ok(r.time_ms >= 290, `RRT* stopped at ${r.time_ms} ms, before its 0.3 s`);
    // (0.1, 0.1) to (0.9, 0.9) through the 0.02 gap at x 0.45..0.55, y 0.49..0.51: no path is
    // shorter than through the gap's corners (1.1500, the visibility graph's), nor far longer here
    assert.ok(r.cost >= 1.15 - 1e-9 && r.cost < 2, `cost ${r.cost}`);
  }
  // RRT and RRT-Connect report their path's length too
  writeFileSync(file, problemText(scenario('narrow'), 'rrt', { range: 0.2828 }).text);
  const [rrt] = runHarness(bin, file, 'rrt', 1, 1, 10);
  assert.ok(rrt.solved && rrt.cost >= 1.15 - 1e-9, JSON.stringify(rrt));
});

test('the suite\'s RRT* at a fixed budget: both sides on narrow and ompl-rect, the table read back against the JSON', { skip: !found.installed && found.message }, () => {
  const out = mkdtempSync(join(tmpdir(), 'planarium-suite-star-'));
  execFileSync(process.execPath, [join(root, 'scripts', 'bench.mjs'), '--quick', '--only', 'rrt-star-budget', '--out', out],
    { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const md = readdirSync(out).find((f) => f.endsWith('.md'));
  const text = readFileSync(join(out, md), 'utf8');
  const json = JSON.parse(readFileSync(join(out, md.replace(/\.md$/, '.json')), 'utf8'));
  assert.deepEqual(json.rrt_star_budget.map((r) => [r.problem, r.budget_s, r.native.length, r.ompl.rows.length]), [['narrow', 0.2, 3, 3], ['ompl-rect', 0.2, 3, 3]]);
  const rows = text.split('\n').filter((l) => /^\| (narrow|ompl-rect) \| 0\.2 s \|/.test(l));
  assert.equal(rows.length, 2, text);
  const median = (xs) => { const v = [...xs].sort((a, b) => a - b); return v.length % 2 ? v[(v.length - 1) / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2; };
  json.rrt_star_budget.forEach((r, i) => {
    const cells = rows[i].split(' | ');
    for (const [side, list, at] of [['Planarium', r.native, 3], ['OMPL', r.ompl.rows, 7]]) {
      const costs = list.filter((x) => x.solved && x.cost >= 0).map((x) => x.cost);
      assert.equal(cells[at - 1], `${costs.length}/3`, `${side}'s solved count on ${r.problem}`);
      if (costs.length) assert.equal(Number(cells[at]), Number(median(costs).toFixed(4)), `${side}'s median cost on ${r.problem}`);
      // narrow: no path is shorter than the visibility graph's 1.1500
      if (r.problem === 'narrow') assert.ok(costs.every((c) => c >= 1.15 - 1e-9), `${side}: ${costs}`);
    }
    // Planarium's runs used the budget: each stopped at its time limit, not before
    assert.ok(r.native.every((x) => x.time_ms >= 190), `Planarium's RRT* on ${r.problem} stopped early`);
  });
});

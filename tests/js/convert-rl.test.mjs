// The Puma 560 scenarios (scripts/convert-rl.mjs, from the Robotics Library's files in
// data/rl-puma560/) checked against rl's files by code of this test's own, never the converter's:
// - forward kinematics of the converted DH rows at q = 0, without the world rotation, puts every
//   link frame where rl's display file (rlsg/unimation-puma560.convex/unimation-puma560.wrl) does;
// - each hull is the file's points through the file's Transform, not flat, and the arm at q = 0
//   stands on the floor (z = 0) rather than through it (the base's hull is turned over by its file);
// - limits, ignored pairs, the room's boxes, start, goal and delta are rl's numbers in radians;
// - the course's wall leaves the 16 cm window of report 001 open and closes it all round;
// - `--check` passes on the committed files and fails on a changed one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { copyFileSync, cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const root = new URL('../..', import.meta.url).pathname;
const data = join(root, 'data', 'rl-puma560');
const convex = join(data, 'rlsg', 'unimation-puma560.convex');
const scenario = (name) => JSON.parse(readFileSync(join(root, 'scenarios', `${name}.json`), 'utf8'));
const wall = scenario('puma-rbo-wall');
const room = scenario('puma-boxes');
const BOTH = [['puma-rbo-wall', wall], ['puma-boxes', room]];
const deg = (x) => x * Math.PI / 180;
const numbers = (s) => s.trim().split(/[\s,]+/).map(Number);

// 4×4 homogeneous matrices, row-major.
const matmul = (A, B) => A.map((row) => B[0].map((_, c) => row.reduce((s, v, k) => s + v * B[k][c], 0)));
const Rz = (t) => [[Math.cos(t), -Math.sin(t), 0, 0], [Math.sin(t), Math.cos(t), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
const Rx = (t) => [[1, 0, 0, 0], [0, Math.cos(t), -Math.sin(t), 0], [0, Math.sin(t), Math.cos(t), 0], [0, 0, 0, 1]];
const Tr = (x, y, z) => [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]];
const I4 = Tr(0, 0, 0);
/** Rotation by angle t about axis (x, y, z): R = cos t·I + sin t·[u]× + (1 − cos t)·u uᵀ. */
function axisAngle(x, y, z, t) {
  const n = Math.hypot(x, y, z);
  const u = [x / n, y / n, z / n];
  const cross = [[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]];
  const R = [0, 1, 2].map((r) => [0, 1, 2].map((c) => (r === c ? Math.cos(t) : 0) + Math.sin(t) * cross[r][c] + (1 - Math.cos(t)) * u[r] * u[c]));
  return [[...R[0], 0], [...R[1], 0], [...R[2], 0], [0, 0, 0, 1]];
}
const point = (M, p) => [0, 1, 2].map((r) => M[r][0] * p[0] + M[r][1] * p[1] + M[r][2] * p[2] + M[r][3]);

/** Every link's frame: base · Π Rz(theta + q)·Tz(d)·Tx(a)·Rx(alpha). */
function frames(robot, q, base = I4) {
  const out = [base];
  robot.joints.forEach((j, k) => {
    out.push(matmul(out[k], matmul(matmul(matmul(Rz(j.theta + q[k]), Tr(0, 0, j.d)), Tr(j.a, 0, 0)), Rx(j.alpha))));
  });
  return out;
}
/** The world pose of the base: Rz(rz)·Ry(ry)·Rx(rx) then the translation (ry is zero here). */
function basePose(robot) {
  const [rx, ry, rz] = robot.base.rotation;
  assert.equal(ry, 0);
  return matmul(matmul(Tr(...robot.base.translation), Rz(rz)), Rx(rx));
}

/** DEF name → {rotation, translation, scale} of each `DEF x Transform { … }` header in a .wrl file. */
function placements(text) {
  const out = new Map();
  for (const m of text.matchAll(/DEF\s+(\S+)\s+Transform\s*\{([^{}[]*?)children/g)) {
    const field = (name) => { const f = new RegExp(`${name}\\s+([-+\\d.eE\\s]+)`).exec(m[2]); return f ? numbers(f[1]) : null; };
    out.set(m[1], { rotation: field('rotation'), translation: field('translation'), scale: field('scale') });
  }
  return out;
}
/** The placement as a matrix: T·R·S. */
function placementMatrix(p) {
  let M = I4;
  if (p.translation) M = matmul(M, Tr(...p.translation));
  if (p.rotation) M = matmul(M, axisAngle(...p.rotation));
  if (p.scale) M = matmul(M, [[p.scale[0], 0, 0, 0], [0, p.scale[1], 0, 0], [0, 0, p.scale[2], 0], [0, 0, 0, 1]]);
  return M;
}
const rawPoints = (text) => {
  const flat = numbers(/point\s*\[([^\]]*)\]/.exec(text)[1]);
  return Array.from({ length: flat.length / 3 }, (_, k) => flat.slice(3 * k, 3 * k + 3));
};

const kinText = readFileSync(join(data, 'rlkin', 'unimation-puma560.xml'), 'utf8');
const planText = readFileSync(join(data, 'rlplan', 'unimation-puma560_boxes_rrtConCon.xml'), 'utf8');
const inner = (text, tag) => [...text.matchAll(new RegExp(`<${tag}(?:\\s[^>]*)?>([^<]*)</${tag}>`, 'g'))].map((m) => Number(m[1]));

test('forward kinematics at q = 0 puts every link frame where rl\'s display file does', () => {
  const shown = placements(readFileSync(join(convex, 'unimation-puma560.wrl'), 'utf8'));
  for (const [name, s] of BOTH) {
    const { robot } = s;
    assert.equal(robot.kind, 'spatial-arm');
    assert.equal(robot.joints.length, 6, name);
    assert.equal(robot.links.length, 7, name);
    const fk = frames(robot, robot.joints.map(() => 0));
    robot.links.forEach((link, k) => {
      assert.equal(link.name, `link${k}`);
      const want = placementMatrix(shown.get(link.name));
      for (let r = 0; r < 3; r++) {
        for (let c = 0; c < 4; c++) {
          assert.ok(Math.abs(fk[k][r][c] - want[r][c]) <= 1e-5,
            `${name}: link${k} frame [${r}][${c}] is ${fk[k][r][c]}, rl's display file says ${want[r][c]}`);
        }
      }
    });
    // The DH rows are rl's (d, a in metres; theta, alpha in degrees) and so are the limits.
    const dh = ['d', 'theta', 'a', 'alpha'].map((f) => inner(kinText, f));
    const [lo, hi] = [inner(kinText, 'min'), inner(kinText, 'max')];
    robot.joints.forEach((j, k) => {
      assert.deepEqual([j.d, j.theta, j.a, j.alpha], [dh[0][k], deg(dh[1][k]), dh[2][k], deg(dh[3][k])], `${name}: joint ${k}`);
      assert.deepEqual(j.limits, [deg(lo[k]), deg(hi[k])], `${name}: joint ${k}'s limits`);
    });
    assert.deepEqual(robot.base, { translation: [0, 0, 0], rotation: [0, 0, Math.PI / 2] });
  }
});

test('each hull is its file\'s points through its file\'s Transform, not flat, and the arm stands on the floor', () => {
  for (const [name, { robot }] of BOTH) {
    const fk = frames(robot, robot.joints.map(() => 0), basePose(robot));
    let lowest = Infinity;
    robot.links.forEach((link, k) => {
      const text = readFileSync(join(convex, `link${k}.wrl`), 'utf8');
      const raw = rawPoints(text);
      const M = placementMatrix(placements(text).get(`link${k}`));
      assert.equal(link.hull.length, raw.length, `${name}: link${k}'s point count`);
      link.hull.forEach((p, i) => {
        const want = point(M, raw[i]);
        for (let c = 0; c < 3; c++) assert.ok(Math.abs(p[c] - want[c]) < 1e-12, `${name}: link${k} point ${i}: ${p} against ${want}`);
      });
      // Not flat: a tetrahedron of its points with a height of over 5 mm (link6, the flange, is 1 cm thick).
      const h = link.hull;
      const sub = (a, b) => a.map((v, c) => v - b[c]);
      const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
      const far = (f) => h.reduce((best, p) => (f(p) > f(best) ? p : best));
      const p0 = h[0];
      const p1 = far((p) => Math.hypot(...sub(p, p0)));
      const p2 = far((p) => Math.hypot(...cross(sub(p1, p0), sub(p, p0))));
      const n = cross(sub(p1, p0), sub(p2, p0));
      const height = Math.abs(dot(n, sub(far((p) => Math.abs(dot(n, sub(p, p0)))), p0))) / Math.hypot(...n);
      assert.ok(h.length >= 4 && height > 0.005, `${name}: link${k}'s hull is flat (${h.length} points, height ${height})`);
      for (const p of h) lowest = Math.min(lowest, point(fk[k], p)[2]);
      if (k === 0) assert.ok(Math.abs(Math.min(...h.map((p) => point(fk[0], p)[2]))) < 2e-3, `${name}: the base's hull does not start at the floor`);
    });
    assert.ok(lowest > -2e-3, `${name}: the arm at q = 0 reaches below the floor, to z = ${lowest}`);
  }
});

test('ignored pairs, exempt links, tool, start, goal, delta and the room are rl\'s', () => {
  const pairs = [[0, 1], [1, 2], [2, 3], [2, 4], [3, 4], [4, 5], [4, 6], [5, 6]];
  for (const [name, s] of BOTH) {
    assert.deepEqual(s.robot.ignore, pairs, name);
    assert.deepEqual(s.robot.exempt, [0], name);
    assert.equal(s.robot.metric, 'joint');
    assert.equal(s.resolution, deg(1), name);
    for (const q of [s.start, s.goal]) {
      assert.equal(q.length, 6);
      q.forEach((x, k) => assert.ok(x >= s.robot.joints[k].limits[0] && x <= s.robot.joints[k].limits[1], `${name}: joint ${k} at ${x}`));
    }
  }
  // rl's problem, without the viewer's own copy of the model and delta.
  const plan = planText.replace(/<viewer>[^]*<\/viewer>/, '');
  const block = (tag) => inner(new RegExp(`<${tag}>([^]*?)</${tag}>`).exec(plan)[1], 'q');
  assert.deepEqual(room.start, block('start').map(deg));
  assert.deepEqual(room.goal, block('goal').map(deg));
  assert.deepEqual(room.start.map((x) => Math.round(x * 180 / Math.PI)), [90, -180, 90, 0, 0, 0]);
  assert.deepEqual(inner(plan, 'delta'), [1]);
  assert.deepEqual(inner(plan, 'epsilon'), [1e-9]);
  assert.deepEqual(room.planner, { name: 'rrt-connect', seed: 1, connect: 'last-free', epsilon: 1e-9, time_limit: 1200 });
  assert.deepEqual(room.robot.tool, [0, 0, 0]);
  assert.equal(room.robot.links[6].boxes, undefined);
  // The room: each DEF'd Transform of boxes.wrl around a Box, translation as centre, size as size.
  const boxes = readFileSync(join(data, 'rlsg', 'boxes.wrl'), 'utf8');
  const want = [...boxes.matchAll(/DEF\s+(\w+)\s+Transform\s*\{\s*translation([^\n]+)[^]*?size([^\n]+)/g)]
    .map((m) => ({ name: m[1], box: { center: numbers(m[2]), size: numbers(m[3]) } }));
  assert.equal(want.length, 8);
  assert.deepEqual(room.obstacles3d, want);
});

test('the course\'s wall leaves the 16 cm window open, closes it all round, and the tool goes through it', () => {
  assert.deepEqual(wall.start, [0, 0, 90, 0, 0, 0].map(deg));
  assert.deepEqual(wall.goal, [-98, 7, 44, 0, 44, 0].map(deg));
  assert.deepEqual(wall.robot.tool, [0.26, 0, 0.26]);
  assert.deepEqual(wall.robot.links[6].boxes.map((b) => b.name), ['rod', 'bar']);
  assert.deepEqual(wall.planner, { name: 'rrt-connect', seed: 1, connect: 'last-free', epsilon: 1e-8, time_limit: 1200 });
  const boxes = wall.obstacles3d.map((o) => o.box);
  assert.equal(boxes.length, 4);
  const inside = (p, b) => p.every((v, c) => Math.abs(v - b.center[c]) <= b.size[c] / 2 + 1e-12);
  const blocked = (p) => boxes.some((b) => inside(p, b));
  // The window's open interior, through the wall's thickness (x from 0.81 to 0.89): no box meets it.
  for (const b of boxes) {
    const lo = b.center.map((v, c) => v - b.size[c] / 2);
    const hi = b.center.map((v, c) => v + b.size[c] / 2);
    const meets = lo[1] < 0.08 && hi[1] > -0.08 && lo[2] < 0.96 && hi[2] > 0.80 && lo[0] <= 0.85 && hi[0] >= 0.85;
    assert.ok(!meets, `a box reaches into the window: ${JSON.stringify(b)}`);
  }
  // Its rim, and the wall around it out to 2 cm, is closed at every x through the wall.
  for (const x of [0.81, 0.83, 0.85, 0.87, 0.89]) {
    for (let t = 0; t <= 1; t += 1 / 32) {
      const y = -0.1 + 0.2 * t;
      const z = 0.78 + 0.2 * t;
      for (const p of [[x, y, 0.80], [x, y, 0.96], [x, -0.08, z], [x, 0.08, z], [x, y, 0.78], [x, y, 0.98], [x, -0.1, z], [x, 0.1, z]]) {
        assert.ok(blocked(p), `the wall is open at ${p}`);
      }
    }
    assert.ok(!blocked([x, 0, 0.88]) && !blocked([x, 0.0799, 0.8001]) && !blocked([x, -0.0799, 0.9599]));
  }
  // At the goal the rod crosses the wall inside the window and the tool centre point is behind it.
  const fk = frames(wall.robot, wall.goal, basePose(wall.robot));
  const tcp = point(fk[6], wall.robot.tool);
  assert.ok(tcp[0] > 0.89, `the tool centre point at the goal is at ${tcp}`);
  const a = point(fk[6], [0, 0, 0]);
  const b = point(fk[6], [0, 0, 0.25]);
  const s = (0.85 - a[0]) / (b[0] - a[0]);
  assert.ok(s > 0 && s < 1, 'the rod does not cross the wall\'s plane at the goal');
  const hit = a.map((v, c) => v + s * (b[c] - v));
  assert.ok(Math.abs(hit[1]) < 0.08 && hit[2] > 0.80 && hit[2] < 0.96, `the rod crosses the wall at ${hit}, outside the window`);
});

test('the top view\'s bounds hold the arm in sampled configurations', () => {
  // A sample (a fixed LCG over the joint limits), not a proof: bounds only frame the drawings.
  for (const [name, s] of BOTH) {
    let seed = 12345;
    const rnd = () => (seed = (seed * 48271) % 2147483647) / 2147483647;
    const [x0, y0, x1, y1] = s.bounds;
    for (let it = 0; it < 500; it++) {
      const q = s.robot.joints.map((j) => j.limits[0] + rnd() * (j.limits[1] - j.limits[0]));
      const fk = frames(s.robot, q, basePose(s.robot));
      s.robot.links.forEach((link, k) => {
        const corners = (link.boxes || []).flatMap((b) => Array.from({ length: 8 },
          (_, i) => b.center.map((v, c) => v + ((i >> c) & 1 ? 0.5 : -0.5) * b.size[c])));
        for (const p of [...link.hull, ...corners]) {
          const [x, y] = point(fk[k], p);
          assert.ok(x >= x0 && x <= x1 && y >= y0 && y <= y1, `${name}: link${k} at ${x}, ${y} outside the bounds at ${q}`);
        }
      });
    }
  }
});

test('--check passes on the committed files and fails on a changed one', () => {
  const script = join(root, 'scripts', 'convert-rl.mjs');
  const ok = spawnSync(process.execPath, [script, '--check'], { encoding: 'utf8' });
  assert.equal(ok.status, 0, ok.stderr);
  const dir = mkdtempSync(join(tmpdir(), 'convert-rl-'));
  try {
    for (const f of ['puma-rbo-wall.json', 'puma-boxes.json']) copyFileSync(join(root, 'scenarios', f), join(dir, f));
    assert.equal(spawnSync(process.execPath, [script, '--check', '--out', dir]).status, 0);
    const file = join(dir, 'puma-boxes.json');
    writeFileSync(file, readFileSync(file, 'utf8').replace('"d": 0.4331', '"d": 0.4332'));
    const bad = spawnSync(process.execPath, [script, '--check', '--out', dir], { encoding: 'utf8' });
    assert.equal(bad.status, 1);
    assert.match(bad.stderr, /puma-boxes\.json is not what scripts\/convert-rl\.mjs writes/);
    assert.doesNotMatch(bad.stderr, /puma-rbo-wall/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a file the converter cannot read is an error naming the file, line and column', async () => {
  const { convert } = await import('../../scripts/convert-rl.mjs');
  const dir = mkdtempSync(join(tmpdir(), 'convert-rl-data-'));
  try {
    cpSync(data, dir, { recursive: true });
    const hull = join(dir, 'rlsg', 'unimation-puma560.convex', 'link3.wrl');
    const good = readFileSync(hull, 'utf8');
    const cases = [
      [hull, good.replace('point [ 0.042098999', 'point [ 0.042098999 oops'), /link3\.wrl:18:36: \{ after oops/],
      [hull, good.replace(/point \[[^\]]*\]/, 'point [ 0 0 0, 1 0 0, 0 1 0 ]'), /link3\.wrl:\d+:\d+: 3 points/],
      [hull, good.replace('DEF link3 Transform {', 'DEF link3 Transform {\n  rotation 0 0 0 1'), /link3\.wrl:4:11: a rotation about a zero axis/],
      [join(dir, 'rlkin', 'unimation-puma560.xml'), kinText.replace('<d>0.4331</d>', '<d>0.43.31</d>'), /unimation-puma560\.xml:\d+:\d+: <d> is not a number/],
      [join(dir, 'rlkin', 'unimation-puma560.xml'), kinText.replace('<max>100</max>', '<max>-100</max>'), /unimation-puma560\.xml:\d+:\d+: min -100 is not below max -100/],
      [join(dir, 'rlplan', 'unimation-puma560_boxes_rrtConCon.xml'), planText.replace('<q unit="deg">-180</q>', '<q unit="deg">-250</q>'),
        /start: joint 1 at -4\.36\d+ is outside its limits/],
    ];
    for (const [file, text, want] of cases) {
      const before = readFileSync(file, 'utf8');
      writeFileSync(file, text);
      assert.throws(() => convert(dir), want);
      writeFileSync(file, before);
    }
    assert.equal(convert(dir)['puma-boxes.json'], readFileSync(join(root, 'scenarios', 'puma-boxes.json'), 'utf8'));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

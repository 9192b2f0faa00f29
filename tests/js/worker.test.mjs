// The planning worker in headless chromium, without the page: a seeded run streams exactly the
// events pinned in tests/golden/runs.json (the same tree as natively and in Node) and returns the
// native CLI's path; cancel is read between batches and the worker stays usable (counted in
// batches, not timed: the times are printed).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { startBrowser } from './browser.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const cases = JSON.parse(readFileSync(join(root, 'tests/golden/cases.json'), 'utf8'));
const golden = JSON.parse(readFileSync(join(root, 'tests/golden/runs.json'), 'utf8'));

let env;
let page;
before(async () => {
  env = await startBrowser();
  page = await env.browser.newPage();
  page.on('pageerror', (e) => console.log(`[page error] ${e}`));
  await page.goto(`${env.base}run/events.js`); // any page of the origin will do
  // In the page: a driver that talks to one worker and collects its replies.
  await page.evaluate(() => {
    const w = new Worker('/worker/worker.js', { type: 'module' });
    const inbox = [];
    const waiters = [];
    w.onmessage = (e) => { inbox.push(e.data); waiters.splice(0).forEach((f) => f()); };
    window.driver = {
      send: (m) => w.postMessage(m),
      async next(type, timeout = 30000) {
        const t0 = performance.now();
        for (;;) {
          const i = inbox.findIndex((m) => m.type === type || m.type === 'crashed' || m.type === 'error');
          if (i >= 0) {
            const [m] = inbox.splice(i, 1);
            if (m.type !== type) throw new Error(`${m.type}: ${m.message}`);
            return m;
          }
          if (performance.now() - t0 > timeout) throw new Error(`no ${type} within ${timeout} ms`);
          await new Promise((r) => { waiters.push(r); setTimeout(r, 50); });
        }
      },
      drain() { inbox.length = 0; },
      count(type, status) { return inbox.filter((m) => m.type === type && (!status || m.status === status)).length; },
    };
  });
  await page.evaluate(async () => { window.ready = await window.driver.next('ready'); });
});

after(async () => { await env?.close(); });

test('a seeded run in the browser grows the same tree and path as natively', async () => {
  const cli = join(root, 'target/release/planarium');
  for (const [i, c] of cases.entries()) {
    const got = await page.evaluate(async (c) => {
      const d = window.driver;
      const text = JSON.stringify(window.ready.builtins.find((b) => b.id === c.scenario).scenario);
      d.send({ type: 'load', text });
      await d.next('loaded');
      d.send({ type: 'configure', planner: c.planner, params: c.params, seed: c.seed });
      await d.next('status');
      d.send({ type: 'run' });
      let h = 0xcbf29ce484222325n;
      for (;;) {
        const m = await d.next('events');
        for (const b of new Uint8Array(m.data.buffer)) h = ((h ^ BigInt(b)) * 0x100000001b3n) & 0xffffffffffffffffn;
        if (m.status !== 'running') break;
      }
      const r = await d.next('result');
      return { events: h.toString(16).padStart(16, '0'), result: r.result, frames: r.frames.length };
    }, c);
    assert.equal(got.events, golden[i].events, `case ${i}: ${c.scenario}/${c.planner} seed ${c.seed}`);
    const flags = Object.entries(c.params).flatMap(([k, v]) => [`--${k.replaceAll('_', '-')}`, String(v)]);
    const native = JSON.parse(execFileSync(cli, ['plan', c.scenario, '--planner', c.planner, '--seed', String(c.seed), '--json', ...flags], { encoding: 'utf8' }));
    assert.deepEqual(got.result.path, native.path);
    assert.deepEqual(got.result.smoothed, native.smoothed);
    assert.ok(got.frames > 0, 'animation frames were sent');
  }
});

test('cancel stops a long run at once, and the worker plans again afterwards', async () => {
  const out = await page.evaluate(async () => {
    const d = window.driver;
    d.drain();
    const text = JSON.stringify(window.ready.builtins.find((b) => b.id === 'narrow').scenario);
    d.send({ type: 'load', text });
    await d.next('loaded');
    // No goal bias, a tiny range: this would run to its 60 s limit.
    d.send({ type: 'configure', planner: 'rrt', params: { goal_bias: 0, range: 0.0004, time_limit: 60 }, seed: 1 });
    await d.next('status');
    d.send({ type: 'run' });
    await d.next('events');
    await new Promise((r) => setTimeout(r, 300));
    const t0 = performance.now();
    d.drain();
    d.send({ type: 'cancel', ack: 1 });
    await d.next('ack');
    const before = d.count('events', 'running'); // batches posted between the cancel's sending and its reading
    const r = await d.next('result');
    const cancelMs = performance.now() - t0;
    d.send({ type: 'configure', planner: 'rrt-connect', params: {}, seed: 7 });
    await d.next('status');
    d.send({ type: 'run' });
    const again = await d.next('result');
    return { status: r.result.status, cancelMs, before, planningMs: r.result.stats.time_ms, again: again.result.status };
  });
  console.log(`cancel answered after ${out.cancelMs.toFixed(1)} ms, ${out.before} batches after it was sent; the run planned ${out.planningMs} ms`);
  assert.equal(out.status, 'cancelled');
  // read between batches: at most the batch under way and one already queued came before it
  assert.ok(out.before <= 2, `${out.before} batches before the cancel was read`);
  assert.equal(out.again, 'solved');
});

/**
 * A unit map whose state checks near the bottom edge are slow even through the broad phase: n
 * discs centred at (1.5, 1.5) whose boxes all hold the free line from the start (0, 0.0005) to the
 * goal (1, 0.0005), so each state on it is tested against every disc (as tests/limits.rs).
 */
function cluttered(n) {
  const obstacles = [];
  for (let i = 0; i < n; i++) obstacles.push({ circle: [1.5, 1.5, 1.5 - 0.0004 * i / n] });
  return { bounds: [0, 0, 1, 1], obstacles, robot: { kind: 'point' }, start: [0, 0.0005], goal: [1, 0.0005], resolution: 1.5e-5 };
}

test('one iteration of seconds: the worker still reads its messages between batches, running or stepping', async () => {
  // One motion checked at 66,667 states, each against 20,000 discs. The core suspends a batch that
  // runs past twice its 12 ms and replays it in the next (src/journal.rs), so the worker reads
  // its messages between batches all along.
  const out = await page.evaluate(async (text) => {
    const d = window.driver;
    d.drain();
    d.send({ type: 'load', text });
    await d.next('loaded');
    d.send({ type: 'configure', planner: 'rrt', params: { goal_bias: 1, range: 2, time_limit: 60 }, seed: 1 });
    await d.next('status');
    const acks = [];
    const ack = async (msg) => {
      const n = acks.length + 1;
      const t0 = performance.now();
      d.send({ ...msg, ack: n });
      for (;;) {
        const m = await d.next('ack');
        if (m.ack === n) break;
      }
      acks.push(performance.now() - t0);
    };
    // Running: the gaps between batches, and how soon a message is read.
    d.send({ type: 'run' });
    let last = performance.now();
    const gaps = [];
    let iterations = 0;
    for (let i = 0; i < 20; i++) {
      const m = await d.next('events');
      const now = performance.now();
      gaps.push(now - last);
      last = now;
      iterations = m.stats.iterations;
      if (m.status !== 'running') break;
    }
    await ack({ type: 'pause' });
    // Stepping one iteration: it takes many batches, and messages are read between them.
    d.send({ type: 'step', iterations: 1 });
    await new Promise((r) => setTimeout(r, 100));
    for (let i = 0; i < 5; i++) await ack({ type: 'ping' });
    await new Promise((r) => setTimeout(r, 100));
    await ack({ type: 'ping' });
    d.send({ type: 'cancel' });
    const r = await d.next('result');
    return { gaps: gaps.slice(1), acks, iterations, batches: gaps.length, status: r.result.status, stepped: r.result.stats.iterations };
  }, JSON.stringify(cluttered(20000)));
  const gaps = [...out.gaps].sort((a, b) => a - b);
  console.log(`batches: median ${gaps[gaps.length >> 1].toFixed(1)} ms, longest ${gaps.at(-1).toFixed(1)} ms; messages read after ${out.acks.map((a) => a.toFixed(1)).join(', ')} ms`);
  // Counted, not timed: 20 batches came, the pause and the pings were answered, and the cancel
  // ended the run, all while its first iteration (seconds of work) was still under way.
  assert.equal(out.batches, 20, 'the worker posted batch after batch');
  assert.equal(out.iterations, 0, 'the one iteration is still under way (so batches were suspended)');
  assert.equal(out.acks.length, 7, 'every message was answered');
  assert.equal(out.status, 'cancelled');
  assert.equal(out.stepped, 0, 'the step\'s iteration had not ended when the messages were read');
});

test('a panic in the core is reported as crashed, not swallowed', async () => {
  const msg = await page.evaluate(async () => {
    const d = window.driver;
    d.drain();
    d.send({ type: 'debug-panic', message: 'boom from the test' });
    try { await d.next('never'); } catch (e) { return String(e.message); }
    return 'no report';
  });
  assert.match(msg, /^crashed: panicked at .*boom from the test/s);
});

test('ready carries the registry\'s capabilities and the robot kinds; loaded carries what the core decided for the scene', async () => {
  const got = await page.evaluate(async () => {
    // a worker of its own (an earlier test made the driver's crash on purpose)
    const w = new Worker('/worker/worker.js', { type: 'module' });
    const next = (type) => new Promise((resolve, reject) => {
      w.onmessage = (e) => { if (e.data.type === type) resolve(e.data); else if (e.data.type === 'invalid' || e.data.type === 'crashed') reject(new Error(JSON.stringify(e.data))); };
    });
    const ready = await next('ready');
    const out = {
      kinds: ready.robotKinds.map((k) => `${k.name}:${k.drawn}:${k.pose}`),
      queries: ready.planners.planners.filter((p) => p.caps.queries).map((p) => p.name),
    };
    for (const id of ['arm-2', 'arm-3', 'narrow', 'asv-3', 'hex-open']) {
      const text = JSON.stringify(ready.builtins.find((b) => b.id === id).scenario);
      const loaded = next('loaded');
      w.postMessage({ type: 'load', text });
      const m = await loaded;
      const c = m.caps;
      out[id] = { robot: c.robot.name, cspace: c.cspace, optimum: c.optimum, solution_file: c.solution_file, pose: c.pose, grid: !!m.cspace, sent: !!m.optimum };
    }
    w.terminate();
    return out;
  });
  assert.deepEqual(got.kinds, ['point:point:position', 'rigid:polygon:position-heading', 'arm:open-chain:joints', 'asv:closed-chain:none',
    'spatial-arm:spatial-arm:joints']);
  assert.deepEqual(got.queries, ['prm', 'prm-star', 'lazy-prm']);
  // the c-space grid and the optimum are sent exactly when the scene's capabilities say so
  const scene = (robot, cspace, optimum, solution, pose) => ({ robot, cspace, optimum, solution_file: solution, pose, grid: cspace, sent: optimum });
  for (const [id, want] of Object.entries({
    'arm-2': scene('arm', true, false, false, 'joints'),
    'arm-3': scene('arm', false, false, false, 'joints'),
    narrow: scene('point', false, true, false, 'position'),
    'asv-3': scene('asv', false, false, true, 'none'),
    'hex-open': scene('rigid', false, true, false, 'position-heading'),
  })) {
    assert.deepEqual(got[id], want, id);
  }
});

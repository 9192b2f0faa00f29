// The planning worker in headless chromium, without the page: a seeded run streams exactly the
// events pinned in tests/golden/runs.json (the same tree as natively and in Node) and returns the
// native CLI's path; cancel takes effect at once and the worker stays usable.
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
  await page.goto(`${env.base}events.js`); // any page of the origin will do
  // In the page: a driver that talks to one worker and collects its replies.
  await page.evaluate(() => {
    const w = new Worker('/worker.js', { type: 'module' });
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
    d.send({ type: 'cancel' });
    const r = await d.next('result');
    const cancelMs = performance.now() - t0;
    d.send({ type: 'configure', planner: 'rrt-connect', params: {}, seed: 7 });
    await d.next('status');
    d.send({ type: 'run' });
    const again = await d.next('result');
    return { status: r.result.status, cancelMs, planningMs: r.result.stats.time_ms, again: again.result.status };
  });
  assert.equal(out.status, 'cancelled');
  assert.ok(out.cancelMs < 250, `cancel took ${out.cancelMs} ms`);
  assert.ok(out.planningMs < 5000, 'the run did not go on in the background');
  assert.equal(out.again, 'solved');
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

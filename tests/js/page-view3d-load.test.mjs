// The 3-D view's frame time while orbiting with 100,000 tree edges drawn (headless chromium,
// WebGL2 through SwiftShader, a software renderer: a GPU is far faster). The edges are synthetic
// (window.planarium.view3d.loadEdges: straight edges round the tool); the test checks they are
// drawn (the trees' colours cover the view) and logs the requestAnimationFrame deltas while the
// camera turns: measured and reported (docs/performance.md), never asserted. Then the default
// puma-rbo-wall run in the page's worker and in a lone worker (nothing drawn) against
// `planarium plan puma-rbo-wall` (the same run: nodes and checks equal), the times logged.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { pageFixture, SHOTS, ROOT } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();

const quantiles = (times) => {
  const s = [...times].sort((a, b) => a - b);
  const q = (f) => s[Math.min(s.length - 1, Math.floor(f * s.length))];
  return `median ${q(0.5).toFixed(1)} ms, p95 ${q(0.95).toFixed(1)} ms, max ${s[s.length - 1].toFixed(1)} ms`;
};

test('100,000 tree edges in the 3-D view: drawn, and the frame time while orbiting logged', async () => {
  const page = fx.page;
  await fx.pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  const empty = await page.evaluate(() => window.planarium.view3d.orbitFrameTimes(40));
  console.log(`no tree, ${empty.length} frames: ${quantiles(empty)}`);
  for (const [edges, steps, frames] of [[100000, 2, 40], [100000, 6, 30]]) {
    // a fresh load: the trees empty
    await page.selectOption('#scenario', 'narrow');
    await fx.waitState('idle');
    await fx.pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
    await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
    const added = await page.evaluate(({ edges, steps }) => {
      const t0 = performance.now();
      const n = window.planarium.view3d.loadEdges(edges, steps);
      return [n, performance.now() - t0];
    }, { edges, steps });
    assert.equal(added[0], edges);
    await fx.nextFrames();
    const [t0, t1] = await page.evaluate((c) => window.planarium.view3d.countColours(c, 40), [PALETTE.tree0, PALETTE.tree1]);
    console.log(`tree pixels ${t0}/${t1}`);
    assert.ok(t0 > 50 && t1 > 50 && t0 + t1 > 5000, 'both trees are drawn (tree 1, drawn last, covers much of tree 0)');
    // what the GPU is sent while orbiting: the draw calls a frame (not one per edge) and no buffer upload
    await page.evaluate(() => {
      const P = WebGL2RenderingContext.prototype;
      const counts = { draws: 0, uploads: 0 };
      window.__glCounts = counts;
      for (const [name, key] of [['drawArrays', 'draws'], ['bufferData', 'uploads'], ['bufferSubData', 'uploads']]) {
        const f = P[name];
        P[name] = function (...a) { counts[key]++; return f.apply(this, a); };
      }
    });
    const times = await page.evaluate((n) => window.planarium.view3d.orbitFrameTimes(n), frames);
    // the frame just drawn, with the camera moving: the trees through a subset (draw3d/lod.js)
    const moving = await page.evaluate((c) => [window.planarium.view3d.treesThinned(), ...window.planarium.view3d.countColours(c, 40)], [PALETTE.tree0, PALETTE.tree1]);
    const gl = await page.evaluate(() => window.__glCounts);
    console.log(`while orbiting ${frames} frames: ${gl.draws} draw calls, ${gl.uploads} buffer uploads`);
    // each tree's subset is sent when built (one or two calls: filled, and allocated when it grew),
    // and built again only when the budget changes (four halvings from 16,000 to 1,000, then at most
    // a change every 30 frames): fewer uploads than frames, where every frame would be two or more
    assert.ok(gl.uploads < frames, `no buffer is uploaded every frame while the camera turns (${gl.uploads} in ${frames} frames)`);
    assert.ok(gl.draws <= frames * 60, 'a few dozen draw calls a frame, not one per edge');
    console.log(`${edges} edges of ${steps - 1} segment(s) (${edges * (steps - 1)} segments; added in ${added[1].toFixed(0)} ms), tree pixels ${t0}/${t1}, orbiting ${times.length} frames at 1280×800 (trees thinned): ${quantiles(times)}`);
    // once the camera rests the whole trees come back, at the same camera: more of their pixels
    await page.waitForFunction(() => !window.planarium.view3d.treesThinned(), null, { timeout: 20000 });
    await fx.nextFrames();
    const [r0, r1] = await page.evaluate((c) => window.planarium.view3d.countColours(c, 40), [PALETTE.tree0, PALETTE.tree1]);
    console.log(`tree pixels while moving ${moving[1]}/${moving[2]}, at rest ${r0}/${r1}`);
    assert.ok(moving[0], 'the trees were thinned while the camera moved');
    assert.ok(moving[1] + moving[2] > 100, `the thinned trees are still drawn (${moving[1] + moving[2]} pixels)`);
    assert.ok(r0 + r1 > (moving[1] + moving[2]) * 1.1, 'at rest the whole trees are drawn');
    const full = [];
    for (let i = 0; i < 3; i++) full.push(await page.evaluate(() => window.planarium.view3d.fullFrameMs()));
    console.log(`a whole frame at rest (the trees in full, waited for): ${quantiles(full)}`);
    await page.screenshot({ path: join(SHOTS, `view3d-edges-${steps - 1}.png`) });
  }
  assert.deepEqual(fx.errors, []);
});

/**
 * The same run in a worker of its own in the page, with nothing drawn: the scenario's own planner
 * block (RRT-Connect, last free configuration, seed 1) sent as the page sends it. Its stats, and
 * `wall_ms`: from the run asked for to its result read, what a person waits (the stats' `time_ms`
 * counts only the core's batches, not the worker's work between them).
 */
const loneRun = (page) => page.evaluate(() => new Promise((resolve, reject) => {
  const w = new Worker('worker/worker.js', { type: 'module' });
  let begin = 0;
  w.onmessage = (e) => {
    const m = e.data;
    if (m.type === 'ready') {
      const scenario = m.builtins.find((b) => b.id === 'puma-rbo-wall').scenario;
      const { name, seed, ...params } = scenario.planner;
      w.postMessage({ type: 'load', text: JSON.stringify(scenario) });
      w.postMessage({ type: 'configure', planner: name, params, seed });
    } else if (m.type === 'status' && m.status === 'idle' && !begin) {
      // loaded and configured, as when a person presses Run
      begin = performance.now();
      w.postMessage({ type: 'run' });
    } else if (m.type === 'result') {
      w.terminate();
      resolve({ ...m.result.stats, wall_ms: performance.now() - begin });
    } else if (m.type === 'crashed' || m.type === 'invalid' || m.type === 'error') {
      w.terminate();
      reject(new Error(`${m.type}: ${m.message ?? JSON.stringify(m.error)}`));
    }
  };
}));

test('the default puma-rbo-wall run in the page\'s worker against the native CLI: the same run, the times logged', async () => {
  const page = fx.page;
  await fx.pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
  await page.click('#speed-instant');
  const cli = join(ROOT, 'target/release/planarium');
  // The page's worker, a lone worker in the same page (nothing drawn) and native alternated, each
  // triple side by side in time, so a busy machine slows all alike; the medians of the ratios are
  // logged. The lone worker tells the wasm engine's share from the drawing's (where the browser
  // draws without a GPU, its rasteriser takes the processor the worker plans on).
  const rows = [];
  const same = (a, b, what) => assert.deepEqual([a.nodes, a.checks, a.free_checks, a.iterations], [b.nodes, b.checks, b.free_checks, b.iterations], what);
  for (let i = 0; i < (existsSync(cli) ? 3 : 1); i++) {
    await page.click('#run');
    if (i > 0) await page.waitForFunction(() => document.getElementById('status')?.textContent !== 'solved', null, { timeout: 20000 });
    await fx.waitStatus('solved', 300000);
    const stats = await page.evaluate(() => window.planarium.result().stats);
    const lone = await loneRun(page);
    same(lone, stats, 'the lone worker makes the page\'s run');
    if (!existsSync(cli)) { console.log(`worker: ${stats.time_ms.toFixed(1)} ms, lone ${lone.time_ms.toFixed(1)} ms (no native CLI built to compare)`); return; }
    const n = JSON.parse(execFileSync(cli, ['plan', 'puma-rbo-wall', '--json'], { encoding: 'utf8' })).stats;
    same(stats, n, 'the same run');
    rows.push([stats.time_ms / n.time_ms, lone.time_ms / n.time_ms, lone.wall_ms / n.time_ms]);
    console.log(`default puma-rbo-wall (seed 1): ${n.nodes} nodes, ${n.checks} checks; page's worker ${stats.time_ms.toFixed(1)} ms, lone worker ${lone.time_ms.toFixed(1)} ms (${lone.wall_ms.toFixed(1)} ms from run to result), native ${n.time_ms.toFixed(1)} ms`);
  }
  const median = (k) => rows.map((r) => r[k]).sort((a, b) => a - b)[Math.floor(rows.length / 2)].toFixed(2);
  console.log(`median of ${rows.length}: page's worker / native ${median(0)}×, lone worker / native ${median(1)}×, lone worker from run to result / native ${median(2)}×`);
});

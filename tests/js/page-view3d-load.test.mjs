// The 3-D view's frame time while orbiting with 100,000 tree edges drawn (headless chromium,
// WebGL2 through SwiftShader, a software renderer: a GPU is far faster). The edges are synthetic
// (window.planarium.view3d.loadEdges: straight edges round the tool); the test checks they are
// drawn (the trees' colours cover the view) and logs the requestAnimationFrame deltas while the
// camera turns: measured and reported (docs/performance.md), never asserted. Then the default
// puma-rbo-wall run in the page's worker against `planarium plan puma-rbo-wall` (the same run:
// nodes and checks equal), both times logged.
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

test('the default puma-rbo-wall run in the page\'s worker against the native CLI: the same run, the times logged', async () => {
  const page = fx.page;
  await fx.pickScenario('puma-rbo-wall', "Puma 560 through a window (report 001's course)");
  await page.click('#speed-instant');
  const cli = join(ROOT, 'target/release/planarium');
  // Worker and native alternated, each pair side by side in time, so a busy machine slows both
  // alike; the median of the pairs' ratios is logged.
  const pairs = [];
  for (let i = 0; i < (existsSync(cli) ? 3 : 1); i++) {
    await page.click('#run');
    if (i > 0) await page.waitForFunction(() => document.getElementById('status')?.textContent !== 'solved', null, { timeout: 20000 });
    await fx.waitStatus('solved', 300000);
    const stats = await page.evaluate(() => window.planarium.result().stats);
    if (!existsSync(cli)) { console.log(`worker: ${stats.time_ms.toFixed(1)} ms (no native CLI built to compare)`); return; }
    const n = JSON.parse(execFileSync(cli, ['plan', 'puma-rbo-wall', '--json'], { encoding: 'utf8' })).stats;
    assert.deepEqual([stats.nodes, stats.checks, stats.free_checks, stats.iterations], [n.nodes, n.checks, n.free_checks, n.iterations], 'the same run');
    pairs.push([stats.time_ms, n.time_ms]);
    console.log(`default puma-rbo-wall (seed 1): ${n.nodes} nodes, ${n.checks} checks; worker ${stats.time_ms.toFixed(1)} ms, native ${n.time_ms.toFixed(1)} ms: ${(stats.time_ms / n.time_ms).toFixed(2)}×`);
  }
  const ratios = pairs.map(([w, n]) => w / n).sort((a, b) => a - b);
  console.log(`worker / native, median of ${pairs.length} pairs: ${ratios[Math.floor(ratios.length / 2)].toFixed(2)}×`);
});

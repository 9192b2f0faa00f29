// The 3-D view of report 001's Puma 560 (headless chromium, WebGL2 through SwiftShader): it is
// loaded only for a scene the core gives a 3-D view (a 2-D scenario fetches nothing of
// www/draw3d/), it draws the arm at the start pose where the core's forward kinematics puts it
// (the tool centre point projected with the view's own camera lands on the arm's colour, and a
// point beside it does not), the trees grow in the top view's tree colours as the replay goes, and
// the solved path is drawn as the tool's curve. Screenshots at 1280×800 and 390×844 go to
// /tmp/view3d-*.png; the frame time while orbiting is logged, never asserted.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { puma, PUMA_NAME, shadeOf, pixelsNear as near3d } from './puma-view.mjs';
import { Scene } from '../../www/pkg/planarium.js';


const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitStatus, pickScenario } = fx;


async function openPuma() {
  await pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  assert.equal(await page.evaluate(() => window.planarium.view3d.error()), '');
}


test('puma-rbo-wall: the arm is drawn at the start pose where the core\'s kinematics puts it', async () => {
  await openPuma();
  const scene = new Scene(JSON.stringify(puma));
  const skeleton = scene.skeleton(new Float64Array(puma.start));
  scene.free();
  const points = [];
  for (let i = 0; i < skeleton.length; i += 3) points.push([...skeleton.slice(i, i + 3)]);
  const tcp = points[points.length - 1];
  // the tool centre point and the wrist (link 4's frame origin, inside its hull) are on the arm
  for (const [name, p] of [['tool centre point', tcp], ['wrist', points[4]]]) {
    const near = await near3d(page, p, 3);
    assert.ok(near, `${name} in front of the camera`);
    const hits = near.out.filter((px) => shadeOf(px, PALETTE.start)).length;
    console.log(`${name} ${p.map((v) => v.toFixed(3))} at css px ${near.at.map((v) => v.toFixed(1))}: ${hits} of ${near.out.length} pixels the start pose's colour`);
    assert.ok(hits >= 3, `${name}: the arm is drawn there`);
  }
  // and not where it is not: 40 cm above the tool (the view is framed on less than 2 m)
  const away = await near3d(page, [tcp[0], tcp[1], tcp[2] + 0.4], 3);
  assert.equal(away.out.filter((px) => shadeOf(px, PALETTE.start)).length, 0, 'nothing of the arm above the tool');
  await page.screenshot({ path: '/tmp/view3d-loaded-1280.png' });

  // Orbiting: a drag turns the camera (the matrix changes); then the frame time, logged.
  const before = await page.evaluate(() => window.planarium.view3d.viewProj());
  const box = await page.locator('#view3d').boundingBox();
  await fx.drag([box.x + box.width / 2, box.y + box.height / 2], [box.x + box.width / 2 + 120, box.y + box.height / 2 + 30]);
  const after = await page.evaluate(() => window.planarium.view3d.viewProj());
  assert.ok(before.some((v, i) => Math.abs(v - after[i]) > 1e-6), 'a drag turns the camera');
  const times = await page.evaluate(() => window.planarium.view3d.orbitFrameTimes(60));
  const sorted = [...times].sort((a, b) => a - b);
  const q = (f) => sorted[Math.min(sorted.length - 1, Math.floor(f * sorted.length))];
  console.log(`orbiting, ${times.length} frames at 1280×800: requestAnimationFrame delta median ${q(0.5).toFixed(1)} ms, p95 ${q(0.95).toFixed(1)} ms, max ${sorted[sorted.length - 1].toFixed(1)} ms`);
  await page.dblclick('#view3d');
  await page.screenshot({ path: '/tmp/view3d-orbited-1280.png' });
});

test('puma-rbo-wall: the trees grow in the 3-D view with the replay, and the path is drawn as the tool\'s curve', async () => {
  await openPuma();
  const count = () => page.evaluate(({ c }) => window.planarium.view3d.countColours(c, 8), { c: [PALETTE.tree0, PALETTE.tree1, PALETTE.smoothPath] });
  const [t0, t1] = await count();
  assert.equal(t0 + t1, 0, 'no tree before the run');
  await page.click('#speed-normal');
  await page.click('#run');
  const seen = [];
  for (let i = 0; i < 6; i++) {
    await page.waitForTimeout(1500);
    const [a, b] = await count();
    seen.push([a, b, await page.evaluate(() => window.planarium.nodeCount())]);
  }
  console.log(`tree pixels (tree 0, tree 1, nodes shown) as the replay goes: ${seen.map((s) => s.join('/')).join(', ')}`);
  assert.ok(seen[seen.length - 1][0] > seen[0][0] && seen[0][0] > 0, 'tree 0 grows');
  assert.ok(seen[seen.length - 1][1] > seen[0][1] && seen[0][1] > 0, 'tree 1 grows');
  await page.screenshot({ path: '/tmp/view3d-growing-1280.png' });
  await page.click('#speed-instant');
  await waitStatus('solved', 240000);
  await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
  await fx.nextFrames();
  await fx.nextFrames();
  const [, , path] = await count();
  console.log(`solved: ${path} pixels of the path's colour`);
  assert.ok(path > 50, 'the path is drawn as the tool\'s curve');
  await page.screenshot({ path: '/tmp/view3d-solved-1280.png' });
  await page.setViewportSize({ width: 390, height: 844 });
  await fx.nextFrames();
  await page.locator('#view3d').scrollIntoViewIfNeeded();
  await fx.nextFrames();
  await page.screenshot({ path: '/tmp/view3d-solved-390.png' });
});

test('a 2-D scenario loads nothing of www/draw3d/; the Puma loads it', async () => {
  const p = await fx.env.browser.newPage({ viewport: { width: 390, height: 844 } });
  const urls = [];
  p.on('request', (r) => urls.push(r.url()));
  await p.goto(fx.env.base);
  await p.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  await p.selectOption('#scenario', 'narrow');
  await p.waitForFunction(() => window.planarium?.state() === 'idle');
  await p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  assert.equal(await p.isHidden('#view3d'), true, 'no 3-D view for a 2-D scenario');
  assert.deepEqual(urls.filter((u) => u.includes('/draw3d/')), [], 'no draw3d module fetched');
  assert.ok(urls.some((u) => u.includes('/draw/view.js')), 'the requests were seen');
  await p.selectOption('#scenario', 'puma-rbo-wall');
  await p.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  assert.ok(urls.some((u) => u.endsWith('/draw3d/view3d.js')), 'the Puma loads the 3-D view');
  await p.locator('#view3d').scrollIntoViewIfNeeded();
  await p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  await p.screenshot({ path: '/tmp/view3d-loaded-390.png' });
  await p.close();
});

// A spatial arm on a phone (390×844) and without WebGL2: the first screen shows the scenario, the
// planner, Run and the arm in 3-D (the view from above a button away), the run bar's Step field
// is whole, one finger turns the camera and two pinch-zoom (real touch events through the
// DevTools protocol), and a browser without WebGL2 gets a plain note in the 3-D view's place while
// the view from above goes on working. At 1280×800 the 3-D view has the larger share of the stage.
// Screenshots go to target/phone3d-*.png. Pages keep their sections as a person finds them.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startBrowser, SHOTS } from './browser.mjs';

let env;
before(async () => { env = await startBrowser({ openSections: false }); });
after(async () => { await env?.close(); });

const nextFrames = (p) => p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

/** A new page on the Puma's scenario; page errors are collected in `errors`. */
async function pumaPage(options, init) {
  const context = await env.browser.newContext(options);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); errors.push(e); });
  if (init) await page.addInitScript(init);
  await page.goto(env.base);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  await page.selectOption('#scenario', 'puma-rbo-wall');
  await page.waitForFunction(() => window.planarium.state() === 'idle' && document.getElementById('scenario-name').textContent.startsWith('Puma'));
  return { page, context, errors };
}

const box = (page, sel) => page.locator(sel).boundingBox();

test('390×844: scenario, planner, Run and the arm in 3-D are in the first screen; the Step field is whole', async () => {
  const { page, context, errors } = await pumaPage({ viewport: { width: 390, height: 844 } });
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await nextFrames(page);
  const boxes = {};
  for (const id of ['scenario', 'planner', 'run', 'view3d', 'run-bar', 'step-size', 'step']) boxes[id] = await box(page, `#${id}`);
  console.log(`390×844 boxes (x, y, w, h): ${Object.entries(boxes).map(([k, b]) => `${k} ${b ? [b.x, b.y, b.width, b.height].map(Math.round).join(',') : 'none'}`).join('; ')}`);
  for (const id of ['scenario', 'planner', 'run', 'view3d', 'step-size']) {
    const b = boxes[id];
    assert.ok(b, `#${id} is shown`);
    assert.ok(b.y >= 0 && b.y + b.height <= 844, `#${id} is within the first screen's height`);
    assert.ok(b.x >= 0 && b.x + b.width <= 390, `#${id} is within the screen's width`);
  }
  assert.equal(await page.evaluate(() => window.scrollY), 0, 'nothing scrolled');
  const v = boxes.view3d;
  assert.ok(v.width >= 300 && v.height >= 180, 'the 3-D view is a real picture, not a strip');
  assert.ok(v.y + v.height <= boxes['run-bar'].y + 1, 'the run bar does not cover the 3-D view');
  // the Step field is whole inside the run bar (which scrolls sideways for the rest)
  const bar = boxes['run-bar'];
  const f = boxes['step-size'];
  assert.ok(f.x >= bar.x && f.x + f.width <= bar.x + bar.width - 2, 'the Step field ends inside the run bar');
  assert.equal(await page.$eval('#run-bar', (el) => el.scrollLeft), 0);
  // the arm is drawn: pixels of the start pose's colour in the 3-D view
  const start = await page.evaluate(() => window.planarium.view3d.countColours(['#e69f00'], 40));
  console.log(`390×844: ${start[0]} pixels near the start colour in the 3-D view`);
  await page.screenshot({ path: join(SHOTS, 'phone3d-390.png') });

  // the view from above is a button away, and back
  assert.equal(await page.isVisible('#canvas'), false, 'one view at a time on a phone');
  await page.click('#view-swap');
  await nextFrames(page);
  assert.equal(await page.isVisible('#canvas'), true, 'the view from above');
  assert.equal(await page.isVisible('#view3d'), false);
  const top = await box(page, '#canvas');
  assert.ok(top.y + top.height <= 844 && top.width >= 180, 'the view from above in the first screen');
  assert.equal(await page.textContent('#view-swap'), 'View in 3-D');
  await page.screenshot({ path: join(SHOTS, 'phone3d-390-above.png') });
  await page.click('#view-swap');
  await nextFrames(page);
  assert.equal(await page.isVisible('#view3d'), true, 'back to the 3-D view');
  // a 2-D scenario on the phone: no button, the top view alone as before
  await page.selectOption('#scenario', 'narrow');
  await page.waitForFunction(() => window.planarium.state() === 'idle' && !document.getElementById('scenario-name').textContent.startsWith('Puma'));
  await nextFrames(page);
  assert.equal(await page.isVisible('#view-swap'), false);
  assert.equal(await page.isVisible('#canvas'), true);
  assert.deepEqual(errors, []);
  await context.close();
});

test('390×844 touch: one finger turns the camera, two fingers pinch-zoom', async () => {
  const { page, context, errors } = await pumaPage({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await nextFrames(page);
  const b = await box(page, '#view3d');
  const [cx, cy] = [b.x + b.width / 2, b.y + b.height / 2];
  const cdp = await context.newCDPSession(page);
  const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
  const cam = () => page.evaluate(() => window.planarium.view3d.camera());
  const c0 = await cam();
  await touch('touchStart', [[cx, cy]]);
  for (let i = 1; i <= 6; i++) await touch('touchMove', [[cx + 12 * i, cy + 3 * i]]);
  await touch('touchEnd', []);
  const c1 = await cam();
  console.log(`one finger: azimuth ${c0.azimuth.toFixed(3)} → ${c1.azimuth.toFixed(3)}, elevation ${c0.elevation.toFixed(3)} → ${c1.elevation.toFixed(3)}`);
  assert.ok(Math.abs(c1.azimuth - c0.azimuth) > 0.2, 'a one-finger drag turns the camera');
  assert.ok(Math.abs(c1.distance - c0.distance) < 1e-9, 'and does not zoom');
  assert.equal(await page.evaluate(() => window.scrollY), 0, 'the page did not scroll under the finger');
  // two fingers moving apart: closer (the distance shrinks); the azimuth stays
  await touch('touchStart', [[cx - 20, cy], [cx + 20, cy]]);
  for (let i = 1; i <= 6; i++) await touch('touchMove', [[cx - 20 - 10 * i, cy], [cx + 20 + 10 * i, cy]]);
  await touch('touchEnd', []);
  const c2 = await cam();
  console.log(`pinch out: distance ${c1.distance.toFixed(3)} → ${c2.distance.toFixed(3)}`);
  assert.ok(c2.distance < c1.distance * 0.6, 'spreading two fingers zooms in');
  assert.ok(Math.abs(c2.azimuth - c1.azimuth) < 1e-9, 'a pinch does not turn');
  // and together again: farther
  await touch('touchStart', [[cx - 80, cy], [cx + 80, cy]]);
  for (let i = 1; i <= 6; i++) await touch('touchMove', [[cx - 80 + 10 * i, cy], [cx + 80 - 10 * i, cy]]);
  await touch('touchEnd', []);
  const c3 = await cam();
  assert.ok(c3.distance > c2.distance * 1.5, 'pinching in zooms out');
  // after the fingers are lifted one drag turns again, from where the finger is
  await touch('touchStart', [[cx, cy]]);
  await touch('touchMove', [[cx + 30, cy]]);
  await touch('touchEnd', []);
  const c4 = await cam();
  assert.ok(c4.azimuth !== c3.azimuth && Math.abs(c4.azimuth - c3.azimuth) < 0.6, 'a short drag turns a little');
  assert.deepEqual(errors, []);
  await context.close();
});

test('no WebGL2: a plain note stands in the 3-D view\'s place and the view from above works', async () => {
  const stub = () => {
    const get = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
      return kind === 'webgl2' ? null : get.call(this, kind, ...rest);
    };
  };
  for (const [w, h] of [[1280, 800], [390, 844]]) {
    const { page, context, errors } = await pumaPage({ viewport: { width: w, height: h } }, stub);
    await page.waitForSelector('.view3d-none', { state: 'visible', timeout: 20000 });
    assert.equal((await page.textContent('.view3d-none')).trim(), 'This browser has no WebGL2; the view from above still works.');
    assert.equal(await page.isVisible('#view3d'), false, 'no blank canvas');
    const note = await box(page, '.view3d-none');
    assert.ok(note.width >= 150 && note.height >= 150 && note.y + note.height <= h, `${w}: the note has the view's place in the first screen`);
    assert.deepEqual(errors, [], 'nothing breaks');
    if (w === 390) {
      await page.click('#view-swap');
      await nextFrames(page);
      assert.equal(await page.isVisible('.view3d-none'), false);
    }
    assert.equal(await page.isVisible('#canvas'), true, 'the view from above is there');
    // the top view draws the arm (the start's orange, www/draw/palette.js) and a run starts and can be cancelled
    const drawn = await page.evaluate(() => {
      const c = document.getElementById('canvas');
      const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - 0xe6) < 30 && Math.abs(px[i + 1] - 0x7e) < 30 && px[i + 2] < 50) n++; // the start's orange
      return n;
    });
    assert.ok(drawn > 20, 'the view from above draws the arm');
    await page.click('#run');
    await page.waitForFunction(() => window.planarium.state() !== 'idle');
    await page.click('#cancel');
    await page.waitForFunction(() => ['finished', 'cancelled', 'idle', 'paused'].includes(window.planarium.state()), null, { timeout: 20000 });
    await page.screenshot({ path: join(SHOTS, `phone3d-nowebgl2-${w}.png`) });
    assert.deepEqual(errors, []);
    await context.close();
  }
});

test('1280×800: the 3-D view has the larger share of the stage', async () => {
  const { page, context, errors } = await pumaPage({ viewport: { width: 1280, height: 800 } });
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await nextFrames(page);
  const [v, c] = [await box(page, '#view3d'), await box(page, '#canvas')];
  console.log(`1280×800: 3-D view ${Math.round(v.width)}×${Math.round(v.height)}, top view ${Math.round(c.width)}×${Math.round(c.height)}`);
  assert.ok(v.width * v.height > 2 * c.width * c.height, 'the 3-D view is the larger picture');
  assert.ok(v.height >= 320, 'and a tall one');
  assert.equal(await page.isVisible('#view-swap'), false, 'both views side by side, no button');
  await page.screenshot({ path: join(SHOTS, 'phone3d-1280.png') });
  assert.deepEqual(errors, []);
  await context.close();
});

// Zoom and pan on the plane (ui/plane-zoom.js, draw/view.js setViewport), clicked like a person:
// the wheel zooms about the pointer (the world point under it stays there), the layers are then
// redrawn at the new scale (thin lines, not a scaled picture), a middle-button drag pans, Fit gives
// back the fitted picture; and on a big tree, frames keep coming while the picture is panned and
// its layers are redrawn in steps. The frame times are printed (a benchmark reports them; with
// PLANARIUM_ZOOM_NODES=1000000 the same test grows the million nodes), never asserted. On a
// phone with touch, two fingers pinch about their midpoint and pan (real touch events through the
// DevTools protocol).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { canvasPixels, pageFixture, SHOTS, walledIn } from './browser.mjs';
import { STYLE } from '../../www/draw/palette.js';
import { EventKind } from '../../www/run/events.js';

const fx = await pageFixture();
const NODES = Number(process.env.PLANARIUM_ZOOM_NODES) || 60000;
const TREE = STYLE[EventKind.NODE_ADDED].colors[0];

/** The workspace canvas's pixels (RGBA, device px). */
const pixels = () => canvasPixels(fx.page);
const settled = () => fx.page.waitForFunction(() => window.planarium.viewport().settled, null, { timeout: 60000 });
const near = (px, hex, tol = 40) => [1, 3, 5].every((i, k) => Math.abs(px[k] - parseInt(hex.slice(i, i + 2), 16)) <= tol);
const count = (img, hex) => {
  let n = 0;
  for (let i = 0; i < img.data.length; i += 4) if (near(img.data.slice(i, i + 3), hex, 30)) n++;
  return n;
};
/** Pixels that differ by more than 60 in some channel. */
const differing = (a, b) => {
  let n = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if ([0, 1, 2].some((k) => Math.abs(a.data[i + k] - b.data[i + k]) > 60)) n++;
  }
  return n;
};

/** Record every animation frame's time and whether the plane's layers are settled (window.__frames). */
const recordFrames = () => fx.page.evaluate(() => {
  window.__frames = [];
  window.__stop = false;
  const tick = (t) => {
    window.__frames.push([t, window.planarium.viewport().settled]);
    if (!window.__stop) requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
});
const stopFrames = () => fx.page.evaluate(() => { window.__stop = true; return window.__frames; });
const gaps = (list) => list.slice(1).map(([t], i) => t - list[i][0]).sort((a, b) => a - b);
const stat = (g) => `median ${g[g.length >> 1].toFixed(1)} ms, 95th percentile ${g[Math.floor(g.length * 0.95)].toFixed(1)} ms`;

/** Open the walled-in goal with `nodes` for RRT's node limit and run it; the frames while it grew. */
async function openWalled(nodes) {
  const walled = walledIn({ max_nodes: nodes, time_limit: 600 });
  await fx.page.setInputFiles('#file', { name: 'walled.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(walled)) });
  await fx.page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Walled-in goal');
  await fx.waitState('idle');
  await fx.fastPlayback();
  await recordFrames();
  await fx.page.click('#run');
  await fx.waitState('finished', 1800000);
  await fx.nextFrames();
  return stopFrames();
}

test('the wheel zooms the plane about the pointer, its layers are redrawn thin at the new scale, a middle drag pans, Fit gives the picture back', async () => {
  const page = fx.page;
  await openWalled(3000);
  const before = await pixels();
  const trees = count(before, TREE);
  assert.ok(trees > 2000, `the tree is drawn (${trees} pixels)`);
  assert.equal(await page.isVisible('#plane-zoom'), false, 'no bar over the fitted map (it would cover a corner)');

  // the wheel over the start: a world point, where the tree is dense
  const at = await fx.toPage(0.1, 0.1);
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(...at);
  await page.mouse.wheel(0, -800); // exp(800 · 0.0015) = 3.3×
  await settled();
  const { zoom } = await page.evaluate(() => window.planarium.viewport());
  assert.ok(zoom > 3 && zoom < 3.5, `zoomed in 3.3× (${zoom})`);
  const [cx, cy] = await page.evaluate(() => window.planarium.toCanvas(0.1, 0.1));
  assert.ok(Math.abs(box.x + cx - at[0]) < 1 && Math.abs(box.y + cy - at[1]) < 1,
    `the point under the pointer stays there: (${box.x + cx}, ${box.y + cy}) against (${at[0]}, ${at[1]})`);
  assert.match(await page.textContent('#zoom-fit'), /^Fit \(3\.\d×\)$/);
  const zoomed = await pixels();
  await page.screenshot({ path: join(SHOTS, 'page-zoom.png') });
  // a picture scaled 3.3× would keep about as many tree pixels in view as the whole tree had (its
  // lines 3.3 times as thick over a tenth of the area); redrawn, the lines keep their width
  const inView = count(zoomed, TREE);
  assert.ok(inView > 200 && inView < 0.7 * trees, `redrawn at the new scale: ${inView} tree pixels in view, ${trees} fitted`);
  // the obstacle's wall is drawn where the transform puts it
  const [wx, wy] = await page.evaluate(() => window.planarium.toCanvas(0.81, 0.9));
  assert.ok(wx < 0 || wy < 0 || wx > box.width, 'the walled goal is out of view at this zoom');

  // a middle-button drag moves the picture with the pointer
  await page.mouse.move(at[0], at[1]);
  await page.mouse.down({ button: 'middle' });
  for (let i = 1; i <= 5; i++) await page.mouse.move(at[0] + 20 * i, at[1] + 10 * i);
  await page.mouse.up({ button: 'middle' });
  await settled();
  const [px, py] = await page.evaluate(() => window.planarium.toCanvas(0.1, 0.1));
  assert.ok(Math.abs(px - cx - 100) < 1.5 && Math.abs(py - cy - 50) < 1.5, `panned by (100, 50): (${px - cx}, ${py - cy})`);

  // the picture follows the start as drawn by the top layer and by the layers alike
  await page.click('#zoom-fit');
  await settled();
  assert.equal((await page.evaluate(() => window.planarium.viewport())).viewport, null);
  const after = await pixels();
  const changed = differing(before, after);
  assert.ok(changed < before.w * before.h * 0.002, `Fit draws the fitted picture again (${changed} pixels differ)`);
  assert.equal(await page.isVisible('#plane-zoom'), false);
});

test('a big tree: frames keep coming while it is panned and zoomed, and its layers are redrawn in steps', async () => {
  const page = fx.page;
  const growth = await openWalled(NODES);
  assert.equal(await page.evaluate(() => window.planarium.stats().nodes), NODES);
  const memory = await page.evaluate(() => ({ heap: /** @type {any} */ (performance).memory?.usedJSHeapSize ?? 0,
    stores: Object.values(window.planarium.memory()).reduce((a, b) => a + b, 0) }));
  console.log(`${NODES} nodes grown in ${((growth.at(-1)[0] - growth[0][0]) / 1000).toFixed(1)} s: ${growth.length} frames, `
    + `${stat(gaps(growth))}; the page's JS heap ${(memory.heap / 1e6).toFixed(0)} MB, its stores ${(memory.stores / 1e6).toFixed(0)} MB`);
  const fitted = count(await pixels(), TREE);
  const at = await fx.toPage(0.5, 0.5);
  await page.mouse.move(...at);
  await page.mouse.wheel(0, -600);
  await settled();
  // record frames: a pan of 30 moves, then the layers' redraw after it
  await recordFrames();
  await page.mouse.down({ button: 'middle' });
  for (let i = 1; i <= 30; i++) {
    await page.mouse.move(at[0] + 4 * i, at[1] + 2 * i);
    await fx.nextFrames();
  }
  await page.mouse.up({ button: 'middle' });
  const moved = await page.evaluate(() => window.__frames.length);
  await settled();
  await fx.nextFrames();
  const frames = await stopFrames();
  const pan = gaps(frames.slice(0, moved));
  const redraw = frames.slice(moved).filter(([, s]) => !s).length;
  console.log(`${NODES} nodes, zoom ${(await page.evaluate(() => window.planarium.viewport().zoom)).toFixed(2)}: `
    + `panning ${moved} frames, ${stat(pan)}; then the layers redrawn over ${redraw} frames, ${stat(gaps(frames.slice(moved - 1)))}`);
  await page.screenshot({ path: join(SHOTS, 'page-zoom-big.png') });
  assert.ok(moved >= 30, `a frame for every move at least (${moved})`);
  assert.ok(redraw >= 2, `the redraw is spread over frames (${redraw})`);
  const inView = count(await pixels(), TREE);
  // (a million nodes cover the plane whole, fitted or zoomed: the count says nothing there)
  if (NODES <= 100000) assert.ok(inView > 1000 && inView < fitted, `redrawn at the new scale: ${inView} tree pixels in view, ${fitted} fitted`);
});

test('the zoom bar: keys and buttons zoom about the centre and say the zoom; a new scenario is fitted', async () => {
  const page = fx.page;
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.keyboard.press('=');
  await page.click('#zoom-in');
  await settled();
  const { zoom, viewport } = await page.evaluate(() => window.planarium.viewport());
  assert.ok(Math.abs(zoom - 2.25) < 1e-9, `a key and a click, 1.5 × 1.5 (${zoom})`);
  const sc = await page.evaluate(() => window.planarium.scenario());
  const [x0, y0, x1, y1] = sc.bounds;
  assert.ok(Math.abs(viewport.cx - (x0 + x1) / 2) < 1e-9 && Math.abs(viewport.cy - (y0 + y1) / 2) < 1e-9, 'about the centre');
  assert.equal(await page.textContent('#zoom-fit'), 'Fit (2.3×)');
  await page.click('#zoom-out');
  await settled();
  assert.ok(Math.abs((await page.evaluate(() => window.planarium.viewport().zoom)) - 1.5) < 1e-9);
  // the keys, with the pointer over the map (the help lists them)
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.keyboard.press('=');
  assert.ok(Math.abs((await page.evaluate(() => window.planarium.viewport().zoom)) - 2.25) < 1e-9, '= zooms in');
  await page.keyboard.press('-');
  assert.ok(Math.abs((await page.evaluate(() => window.planarium.viewport().zoom)) - 1.5) < 1e-9, '- zooms out');
  await page.keyboard.press('0');
  assert.equal((await page.evaluate(() => window.planarium.viewport())).viewport, null, '0 fits');
  await page.keyboard.press('+');
  await settled();
  const other = await page.$$eval('#scenario option', (os) => os.map((o) => /** @type {HTMLOptionElement} */ (o).value));
  const name = await page.textContent('#scenario-name');
  const current = await page.$eval('#scenario', (el) => /** @type {HTMLSelectElement} */ (el).value);
  await page.selectOption('#scenario', other.find((v) => v && v !== current && !/puma/.test(v)));
  await page.waitForFunction((n) => document.getElementById('scenario-name').textContent !== n, name);
  await fx.waitState('idle');
  assert.equal((await page.evaluate(() => window.planarium.viewport())).viewport, null, 'another scenario opens fitted');
  assert.equal(await page.isVisible('#plane-zoom'), false);
  assert.deepEqual(fx.errors, []);
});

test('keyboard only: Tab reaches the map, which shows its focus, and + - 0 zoom it there', async () => {
  const page = fx.page;
  await page.mouse.move(1, 1); // the pointer away from the map: only the focus says where the keys go
  await page.focus('#scenario');
  await page.keyboard.press('Escape');
  await page.evaluate(() => /** @type {HTMLElement} */ (document.activeElement)?.blur());
  await page.keyboard.press('+');
  assert.equal((await page.evaluate(() => window.planarium.viewport())).viewport, null, 'nothing focused, the pointer away: + is not the map\'s');
  let reached = false;
  for (let i = 0; i < 80 && !reached; i++) {
    await page.keyboard.press('Tab');
    reached = await page.evaluate(() => document.activeElement?.id === 'canvas');
  }
  assert.ok(reached, 'Tab reaches the map');
  assert.notEqual(await page.evaluate(() => getComputedStyle(/** @type {Element} */ (document.activeElement)).outlineStyle), 'none', 'a focus ring on the map');
  await page.keyboard.press('+');
  assert.ok(Math.abs((await page.evaluate(() => window.planarium.viewport().zoom)) - 1.5) < 1e-9, '+ zooms in');
  assert.equal(await page.isVisible('#plane-zoom'), true, 'the bar shows once zoomed in');
  // shift + the arrows pan (the run does not step): right looks further right, up further up
  const progress = () => page.evaluate(() => [window.planarium.shownIterations(), window.planarium.nodeCount()]);
  const events = await progress();
  const at = (await page.evaluate(() => window.planarium.viewport())).viewport;
  await page.keyboard.press('Shift+ArrowRight');
  await page.keyboard.press('Shift+ArrowUp');
  const moved = (await page.evaluate(() => window.planarium.viewport())).viewport;
  assert.ok(moved.cx > at.cx + 1e-6 && moved.cy > at.cy + 1e-6, `shift + → and ↑ look right and up: (${at.cx}, ${at.cy}) → (${moved.cx}, ${moved.cy})`);
  await page.keyboard.press('Shift+ArrowLeft');
  await page.keyboard.press('Shift+ArrowDown');
  const back = (await page.evaluate(() => window.planarium.viewport())).viewport;
  assert.ok(Math.abs(back.cx - at.cx) < 1e-9 && Math.abs(back.cy - at.cy) < 1e-9, 'shift + ← and ↓ come back');
  assert.deepEqual(await progress(), events, 'shift + an arrow does not step the run');
  assert.equal(await page.evaluate(() => window.planarium.state()), 'idle', 'nor start it');
  await page.keyboard.press('-');
  assert.ok(Math.abs((await page.evaluate(() => window.planarium.viewport().zoom)) - 1) < 1e-9, '- zooms out');
  await page.keyboard.press('=');
  await page.keyboard.press('0');
  assert.equal((await page.evaluate(() => window.planarium.viewport())).viewport, null, '0 fits');
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'canvas', 'the focus stays on the map');
});

test('the zoom goes into the share link; the link reopens zoomed on the same point; a bad zoom is named', async () => {
  const page = fx.page;
  await fx.pickScenario('narrow', 'Narrow passage');
  await page.waitForTimeout(400);
  assert.doesNotMatch(await page.evaluate(() => location.hash), /zoom=/, 'fitted: no zoom in the link');
  const at = await fx.toPage(0.5, 0.5);
  await page.mouse.move(at[0] + 30, at[1] - 20);
  await page.mouse.wheel(0, -500);
  await settled();
  await page.waitForFunction(() => /[#&]zoom=/.test(location.hash), null, { timeout: 5000 });
  const { viewport } = await page.evaluate(() => window.planarium.viewport());
  const link = await page.evaluate(() => location.href);
  const before = await pixels();

  const other = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
  try {
    await other.goto(link);
    await other.waitForFunction(() => window.planarium?.state() === 'idle' && window.planarium.viewport().settled, null, { timeout: 30000 });
    const read = await other.evaluate(() => window.planarium.viewport().viewport);
    for (const k of ['zoom', 'cx', 'cy']) assert.ok(Math.abs(read[k] - viewport[k]) <= 1e-9 * Math.max(1, Math.abs(viewport[k])), `${k}: ${read[k]} against ${viewport[k]}`);
    const again = await canvasPixels(other);
    assert.equal(again.w, before.w);
    assert.ok(differing(before, again) < before.w * before.h * 0.002, 'the same picture');
    await other.goto(link.replace(/zoom=[^&]*/, 'zoom=300,0.5,0.5'));
    await other.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    assert.match(await other.textContent('#error-text'), /zoom=300,0\.5,0\.5: zoom must be from 1 to 256; the view from above shows the whole workspace\./);
    assert.equal(await other.evaluate(() => window.planarium.viewport().viewport), null);
  } finally {
    await other.close();
  }
});

test('the embed opens at a link\'s zoom; its wheel waits for the focus; its Fit shows the whole workspace', async () => {
  const p = await fx.env.browser.newPage({ viewport: { width: 600, height: 560 } });
  try {
    await p.goto(`${fx.env.base}embed.html#scenario=narrow&zoom=6,0.5,0.5&speed=100&autoplay`);
    const host = p.locator('planarium-playground');
    await p.waitForFunction(() => /** @type {any} */ (document.querySelector('planarium-playground'))?.state === 'finished', null, { timeout: 60000 });
    const zoom = () => p.evaluate(() => /** @type {any} */ (document.querySelector('planarium-playground')).zoom);
    assert.deepEqual(await zoom(), { zoom: 6, cx: 0.5, cy: 0.5 });
    await p.screenshot({ path: join(SHOTS, 'embed-zoom.png') });
    const box = await host.locator('canvas').first().boundingBox();
    await p.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await p.mouse.wheel(0, -400);
    await p.waitForTimeout(200);
    assert.equal((await zoom()).zoom, 6, 'without the focus the wheel is the page\'s');
    await host.locator('canvas').first().click();
    await p.mouse.wheel(0, -400);
    await p.waitForFunction(() => /** @type {any} */ (document.querySelector('planarium-playground')).zoom?.zoom > 6);
    await host.locator('[data-zoom="fit"]').click();
    assert.equal(await zoom(), null);
    assert.equal(await p.evaluate(() => /** @type {any} */ (document.querySelector('planarium-playground')).state), 'finished', 'a click on the bar runs nothing');
  } finally {
    await p.close();
  }
});

test('on a touch screen two fingers pinch the plane about their midpoint and pan it; the page itself neither scrolls nor zooms', async () => {
  const context = await fx.env.browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });
  const p = await context.newPage();
  const errors = [];
  p.on('pageerror', (e) => errors.push(String(e)));
  try {
    await p.goto(fx.env.base);
    await p.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    const canvas = p.locator('#canvas');
    await canvas.scrollIntoViewIfNeeded();
    const scrolled = await p.evaluate(() => window.scrollY);
    const cdp = await context.newCDPSession(p);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    // The world point (0.4, 0.6) under the fingers' midpoint, in page px.
    const at = async () => {
      const b = await canvas.boundingBox();
      const [x, y] = await p.evaluate(() => window.planarium.toCanvas(0.4, 0.6));
      return [b.x + x, b.y + y];
    };
    const [mx, my] = await at();
    // Two fingers 40 px apart spread to 160 px, symmetric about the point: 4× about it.
    await touch('touchStart', [[mx - 20, my], [mx + 20, my]]);
    for (let i = 1; i <= 6; i++) await touch('touchMove', [[mx - 20 - 10 * i, my], [mx + 20 + 10 * i, my]]);
    await touch('touchEnd', []);
    await p.waitForFunction(() => window.planarium.viewport().settled, null, { timeout: 30000 });
    const { zoom } = await p.evaluate(() => window.planarium.viewport());
    assert.ok(Math.abs(zoom - 4) < 0.05, `spreading two fingers from 40 to 160 px zooms 4× (${zoom})`);
    const [ax, ay] = await at();
    assert.ok(Math.abs(ax - mx) < 1.5 && Math.abs(ay - my) < 1.5, `the point between the fingers stays there: (${ax}, ${ay}) against (${mx}, ${my})`);
    // Both fingers moved by (30, 20): the picture follows them, at the same zoom.
    await touch('touchStart', [[mx - 40, my], [mx + 40, my]]);
    for (let i = 1; i <= 5; i++) await touch('touchMove', [[mx - 40 + 6 * i, my + 4 * i], [mx + 40 + 6 * i, my + 4 * i]]);
    await touch('touchEnd', []);
    await p.waitForFunction(() => window.planarium.viewport().settled, null, { timeout: 30000 });
    const [bx, by] = await at();
    assert.ok(Math.abs(bx - mx - 30) < 1.5 && Math.abs(by - my - 20) < 1.5, `panned by (30, 20): (${bx - mx}, ${by - my})`);
    assert.ok(Math.abs((await p.evaluate(() => window.planarium.viewport())).zoom - zoom) < 1e-9, 'a two-finger pan does not zoom');
    assert.match(await p.textContent('#zoom-fit'), /^Fit \(4\.0×\)$/);
    const page = await p.evaluate(() => ({ y: window.scrollY, scale: window.visualViewport?.scale ?? 1 }));
    assert.deepEqual(page, { y: scrolled, scale: 1 }, 'the gesture is the map\'s: the page did not scroll or zoom under it');
    await p.screenshot({ path: join(SHOTS, 'page-zoom-pinch-390.png') });
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

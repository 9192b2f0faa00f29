// Share links and embeds of a spatial arm's scenario (headless chromium): the 3-D view turned and
// zoomed with the mouse like a person goes into the link (`camera=tx,ty,tz,yaw,pitch,distance`); a
// fresh page opened on the link has the same camera (its numbers, as written, and the same pixels
// in the 3-D view before a run) and runs to the same path, number for number. A link with a camera
// out of bounds is reported and the view is framed on the problem. embed.html opened on the same
// hash shows the 3-D view beside the top view, with that camera, drawn (pixels other than the
// background), and runs to the same path. The ghost spacing typed into the 3-D path panel goes into
// the link (`ghosts=`): a fresh page on it, run, draws its path's ghosts at that spacing (the field
// says it, the same number of ghosts); a spacing out of bounds is reported and left at its default.
// <planarium-playground>'s camera attribute sets its 3-D view's camera: two values, two pictures;
// the same value again, the same picture. Screenshots: /tmp/share3d-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { readShare, writeShare } from '../../www/ui/links.js';
import { GHOSTS } from '../../www/ui/ghost-spacing.js';
import { roundCamera, readCamera, writeCamera } from '../../www/ui/camera-link.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const PUMA_NAME = "Puma 560 through a window (report 001's course)";

const camera = (p) => p.evaluate(() => window.planarium.view3d.camera());

/** A fresh page on `url`, errors failing the test; waited until its 3-D view is drawn. */
async function openPage(url) {
  const p = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
  p.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); fx.errors.push(e); });
  await p.goto(url);
  await p.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  await p.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  return p;
}

/** Pixels of the 3-D view (RGBA, 7 × 7 squares) at a grid of css points across it, after two frames. */
async function samples(p) {
  await p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return p.evaluate(() => {
    const c = document.getElementById('view3d');
    const out = [];
    for (let i = 1; i < 6; i++) {
      for (let j = 1; j < 6; j++) out.push(window.planarium.view3d.pixels((c.clientWidth * i) / 6, (c.clientHeight * j) / 6, 3));
    }
    return out;
  });
}

/** How many of the samples' pixels differ between `a` and `b` by more than `tol` in a channel. */
function differing(a, b, tol = 2) {
  let n = 0;
  a.forEach((s, k) => { for (let i = 0; i < s.length; i += 4) if ([0, 1, 2].some((c) => Math.abs(s[i + c] - b[k][i + c]) > tol)) n++; });
  return n;
}

async function runToEnd(p) {
  await p.click('#speed-instant');
  await p.click('#run');
  await p.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 240000 });
  return p.evaluate(() => window.planarium.result());
}

const close = (a, b) => Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(a));
function sameCamera(a, b, what) {
  a.target.forEach((v, i) => assert.ok(close(v, b.target[i]), `${what}: target ${a.target} vs ${b.target}`));
  for (const k of ['yaw', 'pitch', 'distance']) assert.ok(close(a[k], b[k]), `${what}: ${k} ${a[k]} vs ${b[k]}`);
}

test('puma-rbo-wall: the camera turned with the mouse goes into the link; the link reopens with the same camera, pixels and run; the embed shows it too', async () => {
  await fx.pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  const framed = await camera(page);
  assert.equal(framed.framed, true);
  await page.waitForTimeout(400); // the hash is written a moment after a change
  assert.doesNotMatch(await page.evaluate(() => window.planarium.shareLink()), /camera=|ghosts=/, 'a camera framed on the problem and the default ghost spacing are not written');

  // turn it with a drag and zoom with the wheel, like a person
  const box = await page.locator('#view3d').boundingBox();
  const [cx, cy] = [box.x + box.width / 2, box.y + box.height / 2];
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) await page.mouse.move(cx - 12 * i, cy + 5 * i);
  await page.mouse.up();
  await page.mouse.wheel(0, 120);
  const turned = await camera(page);
  assert.equal(turned.framed, false);
  assert.ok(Math.abs(turned.yaw - framed.yaw) > 0.3 && Math.abs(turned.pitch - framed.pitch) > 0.1 && turned.distance > framed.distance * 1.2,
    `the drag turned and the wheel zoomed it (${JSON.stringify(framed)} → ${JSON.stringify(turned)})`);
  await page.waitForFunction(() => /[#&]camera=/.test(location.hash), null, { timeout: 5000 });
  const link = await page.evaluate(() => window.planarium.shareLink());
  const read = await readShare(link.slice(link.indexOf('#')));
  assert.deepEqual(read.problems, []);
  sameCamera(read.view.camera, roundCamera(turned), 'the link carries the camera');
  const before = await samples(page);
  await page.screenshot({ path: '/tmp/share3d-before-1280.png' });

  // the same link in a fresh page: the same camera and pixels
  const again = await openPage(link);
  const reopened = await camera(again);
  assert.equal(reopened.framed, false);
  sameCamera(reopened, read.view.camera, 'the reopened page has the link\'s camera');
  const after = await samples(again);
  const bg = PALETTE.background;
  const nonBg = before.flatMap((s) => { const out = []; for (let i = 0; i < s.length; i += 4) out.push(s.slice(i, i + 3)); return out; })
    .filter(([r, g, b]) => [r, g, b].join() !== [1, 3, 5].map((i) => parseInt(bg.slice(i, i + 2), 16)).join()).length;
  const diff = differing(before, after);
  console.log(`reopened: ${diff} of ${before.length * 49} sampled pixels differ (${nonBg} sampled pixels are not the background)`);
  await again.screenshot({ path: '/tmp/share3d-reopened-1280.png' });
  assert.ok(nonBg >= 50, 'the samples see the scene, not only the background');
  assert.equal(diff, 0, 'the same picture');
  // a fresh page framed on the problem draws something else: the samples tell cameras apart
  const plain = await openPage(link.replace(/&camera=[^&]*/, ''));
  assert.equal((await camera(plain)).framed, true);
  assert.ok(differing(before, await samples(plain)) > 100, 'another camera gives other pixels');
  await plain.close();

  // the same run
  const ran = await runToEnd(page);
  const ranAgain = await runToEnd(again);
  assert.ok(ran.solved);
  assert.deepEqual(ranAgain.path, ran.path, 'the reopened link runs to the same path');
  sameCamera(await camera(again), read.view.camera, 'the run leaves the camera');
  await again.close();

  // the ghost spacing, typed into the path panel like a person, goes into the link
  await page.waitForFunction(() => window.planarium.view3d.path().path, null, { timeout: 20000 });
  await page.locator('#path3d-spacing').fill('0.5');
  await page.locator('#path3d-spacing').press('Tab'); // the field commits when left
  await page.waitForFunction(() => /[#&]ghosts=0\.5(&|$)/.test(location.hash), null, { timeout: 5000 });
  const shown = await page.evaluate(() => window.planarium.view3d.path());
  assert.equal(shown.spacing, 0.5);
  assert.ok(shown.ghosts > 0, `ghosts drawn on the path (${shown.ghosts})`);
  const ghostLink = await page.evaluate(() => window.planarium.shareLink());
  assert.equal((await readShare(ghostLink.slice(ghostLink.indexOf('#')))).view.ghosts, 0.5, 'the link carries the spacing');
  // a fresh page on it, run: the same spacing in the field and the same ghosts on the same path
  const ghostPage = await openPage(ghostLink);
  const ghostRun = await runToEnd(ghostPage);
  assert.deepEqual(ghostRun.path, ran.path);
  await ghostPage.waitForFunction(() => window.planarium.view3d.path().path, null, { timeout: 20000 });
  const reread = await ghostPage.evaluate(() => window.planarium.view3d.path());
  assert.equal(reread.spacing, 0.5, 'the reopened page has the link\'s ghost spacing');
  assert.equal(await ghostPage.locator('#path3d-spacing').inputValue(), '0.5', 'and its field says so');
  assert.equal(reread.ghosts, shown.ghosts, 'the same ghosts along the path');
  await ghostPage.close();
  // out of bounds or not a plain number: reported, and left at the default
  for (const [value, note] of [['0.01', /ghosts=0\.01: it must be 0 \(no ghosts\) or a number from 0\.05 to 10 \(rad\); left at 2\./]]) {
    const badGhosts = await openPage(ghostLink.replace(/ghosts=[^&]*/, `ghosts=${value}`));
    assert.match(await badGhosts.textContent('#error-text'), note);
    await runToEnd(badGhosts);
    await badGhosts.waitForFunction(() => window.planarium.view3d.path().path, null, { timeout: 20000 });
    assert.equal((await badGhosts.evaluate(() => window.planarium.view3d.path())).spacing, GHOSTS.initial, `ghosts=${value}: the default spacing`);
    await badGhosts.close();
  }

  // a camera out of bounds: reported, and the view framed on the problem
  const bad = await openPage(link.replace(/camera=[^&]*/, 'camera=0,0,0,0,2,1'));
  assert.equal((await camera(bad)).framed, true);
  assert.match(await bad.textContent('#error-text'), /camera=0,0,0,0,2,1: pitch must be from -1\.45 to 1\.55 radians; the view is framed on the problem\./);
  await bad.close();

  // the embed on the same hash: the 3-D view beside the top view, with the link's camera, drawn
  const embed = await fx.env.browser.newPage({ viewport: { width: 900, height: 500 } });
  embed.on('pageerror', (e) => { console.log(`[embed error] ${e.stack || e}`); fx.errors.push(e); });
  await embed.goto(`${fx.env.base}embed.html${link.slice(link.indexOf('#'))}&speed=100`); // every event at once
  await embed.waitForFunction(() => document.querySelector('planarium-playground')?.view3dState().ready, null, { timeout: 30000 });
  const state = await embed.evaluate(() => document.querySelector('planarium-playground').view3dState());
  sameCamera(state.camera, read.view.camera, 'the embed has the link\'s camera');
  await embed.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const drawn = await embed.evaluate((bgHex) => {
    const el = document.querySelector('planarium-playground');
    const c = el.shadowRoot.querySelector('canvas[part=view3d]');
    const top = el.shadowRoot.querySelector('canvas[part=canvas]');
    const gl = c.getContext('webgl2');
    const px = new Uint8Array(c.width * c.height * 4);
    gl.readPixels(0, 0, c.width, c.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const bg = [1, 3, 5].map((i) => parseInt(bgHex.slice(i, i + 2), 16));
    let n = 0;
    for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]) > 12) n++;
    const a = c.getBoundingClientRect(), b = top.getBoundingClientRect();
    return { n, total: px.length / 4, visible: !c.hidden && a.width > 100, beside: a.left >= b.right - 1 || a.top >= b.bottom - 1 };
  }, PALETTE.background);
  console.log(`embed 3-D view: ${drawn.n} of ${drawn.total} pixels are not the background`);
  await embed.screenshot({ path: '/tmp/share3d-embed-900.png' });
  assert.ok(drawn.visible && drawn.beside, 'the 3-D view is shown beside the top view');
  assert.ok(drawn.n > drawn.total * 0.05, 'the 3-D view is drawn');
  await embed.evaluate(() => document.querySelector('planarium-playground').run());
  await embed.waitForFunction(() => document.querySelector('planarium-playground').state === 'finished', null, { timeout: 240000 });
  const embedRun = await embed.evaluate(() => document.querySelector('planarium-playground').result());
  assert.deepEqual(embedRun.path, ran.path, 'the embed runs to the same path');
  await embed.close();
  assert.deepEqual(fx.errors, []);
});

test('the ghost spacing in a link: written only off its default, read back bounded', async () => {
  const registry = { planners: [] };
  const hash = (ghosts) => writeShare({ scenario: { id: 'puma-rbo-wall' }, view: { ghosts } }, registry);
  assert.equal(await hash(GHOSTS.initial), 'scenario=puma-rbo-wall', 'the default is not written');
  for (const v of [0, GHOSTS.min, 0.5, GHOSTS.max]) {
    const read = await readShare(await hash(v));
    assert.deepEqual(read.problems, []);
    assert.equal(read.view.ghosts, v, `ghosts=${v} read back`);
  }
  for (const bad of ['-1', '10.5', '0.04', 'NaN', 'Infinity', '1e1', '0x5', ' 1', '1'.repeat(40)]) {
    const read = await readShare(`scenario=puma-rbo-wall&ghosts=${encodeURIComponent(bad)}`);
    assert.equal(read.view.ghosts, undefined, `ghosts=${bad} refused`);
    assert.equal(read.problems.length, 1);
    assert.match(read.problems[0], /^ghosts=.*: it must be 0 \(no ghosts\) or a number from 0\.05 to 10 \(rad\); left at 2\.$/);
  }
});

/**
 * A fresh page holding one <planarium-playground> on puma-rbo-wall with these attributes (`camera`
 * among them, or not); waited until its 3-D view is drawn. Returns {page, state, px}: the element's
 * view3dState() and its 3-D view's pixels (RGB, every third pixel of every third row).
 */
async function elementOn(attrs) {
  const p = await fx.env.browser.newPage({ viewport: { width: 900, height: 500 } });
  p.on('pageerror', (e) => { console.log(`[element error] ${e.stack || e}`); fx.errors.push(e); });
  await p.goto(`${fx.env.base}embed.html`);
  await p.evaluate((attrs) => {
    const el = document.createElement('planarium-playground');
    for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
    document.body.replaceChildren(el);
  }, { scenario: 'puma-rbo-wall', ...attrs });
  await p.waitForFunction(() => document.querySelector('planarium-playground')?.view3dState().ready, null, { timeout: 30000 });
  await p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const got = await p.evaluate(() => {
    const el = document.querySelector('planarium-playground');
    const c = el.shadowRoot.querySelector('canvas[part=view3d]');
    const gl = c.getContext('webgl2');
    const all = new Uint8Array(c.width * c.height * 4);
    gl.readPixels(0, 0, c.width, c.height, gl.RGBA, gl.UNSIGNED_BYTE, all);
    const px = [];
    for (let y = 0; y < c.height; y += 3) for (let x = 0; x < c.width; x += 3) { const i = (y * c.width + x) * 4; px.push(all[i], all[i + 1], all[i + 2]); }
    return { state: el.view3dState(), px, size: [c.width, c.height] };
  });
  return { page: p, ...got };
}

/** How many pixels of two samples differ by more than `tol` in a channel. */
function pixelsDiffering(a, b, tol = 3) {
  assert.equal(a.length, b.length, 'samples of the same size');
  let n = 0;
  for (let i = 0; i < a.length; i += 3) if ([0, 1, 2].some((c) => Math.abs(a[i + c] - b[i + c]) > tol)) n++;
  return n;
}

test('<planarium-playground camera="…"> sets the 3-D view\'s camera: two cameras, two pictures; the same camera again, the same picture', async () => {
  // cameras either side of the one the element frames the problem with, so that both see the arm
  const framed = await elementOn({});
  assert.ok(framed.state.camera, 'the element has a 3-D camera');
  await framed.page.close();
  const f = framed.state.camera;
  const a = writeCamera({ ...f, yaw: f.yaw + 0.7, pitch: Math.min(1.2, f.pitch + 0.3) });
  const b = writeCamera({ ...f, yaw: f.yaw - 0.9, distance: f.distance * 1.4 });
  const shots = [];
  for (const camera of [a, b, a]) {
    const e = await elementOn({ camera });
    sameCamera(e.state.camera, readCamera(camera).camera, `camera="${camera}": the element's camera`);
    await e.page.screenshot({ path: `/tmp/share3d-element-${shots.length}-900.png` });
    await e.page.close();
    shots.push(e);
  }
  const total = shots[0].px.length / 3;
  const bg = [1, 3, 5].map((i) => parseInt(PALETTE.background.slice(i, i + 2), 16));
  let scene = 0;
  for (let i = 0; i < shots[0].px.length; i += 3) if ([0, 1, 2].some((c) => Math.abs(shots[0].px[i + c] - bg[c]) > 12)) scene++;
  const differ = pixelsDiffering(shots[0].px, shots[1].px);
  const same = pixelsDiffering(shots[0].px, shots[2].px);
  console.log(`element cameras: ${scene} of ${total} sampled pixels show the scene; a vs b: ${differ} differ; a vs a again: ${same} differ`);
  assert.ok(scene > total * 0.05, 'the 3-D view is drawn');
  assert.ok(differ > total * 0.02, 'another camera attribute: another picture');
  assert.ok(same <= total * 0.001, 'the same camera attribute: the same picture');
  assert.deepEqual(fx.errors, []);
});

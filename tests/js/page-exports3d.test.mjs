// The PNG and WebM exports of a spatial arm's scene (headless chromium, the export buttons clicked):
// the picture is the top view at the width asked and, on its right at the same height, the 3-D view
// rendered at export time. The PNG is decoded by the browser: the left part is the top view (as a
// 2-D scene's PNG), the right part has the 3-D view's pixels (other than the background: the arm,
// the wall, the floor grid), and it is the page's own 3-D view, the same camera (its picture,
// scaled to the same size, differs little from the export's). The WebM is as wide as the two and
// a frame, decoded by a <video>, has the 3-D view's pixels on its right. Files in /tmp/exports3d-*.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { pageFixture } from './browser.mjs';
import { webmInfo } from '../../www/ui/webm.js';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const PUMA_NAME = "Puma 560 through a window (report 001's course)";

async function download(click) {
  const [d] = await Promise.all([page.waitForEvent('download'), click()]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}

/**
 * Decode an image or a video's middle frame (base64 bytes, `type`) in the page and measure the
 * region right of x = `from` (image px): {width, height, nonBg (share of pixels not the page's
 * background), diff (mean absolute difference per channel from the page's 3-D view scaled to the
 * region, or null)}.
 */
function measure(b64, type, from, bg, compare) {
  return page.evaluate(async ({ b64, type, from, bg, compare }) => {
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const blob = new Blob([bytes], { type });
    let src;
    if (type === 'image/png') src = await createImageBitmap(blob);
    else {
      const v = document.createElement('video');
      v.muted = true;
      v.src = URL.createObjectURL(blob);
      await new Promise((resolve, reject) => { v.onloadeddata = resolve; v.onerror = () => reject(new Error('the video does not load')); });
      v.currentTime = Math.min(0.5, v.duration / 2);
      await new Promise((resolve) => { v.onseeked = resolve; });
      src = v;
    }
    const w = src.width || src.videoWidth, h = src.height || src.videoHeight;
    const c = document.createElement('canvas');
    c.width = w; c.height = h;
    const ctx = c.getContext('2d');
    ctx.drawImage(src, 0, 0);
    const rw = w - from;
    const px = ctx.getImageData(from, 0, rw, h).data;
    const B = [1, 3, 5].map((i) => parseInt(bg.slice(i, i + 2), 16));
    let n = 0;
    for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - B[0]) + Math.abs(px[i + 1] - B[1]) + Math.abs(px[i + 2] - B[2]) > 12) n++;
    let diff = null;
    if (compare) { // the page's 3-D view as it is now, scaled into the region
      const v3 = document.getElementById('view3d');
      const d = document.createElement('canvas');
      d.width = rw; d.height = h;
      const dctx = d.getContext('2d');
      dctx.drawImage(v3, 0, 0, rw, h);
      const q = dctx.getImageData(0, 0, rw, h).data;
      let sum = 0;
      for (let i = 0; i < px.length; i += 4) sum += Math.abs(px[i] - q[i]) + Math.abs(px[i + 1] - q[i + 1]) + Math.abs(px[i + 2] - q[i + 2]);
      diff = sum / (3 * rw * h);
    }
    return { width: w, height: h, nonBg: n / (rw * h), diff };
  }, { b64, type, from, bg, compare });
}

test('puma-rbo-wall: PNG and WebM hold the 3-D view beside the top view, rendered at export time', async () => {
  await fx.pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  assert.equal(await page.isVisible('#export-3d-note'), true, 'the export box says the 3-D view is in the PNG and WebM');
  const [x0, y0, x1, y1] = (await page.evaluate(() => window.planarium.scenario())).bounds;
  const aspect = await page.$eval('#view3d', (c) => c.width / c.height);

  await page.fill('#png-width', '800');
  const png = await download(() => page.click('#export-png'));
  writeFileSync('/tmp/exports3d-puma.png', png.bytes);
  assert.equal(png.bytes.subarray(1, 4).toString(), 'PNG');
  const height = Math.round((800 * (y1 - y0)) / (x1 - x0));
  const gap = Math.round(height * 0.01);
  const side = Math.round(height * aspect);
  const width = png.bytes.readUInt32BE(16);
  assert.equal(png.bytes.readUInt32BE(20), height, 'as high as the top view at 800 px wide');
  assert.equal(width, 800 + gap + side, 'the top view, a gap, and the 3-D view at its aspect');
  assert.match(await page.textContent('#export-status'), /PNG, 800 px wide, the 3-D view beside the top view/);
  const right = await measure(png.bytes.toString('base64'), 'image/png', 800 + gap, PALETTE.background, true);
  const left = await measure(png.bytes.toString('base64'), 'image/png', 0, PALETTE.background, false);
  console.log(`PNG ${right.width} × ${right.height}: the 3-D part has ${(right.nonBg * 100).toFixed(1)}% non-background pixels, `
    + `mean difference ${right.diff.toFixed(2)} from the page's 3-D view scaled`);
  assert.ok(right.nonBg > 0.05, 'the 3-D view is drawn in the PNG');
  assert.ok(right.diff < 12, 'it is the page\'s 3-D view, from the same camera');
  assert.ok(left.nonBg > right.nonBg, 'the top view is on the left');
  // the page's 3-D view is back at its own size
  assert.ok(Math.abs(await page.$eval('#view3d', (c) => c.width / c.height) - aspect) < 1e-9);

  // WebM: as wide as the two pictures (even), the 3-D view on the right of a frame
  await page.fill('#video-width', '640');
  await page.click('#record');
  await page.waitForFunction(() => /^Recording \d+ × \d+/.test(document.getElementById('export-status').textContent));
  await page.waitForTimeout(1200); // a clip of about a second (no assertion rests on how long)
  const webm = await download(() => page.click('#record'));
  writeFileSync('/tmp/exports3d-puma.webm', webm.bytes);
  const info = webmInfo(webm.bytes);
  const vh = Math.round((640 * (y1 - y0)) / (x1 - x0)) & ~1;
  console.log(`WebM ${info.width} × ${info.height}, ${info.duration} ms`);
  assert.equal(info.height, vh);
  assert.ok(Math.abs(info.width - (640 + Math.round(vh * 0.01) + Math.round(vh * aspect))) <= 2, `the video is as wide as the two (${info.width})`);
  const frame = await measure(webm.bytes.toString('base64'), 'video/webm', 640 + Math.round(vh * 0.01), PALETTE.background, false);
  console.log(`WebM frame: the 3-D part has ${(frame.nonBg * 100).toFixed(1)}% non-background pixels`);
  assert.ok(frame.nonBg > 0.05, 'the 3-D view is in the video');
  assert.deepEqual(fx.errors, []);
});

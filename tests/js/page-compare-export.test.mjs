// The compare page's animations and pacing in headless chromium: the GIF and WebM of both lanes
// (clicked like a person, the download caught and decoded: two lanes wide, more than one frame,
// the trees grow; a WebM with its EBML header, size and duration), the Slow / Normal / Fast /
// Instant presets (both lanes' replays paced by them), and each lane's Optimum row on a point
// robot's scenario (the same optimum, each lane's own percentage).
// Files: target/page-compare-export.gif, target/page-compare-export.webm.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { readFileSync, writeFileSync } from 'node:fs';
import { pageFixture, SHOTS as shots } from './browser.mjs';
import { decodeGif } from './gif-decode.mjs';
import { webmInfo } from '../../www/ui/webm.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState } = fx;

async function openCompare(hash = '') {
  await page.goto('about:blank');
  await page.goto(`${fx.env.base}compare.html${hash}`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle' && window.planarium.scenario(), null, { timeout: 30000 });
}

async function download(click) {
  const [d] = await Promise.all([page.waitForEvent('download', { timeout: 120000 }), click()]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}

/** Both lanes run to the end at once (the Instant preset). */
async function runBoth() {
  await page.click('#speed-instant');
  await page.click('#run');
  await waitState('finished', 120000);
  await fx.nextFrames();
}

const HASH = '#scenario=open-field&a=rrt-star&b=rrt-connect&seed=1';
const LANE = 320; // compare-anim.js LANE_WIDTH.gif
const PAD = 12;   // compare-export.js: around and between the lanes

test('compare: a GIF of both lanes as a time-lapse: two lanes wide, many frames, the trees grow', async () => {
  await openCompare(HASH);
  await runBoth();
  await page.selectOption('#export-lapse', '5');
  const gif = await download(() => page.click('#export-lanes-gif'));
  assert.equal(gif.name, 'planarium-compare.gif');
  writeFileSync(join(shots, 'page-compare-export.gif'), gif.bytes);
  const g = decodeGif(gif.bytes);
  assert.equal(g.version, 'GIF89a');
  assert.equal(g.width, PAD + LANE + PAD + LANE + PAD, `two lanes wide: ${g.width}`);
  assert.ok(g.height > LANE, `a lane's picture, its title and numbers: ${g.height} px high`);
  assert.equal(g.frames.length, 50, 'the whole runs in 5 s at 10 frames a second');
  // full frames: the first and the last differ in each lane's picture (the trees grew, the paths came)
  const first = g.frames[0].indices, last = g.frames[g.frames.length - 1].indices;
  for (const f of [g.frames[0], g.frames[g.frames.length - 1]]) assert.deepEqual([f.width, f.height], [g.width, g.height]);
  const changed = (x0, x1) => {
    let n = 0;
    for (let y = 0; y < g.height; y++) for (let x = x0; x < x1; x++) if (first[y * g.width + x] !== last[y * g.width + x]) n++;
    return n;
  };
  const a = changed(PAD, PAD + LANE), b = changed(2 * PAD + LANE, 2 * PAD + 2 * LANE);
  console.log(`GIF ${g.width}×${g.height}, ${g.frames.length} frames; pixels changed first → last: A ${a}, B ${b}`);
  assert.ok(a > 500, `lane A grew: ${a} pixels changed`);
  assert.ok(b > 500, `lane B grew: ${b} pixels changed`);
  assert.match(await page.textContent('#export-status'), /Saved planarium-compare\.gif, 676 × \d+, 50 frames at 10 fps, both whole runs in 5 s/);
});

test('compare: a GIF of both lanes in real time follows both runs as the page plays them', async () => {
  await openCompare('#scenario=open-field&a=rrt-star&b=rrt&seed=1');
  await page.click('#speed-normal'); // both runs in about 15 s: the GIF's 4 s see both trees grow
  await page.click('#run');
  assert.equal(await page.$eval('#export-lapse', (s) => s.value), '0', 'real time by default');
  const gif = await download(() => page.click('#export-lanes-gif'));
  const g = decodeGif(gif.bytes);
  assert.equal(g.width, PAD + LANE + PAD + LANE + PAD, `two lanes wide: ${g.width}`);
  assert.equal(g.frames.length, 40, 'real time: 4 s at 10 frames a second');
  const first = g.frames[0].indices, last = g.frames[g.frames.length - 1].indices;
  // each lane's picture (under its 30 px title; the open field is square), not its numbers
  const changed = (x0) => {
    let n = 0;
    for (let y = PAD + 30; y < PAD + 30 + LANE; y++) for (let x = x0; x < x0 + LANE; x++) if (first[y * g.width + x] !== last[y * g.width + x]) n++;
    return n;
  };
  const [a, b] = [changed(PAD), changed(2 * PAD + LANE)];
  assert.ok(a > 100 && b > 100, `both lanes moved while the GIF was taken: A ${a}, B ${b} pixels changed`);
  assert.match(await page.textContent('#export-status'), /Saved planarium-compare\.gif, 676 × \d+, 40 frames at 10 fps, \d+ kB/);
});

test('compare: a WebM of both lanes as a time-lapse saves by itself, two lanes wide, with a duration', async () => {
  await openCompare(HASH);
  await runBoth();
  await page.selectOption('#export-lapse', '5');
  const webm = await download(() => page.click('#export-lanes-webm')); // saves itself a second after the 5 s
  assert.equal(webm.name, 'planarium-compare.webm');
  writeFileSync(join(shots, 'page-compare-export.webm'), webm.bytes);
  assert.deepEqual([...webm.bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'EBML magic');
  const info = webmInfo(webm.bytes);
  const lane = 640; // compare-anim.js LANE_WIDTH.webm
  // the lanes' pads and text scale with the lane's pixels per css px of the page's canvas
  const css = await page.$eval('#a-canvas', (c) => c.getBoundingClientRect().width);
  const pad = Math.round(PAD * Math.max(1, lane / css));
  const wide = (pad + lane + pad + lane + pad) & ~1;
  assert.ok(Math.abs(info.width - wide) <= 2, `two lanes wide: ${info.width}, ${wide} expected (a lane ${css} css px on the page)`);
  assert.ok(info.height > lane, `${info.height} px high`);
  assert.equal(info.segmentKnown, true, 'the Segment has a known size');
  assert.ok(info.cues.length >= 1, 'cues');
  assert.ok(info.lastBlock > 0, 'more than one frame');
  assert.ok(info.duration > info.lastBlock && info.duration < info.lastBlock + 500, `duration ${info.duration} ms, last frame at ${info.lastBlock} ms`);
  assert.match(await page.textContent('#export-status'), /Saved planarium-compare\.webm, \d+ × \d+/);
});

test('compare: Slow, Normal, Fast and Instant pace both lanes', async () => {
  await openCompare(HASH);
  const paced = async (id, seconds) => {
    if (!(await page.$eval('#reset', (b) => b.disabled))) await page.click('#reset');
    await page.click(`#${id}`);
    assert.equal(await page.$eval(`#${id}`, (b) => b.getAttribute('aria-checked')), 'true', `${id} is marked`);
    const others = await page.$$eval('.speeds [role="radio"]', (bs) => bs.filter((b) => b.getAttribute('aria-checked') === 'true').map((b) => b.id));
    assert.deepEqual(others, [id], 'one preset marked');
    assert.equal(await page.evaluate(() => window.planarium.duration()), seconds);
    await page.click('#run');
    // each lane's pace, as its frames used it
    await page.waitForFunction(() => ['a', 'b'].every((k) => window.planarium.pace(k).frames > 3) || window.planarium.state() === 'finished', null, { timeout: 60000 });
    const pace = await page.evaluate(() => ['a', 'b'].map((k) => window.planarium.pace(k)));
    if (!(await page.$eval('#pause', (b) => b.disabled))) await page.click('#pause');
    return pace;
  };
  const slow = await paced('speed-slow', 40);
  assert.deepEqual(slow.map((p) => p.duration), [40, 40], 'both lanes replay their runs in 40 s');
  assert.match(await page.textContent('#speed-out'), /whole run in 40 s/);
  const fast = await paced('speed-fast', 5);
  assert.deepEqual(fast.map((p) => p.duration), [5, 5], 'both lanes in 5 s');
  const normal = await paced('speed-normal', 15);
  assert.deepEqual(normal.map((p) => p.duration), [15, 15]);
  await page.click('#reset');
  await page.click('#speed-instant');
  assert.equal(await page.evaluate(() => window.planarium.duration()), 0, 'Instant: every event at once');
  await page.click('#run');
  await waitState('finished', 120000);
  assert.equal(await page.textContent('#speed-out'), 'all at once');
  // the slider moved by hand: no preset marked
  await page.$eval('#speed', (el) => { el.value = '20'; el.dispatchEvent(new Event('input', { bubbles: true })); });
  assert.deepEqual(await page.$$eval('.speeds [role="radio"][aria-checked="true"]', (bs) => bs.length), 0);
});

test('compare: on a point robot\'s scenario each lane shows the Optimum row, the same optimum and its own percentage', async () => {
  await openCompare(HASH);
  await runBoth();
  const rows = await page.evaluate(() => ['a', 'b'].map((k) => ({ text: document.getElementById(`${k}-stat-optimum`).textContent, visible: !document.getElementById(`${k}-stat-optimum`).parentElement.hidden, stats: window.planarium.stats(k) })));
  const seen = rows.map((r) => r.text.match(/^(\d+\.\d+) \(visibility graph\): this path ([+-]?\d+\.\d)%$/));
  for (const [k, r] of rows.entries()) {
    assert.ok(r.visible, `lane ${'AB'[k]} shows the row`);
    assert.ok(seen[k], `lane ${'AB'[k]}: ${r.text}`);
  }
  assert.equal(seen[0][1], seen[1][1], 'the same optimum in both lanes');
  assert.equal(seen[0][1], '1.23', "the open field's optimum, as the playground shows it");
  const costs = rows.map((r) => r.stats.cost);
  assert.notEqual(costs[0], costs[1], 'the lanes found different paths');
  for (const k of [0, 1]) {
    const opt = rows[k].stats.optimum;
    assert.ok(Math.abs(opt - 1.23) < 0.005, `the optimum ${opt}`);
    const pct = 100 * (costs[k] / opt - 1);
    assert.equal(seen[k][2], `+${pct.toFixed(1)}`, `lane ${'AB'[k]}: cost ${costs[k]} is ${pct.toFixed(1)}% above ${opt}`);
  }
  assert.notEqual(seen[0][2], seen[1][2], 'each lane its own percentage');
});

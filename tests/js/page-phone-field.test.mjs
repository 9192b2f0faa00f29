// A phone (390 × 844) and the potential field's local minimum, in headless chromium: the cost chart
// sits right under the canvas and its run bar; every run-bar button (Back, Reset, the speeds) is in
// sight, on two rows; the scenario's notes are not cut off. In apf-minimum the heat map is on from
// the start and shaded by value (the minimum light, not dark), the two forces the core measured at
// the minimum are drawn and captioned with their sizes, the label keeps off the goal, and the
// pseudocode says "stuck" in plain words with each item's number on its first line.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const PHONE = { width: 390, height: 844 };

test('phone: the cost chart under the canvas, every run-bar button in sight, the notes whole', async () => {
  await page.setViewportSize(PHONE);
  await fx.pickScenario('narrow', 'Narrow passage');
  await page.selectOption('#planner', 'rrt-star');
  await fx.waitState('idle');
  await page.waitForSelector('#chart-box:not([hidden])');
  const [canvas, chart, bar] = await Promise.all(['#canvas', '#chart-box', '#run-bar'].map((s) => page.locator(s).boundingBox()));
  console.log(`canvas ${JSON.stringify(canvas)}, run bar ${JSON.stringify(bar)}, chart ${JSON.stringify(chart)}`);
  // right under the canvas: only the run bar (two rows of buttons) between them
  const below = chart.y - (canvas.y + canvas.height);
  // (the run bar is sticky: its box is where it floats now, its height what lies between)
  assert.ok(below >= 0 && below <= bar.height + 40, `the chart's top ${below.toFixed(0)} px below the canvas (the run bar ${bar.height.toFixed(0)} px high between)`);
  assert.equal(await page.$eval('#chart-box', (e) => e.previousElementSibling?.id), 'run-bar', 'the chart comes right after the run bar');
  assert.ok(chart.height <= 160, `a compact chart: ${chart.height} px high`);
  // every button of the run bar within the screen's width, none scrolled away sideways
  await page.locator('#run-bar').scrollIntoViewIfNeeded();
  const buttons = await page.$$eval('#run-bar button', (bs) => bs.filter((b) => !b.hidden && b.offsetParent).map((b) => {
    const r = b.getBoundingClientRect();
    return { id: b.id, left: r.left, right: r.right, top: r.top, bottom: r.bottom };
  }));
  for (const id of ['step-back', 'reset', 'speed-slow', 'speed-normal', 'speed-instant']) {
    const b = buttons.find((x) => x.id === id);
    assert.ok(b, `${id} is shown`);
    assert.ok(b.left >= 0 && b.right <= PHONE.width && b.top >= 0 && b.bottom <= PHONE.height, `${id} in the viewport: ${JSON.stringify(b)}`);
  }
  const scroll = await page.$eval('#run-bar', (e) => ({ sw: e.scrollWidth, cw: e.clientWidth }));
  assert.ok(scroll.sw <= scroll.cw + 1, `the run bar does not scroll sideways: ${scroll.sw} > ${scroll.cw}`);
  const rows = new Set(buttons.map((b) => Math.round(b.top / 8))).size;
  console.log(`run-bar rows (by top): ${rows}`);
  // the chart draws when a run finishes
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
  await page.screenshot({ path: join(SHOTS, 'page-phone-chart.png') });
  // the notes of the longest note: not clipped
  await fx.pickScenario('apf-minimum', 'Potential field: a local minimum');
  const notes = await page.$eval('#scenario-notes', (e) => ({ sh: e.scrollHeight, ch: e.clientHeight, text: e.textContent.length }));
  assert.ok(notes.text > 300, `long notes: ${notes.text} characters`);
  assert.ok(notes.sh <= notes.ch + 1, `the notes are not cut off: ${notes.sh} > ${notes.ch}`);
});

/** Load apf-minimum with the potential field and run it to its end. */
async function runMinimum() {
  await fx.pickScenario('apf-minimum', 'Potential field: a local minimum');
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('no path');
  await fx.nextFrames();
}

/**
 * The heat colour (its index in PALETTE.heat, 0 lightest) most pixels in a square of `r` css px
 * around world point (x, y) are nearest to, and how many of them are within 12 of it per channel.
 */
const heatAt = (x, y, r) => page.evaluate(([x, y, r, heat]) => {
  const [cx, cy] = window.planarium.toCanvas(x, y);
  const c = document.getElementById('canvas'), dpr = c.width / c.getBoundingClientRect().width;
  const d = c.getContext('2d').getImageData(Math.round((cx - r) * dpr), Math.round((cy - r) * dpr), Math.round(2 * r * dpr), Math.round(2 * r * dpr)).data;
  const rgb = heat.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
  const votes = heat.map(() => 0);
  for (let i = 0; i < d.length; i += 4) {
    rgb.forEach(([R, G, B], k) => { if (Math.abs(d[i] - R) <= 12 && Math.abs(d[i + 1] - G) <= 12 && Math.abs(d[i + 2] - B) <= 12) votes[k]++; });
  }
  const best = votes.indexOf(Math.max(...votes));
  return { index: best, votes: votes[best], n: d.length / 4 };
}, [x, y, r, [...PALETTE.heat]]);

test('apf-minimum: the field from the start, light at the minimum, the forces captioned, the label off the goal', async () => {
  assert.equal(await page.isChecked('#show-heat'), false, 'no heat map for the default planner');
  await runMinimum();
  assert.equal(await page.isChecked('#show-heat'), true, 'the heat map is on from the start for a field planner');
  const cells = await page.evaluate(() => window.planarium.cells());
  assert.equal(cells.minima.length, 1);
  const m = cells.minima[0];
  // the tile just left of the minimum (off the descent's line and the ring): by value a lower
  // middle colour (U there about 0.08 of a 0 … 0.2 range), where rank shading made it dark
  const near = await heatAt(m.x - 0.05, m.y - 0.0125, 2);
  const start = await heatAt(0.15, 0.7, 3);
  console.log(`heat colour beside the minimum ${JSON.stringify(near)}, on the start's side ${JSON.stringify(start)}`);
  assert.ok(near.votes > near.n / 2, 'a heat-map tile there');
  assert.ok(near.index <= 4, `light beside the minimum: colour ${near.index} of 0–8`);
  // the start's side, higher up the cone, is darker than the minimum's
  assert.ok(start.index > near.index, `farther from the goal is darker: ${start.index} vs ${near.index}`);
  // the two forces at the minimum: the pull towards the goal (+x), the push back (−x), of about one size
  const pull = Math.hypot(...m.pull), push = Math.hypot(...m.push);
  console.log(`pull ${JSON.stringify(m.pull)}, push ${JSON.stringify(m.push)}`);
  assert.ok(m.pull[0] > 0 && m.push[0] < 0, 'the pull points to the goal, the push away from the wall');
  assert.ok(-m.push[0] > 0.5 * m.pull[0] && -m.push[0] < 2 * m.pull[0], `of one order along x: ${pull} vs ${push}`);
  const [pulls, pushes] = await fx.countColours('canvas', [PALETTE.forcePull, PALETTE.forcePush], 10);
  console.log(`force arrow pixels: pull ${pulls}, push ${pushes}`);
  assert.ok(pulls > 40 && pushes > 40, `both forces drawn: ${pulls}, ${pushes}`);
  // the explain panel: step back to the minimum's event and read its caption
  const caption = await page.evaluate(() => window.planarium.explain().caption);
  console.log(`caption: ${caption}`);
  assert.match(caption, /pull [\d.]+ and push [\d.]+ (cancel here|\(sum [\d.]+\): they cancel within a step of here)/);
  // the label "local minimum" is not drawn over the goal: no magenta text pixels around the goal
  const [gx, gy] = await page.evaluate(() => window.planarium.toCanvas(0.9, 0.5));
  const magenta = await page.evaluate(([gx, gy, colour]) => {
    const c = document.getElementById('canvas'), dpr = c.width / c.getBoundingClientRect().width;
    const r = 16;
    const d = c.getContext('2d').getImageData(Math.round((gx - r) * dpr), Math.round((gy - r) * dpr), Math.round(2 * r * dpr), Math.round(2 * r * dpr)).data;
    const [R, G, B] = [1, 3, 5].map((i) => parseInt(colour.slice(i, i + 2), 16));
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - R) < 20 && Math.abs(d[i + 1] - G) < 20 && Math.abs(d[i + 2] - B) < 20) n++;
    return n;
  }, [gx, gy, PALETTE.minimum]);
  assert.ok(magenta < 5, `label pixels over the goal: ${magenta}`);
  const [label] = await fx.countColours('canvas', [PALETTE.minimum], 8);
  assert.ok(label > 60, `the ring and its label are drawn: ${label}`);
  // Looked at: the light basin around the cup's mouth, the ring with the vermilion pull to the right
  // and the dark push to the left, "local minimum" under the ring, the goal clear.
  await page.screenshot({ path: join(SHOTS, 'page-field-minimum.png') });
});

test('the pseudocode: plain words for the minimum; a wrapped item keeps its number on its first line', async () => {
  await page.setViewportSize(PHONE);
  await fx.pickScenario('apf-minimum', 'Potential field: a local minimum');
  const lines = await page.$$eval('#explain li', (ls) => ls.map((l) => ({ id: l.dataset.line, text: l.textContent })));
  const minimum = lines.find((l) => l.id === 'minimum');
  assert.ok(minimum, 'a minimum line');
  assert.doesNotMatch(minimum.text, /no progress over the window/);
  assert.match(minimum.text, /closer to the goal/);
  assert.match(minimum.text, /stuck/);
  assert.ok(lines.some((l) => /give-up/.test(l.text) && /stop/.test(l.text)), 'what give-up does, said');
  // a wrapped item: its marker level with its first line, the rest hanging under the text
  const geo = await page.$eval('#explain li[data-line="minimum"]', (li) => {
    const code = li.querySelector('code');
    const range = document.createRange();
    range.selectNodeContents(code);
    const rects = [...range.getClientRects()];
    const li0 = li.getBoundingClientRect();
    return { lines: new Set(rects.map((r) => Math.round(r.top))).size, first: rects[0], last: rects[rects.length - 1], liTop: li0.top,
      marker: getComputedStyle(li).listStylePosition, codeDisplay: getComputedStyle(code).display };
  });
  console.log(`minimum item: ${geo.lines} lines, first ${JSON.stringify(geo.first)}, last ${JSON.stringify(geo.last)}`);
  assert.ok(geo.lines >= 2, 'the item wraps at phone width');
  assert.equal(geo.codeDisplay, 'block', 'the text is a block, so the number sits on its first line');
  assert.ok(geo.last.left > geo.first.left + 4, `the wrapped lines hang under the text: ${geo.last.left} vs ${geo.first.left}`);
  assert.ok(geo.first.top - geo.liTop < 8, 'the text starts at the item\'s top');
});

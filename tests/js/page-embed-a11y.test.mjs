// The embed page (embed.html, one <planarium-playground>) for keyboard and screen-reader users, in
// headless chromium, as page-a11y does for the playground: Run from the keyboard leaves the focus on
// Pause (and Pause on Run); the element's live regions change at most about once a second while a
// run plays, and a step speaks the status and the step's caption in full; the page's heading names
// the scenario. And a planner that draws a field shows its heat map by default (pixels of the heat
// map's palette), which `overlays=-show-heat` turns off.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startBrowser } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';

let env;
const errors = [];
before(async () => { env = await startBrowser(); });
after(async () => {
  await env?.close();
  assert.deepEqual(errors.map(String), [], 'no page threw');
});

/** embed.html with `hash`, once its element is in `state`. */
async function openEmbed(hash, state = 'idle', timeout = 30000) {
  const page = await env.browser.newPage({ viewport: { width: 900, height: 600 } });
  page.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); errors.push(e); });
  await page.goto(`${env.base}embed.html#${hash}`);
  await page.waitForFunction((s) => document.querySelector('planarium-playground')?.state === s, state, { timeout });
  return page;
}

/** The id of the button focused inside the element (null: none). */
const focusedControl = (page) => page.evaluate(() => document.querySelector('planarium-playground').shadowRoot.activeElement?.id ?? null);
const waitState = (page, s) => page.waitForFunction((w) => document.querySelector('planarium-playground').state === w, s);
const nextFrames = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

test('the embed: its heading names the scenario; Run from the keyboard leaves the focus on Pause, Pause on Run', async () => {
  // Slow (10 events a second): the run still plays when the focus is read
  const page = await openEmbed('scenario=narrow&planner=rrt-connect&seed=7&speed=0&controls=run,pause,step,reset');
  assert.equal(await page.textContent('main h1'), 'Narrow passage with RRT-Connect — Planarium');
  assert.equal(await page.title(), 'Narrow passage with RRT-Connect — Planarium');
  let tabs = 0;
  while (await focusedControl(page) !== 'run' && tabs < 4) { await page.keyboard.press('Tab'); tabs++; }
  assert.equal(await focusedControl(page), 'run', `${tabs} Tabs reach Run`);
  await page.keyboard.press('Enter');
  await waitState(page, 'running');
  await nextFrames(page);
  assert.equal(await focusedControl(page), 'pause', 'the focus moved from Run (now disabled) to Pause');
  await page.keyboard.press('Enter');
  await waitState(page, 'paused');
  await nextFrames(page);
  assert.equal(await focusedControl(page), 'run');
  await page.close();
});

test('while the embed plays its live regions change at most about once a second; a step speaks the status and the caption in full', async () => {
  // Normal (the whole replay in 15 s): the status line's counts change on every frame meanwhile
  const page = await openEmbed('scenario=narrow&planner=rrt-connect&seed=7&speed=33&step-size=5&controls=run,pause,step,reset');
  await page.evaluate(() => document.querySelector('planarium-playground').run());
  await waitState(page, 'running');
  await page.waitForTimeout(300);
  const count = await page.evaluate(() => new Promise((resolve) => {
    const el = document.querySelector('planarium-playground');
    const sel = '[aria-live], [role=status], [role=alert], [role=log]';
    const live = [...document.querySelectorAll(sel), ...el.shadowRoot.querySelectorAll(sel)]
      .filter((e) => e.getAttribute('aria-live') !== 'off');
    const status = el.shadowRoot.querySelector('.status');
    const before = el.stats().shown_events;
    let changes = 0, statusChanges = 0;
    const mo = new MutationObserver((records) => { changes += records.length; });
    for (const e of live) mo.observe(e, { childList: true, characterData: true, subtree: true });
    const so = new MutationObserver((records) => { statusChanges += records.length; });
    so.observe(status, { childList: true, characterData: true, subtree: true });
    setTimeout(() => {
      mo.disconnect();
      so.disconnect();
      resolve({ changes, statusChanges, regions: live.length, events: el.stats().shown_events - before, state: el.state });
    }, 1000);
  }));
  console.log(`a second of playing: ${count.events} events shown, ${count.changes} changes in ${count.regions} live regions, `
    + `${count.statusChanges} in the status line`);
  assert.equal(count.state, 'running', 'the run played the whole second');
  assert.ok(count.events > 20, `the playback moved on (${count.events} events)`);
  assert.ok(count.statusChanges > 2, `the visible status line followed the replay (${count.statusChanges} changes)`);
  assert.ok(count.changes >= 1 && count.changes <= 2, `${count.changes} live-region changes in a second`);

  await page.evaluate(() => document.querySelector('planarium-playground').pause());
  await waitState(page, 'paused');
  await page.focus('planarium-playground');
  await page.keyboard.press('r'); // reset: Step then asks the planner for step-size iterations at a time
  await waitState(page, 'idle');
  for (let i = 0; i < 3; i++) {
    const before = await page.evaluate(() => document.querySelector('planarium-playground').shadowRoot.querySelector('[role=status]').textContent);
    await page.keyboard.press('ArrowRight'); // the element has the focus: its keys
    await page.waitForFunction((was) => {
      const el = document.querySelector('planarium-playground');
      return el.state === 'paused' && el.shadowRoot.querySelector('[role=status]').textContent !== was;
    }, before);
    await nextFrames(page);
    const [said, status] = await page.evaluate(() => {
      const root = document.querySelector('planarium-playground').shadowRoot;
      return [root.querySelector('[role=status]').textContent, root.querySelector('.status').textContent];
    });
    console.log(`after a step: "${said}"`);
    assert.ok(said.startsWith(`${status}. `), `the live region says the status: "${said}" / "${status}"`);
    assert.match(said, /^paused · [\d,]+ iterations · [\d,]+ nodes\. \S.* → /, 'and the step\'s caption, in its parts');
  }
  const label = await page.evaluate(() => document.querySelector('planarium-playground').shadowRoot.querySelector('canvas').getAttribute('aria-label'));
  assert.match(label, /^Map of Narrow passage: tree [\d,]+ nodes; no path yet\.$/);
  await page.close();
});

/** Pixels of the element's canvas within `tol` (per channel) of a colour of the heat map's palette. */
const heatPixels = (page, tol = 3) => page.evaluate(({ heat, tol }) => {
  const c = document.querySelector('planarium-playground').shadowRoot.querySelector('canvas');
  const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const rgb = heat.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
  let n = 0;
  for (let i = 0; i < px.length; i += 4) {
    if (rgb.some(([r, g, b]) => Math.abs(px[i] - r) <= tol && Math.abs(px[i + 1] - g) <= tol && Math.abs(px[i + 2] - b) <= tol)) n++;
  }
  return { n, all: px.length / 4 };
}, { heat: [...PALETTE.heat], tol });

test('a planner that draws a field shows its heat map in the embed by default; overlays=-show-heat turns it off', async () => {
  const counts = {};
  for (const [name, extra] of [['default', ''], ['off', '&overlays=-show-heat']]) {
    const page = await openEmbed(`scenario=apf-minimum&speed=100&autoplay&controls=${extra}`, 'finished', 60000);
    await nextFrames(page);
    counts[name] = await heatPixels(page);
    await page.close();
  }
  console.log(`heat-map pixels: ${counts.default.n} of ${counts.default.all} by default, ${counts.off.n} with -show-heat`);
  assert.ok(counts.default.n > counts.default.all * 0.2, `the heat map covers the free space (${counts.default.n} pixels)`);
  assert.ok(counts.default.n > 5 * counts.off.n, `and is gone with -show-heat (${counts.off.n} pixels)`);
});

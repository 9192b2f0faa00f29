// What a phone (390×844) shows in its first screen, with the page's sections as a person finds
// them (headless chromium): the compare page's first lane's canvas right after loading, with the
// scenario and Run both above it and every set-up control still there below; the playground's
// step caption after "Step one event" on the Puma 560, the page scrolled to it while the focus
// stays on the button. At 1280×800 neither page moves: the compare page keeps its controls in the
// side column, the playground does not scroll. Screenshots: target/phone-screens-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startBrowser, SHOTS } from './browser.mjs';
import { PUMA_NAME } from './puma-view.mjs';

let env;
before(async () => { env = await startBrowser({ openSections: false }); });
after(async () => { await env?.close(); });

const PHONE = { width: 390, height: 844 };
const DESK = { width: 1280, height: 800 };

async function open(path, viewport) {
  const page = await env.browser.newPage({ viewport });
  const errors = [];
  page.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); errors.push(e); });
  await page.goto(`${env.base}${path}`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  return { page, errors };
}

const rect = (page, sel) => page.$eval(sel, (e) => {
  const r = e.getBoundingClientRect();
  return { top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height };
});

test('compare at 390×844: the first lane\'s canvas starts in the first screen, under the scenario and Run both; the set-ups below', async () => {
  const { page, errors } = await open('compare.html', PHONE);
  await page.waitForFunction(() => document.getElementById('a-canvas').getBoundingClientRect().height > 100);
  const canvas = await rect(page, '#a-canvas');
  console.log(`390×844 compare: #a-canvas ${JSON.stringify(canvas)}`);
  assert.ok(canvas.top >= 0 && canvas.top < PHONE.height, `the first lane's canvas starts in the first screen: ${JSON.stringify(canvas)}`);
  assert.ok(canvas.left >= 0 && canvas.right <= PHONE.width, 'and fits its width');
  for (const id of ['scenario', 'seed', 'run', 'pause', 'reset']) {
    const r = await rect(page, `#${id}`);
    assert.ok(r.bottom <= canvas.top, `#${id} is above the canvas, in the first screen: ${JSON.stringify(r)}`);
  }
  assert.equal(await page.evaluate(() => window.scrollY), 0, 'nothing scrolled');
  await page.screenshot({ path: join(SHOTS, 'phone-screens-compare.png') });
  // every control is still there, below the lanes: the set-ups' planners, the seeds, the export, the overlays
  for (const sel of ['#a-panel select', '#b-panel select', '#run-seeds', '#export-lanes', '#overlays input']) {
    const loc = page.locator(sel).first();
    await loc.scrollIntoViewIfNeeded();
    assert.equal(await loc.isVisible(), true, `${sel} is shown`);
    const r = await loc.boundingBox();
    assert.ok(r.x >= 0 && r.x + r.width <= PHONE.width, `${sel} fits the width`);
    const y = await page.evaluate((s) => document.querySelector(s).getBoundingClientRect().top + scrollY, sel);
    assert.ok(y > canvas.bottom, `${sel} is below the lanes`);
  }
  await page.screenshot({ path: join(SHOTS, 'phone-screens-compare-setups.png') });
  assert.deepEqual(errors, []);
  await page.close();
});

test('compare at 1280×800: the controls stay in the side column, left of both lanes, in their order', async () => {
  const { page, errors } = await open('compare.html', DESK);
  const lanes = await rect(page, '#lanes');
  const tops = [];
  for (const id of ['h-scenario', 'h-run', 'h-seeds', 'h-export', 'h-a', 'h-b', 'h-overlays']) {
    const r = await rect(page, `#${id}`);
    assert.ok(r.right <= lanes.left, `#${id} is left of the lanes`);
    tops.push(r.top);
  }
  assert.deepEqual([...tops].sort((a, b) => a - b), tops, 'the side column\'s sections in the page\'s order');
  assert.ok(lanes.top < 150, `the lanes at the top: ${JSON.stringify(lanes)}`);
  assert.deepEqual(errors, []);
  await page.close();
});

/** The Puma 560 scenario, stepped by one event with a click on Step one event; returns the caption's rect. */
async function stepPuma(viewport) {
  const { page, errors } = await open('', viewport);
  await page.selectOption('#scenario', 'puma-rbo-wall');
  await page.waitForFunction((n) => window.planarium.state() === 'idle' && document.getElementById('scenario-name').textContent === n, PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const before = await page.evaluate(() => scrollY);
  await page.click('#step-event');
  await page.waitForFunction(() => window.planarium.explain().events >= 1, null, { timeout: 30000 });
  return { page, errors, before };
}

/** Wait until the page's scrolling stops (a smooth scroll ends). */
async function settled(page) {
  await page.waitForFunction(() => new Promise((r) => {
    const y = scrollY;
    setTimeout(() => requestAnimationFrame(() => r(scrollY === y)), 150);
  }), null, { timeout: 10000 });
}

test('playground at 390×844, Puma 560: after Step one event the step\'s caption is in the screen, the focus still on the button', async () => {
  const { page, errors, before } = await stepPuma(PHONE);
  assert.equal(before, 0, 'the first screen before the step');
  await page.waitForFunction(() => document.getElementById('explain-caption').textContent !== 'Run or step the planner: each step is explained here.', null, { timeout: 10000 });
  await settled(page);
  const cap = await rect(page, '#explain-caption');
  console.log(`390×844 playground after a step: #explain-caption ${JSON.stringify(cap)}, scrollY ${await page.evaluate(() => scrollY)}`);
  assert.ok(cap.top >= 0 && cap.bottom <= PHONE.height, `the caption is within the screen: ${JSON.stringify(cap)}`);
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'step-event', 'the focus stays on Step one event');
  const button = await rect(page, '#step-event');
  assert.ok(button.top >= 0 && button.bottom <= cap.top, `Step one event still in sight, above the caption: ${JSON.stringify(button)}`);
  await page.screenshot({ path: join(SHOTS, 'phone-screens-step.png') });
  // the keyboard's "." steps again: the caption stays in sight
  await page.keyboard.press('.');
  await page.waitForFunction(() => window.planarium.explain().events >= 2, null, { timeout: 30000 });
  await settled(page);
  const again = await rect(page, '#explain-caption');
  assert.ok(again.top >= 0 && again.bottom <= PHONE.height, `after "." the caption is in the screen: ${JSON.stringify(again)}`);
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'step-event');
  assert.deepEqual(errors, []);
  await page.close();
});

test('playground at 1280×800, Puma 560: Step one event scrolls nothing, the caption in the right column', async () => {
  const { page, errors } = await stepPuma(DESK);
  await page.waitForFunction(() => document.getElementById('explain-caption').textContent !== 'Run or step the planner: each step is explained here.', null, { timeout: 10000 });
  await settled(page);
  assert.equal(await page.evaluate(() => scrollY), 0, 'the page did not scroll');
  const cap = await rect(page, '#explain-caption');
  const stage = await rect(page, '#stage');
  assert.ok(cap.left >= stage.right, `the caption is right of the stage: ${JSON.stringify(cap)}`);
  assert.deepEqual(errors, []);
  await page.close();
});

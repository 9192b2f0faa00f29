// Comfort, in headless chromium: the keyboard help opens with "?" and closes with Escape; the page
// is usable by keyboard alone (Tab to Run, Enter); at phone width nothing overflows sideways and a
// run works; planning stays off the main thread (no long task while a big tree grows).
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

test('"?" opens the keyboard help, Escape closes it; keys do nothing while typing', async () => {
  await page.keyboard.press('?');
  await page.waitForFunction(() => document.getElementById('help').open);
  const text = await page.textContent('#help');
  for (const k of ['run / pause', 'step back', 'reset', 'undo / redo', 'this help']) assert.ok(text.includes(k), `help lists "${k}"`);
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => !document.getElementById('help').open);
  // The header button does the same.
  await page.click('#help-button');
  await page.waitForFunction(() => document.getElementById('help').open);
  await page.click('#help-close');
  await page.waitForFunction(() => !document.getElementById('help').open);
  // "?" typed into a field is just a character.
  await page.focus('#step-size');
  await page.keyboard.press('?');
  assert.equal(await page.evaluate(() => document.getElementById('help').open), false);
});

test('keyboard only: Tab reaches Run, Enter runs, space pauses and resumes', async () => {
  await fx.pickScenario('narrow', 'Narrow passage');
  await page.evaluate(() => document.activeElement?.blur());
  let reached = false;
  for (let i = 0; i < 80 && !reached; i++) {
    await page.keyboard.press('Tab');
    reached = await page.evaluate(() => document.activeElement?.id === 'run');
  }
  assert.ok(reached, 'Tab reaches the Run button');
  // The focused control is visibly marked.
  const outline = await page.evaluate(() => getComputedStyle(document.activeElement).outlineStyle);
  assert.notEqual(outline, 'none', 'a focus ring');
  await page.keyboard.press('Enter');
  await fx.waitStatus('solved');
});

test('phone width: nothing overflows sideways, the canvas fits, a run works', async () => {
  await page.setViewportSize({ width: 375, height: 740 });
  await fx.pickScenario('narrow', 'Narrow passage');
  const widths = await page.evaluate(() => ({ doc: document.documentElement.scrollWidth, view: window.innerWidth }));
  assert.ok(widths.doc <= widths.view + 1, `page ${widths.doc} px wide in a ${widths.view} px window`);
  const box = await page.locator('#canvas').boundingBox();
  assert.ok(box.width > 200 && box.x >= 0 && box.x + box.width <= 376, `canvas ${JSON.stringify(box)}`);
  await page.locator('#run').scrollIntoViewIfNeeded();
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitStatus('solved');
  await page.screenshot({ path: join(SHOTS, 'page-phone.png'), fullPage: false });
});

test('planning stays off the main thread: no long task while a big tree grows', async () => {
  await fx.pickScenario('horn-10', 'Kinematic chain in a horn, 10 links');
  await page.evaluate(() => {
    window.__long = [];
    new PerformanceObserver((list) => { for (const e of list.getEntries()) window.__long.push(e.duration); }).observe({ type: 'longtask' });
  });
  await page.click('#run');
  await page.waitForTimeout(3000);
  const longest = await page.evaluate(() => Math.max(0, ...window.__long));
  console.log(`longest main-thread task during 3 s of planning: ${longest.toFixed(0)} ms (${await page.evaluate(() => window.__long.length)} over 50 ms)`);
  assert.ok(longest < 250, `a ${longest} ms task blocked the page`);
});

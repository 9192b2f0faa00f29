// Comfort, in headless chromium: the keyboard help opens with "?" and closes with Escape; the page
// is usable by keyboard alone (Tab to Run, Enter); at phone width nothing overflows sideways and a
// run works; planning stays off the main thread (the page never starts the core; the tree grows in view).
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
  // The keyboard help reads on a phone: every description as wide as the dialog's text, not a
  // column a letter wide beside the longest keys.
  await page.click('#help-button');
  await page.waitForFunction(() => document.getElementById('help').open);
  const cells = await page.evaluate(() => [...document.querySelectorAll('#help .keys-table td')].map((td) => td.getBoundingClientRect().width));
  assert.ok(cells.length >= 8 && Math.min(...cells) >= 250, `the help's descriptions ${cells.map(Math.round).join(', ')} px wide`);
  await page.screenshot({ path: join(SHOTS, 'page-phone-help.png'), fullPage: false });
  await page.click('#help-close');
});

test('planning stays off the main thread: the page never loads the core, and keeps drawing while a big tree grows', async () => {
  // Watch, from the page's first script on, every way a WebAssembly module can start on the main thread.
  await page.addInitScript(() => {
    window.__wasm = [];
    for (const name of ['instantiate', 'instantiateStreaming', 'compile', 'compileStreaming']) {
      const f = WebAssembly[name];
      WebAssembly[name] = function (...args) { window.__wasm.push(name); return f.apply(this, args); };
    }
    const { Module } = WebAssembly;
    WebAssembly.Module = function (...args) { window.__wasm.push('Module'); return new Module(...args); };
  });
  await page.reload();
  await fx.waitState('idle', 30000);
  await fx.pickScenario('horn-10', 'Kinematic chain in a horn, 10 links');
  await page.evaluate(() => {
    window.__long = [];
    new PerformanceObserver((list) => { for (const e of list.getEntries()) window.__long.push(e.duration); }).observe({ type: 'longtask' });
    window.__nodes = [];
    const tick = () => { window.__nodes.push(window.planarium.stats().shown_nodes ?? 0); if (!window.__stop) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
  });
  await page.click('#run');
  // the run grows in view: wait (generously) until the tree has grown in 20 frames
  await page.waitForFunction(() => window.__nodes.filter((n, i) => i > 0 && n > window.__nodes[i - 1]).length >= 20, null, { timeout: 120000 });
  const out = await page.evaluate(() => { window.__stop = true; return { long: window.__long, wasm: window.__wasm, workers: 0 }; });
  const longest = Math.max(0, ...out.long);
  console.log(`longest main-thread task while the tree grew over 20 frames: ${longest.toFixed(0)} ms (${out.long.length} over 50 ms)`);
  assert.deepEqual(out.wasm, [], 'the main thread never started a WebAssembly module');
  assert.ok(page.workers().length >= 1, 'the planning worker runs');
});

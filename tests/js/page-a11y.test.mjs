// The pages for keyboard and screen-reader users: axe-core (a test-only dependency, injected from
// node_modules, never served) over every page, printing every finding and failing on any of
// moderate impact or above; the skip link reaches the run bar in a few Tabs; Run from the keyboard
// leaves the focus on Pause; the live regions change at most about once a second while a run
// plays and speak the explain panel's caption in full when it is stepped; the canvas's text names
// the nodes the stats show and the path's waypoints; every key the page handles is in the "?" help.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, walledIn, ROOT } from './browser.mjs';

const fx = await pageFixture();

const AXE = join(ROOT, 'node_modules', 'axe-core', 'axe.min.js');
const PUMA_NAME = "Puma 560 through a window (report 001's course)";

/**
 * Run axe-core on `page` (the pages' CSP admits scripts of their own origin only: the test serves
 * axe.min.js at a path of the page's origin that only this page's route answers). Prints every
 * finding; returns those of moderate impact or above.
 */
const FAILING = new Set(['moderate', 'serious', 'critical']);
async function axe(page, what) {
  const url = new URL('/__test-only__/axe.min.js', page.url()).href;
  await page.route(url, (route) => route.fulfill({ contentType: 'text/javascript', body: readFileSync(AXE, 'utf8') }));
  await page.addScriptTag({ url });
  const found = await page.evaluate(async () => {
    const r = await window.axe.run(document, { resultTypes: ['violations'] });
    return r.violations.map((v) => ({ id: v.id, impact: v.impact, help: v.help,
      nodes: v.nodes.map((n) => n.target.join(' ')) }));
  });
  console.log(`axe-core on ${what}: ${found.length ? '' : 'no violations'}`);
  for (const v of found) console.log(`  ${v.impact} ${v.id} (${v.help}): ${v.nodes.slice(0, 5).join(', ')}${v.nodes.length > 5 ? ` and ${v.nodes.length - 5} more` : ''}`);
  return found.filter((v) => FAILING.has(v.impact));
}

test('axe-core finds no moderate or worse violation on the playground: idle, after a run, with the Puma in 3-D', async () => {
  const page = fx.page;
  assert.deepEqual(await axe(page, 'the playground (idle)'), []);
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitState('finished', 60000);
  assert.deepEqual(await axe(page, 'the playground after a run'), []);
  await fx.pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => !document.getElementById('view3d').hidden);
  assert.deepEqual(await axe(page, 'the playground with puma-rbo-wall (3-D view)'), []);
});

test('axe-core finds no moderate or worse violation on the compare, benchmark and embed pages', async () => {
  for (const [file, ready] of [
    ['compare.html', () => window.planarium?.state() === 'idle'],
    ['bench.html', () => window.planarium?.state() === 'idle'],
    ['embed.html', () => document.querySelector('planarium-playground')?.state === 'idle'],
  ]) {
    const page = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
    page.on('pageerror', (e) => fx.errors.push(e));
    await page.goto(`${fx.env.base}${file}`);
    await page.waitForFunction(ready, null, { timeout: 30000 });
    assert.deepEqual(await axe(page, file), [], file);
    await page.close();
  }
});

test('the first Tab offers the skip link; it takes the keyboard to Run, and Run from the keyboard leaves the focus on Pause', async () => {
  const page = fx.page;
  await page.$eval('#speed', (el) => { // 10 events a second (Slow): the run still plays when the focus is read
    el.value = '0';
    el.dispatchEvent(new Event('input', { bubbles: true }));
  });
  const focused = () => page.evaluate(() => document.activeElement?.id || document.activeElement?.tagName);
  let tabs = 0;
  await page.keyboard.press('Tab'); tabs++;
  assert.equal(await focused(), 'skip-to-run');
  assert.ok(await page.$eval('#skip-to-run', (a) => a.getBoundingClientRect().top >= 0), 'the focused skip link is in view');
  await page.keyboard.press('Enter');
  assert.doesNotMatch(page.url(), /#run-bar/, 'the skip link leaves the share link in the address bar alone');
  if (await focused() !== 'run') { await page.keyboard.press('Tab'); tabs++; }
  assert.equal(await focused(), 'run');
  assert.ok(tabs <= 3, `${tabs} Tabs`);
  await page.keyboard.press('Enter');
  await fx.waitState('running');
  await fx.nextFrames();
  assert.equal(await focused(), 'pause', 'the focus moved from Run (now disabled) to Pause');
  await page.keyboard.press('Enter'); // Pause, from the keyboard: the focus goes back to Run
  await fx.waitState('paused');
  await fx.nextFrames();
  assert.equal(await focused(), 'run');
});

test('while a run plays the live regions change at most about once a second; a step speaks the caption in full', async () => {
  const page = fx.page;
  await page.setInputFiles('#file', { name: 'walled.json', mimeType: 'application/json',
    buffer: Buffer.from(JSON.stringify(walledIn({ max_nodes: 20000, time_limit: 60 }))) });
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Walled-in goal');
  await fx.waitState('idle');
  await page.click('#speed-normal');
  await page.click('#run');
  await fx.waitState('running');
  await page.waitForTimeout(300);
  const count = await page.evaluate(() => new Promise((resolve) => {
    const live = [...document.querySelectorAll('[aria-live], [role=status], [role=alert], [role=log]')]
      .filter((e) => e.getAttribute('aria-live') !== 'off');
    const shown = () => window.planarium.stats().shown_events;
    const before = shown();
    let changes = 0;
    const where = new Map();
    const mo = new MutationObserver((records) => {
      changes += records.length;
      for (const r of records) {
        const e = r.target instanceof Element ? r.target : r.target.parentElement;
        const k = e?.closest('[aria-live], [role]')?.id || e?.id || e?.tagName;
        where.set(k, (where.get(k) || 0) + 1);
      }
    });
    for (const e of live) mo.observe(e, { childList: true, characterData: true, subtree: true });
    setTimeout(() => {
      mo.disconnect();
      resolve({ changes, where: [...where].map(([k, v]) => `${k}: ${v}`).join(', '), regions: live.length, events: shown() - before, state: window.planarium.state() });
    }, 1000);
  }));
  console.log(`a second of playing: ${count.events} events shown, ${count.changes} changes in ${count.regions} live regions (${count.where})`);
  assert.equal(count.state, 'running', 'the run played the whole second');
  assert.ok(count.events > 20, `the playback moved on (${count.events} events)`);
  assert.ok(count.changes >= 1 && count.changes <= 2, `${count.changes} live-region changes in a second`);
  // the visible status strip changed with the replay meanwhile; it is not a live region
  assert.equal(await page.$eval('#run-status', (e) => e.getAttribute('role') ?? e.getAttribute('aria-live')), null);

  await page.click('#pause');
  await fx.waitState('paused');
  for (let i = 0; i < 3; i++) {
    const before = await page.evaluate(() => window.planarium.explain().events);
    await page.keyboard.press('.');
    await page.waitForFunction((n) => window.planarium.explain().events > n, before);
    await fx.nextFrames();
    const { caption } = await page.evaluate(() => window.planarium.explain());
    const said = await page.textContent('#run-announce');
    assert.ok(caption.length > 10, caption);
    assert.ok(said.endsWith(caption), `the live region says the caption in full: "${said}" / "${caption}"`);
    assert.match(said, /^paused at/);
  }
});

/** The first number in `text` ("1,234 of 2,000" → 1234). */
const firstNumber = (text) => Number(text.match(/\d[\d,]*/)[0].replace(/,/g, ''));

test("the canvas's text names the nodes the stats show, and the path's waypoints and cost", async () => {
  const page = fx.page;
  const label = () => page.$eval('#canvas', (c) => c.getAttribute('aria-label'));
  assert.match(await label(), /^Map of .+: tree 0 nodes; no path yet\.$/);
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitState('finished', 60000);
  await fx.nextFrames();
  const nodes = firstNumber(await page.textContent('#stat-nodes'));
  const result = await page.evaluate(() => window.planarium.result());
  assert.ok(nodes > 1 && result.solved);
  const text = await label();
  console.log(`canvas: ${text}`);
  assert.match(text, new RegExp(`tree ${nodes.toLocaleString('en')} nodes; path ${result.path.length} waypoints, cost ${result.stats.cost.toFixed(2)}\\.$`));
  // stepping back: the text follows the stats
  await page.click('#reset');
  await fx.waitState('idle');
  await page.keyboard.press('ArrowRight');
  await fx.waitState('paused');
  await fx.nextFrames();
  const stepped = firstNumber(await page.textContent('#stat-nodes')); // "1 of 2": drawn of the planner's
  assert.match(await label(), new RegExp(`tree ${stepped.toLocaleString('en')} nodes; no path yet\\.$`));
});

test('every key the page handles is in the "?" help', async () => {
  const page = fx.page;
  // the keys compared against e.key in the playground's modules
  const files = [...readdirSync(join(ROOT, 'www', 'ui')).map((f) => join('www', 'ui', f)), join('www', 'pages', 'main.js')];
  const keys = new Set();
  for (const f of files) {
    for (const m of readFileSync(join(ROOT, f), 'utf8').matchAll(/e\.key === '([^']+)'/g)) keys.add(m[1]);
  }
  const NAMES = { ' ': 'space', ArrowRight: '→', ArrowLeft: '←' };
  const wanted = [...new Set([...keys].map((k) => (NAMES[k] || k).toLowerCase()))];
  assert.ok(wanted.length >= 10, `keys found: ${wanted.join(' ')}`);
  await page.keyboard.press('?');
  await page.waitForFunction(() => document.getElementById('help').open);
  const listed = await page.$$eval('#help kbd', (ks) => ks.filter((k) => k.checkVisibility()).map((k) => k.textContent.trim().toLowerCase()));
  const missing = wanted.filter((k) => !listed.includes(k));
  assert.deepEqual(missing, [], `keys handled but not in the help: ${missing.join(' ')}`);
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => !document.getElementById('help').open);
});

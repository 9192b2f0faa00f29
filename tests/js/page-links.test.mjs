// Links that round-trip and links that attack (headless chromium), issue 13's page reproductions
// 5, 6 and 9: "Copy link" checks the reader's limits and the link's length before saying "Copied."
// (100,000 rectangles: no link, "Save JSON" instead; a normal edited scenario: copied, and opened
// in a new page it restores the same scenario); a hash of `a&` × 524,288 gives a few bounded lines,
// quickly, and the page stays usable; a link cut mid-base64 says so in words; the link as pasted
// stays in the address bar (and in the message) until the user changes something. And hostile
// names, notes and link values (markup, </script>, RTL overrides, 100 kB strings) opened by file,
// link and embed are shown as text, contained, with no element made, no dialog, no CSP violation.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { startBrowser, ROOT, SHOTS } from './browser.mjs';
import { MAX_LINK_CHARS } from '../../www/ui/links.js';
import { encodeScenario } from '../../www/ui/scenario-codec.js';
import { shown } from '../../www/ui/text.js';

let env;
before(async () => { env = await startBrowser(); });
after(async () => { await env?.close(); });

const openField = JSON.parse(readFileSync(join(ROOT, 'scenarios', 'open-field.json'), 'utf8'));

/** A new page (own context: clipboard allowed) collecting CSP violations, dialogs and errors; waited until idle. */
async function openPage(url, { idle = true } = {}) {
  const context = await env.browser.newContext({ viewport: { width: 1280, height: 800 } });
  await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(env.base).origin });
  const page = await context.newPage();
  const seen = { violations: [], dialogs: [], errors: [] };
  await page.exposeBinding('__cspViolation', (_, v) => seen.violations.push(v));
  await page.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (e) => window.__cspViolation(`${e.violatedDirective} ${e.blockedURI}`));
    // the longest task the main thread ran (a freeze), from the first script on
    window.__longest = 0;
    try {
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) window.__longest = Math.max(window.__longest, e.duration);
      }).observe({ type: 'longtask', buffered: true });
    } catch { /* no long-task timing */ }
  });
  page.on('dialog', (d) => { seen.dialogs.push(d.message()); d.dismiss(); });
  page.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); seen.errors.push(String(e)); });
  page.seen = seen;
  page.close = ((close) => async () => { await close.call(page); await context.close(); })(page.close);
  await page.goto(url);
  if (idle) await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 60000 });
  return page;
}

/** Open `text` as a file through "Open file…", like a person; waited until loaded. */
async function openFile(page, name, text) {
  await page.setInputFiles('#file', { name, mimeType: 'application/json', buffer: Buffer.from(text) });
  await page.waitForFunction((n) => document.getElementById('scenario').selectedOptions[0]?.textContent === `File: ${n}`, name);
  await page.waitForFunction(() => window.planarium.state() === 'idle', null, { timeout: 120000 });
}

test('Copy link: a scenario too large for a link gets no "Copied." but "Save JSON"; a normal one round-trips', async () => {
  // 100,000 small rectangles (3.5 MB of JSON), well away from the start and the goal
  let s = 1;
  const r = () => { s = (s * 48271) % 2147483647; return s / 2147483647; };
  const obstacles = Array.from({ length: 100000 }, () => {
    const x = 0.2 + 0.6 * r(), y = 0.2 + 0.6 * r();
    return { rect: [+x.toFixed(4), +y.toFixed(4), +(x + 0.0005).toFixed(4), +(y + 0.0005).toFixed(4)] };
  });
  const huge = JSON.stringify({ ...openField, name: 'Hundred thousand rectangles', obstacles });
  console.log(`100,000 rectangles: ${(huge.length / 1e6).toFixed(2)} MB of JSON`);
  const page = await openPage(env.base);
  try {
    const tLoad = Date.now();
    await openFile(page, 'rects.json', huge);
    console.log(`opened and loaded in ${Date.now() - tLoad} ms`);
    assert.equal(await page.textContent('#scenario-name'), 'Hundred thousand rectangles');
    assert.equal(await page.evaluate(() => window.planarium.scenario().obstacles.length), 100000);
    const t0 = Date.now();
    await page.click('#copy-link');
    await page.waitForFunction(() => document.getElementById('copy-status').textContent !== '', null, { timeout: 60000 });
    const status = await page.textContent('#copy-status');
    console.log(`after ${Date.now() - t0} ms: ${status}`);
    assert.doesNotMatch(status, /Copied/);
    assert.match(status, /^No link copied: (the link would be [\d,]+ characters long, more than the 32,000|this scenario is [\d.]+ MB of JSON, more than the 4 MB)/);
    assert.match(status, /Save the scenario as a JSON file instead/);
    assert.equal(await page.isVisible('#save-json'), true, 'the offer');
    assert.equal(await page.inputValue('#share-url'), '', 'no link shown to copy by hand');
    const href = await page.evaluate(() => location.href);
    assert.ok(href.length <= 2 * 1024 * 1024, `the address bar holds ${href.length} characters`);
    const tSave = Date.now();
    const [d] = await Promise.all([page.waitForEvent('download'), page.click('#save-json')]);
    assert.equal(d.suggestedFilename(), 'hundred-thousand-rectangles.json');
    const saved = JSON.parse(readFileSync(await d.path(), 'utf8'));
    assert.equal(saved.obstacles.length, 100000);
    assert.equal(JSON.stringify(saved), await page.evaluate(() => JSON.stringify(window.planarium.scenario())), 'the file is the scenario shown');
    console.log(`Save JSON and the comparison: ${Date.now() - tSave} ms`);
    await page.screenshot({ path: join(SHOTS, 'links-too-large.png') });

    // past what a link may carry (4 MiB of JSON): 32,000 triangles at full precision. The core
    // accepts it (docs/limits.md), the address bar drops its hash rather than hold a link that
    // would not restore it, and Copy link says why. (No scenario within the core's limits makes a
    // link past the reader's 2 MiB: 4 MiB of JSON numbers deflate to about 1.7 M characters.)
    const triangles = Array.from({ length: 32000 }, () => {
      const x = 0.2 + 0.6 * r(), y = 0.2 + 0.6 * r();
      return { polygon: [[x, y], [x + 0.0003 + 0.0007 * r(), y], [x, y + 0.0003 + 0.0007 * r()]] };
    });
    await openFile(page, 'triangles.json', JSON.stringify({ ...openField, name: 'Noisy triangles', obstacles: triangles }));
    await page.waitForFunction(() => location.hash === '', null, { timeout: 30000 });
    await page.click('#copy-link');
    await page.waitForFunction(() => /^No link copied/.test(document.getElementById('copy-status').textContent), null, { timeout: 60000 });
    const noisy = await page.textContent('#copy-status');
    console.log(noisy);
    assert.match(noisy, /this scenario is 4\.\d+ MB of JSON, more than the 4 MB/);
    assert.equal(await page.evaluate(() => location.hash), '', 'no hash in the address bar');

    // a normal edited scenario: copied; opened in a new page, the same scenario
    const edited = { ...openField, name: 'Open field, edited', obstacles: [...openField.obstacles, { rect: [0.1, 0.5, 0.2, 0.6] }] };
    const tEdited = Date.now();
    await openFile(page, 'edited.json', JSON.stringify(edited));
    console.log(`the edited scenario loaded in ${Date.now() - tEdited} ms`);
    await page.click('#copy-link');
    await page.waitForFunction(() => document.getElementById('copy-status').textContent === 'Copied.');
    assert.equal(await page.isVisible('#save-json'), false);
    const link = await page.evaluate(() => navigator.clipboard.readText());
    assert.equal(link, await page.inputValue('#share-url'));
    assert.match(new URL(link).hash, /^#scenario=deflate:/);
    assert.ok(link.length <= MAX_LINK_CHARS);
    const shown = await page.evaluate(() => window.planarium.scenario());
    const other = await openPage(link);
    try {
      assert.deepEqual(await other.evaluate(() => window.planarium.scenario()), shown, 'the same scenario, read back');
      assert.equal(await other.textContent('#scenario-name'), 'Open field, edited');
      assert.equal(await other.isVisible('#error'), false);
    } finally {
      await other.close();
    }
    assert.deepEqual(page.seen, { violations: [], dialogs: [], errors: [] });
  } finally {
    await page.close();
  }
});

test('a hash of "a&" × 524,288: a few bounded lines, no freeze, the pasted link kept until a change', async () => {
  const hash = `#${'a&'.repeat(524288)}`;
  const t0 = Date.now();
  const page = await openPage(`${env.base}${hash}`, { idle: false });
  try {
    await page.waitForSelector('#error', { state: 'visible', timeout: 60000 });
    const ms = Date.now() - t0;
    await page.waitForFunction(() => window.planarium.state() === 'idle');
    const text = await page.textContent('#error-text');
    const longest = await page.evaluate(() => window.__longest);
    // the reader alone, in the page, on that hash: it decodes the first 1,000 pairs and only
    // counts the rest (its work is bounded by MAX_PAIRS, not by the link's length)
    const read = await page.evaluate(async () => {
      const { readShare } = await import('./ui/links.js');
      const decode = globalThis.decodeURIComponent;
      let decoded = 0;
      globalThis.decodeURIComponent = (t) => { decoded++; return decode(t); };
      const t = performance.now();
      try { await readShare(location.hash); } finally { globalThis.decodeURIComponent = decode; }
      return { ms: performance.now() - t, decoded };
    });
    console.log(`readShare on the 1 MB hash in the page: ${read.ms.toFixed(0)} ms, ${read.decoded} parts decoded`);
    assert.ok(read.decoded <= 2 * 1000, `${read.decoded} parts decoded`);
    console.log(`the message after ${ms} ms (navigation included), longest main-thread task ${longest.toFixed(0)} ms, `
      + `${text.length} characters:\n${text.slice(0, 600)}`);
    assert.ok(text.length < 2000, `${text.length} characters`);
    assert.ok(text.split('\n').length <= 20, `${text.split('\n').length} lines`);
    assert.match(text, /"a" needs a value \(a=…\); it was left out\. \(…and 999 more like it\)/);
    assert.match(text, /523,288 more parts after the first 1,000/);
    assert.match(text, /The link you opened \(1,048,\d{3} characters; it stays in the address bar until you change something\):\nhttp:\/\/127\.0\.0\.1:\d+\/#a&a&a&.*…$/s);
    await page.screenshot({ path: join(SHOTS, 'links-flood-message.png') });
    // the page works: a run to the end
    await page.$eval('#speed', (el) => { el.value = el.max; el.dispatchEvent(new Event('input', { bubbles: true })); });
    // that was a change: the hash now says what is shown
    await page.waitForFunction(() => location.hash.startsWith('#scenario=open-field&planner=rrt&seed=1&speed=100'));
    await page.click('#run');
    await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
    await page.screenshot({ path: join(SHOTS, 'links-flood.png') });
    assert.deepEqual(page.seen, { violations: [], dialogs: [], errors: [] });
  } finally {
    await page.close();
  }
});

test('a link with problems stays in the address bar as pasted; a good one is left alone; Copy link gives the clean one', async () => {
  const bad = '#scenario=narrow&planner=rrt&seed=12&rnage=0.3&speed=70';
  const page = await openPage(`${env.base}${bad}`);
  try {
    await page.waitForSelector('#error', { state: 'visible' });
    assert.match(await page.textContent('#error-text'), /"rnage" is not a parameter of RRT/);
    assert.match(await page.textContent('#error-text'), /The link you opened \(\d+ characters; .*\):\nhttp:.*#scenario=narrow&planner=rrt&seed=12&rnage=0\.3&speed=70$/);
    await page.waitForTimeout(1000); // the hash writer waits 250 ms after a change
    assert.equal(await page.evaluate(() => location.hash), bad, 'kept as pasted');
    const clean = '#scenario=narrow&planner=rrt&seed=12&speed=70';
    assert.equal(new URL(await page.inputValue('#share-url')).hash, clean, 'the link to what is shown, beside it');
    await page.click('#copy-link');
    await page.waitForFunction(() => document.getElementById('copy-status').textContent === 'Copied.');
    assert.equal(await page.evaluate(() => location.hash), clean, 'Copy link writes the clean one');
  } finally {
    await page.close();
  }
  // a seed typed: a change, the hash follows
  const second = await openPage(`${env.base}${bad}`);
  try {
    await second.waitForSelector('#error', { state: 'visible' });
    await second.click('#seed', { clickCount: 3 });
    await second.keyboard.type('13');
    await second.keyboard.press('Tab');
    await second.waitForFunction(() => location.hash === '#scenario=narrow&planner=rrt&seed=13&speed=70');
  } finally {
    await second.close();
  }
});

test('a link cut short mid-base64 says so in words, not with the browser\'s exception', async () => {
  const edited = JSON.stringify({ ...openField, name: 'Cut short', notes: 'x'.repeat(3000) });
  const value = await encodeScenario(edited);
  // `deflate:` and then base64url text 4k + 1 characters long (a stray last character), or cut elsewhere
  const body = value.length - 'deflate:'.length;
  for (const len of [8 + 21, 8 + 4 * Math.floor(body / 8) + 1, value.length - 1]) {
    const page = await openPage(`${env.base}#scenario=${value.slice(0, len)}&planner=rrt`);
    try {
      await page.waitForSelector('#error', { state: 'visible' });
      const text = await page.textContent('#error-text');
      console.log(`cut at ${len} of ${value.length}: ${text.split('\n')[1]}`);
      const why = (len - 8) % 4 === 1 ? 'its base64url text stops in the middle of a character group' : 'its compressed data does not decompress';
      assert.ok(text.includes(`The link's scenario is cut short or damaged (${why}): copy the whole link again, or ask for the scenario as a file.`), text);
      assert.doesNotMatch(text, /atob|DOMException|Failed to execute|InvalidCharacterError/);
      assert.equal(await page.textContent('#scenario-name'), openField.name, 'the first built-in instead');
      assert.deepEqual(page.seen, { violations: [], dialogs: [], errors: [] });
    } finally {
      await page.close();
    }
  }
});

// Hostile text: markup, a closing script tag, bidi overrides, long strings without a space (as
// long as the core's limits allow: 500 characters of name, 20,000 of notes; docs/limits.md)
const HOSTILE_NAME = `<img src=x onerror="window.__pwned='name';alert(1)">\u202eevil\u202c</script><script>window.__pwned='script'</script>${'W'.repeat(380)}`;
const HOSTILE_NOTES = `<b onmouseover=alert(2)>bold?</b> <iframe src="javascript:alert(3)"></iframe> \u202e\u2066rtl\u2069 ${'N'.repeat(19800)}`;

async function assertInert(page, where) {
  const found = await page.evaluate(() => {
    const all = [];
    const walk = (root) => {
      for (const el of root.querySelectorAll('*')) {
        all.push(el.tagName.toLowerCase());
        if (el.shadowRoot) walk(el.shadowRoot);
      }
    };
    walk(document);
    for (const f of document.querySelectorAll('iframe')) { try { walk(f.contentDocument); } catch { /* other origin */ } }
    return { imgs: all.filter((t) => t === 'img' || t === 'b' || t === 'iframe').length, pwned: window.__pwned ?? null,
      wide: document.documentElement.scrollWidth, view: window.innerWidth, tall: document.documentElement.scrollHeight };
  });
  console.log(`${where}: ${JSON.stringify(found)}`);
  assert.equal(found.imgs, 0, `${where}: an element was made from text`);
  assert.equal(found.pwned, null, `${where}: a script ran`);
  assert.ok(found.wide <= found.view + 1, `${where}: the page is ${found.wide} px wide in ${found.view}`);
  assert.deepEqual(page.seen, { violations: [], dialogs: [], errors: [] }, where);
}

test('hostile names, notes and link values by file, link and embed: text only, contained', async () => {
  const scenario = { ...openField, name: HOSTILE_NAME, notes: HOSTILE_NOTES };
  const text = JSON.stringify(scenario);
  // by file
  const page = await openPage(env.base);
  try {
    await page.setInputFiles('#file', { name: '<img src=x onerror=alert(4)>.json', mimeType: 'application/json', buffer: Buffer.from(text) });
    // shown as text, its bidirectional controls written out ([U+202E]: text.js shown)
    await page.waitForFunction((n) => document.getElementById('scenario-name').textContent === n, shown(HOSTILE_NAME), { timeout: 30000 });
    assert.equal(await page.textContent('#scenario-notes'), shown(HOSTILE_NOTES));
    assert.match(await page.textContent('#scenario-name'), /\[U\+202E\]evil\[U\+202C\]/);
    const box = await page.locator('#scenario-name').boundingBox();
    const notes = await page.locator('#scenario-notes').boundingBox();
    console.log(`name box ${box.width}×${box.height}, notes box ${notes.width}×${notes.height}`);
    assert.ok(box.height < 100 && notes.height < 300, 'the long texts are cut to a box that scrolls');
    await page.screenshot({ path: join(SHOTS, 'links-hostile-file.png') });
    await assertInert(page, 'file');
    // a name 100 kB long is refused by the core, which names where and the limit
    const longName = JSON.stringify({ ...scenario, name: `${HOSTILE_NAME}${'W'.repeat(100000)}` });
    await page.setInputFiles('#file', { name: 'long-name.json', mimeType: 'application/json', buffer: Buffer.from(longName) });
    await page.waitForSelector('#error', { state: 'visible' });
    const refused = await page.textContent('#error-text');
    assert.match(refused, /name: has 100\d{3} characters; the limit is 500/);
    assert.ok(refused.length < 3000, `${refused.length} characters`);
    await assertInert(page, 'file with a 100 kB name');
  } finally {
    await page.close();
  }
  // by link: the scenario in the link, and hostile values for the other keys
  const value = await encodeScenario(text);
  const markup = encodeURIComponent('<img src=x onerror=alert(5)></script>\u202e');
  const link = `${env.base}#scenario=${value}&planner=${markup}&${markup}=${markup}${'Z'.repeat(50000)}&overlays=${markup}&speed=${markup}`;
  const viaLink = await openPage(link);
  try {
    await viaLink.waitForSelector('#error', { state: 'visible' });
    await viaLink.waitForFunction((n) => document.getElementById('scenario-name').textContent === n, shown(HOSTILE_NAME));
    const message = await viaLink.textContent('#error-text');
    console.log(message.slice(0, 800));
    assert.match(message, /There is no planner "<img src=x onerror=alert\(5\)><\/script>\[U\+202E\]"/);
    assert.doesNotMatch(message, /\u202e/, 'no override echoed');
    assert.ok(message.length < 3000, `${message.length} characters`);
    await viaLink.screenshot({ path: join(SHOTS, 'links-hostile-link.png') });
    await assertInert(viaLink, 'link');
  } finally {
    await viaLink.close();
  }
  // by embed: embed.html's hash, and the element's attributes
  const embed = await openPage(`${env.base}embed.html#scenario=${value}&controls=${markup}&autoplay`, { idle: false });
  try {
    await embed.waitForFunction(() => document.querySelector('planarium-playground')?.status === 'solved', null, { timeout: 60000 });
    const label = await embed.evaluate(() => document.querySelector('planarium-playground').shadowRoot.querySelector('canvas').getAttribute('aria-label'));
    // the canvas's text of its state ("Map of <name>: …") carries the name as text
    assert.ok(label.startsWith(`Map of ${HOSTILE_NAME.slice(0, 50)}`), `the name as text in the label: ${label.slice(0, 80)}`);
    const msg = await embed.evaluate(() => document.querySelector('planarium-playground').shadowRoot.querySelector('.message').textContent);
    assert.match(msg, /controls: <img src=x onerror=… is not a control/);
    await embed.screenshot({ path: join(SHOTS, 'links-hostile-embed.png') });
    await assertInert(embed, 'embed.html');
    await embed.evaluate(({ v, m }) => {
      const el = document.createElement('planarium-playground');
      el.setAttribute('scenario', v);
      el.setAttribute('planner', m);
      el.setAttribute('params', `${m}=${m}`);
      el.setAttribute('seed', `${m}\ud800`); // a lone surrogate: encodeURIComponent would throw on it
      document.body.replaceChildren(el);
    }, { v: value, m: decodeURIComponent(markup) });
    await embed.waitForFunction(() => /There is no planner/.test(document.querySelector('planarium-playground')?.shadowRoot.querySelector('.message').textContent));
    await assertInert(embed, '<planarium-playground> attributes');
  } finally {
    await embed.close();
  }
});

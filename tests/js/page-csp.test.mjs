// The pages under their Content-Security-Policy (headless chromium): the playground (a run, PNG,
// SVG and WebM exports), compare, bench (a small benchmark), embed.html framed by a page of another
// origin (a second server on another port) and <planarium-playground> in a page of its own. Every
// `securitypolicyviolation` event and console error is collected: there must be none. A page that
// breaks the policy on purpose (an inline <style>, an inline script) shows the collector works.
// The headers of scripts/serve.mjs and the <meta> of every .html in www/ are checked too.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { startBrowser, ROOT, SHOTS } from './browser.mjs';
import { CSP_META, securityHeaders } from '../../scripts/serve.mjs';

let env;
let other;      // a second server: another origin, whose page frames embed.html
let otherBase;
before(async () => {
  env = await startBrowser();
  other = createServer((req, res) => {
    const src = `${env.base}embed.html#scenario=narrow&planner=rrt-connect&autoplay&controls=step,reset&speed=100`;
    res.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    res.end(`<!doctype html><html><head><meta charset="utf-8"><title>Course notes</title></head><body>
<h1>Notes on another site</h1><iframe src="${src}" width="560" height="420" title="Planarium"></iframe></body></html>`);
  });
  await new Promise((r) => other.listen(0, '127.0.0.1', r));
  // "localhost" vs "127.0.0.1" and another port: another origin for sure
  otherBase = `http://localhost:${other.address().port}/`;
});
after(async () => {
  await env?.close();
  await new Promise((r) => other.close(r));
});

/** A fresh page collecting CSP violations (from every frame) and console errors. */
async function watchedPage() {
  const page = await env.browser.newPage({ viewport: { width: 1280, height: 800 } });
  const seen = { violations: [], console: [], errors: [] };
  await page.exposeBinding('__cspViolation', ({ frame }, v) => { seen.violations.push({ ...v, frame: frame.url() }); });
  await page.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (e) => {
      window.__cspViolation({ directive: e.violatedDirective, blocked: e.blockedURI, source: e.sourceFile, line: e.lineNumber, sample: e.sample });
    });
  });
  page.on('console', (m) => { if (m.type() === 'error') seen.console.push(m.text()); });
  page.on('pageerror', (e) => seen.errors.push(String(e)));
  return { page, seen };
}

function assertClean(seen, where) {
  console.log(`${where}: ${seen.violations.length} CSP violations, ${seen.console.length} console errors, ${seen.errors.length} page errors`);
  assert.deepEqual(seen.violations, [], `${where}: CSP violations`);
  assert.deepEqual(seen.console, [], `${where}: console errors`);
  assert.deepEqual(seen.errors, [], `${where}: page errors`);
}

async function download(page, click) {
  const [d] = await Promise.all([page.waitForEvent('download'), click()]);
  const path = await d.path();
  return { name: d.suggestedFilename(), bytes: readFileSync(path) };
}

test('serve.mjs sends the CSP, nosniff and no-referrer; every page carries the same CSP as a <meta>, nothing inline', async () => {
  const pages = readdirSync(join(ROOT, 'www')).filter((f) => f.endsWith('.html'));
  assert.ok(pages.length >= 4, pages.join(', '));
  for (const f of pages) {
    const html = readFileSync(join(ROOT, 'www', f), 'utf8');
    assert.ok(html.includes(CSP_META), `${f}: the CSP <meta>`);
    assert.doesNotMatch(html, /<script(?![^>]*\bsrc=)[^>]*>|<style\b|\sstyle\s*=|\son[a-z]+\s*=/i, `${f}: nothing inline`);
    const res = await fetch(`${env.base}${f}`);
    assert.equal(res.status, 200);
    assert.equal(res.headers.get('content-security-policy'), securityHeaders(f, html)['content-security-policy'], f);
    assert.match(res.headers.get('content-security-policy'), f === 'embed.html' ? /frame-ancestors \*$/ : /frame-ancestors 'self'$/);
    assert.equal(res.headers.get('x-content-type-options'), 'nosniff');
    assert.equal(res.headers.get('referrer-policy'), 'no-referrer');
  }
  // a page that is not one of Planarium's (course notes embedding it) keeps its own policy
  assert.equal(securityHeaders('notes.html', '<p>notes</p>')['content-security-policy'], undefined);
  for (const path of ['worker.js', 'pkg/planarium_bg.wasm', 'style.css', 'no-such-file']) {
    const res = await fetch(`${env.base}${path}`);
    assert.equal(res.headers.get('x-content-type-options'), 'nosniff', path);
    assert.ok(res.headers.get('content-security-policy'), path);
  }
  assert.equal((await fetch(`${env.base}worker/worker.js`)).headers.get('content-type'), 'text/javascript; charset=utf-8');
  assert.equal((await fetch(`${env.base}pkg/planarium_bg.wasm`)).headers.get('content-type'), 'application/wasm');
});

test('the policy is in force: an inline style and an inline script are refused and seen', async () => {
  const { page, seen } = await watchedPage();
  try {
    await page.goto(env.base);
    await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    await page.evaluate(() => {
      const s = document.createElement('script');
      s.textContent = 'window.__ran = true';
      document.body.append(s);
      const st = document.createElement('style');
      st.textContent = 'body { background: red }';
      document.head.append(st);
      const d = document.createElement('div');
      d.setAttribute('style', 'color: red');
    });
    await page.waitForTimeout(200);
    assert.equal(await page.evaluate(() => window.__ran), undefined, 'the inline script did not run');
    const directives = seen.violations.map((v) => v.directive).sort();
    console.log(`refused on purpose: ${directives.join(', ')}`);
    assert.ok(directives.some((d) => d.startsWith('script-src')), directives.join(', '));
    assert.ok(directives.some((d) => d.startsWith('style-src')), directives.join(', '));
  } finally {
    await page.close();
  }
});

test('the playground under its CSP: a run, PNG, SVG and WebM exports, a share link, no violation', async () => {
  const { page, seen } = await watchedPage();
  try {
    await page.goto(env.base);
    await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    await page.selectOption('#scenario', 'narrow');
    await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Narrow passage');
    await page.click('#record');
    await page.click('#run');
    await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
    await page.waitForTimeout(800);
    const webm = await download(page, () => page.click('#record'));
    assert.deepEqual([...webm.bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'a WebM file');
    const png = await download(page, () => page.click('#export-png'));
    assert.deepEqual([...png.bytes.subarray(1, 4)], [0x50, 0x4e, 0x47]);
    const svg = await download(page, () => page.click('#export-svg'));
    assert.match(svg.bytes.toString('utf8'), /<svg/);
    await page.click('#copy-link');
    await page.waitForFunction(() => document.getElementById('copy-status').textContent !== '');
    await page.click('#help-button');
    await page.keyboard.press('Escape');
    await page.screenshot({ path: join(SHOTS, 'csp-playground.png') });
    assertClean(seen, 'playground');
  } finally {
    await page.close();
  }
});

test('compare and bench under their CSP: a run each, no violation', async () => {
  const { page, seen } = await watchedPage();
  try {
    await page.goto(`${env.base}compare.html?scenario=narrow`);
    await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    await page.click('#run');
    await page.waitForFunction(() => window.planarium.stats('a').shown_events > 0 && window.planarium.stats('b').shown_events > 0, null, { timeout: 60000 });
    await page.screenshot({ path: join(SHOTS, 'csp-compare.png') });
    assertClean(seen, 'compare');
    await page.goto(`${env.base}bench.html`);
    await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    await page.fill('#runs', '2');
    await page.click('#bench-run');
    await page.waitForFunction(() => window.planarium.state() === 'idle' && window.planarium.report(), null, { timeout: 120000 });
    const json = await download(page, () => page.click('#export-json'));
    assert.ok(JSON.parse(json.bytes.toString('utf8')));
    await page.screenshot({ path: join(SHOTS, 'csp-bench.png'), fullPage: true });
    assertClean(seen, 'bench');
  } finally {
    await page.close();
  }
});

test('embed.html in an iframe of another origin, and <planarium-playground> in a page, run under the CSP', async () => {
  const { page, seen } = await watchedPage();
  try {
    await page.goto(otherBase);
    const frame = page.frameLocator('iframe');
    await frame.locator('planarium-playground').waitFor();
    const inFrame = page.frames().find((f) => f.url().includes('embed.html'));
    assert.notEqual(new URL(inFrame.url()).origin, new URL(page.url()).origin, 'another origin');
    await inFrame.waitForFunction(() => document.querySelector('planarium-playground')?.status === 'solved', null, { timeout: 60000 });
    // the element's own style applies (a constructed sheet): the bar lays its buttons out in a row
    const styled = await inFrame.evaluate(() => {
      const root = document.querySelector('planarium-playground').shadowRoot;
      return { sheets: root.adoptedStyleSheets.length, bar: getComputedStyle(root.querySelector('.bar')).display };
    });
    assert.deepEqual(styled, { sheets: 1, bar: 'flex' });
    await page.screenshot({ path: join(SHOTS, 'csp-embed-cross-origin.png') });
    assertClean(seen, 'embed.html framed by another origin');

    // the element in a page of the playground's origin, with the same policy as a header
    const url = `${env.base}csp-element-test.html`;
    await page.route(url, (route) => route.fulfill({
      status: 200,
      headers: { 'content-type': 'text/html; charset=utf-8', ...securityHeaders('csp-element-test.html', CSP_META) },
      body: `<!doctype html><html><head><meta charset="utf-8">${CSP_META}<script type="module" src="planarium-playground.js"></script></head>
<body><planarium-playground scenario="narrow" planner="rrt-connect" autoplay speed="100" controls="run,reset"></planarium-playground></body></html>`,
    }));
    await page.goto(url);
    await page.waitForFunction(() => document.querySelector('planarium-playground')?.status === 'solved', null, { timeout: 60000 });
    assertClean(seen, '<planarium-playground>');
  } finally {
    await page.close();
  }
});

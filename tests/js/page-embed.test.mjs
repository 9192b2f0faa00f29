// Embedding (headless chromium): a fresh static copy (scripts/dist.mjs) is served under a sub-path,
// /course/notes/planarium/, next to course-notes pages that hold the two snippets of
// docs/embedding.md exactly as written there: embed.html in an iframe and <planarium-playground>.
// Both run to a solution and draw it (canvas pixels), show only the chosen controls, fit a 320 px
// and a 900 px column, and leave keys sent to the host page alone (they take keys only when they
// have focus). Also: start on click, the seed control, attributes changed later, a bad embed hash,
// and the full page from the same copy giving the embed's path. Screenshots: target/embed-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { startBrowser, ROOT as root, SHOTS as shots } from './browser.mjs';
import { serve } from '../../scripts/serve.mjs';
import { PALETTE } from '../../www/draw/palette.js';

const docs = readFileSync(join(root, 'docs', 'embedding.md'), 'utf8');
/** The html block after `<!-- tested: name -->` in docs/embedding.md. */
function snippet(name) {
  const m = docs.match(new RegExp(`<!-- tested: ${name} -->\\s*\`\`\`html\\n([\\s\\S]*?)\`\`\``));
  assert.ok(m, `docs/embedding.md has the "${name}" snippet`);
  return m[1];
}

let env, site, tmp, notes;
const errors = [];

before(async () => {
  env = await startBrowser();
  tmp = mkdtempSync(join(tmpdir(), 'planarium-site-'));
  const dir = join(tmp, 'course', 'notes');
  mkdirSync(dir, { recursive: true });
  execFileSync(process.execPath, [join(root, 'scripts', 'dist.mjs'), '--out', join(dir, 'planarium')], { stdio: 'inherit' });
  const page = (title, width, body) => `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>${title}</title><link rel="icon" href="data:,">
<style>body { margin: 0; padding: 12px; font: 16px/1.4 Georgia, serif; } .col { width: ${width}px; } .col > * { margin-bottom: 12px; }</style>
</head><body>
<h1 id="heading">Course notes: ${title}</h1>
<div class="col" id="col">
${body}
</div>
<script>window.keysSeen = []; document.addEventListener('keydown', (e) => window.keysSeen.push(e.key));</script>
</body></html>`;
  const both = `${snippet('iframe')}\n${snippet('element')}`;
  writeFileSync(join(dir, 'narrow.html'), page('narrow column', 320, both));
  writeFileSync(join(dir, 'wide.html'), page('wide column', 900, both));
  writeFileSync(join(dir, 'click.html'), page('click to start', 480, `<script type="module" src="planarium/planarium-playground.js"></script>
<planarium-playground id="lazy" scenario="slot" planner="rrt" seed="3" click controls="run,pause,speed,seed" speed="100"></planarium-playground>`));
  writeFileSync(join(dir, 'below.html'), page('autoplay below the fold', 480, `<p id="spacer" style="height: 2400px">Read this first.</p>
<script type="module" src="planarium/planarium-playground.js"></script>
<planarium-playground id="below" scenario="narrow" planner="rrt-connect" seed="7" autoplay speed="100"></planarium-playground>`));
  // Oversized `params` (3,000 pairs: more than a link's 1,000) beside an explicit scenario, planner
  // and seed; and a seed above 2^53 − 1.
  writeFileSync(join(dir, 'params.html'), page('oversized params', 480, `<script type="module" src="planarium/planarium-playground.js"></script>
<planarium-playground id="big" scenario="slot" planner="rrt" seed="4" speed="100" params="${'goal_bias=0.1&'.repeat(3000)}" controls="run,seed"></planarium-playground>
<planarium-playground id="huge" scenario="narrow" seed="9007199254740993" controls="run,seed"></planarium-playground>`));
  // the element's events, recorded by the host page (a module script: the page has no CSP here)
  writeFileSync(join(dir, 'events.html'), page('events', 480, `<script type="module" src="planarium/planarium-playground.js"></script>
<planarium-playground id="ev" scenario="narrow" planner="rrt-connect" seed="7" autoplay speed="100" controls="step"></planarium-playground>
<script>window.seen = []; document.addEventListener('run', (e) => window.seen.push(['run', e.target.id, e.detail]));
document.addEventListener('solved', (e) => window.seen.push(['solved', e.target.id, e.detail]));
document.addEventListener('step', (e) => window.seen.push(['step', e.target.id, e.detail]));</script>`));
  site = await serve({ port: 0, dir: tmp });
  notes = `http://127.0.0.1:${site.address().port}/course/notes/`;
});

after(async () => {
  await env?.close();
  if (site) await new Promise((resolve) => site.close(resolve));
  if (tmp) rmSync(tmp, { recursive: true, force: true });
  assert.deepEqual(errors.map(String), [], 'no page threw');
});

async function open(url, viewport) {
  const p = await env.browser.newPage({ viewport });
  p.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); errors.push(e); });
  p.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') console.log(`[page ${m.type()}] ${m.text()}`); });
  p.on('response', (r) => { if (r.status() >= 400) errors.push(`${r.status()} for ${r.url()}`); });
  await p.goto(url);
  return p;
}

const frameOf = (p) => p.frames().find((f) => f.url().includes('/planarium/embed.html'));
async function embedFrame(p) {
  await p.waitForFunction(() => document.querySelector('iframe')?.contentDocument?.querySelector('planarium-playground'));
  return frameOf(p);
}

/** What one <planarium-playground> (the first matching `sel` in `ctx`) shows. */
const look = (ctx, sel = 'planarium-playground') => ctx.evaluate(({ sel, colours }) => {
  const el = document.querySelector(sel);
  const c = el.shadowRoot.querySelector('canvas');
  const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  const rgb = colours.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
  const counts = rgb.map(() => 0);
  for (let i = 0; i < px.length; i += 4) {
    rgb.forEach(([r, g, b], k) => {
      if (Math.abs(px[i] - r) <= 6 && Math.abs(px[i + 1] - g) <= 6 && Math.abs(px[i + 2] - b) <= 6) counts[k]++;
    });
  }
  const box = (e) => { const r = e.getBoundingClientRect(); return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height }; };
  return {
    state: el.state, status: el.status, nodes: el.nodeCount, pixels: counts,
    controls: [...el.shadowRoot.querySelectorAll('[data-control]')].filter((e) => e.checkVisibility()).map((e) => e.dataset.control),
    canvas: box(c), host: box(el), parent: box(el.parentElement),
    view: { width: innerWidth, height: innerHeight, scrollWidth: document.documentElement.scrollWidth, scrollHeight: document.documentElement.scrollHeight },
    message: el.shadowRoot.querySelector('.message').hidden ? '' : el.shadowRoot.querySelector('.message').textContent,
  };
}, { sel, colours: [PALETTE.tree0, PALETTE.tree1, PALETTE.smoothPath] });

const waitEl = (ctx, status, sel = 'planarium-playground', timeout = 60000) =>
  ctx.waitForFunction(({ sel, status }) => document.querySelector(sel)?.status === status, { sel, status }, { timeout });

for (const [name, width] of [['narrow', 320], ['wide', 900]]) {
  test(`a ${width} px column: the iframe and the element run to a solution, show only step and reset, and fit`, async () => {
    const p = await open(`${notes}${name}.html`, { width: 1000, height: 1900 });
    try {
      const frame = await embedFrame(p);
      await waitEl(frame, 'solved');
      await waitEl(p, 'solved', '#col > planarium-playground');
      await p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const inFrame = await look(frame);
      const inPage = await look(p, '#col > planarium-playground');
      const iframe = await p.evaluate(() => { const r = document.querySelector('iframe').getBoundingClientRect(); return { width: r.width, height: r.height }; });
      console.log(`${width} px: iframe ${iframe.width}×${iframe.height}, its canvas ${inFrame.canvas.width}×${inFrame.canvas.height}, `
        + `pixels ${inFrame.pixels}; element canvas ${inPage.canvas.width}×${inPage.canvas.height}, pixels ${inPage.pixels}`);
      for (const [what, s] of [['iframe', inFrame], ['element', inPage]]) {
        assert.equal(s.message, '', `${what}: no message`);
        assert.ok(s.nodes > 20, `${what}: nodes shown ${s.nodes}`);
        const [tree0, tree1, path] = s.pixels;
        assert.ok(tree0 > 20 && tree1 > 20, `${what}: both trees are drawn (${tree0}, ${tree1})`);
        assert.ok(path > 100, `${what}: the smoothed path is drawn (${path})`);
        assert.deepEqual(s.controls, ['step', 'reset'], `${what}: only the chosen controls`);
        // the narrow passage is square: the canvas keeps that, and stays inside its box
        assert.ok(Math.abs(s.canvas.width / s.canvas.height - 1) < 0.02, `${what}: aspect ${s.canvas.width}/${s.canvas.height}`);
        assert.ok(s.canvas.left >= s.host.left - 0.5 && s.canvas.right <= s.host.right + 0.5, `${what}: the canvas is inside the element`);
        assert.ok(s.view.scrollWidth <= s.view.width, `${what}: nothing sticks out sideways`);
      }
      // the element takes the column's width; the frame's canvas nearly all of the frame's
      assert.ok(inPage.canvas.width >= width - 2 && inPage.canvas.width <= width, `element canvas ${inPage.canvas.width} in ${width}`);
      assert.ok(inPage.host.width <= width + 0.5, 'the element is no wider than its column');
      assert.ok(inFrame.canvas.width >= iframe.width * 0.85 && inFrame.canvas.width <= iframe.width, `frame canvas ${inFrame.canvas.width} in ${iframe.width}`);
      assert.ok(inFrame.view.scrollHeight <= inFrame.view.height, 'the embed fits its frame: no scrolling');
      await p.screenshot({ path: join(shots, `embed-${name}.png`), fullPage: true });
      await p.screenshot({ path: `/tmp/embed-host-${name}.png`, fullPage: true });
    } finally {
      await p.close();
    }
  });
}

test("keys sent to the host page are left alone; the embeds take them only when focused", async () => {
  const p = await open(`${notes}narrow.html`, { width: 1000, height: 1400 });
  try {
    const frame = await embedFrame(p);
    await waitEl(frame, 'solved');
    const el = '#col > planarium-playground';
    await waitEl(p, 'solved', el);
    const states = async () => [await frame.evaluate(() => document.querySelector('planarium-playground').state),
      await p.evaluate((s) => document.querySelector(s).state, el)];
    await p.click('#heading');
    for (const key of ['r', ' ', 'ArrowRight', 'ArrowLeft', 'R']) await p.keyboard.press(key);
    await p.waitForTimeout(300);
    assert.deepEqual(await states(), ['finished', 'finished'], 'keys on the host page do nothing to the embeds');
    assert.deepEqual(await p.evaluate(() => window.keysSeen), ['r', ' ', 'ArrowRight', 'ArrowLeft', 'R'], 'and the page gets them all');

    // the element with focus: r resets, → steps (its controls); space is not one of them: left to the page
    await p.locator(`${el} canvas`).click();
    await p.keyboard.press('r');
    await p.waitForFunction((s) => document.querySelector(s).state === 'idle', el);
    await p.keyboard.press('ArrowRight');
    await p.waitForFunction((s) => document.querySelector(s).state === 'paused', el);
    await p.keyboard.press(' ');
    await p.waitForTimeout(200);
    assert.deepEqual(await states(), ['finished', 'paused']);
    assert.deepEqual((await p.evaluate(() => window.keysSeen)).slice(5), [' '], 'the keys it used stay with it');

    // the iframe with focus
    await p.frameLocator('iframe').locator('planarium-playground canvas').click();
    await p.keyboard.press('r');
    await frame.waitForFunction(() => document.querySelector('planarium-playground').state === 'idle');
    await p.keyboard.press('ArrowRight');
    await frame.waitForFunction(() => document.querySelector('planarium-playground').state === 'paused');
    assert.deepEqual(await states(), ['paused', 'paused']);
    assert.deepEqual((await p.evaluate(() => window.keysSeen)).slice(5), [' '], "the frame's keys never reach the page");
  } finally {
    await p.close();
  }
});

test('click to start, the speed and seed controls, and attributes changed later', async () => {
  const p = await open(`${notes}click.html`, { width: 1000, height: 1000 });
  try {
    await waitEl(p, 'idle', '#lazy');
    await p.waitForTimeout(300);
    let s = await look(p, '#lazy');
    assert.equal(s.state, 'idle', 'nothing runs before the click');
    assert.deepEqual(s.controls, ['start', 'run', 'pause', 'speed', 'seed']);
    await p.locator('#lazy canvas').click({ position: { x: 20, y: 20 } });
    await waitEl(p, 'solved', '#lazy');
    s = await look(p, '#lazy');
    assert.deepEqual(s.controls, ['run', 'pause', 'speed', 'seed'], 'the start button is gone');
    const first = await p.evaluate(() => document.querySelector('#lazy').result());
    assert.equal(first.seed, 3);
    // another seed from the seed field: a new run
    const seed = p.locator('#lazy input[type="number"]');
    await seed.fill('5');
    await seed.press('Tab');
    await waitEl(p, 'idle', '#lazy');
    await p.locator('#lazy button[data-control="run"]').click();
    await waitEl(p, 'solved', '#lazy');
    const second = await p.evaluate(() => document.querySelector('#lazy').result());
    assert.equal(second.seed, 5);
    assert.notDeepEqual(second.path, first.path);
    // a new scenario by attribute
    await p.evaluate(() => document.querySelector('#lazy').setAttribute('scenario', 'narrow'));
    await p.waitForFunction(() => /Narrow passage/.test(document.querySelector('#lazy').shadowRoot.querySelector('canvas').getAttribute('aria-label')));
    await waitEl(p, 'idle', '#lazy');
  } finally {
    await p.close();
  }
});

test('an oversized params attribute is cut and said so, and never drops the explicit scenario; a seed above 2^53 − 1 is refused by name', async () => {
  const p = await open(`${notes}params.html`, { width: 1000, height: 1400 });
  try {
    await waitEl(p, 'idle', '#big');
    await p.waitForFunction(() => /Turn to pass the slot/.test(document.querySelector('#big').shadowRoot.querySelector('canvas').getAttribute('aria-label')));
    let s = await look(p, '#big');
    assert.match(s.message, /The params attribute has 3,000 parts .*only the first 995 were read/);
    assert.doesNotMatch(s.message, /No scenario given/);
    await p.locator('#big button[data-control="run"]').click();
    await p.waitForFunction(() => document.querySelector('#big').state === 'finished', null, { timeout: 120000 });
    const r = await p.evaluate(() => document.querySelector('#big').result());
    assert.deepEqual([r.planner, r.seed], ['rrt', 4], 'the explicit planner and seed');
    // seed="9007199254740993": named, with the largest seed; the scenario's seed runs
    await waitEl(p, 'idle', '#huge');
    s = await look(p, '#huge');
    assert.match(s.message, /seed=9007199254740993: the seed is larger than 9007199254740991 \(2\^53 − 1\)/);
    // the seed field: 2^53 + 1 typed is refused with a message; the field shows the seed that runs
    const field = p.locator('#huge input[type="number"]');
    const before = await field.inputValue();
    await field.fill('9007199254740993');
    await field.press('Tab');
    await p.waitForFunction(() => /Seed: 9007199254740993 is larger than 9007199254740991/.test(document.querySelector('#huge').shadowRoot.querySelector('.message').textContent));
    assert.equal(await field.inputValue(), before);
  } finally {
    await p.close();
  }
});

test('a bad embed hash is reported in the embed, which still works', async () => {
  const p = await open(`${notes}planarium/embed.html#scenario=nope&planner=rrt&seed=x&controls=run,fly&autoplay`, { width: 500, height: 560 });
  try {
    await waitEl(p, 'solved');
    const s = await look(p);
    assert.match(s.message, /no built-in scenario "nope"/);
    assert.match(s.message, /seed=x/);
    assert.match(s.message, /fly is not a control/);
    assert.deepEqual(s.controls, ['run', 'reset'], 'the control asked for, and Reset once the autoplay run has ended');
  } finally {
    await p.close();
  }
});

test('the static copy under a sub-path: the full page runs, and gives the embed\'s path for the same link', async () => {
  const hash = '#scenario=narrow&planner=rrt-connect&seed=7&speed=100';
  const p = await open(`${notes}planarium/index.html${hash}`, { width: 1280, height: 800 });
  const q = await open(`${notes}planarium/embed.html${hash}&autoplay`, { width: 500, height: 560 });
  try {
    await p.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    await p.click('#run');
    await p.waitForFunction(() => document.getElementById('status').textContent === 'solved', null, { timeout: 60000 });
    await waitEl(q, 'solved');
    const page = await p.evaluate(() => window.planarium.result());
    const embed = await q.evaluate(() => document.querySelector('planarium-playground').result());
    assert.deepEqual(embed.path, page.path);
    assert.deepEqual(embed.smoothed, page.smoothed);
  } finally {
    await p.close();
    await q.close();
  }
});

test('autoplay waits until the embed is scrolled into view, then runs from the start', async () => {
  const p = await open(`${notes}below.html`, { width: 800, height: 600 });
  await p.waitForFunction(() => document.querySelector('#below')?.state === 'idle', null, { timeout: 30000 });
  // loaded and ready, off screen: nothing runs (a second of frames to be sure)
  await p.waitForTimeout(1000);
  assert.equal(await p.evaluate(() => document.querySelector('#below').state), 'idle', 'off screen, autoplay waits');
  assert.equal(await p.evaluate(() => document.querySelector('#below').nodeCount), 0);
  await p.evaluate(() => document.querySelector('#below').scrollIntoView({ block: 'center' }));
  await waitEl(p, 'solved', '#below');
  assert.ok((await look(p, '#below')).pixels[0] > 50, 'the tree is drawn');
  await p.close();
});

test('the static copy carries the licences and the third-party notices, served like the pages', async () => {
  const dir = join(tmp, 'course', 'notes', 'planarium');
  for (const f of ['LICENSE-MIT', 'LICENSE-APACHE', 'THIRD_PARTY_NOTICES.md']) {
    assert.equal(readFileSync(join(dir, f), 'utf8'), readFileSync(join(root, f), 'utf8'), `${f} copied as it is`);
  }
  const res = await fetch(`${notes}planarium/THIRD_PARTY_NOTICES.md`);
  assert.equal(res.status, 200);
  const text = await res.text();
  // the crates the wasm core is built on, each with its licence text
  for (const crate of ['nalgebra', 'parry2d-f64', 'serde_json', 'wasm-bindgen', 'rand_xoshiro', 'png']) {
    assert.match(text, new RegExp(`^\\| ${crate} \\| [^|]+ \\| [^|]+ \\| wasm`, 'm'), `${crate} listed as in the wasm core`);
  }
  assert.match(text, /Apache License\s+Version 2\.0/);
  assert.match(text, /Permission is hereby granted, free of charge/);
});

/** The numbers of an embed's status line, "running · 1,234 iterations · 56 nodes": [iterations, nodes] or null. */
const countsOf = (text) => {
  const m = /([\d,]+) iterations · ([\d,]+) nodes/.exec(text);
  return m ? [Number(m[1].replace(/,/g, '')), Number(m[2].replace(/,/g, ''))] : null;
};

test("the embed's counts rise while it runs, and end at the run's final numbers", async () => {
  const p = await open(`${notes}planarium/embed.html#scenario=narrow&planner=rrt-connect&seed=7&autoplay&speed=45&controls=step`, { width: 500, height: 560 });
  try {
    const status = () => p.evaluate(() => {
      const el = document.querySelector('planarium-playground');
      return { state: el?.state, text: el?.shadowRoot.querySelector('.status')?.textContent ?? '' };
    });
    await p.waitForFunction(() => document.querySelector('planarium-playground')?.state === 'running', null, { timeout: 60000 });
    const samples = [];
    for (let i = 0; i < 4000; i++) {
      const s = await status();
      if (s.state !== 'running') break;
      samples.push(s.text);
      await p.waitForTimeout(40);
    }
    await waitEl(p, 'solved');
    const running = samples.map(countsOf);
    console.log(`counts while running: ${samples.length} samples, ${[...new Set(samples)].slice(0, 8).join(' | ')} …`);
    assert.ok(running.every(Boolean), `every sample while running shows counts: ${samples.find((t) => !countsOf(t))}`);
    for (let i = 1; i < running.length; i++) {
      assert.ok(running[i][0] >= running[i - 1][0] && running[i][1] >= running[i - 1][1], `never falls: ${samples[i - 1]} then ${samples[i]}`);
    }
    const distinct = new Set(running.map(([it, n]) => `${it}/${n}`));
    assert.ok(distinct.size >= 3, `at least three different counts while it plays (${[...distinct].join(', ')})`);
    assert.ok(running.some(([, n]) => n > 0), 'some nodes are counted while it plays');
    const end = countsOf((await status()).text);
    const r = await p.evaluate(() => document.querySelector('planarium-playground').result());
    assert.ok(r.solved);
    assert.deepEqual(end, [r.stats.iterations, r.stats.nodes], "the line ends at the run's numbers");
    assert.ok(end[0] >= running[running.length - 1][0] && end[1] >= running[running.length - 1][1]);
    assert.ok(running[0][1] < end[1], `the first count (${samples[0]}) is below the last (${end})`);
  } finally {
    await p.close();
  }
});

test('the element fires run, solved and step; after autoplay, Step replays from the start and Reset is offered', async () => {
  const p = await open(`${notes}events.html`, { width: 1000, height: 1000 });
  try {
    await waitEl(p, 'solved', '#ev');
    await p.waitForFunction(() => window.seen.some(([t]) => t === 'solved'));
    const r = await p.evaluate(() => document.querySelector('#ev').result());
    let seen = await p.evaluate(() => window.seen);
    assert.deepEqual(seen.map(([t, id]) => `${t}:${id}`), ['run:ev', 'solved:ev']);
    assert.deepEqual(seen[0][2], { scenario: 'Narrow passage', planner: 'rrt-connect', seed: 7, resumed: false, autoplay: true });
    const solved = seen[1][2];
    assert.equal(solved.planner, 'rrt-connect');
    assert.equal(solved.seed, 7);
    assert.equal(solved.iterations, r.stats.iterations);
    assert.equal(solved.nodes, r.stats.nodes);
    // Reset joins the controls the author chose once the autoplay run has ended; Step is enabled
    let s = await look(p, '#ev');
    assert.deepEqual(s.controls, ['step', 'reset']);
    const step = p.locator('#ev button[data-control="step"]');
    assert.equal(await step.isEnabled(), true, 'Step is offered on the finished run');
    // Step: the run starts again from its beginning, one iteration shown
    await step.click();
    await p.waitForFunction(() => window.seen.some(([t]) => t === 'step'));
    seen = await p.evaluate(() => window.seen);
    assert.deepEqual(seen[2].slice(0, 2), ['step', 'ev']);
    assert.equal(seen[2][2].iterations, 1, 'one step from the start');
    assert.equal(seen[2][2].stepSize, 1);
    assert.equal(await p.evaluate(() => document.querySelector('#ev').state), 'paused');
    const text = await p.evaluate(() => document.querySelector('#ev').shadowRoot.querySelector('.status').textContent);
    assert.match(text, /^paused · 1 iterations · \d+ nodes$/);
    assert.ok(countsOf(text)[1] < r.stats.nodes, `fewer nodes than the whole run: ${text}`);
    await step.click();
    await p.waitForFunction(() => window.seen.filter(([t]) => t === 'step').length === 2);
    assert.equal((await p.evaluate(() => window.seen))[3][2].iterations, 2);
    // Reset: back to the start, nothing drawn
    await p.locator('#ev button[data-control="reset"]').click();
    await waitEl(p, 'idle', '#ev');
    s = await look(p, '#ev');
    assert.equal(s.nodes, 0);
  } finally {
    await p.close();
  }
});

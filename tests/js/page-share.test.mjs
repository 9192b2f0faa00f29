// Share links and step back in the page (headless chromium): a state set up by clicking and typing
// goes into the link, a fresh page opened on it restores every setting and runs to the same path
// number for number; an edited scenario travels in the link (compressed); a bad link is reported
// and the page still works; step back replays to the same point as a fresh run stepped there.
// The link grammar itself is checked in Node against the registry.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, ROOT as root, SHOTS as shots } from './browser.mjs';
import { initSync, planners, builtins } from '../../www/pkg/planarium.js';
import { readShare, writeShare, setupFor, configOf, RESERVED, VIEW_DEFAULTS } from '../../www/ui/links.js';
import { encodeScenario, decodeScenario } from '../../www/ui/scenario-codec.js';
import { OVERLAYS } from '../../www/draw/palette.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, pickScenario, fastPlayback } = fx;

initSync({ module: readFileSync(join(root, 'www/pkg/planarium_bg.wasm')) });
const registry = JSON.parse(planners());
const builtinList = JSON.parse(builtins());

/** Type into a field like a person: select its text, type, leave it (the panel acts on `change`). */
async function type(p, id, text) {
  await p.click(`#${id}`, { clickCount: 3 });
  await p.keyboard.type(String(text));
  await p.keyboard.press('Tab');
}

/** A fresh page on `url`, errors failing the test; waited until idle. */
async function openPage(url) {
  const p = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
  p.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); fx.errors.push(e); });
  p.on('console', (m) => { if (m.type() === 'error') console.log(`[page error] ${m.text()}`); });
  await p.goto(url);
  await p.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  return p;
}

async function runToEnd(p) {
  await p.click('#run');
  await p.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
  return p.evaluate(() => window.planarium.result());
}

const settingsOf = (p) => p.evaluate(() => ({
  scenario: document.getElementById('scenario').value,
  name: document.getElementById('scenario-name').textContent,
  planner: document.getElementById('planner').value,
  seed: document.getElementById('seed').value,
  speed: document.getElementById('speed').value,
  stepSize: document.getElementById('step-size').value,
  overlays: [...document.querySelectorAll('#overlays input')].map((i) => [i.id, i.checked]),
  params: [...document.querySelectorAll('#panel input, #panel select')].filter((i) => i.id !== 'seed' && i.id !== 'planner')
    .map((i) => [i.id, i.value]),
}));

test('the link grammar: every key round-trips, defaults are left out, no parameter takes a reserved name', async () => {
  for (const p of registry.planners) {
    for (const spec of [...p.params, ...(p.groups || []).flatMap((g) => g.params)]) {
      assert.ok(!RESERVED.includes(spec.name), `${p.name}'s parameter ${spec.name} is a reserved link key`);
    }
  }
  const narrow = builtinList.find((b) => b.id === 'narrow').scenario;
  const hash = await writeShare({
    scenario: { id: 'narrow' },
    config: { planner: 'rrt', params: { range: 0.1, goal_bias: 0.05, sampler: 'gaussian', dd_radius: 0.05, max_iterations: 5000 }, seed: 7 },
    overlays: Object.fromEntries(OVERLAYS.map((o) => [o.option, o.id === 'show-heat' ? true : o.id === 'show-domains' ? false : o.on])),
    view: { speed: 80, anim: 50, rawPath: true, stepSize: 25 },
  }, registry);
  // goal_bias 0.05 is RRT's default: left out; the overlays that differ, in the box's order
  assert.equal(hash, 'scenario=narrow&planner=rrt&seed=7&range=0.1&sampler=gaussian&dd_radius=0.05&max_iterations=5000'
    + '&overlays=-show-domains,+show-heat&speed=80&raw-path&step-size=25');
  // a planner that draws a field shows its heat map by default: written only when it is off
  const field = registry.planners.find((p) => p.caps?.draws === 'field');
  const heat = (on) => writeShare({ scenario: { id: 'narrow' }, config: { planner: field.name, params: {}, seed: 1 },
    overlays: { showHeat: on } }, registry);
  assert.doesNotMatch(await heat(true), /overlays/);
  assert.match(await heat(false), /&overlays=-show-heat$/);
  const share = await readShare(`#${hash}`, { builtins: builtinList });
  assert.deepEqual(share.problems, []);
  assert.deepEqual(share.view, { speed: 80, rawPath: true, stepSize: 25 });
  assert.deepEqual(share.overlays, { showDomains: false, showHeat: true });
  const { block, problems } = setupFor(share, narrow, registry);
  assert.deepEqual(problems, []);
  assert.deepEqual(configOf(block), { planner: 'rrt', seed: 7, params: { range: 0.1, sampler: 'gaussian', dd_radius: 0.05, max_iterations: 5000 } });
  // without a planner: the scenario's own block (narrow: rrt-connect, seed 7), listed values on top
  const own = setupFor(await readShare('#scenario=narrow&range=0.2'), narrow, registry);
  assert.deepEqual(own.block, { name: 'rrt-connect', seed: 7, range: 0.2 });
  // a scenario's JSON, compressed, round-trips
  const text = JSON.stringify(narrow);
  const value = await encodeScenario(text);
  assert.match(value, /^deflate:[A-Za-z0-9_-]+$/);
  assert.ok(value.length < text.length, `compressed: ${value.length} < ${text.length}`);
  assert.equal(await decodeScenario(value), text);
  assert.equal((await readShare(`#scenario=${value}`)).scenario.text, text);
  // without CompressionStream: plain base64url, read back the same
  const saved = globalThis.CompressionStream;
  try {
    delete globalThis.CompressionStream;
    const plain = await encodeScenario(text);
    assert.match(plain, /^base64:[A-Za-z0-9_-]+$/);
    assert.equal((await readShare(`#scenario=${plain}`)).scenario.text, text);
  } finally {
    globalThis.CompressionStream = saved;
  }
  // bad values: problems, never a throw
  const bad = await readShare('#scenario=nope&seed=-1&speed=300&overlays=+bogus&step-size=0&controls=run,fly&%E0%A4%A=1&range', { builtins: builtinList });
  assert.equal(bad.scenario, null);
  assert.equal(bad.seed, null);
  assert.equal(bad.problems.length, 8, bad.problems.join('\n'));
  const worse = await readShare('#scenario=deflate:AAAA_not-deflate&planner=rrt');
  assert.equal(worse.scenario, null);
  assert.match(worse.problems[0], /cut short or damaged/);
});

test('a link restores scenario, planner, parameter, seed, overlay and speed, and the run gives the same path', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  await type(page, 'param-goal_bias', '0.2');
  await waitState('idle');
  await type(page, 'seed', '11');
  await waitState('idle');
  await page.click('#show-rejected'); // off by default
  await page.click('#show-collisions'); // on by default (the domains' box shows only with dynamic domains on)
  await type(page, 'step-size', '25');
  await fastPlayback();
  const before = await settingsOf(page);
  const first = await runToEnd(page);
  assert.equal(first.solved, true);
  assert.equal(first.seed, 11);
  assert.deepEqual(first.params.goal_bias, 0.2);

  await page.click('#copy-link');
  await page.waitForFunction(() => /seed=11/.test(document.getElementById('share-url').value));
  const link = await page.inputValue('#share-url');
  console.log(`link: ${link}`);
  const hash = new URL(link).hash;
  assert.equal(hash, await page.evaluate(() => location.hash), 'the address bar holds the same link');
  assert.match(hash, /^#scenario=narrow&planner=rrt&seed=11&goal_bias=0\.2&overlays=\+show-rejected,-show-collisions&speed=100&step-size=25$/);

  const other = await openPage(link);
  try {
    assert.deepEqual(await settingsOf(other), before, 'every setting is restored');
    assert.equal(await other.isVisible('#error'), false, 'a good link gives no message');
    const second = await runToEnd(other);
    assert.deepEqual(second.path, first.path, 'the same raw path, number for number');
    assert.deepEqual(second.smoothed, first.smoothed, 'the same smoothed path');
    assert.equal(second.stats.iterations, first.stats.iterations);
    assert.equal(second.stats.nodes, first.stats.nodes);
    assert.equal(await other.evaluate(() => window.planarium.nodeCount()), await page.evaluate(() => window.planarium.nodeCount()));
  } finally {
    await other.close();
  }
});

test('an edited scenario travels in the link, compressed, and is restored', async () => {
  await pickScenario('narrow', 'Narrow passage');
  const start = (await page.evaluate(() => window.planarium.scenario())).start;
  // drag the start dot to the right, like a person
  const [sx, sy] = await page.evaluate(([x, y]) => window.planarium.toCanvas(x, y), start);
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + sx, box.y + sy);
  await page.mouse.down();
  await page.mouse.move(box.x + sx + 20, box.y + sy - 10, { steps: 5 });
  await page.mouse.move(box.x + sx + 40, box.y + sy - 20, { steps: 5 });
  await page.mouse.up();
  await page.waitForFunction((x0) => window.planarium.scenario().start[0] > x0 + 0.01, start[0]);
  await waitState('idle');
  const edited = await page.evaluate(() => window.planarium.scenario());
  await fastPlayback();
  const first = await runToEnd(page);
  assert.equal(first.solved, true);
  assert.deepEqual(first.path[0], edited.start, 'the path starts at the dragged start');

  const link = await page.evaluate(() => window.planarium.shareLink());
  assert.match(new URL(link).hash, /^#scenario=deflate:[A-Za-z0-9_-]+&planner=rrt-connect&seed=7&speed=100$/);
  const other = await openPage(link);
  try {
    assert.deepEqual(await other.evaluate(() => window.planarium.scenario()), edited, 'the edited scenario is restored');
    assert.equal(await other.textContent('#scenario-name'), 'Narrow passage');
    assert.equal(await other.textContent('#scenario-course'), 'Shared link');
    const second = await runToEnd(other);
    assert.deepEqual(second.path, first.path);
    assert.deepEqual(second.smoothed, first.smoothed);
    // its own link is the same again
    assert.equal(new URL(await other.evaluate(() => window.planarium.shareLink())).hash, new URL(link).hash);
  } finally {
    await other.close();
  }
});

test('a bad link shows a message, falls back to defaults, and the page still works', async () => {
  const other = await openPage(`${fx.env.base}#scenario=nope&planner=warp-drive&seed=abc&range=fast&overlays=+bogus&speed=9000`);
  try {
    await other.waitForSelector('#error', { state: 'visible' });
    const message = await other.textContent('#error-text');
    console.log(message);
    for (const bit of [/no built-in scenario "nope"/, /no planner "warp-drive"/, /seed=abc/, /range=fast/, /no overlay "bogus"/, /speed=9000/]) {
      assert.match(message, bit);
    }
    // defaults: the first built-in, its own planner block, the default speed
    assert.equal(await other.inputValue('#scenario'), builtinList[0].id);
    assert.equal(await other.inputValue('#planner'), builtinList[0].scenario.planner.name);
    assert.equal(await other.inputValue('#speed'), String(VIEW_DEFAULTS.speed));
    await other.$eval('#speed', (el) => { el.value = el.max; el.dispatchEvent(new Event('input', { bubbles: true })); });
    await other.click('#run');
    await other.waitForFunction(() => document.getElementById('status').textContent === 'solved', null, { timeout: 60000 });
    // the hash now says what is shown
    await other.waitForFunction(() => location.hash.startsWith(`#scenario=open-field&planner=rrt&seed=1`));
  } finally {
    await other.close();
  }
  // a scenario that decodes but is not valid: the core's message, then the first built-in
  const broken = await (await import('../../www/ui/scenario-codec.js')).encodeScenario('{"format": "planarium-scenario/1", "name": "Broken"}');
  const third = await openPage(`${fx.env.base}#scenario=${broken}&planner=rrt-connect`);
  try {
    await third.waitForSelector('#error', { state: 'visible' });
    assert.match(await third.textContent('#error-text'), /scenario is not valid/);
    assert.equal(await third.inputValue('#planner'), 'rrt-connect');
    assert.equal(await third.textContent('#scenario-name'), builtinList[0].scenario.name);
  } finally {
    await third.close();
  }
});

test('step back replays from the seed to the same point as a fresh run stepped there', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await page.fill('#step-size', '40');
  assert.equal(await page.isDisabled('#step-back'), true, 'nothing to go back to before a run');
  await page.click('#step');
  await page.waitForFunction(() => window.planarium.stats().iterations === 40);
  await page.click('#step');
  await page.waitForFunction(() => window.planarium.stats().iterations === 80);
  await page.click('#canvas'); // keys: → steps, ← steps back (focus outside inputs)
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.planarium.stats().iterations === 120 && window.planarium.stats().queued_events === 0);
  const at120 = await page.evaluate(() => window.planarium.nodeCount());
  await page.click('#step-back');
  await page.waitForFunction(() => window.planarium.stats().iterations === 80 && window.planarium.stats().queued_events === 0);
  assert.equal(await page.evaluate(() => window.planarium.state()), 'paused');
  const back80 = await page.evaluate(() => [window.planarium.nodeCount(), window.planarium.stats().nodes, window.planarium.shownIterations()]);
  await page.keyboard.press('ArrowLeft');
  await page.waitForFunction(() => window.planarium.stats().iterations === 40 && window.planarium.stats().queued_events === 0);
  const back40 = await page.evaluate(() => window.planarium.nodeCount());
  // step forward again: the same 120 as before
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.planarium.stats().iterations === 120 && window.planarium.stats().queued_events === 0);
  assert.equal(await page.evaluate(() => window.planarium.nodeCount()), at120);

  // a fresh run stepped straight to 80 and to 40
  await page.click('#reset');
  await waitState('idle');
  await page.fill('#step-size', '80');
  await page.click('#step');
  await page.waitForFunction(() => window.planarium.stats().iterations === 80 && window.planarium.stats().queued_events === 0);
  assert.deepEqual(await page.evaluate(() => [window.planarium.nodeCount(), window.planarium.stats().nodes, window.planarium.shownIterations()]), back80);
  await page.click('#reset');
  await waitState('idle');
  await page.fill('#step-size', '40');
  await page.click('#step');
  await page.waitForFunction(() => window.planarium.stats().iterations === 40 && window.planarium.stats().queued_events === 0);
  assert.equal(await page.evaluate(() => window.planarium.nodeCount()), back40);
  console.log(`nodes shown: 40 it ${back40}, 80 it ${back80[0]}, 120 it ${at120}`);

  // back from a finished run: the result is taken down, paused 40 iterations before the end
  await fastPlayback();
  const result = await runToEnd(page);
  await page.click('#step-back');
  await page.waitForFunction((n) => window.planarium.stats().iterations === n && window.planarium.state() === 'paused', result.stats.iterations - 40);
  assert.equal(await page.textContent('#status'), 'paused');
  // keys in an input are left alone
  await page.focus('#step-size');
  await page.keyboard.press('ArrowLeft');
  await page.waitForTimeout(200);
  assert.equal(await page.evaluate(() => window.planarium.stats().iterations), result.stats.iterations - 40);
  await page.screenshot({ path: join(shots, 'page-step-back.png') });
});

test('Copy embed code: the options go into an iframe whose src opens the same run; sizes out of bounds are refused by name; the element code pasted into a page gives the same run', async () => {
  await pickScenario('narrow', 'Narrow passage');
  await page.selectOption('#planner', 'rrt');
  await waitState('idle');
  await type(page, 'param-range', '0.1');
  await waitState('idle');
  await type(page, 'param-goal_bias', '0.2');
  await waitState('idle');
  await type(page, 'seed', '13');
  await waitState('idle');
  await fastPlayback();
  const first = await runToEnd(page);
  // a width out of bounds: no code, the field named
  await type(page, 'embed-width', '50');
  await page.click('#copy-embed');
  await page.waitForFunction(() => /No embed code: Width: "50" is not a whole number of pixels from 200 to 2000/.test(document.getElementById('embed-status').textContent));
  assert.equal(await page.inputValue('#embed-code'), '');
  // controls: step and reset only; autoplay stays on; 420 × 460
  await type(page, 'embed-width', '420');
  await type(page, 'embed-height', '460');
  for (const c of ['run', 'pause', 'back']) await page.click(`#embed-options input[data-control="${c}"]`);
  await page.click('#copy-embed');
  await page.waitForFunction(() => document.getElementById('embed-code').value.startsWith('<iframe'));
  const code = await page.inputValue('#embed-code');
  console.log(`embed code: ${code}`);
  // the iframe's attributes, read as HTML reads them (the entities decoded)
  const attrOf = (name) => {
    const m = new RegExp(`\\s${name}="([^"]*)"`).exec(code);
    assert.ok(m, `the code has ${name}="…"`);
    return m[1].replace(/&quot;/g, '"').replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&amp;/g, '&');
  };
  assert.match(code, /^<iframe [^<>]*><\/iframe>$/);
  const frame = { src: attrOf('src'), width: attrOf('width'), height: attrOf('height'), title: attrOf('title') };
  assert.deepEqual([frame.width, frame.height, frame.title], ['420', '460', 'Narrow passage']);
  const src = new URL(frame.src);
  assert.equal(src.pathname, '/embed.html');
  assert.match(src.hash, /^#scenario=narrow&planner=rrt&seed=13&.*autoplay&controls=step,reset$/);
  // the clipboard, where the browser gives one, holds the same text
  const clip = await page.evaluate(() => navigator.clipboard.readText().catch(() => null));
  if (clip !== null) assert.equal(clip, code);
  // opening that src, as the iframe would: the same run, the chosen controls
  const other = await fx.env.browser.newPage({ viewport: { width: 420, height: 460 } });
  other.on('pageerror', (e) => fx.errors.push(e));
  try {
    await other.goto(frame.src);
    await other.waitForFunction(() => document.querySelector('planarium-playground')?.state === 'finished', null, { timeout: 60000 });
    const embed = await other.evaluate(() => {
      const el = document.querySelector('planarium-playground');
      return { result: el.result(), controls: el.controls };
    });
    assert.deepEqual(embed.result.path, first.path, 'the same raw path, number for number');
    assert.equal(embed.result.stats.iterations, first.stats.iterations);
    assert.deepEqual(embed.controls, ['step', 'reset'], 'the controls chosen');
  } finally {
    await other.close();
  }

  // the element code: the module next to the playground and the element, the same state in its attributes
  await page.click('#copy-element');
  await page.waitForFunction(() => document.getElementById('embed-code').value.startsWith('<script'));
  const snippet = await page.inputValue('#embed-code');
  console.log(`element code: ${snippet}`);
  assert.equal(await page.textContent('#embed-status'), 'Copied the element code.');
  const lines = snippet.split('\n');
  assert.equal(lines.length, 2, snippet);
  assert.equal(lines[0], `<script type="module" src="${fx.env.base}planarium-playground.js"></script>`);
  assert.match(lines[1], /^<planarium-playground scenario="narrow" planner="rrt" seed="13" speed="100" params="[^"<>]*" autoplay controls="step,reset"><\/planarium-playground>$/);
  assert.match(lines[1], / params="range=0\.1&amp;goal_bias=0\.2"/, 'the & between parameters escaped in the attribute');
  const clip2 = await page.evaluate(() => navigator.clipboard.readText().catch(() => null));
  if (clip2 !== null) assert.equal(clip2, snippet);
  // pasted into a course page of the same site (the worker comes from the element's origin)
  const notes = `${fx.env.base}course-notes-element.html`;
  const host = await fx.env.browser.newPage({ viewport: { width: 700, height: 800 } });
  host.on('pageerror', (e) => fx.errors.push(e));
  await host.route(notes, (route) => route.fulfill({ status: 200, contentType: 'text/html; charset=utf-8',
    body: `<!doctype html><html><head><meta charset="utf-8"><title>Notes</title></head><body><h1>Notes</h1>\n${snippet}\n</body></html>` }));
  try {
    await host.goto(notes);
    await host.waitForFunction(() => document.querySelector('planarium-playground')?.state === 'finished', null, { timeout: 60000 });
    const got = await host.evaluate(() => {
      const el = document.querySelector('planarium-playground');
      return { result: el.result(), status: el.status, controls: el.controls, name: el.scenario?.name };
    });
    assert.equal(got.status, 'solved');
    assert.equal(got.name, 'Narrow passage', 'the same scenario');
    assert.deepEqual([got.result.seed, got.result.params.range, got.result.params.goal_bias], [13, 0.1, 0.2], 'the seed and the parameters');
    assert.deepEqual(got.result.path, first.path, 'the same raw path, number for number');
    assert.equal(got.result.stats.iterations, first.stats.iterations);
    assert.deepEqual(got.controls, ['step', 'reset'], 'the controls chosen');
  } finally {
    await host.close();
  }
});

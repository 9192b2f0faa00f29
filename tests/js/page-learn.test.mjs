// "The first five minutes" of a new student, driven like a person in headless chromium at a laptop's
// 1280×800 and a phone's 390×844: a cold page shows the scenario, the planner and Run in the first
// screen; Step one event walks a growth step with the explain panel's highlighted line and caption
// checked against the events the core emitted; Normal playback is watchable (the status strip and
// the stats follow the replay, not the planner); Slow / Normal / Instant; Run 20 seeds; Compare with
// 20 seeds from the playground's link; the bridge test's plain uniform draws on the zigzag (issue 16).
// Screenshots go to target/learn-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startBrowser, SHOTS } from './browser.mjs';
import { EventKind as K } from '../../www/run/events.js';

let env;
before(async () => { env = await startBrowser({ openSections: false }); });
after(async () => { await env?.close(); });

async function open(viewport, hash = '') {
  const page = await env.browser.newPage({ viewport });
  const errors = [];
  page.on('pageerror', (e) => { console.log(`[page error] ${e.stack || e}`); errors.push(String(e)); });
  page.on('console', (m) => { if (m.type() === 'error') console.log(`[page error] ${m.text()}`); });
  await page.goto(`${env.base}${hash}`);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  return { page, errors };
}

/** Whether element `sel` is drawn wholly inside the first viewport (no scrolling). */
async function inFirstScreen(page, sel) {
  return page.evaluate((sel) => {
    const e = document.querySelector(sel);
    const r = e.getBoundingClientRect();
    return e.checkVisibility() && r.width > 0 && r.top >= 0 && r.left >= 0 && r.bottom <= innerHeight && r.right <= innerWidth;
  }, sel);
}

/** The explain panel as a person sees it: the highlighted line's id and text, and the caption. */
const panelShown = (page) => page.evaluate(() => {
  const now = document.querySelectorAll('#explain-code li.now');
  return {
    count: now.length,
    line: now[0]?.dataset.line ?? null,
    text: now[0]?.textContent ?? '',
    caption: document.getElementById('explain-caption').textContent,
  };
});

/** The record the page revealed last (the playback's store, as the views read it). */
const lastRecord = (page) => page.evaluate(() => window.planarium.lastEvent());

for (const [width, height, tag] of [[1280, 800, 'laptop'], [390, 844, 'phone']]) {
  test(`first five minutes at ${width}×${height}: scenario, planner and Run in the first screen; stepping is explained line by line`, async () => {
    const { page, errors } = await open({ width, height });
    for (const sel of ['#scenario', '#planner', '#run', '#step-event']) {
      assert.ok(await inFirstScreen(page, sel), `${sel} is in the first screen at ${width}×${height}`);
    }
    assert.match(await page.textContent('#run-status'), /^Ready: Run starts RRT, seed 1\.$/, 'the cold page says what Run starts');
    assert.ok(!(await page.isVisible('#group-sampler')), 'the sampler group waits behind "More parameters"');
    await page.screenshot({ path: `${SHOTS}/learn-${tag}-cold.png` });

    // Step one event, twelve times: each shows one more record, and the panel says what it is
    const kinds = new Set();
    for (let i = 1; i <= 12; i++) {
      await page.click('#step-event');
      await page.waitForFunction((n) => window.planarium.explain().events === n, i);
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const r = await lastRecord(page);
      const shown = await panelShown(page);
      const model = await page.evaluate(() => window.planarium.explain());
      kinds.add(r[0]);
      assert.equal(shown.count, 1, 'one line highlighted');
      assert.equal(shown.line, model.line);
      assert.equal(shown.caption, model.caption);
      // the words follow the record's own numbers
      const [kind, , id, parent] = r;
      if (kind === K.SAMPLE) assert.match(shown.caption, /sample .*\(/);
      if (kind === K.NEAREST) {
        assert.ok(shown.caption.includes(`nearest #${id} at`), shown.caption);
        assert.match(shown.text, /NEAREST/);
      }
      if (kind === K.STEER) assert.match(shown.text, /STEER/);
      if (kind === K.NODE_ADDED && parent >= 0) assert.ok(shown.caption.includes(`add #${id} under #${parent}`), shown.caption);
      if (kind === K.COLLISION) assert.match(shown.caption, /blocked by (obstacle \d+|the map's edge)/);
    }
    for (const k of [K.SAMPLE, K.NEAREST, K.STEER, K.NODE_ADDED]) assert.ok(kinds.has(k), `stepped through kind ${k}`);
    assert.equal(await page.evaluate(() => window.planarium.state()), 'paused');
    assert.match(await page.textContent('#run-status'), /^paused at /);
    // the step's actors are on the canvas: the nearest node's ring in the actor colour
    const ring = await page.evaluate(() => {
      const c = document.getElementById('canvas');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - 0x7b) < 12 && Math.abs(d[i + 1] - 0x32) < 12 && Math.abs(d[i + 2] - 0x94) < 12) n++;
      return n;
    });
    assert.ok(ring > 20, `the step's actors are drawn (${ring} px)`);
    // the stats follow the events shown (not the planner, which is ahead by the rest of its batch)
    const st = await page.evaluate(() => ({ nodes: document.getElementById('stat-nodes').textContent, drawn: window.planarium.nodeCount() }));
    assert.equal(Number(st.nodes.split(' of ')[0].replace(/,/g, '')), st.drawn, `stats nodes ${st.nodes}, drawn ${st.drawn}`);
    // the legend names what the step draws
    const legend = await page.$$eval('#legend li', (lis) => lis.map((li) => li.textContent));
    for (const item of ['latest sample', 'this step: nearest node, step, range', 'this step: blocked']) assert.ok(legend.includes(item), `legend: ${item}`);
    await page.screenshot({ path: `${SHOTS}/learn-${tag}-step.png` });

    // Normal playback is watchable: a moment after Run the replay is still behind the planner,
    // and the status strip and the stats say so with the numbers drawn
    await page.click('#speed-normal');
    await page.click('#run');
    await page.waitForFunction(() => /^replaying ≈?\d+ of \d+ iterations · planner finished/.test(document.getElementById('run-status').textContent), null, { timeout: 20000 });
    const strip = await page.textContent('#run-status');
    const [, shownIt, totalIt] = strip.match(/replaying ≈?([\d,]+) of ([\d,]+)/).map((v) => Number(String(v).replace(/,/g, '')));
    assert.ok(shownIt < totalIt, strip);
    const stats = await page.evaluate(() => ({ it: document.getElementById('stat-iterations').textContent, nodes: document.getElementById('stat-nodes').textContent, drawn: window.planarium.nodeCount() }));
    assert.match(stats.it, /^[\d,]+ of [\d,]+$/, 'iterations: drawn of the planner\'s');
    assert.ok(Number(stats.nodes.split(' of ')[0].replace(/,/g, '')) <= stats.drawn + 5, `nodes shown ${stats.nodes}, drawn ${stats.drawn}`);
    await page.screenshot({ path: `${SHOTS}/learn-${tag}-running.png` });
    // Instant: the rest at once
    await page.click('#speed-instant');
    await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 20000 });
    assert.match(await page.textContent('#run-status'), /^solved · [\d,]+ iterations · [\d,]+ nodes · planner finished in/);
    assert.equal(await page.getAttribute('#speed-instant', 'aria-checked'), 'true');
    await page.screenshot({ path: `${SHOTS}/learn-${tag}-finished.png` });
    assert.deepEqual(errors, []);
    await page.close();
  });
}

test('Slow / Normal / Instant set the playback, and Normal is the default', async () => {
  const { page } = await open({ width: 1280, height: 800 });
  assert.equal(await page.getAttribute('#speed-normal', 'aria-checked'), 'true');
  const rate = () => page.textContent('#speed-out');
  assert.equal(await rate(), 'whole run in 15 s');
  await page.click('#speed-slow');
  assert.equal(await rate(), 'whole run in 40 s');
  assert.equal(await page.getAttribute('#speed-slow', 'aria-checked'), 'true');
  assert.equal(await page.getAttribute('#speed-normal', 'aria-checked'), 'false');
  // Slow shows the run step by step: counted in frames, not timed. The frame that first shows 3
  // events shows at most a few more (the run's some thousand events are spread over 40 s), and
  // the rest of the run is still queued.
  await page.evaluate(() => {
    const tick = () => {
      const events = window.planarium.explain().events;
      if (events >= 3) window.__slow = { events, queued: window.planarium.stats().queued_events, state: window.planarium.state() };
      else requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  await page.click('#run');
  await page.waitForFunction(() => window.__slow, null, { timeout: 30000 });
  const slow = await page.evaluate(() => window.__slow);
  console.log(`slow: ${JSON.stringify(slow)}`);
  assert.ok(slow.events < 3 + 10, `slow: ${slow.events} events in the frame that first showed 3`);
  assert.equal(slow.state, 'running');
  assert.ok(slow.queued > 0, 'the rest of the run is queued');
  await page.click('#speed-instant');
  await page.waitForFunction(() => window.planarium.state() === 'finished');
  await page.close();
});

test('only the overlays and parameters that apply are shown', async () => {
  const { page } = await open({ width: 1280, height: 800 });
  await page.click('#sec-overlays summary');
  const visible = () => page.evaluate(() => [...document.querySelectorAll('#overlays label')].filter((l) => !l.hidden).map((l) => l.dataset.option));
  const connect = await visible();
  assert.ok(connect.includes('showRejected') && !connect.includes('showCells') && !connect.includes('showFov') && !connect.includes('showRewires'), connect.join());
  await page.selectOption('#planner', 'rrt-star');
  await page.waitForFunction(() => window.planarium.state() === 'idle');
  assert.ok((await visible()).includes('showRewires'));
  await page.selectOption('#scenario', 'hex-trap');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent.length > 0 && window.planarium.state() === 'idle');
  await page.selectOption('#planner', 'hex-potential');
  await page.waitForFunction(() => window.planarium.state() === 'idle');
  const hex = await visible();
  assert.ok(hex.includes('showCells') && hex.includes('showHeat') && !hex.includes('showRejected'), hex.join());
  assert.match(await page.textContent('#overlays-note'), /^\d+ more apply to other planners or set-ups\.$/);
  // three main parameters in view; the rest behind "More parameters"
  const params = await page.evaluate(() => [...document.querySelectorAll('#planner-params label.field')].length);
  assert.ok(params <= 3, `${params} main parameters`);
  assert.match(await page.textContent('#more-params summary'), /^More parameters \(\d+\)/);
  // a sampling planner: the sampler's own parameters show under the sampler that uses them
  await page.selectOption('#scenario', 'narrow');
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Narrow passage' && window.planarium.state() === 'idle');
  await page.selectOption('#planner', 'rrt');
  await page.waitForFunction(() => window.planarium.state() === 'idle');
  await page.click('#more-params > summary');
  assert.ok(await page.isVisible('#param-sampler'));
  assert.ok(!(await page.isVisible('#param-sigma')) && !(await page.isVisible('#param-perseverance')), 'uniform: no sigma, no perseverance');
  assert.ok(!(await page.isVisible('#param-uniform_share')), 'uniform: no uniform share');
  await page.selectOption('#param-sampler', 'gaussian');
  await page.waitForFunction(() => window.planarium.state() === 'idle');
  assert.ok(await page.isVisible('#param-sigma') && !(await page.isVisible('#param-perseverance')), 'gaussian: sigma');
  assert.ok(await page.isVisible('#param-uniform_share'), 'gaussian: its uniform share');
  assert.ok(!(await page.isVisible('#param-dd_adaptive')), 'no domain radius: no adaptation');
  await page.fill('#param-dd_radius', '0.1');
  await page.press('#param-dd_radius', 'Enter');
  await page.dispatchEvent('#param-dd_radius', 'change');
  await page.waitForFunction(() => window.planarium.state() === 'idle');
  assert.ok(await page.isVisible('#param-dd_adaptive'), 'a domain radius: its adaptation shows');
  assert.ok((await visible()).includes('showDomains') && (await visible()).includes('showTries'), 'and the overlays of domains and raw tries');
  await page.close();
});

test('the bridge test on the zigzag: its tries and its plain uniform draws are told apart step by step, and it solves', async () => {
  // issue 16's hybrid form: a share of plain uniform samples (Sample id 2), captioned as such
  const { page } = await open({ width: 1280, height: 800 }, '#scenario=zigzag&planner=rrt-connect&sampler=bridge&seed=2');
  assert.equal(await page.textContent('#scenario-name'), 'Zigzag of walls');
  // A step may reveal several records (a sample and its growth): read the caption a person reads.
  let plain = null, tries = null;
  for (let i = 0; i < 2000 && !(plain && tries); i++) {
    await page.click('#step-event');
    const caption = await page.textContent('#explain-caption');
    if (/^sample \(/.test(caption) && (await lastRecord(page))?.[0] !== K.SAMPLE_TRY) plain ??= caption;
    if (/^sampler tries \(/.test(caption)) tries ??= caption;
  }
  // the bridge test's own attempts are tries (two occupied ends wanted), its rare successes samples;
  // every sample drawn here in the first steps is a plain one, and says so
  assert.match(tries ?? '', /^sampler tries \(.*\): (free|occupied)/, 'the bridge test\'s tries are shown');
  assert.match(plain ?? '', /^sample \(.*\) \(uniform share\)/, `a plain uniform draw is captioned: ${plain}`);
  await page.click('#speed-instant');
  await page.click('#run');
  await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
  assert.equal((await page.evaluate(() => window.planarium.result())).solved, true);
  await page.close();
});

test('Run 20 seeds in the playground: success and medians, and a seed opens on a click', async () => {
  const { page } = await open({ width: 1280, height: 800 });
  await page.click('#run-seeds');
  await page.waitForFunction(() => /solved \d+ of 20/.test(document.getElementById('trials-status').textContent), null, { timeout: 120000 });
  const table = await page.evaluate(() => Object.fromEntries([...document.querySelectorAll('#trials tr')].map((tr) => [tr.cells[0].textContent, tr.cells[1].textContent])));
  assert.match(table.Solved, /^\d+ of 20$/);
  assert.match(table['Median nodes'], /^[\d,]+$/);
  const dots = await page.$$eval('#trial-dots button', (bs) => bs.map((b) => Number(b.dataset.seed)));
  assert.deepEqual(dots, Array.from({ length: 20 }, (_, i) => 1 + i), 'seeds 1 … 20');
  // the medians are the medians of what the dots say (their titles carry each run's nodes)
  const nodes = await page.$$eval('#trial-dots button.solved', (bs) => bs.map((b) => Number(/, ([\d,]+) nodes/.exec(b.title)[1].replace(/,/g, ''))));
  nodes.sort((a, b) => a - b);
  const m = nodes.length % 2 ? nodes[nodes.length >> 1] : (nodes[nodes.length / 2 - 1] + nodes[nodes.length / 2]) / 2;
  assert.equal(Number(table['Median nodes'].replace(/,/g, '')), m);
  await page.screenshot({ path: `${SHOTS}/learn-seeds.png` });
  await page.click('#trial-dots button[data-seed="12"]');
  await page.waitForFunction(() => document.getElementById('seed').value === '12' && window.planarium.state() === 'idle');
  assert.match(await page.textContent('#run-status'), /seed 12\./);
  await page.close();
});

test('Compare from the playground\'s link, with 20 seeds', async () => {
  const { page } = await open({ width: 1280, height: 800 });
  await page.waitForFunction(() => /#.*scenario=open-field/.test(document.getElementById('to-compare').getAttribute('href')));
  await page.click('#to-compare');
  await page.waitForURL(/compare\.html#/);
  await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  await page.click('#run-seeds');
  await page.waitForFunction(() => !document.getElementById('seeds-table').hidden && /^\d+ runs done$/.test(document.getElementById('seeds-status').textContent)
    && !document.getElementById('run-seeds').disabled, null, { timeout: 180000 });
  assert.ok(await page.evaluate(() => document.querySelectorAll('#seeds-table tbody tr').length >= 4));
  await page.screenshot({ path: `${SHOTS}/learn-compare-seeds.png` });
  await page.close();
});

test('New seed: a fresh seed from the core\'s entropy, shown, in the share link, and replayable', async () => {
  const { page, errors } = await open({ width: 1280, height: 800 });
  assert.equal(await page.inputValue('#seed'), '1');
  await page.click('#new-seed');
  await page.waitForFunction(() => document.getElementById('seed').value !== '1' && window.planarium.state() === 'idle');
  const first = Number(await page.inputValue('#seed'));
  assert.ok(Number.isSafeInteger(first) && first >= 0, `a whole number exact in JavaScript: ${first}`);
  assert.match(await page.textContent('#run-status'), new RegExp(`seed ${first}\\.$`), 'the status says which seed Run uses');
  assert.match(await page.evaluate(() => window.planarium.shareLink()), new RegExp(`seed=${first}\\b`), 'the share link carries it');
  await page.click('#new-seed');
  await page.waitForFunction((s) => document.getElementById('seed').value !== String(s), first);
  const second = Number(await page.inputValue('#seed'));
  assert.notEqual(second, first, 'two fresh seeds differ');
  // the run on a fresh seed replays: the same seed typed in gives the same run
  const runOnce = async () => {
    await page.click('#speed-instant');
    await page.click('#run');
    await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 20000 });
    const r = await page.evaluate(() => window.planarium.result());
    return JSON.stringify([r.status, r.stats.iterations, r.stats.nodes, r.stats.checks, r.path]);
  };
  const a = await runOnce();
  await page.fill('#seed', '1');
  await page.dispatchEvent('#seed', 'change');
  await page.fill('#seed', String(second));
  await page.dispatchEvent('#seed', 'change');
  await page.waitForFunction(() => window.planarium.state() === 'idle');
  assert.equal(await runOnce(), a, 'the same seed typed in replays the same run');
  assert.deepEqual(errors, []);
  await page.close();
});

test('EST on the narrow passage: each step reads pick (with the cell\'s count and probability) → sample → added or blocked, and it solves', async () => {
  // issue 17: the density-based selection is what the panel explains, from the Select events
  const { page, errors } = await open({ width: 1280, height: 800 }, '#scenario=narrow&planner=est&seed=3');
  let picks = 0, added = 0, blocked = 0;
  for (let i = 0; i < 120; i++) {
    await page.click('#step-event');
    const { line, caption } = await panelShown(page);
    if (/^the tree picks #\d+: its cell holds \d+ nodes? \(probability [\d.]+ of \d+ cells\)/.test(caption)) {
      picks++;
      if (/→ add #\d+ under #\d+$/.test(caption)) { added++; assert.equal(line, 'add'); }
      if (/→ (blocked by obstacle \d+|blocked by the map's edge) at /.test(caption)) { blocked++; assert.equal(line, 'check'); }
    }
  }
  console.log(`EST steps: ${picks} captions with a pick, ${added} added, ${blocked} blocked`);
  assert.ok(picks > 20 && added > 5 && blocked > 0, `${picks} picks, ${added} added, ${blocked} blocked`);
  await page.screenshot({ path: `${SHOTS}/learn-est.png` });
  await page.click('#speed-instant');
  await page.click('#run');
  await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
  assert.equal((await page.evaluate(() => window.planarium.result())).solved, true);
  assert.deepEqual(errors, []);
  await page.close();
});

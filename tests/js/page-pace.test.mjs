// Pace by duration (headless chromium, driven like a person): at Normal a run of some sixty
// events and one of some seventy thousand both replay in about 15 s, the small one spread over
// the frames and the large one bunched many a frame; the potential field's heat map is one press
// of "Step one event". The machine is shared, so nothing asserts wall-clock time: the assertions
// read the pacing plan the page computes (window.planarium.pace(): the planned duration and the
// replay clock, the frames' own times summed as the page's loop sums them) and the records each
// frame revealed; the wall time is logged.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { EventKind as K } from '../../www/run/events.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, pickScenario, setField } = fx;

/**
 * Click Normal, then Run, and sample every frame until the page is finished: per frame the
 * records shown and the replay clock. Returns {frames: [[records, clock]...], plan, wall}.
 */
async function runAtNormal() {
  await page.click('#speed-normal');
  assert.match(await page.textContent('#speed-out'), /^whole run in 15 s$/);
  await page.evaluate(() => {
    window.__frames = [];
    window.__wall = undefined;
    window.__t0 = performance.now();
    const tick = () => {
      const p = window.planarium.pace();
      window.__frames.push([p.records, p.clock, p.pending]);
      if (window.planarium.state() === 'finished' && p.pending === 0) window.__wall = (performance.now() - window.__t0) / 1000;
      else requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  await page.click('#run');
  await page.waitForFunction(() => window.__wall !== undefined, null, { timeout: 120000 });
  return page.evaluate(() => ({ frames: window.__frames, plan: window.planarium.pace(), wall: window.__wall }));
}

/** Records revealed per frame, from the first frame that showed any to the last. */
function perFrame(frames) {
  const out = [];
  for (let i = 1; i < frames.length; i++) out.push(frames[i][0] - frames[i - 1][0]);
  const first = out.findIndex((n) => n > 0);
  let last = out.length - 1;
  while (last > 0 && out[last] === 0) last--;
  return out.slice(first, last + 1);
}

/** The replay clock at the frame that showed the last record. */
function clockAtEnd(frames) {
  const total = frames[frames.length - 1][0];
  return frames.find((f) => f[0] === total)[1];
}

test('at Normal a run of some sixty events and one of some seventy thousand both take about 15 s of replay', async () => {
  // small: RRT-Connect on the open field
  await pickScenario('open-field', 'Open field');
  await page.selectOption('#planner', 'rrt-connect');
  await waitState('idle');
  await setField('seed', 1);
  const small = await runAtNormal();
  // large: grid search on the zigzag with cells of 0.0072 (some 140 × 140 cells)
  await page.click('#reset');
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'grid-search');
  await waitState('idle');
  await setField('param-cell', 0.0072);
  const large = await runAtNormal();

  for (const [tag, r] of [['small', small], ['large', large]]) {
    const shown = perFrame(r.frames);
    const end = clockAtEnd(r.frames);
    console.log(`${tag}: ${r.plan.records} events in ${r.plan.steps} steps; planned ${r.plan.duration} s, replay clock at the end ${end.toFixed(2)} s,`
      + ` ${shown.length} frames, most in a frame ${Math.max(...shown)}, wall ${r.wall.toFixed(2)} s`);
    assert.equal(r.plan.duration, 15, `${tag}: Normal plans the whole run in 15 s`);
    assert.ok(end >= 10 && end <= 20, `${tag}: the replay's end came at ${end} s of replay clock`);
  }
  assert.ok(small.plan.records >= 30 && small.plan.records <= 200, `small: ${small.plan.records} events`);
  assert.ok(large.plan.records >= 50000, `large: ${large.plan.records} events`);
  // few events are spread: most frames show nothing, none shows more than a few
  const s = perFrame(small.frames);
  assert.ok(s.filter((n) => n === 0).length > s.filter((n) => n > 0).length, `small: ${s.filter((n) => n > 0).length} of ${s.length} frames showed events`);
  assert.ok(Math.max(...s) <= 5, `small: at most ${Math.max(...s)} events in a frame`);
  // many are bunched: the typical frame shows tens
  const l = perFrame(large.frames).filter((n) => n > 0).sort((a, b) => a - b);
  assert.ok(l[Math.floor(l.length / 2)] >= 10, `large: median ${l[Math.floor(l.length / 2)]} events a frame`);
});

test('Slow, Fast and Instant plan 40 s, 5 s and all at once', async () => {
  const plan = async (id) => {
    await page.click(`#${id}`);
    assert.equal(await page.getAttribute(`#${id}`, 'aria-checked'), 'true');
    return page.textContent('#speed-out');
  };
  assert.equal(await plan('speed-slow'), 'whole run in 40 s');
  assert.equal(await plan('speed-fast'), 'whole run in 5 s');
  assert.equal(await plan('speed-instant'), 'all at once');
  assert.equal(await page.getAttribute('#speed-fast', 'aria-checked'), 'false');
});

test('the potential field\'s heat map is one step: the next press shows its first decision', async () => {
  await pickScenario('apf-minimum', 'Potential field: a local minimum');
  await page.selectOption('#planner', 'potential-field');
  await waitState('idle');
  const press = async () => {
    const before = (await page.evaluate(() => window.planarium.pace())).records;
    await page.click('#step-event');
    await page.waitForFunction((n) => window.planarium.pace().records > n && window.planarium.state() === 'paused', before, { timeout: 20000 });
    // a set-up step may still be arriving (asked of the planner an iteration at a time)
    await fx.nextFrames();
    return page.evaluate(() => ({ pace: window.planarium.pace(), last: window.planarium.lastEvent(), cells: window.planarium.cells() }));
  };
  const first = await press();
  console.log(`first press: ${first.pace.records} records, ${first.pace.steps} step(s), last kind ${first.last[0]}`);
  assert.equal(first.pace.steps, 1, 'the first press is one step');
  assert.ok(first.pace.records > 1000, `the whole heat map at once (${first.pace.records} records)`);
  assert.equal(first.last[0], K.FIELD, 'it ends on the heat map');
  const second = await press();
  assert.equal(second.pace.steps, 2);
  assert.equal(second.pace.records, first.pace.records + 1, 'the second press shows one event');
  assert.notEqual(second.last[0], K.FIELD, 'the planner\'s first decision');
});

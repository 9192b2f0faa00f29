// The solved path of report 001's Puma 560 under the 3-D view (www/ui/path3d.js, headless
// chromium, as a person clicks and types): the panel is there only for a 3-D scene with a path;
// the scrubber, moved with the keyboard and dragged, holds the arm where the core's forward
// kinematics (computed here in Node for the page's pose) puts the tool, and moves the timeline's
// cursor; hovering the timeline poses the arm and moves the scrubber; the timeline's curves start
// at the start's joint angles and end at the goal's (read from the page's data and its legend,
// and found in its pixels); ghosts appear when a spacing is set and vanish at 0; the spacing field
// refuses what is not a bounded number, saying so; "robot follows the raw path" switches to the
// raw path (its length, its tool curve in the raw path's colour). Screenshots go to /tmp/path3d-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { JOINT_COLOURS } from '../../www/draw/timeline.js';
import { puma, core, PUMA_NAME, rgbOf, shadeOf } from './puma-view.mjs';


const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitStatus, pickScenario } = fx;

const path = () => page.evaluate(() => window.planarium.view3d.path());
const toolAt = (q) => {
  const sk = core.skeleton(new Float64Array(q));
  return [...sk.slice(sk.length - 3)];
};
/** The wrist: the origin of the arm's fifth link frame (the skeleton's points: each frame's origin, then the tool). */
const wristAt = (q) => [...core.skeleton(new Float64Array(q)).slice(15, 18)];

/** Of the 3-D view's pixels within `r` css px of world point `p`: how many are a shade of the arm's colour, and where p is. */
async function armPixelsNear(p, r = 20) {
  await fx.nextFrames();
  const got = await page.evaluate(({ p, r }) => {
    const v = window.planarium.view3d;
    const at = v.toCanvas(p);
    return at ? { at, px: v.pixels(at[0], at[1], r) } : null;
  }, { p, r });
  assert.ok(got, 'in front of the camera');
  let arm = 0;
  for (let i = 0; i < got.px.length; i += 4) if (shadeOf([got.px[i], got.px[i + 1], got.px[i + 2]], PALETTE.robotT)) arm++;
  return { arm, at: got.at };
}

/** Keep a copy of the 3-D view's pixels (`snap`) or count the pixels that differ from it (`diff`). */
const pixelsVsSnapshot = (mode) => page.evaluate((mode) => {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('view3d'));
  const t = document.createElement('canvas');
  t.width = c.width; t.height = c.height;
  const ctx = t.getContext('2d');
  ctx.drawImage(c, 0, 0);
  const px = ctx.getImageData(0, 0, t.width, t.height).data;
  if (mode === 'snap') { window.__snap = px; return px.length; }
  let n = 0;
  for (let i = 0; i < px.length; i += 4) {
    if (Math.abs(px[i] - window.__snap[i]) + Math.abs(px[i + 1] - window.__snap[i + 1]) + Math.abs(px[i + 2] - window.__snap[i + 2]) > 6) n++;
  }
  return n;
}, mode);

/**
 * The panel's length is the core's `cost` (the number the results show), its text says it, and the
 * core's lengths at the frames and waypoints agree with the frames' joint-space distances (summed
 * here, independently of the page) and with the path's `waypoints`.
 */
function assertCoreLengths(st, cost, waypoints) {
  assert.equal(st.length, cost, 'the length shown is the core\'s cost, as the stats give it');
  assert.match(st.where, new RegExp(` of ${cost.toFixed(3).replace('.', '\\.')} rad`), 'the scrubber\'s text shows the core\'s cost');
  const dims = st.first.length;
  let sum = 0;
  for (let k = 1; k < st.frames; k++) {
    let d2 = 0;
    for (let j = 0; j < dims; j++) d2 += (st.states[k * dims + j] - st.states[(k - 1) * dims + j]) ** 2;
    sum += Math.sqrt(d2);
    assert.ok(Math.abs(st.at[k] - sum) <= 1e-9 * cost, `frame ${k}: the core's length ${st.at[k]} vs the distances' sum ${sum}`);
  }
  assert.ok(Math.abs(st.at[st.frames - 1] - cost) <= 1e-12 * cost, 'the last frame is at the cost');
  assert.equal(st.waypoints.length, waypoints, 'a length for each waypoint');
  assert.equal(st.waypoints[0], 0);
  assert.equal(st.waypoints[waypoints - 1], st.at[st.frames - 1], 'the last waypoint is at the cost');
}

/** Type into the ghost spacing field and commit (Enter), as a person does. */
async function typeSpacing(text) {
  await page.$eval('#path3d-spacing', (el, v) => {
    el.value = v;
    el.dispatchEvent(new Event('change', { bubbles: true }));
  }, text);
  await fx.nextFrames();
}

/** The timeline's pixels (css px box around (x, y), radius r) as [[r, g, b], …]. */
const timelinePixels = (x, y, r) => page.evaluate(({ x, y, r }) => {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('path3d-timeline'));
  const dpr = c.width / c.clientWidth;
  const d = c.getContext('2d').getImageData(Math.round((x - r) * dpr), Math.round((y - r) * dpr), Math.round(2 * r * dpr) + 1, Math.round(2 * r * dpr) + 1).data;
  const out = [];
  for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 200) out.push([d[i], d[i + 1], d[i + 2]]);
  return out;
}, { x, y, r });
const near = (px, hex, tol = 40) => { const c = rgbOf(hex); return px.some((p) => p.every((v, i) => Math.abs(v - c[i]) <= tol)); };

test('puma-rbo-wall solved: scrubber, timeline and ghosts, linked; the raw path when chosen', async () => {
  // A 2-D scenario solved: no path panel.
  await page.click('#speed-instant');
  await page.click('#run');
  await waitStatus('solved', 60000);
  await fx.nextFrames();
  assert.equal(await page.isHidden('#path3d'), true, 'no 3-D path panel for a 2-D scenario');

  await pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await page.waitForFunction(() => window.planarium.view3d.pose().status.startsWith('Free'), null, { timeout: 20000 });
  assert.equal(await page.isHidden('#path3d'), true, 'no path panel before there is a path');
  await page.click('#speed-instant');
  await page.click('#run');
  await waitStatus('solved', 240000);
  await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
  await page.waitForFunction(() => window.planarium.view3d.path().path, null, { timeout: 20000 });
  assert.equal(await page.isVisible('#path3d'), true, 'the path panel once solved');
  const result = await page.evaluate(() => window.planarium.result());
  let st = await path();
  console.log(`path: ${st.length.toFixed(4)} rad over ${st.frames} frames, ${st.waypoints.length} waypoints; the core's smoothed cost ${result.stats.smoothed_cost}, raw cost ${result.stats.cost}`);

  // The timeline's curves start at the start's joint angles and end at the goal's: the data, the legend, the pixels.
  assert.deepEqual(st.first, puma.start, 'the curves start at the start');
  assert.deepEqual(st.last, puma.goal, 'the curves end at the goal');
  // The length shown is the core's (smoothed) cost, and the lengths along the path are the core's
  // too: checked here against the frames' own joint-space distances, summed by the test.
  assertCoreLengths(st, result.stats.smoothed_cost, result.smoothed.length);
  for (let j = 0; j < 6; j++) {
    const li = page.locator(`#path3d-j${j + 1}`);
    assert.equal(Number(await li.getAttribute('data-start')), puma.start[j], `joint ${j + 1}'s curve starts at the start`);
    assert.equal(Number(await li.getAttribute('data-end')), puma.goal[j], `joint ${j + 1}'s curve ends at the goal`);
    const deg = (r) => `${Number(((r * 180) / Math.PI).toFixed(1))}°`;
    assert.ok((await li.textContent()).includes(`start ${deg(puma.start[j])} · goal ${deg(puma.goal[j])}`), `joint ${j + 1}'s legend says its start and goal`);
  }
  let tlBox = await page.locator('#path3d-timeline').boundingBox();
  for (let j = 0; j < 6; j++) {
    for (const [s, q, end] of [[0, puma.start, 'start'], [st.length, puma.goal, 'goal']]) {
      const at = await page.evaluate(({ s, r }) => window.planarium.view3d.timelineAt(s, r), { s, r: q[j] });
      // a joint drawn later with (nearly) the same angle there covers it: any of those colours will do
      const covering = [j, ...[0, 1, 2, 3, 4, 5].filter((k) => k > j && Math.abs(q[k] - q[j]) * 180 / Math.PI * (at.box.y1 - at.box.y0) / 400 < 3)];
      const px = await timelinePixels(at.x + (end === 'start' ? 2 : -2), at.y, 2);
      assert.ok(covering.some((k) => near(px, JOINT_COLOURS[k])), `joint ${j + 1}'s curve drawn at its ${end} angle (${(q[j] * 180 / Math.PI).toFixed(1)}°)`);
    }
  }

  // Up is more: in the plot's first column, read from the pixels alone, the joint that starts highest
  // (joint 3, 90°) is drawn above the others (0°).
  const box = (await page.evaluate(() => window.planarium.view3d.timelineAt(0, 0))).box;
  const rows = await page.evaluate(({ x, y0, y1 }) => {
    const c = /** @type {HTMLCanvasElement} */ (document.getElementById('path3d-timeline'));
    const dpr = c.width / c.clientWidth;
    const d = c.getContext('2d').getImageData(Math.round(x * dpr), Math.round(y0 * dpr), 1, Math.round((y1 - y0) * dpr)).data;
    const out = [];
    for (let i = 0; i < d.length; i += 4) out.push([d[i], d[i + 1], d[i + 2], d[i + 3]]);
    return out;
  }, { x: box.x0 + 3, y0: box.y0, y1: box.y1 });
  const top = puma.start.indexOf(Math.max(...puma.start));
  const rowOf = (ks) => rows.findIndex(([r, g, b, a]) => a > 200 && ks.some((k) => near([[r, g, b]], JOINT_COLOURS[k], 30)));
  const others = [0, 1, 2, 3, 4, 5].filter((k) => k !== top);
  console.log(`first column: joint ${top + 1}'s curve at row ${rowOf([top])}, the others' from row ${rowOf(others)}`);
  assert.ok(rowOf([top]) >= 0 && rowOf(others) > rowOf([top]), `joint ${top + 1} (the highest start angle) drawn above the others`);

  // No ghosts for the pixel checks of the pose.
  await typeSpacing('0');
  assert.equal((await path()).ghosts, 0);

  // The scrubber with the keyboard: End, Home, arrows (a thousandth of the path a press).
  await page.focus('#path3d-scrub');
  await page.keyboard.press('End');
  st = await path();
  assert.equal(st.s, st.length, 'End: at the goal');
  assert.ok(st.holding, 'the arm is held');
  assert.deepEqual(st.q, puma.goal);
  assert.match(await page.locator('#path3d-where').textContent(), new RegExp(`^${st.length.toFixed(3)} of ${st.length.toFixed(3)} rad, at waypoint ${st.waypoints.length} of ${st.waypoints.length}$`));
  await page.keyboard.press('Home');
  for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowRight');
  st = await path();
  assert.ok(Math.abs(st.s - 0.003 * st.length) < 1e-12, 'three presses: three thousandths of the path');
  assert.match(await page.locator('#path3d-scrub').getAttribute('aria-valuetext'), /rad, between waypoints 1 and 2 of/);

  // Dragged along: the arm's tool where the core's kinematics puts it, and away from where it was.
  const poses = [];
  for (const v of ['300', '650']) {
    await page.locator('#path3d-scrub').fill(v);
    st = await path();
    assert.ok(Math.abs(st.s - (Number(v) / 1000) * st.length) < 1e-12);
    const tcp = toolAt(st.q);
    const on = await armPixelsNear(tcp);
    // the tool's bar is thin and the path's curve is drawn over it: where it threads the window, the
    // wall and the curve may cover it, so the wrist (the fifth frame's origin) is checked as well
    const wrist = await armPixelsNear(wristAt(st.q));
    poses.push({ q: st.q, tcp, at: on.at });
    console.log(`scrubbed to ${v}/1000: s = ${st.s.toFixed(3)} rad, tool ${tcp.map((x) => x.toFixed(3))} at css px ${on.at.map((x) => x.toFixed(0))}: ${on.arm} arm pixels round it, ${wrist.arm} round the wrist`);
    assert.ok(Math.max(on.arm, wrist.arm) >= 30, 'the arm is drawn where the core puts the tool and the wrist');
    // the tool is on the path's curve, drawn over it thick (a 1 px line would colour about 7 of these 49 pixels)
    const curve = await page.evaluate(({ x, y }) => window.planarium.view3d.pixels(x, y, 3), { x: on.at[0], y: on.at[1] });
    let thick = 0;
    for (let i = 0; i < curve.length; i += 4) if ([PALETTE.smoothPath, PALETTE.pathCasing].some((h) => rgbOf(h).every((c, k) => Math.abs(curve[i + k] - c) <= 8))) thick++;
    assert.ok(thick >= 14, `the tool's curve drawn thick over the arm (${thick} of 49 pixels round the tool)`);
  }
  const moved = Math.hypot(poses[1].at[0] - poses[0].at[0], poses[1].at[1] - poses[0].at[1]);
  assert.ok(moved > 40, `the tool moved on screen (${moved.toFixed(0)} px)`);
  const left = await armPixelsNear(poses[0].tcp, 6);
  assert.ok(left.arm <= 5, `nothing of the arm's tool left where it was (${left.arm})`);
  await page.screenshot({ path: '/tmp/path3d-scrubbed-1280.png' });

  // The scrubber moves the timeline's cursor (a dark vertical line at the length).
  const cursorAt = async (s) => {
    const at = await page.evaluate((s) => window.planarium.view3d.timelineAt(s, 0), s);
    const col = await page.evaluate(({ x, y0, y1 }) => {
      const c = /** @type {HTMLCanvasElement} */ (document.getElementById('path3d-timeline'));
      const dpr = c.width / c.clientWidth;
      const d = c.getContext('2d').getImageData(Math.round(x * dpr) - 1, Math.round(y0 * dpr), 3, Math.round((y1 - y0) * dpr)).data;
      let dark = 0;
      for (let i = 0; i < d.length; i += 12) {
        if ([0, 4, 8].some((o) => d[i + o + 3] > 200 && d[i + o] < 60 && d[i + o + 1] < 60 && d[i + o + 2] < 60)) dark++;
      }
      return { dark, rows: d.length / 12 };
    }, { x: at.x, y0: at.box.y0 + 2, y1: at.box.y1 - 2 });
    return col.dark / col.rows;
  };
  assert.ok(await cursorAt(0.65 * st.length) > 0.8, 'the cursor at the scrubbed length');
  assert.ok(await cursorAt(0.3 * st.length) < 0.2, 'and not where the scrubber was before');

  // Hovering the timeline poses the arm there and moves the scrubber (scrolled to, as a person would).
  await page.locator('#path3d-timeline').scrollIntoViewIfNeeded();
  tlBox = await page.locator('#path3d-timeline').boundingBox();
  const target = 0.42 * st.length;
  const at = await page.evaluate((s) => window.planarium.view3d.timelineAt(s, 0), target);
  await page.mouse.move(tlBox.x + at.x, tlBox.y + (at.box.y0 + at.box.y1) / 2);
  st = await path();
  const perPx = st.length / (at.box.x1 - at.box.x0);
  assert.ok(Math.abs(st.s - target) <= perPx, `hover: the arm at the length under the pointer (${st.s.toFixed(4)} vs ${target.toFixed(4)})`);
  assert.equal(Number(await page.locator('#path3d-scrub').inputValue()), Math.round((st.s / st.length) * 1000), 'the scrubber follows');
  const hovered = await armPixelsNear(toolAt(st.q));
  const hoveredWrist = await armPixelsNear(wristAt(st.q));
  console.log(`hovered at ${st.s.toFixed(3)} rad: ${hovered.arm} arm pixels round the tool, ${hoveredWrist.arm} round the wrist`);
  assert.ok(Math.max(hovered.arm, hoveredWrist.arm) >= 30, 'the arm drawn where the core puts the tool at the hovered pose');
  assert.ok(await cursorAt(st.s) > 0.8, 'the cursor under the pointer');
  // dragging along it too
  await fx.drag([tlBox.x + at.x, tlBox.y + at.box.y1 - 10], [tlBox.x + at.x + 80, tlBox.y + at.box.y1 - 10]);
  const dragged = await path();
  assert.ok(Math.abs(dragged.s - (target + 80 * perPx)) <= 2 * perPx, `a drag on the timeline moves the arm along (${dragged.s.toFixed(4)} vs ${(target + 80 * perPx).toFixed(4)}, ${perPx.toFixed(4)} a px)`);
  assert.ok(Math.max((await armPixelsNear(toolAt(dragged.q))).arm, (await armPixelsNear(wristAt(dragged.q))).arm) >= 30);

  // Ghosts: drawn when a spacing is set, gone at 0.
  await page.mouse.move(0, 0);
  await fx.nextFrames();
  await pixelsVsSnapshot('snap');
  await typeSpacing('0.5');
  st = await path();
  assert.equal(st.ghosts, Math.ceil(st.length / 0.5) - 1, 'a ghost every 0.5 rad after the start, before the goal');
  await fx.nextFrames();
  const withGhosts = await pixelsVsSnapshot('diff');
  console.log(`ghosts every 0.5 rad: ${st.ghosts} ghosts, ${withGhosts} pixels changed`);
  assert.ok(withGhosts > 2000, 'the ghosts are drawn');
  await page.screenshot({ path: '/tmp/path3d-ghosts-1280.png' });
  await typeSpacing('0');
  await fx.nextFrames();
  assert.equal((await path()).ghosts, 0);
  assert.equal(await pixelsVsSnapshot('diff'), 0, 'spacing 0: the ghosts are gone, the picture as before');

  // The spacing field refuses what is not a bounded number, and says so.
  await typeSpacing('0.5');
  for (const [text, why] of [['abc', /type a number/], ['NaN', /type a number|not a number/], ['-1', /-1 is below 0/], ['1e9', /1e9 is above 10/], ['0.001', /0\.001 is below 0\.05/]]) {
    await typeSpacing(text);
    const s = await path();
    assert.match(s.note, /^Ghost spacing: /, `"${text}" refused`);
    assert.match(s.note, why);
    assert.equal(s.spacing, 0.5, `"${text}": the spacing unchanged`);
    assert.equal(await page.locator('#path3d-spacing').getAttribute('aria-invalid'), 'true');
  }
  await typeSpacing('0');
  assert.equal(await page.locator('#path3d-spacing').getAttribute('aria-invalid'), null);

  // The frame time while orbiting, with ghosts and without (logged, never asserted).
  const frameTimes = async () => {
    const t = (await page.evaluate(() => window.planarium.view3d.orbitFrameTimes(30))).sort((a, b) => a - b);
    return `median ${t[t.length >> 1].toFixed(1)} ms, max ${t[t.length - 1].toFixed(1)} ms`;
  };
  console.log(`orbiting without ghosts: requestAnimationFrame delta ${await frameTimes()}`);
  await typeSpacing('0.1');
  console.log(`orbiting with ${(await path()).ghosts} ghosts: requestAnimationFrame delta ${await frameTimes()}`);
  await typeSpacing('0');

  // Play: the animation again; the scrubber follows it.
  await page.click('#path3d-play');
  const v0 = await page.locator('#path3d-scrub').inputValue();
  await page.waitForFunction((v) => document.getElementById('path3d-scrub').value !== v, v0, { timeout: 10000 });
  assert.equal((await path()).holding, false);

  // While it plays, the faded trees come from the backdrop's layer, drawn once for the resting
  // camera (not once a frame), and the layer looks like the trees drawn directly.
  const painted = await page.evaluate(() => window.planarium.view3d.backdropPainted());
  const playFrames = await page.evaluate(() => new Promise((resolve) => {
    let n = 0;
    const f = () => (++n >= 20 ? resolve(n) : requestAnimationFrame(f));
    requestAnimationFrame(f);
  }));
  const paintedAfter = await page.evaluate(() => window.planarium.view3d.backdropPainted());
  const scrubbed = await page.locator('#path3d-scrub').inputValue();
  assert.notEqual(scrubbed, v0, 'the arm moved meanwhile');
  assert.ok(paintedAfter - painted <= 1, `the faded trees' layer drawn ${paintedAfter - painted} times in ${playFrames} frames of playback`);
  // (both multisampled and rounded to 8 bits a blend, in different orders: a pixel where many
  // lines cross differs by some 20 in R+G+B; a layer misplaced, stale or blended wrongly by far more)
  const agree = await page.evaluate(() => window.planarium.view3d.backdropAgreement(12));
  console.log(`the faded trees' layer against drawing them: ${JSON.stringify(agree)} (pixels differing by more than 12 in R+G+B, pixels the trees change, the largest difference, the sums of what the trees change)`);
  assert.ok(agree.trees > 20000, `the faded trees change ${agree.trees} pixels`);
  assert.ok(agree.most <= 30, `a pixel differs by ${agree.most} in R+G+B`);
  assert.ok(Math.abs(agree.inkLayer - agree.inkDirect) <= 0.1 * agree.inkDirect, `the trees change the picture by ${agree.inkLayer} from the layer, ${agree.inkDirect} drawn directly`);

  // The raw path: its length (the raw cost), the same ends, its tool curve in the raw path's colour.
  const [smoothPx] = await page.evaluate((c) => window.planarium.view3d.countColours(c, 8), [PALETTE.smoothPath]);
  await page.click('#anim-raw');
  await page.waitForFunction(() => window.planarium.view3d.path().raw === true, null, { timeout: 20000 });
  await fx.nextFrames();
  st = await path();
  console.log(`raw path: ${st.length.toFixed(4)} rad, ${st.frames} frames, ${st.waypoints.length} waypoints`);
  assert.equal(st.raw, true);
  assertCoreLengths(st, result.stats.cost, result.path.length);
  assert.deepEqual(st.first, puma.start);
  assert.deepEqual(st.last, puma.goal);
  const [rawPx, smoothAfter] = await page.evaluate((c) => window.planarium.view3d.countColours(c, 8), [PALETTE.rawPath, PALETTE.smoothPath]);
  console.log(`path colour pixels: smoothed ${smoothPx} before; raw ${rawPx}, smoothed ${smoothAfter} after`);
  assert.ok(smoothPx > 50 && rawPx > 50 && smoothAfter < smoothPx / 4, 'the raw tool curve drawn in the raw path\'s colour');
  await page.screenshot({ path: '/tmp/path3d-raw-1280.png' });
  await page.click('#path3d-play'); // held: the panel's text stays put for the screenshot
  await page.setViewportSize({ width: 390, height: 844 });
  await page.locator('#path3d').scrollIntoViewIfNeeded();
  await fx.nextFrames();
  await page.screenshot({ path: '/tmp/path3d-panel-390.png' });
});

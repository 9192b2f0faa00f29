// Linked views in the page (headless chromium, 1280×800; draw/linked.js): hovering the 2-joint
// arm's configuration space draws that pose as a ghost arm in the workspace (purple when free, red
// when it collides, labelled with its angles), hovering a pose's end effector in the workspace
// puts a crosshair on it in the c-space; the heat map's scale; the cell tooltip's plain first
// line. Screenshots go to target/page-linked-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { GHOST, formatAngles } from '../../www/draw/linked.js';
import { cellSentence } from '../../www/draw/cells.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, waitStatus, pickScenario, nextFrames, fastPlayback } = fx;

const ARM = { base: [0, 0], links: [0.5, 0.4] }; // scenarios/arm-2.json
const TAU = 2 * Math.PI;

/** Base, elbow and end effector of the arm-2 arm at (q1, q2) (joint angles relative, as the core). */
function joints([q1, q2]) {
  const [bx, by] = ARM.base;
  const ex = bx + ARM.links[0] * Math.cos(q1), ey = by + ARM.links[0] * Math.sin(q1);
  return [[bx, by], [ex, ey], [ex + ARM.links[1] * Math.cos(q1 + q2), ey + ARM.links[1] * Math.sin(q1 + q2)]];
}

/**
 * The page point of (q1, q2) on the c-space canvas: the square starts 40 css px from the left and
 * 10 from the top, and is the canvas's width less 52 px (cspace.js MARGIN); both joints span [−π, π].
 */
async function cspacePage([q1, q2]) {
  const box = await page.locator('#cspace').boundingBox();
  const side = box.width - 52;
  assert.ok(Math.abs(box.height - 46 - side) < 1.5, `the c-space plot is square: ${box.width}×${box.height}`);
  return [box.x + 40 + ((q1 + Math.PI) / TAU) * side, box.y + 10 + side - ((q2 + Math.PI) / TAU) * side];
}

/** RGB of canvas `id` at css px (x, y) of the page. */
async function pixelAt(id, [px, py]) {
  const box = await page.locator(`#${id}`).boundingBox();
  return page.evaluate(({ id, x, y }) => {
    const c = document.getElementById(id);
    const k = c.width / c.getBoundingClientRect().width;
    return [...c.getContext('2d').getImageData(Math.round(x * k), Math.round(y * k), 1, 1).data.slice(0, 3)];
  }, { id, x: px - box.x, y: py - box.y });
}

const rgb = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16));
const near = (a, b, tol = 12) => a.every((v, i) => Math.abs(v - b[i]) <= tol);

/** How many of the points along both links (a quarter to three quarters of each) are `colour`. */
async function linkPixels(q, colour) {
  const [b, e, t] = joints(q);
  let hits = 0, total = 0;
  for (const [p0, p1] of [[b, e], [e, t]]) {
    for (const f of [0.25, 0.375, 0.5, 0.625, 0.75]) {
      const at = await fx.toPage(p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1]));
      total++;
      if (near(await pixelAt('canvas', at), rgb(colour))) hits++;
    }
  }
  return { hits, total };
}

/** How many pixels of the c-space canvas within `r` css px of (q1, q2) are the crosshair's colour. */
async function crosshairPixels(q, r = 12) {
  const [px, py] = await cspacePage(q);
  const box = await page.locator('#cspace').boundingBox();
  return page.evaluate(({ x, y, r, col }) => {
    const c = document.getElementById('cspace');
    const k = c.width / c.getBoundingClientRect().width;
    const s = Math.round(2 * r * k);
    const d = c.getContext('2d').getImageData(Math.round((x - r) * k), Math.round((y - r) * k), s, s).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - col[0]) <= 10 && Math.abs(d[i + 1] - col[1]) <= 10 && Math.abs(d[i + 2] - col[2]) <= 10) n++;
    return n;
  }, { x: px - box.x, y: py - box.y, r, col: rgb(GHOST.cross) });
}

test('the plain sentence of each cell state and label', () => {
  assert.equal(cellSentence({ state: 1, why: 1, label: 0, level: 2 }),
    "Blocked: an obstacle vertex lies within t/2 of this cell's centre, where the robot would stand.");
  assert.match(cellSentence({ state: 1, why: 3, label: 0, level: 2 }), /^Blocked: an obstacle edge crosses/);
  assert.match(cellSentence({ state: 1, why: 4, label: 0, level: 2 }), /^Blocked: the map's edge/);
  assert.equal(cellSentence({ state: 2, why: 0, label: 0, level: 3 }), 'Visited: the search stepped into this cell (level 3).');
  assert.match(cellSentence({ state: 3, label: 0, level: 1 }), /^Outside the region of influence/);
  assert.equal(cellSentence({ state: -1, label: 0, level: 2 }), 'Free cell at level 2: no obstacle touches it.');
  assert.match(cellSentence({ state: -1, label: 1, level: 1 }, true), /^Mixed cell: partly inside an obstacle .*so it was split\.$/);
  assert.match(cellSentence({ state: -1, label: 1, level: 3 }, false), /^Mixed cell: .*too small to split/);
  assert.equal(cellSentence({ state: -1, label: 2, level: 0 }), 'Full cell: it lies wholly inside an obstacle.');
  assert.equal(formatAngles([0.5236, -1.2]), 'q1 0.52 (30°), q2 −1.20 (−69°)');
});

test('arm-2: hovering the c-space draws the arm in that pose in the workspace, red where it collides', async () => {
  await pickScenario('arm-2', 'Two-link arm and its configuration space');
  await nextFrames();
  // a free pose (down and to the left, clear of the polygon) and one through the rectangle
  const free = [-2.5, 0.3], hit = [0.8, 0];
  assert.deepEqual(await linkPixels(free, GHOST.free), { hits: 0, total: 10 }, 'no ghost before hovering');

  await page.mouse.move(...await cspacePage(free));
  await page.waitForSelector('#ghost-label:not([hidden])');
  await nextFrames();
  const label = await page.textContent('#ghost-label');
  console.log(`ghost label (free pose): ${label}`);
  assert.match(label, /^q1 −2\.50 \(−143°\), q2 0\.30 \(17°\): free$/);
  const f = await linkPixels(free, GHOST.free);
  assert.ok(f.hits >= 9, `free ghost pixels along the links: ${f.hits} of ${f.total}`);
  // Looked at: the purple ghost arm (white casing) reaching down-left from the base, the label
  // "q1 −2.50 (−143°), q2 0.30 (17°): free" by its end effector, the start and goal arms faint.
  await page.screenshot({ path: join(SHOTS, 'page-linked-ghost-free.png') });

  await page.mouse.move(...await cspacePage(hit));
  await page.waitForFunction(() => /collides$/.test(document.getElementById('ghost-label').textContent));
  await nextFrames();
  const h = await linkPixels(hit, GHOST.collides);
  console.log(`ghost label (colliding pose): ${await page.textContent('#ghost-label')}; red pixels ${h.hits} of ${h.total}`);
  assert.ok(h.hits >= 9, `colliding ghost pixels along the links: ${h.hits} of ${h.total}`);
  assert.equal((await linkPixels(free, GHOST.free)).hits, 0, 'the earlier ghost is gone');
  // Looked at: the red ghost through the brown rectangle, its label "…: collides".
  await page.screenshot({ path: join(SHOTS, 'page-linked-ghost-collides.png') });

  await page.mouse.move(5, 5); // off both canvases
  await page.waitForSelector('#ghost-label', { state: 'hidden' });
  await nextFrames();
  assert.equal((await linkPixels(hit, GHOST.collides)).hits, 0, 'the ghost goes when the pointer leaves');
});

test('arm-2: hovering a path pose in the workspace marks it in the c-space with a crosshair', async () => {
  await pickScenario('arm-2', 'Two-link arm and its configuration space');
  await fastPlayback();
  await page.click('#run');
  await waitStatus('solved');
  await waitState('finished');
  await nextFrames();
  const result = await page.evaluate(() => window.planarium.result());
  const path = result.smoothed;
  assert.ok(path.length >= 3, `smoothed path poses: ${path.length}`);
  const q = path[Math.floor(path.length / 2)];
  assert.equal(await crosshairPixels(q), 0, 'no crosshair before hovering');
  const tip = joints(q)[2];
  const pointer = await fx.toPage(tip[0] + 0.004, tip[1] - 0.004); // a pixel or two off the end effector
  await page.mouse.move(...pointer);
  await page.waitForSelector('#ghost-label:not([hidden])');
  await nextFrames();
  const label = await page.textContent('#ghost-label');
  console.log(`hover at the end effector of path pose ${Math.floor(path.length / 2) + 1}: ${label}`);
  const m = /^(.+): q1 ([−\d.]+) \([^)]*\), q2 ([−\d.]+) /.exec(label);
  assert.ok(m, `label: ${label}`);
  const shown = [Number(m[2].replace('−', '-')), Number(m[3].replace('−', '-'))];
  // the pose named is the nearest within a few pixels: its end effector is under the pointer
  const [sx, sy] = await fx.toPage(...joints(shown)[2]);
  assert.ok(Math.hypot(sx - pointer[0], sy - pointer[1]) <= 9, `its end effector is ${Math.hypot(sx - pointer[0], sy - pointer[1]).toFixed(1)} px away`);
  const cross = await crosshairPixels(shown);
  console.log(`crosshair pixels at (${shown}): ${cross}`);
  assert.ok(cross > 40, `crosshair pixels: ${cross}`);
  // and the pose is drawn as a ghost in the workspace too
  assert.ok((await linkPixels(shown, GHOST.free)).hits >= 8, 'the hovered pose is drawn as a free ghost');
  // Looked at: the purple ghost over the animated path's pose, the purple crosshair with its ring in
  // the c-space on the smoothed path, the label beside it.
  await page.screenshot({ path: join(SHOTS, 'page-linked-crosshair.png') });

  await page.mouse.move(5, 5);
  await page.waitForSelector('#ghost-label', { state: 'hidden' });
  await nextFrames();
  assert.equal(await crosshairPixels(shown), 0, 'the crosshair goes when the pointer leaves');
});

/** Pick a built-in scenario, make sure `planner` is chosen, run it to the end at full speed. */
async function runToEnd(id, name, planner) {
  await pickScenario(id, name);
  if (await page.$eval('#planner', (s) => s.value) !== planner) {
    await page.selectOption('#planner', planner);
    await waitState('idle');
  }
  await fastPlayback();
  await page.click('#run');
  await waitState('finished', 60000);
  await nextFrames();
}

const number = (s) => Number(s.replace('−', '-').replace('∞', 'Infinity'));

test('hex-trap: the heat map has a scale with its lowest and highest value, and hides with it', async () => {
  await runToEnd('hex-trap', 'Hexagons: the dead-end trap', 'hex-potential');
  assert.equal(await page.isHidden('#heat-scale'), true, 'no scale while the heat map is off');
  await page.click('#show-heat');
  await page.waitForSelector('#heat-scale:not([hidden])');
  const [lo, mid, hi, name] = await Promise.all(['#heat-scale-min', '#heat-scale-median', '#heat-scale-max', '.heat-scale-name']
    .map((s) => page.textContent(s)));
  console.log(`scale: ${name}: ${lo} … ${mid} … ${hi}`);
  for (const v of [lo, mid, hi]) assert.ok(Number.isFinite(number(v)), `a number: ${v}`);
  assert.ok(number(lo) < number(hi) && number(lo) <= number(mid) && number(mid) <= number(hi), `${lo} ≤ ${mid} ≤ ${hi}`);
  assert.match(name, /potential/);
  const counts = await fx.countColours('heat-scale-bar', [...PALETTE.heat], 2);
  console.log(`bar pixels per heat colour: ${counts}`);
  assert.ok(counts.every((n) => n >= 100), `every heat colour in the bar: ${counts}`);
  // beside the (square) workspace when the stage has room for it, else over the canvas's top-right
  // corner; in the stage either way
  const [bar, canvas, stage] = await Promise.all(['#heat-scale', '#canvas', '#stage'].map((s) => page.locator(s).boundingBox()));
  console.log(`scale box ${JSON.stringify(bar)}, canvas ${JSON.stringify(canvas)}`);
  const room = stage.x + stage.width - (canvas.x + canvas.width) >= bar.width + 8;
  if (room) assert.ok(bar.x >= canvas.x + canvas.width, 'beside the canvas, where there is room');
  else assert.ok(Math.abs(bar.x + bar.width + 8 - (canvas.x + canvas.width)) <= 2 && bar.y >= canvas.y, 'over the canvas\'s top-right corner');
  assert.ok(bar.x >= stage.x && bar.x + bar.width <= stage.x + stage.width, 'in the stage');
  assert.ok(Math.abs(bar.y - canvas.y) <= (room ? 2 : 10), 'level with its top (a gap below it over the canvas)');
  // Looked at: the scale box right of the canvas, level with its top, light yellow to dark blue in
  // nine steps, its name and the three numbers under the bar; the heat map beside it.
  await page.screenshot({ path: join(SHOTS, 'page-linked-heat-scale.png') });
  await page.click('#show-heat');
  await page.waitForSelector('#heat-scale', { state: 'hidden' });
});

test('apf-minimum: the classic field\'s scale names U', async () => {
  await runToEnd('apf-minimum', 'Potential field: a local minimum', 'potential-field');
  // on from the start for a field planner
  await page.waitForSelector('#heat-scale:not([hidden])');
  assert.match(await page.textContent('.heat-scale-name'), /^potential U/);
  // by value: the top tick is the 90th percentile, "and up"
  const top = await page.textContent('#heat-scale-max');
  assert.match(top, /\+$/);
  const lo = number(await page.textContent('#heat-scale-min')), hi = number(top.slice(0, -1));
  assert.ok(Number.isFinite(lo) && Number.isFinite(hi) && lo < hi, `${lo} < ${hi}`);
  assert.match(await page.textContent('.heat-scale-note'), /by value/);
  await page.screenshot({ path: join(SHOTS, 'page-linked-heat-scale-apf.png') });
});

test('hovering a visited hex cell: the tooltip starts with a plain sentence', async () => {
  await runToEnd('hex-trap-modified', 'Hexagons: the trap, modified potential', 'hex-potential');
  await waitStatus('solved');
  const cells = await page.evaluate(() => window.planarium.cells());
  const cell = cells.visited[Math.floor(cells.visited.length / 2)];
  const [cx, cy] = await page.evaluate(([x, y]) => window.planarium.toCanvas(x, y), [cell.x, cell.y]);
  const box = await page.locator('#canvas').boundingBox();
  await page.mouse.move(box.x + cx + 2, box.y + cy + 2);
  await page.waitForSelector('#cell-tip:not([hidden])');
  const lines = (await page.textContent('#cell-tip')).split('\n');
  console.log(`tooltip:\n${lines.join('\n')}`);
  assert.equal(lines[0], `Visited: the search stepped into this cell (level ${cell.level}).`);
  assert.match(lines[1], new RegExp(`^cell ${cell.id} · level ${cell.level} · free$`));
  // Looked at: the box by the pointer, the sentence first, then the numbers.
  await page.screenshot({ path: join(SHOTS, 'page-linked-cell-tip.png') });
});

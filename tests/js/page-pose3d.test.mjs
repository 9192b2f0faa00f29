// Posing report 001's Puma 560 by hand under the 3-D view (www/ui/pose3d.js), in headless
// chromium: six labelled sliders within the joints' limits (the core's), shown only for a scene
// the core gives a 3-D view; the waist turned with the keyboard, a degree a key press, until the
// arm goes into the wall: the text then says what meets what (the core's `collision`, computed
// here in Node for the page's pose) and the arm's pixels round the projected tool point turn the
// collision colour; a key back and it says "Free". Set as start refuses a pose that collides;
// Set as goal on a free pose edits the scenario (its goal is the pose; the share link changes) and
// a run still solves. Screenshots at 1280×800 and 390×844 go to /tmp/pose3d-*.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { PALETTE } from '../../www/draw/palette.js';
import { puma, core, PUMA_NAME } from './puma-view.mjs';


const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitStatus, pickScenario } = fx;

const pose = () => page.evaluate(() => window.planarium.view3d.pose());
const rgbOf = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
/**
 * Which of `colours` pixel [r, g, b] is a shade of (k·colour, lit by the head light), allowing for
 * the translucent wall drawn over it: the nearest in chromaticity, or null when none is near.
 */
function shadeName([r, g, b], colours) {
  const s = r + g + b;
  if (s < 40) return null;
  let best = null;
  let bestD = 0.08;
  for (const [name, hex] of Object.entries(colours)) {
    const c = rgbOf(hex);
    const cs = c[0] + c[1] + c[2];
    const d = Math.hypot(r / s - c[0] / cs, g / s - c[1] / cs, b / s - c[2] / cs);
    if (d < bestD) { bestD = d; best = name; }
  }
  return best;
}

/** Of the 3-D view's pixels within 20 px (a 41 px square) of the tool centre point at pose `q`: how many are each colour's. */
async function toolPixels(q) {
  const skeleton = core.skeleton(new Float64Array(q));
  const tcp = [...skeleton.slice(skeleton.length - 3)];
  await fx.nextFrames();
  const px = await page.evaluate((p) => {
    const v = window.planarium.view3d;
    const at = v.toCanvas(p);
    return at ? v.pixels(at[0], at[1], 20) : null;
  }, tcp);
  assert.ok(px, 'the tool is in front of the camera');
  const counts = { posed: 0, posedCollides: 0, start: 0, other: 0 };
  const colours = { posed: PALETTE.posed, posedCollides: PALETTE.posedCollides, start: PALETTE.start };
  for (let i = 0; i < px.length; i += 4) counts[shadeName([px[i], px[i + 1], px[i + 2]], colours) ?? 'other']++;
  return counts;
}

async function openPuma() {
  await pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  await page.waitForFunction(() => window.planarium.view3d.pose().status.startsWith('Free'), null, { timeout: 20000 });
}

test('puma-rbo-wall: six sliders pose the arm; into the wall it says what meets what and turns red; Set as goal edits the scenario and a run solves', async () => {
  // a 2-D scenario has no pose panel
  assert.equal(await page.isHidden('#pose3d'), true, 'no pose panel for the first (2-D) scenario');
  await openPuma();
  assert.equal(await page.isVisible('#pose3d'), true);
  const sliders = page.locator('#pose3d input[type=range]');
  assert.equal(await sliders.count(), 6);
  for (let i = 0; i < 6; i++) {
    const s = page.locator(`#pose-q${i + 1}`);
    const [lo, hi] = puma.robot.joints[i].limits;
    assert.ok(Math.abs(Number(await s.getAttribute('min')) - lo) < 1e-12 && Math.abs(Number(await s.getAttribute('max')) - hi) < 1e-12, `joint ${i + 1} within its limits`);
    assert.equal(await page.getByRole('slider', { name: `Joint ${i + 1}`, exact: true }).getAttribute('id'), `pose-q${i + 1}`, 'named for screen readers');
  }
  assert.deepEqual((await pose()).q, puma.start, 'the sliders start at the start pose');
  assert.match(await page.locator('#pose-q3').getAttribute('aria-valuetext'), /^90° \(1\.571 rad\)$/, 'degrees and radians, read out too');
  const atStart = await toolPixels(puma.start);
  console.log(`at the start, pixels round the tool: ${JSON.stringify(atStart)}`);
  await page.screenshot({ path: '/tmp/pose3d-start-1280.png' });
  assert.ok(atStart.start >= 20, 'at the start the arm is drawn in the start colour');

  // The waist turned with the keyboard, a degree a press, until the arm meets something.
  await page.focus('#pose-q1');
  let presses = 0;
  let free = null;
  for (; presses < 200; presses++) {
    const s = await pose();
    if (s.collision) break;
    free = s.q;
    await page.keyboard.press('ArrowLeft');
  }
  const hit = await pose();
  console.log(`${presses} presses of ← on joint 1: ${hit.status} (q1 = ${(hit.q[0] * 180 / Math.PI).toFixed(1)}°)`);
  assert.ok(hit.collision, 'the arm went into the wall');
  assert.equal(hit.collision, core.collision(new Float64Array(hit.q)), 'the text is the core\'s for the page\'s pose');
  assert.match(hit.status, /meets/);
  assert.ok(hit.status.includes(hit.collision), 'the panel says what meets what');
  assert.equal(await page.locator('#pose3d label[for=pose-q1] output').textContent(), `${Math.round(hit.q[0] * 180 / Math.PI)}° (${hit.q[0].toFixed(3)} rad)`);
  const red = await toolPixels(hit.q);
  console.log(`in collision, pixels round the tool: ${JSON.stringify(red)}`);
  await page.screenshot({ path: '/tmp/pose3d-collides-1280.png' });
  assert.ok(red.posedCollides >= 20 && red.posed === 0, 'the arm is drawn in the collision colour');

  // Set as start refuses it; the scenario is not touched.
  await page.click('#pose-set-start');
  assert.match((await pose()).message, /^Not set as the start: this pose collides/);
  assert.deepEqual((await page.evaluate(() => window.planarium.scenario())).start, puma.start);

  // One press back: free again, and drawn in the posed colour.
  await page.focus('#pose-q1');
  await page.keyboard.press('ArrowRight');
  const back = await pose();
  assert.equal(back.collision, '');
  assert.match(back.status, /^Free/);
  assert.deepEqual(back.q, free, 'back at the last free pose');
  const blue = await toolPixels(back.q);
  console.log(`free again, pixels round the tool: ${JSON.stringify(blue)}`);
  assert.ok(blue.posed >= 20 && blue.posedCollides === 0, 'free: the posed colour, not the collision colour');

  // Set as goal: the scenario's goal is the pose, the share link changes, and a run solves.
  const linkBefore = await page.evaluate(() => window.planarium.shareLink());
  await page.click('#pose-set-goal');
  await page.waitForFunction((q) => JSON.stringify(window.planarium.scenario()?.goal) === JSON.stringify(q), back.q, { timeout: 20000 });
  await fx.waitState('idle');
  assert.match((await pose()).message, /goal is now this pose/);
  assert.deepEqual((await pose()).q, back.q, 'the sliders stay where they were');
  const linkAfter = await page.evaluate(() => window.planarium.shareLink());
  assert.notEqual(linkAfter, linkBefore, 'the share link carries the edited scenario');
  await page.click('#speed-instant');
  await page.click('#run');
  await waitStatus('solved', 240000);
  const result = await page.evaluate(() => window.planarium.result());
  const last = result.path[result.path.length - 1];
  assert.ok(last.every((v, i) => Math.abs(v - back.q[i]) < 1e-9), 'the path ends at the pose set as the goal');
  await page.waitForFunction(() => window.planarium.state() === 'finished', null, { timeout: 60000 });
  // once solved the arm moves along the path (drawn in the robot's grey), not held at the pose
  await fx.nextFrames();
  await fx.nextFrames();
  const moving = await toolPixels(back.q);
  console.log(`solved, pixels round the goal's tool point: ${JSON.stringify(moving)}`);
  await page.screenshot({ path: '/tmp/pose3d-solved-1280.png' });
  assert.equal(moving.posed, 0, 'the path\'s animation, not the posed arm');
  // a slider moved stops the animation: the posed arm again
  await page.focus('#pose-q1');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowLeft');
  const posedAgain = await toolPixels((await pose()).q);
  assert.ok(posedAgain.posed >= 20, 'posing again shows the posed arm');

  // A phone: the panel under the views.
  await page.setViewportSize({ width: 390, height: 844 });
  await page.click('#pose-from-start');
  assert.deepEqual((await pose()).q, puma.start);
  await page.locator('#pose3d').scrollIntoViewIfNeeded();
  await fx.nextFrames();
  await page.screenshot({ path: '/tmp/pose3d-panel-390.png' });
  await page.locator('#view3d').scrollIntoViewIfNeeded();
  await fx.nextFrames();
  await page.screenshot({ path: '/tmp/pose3d-view-390.png' });
});

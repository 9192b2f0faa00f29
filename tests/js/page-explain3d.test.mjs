// The explain panel for report 001's Puma 560 in the page (headless chromium, WebGL2 through
// SwiftShader): the scenario's set-up (RRT-Connect, last-free) shows the last-free pseudocode;
// stepped event by event until a collision, the caption gives the sample's joint angles and names
// what meets what (the core's words, the same the 3-D view's step reports), and the 3-D view draws
// the step: the collision mark at the contact point (pixels of its colour there, none when the
// step is hidden), and the ghost arms (the pixels at the ghosts' tool points change when the step
// is hidden). Screenshot at /tmp/explain3d-collision.png.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { pageFixture } from './browser.mjs';
import { pixelsNear as near3d, PUMA_NAME, rgbOf, core } from './puma-view.mjs';
import { ACTOR } from '../../www/ui/explain-panel.js';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const near = (px, hex, tol = 8) => rgbOf(hex).every((v, k) => Math.abs(px[k] - v) <= tol);


test('puma-rbo-wall: stepping to a collision, the caption names the parts and the 3-D view marks it', async () => {
  await fx.pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  const code = await page.locator('#explain-code').textContent();
  assert.ok(code.includes('only the last free q becomes q_new'), `the last-free lines: ${code}`);
  assert.ok(!code.includes('STEER('), 'not the range mode\'s');
  let model = null;
  let sampleCaption = '';
  for (let i = 1; i <= 600; i++) {
    await page.click('#step-event');
    await page.waitForFunction((n) => window.planarium.explain().events === n, i, { timeout: 30000 });
    const last = await page.evaluate(() => window.planarium.lastEvent());
    model = await page.evaluate(() => window.planarium.explain());
    if (last[0] === 0) {
      sampleCaption = model.caption;
      assert.match(model.caption, /^sample q = \((−?\d+°, ){5}−?\d+°\)/, model.caption);
      assert.equal(model.line, 'sample');
    }
    if (last[0] === 3) break;
    model = null;
  }
  assert.ok(model, 'a collision within 600 events');
  console.log(`caption at the collision: ${model.caption}`);
  assert.ok(['check', 'c-check'].includes(model.line), model.line);
  assert.ok(sampleCaption, 'a sample was captioned');
  await fx.nextFrames();
  await fx.nextFrames();
  const step = await page.evaluate(() => window.planarium.explain3d());
  assert.ok(step?.collision, 'the 3-D view has the step\'s collision');
  assert.match(step.collision.words, /meets/);
  assert.ok(model.caption.includes(`collides: ${step.collision.words}`), `the caption names "${step.collision.words}"`);
  assert.ok(step.collision.links.length >= 1 && step.collision.at.every(Number.isFinite), JSON.stringify(step.collision));
  await page.screenshot({ path: '/tmp/explain3d-collision.png' });

  // The contact mark, in the blocked colour, drawn over everything at the contact point.
  const mark = (await near3d(page, step.collision.at, 3))?.out;
  const marked = mark.filter((px) => near(px, ACTOR.blocked)).length;
  await page.evaluate(() => window.planarium.view3d.showStep(false));
  const bare = (await near3d(page, step.collision.at, 3))?.out;
  const unmarked = bare.filter((px) => near(px, ACTOR.blocked)).length;
  console.log(`contact ${step.collision.at.map((v) => v.toFixed(3))}: ${marked} of ${mark.length} pixels the blocked colour with the step drawn, ${unmarked} without`);
  assert.ok(marked >= 5 && unmarked === 0, 'the collision is marked at the contact point');
  // The ghost arms: around their joints (link frames' origins 2 to 5, inside the links' hulls) the
  // pixels are not those of the view without them.
  let ghosts = 0;
  for (const name of ['sample', 'collision']) {
    let changed = 0, seen = 0;
    for (const p of step.joints[name].slice(2, 6)) {
      await page.evaluate(() => window.planarium.view3d.showStep(false));
      const without = (await near3d(page, p, 2))?.out;
      await page.evaluate(() => window.planarium.view3d.showStep(true));
      const withGhost = (await near3d(page, p, 2))?.out;
      if (!without || !withGhost) continue;
      seen += withGhost.length;
      changed += withGhost.filter((px, k) => px.some((v, c) => Math.abs(v - without[k][c]) > 6)).length;
    }
    console.log(`the ${name}'s ghost arm: ${changed} of ${seen} pixels around its joints changed`);
    if (seen) ghosts++;
    assert.ok(changed >= 10, `the ${name} is drawn as a ghost arm`);
  }
  assert.ok(step.sample, 'the sample\'s ghost is drawn');
  assert.ok(ghosts >= 1, 'a ghost was checked');
});

test('puma-rbo-wall: a connect\'s configurations walked one by one, the ghost arm at each, free until the last', async () => {
  await fx.pickScenario('puma-rbo-wall', PUMA_NAME);
  await page.waitForFunction(() => window.planarium.view3d.ready(), null, { timeout: 20000 });
  let n = 0;
  for (let i = 1; i <= 2000 && n < 3; i++) {
    await page.click('#step-event');
    await page.waitForFunction((k) => window.planarium.explain().events === k, i, { timeout: 30000 });
    const m = /(\d+) configurations checked/.exec((await page.evaluate(() => window.planarium.explain())).caption);
    n = m ? Number(m[1]) : 0;
  }
  assert.ok(n >= 3, 'a connect of three configurations or more within 2,000 events');
  await fx.nextFrames();
  const walk = page.locator('#connect-steps');
  assert.ok(await walk.isVisible(), 'the walk is offered');
  assert.equal((await page.locator('#connect-at').textContent()).trim(), `configuration ${n} of ${n}`);
  assert.ok(await page.locator('#connect-next').isDisabled(), 'nothing after the farthest');
  const farthest = await page.evaluate(() => window.planarium.explain3d());
  assert.equal(farthest.walk.q, null, 'the farthest is drawn as the step recorded it');
  // one back: the configuration before, free (the connect went on past it), drawn as the ghost
  await page.click('#connect-prev');
  await fx.nextFrames();
  assert.equal((await page.locator('#connect-at').textContent()).trim(), `configuration ${n - 1} of ${n}`);
  const words = await page.locator('#connect-words').textContent();
  assert.match(words, /^q = \((−?\d+°, ){5}−?\d+°\): free, so the connect goes on$/, words);
  const back = await page.evaluate(() => window.planarium.explain3d());
  assert.equal(back.walk.k, n - 1);
  assert.equal(back.collision, null, 'no collision before the farthest');
  // the ghost is at the configuration the walk names: its link frames the core's for it, in Node
  const frames = core.link_frames(Float64Array.from(back.walk.q));
  const origins = [];
  for (let k = 0; k + 16 <= frames.length; k += 16) origins.push([frames[k + 12], frames[k + 13], frames[k + 14]]);
  assert.equal(back.joints.step.length, origins.length);
  back.joints.step.forEach((o, j) => assert.ok(o.every((v, c) => Math.abs(v - origins[j][c]) < 1e-9), `link ${j}: ${o} against the core's ${origins[j]}`));
  assert.notDeepEqual(back.step, farthest.step, 'the ghost moved');
  // to the first: the keyboard works the buttons too; then forward again to the farthest
  for (let k = n - 1; k > 1; k--) await page.click('#connect-prev');
  assert.equal((await page.locator('#connect-at').textContent()).trim(), `configuration 1 of ${n}`);
  assert.ok(await page.locator('#connect-prev').isDisabled());
  await page.locator('#connect-next').focus();
  await page.keyboard.press('Enter');
  assert.equal((await page.locator('#connect-at').textContent()).trim(), `configuration 2 of ${n}`);
  // the next event leaves the walk: hidden, or a new connect's, at its farthest
  await page.click('#step-event');
  await fx.nextFrames();
  const after = await page.evaluate(() => window.planarium.explain3d());
  assert.ok(!after?.walk || after.walk.k === after.walk.count, JSON.stringify(after?.walk));
  assert.deepEqual(fx.errors, []);
});

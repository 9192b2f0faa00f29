// Issue 13's page reproductions that the core's input limits answer (headless chromium): a
// scenario whose resolution would make one motion check take a minute (1e-9), or skip its checks
// (1e-12), or whose bounds broke the motion check (-9.2e18), opened through "Open file…" or a link,
// is refused with its JSON path and the limit, the page stays usable (a built-in runs to a
// solution right after), and a node limit of 1e8 from a link is refused with the
// limit. The limits the page reads from the core (`limits()`) equal docs/limits.md's.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, ROOT, SHOTS } from './browser.mjs';
import { encodeScenario } from '../../www/ui/scenario-codec.js';

const fx = await pageFixture();
const builtin = (id) => JSON.parse(readFileSync(join(ROOT, 'scenarios', `${id}.json`), 'utf8'));

/** Open `scenario` through "Open file…" as a person would; wait for the page's answer. */
async function openFile(name, scenario) {
  await fx.page.setInputFiles('#file', { name, mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(scenario)) });
}

async function refusedWith(pattern) {
  await fx.page.waitForSelector('#error', { state: 'visible', timeout: 20000 });
  await fx.waitState('invalid');
  const text = await fx.page.textContent('#error-text');
  assert.match(text, pattern);
  assert.equal(await fx.page.isDisabled('#run'), true, 'Run waits for a valid scenario');
  return text;
}

/** Open `hash` on a fresh page, as a person who clicks a link (a new tab). */
async function openLink(hash) {
  await fx.page.close();
  fx.page = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
  fx.page.on('pageerror', (e) => fx.errors.push(e));
  await fx.page.goto(`${fx.env.base}${hash}`);
}

/** A link's scenario refused: the first built-in instead, the reason in words, the page idle. */
async function linkRefusedWith(pattern) {
  await fx.page.waitForSelector('#error', { state: 'visible', timeout: 20000 });
  await fx.waitState('idle', 30000);
  const text = await fx.page.textContent('#error-text');
  assert.match(text, pattern);
  assert.match(text, /The first built-in is shown instead/);
  return text;
}

/** After a refusal: pick a built-in and run it to a solution. */
async function stillUsable() {
  await fx.pickScenario('narrow', 'Narrow passage');
  await fx.fastPlayback();
  await fx.page.click('#run');
  await fx.waitStatus('solved', 60000);
}

test('a resolution too fine for the map is refused with its path, by file and by link; the page stays usable', async () => {
  for (const r of [1e-9, 1e-12]) {
    const t0 = Date.now();
    await openFile(`fine-${r}.json`, { ...builtin('open-field'), resolution: r });
    const text = await refusedWith(/resolution: 1e-(9|12) is too fine: .* the limit is 1e5, so it must be at least 1\.414e-5/);
    console.log(`resolution ${r}: refused after ${Date.now() - t0} ms: ${text}`);
  }
  await fx.page.screenshot({ path: join(SHOTS, 'limits-resolution.png') });
  await stillUsable();
  // the same scenario in a link
  const value = await encodeScenario(JSON.stringify({ ...builtin('open-field'), resolution: 1e-9 }));
  await openLink(`#scenario=${value}&planner=rrt&time_limit=3600`);
  await linkRefusedWith(/not valid at resolution: 1e-9 is too fine/);
  await stillUsable();
});

test('bounds of -9.2e18 on the slot are refused with their path instead of crashing the worker', async () => {
  const slot = builtin('slot');
  const value = await encodeScenario(JSON.stringify({ ...slot, bounds: [-9.2e18, 0, 1, 1] }));
  await openLink(`#scenario=${value}`);
  const text = await linkRefusedWith(/not valid at bounds\[0\]: -9\.2e18 is too large: numbers must lie between -1e9 and 1e9/);
  console.log(text);
  // four tries, as in the report: still refused each time, never "running" with a dead worker
  for (let i = 0; i < 4; i++) {
    await openFile(`slot-${i}.json`, { ...slot, bounds: [-9.2e18, 0, 1, 1] });
    await refusedWith(/bounds\[0\]/);
  }
  await stillUsable();
});

test('a node limit of 1e8 from a link is refused with the limit; the core limits are those of docs/limits.md', async () => {
  await openLink('#scenario=narrow&planner=rrt&max_nodes=100000000');
  await fx.waitState('idle', 30000);
  const problems = await fx.page.textContent('#error-text');
  assert.match(problems, /max_nodes=100000000: .* must be .*1000000/);
  const { limits, specs } = await fx.page.evaluate(async () => {
    const { default: init, limits, planners } = await import('./pkg/planarium.js');
    await init();
    return { limits: JSON.parse(limits()), specs: JSON.parse(planners()).run_params };
  });
  assert.equal(specs.find((s) => s.name === 'max_nodes').max, 1e6);
  const doc = readFileSync(join(ROOT, 'docs', 'limits.md'), 'utf8');
  assert.equal(limits.max_nodes, 1e6);
  assert.equal(limits.max_motion_steps, 1e5);
  assert.match(doc, /\| 100,000 \| the finest built-in needs 1,486/);
  assert.match(doc, /`max_nodes` \| 2 … 1,000,000/);
});

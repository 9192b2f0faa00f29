// The figures of docs/hexagonal-decomposition.md and docs/potential-field.md, made by driving the
// playground in headless chromium like a person: pick a scenario (its planner block selects the
// planner), run at full playback speed, wait for the run to finish, save the canvas as a PNG.
//
//   node scripts/build.mjs && node scripts/figures.mjs [id ...]     (default: every figure)
//
// Writes docs/figures/<id>.png (and docs/screenshot.png, the README's). Uses the test fixture's
// server and browser launcher.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { startBrowser, ROOT } from '../tests/js/browser.mjs';

// Each figure: the scenario, the overlays switched on besides the defaults, and the file name.
const FIGURES = {
  'hex-open': { overlays: [] },
  'hex-corridor': { overlays: [] },
  'hex-trap': { overlays: [] },
  'hex-trap-heat': { scenario: 'hex-trap', overlays: ['show-heat', 'show-arrows'] },
  'hex-trap-modified': { overlays: [] },
  'apf-minimum': { overlays: ['show-heat', 'show-arrows'] },
  // README's picture: the whole page, RRT-Connect in the narrow passage.
  screenshot: { scenario: 'narrow', overlays: [], page: true, file: join('docs', 'screenshot.png') },
};

const wanted = process.argv.slice(2);
const ids = wanted.length ? wanted : Object.keys(FIGURES);
const out = join(ROOT, 'docs', 'figures');
mkdirSync(out, { recursive: true });

const env = await startBrowser();
try {
  for (const id of ids) {
    const page = await env.browser.newPage({ viewport: { width: 1280, height: 900 } });
    page.on('pageerror', (e) => console.error(`[${id}] page error: ${e}`));
    await page.goto(env.base);
    await page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
    await page.selectOption('#scenario', FIGURES[id]?.scenario ?? id);
    await page.waitForFunction(() => window.planarium?.state() === 'idle');
    for (const box of FIGURES[id]?.overlays ?? []) await page.check(`#${box}`);
    await page.$eval('#speed', (el) => {
      el.value = el.max;
      el.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.click('#run');
    await page.waitForFunction(() => window.planarium?.state() === 'finished', null, { timeout: 60000 });
    // Let playback reveal every record and the robot reach the goal.
    await page.waitForTimeout(1500);
    const status = await page.$eval('#status', (el) => el.textContent);
    const file = FIGURES[id]?.file ?? join('docs', 'figures', `${id}.png`);
    if (FIGURES[id]?.page) {
      await page.setViewportSize({ width: 1280, height: 800 });
      await page.waitForTimeout(500);
      await page.screenshot({ path: join(ROOT, file) });
    } else {
      const png = await page.$eval('#canvas', (c) => c.toDataURL('image/png'));
      writeFileSync(join(ROOT, file), Buffer.from(png.split(',')[1], 'base64'));
    }
    console.log(`${id}: ${status} → ${file}`);
    await page.close();
  }
} finally {
  await env.close();
}

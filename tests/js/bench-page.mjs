// Shared by the benchmark page's tests (page-bench, page-bench-slides): open the page, type set-up
// lines, run them and wait for the report, and read a download, as a person would.
import { readFileSync } from 'node:fs';

/** The helpers, on the fixture `fx` of tests/js/browser.mjs's pageFixture. */
export function benchPage(fx) {
  async function openBench() {
    await fx.page.goto(`${fx.env.base}bench.html`);
    await fx.page.waitForFunction(() => window.planarium?.state() === 'idle', null, { timeout: 30000 });
  }

  /** Type set-up lines in the "Advanced" text (opened first, as a person would). */
  async function typeSetups(setups) {
    if (!(await fx.page.$eval('#advanced', (d) => d.open))) await fx.page.click('#advanced summary');
    await fx.page.fill('#setups', setups);
  }

  async function runBench(scenario, setups, runs) {
    await fx.page.selectOption('#scenario', scenario);
    await typeSetups(setups);
    await fx.page.fill('#runs', String(runs));
    await fx.page.click('#bench-run');
  }

  /** Wait until the page is idle with `n` runs in every set-up's rows. */
  const waitReport = (n) => fx.page.waitForFunction((k) => window.planarium.state() === 'idle' && window.planarium.report()?.setups.every((s) => s.rows.length === k),
    n, { timeout: 120000 });

  /** Click `selector` and read the file it downloads: {name, bytes}. */
  async function download(selector) {
    const [d] = await Promise.all([fx.page.waitForEvent('download'), fx.page.click(selector)]);
    return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
  }

  return { openBench, typeSetups, runBench, waitReport, download };
}

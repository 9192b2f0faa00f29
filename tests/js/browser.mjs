// Shared by the browser tests: serve www/ on a free port and launch Debian's chromium headless
// (playwright-core, a fresh profile per launch, no network beyond loopback).
import { mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from '../../scripts/serve.mjs';

/** The project's root, and the folder screenshots are saved in (`target/`). */
export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const SHOTS = join(ROOT, 'target');
mkdirSync(SHOTS, { recursive: true });

export const CHROMIUM_ARGS = ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
  '--disable-component-update', '--no-first-run', '--disable-sync'];

/**
 * Keeps every section of the page open (the sidebar's "Overlays", "Edit the map", "Export for
 * slides"… and the panels' "More parameters"), as a person opens them before using what is inside:
 * most tests are about what the sections hold, not about the first screen, which
 * page-learn.test.mjs checks with the sections as they are (startBrowser({openSections: false})).
 */
function openEverySection() {
  const open = () => document.querySelectorAll('details:not([open])').forEach((d) => { d.open = true; });
  document.addEventListener('DOMContentLoaded', () => {
    open();
    new MutationObserver(open).observe(document.body, { childList: true, subtree: true });
  });
}

/**
 * Start the static server and the browser; returns {server, browser, base, close()}. Its pages
 * keep their sections open unless `openSections` is false.
 */
export async function startBrowser({ openSections = true } = {}) {
  const server = await serve({ port: 0 });
  const base = `http://127.0.0.1:${server.address().port}/`;
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: CHROMIUM_ARGS });
  if (openSections) {
    const newPage = browser.newPage.bind(browser);
    browser.newPage = async (options) => {
      const page = await newPage(options);
      await page.addInitScript(openEverySection);
      return page;
    };
    const newContext = browser.newContext.bind(browser);
    browser.newContext = async (options) => {
      const context = await newContext(options);
      await context.addInitScript(openEverySection);
      return context;
    };
  }
  const close = async () => {
    await browser.close();
    await new Promise((resolve) => server.close(resolve));
  };
  return { server, browser, base, close };
}

/**
 * Register the hooks of a page test file: one browser and server for the file, a fresh page on
 * the playground (waited until idle) for each test, page errors failing the test. Returns the
 * fixture: `fx.page` (the current page) and helpers that wait on it.
 */
export async function pageFixture() {
  const { before, after, beforeEach, afterEach } = await import('node:test');
  const assert = (await import('node:assert/strict')).default;
  const fx = { env: null, page: null, errors: [] };
  fx.waitState = (state, timeout = 20000) =>
    fx.page.waitForFunction((s) => window.planarium?.state() === s, state, { timeout });
  fx.waitStatus = (word, timeout = 60000) =>
    fx.page.waitForFunction((w) => document.getElementById('status')?.textContent === w, word, { timeout });
  fx.pickScenario = async (id, name) => {
    await fx.page.selectOption('#scenario', id);
    await fx.page.waitForFunction((n) => document.getElementById('scenario-name').textContent === n, name);
    await fx.waitState('idle');
  };
  /** Wait until two animation frames have been drawn. */
  fx.nextFrames = () => fx.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  /** Playback speed to its maximum: every event at once. */
  fx.fastPlayback = () => fx.page.$eval('#speed', (el) => {
    el.value = el.max;
    el.dispatchEvent(new Event('input', { bubbles: true }));
  });
  /** Type `value` into the panel field `id` and commit it (the panel acts on `change`). */
  fx.setField = async (id, value) => {
    await fx.page.$eval(`#${id}`, (el, v) => {
      el.value = String(v);
      el.dispatchEvent(new Event('change', { bubbles: true }));
    }, value);
    await fx.waitState('idle');
  };
  /** The page position (css px) of world point (x, y) on the workspace canvas (as draw/transform.js's Layout). */
  fx.toPage = async (x, y) => {
    const box = await fx.page.locator('#canvas').boundingBox();
    const [x0, y0, x1, y1] = await fx.page.evaluate(() => window.planarium.scenario().bounds);
    const margin = 10;
    const scale = Math.min((box.width - 2 * margin) / (x1 - x0), (box.height - 2 * margin) / (y1 - y0));
    const ox = (box.width - scale * (x1 - x0)) / 2 - scale * x0;
    const oy = (box.height + scale * (y1 - y0)) / 2 + scale * y0;
    return [box.x + ox + x * scale, box.y + oy - y * scale];
  };
  /** Press at page point `from`, move in steps to `to`, release (a person's drag). */
  fx.drag = async (from, to) => {
    await fx.page.mouse.move(...from);
    await fx.page.mouse.down();
    const steps = 8;
    for (let i = 1; i <= steps; i++) {
      await fx.page.mouse.move(from[0] + ((to[0] - from[0]) * i) / steps, from[1] + ((to[1] - from[1]) * i) / steps);
    }
    await fx.page.mouse.up();
  };
  /** How many pixels of canvas `id` are within `tol` (per channel) of each `#rrggbb` colour. */
  fx.countColours = (id, colours, tol = 6) =>
    fx.page.evaluate(({ id, colours, tol }) => {
      const c = document.getElementById(id);
      const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      const rgb = colours.map((h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16)));
      const counts = rgb.map(() => 0);
      for (let i = 0; i < px.length; i += 4) {
        rgb.forEach(([r, g, b], k) => {
          if (Math.abs(px[i] - r) <= tol && Math.abs(px[i + 1] - g) <= tol && Math.abs(px[i + 2] - b) <= tol) counts[k]++;
        });
      }
      return counts;
    }, { id, colours, tol });
  before(async () => { fx.env = await startBrowser(); });
  after(async () => { await fx.env?.close(); });
  beforeEach(async () => {
    fx.errors = [];
    fx.page = await fx.env.browser.newPage({ viewport: { width: 1280, height: 800 } });
    fx.page.on('console', (m) => {
      if (m.type() === 'error' || m.type() === 'warning') console.log(`[page ${m.type()}] ${m.text()}`);
    });
    fx.page.on('pageerror', (e) => {
      console.log(`[page error] ${e.stack || e}`);
      fx.errors.push(e);
    });
    await fx.page.goto(fx.env.base);
    await fx.waitState('idle', 30000);
  });
  afterEach(async () => {
    await fx.page?.close();
    assert.deepEqual(fx.errors.map(String), [], 'the page threw');
  });
  return fx;
}

/**
 * The pixels of the canvas `id` on `page`: {w, h, data} (RGBA, device px). They come out of the
 * page as base64: an array of numbers of a canvas's size takes seconds to carry.
 */
export async function canvasPixels(page, id = 'canvas') {
  const { w, h, b64 } = await page.evaluate((id) => {
    const c = /** @type {HTMLCanvasElement} */ (document.getElementById(id));
    const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let bin = '';
    for (let i = 0; i < px.length; i += 0x8000) bin += String.fromCharCode.apply(null, Array.from(px.subarray(i, i + 0x8000)));
    return { w: c.width, h: c.height, b64: btoa(bin) };
  }, id);
  return { w, h, data: new Uint8Array(Buffer.from(b64, 'base64')) };
}

/**
 * A scenario whose goal sits in a closed box, so RRT grows until its node limit: `planner` sets
 * the node and time limits.
 */
export function walledIn(planner) {
  return {
    format: 'planarium-scenario/1',
    name: 'Walled-in goal',
    notes: 'The goal sits in a closed box: RRT grows until its node limit.',
    bounds: [0, 0, 1, 1],
    obstacles: [
      { rect: [0.8, 0.8, 0.98, 0.82] }, { rect: [0.8, 0.96, 0.98, 0.98] },
      { rect: [0.8, 0.8, 0.82, 0.98] }, { rect: [0.96, 0.8, 0.98, 0.98] },
    ],
    robot: { kind: 'point' },
    start: [0.1, 0.1],
    goal: [0.89, 0.89],
    resolution: 0.002,
    planner: { name: 'rrt', seed: 1, goal_bias: 0.05, ...planner },
  };
}

// The SVG export draws what the canvas draws, layer by layer (headless chromium): EST's density
// overlay, paused mid-run, is in the SVG; and for ten planners, each overlay whose switch changes
// the canvas changes the SVG's group for it (present with content when on), and the layers every
// run of that planner draws (trees, roadmap, graph, cells, paths, robot) are groups with content.
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { pageFixture } from './browser.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });
const { waitState, pickScenario, nextFrames, fastPlayback, setField } = fx;

async function svgText() {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#export-svg')]);
  return readFileSync(await d.path(), 'utf8');
}

/** {id: {paths, subpaths, images, texts, bytes}} for every element with an id in the SVG. */
const groups = (text) => page.evaluate((t) => {
  const doc = new DOMParser().parseFromString(t, 'image/svg+xml');
  if (doc.querySelector('parsererror')) return null;
  const out = {};
  for (const e of doc.querySelectorAll('svg [id]')) {
    if (e.closest('defs')) continue;
    const all = [e, ...e.querySelectorAll('*')];
    const paths = all.filter((x) => x.hasAttribute('d') || ['circle', 'rect', 'polygon'].includes(x.localName));
    out[e.id] = {
      paths: paths.length,
      subpaths: paths.reduce((n, x) => n + ((x.getAttribute('d') || '').match(/M/g) || []).length, 0),
      images: all.filter((x) => x.localName === 'image').length,
      texts: all.filter((x) => x.localName === 'text').length,
      bytes: new XMLSerializer().serializeToString(e).length,
    };
  }
  return out;
}, text);

const hasContent = (g) => !!g && (g.subpaths > 0 || g.images > 0 || g.texts > 0 || g.paths > 0);

/** Keep the canvas's pixels in the page, to compare later ones with (kept there: a canvas's pixels
 * carried out to Node as numbers cost seconds a picture). */
const keepPixels = () => page.evaluate(() => {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('canvas'));
  /** @type {any} */ (window).__kept = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
});
/** How many of the canvas's pixels differ from the kept ones by more than 24 in the sum of R, G and B. */
const changedPixels = () => page.evaluate(() => {
  const c = /** @type {HTMLCanvasElement} */ (document.getElementById('canvas'));
  const a = /** @type {any} */ (window).__kept, b = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  if (a.length !== b.length) return a.length + b.length;
  let n = 0;
  for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 24) n++;
  return n;
});

test("EST paused mid-run: the SVG has the density overlay the canvas shows (cells shaded, the pick outlined)", async () => {
  await pickScenario('zigzag', 'Zigzag of walls');
  await page.selectOption('#planner', 'est');
  await waitState('idle');
  await setField('seed', 1);
  await page.fill('#step-size', '120');
  await page.click('#step');
  await waitState('paused');
  await nextFrames();
  const on = await groups(await svgText());
  assert.ok(on, 'the SVG parses');
  const density = on.density;
  console.log(`density group: ${JSON.stringify(density)}`);
  assert.ok(density && density.subpaths >= 10, `the density cells are in the SVG: ${JSON.stringify(density)}`);
  const picked = await page.evaluate((t) => {
    const doc = new DOMParser().parseFromString(t, 'image/svg+xml');
    return [...doc.querySelectorAll('#density path')].filter((p) => p.getAttribute('fill') === 'none').map((p) => p.getAttribute('stroke'));
  }, await svgText());
  const P = await page.evaluate(async () => (await import('./draw/palette.js')).PALETTE);
  assert.deepEqual(picked, [P.densityPick], "the latest pick's cell outlined, once");
  await page.click('#show-density');
  await nextFrames();
  const off = await groups(await svgText());
  assert.equal(off.density, undefined, 'no density group with the overlay off');
});

// [planner, scenario id, scenario name, layers every run of it draws]
const RUNS = [
  ['rrt-connect', 'narrow', 'Narrow passage', ['trees', 'tree-0', 'tree-1', 'smoothed-path', 'raw-path', 'start', 'goal', 'obstacles']],
  ['rrt-star', 'open-field', 'Open field', ['trees', 'smoothed-path', 'start', 'goal']],
  ['prm', 'zigzag', 'Zigzag of walls', ['roadmap', 'smoothed-path']],
  ['lazy-prm', 'zigzag', 'Zigzag of walls', ['roadmap', 'smoothed-path']],
  ['est', 'zigzag', 'Zigzag of walls', ['trees', 'smoothed-path']],
  ['hex-potential', 'hex-trap-modified', 'Hexagons: the trap, modified potential', ['cells', 'veil', 'trees', 'smoothed-path']],
  ['grid-search', 'zigzag', 'Zigzag of walls', ['cells', 'veil', 'smoothed-path']],
  ['potential-field', 'apf-minimum', 'Potential field: a local minimum', ['trees']],
  ['visibility-graph', 'open-field', 'Open field', ['graph', 'trees', 'smoothed-path']],
  ['inspection', 'technion-ip', 'Technion HW3: inspect the room', ['trees', 'inspection']],
];

// the SVG groups an overlay's switch changes
const OVERLAY_GROUPS = {
  'show-accepted': ['samples'], 'show-rejected': ['samples'], 'show-tries': ['samples'], 'show-collisions': ['collisions'],
  'show-domains': ['domains'], 'show-exhausted': ['trees'], 'show-best': ['best'], 'show-seen': ['inspection'],
  'show-fov': ['sensor'], 'show-cells': ['cells'], 'show-heat': ['cells'], 'show-arrows': ['cells'],
  'show-region': ['regions', 'robot-t'], 'show-density': ['density'],
};

test('ten planners: every overlay the canvas draws is in the SVG, in its group, and so is every layer of the run', async () => {
  const seen = new Set();
  for (const [planner, id, name, layers] of RUNS) {
    await pickScenario(id, name);
    if (await page.$eval('#planner', (s) => s.value) !== planner) {
      await page.selectOption('#planner', planner);
      await waitState('idle');
    }
    await setField('seed', 1);
    if (planner === 'inspection') await setField('param-coverage', 0.3);
    await fastPlayback();
    await page.click('#run');
    await waitState('finished', 120000);
    // the robot stops where it is (every frame is drawn at one time), so only a switch changes the canvas
    await page.evaluate(() => {
      const raf = window.requestAnimationFrame.bind(window);
      window.requestAnimationFrame = (cb) => raf(() => cb(12345));
    });
    await page.waitForTimeout(700); // rewire flashes fade out
    const boxes = await page.$$eval('#overlays input[type=checkbox]', (els) => els.filter((e) => e.offsetParent !== null).map((e) => e.id));
    for (const box of boxes) await page.check(`#${box}`);
    await nextFrames();
    const on = await groups(await svgText());
    assert.ok(on, `${planner}: the SVG parses`);
    for (const layer of layers) assert.ok(hasContent(on[layer]), `${planner}: the SVG has layer ${layer} with content: ${JSON.stringify(on[layer])}`);
    await keepPixels();
    const report = [];
    for (const box of boxes) {
      const want = OVERLAY_GROUPS[box];
      if (!want) continue;
      await page.uncheck(`#${box}`);
      await nextFrames();
      const px = await changedPixels();
      if (px > 0) {
        const off = await groups(await svgText());
        const moved = want.filter((g) => hasContent(on[g]) && JSON.stringify(on[g]) !== JSON.stringify(off[g]));
        report.push(`${box} ${px}px → ${moved.join('+') || 'NOTHING'}`);
        assert.ok(moved.length > 0, `${planner}: ${box} changes ${px} canvas pixels but none of the SVG groups ${want.join(', ')} (on: ${JSON.stringify(want.map((g) => on[g]))})`);
        for (const g of moved) seen.add(g);
      }
      await page.check(`#${box}`);
      await nextFrames();
    }
    console.log(`${planner}: overlays ${report.join('; ')}; layers ${Object.keys(on).join(' ')}`);
  }
  console.log(`overlay groups checked: ${[...seen].join(', ')}`);
  for (const g of ['cells', 'samples', 'inspection', 'sensor', 'collisions', 'best']) assert.ok(seen.has(g), `some run showed overlay group ${g}`);
});

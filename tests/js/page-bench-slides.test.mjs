// The benchmark page's figures for a slide, in headless chromium: every plot downloads as a PNG
// twice its size with its title drawn at the top and as an SVG with its full title and its key
// above the data (both read back), and the results table gives mean ± std beside each median and
// copies as Markdown and as LaTeX (the clipboard read back).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, SHOTS } from './browser.mjs';
import { benchPage } from './bench-page.mjs';

const fx = await pageFixture();
const { openBench, runBench, waitReport, download } = benchPage(fx);

test('every plot downloads as a PNG twice its size, its title drawn at the top, and as an SVG with its full title and its key above the data', async () => {
  await openBench();
  await runBench('open-field', 'star: rrt-star --improve-for 400\nplain: rrt', 3);
  await waitReport(3);
  const cards = await fx.page.$$eval('.plot-card', (cs) => cs.map((c) => [c.querySelector('canvas').id, !!c.querySelector('.plot-png'), !!c.querySelector('.plot-svg')]));
  assert.ok(cards.length >= 7 && cards.every(([, png, svg]) => png && svg), `each plot has its downloads: ${JSON.stringify(cards)}`);
  for (const id of ['plot-time', 'plot-curves']) {
    const { w, h, title } = await fx.page.$eval(`#${id}`, (c) => ({ w: c.clientWidth, h: c.clientHeight, title: c.dataset.title }));
    const png = await download(`.plot-card:has(#${id}) .plot-png`);
    assert.match(png.name, /^planarium-.*\.png$/);
    writeFileSync(join(SHOTS, `page-bench-download-${id}.png`), png.bytes);
    assert.equal(png.bytes.subarray(1, 4).toString('latin1'), 'PNG');
    // decoded by the browser: twice the plot's size; the title's dark text in the top band, none
    // in the band between the title and the plot area's top
    const seen = await fx.page.evaluate(async (b64) => {
      const bytes = Uint8Array.from(atob(b64), (ch) => ch.charCodeAt(0));
      const img = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
      const c = new OffscreenCanvas(img.width, img.height);
      const ctx = c.getContext('2d');
      ctx.drawImage(img, 0, 0);
      const dark = (y0, y1) => {
        const px = ctx.getImageData(0, y0, img.width, y1 - y0).data;
        let n = 0;
        for (let i = 0; i < px.length; i += 4) if (px[i] < 80 && px[i + 1] < 80 && px[i + 2] < 80) n++;
        return n;
      };
      return { w: img.width, h: img.height, title: dark(0, 2 * 20) };
    }, png.bytes.toString('base64'));
    assert.deepEqual([seen.w, seen.h], [2 * w, 2 * h], `${id}: the PNG is twice the plot's ${w}×${h}`);
    assert.ok(seen.title > 150, `${id}: the title's dark pixels at the top: ${seen.title}`);
    const svg = (await download(`.plot-card:has(#${id}) .plot-svg`)).bytes.toString('utf8');
    const doc = await fx.page.evaluate((text) => {
      const d = new DOMParser().parseFromString(text, 'image/svg+xml');
      const nums = (g) => [...(g?.querySelectorAll('path') ?? [])].flatMap((p) => (p.getAttribute('d').match(/-?[\d.]+/g) ?? []).map(Number).filter((_, i) => i % 2 === 1));
      return {
        error: !!d.querySelector('parsererror'),
        title: d.querySelector('svg > title')?.textContent,
        drawn: [...d.querySelectorAll('#title text')].map((t) => t.textContent).join(' '),
        key: [...d.querySelectorAll('#key text')].map((t) => Number(t.getAttribute('y'))),
        dataTop: Math.min(...nums(d.getElementById('data'))),
        band: d.querySelectorAll('#data path[fill-opacity="0.22"]').length,
        median: d.querySelectorAll('#data path[stroke-width="2.5"]').length,
      };
    }, svg);
    assert.equal(doc.error, false);
    assert.equal(doc.title, title, `${id}: the SVG's <title>`);
    assert.equal(doc.drawn, title, `${id}: the title drawn in full`);
    if (id === 'plot-curves') {
      assert.equal(doc.key.length, 1, 'RRT*\'s key');
      assert.ok(Math.max(...doc.key) < doc.dataTop, `the key (baseline ${doc.key}) is above the data (top ${doc.dataTop})`);
      assert.equal(doc.band, 1, 'RRT*\'s interquartile band');
      assert.equal(doc.median, 1, 'RRT*\'s median line');
    }
  }
});

test('the results table gives mean ± std beside each median, and copies as Markdown and as LaTeX', async () => {
  await fx.page.context().grantPermissions(['clipboard-read', 'clipboard-write'], { origin: fx.env.base });
  await openBench();
  await runBench('open-field', 'connect: rrt-connect\nplain: rrt', 4);
  await waitReport(4);
  const head = await fx.page.$$eval('#bench-table thead th', (ths) => ths.map((t) => t.textContent));
  assert.deepEqual(head, ['set-up', 'success', 'time (ms) mean ± std', 'time median', 'nodes mean ± std', 'nodes median',
    'checks mean ± std', 'checks median', 'cost mean ± std', 'cost median', 'smoothed cost median']);
  const cells = await fx.page.$$eval('#bench-table tbody tr', (trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent)));
  const report = await fx.page.evaluate(() => window.planarium.report());
  // nodes: mean ± sample std and the median, recomputed from the runs
  report.setups.forEach((s, k) => {
    const v = s.rows.map((r) => r.nodes);
    const mean = v.reduce((a, b) => a + b, 0) / v.length;
    const std = Math.sqrt(v.reduce((a, b) => a + (b - mean) ** 2, 0) / (v.length - 1));
    const [m, sd] = cells[k][4].split(' ± ').map(Number);
    assert.ok(Math.abs(m - mean) <= 1e-3 * mean && Math.abs(sd - std) <= 1e-3 * std + 1e-9, `${s.label}: ${cells[k][4]} vs ${mean} ± ${std}`);
    const sorted = [...v].sort((a, b) => a - b);
    assert.equal(Number(cells[k][5]), (sorted[1] + sorted[2]) / 2);
  });
  // the table uses the page's width: it is not cut off
  const fit = await fx.page.$eval('#table-scroll', (b) => ({ sw: b.scrollWidth, cw: b.clientWidth }));
  assert.ok(fit.sw <= fit.cw + 1, `the table fits its box at 1280 px: ${JSON.stringify(fit)}`);
  await fx.page.click('#copy-md');
  await fx.page.waitForFunction(() => document.getElementById('copy-status').textContent === 'Copied as Markdown.');
  const md = await fx.page.evaluate(() => navigator.clipboard.readText());
  const mdLines = md.trim().split('\n');
  assert.match(mdLines[0], /^open-field|Open field/);
  const table = mdLines.filter((l) => l.startsWith('|'));
  assert.equal(table.length, 2 + cells.length);
  assert.equal(table[0], `| ${head.join(' | ')} |`);
  assert.match(table[1], /^\| --- \|( ---: \|){10}$/);
  assert.equal(table[2], `| ${cells[0].join(' | ')} |`);
  await fx.page.click('#copy-tex');
  await fx.page.waitForFunction(() => document.getElementById('copy-status').textContent === 'Copied as LaTeX.');
  const tex = await fx.page.evaluate(() => navigator.clipboard.readText());
  assert.match(tex, /\\begin\{tabular\}\{lrrrrrrrrrr\}/);
  assert.match(tex, /\\toprule\n {4}set-up & success & time \(ms\) mean \$\\pm\$ std/);
  const row = cells[0].map((c) => c.replace(/%/g, '\\%').replace(/±/g, '$\\pm$')).join(' & ');
  assert.ok(tex.includes(`    ${row} \\\\`), `the first row in LaTeX: ${row}\n${tex}`);
  assert.match(tex, /\\bottomrule\n {2}\\end\{tabular\}\n\\end\{table\}/);
  await fx.page.screenshot({ path: join(SHOTS, 'page-bench-table.png') });
});

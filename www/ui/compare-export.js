// Compare's export for a slide: both lanes side by side in one PNG, each under its title ("A ·
// RRT* · uniform sampler") and above its key numbers (status, time, nodes, checks, cost), drawn
// from the lanes' canvases as the page shows them (both the same size: the lanes share their
// rows); the numbers wrap to as many lines as they need. Text is drawn with fillText from textContent: no HTML.

import { downloadBlob } from '../draw/stage.js';
import { SvgContext, svgNode } from '../draw/svg-context.js';

/**
 * The key numbers under each lane: [label, the stats list's element id suffix, and how its text is
 * shortened for a lane's width, if it is].
 * @type {[string, string, ((text: string) => string)?][]}
 */
export const KEY_NUMBERS = [['status', 'status'], ['time (ms)', 'stat-time'], ['nodes', 'stat-nodes'], ['checks', 'stat-checks'], ['cost', 'stat-cost'], ['smoothed', 'stat-smoothed-cost'],
  ['optimum', 'stat-optimum', (t) => t.replace(' (visibility graph)', '')]];

const PAD = 12; // css px around and between the lanes
const TITLE = 30; // css px of a lane's title row
const NUMBER_LINE = 18; // css px of a line of its numbers (as many lines as they need)

/**
 * Both lanes as one canvas: `lanes` [{key, title, canvas, numbers: [[label, value]]}] (each
 * canvas at the page's device pixels, `dpr` of them a css px).
 * @param {{key: string, title: string, canvas: HTMLCanvasElement, numbers: string[][]}[]} lanes
 * @param {number} dpr
 * @returns {HTMLCanvasElement}
 */
export function composeLanes(lanes, dpr) {
  const w = Math.max(...lanes.map((l) => l.canvas.width));
  const h = Math.max(...lanes.map((l) => l.canvas.height));
  const pad = Math.round(PAD * dpr), title = Math.round(TITLE * dpr), lineH = Math.round(NUMBER_LINE * dpr);
  const out = document.createElement('canvas');
  const font = `${Math.round(13 * dpr)}px system-ui, sans-serif`;
  const lines = lanes.map((l) => wrapItems(out.getContext('2d'), font, l.numbers.filter(([, v]) => v && v !== '–').map(([k, v]) => `${k} ${v}`), w));
  const numbers = Math.max(1, ...lines.map((x) => x.length)) * lineH + Math.round(8 * dpr);
  out.width = pad + lanes.length * (w + pad);
  out.height = pad + title + h + numbers + pad;
  const ctx = out.getContext('2d');
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.textBaseline = 'middle';
  lanes.forEach((l, i) => {
    const x = pad + i * (w + pad);
    // the title: the lane's letter in a dark box, then its set-up, cut to the lane's width
    ctx.font = `600 ${Math.round(15 * dpr)}px system-ui, sans-serif`;
    const key = l.key.toUpperCase();
    const kw = ctx.measureText(key).width + 12 * dpr;
    ctx.fillStyle = '#20262e';
    ctx.fillRect(x, pad + 4 * dpr, kw, title - 10 * dpr);
    ctx.fillStyle = '#ffffff';
    ctx.textAlign = 'center';
    ctx.fillText(key, x + kw / 2, pad + title / 2 - dpr);
    ctx.fillStyle = '#1d2127';
    ctx.textAlign = 'left';
    ctx.fillText(cut(ctx, l.title, w - kw - 8 * dpr), x + kw + 8 * dpr, pad + title / 2 - dpr);
    ctx.drawImage(l.canvas, x + (w - l.canvas.width) / 2, pad + title + (h - l.canvas.height) / 2);
    // the key numbers on one line
    ctx.font = font;
    ctx.fillStyle = '#30343b';
    lines[i].forEach((line, k) => ctx.fillText(cut(ctx, line, w), x, pad + title + h + Math.round(4 * dpr) + (k + 0.5) * lineH));
  });
  return out;
}

/** `items` joined by " · " into lines of at most `maxW` px in `font`. */
function wrapItems(ctx, font, items, maxW) {
  ctx.font = font;
  const lines = [];
  for (const item of items) {
    const next = lines.length ? `${lines[lines.length - 1]} · ${item}` : item;
    if (lines.length && ctx.measureText(next).width <= maxW) lines[lines.length - 1] = next;
    else lines.push(item);
  }
  return lines;
}

/** `text` cut with an ellipsis to `maxW` px. */
function cut(ctx, text, maxW) {
  if (ctx.measureText(text).width <= maxW) return text;
  let t = text;
  while (t.length > 1 && ctx.measureText(`${t}…`).width > maxW) t = t.slice(0, -1);
  return `${t}…`;
}

/**
 * Wire Compare's "PNG of both lanes" button: `lanes()` gives the lanes as composeLanes takes
 * them; `onError(message)` shows a failure; `status` tells what was saved.
 * @param {{button: HTMLButtonElement, status: HTMLElement, lanes: () => any[], onError: (m: string) => void}} options
 */
export function wireCompareExport({ button, status, lanes, onError }) {
  button.addEventListener('click', () => {
    const dpr = window.devicePixelRatio || 1;
    let out;
    try { out = composeLanes(lanes(), dpr); } catch (e) { onError(`The PNG of both lanes: ${e.message}`); return; }
    out.toBlob((b) => {
      if (!b) { onError('The PNG of both lanes could not be made (too big for this browser?)'); return; }
      downloadBlob(b, 'planarium-compare.png');
      status.textContent = `Saved planarium-compare.png, ${out.width} × ${out.height} px.`;
    }, 'image/png');
  });
}

/**
 * Wire a lane's chart downloads: "PNG" (twice the chart's size) and "SVG", each with `title()`
 * (the lane and the chart's caption) above the chart; `now()` the iteration the lane has reached.
 * @param {{chart: any, title: () => string, now: () => number, png: HTMLButtonElement, svg: HTMLButtonElement, name: string, onError: (m: string) => void}} o
 */
export function wireChartDownloads({ chart, title, now, png, svg, name, onError }) {
  png.addEventListener('click', () => {
    const { width, height } = chart.sizeFor(2, title());
    const out = document.createElement('canvas');
    out.width = width;
    out.height = height;
    chart.drawFor(out.getContext('2d'), title(), 2, now());
    out.toBlob((b) => (b ? downloadBlob(b, `${name}.png`) : onError(`${title()}: the PNG could not be made`)), 'image/png');
  });
  svg.addEventListener('click', () => {
    const { width, height } = chart.sizeFor(1, title());
    const root = svgNode('svg', { xmlns: 'http://www.w3.org/2000/svg', width, height, viewBox: `0 0 ${width} ${height}` });
    svgNode('title', {}, root).textContent = title();
    const defs = svgNode('defs', {}, root);
    const ctx = new SvgContext(root, defs, { idPrefix: `${name}-clip` });
    chart.drawFor(ctx, title(), 1, now());
    ctx.finish();
    if (!defs.firstChild) defs.remove();
    const text = `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(root)}\n`;
    downloadBlob(new Blob([text], { type: 'image/svg+xml' }), `${name}.svg`);
  });
}

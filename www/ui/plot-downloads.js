// Every plot as a file for a slide or a report: "PNG" (twice the plot's size on the page) and
// "SVG", each with the plot's full title (the SVG's <title> too) and its key above the data. The
// page draws a plot through plotOn(canvas, draw), which remembers the call; a download calls it
// again on its own surface (draw/plots.js's drawInto: a larger canvas, or svg-context.js's
// recorder), so a file is drawn by the same code as the page's plot, from the same data.

import { drawInto } from '../draw/plots.js';
import { SvgContext, svgNode } from '../draw/svg-context.js';
import { downloadBlob } from '../draw/stage.js';
import { el } from './dom.js';

/** PNG downloads are this many times the plot's size on the page. */
export const PNG_SCALE = 2;

/** @type {WeakMap<HTMLCanvasElement, (canvas: any) => any>} the last call that drew each plot */
const calls = new WeakMap();

/**
 * Draw plot `canvas` with `draw(canvas)` (a plot function's call) and remember it for downloads;
 * returns what `draw` returns.
 * @template T @param {HTMLCanvasElement} canvas @param {(canvas: any) => T} draw @returns {T}
 */
export function plotOn(canvas, draw) {
  calls.set(canvas, draw);
  return draw(canvas);
}

/** A stand-in for the canvas while a download is drawn: the page's canvas keeps its attributes. */
function standIn() {
  const attrs = new Map();
  return { title: '', dataset: {}, setAttribute: (k, v) => attrs.set(k, v), getAttribute: (k) => attrs.get(k) ?? '' };
}

/** The plot's size on the page, css px. */
function sizeOf(canvas) {
  return { w: canvas.clientWidth || 320, h: canvas.clientHeight || 200 };
}

/**
 * Plot `canvas` as a PNG blob, `scale` × its size on the page.
 * @param {HTMLCanvasElement} canvas @param {number} [scale] @returns {Promise<Blob>}
 */
export function plotPng(canvas, scale = PNG_SCALE) {
  const draw = calls.get(canvas);
  if (!draw) return Promise.reject(new Error(`${canvas.id}: nothing drawn yet`));
  const { w, h } = sizeOf(canvas);
  const out = document.createElement('canvas');
  out.width = Math.round(w * scale);
  out.height = Math.round(h * scale);
  drawInto({ ctx: out.getContext('2d'), w, h, scale }, () => draw(standIn()));
  return new Promise((resolve, reject) => out.toBlob((b) => (b ? resolve(b) : reject(new Error(`${canvas.id}: the PNG could not be made`))), 'image/png'));
}

/**
 * Plot `canvas` as an SVG document (text): its <title> the plot's title, the title, key and data
 * in groups of those ids.
 * @param {HTMLCanvasElement} canvas @returns {string}
 */
export function plotSvg(canvas) {
  const draw = calls.get(canvas);
  if (!draw) throw new Error(`${canvas.id}: nothing drawn yet`);
  const { w, h } = sizeOf(canvas);
  const svg = svgNode('svg', { xmlns: 'http://www.w3.org/2000/svg', width: w, height: h, viewBox: `0 0 ${w} ${h}` });
  const title = svgNode('title', {}, svg);
  const defs = svgNode('defs', {}, svg);
  const ctx = new SvgContext(svg, defs, { idPrefix: `${canvas.id}-clip` });
  const stand = standIn();
  drawInto({ ctx, w, h, scale: 1 }, () => draw(stand));
  ctx.finish();
  title.textContent = stand.dataset.title || canvas.dataset.title || '';
  if (!defs.firstChild) defs.remove();
  return `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(svg)}\n`;
}

/** A file name from the plot's title: "planarium-planning-time.png". */
export function plotFileName(canvas, ext) {
  const words = (canvas.dataset.title || canvas.id).toLowerCase().replace(/\(.*?\)|;.*$/g, '').match(/[a-z0-9*]+/g) ?? ['plot'];
  return `planarium-${words.join('-').replace(/\*/g, '-star').slice(0, 60)}.${ext}`;
}

/**
 * Put each plot canvas of `canvases` in a card with its "PNG" and "SVG" buttons (a hidden canvas
 * hides its card). `onError(message)` shows a download that failed.
 * @param {HTMLCanvasElement[]} canvases @param {(message: string) => void} onError
 */
export function addPlotDownloads(canvases, onError) {
  for (const canvas of canvases) {
    const png = el('button', { type: 'button', text: 'PNG', className: 'plot-png' });
    const svg = el('button', { type: 'button', text: 'SVG', className: 'plot-svg' });
    const card = el('figure', { className: 'plot-card' });
    canvas.replaceWith(card);
    const bar = el('div', { className: 'plot-downloads' }, el('span', { className: 'hint', text: 'Download' }), png, svg);
    card.append(canvas, bar);
    const what = () => canvas.dataset.title || canvas.id;
    png.title = `This plot as a PNG image, ${PNG_SCALE}× its size here`;
    svg.title = 'This plot as an SVG drawing';
    png.setAttribute('aria-label', 'Download this plot as PNG');
    svg.setAttribute('aria-label', 'Download this plot as SVG');
    png.addEventListener('click', () => {
      plotPng(canvas).then((b) => downloadBlob(b, plotFileName(canvas, 'png')), (e) => onError(`${what()}: ${e.message}`));
    });
    svg.addEventListener('click', () => {
      try {
        downloadBlob(new Blob([plotSvg(canvas)], { type: 'image/svg+xml' }), plotFileName(canvas, 'svg'));
      } catch (e) { onError(`${what()}: ${e.message}`); }
    });
  }
}

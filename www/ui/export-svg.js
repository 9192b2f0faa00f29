// The SVG export (exports.js): the canvas's own drawing recorded as SVG. The layers of
// draw/picture.js, the list the canvas composites, are drawn in the same order by the same
// functions on an SVG-recording context (draw/svg-context.js), a <g id> a layer (paths merged per
// layer and style; no HTML from data: elements built with DOM calls, then serialised). What only
// the SVG has is here: the title, the legend band under the picture, and the notes on what was
// drawn otherwise. A generator (sceneSvgSteps) yields after every EXPORT_BATCH records or nodes,
// so the page can draw it in steps between frames. Cells beyond SVG_MAX_CELLS (grid search's
// million on a large map) are one embedded PNG image of the cells layer, drawn by the canvas's
// own code at twice the resolution: a polygon a cell made a 145 MB file.

import { PALETTE } from '../draw/palette.js';
import { Layout, makeLayer } from '../draw/transform.js';
import { CellsDrawing } from '../draw/cells.js';
import { EXPORT_BATCH, redrawWork } from '../draw/redraw.js';
import { PICTURE, bestOf } from '../draw/picture.js';
import { SvgContext, svgNode as node, fmt, paint } from '../draw/svg-context.js';
import { LEGEND_TEXT, frameShown, legendLayout, measure } from './export-legend.js';

const SVG_NS = 'http://www.w3.org/2000/svg';
const XLINK_NS = 'http://www.w3.org/1999/xlink';
/** Cells and heat-map tiles drawn as SVG paths; more are one embedded image of the layer. */
export const SVG_MAX_CELLS = 20000;
/** The embedded cells image: device px per css px, and its longest side. */
const CELLS_IMAGE_SCALE = 2;
const CELLS_IMAGE_MAX = 4096;

/** Work counted in units (records, nodes, cells): add() says when a step of `batch` units ended. */
class Work {
  constructor(total, batch) { this.total = Math.max(1, total); this.batch = batch; this.done = 0; this.next = batch; }
  add(n = 1) {
    this.done += n;
    if (this.done < this.next) return false;
    this.next = this.done + this.batch;
    return true;
  }
  get share() { return Math.min(1, this.done / this.total); }
}

/** SVG attributes filling with `c`. */
function fill(c) {
  const p = paint(c);
  return { fill: p.colour, 'fill-opacity': p.opacity < 1 ? fmt(p.opacity) : undefined };
}

/** SVG attributes stroking with `c`, `width` px wide (and `dash` [on, off]). */
function stroke(c, width, dash = null) {
  const p = paint(c);
  return { stroke: p.colour, 'stroke-opacity': p.opacity < 1 ? fmt(p.opacity) : undefined, 'stroke-width': fmt(width),
    'stroke-dasharray': dash?.length ? dash.map(fmt).join(' ') : undefined };
}

/** How many cells and tiles the cells layer draws for options `o` (one element each in the SVG). */
function cellElements(m, o) {
  return (o.showCells ? m.order.length : 0) + (o.showHeat ? m.field.length + (o.showCells ? m.changed.length : 0) : 0)
    + (o.showArrows ? m.field.length : 0);
}

/**
 * The cells layer as one embedded PNG image, drawn by the canvas's own code (cells.js) at
 * CELLS_IMAGE_SCALE device px per css px (its longest side at most CELLS_IMAGE_MAX).
 */
function cellsImage(parent, view) {
  const [w, h] = view.css;
  const scale = Math.min(CELLS_IMAGE_SCALE, CELLS_IMAGE_MAX / Math.max(w, h));
  const L2 = new Layout(view.scenario.bounds, w, h, scale);
  const layer = makeLayer();
  layer.canvas.width = L2.width;
  layer.canvas.height = L2.height;
  new CellsDrawing(layer, view.model).redraw(L2, view.options);
  const url = layer.canvas.toDataURL('image/png');
  layer.canvas.width = 0;
  layer.canvas.height = 0;
  const img = node('image', { x: 0, y: 0, width: w, height: h, preserveAspectRatio: 'none', href: url }, parent);
  img.setAttributeNS(XLINK_NS, 'xlink:href', url); // SVG 1.1 readers
}

/** The legend band under the picture, at y = `top`. */
function legendSvg(svg, items, width, top, transparent) {
  const lay = legendLayout(items, width, measure);
  const g = node('g', { id: 'legend', transform: `translate(0 ${fmt(top)})`, 'font-family': 'system-ui, sans-serif', 'font-size': 12 }, svg);
  if (!transparent) node('rect', { x: 0, y: 0, width, height: fmt(lay.height), fill: PALETTE.background }, g);
  for (const { x, y, item } of lay.at) {
    const { color, shape } = item;
    const line = (w, dash) => node('path', { d: `M${x + 1} ${y}H${x + 15}`, ...stroke(color, w, dash), 'stroke-linecap': 'round' }, g);
    if (shape === 'line') line(2);
    else if (shape === 'dash') line(2, [3, 3]);
    else if (shape === 'thick') line(4);
    else if (shape === 'dot') node('circle', { cx: x + 8, cy: y, r: 4, ...fill(color) }, g);
    else if (shape === 'ring') node('circle', { cx: x + 8, cy: y, r: 4, fill: 'none', ...stroke(color, 2) }, g);
    else if (shape === 'cross') node('path', { d: `M${x + 4} ${y - 4}L${x + 12} ${y + 4}M${x + 4} ${y + 4}L${x + 12} ${y - 4}`, ...stroke(color, 2), 'stroke-linecap': 'round' }, g);
    else node('rect', { x: x + 2, y: y - 5, width: 12, height: 10, ...fill(color) }, g);
    const t = node('text', { x: x + 22, y: fmt(y), 'dominant-baseline': 'middle', fill: LEGEND_TEXT }, g);
    t.textContent = item.label;
  }
  return lay.height;
}

/**
 * The current picture as an SVG document: a generator yielding the share of the work done after
 * every `batch` records or nodes, and returning {text, notes} (notes: what was drawn otherwise
 * than as paths). Drawn as the canvas draws it: every layer of draw/picture.js but those of the
 * page only (rotation handles, rewire flashes, which fade in 0.6 s, and the editors' hooks).
 * `legend`: items under the picture; `transparent`: no background or free-space fill.
 */
export function* sceneSvgSteps(view, { legend = null, transparent = false } = {}, batch = EXPORT_BATCH) {
  const sc = view.scenario;
  if (!view.layout || !sc) throw new Error('nothing to export yet: load a scenario first');
  const m = view.model?.cells;
  const o = view.options;
  const cellsAsImage = !!m && view.cells.active(o) && cellElements(m, o) > SVG_MAX_CELLS;
  const work = new Work(redrawWork(view) + (m ? cellElements(m, o) : 0), batch);
  const notes = [];
  const [w, h] = view.css;
  const L = new Layout(sc.bounds, w, h, 1);
  const legendHeight = legend?.length ? legendLayout(legend, w, measure).height : 0;
  const H = h + legendHeight;
  const svg = node('svg', { xmlns: SVG_NS, width: w, height: fmt(H), viewBox: `0 0 ${w} ${fmt(H)}` });
  node('title', {}, svg).textContent = sc.name ?? 'Planarium';
  const defs = node('defs', {}, svg);
  const ctx = new SvgContext(svg, defs);
  const k = frameShown(view);
  const frames = o.animateRaw && view.rawFrames.length ? view.rawFrames : view.frames;
  const f = { frame: k >= 0 ? frames[k] : null, best: bestOf(view), time: 0, ui: false, batch };
  for (const e of PICTURE) {
    if (e.ui || (transparent && (e.id === 'background' || e.id === 'free'))) continue;
    ctx.beginLayer(e.id, { merge: e.merge, attrs: { class: e.className }, collapse: true });
    if (e.id === 'cells' && cellsAsImage) {
      cellsImage(ctx.top.el, view);
      notes.push(`the cells as an image (${m.order.length.toLocaleString('en')} cells${m.field.length ? `, ${m.field.length.toLocaleString('en')} heat-map tiles` : ''})`);
      work.add(cellElements(m, o));
      yield work.share;
    } else {
      const steps = e.draw(ctx, L, view, f);
      if (steps && typeof steps.next === 'function') for (const n of steps) if (work.add(n)) yield work.share;
    }
    ctx.endLayer();
  }
  ctx.finish();
  if (!defs.firstChild) defs.remove();
  if (legendHeight) legendSvg(svg, legend, w, h, transparent);
  return { text: `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(svg)}\n`, notes };
}

/** The current picture as an SVG document (a string), built at once (sceneSvgSteps). */
export function sceneSvg(view, options = {}) {
  const steps = sceneSvgSteps(view, options, Infinity);
  for (;;) {
    const s = steps.next();
    if (s.done) return s.value.text;
  }
}

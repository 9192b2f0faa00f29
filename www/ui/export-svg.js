// The SVG export (exports.js): the canvas's drawing, element by element, built with DOM calls and
// serialised (no HTML from data). It is built by a generator (sceneSvgSteps) that yields after
// every EXPORT_BATCH records, nodes or cells, so the page can draw it in steps between frames.
// Cells beyond SVG_MAX_CELLS (grid search's million on a large map) are one embedded PNG image of
// the cells layer, drawn by the canvas's own code: a polygon a cell made a 145 MB file.

import { PALETTE, STYLE } from '../draw/palette.js';
import { EventKind, STRIDE } from '../run/events.js';
import { Layout, makeLayer, pointInPolygon } from '../draw/transform.js';
import { robotStyle, outlineOf } from '../draw/robots.js';
import { CellsDrawing, heatScale, cellFill, cellLevel } from '../draw/cells.js';
import { EXPORT_BATCH } from '../draw/redraw.js';
import { LEGEND_TEXT, frameShown, legendLayout, measure } from './export-legend.js';
import { robotDrawing } from '../draw/capabilities.js';

const SVG_NS = 'http://www.w3.org/2000/svg';
const XLINK_NS = 'http://www.w3.org/1999/xlink';
/** Cells and heat-map tiles drawn as SVG elements; more are one embedded image of the layer. */
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

// ---------------------------------------------------------------------------------------------
// SVG: the canvas's drawing, element by element (css px, the canvas at a device pixel ratio of 1)

function node(name, attrs = {}, parent = null) {
  const e = document.createElementNS(SVG_NS, name);
  for (const [k, v] of Object.entries(attrs)) if (v !== undefined && v !== null) e.setAttribute(k, String(v));
  if (parent) parent.append(e);
  return e;
}

const fmt = (v) => (Math.round(v * 100) / 100).toString();

/** A canvas colour as SVG paint: {colour, opacity} ('rgba(r, g, b, a)' split, for SVG 1.1 readers). */
function paint(c) {
  const m = /^rgba?\(\s*([\d.]+)\s*,\s*([\d.]+)\s*,\s*([\d.]+)\s*(?:,\s*([\d.]+)\s*)?\)$/.exec(c);
  if (!m) return { colour: c, opacity: 1 };
  const hex = (v) => Math.round(Number(v)).toString(16).padStart(2, '0');
  return { colour: `#${hex(m[1])}${hex(m[2])}${hex(m[3])}`, opacity: m[4] === undefined ? 1 : Number(m[4]) };
}

/** SVG attributes filling with `c` (times `alpha`). */
function fill(c, alpha = 1) {
  const p = paint(c);
  const o = p.opacity * alpha;
  return { fill: p.colour, 'fill-opacity': o < 1 ? fmt(o) : undefined };
}

/** SVG attributes stroking with `c`, `width` px wide (and `dash` [on, off]). */
function stroke(c, width, dash = null, round = false) {
  const p = paint(c);
  return { stroke: p.colour, 'stroke-opacity': p.opacity < 1 ? fmt(p.opacity) : undefined, 'stroke-width': fmt(width),
    'stroke-dasharray': dash?.length ? dash.map(fmt).join(' ') : undefined,
    'stroke-linecap': round ? 'round' : undefined, 'stroke-linejoin': round ? 'round' : undefined };
}

/** Path data of a polygon (flat [x, y, ...] or [[x, y], ...]), closed or not. */
function polyD(L, pts, close = true) {
  const xy = pts.length && Array.isArray(pts[0]) ? pts : pairs(pts);
  if (!xy.length) return '';
  return xy.map(([x, y], i) => `${i ? 'L' : 'M'}${fmt(L.sx(x))} ${fmt(L.sy(y))}`).join('') + (close ? 'Z' : '');
}

/** Flat [x, y, x, y, ...] → [[x, y], ...]. */
function pairs(flat) {
  const out = [];
  for (let i = 0; i + 1 < flat.length; i += 2) out.push([flat[i], flat[i + 1]]);
  return out;
}

/** A circle as path data (to join many in one path). */
const circleD = (cx, cy, r) => `M${fmt(cx + r)} ${fmt(cy)}A${fmt(r)} ${fmt(r)} 0 1 0 ${fmt(cx - r)} ${fmt(cy)}A${fmt(r)} ${fmt(r)} 0 1 0 ${fmt(cx + r)} ${fmt(cy)}Z`;
/** A square of side `s` at top left (x, y) as path data. */
const squareD = (x, y, s) => `M${fmt(x)} ${fmt(y)}h${fmt(s)}v${fmt(s)}h${fmt(-s)}Z`;

/** One obstacle as an SVG element, as transform.js drawObstacle draws it. */
function obstacleSvg(g, L, ob) {
  const style = { ...fill(PALETTE.obstacle), ...stroke(PALETTE.obstacleEdge, 1.25) };
  if (ob.rect) {
    const [ax, ay, bx, by] = ob.rect;
    const x0 = Math.min(ax, bx), x1 = Math.max(ax, bx), y0 = Math.min(ay, by), y1 = Math.max(ay, by);
    node('rect', { x: fmt(L.sx(x0)), y: fmt(L.sy(y1)), width: fmt((x1 - x0) * L.scale), height: fmt((y1 - y0) * L.scale), ...style }, g);
  } else if (ob.polygon) {
    node('path', { d: polyD(L, ob.polygon), ...style }, g);
  } else if (ob.circle) {
    const [x, y, r] = ob.circle;
    node('circle', { cx: fmt(L.sx(x)), cy: fmt(L.sy(y)), r: fmt(r * L.scale), ...style }, g);
  } else if (ob.segment) {
    const [x0, y0, x1, y1] = ob.segment;
    node('path', { d: polyD(L, [[x0, y0], [x1, y1]], false), fill: 'none', ...stroke(PALETTE.obstacleEdge, 3), 'stroke-linecap': 'round' }, g);
  }
}

/** A polyline of world points [[x, y], ...] as drawPolyline draws it (round joins and caps). */
function polylineSvg(parent, L, pts, colour, width, dash = null, attrs = {}) {
  if (!pts || pts.length < 2) return null;
  return node('path', { d: polyD(L, pts, false), fill: 'none', ...stroke(colour, width, dash, true), ...attrs }, parent);
}

/** A robot (robots.js drawRobotShape) at `state` with outline `polys` in style `st`. */
function robotSvg(parent, L, robot, polys, state, st, cls) {
  const drawing = robotDrawing(robot);
  const g = node('g', { class: cls }, parent);
  if (!polys || !polys.length) {
    if (!state || state.length < 2) return;
    node('circle', { cx: fmt(L.sx(state[0])), cy: fmt(L.sy(state[1])), r: fmt(st.dot), ...fill(st.fill), ...stroke(st.edge, 1) }, g);
    return;
  }
  const p = polys[0];
  if (drawing === 'linkage') {
    if (p.length < 4) return;
    node('path', { d: polyD(L, p, false), fill: 'none', ...stroke(st.line, st.width, null, true) }, g);
    let len = 0;
    for (let i = 2; i < p.length; i += 2) len += Math.hypot(p[i] - p[i - 2], p[i + 1] - p[i - 1]);
    const avg = (len * L.scale) / Math.max(1, p.length / 2 - 1);
    const r = Math.max(1.2, Math.min(3, st.width * 0.6, avg * 0.12));
    let d = '';
    for (let i = 2; i < p.length; i += 2) d += circleD(L.sx(p[i]), L.sy(p[i + 1]), r);
    node('path', { d, ...fill(st.edge) }, g);
    node('rect', { x: fmt(L.sx(p[0]) - 4.5), y: fmt(L.sy(p[1]) - 4.5), width: 9, height: 9, ...fill(st.edge) }, g);
  } else if (drawing === 'chain') {
    const n = p.length / 2;
    if (n >= 2) node('path', { d: polyD(L, p, false), fill: 'none', ...stroke(st.stroke, 2.5), 'stroke-linecap': 'round' }, g);
    if (n >= 3) node('path', { d: polyD(L, [[p[2 * n - 2], p[2 * n - 1]], [p[0], p[1]]], false), fill: 'none', ...stroke(st.stroke, 1.5, [4, 3]), 'stroke-linecap': 'round' }, g);
    let d = '';
    for (let i = 0; i < n; i++) d += circleD(L.sx(p[2 * i]), L.sy(p[2 * i + 1]), st.dot * 0.6);
    node('path', { d, ...fill(st.fill), ...stroke(st.edge, 1) }, g);
  } else {
    node('path', { d: polys.map((q) => polyD(L, q)).join(''), ...fill(st.fill, st.alpha), ...stroke(st.stroke, st.strokeWidth) }, g);
  }
}

/** Samples and raw tries (view.js drawUnder), when their overlays are on. */
function* samplesSvg(svg, view, L, work) {
  const { showAccepted, showRejected, showTries } = view.options;
  if (!showAccepted && !showRejected && !showTries) return;
  const acc = [], rej = [], tries = [[], []];
  const as = Math.max(2, Math.round(2.5)), rs = Math.max(1, Math.round(STYLE[EventKind.SAMPLE_REJECTED].size));
  const ts = Math.max(1, Math.round(STYLE[EventKind.SAMPLE_TRY].size));
  const sq = (out, x, y, s) => out.push(squareD(Math.round(L.sx(x) - s / 2), Math.round(L.sy(y) - s / 2), s));
  let pending = null;
  for (const [d, o0, o1] of view.store.spans(0, view.store.length)) for (let o = o0; o < o1; o += STRIDE) {
    const kind = d[o];
    if (kind === EventKind.SAMPLE) {
      if (pending && showAccepted) sq(acc, ...pending, as);
      pending = [d[o + 4], d[o + 5]];
    } else if (kind === EventKind.SAMPLE_REJECTED) {
      pending = null;
      if (showRejected) sq(rej, d[o + 4], d[o + 5], rs);
    } else if (kind === EventKind.SAMPLE_TRY && showTries) sq(tries[d[o + 2] > 0 ? 1 : 0], d[o + 4], d[o + 5], ts);
    if (work.add()) yield work.share;
  }
  if (pending && showAccepted && view.showResult) sq(acc, ...pending, as);
  const g = node('g', { id: 'samples' }, svg);
  const cols = STYLE[EventKind.SAMPLE_TRY].colors;
  /** @type {Array<[string[], string]>} */
  const layers = [[rej, STYLE[EventKind.SAMPLE_REJECTED].color], [tries[0], cols[0]], [tries[1], cols[1]], [acc, PALETTE.accepted]];
  for (const [parts, colour] of layers) {
    if (parts.length) node('path', { d: parts.join(''), ...fill(colour) }, g);
  }
}

/** The visibility graph's clear edges (view.js drawUnder), one path. */
function* graphSvg(svg, view, L, work) {
  let d = '';
  for (const [r, o0, o1] of view.store.spans(0, view.store.length)) for (let o = o0; o < o1; o += STRIDE) {
    if (r[o] === EventKind.GRAPH_EDGE && r[o + 9] > 0) d += `M${fmt(L.sx(r[o + 4]))} ${fmt(L.sy(r[o + 5]))}L${fmt(L.sx(r[o + 6]))} ${fmt(L.sy(r[o + 7]))}`;
    if (work.add()) yield work.share;
  }
  const st = STYLE[EventKind.GRAPH_EDGE];
  if (d) node('path', { id: 'graph', d, fill: 'none', ...stroke(st.color, st.width) }, svg);
}

/** The cells' × marks (step-blocked cells) of cells `list`, as path data. */
function cellMarksD(L, list) {
  let d = '';
  for (const c of list) {
    const r = Math.max(2.5, Math.min(6, 0.3 * c.radius * L.scale));
    let x = c.x, y = c.y; // the cell's centre, else its corners' mean (as cells.js centreOf)
    if (!pointInPolygon(x, y, c.pts)) {
      x = 0; y = 0;
      for (let i = 0; i + 1 < c.pts.length; i += 2) { x += c.pts[i]; y += c.pts[i + 1]; }
      x /= c.pts.length / 2; y /= c.pts.length / 2;
    }
    const sx = L.sx(x), sy = L.sy(y);
    d += `M${fmt(sx - r)} ${fmt(sy - r)}L${fmt(sx + r)} ${fmt(sy + r)}M${fmt(sx - r)} ${fmt(sy + r)}L${fmt(sx + r)} ${fmt(sy - r)}`;
  }
  return d;
}

const cellPoints = (L, c) => pairs(c.pts).map(([x, y]) => `${fmt(L.sx(x))},${fmt(L.sy(y))}`).join(' ');

/** How many cells and tiles the cells layer draws for options `o` (one element each in the SVG). */
function cellElements(m, o) {
  return (o.showCells ? m.order.length : 0) + (o.showHeat ? m.field.length + (o.showCells ? m.changed.length : 0) : 0)
    + (o.showArrows ? m.field.length : 0);
}

/**
 * The cells layer as one embedded PNG image, drawn by the canvas's own code (cells.js) at
 * CELLS_IMAGE_SCALE device px per css px (its longest side at most CELLS_IMAGE_MAX).
 */
function cellsImage(svg, view) {
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
  const img = node('image', { id: 'cells', x: 0, y: 0, width: w, height: h, preserveAspectRatio: 'none', href: url }, svg);
  img.setAttributeNS(XLINK_NS, 'xlink:href', url); // SVG 1.1 readers
}

/**
 * The cells layer (cells.js redraw): cells filled by label and level or verdict, × marks; the
 * heat map over them, then the judged cells' outlines and marks again; descent arrows; then the
 * obstacles veiled over it all. More than SVG_MAX_CELLS elements: one image (`notes` says so).
 */
function* cellsSvg(svg, view, L, work, notes) {
  const m = view.model?.cells;
  const o = view.options;
  if (!m || !view.cells.active(o)) return;
  const elements = cellElements(m, o);
  if (elements > SVG_MAX_CELLS) {
    cellsImage(svg, view);
    notes.push(`the cells as an image (${m.order.length.toLocaleString('en')} cells${m.field.length ? `, ${m.field.length.toLocaleString('en')} heat-map tiles` : ''})`);
    work.add(elements);
    yield work.share;
  } else yield* cellElementsSvg(svg, view, L, work);
  const veil = node('g', { id: 'veil', 'fill-opacity': 0.6, 'stroke-opacity': 0.6 }, svg);
  for (const ob of view.scenario.obstacles) obstacleSvg(veil, L, ob);
}

/** The cells layer, an element a cell or tile (cellsSvg). */
function* cellElementsSvg(svg, view, L, work) {
  const m = view.model.cells;
  const o = view.options;
  const st = STYLE[EventKind.CELL];
  const marks = (ids, id) => {
    const d = cellMarksD(L, ids.map((k) => m.cells.get(k)).filter((c) => c?.done && c.state === 1));
    if (!d) return;
    const mg = node('g', { id, fill: 'none' }, svg);
    node('path', { d, ...stroke('#ffffff', 3.5) }, mg);
    node('path', { d, ...stroke(PALETTE.cellBlockedMark, 1.75) }, mg);
  };
  if (o.showCells) {
    const g = node('g', { id: 'cells' }, svg);
    for (const id of m.order) {
      const c = m.cells.get(id);
      if (!c || !c.done) continue;
      node('polygon', { points: cellPoints(L, c), ...fill(cellFill(c, o.showHeat)), ...stroke(PALETTE.cellEdge, st.widths[cellLevel(c)]) }, g);
      if (work.add()) yield work.share;
    }
    marks(m.order, 'cell-marks');
  }
  if (o.showHeat && m.field.length) {
    const bin = heatScale(m.field);
    const byColour = new Map();
    for (const s of m.field) {
      const k = bin(s.v);
      const col = k < 0 ? PALETTE.obstacle : PALETTE.heat[k];
      if (!byColour.has(col)) byColour.set(col, []);
      byColour.get(col).push(s);
    }
    const hex = m.cells.size > 0;
    const g = node('g', { id: 'heat' }, svg);
    for (const [col, list] of byColour) {
      const d = list.map((s) => {
        const c = hex ? m.cells.get(s.id) : null;
        if (c && c.done) return polyD(L, c.pts);
        const h = s.half * L.scale;
        return squareD(L.sx(s.x) - h, L.sy(s.y) - h, 2 * h);
      }).join('');
      node('path', { d, ...fill(col), ...(hex ? stroke(PALETTE.cellEdge, 0.75) : {}) }, g);
    }
    if (o.showCells) { // the judged cells' outlines and marks, over the heat map
      const g2 = node('g', { id: 'judged', fill: 'none' }, svg);
      for (const id of m.changed) {
        const c = m.cells.get(id);
        if (c?.done) node('polygon', { points: cellPoints(L, c), ...stroke(PALETTE.cellEdge, st.widths[cellLevel(c)]) }, g2);
      }
      marks(m.changed, 'judged-marks');
    }
  }
  if (o.showArrows && m.field.length) {
    const gap = 14; // css px: cells.js ARROW_GAP
    const taken = new Set();
    let d = '';
    for (const s of m.field) {
      if (!(s.dx || s.dy)) continue;
      const sx = L.sx(s.x), sy = L.sy(s.y);
      const key = `${Math.floor(sx / gap)},${Math.floor(sy / gap)}`;
      if (taken.has(key)) continue;
      taken.add(key);
      const len = Math.max(6, Math.min(18, 0.7 * s.half * L.scale));
      const ex = sx + s.dx * len, ey = sy - s.dy * len;
      const hx = -s.dx * len * 0.35, hy = s.dy * len * 0.35;
      d += `M${fmt(sx)} ${fmt(sy)}L${fmt(ex)} ${fmt(ey)}M${fmt(ex + hx - hy * 0.6)} ${fmt(ey + hy + hx * 0.6)}L${fmt(ex)} ${fmt(ey)}L${fmt(ex + hx + hy * 0.6)} ${fmt(ey + hy - hx * 0.6)}`;
    }
    if (d) node('path', { id: 'arrows', d, fill: 'none', ...stroke(PALETTE.arrow, 1.1) }, svg);
  }
}


/** The trees (view.js redrawTreeLayer): edges, node squares, exhausted nodes. */
function* treesSvg(svg, view, L, work) {
  const trees = view.model?.trees ?? [];
  const edge = STYLE[EventKind.NODE_ADDED];
  const size = Math.max(1, Math.round(edge.size));
  const attempt = view.model ? view.model.cells.attempt : -1;
  for (let k = 0; k < trees.length; k++) {
    const t = trees[k];
    const colour = edge.colors[view.treeGroup(k)];
    const opacity = attempt > k ? 0.3 : undefined;
    let edges = '', nodes = '';
    for (let i = 0; i < t.n; i++) {
      if (!t.known(i)) continue;
      const p = t.parent[i];
      const x = L.sx(t.x[i]), y = L.sy(t.y[i]);
      if (p >= 0 && t.known(p)) edges += `M${fmt(L.sx(t.x[p]))} ${fmt(L.sy(t.y[p]))}L${fmt(x)} ${fmt(y)}`;
      if (p >= 0) nodes += squareD(Math.round(x - size / 2), Math.round(y - size / 2), size);
      if (work.add()) yield work.share;
    }
    // the canvas fills the node squares as it goes and strokes the edges last: nodes under edges
    if (nodes) node('path', { class: 'nodes', d: nodes, opacity, ...fill(colour) }, svg);
    const g = node('g', { id: `tree-${k}`, opacity }, svg);
    if (edges) node('path', { d: edges, fill: 'none', ...stroke(colour, edge.width) }, g);
    if (view.options.showExhausted && t.exhausted) {
      const s = Math.max(3, Math.round(STYLE[EventKind.EXHAUSTED].size));
      let d = '';
      for (let i = 0; i < t.n; i++) {
        if (t.known(i) && t.isExhausted(i)) d += squareD(Math.round(L.sx(t.x[i]) - s / 2) + 0.5, Math.round(L.sy(t.y[i]) - s / 2) + 0.5, s);
      }
      if (d) node('path', { class: 'exhausted', d, ...fill(PALETTE.exhausted), ...stroke(PALETTE.exhaustedEdge, 1) }, svg);
    }
  }
}

/** Dynamic-domain circles (one path: overlapping discs do not darken), clipped to the bounds. */
function* domainsSvg(svg, view, L, work) {
  if (!view.options.showDomains || !view.model) return;
  let d = '';
  for (const t of view.model.trees) {
    if (!t.domains) continue;
    for (let i = 0; i < t.n; i++) {
      const r = t.radius[i];
      if (Number.isFinite(r) && t.known(i)) d += circleD(L.sx(t.x[i]), L.sy(t.y[i]), r * L.scale);
      if (work.add()) yield work.share;
    }
  }
  if (d) node('path', { id: 'domains', d, 'clip-path': 'url(#bounds-clip)', ...fill('rgba(140, 81, 10, 0.06)'), ...stroke(STYLE[EventKind.DOMAIN].color, STYLE[EventKind.DOMAIN].width) }, svg);
}

/** Blocked motions (crosses), when their overlay is on. */
function* collisionsSvg(svg, view, L, work) {
  if (!view.options.showCollisions) return;
  const col = STYLE[EventKind.COLLISION];
  const cs = col.size;
  let d = '';
  for (const [dd, o0, o1] of view.store.spans(0, view.store.length)) for (let o = o0; o < o1; o += STRIDE) {
    if (work.add()) yield work.share;
    if (dd[o] !== EventKind.COLLISION) continue;
    const x = L.sx(dd[o + 4]), y = L.sy(dd[o + 5]);
    d += `M${fmt(x - cs)} ${fmt(y - cs)}L${fmt(x + cs)} ${fmt(y + cs)}M${fmt(x - cs)} ${fmt(y + cs)}L${fmt(x + cs)} ${fmt(y - cs)}`;
  }
  if (d) node('path', { id: 'collisions', d, fill: 'none', ...stroke(col.color, col.width) }, svg);
}

/** Inspection points (robots.js drawInspection): diamonds, the seen ones lit. */
function inspectionSvg(svg, view, L) {
  const points = view.scenario.inspection?.points;
  if (!points?.length) return;
  const seen = view.options.showSeen && view.model ? view.model.seen : null;
  const lit = (i) => !!(seen && seen.has(i));
  const diamonds = (r, pick) => points.map(([x, y], i) => (pick(i)
    ? `M${fmt(L.sx(x))} ${fmt(L.sy(y) - r)}L${fmt(L.sx(x) + r)} ${fmt(L.sy(y))}L${fmt(L.sx(x))} ${fmt(L.sy(y) + r)}L${fmt(L.sx(x) - r)} ${fmt(L.sy(y))}Z` : '')).join('');
  const g = node('g', { id: 'inspection' }, svg);
  const dim = diamonds(4, (i) => !lit(i));
  if (dim) node('path', { d: dim, ...fill(PALETTE.inspection), ...stroke(PALETTE.robotEdge, 1) }, g);
  if (!seen?.size) return;
  node('path', { d: points.map(([x, y], i) => (lit(i) ? circleD(L.sx(x), L.sy(y), 9) : '')).join(''), ...fill('rgba(255, 212, 0, 0.3)') }, g);
  node('path', { d: diamonds(6, lit), ...fill(PALETTE.seen), ...stroke(PALETTE.robotEdge, 1) }, g);
}

/** Regions of influence and local minima (cells.js drawTop). */
function cellsTopSvg(svg, view, L) {
  const m = view.model?.cells;
  if (!m || m.empty) return;
  const o = view.options;
  if (o.showRegion && m.regions.length) {
    const st = STYLE[EventKind.REGION];
    const g = node('g', { id: 'regions', 'clip-path': 'url(#bounds-clip)', fill: 'none' }, svg);
    m.regions.forEach((r, i) => {
      const last = i === m.regions.length - 1;
      node('circle', { cx: fmt(L.sx(r.x)), cy: fmt(L.sy(r.y)), r: fmt(r.radius * L.scale), opacity: last ? undefined : 0.35, ...stroke(st.color, last ? st.width : 1.25, [7, 5]) }, g);
    });
  }
  const st = STYLE[EventKind.MINIMUM];
  for (const p of m.minima) {
    const x = L.sx(p.x), y = L.sy(p.y);
    const g = node('g', { class: 'minimum' }, svg);
    node('circle', { cx: fmt(x), cy: fmt(y), r: st.size, fill: 'none', ...stroke('#ffffff', st.width + 2.5) }, g);
    node('circle', { cx: fmt(x), cy: fmt(y), r: st.size, fill: 'none', ...stroke(st.color, st.width) }, g);
    const label = p.escapes > 0 ? `local minimum (${p.escapes} escapes)` : 'local minimum';
    const t = node('text', { x: fmt(x + st.size + 6), y: fmt(y), 'dominant-baseline': 'middle', 'font-family': 'system-ui, sans-serif', 'font-size': 12, 'font-weight': 600, fill: st.color, stroke: '#ffffff', 'stroke-width': 3, 'paint-order': 'stroke' }, g);
    t.textContent = label;
  }
}

/** The legend band under the picture, at y = `top`. */
function legendSvg(svg, items, width, top) {
  const lay = legendLayout(items, width, measure);
  const g = node('g', { id: 'legend', transform: `translate(0 ${fmt(top)})`, 'font-family': 'system-ui, sans-serif', 'font-size': 12 }, svg);
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
 * every `batch` records, nodes or cells, and returning {text, notes} (notes: what was drawn
 * otherwise than element by element). Drawn as the canvas draws it: background,
 * free space, obstacles and bounds; cells (with the obstacles veiled over them); samples and
 * tries, dynamic domains, trees, blocked motions (each when its overlay is on); inspection
 * points, start and goal, markers, the best branch, the region of influence and local minima,
 * the raw and smoothed paths, the robot where the canvas shows it and its t/2 circle; the heat
 * map and descent arrows when they are on. Not drawn: rewire flashes (they fade in 0.6 s) and
 * the sensor's wedge. `legend`: items under the picture; `transparent`: no background or
 * free-space fill.
 */
export function* sceneSvgSteps(view, { legend = null, transparent = false } = {}, batch = EXPORT_BATCH) {
  const sc = view.scenario;
  if (!view.layout || !sc) throw new Error('nothing to export yet: load a scenario first');
  const nodes = (view.model?.trees ?? []).reduce((n, t) => n + t.n, 0);
  const m = view.model?.cells;
  const work = new Work(3 * view.store.length + 2 * nodes + (m ? cellElements(m, view.options) : 0), batch);
  const notes = [];
  const [w, h] = view.css;
  const L = new Layout(sc.bounds, w, h, 1);
  const legendHeight = legend?.length ? legendLayout(legend, w, measure).height : 0;
  const H = h + legendHeight;
  const svg = node('svg', { xmlns: SVG_NS, width: w, height: fmt(H), viewBox: `0 0 ${w} ${fmt(H)}` });
  node('title', {}, svg).textContent = sc.name ?? 'Planarium';
  const [bx0, by0, bx1, by1] = sc.bounds;
  const boundsBox = { x: fmt(L.sx(bx0)), y: fmt(L.sy(by1)), width: fmt((bx1 - bx0) * L.scale), height: fmt((by1 - by0) * L.scale) };
  const clip = node('clipPath', { id: 'bounds-clip' }, node('defs', {}, svg));
  node('rect', boundsBox, clip);
  if (!transparent) {
    node('rect', { id: 'background', x: 0, y: 0, width: w, height: fmt(H), fill: PALETTE.background }, svg);
    node('rect', { id: 'free', ...boundsBox, fill: PALETTE.free }, svg);
  }
  const obs = node('g', { id: 'obstacles' }, svg);
  for (const ob of sc.obstacles ?? []) obstacleSvg(obs, L, ob);
  node('rect', { id: 'bounds', ...boundsBox, fill: 'none', ...stroke(PALETTE.bounds, 1.5) }, svg);
  yield* cellsSvg(svg, view, L, work, notes);
  yield* samplesSvg(svg, view, L, work);
  yield* graphSvg(svg, view, L, work);
  yield* domainsSvg(svg, view, L, work);
  yield* treesSvg(svg, view, L, work);
  yield* collisionsSvg(svg, view, L, work);
  inspectionSvg(svg, view, L);
  for (const which of ['start', 'goal']) {
    const state = view.stateOf(which);
    if (!state) continue;
    const polys = view.preview[which] ? outlineOf(sc.robot, state) : view[which];
    robotSvg(svg, L, sc.robot, polys, state, robotStyle(PALETTE[which], which, PALETTE), which);
  }
  for (const [kind, x, y] of view.markers) {
    const st = STYLE[kind];
    if (st.shape === 'ring') node('circle', { class: 'marker', cx: fmt(L.sx(x)), cy: fmt(L.sy(y)), r: st.size, fill: 'none', ...stroke(st.color, st.width) }, svg);
    else node('circle', { class: 'marker', cx: fmt(L.sx(x)), cy: fmt(L.sy(y)), r: st.size, ...fill(st.color) }, svg);
  }
  const best = view.options.showBest && view.model ? view.model.bestBranch() : [];
  if (best.length >= 2) {
    const g = node('g', { id: 'best' }, svg);
    polylineSvg(g, L, best, PALETTE.bestCasing, 6);
    polylineSvg(g, L, best, PALETTE.best, 3.5);
  }
  if (!view.showResult && view.lastSample) {
    const st = STYLE[EventKind.SAMPLE];
    node('circle', { id: 'last-sample', cx: fmt(L.sx(view.lastSample[0])), cy: fmt(L.sy(view.lastSample[1])), r: st.size, ...fill(st.color) }, svg);
  }
  cellsTopSvg(svg, view, L);
  if (view.showResult && view.path?.length) polylineSvg(svg, L, view.path, PALETTE.rawPath, 2, [6, 4], { id: 'raw-path' });
  if (view.showResult && view.smoothed?.length) {
    polylineSvg(svg, L, view.smoothed, PALETTE.pathCasing, 6, null, { id: 'smoothed-casing' });
    polylineSvg(svg, L, view.smoothed, PALETTE.smoothPath, 4, null, { id: 'smoothed-path' });
  }
  const k = frameShown(view);
  if (k >= 0) {
    const list = view.options.animateRaw && view.rawFrames.length ? view.rawFrames : view.frames;
    robotSvg(svg, L, sc.robot, list[k].polys, list[k].state, robotStyle(null, 'robot', PALETTE), 'robot');
    const m = view.model?.cells, q = list[k].state;
    if (m && view.options.showRegion && q?.length >= 2 && m.t > 0) { // the robot's t/2 circle (cells.js drawRobotT)
      node('circle', { id: 'robot-t', cx: fmt(L.sx(q[0])), cy: fmt(L.sy(q[1])), r: fmt((m.t / 2) * L.scale), fill: 'none', ...stroke(PALETTE.robotT, 1.5, [4, 3]) }, svg);
    }
  }
  if (legendHeight) legendSvg(svg, legend, w, h);
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

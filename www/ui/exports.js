// Exports for slides: a PNG of the canvas at a chosen size, an SVG of the current picture (the
// scene, cells, trees, paths, start and goal) and a WebM recording of the canvas (MediaRecorder).
// Each returns a Blob; the page decides where it goes (a download link). No HTML from data: the
// SVG is built with DOM calls and serialised.

import { PALETTE } from '../draw/palette.js';
import { downloadBlob } from '../draw/stage.js';

const SVG_NS = 'http://www.w3.org/2000/svg';

/**
 * The canvas redrawn `width` pixels wide (height by the scene's aspect) as a PNG Blob: the view
 * is laid out at that pixel ratio, rendered, copied, and restored.
 */
export async function pngBlob(view, width) {
  const { box, dpr } = view;
  if (!box || !view.layout) throw new Error('nothing to export yet');
  const scale = width / view.css[0];
  view.resize(box[0], box[1], scale);
  view.dirty = true;
  view.render(performance.now(), 1);
  const out = document.createElement('canvas');
  out.width = view.canvas.width;
  out.height = view.canvas.height;
  out.getContext('2d').drawImage(view.canvas, 0, 0);
  view.resize(box[0], box[1], dpr);
  view.dirty = true;
  view.render(performance.now(), 1);
  return new Promise((resolve, reject) => out.toBlob((b) => (b ? resolve(b) : reject(new Error('the PNG could not be made'))), 'image/png'));
}

function node(name, attrs = {}, parent = null) {
  const e = document.createElementNS(SVG_NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (parent) parent.append(e);
  return e;
}

const fmt = (v) => (Math.round(v * 1e4) / 1e4).toString();

/** `x,y x,y ...` in screen units of layout `L` (css pixels) for world points [[x, y], ...]. */
function points(L, pts) {
  return pts.map(([x, y]) => `${fmt(L.sx(x) / L.dpr)},${fmt(L.sy(y) / L.dpr)}`).join(' ');
}

/** Flat [x, y, x, y, ...] → [[x, y], ...]. */
function pairs(flat) {
  const out = [];
  for (let i = 0; i + 1 < flat.length; i += 2) out.push([flat[i], flat[i + 1]]);
  return out;
}

/** One obstacle of the scenario as an SVG element. */
function obstacle(g, L, ob) {
  const style = { fill: PALETTE.obstacle, stroke: PALETTE.obstacleEdge ?? '#333', 'stroke-width': 1 };
  if (ob.rect) {
    const [x0, y0, x1, y1] = ob.rect;
    node('polygon', { points: points(L, [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]), ...style }, g);
  } else if (ob.polygon) {
    node('polygon', { points: points(L, ob.polygon), ...style }, g);
  } else if (ob.circle) {
    const [x, y, r] = ob.circle;
    node('circle', { cx: fmt(L.sx(x) / L.dpr), cy: fmt(L.sy(y) / L.dpr), r: fmt((r * L.scale) / L.dpr), ...style }, g);
  } else if (ob.segment) {
    const [x0, y0, x1, y1] = ob.segment;
    node('polyline', { points: points(L, [[x0, y0], [x1, y1]]), fill: 'none', stroke: PALETTE.obstacle, 'stroke-width': 2 }, g);
  }
}

/** The colour a cell is drawn in, by label and verdict (as the cells layer does). */
function cellFill(c) {
  if (c.state === 2) return PALETTE.cellVisited;
  if (c.state === 1) return PALETTE.cellBlocked;
  if (c.label === 2) return PALETTE.cellFull;
  if (c.label === 1) return PALETTE.cellMixed;
  const free = PALETTE.cellFree;
  return Array.isArray(free) ? free[Math.min(c.level, free.length - 1)] : free;
}

/**
 * The current picture as an SVG document (a string): bounds, cells, obstacles, tree edges, the
 * raw and smoothed paths, start and goal. Vector, so it scales on a slide.
 */
export function sceneSvg(view) {
  const L = view.layout;
  const sc = view.scenario;
  if (!L || !sc) throw new Error('nothing to export yet');
  const [w, h] = view.css;
  const svg = node('svg', { xmlns: SVG_NS, width: w, height: h, viewBox: `0 0 ${w} ${h}` });
  const title = node('title', {}, svg);
  title.textContent = sc.name ?? 'Planarium';
  node('rect', { x: 0, y: 0, width: w, height: h, fill: PALETTE.background ?? '#ffffff' }, svg);
  const [bx0, by0, bx1, by1] = sc.bounds;
  node('polygon', { points: points(L, [[bx0, by0], [bx1, by0], [bx1, by1], [bx0, by1]]), fill: 'none', stroke: '#666', 'stroke-width': 1 }, svg);
  const cells = view.model?.cells;
  if (cells && cells.order.length && view.options.showCells !== false) {
    const g = node('g', { id: 'cells', stroke: '#8a8270', 'stroke-width': 0.4 }, svg);
    for (const id of cells.order) {
      const c = cells.cells.get(id);
      if (!c?.done || c.pts.length < 3) continue;
      node('polygon', { points: points(L, pairs(c.pts)), fill: cellFill(c) }, g);
    }
  }
  const obs = node('g', { id: 'obstacles' }, svg);
  for (const ob of sc.obstacles ?? []) obstacle(obs, L, ob);
  const trees = view.model?.trees ?? [];
  trees.forEach((t, k) => {
    const g = node('g', { id: `tree-${k}`, stroke: k === 1 ? PALETTE.tree1 : PALETTE.tree0, 'stroke-width': 1, fill: 'none' }, svg);
    const parts = [];
    for (let i = 0; i < t.n; i++) {
      if (!t.known(i)) continue;
      const p = t.parent[i];
      if (p < 0 || !t.known(p)) continue;
      parts.push(`M${fmt(L.sx(t.x[p]) / L.dpr)} ${fmt(L.sy(t.y[p]) / L.dpr)}L${fmt(L.sx(t.x[i]) / L.dpr)} ${fmt(L.sy(t.y[i]) / L.dpr)}`);
    }
    if (parts.length) node('path', { d: parts.join('') }, g);
  });
  if (view.showResult && view.path?.length) {
    node('polyline', { id: 'raw-path', points: points(L, view.path), fill: 'none', stroke: PALETTE.rawPath, 'stroke-width': 2, 'stroke-dasharray': '6 4' }, svg);
  }
  if (view.showResult && view.smoothed?.length) {
    node('polyline', { id: 'smoothed-path', points: points(L, view.smoothed), fill: 'none', stroke: PALETTE.smoothPath, 'stroke-width': 4 }, svg);
  }
  for (const which of ['start', 'goal']) {
    const q = view.stateOf(which);
    if (!q) continue;
    const polys = view.preview?.[which] ? [] : view[which] ?? [];
    if (polys.length && polys[0].length >= 4) {
      const arm = sc.robot?.kind === 'arm';
      for (const flat of polys) {
        const attrs = arm ? { fill: 'none', 'stroke-width': 3 } : { fill: PALETTE[which], 'fill-opacity': 0.6 };
        node(arm ? 'polyline' : 'polygon', { class: which, points: points(L, pairs(flat)), stroke: PALETTE[which], ...attrs }, svg);
      }
    } else {
      node('circle', { class: which, cx: fmt(L.sx(q[0]) / L.dpr), cy: fmt(L.sy(q[1]) / L.dpr), r: 6, fill: PALETTE[which] }, svg);
    }
  }
  return `<?xml version="1.0" encoding="UTF-8"?>\n${new XMLSerializer().serializeToString(svg)}\n`;
}

/** A MIME type this browser's MediaRecorder writes WebM in, or null. */
export function webmType() {
  if (typeof MediaRecorder === 'undefined') return null;
  return ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'].find((t) => MediaRecorder.isTypeSupported(t)) ?? null;
}

/**
 * Record the canvas as WebM until `stop()` is called: returns {stop: () => Promise<Blob>}.
 * The canvas is captured at `fps` frames per second.
 */
export function recordCanvas(canvas, fps = 30) {
  const type = webmType();
  if (!type) throw new Error('this browser cannot record WebM (no MediaRecorder)');
  const stream = canvas.captureStream(fps);
  const rec = new MediaRecorder(stream, { mimeType: type, videoBitsPerSecond: 4e6 });
  const chunks = [];
  rec.ondataavailable = (e) => { if (e.data.size) chunks.push(e.data); };
  rec.start(250);
  return {
    stop: () => new Promise((resolve) => {
      rec.onstop = () => {
        stream.getTracks().forEach((t) => t.stop());
        resolve(new Blob(chunks, { type: 'video/webm' }));
      };
      rec.stop();
    }),
  };
}

/**
 * Wire the page's export controls (#png-width, #export-png, #export-svg, #record, #export-status)
 * to `view` and its `canvas`; `stem()` names the files.
 */
export function wireExports({ view, canvas, stem }) {
  /** @param {string} id @returns {any} the page's element (an input or button) */
  const $ = (id) => document.getElementById(id);
  const status = $('export-status');
  const say = (text) => { status.textContent = text; };
  $('export-png').addEventListener('click', async () => {
    const width = Math.max(100, Math.min(8000, Math.round(Number($('png-width').value) || 1600)));
    try {
      downloadBlob(await pngBlob(view, width), `${stem()}-${width}.png`);
      say(`PNG, ${width} px wide`);
    } catch (e) { say(String(e.message ?? e)); }
  });
  $('export-svg').addEventListener('click', () => {
    try {
      downloadBlob(new Blob([sceneSvg(view)], { type: 'image/svg+xml' }), `${stem()}.svg`);
      say('SVG of the current picture');
    } catch (e) { say(String(e.message ?? e)); }
  });
  const record = $('record');
  let recording = null;
  record.disabled = !webmType();
  if (!webmType()) record.title = 'This browser cannot record WebM';
  record.addEventListener('click', async () => {
    if (recording) {
      const blob = await recording.stop();
      recording = null;
      record.textContent = 'Record WebM';
      record.setAttribute('aria-pressed', 'false');
      downloadBlob(blob, `${stem()}.webm`);
      say(`WebM, ${(blob.size / 1024).toFixed(0)} kB`);
      return;
    }
    try {
      recording = recordCanvas(canvas, 30);
      record.textContent = 'Stop and save';
      record.setAttribute('aria-pressed', 'true');
      say('Recording the canvas…');
    } catch (e) { say(String(e.message ?? e)); }
  });
}

// The workspace canvas's geometry: one Layout owns the world↔screen transform (y up in the world,
// y down on the screen); the flat outlines and frames the worker sends, parsed; offscreen layers;
// and the drawing primitives every layer uses (obstacles, markers, polylines, exhausted nodes).

import { EventKind } from '../run/events.js';
import { PALETTE, STYLE } from './palette.js';

const MARGIN = 10; // css px around the bounds

/** The most the plane's view zooms in (times the fitted scale). */
export const MAX_ZOOM = 256;

/**
 * World ↔ screen (device pixels of the canvas backing store). Without `viewport` the bounds fit
 * the canvas; with {zoom, cx, cy} the fitted scale is multiplied by `zoom` (1 … MAX_ZOOM) and
 * world point (cx, cy) is the canvas's centre.
 */
export class Layout {
  constructor(bounds, cssWidth, cssHeight, dpr, viewport = null) {
    const [x0, y0, x1, y1] = bounds;
    this.bounds = bounds;
    this.dpr = dpr;
    this.width = Math.max(1, Math.round(cssWidth * dpr));
    this.height = Math.max(1, Math.round(cssHeight * dpr));
    const m = MARGIN * dpr;
    this.fitScale = Math.min((this.width - 2 * m) / (x1 - x0), (this.height - 2 * m) / (y1 - y0));
    this.scale = this.fitScale;
    // centre the bounds; screen y grows downward, world y upward
    this.ox = (this.width - this.scale * (x1 - x0)) / 2 - this.scale * x0;
    this.oy = (this.height + this.scale * (y1 - y0)) / 2 + this.scale * y0;
    if (viewport) {
      this.scale = this.fitScale * viewport.zoom;
      this.ox = this.width / 2 - this.scale * viewport.cx;
      this.oy = this.height / 2 + this.scale * viewport.cy;
    }
  }
  /** Whether two layouts put every world point at the same device pixel. */
  same(o) {
    return !!o && o.width === this.width && o.height === this.height && o.scale === this.scale && o.ox === this.ox && o.oy === this.oy;
  }
  /** The css size that keeps the bounds' aspect ratio inside a box of `w` × `h` css px. */
  static fit(bounds, w, h) {
    const aspect = (bounds[2] - bounds[0]) / (bounds[3] - bounds[1]);
    const inner = (cw, ch) => [cw - 2 * MARGIN, ch - 2 * MARGIN];
    let [iw, ih] = inner(w, h);
    if (iw / ih > aspect) iw = ih * aspect; else ih = iw / aspect;
    return [Math.max(40, Math.floor(iw + 2 * MARGIN)), Math.max(40, Math.floor(ih + 2 * MARGIN))];
  }
  sx(x) { return this.ox + x * this.scale; }
  sy(y) { return this.oy - y * this.scale; }
  wx(sx) { return (sx - this.ox) / this.scale; }
  wy(sy) { return (this.oy - sy) / this.scale; }
  /** css px → device px (line widths, marker sizes). */
  px(css) { return css * this.dpr; }
}

/** Flat outlines [n_polygons, n_1, x, y, ..., n_2, ...] → [[x, y, x, y, ...], ...] (and the end index). */
export function parseOutline(flat, at = 0) {
  const polys = [];
  let i = at;
  const count = flat[i++] | 0;
  for (let p = 0; p < count; p++) {
    const n = flat[i++] | 0;
    polys.push(flat.subarray(i, i + 2 * n));
    i += 2 * n;
  }
  return { polys, end: i };
}

/** Frames [dims, count, then per frame: dims state numbers, an outline] → [{state, polys}]. */
export function parseFrames(flat) {
  if (!flat || flat.length < 2) return [];
  const dims = flat[0] | 0;
  const count = flat[1] | 0;
  const frames = [];
  let i = 2;
  for (let k = 0; k < count && i < flat.length; k++) {
    const state = flat.subarray(i, i + dims);
    const { polys, end } = parseOutline(flat, i + dims);
    frames.push({ state, polys });
    i = end;
  }
  return frames;
}

export function makeLayer() {
  const c = document.createElement('canvas');
  return { canvas: c, ctx: c.getContext('2d') };
}

/** Exhausted nodes at flat world points [x, y, ...]: grey squares with a dark edge. */
export function drawExhausted(ctx, L, pts) {
  if (!pts.length) return;
  const ex = STYLE[EventKind.EXHAUSTED];
  const s = Math.max(3, Math.round(L.px(ex.size)));
  ctx.beginPath();
  for (let i = 0; i < pts.length; i += 2) ctx.rect(Math.round(L.sx(pts[i]) - s / 2) + 0.5, Math.round(L.sy(pts[i + 1]) - s / 2) + 0.5, s, s);
  ctx.fillStyle = ex.color;
  ctx.fill();
  ctx.strokeStyle = PALETTE.exhaustedEdge;
  ctx.lineWidth = 1;
  ctx.stroke();
}

export function tracePoly(ctx, L, pts) {
  // pts: [[x, y], ...] or flat [x, y, x, y, ...]
  if (pts.length && Array.isArray(pts[0])) {
    pts.forEach(([x, y], i) => (i ? ctx.lineTo(L.sx(x), L.sy(y)) : ctx.moveTo(L.sx(x), L.sy(y))));
  } else {
    for (let i = 0; i < pts.length; i += 2) {
      if (i) ctx.lineTo(L.sx(pts[i]), L.sy(pts[i + 1])); else ctx.moveTo(L.sx(pts[i]), L.sy(pts[i + 1]));
    }
  }
  ctx.closePath();
}

export function drawObstacle(ctx, L, ob) {
  ctx.fillStyle = PALETTE.obstacle;
  ctx.strokeStyle = PALETTE.obstacleEdge;
  ctx.lineWidth = L.px(1.25);
  ctx.beginPath();
  if (ob.rect) {
    const [ax, ay, bx, by] = ob.rect;
    const x0 = Math.min(ax, bx), x1 = Math.max(ax, bx), y0 = Math.min(ay, by), y1 = Math.max(ay, by);
    ctx.rect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
  } else if (ob.polygon) {
    tracePoly(ctx, L, ob.polygon);
  } else if (ob.circle) {
    const [cx, cy, r] = ob.circle;
    ctx.arc(L.sx(cx), L.sy(cy), r * L.scale, 0, 2 * Math.PI);
  } else if (ob.segment) {
    const [ax, ay, bx, by] = ob.segment;
    ctx.moveTo(L.sx(ax), L.sy(ay));
    ctx.lineTo(L.sx(bx), L.sy(by));
    ctx.lineWidth = L.px(3);
    ctx.lineCap = 'round';
    ctx.stroke();
    ctx.lineCap = 'butt';
    return;
  } else {
    return;
  }
  ctx.fill();
  ctx.stroke();
}

export function drawMarker(ctx, L, style, x, y) {
  const r = L.px(style.size);
  ctx.beginPath();
  if (style.shape === 'ring') {
    ctx.arc(L.sx(x), L.sy(y), r, 0, 2 * Math.PI);
    ctx.strokeStyle = style.color;
    ctx.lineWidth = L.px(style.width);
    ctx.stroke();
  } else {
    ctx.arc(L.sx(x), L.sy(y), r, 0, 2 * Math.PI);
    ctx.fillStyle = style.color;
    ctx.fill();
  }
}

export function drawPolyline(ctx, L, pts, color, width, dash = []) {
  if (!pts || pts.length < 2) return;
  ctx.beginPath();
  pts.forEach(([x, y], i) => (i ? ctx.lineTo(L.sx(x), L.sy(y)) : ctx.moveTo(L.sx(x), L.sy(y))));
  ctx.strokeStyle = color;
  ctx.lineWidth = width;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.setLineDash(dash);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.lineCap = 'butt';
}

/** Whether (x, y) is inside the polygon of flat corners [x, y, x, y, ...] (even-odd rule). */
export function pointInPolygon(x, y, p) {
  let inside = false;
  for (let i = 0, j = p.length - 2; i < p.length; j = i, i += 2) {
    const xi = p[i], yi = p[i + 1], xj = p[j], yj = p[j + 1];
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

// Canvas drawing. One Layout owns the world↔screen transform (y up in the world, y down on the
// screen); a style table keyed by EventKind says how each event record is drawn. Three layers:
//   scene  (offscreen): bounds and obstacles, redrawn on load and resize;
//   tree   (offscreen): edges, rejected samples, collisions, drawn incrementally as records are
//          revealed, redrawn from the stored records only on resize or when a toggle changes;
//   top    (the visible canvas): scene + tree composited, then start/goal, markers, paths and the
//          robot, which are cheap to draw every frame.
// Colours follow the Okabe–Ito palette where it matters (tree 0 / tree 1 / paths), so they stay
// distinguishable with the common colour-vision deficiencies (they also differ in lightness).

import { EventKind, STRIDE } from './events.js';
import { drawRobotShape, drawInspection, robotStyle, outlineOf, footprintRadius } from './robots.js';

export const PALETTE = Object.freeze({
  background: '#eef0f3',
  free: '#ffffff',
  bounds: '#30343b',
  obstacle: '#e4877b',
  obstacleEdge: '#a8362b',
  start: '#e67e00',
  goal: '#009e73',
  tree0: '#1f4e9a',
  tree1: '#cc79a7',
  rejected: '#8a8f98',
  collision: 'rgba(178, 24, 43, 0.7)',
  sample: '#30343b',
  connect: '#111111',
  rawPath: '#ffb000',
  smoothPath: '#e0a800',
  pathCasing: '#3d2f00',
  robot: 'rgba(48, 52, 59, 0.55)',
  robotEdge: '#111111',
  inspection: '#56b4e9',
  handle: '#ffffff',
});

// How each event kind is drawn. `layer`: 'tree' (persistent, incremental) or 'marker' (top layer).
// `toggle` names a view option that must be on for the kind to be drawn.
export const STYLE = Object.freeze({
  [EventKind.SAMPLE]: { layer: 'marker', shape: 'dot', color: PALETTE.sample, size: 3, label: 'latest sample' },
  [EventKind.SAMPLE_REJECTED]: { layer: 'tree', shape: 'square', color: PALETTE.rejected, size: 2, toggle: 'showRejected', label: 'rejected sample' },
  [EventKind.NODE_ADDED]: { layer: 'tree', shape: 'edge', colors: [PALETTE.tree0, PALETTE.tree1], width: 1, size: 2, label: 'tree edge' },
  [EventKind.COLLISION]: { layer: 'tree', shape: 'cross', color: PALETTE.collision, size: 2.5, width: 1, toggle: 'showCollisions', label: 'blocked motion' },
  [EventKind.TREES_CONNECTED]: { layer: 'marker', shape: 'ring', color: PALETTE.connect, size: 7, width: 2, label: 'trees connected' },
  [EventKind.SOLVED]: { layer: 'marker', shape: 'ring', color: PALETTE.goal, size: 10, width: 2, label: 'goal reached' },
});

const MARGIN = 10; // css px around the bounds

/** World ↔ screen (device pixels of the canvas backing store). */
export class Layout {
  constructor(bounds, cssWidth, cssHeight, dpr) {
    const [x0, y0, x1, y1] = bounds;
    this.bounds = bounds;
    this.dpr = dpr;
    this.width = Math.max(1, Math.round(cssWidth * dpr));
    this.height = Math.max(1, Math.round(cssHeight * dpr));
    const m = MARGIN * dpr;
    this.scale = Math.min((this.width - 2 * m) / (x1 - x0), (this.height - 2 * m) / (y1 - y0));
    // centre the bounds; screen y grows downward, world y upward
    this.ox = (this.width - this.scale * (x1 - x0)) / 2 - this.scale * x0;
    this.oy = (this.height + this.scale * (y1 - y0)) / 2 + this.scale * y0;
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

function makeLayer() {
  const c = document.createElement('canvas');
  return { canvas: c, ctx: c.getContext('2d') };
}

export class View {
  /** `store` holds the revealed records ({data, length}); the view reads it to redraw. */
  constructor(canvas, store) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.store = store;
    this.sceneLayer = makeLayer();
    this.treeLayer = makeLayer();
    this.layout = null;
    this.css = [300, 300];
    this.dpr = 1;
    this.scenario = null;
    this.start = [];
    this.goal = [];
    this.options = { showRejected: false, showCollisions: true, animateRaw: false };
    this.preview = { start: null, goal: null }; // states being edited (drawn instead of start/goal)
    this.editable = false;                       // draw the rotation handles of a rigid body
    this.robotState = null;                      // the animated robot's state, after render()
    this.clearRun();
  }

  /** Forget the run's drawing (tree, markers, result). */
  clearRun() {
    this.markers = [];
    this.lastSample = null;
    this.path = null;
    this.smoothed = null;
    this.frames = [];
    this.rawFrames = [];
    this.showResult = false;
    if (this.layout) this.treeLayer.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
    this.dirty = true;
  }

  /** A new scenario (or null: nothing valid to show). */
  setScenario(scenario, start, goal) {
    this.scenario = scenario;
    this.start = scenario ? parseOutline(start).polys : [];
    this.goal = scenario && goal && goal.length ? parseOutline(goal).polys : [];
    this.preview = { start: null, goal: null };
    this.clearRun();
    this.relayout();
  }

  /** The css box available for the canvas changed (or the device pixel ratio did). */
  resize(boxWidth, boxHeight, dpr) {
    this.box = [boxWidth, boxHeight];
    this.dpr = dpr;
    this.relayout();
  }

  relayout() {
    if (!this.box) return;
    const bounds = this.scenario ? this.scenario.bounds : [0, 0, 1, 1];
    this.css = Layout.fit(bounds, this.box[0], this.box[1]);
    this.layout = new Layout(bounds, this.css[0], this.css[1], this.dpr);
    const { width, height } = this.layout;
    for (const c of [this.canvas, this.sceneLayer.canvas, this.treeLayer.canvas]) {
      c.width = width;
      c.height = height;
    }
    this.canvas.style.width = `${this.css[0]}px`;
    this.canvas.style.height = `${this.css[1]}px`;
    this.drawScene();
    this.redrawTree();
  }

  setOptions(opts) {
    const before = { ...this.options };
    Object.assign(this.options, opts);
    if (before.showRejected !== this.options.showRejected || before.showCollisions !== this.options.showCollisions) {
      this.redrawTree();
    }
    this.dirty = true;
  }

  /** Paths and animation frames of a finished run; shown once `showResult` is set. */
  setResult(result, frames, rawFrames) {
    this.frames = parseFrames(frames);
    this.rawFrames = parseFrames(rawFrames);
    const solved = !!(result && result.solved);
    if (this.scenario?.robot?.kind === 'arm') {
      // the path as the end effector traces it (the last point of the arm's polyline)
      const tip = (list) => list.filter((f) => f.polys.length && f.polys[0].length >= 2)
        .map(({ polys: [p] }) => [p[p.length - 2], p[p.length - 1]]);
      this.path = solved ? tip(this.rawFrames) : null;
      this.smoothed = solved ? tip(this.frames) : null;
    } else if (this.scenario?.robot?.kind === 'asv') { // the chain's centroid, where its tree is drawn
      const mid = (states) => (states || []).map((s) => {
        let x = 0, y = 0;
        for (let i = 0; i + 1 < s.length; i += 2) { x += s[i]; y += s[i + 1]; }
        return [x / (s.length / 2), y / (s.length / 2)];
      });
      this.path = solved ? mid(result.path) : null;
      this.smoothed = solved ? mid(result.smoothed) : null;
    } else {
      const xy = (states) => (states || []).map((s) => [s[0], s[1]]);
      this.path = solved ? xy(result.path) : null;
      this.smoothed = solved ? xy(result.smoothed) : null;
    }
    this.dirty = true;
  }

  drawScene() {
    const { ctx } = this.sceneLayer;
    const L = this.layout;
    ctx.fillStyle = PALETTE.background;
    ctx.fillRect(0, 0, L.width, L.height);
    if (!this.scenario) return;
    const [x0, y0, x1, y1] = this.scenario.bounds;
    ctx.fillStyle = PALETTE.free;
    ctx.fillRect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
    for (const ob of this.scenario.obstacles) drawObstacle(ctx, L, ob);
    ctx.strokeStyle = PALETTE.bounds;
    ctx.lineWidth = L.px(1.5);
    ctx.strokeRect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
  }

  /** Draw stored records [from, to) onto the tree layer; remember markers. */
  drawRecords(from, to) {
    if (!this.layout || to <= from) return;
    const { ctx } = this.treeLayer;
    const L = this.layout;
    const d = this.store.data;
    const edge = STYLE[EventKind.NODE_ADDED];
    const rej = STYLE[EventKind.SAMPLE_REJECTED];
    const col = STYLE[EventKind.COLLISION];
    const showRej = this.options.showRejected;
    const showCol = this.options.showCollisions;
    const node = Math.max(1, Math.round(L.px(edge.size)));
    const rs = Math.max(1, Math.round(L.px(rej.size)));
    const cs = L.px(col.size);
    // one path per colour: O(new records) work, a handful of stroke calls
    for (let tree = 0; tree < 2; tree++) {
      ctx.beginPath();
      ctx.fillStyle = edge.colors[tree];
      for (let i = from; i < to; i++) {
        const o = i * STRIDE;
        if (d[o] !== EventKind.NODE_ADDED || (d[o + 1] > 0 ? 1 : 0) !== tree) continue;
        const x = L.sx(d[o + 4]), y = L.sy(d[o + 5]);
        if (d[o + 3] >= 0) {
          ctx.moveTo(L.sx(d[o + 6]), L.sy(d[o + 7]));
          ctx.lineTo(x, y);
        }
        ctx.fillRect(Math.round(x - node / 2), Math.round(y - node / 2), node, node);
      }
      ctx.strokeStyle = edge.colors[tree];
      ctx.lineWidth = L.px(edge.width);
      ctx.stroke();
    }
    if (showRej) {
      ctx.fillStyle = rej.color;
      for (let i = from; i < to; i++) {
        const o = i * STRIDE;
        if (d[o] !== EventKind.SAMPLE_REJECTED) continue;
        ctx.fillRect(Math.round(L.sx(d[o + 4]) - rs / 2), Math.round(L.sy(d[o + 5]) - rs / 2), rs, rs);
      }
    }
    if (showCol) {
      ctx.beginPath();
      for (let i = from; i < to; i++) {
        const o = i * STRIDE;
        if (d[o] !== EventKind.COLLISION) continue;
        const x = L.sx(d[o + 4]), y = L.sy(d[o + 5]);
        ctx.moveTo(x - cs, y - cs); ctx.lineTo(x + cs, y + cs);
        ctx.moveTo(x - cs, y + cs); ctx.lineTo(x + cs, y - cs);
      }
      ctx.strokeStyle = col.color;
      ctx.lineWidth = L.px(col.width);
      ctx.stroke();
    }
    // markers: few, kept as world coordinates and drawn on top every frame
    for (let i = from; i < to; i++) {
      const o = i * STRIDE;
      const kind = d[o];
      if (kind === EventKind.SAMPLE || kind === EventKind.SAMPLE_REJECTED) this.lastSample = [d[o + 4], d[o + 5]];
      else if (kind === EventKind.TREES_CONNECTED || kind === EventKind.SOLVED) this.markers.push([kind, d[o + 4], d[o + 5]]);
    }
    this.dirty = true;
  }

  redrawTree() {
    if (!this.layout) return;
    this.treeLayer.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
    this.markers = [];
    this.drawRecords(0, this.store.length);
    this.dirty = true;
  }

  /**
   * Composite the layers and draw the top layer. `time` in ms drives the robot animation; the
   * animated robot's state is left in `robotState` (null when there is none).
   */
  render(time, animFps) {
    if (!this.layout) return;
    const animating = this.showResult && this.frames.length > 0;
    if (!animating) this.robotState = null;
    if (!this.dirty && !animating) return;
    this.dirty = false;
    const { ctx } = this;
    const L = this.layout;
    ctx.clearRect(0, 0, L.width, L.height);
    ctx.drawImage(this.sceneLayer.canvas, 0, 0);
    ctx.drawImage(this.treeLayer.canvas, 0, 0);
    if (!this.scenario) return;
    drawInspection(ctx, L, this.scenario.inspection?.points, PALETTE.inspection, PALETTE.robotEdge);
    for (const which of ['start', 'goal']) {
      const state = this.stateOf(which);
      if (!state) continue;
      const polys = this.preview[which] ? outlineOf(this.scenario.robot, state) : this[which];
      drawRobotShape(ctx, L, this.scenario.robot, polys, state, robotStyle(PALETTE[which], which, PALETTE));
      if (this.editable) this.drawHandle(ctx, which);
    }
    for (const [kind, x, y] of this.markers) drawMarker(ctx, L, STYLE[kind], x, y);
    if (!this.showResult && this.lastSample) drawMarker(ctx, L, STYLE[EventKind.SAMPLE], ...this.lastSample);
    if (this.showResult && this.path) {
      drawPolyline(ctx, L, this.path, PALETTE.rawPath, L.px(2), [L.px(6), L.px(4)]);
    }
    if (this.showResult && this.smoothed) {
      drawPolyline(ctx, L, this.smoothed, PALETTE.pathCasing, L.px(6));
      drawPolyline(ctx, L, this.smoothed, PALETTE.smoothPath, L.px(4));
    }
    if (!animating) return;
    const frames = this.options.animateRaw && this.rawFrames.length ? this.rawFrames : this.frames;
    const frame = frames[Math.floor((time / 1000) * animFps) % frames.length];
    drawRobotShape(ctx, L, this.scenario.robot, frame.polys, frame.state, robotStyle(null, 'robot', PALETTE));
    this.robotState = frame.state;
  }

  /** The start or goal state shown: the one being edited, else the scenario's. */
  stateOf(which) {
    return this.preview[which] || (this.scenario && this.scenario[which]) || null;
  }

  /** Screen position (device px) of a rigid body's rotation handle, or null. */
  handlePoint(which) {
    const q = this.stateOf(which);
    if (!this.layout || !q || this.scenario.robot?.kind !== 'rigid') return null;
    const L = this.layout;
    const r = footprintRadius(this.scenario.robot) * L.scale + L.px(14);
    return { x: L.sx(q[0]) + r * Math.cos(q[2]), y: L.sy(q[1]) - r * Math.sin(q[2]), cx: L.sx(q[0]), cy: L.sy(q[1]) };
  }

  drawHandle(ctx, which) {
    const h = this.handlePoint(which);
    if (!h) return;
    const L = this.layout;
    ctx.beginPath();
    ctx.moveTo(h.cx, h.cy);
    ctx.lineTo(h.x, h.y);
    ctx.strokeStyle = PALETTE[which];
    ctx.lineWidth = L.px(1.5);
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(h.x, h.y, L.px(5), 0, 2 * Math.PI);
    ctx.fillStyle = PALETTE.handle;
    ctx.fill();
    ctx.stroke();
  }

  /** [{label, color, shape}] for the legend under the canvas, from the palette and style table. */
  legend() {
    const items = [
      { label: 'obstacle', color: PALETTE.obstacle, shape: 'box' },
      { label: 'start', color: PALETTE.start, shape: 'box' },
      { label: 'goal', color: PALETTE.goal, shape: 'box' },
      { label: 'tree from the start (tree 0)', color: PALETTE.tree0, shape: 'line' },
      { label: 'tree from the goal (tree 1)', color: PALETTE.tree1, shape: 'line' },
      { label: STYLE[EventKind.SAMPLE_REJECTED].label + ' (if shown)', color: PALETTE.rejected, shape: 'dot' },
      { label: STYLE[EventKind.COLLISION].label + ' (×, if shown)', color: PALETTE.collision, shape: 'cross' },
      { label: 'raw path', color: PALETTE.rawPath, shape: 'dash' },
      { label: 'smoothed path', color: PALETTE.smoothPath, shape: 'thick' },
      { label: 'robot', color: PALETTE.robot, shape: 'box' },
    ];
    if (this.scenario?.inspection?.points?.length) {
      items.push({ label: 'inspection point', color: PALETTE.inspection, shape: 'box' });
    }
    return items;
  }
}

function tracePoly(ctx, L, pts) {
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

function drawObstacle(ctx, L, ob) {
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

function drawMarker(ctx, L, style, x, y) {
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

function drawPolyline(ctx, L, pts, color, width, dash = []) {
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

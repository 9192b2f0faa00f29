// The configuration-space view of a two-dimensional planning space (a 2-joint arm): the
// (q1, q2) square, a torus when both joints wrap. Layers as in view.js:
//   scene (offscreen): the C-obstacle grid from the core (n × n validity, rows from the lowest q2),
//          axes, labels and the range; redrawn on load and resize;
//   tree  (offscreen): edges (c0, c1)–(pc0, pc1) of the event records, drawn incrementally; after
//          a REWIRE (an edge moved) redrawn from the run model's node/parent mirror;
//   top   (the visible canvas): both layers, start, goal, paths and the robot's current state.
// An edge or path segment that wraps (|Δ| > half the range in a wrapping dimension) is drawn as
// two pieces, each leaving the square on its side, clipped to the square.

import { EventKind, STRIDE } from '../run/events.js';
import { makeLayer } from './transform.js';

const MARGIN = { left: 40, right: 12, top: 10, bottom: 36 }; // css px around the square

/** A tick label for an angle-like value: multiples of π/2 by name. */
export function formatTick(v) {
  const k = v / (Math.PI / 2);
  if (Math.abs(k - Math.round(k)) < 1e-9) {
    const names = { '-2': '−π', '-1': '−π/2', 0: '0', 1: 'π/2', 2: 'π' };
    const name = names[String(Math.round(k))];
    if (name) return name;
  }
  return String(Number(v.toFixed(2))).replace('-', '−');
}

/** Map `v` into [lo, hi) when the dimension wraps. */
export function wrapInto(v, d) {
  if (!d.wraps) return v;
  const r = d.hi - d.lo;
  return d.lo + ((((v - d.lo) % r) + r) % r);
}

/**
 * The pieces of the short motion a → b: [[a0, a1, b0, b1]] or, when it wraps, two pieces, the
 * first from a leaving the square, the second entering it towards b.
 */
export function wrapSegments(dims, a0, a1, b0, b1) {
  a0 = wrapInto(a0, dims[0]); a1 = wrapInto(a1, dims[1]);
  b0 = wrapInto(b0, dims[0]); b1 = wrapInto(b1, dims[1]);
  let d0 = b0 - a0, d1 = b1 - a1;
  let wrapped = false;
  const fix = (d, dim) => {
    const r = dim.hi - dim.lo;
    if (dim.wraps && Math.abs(d) > r / 2) { wrapped = true; return d - Math.sign(d) * r; }
    return d;
  };
  d0 = fix(d0, dims[0]);
  d1 = fix(d1, dims[1]);
  if (!wrapped) return [[a0, a1, b0, b1]];
  return [[a0, a1, a0 + d0, a1 + d1], [b0 - d0, b1 - d1, b0, b1]];
}

export class CSpaceView {
  constructor(canvas, store, palette, model = null) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.store = store;
    this.model = model; // playback.js RunModel (its tree mirror), or null: edges from the records only
    this.palette = palette;
    this.sceneLayer = makeLayer();
    this.treeLayer = makeLayer();
    this.gridImage = makeLayer();
    this.space = null;   // {n, grid, dims}
    this.start = null;
    this.goal = null;
    this.box = null;
    this.dpr = 1;
    this.options = { showRejected: false, showCollisions: true };
    this.hooks = [];     // (ctx, view) => void, drawn last (ghost.js: the crosshair of a hovered pose)
    this.clearRun();
  }

  get active() { return !!this.space; }

  clearRun() {
    this.path = null;
    this.smoothed = null;
    this.showResult = false;
    this.state = null;
    this.treeSeen = this.model ? this.model.treeVersion : 0;
    if (this.width) this.treeLayer.ctx.clearRect(0, 0, this.width, this.height);
    this.dirty = true;
  }

  /**
   * A new scenario: `cspace` {n, grid, dims} (the worker's `loaded` reply) or null (no view), its
   * start and goal states.
   * @param {import('../run/messages.js').LoadedReply['cspace'] | null} cspace
   * @param {number[]} [start] @param {number[]} [goal]
   */
  setSpace(cspace, start, goal) {
    this.space = cspace || null;
    this.setStartGoal(start, goal);
    this.clearRun();
    if (this.space) {
      const { n, grid } = this.space;
      const c = this.gridImage.canvas;
      c.width = n;
      c.height = n;
      const img = this.gridImage.ctx.createImageData(n, n);
      const rgb = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16));
      const free = rgb(this.palette.free), bad = rgb(this.palette.obstacle);
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const col = grid[j * n + i] ? free : bad;
          const o = ((n - 1 - j) * n + i) * 4; // row 0 of the image is the highest q2
          img.data[o] = col[0]; img.data[o + 1] = col[1]; img.data[o + 2] = col[2]; img.data[o + 3] = 255;
        }
      }
      this.gridImage.ctx.putImageData(img, 0, 0);
    }
    this.relayout();
  }

  setStartGoal(start, goal) {
    this.start = start || null;
    this.goal = goal || null;
    this.dirty = true;
  }

  resize(boxWidth, boxHeight, dpr) {
    this.box = [boxWidth, boxHeight];
    this.dpr = dpr;
    this.relayout();
  }

  relayout() {
    if (!this.box || !this.space) return;
    const [bw, bh] = this.box;
    const side = Math.max(40, Math.floor(Math.min(bw - MARGIN.left - MARGIN.right, bh - MARGIN.top - MARGIN.bottom)));
    const cssW = side + MARGIN.left + MARGIN.right, cssH = side + MARGIN.top + MARGIN.bottom;
    const dpr = this.dpr;
    this.width = Math.round(cssW * dpr);
    this.height = Math.round(cssH * dpr);
    this.plot = { x: Math.round(MARGIN.left * dpr), y: Math.round(MARGIN.top * dpr), s: Math.round(side * dpr) };
    for (const c of [this.canvas, this.sceneLayer.canvas, this.treeLayer.canvas]) {
      c.width = this.width;
      c.height = this.height;
    }
    this.canvas.style.width = `${cssW}px`;
    this.canvas.style.height = `${cssH}px`;
    this.drawScene();
    this.redrawTree();
  }

  /** The (q1, q2) under css point (x, y) of the canvas, or null outside the square. */
  qAt(x, y) {
    if (!this.space || !this.plot) return null;
    const u = (x * this.dpr - this.plot.x) / this.plot.s, v = 1 - (y * this.dpr - this.plot.y) / this.plot.s;
    if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) return null;
    const [d0, d1] = this.space.dims;
    return [d0.lo + u * (d0.hi - d0.lo), d1.lo + v * (d1.hi - d1.lo)];
  }

  /**
   * Whether (q1, q2) is free by the core's grid, the cell drawn under it (true, false, or null
   * with no space).
   */
  isFree(q) {
    if (!this.space) return null;
    const { n, grid, dims } = this.space;
    const cell = (v, d) => Math.min(n - 1, Math.max(0, Math.floor(((wrapInto(v, d) - d.lo) / (d.hi - d.lo)) * n)));
    return !!grid[cell(q[1], dims[1]) * n + cell(q[0], dims[0])];
  }

  sx(q) { const d = this.space.dims[0]; return this.plot.x + ((q - d.lo) / (d.hi - d.lo)) * this.plot.s; }
  sy(q) { const d = this.space.dims[1]; return this.plot.y + this.plot.s - ((q - d.lo) / (d.hi - d.lo)) * this.plot.s; }
  px(css) { return css * this.dpr; }

  clipToPlot(ctx) {
    ctx.beginPath();
    ctx.rect(this.plot.x, this.plot.y, this.plot.s, this.plot.s);
    ctx.clip();
  }

  drawScene() {
    const { ctx } = this.sceneLayer;
    const P = this.palette;
    const { x, y, s } = this.plot;
    ctx.fillStyle = P.background;
    ctx.fillRect(0, 0, this.width, this.height);
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(this.gridImage.canvas, x, y, s, s);
    ctx.strokeStyle = P.bounds;
    ctx.lineWidth = this.px(1.5);
    ctx.strokeRect(x, y, s, s);
    // ticks and labels
    const [d0, d1] = this.space.dims;
    ctx.fillStyle = P.bounds;
    ctx.font = `${Math.round(this.px(11))}px system-ui, sans-serif`;
    const ticks = (d) => [d.lo, ...(d.lo < 0 && d.hi > 0 ? [0] : []), d.hi];
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    ctx.beginPath();
    for (const v of ticks(d0)) {
      const tx = this.sx(v);
      ctx.moveTo(tx, y + s); ctx.lineTo(tx, y + s + this.px(4));
      ctx.fillText(formatTick(v), tx, y + s + this.px(5));
    }
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (const v of ticks(d1)) {
      const ty = this.sy(v);
      ctx.moveTo(x, ty); ctx.lineTo(x - this.px(4), ty);
      ctx.fillText(formatTick(v), x - this.px(6), ty);
    }
    ctx.lineWidth = this.px(1);
    ctx.stroke();
    ctx.font = `italic ${Math.round(this.px(13))}px system-ui, sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'bottom';
    ctx.fillText('q1', x + s / 2, this.height - this.px(2));
    ctx.save();
    ctx.translate(this.px(12), y + s / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.textBaseline = 'middle';
    ctx.fillText('q2', 0, 0);
    ctx.restore();
  }

  setOptions(opts) {
    const before = { ...this.options };
    Object.assign(this.options, opts);
    if (before.showRejected !== this.options.showRejected || before.showCollisions !== this.options.showCollisions) {
      this.redrawTree();
    }
  }

  /** Draw stored records [from, to) onto the tree layer. */
  drawRecords(from, to, edges = true) {
    if (!this.space || !this.width || to <= from) return;
    const { ctx } = this.treeLayer;
    const dims = this.space.dims;
    const P = this.palette;
    const node = Math.max(1, Math.round(this.px(2)));
    ctx.save();
    this.clipToPlot(ctx);
    for (let tree = 0; tree < 2 && edges; tree++) {
      const color = tree ? P.tree1 : P.tree0;
      ctx.beginPath();
      ctx.fillStyle = color;
      for (const [d, o0, o1] of this.store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
        if (d[o] !== EventKind.NODE_ADDED || (d[o + 1] > 0 ? 1 : 0) !== tree) continue;
        if (d[o + 3] >= 0) {
          for (const [a0, a1, b0, b1] of wrapSegments(dims, d[o + 10], d[o + 11], d[o + 8], d[o + 9])) {
            ctx.moveTo(this.sx(a0), this.sy(a1));
            ctx.lineTo(this.sx(b0), this.sy(b1));
          }
        }
        const x = this.sx(wrapInto(d[o + 8], dims[0])), y = this.sy(wrapInto(d[o + 9], dims[1]));
        ctx.fillRect(Math.round(x - node / 2), Math.round(y - node / 2), node, node);
      }
      ctx.strokeStyle = color;
      ctx.lineWidth = this.px(1);
      ctx.stroke();
    }
    if (this.options.showRejected) {
      ctx.fillStyle = P.rejected;
      for (const [d, o0, o1] of this.store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
        if (d[o] !== EventKind.SAMPLE_REJECTED) continue;
        ctx.fillRect(Math.round(this.sx(wrapInto(d[o + 8], dims[0])) - node / 2),
          Math.round(this.sy(wrapInto(d[o + 9], dims[1])) - node / 2), node, node);
      }
    }
    if (this.options.showCollisions) {
      const cs = this.px(2.5);
      ctx.beginPath();
      for (const [d, o0, o1] of this.store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
        if (d[o] !== EventKind.COLLISION) continue;
        const x = this.sx(wrapInto(d[o + 8], dims[0])), y = this.sy(wrapInto(d[o + 9], dims[1]));
        ctx.moveTo(x - cs, y - cs); ctx.lineTo(x + cs, y + cs);
        ctx.moveTo(x - cs, y + cs); ctx.lineTo(x + cs, y - cs);
      }
      ctx.strokeStyle = P.collision;
      ctx.lineWidth = this.px(1);
      ctx.stroke();
    }
    ctx.restore();
    this.dirty = true;
  }

  /** The edges and nodes of the model's tree mirror (after a rewire moved an edge). */
  drawMirror() {
    const { ctx } = this.treeLayer;
    const dims = this.space.dims;
    const P = this.palette;
    const node = Math.max(1, Math.round(this.px(2)));
    ctx.save();
    this.clipToPlot(ctx);
    this.model.trees.forEach((t, k) => {
      const color = k ? P.tree1 : P.tree0;
      ctx.beginPath();
      ctx.fillStyle = color;
      for (let i = 0; i < t.n; i++) {
        const p = t.parent[i];
        if (!t.known(i) || !(p >= 0) || !t.known(p)) continue;
        for (const [a0, a1, b0, b1] of wrapSegments(dims, t.c0[p], t.c1[p], t.c0[i], t.c1[i])) {
          ctx.moveTo(this.sx(a0), this.sy(a1));
          ctx.lineTo(this.sx(b0), this.sy(b1));
        }
        const x = this.sx(wrapInto(t.c0[i], dims[0])), y = this.sy(wrapInto(t.c1[i], dims[1]));
        ctx.fillRect(Math.round(x - node / 2), Math.round(y - node / 2), node, node);
      }
      ctx.strokeStyle = color;
      ctx.lineWidth = this.px(1);
      ctx.stroke();
    });
    ctx.restore();
  }

  redrawTree() {
    if (!this.space || !this.width) return;
    this.treeLayer.ctx.clearRect(0, 0, this.width, this.height);
    const rewired = this.model && this.model.treeVersion > 0;
    if (rewired) this.drawMirror();
    this.drawRecords(0, this.store.length, !rewired);
    this.treeSeen = this.model ? this.model.treeVersion : 0;
    this.dirty = true;
  }

  setResult(result) {
    const q = (states) => (states || []).filter((s) => s.length >= 2).map((s) => [s[0], s[1]]);
    this.path = result && result.solved ? q(result.path) : null;
    this.smoothed = result && result.solved ? q(result.smoothed) : null;
    this.dirty = true;
  }

  /** Composite and draw the top layer; `state` is the animated robot's state (or null). */
  render(state) {
    if (!this.space || !this.width) return;
    if (this.model && this.model.treeVersion !== this.treeSeen) this.redrawTree();
    const moved = state ? !this.state || state[0] !== this.state[0] || state[1] !== this.state[1] : !!this.state;
    if (!this.dirty && !moved) return;
    this.dirty = false;
    this.state = state ? [state[0], state[1]] : null;
    const { ctx } = this;
    const P = this.palette;
    ctx.clearRect(0, 0, this.width, this.height);
    ctx.drawImage(this.sceneLayer.canvas, 0, 0);
    ctx.drawImage(this.treeLayer.canvas, 0, 0);
    ctx.save();
    this.clipToPlot(ctx);
    if (this.showResult && this.path) this.polyline(this.path, P.rawPath, 2, [6, 4]);
    if (this.showResult && this.smoothed) {
      this.polyline(this.smoothed, P.pathCasing, 5);
      this.polyline(this.smoothed, P.smoothPath, 3);
    }
    if (this.start) this.dot(this.start, P.start, 6);
    if (this.goal) this.dot(this.goal, P.goal, 6);
    if (this.showResult && this.state) this.dot(this.state, P.robotEdge, 4);
    ctx.restore();
    for (const hook of this.hooks) hook(ctx, this);
  }

  polyline(pts, color, width, dash = []) {
    const { ctx } = this;
    const dims = this.space.dims;
    ctx.beginPath();
    for (let i = 1; i < pts.length; i++) {
      for (const [a0, a1, b0, b1] of wrapSegments(dims, pts[i - 1][0], pts[i - 1][1], pts[i][0], pts[i][1])) {
        ctx.moveTo(this.sx(a0), this.sy(a1));
        ctx.lineTo(this.sx(b0), this.sy(b1));
      }
    }
    ctx.strokeStyle = color;
    ctx.lineWidth = this.px(width);
    ctx.lineCap = 'round';
    ctx.setLineDash(dash.map((v) => this.px(v)));
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.lineCap = 'butt';
  }

  dot(q, color, r) {
    const { ctx } = this;
    const dims = this.space.dims;
    ctx.beginPath();
    ctx.arc(this.sx(wrapInto(q[0], dims[0])), this.sy(wrapInto(q[1], dims[1])), this.px(r), 0, 2 * Math.PI);
    ctx.fillStyle = color;
    ctx.fill();
    ctx.strokeStyle = this.palette.robotEdge;
    ctx.lineWidth = this.px(1);
    ctx.stroke();
  }
}

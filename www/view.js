// Canvas drawing. One Layout owns the world↔screen transform (y up in the world, y down on the
// screen); a style table keyed by EventKind says how each event record is drawn. Layers, bottom up:
//   scene  (offscreen): bounds and obstacles, redrawn on load and resize;
//   under  (offscreen): drawn samples (accepted / rejected) and the sampler's raw tries, drawn
//          incrementally as records are revealed, redrawn from the stored records on resize or
//          when one of their toggles changes;
//   domain (offscreen): dynamic-domain radii, redrawn from the run model when a radius changes;
//   tree   (offscreen): edges and nodes (exhausted nodes greyed), drawn incrementally; a REWIRE
//          moves an edge, so the layer is then redrawn from the model's node/parent mirror;
//   over   (offscreen): blocked motions, incremental like `under`;
//   top    (the visible canvas): the layers composited, then inspection points (seen ones lit),
//          the sensor's field of view, start/goal, markers, the best path so far, rewire flashes,
//          the result's paths and the robot, which are cheap to draw every frame.
// Colours follow the Okabe–Ito palette where it matters (tree 0 / tree 1 / paths), so they stay
// distinguishable with the common colour-vision deficiencies (they also differ in lightness).

import { EventKind, STRIDE } from './events.js';
import { drawRobotShape, drawInspection, robotStyle, outlineOf, footprintRadius, sensorPose } from './robots.js';

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
  accepted: '#2a9d8f',
  tryFree: '#4daf4a',
  tryOccupied: '#5e3c99',
  domain: '#8c510a',
  exhausted: '#b0b4ba',
  exhaustedEdge: '#4a4f57',
  rewire: '#e7298a',
  best: '#d55e00',
  bestCasing: '#ffffff',
  seen: '#ffd400',
  fov: '#9a7400',
  fovFill: 'rgba(255, 212, 0, 0.18)',
  chartLine: '#d55e00',
  chartTarget: '#009e73',
  chartAxis: '#5d6470',
});

// How each event kind is drawn. `layer`: 'under', 'tree', 'over' (persistent, incremental),
// 'domain' (from the run model) or 'marker' (top layer, every frame). `toggle` names a view option
// that must be on for the kind to be drawn.
export const STYLE = Object.freeze({
  [EventKind.SAMPLE]: { layer: 'marker', shape: 'dot', color: PALETTE.sample, size: 3, label: 'latest sample' },
  [EventKind.SAMPLE_REJECTED]: { layer: 'under', shape: 'square', color: PALETTE.rejected, size: 2, toggle: 'showRejected', label: 'rejected sample' },
  [EventKind.NODE_ADDED]: { layer: 'tree', shape: 'edge', colors: [PALETTE.tree0, PALETTE.tree1], width: 1, size: 2, label: 'tree edge' },
  [EventKind.COLLISION]: { layer: 'over', shape: 'cross', color: PALETTE.collision, size: 2.5, width: 1, toggle: 'showCollisions', label: 'blocked motion' },
  [EventKind.TREES_CONNECTED]: { layer: 'marker', shape: 'ring', color: PALETTE.connect, size: 7, width: 2, label: 'trees connected' },
  [EventKind.SOLVED]: { layer: 'marker', shape: 'ring', color: PALETTE.goal, size: 10, width: 2, label: 'goal reached' },
  [EventKind.SAMPLE_TRY]: { layer: 'under', shape: 'square', colors: [PALETTE.tryOccupied, PALETTE.tryFree], size: 1.5, toggle: 'showTries', label: 'raw try of the sampler' },
  [EventKind.DOMAIN]: { layer: 'domain', shape: 'circle', color: PALETTE.domain, width: 1.5, toggle: 'showDomains', label: 'dynamic-domain radius' },
  [EventKind.EXHAUSTED]: { layer: 'tree', shape: 'square', color: PALETTE.exhausted, size: 5, toggle: 'showExhausted', label: 'exhausted node' },
  [EventKind.REWIRE]: { layer: 'marker', shape: 'edge', color: PALETTE.rewire, width: 2, size: 3, toggle: 'showRewires', label: 'rewired edge' },
  [EventKind.COST]: { layer: 'marker', shape: 'path', color: PALETTE.best, width: 3, toggle: 'showBest', label: 'best path so far' },
  [EventKind.POINT_SEEN]: { layer: 'marker', shape: 'diamond', color: PALETTE.seen, toggle: 'showSeen', label: 'inspection point seen' },
});

// The switchable overlays, in the order of the overlay box: `option` is the view option, `swatches`
// the legend marks [{color, shape, label?}], `on` the default. `doc` is the box's tooltip.
export const OVERLAYS = Object.freeze([
  { option: 'showAccepted', id: 'show-accepted', label: 'accepted samples', on: false,
    swatches: [{ color: PALETTE.accepted, shape: 'dot' }],
    doc: 'Samples the planner grew toward (a sample not followed by a rejection).' },
  { option: 'showRejected', id: 'show-rejected', label: 'rejected samples', on: false,
    swatches: [{ color: PALETTE.rejected, shape: 'dot' }],
    doc: 'Samples that grew nothing: invalid, outside a dynamic domain, or their growth was blocked.' },
  { option: 'showTries', id: 'show-tries', label: "sampler's raw tries: free / occupied", on: false,
    swatches: [{ color: PALETTE.tryFree, shape: 'dot' }, { color: PALETTE.tryOccupied, shape: 'dot' }],
    doc: 'Every state a validity-checking sampler (gaussian, bridge, obstacle) drew and checked. After the first 50 000 of a run, the worker forwards a thinning share of them (see the stats).' },
  { option: 'showDomains', id: 'show-domains', label: 'dynamic-domain radii', on: true,
    swatches: [{ color: PALETTE.domain, shape: 'ring' }],
    doc: "Each node's latest dynamic-domain radius, drawn around its point. The radius is in the robot's metric: exact for a point robot; for other robots it is drawn in workspace units around the projected point, so only approximate." },
  { option: 'showExhausted', id: 'show-exhausted', label: 'exhausted nodes (greyed)', on: true,
    swatches: [{ color: PALETTE.exhausted, shape: 'box' }],
    doc: 'Nodes whose expansions failed too often (the tree variant "exhausted nodes").' },
  { option: 'showRewires', id: 'show-rewires', label: 'rewires (RRT*), flashing', on: true,
    swatches: [{ color: PALETTE.rewire, shape: 'line' }],
    doc: 'A node moved under a new parent: its new edge flashes for a moment (the tree is redrawn).' },
  { option: 'showBest', id: 'show-best', label: 'best path so far', on: true,
    swatches: [{ color: PALETTE.best, shape: 'thick' }],
    doc: 'The best solution (RRT*) or best inspection branch so far, back to the root, through projected points.' },
  { option: 'showSeen', id: 'show-seen', label: 'inspection points seen (lit)', on: true,
    swatches: [{ color: PALETTE.seen, shape: 'box' }],
    doc: 'Inspection points the planner has seen so far light up.' },
  { option: 'showFov', id: 'show-fov', label: "sensor's field of view", on: true,
    swatches: [{ color: PALETTE.fov, shape: 'box' }],
    doc: "The inspection sensor's wedge (range, ±fov/2) at the end effector of the robot shown: the start, then the animated robot along the path. During a run, a dashed ring of the range marks the best branch's tip (the events do not carry its heading)." },
  { option: 'showCollisions', id: 'show-collisions', label: 'blocked motions (×)', on: true,
    swatches: [{ color: PALETTE.collision, shape: 'cross' }],
    doc: 'Where a motion was found in collision.' },
]);

/** The overlays' default view options. */
export const OVERLAY_DEFAULTS = Object.freeze(Object.fromEntries(OVERLAYS.map((o) => [o.option, o.on])));

const FLASH_MS = 600;        // a rewire flashes this long
const MAX_FLASHES = 80;      // the most flashes shown at once (a burst keeps only the latest)
const BIG_TREE = 20000;      // above this many nodes, a rewired tree is redrawn at most every…
const BIG_TREE_MS = 250;     // …this many ms

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
  /**
   * `store` holds the revealed records ({data, length}), `model` what they say (playback.js
   * RunModel); the view reads both to redraw.
   */
  constructor(canvas, store, model) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.store = store;
    this.model = model;
    this.sceneLayer = makeLayer();
    this.underLayer = makeLayer();
    this.domainLayer = makeLayer();
    this.treeLayer = makeLayer();
    this.overLayer = makeLayer();
    this.layout = null;
    this.css = [300, 300];
    this.dpr = 1;
    this.scenario = null;
    this.start = [];
    this.goal = [];
    this.options = { ...OVERLAY_DEFAULTS, animateRaw: false };
    this.preview = { start: null, goal: null }; // states being edited (drawn instead of start/goal)
    this.editable = false;                       // draw the rotation handles of a rigid body
    this.robotState = null;                      // the animated robot's state, after render()
    this.clearRun();
  }

  get runLayers() { return [this.underLayer, this.domainLayer, this.treeLayer, this.overLayer]; }

  /** Forget the run's drawing (tree, markers, result). */
  clearRun() {
    this.markers = [];
    this.lastSample = null;
    this.pendingSample = null; // the latest SAMPLE, until a rejection or the next sample says what it was
    this.flashes = [];
    this.path = null;
    this.smoothed = null;
    this.frames = [];
    this.rawFrames = [];
    this.showResult = false;
    this.treeSeen = this.model ? this.model.treeVersion : 0;
    this.domainSeen = -1;
    this.treeDrawnAt = 0;
    if (this.layout) for (const l of this.runLayers) l.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
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
    for (const c of [this.canvas, this.sceneLayer.canvas, ...this.runLayers.map((l) => l.canvas)]) {
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
    const changed = (...keys) => keys.some((k) => before[k] !== this.options[k]);
    if (changed('showAccepted', 'showRejected', 'showTries')) this.redrawUnder();
    if (changed('showCollisions')) this.redrawOver();
    if (changed('showExhausted')) this.redrawTreeLayer();
    if (changed('showDomains')) this.domainSeen = -1;
    if (!this.options.showRewires) this.flashes = [];
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

  /** The run is over and its result shown: the last sample drawn counts as accepted. */
  finishRun() {
    if (this.pendingSample && this.layout && this.options.showAccepted) this.drawAccepted(this.underLayer.ctx, this.pendingSample);
    this.pendingSample = null;
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

  /** Draw stored records [from, to) onto the layers; remember markers. */
  drawRecords(from, to) {
    if (!this.layout || to <= from) return;
    this.drawTreeRecords(from, to);
    this.drawUnder(from, to);
    this.drawOver(from, to);
    const d = this.store.data;
    const flash = this.options.showRewires;
    const now = performance.now();
    // markers: few, kept as world coordinates and drawn on top every frame
    for (let i = from; i < to; i++) {
      const o = i * STRIDE;
      const kind = d[o];
      if (kind === EventKind.SAMPLE || kind === EventKind.SAMPLE_REJECTED) this.lastSample = [d[o + 4], d[o + 5]];
      else if (kind === EventKind.TREES_CONNECTED || kind === EventKind.SOLVED) this.markers.push([kind, d[o + 4], d[o + 5]]);
      else if (kind === EventKind.REWIRE && flash) this.flashes.push([now, d[o + 4], d[o + 5], d[o + 6], d[o + 7]]);
    }
    if (this.flashes.length > MAX_FLASHES) this.flashes.splice(0, this.flashes.length - MAX_FLASHES);
    this.dirty = true;
  }

  /** Tree edges and nodes of NODE_ADDED records, exhausted nodes greyed (incremental). */
  drawTreeRecords(from, to) {
    const { ctx } = this.treeLayer;
    const L = this.layout;
    const d = this.store.data;
    const edge = STYLE[EventKind.NODE_ADDED];
    const node = Math.max(1, Math.round(L.px(edge.size)));
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
    if (this.options.showExhausted) {
      const pts = [];
      for (let i = from; i < to; i++) {
        const o = i * STRIDE;
        if (d[o] === EventKind.EXHAUSTED) pts.push(d[o + 4], d[o + 5]);
      }
      drawExhausted(ctx, L, pts);
    }
  }

  /** The whole tree layer from the model's mirror (after a rewire, a toggle or a resize). */
  redrawTreeLayer() {
    if (!this.layout) return;
    const { ctx } = this.treeLayer;
    const L = this.layout;
    ctx.clearRect(0, 0, L.width, L.height);
    const edge = STYLE[EventKind.NODE_ADDED];
    const node = Math.max(1, Math.round(L.px(edge.size)));
    const trees = this.model ? this.model.trees : [];
    trees.forEach((t, k) => {
      const color = edge.colors[k > 0 ? 1 : 0];
      ctx.beginPath();
      ctx.fillStyle = color;
      for (let i = 0; i < t.n; i++) {
        if (!t.known(i)) continue;
        const x = L.sx(t.x[i]), y = L.sy(t.y[i]);
        const p = t.parent[i];
        if (p >= 0 && t.known(p)) {
          ctx.moveTo(L.sx(t.x[p]), L.sy(t.y[p]));
          ctx.lineTo(x, y);
        }
        if (p >= 0) ctx.fillRect(Math.round(x - node / 2), Math.round(y - node / 2), node, node);
      }
      ctx.strokeStyle = color;
      ctx.lineWidth = L.px(edge.width);
      ctx.stroke();
      if (this.options.showExhausted && t.exhausted) {
        const pts = [];
        for (let i = 0; i < t.n; i++) if (t.known(i) && t.isExhausted(i)) pts.push(t.x[i], t.y[i]);
        drawExhausted(ctx, L, pts);
      }
    });
    this.treeSeen = this.model ? this.model.treeVersion : 0;
    this.treeDrawnAt = performance.now();
    this.dirty = true;
  }

  drawAccepted(ctx, [x, y]) {
    const L = this.layout;
    const s = Math.max(2, Math.round(L.px(2.5)));
    ctx.fillStyle = PALETTE.accepted;
    ctx.fillRect(Math.round(L.sx(x) - s / 2), Math.round(L.sy(y) - s / 2), s, s);
  }

  /**
   * Samples and raw tries of records [from, to). A SAMPLE is accepted when no SAMPLE_REJECTED
   * follows it before the next SAMPLE (the rejection is drawn at the same point), so it is drawn
   * once the next sample or its rejection is revealed, or when the run is over.
   */
  drawUnder(from, to) {
    const { ctx } = this.underLayer;
    const L = this.layout;
    const d = this.store.data;
    const { showAccepted, showRejected, showTries } = this.options;
    const rej = STYLE[EventKind.SAMPLE_REJECTED];
    const tries = STYLE[EventKind.SAMPLE_TRY];
    const rs = Math.max(1, Math.round(L.px(rej.size)));
    const ts = Math.max(1, Math.round(L.px(tries.size)));
    for (let i = from; i < to; i++) {
      const o = i * STRIDE;
      const kind = d[o];
      if (kind === EventKind.SAMPLE) {
        if (this.pendingSample && showAccepted) this.drawAccepted(ctx, this.pendingSample);
        this.pendingSample = [d[o + 4], d[o + 5]];
      } else if (kind === EventKind.SAMPLE_REJECTED) {
        this.pendingSample = null;
        if (showRejected) {
          ctx.fillStyle = rej.color;
          ctx.fillRect(Math.round(L.sx(d[o + 4]) - rs / 2), Math.round(L.sy(d[o + 5]) - rs / 2), rs, rs);
        }
      } else if (kind === EventKind.SAMPLE_TRY && showTries) {
        ctx.fillStyle = tries.colors[d[o + 2] > 0 ? 1 : 0];
        ctx.fillRect(Math.round(L.sx(d[o + 4]) - ts / 2), Math.round(L.sy(d[o + 5]) - ts / 2), ts, ts);
      }
    }
  }

  redrawUnder() {
    if (!this.layout) return;
    this.underLayer.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
    this.pendingSample = null;
    this.drawUnder(0, this.store.length);
    if (this.showResult) this.finishRun();
    this.dirty = true;
  }

  /** Blocked motions of records [from, to). */
  drawOver(from, to) {
    if (!this.options.showCollisions) return;
    const { ctx } = this.overLayer;
    const L = this.layout;
    const d = this.store.data;
    const col = STYLE[EventKind.COLLISION];
    const cs = L.px(col.size);
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

  redrawOver() {
    if (!this.layout) return;
    this.overLayer.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
    this.drawOver(0, this.store.length);
    this.dirty = true;
  }

  /** Dynamic-domain circles from the model (latest radius per node). */
  redrawDomains() {
    if (!this.layout) return;
    const { ctx } = this.domainLayer;
    const L = this.layout;
    ctx.clearRect(0, 0, L.width, L.height);
    this.domainSeen = this.model ? this.model.domainVersion : 0;
    if (!this.options.showDomains || !this.model) return;
    const st = STYLE[EventKind.DOMAIN];
    const [x0, y0, x1, y1] = this.scenario ? this.scenario.bounds : [0, 0, 0, 0];
    ctx.save();
    ctx.beginPath();
    ctx.rect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
    ctx.clip();
    ctx.beginPath();
    for (const t of this.model.trees) {
      if (!t.domains) continue;
      for (let i = 0; i < t.n; i++) {
        const r = t.radius[i];
        if (!Number.isFinite(r) || !t.known(i)) continue;
        const x = L.sx(t.x[i]), y = L.sy(t.y[i]), rr = r * L.scale;
        ctx.moveTo(x + rr, y);
        ctx.arc(x, y, rr, 0, 2 * Math.PI);
      }
    }
    ctx.fillStyle = 'rgba(140, 81, 10, 0.06)';
    ctx.fill(); // one fill of the union: overlapping discs do not darken
    ctx.strokeStyle = st.color;
    ctx.lineWidth = L.px(st.width);
    ctx.stroke();
    ctx.restore();
    this.dirty = true;
  }

  /** Every run layer again, from the records and the model. */
  redrawTree() {
    if (!this.layout) return;
    this.markers = [];
    this.flashes = [];
    this.redrawTreeLayer();
    this.redrawUnder();
    this.redrawOver();
    this.redrawDomains();
    const d = this.store.data;
    for (let i = 0; i < this.store.length; i++) {
      const o = i * STRIDE;
      if (d[o] === EventKind.TREES_CONNECTED || d[o] === EventKind.SOLVED) this.markers.push([d[o], d[o + 4], d[o + 5]]);
    }
    this.dirty = true;
  }

  /** Bring the model-drawn layers up to date (at most once a frame; big trees less often). */
  syncModelLayers(time) {
    if (!this.model) return;
    if (this.model.domainVersion !== this.domainSeen) this.redrawDomains();
    if (this.model.treeVersion !== this.treeSeen) {
      const nodes = this.model.trees.reduce((s, t) => s + t.n, 0);
      if (nodes < BIG_TREE || time - this.treeDrawnAt >= BIG_TREE_MS || this.showResult) this.redrawTreeLayer();
    }
  }

  /**
   * Composite the layers and draw the top layer. `time` in ms drives the robot animation; the
   * animated robot's state is left in `robotState` (null when there is none).
   */
  render(time, animFps) {
    if (!this.layout) return;
    const animating = this.showResult && this.frames.length > 0;
    if (!animating) this.robotState = null;
    this.syncModelLayers(time);
    const flashing = this.flashes.length > 0;
    if (!this.dirty && !animating && !flashing) return;
    this.dirty = false;
    const { ctx } = this;
    const L = this.layout;
    ctx.clearRect(0, 0, L.width, L.height);
    ctx.drawImage(this.sceneLayer.canvas, 0, 0);
    for (const l of this.runLayers) ctx.drawImage(l.canvas, 0, 0);
    if (!this.scenario) return;
    const o = this.options;
    const inspection = this.scenario.inspection;
    const seen = o.showSeen && this.model ? this.model.seen : null;
    drawInspection(ctx, L, inspection?.points, PALETTE.inspection, PALETTE.robotEdge, seen, PALETTE.seen);
    for (const which of ['start', 'goal']) {
      const state = this.stateOf(which);
      if (!state) continue;
      const polys = this.preview[which] ? outlineOf(this.scenario.robot, state) : this[which];
      drawRobotShape(ctx, L, this.scenario.robot, polys, state, robotStyle(PALETTE[which], which, PALETTE));
      if (this.editable) this.drawHandle(ctx, which);
    }
    for (const [kind, x, y] of this.markers) drawMarker(ctx, L, STYLE[kind], x, y);
    if (flashing) this.drawFlashes(ctx, time);
    const best = o.showBest && this.model ? this.model.bestBranch() : [];
    if (best.length >= 2) {
      drawPolyline(ctx, L, best, PALETTE.bestCasing, L.px(6));
      drawPolyline(ctx, L, best, PALETTE.best, L.px(3.5));
    }
    if (!this.showResult && this.lastSample) drawMarker(ctx, L, STYLE[EventKind.SAMPLE], ...this.lastSample);
    if (this.showResult && this.path) {
      drawPolyline(ctx, L, this.path, PALETTE.rawPath, L.px(2), [L.px(6), L.px(4)]);
    }
    if (this.showResult && this.smoothed) {
      drawPolyline(ctx, L, this.smoothed, PALETTE.pathCasing, L.px(6));
      drawPolyline(ctx, L, this.smoothed, PALETTE.smoothPath, L.px(4));
    }
    let frame = null;
    if (animating) {
      const frames = this.options.animateRaw && this.rawFrames.length ? this.rawFrames : this.frames;
      frame = frames[Math.floor((time / 1000) * animFps) % frames.length];
    }
    if (inspection && o.showFov) this.drawSensor(ctx, frame ? frame.state : this.stateOf('start'), best);
    if (!frame) return;
    drawRobotShape(ctx, L, this.scenario.robot, frame.polys, frame.state, robotStyle(null, 'robot', PALETTE));
    this.robotState = frame.state;
  }

  /** Rewired edges, fading out; expired flashes are dropped. */
  drawFlashes(ctx, time) {
    const L = this.layout;
    const now = Math.max(time, performance.now());
    this.flashes = this.flashes.filter(([t]) => now - t < FLASH_MS);
    const st = STYLE[EventKind.REWIRE];
    for (const [t, x, y, px, py] of this.flashes) {
      ctx.globalAlpha = Math.max(0, 1 - (now - t) / FLASH_MS);
      ctx.beginPath();
      ctx.moveTo(L.sx(px), L.sy(py));
      ctx.lineTo(L.sx(x), L.sy(y));
      ctx.strokeStyle = st.color;
      ctx.lineWidth = L.px(st.width);
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(L.sx(x), L.sy(y), L.px(st.size), 0, 2 * Math.PI);
      ctx.stroke();
    }
    ctx.globalAlpha = 1;
  }

  /**
   * The inspection sensor: its wedge (radius `range`, half-angle fov/2) at the end effector of the
   * robot shown at `state`; during a run, a dashed ring of the range at the best branch's tip
   * (a wedge when the tip's heading is known: a 2-joint arm, whose two planning coordinates are
   * its whole state).
   */
  drawSensor(ctx, state, best) {
    const L = this.layout;
    const { range, fov } = this.scenario.inspection;
    if (!(range > 0)) return;
    const wedge = (pose) => {
      const cx = L.sx(pose.x), cy = L.sy(pose.y), r = range * L.scale;
      ctx.beginPath();
      if (pose.heading == null || !(fov > 0) || fov >= 2 * Math.PI) {
        ctx.arc(cx, cy, r, 0, 2 * Math.PI);
      } else { // screen y points down: world angle a is screen angle −a
        ctx.moveTo(cx, cy);
        ctx.arc(cx, cy, r, -(pose.heading + fov / 2), -(pose.heading - fov / 2));
        ctx.closePath();
      }
      ctx.fillStyle = PALETTE.fovFill;
      ctx.fill();
      ctx.strokeStyle = PALETTE.fov;
      ctx.lineWidth = L.px(1.5);
      ctx.stroke();
    };
    const robot = this.scenario.robot;
    const pose = state ? sensorPose(robot, state) : null;
    if (pose) wedge(pose);
    if (!this.showResult && best.length && this.model?.best) {
      const t = this.model.trees[this.model.best.tree];
      const id = this.model.best.id;
      const [x, y] = best[best.length - 1];
      if (robot?.kind === 'arm' && robot.links?.length === 2 && t?.known(id)) {
        const tip = sensorPose(robot, [t.c0[id], t.c1[id]]);
        if (tip) { wedge(tip); return; }
      }
      ctx.beginPath();
      ctx.arc(L.sx(x), L.sy(y), range * L.scale, 0, 2 * Math.PI);
      ctx.setLineDash([L.px(5), L.px(4)]);
      ctx.strokeStyle = PALETTE.fov;
      ctx.lineWidth = L.px(1.25);
      ctx.stroke();
      ctx.setLineDash([]);
    }
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

  /**
   * [{label, color, shape}] for the legend under the canvas, from the palette and style table
   * (the switchable overlays have their own marks in the overlay box).
   */
  legend() {
    const items = [
      { label: 'obstacle', color: PALETTE.obstacle, shape: 'box' },
      { label: 'start', color: PALETTE.start, shape: 'box' },
      { label: 'goal', color: PALETTE.goal, shape: 'box' },
      { label: 'tree from the start (tree 0)', color: PALETTE.tree0, shape: 'line' },
      { label: 'tree from the goal (tree 1)', color: PALETTE.tree1, shape: 'line' },
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

/** Exhausted nodes at flat world points [x, y, ...]: grey squares with a dark edge. */
function drawExhausted(ctx, L, pts) {
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

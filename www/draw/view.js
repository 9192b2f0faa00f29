// Canvas drawing. One Layout owns the world↔screen transform (y up in the world, y down on the
// screen); a style table keyed by EventKind says how each event record is drawn. Layers, bottom up:
//   scene  (offscreen): bounds and obstacles, redrawn on load and resize;
//   cells  (offscreen): hexagonal cells, their verdicts, the heat map and arrows (cells.js, from
//          the run model; the obstacles are veiled over it when it shows anything);
//   under  (offscreen): drawn samples (accepted / rejected) and the sampler's raw tries, drawn
//          incrementally as records are revealed, redrawn from the stored records on resize or
//          when one of their toggles changes;
//   domain (offscreen): dynamic-domain radii, redrawn from the run model when a radius changes;
//   tree   (offscreen): edges and nodes (exhausted nodes greyed), drawn incrementally, roadmaps
//          from their records (graphs.js); a REWIRE
//          moves an edge, so the layer is then redrawn from the model's node/parent mirror;
//   over   (offscreen): blocked motions, incremental like `under`;
//   top    (the visible canvas): the layers composited, then inspection points (seen ones lit),
//          the sensor's field of view, start/goal, markers, the best path so far, rewire flashes,
//          the result's paths and the robot, the region of influence, local minima and the robot's
//          t/2 circle, which are cheap to draw every frame.
// The order, and what the top layer draws, is picture.js's list of layers (the SVG export draws the
// same list); the run layers' drawing functions are in layers.js. The tables (colours, styles,
// overlays) are in palette.js; the transform and primitives in transform.js;
// the rewire flashes, the sensor's wedge and the rotation handles in marks.js.

import { EventKind, STRIDE } from '../run/events.js';
import { footprintRadius } from './robots.js';
import { PALETTE, STYLE, OVERLAY_DEFAULTS } from './palette.js';
import { dragsHeading, robotDrawing, treeLegend } from './capabilities.js';
import { Layout, MAX_ZOOM, parseOutline, parseFrames, makeLayer, drawExhausted } from './transform.js';
import { CellsDrawing } from './cells.js';
import { addQueryEdge, drawGraphEdges, drawRoadmap } from './graphs.js';
import { drawAll, redrawSteps, redrawWork, treeLayerSteps } from './redraw.js';
import { drawAccepted, drawCollisions, drawDomains, drawSamples } from './layers.js';
import { PICTURE, bestOf } from './picture.js';

const MAX_FLASHES = 80;      // the most flashes shown at once (a burst keeps only the latest)
const BIG_TREE = 20000;      // above this many nodes, a rewired tree is redrawn at most every…
const BIG_TREE_MS = 250;     // …this many ms
// Zooming and panning the plane: while the viewport moves, the layers' last pictures are moved
// and scaled with it (a few image copies a frame, whatever the run's size); SETTLE_MS after the
// last move they are redrawn at the new transform: at once when the work is at most SYNC_WORK
// (redraw.js redrawWork's units: nodes and records), else in steps of REDRAW_BATCH, at most
// REDRAW_MS of each frame, the moved pictures shown until the new ones are whole.
const SETTLE_MS = 150;
const SYNC_WORK = 60000;
const REDRAW_BATCH = 10000;
const REDRAW_MS = 10;

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
    this.cellsLayer = makeLayer();
    this.cells = new CellsDrawing(this.cellsLayer, model);
    this.underLayer = makeLayer();
    this.domainLayer = makeLayer();
    this.treeLayer = makeLayer();
    this.overLayer = makeLayer();
    /** The offscreen layers by the names picture.js gives them. */
    this.layers = { scene: this.sceneLayer, cells: this.cellsLayer, under: this.underLayer, domain: this.domainLayer,
      tree: this.treeLayer, over: this.overLayer };
    /** @type {Layout | null} what the canvas shows: the world ↔ device-pixel transform */
    this.layout = null;
    /** @type {Layout | null} the transform the offscreen layers are drawn at (the shown one but
     * while the plane is being zoomed or panned, and until its redraw is done) */
    this.drawn = null;
    /** @type {{zoom: number, cx: number, cy: number} | null} zoom and centre, null: the bounds fitted */
    this.viewport = null;
    this.movedAt = 0;       // when the viewport last changed (performance.now())
    /** @type {{zoom: number, cx: number, cy: number} | null | undefined} the viewport the next
     * scenario opens at (a share link's), undefined: fitted */
    this.pendingViewport = undefined;
    /** @type {{steps: Generator, to: number} | null} a big run's layers being redrawn in steps */
    this.redrawing = null;
    /** @type {{canvases: Record<string, HTMLCanvasElement>, layout: Layout} | null} the last whole
     * picture of the layers, shown (moved to the shown transform) while they are redrawn */
    this.stale = null;
    /** @type {Record<string, HTMLCanvasElement> | null} the canvases `stale` keeps, made once */
    this.staleCanvases = null;
    this.css = [300, 300];
    this.dpr = 1;
    this.scenario = null;
    this.start = [];
    this.goal = [];
    /** @type {Record<string, boolean>} the overlays shown (palette.js OVERLAYS) and animateRaw */
    this.options = { ...OVERLAY_DEFAULTS, animateRaw: false };
    this.preview = { start: null, goal: null }; // states being edited (drawn instead of start/goal)
    this.editable = false;                       // draw the rotation handles of a rigid body
    this.robotState = null;                      // the animated robot's state, after render()
    this.overlayHooks = [];                      // (ctx, layout) => void, drawn above the scene
    /** @type {(() => void) | null} called when a new query's answer comes or goes (its legend entry) */
    this.onLegend = null;
    /** @type {(() => void) | null} called when the plane's zoom or centre changes */
    this.onViewport = null;
    this.topHooks = [];                          // (ctx, layout) => void, drawn last, over the robot
                                                 // (ghost.js: the linked views' ghost arm)
    this.clearRun();
  }

  get runLayers() { return [this.cellsLayer, this.underLayer, this.domainLayer, this.treeLayer, this.overLayer]; }

  /** Forget the run's drawing (tree, markers, result). */
  /** Another query's answer on the finished roadmap, or null (ui/roadmap-query.js). */
  setQuery(query) {
    const had = this.query?.points?.length >= 2;
    this.query = query;
    this.dirty = true;
    if (had !== (query?.points?.length >= 2)) this.onLegend?.(); // the legend names the answer
  }

  clearRun() {
    this.markers = [];
    this.lastSample = null;
    /** @type {number[] | null} */
    this.pendingSample = null; // the latest SAMPLE, until a rejection or the next sample says what it was
    this.flashes = [];
    this.queryPath = null; // roadmaps: the latest graph search's path, [[x, y], ...]
    const hadQuery = this.query?.points?.length >= 2;
    this.query = null;     // another query on the finished roadmap: {points, picks} (ui/roadmap-query.js)
    if (hadQuery) this.onLegend?.();
    this.path = null;
    this.smoothed = null;
    this.frames = [];
    this.rawFrames = [];
    this.showResult = false;
    this.treeSeen = this.model ? this.model.treeVersion : 0;
    this.domainSeen = -1;
    this.treeDrawnAt = 0;
    this.attemptSeen = -1; // hex-potential: the attempt whose tree is drawn in full (older ones faint)
    this.cells?.reset();
    if (this.layout) {
      for (const l of this.runLayers) l.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
      if (this.redrawing || this.stale || this.drawn !== this.layout) { // empty layers fit any transform
        this.redrawing = null;
        this.stale = null;
        this.drawn = this.layout;
        this.drawScene();
      }
    }
    this.dirty = true;
  }

  /**
   * A new scenario (or null: nothing valid to show); `start` and `goal` the robot's outlines there,
   * flat (the worker's `loaded` reply; the goal's empty without a goal).
   * @param {any} scenario @param {Float64Array | number[]} [start] @param {Float64Array | number[]} [goal]
   */
  setScenario(scenario, start, goal) {
    // another scenario opens fitted (an edit of this one keeps its name and bounds, and the zoom)
    const key = (sc) => (sc ? `${sc.name}|${sc.bounds}` : '');
    if (key(scenario) !== key(this.scenario)) this.viewport = null;
    this.scenario = scenario;
    this.start = scenario ? parseOutline(start).polys : [];
    this.goal = scenario && goal && goal.length ? parseOutline(goal).polys : [];
    this.preview = { start: null, goal: null };
    this.clearRun();
    this.relayout();
    const asked = this.pendingViewport;
    this.pendingViewport = undefined;
    if (asked !== undefined && scenario) { this.setViewport(asked); this.movedAt = 0; } // drawn at the next frame
    this.onViewport?.();
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
    if (this.viewport && !this.scenario) this.viewport = null;
    this.layout = new Layout(bounds, this.css[0], this.css[1], this.dpr, this.viewport);
    this.drawn = this.layout;
    this.redrawing = null;
    this.stale = null;
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
    if (changed('showCells', 'showHeat', 'showArrows')) this.cells.invalidate();
    if (!this.options.showRewires) this.flashes = [];
    this.dirty = true;
  }

  /** Paths and animation frames of a finished run; shown once `showResult` is set. */
  setResult(result, frames, rawFrames) {
    this.frames = parseFrames(frames);
    this.rawFrames = parseFrames(rawFrames);
    const solved = !!(result && result.solved);
    const drawing = robotDrawing(this.scenario?.robot);
    if (drawing === 'linkage' || drawing === 'skeleton') {
      // the path as the end effector traces it (the last point of the arm's polyline)
      const tip = (list) => list.filter((f) => f.polys.length && f.polys[0].length >= 2)
        .map(({ polys: [p] }) => [p[p.length - 2], p[p.length - 1]]);
      this.path = solved ? tip(this.rawFrames) : null;
      this.smoothed = solved ? tip(this.frames) : null;
    } else if (drawing === 'chain') { // the chain's centroid, where its tree is drawn
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
    this.paintScene(this.scenario?.obstacles ?? []);
  }

  /** The scene layer: background, free space, `obstacles`, bounds (picture.js's 'scene' layers). */
  paintScene(obstacles) {
    const { ctx } = this.sceneLayer;
    const L = this.drawn;
    for (const e of PICTURE) {
      if (e.layer === 'scene' && (this.scenario || e.id === 'background')) e.draw(ctx, L, this, { obstacles });
    }
  }

  /**
   * The scene layer again inside world box `box` only (and 2 px around it), with `obstacles`: all
   * that reach into it, in drawing order. An edit in progress (the Cells tool) redraws what it
   * changed, not a map of 100,000 obstacles at every pointer move.
   */
  drawSceneIn(box, obstacles) {
    const L = this.drawn;
    if (!L || !this.scenario) return;
    const { ctx } = this.sceneLayer;
    const pad = Math.ceil(L.px(2));
    const x0 = Math.max(0, Math.floor(L.sx(box[0])) - pad), x1 = Math.min(L.width, Math.ceil(L.sx(box[2])) + pad);
    const y0 = Math.max(0, Math.floor(L.sy(box[3])) - pad), y1 = Math.min(L.height, Math.ceil(L.sy(box[1])) + pad);
    if (x1 <= x0 || y1 <= y0) return;
    ctx.save();
    ctx.beginPath();
    ctx.rect(x0, y0, x1 - x0, y1 - y0);
    ctx.clip();
    this.paintScene(obstacles);
    ctx.restore();
    this.dirty = true;
  }

  /** Draw stored records [from, to) onto the layers; remember markers. */
  drawRecords(from, to) {
    if (!this.layout || to <= from) return;
    if (!this.redrawing) this.drawLayers(from, to); // else the redraw's catch-up draws them
    const flash = this.options.showRewires;
    const now = performance.now();
    // markers: few, kept as world coordinates and drawn on top every frame
    for (const [d, o0, o1] of this.store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
      const kind = d[o];
      if (kind === EventKind.SAMPLE || kind === EventKind.SAMPLE_REJECTED) this.lastSample = [d[o + 4], d[o + 5]];
      else if (kind === EventKind.TREES_CONNECTED || kind === EventKind.SOLVED) this.markers.push([kind, d[o + 4], d[o + 5]]);
      else if (kind === EventKind.REWIRE && flash) this.flashes.push([now, d[o + 4], d[o + 5], d[o + 6], d[o + 7]]);
      else if (kind === EventKind.QUERY_PATH) this.queryPath = addQueryEdge(this.queryPath, d, o);
    }
    if (this.flashes.length > MAX_FLASHES) this.flashes.splice(0, this.flashes.length - MAX_FLASHES);
    this.dirty = true;
  }

  /** Records [from, to) onto the offscreen layers (at the layout they are drawn at). */
  drawLayers(from, to) {
    this.drawTreeRecords(from, to);
    this.drawUnder(from, to);
    this.drawOver(from, to);
  }

  /** Tree edges and nodes of NODE_ADDED records, exhausted nodes greyed (incremental). */
  drawTreeRecords(from, to) {
    const { ctx } = this.treeLayer;
    const L = this.drawn;
    const edge = STYLE[EventKind.NODE_ADDED];
    const node = Math.max(1, Math.round(L.px(edge.size)));
    // one path per colour: O(new records) work, a handful of stroke calls
    for (let tree = 0; tree < 2; tree++) {
      ctx.beginPath();
      ctx.fillStyle = edge.colors[tree];
      for (const [d, o0, o1] of this.store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
        if (d[o] !== EventKind.NODE_ADDED || this.treeGroup(d[o + 1]) !== tree) continue;
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
      for (const [d, o0, o1] of this.store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
        if (d[o] === EventKind.EXHAUSTED) pts.push(d[o + 4], d[o + 5]);
      }
      drawExhausted(ctx, L, pts);
    }
    if (this.roadmap) drawRoadmap(this.treeLayer.ctx, L, this.store, from, to, false);
  }

  /** Whether the run drew a roadmap (its layer is then redrawn from the records). */
  get roadmap() {
    const c = this.model?.counts;
    return !!c && (c[EventKind.ROADMAP_EDGE] > 0 || c[EventKind.QUERY_PATH] > 0);
  }

  /** The whole tree layer from the model's mirror (after a rewire, a toggle or a resize). */
  redrawTreeLayer() {
    if (this.redrawing) this.beginRedraw();
    else if (this.layout) drawAll(treeLayerSteps(this));
  }

  /** The colour of tree `k`'s records: 0 or 1 (hex-potential's trees are its attempts: all 0). */
  treeGroup(k) { return k > 0 && !(this.model?.cells.regions.length) ? 1 : 0; }

  /** @param {CanvasRenderingContext2D} ctx @param {number[]} at the sample's point */
  drawAccepted(ctx, at) { drawAccepted(ctx, this.drawn, at); }

  /**
   * Samples and raw tries of records [from, to) (layers.js drawSamples: a sample is drawn once the
   * next one or its rejection is revealed, or when the run is over), and the visibility graph's edges.
   */
  drawUnder(from, to) {
    drawSamples(this.underLayer.ctx, this.drawn, this.store, from, to, this.options, this);
    drawGraphEdges(this.underLayer.ctx, this.drawn, this.store, from, to);
  }

  redrawUnder() {
    if (!this.layout) return;
    if (this.redrawing) { this.beginRedraw(); return; }
    this.underLayer.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
    this.pendingSample = null;
    this.drawUnder(0, this.store.length);
    if (this.showResult) this.finishRun();
    this.dirty = true;
  }

  /** Blocked motions of records [from, to). */
  drawOver(from, to) {
    if (this.options.showCollisions) drawCollisions(this.overLayer.ctx, this.drawn, this.store, from, to);
  }

  redrawOver() {
    if (!this.layout) return;
    if (this.redrawing) { this.beginRedraw(); return; }
    this.overLayer.ctx.clearRect(0, 0, this.layout.width, this.layout.height);
    this.drawOver(0, this.store.length);
    this.dirty = true;
  }

  /** Dynamic-domain circles from the model (latest radius per node). */
  redrawDomains() {
    if (!this.layout) return;
    const { ctx } = this.domainLayer;
    const L = this.drawn;
    ctx.clearRect(0, 0, L.width, L.height);
    this.domainSeen = this.model ? this.model.domainVersion : 0;
    if (this.options.showDomains && this.model && this.scenario) drawDomains(ctx, L, this.model, this.scenario.bounds);
    this.dirty = true;
  }

  /** Every run layer again, from the records and the model (redraw.js: an export does it in steps). */
  redrawTree() {
    if (this.redrawing) this.beginRedraw();
    else if (this.layout) drawAll(redrawSteps(this));
  }

  /** Bring the model-drawn layers up to date (at most once a frame; big trees less often). */
  syncModelLayers(time) {
    if (!this.model || this.redrawing) return;
    if (this.model.domainVersion !== this.domainSeen) this.redrawDomains();
    if (this.cells.sync(this.drawn, this.options, time, this.showResult)) this.dirty = true;
    if (this.model.cells.attempt !== this.attemptSeen) this.redrawTreeLayer();
    if (this.model.treeVersion !== this.treeSeen) {
      const nodes = this.model.trees.reduce((s, t) => s + t.n, 0);
      if (nodes < BIG_TREE || time - this.treeDrawnAt >= BIG_TREE_MS || this.showResult) this.redrawTreeLayer();
    }
  }

  /** The zoom shown: 1 when the bounds are fitted. */
  get zoom() { return this.viewport ? this.viewport.zoom : 1; }

  /** Whether the layers are whole and drawn at the transform shown (no move or redraw pending). */
  get settled() { return !!this.drawn && this.drawn.same(this.layout) && !this.redrawing && !this.stale; }

  /**
   * Show the plane at `viewport` ({zoom, cx, cy}, the zoom clamped to 1 … MAX_ZOOM and the centre
   * to the bounds; zoom 1 fits the bounds again) or null (fitted). The layers follow SETTLE_MS
   * after the last change; the shown transform (`layout`, what pointer positions map through)
   * changes at once.
   */
  setViewport(viewport) {
    if (!this.layout || !this.scenario) return;
    const [x0, y0, x1, y1] = this.scenario.bounds;
    let vp = null;
    if (viewport && Number.isFinite(viewport.zoom) && viewport.zoom > 1 + 1e-9) {
      const clamp = (v, lo, hi) => (Number.isFinite(v) ? Math.min(hi, Math.max(lo, v)) : (lo + hi) / 2);
      vp = { zoom: Math.min(MAX_ZOOM, viewport.zoom), cx: clamp(viewport.cx, x0, x1), cy: clamp(viewport.cy, y0, y1) };
    }
    this.viewport = vp;
    this.layout = new Layout(this.scenario.bounds, this.css[0], this.css[1], this.dpr, vp);
    this.movedAt = performance.now();
    this.dirty = true;
    this.onViewport?.();
  }

  /** Zoom by `factor` about device point (px, py): the world point there stays under it. */
  zoomAt(factor, px, py) {
    const L = this.layout;
    if (!L || !this.scenario) return;
    const zoom = Math.min(MAX_ZOOM, Math.max(1, this.zoom * factor));
    const scale = L.fitScale * zoom;
    const wx = L.wx(px), wy = L.wy(py);
    this.setViewport({ zoom, cx: wx - (px - L.width / 2) / scale, cy: wy + (py - L.height / 2) / scale });
  }

  /** Move the picture by (dx, dy) device px (a drag). */
  panBy(dx, dy) {
    const L = this.layout;
    if (!L || !this.viewport) return;
    const { zoom, cx, cy } = this.viewport;
    this.setViewport({ zoom, cx: cx - dx / L.scale, cy: cy + dy / L.scale });
  }

  /** Bring the layers to the shown transform once the viewport has rested; step a redraw in progress. */
  followViewport() {
    const L = this.layout;
    if (!this.drawn.same(L) && performance.now() - this.movedAt >= SETTLE_MS) {
      if (!this.redrawing && redrawWork(this) <= SYNC_WORK) {
        this.drawn = L;
        this.stale = null;
        this.drawScene();
        drawAll(redrawSteps(this));
      } else this.beginRedraw();
    }
    if (this.redrawing && this.drawn.same(L)) this.stepRedraw();
  }

  /**
   * Redraw every layer at the shown transform in steps (again from the start when one is in
   * progress): the layers' last whole picture is kept to be shown meanwhile, new records wait.
   */
  beginRedraw() {
    if (!this.stale) {
      const canvases = this.staleCanvases ??= Object.fromEntries(Object.keys(this.layers).map((k) => [k, document.createElement('canvas')]));
      for (const [k, layer] of Object.entries(this.layers)) {
        const c = canvases[k];
        c.width = layer.canvas.width;
        c.height = layer.canvas.height;
        c.getContext('2d').drawImage(layer.canvas, 0, 0);
      }
      this.stale = { canvases, layout: this.drawn };
    }
    this.drawn = this.layout;
    this.drawScene();
    this.redrawing = { steps: redrawSteps(this, REDRAW_BATCH, this.store.length), to: this.store.length };
    this.stepRedraw(); // its first step forgets the markers before more records come
  }

  stepRedraw() {
    const r = this.redrawing;
    const until = performance.now() + REDRAW_MS;
    let s;
    do s = r.steps.next(); while (!s.done && performance.now() < until);
    if (!s.done) return;
    this.redrawing = null;
    this.stale = null;
    this.drawLayers(r.to, this.store.length); // what came while it was redrawn
    this.dirty = true;
  }

  /** The offscreen layers onto `ctx`, moved from the transform they were drawn at to the shown one. */
  compositeLayer(ctx, name) {
    const L = this.layout;
    const from = this.stale ? this.stale.layout : this.drawn;
    const canvas = this.stale ? this.stale.canvases[name] : this.layers[name].canvas;
    if (from.same(L)) { ctx.drawImage(canvas, 0, 0); return; }
    const s = L.scale / from.scale;
    if (name === 'scene') { // outside the old picture: the background
      ctx.fillStyle = PALETTE.background;
      ctx.fillRect(0, 0, L.width, L.height);
    }
    ctx.drawImage(canvas, L.ox - from.ox * s, L.oy - from.oy * s, from.width * s, from.height * s);
  }

  /**
   * Composite the layers and draw the top layer. `time` in ms drives the robot animation; the
   * animated robot's state is left in `robotState` (null when there is none).
   */
  render(time, animFps) {
    if (!this.layout) return;
    this.followViewport();
    const animating = this.showResult && this.frames.length > 0;
    if (!animating) this.robotState = null;
    this.syncModelLayers(time);
    const flashing = this.flashes.length > 0;
    if (!this.dirty && !animating && !flashing) return;
    this.dirty = false;
    const { ctx } = this;
    const L = this.layout;
    ctx.clearRect(0, 0, L.width, L.height);
    let frame = null;
    if (animating) {
      const frames = this.options.animateRaw && this.rawFrames.length ? this.rawFrames : this.frames;
      frame = frames[Math.floor((time / 1000) * animFps) % frames.length];
    }
    // picture.js's layers in order: the offscreen ones composited, the others drawn now
    const f = { frame, best: bestOf(this), time, ui: true };
    let composited = null;
    for (const e of PICTURE) {
      if (e.layer) {
        if (e.layer !== composited) this.compositeLayer(ctx, e.layer);
        composited = e.layer;
      } else if (this.scenario) e.draw(ctx, L, this, f);
    }
    if (frame) this.robotState = frame.state;
    this.drawTopHooks(ctx, L);
  }

  /** The hooks drawn over everything (they also run, to clear what they show, with no scenario). */
  drawTopHooks(ctx, L) {
    for (const hook of this.topHooks) hook(ctx, L);
  }

  /** The start or goal state shown: the one being edited, else the scenario's. */
  stateOf(which) {
    return this.preview[which] || (this.scenario && this.scenario[which]) || null;
  }

  /** Screen position (device px) of a rigid body's rotation handle, or null. */
  handlePoint(which) {
    const q = this.stateOf(which);
    if (!this.layout || !q || !dragsHeading(this.scenario.robot)) return null;
    const L = this.layout;
    const r = footprintRadius(this.scenario.robot) * L.scale + L.px(14);
    return { x: L.sx(q[0]) + r * Math.cos(q[2]), y: L.sy(q[1]) - r * Math.sin(q[2]), cx: L.sx(q[0]), cy: L.sy(q[1]) };
  }

  /**
   * [{label, color, shape}] for the legend under the canvas, from the palette and style table
   * (the switchable overlays have their own marks in the overlay box). The trees are named for
   * the planner `name` when it is given (what tree 0 and tree 1 mean differs: the registry's legend).
   */
  legend(name = null) {
    const items = [
      { label: 'obstacle', color: PALETTE.obstacle, shape: 'box' },
      { label: 'start', color: PALETTE.start, shape: 'box' },
      { label: 'goal', color: PALETTE.goal, shape: 'box' },
      ...treeLegend(name),
      { label: 'raw path', color: PALETTE.rawPath, shape: 'dash' },
      { label: 'smoothed path', color: PALETTE.smoothPath, shape: 'thick' },
      { label: 'robot', color: PALETTE.robot, shape: 'box' },
    ];
    if (this.scenario?.inspection?.points?.length) {
      items.push({ label: 'inspection point', color: PALETTE.inspection, shape: 'box' });
    }
    if (this.query?.points?.length >= 2) {
      items.push({ label: 'new query: its path (start hollow, goal filled)', color: PALETTE.queryAnswer, shape: 'thick' });
    }
    return items;
  }
}

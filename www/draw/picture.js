// The picture, bottom up: one list of layers that both renderers draw from. The canvas (view.js)
// keeps the layers marked `layer` on offscreen canvases (drawn incrementally as records come, in
// full by redraw.js, both with the functions of layers.js) and composites them in this order,
// drawing the others over them every frame with `draw`; the SVG export (ui/export-svg.js) calls
// `draw` of every layer, in this order, on an SVG-recording context (svg-context.js), a <g id> a
// layer. `ui`: drawn on the canvas only (handles, flashes that fade in 0.6 s, editor hooks).
// `merge`: how the SVG merges a layer's paths (svg-context.js). `draw(ctx, L, view, f)` may return
// a generator (yielding units of work done) for layers of many records or nodes; `f` is what the
// frame shows: {frame, best, obstacles, ui, time}.

import { EventKind } from '../run/events.js';
import { PALETTE, STYLE } from './palette.js';
import { drawObstacle, drawMarker, drawPolyline } from './transform.js';
import { drawRobotShape, drawInspection, robotStyle, outlineOf } from './robots.js';
import { CellsDrawing } from './cells.js';
import { drawDensity } from './density.js';
import { drawGraphEdges, drawRoadmap, drawQueryAnswer } from './graphs.js';
import { drawFlashes, drawSensor, drawHandle } from './marks.js';
import { drawAccepted, drawCollisions, drawDomains, drawSamples, ranges, treeSteps } from './layers.js';

/** The informed set's ellipses ([cx, cy, a, b, ux, uy, cost] each, oldest first): the latest bold, the earlier faint. */
function drawInformed(ctx, L, list) {
  list.forEach(([cx, cy, a, b, ux, uy], i) => {
    if (![cx, cy, a, b, ux, uy].every(Number.isFinite)) return;
    const latest = i === list.length - 1;
    ctx.save();
    ctx.globalAlpha = latest ? 1 : 0.25;
    ctx.strokeStyle = PALETTE.informed;
    ctx.lineWidth = L.px(latest ? 2 : 1);
    ctx.beginPath();
    const n = 96; // a polygon of n sides: both renderers draw it alike, rotated or not
    for (let k = 0; k <= n; k++) {
      const t = (2 * Math.PI * k) / n, p = a * Math.cos(t), q = b * Math.sin(t);
      const x = L.sx(cx + p * ux - q * uy), y = L.sy(cy + p * uy + q * ux);
      if (k) ctx.lineTo(x, y); else ctx.moveTo(x, y);
    }
    ctx.stroke();
    ctx.restore();
  });
}

const boundsRect = (ctx, L, [x0, y0, x1, y1]) => [L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale];

/** A start or goal: its outline (the edited state's, while one is dragged), and its rotation handle on the canvas. */
function endpoint(which) {
  return (ctx, L, v, f) => {
    const state = v.stateOf(which);
    if (!state) return;
    const polys = v.preview[which] ? outlineOf(v.scenario.robot, state) : v[which];
    drawRobotShape(ctx, L, v.scenario.robot, polys, state, robotStyle(PALETTE[which], which, PALETTE));
    if (f.ui && v.editable) drawHandle(ctx, L, v.handlePoint(which), PALETTE[which]);
  };
}

/**
 * @typedef {{id: string, layer?: string, ui?: boolean, merge?: 'order' | 'style', className?: string,
 *   draw: (ctx: any, L: any, view: any, f: any) => any}} PictureLayer
 */
/** @type {PictureLayer[]} */
export const PICTURE = [
  { id: 'background', layer: 'scene', draw(ctx, L) {
    ctx.fillStyle = PALETTE.background;
    ctx.fillRect(0, 0, L.width, L.height);
  } },
  { id: 'free', layer: 'scene', draw(ctx, L, v) {
    ctx.fillStyle = PALETTE.free;
    ctx.fillRect(...boundsRect(ctx, L, v.scenario.bounds));
  } },
  { id: 'obstacles', layer: 'scene', draw(ctx, L, v, f) {
    for (const ob of f.obstacles ?? v.scenario.obstacles ?? []) drawObstacle(ctx, L, ob);
  } },
  { id: 'bounds', layer: 'scene', draw(ctx, L, v) {
    ctx.strokeStyle = PALETTE.bounds;
    ctx.lineWidth = L.px(1.5);
    ctx.strokeRect(...boundsRect(ctx, L, v.scenario.bounds));
  } },
  // cells, heat map, arrows (cells.js; the view keeps its own CellsDrawing, drawn incrementally)
  { id: 'cells', layer: 'cells', draw(ctx, L, v) {
    if (v.cells.active(v.options)) new CellsDrawing({ canvas: null, ctx }, v.model).redraw(L, v.options);
  } },
  { id: 'veil', draw(ctx, L, v) { if (v.cells.active(v.options)) v.cells.veil(ctx, L, v.scenario); } },
  { id: 'density', merge: 'style', draw(ctx, L, v) {
    if (v.options.showDensity && !v.showResult) drawDensity(ctx, L, v.model?.density, v.scenario.bounds);
  } },
  { id: 'informed', draw(ctx, L, v) {
    if (v.options.showInformed && v.model?.informed.length) drawInformed(ctx, L, v.model.informed);
  } },
  { id: 'samples', layer: 'under', merge: 'style', *draw(ctx, L, v, f) {
    const st = { pendingSample: null };
    const o = v.options;
    if (!o.showAccepted && !o.showRejected && !o.showTries) return;
    for (const [r0, r1] of ranges(v.store.length, f.batch ?? Infinity)) {
      drawSamples(ctx, L, v.store, r0, r1, o, st);
      yield r1 - r0;
    }
    if (st.pendingSample && o.showAccepted && v.showResult) drawAccepted(ctx, L, st.pendingSample);
  } },
  { id: 'graph', layer: 'under', merge: 'style', draw(ctx, L, v) { drawGraphEdges(ctx, L, v.store, 0, v.store.length); } },
  { id: 'domains', layer: 'domain', draw(ctx, L, v) {
    if (v.options.showDomains && v.model) drawDomains(ctx, L, v.model, v.scenario.bounds);
  } },
  { id: 'trees', layer: 'tree', draw: (ctx, L, v, f) => treeSteps(ctx, L, v, f.batch ?? Infinity) },
  { id: 'roadmap', layer: 'tree', merge: 'style', *draw(ctx, L, v, f) {
    if (!v.roadmap) return;
    for (const [r0, r1] of ranges(v.store.length, f.batch ?? Infinity)) {
      drawRoadmap(ctx, L, v.store, r0, r1, true);
      yield r1 - r0;
    }
  } },
  { id: 'collisions', layer: 'over', merge: 'style', draw(ctx, L, v) {
    if (v.options.showCollisions) drawCollisions(ctx, L, v.store, 0, v.store.length);
  } },
  // the top layer, drawn every frame
  { id: 'inspection', draw(ctx, L, v) {
    const seen = v.options.showSeen && v.model ? v.model.seen : null;
    drawInspection(ctx, L, v.scenario.inspection?.points, PALETTE.inspection, PALETTE.robotEdge, seen, PALETTE.seen);
  } },
  { id: 'start', className: 'start', draw: endpoint('start') },
  { id: 'goal', className: 'goal', draw: endpoint('goal') },
  { id: 'markers', draw(ctx, L, v) { for (const [kind, x, y] of v.markers) drawMarker(ctx, L, STYLE[kind], x, y); } },
  { id: 'flashes', ui: true, draw(ctx, L, v, f) { if (v.flashes.length) v.flashes = drawFlashes(ctx, L, v.flashes, f.time); } },
  { id: 'best', draw(ctx, L, v, f) {
    if (f.best.length < 2) return;
    drawPolyline(ctx, L, f.best, PALETTE.bestCasing, L.px(6));
    drawPolyline(ctx, L, f.best, PALETTE.best, L.px(3.5));
  } },
  { id: 'query-path', draw(ctx, L, v) {
    if (v.showResult || !v.queryPath) return;
    const q = STYLE[EventKind.QUERY_PATH];
    drawPolyline(ctx, L, v.queryPath, q.color, L.px(q.width), q.dash.map((d) => L.px(d)));
  } },
  { id: 'last-sample', draw(ctx, L, v) { if (!v.showResult && v.lastSample) drawMarker(ctx, L, STYLE[EventKind.SAMPLE], ...v.lastSample); } },
  { id: 'regions', draw(ctx, L, v) { v.cells.drawTop(ctx, L, v.options, v.scenario.bounds, v.scenario.goal); } },
  { id: 'overlay-hooks', ui: true, draw(ctx, L, v) { for (const hook of v.overlayHooks) hook(ctx, L); } },
  { id: 'raw-path', draw(ctx, L, v) {
    if (v.showResult && v.path) drawPolyline(ctx, L, v.path, PALETTE.rawPath, L.px(2), [L.px(6), L.px(4)]);
  } },
  { id: 'smoothed-path', draw(ctx, L, v) {
    if (!v.showResult || !v.smoothed) return;
    drawPolyline(ctx, L, v.smoothed, PALETTE.pathCasing, L.px(6));
    drawPolyline(ctx, L, v.smoothed, PALETTE.smoothPath, L.px(4));
  } },
  { id: 'query-answer', draw(ctx, L, v) { drawQueryAnswer(ctx, L, v.query); } },
  { id: 'sensor', draw(ctx, L, v, f) {
    if (v.scenario.inspection && v.options.showFov) drawSensor(ctx, L, v, f.frame ? f.frame.state : v.stateOf('start'), f.best);
  } },
  { id: 'robot', className: 'robot', draw(ctx, L, v, f) {
    if (f.frame) drawRobotShape(ctx, L, v.scenario.robot, f.frame.polys, f.frame.state, robotStyle(null, 'robot', PALETTE));
  } },
  { id: 'robot-t', draw(ctx, L, v, f) { if (f.frame) v.cells.drawRobotT(ctx, L, v.options, f.frame.state); } },
];

/** The best branch so far, when its overlay is on ([[x, y], ...]). */
export const bestOf = (v) => (v.options.showBest && v.model ? v.model.bestBranch() : []);

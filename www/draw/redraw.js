// The run's layers redrawn in full from the stored records and the run model (view.js redrawTree,
// redrawTreeLayer), written as generators: every `yield` ends a step of at most `batch` nodes or
// records and gives the share of the work done so far. The view runs them to the end at once
// (`batch` Infinity: one step a layer, the same drawing calls as a single pass); an export
// (ui/exports.js) draws a big run in steps of EXPORT_BATCH, yielding to the page between them, so
// the tab keeps drawing frames, shows progress and can cancel.

import { EventKind, STRIDE } from '../run/events.js';
import { addQueryEdge, drawRoadmap } from './graphs.js';
import { ranges, treeSteps } from './layers.js';

/**
 * Nodes or records an export draws between two yields to the page: about 30–60 ms of drawing on a
 * laptop (a million-node RRT run is some 3 million records, so about 60 steps).
 */
export const EXPORT_BATCH = 50000;

/** Run drawing steps to their end (the live view's full redraws). */
export function drawAll(steps) {
  for (let s = steps.next(); !s.done; s = steps.next()) { /* each step draws */ }
}

/**
 * The tree layer from the model's mirror (edges and nodes, exhausted nodes greyed, an earlier
 * attempt of hex-potential faint) and the roadmap from records [0, `to`). Yields the nodes or
 * records drawn by each step.
 */
export function* treeLayerSteps(view, batch = Infinity, to = view.store.length) {
  const { ctx } = view.treeLayer;
  const L = view.drawn;
  ctx.clearRect(0, 0, L.width, L.height);
  view.attemptSeen = view.model ? view.model.cells.attempt : -1;
  yield* treeSteps(ctx, L, view, batch);
  if (view.roadmap) {
    for (const [r0, r1] of ranges(to, batch)) {
      drawRoadmap(ctx, L, view.store, r0, r1, true);
      yield r1 - r0;
    }
  }
  view.treeSeen = view.model ? view.model.treeVersion : 0;
  view.treeDrawnAt = performance.now();
  view.dirty = true;
}

/** The units of work redrawSteps does for `view` (nodes, and records per pass over them). */
export function redrawWork(view, to = view.store.length) {
  const nodes = (view.model?.trees ?? []).reduce((s, t) => s + Math.max(t.n, 1), 0);
  return nodes + to * (2 + (view.roadmap ? 1 : 0) + (view.options.showCollisions ? 1 : 0));
}

/**
 * Every run layer again, from the records [0, `to`) and the model (view.js redrawTree): the tree
 * layer, samples and tries, blocked motions, dynamic domains, cells; then the markers. Yields the
 * share of the work done (0…1) after each step.
 */
export function* redrawSteps(view, batch = Infinity, to = view.store.length) {
  if (!view.layout) return;
  const total = Math.max(1, redrawWork(view, to));
  let done = 0;
  view.markers = [];
  view.flashes = [];
  view.queryPath = null;
  const L = view.drawn;
  view.underLayer.ctx.clearRect(0, 0, L.width, L.height);
  view.overLayer.ctx.clearRect(0, 0, L.width, L.height);
  for (const n of treeLayerSteps(view, batch, to)) { done += n; yield done / total; }
  view.pendingSample = null;
  for (const [r0, r1] of ranges(to, batch)) {
    view.drawUnder(r0, r1);
    done += r1 - r0;
    yield done / total;
  }
  if (view.showResult) view.finishRun();
  if (view.options.showCollisions) {
    for (const [r0, r1] of ranges(to, batch)) {
      view.drawOver(r0, r1);
      done += r1 - r0;
      yield done / total;
    }
  }
  view.redrawDomains();
  view.cells.redraw(L, view.options);
  for (const [r0, r1] of ranges(to, batch)) {
    for (const [d, o0, o1] of view.store.spans(r0, r1)) for (let o = o0; o < o1; o += STRIDE) {
      if (d[o] === EventKind.TREES_CONNECTED || d[o] === EventKind.SOLVED) view.markers.push([d[o], d[o + 4], d[o + 5]]);
      else if (d[o] === EventKind.QUERY_PATH) view.queryPath = addQueryEdge(view.queryPath, d, o);
    }
    done += r1 - r0;
    yield done / total;
  }
  view.dirty = true;
}

// The run's layers redrawn in full from the stored records and the run model (view.js redrawTree,
// redrawTreeLayer), written as generators: every `yield` ends a step of at most `batch` nodes or
// records and gives the share of the work done so far. The view runs them to the end at once
// (`batch` Infinity: one step a layer, the same drawing calls as a single pass); an export
// (ui/exports.js) draws a big run in steps of EXPORT_BATCH, yielding to the page between them, so
// the tab keeps drawing frames, shows progress and can cancel.

import { EventKind, STRIDE } from '../run/events.js';
import { STYLE } from './palette.js';
import { drawExhausted } from './transform.js';
import { addQueryEdge, drawRoadmap } from './graphs.js';

/**
 * Nodes or records an export draws between two yields to the page: about 30–60 ms of drawing on a
 * laptop (a million-node RRT run is some 3 million records, so about 60 steps).
 */
export const EXPORT_BATCH = 50000;

/** Run drawing steps to their end (the live view's full redraws). */
export function drawAll(steps) {
  for (let s = steps.next(); !s.done; s = steps.next()) { /* each step draws */ }
}

/** [from, to) ranges of at most `batch` covering [0, n). */
function* ranges(n, batch) {
  for (let from = 0; from < n; from += batch) yield [from, Math.min(n, from + batch)];
}

/**
 * The tree layer from the model's mirror (edges and nodes, exhausted nodes greyed, an earlier
 * attempt of hex-potential faint) and the roadmap from records [0, `to`). Yields the nodes or
 * records drawn by each step.
 */
export function* treeLayerSteps(view, batch = Infinity, to = view.store.length) {
  const { ctx } = view.treeLayer;
  const L = view.layout;
  ctx.clearRect(0, 0, L.width, L.height);
  const edge = STYLE[EventKind.NODE_ADDED];
  const node = Math.max(1, Math.round(L.px(edge.size)));
  const trees = view.model ? view.model.trees : [];
  view.attemptSeen = view.model ? view.model.cells.attempt : -1;
  for (let k = 0; k < trees.length; k++) {
    const t = trees[k];
    const color = edge.colors[view.treeGroup(k)];
    const alpha = view.attemptSeen > k ? 0.3 : 1; // an earlier attempt of hex-potential
    for (const [i0, i1] of ranges(Math.max(t.n, 1), batch)) {
      ctx.globalAlpha = alpha;
      ctx.beginPath();
      ctx.fillStyle = color;
      for (let i = i0; i < i1 && i < t.n; i++) {
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
      if (view.options.showExhausted && t.exhausted) {
        const pts = [];
        for (let i = i0; i < i1 && i < t.n; i++) if (t.known(i) && t.isExhausted(i)) pts.push(t.x[i], t.y[i]);
        drawExhausted(ctx, L, pts);
      }
      ctx.globalAlpha = 1;
      yield i1 - i0;
    }
  }
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
  for (const n of treeLayerSteps(view, batch, to)) { done += n; yield done / total; }
  const L = view.layout;
  view.underLayer.ctx.clearRect(0, 0, L.width, L.height);
  view.pendingSample = null;
  for (const [r0, r1] of ranges(to, batch)) {
    view.drawUnder(r0, r1);
    done += r1 - r0;
    yield done / total;
  }
  if (view.showResult) view.finishRun();
  view.overLayer.ctx.clearRect(0, 0, L.width, L.height);
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

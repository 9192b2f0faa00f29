// The run layers' drawing, as functions of a 2-D context and what they draw (no view state
// changed): the view (view.js, redraw.js) calls them on its offscreen layers, incrementally or in
// full, and the SVG export (picture.js, ui/export-svg.js) on an SVG-recording context.

import { EventKind, STRIDE } from '../run/events.js';
import { PALETTE, STYLE } from './palette.js';
import { drawExhausted } from './transform.js';

/** [from, to) ranges of at most `batch` covering [0, n). */
export function* ranges(n, batch) {
  for (let from = 0; from < n; from += batch) yield [from, Math.min(n, from + batch)];
}

/** An accepted sample at world point `at` = [x, y]. @param {CanvasRenderingContext2D} ctx @param {any} L @param {number[]} at */
export function drawAccepted(ctx, L, at) {
  const [x, y] = at;
  const s = Math.max(2, Math.round(L.px(2.5)));
  ctx.fillStyle = PALETTE.accepted;
  ctx.fillRect(Math.round(L.sx(x) - s / 2), Math.round(L.sy(y) - s / 2), s, s);
}

/**
 * Samples and raw tries of records [from, to) of `store`, for overlays `o`. A SAMPLE is accepted
 * when no SAMPLE_REJECTED follows it before the next SAMPLE (the rejection is drawn at the same
 * point), so it is drawn once the next sample or its rejection comes; `st.pendingSample` holds the
 * one not yet drawn between calls (the caller draws it when the run is over).
 */
export function drawSamples(ctx, L, store, from, to, o, st) {
  const { showAccepted, showRejected, showTries } = o;
  const rej = STYLE[EventKind.SAMPLE_REJECTED];
  const tries = STYLE[EventKind.SAMPLE_TRY];
  const rs = Math.max(1, Math.round(L.px(rej.size)));
  const ts = Math.max(1, Math.round(L.px(tries.size)));
  for (const [d, o0, o1] of store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
    const kind = d[o];
    if (kind === EventKind.SAMPLE) {
      if (st.pendingSample && showAccepted) drawAccepted(ctx, L, st.pendingSample);
      st.pendingSample = [d[o + 4], d[o + 5]];
    } else if (kind === EventKind.SAMPLE_REJECTED) {
      st.pendingSample = null;
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

/** Blocked motions (crosses) of records [from, to) of `store`. */
export function drawCollisions(ctx, L, store, from, to) {
  const col = STYLE[EventKind.COLLISION];
  const cs = L.px(col.size);
  ctx.beginPath();
  for (const [d, o0, o1] of store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
    if (d[o] !== EventKind.COLLISION) continue;
    const x = L.sx(d[o + 4]), y = L.sy(d[o + 5]);
    ctx.moveTo(x - cs, y - cs); ctx.lineTo(x + cs, y + cs);
    ctx.moveTo(x - cs, y + cs); ctx.lineTo(x + cs, y - cs);
  }
  ctx.strokeStyle = col.color;
  ctx.lineWidth = L.px(col.width);
  ctx.stroke();
}

/** Dynamic-domain circles of the run model's trees (latest radius per node), clipped to `bounds`. */
export function drawDomains(ctx, L, model, bounds) {
  const st = STYLE[EventKind.DOMAIN];
  const [x0, y0, x1, y1] = bounds;
  ctx.save();
  ctx.beginPath();
  ctx.rect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
  ctx.clip();
  ctx.beginPath();
  for (const t of model.trees) {
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
}

/**
 * The trees of the run model `view.model` (edges and nodes, exhausted nodes greyed, an earlier
 * attempt of hex-potential faint), `batch` nodes a step; yields the nodes drawn by each step. An
 * SVG-recording context gets a group a tree (`beginLayer`, which a canvas has not).
 */
export function* treeSteps(ctx, L, view, batch = Infinity) {
  const edge = STYLE[EventKind.NODE_ADDED];
  const node = Math.max(1, Math.round(L.px(edge.size)));
  const trees = view.model ? view.model.trees : [];
  const attempt = view.model ? view.model.cells.attempt : -1;
  for (let k = 0; k < trees.length; k++) {
    const t = trees[k];
    const color = edge.colors[view.treeGroup(k)];
    const alpha = attempt > k ? 0.3 : 1; // an earlier attempt of hex-potential
    ctx.beginLayer?.(`tree-${k}`, { merge: 'style' });
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
    ctx.endLayer?.();
  }
}

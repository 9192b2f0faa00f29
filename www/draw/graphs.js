// Graphs drawn from their event records (not from the model's tree mirror): the roadmaps' edges
// (PRM, PRM*: checked, solid; Lazy PRM: unchecked dashed, then what its checks found), their
// milestones, the latest graph search's path, and the visibility graph's edges. view.js calls these
// on its layers, incrementally as records are revealed and in full on a redraw.

import { EventKind, STRIDE } from '../run/events.js';
import { PALETTE, STYLE } from './palette.js';
import { drawPolyline } from './transform.js';

/** A QUERY_PATH record added to `path` ([[x, y], ...]); its first edge (tree 0) starts a new one. */
export function addQueryEdge(path, d, o) {
  const out = d[o + 1] === 0 || !path ? [[d[o + 4], d[o + 5]]] : path;
  out.push([d[o + 6], d[o + 7]]);
  return out;
}

/**
 * Roadmap edges of records [from, to) of `store` onto `ctx`: checked edges solid, Lazy PRM's
 * unchecked ones dashed, then what its checks found (blocked: faint vermilion over the dashes;
 * valid: solid, on top). With `nodes`, milestones too (NODE_ADDED records without a parent, which
 * the model's tree mirror does not draw).
 */
export function drawRoadmap(ctx, L, store, from, to, nodes) {
  const added = STYLE[EventKind.ROADMAP_EDGE];
  const checked = STYLE[EventKind.EDGE_CHECKED];
  const node = Math.max(1, Math.round(L.px(STYLE[EventKind.NODE_ADDED].size)));
  const pass = (kind, group, style, dash) => {
    ctx.beginPath();
    for (const [d, o0, o1] of store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
      if (d[o] !== kind || (d[o + 1] > 0 ? 1 : 0) !== group) continue;
      ctx.moveTo(L.sx(d[o + 4]), L.sy(d[o + 5]));
      ctx.lineTo(L.sx(d[o + 6]), L.sy(d[o + 7]));
    }
    ctx.strokeStyle = style.colors[group];
    ctx.lineWidth = L.px(style.width);
    ctx.setLineDash(dash);
    ctx.stroke();
    ctx.setLineDash([]);
  };
  pass(EventKind.ROADMAP_EDGE, 1, added, added.dash.map((v) => L.px(v)));
  pass(EventKind.EDGE_CHECKED, 1, checked, []);
  pass(EventKind.ROADMAP_EDGE, 0, added, []);
  pass(EventKind.EDGE_CHECKED, 0, checked, []);
  if (!nodes) return;
  ctx.fillStyle = STYLE[EventKind.NODE_ADDED].colors[0];
  for (const [d, o0, o1] of store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
    if (d[o] !== EventKind.NODE_ADDED || d[o + 3] >= 0) continue;
    ctx.fillRect(Math.round(L.sx(d[o + 4]) - node / 2), Math.round(L.sy(d[o + 5]) - node / 2), node, node);
  }
}

/** The visibility graph's kept edges (GRAPH_EDGE records marked clear) of records [from, to): one stroke. */
export function drawGraphEdges(ctx, L, store, from, to) {
  const graph = STYLE[EventKind.GRAPH_EDGE];
  ctx.beginPath();
  let edges = 0;
  for (const [d, o0, o1] of store.spans(from, to)) for (let o = o0; o < o1; o += STRIDE) {
    if (d[o] !== EventKind.GRAPH_EDGE || !(d[o + 9] > 0)) continue;
    ctx.moveTo(L.sx(d[o + 4]), L.sy(d[o + 5]));
    ctx.lineTo(L.sx(d[o + 6]), L.sy(d[o + 7]));
    edges++;
  }
  if (!edges) return;
  ctx.strokeStyle = graph.color;
  ctx.lineWidth = L.px(graph.width);
  ctx.stroke();
}

/**
 * Another query on a finished roadmap (ui/roadmap-query.js): `query` = {points, picks}: the
 * answer's path (projected points) drawn thick over the run's, and the clicked start and goal as
 * rings (the start hollow, the goal filled).
 */
export function drawQueryAnswer(ctx, L, query) {
  if (!query) return;
  if (query.points?.length >= 2) {
    drawPolyline(ctx, L, query.points, PALETTE.pathCasing, L.px(7));
    drawPolyline(ctx, L, query.points, PALETTE.queryAnswer, L.px(4.5));
  }
  (query.picks || []).forEach(([x, y], i) => {
    ctx.beginPath();
    ctx.arc(L.sx(x), L.sy(y), L.px(6), 0, 2 * Math.PI);
    ctx.lineWidth = L.px(2.5);
    ctx.strokeStyle = PALETTE.queryAnswer;
    ctx.fillStyle = i === 0 ? '#ffffff' : PALETTE.queryAnswer;
    ctx.fill();
    ctx.stroke();
  });
}

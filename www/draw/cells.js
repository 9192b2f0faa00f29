// Cells and potential fields: what the hex-potential and potential-field planners record, mirrored
// (CellMirror, cell-mirror.js, fed by playback.js's RunModel) and drawn (CellsDrawing, owned by view.js: its
// offscreen 'cells' layer lies between the scene and the samples; the region of influence, the
// local minima and the robot's t/2 circle are drawn on the top layer every frame).
//
//   CELL + CELL_SHAPE  a cell of the hexagonal decomposition, complete once all its outline
//                      vertices have come (NaN pads the last CELL_SHAPE); drawn in arrival order,
//                      so a refined cell is covered by its children (they partition it exactly);
//   CELL_STATE         the search's verdict on a cell: visited or, for A*/Dijkstra, closed (blue),
//                      opened by A*/Dijkstra (green), step-blocked (pink, ×, the reason on hover;
//                      an open or closed cell stays so), outside the region (hover text only);
//   POTENTIAL          a candidate's terms, the latest per cell, for the hover text;
//   REGION             the region of influence (an attempt): a new one resets the verdicts and
//                      replaces the field; `t` (the robot's diagonal) is remembered;
//   FIELD              the heat map and the descent arrows: a hex cell's own polygon when `id` is
//                      a known cell, else a square tile of half-size `pc1`;
//   MINIMUM            a local minimum of the classic field: a ring with a label.
// Every text shown comes from numbers and fixed words, set with textContent by the page.

import { EventKind } from '../run/events.js';
import { PALETTE, STYLE } from './palette.js';
import { markLegend } from './capabilities.js';
import { drawObstacle, pointInPolygon } from './transform.js';
import { CellRaster, SMALL_CELL_PX, smallCell } from './cell-raster.js';

export { CellMirror } from './cell-mirror.js';

const BIG = 20000;     // above this many cells, full redraws happen at most every…
const BIG_MS = 250;    // …this many ms
const ARROW_GAP = 14;  // css px: at most one arrow per square of this size

const LABELS = ['free', 'mixed', 'full'];
const STATES = ['passable (open)', 'step blocked', 'visited (closed)', 'outside the region of influence', 'obstacle cell'];
const WHY = {
  1: 'an obstacle vertex within t/2',
  2: 'an obstacle vertex in the swept rectangle',
  3: 'an obstacle edge crosses the swept region',
  4: "the map's edge is within t/2",
};


/** A number for the hover text. */
export function fmt(v) {
  if (v === Infinity) return '∞';
  if (v === -Infinity) return '−∞';
  if (!Number.isFinite(v)) return '–';
  if (v === 0) return '0';
  const a = Math.abs(v);
  const s = a < 1e-3 || a >= 1e5 ? v.toExponential(2) : String(Number(v.toPrecision(3)));
  return s.replace('-', '−');
}

/** The classic field's heat map colours by value up to this quantile of its finite values. */
export const HEAT_CAP = 0.9;

/**
 * The heat map's colour index of a value: by rank among the field's finite values (each colour
 * holds about as many samples, so neither the repulsion's blow-up near obstacles nor a long
 * attractive slope flattens the rest; equal values share a colour), or when `linear` (the classic
 * field: a local minimum must look as low as it is) by value from the lowest to the HEAT_CAP
 * quantile, the values above it in the darkest colour; -1 for an infinite (colliding) value.
 */
export function heatScale(field, bins = PALETTE.heat.length, linear = false) {
  const vals = Float64Array.from(field.map((s) => s.v).filter(Number.isFinite)).sort();
  const n = vals.length;
  if (!n) return () => -1;
  if (linear) {
    // by value, from the lowest up to the 90th percentile (HEAT_CAP); the top tenth in the darkest colour
    const lo = vals[0], span = vals[Math.floor(HEAT_CAP * (n - 1))] - lo;
    return (v) => (!Number.isFinite(v) ? -1 : span > 0 ? Math.min(bins - 1, Math.max(0, Math.floor(((v - lo) / span) * bins))) : 0);
  }
  return (v) => {
    if (!Number.isFinite(v)) return -1;
    let lo = 0, hi = n; // the first index whose value is ≥ v
    while (lo < hi) { const mid = (lo + hi) >> 1; if (vals[mid] < v) lo = mid + 1; else hi = mid; }
    return Math.min(bins - 1, Math.floor((lo / n) * bins));
  };
}

/** Draws a CellMirror on its layer (from the run model `model.cells`). */
export class CellsDrawing {
  constructor(layer, model) {
    this.layer = layer;
    this.model = model;
    this.raster = new CellRaster(); // the small cells' pixels (cell-raster.js)
    this.reset();
  }

  get mirror() { return this.model ? this.model.cells : null; }

  /** Forget what was drawn (the view clears the layer). */
  reset() {
    this.drawn = 0;        // cells of mirror.order drawn
    this.statesDrawn = 0;  // entries of mirror.changed drawn
    this.fieldSeen = -1;
    this.stale = false;    // a full redraw is owed
    this.drawnAt = 0;
    this.mirrorSeen = null;
    this.raster?.clear();
  }

  /** Whether there is anything to draw (the view then veils the obstacles over the layer). */
  active(o) {
    const m = this.mirror;
    return !!m && ((o.showCells && m.order.length > 0) || (o.showHeat && m.field.length > 0) || (o.showArrows && m.field.length > 0));
  }

  /** A toggle changed: redraw at the next sync. */
  invalidate() { this.stale = true; }

  /**
   * Bring the layer up to date with the mirror: new cells and verdicts drawn on top, a full
   * redraw when the field or region changed (big decompositions at most every BIG_MS, unless `now`).
   */
  sync(L, o, time, now = false) {
    const m = this.mirror;
    if (!m || !L) return false;
    if (m !== this.mirrorSeen) { this.mirrorSeen = m; this.stale = true; }
    if (m.fieldVersion !== this.fieldSeen) this.stale = true;
    if (this.statesDrawn < m.changed.length && (o.showHeat || o.showArrows)) this.stale = true;
    if (this.stale) {
      if (now || m.order.length < BIG || time - this.drawnAt >= BIG_MS) { this.redraw(L, o); return true; }
      return false;
    }
    let drew = false;
    const { ctx } = this.layer;
    if (this.drawn < m.order.length) {
      if (o.showCells) this.drawCells(ctx, L, o, m.orderCells, this.drawn, m.order.length);
      this.drawn = m.order.length;
      drew = true;
    }
    if (this.statesDrawn < m.changed.length) {
      if (o.showCells) this.drawCells(ctx, L, o, cellsOf(m, m.changed, this.statesDrawn), 0, m.changed.length - this.statesDrawn);
      this.statesDrawn = m.changed.length;
      drew = true;
    }
    return drew;
  }

  /** The whole layer from the mirror: cells, heat map, verdicts, arrows. */
  redraw(L, o) {
    const m = this.mirror;
    const { ctx } = this.layer;
    ctx.clearRect(0, 0, L.width, L.height);
    this.raster.clear(L);
    this.stale = false;
    this.drawnAt = performance.now();
    if (!m) return;
    this.mirrorSeen = m;
    this.fieldSeen = m.fieldVersion;
    this.drawn = m.order.length;
    this.statesDrawn = m.changed.length;
    if (o.showCells) this.drawCells(ctx, L, o, m.orderCells, 0, m.order.length);
    if (o.showHeat && m.field.length) {
      this.drawHeat(ctx, L);
      if (o.showCells) this.drawCells(ctx, L, o, cellsOf(m, m.changed, 0), 0, m.changed.length, true); // the × marks
    }
    if (o.showArrows && m.field.length) this.drawArrows(ctx, L);
  }

  /**
   * Cells cells[from, to) (CellMirror cells) filled by label and level, or by verdict (× on step-blocked cells);
   * `overHeat`: outlines and marks only, over the heat map. A few paths, not one a cell: the cells
   * of a level are filled one colour at a time, then outlined at once, level by level (a refined
   * cell's children, a level down, cover it); cells under SMALL_CELL_PX are painted as pixels.
   */
  drawCells(ctx, L, o, cells, from, to, overHeat = false) {
    const st = STYLE[EventKind.CELL];
    const marks = [];
    const levels = new Map(); // level → Map(fill → [cell])
    const raster = this.raster;
    // the mirror's own list: its small rectangles are read from its table (no object each)
    const m = this.mirror;
    const t = cells === m?.orderCells && !overHeat ? m.table : null;
    const small = SMALL_CELL_PX / L.scale;
    for (let k = from; k < to; k++) {
      if (t && t.rect[k]) {
        const b = 4 * k;
        const x0 = t.box[b], y0 = t.box[b + 1], x1 = t.box[b + 2], y1 = t.box[b + 3];
        if (x1 - x0 < small && y1 - y0 < small
          && raster.paintBox(x0, y0, x1, y1, fillOf(t.state[k], t.label[k], t.level[k], o.showHeat), L)) {
          if (t.state[k] === 1) marks.push(cells[k]);
          continue;
        }
      }
      const c = cells[k];
      if (!c || !c.done) continue;
      if (c.state === 1) marks.push(c);
      const fill = cellFill(c, o.showHeat);
      if (smallCell(c, L) && (overHeat || raster.paint(c, L, fill))) continue;
      let byFill = levels.get(c.level);
      if (!byFill) levels.set(c.level, byFill = new Map());
      const list = byFill.get(fill);
      if (list) list.push(c); else byFill.set(fill, [c]);
    }
    for (const level of [...levels.keys()].sort((a, b) => a - b)) {
      const byFill = levels.get(level);
      if (!overHeat) {
        for (const [fill, list] of byFill) {
          ctx.beginPath();
          for (const c of list) traceInto(ctx, L, c.pts);
          ctx.fillStyle = fill;
          ctx.fill();
        }
      }
      ctx.beginPath();
      for (const list of byFill.values()) for (const c of list) traceInto(ctx, L, c.pts);
      ctx.strokeStyle = PALETTE.cellEdge;
      ctx.lineWidth = L.px(st.widths[cellLevel({ level })]);
      ctx.stroke();
    }
    this.raster.flush(ctx);
    if (!marks.length) return;
    ctx.beginPath();
    for (const c of marks) {
      const r = Math.max(L.px(2.5), Math.min(L.px(6), 0.3 * c.radius * L.scale));
      const [x, y] = centreOf(c);
      const sx = L.sx(x), sy = L.sy(y);
      ctx.moveTo(sx - r, sy - r); ctx.lineTo(sx + r, sy + r);
      ctx.moveTo(sx - r, sy + r); ctx.lineTo(sx + r, sy - r);
    }
    ctx.strokeStyle = '#ffffff'; // a halo, for the dark end of the heat map
    ctx.lineWidth = L.px(3.5);
    ctx.stroke();
    ctx.strokeStyle = PALETTE.cellBlockedMark;
    ctx.lineWidth = L.px(1.75);
    ctx.stroke();
  }

  /** The heat map: each sample's cell (or square tile), by colour bin. */
  drawHeat(ctx, L) {
    const m = this.mirror;
    const hex = m.cells.size > 0;
    const bin = heatScale(m.field, PALETTE.heat.length, !hex);
    const colors = PALETTE.heat;
    const byColour = new Map();
    for (const s of m.field) {
      const k = bin(s.v);
      const col = k < 0 ? PALETTE.obstacle : colors[k];
      if (!byColour.has(col)) byColour.set(col, []);
      byColour.get(col).push(s);
    }
    for (const [col, list] of byColour) {
      ctx.beginPath();
      for (const s of list) {
        const c = hex ? m.cells.get(s.id) : null;
        if (c && c.done) { traceInto(ctx, L, c.pts); continue; }
        const h = s.half * L.scale;
        ctx.rect(L.sx(s.x) - h, L.sy(s.y) - h, 2 * h, 2 * h);
      }
      ctx.fillStyle = col;
      ctx.fill();
      if (hex) {
        ctx.strokeStyle = PALETTE.cellEdge;
        ctx.lineWidth = L.px(0.75);
        ctx.stroke();
      }
    }
  }

  /** A short arrow along each sample's descent direction (one per ARROW_GAP square at most). */
  drawArrows(ctx, L) {
    const m = this.mirror;
    const gap = L.px(ARROW_GAP);
    const taken = new Set();
    ctx.beginPath();
    for (const s of m.field) {
      if (!(s.dx || s.dy)) continue;
      const sx = L.sx(s.x), sy = L.sy(s.y);
      const key = `${Math.floor(sx / gap)},${Math.floor(sy / gap)}`;
      if (taken.has(key)) continue;
      taken.add(key);
      const len = Math.max(L.px(6), Math.min(L.px(18), 0.7 * s.half * L.scale));
      const ex = sx + s.dx * len, ey = sy - s.dy * len; // screen y points down
      const hx = -s.dx * len * 0.35, hy = s.dy * len * 0.35;
      ctx.moveTo(sx, sy); ctx.lineTo(ex, ey);
      ctx.moveTo(ex + hx - hy * 0.6, ey + hy + hx * 0.6); ctx.lineTo(ex, ey); ctx.lineTo(ex + hx + hy * 0.6, ey + hy - hx * 0.6);
    }
    ctx.strokeStyle = PALETTE.arrow;
    ctx.lineWidth = L.px(1.1);
    ctx.stroke();
  }

  /** The obstacles again over the layer, half transparent, so cells and tiles do not hide them. */
  veil(ctx, L, scenario) {
    if (!scenario) return;
    ctx.globalAlpha = 0.6;
    for (const ob of scenario.obstacles) drawObstacle(ctx, L, ob);
    ctx.globalAlpha = 1;
  }

  /**
   * On the top layer: the regions of influence (older radii faint) and the local minima (their
   * labels kept off the `goal` state, when there is one).
   */
  drawTop(ctx, L, o, bounds, goal) {
    const m = this.mirror;
    if (!m || m.empty) return;
    if (o.showRegion && m.regions.length) {
      const st = STYLE[EventKind.REGION];
      const [x0, y0, x1, y1] = bounds;
      ctx.save();
      ctx.beginPath();
      ctx.rect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
      ctx.clip();
      ctx.setLineDash([L.px(7), L.px(5)]);
      m.regions.forEach((r, i) => {
        const last = i === m.regions.length - 1;
        ctx.globalAlpha = last ? 1 : 0.35;
        ctx.beginPath();
        ctx.arc(L.sx(r.x), L.sy(r.y), r.radius * L.scale, 0, 2 * Math.PI);
        ctx.strokeStyle = st.color;
        ctx.lineWidth = L.px(last ? st.width : 1.25);
        ctx.stroke();
      });
      ctx.restore();
    }
    m.minima.forEach((p, i) => drawMinimum(ctx, L, p, goal, i === m.minima.length - 1));
  }

  /** The robot's t/2 circle (dashed) around `state`, when a region gave t > 0. */
  drawRobotT(ctx, L, o, state) {
    const m = this.mirror;
    if (!m || !o.showRegion || !state || state.length < 2 || !(m.t > 0)) return;
    ctx.beginPath();
    ctx.arc(L.sx(state[0]), L.sy(state[1]), (m.t / 2) * L.scale, 0, 2 * Math.PI);
    ctx.setLineDash([L.px(4), L.px(3)]);
    ctx.strokeStyle = PALETTE.robotT;
    ctx.lineWidth = L.px(1.5);
    ctx.stroke();
    ctx.setLineDash([]);
  }

  /** The hover text (lines) for the world point (x, y), or null. */
  describe(x, y, o) {
    const m = this.mirror;
    if (!m) return null;
    if (m.order.length && (o.showCells || o.showHeat)) {
      const c = m.cellAt(x, y);
      return c ? describeCell(m, c) : null;
    }
    if (!m.cells.size && m.field.length && (o.showHeat || o.showArrows)) {
      const s = m.sampleAt(x, y);
      if (!s) return null;
      return [
        Number.isFinite(s.v) ? 'Potential here: the goal pulls the robot and the obstacles push it; it moves downhill.'
          : 'The robot would collide here: the potential is infinite.',
        `potential field at (${fmt(s.x)}, ${fmt(s.y)})`,
        `attraction ${fmt(s.a)}`,
        `repulsion ${fmt(s.b)}`,
        `total ${fmt(s.v)}${Number.isFinite(s.v) ? '' : ' (the robot would collide)'}`,
        s.dx || s.dy ? `descent direction (${fmt(s.dx)}, ${fmt(s.dy)})` : 'no descent direction',
      ];
    }
    return null;
  }
}

/** The cells of mirror `m` whose ids are ids[from…]. */
const cellsOf = (m, ids, from) => ids.slice(from).map((id) => m.cells.get(id));

/** A cell's centre as drawn: the record's, or its outline's mean when that lies outside. */
function centreOf(c) {
  if (pointInPolygon(c.x, c.y, c.pts)) return [c.x, c.y];
  let x = 0, y = 0;
  for (let i = 0; i < c.pts.length; i += 2) { x += c.pts[i]; y += c.pts[i + 1]; }
  return [x / (c.pts.length / 2), y / (c.pts.length / 2)];
}

// Why a step was blocked, as the end of a sentence (the step test's reasons, src/planners/hex/step.rs).
const WHY_SENTENCE = {
  1: "an obstacle vertex lies within t/2 of this cell's centre, where the robot would stand",
  2: 'an obstacle vertex lies in the rectangle the robot would sweep on the step here',
  3: 'an obstacle edge crosses the region the robot would sweep on the step here',
  4: "the map's edge is within t/2 of this cell's centre",
};

/**
 * The hover text's first line: one plain sentence about cell `c` (fields of a CellMirror cell:
 * label, level, state, why) — the search's verdict when it has one, else what the cell is.
 * `split`: whether the cell was refined into children.
 */
export function cellSentence(c, split = false) {
  switch (c.state) {
    case 0: return 'Passable: the step into this cell is clear, so the search may go here.';
    case 1: return `Blocked: ${WHY_SENTENCE[c.why] || 'the step test failed'}.`;
    case 2: return `Visited: the search stepped into this cell (level ${c.level}).`;
    case 3: return 'Outside the region of influence: the search does not look at this cell yet.';
    case 4: return 'Obstacle cell: an obstacle meets it, so the search does not go here.';
    default:
  }
  if (c.label === 0) return `Free cell at level ${c.level}: no obstacle touches it.`;
  if (c.label === 2) return 'Full cell: it lies wholly inside an obstacle.';
  if (c.label === 1) {
    return split ? 'Mixed cell: partly inside an obstacle (or, refining for clearance, within t/2 of one), so it was split.'
      : 'Mixed cell: partly inside an obstacle and too small to split, so the search leaves it out.';
  }
  return `Cell at level ${c.level}.`;
}

function describeCell(m, c) {
  const lines = [cellSentence(c, m.split.has(c.id)), `cell ${c.id} · level ${c.level} · ${LABELS[c.label] || `label ${c.label}`}`];
  if (c.state >= 0) {
    let s = STATES[c.state] || `state ${c.state}`;
    if (c.state === 1 && WHY[c.why]) s += `: ${WHY[c.why]}`;
    lines.push(`${s} (from ${c.from >= 0 ? `cell ${c.from}` : 'the start'}, attempt ${c.attempt + 1})`);
  }
  const t = c.terms;
  if (t) {
    lines.push(`potential seen from cell ${t.from}${t.chosen ? ' (chosen)' : ''}, attempt ${t.attempt + 1}:`,
      `repulsion Σk1/r² ${fmt(t.repulsion)}`,
      `trap term k3/r_j² ${fmt(t.trap)}`,
      `goal term −C(1−k2·α) ${fmt(t.goal)}, α ${fmt((t.alpha * 180) / Math.PI)}°`,
      `total ${fmt(t.total)}`);
  } else {
    const s = m.field.find((f) => f.id === c.id);
    if (s) lines.push('obstacle terms at its centre:', `repulsion Σk1/r² ${fmt(s.a)}`, `trap term k3/r_j² ${fmt(s.b)}`, `sum ${fmt(s.v)}`);
  }
  return lines;
}

/** The size of a force vector `[x, y]` (0 when not a number). */
export const forceSize = (f) => (f && Number.isFinite(f[0]) && Number.isFinite(f[1]) ? Math.sqrt(f[0] * f[0] + f[1] * f[1]) : 0);

/**
 * A local minimum: a ring, its label where it covers neither the goal nor the forces, and for the
 * latest (`last`) the two forces the core measured there (the goal's pull, the obstacles' push),
 * arrows on one scale with their sizes.
 */
function drawMinimum(ctx, L, p, goal, last) {
  const st = STYLE[EventKind.MINIMUM];
  const x = L.sx(p.x), y = L.sy(p.y), r = L.px(st.size);
  const pull = forceSize(p.pull), push = forceSize(p.push), most = Math.max(pull, push);
  const arrows = [];
  if (last && most > 0) {
    const len = L.px(42);
    for (const [f, size, name, color] of [[p.pull, pull, 'pull', PALETTE.forcePull], [p.push, push, 'push', PALETTE.forcePush]]) {
      if (!(size > 0)) continue;
      const k = len / most; // screen px per unit of force: one scale for both
      arrows.push({ ex: x + f[0] * k, ey: y - f[1] * k, ux: f[0] / size, uy: -f[1] / size, text: `${name} ${fmt(size)}`, color });
    }
  }
  for (const a of arrows) {
    const h = L.px(7);
    ctx.beginPath();
    ctx.moveTo(x, y); ctx.lineTo(a.ex, a.ey);
    ctx.moveTo(a.ex - a.ux * h - a.uy * h * 0.6, a.ey - a.uy * h + a.ux * h * 0.6); ctx.lineTo(a.ex, a.ey);
    ctx.lineTo(a.ex - a.ux * h + a.uy * h * 0.6, a.ey - a.uy * h - a.ux * h * 0.6);
    ctx.lineCap = 'round';
    ctx.strokeStyle = '#ffffff';
    ctx.lineWidth = L.px(5);
    ctx.stroke();
    ctx.strokeStyle = a.color;
    ctx.lineWidth = L.px(2.5);
    ctx.stroke();
  }
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.strokeStyle = '#ffffff';
  ctx.lineWidth = L.px(st.width + 2.5);
  ctx.stroke();
  ctx.strokeStyle = st.color;
  ctx.lineWidth = L.px(st.width);
  ctx.stroke();
  ctx.font = `600 ${Math.round(L.px(12))}px system-ui, sans-serif`;
  ctx.textBaseline = 'middle';
  const label = p.escapes > 0 ? `local minimum (${p.escapes} escapes)` : 'local minimum';
  const lh = L.px(14), gap = L.px(6);
  // the goal's box, and each force's label at its arrow's head
  const keepOff = [];
  if (goal && goal.length >= 2) {
    const gx = L.sx(goal[0]), gy = L.sy(goal[1]), g = L.px(16);
    keepOff.push([gx - g, gy - g, gx + g, gy + g]);
  }
  const texts = arrows.map((a) => {
    const w = ctx.measureText(a.text).width;
    const tx = a.ux >= 0 ? a.ex + gap : a.ex - gap - w;
    const ty = a.ey + (a.uy >= 0 ? 1 : -1) * lh * 0.9;
    keepOff.push([tx, ty - lh / 2, tx + w, ty + lh / 2]);
    return { text: a.text, tx, ty, color: a.color };
  });
  const w = ctx.measureText(label).width;
  const spots = [[x - w / 2, y + r + gap + lh / 2], [x - w / 2, y - r - gap - lh / 2], [x - r - gap - w, y], [x + r + gap, y]];
  /** @param {number[]} s */
  const inside = (s) => s[0] >= 0 && s[0] + w <= L.width && s[1] - lh / 2 >= 0 && s[1] + lh / 2 <= L.height;
  /** @param {number[]} s */
  const clear = (s) => keepOff.every(([a, b, c, d]) => s[0] + w < a || s[0] > c || s[1] + lh / 2 < b || s[1] - lh / 2 > d);
  const [tx, ty] = spots.find((s) => inside(s) && clear(s)) || spots.find(clear) || spots[0];
  for (const t of [...texts, { text: label, tx, ty, color: st.color }]) {
    ctx.lineWidth = L.px(3);
    ctx.strokeStyle = '#ffffff';
    ctx.strokeText(t.text, t.tx, t.ty);
    ctx.fillStyle = t.color;
    ctx.fillText(t.text, t.tx, t.ty);
  }
}

function traceInto(ctx, L, p) {
  for (let i = 0; i < p.length; i += 2) {
    if (i) ctx.lineTo(L.sx(p[i]), L.sy(p[i + 1])); else ctx.moveTo(L.sx(p[i]), L.sy(p[i + 1]));
  }
  ctx.closePath();
}

/** A cell's drawing level (0–3: coarser levels get lighter fills and thicker outlines). */
export const cellLevel = (c) => Math.min(3, Math.max(0, c.level | 0));

/**
 * A cell's fill, on the canvas and in the SVG export alike: by label (free by level, mixed, full),
 * or, unless the heat map is shown, by the search's verdict (open or passable, closed or visited,
 * step-blocked).
 */
export function cellFill(c, showHeat) {
  return fillOf(c.state, c.label, cellLevel(c), showHeat);
}

/** cellFill from a cell's state, label and drawing level. */
function fillOf(state, label, level, showHeat) {
  if (!showHeat && state === 0) return PALETTE.cellOpen;
  if (!showHeat && state === 2) return PALETTE.cellVisited;
  if (!showHeat && state === 1) return PALETTE.cellBlocked;
  return label === 1 ? PALETTE.cellMixed : label === 2 || state === 4 ? PALETTE.cellFull : PALETTE.cellFree[level];
}

/** Legend items for the planner `name` (marks the overlay box does not show): its registry's marks. */
export function cellLegend(name) {
  return markLegend(name);
}

/** What the mirror holds, for tests and the console (window.planarium.cells()). */
export function cellSummary(m) {
  const labels = [0, 0, 0];
  for (const id of m.order) { const l = m.cells.get(id).label; if (l >= 0 && l < 3) labels[l]++; }
  const pick = (state) => [...new Set(m.changed)].map((id) => m.cells.get(id)).filter((c) => c && c.state === state)
    .map((c) => { const [x, y] = centreOf(c); return { id: c.id, x, y, level: c.level, radius: c.radius }; });
  return {
    cells: m.order.length, labels, full: m.order.filter((id) => m.cells.get(id).label === 2), visited: pick(2), open: pick(0).length, blocked: pick(1).length, field: m.field.length,
    regions: m.regions.map((r) => ({ ...r })), minima: m.minima.map((p) => ({ ...p })), t: m.t,
  };
}

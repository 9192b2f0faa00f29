// Plots for the benchmark page, drawn on canvases: box plots per metric, success bars, and cost
// against time (one dot per solved run). Colours are the Okabe–Ito set, distinguishable with the
// common colour-blindness types; set-ups also differ by position and label, never colour alone.
// Labels never overlap: too wide for their slot, they are tilted and cut with an ellipsis (the
// canvas's title, a tooltip, and its aria-label hold them in full); titles wrap (up to three lines on
// the page, in full in a download: drawInto), and keys sit above the data, never on it.
// Axes whose data span decades (largest / smallest > LOG_SPAN, all above 0) are drawn on a log
// scale with labelled decade ticks, unless the caller asks for `scale: 'linear'`; the scale chosen
// is kept in the canvas's data-y-scale / data-x-scale. scatter() returns the dots' screen
// positions, so the page can open the run under a click.

import { quartiles } from '../run/summary.js';

export const SERIES = ['#0072b2', '#e69f00', '#009e73', '#cc79a7', '#56b4e9', '#d55e00', '#f0e442', '#000000'];

/** Where the next plot is drawn instead of its canvas (a download): {ctx, w, h, scale}, else null. */
let surface = null;

/**
 * Call `draw` (a plot function's call) so that it draws on `into` — {ctx, w, h, scale}: a
 * download's canvas, or an SVG recorder (svg-context.js) — instead of its canvas; returns what
 * `draw` returns.
 * @template T @param {{ctx: any, w: number, h: number, scale: number}} into @param {() => T} draw @returns {T}
 */
export function drawInto(into, draw) {
  surface = into;
  try { return draw(); } finally { surface = null; }
}

const TITLE_FONT = '600 12px system-ui, sans-serif';
const TITLE_LINE = 15;

/** `text` broken at spaces into lines of at most `maxW` px (a word wider than that is cut). */
export function wrapText(ctx, text, maxW) {
  const lines = [];
  let line = '';
  for (const word of text.split(/\s+/).filter(Boolean)) {
    const next = line ? `${line} ${word}` : word;
    if (!line || ctx.measureText(next).width <= maxW) line = next;
    else { lines.push(line); line = word; }
  }
  if (line) lines.push(line);
  return lines.map((l) => fitText(ctx, l, maxW));
}

function setup(canvas, title) {
  let ctx, w, h;
  if (surface) {
    ({ ctx, w, h } = surface);
    ctx.setTransform(surface.scale, 0, 0, surface.scale, 0, 0);
  } else {
    const dpr = window.devicePixelRatio || 1;
    w = canvas.clientWidth || 320;
    h = canvas.clientHeight || 200;
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
    ctx = canvas.getContext('2d');
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  }
  ctx.clearRect(0, 0, w, h);
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, w, h);
  ctx.fillStyle = '#222';
  ctx.font = TITLE_FONT;
  // the whole title, on as many lines as it needs (at most 3 on the page; a download's in full)
  const all = wrapText(ctx, title, w - 16);
  const lines = surface ? all : all.slice(0, 3);
  if (lines.length < all.length) lines[lines.length - 1] = fitText(ctx, `${lines[lines.length - 1]} ${all[lines.length]}`, w - 16);
  ctx.textAlign = 'left';
  ctx.beginLayer?.('title');
  lines.forEach((l, i) => ctx.fillText(l, 8, 16 + i * TITLE_LINE));
  ctx.endLayer?.();
  canvas.setAttribute('aria-label', title);
  canvas.dataset.title = title;
  return { canvas, ctx, w, h, pad: { l: 64, r: 12, t: 28 + (lines.length - 1) * TITLE_LINE, b: 36 } };
}

/** Largest over smallest value beyond which an axis is drawn on a log scale. */
export const LOG_SPAN = 100;

/**
 * Whether `vals` want a log axis: `scale` 'log' (if every value is above 0), 'linear' (never) or
 * 'auto' (their span is over LOG_SPAN).
 */
export function wantsLog(vals, scale = 'auto') {
  if (scale === 'linear' || !vals.length) return false;
  const [lo, hi] = extent(vals);
  if (!(lo > 0) || !Number.isFinite(hi)) return false;
  return scale === 'log' || hi / lo > LOG_SPAN;
}

/** A decade's label: 0.001 … 1000 as written, else 10 with a superscript exponent ("10⁴"). */
export function decadeLabel(k) {
  if (k >= -3 && k <= 3) return String(Number((10 ** k).toPrecision(1)));
  const sup = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };
  return `10${[...String(k)].map((c) => sup[c]).join('')}`;
}

/** Log axis ticks for [lo, hi] (both > 0): the decades around them, and 2…9 between as minor ticks. */
function logTicks(lo, hi) {
  const a = Math.floor(Math.log10(lo)), b = Math.max(a + 1, Math.ceil(Math.log10(hi)));
  const major = [], minor = [];
  for (let k = a; k <= b; k++) {
    major.push(k);
    if (k < b) for (let m = 2; m <= 9; m++) minor.push(Math.log10(m) + k);
  }
  return { major, minor, a, b };
}

/** A "nice" axis: [lo, hi] widened to round ticks. */
function ticks(lo, hi, n = 4) {
  if (!(hi > lo)) { hi = lo + 1; }
  const step0 = (hi - lo) / n;
  const mag = 10 ** Math.floor(Math.log10(step0));
  const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= step0);
  const a = Math.floor(lo / step) * step, b = Math.ceil(hi / step) * step;
  const out = [];
  for (let t = a; t <= b + step / 2; t += step) out.push(Number(t.toPrecision(12)));
  return out;
}

const short = (v) => (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-2 && v !== 0) ? v.toExponential(1) : String(Number(v.toPrecision(3))));

function yAxis(ctx, g, lo, hi, unit, log = false) {
  ctx.strokeStyle = '#ddd';
  ctx.fillStyle = '#444';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'right';
  let y;
  if (log) {
    const { major, minor, a, b } = logTicks(lo, hi);
    const py = (e) => g.h - g.pad.b - ((e - a) / (b - a)) * (g.h - g.pad.t - g.pad.b);
    y = (v) => py(Math.log10(v));
    ctx.strokeStyle = '#f0f0f0';
    for (const e of minor) { ctx.beginPath(); ctx.moveTo(g.pad.l, py(e)); ctx.lineTo(g.w - g.pad.r, py(e)); ctx.stroke(); }
    ctx.strokeStyle = '#cfcfcf';
    for (const k of major) {
      ctx.beginPath(); ctx.moveTo(g.pad.l, py(k)); ctx.lineTo(g.w - g.pad.r, py(k)); ctx.stroke();
      ctx.fillText(decadeLabel(k), g.pad.l - 4, py(k) + 4);
    }
    unit = `${unit} (log)`;
  } else {
    const ts = ticks(lo, hi);
    const [a, b] = [ts[0], ts[ts.length - 1]];
    y = (v) => g.h - g.pad.b - ((v - a) / (b - a)) * (g.h - g.pad.t - g.pad.b);
    for (const t of ts) {
      ctx.beginPath(); ctx.moveTo(g.pad.l, y(t)); ctx.lineTo(g.w - g.pad.r, y(t)); ctx.stroke();
      ctx.fillText(short(t), g.pad.l - 4, y(t) + 4);
    }
  }
  ctx.save();
  ctx.translate(12, (g.h - g.pad.b + g.pad.t) / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = 'center';
  ctx.fillText(unit, 0, 0);
  ctx.restore();
  return y;
}

/** `text` cut with an ellipsis to fit `maxW` px in the context's font. */
export function fitText(ctx, text, maxW) {
  if (ctx.measureText(text).width <= maxW) return text;
  let lo = 0, hi = text.length;
  while (lo < hi) { // the longest prefix that fits with the ellipsis
    const mid = Math.ceil((lo + hi) / 2);
    if (ctx.measureText(`${text.slice(0, mid)}…`).width <= maxW) lo = mid; else hi = mid - 1;
  }
  return `${text.slice(0, lo)}…`;
}

const LABEL_FONT = '11px system-ui, sans-serif';
const TILT = Math.PI / 5; // crowded labels are drawn at 36°, up to TILT_MAX px long
const TILT_MAX = 96;

/**
 * Room for the category labels under a plot: when the longest label is wider than its slot, the
 * labels are tilted and the bottom margin grows to hold them. Call before the y axis is drawn.
 */
function labelRoom(canvas, g, labels) {
  const { ctx } = g;
  ctx.font = LABEL_FONT;
  const slot = (g.w - g.pad.l - g.pad.r) / Math.max(1, labels.length);
  g.tilt = labels.some((l) => ctx.measureText(l).width > slot - 6);
  if (g.tilt) g.pad.b = Math.ceil(Math.sin(TILT) * TILT_MAX) + 16;
  // every label in full, for a pointer's tooltip and a screen reader
  const full = labels.map((l, i) => `${i + 1}. ${l}`).join('\n');
  canvas.title = g.tilt || labels.some((l) => ctx.measureText(l).width > slot - 6) ? full : '';
  canvas.setAttribute('aria-label', `${canvas.getAttribute('aria-label')}; set-ups: ${labels.join(', ')}`);
}

function xLabels(ctx, g, labels, x) {
  ctx.fillStyle = '#222';
  ctx.font = LABEL_FONT;
  const slot = (g.w - g.pad.l - g.pad.r) / Math.max(1, labels.length);
  labels.forEach((l, i) => {
    if (!g.tilt) {
      ctx.textAlign = 'center';
      ctx.fillText(fitText(ctx, l, slot - 6), x(i), g.h - g.pad.b + 14);
      return;
    }
    // tilted: each label ends under its box, and neighbours do not overlap (they are parallel,
    // slot·sin(TILT) apart, more than the font's height down to a 20 px slot)
    ctx.save();
    ctx.translate(x(i) + 4, g.h - g.pad.b + 8);
    ctx.rotate(-TILT);
    ctx.textAlign = 'right';
    ctx.fillText(fitText(ctx, l, TILT_MAX), 0, 4);
    ctx.restore();
  });
}

/**
 * Box plots: `groups` [{label, values}] (empty groups get "no data"). `scale`: 'auto' (a log axis
 * where the values span decades), 'linear' or 'log'.
 * @param {HTMLCanvasElement} canvas
 * @param {string} title
 * @param {string} unit
 * @param {{label: string, values: number[]}[]} groups
 * @param {{scale?: 'auto' | 'linear' | 'log'}} [options]
 */
export function boxPlot(canvas, title, unit, groups, { scale = 'auto' } = {}) {
  const g = setup(canvas, title);
  const { ctx } = g;
  const all = groups.flatMap((s) => s.values).filter(Number.isFinite);
  canvas.dataset.yScale = 'linear';
  if (!all.length) { ctx.fillText('no data', g.pad.l, g.h / 2); return; }
  labelRoom(canvas, g, groups.map((s) => s.label));
  const log = wantsLog(all, scale);
  canvas.dataset.yScale = log ? 'log' : 'linear';
  const y = yAxis(ctx, g, ...extent(all), unit, log);
  const slot = (g.w - g.pad.l - g.pad.r) / groups.length;
  const x = (i) => g.pad.l + slot * (i + 0.5);
  const bw = Math.min(40, slot * 0.5);
  groups.forEach((s, i) => {
    const vals = s.values.filter(Number.isFinite);
    const c = SERIES[i % SERIES.length];
    if (!vals.length) { ctx.fillStyle = '#888'; ctx.textAlign = 'center'; ctx.fillText('no data', x(i), g.h / 2); return; }
    const q = quartiles(vals);
    ctx.strokeStyle = c; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(x(i), y(q.min)); ctx.lineTo(x(i), y(q.q1)); ctx.moveTo(x(i), y(q.q3)); ctx.lineTo(x(i), y(q.max)); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(x(i) - bw / 4, y(q.min)); ctx.lineTo(x(i) + bw / 4, y(q.min)); ctx.moveTo(x(i) - bw / 4, y(q.max)); ctx.lineTo(x(i) + bw / 4, y(q.max)); ctx.stroke();
    ctx.fillStyle = `${c}40`;
    ctx.fillRect(x(i) - bw / 2, y(q.q3), bw, y(q.q1) - y(q.q3));
    ctx.strokeRect(x(i) - bw / 2, y(q.q3), bw, y(q.q1) - y(q.q3));
    ctx.lineWidth = 3;
    ctx.beginPath(); ctx.moveTo(x(i) - bw / 2, y(q.median)); ctx.lineTo(x(i) + bw / 2, y(q.median)); ctx.stroke();
  });
  xLabels(ctx, g, groups.map((s) => s.label), x);
}

/** Success bars: `bars` [{label, solved, runs}], as percentages. */
export function successBars(canvas, title, bars) {
  const g = setup(canvas, title);
  const { ctx } = g;
  labelRoom(canvas, g, bars.map((b) => b.label));
  const slot = (g.w - g.pad.l - g.pad.r) / Math.max(1, bars.length);
  ctx.font = LABEL_FONT;
  // where counts are wider than a bar's slot, every other one is raised a line: no two touch
  const stagger = bars.some((c) => ctx.measureText(`${c.solved}/${c.runs}`).width > slot - 4);
  if (stagger) g.pad.t += 11;
  const y = yAxis(ctx, g, 0, 100, '% solved');
  const x = (i) => g.pad.l + slot * (i + 0.5);
  const bw = Math.min(48, slot * 0.6);
  bars.forEach((b, i) => {
    const pct = b.runs ? (100 * b.solved) / b.runs : 0;
    ctx.fillStyle = SERIES[i % SERIES.length];
    ctx.fillRect(x(i) - bw / 2, y(pct), bw, y(0) - y(pct));
    ctx.fillStyle = '#222';
    ctx.textAlign = 'center';
    ctx.fillText(`${b.solved}/${b.runs}`, x(i), y(pct) - 4 - (stagger && i % 2 ? 11 : 0));
  });
  xLabels(ctx, g, bars.map((b) => b.label), x);
}

/** The extent of `vals` without spreading them into a call (curves can hold many points). */
function extent(vals) {
  return vals.reduce(([lo, hi], v) => [Math.min(lo, v), Math.max(hi, v)], [Infinity, -Infinity]);
}

/**
 * Axes for points [[x, y], ...]: y as yAxis draws it, x from 0 (or below) to the largest x; either
 * on a log scale where its values span decades (`scale` as boxPlot's). Sets the canvas's
 * data-x-scale and data-y-scale.
 */
function xyAxes(ctx, g, pts, xUnit, yUnit, scale) {
  const yv = pts.map((p) => p[1]), xv = pts.map((p) => p[0]);
  const ylog = wantsLog(yv, scale), xlog = wantsLog(xv, scale);
  g.canvas.dataset.yScale = ylog ? 'log' : 'linear';
  g.canvas.dataset.xScale = xlog ? 'log' : 'linear';
  const [ylo, yhi] = extent(yv);
  const y = yAxis(ctx, g, ylo, yhi, yUnit, ylog);
  const [xlo, xhi] = extent(xv);
  const span = g.w - g.pad.l - g.pad.r;
  ctx.fillStyle = '#444'; ctx.textAlign = 'center';
  let x;
  if (xlog) {
    const { major, minor, a, b } = logTicks(xlo, xhi);
    const px = (e) => g.pad.l + ((e - a) / (b - a)) * span;
    x = (v) => px(Math.log10(v));
    ctx.strokeStyle = '#f0f0f0';
    for (const e of minor) { ctx.beginPath(); ctx.moveTo(px(e), g.pad.t); ctx.lineTo(px(e), g.h - g.pad.b); ctx.stroke(); }
    ctx.strokeStyle = '#cfcfcf';
    for (const k of major) {
      ctx.beginPath(); ctx.moveTo(px(k), g.pad.t); ctx.lineTo(px(k), g.h - g.pad.b); ctx.stroke();
      ctx.fillText(decadeLabel(k), px(k), g.h - g.pad.b + 14);
    }
    xUnit = `${xUnit}, log`;
  } else {
    const xs = ticks(Math.min(0, xlo), xhi);
    const [a, b] = [xs[0], xs[xs.length - 1]];
    x = (v) => g.pad.l + ((v - a) / (b - a)) * span;
    for (const t of xs) ctx.fillText(short(t), x(t), g.h - g.pad.b + 14);
  }
  ctx.fillText(xUnit, (g.w + g.pad.l) / 2, g.h - 6);
  return { x, y };
}

const KEY_LINE = 13;

/** Room for the key above the plot area (three series to a row): call before the axes. */
function keyRoom(g, series) {
  g.keyTop = g.pad.t - 6;
  g.pad.t += Math.ceil(series.length / 3) * KEY_LINE + 4;
}

/** The key, above the data (keyRoom): each series' label after its mark (`marks` alternate, so colour is not alone). */
function seriesKey(ctx, g, series, marks) {
  ctx.textAlign = 'left';
  ctx.font = LABEL_FONT;
  ctx.beginLayer?.('key');
  const col = (g.w - g.pad.l - g.pad.r - 4) / 3; // three to a row, each cut to its column
  series.forEach((s, i) => {
    ctx.fillStyle = SERIES[i % SERIES.length];
    ctx.fillText(fitText(ctx, `${marks[i % 2]} ${s.label}`, col - 6), g.pad.l + 4 + (i % 3) * col, g.keyTop + 12 + Math.floor(i / 3) * KEY_LINE);
  });
  ctx.endLayer?.();
}

/**
 * Cost against time: `series` [{label, points: [[time, cost], ...]}], one dot per solved run.
 * Returns the dots as drawn: [{x, y, series, index}] in css px from the canvas's top left
 * (`series`: the series' index, `index`: the point's in its series), for a click to find its run.
 * @param {HTMLCanvasElement} canvas
 * @param {string} title
 * @param {string} xUnit
 * @param {string} yUnit
 * @param {{label: string, points: number[][]}[]} series
 * @param {{scale?: 'auto' | 'linear' | 'log'}} [options]
 * @returns {{x: number, y: number, series: number, index: number}[]}
 */
export function scatter(canvas, title, xUnit, yUnit, series, { scale = 'auto' } = {}) {
  const g = setup(canvas, title);
  const { ctx } = g;
  const pts = series.flatMap((s) => s.points);
  if (!pts.length) { ctx.fillText('no solved runs', g.pad.l, g.h / 2); return []; }
  keyRoom(g, series);
  const { x, y } = xyAxes(ctx, g, pts, xUnit, yUnit, scale);
  ctx.beginLayer?.('data');
  canvas.title = series.map((s, i) => `${['●', '■'][i % 2]} ${s.label}`).join('\n');
  const hits = [];
  series.forEach((s, i) => {
    ctx.fillStyle = SERIES[i % SERIES.length];
    s.points.forEach(([t, c], k) => {
      ctx.beginPath();
      if (i % 2) ctx.rect(x(t) - 3, y(c) - 3, 6, 6); else ctx.arc(x(t), y(c), 3.5, 0, 2 * Math.PI);
      ctx.fill();
      hits.push({ x: x(t), y: y(c), series: i, index: k });
    });
  });
  ctx.endLayer?.();
  seriesKey(ctx, g, series, ['●', '■']);
  return hits;
}

/** The dot of `hits` (from scatter) nearest to (x, y) within `radius` css px, or null. */
export function hitDot(hits, x, y, radius = 8) {
  let best = null, bestD = radius * radius;
  for (const h of hits) {
    const d = (h.x - x) ** 2 + (h.y - y) ** 2;
    if (d <= bestD) { best = h; bestD = d; }
  }
  return best;
}

/**
 * Step lines: `series` [{label, lines: [[[x, y], ...], ...]}] (each line one run), by series
 * colour; `scale` as boxPlot's.
 * @param {HTMLCanvasElement} canvas
 * @param {string} title
 * @param {string} xUnit
 * @param {string} yUnit
 * @param {{label: string, lines: number[][][]}[]} series
 * @param {{scale?: 'auto' | 'linear' | 'log', band?: boolean}} [options] `band`: the runs' lines
 *   faint, and over them each series' median and its interquartile band (medianBand)
 */
export function stepLines(canvas, title, xUnit, yUnit, series, { scale = 'auto', band = false } = {}) {
  const g = setup(canvas, title);
  const { ctx } = g;
  const pts = series.flatMap((s) => s.lines.flat());
  if (!pts.length) { ctx.fillText('no data', g.pad.l, g.h / 2); return; }
  keyRoom(g, series);
  const { x, y } = xyAxes(ctx, g, pts, xUnit, yUnit, scale);
  ctx.beginLayer?.('data');
  series.forEach((s, i) => {
    ctx.strokeStyle = SERIES[i % SERIES.length];
    ctx.globalAlpha = band ? 0.2 : 0.55;
    ctx.lineWidth = band ? 1 : 1.5;
    ctx.setLineDash(i % 2 ? [5, 3] : []);
    for (const line of s.lines) {
      ctx.beginPath();
      line.forEach(([t, c], k) => {
        if (k === 0) ctx.moveTo(x(t), y(c));
        else { ctx.lineTo(x(t), y(line[k - 1][1])); ctx.lineTo(x(t), y(c)); }
      });
      ctx.stroke();
    }
  });
  ctx.globalAlpha = 1;
  ctx.setLineDash([]);
  if (band) {
    // Planner Arena's form: per series the median over its runs and the band between the quartiles
    const [t0, t1] = extent(pts.map((p) => p[0]));
    const grid = Array.from({ length: 121 }, (_, k) => t0 + (k / 120) * (t1 - t0));
    series.forEach((s, i) => {
      const m = medianBand(s.lines, grid);
      if (!m.length) return;
      ctx.fillStyle = SERIES[i % SERIES.length];
      ctx.globalAlpha = 0.22;
      ctx.beginPath();
      m.forEach(([t, , q1], k) => (k ? ctx.lineTo(x(t), y(q1)) : ctx.moveTo(x(t), y(q1))));
      for (let k = m.length - 1; k >= 0; k--) ctx.lineTo(x(m[k][0]), y(m[k][3]));
      ctx.closePath();
      ctx.fill();
      ctx.globalAlpha = 1;
      ctx.strokeStyle = SERIES[i % SERIES.length];
      ctx.lineWidth = 2.5;
      ctx.setLineDash(i % 2 ? [6, 3] : []);
      ctx.beginPath();
      m.forEach(([t, med], k) => (k ? ctx.lineTo(x(t), y(med)) : ctx.moveTo(x(t), y(med))));
      ctx.stroke();
    });
    ctx.setLineDash([]);
  }
  ctx.endLayer?.();
  seriesKey(ctx, g, series, ['—', '┄']);
}

/**
 * The median and quartiles over runs of a best-cost-against-time step function, at each time of
 * `grid`: [[t, median, q1, q3], ...] (`lines` [[[t, cost], ...] per run], each run's cost at t its
 * last point at or before t). A run not solved by t counts as an infinite cost, as Planner Arena
 * counts it; a time where the median is still infinite is left out, and q3 is held at the largest
 * finite cost there.
 * @param {number[][][]} lines @param {number[]} grid @returns {number[][]}
 */
export function medianBand(lines, grid) {
  const out = [];
  for (const t of grid) {
    const v = lines.map((line) => {
      let c = Infinity;
      for (const [tt, cc] of line) { if (tt <= t) c = cc; else break; }
      return c;
    }).sort((a, b) => a - b);
    const at = (q) => {
      const pos = q * (v.length - 1), lo = Math.floor(pos), hi = Math.ceil(pos);
      return v[lo] === v[hi] ? v[lo] : v[lo] + (v[hi] - v[lo]) * (pos - lo);
    };
    const median = at(0.5);
    if (!Number.isFinite(median)) continue;
    const finite = v.filter(Number.isFinite);
    const q3 = at(0.75);
    out.push([t, median, at(0.25), Number.isFinite(q3) ? q3 : finite[finite.length - 1]]);
  }
  return out;
}

// A live line chart on its own canvas (no library): the best cost against iterations (a planner
// that keeps improving, RRT*) or the coverage against iterations (inspection), read from the run
// model's series (playback.js). Both are step functions: a value holds until the next event.
//
//   chart.setKind('cost' | 'coverage' | null, {target, optimum})   null hides it; optimum: the
//                                      exact shortest cost (visibility graph), drawn dashed
//   chart.render(iterationNow)                             redraws when the data or size changed

const PAD = { left: 46, right: 10, top: 8, bottom: 22 }; // css px

/** Round `v` up to 1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 × a power of ten. */
export function niceCeil(v) {
  if (!(v > 0)) return 1;
  const p = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10]) if (m * p >= v * (1 - 1e-12)) return m * p;
  return 10 * p;
}

/** A short label for an axis value. */
export function formatValue(v) {
  const a = Math.abs(v);
  if (a >= 1e6) return `${Number((v / 1e6).toFixed(1))}M`;
  if (a >= 1e4) return `${Number((v / 1e3).toFixed(0))}k`;
  if (a >= 100 || Number.isInteger(v)) return String(Math.round(v));
  return String(Number(v.toPrecision(3)));
}

/** A downloaded chart's title: its font at `scale`, its line height (css px). */
const TITLE_FONT = (scale) => `600 ${Math.round(12 * scale)}px system-ui, sans-serif`;
const TITLE_LINE = 15;

export class Chart {
  /** `canvas`: the chart's canvas (sized by CSS); `model`: a RunModel; `palette`: palette.js PALETTE. */
  constructor(canvas, model, palette) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.model = model;
    this.palette = palette;
    this.kind = null;
    this.target = null;
    this.optimum = null;
    this.drawn = '';
  }

  setKind(kind, { target = null, optimum = null } = {}) {
    this.kind = kind;
    this.target = target;
    this.optimum = kind === 'cost' && Number.isFinite(optimum) ? optimum : null;
    this.drawn = '';
  }

  clearRun() { this.drawn = ''; }

  series() {
    if (this.kind === 'cost') return this.model.costs;
    if (this.kind === 'coverage') return this.model.coverage;
    return [];
  }

  /** Redraw if anything changed; `now`: the iteration the run has reached (extends the last step). */
  render(now = 0) {
    if (!this.kind) return;
    const rect = this.canvas.getBoundingClientRect();
    if (rect.width < 10 || rect.height < 10) return;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(rect.width * dpr), h = Math.round(rect.height * dpr);
    const data = this.series();
    const key = `${this.kind}|${w}|${h}|${data.length}|${now}|${this.target}|${this.optimum}`;
    if (key === this.drawn) return;
    this.drawn = key;
    if (this.canvas.width !== w || this.canvas.height !== h) { this.canvas.width = w; this.canvas.height = h; }
    this.draw(data, now, w, h, dpr);
  }

  /** `title` broken into lines that fit the chart's width (css px), for a download. */
  titleLines(title) {
    const width = Math.max(10, this.canvas.getBoundingClientRect().width) - 12;
    const m = document.createElement('canvas').getContext('2d');
    m.font = TITLE_FONT(1);
    const lines = [];
    for (const word of title.split(/\s+/).filter(Boolean)) {
      const next = lines.length ? `${lines[lines.length - 1]} ${word}` : word;
      if (lines.length && m.measureText(next).width <= width) lines[lines.length - 1] = next;
      else lines.push(word);
    }
    return lines;
  }

  /** A download's size, device px, at `scale` × the chart's size on the page, `title`'s lines above. */
  sizeFor(scale, title) {
    const rect = this.canvas.getBoundingClientRect();
    const room = this.titleLines(title).length * TITLE_LINE + 7;
    return { width: Math.round(Math.max(10, rect.width) * scale), height: Math.round((Math.max(10, rect.height) + room) * scale), room };
  }

  /**
   * The chart as it stands, for a download, on `ctx` (a canvas's of sizeFor(scale, title), or
   * svg-context.js's recorder): `title` in full above the plot (wrapped), on white, `scale` × its
   * size on the page.
   * @param {any} ctx @param {string} title @param {number} scale @param {number} [now]
   */
  drawFor(ctx, title, scale, now = 0) {
    const { width: w, height: full, room } = this.sizeFor(scale, title);
    const h = full - Math.round(room * scale);
    const onCanvas = typeof CanvasRenderingContext2D !== 'undefined' && ctx instanceof CanvasRenderingContext2D;
    const white = () => { ctx.fillStyle = '#ffffff'; ctx.fillRect(0, 0, w, full); };
    if (!onCanvas) white(); // an SVG: the background first (its clearRect draws nothing)
    ctx.fillStyle = '#222222';
    ctx.font = TITLE_FONT(scale);
    ctx.textAlign = 'left';
    ctx.textBaseline = 'alphabetic';
    ctx.beginLayer?.('title');
    this.titleLines(title).forEach((line, i) => ctx.fillText(line, 6 * scale, (15 + i * TITLE_LINE) * scale));
    ctx.endLayer?.();
    const own = this.ctx;
    this.ctx = ctx;
    ctx.save();
    ctx.translate(0, Math.round(room * scale));
    try { this.draw(this.series(), now, w, h, scale); } finally { ctx.restore(); this.ctx = own; }
    if (onCanvas) { // the plot's clearRect left it transparent: white behind everything
      ctx.save();
      ctx.globalCompositeOperation = 'destination-over';
      white();
      ctx.restore();
    }
  }

  draw(data, now, w, h, dpr) {
    const { ctx } = this;
    const P = this.palette;
    const px = (v) => v * dpr;
    ctx.clearRect(0, 0, w, h);
    const x0 = px(PAD.left), x1 = w - px(PAD.right), y0 = px(PAD.top), y1 = h - px(PAD.bottom);
    const last = data.length ? data[data.length - 1][0] : 0;
    const xmax = niceCeil(Math.max(10, now, last) * 1.02);
    let lo, hi;
    if (this.kind === 'coverage') {
      lo = 0; hi = 1;
    } else if (data.length || this.optimum != null) {
      const vals = data.map((d) => d[1]);
      if (this.optimum != null) vals.push(this.optimum);
      const vmin = Math.min(...vals), vmax = Math.max(...vals);
      const span = Math.max(vmax - vmin, Math.abs(vmax) * 0.05, 1e-9);
      lo = Math.max(0, vmin - span * 0.15);
      hi = vmax + span * 0.15;
    } else {
      lo = 0; hi = 1;
    }
    const sx = (v) => x0 + (v / xmax) * (x1 - x0);
    const sy = (v) => y1 - ((v - lo) / (hi - lo)) * (y1 - y0);

    // axes, ticks and labels
    ctx.strokeStyle = P.chartAxis;
    ctx.fillStyle = P.chartAxis;
    ctx.lineWidth = px(1);
    ctx.font = `${Math.round(px(10))}px system-ui, sans-serif`;
    ctx.beginPath();
    ctx.moveTo(x0, y0); ctx.lineTo(x0, y1); ctx.lineTo(x1, y1);
    ctx.stroke();
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    const yTicks = this.kind === 'coverage' ? [0, 0.5, 1] : [lo, (lo + hi) / 2, hi];
    for (const v of yTicks) {
      const y = sy(v);
      ctx.beginPath(); ctx.moveTo(x0 - px(3), y); ctx.lineTo(x0, y); ctx.stroke();
      ctx.fillText(this.kind === 'coverage' ? `${Math.round(v * 100)}%` : formatValue(v), x0 - px(5), y);
    }
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    for (const v of [0, xmax / 2, xmax]) {
      const x = sx(v);
      ctx.beginPath(); ctx.moveTo(x, y1); ctx.lineTo(x, y1 + px(3)); ctx.stroke();
      ctx.fillText(formatValue(v), Math.min(x, x1 - px(12)), y1 + px(4));
    }
    // the coverage target
    if (this.kind === 'coverage' && this.target > 0) {
      ctx.beginPath();
      ctx.setLineDash([px(4), px(3)]);
      ctx.moveTo(x0, sy(this.target)); ctx.lineTo(x1, sy(this.target));
      ctx.strokeStyle = P.chartTarget;
      ctx.stroke();
      ctx.setLineDash([]);
    }
    // the optimum (visibility graph): what the best cost can approach, never beat
    if (this.optimum != null) {
      const y = sy(this.optimum);
      ctx.beginPath();
      ctx.setLineDash([px(5), px(4)]);
      ctx.moveTo(x0, y); ctx.lineTo(x1, y);
      ctx.strokeStyle = P.chartTarget;
      ctx.lineWidth = px(1.5);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = P.chartTarget;
      ctx.textAlign = 'right';
      ctx.textBaseline = 'bottom';
      ctx.fillText(`optimum ${formatValue(this.optimum)}`, x1, y - px(2));
      ctx.lineWidth = px(1);
    }
    if (!data.length) {
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.fillStyle = P.chartAxis;
      ctx.fillText(this.kind === 'cost' ? 'no solution yet' : 'nothing seen yet', (x0 + x1) / 2, (y0 + y1) / 2);
      return;
    }
    // the step line: each value holds until the next, the last until `now`
    ctx.beginPath();
    ctx.moveTo(sx(data[0][0]), sy(data[0][1]));
    for (let i = 1; i < data.length; i++) {
      ctx.lineTo(sx(data[i][0]), sy(data[i - 1][1]));
      ctx.lineTo(sx(data[i][0]), sy(data[i][1]));
    }
    ctx.lineTo(sx(Math.max(now, last)), sy(data[data.length - 1][1]));
    ctx.strokeStyle = P.chartLine;
    ctx.lineWidth = px(2);
    ctx.lineJoin = 'round';
    ctx.stroke();
    ctx.beginPath();
    for (const [i, v] of data) {
      ctx.moveTo(sx(i) + px(2.5), sy(v));
      ctx.arc(sx(i), sy(v), px(2.5), 0, 2 * Math.PI);
    }
    ctx.fillStyle = P.chartLine;
    ctx.fill();
  }
}

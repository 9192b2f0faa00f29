// The joint-angle timeline under the 3-D view (www/ui/path3d.js feeds it): one curve a joint, in
// degrees, against the path's length in rad (the planner's metric: the joint-space distance
// travelled from the start), the waypoints as faint vertical lines, and a cursor at the pose the
// arm is drawn at. It maps a pointer's x back to a length, so hovering or dragging on it poses the
// arm. A 2-D canvas; the numbers drawn are the path's own states, as the core sampled them.

/** One colour a joint, Okabe–Ito (told apart with any colour-vision deficiency); a 7th joint on wraps. */
export const JOINT_COLOURS = ['#0072b2', '#d55e00', '#009e73', '#cc79a7', '#e69f00', '#56b4e9'];
const AXIS = '#6b7280';
const GRIDLINE = '#e5e7eb';
const WAYPOINT = '#c9ccd1';
const CURSOR = '#111111';
const PAD = { left: 40, right: 10, top: 8, bottom: 22 };

/** A tick step of about `span / n`: 1, 2 or 5 times a power of ten. */
function tickStep(span, n) {
  const raw = span / Math.max(1, n);
  const p = 10 ** Math.floor(Math.log10(raw));
  const m = raw / p;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
}

export class Timeline {
  /** @param {HTMLCanvasElement} canvas */
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    this.data = null; // {s: Float64Array, states: Float64Array (dims a frame), dims, length, waypoints: number[]}
    this.cursor = null;
    this.size = [1, 1];
    this.lo = 0;
    this.hi = 1;
    this.base = document.createElement('canvas'); // the axes and curves, drawn once per path and size
  }

  /**
   * The path to draw: `s` each frame's length from the start (rad), `states` the frames' joint
   * angles (`dims` a frame, radians), `waypoints` the waypoints' lengths; or null.
   * @param {{s: Float64Array, states: Float64Array, dims: number, length: number, waypoints: number[]} | null} data
   */
  setData(data) {
    this.data = data;
    if (data) {
      let lo = Infinity;
      let hi = -Infinity;
      for (const v of data.states) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      const deg = 180 / Math.PI;
      const step = tickStep(Math.max(1, (hi - lo) * deg), 4);
      this.lo = Math.floor((lo * deg) / step) * step;
      this.hi = Math.max(this.lo + step, Math.ceil((hi * deg) / step) * step);
      this.yStep = step;
    }
    this.drawBase();
  }

  setCursor(s) {
    this.cursor = s;
    this.render();
  }

  resize(w, h, dpr) {
    this.size = [w, h];
    this.canvas.style.height = `${h}px`; // its width is the panel's (css), so it never widens the panel
    this.canvas.width = Math.max(1, Math.round(w * dpr));
    this.canvas.height = Math.max(1, Math.round(h * dpr));
    this.dpr = dpr;
    this.drawBase();
  }

  /** The plot's box in css px. */
  box() {
    const [w, h] = this.size;
    return { x0: PAD.left, x1: Math.max(PAD.left + 1, w - PAD.right), y0: PAD.top, y1: Math.max(PAD.top + 1, h - PAD.bottom) };
  }

  /** Css px x of length `s`. */
  xOf(s) {
    const { x0, x1 } = this.box();
    const L = this.data?.length || 1;
    return x0 + ((x1 - x0) * s) / L;
  }

  /** Css px y of an angle in degrees. */
  yOf(deg) {
    const { y0, y1 } = this.box();
    return y1 - ((y1 - y0) * (deg - this.lo)) / (this.hi - this.lo);
  }

  /** The length (rad) at css px x within the canvas, clamped to the path. */
  sAt(x) {
    const { x0, x1 } = this.box();
    const L = this.data?.length || 0;
    return Math.min(L, Math.max(0, ((x - x0) / (x1 - x0)) * L));
  }

  /** The axes, waypoints and curves into the base canvas (a path has up to 100,000 frames: not redrawn per cursor move). */
  drawBase() {
    const canvas = this.base;
    canvas.width = this.canvas.width;
    canvas.height = this.canvas.height;
    const ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext('2d'));
    const dpr = this.dpr || 1;
    const d = this.data;
    if (d && d.length > 0) this.drawPlot(ctx, dpr, d);
    this.render();
  }

  /** The cursor over the base. */
  render() {
    const { ctx, canvas } = this;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    if (!this.data || !(this.data.length > 0)) return;
    ctx.drawImage(this.base, 0, 0);
    if (this.cursor !== null && Number.isFinite(this.cursor)) {
      const dpr = this.dpr || 1;
      const { y0, y1 } = this.box();
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      const x = Math.round(this.xOf(this.cursor)) + 0.5;
      ctx.strokeStyle = CURSOR;
      ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.moveTo(x, y0); ctx.lineTo(x, y1); ctx.stroke();
    }
  }

  /** @param {CanvasRenderingContext2D} ctx @param {number} dpr @param {any} d */
  drawPlot(ctx, dpr, d) {
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const { x0, x1, y0, y1 } = this.box();
    ctx.font = '11px system-ui, sans-serif';
    ctx.lineWidth = 1;
    // the degrees' grid and labels
    ctx.fillStyle = AXIS;
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (let v = this.lo, i = 0; v <= this.hi + 1e-9 && i < 50; v += this.yStep, i++) {
      const y = Math.round(this.yOf(v)) + 0.5;
      ctx.strokeStyle = GRIDLINE;
      ctx.beginPath(); ctx.moveTo(x0, y); ctx.lineTo(x1, y); ctx.stroke();
      ctx.fillText(`${Number(v.toFixed(6))}°`, x0 - 4, y);
    }
    // the length's ticks (rad)
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    const xs = tickStep(d.length, 6);
    for (let v = 0, i = 0; v <= d.length + 1e-9 && i < 50; v += xs, i++) {
      const x = Math.round(this.xOf(v)) + 0.5;
      ctx.strokeStyle = AXIS;
      ctx.beginPath(); ctx.moveTo(x, y1); ctx.lineTo(x, y1 + 3); ctx.stroke();
      ctx.fillText(`${Number(v.toFixed(6))}`, x, y1 + 5);
    }
    // the waypoints
    ctx.strokeStyle = WAYPOINT;
    ctx.setLineDash([3, 3]);
    for (const w of d.waypoints) {
      const x = Math.round(this.xOf(w)) + 0.5;
      ctx.beginPath(); ctx.moveTo(x, y0); ctx.lineTo(x, y1); ctx.stroke();
    }
    ctx.setLineDash([]);
    ctx.strokeStyle = AXIS;
    ctx.strokeRect(x0 + 0.5, y0 + 0.5, x1 - x0, y1 - y0);
    // the curves: at most a point every half css px (a path has up to 100,000 frames)
    const n = d.s.length;
    const every = Math.max(1, Math.floor(n / (2 * (x1 - x0))));
    const deg = 180 / Math.PI;
    ctx.lineWidth = 2;
    ctx.lineJoin = 'round';
    for (let j = 0; j < d.dims; j++) {
      ctx.strokeStyle = JOINT_COLOURS[j % JOINT_COLOURS.length];
      ctx.beginPath();
      for (let k = 0; k < n; k += every) {
        const x = this.xOf(d.s[k]);
        const y = this.yOf(d.states[k * d.dims + j] * deg);
        if (k === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.lineTo(this.xOf(d.s[n - 1]), this.yOf(d.states[(n - 1) * d.dims + j] * deg));
      ctx.stroke();
    }
  }

  /** For tests: css px of joint `j`'s value `rad` at length `s`, and the plot's box. */
  where(s, rad) {
    return { x: this.xOf(s), y: this.yOf((rad * 180) / Math.PI), box: this.box() };
  }
}

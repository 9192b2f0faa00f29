// A CanvasRenderingContext2D that records SVG: the subset the layer drawing functions use (paths,
// rectangles, arcs, text, images, styles, dashes, alpha, save/restore, clipping, affine
// transforms), so the SVG export (ui/export-svg.js) draws with the canvas's own code (picture.js)
// instead of a second renderer. Elements are built with createElementNS and attributes, numbers
// written with two decimals; an image (a layer's raster of small cells) is embedded as a PNG data
// URL. Output is grouped: beginLayer(id) … endLayer() make a <g id=…>; within a layer, ops of the
// same style are merged into one <path> ('order': only consecutive ones, keeping the stacking;
// 'style': all of them, at the first one's place, for layers of marks that do not overlap in a
// way that shows), and a fill followed by a stroke of the same path is one element. clearRect
// draws nothing: the recorder starts empty, as a cleared layer.

const SVG_NS = 'http://www.w3.org/2000/svg';
const XLINK_NS = 'http://www.w3.org/1999/xlink';
const TAU = 2 * Math.PI;

/** A number with at most two decimals (no "-0"). */
export const fmt = (v) => {
  const r = Math.round(v * 100) / 100;
  return (r === 0 ? 0 : r).toString();
};

/** An SVG element `name` with attributes `attrs` (undefined and null skipped), appended to `parent`. */
export function svgNode(name, attrs = {}, parent = null) {
  const e = document.createElementNS(SVG_NS, name);
  for (const [k, v] of Object.entries(attrs)) if (v !== undefined && v !== null) e.setAttribute(k, String(v));
  if (parent) parent.append(e);
  return e;
}

/** A canvas colour as SVG paint: {colour, opacity} ('rgba(r, g, b, a)' split, for SVG 1.1 readers). */
export function paint(c) {
  if (typeof c !== 'string') return { colour: '#000000', opacity: 1 };
  const m = /^rgba?\(\s*([\d.]+)\s*,\s*([\d.]+)\s*,\s*([\d.]+)\s*(?:,\s*([\d.]+)\s*)?\)$/.exec(c);
  if (!m) return { colour: c, opacity: 1 };
  const hex = (v) => Math.min(255, Math.round(Number(v))).toString(16).padStart(2, '0');
  return { colour: `#${hex(m[1])}${hex(m[2])}${hex(m[3])}`, opacity: m[4] === undefined ? 1 : Math.min(1, Number(m[4])) };
}

const ANCHOR = { start: undefined, left: undefined, center: 'middle', end: 'end', right: 'end' };
const BASELINE = { alphabetic: undefined, middle: 'middle', top: 'text-before-edge', hanging: 'hanging', bottom: 'text-after-edge', ideographic: 'ideographic' };

/** A canvas font ('600 12px system-ui, sans-serif') as SVG attributes. */
function fontAttrs(font) {
  const m = /^\s*(?:(normal|bold|[1-9]00)\s+)?(\d+(?:\.\d+)?)px\s+(.+)$/.exec(font);
  if (!m) return { 'font-family': 'sans-serif', 'font-size': 10 };
  return { 'font-weight': m[1] && m[1] !== 'normal' ? m[1] : undefined, 'font-size': m[2], 'font-family': m[3] };
}

let measurer = null;

export class SvgContext {
  /**
   * Records into `root` (an <svg> or <g>); clip paths go into `defs`. `idPrefix` names the clip
   * paths (unique within the document).
   */
  constructor(root, defs, { idPrefix = 'clip' } = {}) {
    this.defs = defs;
    this.idPrefix = idPrefix;
    this.clips = 0;
    this.canvas = { width: 0, height: 0 };
    this.fillStyle = '#000000';
    this.strokeStyle = '#000000';
    this.lineWidth = 1;
    this.lineCap = 'butt';
    this.lineJoin = 'miter';
    this.globalAlpha = 1;
    this.font = '10px sans-serif';
    this.textAlign = 'start';
    this.textBaseline = 'alphabetic';
    this.imageSmoothingEnabled = true;
    this.dash = [];
    this.m = [1, 0, 0, 1, 0, 0];
    this.states = [];
    /** Open containers, innermost last: {el, mode, records, byKey, last, collapse, depth}. */
    this.stack = [this.container(root, 'order')];
    this.beginPath();
  }

  container(el, mode, collapse = false, layer = false) {
    return { el, mode, records: [], byKey: new Map(), last: null, collapse, layer };
  }

  get top() { return this.stack[this.stack.length - 1]; }

  // ---- groups (SVG only: a canvas has no such methods, so drawing code calls them with ?.) ----

  /**
   * Open <g id=`id`> (with `attrs`); `merge` 'order' or 'style' (see the file's head); `collapse`:
   * at its end, a group holding one element gives that element its id instead.
   */
  beginLayer(id, { merge = 'order', attrs = {}, collapse = false } = {}) {
    const g = svgNode('g', { id, ...attrs }, this.top.el);
    this.stack.push(this.container(g, merge, collapse, true));
  }

  /** Close the innermost layer (and the clip groups opened in it); an empty layer is removed. */
  endLayer() {
    if (this.stack.length <= 1) return;
    while (this.stack.length > 1 && !this.top.layer) this.flush(this.stack.pop()); // clip groups left open
    if (this.stack.length <= 1) return;
    const c = this.stack.pop();
    this.flush(c);
    const g = c.el;
    if (!g.firstChild) { g.remove(); return; }
    if (c.collapse && g.childElementCount === 1 && !g.firstElementChild.hasAttribute('id')) {
      const child = g.firstElementChild;
      for (const a of [...g.attributes]) if (!child.hasAttribute(a.name)) child.setAttribute(a.name, a.value);
      g.replaceWith(child);
    }
  }

  /** Write every record's path data (call once drawing is over). */
  finish() {
    while (this.stack.length > 1) this.endLayer();
    this.flush(this.top);
  }

  flush(c) {
    for (const r of c.records) if (r.parts) { r.el.setAttribute('d', r.parts.join('')); r.parts = null; }
    c.records = [];
    c.byKey.clear();
    c.last = null;
  }

  // ---- state ----

  save() {
    this.states.push({ fillStyle: this.fillStyle, strokeStyle: this.strokeStyle, lineWidth: this.lineWidth, lineCap: this.lineCap,
      lineJoin: this.lineJoin, globalAlpha: this.globalAlpha, font: this.font, textAlign: this.textAlign,
      textBaseline: this.textBaseline, dash: this.dash, m: this.m, stack: this.stack.length });
  }

  restore() {
    const s = this.states.pop();
    if (!s) return;
    while (this.stack.length > s.stack) {
      const c = this.stack.pop();
      this.flush(c);
      if (!c.el.firstChild) c.el.remove();
    }
    for (const k of ['fillStyle', 'strokeStyle', 'lineWidth', 'lineCap', 'lineJoin', 'globalAlpha', 'font', 'textAlign', 'textBaseline', 'dash', 'm']) this[k] = s[k];
  }

  setLineDash(d) { this.dash = Array.isArray(d) && d.every((v) => Number.isFinite(v) && v >= 0) ? [...d] : this.dash; }
  getLineDash() { return [...this.dash]; }

  setTransform(a = 1, b = 0, c = 0, d = 1, e = 0, f = 0) {
    if (typeof a === 'object' && a) ({ a, b, c, d, e, f } = a);
    this.m = [a, b, c, d, e, f];
  }
  resetTransform() { this.m = [1, 0, 0, 1, 0, 0]; }
  transform(a, b, c, d, e, f) {
    const [A, B, C, D, E, F] = this.m;
    this.m = [A * a + C * b, B * a + D * b, A * c + C * d, B * c + D * d, A * e + C * f + E, B * e + D * f + F];
  }
  translate(x, y) { this.transform(1, 0, 0, 1, x, y); }
  scale(x, y) { this.transform(x, 0, 0, y, 0, 0); }
  rotate(a) { const c = Math.cos(a), s = Math.sin(a); this.transform(c, s, -s, c, 0, 0); }

  /** Point (x, y) through the transform, written. */
  pt(x, y) {
    const [a, b, c, d, e, f] = this.m;
    return `${fmt(a * x + c * y + e)} ${fmt(b * x + d * y + f)}`;
  }

  /** How much the transform scales lengths. */
  get unit() { return Math.sqrt(Math.abs(this.m[0] * this.m[3] - this.m[1] * this.m[2])); }

  // ---- the path ----

  beginPath() { this.path = []; this.open = false; this.version = (this.version || 0) + 1; }
  moveTo(x, y) { this.path.push(`M${this.pt(x, y)}`); this.start = [x, y]; this.at = [x, y]; this.open = true; this.version++; }
  lineTo(x, y) {
    if (!this.open) { this.moveTo(x, y); return; }
    this.path.push(`L${this.pt(x, y)}`);
    this.at = [x, y];
    this.version++;
  }
  closePath() { if (this.open) { this.path.push('Z'); this.at = this.start; this.version++; } }

  rect(x, y, w, h) {
    const [, b, c] = this.m;
    if (b === 0 && c === 0) {
      const sx = this.m[0], sy = this.m[3];
      this.path.push(`M${this.pt(x, y)}h${fmt(w * sx)}v${fmt(h * sy)}h${fmt(-w * sx)}Z`);
    } else {
      this.path.push(`M${this.pt(x, y)}L${this.pt(x + w, y)}L${this.pt(x + w, y + h)}L${this.pt(x, y + h)}Z`);
    }
    this.start = [x, y];
    this.at = [x, y];
    this.open = true;
    this.version++;
  }

  arc(x, y, r, a0, a1, ccw = false) {
    if (!(r >= 0) || ![x, y, a0, a1].every(Number.isFinite)) return;
    const px = (a) => x + r * Math.cos(a), py = (a) => y + r * Math.sin(a);
    if (this.open) this.lineTo(px(a0), py(a0)); else this.moveTo(px(a0), py(a0));
    let sweep = ccw ? a0 - a1 : a1 - a0;
    const rr = fmt(r * this.unit);
    const det = this.m[0] * this.m[3] - this.m[1] * this.m[2];
    const flag = (ccw ? 0 : 1) ^ (det < 0 ? 1 : 0);
    if (sweep >= TAU) { // a full circle: two half arcs
      const mid = ccw ? a0 - Math.PI : a0 + Math.PI;
      this.path.push(`A${rr} ${rr} 0 0 ${flag} ${this.pt(px(mid), py(mid))}A${rr} ${rr} 0 0 ${flag} ${this.pt(px(a0), py(a0))}`);
      this.at = [px(a0), py(a0)];
    } else {
      sweep = ((sweep % TAU) + TAU) % TAU;
      if (sweep === 0) return;
      this.path.push(`A${rr} ${rr} 0 ${sweep > Math.PI ? 1 : 0} ${flag} ${this.pt(px(a1), py(a1))}`);
      this.at = [px(a1), py(a1)];
    }
    this.version++;
  }

  // ---- painting ----

  fillAttrs(style) {
    const p = paint(style);
    const o = p.opacity * this.globalAlpha;
    return { fill: p.colour, 'fill-opacity': o < 1 ? fmt(Math.max(0, o)) : undefined };
  }

  strokeAttrs() {
    const p = paint(this.strokeStyle);
    const o = p.opacity * this.globalAlpha;
    const u = this.unit;
    return { stroke: p.colour, 'stroke-opacity': o < 1 ? fmt(Math.max(0, o)) : undefined, 'stroke-width': fmt(this.lineWidth * u),
      'stroke-dasharray': this.dash.length && this.dash.some((v) => v > 0) ? this.dash.map((v) => fmt(v * u)).join(' ') : undefined,
      'stroke-linecap': this.lineCap !== 'butt' ? this.lineCap : undefined,
      'stroke-linejoin': this.lineJoin !== 'miter' ? this.lineJoin : undefined };
  }

  /** Record path data `d` painted with `attrs` (merged per the layer's rule). */
  record(d, attrs, kind) {
    if (!d) return;
    const c = this.top;
    const key = JSON.stringify(attrs);
    if (kind === 'stroke' && c.last && c.last.kind === 'fill' && c.last.single && c.last.version === this.version && c.last.pathKey === d) {
      const r = c.last; // the path just filled, now stroked: one element
      for (const [k, v] of Object.entries(attrs)) if (k !== 'fill' && v !== undefined) r.el.setAttribute(k, String(v));
      if (c.byKey.get(r.key) === r) c.byKey.delete(r.key);
      r.kind = 'both';
      r.single = false;
      return;
    }
    const target = c.mode === 'style' ? c.byKey.get(key) : (c.last && c.last.key === key && c.last.kind === kind ? c.last : null);
    if (target) {
      target.parts.push(d);
      target.single = false;
      c.last = target;
      return;
    }
    const el = svgNode('path', kind === 'stroke' ? { fill: 'none', ...attrs } : attrs, c.el);
    const r = { el, key, kind, parts: [d], single: true, version: this.version, pathKey: d };
    c.records.push(r);
    c.byKey.set(key, r);
    c.last = r;
  }

  fill(rule) {
    const attrs = this.fillAttrs(this.fillStyle);
    if (rule === 'evenodd') attrs['fill-rule'] = 'evenodd';
    this.record(this.path.join(''), attrs, 'fill');
  }

  stroke() { this.record(this.path.join(''), this.strokeAttrs(), 'stroke'); }

  /** Clip to the current path: what follows, until the matching restore(), goes into a clipped group. */
  clip(rule) {
    const id = `${this.idPrefix}-${++this.clips}`;
    const cp = svgNode('clipPath', { id }, this.defs);
    svgNode('path', { d: this.path.join(''), 'clip-rule': rule === 'evenodd' ? 'evenodd' : undefined }, cp);
    const g = svgNode('g', { 'clip-path': `url(#${id})` }, this.top.el);
    this.stack.push(this.container(g, this.top.mode));
  }

  rectD(x, y, w, h) {
    const saved = [this.path, this.open, this.start, this.at, this.version];
    this.path = [];
    this.rect(x, y, w, h);
    const d = this.path.join('');
    [this.path, this.open, this.start, this.at, this.version] = saved;
    return d;
  }

  fillRect(x, y, w, h) { this.record(this.rectD(x, y, w, h), this.fillAttrs(this.fillStyle), 'fill'); this.top.last.single = false; }
  strokeRect(x, y, w, h) { this.record(this.rectD(x, y, w, h), this.strokeAttrs(), 'stroke'); }
  clearRect() { /* nothing recorded yet is cleared: layers are drawn into a fresh recorder */ }

  text(t, x, y, paintAttrs) {
    const [a, b, c, d, e, f] = this.m;
    const el = svgNode('text', { x: fmt(a * x + c * y + e), y: fmt(b * x + d * y + f), ...fontAttrs(this.font),
      'text-anchor': ANCHOR[this.textAlign], 'dominant-baseline': BASELINE[this.textBaseline], ...paintAttrs }, this.top.el);
    el.textContent = String(t);
    this.top.last = null;
  }

  fillText(t, x, y) { this.text(t, x, y, this.fillAttrs(this.fillStyle)); }
  strokeText(t, x, y) { this.text(t, x, y, { fill: 'none', ...this.strokeAttrs() }); }

  measureText(t) {
    measurer ??= document.createElement('canvas').getContext('2d');
    measurer.font = this.font;
    return measurer.measureText(t);
  }

  /**
   * An image (a canvas) as an embedded PNG: drawImage(img, dx, dy[, dw, dh]) or
   * drawImage(img, sx, sy, sw, sh, dx, dy, dw, dh). Transforms: translation and scale only.
   */
  drawImage(img, ...a) {
    const iw = img.width, ih = img.height;
    let [sx, sy, sw, sh] = [0, 0, iw, ih], dx, dy, dw, dh;
    if (a.length >= 8) [sx, sy, sw, sh, dx, dy, dw, dh] = a;
    else if (a.length >= 4) [dx, dy, dw, dh] = a;
    else { [dx, dy] = a; dw = iw; dh = ih; }
    if (!(sw > 0 && sh > 0 && dw > 0 && dh > 0)) return;
    let url;
    if (sx === 0 && sy === 0 && sw === iw && sh === ih && typeof img.toDataURL === 'function') url = img.toDataURL('image/png');
    else {
      const c = document.createElement('canvas');
      c.width = Math.ceil(sw);
      c.height = Math.ceil(sh);
      c.getContext('2d').drawImage(img, sx, sy, sw, sh, 0, 0, sw, sh);
      url = c.toDataURL('image/png');
      c.width = 0;
      c.height = 0;
    }
    const [ma, , , md, me, mf] = this.m;
    const el = svgNode('image', { x: fmt(ma * dx + me), y: fmt(md * dy + mf), width: fmt(dw * ma), height: fmt(dh * md),
      preserveAspectRatio: 'none', opacity: this.globalAlpha < 1 ? fmt(this.globalAlpha) : undefined,
      'image-rendering': this.imageSmoothingEnabled ? undefined : 'pixelated', href: url }, this.top.el);
    el.setAttributeNS(XLINK_NS, 'xlink:href', url); // SVG 1.1 readers
    this.top.last = null;
  }
}

// Zoom and pan on the plane (the view from above): the wheel zooms about the pointer, a drag with
// the middle button pans, two fingers on a touch screen pinch and pan, and the bar's buttons zoom
// about the centre or fit the workspace's bounds again (also the keys + (or =) - 0, and shift + the
// arrows pan once zoomed in: in the playground
// while the pointer is over the canvas, the canvas has the focus (Tab reaches it) or a button of the
// bar has; in the embed while it has the focus, which the wheel waits for too, so a course page
// scrolls past an embed). The view (draw/view.js setViewport) moves
// its layers' last pictures at once and redraws them at the new scale once the viewport rests, so
// a gesture costs the same few image copies a frame over a tree of ten nodes or of a million.

import { MAX_ZOOM } from '../draw/transform.js';
import { readNumbers } from './camera-link.js';

const WHEEL = 0.0015; // zoom factor per pixel of wheel travel: exp(−deltaY · WHEEL)
const LINE = 40;      // pixels per line when the wheel reports lines
const STEP = 1.5;     // a button's or key's zoom factor
const PAN_STEP = 0.1; // shift + an arrow pans by this share of the map's shorter side
/** shift + an arrow: which way the picture moves (to look right, it moves left) */
const PAN = { ArrowRight: [-1, 0], ArrowLeft: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
const MAX_CENTRE = 1e6; // |cx|, |cy| a link may give (a scenario's bounds are within ±1e6)

/**
 * A share link's `zoom=z,cx,cy` (the plane's zoom, 1 … MAX_ZOOM times the fitted scale, and the
 * world point at the view's centre) → {viewport: {zoom, cx, cy}} or {why} in words. The view
 * keeps the centre within the scenario's bounds.
 * @param {unknown} text
 * @returns {{viewport: {zoom: number, cx: number, cy: number}, why?: undefined} | {why: string, viewport?: undefined}}
 */
export function readZoom(text) {
  const r = readNumbers(text, ['zoom', 'cx', 'cy'], 80);
  if (r.why !== undefined) return { why: r.why };
  const v = r.values;
  if (v[0] < 1 || v[0] > MAX_ZOOM) return { why: `zoom must be from 1 to ${MAX_ZOOM}` };
  if (Math.abs(v[1]) > MAX_CENTRE || Math.abs(v[2]) > MAX_CENTRE) return { why: `cx and cy must be within ±${MAX_CENTRE.toExponential()}` };
  return { viewport: { zoom: v[0], cx: v[1], cy: v[2] } };
}

/** The bar's three buttons (− Fit +) in a group, for a page that builds its own (the embed). */
export function zoomBar() {
  const bar = document.createElement('div');
  bar.className = 'plane-zoom';
  bar.setAttribute('role', 'group');
  bar.setAttribute('aria-label', 'Zoom the view from above');
  const make = (which, text, label, title) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.dataset.zoom = which;
    b.textContent = text;
    if (label) b.setAttribute('aria-label', label);
    b.title = title;
    return b;
  };
  bar.append(make('out', '−', 'Zoom out', 'Zoom out (-; or the wheel over the map)'),
    make('fit', 'Fit', '', 'Fit the workspace\'s bounds (0); when zoomed in, drag with the middle button or two fingers to pan'),
    make('in', '+', 'Zoom in', 'Zoom in (+; or the wheel over the map)'));
  return bar;
}

/** A viewport {zoom, cx, cy} as a link's value (10 significant digits; what readZoom reads back). */
export function writeZoom(vp) {
  return [vp.zoom, vp.cx, vp.cy].map((x) => String(Number(x.toPrecision(10)))).join(',');
}

/**
 * `canvas` the plane's canvas, `view` its draw/view.js View, `bar` the group of its three buttons
 * (found inside it by their `data-zoom`: out, fit, in; shown only once zoomed in); `onChange` is called when the zoom or
 * centre changes (the share link). `keys`: the element whose keydown events are read, and `keysWhen()`
 * whether one is meant for the map; `wheelWhen()` whether the wheel zooms now.
 * @param {{canvas: HTMLCanvasElement, view: any, bar: HTMLElement, onChange?: () => void,
 *   keys?: EventTarget, keysWhen?: () => boolean, wheelWhen?: () => boolean}} options
 */
export function wirePlaneZoom({ canvas, view, bar, onChange = () => {}, keys = document, keysWhen = null, wheelWhen = () => true }) {
  const button = (end) => /** @type {HTMLButtonElement} */ (bar.querySelector(`[data-zoom="${end}"]`));
  const out = button('out'), fit = button('fit'), zin = button('in');
  const centre = () => [view.layout.width / 2, view.layout.height / 2];
  const dpr = () => view.layout?.dpr ?? 1;
  const sync = () => {
    const z = view.zoom;
    // shown once zoomed in: over the fitted map the bar would cover a corner, where a start or a
    // goal often sits (the wheel, a pinch or the keys zoom in)
    bar.hidden = z <= 1;
    fit.textContent = `Fit (${z < 10 ? z.toFixed(1) : Math.round(z)}×)`;
  };
  view.onViewport = () => { sync(); onChange(); };
  const zoomBy = (f) => { if (view.layout) view.zoomAt(f, ...centre()); };
  zin.addEventListener('click', () => zoomBy(STEP));
  out.addEventListener('click', () => zoomBy(1 / STEP));
  fit.addEventListener('click', () => view.setViewport(null));

  canvas.addEventListener('wheel', (e) => {
    if (!view.layout || !view.scenario || !wheelWhen()) return;
    e.preventDefault();
    const px = e.deltaMode === 1 ? LINE : e.deltaMode === 2 ? canvas.clientHeight : 1;
    view.zoomAt(Math.exp(-e.deltaY * px * WHEEL), e.offsetX * dpr(), e.offsetY * dpr());
  }, { passive: false });

  // Panning: the middle button, or two touches (which also pinch)
  /** @type {Map<number, [number, number]>} */
  const touches = new Map();
  let drag = null; // {x, y} of the middle button's last position
  const mid = () => {
    const [[ax, ay], [bx, by]] = [...touches.values()];
    return { x: (ax + bx) / 2, y: (ay + by) / 2, d: Math.hypot(ax - bx, ay - by) };
  };
  let pinch = null;
  canvas.addEventListener('pointerdown', (e) => {
    if (e.pointerType === 'touch') {
      touches.set(e.pointerId, [e.offsetX, e.offsetY]);
      if (touches.size === 2) pinch = mid();
    } else if (e.button === 1 && view.zoom > 1) {
      e.preventDefault(); // no auto-scroll
      drag = { x: e.offsetX, y: e.offsetY };
      canvas.setPointerCapture(e.pointerId);
    }
  });
  canvas.addEventListener('pointermove', (e) => {
    if (drag) {
      view.panBy((e.offsetX - drag.x) * dpr(), (e.offsetY - drag.y) * dpr());
      drag = { x: e.offsetX, y: e.offsetY };
    } else if (touches.has(e.pointerId)) {
      touches.set(e.pointerId, [e.offsetX, e.offsetY]);
      if (touches.size !== 2 || !pinch) return;
      const now = mid();
      if (pinch.d > 0 && now.d > 0) view.zoomAt(now.d / pinch.d, pinch.x * dpr(), pinch.y * dpr());
      view.panBy((now.x - pinch.x) * dpr(), (now.y - pinch.y) * dpr());
      pinch = now;
    }
  });
  const end = (e) => {
    touches.delete(e.pointerId);
    if (touches.size < 2) pinch = null;
    if (drag && e.button === 1 || e.type === 'pointercancel') drag = null;
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);

  // Keys over the canvas, or with the canvas or the bar focused
  let over = false;
  canvas.addEventListener('pointerenter', () => { over = true; });
  canvas.addEventListener('pointerleave', () => { over = false; });
  const meant = keysWhen ?? (() => over || document.activeElement === canvas || !!(document.activeElement && bar.contains(document.activeElement)));
  keys.addEventListener('keydown', (/** @type {KeyboardEvent} */ e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || !view.scenario || !meant()) return;
    const t = e.composedPath()[0];
    if (t instanceof Element && t.closest('input, select, textarea, [contenteditable]')) return;
    if (e.key === '+' || e.key === '=') zoomBy(STEP);
    else if (e.key === '-') zoomBy(1 / STEP);
    else if (e.key === '0') view.setViewport(null);
    else if (e.shiftKey && Object.hasOwn(PAN, e.key) && view.zoom > 1 && view.layout) {
      const s = PAN_STEP * Math.min(view.layout.width, view.layout.height);
      view.panBy(PAN[e.key][0] * s, PAN[e.key][1] * s);
    } else return;
    e.preventDefault();
    e.stopPropagation(); // an embed's host page keeps its own keys otherwise
  });
  sync();
}

// The 3-D view's orbit camera: it looks at a target from a distance, turned by an azimuth about
// the world's z (up) and an elevation above the floor. Drag turns it, the wheel zooms, two fingers
// pinch-zoom, a double click (or double tap) frames the problem again. It only changes numbers and
// asks for a redraw (`onChange`). A share link carries it (`state()` / `setState()`, within the
// bounds of ui/camera-link.js, which are its own).

import { lookAt, perspective, multiply } from './gl.js';
import { CAMERA, wrapAngle } from '../ui/camera-link.js';

const FOV = (40 * Math.PI) / 180;
const MIN_ELEVATION = CAMERA.minPitch;
const MAX_ELEVATION = CAMERA.maxPitch;

export class OrbitCamera {
  /** @param {HTMLCanvasElement} canvas @param {() => void} onChange */
  constructor(canvas, onChange) {
    this.canvas = canvas;
    this.onChange = onChange;
    this.target = [0, 0, 0];
    this.distance = 3;
    this.azimuth = -2.6;   // radians about z, from +x: from behind the arm and to its right
    this.elevation = 0.4;  // radians above the xy plane
    this.home = null;      // what a double click frames: {centre, radius}
    this.aspect = 1;
    this.pointers = new Map(); // active pointers: id → [x, y]
    this.pinch = 0;
    this.touched = false; // the user turned or zoomed (a resize then keeps the view)
    this.listen();
  }

  /** Frame a sphere (centre, radius) from the current direction; kept as "home" for double clicks. */
  frame(centre, radius, keep = true) {
    if (keep) this.home = { centre: [...centre], radius };
    this.target = [...centre];
    const half = Math.min(FOV, FOV * this.aspect) / 2;
    this.distance = Math.min(CAMERA.maxDistance, Math.max(CAMERA.minDistance, (radius / Math.sin(half)) * 1.05));
    this.onChange();
  }

  /** The camera as a share link carries it: {target, yaw (azimuth, within ±π), pitch (elevation), distance}. */
  state() {
    return { target: [...this.target], yaw: wrapAngle(this.azimuth), pitch: this.elevation, distance: this.distance };
  }

  /** Put the camera where `c` says (a link's camera, already bounded); it then stays through resizes. */
  setState(c) {
    const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));
    this.target = c.target.map((v) => clamp(v, -CAMERA.maxTarget, CAMERA.maxTarget));
    this.azimuth = wrapAngle(c.yaw);
    this.elevation = clamp(c.pitch, MIN_ELEVATION, MAX_ELEVATION);
    this.distance = clamp(c.distance, CAMERA.minDistance, CAMERA.maxDistance);
    this.touched = true;
    this.onChange();
  }

  /** The eye's position. */
  get eye() {
    const [t, d, a, e] = [this.target, this.distance, this.azimuth, this.elevation];
    return [t[0] + d * Math.cos(e) * Math.cos(a), t[1] + d * Math.cos(e) * Math.sin(a), t[2] + d * Math.sin(e)];
  }

  /** {view, proj, viewProj} for the canvas's aspect. */
  matrices() {
    const view = lookAt(this.eye, this.target, [0, 0, 1]);
    const proj = perspective(FOV, this.aspect, this.distance / 100, this.distance * 20);
    return { view, proj, viewProj: multiply(proj, view) };
  }

  rotate(dx, dy) {
    this.touched = true;
    const k = 2 * Math.PI / Math.max(200, this.canvas.clientWidth);
    this.azimuth -= dx * k;
    this.elevation = Math.min(MAX_ELEVATION, Math.max(MIN_ELEVATION, this.elevation + dy * k));
    this.onChange();
  }

  zoom(factor) {
    this.touched = true;
    this.distance = Math.min(CAMERA.maxDistance, Math.max(CAMERA.minDistance, this.distance * factor));
    this.onChange();
  }

  listen() {
    const c = this.canvas;
    c.addEventListener('pointerdown', (e) => {
      c.setPointerCapture?.(e.pointerId);
      this.pointers.set(e.pointerId, [e.clientX, e.clientY]);
      if (this.pointers.size === 2) this.pinch = this.spread();
    });
    c.addEventListener('pointermove', (e) => {
      const last = this.pointers.get(e.pointerId);
      if (!last) return;
      const now = [e.clientX, e.clientY];
      this.pointers.set(e.pointerId, now);
      if (this.pointers.size === 1) this.rotate(now[0] - last[0], now[1] - last[1]);
      else if (this.pointers.size === 2) {
        const s = this.spread();
        if (this.pinch > 0 && s > 0) this.zoom(this.pinch / s);
        this.pinch = s;
      }
    });
    const up = (e) => { this.pointers.delete(e.pointerId); this.pinch = this.pointers.size === 2 ? this.spread() : 0; };
    c.addEventListener('pointerup', up);
    c.addEventListener('pointercancel', up);
    c.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.zoom(Math.exp(Math.max(-1, Math.min(1, e.deltaY / 300))));
    }, { passive: false });
    c.addEventListener('dblclick', () => { if (this.home) this.frame(this.home.centre, this.home.radius, false); });
  }

  /** The distance between the two active pointers. */
  spread() {
    const [a, b] = [...this.pointers.values()];
    return a && b ? Math.hypot(a[0] - b[0], a[1] - b[1]) : 0;
  }
}

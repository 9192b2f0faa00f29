// The solved path in the 3-D view, kept apart from view3d.js (which calls these from its render):
// the tool's curve drawn as thick as the top view's path (a dark casing, then the path's colour:
// WebGL2 draws lines a pixel wide, so the curve is also drawn as round points along it, its
// animation frames being a few millimetres apart) over everything, and the arm as see-through
// ghosts at poses along the path (www/ui/path3d.js picks them at a spacing in rad and gets their
// link frames from the core). Nothing here computes kinematics.

import { LineBuffer, rgb } from './gl.js';

/** The ghosts' opacity: see-through, so the arm at the scrubbed pose and the trees show through. */
export const GHOST_ALPHA = 0.22;
/** The curve's points, css px: the casing's and the colour's (the top view's path is 3 px on a 5 px casing). */
const CASING_PX = 6;
const PATH_PX = 4;

export class PathCurve {
  /** @param {WebGL2RenderingContext} gl @param {any} prog the line program */
  constructor(gl, prog) {
    this.lines = new LineBuffer(gl, prog);
    this.points = new LineBuffer(gl, prog);
    this.raw = false;
  }

  get length() { return this.lines.length; }

  clear() { this.lines.clear(); this.points.clear(); }

  /** The tool's curve (flat x, y, z…); `raw`: the raw path's (drawn in the top view's raw path colour). */
  set(curve, raw) {
    this.clear();
    this.raw = !!raw;
    for (let i = 0; i + 5 < curve.length; i += 3) this.lines.push(curve, i, i + 6);
    this.points.push(curve, 0, curve.length - (curve.length % 3));
  }

  /**
   * Draw over everything (the caller has the line program in use, depth test off).
   * @param {(buf: LineBuffer, colour: string, mode?: number, alpha?: number) => void} lines the view's line drawer
   */
  draw(gl, prog, palette, lines) {
    if (!this.lines.length) return;
    const dpr = window.devicePixelRatio || 1;
    const colour = this.raw ? palette.rawPath : palette.smoothPath;
    gl.uniform1f(prog.u.pointSize, CASING_PX * dpr);
    lines(this.points, palette.pathCasing, gl.POINTS);
    gl.uniform1f(prog.u.pointSize, PATH_PX * dpr);
    lines(this.points, colour, gl.POINTS);
    lines(this.lines, colour, gl.LINES);
    gl.uniform1f(prog.u.pointSize, 3 * dpr);
  }
}

/**
 * The ghosts: the arm at each pose of `ghosts` (link frames, 16 numbers a link), see-through in
 * `colour`. Call with the mesh program in use, blending on and depth writes off.
 * @param {import('./view3d.js').View3D} view
 * @param {Float64Array[]} ghosts
 * @param {string} colour '#rrggbb'
 */
export function drawGhosts(view, ghosts, colour) {
  if (!ghosts.length) return;
  const c = rgb(colour);
  for (const frames of ghosts) {
    for (const p of view.parts) view.drawMesh(p.buffers, frames.subarray(p.link * 16, p.link * 16 + 16), c, GHOST_ALPHA);
  }
}

// The explain panel's actors in the 3-D view (the arm's counterpart of the top view's sample dot,
// step edge and collision cross, ui/explain-panel.js): the step's sample as a see-through ghost arm,
// the configuration being checked as another, and a collision marked where it happened: the arm
// at the colliding configuration with the colliding link (and, when two links meet, the other)
// tinted, and a mark at the contact point drawn over everything.
//
// Every number comes from the core: the states are the core's state log (run/arm-states.js), the
// link frames and the contact point the core's `Scene.link_frames` and `Scene.contact` at those
// states (the page thread's copy of the core, as the pose panel's). View3D calls `drawGhosts`
// in its translucent phase and `drawMarks` last; nothing here computes kinematics.

import { LineBuffer, rgb } from './gl.js';

/** The ghosts' opacity. */
const GHOST = 0.3;
/** The colliding link's opacity. */
const TINT = 0.85;

/**
 * @typedef {{frames: Float64Array | null, colour: string}} Ghost
 * @typedef {{sample?: Ghost, step?: Ghost, collision?: {frames: Float64Array, colour: string, links: number[], at: number[] | null, words: string}}} Actors3DData
 */

export class Actors3D {
  /** @param {import('./view3d.js').View3D} view */
  constructor(view) {
    this.view = view;
    this.mark = new LineBuffer(view.gl, view.progs.line);
    /** @type {Actors3DData | null} */
    this.data = null;
    this.hidden = false; // not drawn (tests compare the view with and without)
  }

  /** The step's actors (or null: none). */
  set(data) {
    this.data = data;
    this.mark.clear();
    const c = data?.collision;
    if (c?.at) {
      // A cross of three bars at the contact point, a tenth of the scene's size, and the point.
      const s = Math.max(0.02, 0.04 * Math.max(...this.view.size));
      const [x, y, z] = c.at;
      this.mark.push([x - s, y, z, x + s, y, z, x, y - s, z, x, y + s, z, x, y, z - s, x, y, z + s]);
    }
    this.view.requestRender();
  }

  /** The ghosts and the collision's arm (the mesh program in use, blending on, depth not written). */
  drawGhosts() {
    const d = this.data;
    if (!d || this.hidden) return;
    const v = this.view;
    const arm = (frames, colour, alpha, tinted = [], tint = colour) => {
      if (!frames) return;
      for (const p of v.parts) {
        if (p.link * 16 + 16 > frames.length) continue;
        const hit = tinted.includes(p.link);
        v.drawMesh(p.buffers, frames.subarray(p.link * 16, p.link * 16 + 16), rgb(hit ? tint : colour), hit ? TINT : alpha);
      }
    };
    if (d.sample) arm(d.sample.frames, d.sample.colour, GHOST);
    if (d.collision) arm(d.collision.frames, d.step?.colour || d.collision.colour, GHOST, d.collision.links, d.collision.colour);
    else if (d.step) arm(d.step.frames, d.step.colour, GHOST);
  }

  /** The contact mark over everything (the line program in use, no depth test). */
  drawMarks(lines) {
    const c = this.data?.collision;
    if (!c?.at || !this.mark.length || this.hidden) return;
    lines(this.mark, c.colour);
    lines(this.mark, c.colour, this.view.gl.POINTS);
  }
}

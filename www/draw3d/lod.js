// How much of the trees the 3-D view draws while its camera moves. A solved course run holds some
// 14,000 nodes, and a long one 100,000 edges drawn through their `delta` steps: fine on a GPU, but
// rasterised on the CPU (SwiftShader, a browser without a GPU) each frame takes most of a second,
// and a drag would stutter. So while the camera moves (a drag, the wheel, a pinch, framing), each
// tree is drawn through an evenly spread subset of its segments (every stride-th, the stride a power
// of two), and without its node points; once the camera has rested SETTLE_MS the whole trees are
// drawn again. How many segments a moving frame draws adapts to the frame times the browser
// reports: halved while a frame takes over 1.5 × TARGET_MS, doubled while frames keep pace (a GPU
// soon draws every segment, moving or not). Past POINTS_MAX nodes a tree's node points are not drawn at all: its edges' ends show the
// nodes. Nothing is dropped from the data: the subset is a second buffer, rebuilt when a tree grew.

import { LineBuffer } from './gl.js';

/** Segments drawn across both trees while the camera moves, at first (then adapted). */
export const MOVING_SEGMENTS = 16000;
/** The fewest segments a moving frame draws, and the frame time aimed at (60 fps). */
export const MIN_SEGMENTS = 1000;
export const TARGET_MS = 1000 / 60;
/** Frames after a halving before the budget may grow again (no flicker between two levels). */
const COOLDOWN = 30;
/** Node points drawn per tree; past that, none (the edges' ends show the nodes). */
export const POINTS_MAX = 20000;
/** How long the camera rests before the whole trees are drawn again (ms). */
export const SETTLE_MS = 180;

export class TreeLod {
  /** @param {WebGL2RenderingContext} gl @param {any} prog the line program */
  constructor(gl, prog) {
    this.subsets = [new LineBuffer(gl, prog), new LineBuffer(gl, prog)];
    /** the full buffer's length and the stride each subset was built from */
    this.built = [{ length: -1, stride: 0 }, { length: -1, stride: 0 }];
    this.until = 0;
    /** a camera change not yet drawn */
    this.changed = false;
    /** whether the frame being drawn (or the last drawn) thins the trees */
    this.thin = false;
    /** @type {ReturnType<typeof setTimeout> | null} */
    this.timer = null;
    /** off: always the whole trees (tests that time a full frame) */
    this.off = false;
    /** segments a moving frame draws */
    this.budget = MOVING_SEGMENTS;
    this.cooldown = 0;
    /** the last frame's time stamp, when it was a moving one */
    this.last = null;
  }

  /**
   * After a frame drawn at `time` (requestAnimationFrame's): two moving frames in a row tell how
   * long a moving frame takes, and the budget follows.
   * @param {number} time
   */
  drawn(time) {
    if (this.thin && this.last !== null) {
      const dt = time - this.last;
      if (this.cooldown > 0) this.cooldown--;
      if (dt > 1.5 * TARGET_MS && this.budget > MIN_SEGMENTS) {
        this.budget = Math.max(MIN_SEGMENTS, this.budget / 2);
        this.cooldown = COOLDOWN;
      } else if (dt <= 1.1 * TARGET_MS && this.cooldown === 0) {
        this.budget = Math.min(1 << 24, this.budget * 2);
      }
    }
    this.last = this.thin ? time : null;
  }

  /** The camera moved: subsets until it rests, then `redraw()` once for the whole trees. */
  moved(redraw) {
    this.changed = true;
    this.until = performance.now() + SETTLE_MS;
    if (this.timer) clearTimeout(this.timer);
    this.timer = setTimeout(() => { this.timer = null; redraw(); }, SETTLE_MS + 5);
  }

  /**
   * At the start of a frame: whether it thins the trees (a camera change since the last frame, or
   * one within SETTLE_MS: a frame slower than that still counts as moving).
   */
  frame() {
    this.thin = !this.off && (this.changed || performance.now() < this.until);
    this.changed = false;
    return this.thin;
  }

  /**
   * The segment buffers to draw for the two trees' `full` segment buffers (2 points a segment):
   * themselves, or while moving and past MOVING_SEGMENTS in all, every stride-th segment of each
   * (one stride for both, so the two trees keep their proportions).
   * @param {LineBuffer[]} full
   */
  edges(full) {
    const segments = (full[0].length + full[1].length) / 2;
    if (!this.thin || segments <= this.budget) return full;
    const stride = 2 ** Math.ceil(Math.log2(segments / this.budget));
    return full.map((buf, t) => {
      const b = this.built[t];
      const sub = this.subsets[t];
      if (b.length !== buf.length || b.stride !== stride) {
        sub.clear();
        for (let s = 0; 2 * s < buf.length; s += stride) sub.push(buf.data, 6 * s, 6 * s + 6);
        this.built[t] = { length: buf.length, stride };
      }
      return sub;
    });
  }

  /** Whether a tree's node points (`count` of them) are drawn this frame. */
  points(count) {
    return count <= POINTS_MAX && !(this.thin && count > this.budget / 4);
  }

  clear() {
    for (const s of this.subsets) s.clear();
    this.built = [{ length: -1, stride: 0 }, { length: -1, stride: 0 }];
  }
}

// Where the 3-D view plugs into the page: a view of the lane (drawRecords, clearRun, setResult,
// like the C-space view) that loads www/draw3d/ with a dynamic import() only when the core says the
// loaded scene has a 3-D view (its `caps.view3d`: the robot's Spatial capability), so a 2-D
// scenario never fetches it. It keeps what the worker sends for the 3-D view (the trees' tool
// curves with each events batch, the path's tool curve and poses with the result) and hands each
// node to the view when its NODE_ADDED record is revealed, so the trees grow with the replay.
// Once solved it hands the path to www/ui/path3d.js (`onPath`), which scrubs along it (`setScrub`),
// asks for ghosts (`setGhosts`) and says which path the arm follows (`setRaw`: the top view's
// "robot follows the raw path").

import { EventKind } from '../run/events.js';

export class View3dSlot {
  /**
   * @param {HTMLCanvasElement} canvas the 3-D view's canvas (hidden while there is none)
   * @param {{record: (i: number) => Float64Array}} store the revealed records
   * @param {Record<string, any>} palette
   * @param {() => void} [onActive] called when the view appears or goes (the page resizes the stage)
   */
  constructor(canvas, store, palette, onActive = () => {}) {
    this.canvas = canvas;
    this.store = store;
    this.palette = palette;
    this.onActive = onActive;
    this.view = null;       // the View3D, once loaded
    this.active = false;    // the loaded scene has a 3-D view
    this.spatial = null;    // the worker's drawing data for it
    this.generation = 0;    // loads, so a late import does not show an old scene
    this.nodes = new Map(); // `${tree}:${id}` → [points (Float64Array), at, n]: tool curves not yet revealed
    this.path = null;       // {tool, frames, links, stride}: the smoothed path's, from the worker
    this.rawPath = null;    // the same for the raw path
    this.raw = false;       // the arm follows the raw path
    this.solved = null;     // {result, frames, rawFrames}: the result's animation frames, for the path panel
    this.scrub = null;      // link frames of the pose scrubbed to (www/ui/path3d.js), or null: animate
    this.ghosts = [];       // link frames of the path's ghosts
    /** @type {(solved: {result: any, frames: Float64Array, rawFrames: Float64Array} | null) => void} */
    this.onPath = () => {}; // the solved path is shown (or gone)
    this.showResult = false;
    this.dirty = false;
    this.error = '';
    this.manual = null;     // the arm posed by hand (www/ui/pose3d.js): {frames, colour, ghost}
    this.posing = false;    // posed since the run began: the path's animation waits for the next run
  }

  /** A scene was loaded: `spatial` (the `loaded` reply's, present when `caps.view3d`) or null. */
  async setScene(spatial, view3d) {
    const gen = ++this.generation;
    this.spatial = view3d && spatial ? spatial : null;
    this.manual = null;
    this.active = !!this.spatial;
    this.canvas.hidden = !this.active;
    this.clearRun();
    this.onActive();
    if (!this.active) return;
    try {
      if (!this.view) {
        const { View3D } = await import('../draw3d/view3d.js');
        if (gen !== this.generation) return;
        this.view ??= new View3D(this.canvas, this.palette);
        if (this.size) this.view.resize(...this.size);
      }
      if (gen !== this.generation) return;
      this.view.setScene(this.spatial);
      this.view.setManual(this.manual);
      if (this.showResult) this.finishRun(); // a result that came while the view was loading
      this.error = '';
    } catch (e) {
      this.error = String(e?.message || e);
      console.error(`3-D view: ${this.error}`);
    }
  }

  resize(w, h, dpr) {
    this.size = [w, h, dpr];
    this.view?.resize(w, h, dpr);
  }

  /** An events batch: keep its tool curves (`tree3d`: [tree, id, n, x, y, z…] per node). */
  takeEvents(msg) {
    const d = msg.tree3d;
    if (!this.active || !d) return;
    for (let at = 0; at + 2 < d.length;) {
      const n = d[at + 2] | 0;
      if (n < 1 || at + 3 + 3 * n > d.length) break;
      this.nodes.set(`${d[at]}:${d[at + 1]}`, [d, at + 3, n]);
      at += 3 + 3 * n;
    }
  }

  /** Records [from, to) were revealed: their nodes join the drawn trees. */
  drawRecords(from, to) {
    if (!this.active) return;
    for (let i = from; i < to; i++) {
      const r = this.store.record(i);
      if (r[0] !== EventKind.NODE_ADDED) continue;
      const key = `${r[1]}:${r[2]}`;
      const node = this.nodes.get(key);
      if (!node) continue;
      this.nodes.delete(key);
      this.view?.addNode(r[1], node[0], node[1], node[2]);
    }
  }

  /**
   * The arm posed by hand (link frames from the core, drawn in `colour`, the start as a ghost when
   * `ghost`), or null. Posing by hand (`byHand`: a slider moved, a pose loaded) stops the path's
   * animation until the next run; a pose kept across a load does not.
   * @param {{frames: Float64Array, colour: string, ghost: boolean} | null} manual
   * @param {boolean} byHand
   */
  setManual(manual, byHand) {
    this.manual = manual;
    if (!byHand) { this.view?.setManual(manual); return; }
    this.posing = true;
    this.poseIndex = -1;
    this.scrub = null;
    this.view?.setPose(null);
    this.view?.setManual(manual);
  }

  clearRun() {
    this.posing = false;
    this.nodes.clear();
    this.path = null;
    this.rawPath = null;
    this.solved = null;
    this.scrub = null;
    this.ghosts = [];
    this.showResult = false;
    this.poseIndex = -1;
    this.view?.clearRun();
    this.onPath(null);
  }

  /**
   * The result: the path's tool curve and poses (the worker's `path3d`, and `rawPath3d` for the
   * raw path), shown once finished; the animation frames (states) go to the path panel then.
   */
  setResult(result, frames, rawFrames, path3d, rawPath3d) {
    const solved = !!(this.active && result?.solved && path3d);
    this.path = solved ? path3d : null;
    this.rawPath = solved && rawPath3d ? rawPath3d : null;
    this.solved = solved ? { result, frames, rawFrames } : null;
  }

  /** The path the arm follows: the raw one when chosen (and sent), else the smoothed one. */
  get followed() { return this.raw && this.rawPath ? this.rawPath : this.path; }

  finishRun() {
    const p = this.followed;
    if (p && this.view) {
      this.view.setPath(p.tool, p === this.rawPath);
      this.view.setGhosts(this.ghosts);
      if (this.scrub) this.view.setPose(this.scrub);
    }
    if (this.solved) this.onPath(this.solved);
  }

  /** Follow the raw path (`raw`) or the smoothed one: its tool curve drawn, its poses animated. */
  setRaw(raw) {
    if (this.raw === !!raw) return;
    this.raw = !!raw;
    this.poseIndex = -1;
    if (this.showResult && this.followed) this.view?.setPath(this.followed.tool, this.followed === this.rawPath);
  }

  /**
   * The arm held at a pose along the path (link frames), or `null`: the animation goes on (also
   * after a pose set by hand: holding or playing the path is the user's choice too).
   */
  setScrub(frames) {
    this.scrub = frames;
    this.poseIndex = -1;
    this.posing = false;
    this.view?.setPose(frames);
  }

  /** The arm as see-through ghosts at these poses (link frames each). */
  setGhosts(list) {
    this.ghosts = list;
    this.view?.setGhosts(list);
  }

  /** The animation frame (of the followed path's `frames`) the arm is drawn at, or -1 (held, posed, none). */
  animatedFrame() {
    const p = this.followed;
    if (!p || this.scrub || this.posing || this.poseIndex < 0) return -1;
    return this.poseIndex * (p.stride || 1);
  }

  /** Each page frame: once solved, the arm at the path pose of the page's animation (`fps` poses a second). */
  render(time, fps) {
    const p = this.followed;
    if (!this.view || !this.showResult || !p || !p.count || this.posing || this.scrub) return;
    const { frames, count, links } = p;
    const k = Math.floor((time / 1000) * fps) % count;
    if (k === this.poseIndex) return;
    this.poseIndex = k;
    this.view.setPose(frames.subarray(k * links * 16, (k + 1) * links * 16));
  }
}

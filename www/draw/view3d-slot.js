// Where the 3-D view plugs into the page: a view of the lane (drawRecords, clearRun, setResult,
// like the C-space view) that loads www/draw3d/ with a dynamic import() only when the core says the
// loaded scene has a 3-D view (its `caps.view3d`: the robot's Spatial capability), so a 2-D
// scenario never fetches it. It keeps what the worker sends for the 3-D view (the trees' tool
// curves with each events batch, the path's tool curve and poses with the result) and hands each
// node to the view when its NODE_ADDED record is revealed, so the trees grow with the replay.
// The camera: a share link's is put in place once its scene is drawn (`setCamera`), an edit of
// the scene keeps the one the user turned to, and `onCamera` hears of each turn (the share link).
// Once solved it hands the path to www/ui/path3d.js (`onPath`), which scrubs along it (`setScrub`),
// asks for ghosts (`setGhosts`) and says which path the arm follows (`setRaw`: the top view's
// "robot follows the raw path").

import { EventKind } from '../run/events.js';

/** What stands in the 3-D view's place when the browser cannot draw it. */
export const NO_WEBGL2 = 'This browser has no WebGL2; the view from above still works.';

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
    this.solved = null;     // {result, frames, rawFrames, lengths, rawLengths}: the result's animation frames and the core's lengths along them, for the path panel
    this.scrub = null;      // link frames of the pose scrubbed to (www/ui/path3d.js), or null: animate
    this.ghosts = [];       // link frames of the path's ghosts
    /** @type {(solved: {result: any, frames: Float64Array, rawFrames: Float64Array, lengths: Float64Array, rawLengths?: Float64Array} | null) => void} */
    this.onPath = () => {}; // the solved path is shown (or gone)
    this.showResult = false;
    this.dirty = false;
    this.error = '';
    this.manual = null;     // the arm posed by hand (www/ui/pose3d.js): {frames, colour, ghost}
    this.posing = false;    // posed since the run began: the path's animation waits for the next run
    this.unavailable = false; // the browser has no WebGL2: a note stands in the view's place
    this.note = null;       // that note (a <p> after the canvas), made when needed
    this.pendingCamera = null; // a link's camera, put in place when its scene is drawn
    this.onCamera = () => {};  // the user turned or zoomed the camera (or a link's was put in place)
    this.step = null;       // the explain panel's step in 3-D (setStep)
  }

  /** A link's camera ({target, yaw, pitch, distance}) for the next scene loaded, or null: framed on the problem. */
  setCamera(camera) {
    this.pendingCamera = camera;
  }

  /** The camera when the user turned it or a link set it (null: framed on the problem, as a link need not say). */
  camera() {
    const c = this.active ? this.view?.camera : null;
    return c && c.touched ? c.state() : null;
  }

  /** Show the note instead of the canvas (no WebGL2), or the canvas. */
  showNote(text) {
    if (text && !this.note) {
      this.note = document.createElement('p');
      this.note.className = 'view3d-none';
      this.note.setAttribute('role', 'note');
      this.canvas.after(this.note);
      if (this.size) this.sizeNote();
    }
    if (this.note) {
      this.note.textContent = text || '';
      this.note.hidden = !text;
    }
    this.canvas.hidden = !this.active || !!text;
  }

  sizeNote() {
    if (!this.note || !this.size) return;
    this.note.style.width = `${this.size[0]}px`;
    this.note.style.height = `${this.size[1]}px`;
  }

  /** A scene was loaded: `spatial` (the `loaded` reply's, present when `caps.view3d`) or null. */
  async setScene(spatial, view3d, edited = false) {
    const gen = ++this.generation;
    // a link's camera, else (an edit of the scene) the one the user turned to
    const camera = this.pendingCamera ?? (edited ? this.camera() : null);
    this.pendingCamera = null;
    this.spatial = view3d && spatial ? spatial : null;
    this.manual = null;
    this.active = !!this.spatial;
    this.showNote(this.active && this.unavailable ? NO_WEBGL2 : '');
    this.clearRun();
    this.onActive();
    if (!this.active || this.unavailable) return;
    try {
      if (!this.view) {
        const [{ View3D }, { Actors3D }] = await Promise.all([import('../draw3d/view3d.js'), import('../draw3d/actors3d.js')]);
        if (gen !== this.generation) return;
        if (!this.view) {
          const view = new View3D(this.canvas, this.palette);
          const redraw = view.camera.onChange;
          view.camera.onChange = () => { redraw(); if (view.camera.touched) this.onCamera(); };
          view.actors = new Actors3D(view);
          this.view = view;
        }
        if (this.size) this.view.resize(...this.size);
      }
      if (gen !== this.generation) return;
      if (!camera) this.view.camera.touched = false; // framed on the new problem, and again on a resize
      this.view.setScene(this.spatial);
      if (camera) this.view.camera.setState(camera);
      this.view.setManual(this.manual);
      if (this.showResult) this.finishRun(); // a result that came while the view was loading
      this.error = '';
    } catch (e) {
      this.error = String(e?.message || e);
      if (e?.noWebGL2) {
        this.unavailable = true;
        this.showNote(NO_WEBGL2);
        return;
      }
      console.error(`3-D view: ${this.error}`);
    }
  }

  resize(w, h, dpr) {
    this.size = [w, h, dpr];
    this.view?.resize(w, h, dpr);
    this.sizeNote();
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

  /**
   * The explain panel's step in 3-D (draw3d/actors3d.js): ghosts of the sample and of the
   * configuration checked, the collision's arm and contact point; null: none.
   * @param {import('../draw3d/actors3d.js').Actors3DData | null} data
   */
  setStep(data) {
    this.step = data;
    this.view?.actors?.set(data);
  }

  clearRun() {
    this.step = null;
    this.view?.actors?.set(null);
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
    this.solved = solved ? { result, frames, rawFrames, lengths: path3d.lengths, rawLengths: rawPath3d?.lengths } : null;
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

  /**
   * For the frame-time measure (tests): `edges` straight edges of `steps` points each (`steps` - 1
   * segments), from a seeded walk round the start's tool point, added to the view's two trees.
   * Returns how many were added.
   */
  addTestEdges(edges, steps) {
    const v = this.view;
    if (!v || !v.start) return 0;
    const n = Math.max(2, Math.min(64, steps | 0));
    const count = Math.max(0, Math.min(1e6, edges | 0));
    const c = v.toolAt(v.start);
    let s = 12345;
    const rand = () => ((s = (Math.imul(s, 1103515245) + 12345) >>> 0) / 2 ** 32) - 0.5;
    const pts = new Float64Array(3 * n);
    for (let e = 0; e < count; e++) {
      const a = [c[0] + rand(), c[1] + rand(), c[2] + rand() * 0.6];
      const d = [rand() * 0.1, rand() * 0.1, rand() * 0.1];
      for (let k = 0; k < n; k++) for (let i = 0; i < 3; i++) pts[3 * k + i] = a[i] + (d[i] * k) / (n - 1);
      v.addNode(e & 1, pts, 0, n);
    }
    return count;
  }
}

/**
 * The 3-D view's hooks for the page tests (`window.planarium.view3d`): whether it is drawn, css px
 * of a world point with its camera, pixels, colour counts, and the 3-D panels' states.
 * @param {View3dSlot} slot
 * @param {{pose: {state: () => any}, boxes: {state: () => any}, path: {state: () => any, timelineAt: (s: number, rad: number) => any}}} panels
 */
export function view3dHooks(slot, panels) {
  return Object.freeze({
    ready: () => !!(slot.active && slot.view?.matrices),
    error: () => slot.error,
    toCanvas: (p) => slot.view?.toCanvas(p) ?? null,
    pixels: (x, y, r) => (slot.view ? [...slot.view.pixels(x, y, r)] : null),
    countColours: (colours, tol) => slot.view?.countColours(colours, tol) ?? null,
    viewProj: () => (slot.view?.matrices ? [...slot.view.matrices.viewProj] : null),
    /** Resolves with the requestAnimationFrame deltas (ms) of the next `n` frames the view draws while it turns. */
    orbitFrameTimes: (n) => slot.view?.orbitFrameTimes(n) ?? Promise.resolve([]),
    /** One whole frame's time (ms), the trees in full as when the camera rests. */
    fullFrameMs: () => slot.view?.fullFrameMs() ?? null,
    /** The faded trees from the backdrop's layer against drawn directly (draw3d/backdrop.js); how often the layer was drawn. */
    backdropAgreement: (tol) => slot.view?.backdropAgreement(tol) ?? null,
    backdropPainted: () => slot.view?.backdrop.painted ?? null,
    /** Whether the last frame drew the trees through a subset (the camera moving: draw3d/lod.js). */
    treesThinned: () => !!slot.view && slot.view.lod.thin,
    /** Add `edges` synthetic tree edges (straight, `steps` points each) round the tool: the frame-time measure's load. */
    loadEdges: (edges, steps) => slot.addTestEdges(edges, steps),
    /** Draw the explain panel's step (ghost arms, collision mark) or not, at once (tests compare the pixels). */
    showStep: (on) => { if (slot.view?.actors) { slot.view.actors.hidden = !on; slot.view.render(); } },
    /** The solved path's panel (path3d.js): what it shows, and css px in its timeline of a joint value at a length. */
    path: () => panels.path.state(),
    timelineAt: (s, rad) => panels.path.timelineAt(s, rad),
    /** The pose panel: {q (radians), status, collision, message}. */
    pose: () => panels.pose.state(),
    /**
     * The camera: {target, yaw, pitch, distance} as a link carries it, {framed: true} while framed
     * on the problem, and the orbit's raw {azimuth, elevation}.
     */
    camera: () => {
      const c = slot.view?.camera;
      return c ? { ...c.state(), framed: !c.touched, azimuth: c.azimuth, elevation: c.elevation } : null;
    },
    /** The scene boxes panel: {rows: [{values, error}], status}. */
    boxes: () => panels.boxes.state(),
  });
}

// The 3-D view of a spatial arm (report 001's Puma 560), drawn with the project's own WebGL2
// renderer (gl.js; no library): the arm's parts as flat-shaded meshes placed by the core's link
// frames (start pose in the start colour, the goal pose as a ghost in the goal colour, the path's
// poses animated once solved), the scene's 3-D obstacles (translucent, so the tool is seen through
// the wall; the trees and path are drawn over them), a floor grid and axes, the two trees as
// the tool sweeps them (each edge through its `delta` steps, in the trees' colours of the top view)
// and the path as the tool's curve (ghosts.js: thick, over everything; once solved the trees fade
// and go under the arm, which can be drawn as see-through ghosts along the path). An orbit camera
// (camera.js) opens framed on the problem: the start and goal tool points and the obstacles
// nearest them (the course's window).
//
// Every number drawn comes from the core through the worker (www/draw/view3d-slot.js hands them
// over): meshes once per scenario (`Scene.spatial_json`), link frames (`Scene.link_frames`), the
// trees' tool curves (`Run.drain_tool_tree`). Nothing here computes kinematics.

import { programs, meshBuffers, LineBuffer, identity, transformPoint, project, rgb, sub, dot } from './gl.js';
import { OrbitCamera } from './camera.js';
import { PathCurve, drawGhosts } from './ghosts.js';
import { TreeLod } from './lod.js';
import { Backdrop, premultipliedBlend } from './backdrop.js';

/** Parts of the last link (the tool's) are drawn this much darker, so the tool stands out. */
const TOOL_SHADE = 0.6;
/** The trees' opacity once a path is shown. */
const TREE_FADED = 0.02;
const GRID = '#c3c8cf';
/** @type {Array<[string, number[]]>} the axes' colours and directions (x red, y green, z blue) */
const AXES = [['#d62728', [1, 0, 0]], ['#2ca02c', [0, 1, 0]], ['#1f77b4', [0, 0, 1]]];

export class View3D {
  /** @param {HTMLCanvasElement} canvas @param {Record<string, any>} palette */
  constructor(canvas, palette) {
    this.canvas = canvas;
    this.palette = palette;
    const gl = canvas.getContext('webgl2', { antialias: true, preserveDrawingBuffer: true });
    if (!gl) throw Object.assign(new Error('this browser has no WebGL2: the 3-D view is not available'), { noWebGL2: true });
    this.gl = gl;
    this.progs = programs(gl);
    // While the camera moves, the trees are drawn through a subset of their segments (lod.js).
    this.lod = new TreeLod(gl, this.progs.line);
    // Once solved, the faded trees drawn once into a layer reused while the camera rests (backdrop.js).
    this.backdrop = new Backdrop(gl);
    this.camera = new OrbitCamera(canvas, () => {
      this.lod.moved(() => this.requestRender());
      this.requestRender();
    });
    this.parts = [];      // {link, buffers, tool}
    this.obstacles = [];  // buffers
    this.trees = [new LineBuffer(gl, this.progs.line), new LineBuffer(gl, this.progs.line)];
    this.nodes = [new LineBuffer(gl, this.progs.line), new LineBuffer(gl, this.progs.line)];
    this.grid = new LineBuffer(gl, this.progs.line);
    this.axes = AXES.map(() => new LineBuffer(gl, this.progs.line));
    this.path = new PathCurve(gl, this.progs.line); // the solved path's tool curve (ghosts.js)
    this.ghosts = [];     // link frames of the path's ghosts (ghosts.js), see-through
    this.start = null;    // link frames (Float64Array, 16 a link)
    this.goal = null;
    this.pose = null;     // the animated path pose's link frames, or null
    this.manual = null;   // the pose set by hand (www/ui/pose3d.js): {frames, colour, ghost}, or null
    this.size = [1, 1, 1];
    this.pending = false;
    this.backdropOff = false; // tests: the faded trees drawn directly, as without backdrop.js
    this.treesHidden = false; // tests: no trees drawn (faded or not)
    this.onFrame = null;  // (time) => void, after each frame drawn (tests and the frame-time log)
    /** @type {import('./actors3d.js').Actors3D | null} the explain panel's actors (actors3d.js), drawn by its hooks */
    this.actors = null;
  }

  /**
   * The scenario's drawing: `spatial` as the worker sends it ({links, tool, parts, obstacles} and
   * the start and goal link frames).
   */
  setScene(spatial) {
    const gl = this.gl;
    for (const p of [...this.parts, ...this.obstacles]) p.buffers.buffers.forEach((b) => gl.deleteBuffer(b));
    const { mesh } = this.progs;
    const last = spatial.links - 1;
    this.parts = spatial.parts.map((p) => ({ link: p.link, tool: p.link === last, buffers: meshBuffers(gl, mesh, p.vertices, p.triangles) }));
    this.obstacles = spatial.obstacles.map((o) => ({ buffers: meshBuffers(gl, mesh, o.vertices, o.triangles), box: boxOf(o.vertices) }));
    this.tool = spatial.tool;
    this.start = spatial.start;
    this.goal = spatial.goal && spatial.goal.length ? spatial.goal : null;
    this.manual = null;
    this.clearRun();
    this.buildFloor(spatial);
    this.frameProblem();
  }

  /** The tool centre point at link frames `frames` (the last link's frame applied to the tool). */
  toolAt(frames) {
    return transformPoint(frames.subarray(frames.length - 16), this.tool);
  }

  /** A floor grid under everything (at the lowest point of the obstacles and the arm's base) and axes at the origin. */
  buildFloor(spatial) {
    const pts = [];
    for (const o of spatial.obstacles) for (let i = 0; i < o.vertices.length; i += 3) pts.push(o.vertices.slice(i, i + 3));
    const base = spatial.start.subarray(0, 16);
    for (const p of spatial.parts) {
      if (p.link !== 0) continue;
      for (let i = 0; i < p.vertices.length; i += 3) pts.push(transformPoint(base, p.vertices, [0, 0, 0], i));
    }
    pts.push(this.toolAt(spatial.start));
    if (this.goal) pts.push(this.toolAt(this.goal));
    const lo = [0, 1, 2].map((k) => Math.min(...pts.map((p) => p[k])));
    const hi = [0, 1, 2].map((k) => Math.max(...pts.map((p) => p[k])));
    this.size = hi.map((h, k) => h - lo[k]);
    const span = Math.max(this.size[0], this.size[1], 0.5);
    const step = 10 ** Math.floor(Math.log10(span / 4));
    const z = lo[2];
    const [x0, x1] = [Math.floor((lo[0] - span * 0.25) / step) * step, Math.ceil((hi[0] + span * 0.25) / step) * step];
    const [y0, y1] = [Math.floor((lo[1] - span * 0.25) / step) * step, Math.ceil((hi[1] + span * 0.25) / step) * step];
    this.grid.clear();
    const lines = [];
    for (let x = x0, i = 0; x <= x1 + step / 2 && i < 400; x += step, i++) lines.push(x, y0, z, x, y1, z);
    for (let y = y0, i = 0; y <= y1 + step / 2 && i < 400; y += step, i++) lines.push(x0, y, z, x1, y, z);
    this.grid.push(lines);
    const a = step * 2;
    this.axes.forEach((b, k) => { b.clear(); b.push([0, 0, z, ...AXES[k][1].map((d, i) => d * a + (i === 2 ? z : 0))]); });
  }

  /**
   * Open framed on the problem: the box around the start and goal tool points and the obstacles
   * nearest either (within a third of the scene's size: the course's window round the tool).
   */
  frameProblem() {
    const pts = [this.toolAt(this.start)];
    if (this.goal) pts.push(this.toolAt(this.goal));
    const reach = Math.max(...this.size) / 3;
    for (const o of this.obstacles) {
      if (pts.slice(0, 2).some((p) => boxDistance(o.box, p) <= reach)) pts.push(o.box.lo, o.box.hi);
    }
    const lo = [0, 1, 2].map((k) => Math.min(...pts.map((p) => p[k])));
    const hi = [0, 1, 2].map((k) => Math.max(...pts.map((p) => p[k])));
    const centre = lo.map((l, k) => (l + hi[k]) / 2);
    const radius = Math.max(0.05, Math.hypot(...sub(hi, lo)) / 2);
    this.camera.frame(centre, radius);
  }

  /** Forget the run's trees and path. */
  clearRun() {
    for (const b of [...this.trees, ...this.nodes, this.path]) b.clear();
    this.lod.clear();
    this.backdrop.invalidate();
    this.pose = null;
    this.ghosts = [];
    this.requestRender();
  }

  /**
   * A node added to tree `tree`: its edge as the tool sweeps it, `n` points (flat x, y, z) from
   * `at` in `pts`, the node's own last.
   */
  addNode(tree, pts, at, n) {
    const t = tree === 1 ? 1 : 0;
    for (let k = 0; k + 1 < n; k++) this.trees[t].push(pts, at + 3 * k, at + 3 * k + 6);
    this.nodes[t].push(pts, at + 3 * (n - 1), at + 3 * n);
    this.backdrop.invalidate();
    this.requestRender();
  }

  /** The solved path: the tool's curve (flat x, y, z…); `raw`: the raw path's (its colour in the top view). */
  setPath(curve, raw = false) {
    this.path.set(curve, raw);
    this.requestRender();
  }

  /** The arm as see-through ghosts at these poses along the path (link frames each), or none. */
  setGhosts(list) {
    this.ghosts = list;
    this.requestRender();
  }

  /** The arm drawn at a path pose (link frames), or `null`: at the start. */
  setPose(frames) {
    if (frames === this.pose) return;
    this.pose = frames;
    this.requestRender();
  }

  /**
   * The arm posed by hand: its link frames, drawn in `colour` ('#rrggbb'), with the start as a
   * ghost when `ghost`; `null`: back to the start. A path pose (`setPose`) is drawn over it.
   * @param {{frames: Float64Array, colour: string, ghost: boolean} | null} manual
   */
  setManual(manual) {
    this.manual = manual;
    this.requestRender();
  }

  resize(w, h, dpr) {
    this.canvas.style.width = `${w}px`;
    this.canvas.style.height = `${h}px`;
    this.canvas.width = Math.max(1, Math.round(w * dpr));
    this.canvas.height = Math.max(1, Math.round(h * dpr));
    const was = this.camera.aspect;
    this.camera.aspect = w / Math.max(1, h);
    if (was !== this.camera.aspect && this.camera.home && !this.camera.touched) this.frameProblem();
    this.requestRender();
  }

  requestRender() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame((t) => { this.pending = false; this.render(); this.lod.drawn(t); this.onFrame?.(t); });
  }

  /** Draw everything now. */
  render() {
    const gl = this.gl;
    const { mesh, line } = this.progs;
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    const [br, bg, bb] = rgb(this.palette.background);
    gl.clearColor(br, bg, bb, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    this.lod.frame();
    const { view, proj } = this.camera.matrices();
    this.matrices = this.camera.matrices();
    // Lines: the floor, the axes, the trees, the path.
    gl.useProgram(line.p);
    gl.uniformMatrix4fv(line.u.view, false, new Float32Array(view));
    gl.uniformMatrix4fv(line.u.proj, false, new Float32Array(proj));
    gl.uniform1f(line.u.pointSize, 3 * (window.devicePixelRatio || 1));
    gl.uniform1f(line.u.alpha, 1);
    /** @param {LineBuffer} buf @param {string} colour @param {number} [mode] @param {number} [alpha] */
    const lines = (buf, colour, mode = gl.LINES, alpha = 1) => {
      if (!buf.length) return;
      buf.upload();
      gl.uniform3fv(line.u.colour, rgb(colour));
      gl.uniform1f(line.u.alpha, alpha);
      gl.bindVertexArray(buf.vao);
      gl.drawArrays(mode, 0, buf.length);
    };
    lines(this.grid, GRID);
    this.axes.forEach((b, k) => lines(b, AXES[k][0]));
    const P = this.palette;
    // Once a path is shown the trees fade (a solved course run has some 14,000 nodes: they would
    // bury the arm) and go under everything else: drawn first, writing no depth.
    const faded = this.path.length > 0 && !this.treesHidden;
    if (faded && (this.lod.thin || this.backdropOff)) this.drawTrees(lines, TREE_FADED);
    else if (faded) this.backdrop.draw(this.backdropKey(view, proj), () => { gl.useProgram(line.p); this.drawTrees(lines, TREE_FADED, true); });
    // The arm: at the animated path pose once solved, else as posed by hand, else at the start;
    // the goal as a ghost (and the start, when the arm is posed elsewhere).
    gl.useProgram(mesh.p);
    gl.uniformMatrix4fv(mesh.u.view, false, new Float32Array(view));
    gl.uniformMatrix4fv(mesh.u.proj, false, new Float32Array(proj));
    const arm = (frames, colour, alpha) => {
      if (!frames) return;
      for (const p of this.parts) {
        const c = rgb(colour).map((v) => (p.tool ? v * TOOL_SHADE : v));
        this.drawMesh(p.buffers, frames.subarray(p.link * 16, p.link * 16 + 16), c, alpha);
      }
    };
    const hand = !this.pose && this.manual;
    arm(this.pose || (hand ? hand.frames : this.start), this.pose ? P.robotT : hand ? hand.colour : P.start, 1);
    // Translucent last, without writing depth: the goal's ghost and the obstacles (the tool is seen through the wall).
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    gl.depthMask(false);
    arm(this.goal, P.goal, 0.35);
    if (hand && hand.ghost) arm(this.start, P.start, 0.35);
    drawGhosts(this, this.ghosts, P.robotT);
    if (!this.pose) this.actors?.drawGhosts();
    for (const o of this.obstacles) this.drawMesh(o.buffers, IDENTITY, rgb(P.obstacle), 0.55);
    // While growing, the trees over the translucent walls (which write no depth), so a branch
    // behind the wall keeps its tree's colour; the opaque arm still hides what is behind it.
    gl.useProgram(line.p);
    gl.disable(gl.BLEND);
    if (!faded && !this.treesHidden) this.drawTrees(lines, 1);
    gl.depthMask(true);
    gl.disable(gl.DEPTH_TEST);
    // The path, the tool's curve, over everything (ghosts.js).
    this.path.draw(gl, line, P, lines);
    if (!this.pose) this.actors?.drawMarks(lines);
    gl.bindVertexArray(null);
  }

  /**
   * The trees' edges and nodes at opacity `a` (< 1: blended, no depth written; `premultiplied`:
   * into the backdrop's layer), line program in use.
   */
  drawTrees(lines, a, premultiplied = false) {
    const gl = this.gl;
    const P = this.palette;
    if (a < 1) {
      gl.enable(gl.BLEND);
      if (premultiplied) premultipliedBlend(gl);
      else gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
      gl.depthMask(false);
    }
    const [e0, e1] = this.lod.edges(this.trees);
    lines(e0, P.tree0, gl.LINES, a);
    lines(e1, P.tree1, gl.LINES, a);
    if (this.lod.points(this.nodes[0].length)) lines(this.nodes[0], P.tree0, gl.POINTS, a);
    if (this.lod.points(this.nodes[1].length)) lines(this.nodes[1], P.tree1, gl.POINTS, a);
    gl.depthMask(true);
    gl.disable(gl.BLEND);
  }

  /** What the backdrop's layer depends on: the camera, the canvas, the trees and their colours. */
  backdropKey(view, proj) {
    const P = this.palette;
    const sizes = [...this.trees, ...this.nodes].map((b) => b.length);
    return `${this.canvas.width}x${this.canvas.height} ${view.join()} ${proj.join()} ${sizes.join()} ${P.tree0} ${P.tree1} ${window.devicePixelRatio || 1}`;
  }

  drawMesh(buffers, model, colour, alpha) {
    const gl = this.gl;
    const { mesh } = this.progs;
    gl.uniformMatrix4fv(mesh.u.model, false, new Float32Array(model));
    gl.uniform3fv(mesh.u.colour, colour);
    gl.uniform1f(mesh.u.alpha, alpha);
    gl.bindVertexArray(buffers.vao);
    gl.drawArrays(gl.TRIANGLES, 0, buffers.count);
  }

  // ---- For tests (window.planarium.view3d) ----

  /**
   * Turn the camera a little every animation frame for `n` frames, and resolve with the
   * requestAnimationFrame deltas (ms): the frame time while orbiting. Each turn asks for one frame
   * (`requestRender`), as a drag does; drawing here as well drew every frame twice.
   */
  orbitFrameTimes(n) {
    return new Promise((resolve) => {
      const times = [];
      let last = null;
      const step = (t) => {
        if (last !== null) times.push(t - last);
        last = t;
        if (times.length >= n) { resolve(times); return; }
        this.camera.rotate(4, 0);
        requestAnimationFrame(step);
      };
      requestAnimationFrame(step);
    });
  }

  /**
   * One whole frame drawn (the trees in full, as when the camera rests) and waited for (a pixel
   * read back): its time in ms.
   */
  fullFrameMs() {
    const [off, changed] = [this.lod.off, this.lod.changed];
    this.lod.off = true;
    this.backdrop.invalidate();
    const t0 = performance.now();
    this.render();
    this.gl.readPixels(0, 0, 1, 1, this.gl.RGBA, this.gl.UNSIGNED_BYTE, new Uint8Array(4));
    const ms = performance.now() - t0;
    [this.lod.off, this.lod.changed] = [off, changed];
    return ms;
  }

  /**
   * The faded trees laid from the backdrop's layer against drawn directly (each frame read back):
   * how many pixels differ by more than `tol` (summed over red, green and blue), how many the trees
   * change at all (against a frame without them), the largest difference, and the sums of what
   * the trees change either way.
   */
  backdropAgreement(tol) {
    const gl = this.gl;
    const frame = (off, hidden) => {
      [this.backdropOff, this.treesHidden] = [off, hidden];
      this.lod.off = true;
      this.render();
      const px = new Uint8Array(this.canvas.width * this.canvas.height * 4);
      gl.readPixels(0, 0, this.canvas.width, this.canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, px);
      return px;
    };
    const off = this.lod.off;
    const [layer, direct, none] = [frame(false, false), frame(true, false), frame(false, true)];
    [this.backdropOff, this.treesHidden, this.lod.off] = [false, false, off];
    this.render(); // the canvas as it was, trees and all
    const diff = (a, b, i) => Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]);
    let differ = 0, trees = 0, most = 0, inkLayer = 0, inkDirect = 0;
    for (let i = 0; i < layer.length; i += 4) {
      const d = diff(layer, direct, i);
      most = Math.max(most, d);
      if (d > tol) differ++;
      if (diff(direct, none, i) > 0) trees++;
      inkLayer += diff(layer, none, i);
      inkDirect += diff(direct, none, i);
    }
    return { differ, trees, most, inkLayer, inkDirect };
  }

  /** Css px within the canvas of world point `p`, with the camera of the last frame drawn. */
  toCanvas(p) {
    const { viewProj } = this.matrices || this.camera.matrices();
    const [x, y, , w] = project(viewProj, p);
    if (!(w > 0)) return null;
    return [((x + 1) / 2) * this.canvas.clientWidth, ((1 - y) / 2) * this.canvas.clientHeight];
  }

  /** The pixels (device px, RGBA) of the square of side 2r + 1 around css px (x, y). */
  pixels(x, y, r) {
    const gl = this.gl;
    const dpr = this.canvas.width / Math.max(1, this.canvas.clientWidth);
    const [cx, cy] = [Math.round(x * dpr), Math.round(this.canvas.height - y * dpr)];
    const side = 2 * r + 1;
    const out = new Uint8Array(side * side * 4);
    gl.readPixels(cx - r, cy - r, side, side, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return out;
  }

  /** How many pixels of the whole canvas are within `tol` of each colour ('#rrggbb'). */
  countColours(colours, tol = 6) {
    const gl = this.gl;
    const [w, h] = [this.canvas.width, this.canvas.height];
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const want = colours.map((c) => rgb(c).map((v) => v * 255));
    const counts = want.map(() => 0);
    for (let i = 0; i < px.length; i += 4) {
      want.forEach(([r, g, b], k) => {
        if (Math.abs(px[i] - r) <= tol && Math.abs(px[i + 1] - g) <= tol && Math.abs(px[i + 2] - b) <= tol) counts[k]++;
      });
    }
    return counts;
  }
}

const IDENTITY = identity();

/** The box around flat points. */
function boxOf(v) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < v.length; i += 3) {
    for (let k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], v[i + k]); hi[k] = Math.max(hi[k], v[i + k]); }
  }
  return { lo, hi };
}

/** The distance from point `p` to box `b` (0 inside). */
function boxDistance(b, p) {
  const d = [0, 1, 2].map((k) => Math.max(b.lo[k] - p[k], 0, p[k] - b.hi[k]));
  return Math.sqrt(dot(d, d));
}

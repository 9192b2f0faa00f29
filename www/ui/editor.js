// Setting the start and goal: drag them on the canvas (point: the dot; rigid: the footprint moves,
// shift-drag or the round handle turns it), or, for an arm, one slider per joint in the
// "Start / Goal" panel. While dragging, the view draws a preview; on release the edited scenario
// is handed to `onCommit(scenario)`, which reloads it through the worker (the core validates it: an
// invalid start or goal is reported there, and dragging back fixes it).

import { el } from './dom.js';
import { pointInPolygon } from '../draw/transform.js';
import { dragsHeading, dragsPosition, posedByJoints } from '../draw/capabilities.js';

const HIT = 10; // css px: how near a start/goal dot or handle a press must be

/** Round `v` to a step that keeps about four digits below the scene's size. */
function tidy(v, extent) {
  const step = 10 ** (Math.floor(Math.log10(Math.max(extent, 1e-9))) - 4);
  return Number((Math.round(v / step) * step).toFixed(12));
}

export class Editor {
  /**
   * `root`: the panel's container; `onPreview(which, state)`: a start/goal is being changed;
   * `onCommit(scenario)`: it changed.
   */
  constructor({ canvas, view, root, palette, onPreview, onCommit }) {
    this.canvas = canvas;
    this.view = view;
    this.root = root;
    this.palette = palette;
    this.onPreview = onPreview;
    this.onCommit = onCommit;
    /** @type {(() => void) | null} set by the obstacle editor: records its undo history */
    this.beforeCommit = null;
    this.scenario = null; // the scenario being edited (the last one sent to the worker)
    this.original = null; // as opened, for "Restore"
    this.stale = false;   // another scenario is being loaded: ignore edits of this one
    this.drag = null;
    this.sliders = [];
    /** @type {((x: number, y: number) => number[]) | null} where a dragged start/goal lands (set by the obstacle editor) */
    this.place = null;
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', () => this.cancel());
    root.classList.add('endpoints');
    this.render();
  }

  // The editor's modes follow the robot kind's draggable pose (the core's robot kinds, capabilities.js):
  // a position to drag, with a heading to turn, or joint angles on sliders.
  get draggable() { return dragsPosition(this.scenario?.robot); }
  get turns() { return dragsHeading(this.scenario?.robot); }
  get jointed() { return posedByJoints(this.scenario?.robot); }

  /** Another scenario (not an edit of this one) was sent to the worker. */
  loading() { this.stale = true; this.cancel(); }

  /** A scenario loaded (`edited`: it came from this editor) or null (nothing valid). */
  setScenario(scenario, space, edited) {
    this.stale = false;
    if (!scenario) {
      this.scenario = this.original = null;
      this.render();
      return;
    }
    this.scenario = structuredClone(scenario);
    if (!edited || !this.original) this.original = structuredClone(scenario);
    this.space = space || null;
    if (edited && this.sliders.length) this.syncSliders(); // keep the sliders (and their focus)
    else this.render();
  }

  syncSliders() {
    for (const { which, i, input, out } of this.sliders) {
      const v = this.scenario[which]?.[i];
      if (v === undefined) continue;
      input.value = String(v);
      out.textContent = v.toFixed(2);
    }
    if (this.restore) this.restore.disabled = !this.changed();
  }

  changed() {
    const a = this.scenario, b = this.original;
    return !!a && !!b && JSON.stringify([a.start, a.goal]) !== JSON.stringify([b.start, b.goal]);
  }

  render() {
    this.sliders = [];
    this.restore = null;
    this.canvas.classList.toggle('editable', !!this.scenario && this.draggable);
    this.view.editable = !!this.scenario && this.turns;
    this.view.dirty = true;
    if (!this.scenario) {
      this.root.replaceChildren(el('p', { className: 'hint', text: 'No scenario loaded.' }));
      return;
    }
    const parts = [];
    if (this.draggable) {
      parts.push(el('p', { className: 'hint', text: this.turns
        ? 'Drag the start or goal on the canvas to move it; shift-drag it, or drag its round handle, to turn it.'
        : 'Drag the start or goal dot on the canvas.' }));
    } else if (this.jointed) {
      for (const which of ['start', 'goal']) if (this.scenario[which]) parts.push(this.jointSliders(which));
      parts.push(el('p', { className: 'hint', text: 'Joint angles in radians, each relative to the previous link.' }));
    } else {
      parts.push(el('p', { className: 'hint', text: 'The start and goal of this robot come from the scenario file.' }));
    }
    if (this.draggable || this.jointed) {
      this.restore = el('button', { id: 'restore-endpoints', type: 'button', text: 'Restore start and goal' });
      this.restore.disabled = !this.changed();
      this.restore.addEventListener('click', () => {
        if (!this.original || this.stale) return;
        this.scenario.start = structuredClone(this.original.start);
        this.scenario.goal = structuredClone(this.original.goal);
        this.commit();
        this.syncSliders();
        for (const which of ['start', 'goal']) if (this.scenario[which]) this.onPreview(which, this.scenario[which]);
      });
      parts.push(el('div', { className: 'row' }, this.restore));
    }
    this.root.replaceChildren(...parts);
  }

  jointSliders(which) {
    const q = this.scenario[which];
    // a planar arm lists its limits; a spatial arm gives them per joint row
    const limits = this.scenario.robot.limits ?? this.scenario.robot.joints?.map((j) => j.limits);
    const set = el('fieldset', { id: `${which}-joints` });
    const sw = el('span', { className: 'swatch box', 'aria-hidden': 'true' });
    sw.style.setProperty('--c', this.palette[which]);
    const title = which === 'start' ? 'Start' : 'Goal';
    // a long chain's sliders fold away
    const body = q.length > 4 ? el('details', {}, el('summary', { text: `${q.length} joint angles` })) : set;
    set.append(el('legend', {}, sw, title));
    if (body !== set) set.append(body);
    q.forEach((v, i) => {
      const lim = Array.isArray(limits) ? limits[i] : null;
      const dim = this.space && this.space.length === q.length ? this.space[i] : null;
      const [lo, hi] = lim || (dim ? [dim.lo, dim.hi] : [-Math.PI, Math.PI]);
      const id = `${which}-q${i + 1}`;
      const input = el('input', { id, type: 'range', min: String(lo), max: String(hi), step: 'any', value: String(v) });
      const out = el('output', { htmlFor: id, text: v.toFixed(2) });
      input.addEventListener('input', () => {
        if (this.stale) return;
        // rounded, but never past a limit (a joint at its limit rounded up would leave it)
        this.scenario[which][i] = Math.min(hi, Math.max(lo, tidy(Number(input.value), 1)));
        out.textContent = Number(input.value).toFixed(2);
        this.onPreview(which, this.scenario[which]);
      });
      input.addEventListener('change', () => { if (!this.stale) this.commit(); });
      this.sliders.push({ which, i, input, out });
      body.append(el('label', { className: 'joint', htmlFor: id }, el('span', { text: `q${i + 1}` }), input, out));
    });
    return set;
  }

  /**
   * Set the start or goal to joint angles `q` (the 3-D view's pose panel, www/ui/pose3d.js), as a
   * slider's commit does: the edited scenario goes to the worker. False when there is no such
   * endpoint to edit now (no scenario, another one loading, a robot not posed by joints).
   * @param {'start' | 'goal'} which
   * @param {number[]} q
   */
  setEndpoint(which, q) {
    if (!this.scenario || this.stale || !this.jointed || !Array.isArray(this.scenario[which])) return false;
    if (this.scenario[which].length !== q.length) return false;
    this.scenario[which] = q.slice();
    this.syncSliders();
    this.onPreview(which, this.scenario[which]);
    this.commit();
    return true;
  }

  commit() {
    if (this.restore) this.restore.disabled = !this.changed();
    this.beforeCommit?.(); // the obstacle editor's undo history
    this.onCommit(structuredClone(this.scenario));
  }

  // Dragging on the canvas

  devicePoint(e) {
    const L = this.view.layout;
    return { x: e.offsetX * L.dpr, y: e.offsetY * L.dpr };
  }

  /** What a press at device point p grabs: {which, mode: 'move' | 'turn' | 'handle'} or null. */
  hit(p, shift) {
    const L = this.view.layout;
    const whiches = ['goal', 'start'].filter((w) => this.scenario[w]);
    for (const which of whiches) {
      const h = this.view.handlePoint(which);
      if (h && Math.hypot(p.x - h.x, p.y - h.y) <= L.px(HIT)) return { which, mode: 'handle' };
    }
    const wx = L.wx(p.x), wy = L.wy(p.y);
    for (const which of whiches) {
      const q = this.view.stateOf(which);
      const near = Math.hypot(p.x - L.sx(q[0]), p.y - L.sy(q[1])) <= L.px(HIT);
      const inside = this.turns && pointInPolygon(wx, wy, rigidOutline(this.scenario.robot, q));
      if (near || inside) return { which, mode: shift && this.turns ? 'turn' : 'move' };
    }
    return null;
  }

  down(e) {
    if (!this.scenario || !this.draggable || !this.view.layout || e.button !== 0 || this.stale) return;
    const p = this.devicePoint(e);
    const h = this.hit(p, e.shiftKey);
    if (!h) return;
    e.preventDefault();
    const L = this.view.layout;
    const q0 = Array.from(this.view.stateOf(h.which));
    this.drag = { ...h, q0, wx: L.wx(p.x), wy: L.wy(p.y), moved: false };
    this.canvas.setPointerCapture(e.pointerId);
    this.canvas.classList.add('grabbing');
  }

  move(e) {
    if (!this.drag) {
      if (this.scenario && this.draggable && this.view.layout && !this.stale) {
        this.canvas.classList.toggle('grab', !!this.hit(this.devicePoint(e), e.shiftKey));
      }
      return;
    }
    const L = this.view.layout;
    const p = this.devicePoint(e);
    const wx = L.wx(p.x), wy = L.wy(p.y);
    const { q0 } = this.drag;
    const [x0, y0, x1, y1] = this.scenario.bounds;
    const extent = Math.max(x1 - x0, y1 - y0);
    const q = q0.slice();
    if (this.drag.mode === 'move') {
      const x = q0[0] + wx - this.drag.wx, y = q0[1] + wy - this.drag.wy;
      // on the grid when the obstacle editor snaps (`place`), else tidied; then kept in the bounds
      const [px, py] = this.place ? this.place(x, y) : [tidy(x, extent), tidy(y, extent)];
      q[0] = Math.min(x1, Math.max(x0, px));
      q[1] = Math.min(y1, Math.max(y0, py));
    } else {
      const a = Math.atan2(wy - q0[1], wx - q0[0]);
      const turn = this.drag.mode === 'handle' ? a : q0[2] + a - Math.atan2(this.drag.wy - q0[1], this.drag.wx - q0[0]);
      q[2] = tidy(Math.atan2(Math.sin(turn), Math.cos(turn)), 1);
    }
    this.drag.moved = true;
    this.scenario[this.drag.which] = q;
    this.onPreview(this.drag.which, q);
  }

  up(e) {
    if (!this.drag) return;
    const { moved } = this.drag;
    this.drag = null;
    this.canvas.classList.remove('grabbing');
    if (this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
    if (moved && !this.stale) this.commit();
  }

  cancel() {
    if (!this.drag) return;
    this.scenario[this.drag.which] = this.drag.q0;
    this.onPreview(this.drag.which, this.drag.q0);
    this.drag = null;
    this.canvas.classList.remove('grabbing');
  }
}

function rigidOutline(robot, q) {
  const c = Math.cos(q[2]), s = Math.sin(q[2]);
  return robot.footprint.flatMap(([u, v]) => [q[0] + c * u - s * v, q[1] + s * u + c * v]);
}

// Posing a spatial arm by hand (report 001's Puma 560), under the 3-D view: one slider a joint,
// within the joint's limits (the core's planning space), its value in degrees and radians; the arm
// drawn at once at that pose in the 3-D view and the panel says whether it is free or what meets
// what (the core's `Scene.collision`, "link4 meets the slab"); the arm turns red when it collides.
// "From start" / "From goal" load those poses; "Set as start" / "Set as goal" edit the scenario
// through the Start / Goal editor (ui/editor.js: the edit is sent to the worker, which validates
// it), refused with a message when the pose collides.
//
// The panel appears only for a scene whose capabilities say `view3d` (the robot's Spatial
// capability, decided by the core). For the pose to follow the slider within the same frame, the
// panel keeps its own copy of the core on the page's thread (the wasm module imported only then)
// and its own `Scene` of the loaded scenario: `link_frames(q)` and `collision(q)` are pure
// functions of the scenario, so they agree with the worker's. Text goes in with textContent only.

import { el } from './dom.js';

/** One slider step: a degree. */
const STEP = Math.PI / 180;

/** A degree value as shown: whole degrees when it is one, else one decimal. */
function degrees(rad) {
  const d = (rad * 180) / Math.PI;
  return `${Number(d.toFixed(Math.abs(d - Math.round(d)) < 0.05 ? 0 : 1))}°`;
}

/** The value shown and read out for an angle: "90° (1.571 rad)". */
export function angleText(rad) {
  return `${degrees(rad)} (${rad.toFixed(3)} rad)`;
}

let core = null; // the core's module on this thread, once imported

/** The core's wasm module on the page's thread (imported once, shared with ui/boxes3d.js). */
export async function loadCore() {
  core ??= import('../pkg/planarium.js').then(async (m) => { await m.default(); return m; });
  return core;
}

export class PosePanel {
  /**
   * @param {{root: HTMLElement, slot: import('../draw/view3d-slot.js').View3dSlot,
   *   editor: import('./editor.js').Editor, palette: Record<string, any>}} options
   */
  constructor({ root, slot, editor, palette }) {
    this.root = root;
    this.slot = slot;
    this.editor = editor;
    this.palette = palette;
    this.scene = null;     // the core's Scene of the loaded scenario (this thread's copy)
    this.scenario = null;
    this.q = [];           // the pose, radians
    this.limits = [];      // [lo, hi] a joint
    this.sliders = [];     // {input, out}
    this.goalButtons = []; // From goal, Set as goal
    /** @type {HTMLElement | null} free, or what collides */
    this.status = null;
    /** @type {HTMLElement | null} what Set as start / goal did */
    this.message = null;
    this.generation = 0;
    this.collision = '';
    this.error = '';
    root.hidden = true;
  }

  /**
   * A scene loaded: its normalised `scenario`, the planning space `space` ([{lo, hi}] a joint),
   * the core's `caps`, `edited` (an edit of the same scenario: the pose stays).
   */
  async setScene(scenario, space, caps, edited) {
    const gen = ++this.generation;
    const on = !!(caps?.view3d && scenario && Array.isArray(scenario.start) && Array.isArray(space) && space.length === scenario.start.length);
    this.root.hidden = !on;
    this.scene?.free();
    this.scene = null;
    if (!on) { this.scenario = null; return; }
    const keep = edited && this.scenario && this.q.length === scenario.start.length;
    this.scenario = scenario;
    this.limits = space.map((d) => [d.lo, d.hi]);
    if (!keep) this.q = scenario.start.slice();
    this.q = this.q.map((v, i) => Math.min(this.limits[i][1], Math.max(this.limits[i][0], v)));
    try {
      const m = await loadCore();
      if (gen !== this.generation) return;
      this.scene = new m.Scene(JSON.stringify(scenario));
      this.error = '';
    } catch (e) {
      if (gen !== this.generation) return;
      this.error = String(e?.message || e);
    }
    // an edit keeps the panel (and the focus on its button or slider); only the goal's buttons follow
    if (!keep || this.sliders.length !== this.q.length) this.build();
    else this.syncButtons();
    this.pose();
  }

  build() {
    const n = this.q.length;
    this.sliders = [];
    const grid = el('div', { className: 'pose-joints' });
    for (let i = 0; i < n; i++) {
      const [lo, hi] = this.limits[i];
      const id = `pose-q${i + 1}`;
      // named "Joint i" (the label around it would add the value and the limits to its name), its limits as its description
      const input = el('input', { id, type: 'range', min: String(lo), max: String(hi), step: String(STEP), value: String(this.q[i]),
        'aria-label': `Joint ${i + 1}`, 'aria-describedby': `${id}-limits` });
      const out = el('output', { htmlFor: id });
      input.addEventListener('input', () => {
        this.q[i] = Math.min(hi, Math.max(lo, Number(Number(input.value).toFixed(9))));
        this.say('');
        this.pose(true);
      });
      this.sliders.push({ input, out });
      grid.append(el('label', { className: 'pose-joint', htmlFor: id },
        el('span', { text: `Joint ${i + 1}` }), input, out,
        el('span', { id: `${id}-limits`, className: 'pose-limits', text: `limits ${degrees(lo)} … ${degrees(hi)}` })));
    }
    this.status = el('p', { id: 'pose-status', className: 'pose-status', role: 'status' });
    this.message = el('p', { id: 'pose-message', className: 'hint pose-message', role: 'status' });
    const button = (id, text, title, act) => {
      const b = el('button', { id, type: 'button', text, title });
      b.addEventListener('click', act);
      return b;
    };
    this.goalButtons = [
      button('pose-from-goal', 'From goal', 'Put the sliders at the scenario\'s goal', () => this.load('goal')),
      button('pose-set-goal', 'Set as goal', 'Make this pose the scenario\'s goal', () => this.set('goal')),
    ];
    this.syncButtons();
    const [fromGoal, setGoal] = this.goalButtons;
    this.root.replaceChildren(
      el('h2', { id: 'h-pose3d', text: 'Pose the arm' }),
      el('p', { className: 'hint', text: 'One slider a joint, within its limits (arrow keys: a degree). The arm is drawn at once in the 3-D view, red when it collides.' }),
      grid, this.status,
      el('div', { className: 'row pose-buttons' },
        button('pose-from-start', 'From start', 'Put the sliders at the scenario\'s start', () => this.load('start')), fromGoal,
        button('pose-set-start', 'Set as start', 'Make this pose the scenario\'s start', () => this.set('start')), setGoal),
      this.message);
  }

  /** A scenario without a goal (none to load or set) greys out the goal's buttons. */
  syncButtons() {
    const hasGoal = Array.isArray(this.scenario?.goal) && this.scenario.goal.length === this.q.length;
    for (const b of this.goalButtons) b.disabled = !hasGoal;
  }

  /** Draw the arm at the pose and say whether it is free (`byHand`: the user posed it). */
  pose(byHand = false) {
    this.sliders.forEach(({ input, out }, i) => {
      const v = this.q[i];
      if (Math.abs(Number(input.value) - v) > STEP / 2) input.value = String(v);
      out.textContent = angleText(v);
      input.setAttribute('aria-valuetext', angleText(v));
    });
    if (!this.scene) {
      this.collision = '';
      if (this.status) this.status.textContent = this.error ? `The pose cannot be checked: ${this.error}` : 'Loading…';
      return;
    }
    const q = Float64Array.from(this.q);
    const frames = this.scene.link_frames(q);
    this.collision = this.scene.collision(q);
    const atStart = this.q.every((v, i) => v === this.scenario.start[i]);
    const colour = this.collision ? this.palette.posedCollides : atStart ? this.palette.start : this.palette.posed;
    if (frames.length) this.slot.setManual({ frames, colour, ghost: !atStart }, byHand);
    this.status.textContent = this.collision
      ? `In collision (drawn red): ${this.collision}.`
      : 'Free: no part of the arm meets an obstacle or another link.';
    this.status.classList.toggle('collides', !!this.collision);
  }

  /** The sliders at the scenario's start or goal. */
  load(which) {
    const q = this.scenario?.[which];
    if (!Array.isArray(q) || q.length !== this.q.length) return;
    this.q = q.slice();
    this.say('');
    this.pose(true);
  }

  /** Make the pose the scenario's start or goal (refused when it collides). */
  set(which) {
    const name = which === 'start' ? 'start' : 'goal';
    if (!this.scene) { this.say(`Not set: the pose cannot be checked yet.`); return; }
    if (this.collision) { this.say(`Not set as the ${name}: this pose collides (${this.collision}). Move it free first.`); return; }
    if (!this.editor.setEndpoint(which, this.q)) { this.say(`Not set: the scenario is loading; try again in a moment.`); return; }
    this.say(`The ${name} is now this pose; the scenario was sent to the planner again.`);
  }

  /** The link frames at `q` from this thread's core (null until it is loaded): for the path panel (path3d.js). */
  linkFrames(q) {
    return this.scene ? this.scene.link_frames(q) : null;
  }

  say(text) {
    if (this.message) this.message.textContent = text;
  }

  /** For tests: the pose (radians), the text shown, whether it collides. */
  state() {
    return { q: this.q.slice(), status: this.status?.textContent ?? '', collision: this.collision, message: this.message?.textContent ?? '' };
  }
}

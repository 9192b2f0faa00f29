// The explain panel beside the canvas: the chosen planner's pseudocode (run/explain.js) with the
// line the shown events reached highlighted, the caption of the step in words, and where in the
// run it is. It is fed like a view (the lane calls drawRecords for every record revealed), so it
// follows the playback, step by event or by iteration, and says only what the events say. It also
// draws the step's actors on the workspace canvas (the sample, the nearest node, the range, the
// step's edge, the collision) through the view's top hooks. Built with DOM calls and textContent.

import { el } from './dom.js';
import { Explainer, optionsOf, pseudocode } from '../run/explain.js';
import { PALETTE } from '../draw/palette.js';
import { emits } from '../draw/capabilities.js';
import { StateMirror } from '../run/arm-states.js';
import { ConnectSteps } from './connect-steps.js';
import { showWhole } from '../draw/stage.js';

/** The actors' colours (also in the legend): apart from the tree blue and the obstacle brown. */
// (Purple: apart from the trees' blue and pink and from the best path's vermillion, which a paused
// RRT* shows beside the step.)
export const ACTOR = Object.freeze({ near: '#7b3294', range: 'rgba(123, 50, 148, 0.55)', edge: '#7b3294', blocked: '#b2182b', sample: PALETTE.sample });

export class ExplainPanel {
  /**
   * `root`: the panel's element; `store`: the playback's RecordStore; `view`: the workspace View
   * (its top hooks draw the actors).
   */
  constructor(root, store, view) {
    this.store = store;
    this.view = view;
    this.states = new StateMirror(); // a spatial arm's full states, from the core's state log
    /** @type {{scene: () => any, slot: import('../draw/view3d-slot.js').View3dSlot} | null} the 3-D view and the page thread's core */
    this.arm = null;
    this.shown3d = null;
    this.explainer = new Explainer();
    this.title = el('p', { id: 'explain-title', className: 'explain-title' });
    this.code = el('ol', { id: 'explain-code', className: 'explain-code' });
    this.caption = el('p', { id: 'explain-caption', className: 'explain-caption', text: 'Run or step the planner: each step is explained here.' });
    // not a live region: the page's one (ui/a11y.js) speaks the caption when the run is paused or stepped
    this.where = el('p', { id: 'explain-where', className: 'hint' });
    // a last-free connect's configurations, one at a time (a spatial arm's: the 3-D view's ghost)
    this.walk = new ConnectSteps((q) => { this.walkQ = q; this.show3d(); });
    this.walkQ = null;
    this.walkAt = 0;
    // the step now: its caption and a connect's walk (on a phone under the run bar, pages/main.js)
    this.now = el('div', { id: 'explain-now', className: 'explain-now' }, this.caption, this.walk.root);
    this.reveal = false; // scroll the caption into sight at the next render (a phone's step)
    root.replaceChildren(this.title, this.code, this.now, this.where);
    this.items = new Map();
    this.read = 0; // records read so far
    this.scheduled = 0;
    this.showResult = false;
    this.dirty = false;
    view.topHooks.push((ctx, L) => this.drawActors(ctx, L));
  }

  /**
   * Show `planner`'s pseudocode for the set-up `config` ({planner, params}) and robot kind;
   * `scene`: what the scenario decides ({vertices}: inspection counted at the tree's vertices).
   */
  setPlanner(config, robotKind, scene = {}) {
    const planner = config?.planner || '';
    const options = { ...optionsOf(config), ...scene };
    const code = pseudocode(planner, options);
    this.explainer = new Explainer(planner, robotKind || '', options);
    this.wire();
    this.items.clear();
    this.title.textContent = code ? code.title : `${planner}: no pseudocode yet`;
    this.code.replaceChildren(...(code ? code.lines : []).map((l) => {
      const li = el('li', { className: `indent-${l.indent || 0}` }, el('code', { text: l.text }));
      li.dataset.line = l.id;
      this.items.set(l.id, li);
      return li;
    }));
    this.clearRun();
  }

  /**
   * A robot in 3-D: `scene()` gives the page thread's core Scene of the loaded scenario (the pose
   * panel's: `collision`, `contact`, `link_frames`), `slot` the 3-D view that draws the step.
   */
  setArm(scene, slot) {
    this.arm = { scene, slot };
    this.wire();
  }

  /** The explainer reads the state log, and the core's words for a collision. */
  wire() {
    this.explainer.states = this.states;
    const scene = this.arm?.scene;
    this.explainer.describe = scene ? { collision: (q) => scene()?.collision(Float64Array.from(q)) ?? '' } : null;
  }

  /**
   * Legend items for what the panel draws on the canvas and the marks a sampling planner's step
   * leaves (the latest sample; RRT-Connect's meeting ring), for `planner` (registry name).
   */
  legend(planner) {
    if (!emits(planner, 'NEAREST')) return []; // the panel draws a growth step's actors
    /** @type {Array<{label: string, color: string, shape: string}>} */
    const items = [
      { label: 'latest sample', color: ACTOR.sample, shape: 'dot' },
      { label: 'this step: nearest node, step, range', color: ACTOR.near, shape: 'ring' },
      { label: 'this step: blocked', color: ACTOR.blocked, shape: 'cross' },
    ];
    if (emits(planner, 'TREES_CONNECTED')) items.push({ label: 'trees connected', color: PALETTE.connect, shape: 'ring' });
    return items;
  }

  // The view interface the lane feeds (lane.js)

  takeEvents(msg) {
    if (msg.states) this.states.push(msg.states);
  }

  /** After the next event shown, bring the step's caption into the screen on a phone. */
  revealNext() { this.reveal = true; }

  clearRun() {
    this.reveal = false;
    this.states.clear();
    this.explainer.reset();
    this.read = 0;
    this.showResult = false;
    this.schedule();
  }

  drawRecords(from, to) {
    if (from < this.read) { this.explainer.reset(); this.read = 0; }
    this.states.assign(this.store, from, to);
    this.explainer.readStore(this.store, this.read, to);
    this.read = Math.max(this.read, to);
    this.schedule();
  }

  setResult() {}
  finishRun() { this.schedule(); }

  schedule() {
    this.view.dirty = true;
    if (this.scheduled) return;
    this.scheduled = requestAnimationFrame(() => { this.scheduled = 0; this.render(); });
  }

  /** The line and caption now (for tests and the page's API). */
  state() {
    return { line: this.read ? this.explainer.line : null, caption: this.read ? this.explainer.caption : '', events: this.read };
  }

  render() {
    const x = this.explainer;
    const line = this.read ? x.line : null;
    for (const [id, li] of this.items) {
      const now = id === line;
      li.classList.toggle('now', now);
      if (now) li.setAttribute('aria-current', 'step'); else li.removeAttribute('aria-current');
    }
    this.caption.textContent = this.read ? x.caption : 'Run or step the planner: each step is explained here.';
    this.where.textContent = this.read ? `event ${this.read.toLocaleString('en')} of ${this.store.length.toLocaleString('en')} shown` : '';
    const connect = this.read && !this.view.showResult && this.arm?.slot?.active ? x.actors.connect : undefined;
    // each event shown starts the walk again at the farthest configuration, as the step says
    const fresh = connect !== this.walk.key || this.read !== this.walkAt;
    if (fresh) this.walkQ = null;
    this.walkAt = this.read;
    this.walk.show(connect, connect ? this.arm?.scene() : null, fresh);
    this.show3d();
    if (this.reveal && this.read) { this.reveal = false; showWhole(this.now); }
  }

  /**
   * The step's actors in the 3-D view (draw3d/actors3d.js), from the states the core logged: the
   * sample and the configuration checked as ghost arms, a collision's arm with the colliding
   * link(s) tinted and its contact point; none once the result is shown.
   */
  show3d() {
    const slot = this.arm?.slot;
    if (!slot?.active) return;
    const scene = this.arm.scene();
    const a = this.read && !this.view.showResult ? this.explainer.actors : null;
    // walking a connect's configurations (ui/connect-steps.js): the one chosen as the step's
    // ghost, and no collision yet (it is at the farthest)
    const walking = a && this.walkQ;
    const stepQ = walking ? this.walkQ : a?.stepQ;
    const collisionQ = walking ? undefined : a?.collisionQ;
    const key = a && scene ? [a.sampleQ, stepQ, collisionQ] : null;
    const same = key && this.shown3d && this.shown3d.scene === scene && key.every((q, i) => q === this.shown3d.key[i]);
    if (same || (!key && !this.shown3d)) return;
    this.shown3d = key ? { key, scene } : null;
    if (!key) { slot.setStep(null); return; }
    const frames = (q) => (q ? scene.link_frames(Float64Array.from(q)) : null);
    /** @type {import('../draw3d/actors3d.js').Actors3DData} */
    const data = {};
    if (a.sampleQ) data.sample = { frames: frames(a.sampleQ), colour: ACTOR.sample };
    if (stepQ) data.step = { frames: frames(stepQ), colour: ACTOR.near };
    if (collisionQ) {
      const q = Float64Array.from(collisionQ);
      const c = scene.contact(q); // [link, other, obstacle, x, y, z] or empty
      data.collision = {
        frames: frames(q),
        colour: ACTOR.blocked,
        links: c.length === 6 ? [c[0], c[1]].filter((l) => l >= 0) : [],
        at: c.length === 6 ? [c[3], c[4], c[5]] : null,
        words: scene.collision(q),
      };
    }
    slot.setStep(data);
  }

  /**
   * The step in 3-D as drawn (tests and the page's API): the tool centre point of each ghost arm
   * (null: not drawn) and its link frames' origins, and what collides, where.
   */
  state3d() {
    const slot = this.arm?.slot;
    const d = slot?.step;
    if (!d) return null;
    const offset = slot.spatial?.tool || [0, 0, 0];
    const tool = (g) => {
      const f = g?.frames;
      if (!f || f.length < 16) return null;
      const m = f.subarray(f.length - 16);
      return [0, 1, 2].map((r) => m[r] * offset[0] + m[4 + r] * offset[1] + m[8 + r] * offset[2] + m[12 + r]);
    };
    // every link frame's origin (the joints, inside the links' hulls)
    const origins = (g) => {
      const f = g?.frames;
      const out = [];
      for (let k = 0; f && k + 16 <= f.length; k += 16) out.push([f[k + 12], f[k + 13], f[k + 14]]);
      return out;
    };
    return {
      sample: tool(d.sample),
      step: tool(d.step),
      joints: { sample: origins(d.sample), step: origins(d.step), collision: origins(d.collision) },
      collision: d.collision ? { links: d.collision.links, at: d.collision.at, words: d.collision.words, tool: tool(d.collision) } : null,
      // walking a connect's configurations (ui/connect-steps.js): where, and the one drawn
      walk: this.walk.key ? { k: this.walk.k, count: this.walk.count, q: this.walkQ ? Array.from(this.walkQ) : null } : null,
    };
  }

  /** The current step's actors on the workspace canvas (not once the result is shown). */
  drawActors(ctx, L) {
    if (!this.read || this.view.showResult || !L) return;
    const a = this.explainer.actors;
    const px = (v) => L.px(v);
    ctx.save();
    if (a.range) {
      const [x, y, r] = a.range;
      ctx.strokeStyle = ACTOR.range;
      ctx.setLineDash([px(4), px(3)]);
      ctx.lineWidth = px(1.5);
      ctx.beginPath();
      ctx.arc(L.sx(x), L.sy(y), r * L.scale, 0, 2 * Math.PI);
      ctx.stroke();
      ctx.setLineDash([]);
    }
    if (a.near && a.target) { // the distance measured: nearest node to its target
      ctx.strokeStyle = ACTOR.range;
      ctx.lineWidth = px(1);
      ctx.setLineDash([px(2), px(3)]);
      ctx.beginPath();
      ctx.moveTo(L.sx(a.near[0]), L.sy(a.near[1]));
      ctx.lineTo(L.sx(a.target[0]), L.sy(a.target[1]));
      ctx.stroke();
      ctx.setLineDash([]);
    }
    if (a.edge) {
      const [x0, y0, x1, y1] = a.edge;
      ctx.strokeStyle = a.blocked ? ACTOR.blocked : ACTOR.edge;
      ctx.lineWidth = px(3);
      ctx.beginPath();
      ctx.moveTo(L.sx(x0), L.sy(y0));
      ctx.lineTo(L.sx(x1), L.sy(y1));
      ctx.stroke();
    }
    if (a.near) ring(ctx, L.sx(a.near[0]), L.sy(a.near[1]), px(6), ACTOR.near, px(2.5));
    if (a.sample) dot(ctx, L.sx(a.sample[0]), L.sy(a.sample[1]), px(4), ACTOR.sample);
    if (a.collision) cross(ctx, L.sx(a.collision[0]), L.sy(a.collision[1]), px(7), ACTOR.blocked, px(3));
    ctx.restore();
  }
}

function ring(ctx, x, y, r, color, w) {
  ctx.strokeStyle = '#ffffff';
  ctx.lineWidth = w + 2;
  ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.stroke();
  ctx.strokeStyle = color;
  ctx.lineWidth = w;
  ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.stroke();
}

function dot(ctx, x, y, r, color) {
  ctx.fillStyle = '#ffffff';
  ctx.beginPath(); ctx.arc(x, y, r + 1.5, 0, 2 * Math.PI); ctx.fill();
  ctx.fillStyle = color;
  ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fill();
}

function cross(ctx, x, y, r, color, w) {
  ctx.strokeStyle = color;
  ctx.lineWidth = w;
  ctx.beginPath();
  ctx.moveTo(x - r, y - r); ctx.lineTo(x + r, y + r);
  ctx.moveTo(x + r, y - r); ctx.lineTo(x - r, y + r);
  ctx.stroke();
}

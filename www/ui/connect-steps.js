// The configurations one connect checked, one at a time, under the explain panel's caption: the
// Robotics Library's connect (report 001's course) steps along the line by the resolution and
// tests each configuration, and the core records it as one step (its farthest configuration and
// its query count). Here a student walks through them: "◀ configuration 3 of 68 ▶", the 3-D view's
// ghost arm at that configuration, and whether it is free or what it hits, in the core's words.
//
// The configurations are the core's (`Scene.connect_configs`: the connect's own schedule, bit for
// bit the ones it tested; a Rust test compares them with the state log), from the connect's node
// and target as the state log gave them (run/explain.js: `actors.connect`); the words are
// `Scene.collision`'s. Nothing here interpolates.

import { el } from './dom.js';
import { joints } from '../run/explain.js';

/** The most configurations one connect may list (the core's own bound is larger; the panel's walk stops here). */
export const MAX_WALK = 100000;

export class ConnectSteps {
  /** `onPose(q | null)`: the configuration to draw as the step's ghost (null: the step as recorded). */
  constructor(onPose) {
    this.onPose = onPose;
    this.prev = el('button', { type: 'button', id: 'connect-prev', text: '◀', title: 'The configuration before', 'aria-label': 'The configuration before' });
    this.next = el('button', { type: 'button', id: 'connect-next', text: '▶', title: 'The configuration after', 'aria-label': 'The configuration after' });
    this.label = el('span', { id: 'connect-at' });
    this.words = el('p', { id: 'connect-words', className: 'hint' });
    this.root = el('div', { id: 'connect-steps', className: 'connect-steps', hidden: true },
      el('span', { text: 'Configurations this connect checked: ' }), this.prev, this.label, this.next, this.words);
    this.prev.addEventListener('click', () => this.go(this.k - 1));
    this.next.addEventListener('click', () => this.go(this.k + 1));
    this.key = null;
    this.k = 0;
    this.count = 0;
    this.configs = null;
    this.dims = 0;
    this.scene = null;
  }

  /**
   * The step shown: its connect ({from, target, count}, from the state log) and the page thread's
   * core, or nothing (hidden). A new connect starts at its farthest configuration, as recorded.
   * @param {{from: ArrayLike<number>, target: ArrayLike<number>, count: number} | undefined} connect
   * @param {any} scene
   * @param {boolean} [restart] back to the farthest even when it is the same connect (a new event shown)
   */
  show(connect, scene, restart = false) {
    const ok = connect && scene && Number.isInteger(connect.count) && connect.count >= 2 && connect.count <= MAX_WALK;
    if (!ok) {
      if (this.key) { this.key = null; this.root.hidden = true; this.configs = null; }
      return;
    }
    if (this.key === connect && this.scene === scene) {
      if (restart && this.k !== this.count) this.go(this.count, false);
      return;
    }
    this.key = connect;
    this.scene = scene;
    this.dims = connect.from.length;
    this.count = connect.count;
    this.configs = null; // asked for at the first step back
    this.root.hidden = false;
    this.go(this.count, false);
  }

  /** Configuration `k` (1 … count). `pose`: draw it (not for the farthest, drawn as recorded). */
  go(k, pose = true) {
    if (!this.key) return;
    this.k = Math.min(this.count, Math.max(1, k));
    if (!this.configs && this.k < this.count) {
      const c = this.key;
      this.configs = this.scene.connect_configs(Float64Array.from(c.from), Float64Array.from(c.target), this.count);
    }
    const q = this.configs && this.configs.length >= this.k * this.dims
      ? this.configs.subarray((this.k - 1) * this.dims, this.k * this.dims) : null;
    this.label.textContent = ` configuration ${this.k.toLocaleString('en')} of ${this.count.toLocaleString('en')} `;
    this.prev.disabled = this.k <= 1;
    this.next.disabled = this.k >= this.count;
    if (this.k === this.count) {
      this.words.textContent = 'the farthest it checked, as the step above says';
    } else if (q) {
      const hit = this.scene.collision(Float64Array.from(q));
      this.words.textContent = `${joints(q)}: ${hit ? `collides: ${hit}` : 'free, so the connect goes on'}`;
    } else {
      this.words.textContent = 'the core gave no configuration here';
    }
    if (pose) this.onPose(this.k === this.count ? null : q);
  }
}

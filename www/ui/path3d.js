// A solved path of a spatial arm (report 001's Puma 560), under the 3-D view: a scrubber along the
// path (a range input: arrow keys, Home, End), labelled with the length travelled in rad (the
// planner's metric, the joint-space distance) and the waypoint; the arm as see-through ghosts
// every so many rad; and a joint-angle timeline (www/draw/timeline.js), six curves in degrees
// against that length, linked both ways: hovering or dragging on it poses the arm there and moves
// the scrubber, and the scrubber (or the playing animation) moves its cursor.
//
// Shown only when the 3-D view has a solved path (www/draw/view3d-slot.js's `onPath`: a scene
// whose caps say `view3d`). The states are the result's animation frames (`Run.path_frames`, the
// smoothed path's or, when the page's "robot follows the raw path" is on, the raw path's), as the
// core sampled them; a pose between two frames is interpolated along the straight joint-space
// motion the planner checked. The lengths (the total shown, each frame's and each waypoint's) are
// the core's (the run's stats and `Run.path_lengths`, posted by the worker); the page sums none.
// Link frames come from the core on the page's thread (the pose panel's `Scene.link_frames`). Text
// goes in with textContent only.

import { el } from './dom.js';
import { Timeline, JOINT_COLOURS } from '../draw/timeline.js';
import { parseFrames } from '../draw/transform.js';
import { GHOSTS, readSpacing } from './ghost-spacing.js';

/** The scrubber's steps along the path (its value is a thousandth of the length). */
const SCRUB_STEPS = 1000;
const TIMELINE_HEIGHT = 170;

/** A joint's colour swatch (set through the CSS object model: the page's CSP allows no inline style). */
function swatch(colour) {
  const s = el('span', { className: 'swatch' });
  s.style.background = colour;
  return s;
}

const deg = (rad) => `${Number(((rad * 180) / Math.PI).toFixed(1))}°`;

/**
 * The states of a result's animation frames (`Run.path_frames`: dims, count, then each frame's
 * state and outline) with the core's length from the start at each frame and at each waypoint
 * (`Run.path_lengths` for the same frames: [frames, s…, waypoints, w…]; the page sums nothing).
 * Null when the two do not belong together (counts differ, a length not finite or going back).
 * @param {Float64Array} frames
 * @param {Float64Array | undefined} lengths
 * @returns {{dims: number, states: Float64Array, s: Float64Array, waypoints: number[]} | null}
 */
export function parseStates(frames, lengths) {
  const parsed = parseFrames(frames);
  const dims = frames?.[0] | 0;
  const n = parsed.length;
  if (dims < 1 || n < 1 || parsed[n - 1].state.length < dims) return null;
  if (!lengths || lengths[0] !== n || lengths.length < n + 2) return null;
  const w = lengths[n + 1];
  if (!(Number.isInteger(w) && w >= 1 && lengths.length === n + 2 + w)) return null;
  const s = Float64Array.from(lengths.subarray(1, n + 1));
  const waypoints = Array.from(lengths.subarray(n + 2));
  const ordered = (a) => a.every((v, k) => Number.isFinite(v) && v >= 0 && (k === 0 || v >= a[k - 1]));
  if (!ordered(Array.from(s)) || !ordered(waypoints)) return null;
  const states = new Float64Array(dims * n);
  parsed.forEach(({ state }, k) => states.set(state, k * dims));
  return { dims, states, s, waypoints };
}

export class PathPanel {
  /**
   * @param {{root: HTMLElement, slot: import('../draw/view3d-slot.js').View3dSlot,
   *   linkFrames: (q: Float64Array) => Float64Array | null, onSpacing?: () => void}} options
   * (`onSpacing`: the ghost spacing was changed by hand, for the share link).
   */
  constructor({ root, slot, linkFrames, onSpacing = () => {} }) {
    this.root = root;
    this.slot = slot;
    this.linkFrames = linkFrames;
    this.onSpacing = onSpacing;
    this.solved = null;   // the slot's {result, frames, rawFrames}
    this.raw = false;
    this.path = null;     // {dims, states, s, length, waypoints}
    this.s = 0;           // the length at the arm (rad)
    this.holding = false; // the arm held where the user put it (else it plays along the path)
    this.spacing = GHOSTS.initial;
    this.ghostCount = 0;
    this.shownFrame = -1;
    this.built = false;
    root.hidden = true;
    slot.onPath = (solved) => this.setSolved(solved);
  }

  build() {
    this.built = true;
    this.play = el('button', { id: 'path3d-play', type: 'button', text: 'Hold', title: 'Hold the arm where it is, or play it along the path again' });
    this.play.addEventListener('click', () => (this.holding ? this.resume() : this.holdAt(this.s)));
    this.scrub = el('input', { id: 'path3d-scrub', type: 'range', min: '0', max: String(SCRUB_STEPS), step: '1', value: '0',
      'aria-describedby': 'path3d-where' });
    this.scrub.addEventListener('input', () => this.holdAt((Number(this.scrub.value) / SCRUB_STEPS) * (this.path?.length || 0), 'scrub'));
    this.where = el('output', { id: 'path3d-where', htmlFor: 'path3d-scrub', className: 'path3d-where' });
    this.spacingInput = el('input', { id: 'path3d-spacing', type: 'number', min: '0', max: String(GHOSTS.max), step: '0.05',
      value: String(this.spacing), 'aria-describedby': 'path3d-spacing-note' });
    this.spacingInput.addEventListener('change', () => this.setSpacingText(this.spacingInput.value));
    this.spacingNote = el('span', { id: 'path3d-spacing-note', className: 'hint', role: 'status' });
    this.canvas = el('canvas', { id: 'path3d-timeline', className: 'path3d-timeline', role: 'img',
      'aria-label': 'Joint angles in degrees against the length along the path in rad: hover or drag to pose the arm there' });
    this.timeline = new Timeline(this.canvas);
    const at = (e) => this.holdAt(this.timeline.sAt(e.clientX - this.canvas.getBoundingClientRect().left), 'timeline');
    this.canvas.addEventListener('pointermove', at);
    this.canvas.addEventListener('pointerdown', (e) => { this.canvas.setPointerCapture?.(e.pointerId); at(e); });
    this.legend = el('ul', { className: 'path3d-joints', 'aria-label': 'The joints\' curves' });
    this.root.replaceChildren(
      el('h2', { id: 'h-path3d', text: 'The path in 3-D' }),
      el('div', { className: 'row path3d-scrubber' },
        this.play,
        el('label', { htmlFor: 'path3d-scrub', className: 'path3d-scrub-label', text: 'Along the path' }), this.scrub, this.where),
      el('div', { className: 'row path3d-ghosts' },
        el('label', { htmlFor: 'path3d-spacing', text: 'Ghosts every' }), this.spacingInput,
        el('span', { text: 'rad (0: none)' }), this.spacingNote),
      el('p', { className: 'hint path3d-caption', text: 'Each joint\'s angle (degrees) against the length along the path (rad, the planner\'s metric): hover or drag on it to pose the arm there.' }),
      this.canvas, this.legend);
    new ResizeObserver(() => this.fit()).observe(this.root);
  }

  fit() {
    if (!this.timeline || this.root.hidden) return;
    const w = Math.max(120, Math.floor(this.canvas.clientWidth));
    this.timeline.resize(w, TIMELINE_HEIGHT, window.devicePixelRatio || 1);
  }

  /** The solved path shown in the 3-D view (or none). */
  setSolved(solved) {
    if (solved === this.solved && this.path) return;
    this.solved = solved;
    this.holding = false;
    this.shownFrame = -1;
    this.load();
  }

  /** Follow the raw path (`raw`) or the smoothed one, as the page's option says. */
  setRaw(raw) {
    raw = !!raw;
    this.slot.setRaw(raw);
    if (raw === this.raw) return;
    this.raw = raw;
    if (this.solved) { this.holding = false; this.load(); }
  }

  /** Read the followed path's states and waypoints, and show them. */
  load() {
    const sv = this.solved;
    const parsed = sv ? parseStates(this.raw ? sv.rawFrames : sv.frames, this.raw ? sv.rawLengths : sv.lengths) : null;
    this.root.hidden = !parsed;
    if (!parsed) { this.path = null; this.slot.setGhosts([]); return; }
    if (!this.built) this.build();
    // The length shown is the core's cost of the path followed (the run's stats, as the results show it).
    const stats = this.solved.result.stats;
    const length = (this.raw ? stats?.cost : stats?.smoothed_cost ?? stats?.cost) ?? parsed.s[parsed.s.length - 1];
    this.path = { ...parsed, length };
    this.s = Math.min(this.s, length);
    this.timeline.setData(this.path);
    this.legend.replaceChildren(...Array.from({ length: parsed.dims }, (_, j) => {
      const first = parsed.states[j];
      const last = parsed.states[parsed.states.length - parsed.dims + j];
      return el('li', { id: `path3d-j${j + 1}`, 'data-start': String(first), 'data-end': String(last) },
        swatch(JOINT_COLOURS[j % JOINT_COLOURS.length]),
        el('span', { text: `Joint ${j + 1}` }),
        el('output', { className: 'path3d-value' }),
        el('span', { className: 'hint', text: `start ${deg(first)} · goal ${deg(last)}` }));
    }));
    this.fit();
    this.syncGhosts();
    if (this.holding) this.holdAt(this.s); else this.resume();
  }

  /** The state at length `s` along the path: between the two frames around it, on the straight motion. */
  stateAt(s) {
    const { dims, states, s: at } = this.path;
    const n = at.length;
    let lo = 0;
    let hi = n - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (at[mid] <= s) lo = mid; else hi = mid;
    }
    const q = new Float64Array(dims);
    const span = at[hi] - at[lo];
    const t = span > 0 ? Math.min(1, Math.max(0, (s - at[lo]) / span)) : 0;
    if (s >= at[n - 1]) return Float64Array.from(states.subarray((n - 1) * dims, n * dims));
    for (let j = 0; j < dims; j++) q[j] = states[lo * dims + j] + t * (states[hi * dims + j] - states[lo * dims + j]);
    return q;
  }

  /** Hold the arm at length `s` (`from`: the control that moved it, which is left alone). */
  holdAt(s, from = '') {
    if (!this.path) return;
    this.holding = true;
    this.s = Math.min(this.path.length, Math.max(0, s));
    const q = this.stateAt(this.s);
    this.q = q;
    const frames = this.linkFrames(q);
    this.slot.setScrub(frames && frames.length ? frames : this.nearestPose());
    this.show(from);
  }

  /** Without the core on this thread: the worker's pose nearest the held length. */
  nearestPose() {
    const p = this.slot.followed;
    if (!p || !p.count) return null;
    const f = this.frameAt(this.s);
    const k = Math.min(p.count - 1, Math.round(f / (p.stride || 1)));
    return p.frames.subarray(k * p.links * 16, (k + 1) * p.links * 16);
  }

  /** The frame index at length `s`. */
  frameAt(s) {
    const at = this.path.s;
    let lo = 0;
    let hi = at.length - 1;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (at[mid] < s) lo = mid + 1; else hi = mid;
    }
    return lo;
  }

  /** Play along the path again (the 3-D view's animation). */
  resume() {
    this.holding = false;
    this.slot.setScrub(null);
    this.shownFrame = -1;
    this.show();
  }

  /** Each page frame: while playing, the scrubber and the cursor follow the animated arm. */
  frame() {
    if (!this.path || this.holding || this.root.hidden) return;
    const f = this.slot.animatedFrame();
    if (f < 0 || f === this.shownFrame) return;
    this.shownFrame = f;
    const k = Math.min(f, this.path.s.length - 1);
    this.s = this.path.s[k];
    this.q = this.path.states.slice(k * this.path.dims, (k + 1) * this.path.dims);
    this.show();
  }

  /** The scrubber, its label, the timeline's cursor and the joints' values at the arm's length. */
  show(from = '') {
    const { length, waypoints } = this.path;
    if (from !== 'scrub') this.scrub.value = String(Math.round((this.s / (length || 1)) * SCRUB_STEPS));
    const w = waypoints.length;
    let i = 0;
    while (i + 1 < w && waypoints[i + 1] <= this.s + 1e-12) i++;
    const atWay = Math.abs(waypoints[i] - this.s) <= 1e-9 * Math.max(1, length);
    const way = atWay || i + 1 >= w ? `at waypoint ${i + 1} of ${w}` : `between waypoints ${i + 1} and ${i + 2} of ${w}`;
    const text = `${this.s.toFixed(3)} of ${length.toFixed(3)} rad, ${way}${this.raw ? ' (raw path)' : ''}`;
    this.where.textContent = text;
    this.scrub.setAttribute('aria-valuetext', text);
    this.play.textContent = this.holding ? 'Play' : 'Hold';
    this.timeline.setCursor(this.s);
    const q = this.q || this.stateAt(this.s);
    [...this.legend.children].forEach((li, j) => {
      const out = li.querySelector('output');
      if (out) { out.textContent = deg(q[j]); li.setAttribute('data-value', String(q[j])); }
    });
  }

  /** The ghost spacing as typed: applied when valid, else a message and the ghosts unchanged. */
  setSpacingText(text) {
    const r = readSpacing(text);
    if ('error' in r) {
      this.spacingInput.setAttribute('aria-invalid', 'true');
      this.spacingNote.textContent = `${r.error} The ghosts stay every ${this.spacing} rad.`;
      return false;
    }
    this.spacingInput.removeAttribute('aria-invalid');
    this.spacing = r.value;
    this.syncGhosts();
    this.onSpacing();
    return true;
  }

  /** The ghost spacing a share link gives (a value readSpacing accepted), or the default (`undefined`). */
  setSpacing(value = GHOSTS.initial) {
    this.spacing = value;
    if (!this.built) return;
    this.spacingInput.value = String(value);
    this.spacingInput.removeAttribute('aria-invalid');
    if (this.path) this.syncGhosts(); else this.spacingNote.textContent = '';
  }

  /** The ghosts at every `spacing` rad after the start, before the goal (at most GHOSTS.most). */
  syncGhosts() {
    const list = [];
    let note = '';
    const L = this.path?.length || 0;
    if (this.path && this.spacing > 0 && L > 0) {
      let step = this.spacing;
      if (L / step - 1 > GHOSTS.most) {
        step = L / (GHOSTS.most + 1);
        note = `At most ${GHOSTS.most} ghosts: drawn every ${step.toFixed(3)} rad on this path.`;
      }
      for (let k = 1; k * step < L - 1e-9 && list.length < GHOSTS.most; k++) {
        const f = this.linkFrames(this.stateAt(k * step));
        if (f && f.length) list.push(f);
      }
    }
    this.ghostCount = list.length;
    this.spacingNote.textContent = note;
    this.slot.setGhosts(list);
  }

  /** For tests: what the panel shows. */
  state() {
    if (!this.path) return { shown: !this.root.hidden, path: false };
    return {
      shown: !this.root.hidden, path: true, raw: this.raw, length: this.path.length, s: this.s, holding: this.holding,
      q: Array.from(this.q || this.stateAt(this.s)), first: Array.from(this.path.states.subarray(0, this.path.dims)),
      last: Array.from(this.path.states.subarray(this.path.states.length - this.path.dims)), frames: this.path.s.length,
      waypoints: this.path.waypoints.slice(), at: Array.from(this.path.s), states: Array.from(this.path.states),
      ghosts: this.ghostCount, spacing: this.spacing, where: this.where.textContent,
      note: this.spacingNote.textContent,
    };
  }

  /** For tests: css px within the timeline of joint value `rad` (radians) at length `s`, and the plot's box. */
  timelineAt(s, rad) { return this.timeline?.where(s, rad) ?? null; }
}

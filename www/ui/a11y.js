// The playground for keyboard and screen-reader users: a skip link to the run bar, focus kept in
// the run bar when the focused button turns off (Run → Pause, Pause → Run), one live region that
// speaks the run at most about once a second while it plays and in full (the status and the
// explain panel's caption) when it is paused, stepped or done, and the canvas's text of its state
// ("tree 235 nodes; path 12 waypoints, cost 1.16"), refreshed at the same pace. The embedded
// playground (planarium-playground.js) wires the same in its shadow root, without a skip link,
// and reads its caption from a StepCaption (it has no explain panel).

import { Explainer, optionsOf } from '../run/explain.js';

/** While a run plays, the live region and the canvas text change at most once per this many ms. */
export const ANNOUNCE_MS = 1000;

/** The button that takes the focus when the focused one turns off (by id). */
const PARTNER = Object.freeze({ run: 'pause', pause: 'run', 'step-event': 'pause', step: 'pause', cancel: 'reset' });

const n = (v) => Number(v).toLocaleString('en');

/**
 * The canvas's text of its state: the scenario, the nodes drawn and the path found (its waypoints
 * and cost), or the best cost so far while a planner that keeps improving plays.
 * `name`: the scenario's name; `nodes`: the nodes drawn (the stats' Nodes); `result`: the run's
 * result, or null; `bestCost`: the best cost in the events shown, or null; `state`: the controller's.
 * @param {{name?: string, nodes?: number, result?: any, bestCost?: number | null, state?: string}} s
 */
export function describeCanvas({ name, nodes, result, bestCost, state }) {
  const scene = `Map of ${name || 'no scenario'}`;
  if (!name || state === 'loading' || state === 'invalid') return `${scene}.`;
  const parts = [`tree ${n(nodes || 0)} nodes`];
  const path = result?.solved ? result.path : null;
  if (path?.length) {
    const cost = Number.isFinite(result.stats?.cost) ? `, cost ${result.stats.cost.toFixed(2)}` : '';
    parts.push(`path ${n(path.length)} waypoints${cost}`);
  } else if (Number.isFinite(bestCost)) {
    parts.push(`best cost so far ${Number(bestCost).toFixed(2)}`);
  } else if (result && !result.solved) {
    parts.push('no path');
  } else {
    parts.push('no path yet');
  }
  return `${scene}: ${parts.join('; ')}.`;
}

/**
 * The spoken text: while running the status alone; else the status and the caption in full.
 * @param {string} state @param {string} status @param {string} caption
 */
export function announcement(state, status, caption) {
  if (state === 'running' || !caption) return status;
  return `${status}. ${caption}`;
}

/**
 * The caption of the step shown, for a page without the explain panel (the embed): a view the
 * lane feeds (lane.js: clearRun, drawRecords, setResult, finishRun) that reads the records shown
 * with an Explainer, as the explain panel does, and draws nothing.
 */
export class StepCaption {
  /** `store`: the playback's RecordStore. */
  constructor(store) {
    this.store = store;
    this.explainer = new Explainer();
    this.read = 0;
    this.showResult = false;
    this.dirty = false;
  }

  /** The planner set-up {planner, params} and the scenario's robot kind. */
  setPlanner(config, robotKind = '') {
    this.explainer = new Explainer(config?.planner || '', robotKind, optionsOf(config));
    this.read = 0;
  }

  clearRun() { this.explainer.reset(); this.read = 0; this.showResult = false; }

  drawRecords(from, to) {
    if (from < this.read) { this.explainer.reset(); this.read = 0; }
    this.explainer.readStore(this.store, this.read, to);
    this.read = Math.max(this.read, to);
  }

  setResult() {}
  finishRun() {}

  /** The step's caption, '' before the first record. */
  get caption() { return this.read ? this.explainer.caption : ''; }
}

/**
 * Wire the page's accessibility. `skip`: the skip link (none in the embed); `bar`: the run bar
 * (its buttons); `live`: the live region; `canvas`: the workspace canvas; `root`: the document or
 * the shadow root the bar is in (its buttons' ids and the focus are looked up there); `read()`
 * gives {state, status, caption, name, nodes, result, bestCost} now. Returns {update(), refocus()}:
 * update() after each frame and state change (throttled while running), refocus() after the run
 * bar's buttons were enabled or disabled.
 * @param {{skip?: HTMLElement | null, bar: HTMLElement, live: HTMLElement, canvas: HTMLElement,
 *   root?: Document | ShadowRoot, read: () => any}} parts
 */
export function wireA11y({ skip = null, bar, live, canvas, root = document, read }) {
  skip?.addEventListener('click', (e) => {
    e.preventDefault(); // the hash holds the share link: a fragment would be read as one
    const first = [...bar.querySelectorAll('button')].find((b) => !b.disabled && !b.hidden);
    (first || bar).focus();
  });

  // the run bar's button focused last, kept while the focus is inside the bar or was lost (a
  // disabled button drops it to the page)
  let lastInBar = null;
  bar.addEventListener('focusin', (e) => { lastInBar = e.target; });
  bar.addEventListener('focusout', (e) => {
    const to = /** @type {Node | null} */ (e.relatedTarget);
    if (to && !bar.contains(to)) lastInBar = null;
  });

  function refocus() {
    const b = lastInBar;
    if (!(b instanceof HTMLButtonElement) || !b.disabled) return;
    const active = root.activeElement;
    if (active && active !== document.body && active !== b) return; // the focus went elsewhere on purpose
    const partner = PARTNER[b.id] && root.getElementById(PARTNER[b.id]);
    const usable = (x) => x instanceof HTMLButtonElement && !x.disabled && !x.hidden && bar.contains(x);
    const next = usable(partner) ? partner : [...bar.querySelectorAll('button')].find(usable);
    if (next) next.focus();
  }

  let said = '', described = '', last = -Infinity, lastState = '';
  let timer = 0;
  function update() {
    const s = read();
    const now = performance.now();
    const changed = s.state !== lastState;
    if (s.state === 'running' && !changed && now - last < ANNOUNCE_MS) {
      // the region waits; a frame after the pause is due writes it (the frame loop calls again)
      if (!timer) timer = window.setTimeout(() => { timer = 0; update(); }, ANNOUNCE_MS - (now - last));
      return;
    }
    lastState = s.state;
    const text = announcement(s.state, s.status, s.caption);
    const label = describeCanvas(s);
    if (text !== said) { said = text; live.textContent = text; last = now; }
    if (label !== described) { described = label; canvas.setAttribute('aria-label', label); }
  }

  return { update, refocus };
}

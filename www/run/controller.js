// The page's controller: an explicit state-transition table (PathFinding.js style). The table is
// the single source of truth: which buttons are enabled is derived from it (a button is enabled
// when its event has a transition from the current state), and docs/state-diagram.gv is generated
// from it by toDot() (a test checks the checked-in diagram against the table).
//
//   idle → running ⇄ paused → finished, plus
//   loading  while a scenario is being validated by the worker,
//   invalid  when the scenario the user opened has errors (only loading another one leaves it),
//   stopped  when the planning worker kept dying (session.js `fatal`): nothing runs, and loading
//            a scenario (a built-in, a file) starts a fresh worker.
//
// Events: load (a scenario was sent to the worker), loaded / invalid (its answer), configure
// (planner, parameters or seed changed), run, pause, step (N planner iterations), stepEvent
// (reveal one more buffered event), finish (the planner stopped and playback caught up), cancel,
// reset, fail (the worker refused to start the run), stop (the worker kept dying).

export const STATES = Object.freeze(['loading', 'idle', 'running', 'paused', 'finished', 'invalid', 'stopped']);

export const TRANSITIONS = Object.freeze({
  loading: Object.freeze({
    load: 'loading', loaded: 'idle', invalid: 'invalid', stop: 'stopped',
  }),
  idle: Object.freeze({
    run: 'running', step: 'paused', stepEvent: 'paused', configure: 'idle',
    load: 'loading', loaded: 'idle', invalid: 'invalid', stop: 'stopped',
  }),
  running: Object.freeze({
    pause: 'paused', stepEvent: 'paused', finish: 'finished', cancel: 'finished', reset: 'idle', fail: 'idle',
    configure: 'idle', load: 'loading', loaded: 'idle', invalid: 'invalid', stop: 'stopped',
  }),
  paused: Object.freeze({
    run: 'running', step: 'paused', stepEvent: 'paused', finish: 'finished', cancel: 'finished',
    reset: 'idle', fail: 'idle', configure: 'idle', load: 'loading', loaded: 'idle', invalid: 'invalid',
    stop: 'stopped',
  }),
  finished: Object.freeze({
    run: 'running', reset: 'idle', configure: 'idle',
    load: 'loading', loaded: 'idle', invalid: 'invalid', stop: 'stopped',
  }),
  invalid: Object.freeze({
    configure: 'invalid', load: 'loading', loaded: 'idle', invalid: 'invalid', stop: 'stopped',
  }),
  stopped: Object.freeze({
    load: 'loading',
  }),
});

// Button id → the event it fires. Enabled iff TRANSITIONS[state] has that event.
export const BUTTONS = Object.freeze({
  run: 'run',
  pause: 'pause',
  step: 'step',
  'step-event': 'stepEvent',
  reset: 'reset',
  cancel: 'cancel',
});

export class Controller {
  #state;
  #listeners = [];

  constructor(initial = 'loading') {
    if (!TRANSITIONS[initial]) throw new Error(`unknown state ${initial}`);
    this.#state = initial;
  }

  get state() { return this.#state; }

  /** Whether `event` is allowed in the current state. */
  can(event) { return Object.hasOwn(TRANSITIONS[this.#state], event); }

  /** Take the transition for `event`; returns false (and changes nothing) when it is not allowed. */
  fire(event) {
    if (!this.can(event)) return false;
    const from = this.#state;
    this.#state = TRANSITIONS[from][event];
    for (const fn of this.#listeners) fn(this.#state, from, event);
    return true;
  }

  /** Button id → enabled, derived from the table. */
  buttons() {
    const out = {};
    for (const [id, event] of Object.entries(BUTTONS)) out[id] = this.can(event);
    return out;
  }

  onChange(fn) { this.#listeners.push(fn); }
}

/** The table as a graphviz digraph (docs/state-diagram.gv is this text). */
export function toDot(table = TRANSITIONS) {
  const lines = [
    '// Generated from www/run/controller.js (toDot); tests/js/page.test.mjs checks it against the table.',
    'digraph controller {',
    '  rankdir=LR;',
    '  node [shape=box, style=rounded, fontname="Helvetica"];',
    '  edge [fontname="Helvetica", fontsize=10];',
  ];
  for (const state of Object.keys(table)) lines.push(`  ${state};`);
  for (const [from, edges] of Object.entries(table)) {
    // One arrow per target, labelled with every event that leads there.
    const byTarget = new Map();
    for (const [event, to] of Object.entries(edges)) {
      if (!byTarget.has(to)) byTarget.set(to, []);
      byTarget.get(to).push(event);
    }
    for (const [to, events] of byTarget) lines.push(`  ${from} -> ${to} [label="${events.join(', ')}"];`);
  }
  lines.push('}');
  return lines.join('\n') + '\n';
}

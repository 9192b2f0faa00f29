// Steps and pace: the playback shows a run as steps and paces it by duration, not by events per
// second.
//
// A step is one record, except that a run of set-up records (events.js SETUP_KINDS: a grid's
// cells, one level of a decomposition, a region of influence and its heat map) is one step: the
// "Step one event" button then shows the whole heat map at once and the next press the planner's
// first decision. A CELL record of another level than the run of set-up records it follows starts
// a new step (a decomposition is shown level by level).
//
// The pace: the whole run in `duration` seconds of replay (Slow 40, Normal 15, Fast 5), whatever
// its size. Each frame the steps still queued are spread over the time left, so a run of 50 steps
// shows one every few frames and one of 70,000 shows some tens a frame; while the planner is still
// sending, what it sent so far is spread, and the rest comes faster. Past its duration a replay
// shows what comes at once (a planner slower than its replay is followed live).

import { EventKind, SETUP_KINDS } from './events.js';

const SETUP = new Set(SETUP_KINDS);

/** Marks which records start a step, in the order they come (one scanner per run). */
export class StepScanner {
  constructor() { this.clear(); }

  clear() {
    this.setup = false; // the last record was a set-up record
    this.level = null;  // the CELL level of the current run of set-up records (null: none yet)
  }

  /**
   * Flags for the records of `data` (STRIDE numbers each): 1 where a record starts a step.
   * Returns {starts: Uint8Array, steps}.
   */
  scan(data, stride) {
    const n = Math.floor(data.length / stride);
    const starts = new Uint8Array(n);
    let steps = 0;
    for (let i = 0; i < n; i++) {
      const kind = data[i * stride];
      const setup = SETUP.has(kind);
      let start = !(setup && this.setup);
      if (setup) {
        if (kind === EventKind.CELL) {
          const level = data[i * stride + 1];
          if (!start && this.level !== null && level !== this.level) start = true;
          this.level = level;
        } else if (start) this.level = null;
      }
      this.setup = setup;
      if (start) { starts[i] = 1; steps++; }
    }
    return { starts, steps };
  }
}

/**
 * The pacing plan of one replay: the replay clock (seconds of running replay, frames' times capped
 * as the page's loop caps them) and how many steps a frame owes.
 */
export class Pace {
  constructor() { this.clear(); }

  clear() {
    this.clock = 0;      // seconds of replay so far
    this.budget = 0;     // fractional steps owed
    this.duration = 0;   // the whole run's seconds at the last tick (0: all at once)
    this.lastSteps = 0;  // steps owed by the last tick
    this.frames = 0;     // ticks
  }

  /**
   * Steps to show this frame: `queued` steps wait, the run should take `duration` seconds (0 or
   * not finite: all at once, returns Infinity), `dt` seconds passed since the last frame.
   */
  owe(queued, duration, dt) {
    this.frames++;
    this.duration = duration > 0 && Number.isFinite(duration) ? duration : 0;
    if (!this.duration) { this.budget = 0; this.lastSteps = Infinity; return Infinity; }
    this.clock += dt;
    const left = this.duration - this.clock;
    if (left <= dt) { this.budget = 0; this.lastSteps = queued; return queued; } // due: all of it
    this.budget = Math.min(this.budget + (queued * dt) / left, Math.max(1, queued));
    const n = Math.floor(this.budget);
    this.budget -= n;
    this.lastSteps = n;
    return n;
  }
}

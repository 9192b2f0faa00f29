// Time-lapse exports: "the whole run in N seconds", beside real time (what the page shows as it
// plays). The run's records so far are replayed off the page, in a playback of their own
// (playback.js: its store and run model), and an export view (exports.js ExportView, given this
// time-lapse) draws that replay at its own size; the page's run and views are left as they are. The replay goes by steps
// as the page's pace does (pace.js: a run of set-up events is one step), so a GIF of N seconds
// shows a frame's share of the steps per frame, and a WebM shows the share of N seconds gone.
// The result (path, robot) is shown once the replay reached the end, if the page shows it.

import { Playback } from '../run/playback.js';

/** The longest time-lapse asked for, in seconds (a GIF has at most 150 frames: 15 s at 10 a second). */
export const LAPSE_SECONDS = Object.freeze({ min: 1, max: 120 });

export class TimeLapse {
  /** The records `store` holds now (a RecordStore: the page's), replayed in `seconds`. */
  constructor(store, seconds) {
    if (!(seconds >= LAPSE_SECONDS.min && seconds <= LAPSE_SECONDS.max)) {
      throw new Error(`time-lapse: ${seconds} s is outside ${LAPSE_SECONDS.min} to ${LAPSE_SECONDS.max} s`);
    }
    if (!store.length) throw new Error('time-lapse: there is no run to replay yet: run the planner first');
    this.seconds = seconds;
    this.playback = new Playback();
    for (const [d, o0, o1] of store.spans(0, store.length)) this.playback.push(d.slice(o0, o1));
    this.total = this.playback.pendingSteps;
    this.start = null; // performance.now() at the first advance()
  }

  /** Whether every step is shown. */
  get atEnd() { return this.playback.pending === 0; }

  /** Show the share `f` (0 to 1) of the run's steps. */
  to(f) {
    const want = Math.ceil(Math.min(1, Math.max(0, f)) * this.total);
    if (want > this.playback.steps) this.playback.revealSteps(want - this.playback.steps);
    if (f >= 1) this.playback.revealAll();
  }

  /** Show the share of `seconds` gone since the first call (a recording's frames). */
  advance(now = performance.now()) {
    this.start ??= now;
    this.to((now - this.start) / 1000 / this.seconds);
  }
}

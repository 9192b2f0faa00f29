// One planner set-up and its run as the page shows it: a worker session (session.js), the
// playback of its events (playback.js), the views that draw them (view.js, and any other with the
// same drawRecords / clearRun / setResult methods, such as the C-space view), an optional live
// chart (chart.js), and the run's state: the worker's latest stats, the terminal status, the
// result. The playground has one lane; the compare page has two, driven together. Which state the
// page is in (the controller) stays with the page: hooks ask it.

import { WorkerSession } from './session.js';
import { REVEAL_PER_FRAME, nextRevealCap } from './limits.js';

export class Lane {
  /**
   * `playback`: a Playback; `views`: [View, ...] fed with revealed records; `chart`: a Chart or
   * null; `hooks`: {ready, loaded, invalid, error, asv, seed, stopped} (see session.js), plus
   * `revealed()` after records were revealed or the result came (the page checks whether the run
   * is finished), `finished()` whether the page is in its finished state (a late batch is then
   * shown at once), and `changed()` when the stats changed.
   */
  /** @param {{playback: any, views: any[], chart?: any, hooks?: Record<string, Function>}} options */
  constructor({ playback, views, chart = null, hooks = {} }) {
    this.playback = playback;
    this.views = views;
    this.view = views[0];
    this.chart = chart;
    this.hooks = hooks;
    this.session = new WorkerSession({
      ready: (m) => hooks.ready?.(m),
      loaded: (m) => hooks.loaded?.(m),
      invalid: (e) => hooks.invalid?.(e),
      events: (m) => this.onEvents(m),
      result: (m) => this.onResult(m),
      error: (message) => {
        this.stepPending = 0;
        this.revealOnePending = false;
        this.setupPending = false;
        hooks.error?.(message);
      },
      asv: (text) => hooks.asv?.(text),
      query: (m) => this.onQuery(m),
      seed: (seed) => hooks.seed?.(seed),
      stopped: (message, fatal, why) => { this.clearRun(); hooks.stopped?.(message, fatal, why); },
    });
    /** Records a frame may reveal (limits.js nextRevealCap), learnt from the frames drawn */
    this.revealCap = REVEAL_PER_FRAME / 4;
    this.clearRun(false);
  }

  start() { this.session.start(); }

  /** Forget the run (the views' drawing too); `notify`: tell the page its stats changed. */
  clearRun(notify = true) {
    this.playback.clear();
    for (const v of this.views) v.clearRun();
    this.chart?.clearRun();
    this.stats = null;        // the worker's latest stats
    this.tries = null;        // {seen, sent}: raw tries drawn by the core and sent by the worker
    this.finalStatus = null;  // the planner's terminal status word
    this.result = null;
    this.done = false;        // the `result` message arrived
    this.stepPending = 0;     // steps sent, not yet answered: reveal each answer at once
    this.revealOnePending = false;
    this.setupPending = false; // a set-up step is still arriving: show the rest of it as it comes
    if (notify) this.hooks.changed?.();
  }

  // Requests (the page's controller decides whether they are allowed)

  load(text, file = null, map = null) { this.clearRun(); this.session.load(text, file, map); }
  configure(config) { this.session.configure(config); this.clearRun(); }
  resetRun() { this.session.reset(); this.clearRun(); }
  run() { if (!this.done) this.session.send({ type: 'run' }); }
  pause() { if (!this.done) this.session.send({ type: 'pause' }); }

  /** Run `iterations` planner iterations and show them at once (or show what is left). */
  step(iterations) {
    if (this.done) { this.reveal(this.playback.revealAll()); return; }
    this.stepPending++;
    this.session.send({ type: 'step', iterations });
  }

  /** Another query on the finished run's roadmap (start and goal: scenario states). */
  query(start, goal) {
    if (this.done) this.session.send({ type: 'query', start, goal });
  }

  /**
   * Show one more step (an event, or a whole run of set-up events: pace.js); with nothing
   * buffered, ask the planner for one more iteration.
   */
  stepEvent() {
    if (this.playback.pending > 0) { this.reveal(this.playback.revealSteps(1)); this.moreSetup(); }
    else if (!this.done) { this.revealOnePending = true; this.session.send({ type: 'step', iterations: 1 }); }
  }

  /**
   * The step shown is a run of set-up events that may go on (a grid is labelled a row an
   * iteration): ask the planner for more, until something else comes (onEvents shows the rest).
   */
  moreSetup() {
    if (this.playback.pending > 0 || this.done || !this.playback.scanner.setup) return;
    this.setupPending = true;
    this.session.send({ type: 'step', iterations: 1 });
  }

  /** Stop the planner now (or, when it already stopped, show the rest). */
  cancel() {
    if (!this.done) {
      this.session.cancel();
      this.finalStatus = 'cancelled';
    }
    this.reveal(this.playback.revealAll());
  }

  // Replies

  onEvents(msg) {
    if (this.done) return; // one run, one result: nothing after the result
    this.playback.push(msg.data);
    for (const v of this.views) v.takeEvents?.(msg); // what a view needs beside the records (the 3-D view's tool curves)
    this.stats = msg.stats;
    if (msg.tries) this.tries = msg.tries;
    if (msg.status !== 'running') this.finalStatus = msg.status;
    if (this.stepPending > 0 || this.hooks.finished?.()) {
      this.stepPending = Math.max(0, this.stepPending - 1);
      this.reveal(this.playback.revealAll());
    }
    if (this.setupPending) { this.setupPending = false; this.reveal(this.playback.revealContinuation()); this.moreSetup(); }
    if (this.revealOnePending) { this.revealOnePending = false; this.reveal(this.playback.revealSteps(1)); this.moreSetup(); }
    this.hooks.changed?.();
  }

  onResult(msg) {
    if (this.done) return;
    this.result = msg.result;
    this.done = true;
    for (const v of this.views) v.setResult(msg.result, msg.frames, msg.rawFrames, msg.path3d, msg.rawPath3d);
    this.hooks.revealed?.();
    this.hooks.changed?.();
  }

  /**
   * A query's events join the run's (shown at once); the page gets the answer (hooks.query). The
   * stats stay the run's result's.
   */
  onQuery(msg) {
    if (!this.done) return;
    this.playback.push(msg.data);
    for (const v of this.views) v.takeEvents?.(msg);
    this.reveal(this.playback.revealAll());
    this.hooks.query?.(msg.answer);
    this.hooks.changed?.();
  }

  // Playback

  /** Draw records [from, to) that were just revealed. */
  reveal([from, to]) {
    if (to > from) for (const v of this.views) v.drawRecords(from, to);
    this.hooks.revealed?.();
  }

  /**
   * Reveal what the pace owes: the whole run in `duration` seconds (0: at once), `dt` seconds on;
   * at most as many records as this machine draws in limits.js's REVEAL_MS (`revealCap`).
   */
  tick(duration, dt) {
    if (this.playback.pending <= 0) return;
    const t0 = performance.now();
    const range = this.playback.tick(duration, dt, this.revealCap);
    this.reveal(range);
    this.revealCap = nextRevealCap(this.revealCap, range[1] - range[0], performance.now() - t0);
  }

  /** The planner stopped and every event it sent is shown. */
  get caughtUp() { return this.done && this.playback.pending === 0; }

  /** Show the result (paths, robot animation) once the page is finished; true when it changed. */
  showResult() {
    if (!this.result || this.view.showResult) return false;
    for (const v of this.views) {
      v.showResult = true;
      v.dirty = true;
      v.finishRun?.();
    }
    return true;
  }

  /** The iteration the shown run has reached (for the chart's x axis). */
  get iterationNow() {
    if (this.result?.stats && this.caughtUp) return this.result.stats.iterations;
    if (this.playback.pending === 0 && this.stats) return this.stats.iterations;
    const m = this.playback.model;
    const last = (s) => (s.length ? s[s.length - 1][0] : 0);
    return Math.max(last(m.costs), last(m.coverage));
  }

  /**
   * Everything the stats panel shows: the worker's stats (the result's once the page is
   * finished), what the shown events say (best cost, coverage), and the playback's counters.
   */
  statsFor(status, finished) {
    const s = (finished && this.result?.stats) || this.stats || {};
    const m = this.playback.model;
    const cov = m.bestCoverage;
    return {
      ...s,
      status,
      reason: finished ? this.result?.reason ?? null : null, // status no_path: why the planner gave up
      best_cost: m.bestCost,
      coverage: cov ? cov.fraction : null,
      points_seen: cov ? cov.seen : m.seen.size || null,
      tries_seen: this.tries?.seen ?? null,
      tries_sent: this.tries?.sent ?? null,
      shown_nodes: this.playback.nodeCount,
      shown_events: this.playback.store.length,
      queued_events: this.playback.pending,
    };
  }
}

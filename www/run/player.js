// One planner run on a canvas, as the playground (main.js), embed.html and <planarium-playground>
// show it: the controller's table (controller.js), a lane (lane.js: the worker session, the
// playback, the views), the actions buttons and keys fire (run, pause, step, step back, step one
// event, reset, cancel), and the animation-frame loop that reveals events at the playback's pace
// (pace.js: the whole run in so many seconds).
// The page around it (panels, stats, legend) hooks in; nothing here touches the document.
//
// Step back replays: the core is deterministic, so the run is reset and stepped again from the
// same seed to (iterations shown − N) in one batch, which the playback reveals at once.

import { Controller } from './controller.js';
import { Lane } from './lane.js';

export class Player {
  /**
   * `playback`: a Playback; `views`: [View, ...] (the first is the workspace view); `chart`: a
   * Chart or null; `duration()`: seconds the whole run's replay takes while running (0: all at
   * once; pace.js);
   * `fps()`: robot animation frames per second; `hooks`: {ready, loaded, invalid, error, asv, seed,
   * query, stopped, changed} as lane.js's (the player does the controller's part of error / stopped and
   * the run's bookkeeping), plus `frame(time)` after the views were drawn.
   */
  /** @param {{playback: any, views: any[], chart?: any, duration?: () => number, fps?: () => number, hooks?: Record<string, Function>}} options */
  constructor({ playback, views, chart = null, duration = () => 0, fps = () => 10, hooks = {} }) {
    this.controller = new Controller('loading');
    this.playback = playback;
    this.view = views[0];
    this.duration = duration;
    this.fps = fps;
    this.hooks = hooks;
    this.marks = [];    // per batch the worker sent: [records pushed so far, its iterations]
    this.raf = 0;
    this.lastFrame = 0;
    const c = this.controller;
    this.lane = new Lane({
      playback, views, chart,
      hooks: {
        ready: (m) => {
          // a load the replaced worker never read goes to the new one (the page's own reload of
          // its last scenario then stands aside: a load is pending)
          const again = this.resend;
          this.resend = null;
          if (again) this.lane.load(again.text, again.file, again.map);
          hooks.ready?.(m);
        },
        loaded: (m) => { this.pendingLoad = null; hooks.loaded?.(m); },
        invalid: (e) => { this.pendingLoad = null; hooks.invalid?.(e); },
        error: (message) => {
          hooks.error?.(message);
          if (!this.lane.done && c.fire('fail')) this.lane.clearRun();
        },
        asv: (text) => hooks.asv?.(text),
        query: (answer) => hooks.query?.(answer),
        seed: (seed) => hooks.seed?.(seed),
        stopped: (message, fatal, why) => {
          // Run after Cancel on a worker that did not stop: the run the user asked for starts
          // as soon as the replacement has the scenario again (not after a crash: it would crash again)
          this.rerun = why === 'hung' && !fatal && c.state === 'running';
          // not after a crash: the scenario being loaded may be what crashed the core
          this.resend = why === 'hung' && !fatal ? this.pendingLoad : null;
          hooks.stopped?.(message, fatal, why);
          c.fire(fatal ? 'stop' : 'load');
        },
        revealed: () => this.maybeFinish(),
        finished: () => c.state === 'finished',
        changed: () => { this.mark(); hooks.changed?.(); },
      },
    });
    this.rerun = false;
    this.pendingLoad = null; // {text, file}: the latest load, until its answer
    this.resend = null;
    c.onChange((state, from, event) => {
      if (event === 'loaded' && this.rerun) queueMicrotask(() => this.run());
      if (event === 'loaded' || event === 'invalid' || event === 'stop') this.rerun = false;
    });
    this.frame = this.frame.bind(this);
  }

  get state() { return this.controller.state; }

  /** Start the worker and the frame loop. */
  start() {
    this.lane.start();
    this.raf = requestAnimationFrame(this.frame);
  }

  /** Stop the frame loop and the worker for good (an element taken out of the page). */
  stop() {
    cancelAnimationFrame(this.raf);
    this.raf = 0;
    this.lane.session.stop();
  }

  // Requests

  /**
   * Send a scenario (JSON text; with `file`, any file the core imports) to the worker (in the
   * `stopped` state, to a fresh one).
   */
  load(text, file = null, map = null) {
    this.pendingLoad = { text, file, map };
    this.lane.load(text, file, map);
    this.controller.fire('load');
  }

  /** Choose the planner set-up {planner, params, seed} for the next run. */
  configure(config) {
    if (!this.lane.session.alive) return;
    this.lane.configure(config);
    this.controller.fire('configure');
  }

  // Actions: each returns whether it did anything

  run() {
    const c = this.controller;
    if (!c.can('run')) return false;
    if (c.state === 'finished') this.lane.resetRun();
    c.fire('run');
    this.lane.run();
    return true;
  }

  pause() {
    if (!this.controller.fire('pause')) return false;
    this.lane.pause();
    return true;
  }

  /** Run or pause, whichever fits (the space key). */
  toggle() { return this.controller.state === 'running' ? this.pause() : this.run(); }

  /** Run `n` planner iterations and show them at once, then pause. */
  step(n) {
    if (!this.controller.fire('step')) return false;
    this.lane.step(Math.max(1, Math.floor(Number(n)) || 1));
    return true;
  }

  /** Show one more event (from a run, pause it first; from idle, start it paused). */
  stepEvent() {
    const wasRunning = this.controller.state === 'running';
    if (!this.controller.fire('stepEvent')) return false;
    if (wasRunning) this.lane.pause();
    this.lane.stepEvent();
    return true;
  }

  reset() {
    if (!this.controller.can('reset')) return false;
    this.lane.resetRun();
    this.controller.fire('reset');
    return true;
  }

  cancel() {
    if (!this.controller.can('cancel')) return false;
    const stopped = this.lane.done; // the planner already stopped: show the rest now
    this.lane.cancel();
    if (!stopped) this.controller.fire('cancel');
    return true;
  }

  /** Whether step back can act: a run has started (running, paused or finished). */
  canBack() { return ['running', 'paused', 'finished'].includes(this.controller.state); }

  /**
   * Go back `n` iterations: reset, and replay from the same seed to (iterations shown − n), shown
   * at once and paused there (nothing left: the reset run). Returns the iteration gone back to, or
   * null when it could not act.
   */
  back(n) {
    if (!this.canBack()) return null;
    const target = Math.max(0, this.shownIterations - Math.max(1, Math.floor(Number(n)) || 1));
    this.lane.resetRun();
    this.controller.fire('reset');
    if (target > 0) this.step(target);
    return target;
  }

  // The run's bookkeeping

  mark() {
    const s = this.lane.stats;
    if (!s) { this.marks = []; return; }
    const end = this.playback.store.length + this.playback.pending;
    const last = this.marks[this.marks.length - 1];
    if (!last || last[1] !== s.iterations) this.marks.push([end, s.iterations]);
    else last[0] = end;
  }

  /** The planner iterations whose events are all shown (the worker may be ahead of the playback). */
  get shownIterations() {
    const lane = this.lane;
    if (lane.caughtUp && lane.result?.stats) return lane.result.stats.iterations;
    const shown = this.playback.store.length;
    let it = 0;
    for (const [end, iterations] of this.marks) {
      if (end > shown) break;
      it = iterations;
    }
    return it;
  }

  /**
   * The iteration the replay has reached, for the status strip: whole batches shown, plus the
   * shown share of the batch being revealed (the worker's batches can hold hundreds of
   * iterations). `exact` is false when interpolated.
   */
  replayIteration() {
    const lane = this.lane;
    if (lane.caughtUp && lane.result?.stats) return { iteration: lane.result.stats.iterations, exact: true };
    const shown = this.playback.store.length;
    let prev = [0, 0];
    for (const m of this.marks) {
      if (m[0] > shown) {
        const span = m[0] - prev[0];
        const part = span > 0 ? (shown - prev[0]) / span : 0;
        return { iteration: Math.floor(prev[1] + part * (m[1] - prev[1])), exact: part === 0 };
      }
      prev = m;
    }
    return { iteration: prev[1], exact: true };
  }

  maybeFinish() {
    if (this.lane.caughtUp && this.controller.fire('finish')) this.hooks.changed?.();
    if (this.controller.state === 'finished' && this.lane.showResult()) this.hooks.changed?.();
  }

  /** The status word shown: the controller's state, or the planner's terminal status when finished. */
  statusWord() {
    const lane = this.lane;
    return this.controller.state === 'finished'
      ? (lane.finalStatus || (lane.result?.solved ? 'solved' : 'finished')) : this.controller.state;
  }

  /**
   * The stats shown: the worker's, except that while the replay is behind the planner, iterations
   * and nodes are those drawn (the planner's totals are in `planner_iterations`, `planner_nodes`),
   * and `behind` says how the planner's own numbers are marked: 'final' once it has finished,
   * 'planner' while it runs.
   */
  stats() {
    const s = this.lane.statsFor(this.statusWord(), this.controller.state === 'finished');
    if (!this.lane.caughtUp && s.iterations !== undefined) {
      s.behind = this.lane.done ? 'final' : 'planner'; // what the planner's own numbers are marked
      s.planner_iterations = s.iterations;
      s.planner_nodes = s.nodes;
      s.iterations = this.replayIteration().iteration;
      s.nodes = s.shown_nodes;
    }
    return s;
  }

  frame(time) {
    const dt = Math.min(0.25, (time - (this.lastFrame || time)) / 1000);
    this.lastFrame = time;
    if (this.controller.state === 'running' && this.playback.pending > 0) this.lane.tick(this.duration(), dt);
    else if (this.controller.state === 'running') this.maybeFinish();
    this.view.render(time, this.fps());
    this.hooks.frame?.(time);
    if (this.raf) this.raf = requestAnimationFrame(this.frame);
  }
}

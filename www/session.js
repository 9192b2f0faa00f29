// One planning worker as the page sees it: starts it, sends requests, keeps the bookkeeping that
// decides which replies are current, and replaces the worker when it crashes. The page's run state
// lives in lane.js; the worker's protocol is in worker.js's header.
//
// Staleness: `run` in a reply is the worker's counter (bumped on every load/configure/reset). The
// session remembers the latest counter it saw in a status/loaded/invalid reply, and how many
// load/configure/reset requests are still unanswered: events and results are passed on only when
// they belong to the latest counter and nothing is pending. Only the answer to the latest load
// is passed on.

export class WorkerSession {
  /**
   * `hooks`: {ready(msg), loaded(msg), invalid(error), events(msg), result(msg), error(message),
   * asv(text), stopped(message, fatal)}; `stopped` is called when the worker died (a panic or a
   * failed start): the session starts a new one, whose `ready` follows, unless the worker keeps
   * dying (`fatal`: more than 3 times in 10 s).
   */
  constructor(hooks) {
    this.hooks = hooks;
    this.worker = null;
    this.crashes = [];
  }

  start() {
    const w = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.worker = w;
    this.latestRun = -1;      // `run` of the latest status/loaded/invalid message
    this.bumpsPending = 0;    // load/configure/reset sent, not yet answered: drop events until answered
    this.loadsPending = 0;
    w.onmessage = (e) => { if (w === this.worker) this.onMessage(e.data); };
    w.onerror = (e) => {
      e.preventDefault();
      if (w === this.worker) this.recover(e.message || 'the worker failed to start');
    };
    w.onmessageerror = () => { if (w === this.worker) this.recover('a message from the worker could not be read'); };
  }

  get alive() { return !!this.worker; }

  send(msg) { this.worker?.postMessage(msg); }

  /** Send a scenario (or, with `file`, any file the core imports). */
  load(text, file = null) {
    if (!this.worker) return;
    this.loadsPending++;
    this.bumpsPending++;
    this.send(file ? { type: 'import', text, name: file } : { type: 'load', text });
  }

  /** Choose the planner set-up {planner, params, seed}. */
  configure(config) {
    if (!this.worker) return;
    this.bumpsPending++;
    this.send({ type: 'configure', ...config });
  }

  reset() {
    if (!this.worker) return;
    this.bumpsPending++;
    this.send({ type: 'reset' });
  }

  /** Whether a reply for a run (events, result) is current. */
  current(msg) { return msg.run === this.latestRun && !this.bumpsPending; }

  recover(message) {
    this.worker.terminate();
    this.worker = null;
    const now = performance.now();
    this.crashes = this.crashes.filter((t) => now - t < 10000).concat(now);
    const fatal = this.crashes.length > 3;
    this.hooks.stopped?.(message, fatal);
    if (!fatal) this.start(); // its `ready` lets the page reload the scenario and configuration
  }

  onMessage(msg) {
    const h = this.hooks;
    switch (msg.type) {
      case 'ready': h.ready?.(msg); return;
      case 'loaded':
      case 'invalid':
        this.latestRun = msg.run;
        this.bumpsPending = Math.max(0, this.bumpsPending - 1);
        if (--this.loadsPending > 0) return; // a newer load is on its way
        this.loadsPending = 0;
        if (msg.type === 'loaded') h.loaded?.(msg); else h.invalid?.(msg.error);
        return;
      case 'status':
        this.latestRun = msg.run;
        if (msg.status === 'idle') this.bumpsPending = Math.max(0, this.bumpsPending - 1);
        return;
      case 'events':
        if (this.current(msg)) h.events?.(msg);
        return;
      case 'result':
        if (this.current(msg)) h.result?.(msg);
        return;
      case 'error': h.error?.(msg.message); return;
      case 'asv-solution':
        if (msg.run === this.latestRun) h.asv?.(msg.text);
        return;
      case 'crashed': this.recover(msg.message); return;
      default:
        console.warn('unknown message from the worker', msg.type);
    }
  }
}

// One planning worker as the page sees it: starts it, sends requests, keeps the bookkeeping that
// decides which replies are current, and replaces the worker when it crashes. The page's run state
// lives in lane.js; the worker's protocol is in worker.js's header, its types in messages.js.
//
// Staleness: `run` in a reply is the worker's counter (bumped on every load/configure/reset). The
// session remembers the latest counter it saw in a status/loaded/invalid reply, and how many
// load/configure/reset requests are still unanswered: events and results are passed on only when
// they belong to the latest counter and nothing is pending. Only the answer to the latest load
// is passed on.
//
// Watchdog: cancel, reset, configure and load/import carry `ack: n`, which the worker answers as
// soon as it reads the message. A worker that has not acknowledged one within WATCHDOG_MS (a
// planning batch that does not end) is terminated and replaced, as after a crash, and `stopped`
// says so in words. Deaths (crashes and replacements) are counted: after more than CRASH_LIMIT
// within CRASH_WINDOW_MS the session stops replacing the worker on its own (`fatal`), and the next
// load() starts a fresh one (a user who picks a scenario or opens a file always gets a worker).

import { WATCHDOG_MS, CRASH_LIMIT, CRASH_WINDOW_MS } from './limits.js';
import { learn } from '../draw/capabilities.js';

/** What `stopped` says when a worker did not acknowledge a message in time, per message type. */
const HUNG = {
  cancel: 'The planner did not stop within a second; it was restarted.',
  reset: 'The planner did not reset within a second; it was restarted.',
  configure: 'The planner did not take the new set-up within a second; it was restarted.',
  load: 'The planner did not take the new scenario within a second; it was restarted.',
};
HUNG.import = HUNG.load;

export class WorkerSession {
  /**
   * `hooks`: {ready(msg), loaded(msg), invalid(error), events(msg), result(msg), error(message),
   * asv(text), seed(seed), stopped(message, fatal, why)}; `stopped` is called when the worker died (why:
   * 'crashed', a panic or a failed start) or was replaced by the watchdog (why: 'hung'; the message
   * says so in words): the session starts a new one, whose `ready` follows, unless the worker keeps
   * dying (`fatal`: more than CRASH_LIMIT times in CRASH_WINDOW_MS; the next load() starts one).
   */
  constructor(hooks) {
    this.hooks = hooks;
    this.worker = null;
    this.crashes = [];
    this.acks = new Map(); // ack number → {type, sent}: watched messages not yet acknowledged
    this.ackSeq = 0;
    this.watchdog = 0;
  }

  start() {
    const w = new Worker(new URL('../worker/worker.js', import.meta.url), { type: 'module' });
    this.worker = w;
    this.latestRun = -1;      // `run` of the latest status/loaded/invalid message
    this.bumpsPending = 0;    // load/configure/reset sent, not yet answered: drop events until answered
    this.loadsPending = 0;
    this.acks.clear();
    clearTimeout(this.watchdog);
    w.onmessage = (e) => { if (w === this.worker) this.onMessage(e.data); };
    w.onerror = (e) => {
      e.preventDefault();
      if (w === this.worker) this.recover(e.message || 'the worker failed to start');
    };
    w.onmessageerror = () => { if (w === this.worker) this.recover('a message from the worker could not be read'); };
  }

  get alive() { return !!this.worker; }

  /** @param {import('./messages.js').WorkerIn} msg @param {Transferable[]} [transfer] */
  send(msg, transfer = []) { this.worker?.postMessage(msg, transfer); }

  /**
   * Send `msg` and expect the worker to acknowledge it within WATCHDOG_MS.
   * @param {import('./messages.js').WorkerRequest} msg @param {Transferable[]} [transfer]
   */
  sendWatched(msg, transfer = []) {
    if (!this.worker) return;
    const ack = ++this.ackSeq;
    this.acks.set(ack, { type: msg.type, sent: performance.now() });
    this.send({ ...msg, ack }, transfer);
    this.armWatchdog();
  }

  /** Time the oldest unacknowledged message. */
  armWatchdog() {
    clearTimeout(this.watchdog);
    const oldest = this.acks.values().next().value;
    if (!oldest) return;
    const left = Math.max(0, oldest.sent + WATCHDOG_MS - performance.now());
    const due = performance.now() + left + 5;
    this.watchdog = setTimeout(() => {
      const late = this.acks.values().next().value;
      if (!late || !this.worker) return;
      if (performance.now() - late.sent < WATCHDOG_MS) { this.armWatchdog(); return; }
      // The page itself was busy past the deadline (a long task): the worker's ack may be queued
      // behind this timer. Look again once the queue has had a moment, rather than kill a healthy worker.
      if (performance.now() - due > 50 && !late.graced) {
        late.graced = true;
        this.watchdog = setTimeout(() => this.armWatchdog(), 100);
        return;
      }
      this.recover(HUNG[late.type] || HUNG.cancel, 'hung');
    }, left + 5);
  }

  /**
   * Send a scenario (or, with `file`, any file the core imports; with `map`, an occupancy map:
   * an image's bytes and/or a map_server YAML's text). Without a worker (it kept crashing:
   * `fatal`), a fresh one is started first, the crash count forgotten.
   * @param {string} text @param {string | null} [file]
   * @param {{bytes: ArrayBuffer | null, yaml?: string | null, yamlName?: string | null} | null} [map]
   */
  load(text, file = null, map = null) {
    if (!this.worker) {
      this.crashes = [];
      this.start();
    }
    this.loadsPending++;
    this.bumpsPending++;
    if (map) {
      // An occupancy map: the image's bytes (a copy is transferred, so the page keeps its own
      // for a resend) and the YAML's text, decoded by the core.
      const bytes = map.bytes ? map.bytes.slice(0) : null;
      this.sendWatched({ type: 'import', text: '', name: file || '', bytes, yaml: map.yaml ?? null, yamlName: map.yamlName ?? null },
        bytes ? [bytes] : []);
      return;
    }
    this.sendWatched(file ? { type: 'import', text, name: file } : { type: 'load', text });
  }

  /** Choose the planner set-up {planner, params, seed}. */
  configure(config) {
    if (!this.worker) return;
    this.bumpsPending++;
    this.sendWatched({ type: 'configure', ...config });
  }

  reset() {
    if (!this.worker) return;
    this.bumpsPending++;
    this.sendWatched({ type: 'reset' });
  }

  /** Stop the run now (the worker's events and result with status `cancelled` follow). */
  cancel() { this.sendWatched({ type: 'cancel' }); }

  /** Whether a reply for a run (events, result) is current. */
  current(msg) { return msg.run === this.latestRun && !this.bumpsPending; }

  recover(message, why = 'crashed') {
    this.worker.terminate();
    this.worker = null;
    this.acks.clear();
    clearTimeout(this.watchdog);
    const now = performance.now();
    this.crashes = this.crashes.filter((t) => now - t < CRASH_WINDOW_MS).concat(now);
    const fatal = this.crashes.length > CRASH_LIMIT;
    this.hooks.stopped?.(message, fatal, why);
    if (!fatal) this.start(); // its `ready` lets the page reload the scenario and configuration
  }

  /** Stop the worker for good (an element taken out of the page). */
  stop() {
    this.worker?.terminate();
    this.worker = null;
    this.acks.clear();
    clearTimeout(this.watchdog);
  }

  /** @param {import('./messages.js').WorkerOut} msg */
  onMessage(msg) {
    const h = this.hooks;
    switch (msg.type) {
      case 'ready': learn(msg); h.ready?.(msg); return; // the registry's capabilities (capabilities.js)
      case 'ack':
        this.acks.delete(msg.ack);
        this.armWatchdog();
        return;
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
      case 'query':
        if (this.current(msg)) h.query?.(msg);
        return;
      case 'seed': h.seed?.(msg.seed); return;
      case 'crashed': this.recover(msg.message); return;
      default:
        console.warn('unknown message from the worker', /** @type {any} */ (msg).type); // a worker newer than the page
    }
  }
}

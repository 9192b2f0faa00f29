// <planarium-playground>: one scenario and a few chosen controls, for course notes and slides.
//
//   <script type="module" src="planarium/planarium-playground.js"></script>
//   <planarium-playground scenario="narrow" planner="rrt-connect" seed="7" autoplay controls="step,reset">
//   </planarium-playground>
//
// Attributes (the share-link grammar of ui/links.js, one key per attribute): scenario, planner, seed,
// speed, anim, overlays, step-size, raw-path, camera, zoom, autoplay, click, controls; `params` for planner
// parameters in link form ("range=0.1&goal_bias=0.2"); `link` for a whole share link's hash (the
// other attributes win over it); `fill` to fill the element's height (embed.html) instead of
// taking the height the scenario's aspect ratio gives the element's width.
//
// Shadow DOM; the canvas scales to the element's width and keeps the scenario's aspect ratio (a spatial
// arm's scene: its 3-D view beside it, the two side by side or stacked, with a link's camera). Keys
// (space run / pause, → step, ← step back, r reset; only those whose control is shown) act only
// while the element has focus: no listener on the document. The planning worker is loaded from
// this module's folder (worker.js next to it), so the page must come from the same origin as this
// file (a worker cannot be started across origins; use embed.html in an iframe there).
// Read-only state for scripts and tests: el.state, el.status, el.result(), el.stats(), el.nodeCount,
// el.shownIterations, el.controls, el.view3dState(); and el.run(), pause(), step(), back(), reset().
// Events (CustomEvent, bubbling, composed): `loaded` (a scenario and set-up are ready to run), `run`
// (a run starts or resumes), `step` (a step's answer is shown), `solved` (a run ended with a path);
// their detail types are in planarium-playground.d.ts. A planner that draws a field shows its heat
// map unless `overlays` names it (`-show-heat`). For keyboard and screen-reader users (ui/a11y.js,
// as the playground): the focus stays in the bar when the focused button turns off (Run → Pause);
// one live region speaks the run at most about once a second while it plays and in full (the
// status and the step's caption) when it is paused, stepped or done; the canvas's text names the
// nodes drawn and the path.
// The status line shows the iterations and nodes drawn so far, rising while the run plays; Step on a
// finished run replays it from its start, step by step; after an autoplay run Reset is offered.

import { Playback } from './run/playback.js';
import { View } from './draw/view.js';
import { View3dSlot } from './draw/view3d-slot.js';
import { PALETTE } from './draw/palette.js';
import { Player } from './run/player.js';
import { fitViews } from './draw/stage.js';
import { speedSeconds, animFps, describeSpeed } from './ui/controls.js';
import { readShare, setupFor, configOf, overlayOptions, boundedProblems, DEFAULT_CONTROLS, VIEW_DEFAULTS, MAX_PAIRS } from './ui/links.js';
import { MAX_HASH_CHARS } from './ui/scenario-codec.js';
import { applyPageLimits } from './run/limits.js';
import { shown } from './ui/text.js';
import { readSeed } from './ui/seed.js';
import { wireA11y, StepCaption } from './ui/a11y.js';
import { wirePlaneZoom, zoomBar } from './ui/plane-zoom.js';
import { plannerCaps } from './draw/capabilities.js';

const KEYS = ['scenario', 'planner', 'seed', 'speed', 'anim', 'overlays', 'step-size', 'raw-path', 'camera', 'zoom', 'autoplay', 'click', 'controls'];
const FLAGS = ['raw-path', 'autoplay', 'click'];
const LABELS = { run: 'Run', pause: 'Pause', step: 'Step', back: 'Step back', reset: 'Reset' };
const TITLES = {
  run: 'Run (space)', pause: 'Pause (space)', step: 'Run more iterations, then pause (→)',
  back: 'Go back: the run is replayed from its seed (←)', reset: 'Reset (r)',
};

const CSS = `
:host { display: block; position: relative; min-width: 0; font: 14px/1.35 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
  color: #1d2127; text-align: left; }
:host([hidden]) { display: none; }
:host(:focus) { outline: none; }
:host(:focus-visible) .stage canvas { outline: 2px solid #e67e00; outline-offset: 1px; }
:host([fill]) { display: flex; flex-direction: column; height: 100%; }
.stage { position: relative; display: flex; align-items: center; justify-content: center; overflow: hidden; width: 100%; min-height: 40px;
  column-gap: 6px; row-gap: 6px; }
.stage.stacked { flex-direction: column; }
:host([fill]) .stage { flex: 1 1 auto; min-height: 0; }
canvas { display: block; background: #eef0f3; border-radius: 4px; }
.start { position: absolute; inset: 0; margin: auto; width: max-content; height: max-content; padding: 0.5rem 1.1rem;
  font: inherit; font-size: 1.05rem; border: 0; border-radius: 999px; background: rgba(31, 78, 154, 0.92); color: #fff; cursor: pointer;
  box-shadow: 0 1px 4px rgba(0, 0, 0, 0.3); }
.bar { display: flex; flex-wrap: wrap; align-items: center; gap: 0.3rem 0.4rem; padding-top: 0.35rem; }
.bar:empty { display: none; }
button { font: inherit; font-size: 0.88rem; padding: 0.2rem 0.55rem; border: 1px solid #b9bfc8; border-radius: 4px; background: #f3f5f8;
  color: #1d2127; cursor: pointer; }
button:hover:not(:disabled) { background: #e7ebf0; }
button:disabled { opacity: 0.45; cursor: default; }
button:focus-visible, input:focus-visible { outline: 2px solid #e67e00; outline-offset: 1px; }
label { display: inline-flex; align-items: center; gap: 0.3rem; font-size: 0.85rem; color: #5d6470; }
input[type="range"] { width: 7rem; }
input[type="number"] { width: 5rem; font: inherit; padding: 0.15rem 0.3rem; border: 1px solid #b9bfc8; border-radius: 4px; }
.status { margin-left: auto; font-size: 0.85rem; color: #5d6470; font-variant-numeric: tabular-nums; }
.status[data-status="solved"] { color: #007a5a; }
.message { margin: 0.35rem 0 0; padding: 0.3rem 0.5rem; border: 1px solid #a8362b; border-radius: 4px; background: #fdecea;
  color: #5a1710; font-size: 0.82rem; white-space: pre-wrap; overflow-wrap: anywhere; max-height: 12em; overflow: auto; flex: none; }
[hidden] { display: none !important; }
.plane-zoom { position: absolute; left: 4px; bottom: 4px; z-index: 1; display: flex; gap: 3px; }
.plane-zoom button { font-size: 0.8rem; padding: 0.1rem 0.45rem; min-width: 1.8rem; background: rgba(243, 245, 248, 0.92); }
.sr-only { position: absolute; width: 1px; height: 1px; padding: 0; margin: -1px; overflow: hidden; clip: rect(0 0 0 0);
  white-space: nowrap; border: 0; }
`;

const el = (tag, props = {}) => Object.assign(document.createElement(tag), props);
/** `s` with lone surrogates as U+FFFD (encodeURIComponent throws on them; an attribute may hold one). */
const wellFormed = (s) => (typeof s.toWellFormed === 'function' ? s.toWellFormed()
  : s.replace(/[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/g, '\uFFFD'));

/**
 * The element's CSS for shadow root `root`: a constructed style sheet, which a page's
 * Content-Security-Policy (style-src without 'unsafe-inline', as Planarium's own pages) allows;
 * a <style> element (returned, to append) only where constructed sheets are missing.
 */
let sheet = null;
function adoptStyle(root) {
  if ('adoptedStyleSheets' in Document.prototype && typeof CSSStyleSheet.prototype.replaceSync === 'function') {
    if (!sheet) { sheet = new CSSStyleSheet(); sheet.replaceSync(CSS); }
    root.adoptedStyleSheets = [sheet];
    return null;
  }
  return el('style', { textContent: CSS });
}

export class PlanariumPlayground extends HTMLElement {
  static get observedAttributes() { return [...KEYS, 'params', 'link']; }

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    const style = adoptStyle(root);
    this.canvas = el('canvas');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('part', 'canvas');
    this.startButton = el('button', { className: 'start', type: 'button', textContent: '▶ Run', hidden: true });
    this.startButton.dataset.control = 'start';
    this.stage = el('div', { className: 'stage' });
    // a spatial arm's 3-D view beside the top view (www/draw3d/, imported only for such a scene)
    this.canvas3d = el('canvas', { hidden: true });
    this.canvas3d.setAttribute('role', 'img');
    this.canvas3d.setAttribute('part', 'view3d');
    this.canvas3d.setAttribute('aria-label', 'The arm in 3-D: drag to turn, wheel or pinch to zoom, double-click to frame the problem');
    // zoom and pan on the top view (ui/plane-zoom.js): the wheel and keys once the embed has the focus
    this.zoomBar = zoomBar();
    this.zoomBar.addEventListener('click', (e) => e.stopPropagation()); // not the stage's click-to-run
    this.stage.append(this.canvas, this.startButton, this.zoomBar); // the 3-D canvas joins only for a scene that has one
    this.bar = el('div', { className: 'bar' });
    this.message = el('p', { className: 'message', hidden: true });
    this.message.setAttribute('role', 'alert');
    // the one live region (ui/a11y.js): the run at most about once a second while it plays, in full
    // (the status and the step's caption) when it is paused, stepped or done
    this.announcer = el('p', { className: 'sr-only' });
    this.announcer.setAttribute('role', 'status');
    this.announcer.setAttribute('aria-atomic', 'true');
    root.append(...(style ? [style] : []), this.stage, this.bar, this.message, this.announcer);
    this.player = null;
    this.share = null;
    this.registry = null;
    this.builtins = [];
    this.started = false; // autoplay / click: the run has been started once
    this.crashNote = '';  // why the worker stopped, kept until the user acts
    this.pending = 0;
    this.stepsAsked = 0; // steps asked whose answer is not shown yet (the `step` event)
    this.acted = false;  // a control was used since the last restore
    this.aspect = 1;
    this.shown = [];
    this.onKey = this.onKey.bind(this);
    this.stage.addEventListener('pointerdown', () => this.focus({ preventScroll: true }));
    this.stage.addEventListener('click', () => this.startOnClick());
    this.playback = new Playback();
    this.view = new View(this.canvas, this.playback.store, this.playback.model);
    wirePlaneZoom({ canvas: this.canvas, view: this.view, bar: this.zoomBar, keys: this, keysWhen: () => true,
      wheelWhen: () => document.activeElement === this });
    this.view3d = new View3dSlot(this.canvas3d, this.playback.store, PALETTE, () => { this.sizeStage?.(); this.resize?.(); });
    this.stepCaption = new StepCaption(this.playback.store);
    this.resize = null;
    // focus kept in the bar when the focused button turns off (Run → Pause), the live region, the
    // canvas's text of its state: the playground's own (ui/a11y.js), in the shadow root
    this.a11y = wireA11y({ bar: this.bar, live: this.announcer, canvas: this.canvas, root,
      read: () => ({ state: this.state, status: this.statusText?.textContent || this.status, caption: this.stepCaption.caption,
        name: this.scenario?.name, nodes: this.nodeCount, result: this.player?.lane.result ?? null,
        bestCost: this.playback.model.bestCost }) });
  }

  connectedCallback() {
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    this.addEventListener('keydown', this.onKey);
    if (this.player) return;
    this.player = new Player({
      playback: this.playback,
      views: [this.view, this.view3d, this.stepCaption],
      duration: () => speedSeconds(this.speedInput || { value: String(this.share?.view.speed ?? VIEW_DEFAULTS.speed), max: '100' }),
      fps: () => animFps({ value: String(this.share?.view.anim ?? VIEW_DEFAULTS.anim) }),
      hooks: {
        ready: (msg) => this.onReady(msg),
        loaded: (msg) => this.onLoaded(msg),
        invalid: (error) => this.onInvalid(error),
        error: (message) => this.say(message),
        stopped: (message, fatal, why) => this.onStopped(message, fatal, why),
        changed: () => { this.sync(); this.stepShown(); },
        frame: () => {
          this.view3d.render(performance.now(), this.player.fps());
          if (this.player?.state === 'running') this.syncStatus(); // the counts rise as the playback reveals the run
          this.a11y.update();
        },
      },
    });
    this.player.controller.onChange((to, from, event) => { this.sync(); this.announce(to, from, event); this.a11y.update(); });
    this.sizeStage = () => {
      if (this.hasAttribute('fill')) { this.stage.style.height = ''; return; }
      const w = this.stage.clientWidth;
      if (!w) return;
      // Layout.fit keeps a 10 px margin around the bounds
      const h = this.view3d.active ? (w - 6) / 2 : (w - 20) / this.aspect + 20; // the 3-D view beside: two squares
      const cap = Math.max(160, (window.innerHeight || 800) * 0.85);
      this.stage.style.height = `${Math.round(Math.min(h, cap))}px`;
    };
    this.hostObserver = new ResizeObserver(() => this.sizeStage());
    this.hostObserver.observe(this);
    this.sizeStage();
    const slot = this.view3d;
    this.resize ||= fitViews(this.stage, this.view, {
      get active() { return slot.active; },
      resize(w, h, dpr) { if (slot.active) slot.resize(w, h, dpr); },
    });
    this.player.start();
  }

  disconnectedCallback() {
    this.removeEventListener('keydown', this.onKey);
    this.hostObserver?.disconnect();
    this.seenObserver?.disconnect();
    this.player?.stop();
    this.player = null;
  }

  attributeChangedCallback() {
    if (!this.registry) return; // read once the worker is ready
    clearTimeout(this.pending);
    this.pending = setTimeout(() => this.restore(), 0);
  }

  /**
   * The element's attributes as a share link's hash {text, problems}: `link`, then `params`, then
   * the explicit attributes (which win over the same keys in the other two). `link` and `params`
   * are read within the link limits left once the explicit attributes have their room (links.js
   * MAX_PAIRS pairs, MAX_HASH_CHARS characters), so an oversized `params` is cut, and said so, but
   * never pushes `scenario`, `planner` or `seed` out of the link.
   */
  linkText() {
    const own = [];
    for (const key of KEYS) {
      if (!this.hasAttribute(key)) continue;
      const v = this.getAttribute(key);
      if (FLAGS.includes(key) && v === '') own.push(key);
      else own.push(`${key}=${encodeURIComponent(wellFormed(v))}`);
    }
    const problems = [];
    let pairs = MAX_PAIRS - own.length;
    let chars = MAX_HASH_CHARS - own.join('&').length - 2;
    const parts = [];
    for (const name of ['link', 'params']) {
      const text = (this.getAttribute(name) || '').replace(/^[#?&]/, '');
      if (!text) continue;
      const all = text.split('&').filter(Boolean);
      let kept = all.slice(0, Math.max(0, pairs));
      let joined = kept.join('&');
      while (kept.length && joined.length > chars) { // whole pairs only
        kept = kept.slice(0, Math.max(0, Math.min(kept.length - 1, Math.floor((kept.length * chars) / joined.length))));
        joined = kept.join('&');
      }
      if (kept.length < all.length) {
        problems.push(`The ${name} attribute has ${all.length.toLocaleString('en')} parts (${text.length.toLocaleString('en')} characters), `
          + `more than an embed reads; only the first ${kept.length.toLocaleString('en')} were read (the other attributes still apply).`);
      }
      if (!kept.length) continue;
      parts.push(joined);
      pairs -= kept.length;
      chars -= joined.length + 1;
    }
    return { text: [...parts, ...own].join('&'), problems };
  }

  // The worker's answers

  onReady(msg) {
    const first = !this.registry;
    this.registry = applyPageLimits(msg.planners);
    this.builtins = msg.builtins;
    if (first) this.restore();
    else if (!this.player.lane.session.loadsPending) { // after a crash: the same again
      if (this.scenarioText) this.player.load(this.scenarioText);
      else if (this.share) this.loadShared(); // it crashed on load: try again (repeated crashes end in `stopped`)
    }
  }

  /**
   * The worker crashed or was replaced: the note stays (the reload that follows, and its
   * `loaded`, do not wipe it) until the user acts; after repeated crashes (`fatal`) nothing runs
   * and the status says `stopped`.
   */
  onStopped(message, fatal, why) {
    const what = why === 'hung' ? message : `The planning worker stopped: ${message}`;
    this.crashNote = fatal
      ? `The planning worker keeps stopping (${message}). Reload the page to try again.`
      : what;
    this.say(this.notes());
  }

  /** The crash note (if any) and the settings that could not be used, as one message. */
  notes() {
    const problems = this.problems?.length ? `Some of this embed's settings could not be used:\n• ${boundedProblems(this.problems, 8).join('\n• ')}` : '';
    return [this.crashNote, problems].filter(Boolean).join('\n');
  }

  async restore() {
    const link = this.linkText();
    const share = await readShare(link.text, { builtins: this.builtins });
    this.share = share;
    this.problems = [...link.problems, ...share.problems];
    this.crashNote = '';
    this.started = false;
    this.acted = false;
    this.stepsAsked = 0;
    this.buildControls(share.controls ?? DEFAULT_CONTROLS);
    this.view.setOptions({ ...overlayOptions(share.overlays), animateRaw: !!share.view.rawPath });
    if (!share.scenario) this.problems.push('No scenario given (scenario=…): the first built-in is shown.');
    this.loadShared();
  }

  /** Load the scenario the link names: its JSON, a built-in, or the first built-in. */
  loadShared() {
    const share = this.share;
    const b = share.scenario?.id ? this.builtins.find((x) => x.id === share.scenario.id) : null;
    if (share.scenario?.text) this.player.load(share.scenario.text);
    else if (b) this.player.load(JSON.stringify(b.scenario));
    else this.player.load(JSON.stringify(this.builtins[0].scenario));
  }

  onLoaded(msg) {
    this.scenarioText = JSON.stringify(msg.scenario);
    this.scenario = msg.scenario;
    const [x0, y0, x1, y1] = msg.scenario.bounds;
    this.aspect = (x1 - x0) / (y1 - y0) || 1;
    this.view.pendingViewport = this.share.view.zoom ?? null; // a link's zoom (once per restore)
    this.share.view.zoom = null;
    this.view.setScenario(msg.scenario, msg.start, msg.goal);
    this.view3d.setCamera(this.share.view.camera ?? null); // a link's camera (once per restore)
    this.share.view.camera = null;
    if (!msg.caps?.view3d) this.canvas3d.remove(); // a host page's `canvas` selectors find the top view alone
    else if (!this.canvas3d.isConnected) this.canvas.after(this.canvas3d);
    this.view3d.setScene(msg.spatial || null, !!msg.caps?.view3d);
    this.sizeStage();
    this.resize();
    const { block, problems } = setupFor(this.share, msg.scenario, this.registry);
    this.config = configOf(block);
    // a planner that draws a field shows its heat map unless the overlays attribute says otherwise (as the playground)
    if (!Object.hasOwn(this.share.overlays, 'showHeat')) this.view.setOptions({ showHeat: plannerCaps(this.config.planner).draws === 'field' });
    this.stepCaption.setPlanner(this.config, msg.scenario.robot?.kind);
    if (this.seedInput) this.seedInput.value = String(this.config.seed);
    this.player.configure(this.config);
    this.player.controller.fire('loaded');
    this.problems.push(...problems);
    this.say(this.notes());
    if (this.share.autoplay && !this.started) this.autoplayWhenSeen();
    this.sync();
    const spec = this.registry?.planners?.find((/** @type {{name: string}} */ q) => q.name === this.config.planner);
    this.emit('loaded', { scenario: this.scenario?.name ?? '', planner: this.config.planner ?? '', plannerLabel: spec?.label ?? this.config.planner ?? '', seed: this.config.seed ?? null });
  }

  /**
   * Autoplay starts when at least half the element is on screen (a reader scrolling to it sees
   * the run from its start, not its end); at once where IntersectionObserver is missing.
   */
  autoplayWhenSeen() {
    const start = () => {
      this.seenObserver?.disconnect();
      this.seenObserver = null;
      if (this.started || this.player?.state !== 'idle') return;
      this.started = true;
      this.player.run();
      this.sync();
    };
    if (typeof IntersectionObserver !== 'function') { start(); return; }
    this.seenObserver?.disconnect();
    this.seenObserver = new IntersectionObserver((entries) => {
      if (entries.some((e) => e.isIntersecting)) start();
    }, { threshold: 0.5 });
    this.seenObserver.observe(this);
  }

  onInvalid(error) {
    const where = error.path ? ` at ${error.path}` : error.line != null ? ` at line ${error.line}` : '';
    this.problems.push(`The scenario is not valid${where}: ${error.message || error.text}. The first built-in is shown instead.`);
    this.player.controller.fire('invalid');
    if (this.share.scenario) {
      this.share.scenario = null;
      this.player.load(JSON.stringify(this.builtins[0].scenario));
    }
  }

  say(text) {
    this.message.textContent = shown(text);
    this.message.hidden = !text;
  }

  // Controls

  buildControls(names) {
    this.shown = names;
    this.buttons = {};
    this.speedInput = null;
    this.seedInput = null;
    const items = [];
    for (const name of names) {
      if (LABELS[name]) {
        const b = el('button', { type: 'button', id: name, textContent: LABELS[name], title: TITLES[name] });
        b.dataset.control = name;
        b.setAttribute('part', `button ${name}`);
        b.addEventListener('click', () => this.act(name));
        this.buttons[name] = b;
        items.push(b);
      } else if (name === 'speed') {
        const input = el('input', { type: 'range', min: '0', max: '100', step: '1', value: String(this.share.view.speed ?? VIEW_DEFAULTS.speed) });
        const out = el('output', { textContent: describeSpeed(input) });
        input.addEventListener('input', () => { out.textContent = describeSpeed(input); });
        const label = el('label', { title: 'Playback speed' });
        label.dataset.control = 'speed';
        label.append('Speed', input, out);
        this.speedInput = input;
        items.push(label);
      } else if (name === 'seed') {
        const input = el('input', { type: 'number', min: '0', step: '1', value: String(this.config?.seed ?? this.share.seed ?? 1), inputMode: 'numeric' });
        input.addEventListener('change', () => {
          if (!this.config) return;
          const r = readSeed(input.value);
          if (r.why) { // refused: the field shows the seed that runs, the message why
            input.value = String(this.config.seed);
            this.say([this.notes(), `Seed: ${r.why}; the seed stays ${this.config.seed}.`].filter(Boolean).join('\n'));
            return;
          }
          this.say(this.notes());
          this.config = { ...this.config, seed: r.seed };
          this.player.configure(this.config);
        });
        const label = el('label', { title: 'Random seed: the same seed replays the same run' });
        label.dataset.control = 'seed';
        label.append('Seed', input);
        this.seedInput = input;
        items.push(label);
      }
    }
    this.statusText = el('span', { className: 'status' }); // not a live region: this.announcer speaks the run
    this.bar.replaceChildren(...items, this.statusText);
  }

  stepSize() { return this.share?.view.stepSize ?? VIEW_DEFAULTS.stepSize; }

  act(name) {
    const p = this.player;
    if (!p) return false;
    this.started = true;
    this.acted = true;
    if (this.crashNote && p.controller.state !== 'stopped') { this.crashNote = ''; this.say(this.notes()); }
    switch (name) {
      case 'run': return p.run();
      case 'pause': return p.pause();
      case 'toggle': return p.toggle();
      case 'step': // a finished run (autoplay's, say) is replayed from its start, step by step
        if (p.controller.state === 'finished') p.reset();
        if (!p.step(this.stepSize())) return false;
        this.stepsAsked++;
        return true;
      case 'back': return p.back(this.stepSize()) !== null;
      case 'reset': this.stepsAsked = 0; return p.reset();
      default: return false;
    }
  }

  startOnClick() {
    if (!this.share?.click || this.started || !this.player?.controller.can('run')) return;
    this.started = true;
    this.player.run();
    this.sync();
  }

  onKey(e) {
    if (e.ctrlKey || e.metaKey || e.altKey || (e.repeat && e.key !== 'ArrowRight')) return;
    if (e.shiftKey && e.key.startsWith('Arrow')) return; // shift + an arrow pans the map
    const t = e.composedPath()[0];
    if (t instanceof Element && t.closest('input, select, textarea, [contenteditable]')) return;
    const has = (n) => this.shown.includes(n);
    let name = null;
    if (e.key === ' ' && (has('run') || has('pause'))) name = this.state === 'running' ? (has('pause') ? 'pause' : null) : (has('run') ? 'run' : null);
    else if (e.key === 'ArrowRight' && has('step')) name = 'step';
    else if (e.key === 'ArrowLeft' && has('back')) name = 'back';
    else if ((e.key === 'r' || e.key === 'R') && has('reset')) name = 'reset';
    if (!name) return;
    e.preventDefault();
    e.stopPropagation(); // a slide deck's own keys stay out of it while the embed has focus
    this.act(name);
  }

  sync() {
    const p = this.player;
    if (!p || !this.statusText) return;
    const c = p.controller;
    const can = { run: c.can('run'), pause: c.can('pause'), step: c.can('step') || c.state === 'finished', back: p.canBack(), reset: c.can('reset') };
    for (const [name, b] of Object.entries(this.buttons || {})) b.disabled = !can[name];
    this.a11y.refocus(); // Run → Pause: the focus stays in the bar
    if (this.seedInput) this.seedInput.disabled = c.state === 'loading';
    this.startButton.hidden = !(this.share?.click && !this.started && c.state === 'idle');
    this.offerReset(c.state);
    this.syncStatus();
    this.dataset.state = c.state;
  }

  /**
   * The status line: the state word and, once a run has begun, the iterations and nodes the
   * playback has drawn (player.stats(): the replay's, not the worker's, which may be far ahead).
   * Called by sync() and on every frame while running; the text is written only when it changes.
   */
  syncStatus() {
    const p = this.player;
    if (!p || !this.statusText) return;
    const state = p.controller.state;
    const s = p.stats();
    const word = s.status === 'no_path' ? 'no path' : s.status;
    // a run that has begun but not yet drawn its first batch counts from zero, so the line's
    // shape does not change under a reader (or a screen reader) between its first two frames
    const counted = s.iterations != null || state === 'running';
    const text = counted && state !== 'loading' && state !== 'idle'
      ? `${word} · ${Number(s.iterations ?? 0).toLocaleString('en')} iterations · ${Number(s.nodes ?? s.shown_nodes ?? 0).toLocaleString('en')} nodes` : word;
    if (this.statusText.textContent !== text) this.statusText.textContent = text;
    if (this.statusText.dataset.status !== s.status) this.statusText.dataset.status = s.status;
  }

  /**
   * After an autoplay run has ended, Reset is offered even where `controls` did not ask for it
   * (but some control is shown): the reader can then run or step it again from the start.
   */
  offerReset(state) {
    if (!this.share?.autoplay || this.buttons?.reset || !this.bar.querySelector('[data-control]')) return;
    if (state !== 'finished') return;
    const b = el('button', { type: 'button', id: 'reset', textContent: LABELS.reset, title: TITLES.reset });
    b.dataset.control = 'reset';
    b.setAttribute('part', 'button reset');
    b.addEventListener('click', () => this.act('reset'));
    this.buttons.reset = b;
    this.shown = [...this.shown, 'reset'];
    this.statusText.before(b);
  }

  // Events for the host page (CustomEvent, bubbling and composed; types in planarium-playground.d.ts)

  /** Controller transitions as events: `run` when a run starts or resumes, `solved` when it ends with a path. */
  announce(to, from, event) {
    if (event === 'run') {
      this.emit('run', { scenario: this.scenario?.name ?? '', planner: this.config?.planner ?? '', seed: this.config?.seed ?? null,
        resumed: from === 'paused', autoplay: !!this.share?.autoplay && !this.acted });
    } else if (event === 'finish') {
      const r = this.player?.lane.result;
      if (!r?.solved) return;
      const st = r.stats || {};
      this.emit('solved', { scenario: this.scenario?.name ?? '', planner: r.planner ?? this.config?.planner ?? '', seed: r.seed ?? this.config?.seed ?? null,
        iterations: st.iterations ?? 0, nodes: st.nodes ?? 0, cost: typeof st.cost === 'number' ? st.cost : null });
    }
  }

  /** A step's answer has been shown (changed hook): `step` with the counts drawn. */
  stepShown() {
    if (!this.stepsAsked || this.player?.lane.stepPending > 0) return;
    this.stepsAsked = 0;
    const s = this.player.stats();
    this.emit('step', { iterations: s.iterations ?? 0, nodes: s.nodes ?? s.shown_nodes ?? 0, stepSize: this.stepSize(), status: this.status });
  }

  emit(type, detail) {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }

  // Read-only state and actions for scripts

  get state() { return this.player?.state ?? 'loading'; }
  get status() { return this.player?.statusWord() ?? 'loading'; }
  get nodeCount() { return this.player?.playback.nodeCount ?? 0; }
  get shownIterations() { return this.player?.shownIterations ?? 0; }
  get controls() { return [...this.shown]; }
  result() { return this.player?.lane.result ? structuredClone(this.player.lane.result) : null; }
  /** The 3-D view: {active, ready, camera: {target, yaw, pitch, distance} | null}. */
  view3dState() {
    const v = this.view3d.view;
    return { active: this.view3d.active, ready: !!(this.view3d.active && v?.matrices), camera: v ? v.camera.state() : null };
  }
  stats() { return this.player ? this.player.stats() : null; }
  /** The top view's zoom and centre ({zoom, cx, cy}), null while the workspace is fitted. */
  get zoom() { return this.view.viewport ? { ...this.view.viewport } : null; }
  run() { return this.act('run'); }
  pause() { return this.act('pause'); }
  step() { return this.act('step'); }
  back() { return this.act('back'); }
  reset() { return this.act('reset'); }
}

if (!customElements.get('planarium-playground')) customElements.define('planarium-playground', PlanariumPlayground);

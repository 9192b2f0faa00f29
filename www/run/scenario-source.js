// The scenario a page shows and where it came from: the one owner of that state for the
// playground (pages/main.js), Compare (pages/compare.js) and the benchmark page (pages/bench.js).
// A page tells it why it sends a scenario to be loaded (`sent`: a built-in as shipped, an edit, an
// opened file, a link's scenario, or a reload of the same one after a crash), what came back
// (`loaded`, `refused`), and when a link is being restored (`reading`, then `restore`: its state
// waits here until its scenario has loaded, and is handed back once). From that it knows:
// - `text` / `scenario`: the last valid scenario (as the core normalised it), what a reload sends;
// - `source`: {id} while it is a built-in as shipped, {custom: true} otherwise; in the playground
//   (`matchBuiltins`) a scenario that gives a built-in back exactly (an edit, say "Restore start and
//   goal") is that built-in again; a link carries the built-in's id, else the scenario's text
//   (`linkSource`);
// - `course`, `file`, `defaults` (whether the scenario's planner block is applied), `edit`;
// - `generation`: bumped by every load, so a page with two workers knows both answered the latest;
// - `settled`: a first scenario was asked for and no link is being read or restored (the playground
//   writes its hash only then).
// No DOM: a Node test walks its transitions.

/**
 * @typedef {'builtin' | 'edit' | 'file' | 'link' | 'reload'} LoadReason
 * @typedef {{id: string} | {custom: true}} Source
 */

export class ScenarioSource {
  /**
   * `matchBuiltins`: a custom scenario whose normalised text is a built-in's loaded earlier is
   * that built-in (the playground, whose edits can give one back).
   * @param {{matchBuiltins?: boolean}} [options]
   */
  constructor({ matchBuiltins = false } = {}) {
    this.matchBuiltins = matchBuiltins;
    /** @type {string | null} the last valid scenario's JSON (the core's normalised form) */
    this.text = null;
    /** @type {any} the last valid scenario, parsed */
    this.scenario = null;
    /** @type {Source | null} */
    this.source = null;
    /** @type {LoadReason | null} why the latest load was sent */
    this.reason = null;
    /** The course (or origin) shown above the scenario's name. */
    this.course = '';
    /** @type {string | null} the name of the file being loaded (its errors name it) */
    this.file = null;
    /** Whether the latest load applies the scenario's planner block when it loads. */
    this.defaults = false;
    /** @type {any} a link's state waiting for its scenario (applied once, by the page) */
    this.pending = null;
    /** @type {string[]} the problems of the link being restored, shown once its scenario has loaded */
    this.notes = [];
    /** Bumped by every load. */
    this.generation = 0;
    this.reading = false;
    this.started = false;
    /** @type {Map<string, string>} built-in id → its scenario as the core normalised it */
    this.builtinText = new Map();
  }

  /** The latest load is an edit of the scenario shown (the scene stays on screen if it is refused). */
  get edit() { return this.reason === 'edit'; }

  /** A first scenario was asked for, and no link is being read or restored. */
  get settled() { return this.started && !this.reading && !this.pending; }

  /**
   * A scenario is sent to be loaded, and why. `id`: the built-in's; `course`: what to show above
   * its name (kept when left out); `file`: the opened file's name; `defaults`: apply its planner
   * block. A reload keeps the source; a built-in is {id}; anything else is custom.
   * @param {LoadReason} reason
   * @param {{id?: string, course?: string, file?: string | null, defaults?: boolean}} [options]
   */
  sent(reason, { id, course, file = null, defaults = false } = {}) {
    this.reason = reason;
    this.generation++;
    this.defaults = defaults;
    this.file = file;
    if (course !== undefined) this.course = course;
    if (reason === 'builtin') this.source = { id };
    else if (reason !== 'reload') this.source = { custom: true };
    this.started = true;
  }

  /**
   * The scenario loaded (`text`: its JSON, by default `scenario`'s). Returns what the page applies
   * once: `restore`, the link's state that was waiting for it (null when none), and `defaults`,
   * whether the load asked for the scenario's planner block.
   * @param {any} scenario @param {string} [text]
   * @returns {{restore: any, defaults: boolean}}
   */
  loaded(scenario, text = JSON.stringify(scenario)) {
    this.scenario = scenario;
    this.text = text;
    this.file = null;
    const id = 'id' in (this.source ?? {}) ? /** @type {{id: string}} */ (this.source).id : null;
    if (id && this.reason !== 'edit') this.builtinText.set(id, text);
    if (this.matchBuiltins && this.source && 'custom' in this.source) {
      for (const [b, t] of this.builtinText) if (t === text) this.source = { id: b };
    }
    const restore = this.pending;
    this.pending = null;
    const defaults = this.defaults;
    this.defaults = false;
    return { restore, defaults };
  }

  /**
   * The scenario was refused. Not an edit: nothing valid is shown any more (a reload after a crash
   * still sends the last valid one). Returns the link's state when the refused scenario was a link's,
   * which stays pending (the page loads a built-in in its place).
   */
  refused() {
    this.file = null;
    if (!this.edit) this.scenario = null;
    return this.pending;
  }

  /**
   * Forget the scenario's text while another loads (Compare: nothing is run, linked or reloaded
   * after a crash until the new one has loaded); the scenario stays on show.
   */
  clear() {
    this.text = null;
  }

  /** A link is being read (its state follows with `restore`); nothing is written meanwhile. */
  read() { this.reading = true; }

  /** The link read: `state` waits for its scenario; `problems` are shown once it has loaded. */
  restore(state, problems = []) {
    this.reading = false;
    this.pending = state;
    this.notes = [...problems];
  }

  /** Take the link's problems (and forget them). */
  takeNotes() {
    const notes = this.notes;
    this.notes = [];
    return notes;
  }

  /** Forget a link being restored (the user left it: "Open the default scenario instead"). */
  forget() {
    this.reading = false;
    this.pending = null;
    this.notes = [];
  }

  /** What a link carries: the built-in's id while it is one as shipped, else the scenario's text (null: none yet). */
  linkSource() {
    if (this.source && 'id' in this.source) return { id: this.source.id };
    return this.text === null ? null : { text: this.text };
  }
}

// The scene's 3-D obstacles as numbers (a spatial arm's `obstacles3d`), under the 3-D view: a row
// a box with its name, centre x, y, z and full size x, y, z in metres (axis-aligned: the format
// has no rotation), each a field; a convex hull listed read-only (its point count). "Add box" and
// each row's "Remove" change the list.
//
// An edit is checked as a file is: the scenario with the field's text in it goes through the
// core's own parser on this thread (`new Scene(json)`, the wasm module the pose panel imports), so
// the bounds and the errors are the file's: a refused edit leaves the scenario as it was and says
// why beside the field, naming the box and the field ("box1, centre x: 2e9 is too large…", or the
// start or goal the box would meet). An accepted one goes through the Start / Goal editor
// (ui/editor.js: sent to the worker, which checks it again and reloads the scene), so the 3-D view
// and the pose panel's collision text follow, and the share link carries it. Text goes in with
// textContent only.

import { el } from './dom.js';
import { loadCore } from './pose3d.js';

const AXES = ['x', 'y', 'z'];
/** The fields of a box row: [key in the row, the file's key, axis, label]. */
const FIELDS = [
  ...AXES.map((a, k) => ({ id: `c${a}`, key: 'center', k, label: `centre ${a}` })),
  ...AXES.map((a, k) => ({ id: `s${a}`, key: 'size', k, label: `size ${a}` })),
];
/** A new box's full size (metres). */
const NEW_SIZE = 0.2;

/** The number a field's text is, or the text itself (for the core to say it is not a number). */
export function fieldValue(text) {
  const t = String(text).trim();
  if (/^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(t)) {
    const v = Number(t);
    if (Number.isFinite(v)) return v;
  }
  return t;
}

/** What an obstacle is called in messages: its name, else "obstacle i + 1". */
export function boxLabel(o, i) {
  return typeof o?.name === 'string' && o.name ? o.name : `obstacle ${i + 1}`;
}

/**
 * Where in the panel a core error's JSON `path` points: {index, field} (field: a FIELDS id or
 * 'name'), {index} alone for the obstacle as a whole, or null (elsewhere: start, goal, …).
 */
export function errorPlace(path) {
  const m = /^obstacles3d\[(\d+)\](?:\.(name|box)(?:\.(center|size)(?:\[(\d)\])?)?)?/.exec(String(path ?? ''));
  if (!m) return null;
  const index = Number(m[1]);
  if (m[2] === 'name') return { index, field: 'name' };
  if (m[3]) {
    const f = FIELDS.find((x) => x.key === m[3] && x.k === Number(m[4] ?? 0));
    return { index, field: f ? f.id : null };
  }
  return { index };
}

export class BoxesPanel {
  /**
   * @param {{root: HTMLElement, editor: import('./editor.js').Editor}} options
   */
  constructor({ root, editor }) {
    this.root = root;
    this.editor = editor;
    this.core = null;
    this.rows = [];      // per obstacle: {fields: Map(id → input), error: HTMLElement} (a hull: {error})
    this.count = -1;     // obstacles the rows were built for
    this.status = null;
    this.pending = null; // {index, field}: the edit sent, whose message waits for the reload
    this.generation = 0;
    this.open = false;   // the panel's <details> is open
    root.hidden = true;
  }

  /** A scene loaded: its normalised `scenario` and the core's `caps`; `edited`: an edit of it. */
  async setScene(scenario, caps, edited) {
    const gen = ++this.generation;
    const on = !!(caps?.view3d && scenario && Array.isArray(scenario.obstacles3d));
    this.root.hidden = !on;
    if (!on) { this.count = -1; return; }
    this.core ??= await loadCore().catch(() => null);
    if (gen !== this.generation) return;
    const list = scenario.obstacles3d;
    // an edit keeps the rows (and the focus in them) when the list kept its length
    if (edited && this.count === list.length) this.fill(list);
    else this.build(list);
    const p = this.pending;
    this.pending = null;
    this.say(edited && p ? p.done : '');
  }

  /** The scenario being edited (the last one sent), or null. */
  get scenario() { return this.editor.scenario; }

  build(list) {
    this.count = list.length;
    this.rows = [];
    const head = el('tr', {}, el('th', { scope: 'col', text: 'Name' }),
      ...FIELDS.map((f) => el('th', { scope: 'col', text: f.label })), el('th', { scope: 'col' }, el('span', { className: 'sr-only', text: 'Remove' })));
    const body = el('tbody');
    list.forEach((o, i) => {
      const error = el('td', { id: `box3d-${i}-error`, className: 'box3d-error', colSpan: FIELDS.length + 2, role: 'alert' });
      const errorRow = el('tr', { className: 'box3d-error-row', hidden: true }, error);
      if (!o.box) {
        const n = Array.isArray(o.hull) ? o.hull.length : 0;
        body.append(el('tr', { className: 'box3d-hull' }, el('td', { text: boxLabel(o, i) }),
          el('td', { colSpan: FIELDS.length + 1, text: `convex hull of ${n} points (read-only here; edit it in the file)` })), errorRow);
        this.rows.push({ fields: new Map(), error, errorRow });
        return;
      }
      const fields = new Map();
      const input = (id, label) => {
        const f = el('input', { id: `box3d-${i}-${id}`, type: 'text', inputMode: id === 'name' ? 'text' : 'decimal',
          spellcheck: false, autocomplete: 'off', 'aria-label': label });
        f.addEventListener('change', () => this.edit(i, id, f.value));
        fields.set(id, f);
        return el('td', {}, f);
      };
      const remove = el('button', { type: 'button', text: 'Remove', id: `box3d-${i}-remove`, title: 'Remove this box from the scene' });
      remove.addEventListener('click', () => this.remove(i));
      body.append(el('tr', {}, input('name', `Obstacle ${i + 1} name`), ...FIELDS.map((f) => input(f.id, `${boxLabel(o, i)} ${f.label}`)),
        el('td', {}, remove)), errorRow);
      this.rows.push({ fields, error, errorRow });
    });
    this.status = el('p', { id: 'box3d-status', className: 'hint', role: 'status' });
    const add = el('button', { id: 'box3d-add', type: 'button', text: 'Add box', title: `A ${NEW_SIZE} m cube in a corner of the scene's extent` });
    add.addEventListener('click', () => this.add());
    // closed at first (the views keep their height), open across reloads once opened
    const details = el('details', { open: this.open },
      el('summary', {}, el('h2', { id: 'h-boxes3d', text: `Scene boxes (${list.length})` })),
      el('p', { className: 'hint', text: 'The scene\'s obstacles in metres: each box\'s centre and full size, axis-aligned (the file\'s obstacles3d; a box has no rotation). Enter or leaving a field applies it; the core checks it as it checks a file.' }),
      el('div', { className: 'box3d-scroll' }, el('table', { className: 'box3d-table' }, el('thead', {}, head), body)),
      el('div', { className: 'row' }, add), this.status);
    details.addEventListener('toggle', () => { this.open = details.open; });
    this.root.replaceChildren(details);
    this.rows.forEach((_, i) => this.mark(i, null, ''));
    this.fill(list);
  }

  /**
   * The fields show the scenario's numbers, but a field refused since the last edit sent keeps its
   * text and its error (the reload of an earlier edit may arrive after it was refused).
   */
  fill(list) {
    list.forEach((o, i) => {
      const row = this.rows[i];
      if (!row || !o.box) return;
      const keep = (f) => f.getAttribute('aria-invalid') === 'true';
      const name = row.fields.get('name');
      if (!keep(name)) name.value = typeof o.name === 'string' ? o.name : '';
      for (const f of FIELDS) {
        const input = row.fields.get(f.id);
        if (!keep(input)) input.value = String(o.box[f.key][f.k]);
      }
    });
  }

  /** Show `text` beside obstacle `i`'s row (the field `id` marked invalid), or clear it. */
  mark(i, id, text) {
    const row = this.rows[i];
    if (!row) return;
    row.error.textContent = text;
    row.errorRow.hidden = !text;
    for (const [fid, f] of row.fields) {
      const bad = !!text && fid === id;
      f.setAttribute('aria-invalid', String(bad));
      if (bad) f.setAttribute('aria-describedby', row.error.id); else f.removeAttribute('aria-describedby');
    }
  }

  say(text) { if (this.status) this.status.textContent = text; }

  /** Field `id` of obstacle `i` set to `text`. */
  edit(i, id, text) {
    const s = this.scenario;
    const o = s?.obstacles3d?.[i];
    if (!o?.box) return;
    const f = FIELDS.find((x) => x.id === id);
    const label = `${boxLabel(o, i)}, ${f ? f.label : 'name'}`;
    const next = structuredClone(s);
    const b = next.obstacles3d[i];
    if (f) b.box[f.key][f.k] = fieldValue(text);
    else if (text.trim()) b.name = text.trim(); else delete b.name;
    this.apply(next, { index: i, field: id, label, done: `Applied: ${label} is now ${f ? b.box[f.key][f.k] : `"${text.trim()}"`}; the scene was reloaded.` });
  }

  remove(i) {
    const s = this.scenario;
    if (!s?.obstacles3d?.[i]) return;
    const next = structuredClone(s);
    const [gone] = next.obstacles3d.splice(i, 1);
    this.apply(next, { index: i, field: null, label: boxLabel(gone, i), done: `Removed ${boxLabel(gone, i)}; the scene was reloaded.` });
  }

  /** A new cube a tenth of the way in from the scene extent's lower-left corner, on the floor's level. */
  add() {
    const s = this.scenario;
    if (!s?.obstacles3d) return;
    const next = structuredClone(s);
    const [x0, y0, x1, y1] = s.bounds;
    const names = new Set(next.obstacles3d.map((o) => o.name));
    let k = next.obstacles3d.length + 1;
    while (names.has(`box${k}`)) k++;
    next.obstacles3d.push({ name: `box${k}`, box: {
      center: [x0 + (x1 - x0) / 10, y0 + (y1 - y0) / 10, NEW_SIZE / 2].map((v) => Number(v.toFixed(6))),
      size: [NEW_SIZE, NEW_SIZE, NEW_SIZE],
    } });
    const i = next.obstacles3d.length - 1;
    this.apply(next, { index: -1, field: null, label: `box${k}`, done: `Added box${k} (obstacle ${i + 1}); the scene was reloaded.` });
  }

  /**
   * Check `next` with the core's parser; refused: say why beside the row (the box and field named),
   * else send it through the editor (the worker reloads the scene).
   */
  apply(next, at) {
    for (let i = 0; i < this.rows.length; i++) this.mark(i, null, '');
    if (this.editor.stale || !this.scenario) { this.say('Not applied: the scenario is loading; try again in a moment.'); return; }
    if (!this.core) { this.say('Not applied: the core could not be loaded on this page.'); return; }
    let why = null;
    try {
      new this.core.Scene(JSON.stringify(next)).free();
    } catch (e) {
      why = readError(e);
    }
    if (why) {
      const place = errorPlace(why.path);
      const where = place && place.index !== at.index
        ? `${boxLabel(next.obstacles3d[place.index], place.index)}${place.field ? `, ${FIELDS.find((f) => f.id === place.field)?.label ?? place.field}` : ''}`
        : at.label;
      const text = place ? `${where}: ${why.message}` : `${at.label}: not applied, the ${why.path || 'scenario'} would be refused: ${why.message}`;
      const row = place && place.index < this.rows.length ? place.index : at.index;
      if (row >= 0) this.mark(row, place?.index === row ? place.field ?? at.field : at.field, text);
      this.say(`Not applied (the scenario is as it was): ${text}`);
      return;
    }
    this.pending = at;
    this.editor.scenario = next;
    this.editor.commit();
    this.say('Checking…');
  }

  /** The worker refused the edit sent (it checks more than the scene: the planner block too). */
  refused(error) {
    const p = this.pending;
    if (!p) return;
    this.pending = null;
    this.say(`Not applied: ${p.label}: ${error?.path ? `${error.path}: ` : ''}${error?.message || error?.text || 'refused'}`);
  }

  /** For tests: the rows' values and errors, and the status line. */
  state() {
    return {
      rows: this.rows.map((r) => ({ values: Object.fromEntries([...r.fields].map(([k, f]) => [k, f.value])), error: r.errorRow.hidden ? '' : r.error.textContent })),
      status: this.status?.textContent ?? '',
    };
  }
}

/** The core's error (JSON {path, message, text}) as {path, message}. */
function readError(e) {
  const text = String(e?.message ?? e);
  try {
    const j = JSON.parse(text);
    return { path: String(j.path ?? ''), message: String(j.message ?? j.text ?? text) };
  } catch {
    return { path: '', message: text };
  }
}

// The obstacle editor: draw rectangles, circles and polygons on the canvas, select one to move it
// (drag its inside), resize it (drag a handle: a rectangle's corners, a circle's rim, a polygon's
// vertices), delete it, set the bounds, undo and redo, save the scenario as JSON. Every change is
// handed to the start/goal Editor's commit, so the worker re-validates the scenario: an invalid
// start or goal is reported there (with its JSON path) and the page stays usable.
//
// Tools: select (default), rect, circle, polygon (click the corners; double-click, Enter or a click
// on the first corner closes it; Escape drops it), and cells (PathFinding.js's walls, cell-painter.js:
// drag from a free cell to paint walls on grid search's cells, from a wall to erase; the lattice is
// drawn faintly while it is the tool). Keys (never while typing in a field): Delete/Backspace
// deletes the selection; ctrl/cmd+Z undo, ctrl/cmd+shift+Z or ctrl+Y redo; Escape drops a polygon
// being drawn or a cell drag (the map as before it).
//
// The map as a whole: "New map" (same bounds and robot, no obstacles, start and goal in opposite
// corners, "Untitled map"), "Clear walls" and "Clear obstacles", all undoable. Clear walls is
// PathFinding.js's button: it removes the painted cells (the rectangles that lie within one cell of
// the Cells tool's lattice) and keeps drawn shapes and the built-in maps' walls, as a student who
// painted a maze over a map expects; Clear obstacles removes every obstacle. "Snap to grid" with a grid step
// (drawn faintly while on): every placed or dragged vertex, corner, circle centre and radius, start
// and goal lands on the grid, rounded to the step's decimals; off, values are rounded to about four
// digits below the map's size. Under the pointer, a read-out gives the world coordinates. The name
// and notes are edited here too (bounded: MAX_NAME / MAX_NOTES characters; an edit over the bound
// is refused and says so), so Save JSON and the share link carry them.
// The toolbar (tools, actions, the hint, the status line, the bounds) is obstacle-toolbar.js's.

import { el } from './dom.js';
import { PALETTE } from '../draw/palette.js';
import { anchor, handles, inside, moved, reshaped, niceStep, stepDecimals, snapTo, tidy, readoutDecimals } from './obstacle-shapes.js';
import { CellPainter } from './cell-painter.js';
import { buildBar, renderBar } from './obstacle-toolbar.js';
import { dragsHeading, dragsPosition } from '../draw/capabilities.js';
import { footprintRadius } from '../draw/robots.js';

const HANDLE = 6; // css px: handle half-size and grab distance
const MIN = 1e-3; // the smallest rectangle side or circle radius, as a fraction of the scene
export const MAX_NAME = 120;   // characters of a name typed here (the core reads up to 500)
export const MAX_NOTES = 2000; // characters of notes typed here (the core reads up to 20,000)
const GRID_MIN = 1 / 1000; // the grid step's bounds, as fractions of the map's larger side
const GRID_MAX = 1 / 2;
const GRID_COLOUR = 'rgba(31, 78, 154, 0.16)'; // faint blue lines
const TYPED_MS = 300; // the map's name and notes are committed this long after the last key
const GRID_PX = 6; // css px: grid lines closer than this are thinned (every 2nd, 5th, 10th…)

export class ObstacleEditor {
  /**
   * `editor`: the start/goal Editor (its `scenario` and `commit()` are shared); `root`: where the
   * toolbar goes. The view draws the selection through `view.overlayHooks`. `config()`: the
   * planner chosen, {planner, params} (the Cells tool paints on grid search's cells). `idle()`:
   * whether no run is shown (the selection's handles and the snapping grid are drawn only then).
   */
  constructor({ canvas, view, editor, root, download, config = () => null, idle = () => true }) {
    this.idle = idle;
    this.canvas = canvas;
    this.view = view;
    this.editor = editor;
    this.root = root;
    this.download = download;
    this.tool = 'select';
    this.selected = -1;
    this.drag = null;
    this.draft = null; // polygon corners being placed
    this.undoStack = [];
    this.redoStack = [];
    this.committed = null; // the scenario as last committed (what undo returns to)
    this.grid = { on: false, step: 0.05, custom: false }; // custom: the step was typed, not the default
    this.cells = new CellPainter(this, config);
    view.overlayHooks = [...(view.overlayHooks ?? []), (ctx, L) => this.draw(ctx, L)];
    editor.beforeCommit = () => this.record(); // start/goal drags are undoable too
    editor.place = (x, y) => this.place(x, y); // a dragged start/goal snaps (or is tidied) as obstacles are
    // Capture phase: a drawing tool takes the press before the start/goal drag sees it.
    canvas.addEventListener('pointerdown', (e) => this.down(e), true);
    canvas.addEventListener('pointermove', (e) => { this.move(e); this.showPointer(e); });
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointerleave', () => { this.readout.hidden = true; });
    canvas.addEventListener('pointercancel', () => this.cells.cancel());
    canvas.addEventListener('dblclick', (e) => { if (this.draft) { e.preventDefault(); this.closeDraft(); } });
    document.addEventListener('keydown', (e) => this.key(e));
    // The pointer's world coordinates, in a corner of the stage (text only).
    this.readout = el('output', { id: 'pointer-coords', className: 'pointer-coords', 'aria-live': 'off' });
    this.readout.hidden = true;
    canvas.parentElement?.append(this.readout);
    this.bar = el('div', { className: 'obstacle-bar' });
    /** @type {any} tools, buttons, boundInputs, hint, status (obstacle-toolbar.js) */
    this.barParts = null;
    this.buildBar();                // built once, brought up to date by render()
    this.fixed = this.buildFixed(); // the same: typing in a field keeps its focus
    root.replaceChildren(this.bar, this.fixed);
    this.syncFixed();
    this.render();
  }

  get scenario() { return this.editor.scenario; }

  /** A scenario loaded: an edit of ours keeps history and selection; another one clears them. */
  loaded(edited) {
    if (!edited) {
      this.undoStack = [];
      this.redoStack = [];
      this.selected = -1;
      this.draft = null;
      this.say('');
    }
    this.cells.drag = null;
    this.committed = this.scenario ? structuredClone(this.scenario) : null;
    if (this.selected >= (this.scenario?.obstacles?.length ?? 0)) this.selected = -1;
    this.fitGrid(!edited);
    this.syncFixed();
    this.render();
  }

  /** Another planner or parameter: the Cells tool's lattice may have changed. */
  plannerChanged() {
    this.render();
    this.view.dirty = true;
  }

  /** Record the change about to be committed (any edit: obstacles, bounds, start, goal). */
  record() {
    if (this.committed) this.undoStack.push(this.committed);
    if (this.undoStack.length > 200) this.undoStack.shift();
    this.redoStack = [];
  }

  commit() {
    this.editor.commit(); // records the previous state through beforeCommit
    this.committed = structuredClone(this.scenario);
    this.render();
  }

  undo() { this.travel(this.undoStack, this.redoStack); }
  redo() { this.travel(this.redoStack, this.undoStack); }

  travel(from, to) {
    if (!from.length || !this.scenario) return;
    to.push(structuredClone(this.scenario));
    const s = from.pop();
    this.editor.scenario = structuredClone(s);
    this.committed = structuredClone(s);
    this.selected = -1;
    this.editor.onCommit(structuredClone(s));
    this.render();
  }

  setTool(tool) {
    this.tool = tool;
    this.draft = null;
    this.say('');
    this.canvas.classList.toggle('drawing', tool !== 'select');
    this.render();
    this.view.dirty = true;
  }

  deleteSelected() {
    if (this.selected < 0 || !this.scenario) return;
    this.scenario.obstacles.splice(this.selected, 1);
    this.selected = -1;
    this.preview();
    this.commit();
  }

  /** "New map": the same bounds and robot, no obstacles, start and goal in opposite corners. */
  newMap() {
    const s = this.scenario;
    if (!s || this.editor.stale) return;
    const m = structuredClone(s);
    m.name = 'Untitled map';
    delete m.notes;
    delete m.planner; // the panel keeps the planner chosen now
    m.obstacles = [];
    if (dragsPosition(s.robot)) {
      // an arm or a vehicle chain keeps its start and goal: they were valid in these bounds
      const [x0, y0, x1, y1] = s.bounds;
      const side = Math.min(x1 - x0, y1 - y0);
      const reach = footprintRadius(s.robot);
      const inset = Math.min(side / 2, Math.max(side / 10, reach * 1.25));
      const corner = (x, y) => this.place(x, y);
      const a = corner(x0 + inset, y0 + inset), b = corner(x1 - inset, y1 - inset);
      const turns = dragsHeading(s.robot);
      m.start = turns ? [...a, 0] : a;
      if (s.goal || !s.inspection) m.goal = turns ? [...b, 0] : b;
    }
    this.editor.scenario = m;
    this.selected = -1;
    this.draft = null;
    this.preview();
    this.commit();
  }

  /** "Clear obstacles": all of them (undo brings them back). */
  clearObstacles() {
    if (!this.scenario?.obstacles?.length || this.editor.stale) return;
    this.scenario.obstacles = [];
    this.selected = -1;
    this.preview();
    this.commit();
  }

  /** "Clear walls": the painted cells (rectangles within one cell of the Cells tool's lattice). */
  clearWalls() {
    if (!this.scenario || this.editor.stale) return;
    const lat = this.cells.lattice();
    const kept = this.scenario.obstacles.filter((ob) => !this.cells.isPiece(ob, lat));
    if (kept.length === this.scenario.obstacles.length) return;
    this.scenario.obstacles = kept;
    this.selected = -1;
    this.preview();
    this.commit();
  }

  /** The status line under the tools (why a cell was not painted or erased); '' hides it. */
  say(text) {
    const s = this.barParts?.status;
    if (!s || s.textContent === text) return;
    s.textContent = text;
    s.hidden = !text;
  }

  save() {
    if (!this.scenario) return;
    const name = (this.scenario.name || 'scenario').replace(/[^\w.-]+/g, '-').toLowerCase();
    this.download(`${JSON.stringify(this.scenario, null, 2)}\n`, `${name}.json`);
  }

  // Toolbar (obstacle-toolbar.js)

  buildBar() { buildBar(this); }

  /** The toolbar from the state: the pressed tool, what can be done, the hint, the bounds. */
  render() { renderBar(this); }

  /** The parts of the toolbar built once: snapping and the grid step, the name and the notes. */
  buildFixed() {
    const snap = el('input', { id: 'snap-grid', type: 'checkbox' });
    const step = el('input', { id: 'grid-step', type: 'number', step: 'any', value: String(this.grid.step) });
    const gridError = el('p', { id: 'grid-error', className: 'hint bad', role: 'alert' });
    gridError.hidden = true;
    snap.addEventListener('change', () => {
      this.grid.on = snap.checked;
      this.view.dirty = true;
    });
    step.addEventListener('change', () => {
      const why = this.setGridStep(step.value);
      gridError.textContent = why;
      gridError.hidden = !why;
      step.setAttribute('aria-invalid', String(!!why));
      if (!why) step.value = String(this.grid.step);
    });
    const name = el('input', { id: 'edit-name', type: 'text', spellcheck: true, autocomplete: 'off' });
    const notes = el('textarea', { id: 'edit-notes', rows: 3, spellcheck: true });
    const metaError = el('p', { id: 'meta-error', className: 'hint bad', role: 'alert' });
    metaError.hidden = true;
    const check = () => {
      const problems = [];
      if (name.value.length > MAX_NAME) problems.push(`The name is ${name.value.length} characters long (at most ${MAX_NAME}): shorten it to keep it.`);
      if (notes.value.length > MAX_NOTES) problems.push(`The notes are ${notes.value.length.toLocaleString('en')} characters long (at most ${MAX_NOTES.toLocaleString('en')}): shorten them to keep them.`);
      metaError.textContent = problems.join(' ');
      metaError.hidden = !problems.length;
      name.setAttribute('aria-invalid', String(name.value.length > MAX_NAME));
      notes.setAttribute('aria-invalid', String(notes.value.length > MAX_NOTES));
      return !problems.length;
    };
    const commitMeta = () => {
      if (!check() || !this.scenario || this.editor.stale) return;
      const n = name.value.trim(), t = notes.value.trim();
      if (n === (this.scenario.name ?? '') && t === (this.scenario.notes ?? '')) return;
      if (n) this.scenario.name = n; else delete this.scenario.name;
      if (t) this.scenario.notes = t; else delete this.scenario.notes;
      this.commit();
    };
    // Committed a moment after the typing stops (and on leaving the field, as before), so the
    // click that ends the typing finds nothing left to commit: a commit then reloads the map,
    // which swallowed that click (a tool's button redrawn under it, Run disabled while loading).
    let typing = 0;
    const later = () => { // while the map reloads from the last commit, wait for it
      typing = this.editor.stale ? setTimeout(later, TYPED_MS) : 0;
      if (!typing) commitMeta();
    };
    const typed = () => { clearTimeout(typing); if (check()) typing = setTimeout(later, TYPED_MS); };
    name.addEventListener('input', typed);
    notes.addEventListener('input', typed);
    name.addEventListener('change', commitMeta);
    notes.addEventListener('change', commitMeta);
    this.fields = { snap, step, gridError, name, notes, metaError };
    return el('div', { className: 'map-fields' },
      el('div', { className: 'row grid-row' },
        el('label', { className: 'inline', htmlFor: 'snap-grid', title: 'Placed and dragged corners, centres, radii, start and goal land on the grid' }, snap, ' Snap to grid'),
        el('label', { className: 'bound', htmlFor: 'grid-step' }, el('span', { text: 'step' }), step)),
      gridError,
      el('label', { className: 'field', htmlFor: 'edit-name' }, el('span', { text: 'Name' }), name),
      el('label', { className: 'field', htmlFor: 'edit-notes' }, el('span', { text: 'Notes (shown under the canvas)' }), notes),
      metaError,
      el('p', { className: 'hint', text: 'Save JSON and Copy link carry the name and notes.' }));
  }

  /** The fields built once, from the scenario (a field being typed in is left alone). */
  syncFixed() {
    const f = this.fields;
    const s = this.scenario;
    for (const input of [f.snap, f.step, f.name, f.notes]) input.disabled = !s;
    f.step.value = String(this.grid.step);
    if (s) this.setStepLimits();
    if (document.activeElement !== f.name) f.name.value = s?.name ?? '';
    if (document.activeElement !== f.notes) f.notes.value = s?.notes ?? '';
    if (document.activeElement !== f.name && document.activeElement !== f.notes) f.metaError.hidden = true;
  }

  /** The grid step's allowed range on this map: [extent × GRID_MIN, extent × GRID_MAX]. */
  stepRange() {
    const e = this.extent();
    return [Number((e * GRID_MIN).toPrecision(3)), Number((e * GRID_MAX).toPrecision(3))];
  }

  setStepLimits() {
    const [lo, hi] = this.stepRange();
    this.fields.step.min = String(lo);
    this.fields.step.max = String(hi);
  }

  /** Set the grid step from what was typed; '' if it was taken, else why not. */
  setGridStep(text) {
    if (!this.scenario) return 'No map is loaded.';
    const [lo, hi] = this.stepRange();
    const v = Number(String(text).trim());
    if (String(text).trim() === '' || !Number.isFinite(v) || v < lo || v > hi) {
      return `The grid step must be a number from ${lo} to ${hi} on this map (it is ${this.extent()} across); it stays ${this.grid.step}.`;
    }
    this.grid.step = Number(v.toPrecision(6));
    this.grid.custom = true;
    this.view.dirty = true;
    return '';
  }

  /** Keep the grid step fitting the map: the default (1/20 of its width, rounded to a nice number) for a new map, or when the typed one no longer fits. */
  fitGrid(fresh) {
    if (!this.scenario) return;
    const [lo, hi] = this.stepRange();
    if ((fresh && !this.grid.custom) || this.grid.step < lo || this.grid.step > hi) {
      const [x0, , x1] = this.scenario.bounds;
      this.grid.step = Math.min(hi, Math.max(lo, niceStep((x1 - x0) / 20)));
      this.grid.custom = false;
      this.fields.gridError.hidden = true;
    }
  }

  /** World point (x, y) as an edit places it: on the grid when snapping, else tidied. */
  place(x, y) {
    if (this.grid.on && this.scenario) return [snapTo(x, this.grid.step), snapTo(y, this.grid.step)];
    const e = this.scenario ? this.extent() : 1;
    return [tidy(x, e), tidy(y, e)];
  }

  /** A length (a circle's radius) as an edit places it: a whole number of grid steps when snapping. */
  placeLength(r) {
    if (this.grid.on) return snapTo(r, this.grid.step); // under half a step: 0, a click (no circle)
    return tidy(r, this.extent());
  }

  /** The read-out of the world point under the pointer. */
  showPointer(e) {
    const L = this.view.layout;
    if (!L || !this.scenario) { this.readout.hidden = true; return; }
    const [x, y] = this.world(e);
    let d = readoutDecimals(this.extent());
    if (this.grid.on) d = Math.max(d, stepDecimals(this.grid.step));
    let text = `x ${x.toFixed(d)}, y ${y.toFixed(d)}`;
    if (this.grid.on) {
      const [gx, gy] = this.place(x, y);
      text += ` · grid (${gx}, ${gy})`;
    }
    this.readout.textContent = text;
    this.readout.hidden = false;
  }

  // Canvas

  world(e) {
    const L = this.view.layout;
    return [L.wx(e.offsetX * L.dpr), L.wy(e.offsetY * L.dpr)];
  }

  tol() { return (HANDLE * this.view.layout.dpr) / this.view.layout.scale; }

  extent() {
    const [a, b, c, d] = this.scenario.bounds;
    return Math.max(c - a, d - b);
  }

  /** Redraw the scene from the edited scenario (before the worker has checked it). */
  preview() {
    this.view.scenario = this.scenario;
    this.view.drawScene();
    this.view.dirty = true;
  }

  down(e) {
    if (!this.scenario || !this.view.layout || e.button !== 0 || this.editor.stale) return;
    const [rx, ry] = this.world(e); // where the press is (what it grabs)
    const [x, y] = this.tool === 'select' ? [rx, ry] : this.place(rx, ry); // where a new corner goes
    const obs = this.scenario.obstacles;
    if (this.tool === 'cells') {
      if (this.editor.draggable && this.editor.hit(this.editor.devicePoint(e), e.shiftKey)) return; // start/goal first
      this.selected = -1;
      if (!this.cells.down(rx, ry)) return;
    } else if (this.tool === 'select') {
      if (this.editor.draggable && this.editor.hit(this.editor.devicePoint(e), e.shiftKey)) return; // start/goal first
      const sel = obs[this.selected];
      const k = sel ? handles(sel).findIndex(([hx, hy]) => Math.hypot(hx - x, hy - y) <= this.tol()) : -1;
      let mode = k >= 0 ? 'reshape' : null;
      if (!mode) {
        const i = obs.map((o, j) => j).reverse().find((j) => inside(obs[j], x, y, this.tol()));
        this.selected = i ?? -1;
        mode = i === undefined ? null : 'move';
        this.render();
        this.view.dirty = true;
      }
      if (!mode) return;
      this.drag = { mode, k, x, y, ob: structuredClone(obs[this.selected]), changed: false };
    } else if (this.tool === 'polygon') {
      const first = this.draft?.[0];
      if (first && this.draft.length >= 3 && Math.hypot(first[0] - x, first[1] - y) <= this.tol()) this.closeDraft();
      else (this.draft ??= []).push([x, y]);
      this.view.dirty = true;
    } else {
      obs.push(this.tool === 'rect' ? { rect: [x, y, x, y] } : { circle: [x, y, 0] });
      this.selected = obs.length - 1;
      this.drag = { mode: 'reshape', k: this.tool === 'rect' ? 2 : 0, x, y, ob: structuredClone(obs[this.selected]), changed: false, fresh: true };
    }
    e.preventDefault();
    e.stopImmediatePropagation();
    this.canvas.setPointerCapture(e.pointerId);
  }

  move(e) {
    if (this.cells.drag) { this.cells.move(...this.world(e)); return; }
    if (!this.drag || !this.scenario) { if (this.draft) this.view.dirty = true; this.hover = this.view.layout && this.scenario ? this.place(...this.world(e)) : null; return; }
    const [x, y] = this.world(e);
    const obs = this.scenario.obstacles;
    const d = this.drag;
    if (d.mode === 'move') {
      // the anchor (a circle's centre, else the first corner) lands where an edit places a point;
      // the other corners follow by the same step
      const [ax, ay] = anchor(d.ob);
      const [px, py] = this.place(ax + x - d.x, ay + y - d.y);
      const ext = this.extent();
      const clean = (v) => (this.grid.on ? Number(v.toFixed(12)) : tidy(v, ext));
      const m = moved(d.ob, px - ax, py - ay);
      obs[this.selected] = Object.fromEntries(Object.entries(m).map(([k, v]) => [k, k === 'polygon'
        ? v.map((p) => p.map(clean))
        : v.map((c, i) => (k === 'circle' && i === 2 ? c : clean(c)))]));
    } else if (d.ob.circle) {
      const [cx, cy] = d.ob.circle;
      obs[this.selected] = { circle: [cx, cy, this.placeLength(Math.hypot(x - cx, y - cy))] };
    } else {
      obs[this.selected] = reshaped(d.ob, d.k, ...this.place(x, y));
    }
    d.changed = true;
    this.preview();
  }

  up(e) {
    if (this.cells.drag) {
      if (this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
      this.cells.up();
      return;
    }
    const d = this.drag;
    if (!d) return;
    this.drag = null;
    if (this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
    const obs = this.scenario.obstacles;
    const ob = obs[this.selected];
    const tiny = (ob.rect && (Math.abs(ob.rect[2] - ob.rect[0]) < MIN * this.extent() || Math.abs(ob.rect[3] - ob.rect[1]) < MIN * this.extent()))
      || (ob.circle && ob.circle[2] < MIN * this.extent());
    if (d.fresh && tiny) { // a click, not a drag: no obstacle
      obs.splice(this.selected, 1);
      this.selected = -1;
      this.preview();
      this.render();
      return;
    }
    if (ob.rect) ob.rect = [Math.min(ob.rect[0], ob.rect[2]), Math.min(ob.rect[1], ob.rect[3]), Math.max(ob.rect[0], ob.rect[2]), Math.max(ob.rect[1], ob.rect[3])];
    if (d.changed) this.commit();
  }

  closeDraft() {
    const pts = this.draft;
    this.draft = null;
    if (!pts || pts.length < 3) return;
    this.scenario.obstacles.push({ polygon: pts });
    this.selected = this.scenario.obstacles.length - 1;
    this.preview();
    this.commit();
  }

  key(e) {
    if (e.target.closest?.('input, select, textarea') || !this.scenario) return;
    const mod = e.ctrlKey || e.metaKey;
    if (mod && (e.key === 'z' || e.key === 'Z')) { e.preventDefault(); if (e.shiftKey) this.redo(); else this.undo(); }
    else if (mod && e.key === 'y') { e.preventDefault(); this.redo(); }
    else if ((e.key === 'Delete' || e.key === 'Backspace') && this.selected >= 0) { e.preventDefault(); this.deleteSelected(); }
    else if (e.key === 'Enter' && this.draft) { e.preventDefault(); this.closeDraft(); }
    else if (e.key === 'Escape' && this.draft) { e.preventDefault(); this.draft = null; this.view.dirty = true; }
    else if (e.key === 'Escape' && this.cells.drag) { e.preventDefault(); this.cells.cancel(); }
  }

  /** The selection's outline and handles, and a polygon being drawn (called by the view). */
  draw(ctx, L) {
    const s = this.scenario;
    if (!s) return;
    const px = (x, y) => [L.sx(x), L.sy(y)];
    const ob = s.obstacles[this.selected];
    // a run shows the planner's picture: no editing marks over it
    const idle = this.idle();
    ctx.save();
    if (idle && this.grid.on && this.tool !== 'cells') this.drawGrid(ctx, L);
    if (this.tool === 'cells') this.cells.draw(ctx, L);
    if (ob && idle) {
      ctx.fillStyle = PALETTE.start;
      ctx.strokeStyle = '#000';
      ctx.lineWidth = L.px(1);
      for (const [hx, hy] of handles(ob)) {
        const [sx, sy] = px(hx, hy);
        const h = L.px(HANDLE);
        ctx.fillRect(sx - h / 2, sy - h / 2, h, h);
        ctx.strokeRect(sx - h / 2, sy - h / 2, h, h);
      }
    }
    if (this.draft) {
      ctx.strokeStyle = PALETTE.obstacleEdge;
      ctx.setLineDash([L.px(4), L.px(3)]);
      ctx.lineWidth = L.px(2);
      ctx.beginPath();
      this.draft.forEach(([x, y], i) => (i ? ctx.lineTo(...px(x, y)) : ctx.moveTo(...px(x, y))));
      if (this.hover) ctx.lineTo(...px(...this.hover));
      ctx.stroke();
    }
    ctx.restore();
  }

  /** The snapping grid, faint, inside the bounds (lines closer than GRID_PX css px are thinned). */
  drawGrid(ctx, L) {
    const [x0, y0, x1, y1] = this.scenario.bounds;
    const step = this.grid.step;
    let every = 1;
    for (const m of [2, 5, 10, 20, 50, 100, 200, 500, 1000]) {
      if (step * every * L.scale >= L.px(GRID_PX)) break;
      every = m;
    }
    const g = step * every;
    ctx.beginPath();
    for (let i = Math.ceil(x0 / g); i * g <= x1 + 1e-9 * g; i++) {
      const sx = Math.round(L.sx(i * g)) + 0.5;
      ctx.moveTo(sx, L.sy(y0));
      ctx.lineTo(sx, L.sy(y1));
    }
    for (let i = Math.ceil(y0 / g); i * g <= y1 + 1e-9 * g; i++) {
      const sy = Math.round(L.sy(i * g)) + 0.5;
      ctx.moveTo(L.sx(x0), sy);
      ctx.lineTo(L.sx(x1), sy);
    }
    ctx.strokeStyle = GRID_COLOUR;
    ctx.lineWidth = 1;
    ctx.stroke();
  }
}

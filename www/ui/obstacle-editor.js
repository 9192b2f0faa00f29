// The obstacle editor: draw rectangles, circles and polygons on the canvas, select one to move it
// (drag its inside), resize it (drag a handle: a rectangle's corners, a circle's rim, a polygon's
// vertices), delete it, set the bounds, undo and redo, save the scenario as JSON. Every change is
// handed to the start/goal Editor's commit, so the worker re-validates the scenario: an invalid
// start or goal is reported there (with its JSON path) and the page stays usable.
//
// Tools: select (default), rect, circle, polygon (click the corners; double-click, Enter or a click
// on the first corner closes it; Escape drops it). Keys (never while typing in a field):
// Delete/Backspace deletes the selection; ctrl/cmd+Z undo, ctrl/cmd+shift+Z or ctrl+Y redo.

import { el } from './dom.js';
import { PALETTE } from '../draw/palette.js';
import { pointInPolygon } from '../draw/transform.js';

const HANDLE = 6; // css px: handle half-size and grab distance
const MIN = 1e-3; // the smallest rectangle side or circle radius, as a fraction of the scene

/** The handles of obstacle `ob`: [[x, y], ...] in world units. */
function handles(ob) {
  if (ob.rect) { const [a, b, c, d] = ob.rect; return [[a, b], [c, b], [c, d], [a, d]]; }
  if (ob.circle) { const [x, y, r] = ob.circle; return [[x + r, y]]; }
  if (ob.polygon) return ob.polygon.map((p) => [...p]);
  if (ob.segment) { const [a, b, c, d] = ob.segment; return [[a, b], [c, d]]; }
  return [];
}

/** Whether world point (x, y) is inside obstacle `ob` (a segment: within `tol`). */
function inside(ob, x, y, tol) {
  if (ob.rect) { const [a, b, c, d] = ob.rect; return x >= Math.min(a, c) && x <= Math.max(a, c) && y >= Math.min(b, d) && y <= Math.max(b, d); }
  if (ob.circle) { const [cx, cy, r] = ob.circle; return Math.hypot(x - cx, y - cy) <= r; }
  if (ob.polygon) return pointInPolygon(x, y, ob.polygon.flat());
  if (ob.segment) {
    const [a, b, c, d] = ob.segment;
    const dx = c - a, dy = d - b, len2 = dx * dx + dy * dy || 1;
    const t = Math.max(0, Math.min(1, ((x - a) * dx + (y - b) * dy) / len2));
    return Math.hypot(x - a - t * dx, y - b - t * dy) <= tol;
  }
  return false;
}

function moved(ob, dx, dy) {
  if (ob.rect) { const [a, b, c, d] = ob.rect; return { rect: [a + dx, b + dy, c + dx, d + dy] }; }
  if (ob.circle) { const [x, y, r] = ob.circle; return { circle: [x + dx, y + dy, r] }; }
  if (ob.polygon) return { polygon: ob.polygon.map(([x, y]) => [x + dx, y + dy]) };
  if (ob.segment) { const [a, b, c, d] = ob.segment; return { segment: [a + dx, b + dy, c + dx, d + dy] }; }
  return ob;
}

/** Obstacle `ob` with handle `k` dragged to (x, y). */
function reshaped(ob, k, x, y) {
  if (ob.rect) {
    const [a, b, c, d] = ob.rect;
    const opp = [[c, d], [a, d], [a, b], [c, b]][k]; // the corner across from handle k stays
    return { rect: [opp[0], opp[1], x, y] };
  }
  if (ob.circle) { const [cx, cy] = ob.circle; return { circle: [cx, cy, Math.hypot(x - cx, y - cy)] }; }
  if (ob.polygon) return { polygon: ob.polygon.map((p, i) => (i === k ? [x, y] : [...p])) };
  if (ob.segment) { const s = [...ob.segment]; s[2 * k] = x; s[2 * k + 1] = y; return { segment: s }; }
  return ob;
}

export class ObstacleEditor {
  /**
   * `editor`: the start/goal Editor (its `scenario` and `commit()` are shared); `root`: where the
   * toolbar goes. The view draws the selection through `view.overlayHooks`.
   */
  constructor({ canvas, view, editor, root, download }) {
    Object.assign(this, { canvas, view, editor, root, download });
    this.tool = 'select';
    this.selected = -1;
    this.drag = null;
    this.draft = null; // polygon corners being placed
    this.undoStack = [];
    this.redoStack = [];
    this.committed = null; // the scenario as last committed (what undo returns to)
    view.overlayHooks = [...(view.overlayHooks ?? []), (ctx, L) => this.draw(ctx, L)];
    editor.beforeCommit = () => this.record(); // start/goal drags are undoable too
    // Capture phase: a drawing tool takes the press before the start/goal drag sees it.
    canvas.addEventListener('pointerdown', (e) => this.down(e), true);
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('dblclick', (e) => { if (this.draft) { e.preventDefault(); this.closeDraft(); } });
    document.addEventListener('keydown', (e) => this.key(e));
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
    }
    this.committed = this.scenario ? structuredClone(this.scenario) : null;
    if (this.selected >= (this.scenario?.obstacles?.length ?? 0)) this.selected = -1;
    this.render();
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

  save() {
    if (!this.scenario) return;
    const name = (this.scenario.name || 'scenario').replace(/[^\w.-]+/g, '-').toLowerCase();
    this.download(`${JSON.stringify(this.scenario, null, 2)}\n`, `${name}.json`);
  }

  // Toolbar

  render() {
    const s = this.scenario;
    const tool = (id, label, title) => {
      const b = el('button', { id: `tool-${id}`, type: 'button', text: label, title });
      b.setAttribute('aria-pressed', String(this.tool === id));
      b.addEventListener('click', () => this.setTool(id));
      return b;
    };
    const act = (id, label, fn, disabled, title) => {
      const b = el('button', { id, type: 'button', text: label, title });
      b.disabled = disabled;
      b.addEventListener('click', fn);
      return b;
    };
    const bounds = el('div', { className: 'row bounds' });
    ['x min', 'y min', 'x max', 'y max'].forEach((label, i) => {
      const id = `bounds-${i}`;
      const input = el('input', { id, type: 'number', step: 'any', value: s ? String(s.bounds[i]) : '' });
      input.disabled = !s;
      input.addEventListener('change', () => {
        const v = Number(input.value);
        if (!s || !Number.isFinite(v)) return;
        s.bounds[i] = v;
        this.preview();
        this.commit();
      });
      bounds.append(el('label', { className: 'bound', htmlFor: id }, el('span', { text: label }), input));
    });
    const hint = {
      select: 'Click an obstacle to select it; drag it to move it, drag a square handle to resize it.',
      rect: 'Drag on the canvas to draw a rectangle.',
      circle: 'Drag from the centre to draw a circle.',
      polygon: 'Click the corners; double-click, press Enter or click the first corner to close it. Escape drops it.',
    }[this.tool];
    this.root.replaceChildren(
      el('div', { className: 'row tools', role: 'toolbar', 'aria-label': 'Obstacle tools' },
        tool('select', 'Select', 'Select, move and resize obstacles'), tool('rect', 'Rectangle', 'Draw a rectangle'),
        tool('circle', 'Circle', 'Draw a circle'), tool('polygon', 'Polygon', 'Draw a polygon')),
      el('div', { className: 'row' },
        act('obstacle-delete', 'Delete', () => this.deleteSelected(), this.selected < 0, 'Delete the selected obstacle (Delete)'),
        act('undo', 'Undo', () => this.undo(), !this.undoStack.length, 'Undo (ctrl+Z)'),
        act('redo', 'Redo', () => this.redo(), !this.redoStack.length, 'Redo (ctrl+shift+Z)'),
        act('save-scenario', 'Save JSON', () => this.save(), !s, 'Download the scenario as JSON')),
      el('p', { className: 'hint', text: hint }),
      bounds,
    );
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
    const [x, y] = this.world(e);
    const obs = this.scenario.obstacles;
    if (this.tool === 'select') {
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
    if (!this.drag || !this.scenario) { if (this.draft) this.view.dirty = true; this.hover = this.view.layout && this.scenario ? this.world(e) : null; return; }
    const [x, y] = this.world(e);
    const obs = this.scenario.obstacles;
    const d = this.drag;
    obs[this.selected] = d.mode === 'move' ? moved(d.ob, x - d.x, y - d.y) : reshaped(d.ob, d.k, x, y);
    d.changed = true;
    this.preview();
  }

  up(e) {
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
  }

  /** The selection's outline and handles, and a polygon being drawn (called by the view). */
  draw(ctx, L) {
    const s = this.scenario;
    if (!s) return;
    const px = (x, y) => [L.sx(x), L.sy(y)];
    const ob = s.obstacles[this.selected];
    ctx.save();
    if (ob) {
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
}

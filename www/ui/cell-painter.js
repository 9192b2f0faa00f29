// The obstacle editor's Cells tool (PathFinding.js's walls): press on a free cell and drag to paint
// walls on every cell the pointer crosses; press on a wall and drag to erase. A press on the start
// or goal still drags them. The cells are grid search's (src/planners/grid.rs: its origin and its
// `cell` parameter) when it is the chosen planner, else the snapping grid's when Snap to grid is
// on, else grid search's default. Walls are ordinary `rect` obstacles inside their cells (see
// cell-grid.js for why a hair inside); erasing a cell cuts it out of any rectangle over it (split
// into up to 4 rectangles), but leaves circles and polygons (the status line says so). A painted
// cell never covers the start or goal. A whole drag is one undo step and one commit (on release);
// the canvas shows the cells as they are painted. A drag paints at most MAX_DRAG_CELLS cells, and
// the map keeps at most MAX_OBSTACLES obstacles and MAX_TOTAL_VERTICES vertices (a rect counts 4:
// the core's limits, src/limits.rs).
//
// A pointer move costs the same on a map of 10 obstacles or 100,000: the press files the
// obstacles by cell (painted cells' pieces in a map by cell, the others in a CellIndex,
// cell-index.js), each cell crossed asks only about the obstacles filed near it, and the picture
// is redrawn around the cells that changed (the view's drawSceneIn), not as a whole. The
// scenario's list of obstacles is rebuilt once, on release.

import { lattice, gridLattice, cellAt, cellBox, cellsOnSegment, grow, meets, rectMinus, wallPieces, pieceCell } from './cell-grid.js';
import { CellIndex, obstacleBox } from './cell-index.js';
import { inside } from './obstacle-shapes.js';
import { plannerCaps } from '../draw/capabilities.js';

export const MAX_DRAG_CELLS = 10000;
export const MAX_OBSTACLES = 100000;
export const MAX_TOTAL_VERTICES = 400000;
const LATTICE_COLOUR = 'rgba(31, 78, 154, 0.22)';
const LATTICE_PX = 6; // css px: lines closer than this are thinned

export class CellPainter {
  /**
   * `host`: the ObstacleEditor (its scenario, grid, preview(), commit(), say());
   * `config()`: the planner chosen in the panel, {planner, params} or null.
   */
  constructor(host, config) {
    this.host = host;
    this.config = config;
    this.drag = null;
  }

  /** The lattice cells are painted on, for the current map and planner. */
  lattice() {
    const s = this.host.scenario;
    const c = this.config?.();
    if (c && plannerCaps(c.planner).draws === 'grid') return gridLattice(s, Number(c.params?.cell) || 0);
    if (this.host.grid.on) return lattice(s.bounds, this.host.grid.step, 0);
    return gridLattice(s);
  }

  /** Rectangles that are painted cells' pieces on the current lattice (what Clear walls removes). */
  isPiece(ob, lat = this.lattice()) {
    return !!ob.rect && !!pieceCell(lat, ob.rect);
  }

  /** Press at world point (x, y): start painting or erasing; false if the press is not ours. */
  down(x, y) {
    const s = this.host.scenario;
    const lat = this.lattice();
    const c = cellAt(lat, x, y);
    if (!c) return false;
    // The obstacles split: each cell's pieces (rects within one cell), and the others, filed by
    // cell; an other a cut replaces keeps its place, and its pieces (`repl`) take it.
    const pieces = new Map();
    const others = [];
    const index = new CellIndex(lat);
    for (const ob of s.obstacles) {
      const p = ob.rect ? pieceCell(lat, ob.rect) : null;
      if (p) {
        const k = key(...p);
        if (!pieces.has(k)) pieces.set(k, []);
        pieces.get(k).push(ob.rect);
      } else {
        index.insert(others.length, obstacleBox(ob));
        others.push({ ob, id: others.length, repl: null, cut: false });
      }
    }
    this.drag = { lat, pieces, others, index, base: s.obstacles.length, baseVerts: s.obstacles.reduce((n, ob) => n + (ob.polygon ? ob.polygon.length : 4), 0), count: 0, added: 0, changed: false, notes: new Set(), last: [x, y], redraw: [] };
    this.drag.mode = this.isWall(...c) ? 'erase' : 'paint';
    this.visit(c);
    this.flush();
    return true;
  }

  /** The other obstacles (not painted cells' pieces) that may meet world box `b`: [{ob, repl}] in order, none replaced. */
  othersNear(b) {
    const d = this.drag;
    return d.index.query(b).map((id) => d.others[id]).filter((e) => !e.repl);
  }

  /** Every obstacle as drag `d` left them: the others in their places (a cut one by its pieces), then the painted cells' pieces. */
  obstacles(d = this.drag) {
    const out = [];
    const put = (e) => { if (e.repl) e.repl.forEach((id) => put(d.others[id])); else out.push(e.ob); };
    for (const e of d.others) if (!e.cut) put(e);
    for (const list of d.pieces.values()) for (const rect of list) out.push({ rect });
    return out;
  }

  /** The pointer moved to (x, y): every cell crossed since the last sample. */
  move(x, y) {
    const d = this.drag;
    if (!d || d.stopped) return;
    const cells = cellsOnSegment(d.lat, d.last, [x, y]);
    d.last = [x, y];
    for (const c of cells.slice(1)) {
      if (d.stopped) break;
      if (c[0] >= 0 && c[1] >= 0 && c[0] < d.lat.nx && c[1] < d.lat.ny) this.visit(c);
    }
    this.flush();
  }

  /** Release: one commit for the whole drag (one undo step). */
  up() {
    const d = this.drag;
    if (!d) return;
    this.drag = null;
    if (!d.changed) return;
    this.host.scenario.obstacles = this.obstacles(d);
    this.host.commit();
  }

  /** Escape or a lost pointer: the map as it was before the drag. */
  cancel() {
    if (!this.drag) return;
    this.drag = null;
    this.host.editor.scenario = structuredClone(this.host.committed);
    this.host.preview();
    this.host.say('');
  }

  // Cells

  /** Whether cell [i, j] is a wall: a painted cell, or its centre covered by another obstacle. */
  isWall(i, j) {
    const d = this.drag;
    const { lat } = d;
    if (i < 0 || j < 0 || i >= lat.nx || j >= lat.ny) return true; // past the map: walls touch its edge
    if (d.pieces.has(key(i, j))) return true;
    const cx = lat.ox + (i + 0.5) * lat.side, cy = lat.oy + (j + 0.5) * lat.side;
    return this.othersNear([cx, cy, cx, cy]).some((e) => inside(e.ob, cx, cy, 0));
  }

  /** @param {number[]} c a cell [i, j] */
  visit(c) {
    const [i, j] = c;
    const d = this.drag;
    if (d.mode === 'paint') this.paint(i, j); else this.erase(i, j);
  }

  paint(i, j) {
    const d = this.drag;
    if (this.isWall(i, j)) return;
    const s = this.host.scenario;
    const { lat } = d;
    const box = cellBox(lat, i, j);
    const [bx0, by0, bx1, by1] = s.bounds;
    const [cx, cy] = [(box[0] + box[2]) / 2, (box[1] + box[3]) / 2];
    if (cx < bx0 || cx > bx1 || cy < by0 || cy > by1) return; // grid search blocks it anyway
    const g = grow(box, lat.margin);
    const ends = ['start', 'goal'].filter((w) => s[w] && g[0] <= s[w][0] && s[w][0] <= g[2] && g[1] <= s[w][1] && s[w][1] <= g[3]);
    if (ends.length) { d.notes.add(`A wall never covers the ${ends.join(' or ')}: that cell is left free.`); return; }
    if (!this.room(5)) return; // a cell makes at most 5 pieces
    d.pieces.set(key(i, j), []); // a wall now, for its neighbours' pieces
    for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) this.rebuild(i + di, j + dj);
    d.changed = true;
    d.redraw.push([i, j]);
  }

  erase(i, j) {
    const d = this.drag;
    const { lat } = d;
    const k = key(i, j);
    const box = cellBox(lat, i, j);
    const g = grow(box, lat.margin);
    const tiny = lat.margin / 100;
    const near = this.othersNear(g);
    const cut = near.filter((e) => e.ob.rect && meets(norm(e.ob.rect), g));
    if (!this.room(3 * cut.length + 8)) return; // splits; neighbours' corners
    let changed = d.pieces.delete(k);
    // rectangles over the cell lose it (their pieces around it stay, in their place); circles and polygons stay
    for (const e of cut) {
      changed = true;
      e.repl = rectMinus(e.ob.rect, g, tiny).map((rect) => {
        const id = d.others.length;
        d.others.push({ ob: { rect }, id, repl: null, cut: true });
        d.index.insert(id, obstacleBox({ rect }));
        return id;
      });
      d.index.remove(e.id);
    }
    if (near.some((e) => !e.ob.rect && touches(e.ob, box))) d.notes.add('Cells under a circle or polygon are not erased: select it and delete it.');
    if (!changed) return;
    // the painted neighbours draw back from it (their sides facing it were exact)
    for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) if (di || dj) this.rebuild(i + di, j + dj);
    d.changed = true;
    d.redraw.push([i, j]);
  }

  /**
   * Whether one more cell, adding at most `more` obstacles, stays within the bounds; if not, the
   * drag stops and says why.
   */
  room(more) {
    const d = this.drag;
    const verb = d.mode === 'paint' ? 'paints' : 'erases';
    if (d.count >= MAX_DRAG_CELLS) d.notes.add(`A drag ${verb} at most ${MAX_DRAG_CELLS.toLocaleString('en')} cells: release and drag again.`);
    else if (d.base + d.added + more > MAX_OBSTACLES || d.baseVerts + 4 * (d.added + more) > MAX_TOTAL_VERTICES) {
      d.notes.add(`The map holds at most ${MAX_OBSTACLES.toLocaleString('en')} obstacles and ${MAX_TOTAL_VERTICES.toLocaleString('en')} vertices (a rectangle counts 4): the drag stops here.`);
    }
    else {
      d.count++;
      d.added += more;
      return true;
    }
    d.stopped = true;
    return false;
  }

  /** Cell [i, j]'s pieces again from its neighbours, if it is a painted cell. */
  rebuild(i, j) {
    const d = this.drag;
    const k = key(i, j);
    if (!d.pieces.has(k)) return;
    d.pieces.set(k, wallPieces(d.lat, i, j, (a, b) => this.isWall(a, b)));
  }

  /**
   * The drag so far, drawn at once (not yet committed): the picture around each cell it changed
   * (the cell and its neighbours, whose pieces it rebuilt), with the obstacles that reach there.
   */
  flush() {
    const d = this.drag;
    const L = this.host.view.layout;
    this.host.selected = -1;
    for (const [i, j] of d.redraw.splice(0)) {
      if (!L) break;
      const area = [...cellBox(d.lat, i - 1, j - 1).slice(0, 2), ...cellBox(d.lat, i + 1, j + 1).slice(2)];
      const near = grow(area, L.px(4) / L.scale); // obstacle edges reaching into it
      const [i0, j0, i1, j1] = d.index.cells(near);
      const obstacles = this.othersNear(near).map((e) => e.ob);
      for (let cj = j0; cj <= j1; cj++) {
        for (let ci = i0; ci <= i1; ci++) for (const rect of d.pieces.get(key(ci, cj)) ?? []) obstacles.push({ rect });
      }
      this.host.view.drawSceneIn(area, obstacles);
    }
    this.host.say([...d.notes].join(' '));
  }

  /** The lattice, faint, over the map (lines closer than LATTICE_PX css px are thinned). */
  draw(ctx, L) {
    const s = this.host.scenario;
    const lat = this.drag?.lat ?? this.lattice();
    const [x0, y0, x1, y1] = s.bounds;
    let every = 1;
    for (const m of [2, 5, 10, 20, 50, 100, 200, 500, 1000]) {
      if (lat.side * every * L.scale >= L.px(LATTICE_PX)) break;
      every = m;
    }
    const xs = Math.min(x1, lat.ox + lat.nx * lat.side), ys = Math.min(y1, lat.oy + lat.ny * lat.side);
    ctx.save();
    ctx.beginPath();
    for (let i = 0; i <= lat.nx; i += every) {
      const x = lat.ox + i * lat.side;
      if (x < x0 - 1e-9 || x > xs + 1e-9) continue;
      const sx = Math.round(L.sx(x)) + 0.5;
      ctx.moveTo(sx, L.sy(y0));
      ctx.lineTo(sx, L.sy(ys));
    }
    for (let j = 0; j <= lat.ny; j += every) {
      const y = lat.oy + j * lat.side;
      if (y < y0 - 1e-9 || y > ys + 1e-9) continue;
      const sy = Math.round(L.sy(y)) + 0.5;
      ctx.moveTo(L.sx(x0), sy);
      ctx.lineTo(L.sx(xs), sy);
    }
    ctx.strokeStyle = LATTICE_COLOUR;
    ctx.lineWidth = 1;
    ctx.stroke();
    ctx.restore();
  }
}

const key = (i, j) => `${i},${j}`;
const norm = (r) => [Math.min(r[0], r[2]), Math.min(r[1], r[3]), Math.max(r[0], r[2]), Math.max(r[1], r[3])];

/** Whether a circle, polygon or segment covers a point of cell box b (its centre or a corner). */
function touches(ob, b) {
  const pts = [[(b[0] + b[2]) / 2, (b[1] + b[3]) / 2], [b[0], b[1]], [b[2], b[1]], [b[2], b[3]], [b[0], b[3]]];
  if (pts.some(([x, y]) => inside(ob, x, y, 0))) return true;
  const verts = ob.polygon ?? (ob.segment ? [ob.segment.slice(0, 2), ob.segment.slice(2)] : ob.circle ? [ob.circle.slice(0, 2)] : []);
  return verts.some(([x, y]) => x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3]);
}

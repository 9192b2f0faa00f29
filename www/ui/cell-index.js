// The Cells tool's index of obstacles by lattice cell (cell-painter.js): a drag over a map of
// 90,000 rectangles asks, for each cell it crosses, which obstacles cover the cell's centre or
// meet it, and which to redraw around it. Scanning every obstacle for each cell took 0.4 s a
// pointer move; the index answers from the few obstacles filed near the cell.
//
// An obstacle is filed by its bounding box in lattice cells (clamped to one cell beyond the
// lattice), in the level of buckets 1, 2, 4, … cells wide where the box spans at most 2 × 2
// buckets: every obstacle is in at most four buckets, and a query of a few cells looks at a few
// buckets a level (about log2 of the lattice's side levels), whatever the obstacles' number or sizes.

/** World box [x0, y0, x1, y1] of an obstacle (rect, circle, polygon or segment). */
export function obstacleBox(ob) {
  if (ob.rect) {
    const [a, b, c, d] = ob.rect;
    return [Math.min(a, c), Math.min(b, d), Math.max(a, c), Math.max(b, d)];
  }
  if (ob.circle) {
    const [x, y, r] = ob.circle;
    return [x - r, y - r, x + r, y + r];
  }
  const pts = ob.polygon ?? (ob.segment ? [ob.segment.slice(0, 2), ob.segment.slice(2)] : []);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of pts) {
    x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
  }
  return [x0, y0, x1, y1];
}

export class CellIndex {
  /** An empty index over lattice `lat` ({ox, oy, side, nx, ny}, cell-grid.js). */
  constructor(lat) {
    this.lat = lat;
    this.levels = []; // per level: Map(bucket key → Set of ids)
    this.filed = new Map(); // id → [level, keys]
  }

  /** The lattice cells a world box covers: [i0, j0, i1, j1], clamped to one cell beyond the lattice. */
  cells(box) {
    const { ox, oy, side, nx, ny } = this.lat;
    const c = (v, n) => Math.max(-1, Math.min(n, Number.isFinite(v) ? Math.floor(v) : (v > 0 ? n : -1)));
    return [c((box[0] - ox) / side, nx), c((box[1] - oy) / side, ny), c((box[2] - ox) / side, nx), c((box[3] - oy) / side, ny)];
  }

  /** File `id` under world box `box`. */
  insert(id, box) {
    const [i0, j0, i1, j1] = this.cells(box);
    let level = 0;
    while (((i1 + 1) >> level) - ((i0 + 1) >> level) > 1 || ((j1 + 1) >> level) - ((j0 + 1) >> level) > 1) level++;
    while (this.levels.length <= level) this.levels.push(new Map());
    const map = this.levels[level];
    const keys = [];
    for (let bj = (j0 + 1) >> level; bj <= (j1 + 1) >> level; bj++) {
      for (let bi = (i0 + 1) >> level; bi <= (i1 + 1) >> level; bi++) {
        const key = bi * 65536 + bj;
        let set = map.get(key);
        if (!set) map.set(key, set = new Set());
        set.add(id);
        keys.push(key);
      }
    }
    this.filed.set(id, [level, keys]);
  }

  /** Take `id` out. */
  remove(id) {
    const f = this.filed.get(id);
    if (!f) return;
    this.filed.delete(id);
    const map = this.levels[f[0]];
    for (const key of f[1]) {
      const set = map.get(key);
      set?.delete(id);
      if (set && !set.size) map.delete(key);
    }
  }

  /** The ids filed near world box `box` (a superset of those whose boxes meet it), ascending. */
  query(box) {
    const [i0, j0, i1, j1] = this.cells(box);
    const out = new Set();
    this.levels.forEach((map, level) => {
      if (!map.size) return;
      for (let bj = (j0 + 1) >> level; bj <= (j1 + 1) >> level; bj++) {
        for (let bi = (i0 + 1) >> level; bi <= (i1 + 1) >> level; bi++) {
          const set = map.get(bi * 65536 + bj);
          if (set) for (const id of set) out.add(id);
        }
      }
    });
    return [...out].sort((a, b) => a - b);
  }
}

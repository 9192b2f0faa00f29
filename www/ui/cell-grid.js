// The Cells tool's geometry (cell-painter.js): the lattice of square cells, the cell under a point,
// the cells a pointer crosses between two samples, a rectangle minus a box, and the rectangles that
// make a painted cell a wall.
//
// Why walls are not the cells' exact squares: obstacles are closed sets and grid search blocks a
// cell an obstacle touches (src/planners/grid.rs), so an exact square would also block its eight
// neighbours, which share its edges and corners. A painted cell is its square minus the free
// neighbours grown by `margin` (a hundredth of a cell): its sides are exact where the neighbour is
// a wall too (the walls touch, so no planner slips between them), and a hair inside the cell where
// the neighbour is free (which grid search then leaves free). Rectangles are [x0, y0, x1, y1].

/** Grid search's default cell side: a fortieth of the map's shorter side (grid.rs). */
export function defaultCell(bounds) {
  const [x0, y0, x1, y1] = bounds;
  return Math.min(x1 - x0, y1 - y0) / 40;
}

/**
 * Grid search's lattice for a scenario and a `cell` parameter (0: the default): on an occupancy map
 * (the scenario's `map` block, io::occupancy) the default is one pixel and the lattice is the
 * image's pixels, anchored at the map's origin, as grid.rs lays it; else the bounds' fortieth.
 */
export function gridLattice(scenario, cell = 0) {
  const map = scenario.map;
  const r = Number(map?.resolution);
  const onMap = r > 0 && Array.isArray(map.origin) && map.origin.every(Number.isFinite);
  const side = cell > 0 ? cell : onMap ? r : defaultCell(scenario.bounds);
  return onMap && side === r ? lattice(scenario.bounds, side, map.origin) : lattice(scenario.bounds, side);
}

/**
 * The lattice of square cells of `side` covering `bounds`, anchored at (ox, oy): grid search's
 * own (anchored at the bounds' lower-left corner, ceil(w / side) × ceil(h / side) cells, the last
 * ones reaching past the bounds) unless `anchor` is given (the snapping grid's 0, or an
 * occupancy map's origin [x, y]).
 * @param {number[]} bounds @param {number} side @param {null | number | number[]} [anchor]
 * @returns {{ox: number, oy: number, side: number, nx: number, ny: number, margin: number}}
 */
export function lattice(bounds, side, anchor = null) {
  const [x0, y0, x1, y1] = bounds;
  const [ax, ay] = Array.isArray(anchor) ? anchor : [anchor, anchor];
  const ox = ax === null ? x0 : ax + Math.floor((x0 - ax) / side) * side;
  const oy = ay === null ? y0 : ay + Math.floor((y0 - ay) / side) * side;
  const nx = Math.max(1, Math.ceil((x1 - ox) / side - 1e-9));
  const ny = Math.max(1, Math.ceil((y1 - oy) / side - 1e-9));
  return { ox, oy, side, nx, ny, margin: side / 100 };
}

/** The cell [i, j] holding world point (x, y) (grid.rs's cell_of: floor), or null outside the lattice. */
export function cellAt(lat, x, y) {
  const i = Math.floor((x - lat.ox) / lat.side), j = Math.floor((y - lat.oy) / lat.side);
  return i >= 0 && j >= 0 && i < lat.nx && j < lat.ny ? [i, j] : null;
}

/** A lattice coordinate, rounded to 12 significant digits (0.325, not 0.32500000000000007). */
export const clean = (v) => Number(v.toPrecision(12));

/** Cell [i, j]'s square. */
export function cellBox(lat, i, j) {
  const { ox, oy, side } = lat;
  return [clean(ox + i * side), clean(oy + j * side), clean(ox + (i + 1) * side), clean(oy + (j + 1) * side)];
}

/** Box `b` grown by `d` on every side. */
export const grow = (b, d) => [b[0] - d, b[1] - d, b[2] + d, b[3] + d];

/**
 * The cells a straight move from world point a to b crosses, in order (a grid walk: each cell
 * shares a side with the one before, so a fast drag leaves no gap, even diagonally). At most `max`
 * cells; they may lie outside the lattice (the caller skips those).
 */
export function cellsOnSegment(lat, a, b, max = 100000) {
  const u0 = (a[0] - lat.ox) / lat.side, v0 = (a[1] - lat.oy) / lat.side;
  const u1 = (b[0] - lat.ox) / lat.side, v1 = (b[1] - lat.oy) / lat.side;
  let i = Math.floor(u0), j = Math.floor(v0);
  const ie = Math.floor(u1), je = Math.floor(v1);
  const du = u1 - u0, dv = v1 - v0;
  const si = Math.sign(du), sj = Math.sign(dv);
  const stepU = du ? Math.abs(1 / du) : Infinity, stepV = dv ? Math.abs(1 / dv) : Infinity;
  let tu = du > 0 ? (i + 1 - u0) / du : du < 0 ? (u0 - i) / -du : Infinity;
  let tv = dv > 0 ? (j + 1 - v0) / dv : dv < 0 ? (v0 - j) / -dv : Infinity;
  const out = [[i, j]];
  const n = Math.min(max - 1, Math.abs(ie - i) + Math.abs(je - j));
  for (let k = 0; k < n; k++) {
    // the next side crossed; past the end (float noise), head for the last cell anyway
    const alongU = i !== ie && (j === je || tu < tv || (tu === tv && Math.abs(du) >= Math.abs(dv)));
    if (alongU) { i += si; tu += stepU; } else { j += sj; tv += stepV; }
    out.push([i, j]);
  }
  return out;
}

/** Whether closed boxes a and b share a point. */
export const meets = (a, b) => a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];

/**
 * Rectangle `r` minus box `b`: up to 4 rectangles covering every point of r outside b exactly
 * once (below b, above b, and left and right of b within b's rows); [r] when their insides do not
 * overlap. Pieces thinner than `tiny` are dropped.
 */
export function rectMinus(r, b, tiny = 0) {
  const [x0, y0, x1, y1] = [Math.min(r[0], r[2]), Math.min(r[1], r[3]), Math.max(r[0], r[2]), Math.max(r[1], r[3])];
  if (b[0] >= x1 || b[2] <= x0 || b[1] >= y1 || b[3] <= y0) return [[x0, y0, x1, y1]];
  const lo = Math.max(y0, b[1]), hi = Math.min(y1, b[3]);
  const pieces = [
    [x0, y0, x1, lo],             // below
    [x0, hi, x1, y1],             // above
    [x0, lo, Math.max(x0, b[0]), hi], // left, in b's rows
    [Math.min(x1, b[2]), lo, x1, hi], // right, in b's rows
  ];
  return pieces.filter(([a, c, d, e]) => d - a > tiny && e - c > tiny);
}

/**
 * The rectangles that make cell [i, j] a wall: its square minus every free neighbour (of the 8)
 * grown by the lattice's margin. `wall(i, j)`: whether a cell is a wall (painted or covered).
 */
export function wallPieces(lat, i, j, wall) {
  let pieces = [cellBox(lat, i, j)];
  for (let dj = -1; dj <= 1; dj++) {
    for (let di = -1; di <= 1; di++) {
      if ((di || dj) && !wall(i + di, j + dj)) {
        const g = grow(cellBox(lat, i + di, j + dj), lat.margin);
        pieces = pieces.flatMap((p) => rectMinus(p, g, lat.margin / 100));
      }
    }
  }
  return pieces.map((p) => p.map(clean));
}

/** Whether rectangle `r` lies within cell box `box` (a painted cell's piece). */
export function within(r, box, tol) {
  return Math.min(r[0], r[2]) >= box[0] - tol && Math.max(r[0], r[2]) <= box[2] + tol
    && Math.min(r[1], r[3]) >= box[1] - tol && Math.max(r[1], r[3]) <= box[3] + tol;
}

/** The cell a rectangle lies within ([i, j]), or null: then it is not a painted cell's piece. */
export function pieceCell(lat, r) {
  const c = cellAt(lat, (r[0] + r[2]) / 2, (r[1] + r[3]) / 2);
  return c && within(r, cellBox(lat, c[0], c[1]), lat.side * 1e-9) ? c : null;
}

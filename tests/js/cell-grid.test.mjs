// The Cells tool's geometry (www/ui/cell-grid.js): the lattice is grid search's (src/planners/grid.rs),
// the cell under a point, the cells a drag crosses (no gaps), a rectangle minus a box (every point
// left covered exactly once, the box's not at all), a painted cell's pieces (they cover the wall
// cells and never meet a free cell, which grid search would then block), and the Cells tool itself
// on a stand-in editor: random drags against a model of the painted set.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { lattice, defaultCell, cellAt, cellBox, cellsOnSegment, rectMinus, wallPieces, pieceCell, grow, meets } from '../../www/ui/cell-grid.js';
import { readFileSync } from 'node:fs';
import { CellPainter, MAX_OBSTACLES, MAX_TOTAL_VERTICES, MAX_DRAG_CELLS } from '../../www/ui/cell-painter.js';
import { mulberry32 as rng } from './seeded.mjs';
import { learn } from '../../www/draw/capabilities.js';
import { initSync, planners } from '../../www/pkg/planarium.js';

// The painter paints on the lattice of the planner that draws a grid (the registry's capabilities,
// learnt by the page from its worker; here from the core in Node).
initSync({ module: readFileSync(new URL('../../www/pkg/planarium_bg.wasm', import.meta.url)) });
learn({ planners: JSON.parse(planners()) });

const inBox = (b, x, y) => x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3];
const inOpen = (b, x, y) => x > b[0] && x < b[2] && y > b[1] && y < b[3];

test('the lattice is grid search\'s: origin at the lower-left corner, ceil(w / cell) × ceil(h / cell) cells, a fortieth of the shorter side by default', () => {
  const unit = lattice([0, 0, 1, 1], defaultCell([0, 0, 1, 1]));
  assert.deepEqual([unit.ox, unit.oy, unit.side, unit.nx, unit.ny], [0, 0, 0.025, 40, 40]);
  const wide = lattice([-2, 1, 8, 6], defaultCell([-2, 1, 8, 6]));
  assert.deepEqual([wide.ox, wide.oy, wide.side, wide.nx, wide.ny], [-2, 1, 0.125, 80, 40]);
  const odd = lattice([0, 0, 1, 0.7], 0.3); // the last row and column reach past the bounds
  assert.deepEqual([odd.nx, odd.ny], [4, 3]);
  // the snapping grid's lattice is anchored at 0
  const snap = lattice([0.12, -0.33, 1, 1], 0.1, 0);
  assert.ok(Math.abs(snap.ox - 0.1) < 1e-12 && Math.abs(snap.oy + 0.4) < 1e-12, JSON.stringify(snap));
  assert.deepEqual([snap.nx, snap.ny], [9, 14]);
});

test('the cell under a point: floor, as grid.rs\'s cell_of; outside the lattice, none', () => {
  const lat = lattice([0, 0, 1, 1], 0.025);
  assert.deepEqual(cellAt(lat, 0.0125, 0.0125), [0, 0]);
  assert.deepEqual(cellAt(lat, 0.1, 0.1), [4, 4]);
  assert.deepEqual(cellAt(lat, 0.999, 0.5125), [39, 20]);
  assert.equal(cellAt(lat, -0.001, 0.5), null);
  assert.equal(cellAt(lat, 0.5, 1.0001), null);
  assert.deepEqual(cellBox(lat, 13, 2), [0.325, 0.05, 0.35, 0.075], 'no float noise');
});

test('the cells a drag crosses: each shares a side with the one before, from the first cell to the last, every point of the move in one of them', () => {
  const lat = lattice([0, 0, 1, 1], 0.05);
  const r = rng(7);
  for (let n = 0; n < 500; n++) {
    const a = [r() * 1.2 - 0.1, r() * 1.2 - 0.1];
    const b = n % 5 === 0 ? [a[0], r()] : [r() * 1.2 - 0.1, r() * 1.2 - 0.1]; // some vertical moves
    const cells = cellsOnSegment(lat, a, b);
    const f = (p) => [Math.floor((p[0] - lat.ox) / lat.side), Math.floor((p[1] - lat.oy) / lat.side)];
    assert.deepEqual(cells[0], f(a));
    assert.deepEqual(cells.at(-1), f(b));
    for (let k = 1; k < cells.length; k++) {
      assert.equal(Math.abs(cells[k][0] - cells[k - 1][0]) + Math.abs(cells[k][1] - cells[k - 1][1]), 1, `${JSON.stringify([a, b])}: step ${k}`);
    }
    const keys = new Set(cells.map((c) => c.join()));
    for (let t = 0; t <= 1; t += 1 / 400) {
      const c = f([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
      assert.ok(keys.has(c.join()), `${JSON.stringify([a, b])} at t = ${t}: cell ${c} missed`);
    }
  }
  // a long drag is bounded
  assert.equal(cellsOnSegment(lat, [0, 0], [1e6, 0], 100).length, 100);
});

test('a rectangle minus a box: every point left covered exactly once, the box\'s not at all', () => {
  const r = rng(11);
  for (let n = 0; n < 300; n++) {
    const rect = [r(), r(), r(), r()]; // any corner order
    const bx = r() * 1.2 - 0.1, by = r() * 1.2 - 0.1;
    const box = [bx, by, bx + r() * 0.5, by + r() * 0.5];
    const pieces = rectMinus(rect, box);
    assert.ok(pieces.length <= 4);
    const R = [Math.min(rect[0], rect[2]), Math.min(rect[1], rect[3]), Math.max(rect[0], rect[2]), Math.max(rect[1], rect[3])];
    for (const p of pieces) assert.ok(p[2] > p[0] && p[3] > p[1] && p[0] >= R[0] && p[2] <= R[2] && p[1] >= R[1] && p[3] <= R[3], JSON.stringify(p));
    for (let k = 0; k < 400; k++) {
      const x = r() * 1.2 - 0.1, y = r() * 1.2 - 0.1;
      const covered = pieces.filter((p) => inBox(p, x, y)).length;
      const want = inBox(R, x, y) && !inBox(box, x, y) ? 1 : 0;
      assert.equal(covered, want, `${JSON.stringify({ rect, box, x, y, pieces })}`);
    }
  }
  assert.deepEqual(rectMinus([0, 0, 1, 1], [2, 2, 3, 3]), [[0, 0, 1, 1]], 'apart: unchanged');
  assert.deepEqual(rectMinus([0, 0, 1, 1], [-1, -1, 2, 2]), [], 'covered: nothing left');
  assert.deepEqual(rectMinus([0, 0, 3, 3], [1, 1, 2, 2]).length, 4, 'a hole: four pieces around it');
});

test('a painted cell\'s pieces: inside its cell, covering it up to a hair from free cells, never meeting a free cell; walls side by side touch', () => {
  const lat = lattice([0, 0, 1, 1], 0.1);
  const r = rng(3);
  for (let n = 0; n < 40; n++) {
    const wall = new Set();
    for (let i = 0; i < lat.nx; i++) for (let j = 0; j < lat.ny; j++) if (r() < 0.45) wall.add(`${i},${j}`);
    const isWall = (i, j) => i < 0 || j < 0 || i >= lat.nx || j >= lat.ny || wall.has(`${i},${j}`);
    const pieces = [];
    for (const k of wall) {
      const [i, j] = k.split(',').map(Number);
      for (const p of wallPieces(lat, i, j, isWall)) {
        assert.deepEqual(pieceCell(lat, p), [i, j], 'a piece lies within its cell');
        pieces.push(p);
      }
    }
    for (let i = 0; i < lat.nx; i++) {
      for (let j = 0; j < lat.ny; j++) {
        if (isWall(i, j)) continue;
        const box = cellBox(lat, i, j);
        const p = pieces.find((q) => meets(q, box));
        assert.ok(!p, `free cell ${i},${j} is met by ${JSON.stringify(p)}`);
      }
    }
    // every point of a wall cell farther than the margin from any free cell is covered
    const free = [];
    for (let i = 0; i < lat.nx; i++) for (let j = 0; j < lat.ny; j++) if (!isWall(i, j)) free.push(grow(cellBox(lat, i, j), lat.margin));
    for (let k = 0; k < 3000; k++) {
      const x = r(), y = r();
      const c = cellAt(lat, x, y);
      if (!isWall(...c) || free.some((b) => inBox(b, x, y))) continue;
      assert.ok(pieces.some((p) => inBox(p, x, y)), `(${x}, ${y}) in wall cell ${c} is not covered`);
    }
    // two walls side by side share their edge: its midpoint is in both cells' pieces
    for (const k of wall) {
      const [i, j] = k.split(',').map(Number);
      if (!wall.has(`${i + 1},${j}`)) continue;
      const x = cellBox(lat, i + 1, j)[0], y = lat.oy + (j + 0.5) * lat.side;
      assert.ok(pieces.some((p) => inBox(p, x, y) && p[2] === x) && pieces.some((p) => inBox(p, x, y) && p[0] === x), `edge of ${k}`);
    }
  }
  // a lone cell: its square a hundredth of a cell inside on every side
  const lone = wallPieces(lat, 3, 4, (i, j) => i === 3 && j === 4);
  assert.deepEqual(lone, [[0.301, 0.401, 0.399, 0.499]]);
  assert.ok(!inOpen(lone[0], 0.3, 0.45));
});

/** The Cells tool (cell-painter.js) on a stand-in for the obstacle editor: the scenario it edits, commits counted. */
function painterOn(scenario, config = () => ({ planner: 'grid-search', params: { cell: 0.1 } })) {
  const host = {
    scenario, grid: { on: false, step: 0.05 }, selected: -1, said: '', commits: 0,
    // no canvas here: the painter draws a drag's cells only once the view has a layout
    view: { layout: null, drawSceneIn() { throw new Error('drawn without a layout'); } },
    preview() {}, say(text) { this.said = text; }, commit() { this.commits++; },
  };
  return [new CellPainter(host, config), host];
}
/** Grid search's labels (grid.rs): a cell is blocked when a (closed) rect meets its (closed) square. */
function blockedByGrid(lat, obstacles) {
  const out = new Set();
  for (let j = 0; j < lat.ny; j++) {
    for (let i = 0; i < lat.nx; i++) {
      const cx = lat.ox + (i + 0.5) * lat.side, cy = lat.oy + (j + 0.5) * lat.side, h = 0.5 * lat.side;
      const sq = [cx - h, cy - h, cx + h, cy + h];
      if (obstacles.some((o) => meets([Math.min(o.rect[0], o.rect[2]), Math.min(o.rect[1], o.rect[3]), Math.max(o.rect[0], o.rect[2]), Math.max(o.rect[1], o.rect[3])], sq))) out.add(`${i},${j}`);
    }
  }
  return out;
}

test('the Cells tool, drag after drag: grid search blocks exactly the cells painted and not erased, walls side by side touch, the start and goal cells stay free', () => {
  const r = rng(5);
  const scenario = { bounds: [0, 0, 1, 1], start: [0.15, 0.15], goal: [0.85, 0.85], obstacles: [] };
  const [painter, host] = painterOn(scenario);
  const lat = painter.lattice();
  assert.deepEqual([lat.nx, lat.ny, lat.side], [10, 10, 0.1]);
  const model = new Set();
  const ends = new Set(['1,1', '8,8']);
  for (let n = 0; n < 150; n++) {
    const a = [r(), r()];
    const path = [a, ...Array.from({ length: 1 + Math.floor(r() * 3) }, () => [r() * 1.1 - 0.05, r() * 1.1 - 0.05])];
    const first = cellAt(lat, ...a).join();
    const paint = !model.has(first);
    const cells = [first];
    for (let k = 1; k < path.length; k++) {
      for (const c of cellsOnSegment(lat, path[k - 1], path[k]).slice(1)) if (cellAt(lat, c[0] * 0.1 + 0.05, c[1] * 0.1 + 0.05)) cells.push(c.join());
    }
    for (const c of cells) if (paint && !ends.has(c)) model.add(c); else if (!paint) model.delete(c);
    const commits = host.commits;
    assert.ok(painter.down(...a));
    for (const p of path.slice(1)) painter.move(...p);
    painter.up();
    assert.ok(host.commits - commits <= 1, 'one commit per drag');
    assert.deepEqual([...blockedByGrid(lat, scenario.obstacles)].sort(), [...model].sort(), `drag ${n}`);
    for (const c of model) {
      const [i, j] = c.split(',').map(Number);
      if (!model.has(`${i + 1},${j}`)) continue;
      const x = cellBox(lat, i + 1, j)[0], y = (j + 0.5) * 0.1;
      assert.ok(scenario.obstacles.some((o) => inBox(o.rect, x, y)), `the edge between ${c} and its right neighbour is a wall`);
    }
  }
});

test('the Cells tool stops at the obstacle limit and says so; a painted cell is never the start\'s', () => {
  const scenario = { bounds: [0, 0, 1, 1], start: [0.15, 0.15], goal: [0.85, 0.85], obstacles: Array.from({ length: MAX_OBSTACLES - 12 }, () => ({ circle: [2, 2, 0.01] })) };
  const [painter, host] = painterOn(scenario);
  painter.down(0.05, 0.55);
  painter.move(0.95, 0.55);
  painter.up();
  assert.equal(scenario.obstacles.length, MAX_OBSTACLES - 12 + 2, 'two cells (5 obstacles at most each), then it stops');
  assert.match(host.said, /at most 100,000 obstacles and 400,000 vertices/);
  // the same limits as the core's
  const rust = readFileSync(new URL('../../src/limits.rs', import.meta.url), 'utf8');
  const limit = (name) => Number(new RegExp(`pub const ${name}: usize = ([\\d_]+);`).exec(rust)[1].replaceAll('_', ''));
  assert.deepEqual([MAX_OBSTACLES, MAX_TOTAL_VERTICES], [limit('MAX_OBSTACLES'), limit('MAX_TOTAL_VERTICES')]);
  // polygons count their vertices
  const poly = { polygon: Array.from({ length: 1000 }, (_, k) => [2 + Math.cos(k / 159.2), 2 + Math.sin(k / 159.2)]) };
  const [p3] = painterOn({ bounds: [0, 0, 1, 1], start: [0.15, 0.15], goal: [0.85, 0.85], obstacles: [...Array.from({ length: 399 }, () => poly), { polygon: poly.polygon.slice(0, 900) }] });
  p3.down(0.05, 0.55);
  p3.move(0.95, 0.55);
  p3.up();
  assert.equal(p3.host.scenario.obstacles.length, 400 + 5, '100 vertices left: 25 rects, 5 cells budgeted at 5 each');
  const [p2, h2] = painterOn({ bounds: [0, 0, 1, 1], start: [0.15, 0.15], goal: [0.85, 0.85], obstacles: [] });
  p2.down(0.05, 0.15);
  p2.move(0.25, 0.15);
  p2.up();
  assert.equal(p2.host.scenario.obstacles.length, 2, 'cells 0 and 2 of the row, not the start\'s');
  assert.match(h2.said, /never covers the start/);
  assert.ok(MAX_DRAG_CELLS >= 1000);
});

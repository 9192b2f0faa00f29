// EST's density overlay (www/draw/density.js) against the planner: EST and bi-EST run under Node
// (the wasm build) and their records go through the page's RunModel one at a time. At every SELECT
// record, the cell the planner says it picked must hold, in the overlay's mirror, as many nodes as
// the record says, the tree must have as many non-empty cells, and the probability the overlay
// shades that cell by must be the record's. The mirror files points itself (the rule of
// src/planners/est.rs, re-implemented in JS), so a wrong cell rule, a missed root or a wrong grid
// size fails here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { scenarios, runRecords as records } from './core-runs.mjs';
import { EventKind as K, STRIDE } from '../../www/run/events.js';
import { RunModel } from '../../www/run/playback.js';
import { densityCell } from '../../www/draw/density.js';

const RUNS = [
  ['narrow', 'est', {}, 3],
  ['zigzag', 'bi-est', {}, 2],
  ['arm-2', 'est', { grid: 7 }, 1],
  ['ompl-rect', 'bi-est', { grid: 33 }, 4],
];

for (const [scenario, planner, params, seed] of RUNS) {
  test(`density overlay: ${planner} ${JSON.stringify(params)} on ${scenario}: every pick's cell, count and probability as the planner says`, () => {
    const { out, status } = records(scenario, planner, params, seed);
    assert.equal(status, 'solved');
    const model = new RunModel();
    const b = scenarios[scenario].bounds;
    const d = Float64Array.from(out);
    let picks = 0, trees = new Set();
    for (let o = 0; o < d.length; o += STRIDE) {
      model.apply(d, o);
      if (d[o] !== K.SELECT) continue;
      const t = d[o + 1];
      const counts = model.density.counts(t, b);
      assert.equal(model.density.grid, params.grid ?? 20);
      const key = d[o + 9] * model.density.grid + d[o + 10];
      assert.equal(counts.get(key), d[o + 6], `pick ${picks}: cell ${key} of tree ${t}`);
      assert.equal(counts.size, d[o + 8], `pick ${picks}: cells of tree ${t}`);
      let total = 0;
      for (const n of counts.values()) total += 1 / n;
      assert.ok(Math.abs((1 / d[o + 6]) / total - d[o + 7]) < 1e-12, `pick ${picks}: probability`);
      // the picked node's own point lies in the picked cell
      assert.equal(densityCell(d[o + 4], b[0], b[2], model.density.grid), d[o + 9]);
      assert.equal(densityCell(d[o + 5], b[1], b[3], model.density.grid), d[o + 10]);
      picks++;
      trees.add(t);
    }
    assert.ok(picks > 20, `${picks} picks checked`);
    assert.equal(trees.size, planner === 'bi-est' ? 2 : 1);
  });
}

test('density overlay: densityCell clamps to the grid and puts the far edge in the last cell', () => {
  assert.equal(densityCell(0, 0, 1, 20), 0);
  assert.equal(densityCell(1, 0, 1, 20), 19);
  assert.equal(densityCell(-5, 0, 1, 20), 0);
  assert.equal(densityCell(0.05, 0, 1, 20), 1);
  assert.equal(densityCell(0.5, 0, 0, 4), 3, 'a zero-width side: everything in one cell, clamped');
});

test('density overlay: a run without SELECT records keeps the mirror empty (RRT files nothing)', () => {
  const { out } = records('narrow', 'rrt-connect', {}, 1);
  const model = new RunModel();
  const d = Float64Array.from(out);
  for (let o = 0; o < d.length; o += STRIDE) model.apply(d, o);
  assert.equal(model.density.empty, true);
  assert.equal(model.density.trees.length, 0);
});

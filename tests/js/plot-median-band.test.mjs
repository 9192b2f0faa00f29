// RRT*'s cost against time over runs in Planner Arena's form (draw/plots.js medianBand): at each
// time the median of the runs' best costs and the quartiles, a run not solved yet counting as an
// infinite cost.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { medianBand } from '../../www/draw/plots.js';

test('medianBand: the median and quartiles of the runs\' step functions, unsolved runs as infinite, no median while most are unsolved', () => {
  const lines = [
    [[1, 10], [4, 6]],
    [[2, 8], [3, 5]],
    [[5, 9]],
    [[6, 7]],
  ];
  const m = medianBand(lines, [0, 1, 2, 3, 4, 5, 6]);
  // up to t = 4 at most two of the four runs are solved: the median (between the 2nd and 3rd
  // smallest costs) is infinite, and the time left out
  assert.deepEqual(m.map((r) => r[0]), [5, 6]);
  // t = 5: costs [5, 6, 9, ∞]: median 7.5, q1 5.75, q3 between 9 and ∞, held at 9
  assert.deepEqual(m[0], [5, 7.5, 5.75, 9]);
  // t = 6: costs [5, 6, 7, 9]: median 6.5, q1 5.75, q3 7.5
  assert.deepEqual(m[1], [6, 6.5, 5.75, 7.5]);
  // every run solved from the start: the band closes on one run's line
  assert.deepEqual(medianBand([[[0, 3], [2, 1]]], [0, 1, 2]), [[0, 3, 3, 3], [1, 3, 3, 3], [2, 1, 1, 1]]);
});

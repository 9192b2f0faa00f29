// The palette's colours stay distinguishable for the common colour-vision deficiencies: every pair
// that must be told apart on the canvas is simulated for protanopia, deuteranopia and tritanopia
// (Machado, Oliveira and Fernandes 2009, severity 1) and compared in CIELAB (ΔE*ab, CIE76).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { PALETTE } from '../../www/draw/palette.js';
import { SERIES } from '../../www/draw/plots.js';

const MACHADO = {
  normal: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  protanopia: [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216], [-0.003882, -0.048116, 1.051998]],
  deuteranopia: [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413], [-0.01182, 0.04294, 0.968881]],
  tritanopia: [[1.255528, -0.076749, -0.178779], [-0.078411, 0.930809, 0.147602], [0.004733, 0.691367, 0.3039]],
};

const toLinear = (c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
function rgb(hex) {
  const h = hex.replace('#', '');
  return [0, 2, 4].map((i) => toLinear(parseInt(h.slice(i, i + 2), 16) / 255));
}
function lab([r, g, b]) {
  const x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const f = (t) => (t > 216 / 24389 ? Math.cbrt(t) : (24389 / 27 * t + 16) / 116);
  return [116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))];
}
function seen(hex, m) {
  const c = rgb(hex);
  return m.map((row) => Math.min(1, Math.max(0, row[0] * c[0] + row[1] * c[1] + row[2] * c[2])));
}
const deltaE = (a, b) => Math.hypot(...lab(a).map((v, i) => v - lab(b)[i]));

// Pairs a student must tell apart, with why.
const PAIRS = [
  ['start', 'goal', 'start and goal'],
  ['tree0', 'tree1', "RRT-Connect's two trees"],
  ['tree0', 'smoothPath', 'the tree and the path'],
  ['obstacle', 'start', 'an obstacle and the start'],
  ['obstacle', 'goal', 'an obstacle and the goal'],
  ['obstacle', 'tree0', 'an obstacle and the tree'],
  ['obstacle', 'smoothPath', 'an obstacle and the path'],
  ['cellVisited', 'cellBlocked', 'visited and step-blocked cells'],
  ['cellMixed', 'cellFull', 'mixed and full cells'],
  ['cellVisited', 'cellMixed', 'visited and mixed cells'],
  ['cellOpen', 'cellVisited', 'open and closed cells (A*, Dijkstra)'],
  ['cellOpen', 'cellBlocked', 'open and step-blocked cells'],
  ['cellOpen', 'cellFree', 'open and free cells'],
  ['posed', 'posedCollides', 'an arm posed free and in collision'],
  ['posedCollides', 'obstacle', 'an arm in collision and an obstacle'],
  ['posedCollides', 'start', 'an arm in collision and the start'],
  ['posed', 'obstacle', 'an arm posed and an obstacle'],
];
const MIN_DELTA_E = 12;

test('pairs on the canvas stay apart under every colour-vision deficiency', () => {
  const report = [];
  for (const [name, m] of Object.entries(MACHADO)) {
    for (const [a, b, why] of PAIRS) {
      const ca = Array.isArray(PALETTE[a]) ? PALETTE[a][0] : PALETTE[a];
      const cb = Array.isArray(PALETTE[b]) ? PALETTE[b][0] : PALETTE[b];
      const d = deltaE(seen(ca, m), seen(cb, m));
      report.push(`${name.padEnd(12)} ${why.padEnd(34)} ΔE ${d.toFixed(1)}`);
      assert.ok(d >= MIN_DELTA_E, `${why} (${ca} vs ${cb}) under ${name}: ΔE ${d.toFixed(1)} < ${MIN_DELTA_E}`);
    }
  }
  console.log(report.join('\n'));
});

test('the plots\' first four series stay apart under every colour-vision deficiency', () => {
  for (const [name, m] of Object.entries(MACHADO)) {
    for (let i = 0; i < 4; i++) {
      for (let j = i + 1; j < 4; j++) {
        const d = deltaE(seen(SERIES[i], m), seen(SERIES[j], m));
        assert.ok(d >= MIN_DELTA_E, `series ${i} ${SERIES[i]} vs ${j} ${SERIES[j]} under ${name}: ΔE ${d.toFixed(1)}`);
      }
    }
  }
});

test('the simulation itself separates what it should and merges what it should', () => {
  // Red and green are far apart for normal vision and close under deuteranopia.
  assert.ok(deltaE(seen('#d62728', MACHADO.normal), seen('#2ca02c', MACHADO.normal)) > 60);
  assert.ok(deltaE(seen('#d62728', MACHADO.deuteranopia), seen('#2ca02c', MACHADO.deuteranopia)) < 25);
});

// What a frame reveals follows what drawing costs (www/run/limits.js nextRevealCap): the cap moves
// halfway to the records drawn in REVEAL_MS each frame, stays within MIN_REVEAL_PER_FRAME …
// REVEAL_PER_FRAME, and keeps its value when a frame drew too few records to measure.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MIN_REVEAL_PER_FRAME, REVEAL_MS, REVEAL_PER_FRAME, nextRevealCap } from '../../www/run/limits.js';

test('the cap converges to what the machine draws in REVEAL_MS, within its bounds', () => {
  const perRecord = 0.0005; // ms: 2 µs a record drawn
  let cap = REVEAL_PER_FRAME / 4;
  for (let i = 0; i < 30; i++) cap = nextRevealCap(cap, cap, cap * perRecord);
  assert.ok(Math.abs(cap - REVEAL_MS / perRecord) <= 1, `converges to ${REVEAL_MS / perRecord} (${cap})`);
  // a slow machine: never below the floor; a fast one: never above the ceiling
  assert.equal(nextRevealCap(MIN_REVEAL_PER_FRAME, 5000, 1000), MIN_REVEAL_PER_FRAME);
  assert.equal(nextRevealCap(REVEAL_PER_FRAME, 50000, 0.5), REVEAL_PER_FRAME);
  // too few records, or no time measured, say nothing
  assert.equal(nextRevealCap(12345, 999, 50), 12345);
  assert.equal(nextRevealCap(12345, 5000, 0), 12345);
  // a frame twice as slow as the budget halves the next frame's records, halfway
  assert.equal(nextRevealCap(20000, 20000, 2 * REVEAL_MS), 15000);
});

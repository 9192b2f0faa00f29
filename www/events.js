// Event records streamed by the worker: fixed-stride Float64Array records
// [kind, tree, id, parent, x, y, px, py, c0, c1, pc0, pc1] (see src/events.rs). A test checks these
// constants against the wasm module's event_kinds().
export const STRIDE = 12;
export const EventKind = Object.freeze({
  SAMPLE: 0,
  SAMPLE_REJECTED: 1,
  NODE_ADDED: 2,
  COLLISION: 3,
  TREES_CONNECTED: 4,
  SOLVED: 5,
  SAMPLE_TRY: 6, // id: 1 free, 0 occupied
  DOMAIN: 7, // id: node, px: radius (Infinity: none)
  EXHAUSTED: 8, // id: node
  REWIRE: 9, // id: node, parent: its new parent (x, y; px, py)
  COST: 10, // id: best node, parent: iteration, px: cost
  COVERAGE: 11, // id: best node, parent: iteration, px: fraction, py: points seen
  POINT_SEEN: 12, // id: inspection point
});

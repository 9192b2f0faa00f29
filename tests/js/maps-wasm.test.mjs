// Occupancy maps through the wasm build under Node (issue 17): `import_map` on the sample's PGM +
// YAML and on its PNG gives the scenario the native CLI gives (`planarium validate map.yaml`), and
// `map_image_name` and the errors are what the worker relies on.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';
import { initSync, import_map, map_image_name, limits } from '../../www/pkg/planarium.js';
import { MAX_FILE_BYTES } from '../../www/run/limits.js';
import { gridLattice } from '../../www/ui/cell-grid.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
initSync({ module: readFileSync(join(root, 'www/pkg/planarium_bg.wasm')) });
const data = (name) => readFileSync(join(root, 'tests', 'data', 'maps', name));

test('import_map gives the native CLI\'s scenario for the PGM + YAML and the PNG', () => {
  const yaml = data('sample.yaml').toString('utf8');
  const fromPgm = JSON.parse(import_map(data('sample.pgm'), 'sample.pgm', yaml, 'sample.yaml'));
  // the CLI built by `cargo test --release` (as the other tests that ask it; `cargo run` here rebuilt it, 80 s)
  const native = JSON.parse(execFileSync(join(root, 'target/release/planarium'), ['validate', join(root, 'tests/data/maps/sample.yaml')],
    { cwd: root, encoding: 'utf8', maxBuffer: 1 << 26 }));
  assert.deepEqual(fromPgm, native);
  const fromPng = JSON.parse(import_map(data('sample.png'), 'sample.png', yaml, 'sample.yaml'));
  assert.deepEqual(fromPng, native);
  assert.equal(map_image_name(yaml, 'sample.yaml'), 'sample.pgm');
  const plain = JSON.parse(import_map(data('sample.png'), 'sample.png'));
  assert.deepEqual(plain.bounds, [0, 0, 2, 1.5]);
});

test('errors are JSON with the line, column and key', () => {
  assert.throws(() => map_image_name('image: a.pgm\nresolution: 0.o5\n', 'm.yaml'), (e) => {
    const err = JSON.parse(e.message);
    assert.equal(err.path, 'resolution');
    assert.equal(err.line, 2);
    assert.equal(err.column, 13);
    assert.equal(err.text, 'line 2, column 13: m.yaml: resolution: "0.o5" is not a number');
    return true;
  });
  assert.throws(() => import_map(new Uint8Array([80, 53, 10, 52]), 't.pgm'), (e) => /t\.pgm: byte \d+: the file ends/.test(JSON.parse(e.message).text));
});

test('a bidirectional control in a YAML key or value is echoed as [U+202E], never raw', () => {
  for (const yaml of ['image: a.pgm\nres\u202eolution: 0.05\n', 'image: a.pgm\nresolution: 0.0\u202e5\n']) {
    assert.throws(() => map_image_name(yaml, 'm\u202e.yaml'), (e) => {
      const err = JSON.parse(e.message);
      assert.ok(err.text.includes('[U+202E]'), err.text);
      assert.ok(!/[\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]/.test(e.message), e.message);
      return true;
    });
  }
});

test("the Cells tool paints on a map's pixels: its lattice is the image's (origin, one pixel a cell), as grid search's", () => {
  const yaml = data('sample.yaml').toString('utf8');
  const sc = JSON.parse(import_map(data('sample.pgm'), 'sample.pgm', yaml, 'sample.yaml'));
  const lat = gridLattice(sc);
  assert.deepEqual([lat.ox, lat.oy, lat.side, lat.nx, lat.ny], [-1, -0.5, 0.1, 40, 30]);
  // every rectangle the importer made from occupied pixels lies on that lattice
  for (const o of sc.obstacles) {
    for (const [v, a] of [[o.rect[0], lat.ox], [o.rect[1], lat.oy], [o.rect[2], lat.ox], [o.rect[3], lat.oy]]) {
      const k = (v - a) / lat.side;
      assert.ok(Math.abs(k - Math.round(k)) < 1e-9, `rect ${o.rect} on the pixels`);
    }
  }
  // another cell size is grid search's plain lattice from the bounds' corner
  const coarse = gridLattice(sc, 0.25);
  assert.deepEqual([coarse.ox, coarse.oy, coarse.side], [sc.bounds[0], sc.bounds[1], 0.25]);
});

test("the page's file limit is the core's", () => {
  assert.equal(MAX_FILE_BYTES, JSON.parse(limits()).max_text_bytes);
});

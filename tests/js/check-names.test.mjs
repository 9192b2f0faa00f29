// scripts/check-names.mjs: what counts as comparing or listing a planner name or robot kind in the
// page, on snippets written as the page was before its capabilities came from the registry.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { findNames, registeredNames } from '../../scripts/check-names.mjs';

const NAMES = ['rrt', 'rrt-connect', 'prm', 'inspection', 'point', 'rigid', 'arm'];
const hows = (src) => findNames(src, NAMES).map(({ line, name, how }) => `${line} ${name} ${how}`);

test('comparisons, switch cases, sets, keys and indexes are found, with their lines', () => {
  const src = [
    "if (planner === 'rrt-star' || planner === 'rrt') x();",     // 1: rrt compared
    "const TWO = new Set(['rrt-connect', 'bi-est']);",          // 2: rrt-connect listed
    "switch (robot.kind) { case 'arm': break; }",                // 3: arm a switch case
    "const T = { 'rrt-connect': 1, prm: 2 };",                   // 4: rrt-connect a key (prm bare: not)
    "T['prm'] = 3;",                                             // 5: prm an index
    "if ('rigid' !== kind) y();",                                // 6: rigid compared
    "return ['rrt', 'prm'].includes(p);",                        // 7: rrt, prm listed
    'const k = robot?.kind === "point";',                        // 8: point compared (double quotes)
    'if (kind === `arm`) z();',                                  // 9: arm compared (template)
  ].join('\n');
  assert.deepEqual(hows(src), [
    '1 rrt compared', '2 rrt-connect listed', '3 arm a switch case', '4 rrt-connect an object key', '5 prm an index',
    '6 rigid compared', '7 rrt listed', '7 prm listed', '8 point compared', '9 arm compared',
  ]);
});

test('values, comments, strings inside others, regexes and task kinds are not', () => {
  const src = [
    "let setup = { planner: 'rrt-connect', params: {} };",       // a default value
    "// if (planner === 'rrt') — a comment",
    "/* case 'arm': */",
    "const s = 'the rrt planner'; const u = `${kind}-arm`;",
    "const re = /'rrt'/; const t = p.task === 'inspection';",    // a regex; the task vocabulary
    "if ((p.task || 'goal') === 'inspection') w();",
    "node('g', { id: 'inspection' }, svg);",                     // a value in an object
  ].join('\n');
  assert.deepEqual(hows(src), []);
});

test('the names come from the core (the wasm build)', async () => {
  const { planners, kinds } = await registeredNames();
  assert.ok(planners.includes('rrt') && planners.includes('visibility-graph') && planners.length >= 13);
  assert.deepEqual([...kinds].sort(), ['arm', 'asv', 'point', 'rigid', 'spatial-arm']);
});

// The registry walked from the page's side: every planner the core registers has its page pieces
// (pseudocode for its key, a legend whose colours are the palette's, a drawing for what it draws,
// the overlays it offers, every event kind it emits handled by a drawing or the explain panel) and
// every robot kind a drawing and a pose the editor knows. A planner added to the core without them
// fails here, by name; a broken copy of the registry shows the walk can fail.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT } from './core-runs.mjs';
import { planners, robot_kinds } from '../../www/pkg/planarium.js';
import { EventKind, STRIDE } from '../../www/run/events.js';
import { Explainer, pseudocode } from '../../www/run/explain.js';
import { PALETTE, STYLE } from '../../www/draw/palette.js';
import { OFFERED } from '../../www/draw/overlays.js';
import {
  learn, plannerCaps, robotCaps, DRAWINGS, ROBOT_DRAWINGS, LEGEND_SHAPES, treeLegend,
} from '../../www/draw/capabilities.js';

const registry = JSON.parse(planners());
const kinds = JSON.parse(robot_kinds());
learn({ planners: registry, robotKinds: kinds });

/** Event kinds read by a module of their own rather than the style table or the explain panel. */
const READ_BY = { CELL_SHAPE: 'www/draw/cell-mirror.js', SELECT: 'www/run/playback.js', COVERAGE: 'www/run/playback.js' };

/** Whether the explain panel says something on a record of kind `k` for `planner`. */
function explained(planner, k) {
  const e = new Explainer(planner, kinds[0].name);
  const r = new Float64Array(STRIDE);
  r[0] = k; r[2] = 3; r[3] = 1; r[4] = 0.5; r[5] = 0.5;
  const before = [e.line, e.caption];
  e.read(r);
  return e.line !== before[0] || e.caption !== before[1];
}

/** What planner `p` (a registry entry) lacks on the page. */
function lacks(p) {
  const c = p.caps;
  const out = [];
  if (!c) return ['capabilities'];
  const code = pseudocode(p.name);
  if (!code || !code.lines.length) out.push(`pseudocode for "${c.pseudocode}" (www/run/pseudocode.js)`);
  if (!(c.draws in DRAWINGS)) out.push(`a drawing for "${c.draws}" (capabilities.js DRAWINGS)`);
  if (!c.legend.length && !c.marks.length) out.push('a legend entry');
  for (const l of [...c.legend, ...c.marks]) {
    if (!(l.color in PALETTE)) out.push(`a palette colour "${l.color}" for "${l.label}"`);
    if (!LEGEND_SHAPES.includes(l.shape)) out.push(`a legend shape "${l.shape}"`);
  }
  for (const o of c.overlays) if (!Object.values(OFFERED).includes(o)) out.push(`an overlay "${o}" (overlays.js)`);
  for (const name of c.events) {
    const k = EventKind[name];
    if (k === undefined) { out.push(`event kind ${name} in events.js`); continue; }
    const read = READ_BY[name] && readFileSync(join(ROOT, READ_BY[name]), 'utf8').includes(`EventKind.${name}`);
    if (!(k in STYLE) && !read && !explained(p.name, k)) out.push(`a drawing or caption for its ${name} events`);
  }
  return out;
}

test('every registered planner has its page pieces', () => {
  assert.ok(registry.planners.length >= 13);
  for (const p of registry.planners) assert.deepEqual(lacks(p), [], p.name);
  // the legend the page shows is the registry's
  for (const p of registry.planners) {
    assert.deepEqual(treeLegend(p.name).map((l) => l.label), (p.caps.legend.length ? p.caps.legend : [{ label: 'tree from the start (tree 0)' }, { label: 'tree from the goal (tree 1)' }]).map((l) => l.label));
  }
});

test('a planner without its pieces is named', () => {
  const p = structuredClone(registry.planners[0]);
  p.name = 'new-planner';
  p.caps.pseudocode = 'tree-new-planner';
  p.caps.draws = 'ellipse';
  p.caps.legend = [{ label: 'informed set', color: 'noSuchColour', shape: 'line' }];
  p.caps.events = [...p.caps.events, 'NO_SUCH_EVENT'];
  learn({ planners: [p] });
  const missing = lacks(p);
  assert.equal(missing.length, 4, missing.join('; '));
  assert.match(missing.join('; '), /pseudocode for "tree-new-planner"/);
  assert.match(missing.join('; '), /a drawing for "ellipse"/);
  assert.match(missing.join('; '), /noSuchColour/);
  assert.match(missing.join('; '), /NO_SUCH_EVENT/);
});

test('every robot kind has a drawing and a pose the editor knows', () => {
  assert.deepEqual(kinds.map((k) => k.name).sort(), ['arm', 'asv', 'point', 'rigid', 'spatial-arm']);
  for (const k of kinds) {
    assert.ok(k.drawn in ROBOT_DRAWINGS, `${k.name}: a drawing for "${k.drawn}"`);
    assert.ok(['none', 'position', 'position-heading', 'joints'].includes(k.pose), `${k.name}: pose ${k.pose}`);
    assert.equal(robotCaps({ kind: k.name }).drawn, k.drawn);
  }
  // An unknown kind is drawn as a dot with nothing to drag; an unknown planner offers nothing.
  assert.equal(robotCaps({ kind: 'none-such' }).pose, 'none');
  assert.equal(plannerCaps('none-such').queries, false);
});

test('a parameter is shown where it acts by the registry\'s condition (applies), not by its name', async () => {
  const { applies } = await import('../../www/ui/panel.js');
  const rc = registry.planners.find((p) => p.params.some((s) => s.name === 'epsilon'));
  const own = (n) => rc.params.find((s) => s.name === n);
  const ladder = rc.groups.flatMap((g) => g.params).find((s) => s.name === 'ladder');
  const values = (v) => (name) => v[name] ?? [...rc.params, ...rc.groups.flatMap((g) => g.params)].find((s) => s.name === name)?.default;
  // RRT-Connect's last-free connect: epsilon acts only in it, range and ladder steps only outside it.
  assert.equal(applies(own('epsilon'), values({ connect: 'last-free' })), true);
  assert.equal(applies(own('epsilon'), values({ connect: 'range' })), false);
  assert.equal(applies(own('range'), values({ connect: 'last-free' })), false);
  assert.equal(applies(own('range'), values({})), true);
  assert.equal(applies(ladder, values({ connect: 'last-free' })), false);
  assert.equal(applies(ladder, values({ connect: 'range' })), true);
  // A planner without `connect` (RRT) shows its ladder; dynamic-domain adaptation needs a radius.
  const rrt = registry.planners.find((p) => p.name === 'rrt');
  const tree = rrt.groups.find((g) => g.params.some((s) => s.name === 'ladder')).params;
  assert.equal(tree.find((s) => s.name === 'ladder').applies, null);
  const adaptive = tree.find((s) => s.name === 'dd_adaptive');
  assert.equal(applies(adaptive, (n) => ({ dd_radius: 0 })[n]), false);
  assert.equal(applies(adaptive, (n) => ({ dd_radius: 0.2 })[n]), true);
  // The panel reads conditions, never parameter names.
  const panel = readFileSync(join(ROOT, 'www', 'ui', 'panel.js'), 'utf8');
  for (const name of ['connect', 'sampler', 'dd_radius', 'exhausted', 'epsilon', 'ladder']) assert.doesNotMatch(panel, new RegExp(`['"]${name}['"]`), name);
});

// The explain panel for a spatial arm (report 001's Puma 560, RRT-Connect in the course's
// last-free mode): stepped record by record under Node (the wasm build), with the core's state log
// matched to the records as the page does (run/arm-states.js). Each caption must give the joint
// angles of the state the core logged for that record (and that state must be the record's: its
// first two coordinates and, through the core's kinematics, its drawn point), the connect's query
// count, the node added as the last free configuration, a collision in the core's own words; and
// the panel must be on the last-free mode's own lines of the pseudocode.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { scenarios } from './core-runs.mjs';
import { EventKind as K, STRIDE } from '../../www/run/events.js';
import { Explainer, pseudocode, optionsOf, joints, num } from '../../www/run/explain.js';
import { StateMirror } from '../../www/run/arm-states.js';
import { learn } from '../../www/draw/capabilities.js';
import { planners, robot_kinds, Scene } from '../../www/pkg/planarium.js';

learn({ planners: JSON.parse(planners()), robotKinds: JSON.parse(robot_kinds()) });

const deg = (v) => `${Math.round((v * 180) / Math.PI) || 0}°`.replace('-', '−');

test('explain: the Puma in last-free mode is told in its joints from the core\'s states, on the last-free lines', () => {
  const sc = scenarios['puma-rbo-wall'];
  const params = { connect: 'last-free' };
  const options = optionsOf({ planner: 'rrt-connect', params });
  const code = pseudocode('rrt-connect', options);
  const text = new Map(code.lines.map((l) => [l.id, l.text]));
  assert.match(text.get('steer'), /δ/, 'the last-free connect steps by the resolution');
  assert.match(text.get('add'), /only the last free q/);
  assert.match(text.get('c-add'), /only the last free q/);
  assert.ok(!code.lines.some((l) => l.text.includes('STEER(')), 'no range-mode line');
  const range = pseudocode('rrt-connect', optionsOf({ planner: 'rrt-connect', params: {} }));
  assert.ok(range.lines.some((l) => l.text.includes('STEER(')) && !range.lines.some((l) => l.text.includes('last free')), 'range mode keeps its lines');

  const scene = new Scene(JSON.stringify(sc));
  const run = scene.run('rrt-connect', JSON.stringify(params), 3);
  run.log_states(true);
  const x = new Explainer('rrt-connect', sc.robot.kind, options);
  x.describe = { collision: (q) => scene.collision(Float64Array.from(q)) };
  const recs = [];
  const store = { record: (i) => recs[i] };
  const mirror = new StateMirror();
  const seen = { sample: 0, collision: 0, added: 0, steer: 0, connect: 0 };
  const ids = new Set(code.lines.map((l) => l.id));
  for (let batch = 0; batch < 200 && seen.collision < 40; batch++) {
    const status = run.step(2, 1e9);
    const data = run.drain_events();
    mirror.push(run.drain_states());
    const from = recs.length;
    for (let o = 0; o < data.length; o += STRIDE) recs.push(data.slice(o, o + STRIDE));
    mirror.assign(store, from, recs.length);
    for (let i = from; i < recs.length; i++) {
      const r = recs[i];
      const st = mirror.get(i);
      x.read(r, 0, st);
      const caption = x.caption;
      assert.ok(ids.has(x.line), `kind ${r[0]}: line "${x.line}" is a line of the last-free pseudocode`);
      if (r[0] === K.SAMPLE) {
        assert.ok(st, 'a sample has its states');
        assert.equal(st.q.length, 6);
        // the state is the record's: its first two joints, and the tool seen from above
        assert.deepEqual([st.q[0], st.q[1]], [r[8], r[9]]);
        const s = scene.skeleton(Float64Array.from(st.q));
        assert.ok(Math.abs(s[s.length - 3] - r[4]) < 1e-12 && Math.abs(s[s.length - 2] - r[5]) < 1e-12, 'its drawn point is its tool\'s');
        const want = `q = (${Array.from(st.q, deg).join(', ')})`;
        assert.equal(joints(st.q), want);
        assert.ok(caption.startsWith(`sample ${want}`), `"${caption}" gives the sample's joints ${want}`);
        assert.equal(x.line, 'sample');
        seen.sample++;
      }
      if (r[0] === K.NEAREST) {
        assert.ok(caption.includes(`nearest #${r[2]} at ${num(r[8])} rad`), caption);
        if (r[10] === 0) { assert.equal(x.line, 'c-nearest'); seen.connect++; } else assert.equal(x.line, 'nearest');
      }
      if (r[0] === K.STEER) {
        assert.ok(Number.isInteger(st.extra) && st.extra >= 1, `the connect's queries: ${st.extra}`);
        assert.ok(caption.includes(`${st.extra} configuration${st.extra === 1 ? '' : 's'} checked (${st.extra} quer`), caption);
        assert.ok(caption.includes(`the farthest ${joints(st.q)}`), caption);
        assert.ok(['steer', 'c-steer'].includes(x.line));
        seen.steer++;
      }
      if (r[0] === K.COLLISION) {
        const words = scene.collision(Float64Array.from(st.q));
        assert.match(words, /meets/, 'the core names what meets what');
        assert.ok(caption.includes(`${joints(st.q)} collides: ${words}`), `"${caption}" names "${words}"`);
        assert.ok(['check', 'c-check'].includes(x.line), x.line);
        assert.ok(x.actors.collisionQ && x.actors.stepQ, 'the collision\'s state for the 3-D view');
        seen.collision++;
      }
      if (r[0] === K.NODE_ADDED && r[3] >= 0) {
        assert.ok(caption.includes(`only the last free configuration ${joints(st.q)} becomes a node: #${r[2]} under #${r[3]}`), caption);
        assert.ok(['add', 'c-add'].includes(x.line));
        seen.added++;
      }
    }
    if (status !== 'running') break;
  }
  assert.equal(mirror.mismatches, 0, 'every entry matched its record\'s kind');
  console.log(`puma last-free, seed 3: ${JSON.stringify(seen)} over ${recs.length} records`);
  assert.ok(seen.sample > 20 && seen.collision >= 40 && seen.added > 10 && seen.steer > 40 && seen.connect > 10, JSON.stringify(seen));
  run.free();
  scene.free();
});

test('arm states: entries are matched to their records in order, kept bounded, and a kind that disagrees stops the matching', () => {
  const rec = (kind) => Float64Array.of(kind, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
  const recs = [rec(K.SAMPLE), rec(K.SAMPLE_TRY), rec(K.NEAREST), rec(K.SOLVED), rec(K.COLLISION)];
  const store = { record: (i) => recs[i] };
  const batch = (kinds) => Float64Array.from([2, ...kinds.flatMap((k, j) => [k, j, j, j + 0.5, -j, -j - 0.5])]);
  const m = new StateMirror(2);
  m.push(batch([K.SAMPLE, K.NEAREST, K.COLLISION]));
  m.assign(store, 0, 3);
  assert.deepEqual([...m.get(0).q], [0, 0.5]);
  assert.equal(m.get(1), undefined, 'a raw try has no entry');
  assert.deepEqual([...m.get(2).pq], [-1, -1.5]);
  m.assign(store, 3, 5);
  assert.equal(m.get(4).extra, 2);
  assert.equal(m.get(0), undefined, 'only the last 2 kept');
  assert.equal(m.mismatches, 0);
  const n = new StateMirror();
  n.push(batch([K.NEAREST, K.SAMPLE]));
  n.assign(store, 0, 5);
  assert.equal(n.mismatches, 1, 'a sample\'s record met a nearest entry');
  assert.equal(n.get(0), undefined);
  assert.equal(n.get(2), undefined, 'nothing matched after a disagreement');
});

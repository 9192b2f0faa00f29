// The pages' scenario source (www/run/scenario-source.js), without a browser: why a scenario was
// loaded, where it came from, what a link carries, and a link's state waiting for its scenario.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ScenarioSource } from '../../www/run/scenario-source.js';

const field = { name: 'Open field', start: [0.1, 0.1], goal: [0.9, 0.9] };
const edited = { ...field, start: [0.2, 0.1] };

test('a built-in as shipped is {id}; an edit is custom until it gives the built-in back exactly', () => {
  const s = new ScenarioSource({ matchBuiltins: true });
  assert.equal(s.settled, false, 'nothing asked for yet');
  assert.equal(s.linkSource(), null);
  s.sent('builtin', { id: 'open-field', course: 'Course A', defaults: true });
  assert.equal(s.settled, true);
  assert.deepEqual(s.source, { id: 'open-field' });
  assert.deepEqual(s.loaded(field), { restore: null, defaults: true });
  assert.equal(s.text, JSON.stringify(field));
  assert.deepEqual(s.linkSource(), { id: 'open-field' });
  // the defaults are applied once
  s.sent('reload');
  assert.deepEqual(s.loaded(field), { restore: null, defaults: false });
  assert.deepEqual(s.source, { id: 'open-field' }, 'a reload keeps the source');
  assert.equal(s.course, 'Course A', 'and the course');

  s.sent('edit');
  assert.equal(s.edit, true);
  s.loaded(edited);
  assert.deepEqual(s.source, { custom: true });
  assert.deepEqual(s.linkSource(), { text: JSON.stringify(edited) });
  assert.equal(s.course, 'Course A', 'an edit keeps the course');
  // "Restore start and goal": the same text as the built-in loaded → the built-in again
  s.sent('edit');
  s.loaded(field);
  assert.deepEqual(s.source, { id: 'open-field' });
  // without matchBuiltins (Compare, the benchmark) a custom scenario stays custom
  const c = new ScenarioSource();
  c.sent('builtin', { id: 'open-field' });
  c.loaded(field);
  c.sent('file', { file: 'open-field.json' });
  c.loaded(field);
  assert.deepEqual(c.source, { custom: true });
  c.clear();
  assert.equal(c.text, null);
  assert.equal(c.linkSource(), null);
});

test('a file or a link\'s scenario is custom; the file\'s name is kept while it loads', () => {
  const s = new ScenarioSource();
  s.sent('file', { file: 'maze.json', course: 'Opened file', defaults: true });
  assert.deepEqual(s.source, { custom: true });
  assert.equal(s.file, 'maze.json');
  assert.deepEqual(s.loaded(edited), { restore: null, defaults: true });
  assert.equal(s.file, null);
  s.sent('link', { course: 'Shared link' });
  s.loaded(edited, 'text as normalised');
  assert.equal(s.text, 'text as normalised');
  assert.deepEqual(s.linkSource(), { text: 'text as normalised' });
  const g = s.generation;
  s.sent('reload');
  assert.equal(s.generation, g + 1, 'every load is a new generation');
});

test('a refused scenario: not an edit leaves nothing shown, the last valid text stays for a reload', () => {
  const s = new ScenarioSource();
  s.sent('builtin', { id: 'open-field' });
  s.loaded(field);
  s.sent('edit');
  assert.equal(s.refused(), null);
  assert.deepEqual(s.scenario, field, 'an edit keeps the scene');
  s.sent('file', { file: 'bad.json' });
  s.refused();
  assert.equal(s.scenario, null);
  assert.equal(s.file, null);
  assert.equal(s.text, JSON.stringify(field));
});

test('a link: not settled while it is read or waits for its scenario; its state is handed back once', () => {
  const s = new ScenarioSource();
  s.sent('builtin', { id: 'open-field' });
  s.loaded(field);
  assert.equal(s.settled, true);
  s.read();
  assert.equal(s.settled, false, 'being read');
  const state = { scenario: { text: '{}' }, planner: 'rrt' };
  s.restore(state, ['seed=x: not a number']);
  assert.equal(s.settled, false, 'waiting for its scenario');
  s.sent('link', { course: 'Shared link', defaults: true });
  // the link's scenario is refused: its state stays, the page shows a built-in instead
  assert.equal(s.refused(), state);
  s.notes.push('The link\'s scenario is not valid.');
  s.sent('builtin', { id: 'open-field' });
  assert.equal(s.settled, false);
  const got = s.loaded(field);
  assert.equal(got.restore, state);
  assert.equal(got.defaults, false, 'as the load asked');
  assert.deepEqual(s.takeNotes(), ['seed=x: not a number', 'The link\'s scenario is not valid.']);
  assert.deepEqual(s.takeNotes(), []);
  assert.equal(s.settled, true);
  assert.equal(s.loaded(field).restore, null, 'handed back once');
});

test('forget: "Open the default scenario instead" drops a link being restored', () => {
  const s = new ScenarioSource();
  s.read();
  s.restore({ scenario: null }, ['a problem']);
  s.forget();
  assert.equal(s.pending, null);
  assert.deepEqual(s.notes, []);
  s.sent('builtin', { id: 'open-field', defaults: true });
  assert.equal(s.settled, true);
  assert.deepEqual(s.loaded(field), { restore: null, defaults: true });
  // a link whose load asks for the scenario's defaults too (Compare): both are handed back
  s.restore({ share: {} });
  s.sent('link', { defaults: true });
  assert.deepEqual(s.loaded(field), { restore: { share: {} }, defaults: true });
});

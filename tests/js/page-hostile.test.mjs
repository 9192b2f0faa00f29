// Hostile inputs in the playground end with a clear message, never with a silent substitution or a
// message that reads backwards: a map_server YAML whose image was not chosen (or several images, or
// several scenarios) is refused by name instead of opening another file; a seed above 2^53 − 1,
// typed, linked or in a scenario's planner block, is refused naming the field and the largest
// seed, and the seed that runs is the one shown; bidirectional controls (U+202E) in a scenario's
// key, name or notes, a map YAML's key or a file's name are shown written out ([U+202E]).
import { test, beforeEach } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pageFixture, ROOT as root } from './browser.mjs';

const fx = await pageFixture();
let page;
beforeEach(() => { page = fx.page; });

const data = (name) => readFileSync(join(root, 'tests', 'data', 'maps', name));
const RLO = '\u202e';
const SMALL = { format: 'planarium-scenario/1', name: 'Small', bounds: [0, 0, 1, 1], obstacles: [{ rect: [0.4, 0.4, 0.6, 0.6] }],
  robot: { kind: 'point' }, start: [0.1, 0.1], goal: [0.9, 0.9] };
const openJson = (name, sc) => page.setInputFiles('#file', { name, mimeType: 'application/json', buffer: Buffer.from(typeof sc === 'string' ? sc : JSON.stringify(sc)) });
const errorText = async () => (await page.isVisible('#error') ? page.textContent('#error-text') : '');

test('Open file: a YAML whose image was not chosen, several images, or several scenarios are refused by name; nothing else opens', async () => {
  const before = await page.evaluate(() => window.planarium.scenario());
  // sample.yaml names sample.pgm; only sample.png is chosen with it
  await page.setInputFiles('#file', [
    { name: 'sample.yaml', mimeType: 'application/x-yaml', buffer: data('sample.yaml') },
    { name: 'sample.png', mimeType: 'image/png', buffer: data('sample.png') },
  ]);
  await page.waitForSelector('#error', { state: 'visible' });
  assert.equal(await errorText(), 'sample.yaml names its image "sample.pgm", which is not among the files chosen ("sample.png"): choose sample.yaml and sample.pgm together.');
  await page.waitForTimeout(300);
  assert.deepEqual(await page.evaluate(() => window.planarium.scenario()), before, 'the map shown stays');
  // two images without a YAML
  await page.setInputFiles('#file', [
    { name: 'sample.pgm', mimeType: 'image/x-portable-graymap', buffer: data('sample.pgm') },
    { name: 'sample.png', mimeType: 'image/png', buffer: data('sample.png') },
  ]);
  await page.waitForFunction(() => /were chosen together: open one image at a time/.test(document.getElementById('error-text').textContent));
  // two scenarios
  await page.setInputFiles('#file', [
    { name: 'a.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(SMALL)) },
    { name: 'b.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify({ ...SMALL, name: 'B' })) },
  ]);
  await page.waitForFunction(() => /reads one scenario at a time; "a\.json", "b\.json" were chosen/.test(document.getElementById('error-text').textContent));
  assert.deepEqual(await page.evaluate(() => window.planarium.scenario()), before);
  // the YAML with the image it names still opens
  await page.setInputFiles('#file', [
    { name: 'sample.yaml', mimeType: 'application/x-yaml', buffer: data('sample.yaml') },
    { name: 'sample.pgm', mimeType: 'image/x-portable-graymap', buffer: data('sample.pgm') },
    { name: 'sample.png', mimeType: 'image/png', buffer: data('sample.png') },
  ]);
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Occupancy map (sample.yaml)');
});

test('seeds above 2^53 − 1 typed, linked or in a scenario are refused naming the field and the limit; the seed shown is the seed that runs', async () => {
  await fx.pickScenario('narrow', 'Narrow passage');
  await fx.setField('seed', 7);
  // typed: refused, the field back to 7, the hint names the field and the largest seed
  await page.fill('#seed', '9007199254740993');
  await page.$eval('#seed', (el) => el.dispatchEvent(new Event('change', { bubbles: true })));
  assert.equal(await page.inputValue('#seed'), '7');
  assert.equal(await page.textContent('#seed + .hint, #seed ~ .hint'),
    'Seed: 9007199254740993 is larger than 9007199254740991 (2^53 − 1), the largest seed the page carries exactly; the seed stays 7.');
  await fx.fastPlayback();
  await page.click('#run');
  await fx.waitState('finished', 60000);
  assert.equal((await page.evaluate(() => window.planarium.result())).seed, 7);
  // the largest seed is carried exactly, to the worker and back
  await fx.setField('seed', '9007199254740991');
  await page.click('#run');
  await fx.waitState('finished', 60000);
  assert.equal((await page.evaluate(() => window.planarium.result())).seed, 9007199254740991);
  // a scenario whose planner block has such a seed: said, and seed 1 shown and used
  await openJson('big-seed.json', JSON.stringify({ ...SMALL, name: 'Big seed', planner: { name: 'rrt-connect', seed: 1 } }).replace('"seed":1', '"seed":9007199254740993'));
  await page.waitForFunction(() => document.getElementById('scenario-name').textContent === 'Big seed');
  await fx.waitState('idle');
  assert.match(await page.textContent('#seed ~ .hint'), /^The scenario's seed \(planner\.seed\) is larger than 9007199254740991 \(2\^53 − 1\).*so it is not used; the seed stays \d+\.$/);
  const shown = Number(await page.inputValue('#seed'));
  await page.click('#run');
  await fx.waitState('finished', 60000);
  assert.equal((await page.evaluate(() => window.planarium.result())).seed, shown);
  // a link's seed
  await page.goto(`${fx.env.base}#scenario=narrow&planner=rrt-connect&seed=18446744073709551615`);
  await fx.waitState('idle', 30000);
  await page.waitForFunction(() => /seed=18446744073709551615: the seed is larger than 9007199254740991 \(2\^53 − 1\)/.test(document.body.textContent));
});

test('bidirectional controls in a scenario key, name and notes, a map YAML key and a file name are shown written out', async () => {
  const noRaw = (text, what) => assert.ok(!text.includes(RLO), `${what} holds no raw U+202E: ${JSON.stringify(text)}`);
  // a scenario key: the error box echoes it
  await openJson('key.json', { ...SMALL, [`evil${RLO}key`]: 1 });
  await page.waitForSelector('#error', { state: 'visible' });
  const keyError = await errorText();
  assert.match(keyError, /evil\[U\+202E\]key/);
  noRaw(keyError, 'the error box');
  // a name, notes and the file's name (the picker's entry)
  await openJson(`ev${RLO}nosj.json`, { ...SMALL, name: `Name ${RLO}desrever`, notes: `Notes ${RLO}desrever` });
  await page.waitForFunction(() => /^Name /.test(document.getElementById('scenario-name').textContent));
  const name = await page.textContent('#scenario-name');
  assert.equal(name, 'Name [U+202E]desrever');
  assert.match(await page.textContent('#scenario-notes'), /^Notes \[U\+202E\]desrever$/);
  const option = await page.$eval('#scenario', (s) => s.options[s.selectedIndex].textContent);
  assert.equal(option, 'File: ev[U+202E]nosj.json');
  // a map_server YAML's key
  await page.setInputFiles('#file', [
    { name: 'bidi.yaml', mimeType: 'application/x-yaml', buffer: Buffer.from(`image: sample.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n${RLO}evil: 1\n`) },
    { name: 'sample.pgm', mimeType: 'image/x-portable-graymap', buffer: data('sample.pgm') },
  ]);
  await page.waitForFunction(() => /evil/.test(document.getElementById('error-text').textContent));
  const yamlError = await errorText();
  assert.match(yamlError, /\[U\+202E\]evil/);
  noRaw(yamlError, 'the error box');
});

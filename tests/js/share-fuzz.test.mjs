// A fuzz of the share-link reader (ui/links.js) in Node: valid links written by the page's own writer,
// then mutated (cut short, base64 characters flipped, bad %-escapes, unicode, RTL overrides, lone
// surrogates, huge repeats of pairs, long keys and values, deflate bombs), thrown at readShare,
// decodeScenario and parsePairs. For every input: no throw (decodeScenario: only an Error in words),
// bounded work (at most MAX_PAIRS pairs decoded; the time is printed), problems bounded in count
// and length; and every link left as written reads back exactly. Seeded (mulberry32): the same
// inputs on every run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readShare, writeShare, parsePairs, boundedProblems, MAX_PAIRS, MAX_PROBLEMS, VIEW_DEFAULTS } from '../../www/ui/links.js';
import { decodeScenario, encodeScenario, toBase64url, MAX_HASH_CHARS, MAX_SCENARIO_BYTES } from '../../www/ui/scenario-codec.js';
import { CAMERA, readCamera, writeCamera, roundCamera } from '../../www/ui/camera-link.js';
import { readZoom, writeZoom } from '../../www/ui/plane-zoom.js';
import { mulberry32 } from './seeded.mjs';

const SEED = 0x5eed13;
const INPUTS = 10000;
const MAX_DECODES = 2 * MAX_PAIRS + 2; // a key and a value per pair read, and a scenario's value
const MAX_PROBLEM_CHARS = 400;

const rand = mulberry32(SEED);
const int = (n) => Math.floor(rand() * n);
const pick = (xs) => xs[int(xs.length)];

const B64 = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_';
const ODD = ['\u202e', '\u202d', '\u200f', '\ud800', '\udfff', '\u0000', '<img src=x onerror=alert(1)>', '</script>',
  '%', '%E0%A4%A', '%zz', '%C0%80', '%ED%A0%80', '=', '&&', '#', '+', ' ', '\n', 'é', '😀', '\ufeff', ':'];
const KEYS = ['scenario', 'planner', 'seed', 'overlays', 'speed', 'anim', 'raw-path', 'step-size', 'camera', 'autoplay', 'click',
  'controls', 'range', 'goal_bias', 'max_iterations', 'sampler'];

/** A small scenario-like JSON text (the reader does not validate it: any text must come back). */
function scenarioText() {
  const obstacles = Array.from({ length: int(12) }, () => ({ rect: [rand(), rand(), rand() + 1, rand() + 1].map((v) => +v.toFixed(3)) }));
  const name = Array.from({ length: int(20) }, () => (rand() < 0.2 ? pick(ODD) : pick(B64))).join('');
  return JSON.stringify({ format: 'planarium-scenario/1', name, bounds: [0, 0, 2, 2], obstacles, start: [0.1, 0.1], goal: [1.9, 1.9] });
}

const registry = { planners: [{ name: 'rrt', params: [{ name: 'range', default: 0.2 }, { name: 'goal_bias', default: 0.05 }] }], run_params: [] };

/** A valid link's hash and what it must read back as. */
async function validLink() {
  const text = scenarioText();
  const seed = int(1e6);
  const speed = int(101);
  const builtin = rand() < 0.3;
  // a 3-D view's camera in a third of them: anywhere within its bounds, the yaw any number of turns
  const camera = rand() < 0.33 ? {
    target: [0, 1, 2].map(() => (rand() - 0.5) * 10 ** int(7)), yaw: (rand() - 0.5) * 40,
    pitch: CAMERA.minPitch + rand() * (CAMERA.maxPitch - CAMERA.minPitch), distance: CAMERA.minDistance + rand() * 50,
  } : null;
  const hash = await writeShare({
    scenario: builtin ? { id: 'narrow' } : { text },
    config: { planner: 'rrt', params: { range: +(rand() + 0.01).toFixed(3) }, seed },
    view: { speed, stepSize: 1 + int(50), camera },
  }, registry);
  return { hash: `#${hash}`, text: builtin ? null : text, seed, speed, camera: camera && roundCamera(camera) };
}

/** One mutation of `hash`, by kind. */
function mutate(hash, kind) {
  const at = int(hash.length + 1);
  switch (kind) {
    case 'cut': return hash.slice(0, at);
    case 'flip': {
      const chars = [...hash];
      for (let k = 1 + int(4); k > 0; k--) chars[int(chars.length)] = rand() < 0.7 ? pick(B64) : pick(ODD);
      return chars.join('');
    }
    case 'insert': return hash.slice(0, at) + pick(ODD).repeat(1 + int(5)) + hash.slice(at);
    case 'percent': return hash.slice(0, at) + pick(['%', '%E0%A4%A', '%zz', '%ED%A0%80', '%FF', '%25']) + hash.slice(at);
    case 'pairs': return `${hash}&${Array.from({ length: 1 + int(40) }, () => `${pick(KEYS)}=${pick(ODD)}${int(1000)}`).join('&')}`;
    case 'long-key': return `${hash}&${'k'.repeat(100 + int(10000))}=${'v'.repeat(int(5000))}`;
    case 'long-value': return `${hash}&${pick(KEYS)}=${pick(ODD).repeat(100 + int(5000))}`;
    case 'unicode': return hash.slice(0, at) + String.fromCodePoint(...Array.from({ length: 1 + int(30) }, () => int(0x110000))) + hash.slice(at);
    case 'scenario-twice': return `${hash}&scenario=${pick(['deflate:', 'base64:', 'zip:', ''])}${Array.from({ length: int(200) }, () => pick(B64)).join('')}`;
    case 'encoding': return hash.replace(/scenario=(deflate|base64):/, `scenario=${pick(['base64', 'deflate', 'gzip', 'DEFLATE', ''])}:`);
    default: throw new Error(kind);
  }
}
const KINDS = ['cut', 'cut', 'flip', 'flip', 'insert', 'percent', 'pairs', 'long-key', 'long-value', 'unicode', 'scenario-twice', 'encoding'];

/** The huge ones, a few times each (a second or less apiece). */
async function hugeInputs() {
  const bomb = await encodeScenario(' '.repeat(MAX_SCENARIO_BYTES + 1)); // compresses to a few kB
  const bigB64 = `base64:${toBase64url(new Uint8Array(MAX_SCENARIO_BYTES + 3))}`;
  return [
    `#${'a&'.repeat(524288)}`,
    `#${Array.from({ length: 200000 }, (_, i) => `k${i}=${i}`).join('&')}`,
    `#${'&'.repeat(MAX_HASH_CHARS + 10)}`,
    `#scenario=${bomb}`,
    `#scenario=${bigB64.slice(0, MAX_HASH_CHARS - 20)}`,
    `#overlays=${'+bogus,'.repeat(100000)}`,
    `#controls=${'fly,'.repeat(100000)}`,
    `#${'scenario=deflate:AAAA&'.repeat(50000)}`,
    `#${'%'.repeat(300000)}`,
    `#${'\u202e'.repeat(500000)}=1`,
    `#seed=${'9'.repeat(1000000)}&${'k'.repeat(500000)}=${'<img src=x onerror=alert(1)>'.repeat(20000)}`,
  ];
}

function checkProblems(problems, input) {
  assert.ok(Array.isArray(problems), 'problems is a list');
  assert.ok(problems.length <= MAX_PROBLEMS + 1, `${problems.length} problems for ${input.slice(0, 80)}`);
  for (const p of problems) {
    assert.equal(typeof p, 'string');
    assert.ok(p.length <= MAX_PROBLEM_CHARS, `a problem of ${p.length} characters: ${p.slice(0, 120)}`);
    assert.doesNotMatch(p, /[\u202a-\u202e\u2066-\u2069]/, `a bidirectional control echoed: ${p.slice(0, 120)}`);
  }
}

test(`share-link reader: ${INPUTS} seeded inputs, no throw, bounded work and problems, valid links read back`, async () => {
  const t0 = performance.now();
  let slowest = { ms: 0, input: '' };
  let count = 0;
  let readBack = 0;
  // The time each input takes is printed (the slowest); what is asserted is the reader's work:
  // at most MAX_PAIRS pairs are decoded, whatever the input's length.
  const decode = globalThis.decodeURIComponent;
  let decodes = 0;
  globalThis.decodeURIComponent = (t) => { decodes++; return decode(t); };
  const timed = async (input, fn) => {
    const t = performance.now();
    decodes = 0;
    const out = await fn();
    const ms = performance.now() - t;
    if (ms > slowest.ms) slowest = { ms, input };
    assert.ok(decodes <= MAX_DECODES, `${decodes} parts decoded for ${input.slice(0, 80)}… (${input.length} chars)`);
    count++;
    return out;
  };
  const inputs = [];
  for (const h of await hugeInputs()) inputs.push({ hash: h });
  const pool = [];
  for (let i = 0; i < 400; i++) pool.push(await validLink());
  while (inputs.length < INPUTS) {
    const v = pool[int(pool.length)];
    if (rand() < 0.12) inputs.push({ hash: v.hash, valid: v });
    else {
      let h = v.hash;
      for (let k = 1 + int(3); k > 0; k--) h = mutate(h, pick(KINDS));
      inputs.push({ hash: h });
    }
  }
  for (const { hash, valid } of inputs) {
    let share;
    try {
      share = await timed(hash, () => readShare(hash, { builtins: [{ id: 'narrow' }] }));
    } catch (e) {
      assert.fail(`readShare threw ${e} on ${hash.slice(0, 120)}`);
    }
    checkProblems(share.problems, hash);
    assert.ok(share.params.length <= MAX_PAIRS);
    if (valid) {
      assert.deepEqual(share.problems, [], `a valid link reads without problems: ${hash.slice(0, 120)}`);
      assert.deepEqual(share.scenario, valid.text === null ? { id: 'narrow' } : { text: valid.text });
      assert.equal(share.seed, valid.seed);
      assert.equal(share.view.speed ?? VIEW_DEFAULTS.speed, valid.speed);
      assert.deepEqual(share.view.camera ?? null, valid.camera, 'the camera reads back as written');
      readBack++;
    }
    // the pieces alone
    const pairs = parsePairs(hash, { push() {} });
    assert.ok(pairs.length <= MAX_PAIRS);
    const value = pairs.findLast?.(([k]) => k === 'scenario')?.[1];
    if (value && value.length < 300000) {
      try {
        const text = await timed(value, () => decodeScenario(value));
        assert.equal(typeof text, 'string');
      } catch (e) {
        assert.equal(e?.constructor, Error, `decodeScenario throws only Error in words, not ${e?.name}: ${e}`);
        assert.ok(e.message.length < 200 && !/atob|DOMException|InvalidCharacter|Failed to execute/.test(e.message), e.message);
      }
    }
  }
  globalThis.decodeURIComponent = decode;
  const total = performance.now() - t0;
  console.log(`share-link fuzz: ${count} calls on ${inputs.length} inputs (${readBack} valid links read back exactly) in ${(total / 1000).toFixed(1)} s; `
    + `slowest ${slowest.ms.toFixed(1)} ms on a ${slowest.input.length.toLocaleString('en')}-character input "${slowest.input.slice(0, 40)}…"`);
  assert.ok(inputs.length >= 10000);
  assert.ok(readBack >= 1000, `${readBack} valid links`);
});

test('reproductions: 524,288 empty pairs, a link cut mid-base64, long keys are echoed cut', async () => {
  const flood = await readShare(`#${'a&'.repeat(524288)}`);
  console.log(flood.problems.join('\n'));
  assert.equal(flood.problems.length, 2);
  assert.match(flood.problems.join('\n'), /523,288 more parts after the first 1,000/);
  assert.match(flood.problems.join('\n'), /"a" needs a value .*\(…and 999 more like it\)/);
  const link = (await validLink());
  let v = link.hash;
  while (!/scenario=deflate/.test(v)) v = (await validLink()).hash;
  const b64 = v.indexOf('deflate:') + 8;
  for (let cutAt = b64 + 1; cutAt < b64 + 40; cutAt++) {
    const share = await readShare(v.slice(0, cutAt));
    assert.equal(share.scenario, null);
    assert.equal(share.problems.length, 1, share.problems.join('\n'));
    assert.match(share.problems[0], /^The link's scenario is cut short or damaged \(.+\): copy the whole link again/);
    assert.doesNotMatch(share.problems[0], /atob|DOMException|Failed to execute/);
  }
  const long = await readShare(`#scenario=${'n'.repeat(100000)}&seed=${'9'.repeat(100000)}&${encodeURIComponent('<img src=x onerror=alert(1)>').repeat(1000)}`, { builtins: [{ id: 'narrow' }] });
  assert.equal(long.problems.length, 3);
  for (const p of long.problems) assert.ok(p.length < 200, p);
  assert.match(long.problems.join('\n'), /no built-in scenario "n{59}…"/);
  // 200 distinct unknown overlays and 100 controls: 30 lines from the reader, 12 on the page, every one counted
  const many = await readShare(`#${Array.from({ length: 200 }, (_, i) => `k${i}`).join('&')}&seed=x`);
  assert.equal(many.problems.length, MAX_PROBLEMS + 1);
  assert.equal(many.problems.at(-1), '…and 171 more problems.');
  const page = boundedProblems([...many.problems, 'one more'], 12);
  assert.equal(page.length, 13);
  assert.equal(page.at(-1), `…and ${201 + 1 - 12} more problems.`);
  // the writer: a lone surrogate in a value (encodeURIComponent throws on it) is written as U+FFFD
  const odd = await writeShare({ scenario: { id: 'narrow' }, extra: [['note', 'a\ud800b']] }, registry);
  assert.equal(odd, 'scenario=narrow&note=a%EF%BF%BDb');
});

test('the camera in a link: six numbers within the orbit camera\'s bounds, else a problem naming the number and the view framed', async () => {
  const ok = await readShare('#scenario=puma-boxes&camera=0.1,-0.2,0.5,7,0.3,2.5');
  assert.deepEqual(ok.problems, []);
  assert.equal(ok.view.camera.yaw, 7 - 2 * Math.PI, 'the yaw is wrapped into (-π, π]');
  assert.deepEqual(ok.view.camera.target, [0.1, -0.2, 0.5]);
  const cases = [
    ['1,2,3', /six numbers .*found 3/],
    ['0,0,0,0,0,0,0', /found 7/],
    ['0,0,0,0,1.56,1', /pitch must be from -1.45 to 1.55/],
    ['0,0,0,0,-1.46,1', /pitch must be from -1.45 to 1.55/],
    ['0,0,0,0,0,0', /distance must be from 0.001 to 10000/],
    ['0,0,0,0,0,10001', /distance must be from 0.001 to 10000/],
    ['2e6,0,0,0,0,1', /tx must be within/],
    ['0,0,-1e7,0,0,1', /tz must be within/],
    ['0,0,0,1001,0,1', /yaw must be within/],
    ['0,0,0,NaN,0,1', /yaw is not a number/],
    ['0,Infinity,0,0,0,1', /ty is not a number/],
    ['0,1e999,0,0,0,1', /ty is not a number/],
    ['0,0x10,0,0,0,1', /ty is not a number/],
    [' ,0,0,0,0,1', /tx is not a number/],
    [`${'1'.repeat(200)},0,0,0,0,1`, /characters long/],
  ];
  for (const [value, why] of cases) {
    const r = await readShare(`#camera=${encodeURIComponent(value)}`);
    assert.equal(r.view.camera, undefined, value);
    assert.equal(r.problems.length, 1, value);
    assert.match(r.problems[0], why, value);
    assert.match(r.problems[0], /the view is framed on the problem\.$/);
    assert.ok(r.problems[0].length < 200);
  }
  assert.match((await readShare('#camera')).problems[0], /"camera" needs a value/);
  // the writer keeps what it writes within the bounds, so the page's link always reads back
  const wild = { target: [5e6, -5e6, 0], yaw: 1e9, pitch: 3, distance: 1e7 };
  const back = readCamera(writeCamera(wild));
  assert.ok(back.camera, 'a camera beyond the bounds is written within them');
  assert.deepEqual(back.camera.target, [CAMERA.maxTarget, -CAMERA.maxTarget, 0]);
  assert.equal(back.camera.pitch, CAMERA.maxPitch);
  assert.equal(back.camera.distance, CAMERA.maxDistance);
  assert.ok(Math.abs(back.camera.yaw) <= Math.PI);
});

test('the plane\'s zoom in a link: three numbers, the zoom 1 … 256, else a problem naming the number and the whole workspace', async () => {
  const ok = await readShare('#scenario=narrow&zoom=3.5,0.25,-1e2');
  assert.deepEqual(ok.problems, []);
  assert.deepEqual(ok.view.zoom, { zoom: 3.5, cx: 0.25, cy: -100 });
  const cases = [
    ['2,0.5', /three numbers zoom,cx,cy, found 2/],
    ['0.5,0,0', /zoom must be from 1 to 256/],
    ['257,0,0', /zoom must be from 1 to 256/],
    ['2,2e6,0', /cx and cy must be within/],
    ['2,0,NaN', /cy is not a number/],
    ['Infinity,0,0', /zoom is not a number/],
    [`${'1'.repeat(90)},0,0`, /characters long \(three numbers need at most 80\)/],
  ];
  for (const [value, why] of cases) {
    const r = await readShare(`#zoom=${encodeURIComponent(value)}`);
    assert.equal(r.view.zoom, undefined, value);
    assert.equal(r.problems.length, 1, value);
    assert.match(r.problems[0], why, value);
    assert.match(r.problems[0], /the view from above shows the whole workspace\.$/);
  }
  // what the page writes reads back
  const vp = { zoom: 2.117000017, cx: 0.5488549488, cy: 0.5325699659 };
  assert.deepEqual(readZoom(writeZoom(vp)).viewport, vp);
});

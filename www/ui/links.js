// Share links: the playground's whole state in the URL hash, and back. The same grammar drives
// embed.html and <planarium-playground> (which add `autoplay`, `click` and `controls`).
//
//   #scenario=narrow&planner=rrt-connect&seed=7&range=0.1&overlays=-show-domains,+show-heat&speed=80
//
// pairs `key` or `key=value`, joined by `&`, percent-encoded (a `+` is a plus, not a space):
//   scenario   a built-in's id; or an edited / opened scenario's full JSON: `deflate:` + base64url of
//              its deflate-raw bytes (CompressionStream), or `base64:` + base64url of the JSON text
//              (written where CompressionStream is missing)
//   planner    a planner's name; with it, the parameters are exactly those listed (others at their
//              defaults); without it, the scenario's own `planner` block, with the listed ones on top
//   seed       a whole number ≥ 0 (default: the scenario's, else 1)
//   <param>    any parameter of the planner (its own, its groups', the run's), by the registry's
//              name, e.g. range, goal_bias, sampler, max_iterations; written only when it differs
//              from the registry's default
//   overlays   comma-separated `+id` / `-id` of the overlay box (show-accepted, show-domains, …),
//              written only where they differ from the defaults
//   speed      playback speed slider, 0…100 (100: every event at once; default 60)
//   anim       robot animation slider, 0…100 (default 50)
//   raw-path   the robot follows the raw path (flag)
//   step-size  iterations per step / step back (default 1)
//   camera     the 3-D view's camera (a spatial arm's scene): tx,ty,tz,yaw,pitch,distance, its orbit
//              target in metres, yaw and pitch in radians (pitch -1.45 … 1.55), distance 0.001 … 10000
//              metres (ui/camera-link.js); written only once the camera was turned or zoomed
//   zoom       the view from above zoomed in: zoom,cx,cy, the zoom 1 … 256 times the fitted scale
//              and the world point at the view's centre (ui/plane-zoom.js); written only when zoomed
//   ghosts     the 3-D path's ghost spacing in rad: 0 (none) or 0.05 … 10 (default 2; ui/ghost-spacing.js)
// embed.html and <planarium-playground> only:
//   autoplay   run as soon as the scenario is loaded
//   click      run on the first click on the canvas
//   controls   comma-separated, from run, pause, step, back, reset, speed, seed (default: run,
//              pause, step, back, reset; empty: none)
// Unknown keys and bad values are reported as problems (text for the page to show) and left out;
// nothing here throws on what a link says.
//
// Limits (docs/embedding.md, "Link limits"): a link the page writes is at most MAX_LINK_CHARS
// characters long, whole URL, and its scenario at most MAX_SCENARIO_BYTES when decompressed
// (scenario-codec.js; checkLink() says why not, and the page offers the scenario as a file instead). The reader reads
// hashes up to MAX_HASH_CHARS (Chromium's own URL limit), the first MAX_PAIRS pairs, decodes only the
// last `scenario=` it sees, and gives back at most MAX_PROBLEMS problems: identical ones once, with
// how many more were like it, every key or value echoed cut to text.js's ECHO_CHARS characters.

import { parseParam, plannerFits, taskOf } from './panel.js';
import { OVERLAYS } from '../draw/palette.js';
import { cut } from './text.js';
import { MAX_HASH_CHARS, MAX_SCENARIO_BYTES, decodeScenario, encodeScenario } from './scenario-codec.js';
import { readSeed, blockSeedProblem } from './seed.js';
import { readCamera, writeCamera } from './camera-link.js';
import { readZoom, writeZoom } from './plane-zoom.js';
import { GHOSTS, readSpacing } from './ghost-spacing.js';

export const VIEW_DEFAULTS = Object.freeze({ speed: 33, anim: 50, rawPath: false, stepSize: 1 });
export const CONTROLS = Object.freeze(['run', 'pause', 'step', 'back', 'reset', 'speed', 'seed']);
export const DEFAULT_CONTROLS = Object.freeze(['run', 'pause', 'step', 'back', 'reset']);
/** Keys that are not planner parameters (a parameter of that name could not be shared). */
export const RESERVED = Object.freeze(['scenario', 'planner', 'seed', 'overlays', 'speed', 'anim', 'raw-path',
  'step-size', 'camera', 'zoom', 'ghosts', 'autoplay', 'click', 'controls']);

/**
 * The longest link (whole URL) the page writes: Chromium opens up to 2 MB, but a link is pasted
 * into chats, forums, e-mails and course pages, whose fields hold far less (Slack's API cuts a message at
 * 40,000 characters); 32,000 characters carry an edited scenario of about 2,500 rectangles (an
 * edited built-in takes at most about 2,100).
 */
export const MAX_LINK_CHARS = 32000;
/** Pairs read from one hash (a link the page writes has fewer than 50); the rest are counted only. */
export const MAX_PAIRS = 1000;
/** Problems given back (distinct texts). */
export const MAX_PROBLEMS = 30;

/**
 * A bounded list of problems: `push(text)` as on an array; identical texts are kept once and
 * counted, at most `max` distinct ones are kept. `list()`: the texts, "(and N more like it)" added
 * where repeated, and a last line counting those left out.
 */
export class Problems {
  constructor(max = MAX_PROBLEMS) { this.max = max; this.counts = new Map(); this.dropped = 0; }

  push(...texts) {
    for (const text of texts) {
      const t = String(text);
      if (this.counts.has(t)) this.counts.set(t, this.counts.get(t) + 1);
      else if (this.counts.size < this.max) this.counts.set(t, 1);
      else this.dropped++;
    }
  }

  get length() { return this.counts.size + this.dropped; }

  list() {
    const n = (k) => k.toLocaleString('en');
    const out = [...this.counts].map(([t, c]) => (c > 1 ? `${t} (…and ${n(c - 1)} more like it)` : t));
    if (this.dropped) out.push(`…and ${n(this.dropped)} more problem${this.dropped === 1 ? '' : 's'}.`);
    return out;
  }
}

/**
 * Problem texts (from several sources, some already bounded lists) as at most `max` lines,
 * repeated ones once, and the count of the rest (a list's own "…and N more problems." included).
 */
export function boundedProblems(texts, max = MAX_PROBLEMS) {
  const p = new Problems(max);
  for (const t of texts) {
    const more = /^…and ([\d,]+) more problems?\.$/.exec(t);
    if (more) p.dropped += Number(more[1].replace(/,/g, ''));
    else p.push(t);
  }
  return p.list();
}

// Encoding: percent-encoding that keeps `,`, `:`, `+` readable

function encodeValue(v) {
  const s = String(v);
  // lone surrogates (encodeURIComponent throws on them) as U+FFFD
  const text = typeof s.toWellFormed === 'function' ? s.toWellFormed()
    : s.replace(/[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/g, '\uFFFD');
  return encodeURIComponent(text).replace(/%2C/gi, ',').replace(/%3A/gi, ':').replace(/%2B/gi, '+');
}

function safeDecode(text) {
  try { return decodeURIComponent(text); } catch { return null; }
}

/**
 * `#a=1&b&c=x` → [[key, value or null], ...] (decoded; pairs that do not decode are reported). At
 * most MAX_PAIRS pairs are read (the rest are counted in one problem); a hash over MAX_HASH_CHARS
 * is not read at all. `problems`: anything with push(text).
 * @param {string} hash
 * @param {{push: (...texts: string[]) => any}} [problems]
 */
export function parsePairs(hash, problems = []) {
  const text = String(hash ?? '').replace(/^#/, '');
  const out = [];
  if (text.length > MAX_HASH_CHARS) {
    problems.push(`This link is ${text.length.toLocaleString('en')} characters long: more than the `
      + `${MAX_HASH_CHARS.toLocaleString('en')} a link may have (it is cut short or not a Planarium link); nothing in it was used.`);
    return out;
  }
  let read = 0;
  for (let at = 0; at < text.length;) {
    const start = at;
    let end = text.indexOf('&', at);
    if (end < 0) end = text.length;
    at = end + 1;
    if (end === start) continue;
    if (read === MAX_PAIRS) {
      let rest = 0; // the non-empty parts from here on, counted without reading them
      for (let i = start; i < text.length;) {
        let e = text.indexOf('&', i);
        if (e < 0) e = text.length;
        if (e > i) rest++;
        i = e + 1;
      }
      problems.push(`This link has ${rest.toLocaleString('en')} more parts after the first ${MAX_PAIRS.toLocaleString('en')} `
        + '(a link the page writes has fewer than 50); they were left out.');
      break;
    }
    read++;
    const part = text.slice(start, end);
    const eq = part.indexOf('=');
    const key = safeDecode(eq < 0 ? part : part.slice(0, eq));
    const value = eq < 0 ? null : safeDecode(part.slice(eq + 1));
    if (key === null || (eq >= 0 && value === null)) {
      problems.push(`"${cut(part)}" is not a valid part of a link (a bad %-escape); it was left out.`);
      continue;
    }
    out.push([key.trim(), value]);
  }
  return out;
}

// Reading a link

function wholeNumber(text, lo, hi) {
  if (text === null || !/^\s*\d+\s*$/.test(text)) return null;
  const v = Number(text);
  return Number.isSafeInteger(v) && v >= lo && v <= hi ? v : null;
}

function flag(key, value, problems) {
  if (value === null || /^(1|true|yes|on|)$/i.test(value)) return true;
  if (/^(0|false|no|off)$/i.test(value)) return false;
  problems.push(`${key}=${cut(value)}: write ${key} alone (on) or ${key}=0 (off); it was left out.`);
  return null;
}

function overlayById(name) {
  const id = name.startsWith('show-') ? name : `show-${name}`;
  return OVERLAYS.find((o) => o.id === id) || null;
}

/**
 * Read a link's hash (with or without `#`). `builtins`: [{id, name, ...}] to check a built-in's id
 * against (optional). Returns {scenario: {id} | {text} | null, planner, seed, params: [[key, text]],
 * overlays: {option: bool} (only those named), view: {speed?, anim?, rawPath?, stepSize?, camera?, zoom?, ghosts?},
 * autoplay, click, controls: [names] | null, problems: [text]}.
 */
export async function readShare(hash, { builtins = null } = {}) {
  const problems = new Problems();
  const share = {
    scenario: null, planner: null, seed: null, params: [], overlays: {}, view: {},
    autoplay: false, click: false, controls: null, problems: [],
  };
  const needs = (key, value) => {
    if (value !== null && value !== '') return true;
    problems.push(`"${cut(key)}" needs a value (${cut(key)}=…); it was left out.`);
    return false;
  };
  const params = new Map();
  let scenario = null; // the last scenario= value: only it is decoded
  for (const [key, value] of parsePairs(hash, problems)) {
    switch (key) {
      case 'scenario':
        if (needs(key, value)) scenario = value;
        break;
      case 'planner':
        if (needs(key, value)) share.planner = value;
        break;
      case 'seed': {
        if (!needs(key, value)) break;
        const r = readSeed(value);
        if (r.why) problems.push(`seed=${cut(value)}: the seed ${r.reason}; the scenario's seed is used.`);
        else share.seed = r.seed;
        break;
      }
      case 'overlays':
        if (!needs(key, value)) break;
        for (let item of value.split(',', 100)) { // the overlay box has a dozen
          item = item.trim();
          if (!item) continue;
          // a `+` that went through form decoding arrives as a space (trimmed away): no sign means on
          const on = item[0] !== '-';
          const o = overlayById(/^[+-]/.test(item) ? item.slice(1) : item);
          if (!o) problems.push(`overlays: there is no overlay "${cut(item.replace(/^[+-]/, ''))}"; it was left out.`);
          else share.overlays[o.option] = on;
        }
        break;
      case 'speed': case 'anim': {
        if (!needs(key, value)) break;
        const v = Number(value);
        if (!Number.isFinite(v) || v < 0 || v > 100) problems.push(`${key}=${cut(value)}: it must be a number from 0 to 100; left at its default.`);
        else share.view[key] = Math.round(v);
        break;
      }
      case 'raw-path': {
        const v = flag(key, value, problems);
        if (v !== null) share.view.rawPath = v;
        break;
      }
      case 'step-size': {
        if (!needs(key, value)) break;
        const v = wholeNumber(value, 1, 1000000);
        if (v === null) problems.push(`step-size=${cut(value)}: it must be a whole number from 1 to 1000000; left at 1.`);
        else share.view.stepSize = v;
        break;
      }
      case 'camera': {
        if (!needs(key, value)) break;
        const r = readCamera(value);
        if (r.why) problems.push(`camera=${cut(value)}: ${r.why}; the view is framed on the problem.`);
        else share.view.camera = r.camera;
        break;
      }
      case 'zoom': {
        if (!needs(key, value)) break;
        const r = readZoom(value);
        if (r.why) problems.push(`zoom=${cut(value)}: ${r.why}; the view from above shows the whole workspace.`);
        else share.view.zoom = r.viewport;
        break;
      }
      case 'ghosts': {
        if (!needs(key, value)) break;
        // a plain decimal (no hex, no blanks), then the panel's own bounds
        const r = /^[+-]?(\d{1,6}(\.\d{0,12})?|\.\d{1,12})$/.test(value) ? readSpacing(value) : null;
        if (!r || 'error' in r) problems.push(`ghosts=${cut(value)}: it must be 0 (no ghosts) or a number from ${GHOSTS.min} to ${GHOSTS.max} (rad); left at ${GHOSTS.initial}.`);
        else share.view.ghosts = r.value;
        break;
      }
      case 'autoplay': case 'click': {
        const v = flag(key, value, problems);
        if (v !== null) share[key] = v;
        break;
      }
      case 'controls': {
        const names = (value || '').split(',', 100).map((s) => s.trim()).filter(Boolean);
        const bad = [...new Set(names.filter((n) => !CONTROLS.includes(n)))];
        if (bad.length) {
          const shown = bad.slice(0, 5).map((n) => cut(n, 20)).join(', ') + (bad.length > 5 ? ` and ${bad.length - 5} more` : '');
          problems.push(`controls: ${shown} ${bad.length === 1 ? 'is' : 'are'} not a control (${CONTROLS.join(', ')}).`);
        }
        share.controls = CONTROLS.filter((n) => names.includes(n)).sort((x, y) => names.indexOf(x) - names.indexOf(y));
        break;
      }
      default:
        if (!key) break;
        if (value === null) { problems.push(`"${cut(key)}" needs a value (${cut(key)}=…); it was left out.`); break; }
        params.delete(key); // the last one counts, in its place
        params.set(key, value);
    }
  }
  share.params = [...params];
  if (scenario !== null) {
    if (/^[a-z0-9]+:/i.test(scenario)) {
      try {
        share.scenario = { text: await decodeScenario(scenario) };
      } catch (e) {
        problems.push(e.damaged ? `The link's scenario is cut short or damaged (${e.damaged}): copy the whole link again, or ask for the scenario as a file.`
          : `The link's scenario could not be read: ${e.message}.`);
      }
    } else if (builtins && !builtins.some((b) => b.id === scenario)) {
      problems.push(`There is no built-in scenario "${cut(scenario)}".`);
    } else {
      share.scenario = { id: scenario };
    }
  }
  share.problems = problems.list();
  return share;
}

/** Planner spec `p`'s parameter specs: its own, its groups', the run's. */
export function paramSpecs(p, registry) {
  return [...p.params, ...(p.groups || []).flatMap((g) => g.params), ...(registry.run_params || [])];
}

/**
 * The planner set-up a share restores on `scenario` (the loaded, normalised scenario): a block
 * {name, seed, ...params} for panel.apply(), with only values that are valid parameters of that
 * planner, and the problems found. `fallback`: the planner's name when neither the link nor the
 * scenario names one that fits (the panel's current one; else the first that fits).
 */
export function setupFor(share, scenario, registry, fallback = null) {
  const problems = new Problems();
  const planners = registry.planners;
  const task = taskOf(scenario);
  const fits = (p) => plannerFits(p, task);
  const byName = (n) => planners.find((q) => q.name === n);
  const own = scenario?.planner && byName(scenario.planner.name);
  let p = null;
  let base = {};
  if (share.planner !== null) {
    p = byName(share.planner);
    if (!p) {
      problems.push(`There is no planner "${cut(share.planner)}" (${planners.map((q) => q.name).join(', ')}).`);
    } else if (!fits(p)) {
      problems.push(`${p.label} does not fit this scenario (it needs ${p.task === 'inspection' ? 'inspection points' : 'a goal'}).`);
      p = null;
    }
  }
  if (!p) {
    if (own && fits(own)) { p = own; base = scenario.planner; } else p = (fallback && byName(fallback) && fits(byName(fallback)) ? byName(fallback) : planners.find(fits)) || planners[0];
  }
  const specs = paramSpecs(p, registry);
  const block = { name: p.name };
  for (const [key, value] of Object.entries(base)) {
    if (key !== 'name' && key !== 'seed' && specs.some((s) => s.name === key)) block[key] = value;
  }
  const seedOf = (s) => (Number.isSafeInteger(s) && s >= 0 ? s : null);
  block.seed = share.seed ?? seedOf(scenario?.planner?.seed) ?? 1;
  const unusable = share.seed === null ? blockSeedProblem(scenario?.planner?.seed) : '';
  if (unusable) problems.push(`${unusable}; seed ${block.seed} is used.`);
  for (const [key, text] of share.params) {
    const spec = specs.find((s) => s.name === key);
    if (!spec) {
      problems.push(`"${cut(key)}" is not a parameter of ${p.label}; it was left out.`);
      continue;
    }
    const parsed = parseParam(spec, text);
    if (!parsed.ok || parsed.value === undefined) {
      problems.push(`${key}=${cut(text)}: ${spec.label} must be ${parsed.ok ? 'given' : parsed.why}; left at its default.`);
      continue;
    }
    block[key] = parsed.value;
  }
  return { block, problems: problems.list() };
}

/** A block from setupFor as the worker's `configure` request {planner, params, seed}. */
export function configOf(block) {
  const { name, seed, ...params } = block;
  return { planner: name, params, seed };
}

/** View options {showAccepted, ...}: the overlays' defaults with a share's on top. */
export function overlayOptions(overlays = {}) {
  return Object.fromEntries(OVERLAYS.map((o) => [o.option, overlays[o.option] ?? o.on]));
}

// Writing a link

/**
 * The hash (without `#`) for a state: `scenario` {id} or {text} (the JSON of an edited or opened
 * scenario), `config` {planner, params, seed} (the panel's), `overlays` {option: bool}, `view`
 * {speed, anim, rawPath, stepSize, camera, zoom, ghosts}; `registry` to leave out parameters at their defaults. `extra`:
 * more [key, value | null] pairs (embed options). `encoded`: a cache (Map) of scenario texts'
 * encodings.
 * @param {{scenario: {id?: string, text?: string}, config?: any, overlays?: Record<string, boolean>,
 *   view?: {speed?: number, anim?: number, rawPath?: boolean, stepSize?: number,
 *     camera?: {target: number[], yaw: number, pitch: number, distance: number} | null,
 *     zoom?: {zoom: number, cx: number, cy: number} | null, ghosts?: number},
 *   extra?: Array<[string, any]>}} state
 * @param {any} registry
 * @param {Map<string, string> | null} [encoded]
 */
export async function writeShare({ scenario, config, overlays = {}, view = {}, extra = [] }, registry, encoded = null) {
  const pairs = [];
  if (scenario?.id) {
    pairs.push(['scenario', scenario.id]);
  } else if (scenario?.text) {
    let value = encoded?.get(scenario.text);
    if (!value) {
      value = await encodeScenario(scenario.text);
      encoded?.clear(); // one scenario at a time is enough
      encoded?.set(scenario.text, value);
    }
    pairs.push(['scenario', value]);
  }
  if (config) {
    pairs.push(['planner', config.planner], ['seed', config.seed]);
    const p = registry.planners.find((q) => q.name === config.planner);
    const specs = p ? paramSpecs(p, registry) : [];
    const written = new Set();
    for (const spec of specs) { // the registry's order: own, groups, run
      if (written.has(spec.name) || !Object.hasOwn(config.params, spec.name)) continue;
      written.add(spec.name);
      const v = config.params[spec.name];
      if (v !== spec.default) pairs.push([spec.name, v]);
    }
  }
  // a planner that draws a field shows its heat map by default (the playground's overlay box, the
  // embed): for it the heat map is written only when it is off
  const field = !!config && registry?.planners?.find((q) => q.name === config.planner)?.caps?.draws === 'field';
  const byDefault = (o) => o.on || (o.option === 'showHeat' && field);
  const flips = OVERLAYS.filter((o) => Object.hasOwn(overlays, o.option) && overlays[o.option] !== byDefault(o))
    .map((o) => `${overlays[o.option] ? '+' : '-'}${o.id}`);
  if (flips.length) pairs.push(['overlays', flips.join(',')]);
  if (view.speed !== undefined && view.speed !== VIEW_DEFAULTS.speed) pairs.push(['speed', view.speed]);
  if (view.anim !== undefined && view.anim !== VIEW_DEFAULTS.anim) pairs.push(['anim', view.anim]);
  if (view.rawPath) pairs.push(['raw-path', null]);
  if (view.stepSize !== undefined && view.stepSize !== VIEW_DEFAULTS.stepSize) pairs.push(['step-size', view.stepSize]);
  if (view.camera) pairs.push(['camera', writeCamera(view.camera)]);
  if (view.zoom) pairs.push(['zoom', writeZoom(view.zoom)]);
  if (view.ghosts !== undefined && view.ghosts !== GHOSTS.initial) pairs.push(['ghosts', view.ghosts]);
  pairs.push(...extra);
  return pairs.map(([k, v]) => (v === null ? encodeValue(k) : `${encodeValue(k)}=${encodeValue(v)}`)).join('&');
}

/**
 * Why `url` (a link the page wrote, whose scenario is `scenarioText` or a built-in's id) should not
 * be offered as a link, in words; null when it can: it is at most MAX_LINK_CHARS long, its scenario
 * at most MAX_SCENARIO_BYTES, and read back it gives no problem and the same scenario text.
 */
export async function checkLink(url, scenarioText = null) {
  const n = (k) => k.toLocaleString('en');
  if (scenarioText !== null) {
    const bytes = new TextEncoder().encode(scenarioText).length;
    if (bytes > MAX_SCENARIO_BYTES) {
      return `this scenario is ${(bytes / (1 << 20)).toFixed(1)} MB of JSON, more than the ${MAX_SCENARIO_BYTES >> 20} MB a link may carry`;
    }
  }
  if (url.length > MAX_LINK_CHARS) {
    return `the link would be ${n(url.length)} characters long, more than the ${n(MAX_LINK_CHARS)} that survive being pasted `
      + 'into a chat, a forum or a course page';
  }
  const hash = url.includes('#') ? url.slice(url.indexOf('#')) : '';
  const back = await readShare(hash);
  if (back.problems.length) return `the link does not read back (${back.problems[0]})`;
  if (scenarioText !== null && back.scenario?.text !== scenarioText) return 'the link does not read back the same scenario';
  return null;
}

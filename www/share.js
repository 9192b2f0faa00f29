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
// embed.html and <planarium-playground> only:
//   autoplay   run as soon as the scenario is loaded
//   click      run on the first click on the canvas
//   controls   comma-separated, from run, pause, step, back, reset, speed, seed (default: run,
//              pause, step, back, reset; empty: none)
// Unknown keys and bad values are reported as problems (text for the page to show) and left out;
// nothing here throws on what a link says.

import { parseParam, plannerFits, taskOf } from './panel.js';
import { OVERLAYS } from './palette.js';

export const VIEW_DEFAULTS = Object.freeze({ speed: 60, anim: 50, rawPath: false, stepSize: 1 });
export const CONTROLS = Object.freeze(['run', 'pause', 'step', 'back', 'reset', 'speed', 'seed']);
export const DEFAULT_CONTROLS = Object.freeze(['run', 'pause', 'step', 'back', 'reset']);
/** Keys that are not planner parameters (a parameter of that name could not be shared). */
export const RESERVED = Object.freeze(['scenario', 'planner', 'seed', 'overlays', 'speed', 'anim', 'raw-path',
  'step-size', 'autoplay', 'click', 'controls']);

const MAX_SCENARIO_BYTES = 4 << 20; // decompressed: no scenario is anywhere near this

// Encoding: percent-encoding that keeps `,`, `:`, `+` readable

function encodeValue(v) {
  return encodeURIComponent(String(v)).replace(/%2C/gi, ',').replace(/%3A/gi, ':').replace(/%2B/gi, '+');
}

function safeDecode(text) {
  try { return decodeURIComponent(text); } catch { return null; }
}

/** `#a=1&b&c=x` → [[key, value or null], ...] (decoded; pairs that do not decode are reported). */
export function parsePairs(hash, problems = []) {
  const text = String(hash || '').replace(/^#/, '');
  const out = [];
  for (const part of text.split('&')) {
    if (!part) continue;
    const eq = part.indexOf('=');
    const key = safeDecode(eq < 0 ? part : part.slice(0, eq));
    const value = eq < 0 ? null : safeDecode(part.slice(eq + 1));
    if (key === null || (eq >= 0 && value === null)) {
      problems.push(`"${part.slice(0, 40)}" is not a valid part of a link; it was left out.`);
      continue;
    }
    out.push([key.trim(), value]);
  }
  return out;
}

// base64url and deflate-raw

export function toBase64url(bytes) {
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function fromBase64url(text) {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('it is not base64url');
  const b64 = text.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (text.length % 4)) % 4);
  const bin = atob(b64);
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

async function pipeBytes(bytes, transform) {
  const stream = new Blob([bytes]).stream().pipeThrough(transform);
  const reader = stream.getReader();
  const chunks = [];
  let size = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    size += value.length;
    if (size > MAX_SCENARIO_BYTES) { reader.cancel().catch(() => {}); throw new Error('it is too large'); }
    chunks.push(value);
  }
  const out = new Uint8Array(size);
  let at = 0;
  for (const c of chunks) { out.set(c, at); at += c.length; }
  return out;
}

function hasStream(Type) {
  try { new globalThis[Type]('deflate-raw'); return true; } catch { return false; }
}

/** A scenario's JSON text as a link value: `deflate:…`, or `base64:…` without CompressionStream. */
export async function encodeScenario(text) {
  const bytes = new TextEncoder().encode(text);
  if (hasStream('CompressionStream')) {
    return `deflate:${toBase64url(await pipeBytes(bytes, new CompressionStream('deflate-raw')))}`;
  }
  return `base64:${toBase64url(bytes)}`;
}

/** A link's `deflate:` / `base64:` value → the scenario's JSON text; throws Error(why). */
export async function decodeScenario(value) {
  const colon = value.indexOf(':');
  const kind = value.slice(0, colon);
  const bytes = fromBase64url(value.slice(colon + 1));
  let out;
  if (kind === 'deflate') {
    if (!hasStream('DecompressionStream')) throw new Error('this browser cannot decompress it (no DecompressionStream)');
    try { out = await pipeBytes(bytes, new DecompressionStream('deflate-raw')); } catch (e) {
      throw new Error(/too large/.test(e.message) ? e.message : 'it does not decompress (the link may be cut short)');
    }
  } else if (kind === 'base64') {
    out = bytes;
  } else {
    throw new Error(`"${kind}:" is not a known encoding (deflate: or base64:)`);
  }
  try { return new TextDecoder('utf-8', { fatal: true }).decode(out); } catch { throw new Error('it is not text'); }
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
  problems.push(`${key}=${value}: write ${key} alone (on) or ${key}=0 (off); it was left out.`);
  return null;
}

function overlayById(name) {
  const id = name.startsWith('show-') ? name : `show-${name}`;
  return OVERLAYS.find((o) => o.id === id) || null;
}

/**
 * Read a link's hash (with or without `#`). `builtins`: [{id, name, ...}] to check a built-in's id
 * against (optional). Returns {scenario: {id} | {text} | null, planner, seed, params: [[key, text]],
 * overlays: {option: bool} (only those named), view: {speed?, anim?, rawPath?, stepSize?},
 * autoplay, click, controls: [names] | null, problems: [text]}.
 */
export async function readShare(hash, { builtins = null } = {}) {
  const problems = [];
  const share = {
    scenario: null, planner: null, seed: null, params: [], overlays: {}, view: {},
    autoplay: false, click: false, controls: null, problems,
  };
  const needs = (key, value) => {
    if (value !== null && value !== '') return true;
    problems.push(`"${key}" needs a value (${key}=…); it was left out.`);
    return false;
  };
  for (const [key, value] of parsePairs(hash, problems)) {
    switch (key) {
      case 'scenario': {
        if (!needs(key, value)) break;
        if (/^[a-z0-9]+:/i.test(value)) {
          try {
            share.scenario = { text: await decodeScenario(value) };
          } catch (e) {
            share.scenario = null;
            problems.push(`The link's scenario could not be read: ${e.message}.`);
          }
        } else if (builtins && !builtins.some((b) => b.id === value)) {
          share.scenario = null;
          problems.push(`There is no built-in scenario "${value}".`);
        } else {
          share.scenario = { id: value };
        }
        break;
      }
      case 'planner':
        if (needs(key, value)) share.planner = value;
        break;
      case 'seed': {
        if (!needs(key, value)) break;
        const v = wholeNumber(value, 0, Number.MAX_SAFE_INTEGER);
        if (v === null) problems.push(`seed=${value}: the seed must be a whole number ≥ 0; the scenario's seed is used.`);
        else share.seed = v;
        break;
      }
      case 'overlays':
        if (!needs(key, value)) break;
        for (let item of value.split(',')) {
          item = item.trim();
          if (!item) continue;
          // a `+` that went through form decoding arrives as a space (trimmed away): no sign means on
          const on = item[0] !== '-';
          const o = overlayById(/^[+-]/.test(item) ? item.slice(1) : item);
          if (!o) problems.push(`overlays: there is no overlay "${item.replace(/^[+-]/, '')}"; it was left out.`);
          else share.overlays[o.option] = on;
        }
        break;
      case 'speed': case 'anim': {
        if (!needs(key, value)) break;
        const v = Number(value);
        if (!Number.isFinite(v) || v < 0 || v > 100) problems.push(`${key}=${value}: it must be a number from 0 to 100; left at its default.`);
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
        if (v === null) problems.push(`step-size=${value}: it must be a whole number from 1 to 1000000; left at 1.`);
        else share.view.stepSize = v;
        break;
      }
      case 'autoplay': case 'click': {
        const v = flag(key, value, problems);
        if (v !== null) share[key] = v;
        break;
      }
      case 'controls': {
        const names = (value || '').split(',').map((s) => s.trim()).filter(Boolean);
        const bad = names.filter((n) => !CONTROLS.includes(n));
        if (bad.length) problems.push(`controls: ${bad.join(', ')} ${bad.length === 1 ? 'is' : 'are'} not a control (${CONTROLS.join(', ')}).`);
        share.controls = names.filter((n, i) => CONTROLS.includes(n) && names.indexOf(n) === i);
        break;
      }
      default:
        if (!key) break;
        if (value === null) { problems.push(`"${key}" needs a value (${key}=…); it was left out.`); break; }
        share.params = share.params.filter(([k]) => k !== key).concat([[key, value]]);
    }
  }
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
  const problems = [];
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
      problems.push(`There is no planner "${share.planner}" (${planners.map((q) => q.name).join(', ')}).`);
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
  for (const [key, text] of share.params) {
    const spec = specs.find((s) => s.name === key);
    if (!spec) {
      problems.push(`"${key}" is not a parameter of ${p.label}; it was left out.`);
      continue;
    }
    const parsed = parseParam(spec, text);
    if (!parsed.ok || parsed.value === undefined) {
      problems.push(`${key}=${text}: ${spec.label} must be ${parsed.ok ? 'given' : parsed.why}; left at its default.`);
      continue;
    }
    block[key] = parsed.value;
  }
  return { block, problems };
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
 * {speed, anim, rawPath, stepSize}; `registry` to leave out parameters at their defaults. `extra`:
 * more [key, value | null] pairs (embed options). `encoded`: a cache (Map) of scenario texts'
 * encodings.
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
  const flips = OVERLAYS.filter((o) => Object.hasOwn(overlays, o.option) && overlays[o.option] !== o.on)
    .map((o) => `${overlays[o.option] ? '+' : '-'}${o.id}`);
  if (flips.length) pairs.push(['overlays', flips.join(',')]);
  if (view.speed !== undefined && view.speed !== VIEW_DEFAULTS.speed) pairs.push(['speed', view.speed]);
  if (view.anim !== undefined && view.anim !== VIEW_DEFAULTS.anim) pairs.push(['anim', view.anim]);
  if (view.rawPath) pairs.push(['raw-path', null]);
  if (view.stepSize !== undefined && view.stepSize !== VIEW_DEFAULTS.stepSize) pairs.push(['step-size', view.stepSize]);
  pairs.push(...extra);
  return pairs.map(([k, v]) => (v === null ? encodeValue(k) : `${encodeValue(k)}=${encodeValue(v)}`)).join('&');
}

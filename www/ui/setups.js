// Planner set-ups as the benchmark and compare pages share them, and those pages' URL state.
//
// A set-up {label, planner, params} is written as a line of the CLI's `--setup` syntax
// (`label: planner --param-name value …`, read back by the core's parse_setups), so a set-up built
// from menus, typed by hand, or carried by a link is the same thing.
//
// The pages keep their state in the URL hash, in the playground's share-link grammar (ui/links.js:
// `scenario` a built-in's id or an opened scenario's `deflate:` JSON, `seed`, `planner` and its
// parameters), plus their own keys: compare.html `a` and `b` (one set-up line each); bench.html
// `setups` (the set-up lines, one per line) and `runs`. A playground link's `#…` opened on either
// page brings its scenario, and its planner set-up as a set-up. Bad values are problems in words
// (the page shows them) and defaults are used; nothing here throws on what a link says.

import { readShare, writeShare, paramSpecs, MAX_LINK_CHARS } from './links.js';
import { cut } from './text.js';

/** Set-ups a link or the benchmark may hold: the core's own limit (docs/limits.md). */
export const MAX_SETUPS = 16;
/** Characters of set-up text a link may hold (16 set-ups of 1,250 characters: far more than any needs). */
export const MAX_SETUP_CHARS = 20000;
/** The largest scenario file the pages open: the core's limit on one file's text (docs/limits.md). */
export const MAX_FILE_BYTES = 16 << 20;

/**
 * A set-up as a line of the CLI's `--setup` syntax: `label: planner --param-name value …`; the
 * label is left out when it is the line itself (the parser's default label).
 * @param {{label?: string, planner: string, params?: Record<string, number | string>}} setup
 * @returns {string}
 */
export function setupLine({ label = '', planner, params = {} }) {
  const body = [planner, ...Object.entries(params).map(([k, v]) => `--${k.replace(/_/g, '-')} ${v}`)].join(' ');
  const l = String(label).replace(/[:\n\r]/g, ' ').trim();
  return l && l !== body ? `${l}: ${body}` : body;
}

/**
 * Of `params`, those that differ from planner spec `p`'s defaults (its own, its groups', the
 * run's): what a set-up line needs to say.
 * @param {object} p a planner spec from the registry
 * @param {Record<string, number | string>} params
 * @param {object} registry
 * @returns {Record<string, number | string>}
 */
export function differingParams(p, params, registry) {
  const specs = paramSpecs(p, registry);
  return Object.fromEntries(Object.entries(params).filter(([k, v]) => specs.find((s) => s.name === k)?.default !== v));
}

/**
 * The lines of set-up text that are set-ups (not blank, not `#` comments), with their line
 * indices: [{line, at}].
 * @param {string} text
 * @returns {{line: string, at: number}[]}
 */
export function setupLines(text) {
  return String(text).split('\n').map((line, at) => ({ line, at })).filter(({ line }) => line.trim() && !line.trim().startsWith('#'));
}

/**
 * Read a page's hash: the playground's share (readShare) with the page's own `keys` taken out of
 * its parameters. Returns {share, own: Map(key → value text)}; problems are in share.problems.
 * @param {string} hash
 * @param {{builtins?: object[] | null, keys: string[]}} options
 */
export async function readPageState(hash, { builtins = null, keys }) {
  const share = await readShare(hash, { builtins });
  const own = new Map();
  share.params = share.params.filter(([k, v]) => {
    if (!keys.includes(k)) return true;
    own.set(k, v);
    return false;
  });
  return { share, own };
}

/**
 * `text` as a whole number from `lo` to `hi`, else null.
 * @param {string | null | undefined} text
 * @param {number} lo
 * @param {number} hi
 * @returns {number | null}
 */
export function wholeIn(text, lo, hi) {
  if (text === null || text === undefined || !/^\s*\d+\s*$/.test(String(text))) return null;
  const v = Number(text);
  return Number.isSafeInteger(v) && v >= lo && v <= hi ? v : null;
}

/**
 * Set-up text from a link, checked by `parse` (the core's parse_setups): {text, setups} or
 * {problem} (in words, naming the key and the line).
 * @param {string} key the link's key, for the message
 * @param {string} text
 * @param {(text: string) => string} parse
 * @param {number} [max] most set-ups allowed
 */
export function checkSetups(key, text, parse, max = MAX_SETUPS) {
  if (text.length > MAX_SETUP_CHARS) {
    return { problem: `${key}: the set-ups are ${text.length.toLocaleString('en')} characters long, more than the ${MAX_SETUP_CHARS.toLocaleString('en')} a link may hold` };
  }
  const n = setupLines(text).length;
  if (n > max) return { problem: `${key}: ${n} set-ups, more than the ${max} allowed` };
  try {
    return { text, setups: JSON.parse(parse(text)) };
  } catch (e) {
    return { problem: `${key}=${cut(text.replace(/\n/g, ' / '))}: ${cut(String(e?.message ?? e), 200)}` };
  }
}

/** A core error (JSON `{path, message, line, column, text}`, or plain text) in words. */
export function coreError(e) {
  const raw = String(e?.message ?? e);
  try {
    const j = JSON.parse(raw);
    return j.text || j.message || raw;
  } catch {
    return raw;
  }
}

/**
 * The page's hash: `scenario` ({id} or {text}), the page's own pairs `extra` [[key, value]] and
 * what the views show `view` (the playground's grammar: the plane's `zoom`).
 * @param {{id?: string, text?: string}} scenario
 * @param {[string, string | number][]} extra
 * @param {object} registry
 * @param {Map<string, string>} [cache] encoded scenario texts
 * @param {{zoom?: {zoom: number, cx: number, cy: number} | null}} [view]
 * @returns {Promise<string>}
 */
export function pageHash(scenario, extra, registry, cache, view = {}) {
  return writeShare({ scenario, extra, view }, registry, cache);
}

/**
 * A link to the playground (index.html, next to this page) showing `config` {planner, params,
 * seed} on `scenario` ({id} or {text}); null when it would be longer than a link may be.
 * @param {{id?: string, text?: string}} scenario
 * @param {{planner: string, params: object, seed: number}} config
 * @param {object} registry
 * @param {Map<string, string>} [cache]
 * @returns {Promise<string | null>}
 */
export async function playgroundLink(scenario, config, registry, cache) {
  const hash = await writeShare({ scenario, config }, registry, cache);
  const url = `${new URL('index.html', location.href).href}#${hash}`;
  return url.length <= MAX_LINK_CHARS ? url : null;
}

/**
 * Read a file the user chose (bounded by MAX_FILE_BYTES): its text, or throws Error naming the file.
 * @param {File} file
 * @returns {Promise<string>}
 */
export async function readChosenFile(file) {
  if (file.size > MAX_FILE_BYTES) {
    throw new Error(`${file.name} is ${(file.size / (1 << 20)).toFixed(1)} MB, more than the ${MAX_FILE_BYTES >> 20} MB a scenario file may be`);
  }
  try {
    return await file.text();
  } catch (e) {
    throw new Error(`Could not read ${file.name}: ${e?.message ?? e}`);
  }
}

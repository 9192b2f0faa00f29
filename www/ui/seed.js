// Seeds the user types or links (the playground's panel, Compare's field, the embed's attribute and
// field, every page's `seed=` link key, a scenario's planner block): a whole number from 0 to
// MAX_SEED. The core takes any 64-bit seed natively, but the page holds a seed as a JavaScript
// number and the worker passes it as one, so above 2^53 − 1 a typed seed was rounded to another
// (9007199254740993 is …992 as a number) or shown and not used: such a seed is refused, with a
// message naming the field and the largest seed, and the seed in use stays.

import { shown } from './text.js';

/** The largest seed the page carries exactly: 2^53 − 1. */
export const MAX_SEED = Number.MAX_SAFE_INTEGER;

const TOO_LARGE = `is larger than ${MAX_SEED} (2^53 − 1), the largest seed the page carries exactly`;
const echo = (t) => { const s = shown(t); return s.length > 30 ? `${s.slice(0, 29)}…` : s; };

/**
 * A seed as typed or linked (`text`), read exactly: {seed} for a whole number 0 … MAX_SEED, else
 * {why, reason}: what is wrong with it, as the end of a sentence that starts with the field's name
 * ("Seed: 9007199254740993 is larger than …"), with the value (`why`) or without (`reason`).
 */
export function readSeed(text) {
  const t = String(text ?? '').trim();
  if (/^\d+$/.test(t)) {
    // compared as digits: as a number, 9007199254740993 would already be …992
    const digits = t.replace(/^0+(?=\d)/, '');
    if (digits.length > 16 || BigInt(digits) > BigInt(MAX_SEED)) return { why: `${echo(digits)} ${TOO_LARGE}`, reason: TOO_LARGE };
    return { seed: Number(digits) };
  }
  const v = Number(t);
  if (t !== '' && Number.isInteger(v) && v >= 0 && v <= MAX_SEED) return { seed: v }; // 1e3, 7.0
  if (t !== '' && Number.isInteger(v) && v > MAX_SEED) return { why: `${echo(t)} ${TOO_LARGE}`, reason: TOO_LARGE };
  const reason = `is not a whole number from 0 to ${MAX_SEED}`;
  return { why: `"${echo(t)}" ${reason}`, reason };
}

/** A scenario planner block's `seed` (a JSON number): why the page cannot use it, or '' (none, or usable). */
export function blockSeedProblem(seed) {
  if (seed === undefined || seed === null || (Number.isSafeInteger(seed) && seed >= 0)) return '';
  if (typeof seed === 'number' && seed > MAX_SEED) return `The scenario's seed (planner.seed) ${TOO_LARGE}, so it is not used`;
  return "The scenario's seed (planner.seed) is not a whole number ≥ 0, so it is not used";
}

// A scenario carried in a share link (links.js): its JSON text as `deflate:` and the base64url of
// its deflate-raw bytes (CompressionStream), or `base64:` and the base64url of the text where the
// browser has no CompressionStream; read back within the link limits, any damage said in words.

import { cut } from './text.js';

/** The largest scenario (UTF-8 bytes of its JSON, decompressed) a link may carry: no built-in is near it. */
export const MAX_SCENARIO_BYTES = 4 << 20;
/** The longest hash the reader reads: Chromium's URL limit (2 MiB); a longer one is refused whole. */
export const MAX_HASH_CHARS = 2 * 1024 * 1024;

export function toBase64url(bytes) {
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** base64url text → bytes; throws Error(why, in words) on anything else (never atob's own exception). */
export function fromBase64url(text) {
  const bad = /[^A-Za-z0-9_-]/.exec(text);
  if (bad) {
    const c = bad[0].codePointAt(0);
    const shown = c > 32 && c < 127 ? `"${bad[0]}"` : `U+${c.toString(16).toUpperCase().padStart(4, '0')}`;
    throw new Error(`it has ${shown} at character ${bad.index + 1}, which base64url text never has`);
  }
  if (text.length % 4 === 1) throw new Error('its base64url text stops in the middle of a character group');
  const b64 = text.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (text.length % 4)) % 4);
  let bin;
  try { bin = atob(b64); } catch { throw new Error('its base64url text does not decode'); }
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

/**
 * A link's `deflate:` / `base64:` value → the scenario's JSON text; throws Error(why, in words),
 * with `damaged` (the why alone) when the value is cut short or corrupted.
 */
export async function decodeScenario(value) {
  const text = String(value);
  const colon = text.indexOf(':');
  const kind = colon < 0 ? '' : text.slice(0, colon);
  if (kind !== 'deflate' && kind !== 'base64') throw new Error(`"${cut(kind || text, 20)}:" is not a known encoding (deflate: or base64:)`);
  const damaged = (why) => Object.assign(new Error(`it is cut short or damaged: ${why}`), { damaged: why });
  if (text.length - colon - 1 > MAX_HASH_CHARS) throw new Error('it is too large');
  let bytes;
  try { bytes = fromBase64url(text.slice(colon + 1)); } catch (e) { throw damaged(e.message); }
  let out;
  if (kind === 'deflate') {
    if (!hasStream('DecompressionStream')) throw new Error('this browser cannot decompress it (no DecompressionStream)');
    try { out = await pipeBytes(bytes, new DecompressionStream('deflate-raw')); } catch (e) {
      throw /too large/.test(e?.message) ? new Error(`it is too large (over ${MAX_SCENARIO_BYTES >> 20} MB decompressed)`)
        : damaged('its compressed data does not decompress');
    }
  } else {
    if (bytes.length > MAX_SCENARIO_BYTES) throw new Error(`it is too large (over ${MAX_SCENARIO_BYTES >> 20} MB)`);
    out = bytes;
  }
  try { return new TextDecoder('utf-8', { fatal: true }).decode(out); } catch { throw damaged('it is not UTF-8 text'); }
}

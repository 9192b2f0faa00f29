// An animated GIF (GIF89a) encoder: a palette of at most 256 colours (the fixed colours the page
// draws with first, then the frame's most common other colours), pixels mapped to their nearest
// palette colour, LZW compression, a delay per frame and the NETSCAPE2.0 loop. Pure (no DOM):
// RGBA bytes in, GIF bytes out, so Node tests use it directly. No transparency.

/** '#rrggbb' → [r, g, b] (null for anything else, e.g. rgba() colours). */
export function hexRgb(hex) {
  const m = /^#([0-9a-f]{6})$/i.exec(String(hex));
  if (!m) return null;
  const n = parseInt(m[1], 16);
  return [n >> 16, (n >> 8) & 255, n & 255];
}

/**
 * A palette (flat Uint8Array r, g, b, ...; at most `max` colours, at least 2) for RGBA pixels
 * `rgba`: the `fixed` [r, g, b] colours first (exact, so what the page draws in them stays exact),
 * then the most frequent other colours (averaged over 5-bit buckets), skipping near-duplicates.
 */
export function buildPalette(rgba, fixed = [], max = 256) {
  const out = [];
  const seen = new Set();
  /** @param {number[]} rgb */
  const add = ([r, g, b]) => {
    const key = (r << 16) | (g << 8) | b;
    if (seen.has(key) || out.length >= max) return;
    seen.add(key);
    out.push([r, g, b]);
  };
  fixed.forEach(add);
  const count = new Uint32Array(32768), sr = new Float64Array(32768), sg = new Float64Array(32768), sb = new Float64Array(32768);
  for (let i = 0; i < rgba.length; i += 4) {
    const k = ((rgba[i] >> 3) << 10) | ((rgba[i + 1] >> 3) << 5) | (rgba[i + 2] >> 3);
    count[k]++; sr[k] += rgba[i]; sg[k] += rgba[i + 1]; sb[k] += rgba[i + 2];
  }
  const buckets = [];
  for (let k = 0; k < 32768; k++) if (count[k]) buckets.push(k);
  buckets.sort((a, b) => count[b] - count[a]);
  for (const k of buckets) {
    if (out.length >= max) break;
    const c = [Math.round(sr[k] / count[k]), Math.round(sg[k] / count[k]), Math.round(sb[k] / count[k])];
    if (out.some(([r, g, b]) => (r - c[0]) ** 2 + (g - c[1]) ** 2 + (b - c[2]) ** 2 < 48)) continue;
    add(c);
  }
  while (out.length < 2) out.push([0, 0, 0]);
  return Uint8Array.from(out.flat());
}

/**
 * RGBA pixels → palette indices (nearest colour, alpha ignored). `cache` (a Map, optional) keeps
 * colour → index between frames of one palette.
 */
export function indexPixels(rgba, palette, cache = new Map()) {
  const n = rgba.length >> 2;
  const out = new Uint8Array(n);
  const size = palette.length / 3;
  for (let p = 0, i = 0; p < n; p++, i += 4) {
    const key = (rgba[i] << 16) | (rgba[i + 1] << 8) | rgba[i + 2];
    let idx = cache.get(key);
    if (idx === undefined) {
      let best = Infinity;
      idx = 0;
      for (let c = 0; c < size; c++) {
        const dr = palette[3 * c] - rgba[i], dg = palette[3 * c + 1] - rgba[i + 1], db = palette[3 * c + 2] - rgba[i + 2];
        const d = dr * dr + dg * dg + db * db;
        if (d < best) { best = d; idx = c; if (!d) break; }
      }
      cache.set(key, idx);
    }
    out[p] = idx;
  }
  return out;
}

/** A growing byte buffer. */
class Bytes {
  constructor() { this.buf = new Uint8Array(1 << 16); this.length = 0; }
  push(...bytes) { for (const b of bytes) this.byte(b); }
  byte(b) {
    if (this.length === this.buf.length) {
      const next = new Uint8Array(this.buf.length * 2);
      next.set(this.buf);
      this.buf = next;
    }
    this.buf[this.length++] = b;
  }
  u16(v) { this.byte(v & 255); this.byte((v >> 8) & 255); }
  bytes() { return this.buf.slice(0, this.length); }
}

// the LZW table: key (prefix code × 256 + next index) → code, valid when stamped with the current generation
const TABLE = 4096 * 256;
let codes = null, stamps = null, generation = 0;

/**
 * GIF LZW of `indices` (values < 2^minCodeSize) with code size `minCodeSize` (2..8): the code
 * stream's bytes (not yet cut into sub-blocks).
 */
export function lzwEncode(indices, minCodeSize) {
  if (!codes) { codes = new Int16Array(TABLE); stamps = new Uint32Array(TABLE); }
  const clear = 1 << minCodeSize, eoi = clear + 1;
  const out = new Bytes();
  let acc = 0, bits = 0;
  let width = minCodeSize + 1, next = eoi + 1;
  const emit = (code) => {
    acc |= code << bits;
    bits += width;
    while (bits >= 8) { out.byte(acc & 255); acc >>>= 8; bits -= 8; }
  };
  const reset = () => { generation++; width = minCodeSize + 1; next = eoi + 1; };
  reset();
  emit(clear);
  if (indices.length) {
    let prefix = indices[0];
    for (let i = 1; i < indices.length; i++) {
      const k = indices[i];
      const key = prefix * 256 + k;
      if (stamps[key] === generation) { prefix = codes[key]; continue; }
      emit(prefix);
      if (next < 4096) {
        codes[key] = next; stamps[key] = generation;
        // the decoder adds this entry one code later: widen when `next` no longer fits
        if (next === 1 << width && width < 12) width++;
        next++;
      } else {
        emit(clear);
        reset();
      }
      prefix = k;
    }
    emit(prefix);
  }
  emit(eoi);
  if (bits > 0) out.byte(acc & 255);
  return out.bytes();
}

/** Bits of a colour table that holds `colours` (1..8). */
function tableBits(colours) {
  let bits = 1;
  while (1 << bits < colours) bits++;
  return bits;
}

/** The LZW minimum code size of a GIF whose palette has `colours` colours. */
export function gifCodeSize(colours) { return Math.max(2, tableBits(colours)); }

/**
 * An animated GIF: `width` × `height`, global `palette` (flat r, g, b; at most 256 colours),
 * `frames` [{indices (Uint8Array, width × height) or lzw (those compressed by lzwEncode with
 * gifCodeSize(colours)), delay (hundredths of a second)}], looping
 * forever (`loop` 0) or that many times. Returns the file's bytes.
 */
export function encodeGif({ width, height, palette, frames, loop = 0 }) {
  if (!(width >= 1 && width <= 65535 && height >= 1 && height <= 65535)) throw new Error(`GIF: size ${width} × ${height} out of range`);
  const colours = palette.length / 3;
  if (!Number.isInteger(colours) || colours < 1 || colours > 256) throw new Error(`GIF: ${colours} palette colours (1 to 256)`);
  const bitsPer = tableBits(colours);
  const out = new Bytes();
  for (const ch of 'GIF89a') out.byte(ch.charCodeAt(0));
  out.u16(width); out.u16(height);
  out.push(0xf0 | (bitsPer - 1), 0, 0); // global table, 8-bit colour resolution, table size
  for (let i = 0; i < 3 << bitsPer; i++) out.byte(palette[i] ?? 0);
  out.push(0x21, 0xff, 11);
  for (const ch of 'NETSCAPE2.0') out.byte(ch.charCodeAt(0));
  out.push(3, 1); out.u16(loop); out.byte(0);
  const minCode = gifCodeSize(colours);
  for (const [n, f] of frames.entries()) {
    if (!f.lzw && f.indices?.length !== width * height) throw new Error(`GIF: frame ${n + 1} has ${f.indices?.length} pixels, not ${width * height}`);
    out.push(0x21, 0xf9, 4, 0x04); // graphic control: keep the frame (disposal 1), no transparency
    out.u16(Math.max(0, Math.min(65535, Math.round(f.delay ?? 10)))); out.push(0, 0);
    out.byte(0x2c); out.u16(0); out.u16(0); out.u16(width); out.u16(height); out.byte(0);
    out.byte(minCode);
    const data = f.lzw ?? lzwEncode(f.indices, minCode);
    for (let i = 0; i < data.length; i += 255) {
      const len = Math.min(255, data.length - i);
      out.byte(len);
      for (let j = 0; j < len; j++) out.byte(data[i + j]);
    }
    out.byte(0);
  }
  out.byte(0x3b);
  return out.bytes();
}

/**
 * Collects frames of RGBA pixels (ImageData-like {data, width, height}) into a GIF: the palette
 * is made from the first frame (and `fixed` colours), each frame is mapped and compressed as it
 * comes, so only compressed frames are held.
 */
export class GifWriter {
  constructor(width, height, fixed = []) {
    this.width = width;
    this.height = height;
    this.fixed = fixed;
    this.palette = null;
    this.cache = new Map();
    this.frames = [];
  }

  /** Add a frame shown for `delay` hundredths of a second; returns its palette indices. */
  add(image, delay = 10) {
    if (image.width !== this.width || image.height !== this.height) throw new Error(`GIF: a ${image.width} × ${image.height} frame in a ${this.width} × ${this.height} GIF`);
    if (!this.palette) this.palette = buildPalette(image.data, this.fixed);
    const indices = indexPixels(image.data, this.palette, this.cache);
    this.frames.push({ lzw: lzwEncode(indices, gifCodeSize(this.palette.length / 3)), delay });
    return indices;
  }

  /** The GIF's bytes. */
  finish() {
    if (!this.frames.length) throw new Error('GIF: no frames');
    return encodeGif({ width: this.width, height: this.height, palette: this.palette, frames: this.frames });
  }
}

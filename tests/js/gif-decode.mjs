// A small GIF decoder for the tests (written apart from www/ui/gif.js's encoder, from the GIF89a
// spec): header, logical screen, global palette, NETSCAPE2.0 loop, graphic-control delays and
// each frame's LZW-decoded palette indices.

/** Decode GIF bytes: {version, width, height, palette, loop, frames: [{delay, left, top, width, height, indices}]}. */
export function decodeGif(bytes) {
  const b = Uint8Array.from(bytes);
  let p = 0;
  const u8 = () => { if (p >= b.length) throw new Error('GIF cut off'); return b[p++]; };
  const u16 = () => u8() | (u8() << 8);
  const version = String.fromCharCode(...b.subarray(0, 6));
  if (!/^GIF8[79]a$/.test(version)) throw new Error(`not a GIF: ${version}`);
  p = 6;
  const width = u16(), height = u16(), packed = u8();
  u8(); u8();
  let palette = null;
  if (packed & 0x80) { const n = 3 << ((packed & 7) + 1); palette = b.slice(p, p + n); p += n; }
  const out = { version, width, height, palette, loop: null, frames: [] };
  let delay = null;
  const blocks = () => {
    const parts = [];
    for (let len = u8(); len; len = u8()) { parts.push(b.subarray(p, p + len)); p += len; }
    const all = new Uint8Array(parts.reduce((s, x) => s + x.length, 0));
    let at = 0;
    for (const x of parts) { all.set(x, at); at += x.length; }
    return all;
  };
  for (;;) {
    const t = u8();
    if (t === 0x3b) break;
    if (t === 0x21) {
      const label = u8();
      const data = blocks();
      if (label === 0xf9) delay = data[1] | (data[2] << 8);
      else if (label === 0xff && String.fromCharCode(...data.subarray(0, 11)) === 'NETSCAPE2.0') out.loop = data[12] | (data[13] << 8);
      continue;
    }
    if (t !== 0x2c) throw new Error(`unexpected block 0x${t.toString(16)} at ${p - 1}`);
    const left = u16(), top = u16(), w = u16(), h = u16(), ip = u8();
    if (ip & 0x80) p += 3 << ((ip & 7) + 1);
    const minCode = u8();
    const indices = lzwDecode(blocks(), minCode, w * h);
    out.frames.push({ delay, left, top, width: w, height: h, indices });
    delay = null;
  }
  return out;
}

function lzwDecode(data, minCode, count) {
  const clear = 1 << minCode, eoi = clear + 1;
  const out = new Uint8Array(count);
  let n = 0;
  let dict, width, prev;
  const reset = () => {
    dict = [];
    for (let i = 0; i < clear; i++) dict.push([i]);
    dict.push(null, null);
    width = minCode + 1;
    prev = null;
  };
  reset();
  let acc = 0, bits = 0, i = 0;
  for (;;) {
    while (bits < width && i < data.length) { acc |= data[i++] << bits; bits += 8; }
    if (bits < width) throw new Error('LZW data cut off');
    const code = acc & ((1 << width) - 1);
    acc >>>= width; bits -= width;
    if (code === clear) { reset(); continue; }
    if (code === eoi) break;
    let entry;
    if (code < dict.length && dict[code]) entry = dict[code];
    else if (code === dict.length && prev) entry = [...prev, prev[0]];
    else throw new Error(`bad LZW code ${code}`);
    for (const v of entry) { if (n >= count) throw new Error('too many pixels'); out[n++] = v; }
    if (prev && dict.length < 4096) {
      dict.push([...prev, entry[0]]);
      if (dict.length === 1 << width && width < 12) width++;
    }
    prev = entry;
  }
  if (n !== count) throw new Error(`${n} pixels decoded, ${count} expected`);
  return out;
}

// Precompressed copies of the page's largest files, written beside them: `f.br` (brotli, quality
// 11) and `f.gz` (gzip, level 9), so the server (scripts/serve.mjs) and any static host that
// serves precompressed files (nginx's gzip_static / brotli_static, Caddy's precompressed, …) send
// the wasm module as about a third of its size without compressing on every request. Node's own
// zlib: no dependency. scripts/build.mjs runs it after wasm-opt, scripts/dist.mjs on its copy.
import { readFileSync, writeFileSync, statSync, existsSync } from 'node:fs';
import { brotliCompressSync, gzipSync, constants } from 'node:zlib';

/** The files precompressed, relative to www/ (or to a copy of it). */
export const PRECOMPRESSED = ['pkg/planarium_bg.wasm', 'pkg/planarium.js'];

/** The encodings written, as a request's Accept-Encoding names them, and their suffixes. */
export const ENCODINGS = [['br', '.br'], ['gzip', '.gz']];

/** Brotli at its best, as the .br files are written (tests measure with the same). */
export function brotli(bytes) {
  return brotliCompressSync(bytes, {
    params: { [constants.BROTLI_PARAM_QUALITY]: 11, [constants.BROTLI_PARAM_SIZE_HINT]: bytes.length },
  });
}

/** Write `file.br` and `file.gz` beside `file`; returns their sizes {raw, br, gz}. */
export function precompress(file) {
  const bytes = readFileSync(file);
  const br = brotli(bytes);
  const gz = gzipSync(bytes, { level: 9 });
  writeFileSync(`${file}.br`, br);
  writeFileSync(`${file}.gz`, gz);
  return { raw: bytes.length, br: br.length, gz: gz.length };
}

/** Whether `file`'s precompressed copy `file + suffix` exists and is not older than it. */
export function fresh(file, suffix) {
  const copy = `${file}${suffix}`;
  return existsSync(copy) && statSync(copy).mtimeMs >= statSync(file).mtimeMs;
}

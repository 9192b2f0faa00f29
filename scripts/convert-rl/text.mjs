// Shared by the readers of scripts/convert-rl.mjs: the repository's root, the limits on what is read,
// reading a file, and errors naming a file, line and column.
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

export const MAX_FILE_BYTES = 1 << 20;
export const MAX_DEPTH = 64;

/** Degrees to radians, as the course and the scenario format write it. @param {number} deg */
export const rad = (deg) => deg * Math.PI / 180;

/** @param {string} file @param {number} line @param {number} col @param {string} message @returns {never} */
export function fail(file, line, col, message) {
  throw new Error(`${relative(root, file)}:${line}:${col}: ${message}`);
}

/** @param {string} file */
export function readText(file) {
  if (!existsSync(file)) throw new Error(`${relative(root, file)}: missing`);
  const text = readFileSync(file, 'utf8');
  if (text.length > MAX_FILE_BYTES) throw new Error(`${relative(root, file)}: over ${MAX_FILE_BYTES} bytes`);
  return text;
}

/** Line and column (1-based) of offset `at` in `text`. @param {string} text @param {number} at @returns {[number, number]} */
export function position(text, at) {
  let line = 1;
  let start = 0;
  for (let i = 0; i < at; i++) if (text.charCodeAt(i) === 10) { line++; start = i + 1; }
  return [line, at - start + 1];
}

// Text the page shows that came from a user (an error that echoes a file's key, a scenario's name
// and notes, a file's name, a link's value): shown as text (textContent, never HTML), and with its
// bidirectional controls written out, so an override such as U+202E cannot turn the rest of the
// line around (an error box that echoed one read backwards). One helper for every such place;
// share links' messages (cut) use it too.

/** Bidirectional controls: embeddings, overrides, isolates and marks (U+061C, U+200E–F, U+202A–E, U+2066–9). */
export const BIDI_CONTROLS = /[\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]/g;

/** `text` as the page shows it: each bidirectional control as "[U+202E]" (its code point). */
export function shown(text) {
  return String(text ?? '').replace(BIDI_CONTROLS, (c) => `[U+${c.charCodeAt(0).toString(16).toUpperCase().padStart(4, '0')}]`);
}

/** How much of a key or value a share link's problem echoes. */
export const ECHO_CHARS = 60;

/**
 * `text` as a message echoes it: bidirectional controls shown as [U+202E] (text.js shown: an
 * override in a link cannot turn the message around), cut to `n` characters (code points kept
 * whole) with an ellipsis when cut.
 */
export function cut(text, n = ECHO_CHARS) {
  const s = shown(text);
  if (s.length <= n) return s;
  let end = n - 1;
  if (/[\uD800-\uDBFF]/.test(s[end - 1])) end--; // never half a surrogate pair
  return `${s.slice(0, end)}…`;
}

// Text the page shows that came from a user (an error that echoes a file's key, a scenario's name
// and notes, a file's name, a link's value): shown as text (textContent, never HTML), and with its
// bidirectional controls written out, so an override such as U+202E cannot turn the rest of the
// line around (an error box that echoed one read backwards). One helper for every such place;
// share links' messages (links.js cut) use it too.

/** Bidirectional controls: embeddings, overrides, isolates and marks (U+061C, U+200E–F, U+202A–E, U+2066–9). */
export const BIDI_CONTROLS = /[\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]/g;

/** `text` as the page shows it: each bidirectional control as "[U+202E]" (its code point). */
export function shown(text) {
  return String(text ?? '').replace(BIDI_CONTROLS, (c) => `[U+${c.charCodeAt(0).toString(16).toUpperCase().padStart(4, '0')}]`);
}

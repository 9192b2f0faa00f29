// The 3-D path panel's ghost spacing (www/ui/path3d.js: the arm drawn see-through every so many rad
// along a solved path): its bounds and how a typed value or a share link's `ghosts=` is read.
// Apart from the panel so that the share link's reader (links.js) needs nothing of the DOM.

/** Ghost spacing, rad: the default, the bounds (0 turns them off) and the most ghosts drawn. */
export const GHOSTS = { initial: 2, min: 0.05, max: 10, most: 60 };

/**
 * A ghost spacing as typed: {value} (0: none) or {error}, naming the field and the bounds.
 * @param {string} text
 */
export function readSpacing(text) {
  const t = String(text ?? '').trim();
  const name = 'Ghost spacing';
  const bounds = `0 (no ghosts) or from ${GHOSTS.min} to ${GHOSTS.max} rad`;
  if (t === '') return { error: `${name}: type a number of rad, ${bounds}.` };
  const v = Number(t);
  if (!Number.isFinite(v)) return { error: `${name}: "${t.slice(0, 20)}" is not a number; ${bounds}.` };
  if (v < 0) return { error: `${name}: ${t.slice(0, 20)} is below 0; ${bounds}.` };
  if (v > GHOSTS.max) return { error: `${name}: ${t.slice(0, 20)} is above ${GHOSTS.max}; ${bounds}.` };
  if (v > 0 && v < GHOSTS.min) return { error: `${name}: ${t.slice(0, 20)} is below ${GHOSTS.min}; ${bounds}.` };
  return { value: v };
}

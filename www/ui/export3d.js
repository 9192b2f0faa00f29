// The 3-D view in the PNG and WebM exports (ui/exports.js): with a spatial arm's scene the picture
// is the top view and, beside it on the right at the same height, the 3-D view from the camera
// shown. The PNG's 3-D view is rendered at export time at the picture's height (the view's canvas
// is drawn once more at that size and put back, within one task, so the page never shows it); a
// WebM's frames take the 3-D view as it is drawn on the page, scaled to the video's height. SVG
// and GIF hold the top view only.

import { PALETTE } from '../draw/palette.js';

/** The gap between the two pictures, as a share of the height. */
const GAP = 0.01;

/**
 * The 3-D view (a View3dSlot) rendered `height` device pixels high (its on-screen aspect), as a
 * new canvas, or null when there is none. `live`: take the page's picture as drawn (scaled) rather
 * than rendering it again at that size.
 * @param {{active: boolean, view: any, canvas: HTMLCanvasElement} | null} slot
 * @param {number} height
 */
export function render3d(slot, height, live = false) {
  const view = slot?.active ? slot.view : null;
  if (!view || !view.matrices) return null;
  const c = slot.canvas;
  const [w0, h0] = [c.width, c.height];
  if (!(w0 > 0 && h0 > 0)) return null;
  const aspect = w0 / h0;
  const out = document.createElement('canvas');
  out.height = Math.max(1, Math.round(height));
  out.width = Math.max(1, Math.round(out.height * aspect));
  const ctx = out.getContext('2d');
  if (live) {
    ctx.drawImage(c, 0, 0, out.width, out.height);
    return out;
  }
  // drawn at the export's size (within what the GPU draws: larger is scaled up from its largest)
  const gl = view.gl;
  const [maxW, maxH] = gl.getParameter(gl.MAX_VIEWPORT_DIMS);
  const k = Math.min(1, maxW / out.width, maxH / out.height, 4096 / Math.max(out.width, out.height));
  try {
    c.width = Math.max(1, Math.floor(out.width * k));
    c.height = Math.max(1, Math.floor(out.height * k));
    view.render();
    ctx.drawImage(c, 0, 0, c.width, c.height, 0, 0, out.width, out.height);
  } finally {
    c.width = w0;
    c.height = h0;
    view.render();
  }
  return out;
}

/**
 * `picture` (the top view) with `side` (the 3-D view, as tall) beside it on the right, on the
 * page's background unless `transparent`. Returns a new canvas (the picture when there is no side).
 */
export function beside(picture, side, transparent = false) {
  if (!side) return picture;
  const gap = Math.round(picture.height * GAP);
  const out = document.createElement('canvas');
  out.width = picture.width + gap + side.width;
  out.height = Math.max(picture.height, side.height);
  const ctx = out.getContext('2d');
  if (!transparent) { ctx.fillStyle = PALETTE.background; ctx.fillRect(0, 0, out.width, out.height); }
  ctx.drawImage(picture, 0, 0);
  ctx.drawImage(side, picture.width + gap, 0);
  return out;
}

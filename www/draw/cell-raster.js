// Cells smaller than a few device pixels, painted as pixels (cells.js): grid search on a 998×998
// occupancy map has a million cells, and filling and stroking each as a path froze the page for
// seconds, again on every resize or overlay toggle. A small cell's outline would cover it anyway,
// so each pixel whose centre lies in a small cell takes the cell's fill colour (the cell a pixel's
// centre falls in, as a picture scaled down samples it), written into an ImageData the size of
// the layer; the pixels changed are put on an offscreen canvas and drawn onto the cells layer.

import { pointInPolygon } from './transform.js';

/** Device px: a cell narrower or lower than this on screen is painted as pixels, without outline. */
export const SMALL_CELL_PX = 4;

const colours = new Map();
/** A '#rrggbb' colour as an opaque pixel (RGBA bytes in memory order), or null for any other form. */
function pixelOf(css) {
  let v = colours.get(css);
  if (v === undefined) {
    const m = /^#([0-9a-f]{6})$/i.exec(css);
    if (m) {
      const n = parseInt(m[1], 16);
      const bytes = new Uint8Array([n >> 16, (n >> 8) & 255, n & 255, 255]);
      v = new Uint32Array(bytes.buffer)[0];
    } else v = null;
    colours.set(css, v);
  }
  return v;
}

/** Whether complete cell `c` (a CellMirror cell, with its `box`) is small at layout `L`. */
export function smallCell(c, L) {
  const b = c.box;
  return (b[2] - b[0]) * L.scale < SMALL_CELL_PX && (b[3] - b[1]) * L.scale < SMALL_CELL_PX;
}

/** The small cells' pixels of one cells layer. */
export class CellRaster {
  constructor() {
    this.width = 0;
    this.height = 0;
    this.pixels = null; // Uint32Array over `image`, allocated at the first small cell
    this.image = null;
    this.canvas = null;
    this.dirty = null;  // [x0, y0, x1, y1) of pixels changed since the last flush
    this.blank = true;  // no pixel set since the last clear
    this.fill = null;   // the last colour painted, and its pixel
    this.px = null;
  }

  /** Forget every pixel; the layer is `L.width` × `L.height` from now on. */
  clear(L = null) {
    if (L && (L.width !== this.width || L.height !== this.height)) {
      this.width = L.width;
      this.height = L.height;
      this.pixels = null;
      this.image = null;
      this.canvas = null;
    }
    if (this.pixels && !this.blank) this.pixels.fill(0);
    this.blank = true;
    this.dirty = null;
  }

  /**
   * Paint cell `c` in `fill` ('#rrggbb'): every pixel whose centre lies in it. False (nothing
   * done) when the colour is not an opaque '#rrggbb', so the caller draws the cell as a path.
   */
  paint(c, L, fill) {
    if (c.rect) return this.paintBox(c.box[0], c.box[1], c.box[2], c.box[3], fill, L);
    if (fill !== this.fill) { this.fill = fill; this.px = pixelOf(fill); }
    const px = this.px;
    if (px === null) return false;
    if (L.width !== this.width || L.height !== this.height) this.clear(L);
    const W = this.width, H = this.height;
    const b = c.box, s = L.scale;
    // pixels i whose centre i + 0.5 lies in [sx(x0), sx(x1)), rows likewise from the top
    const i0 = Math.max(0, Math.ceil(L.ox + b[0] * s - 0.5)), i1 = Math.min(W, Math.ceil(L.ox + b[2] * s - 0.5));
    const j0 = Math.max(0, Math.ceil(L.oy - b[3] * s - 0.5)), j1 = Math.min(H, Math.ceil(L.oy - b[1] * s - 0.5));
    if (i0 >= i1 || j0 >= j1) return true;
    if (!this.pixels) {
      this.image = new ImageData(W, H);
      this.pixels = new Uint32Array(this.image.data.buffer);
    }
    const p = this.pixels;
    for (let j = j0; j < j1; j++) {
      for (let i = i0; i < i1; i++) {
        if (c.rect || pointInPolygon(L.wx(i + 0.5), L.wy(j + 0.5), c.pts)) p[j * W + i] = px;
      }
    }
    this.touched(i0, j0, i1, j1);
    return true;
  }

  /**
   * Paint the axis-aligned rectangle [x0, y0, x1, y1] (world) in `fill`: every pixel whose centre
   * lies in it. False when the colour is not an opaque '#rrggbb'.
   */
  paintBox(x0, y0, x1, y1, fill, L) {
    if (fill !== this.fill) { this.fill = fill; this.px = pixelOf(fill); }
    const px = this.px;
    if (px === null) return false;
    if (L.width !== this.width || L.height !== this.height) this.clear(L);
    const W = this.width, s = L.scale;
    const i0 = Math.max(0, Math.ceil(L.ox + x0 * s - 0.5)), i1 = Math.min(W, Math.ceil(L.ox + x1 * s - 0.5));
    const j0 = Math.max(0, Math.ceil(L.oy - y1 * s - 0.5)), j1 = Math.min(this.height, Math.ceil(L.oy - y0 * s - 0.5));
    if (i0 >= i1 || j0 >= j1) return true;
    if (!this.pixels) {
      this.image = new ImageData(W, this.height);
      this.pixels = new Uint32Array(this.image.data.buffer);
    }
    const p = this.pixels;
    for (let j = j0; j < j1; j++) p.fill(px, j * W + i0, j * W + i1);
    this.touched(i0, j0, i1, j1);
    return true;
  }

  /** Pixels [i0, i1) × [j0, j1) were painted: the image is not blank, and they join the dirty box. */
  touched(i0, j0, i1, j1) {
    this.blank = false;
    const d = this.dirty;
    if (!d) this.dirty = [i0, j0, i1, j1];
    else {
      if (i0 < d[0]) d[0] = i0;
      if (j0 < d[1]) d[1] = j0;
      if (i1 > d[2]) d[2] = i1;
      if (j1 > d[3]) d[3] = j1;
    }
  }

  /** Draw the pixels changed since the last flush onto `ctx` (the cells layer). */
  flush(ctx) {
    const d = this.dirty;
    if (!d) return;
    this.dirty = null;
    if (!this.canvas) {
      this.canvas = document.createElement('canvas');
      this.canvas.width = this.width;
      this.canvas.height = this.height;
    }
    const [x0, y0, x1, y1] = d;
    this.canvas.getContext('2d').putImageData(this.image, 0, 0, x0, y0, x1 - x0, y1 - y0);
    ctx.drawImage(this.canvas, x0, y0, x1 - x0, y1 - y0, x0, y0, x1 - x0, y1 - y0);
  }
}

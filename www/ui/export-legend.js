// What the exports (exports.js, export-svg.js) share: the legend's layout and font, and which
// animation frame a view shows.

export const LEGEND_FONT = '12px system-ui, sans-serif';
export const LEGEND_TEXT = '#30343b';

/** The animation frame list `view` plays and the index of the one it last showed (or -1). */
export function frameShown(view) {
  const list = view.options.animateRaw && view.rawFrames.length ? view.rawFrames : view.frames;
  if (!view.showResult || !list.length) return -1;
  return list.findIndex((f) => f.state === view.robotState);
}

// ---------------------------------------------------------------------------------------------
// The legend: rows of a mark and a label, laid out in css px (scaled with the picture)

/**
 * Where each legend item goes in a band `width` css px wide: {height, at: [{x, y, item}]}
 * (x, y: the mark's left and the row's middle). `measure(text)` is the label's width in css px.
 */
export function legendLayout(items, width, measure) {
  const pad = 8, row = 20, mark = 16, gap = 6, sep = 16;
  const at = [];
  let x = pad, y = pad + row / 2;
  for (const item of items) {
    const w = mark + gap + measure(item.label);
    if (x > pad && x + w > width - pad) { x = pad; y += row; }
    at.push({ x, y, item });
    x += w + sep;
  }
  return { height: items.length ? y + row / 2 + pad : 0, at };
}

let measureCtx = null;
export function measure(text) {
  measureCtx ??= document.createElement('canvas').getContext('2d');
  measureCtx.font = LEGEND_FONT;
  return measureCtx.measureText(text).width;
}

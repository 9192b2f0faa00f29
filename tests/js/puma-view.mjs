// Shared by the 3-D page tests: report 001's Puma scenario with a copy of the core on it (in
// Node, to say where the core's forward kinematics puts the arm), and the 3-D view's pixels read
// through the page's test hooks (`window.planarium.view3d`).

import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { ROOT } from './browser.mjs';
import { initSync, Scene, builtins } from '../../www/pkg/planarium.js';

initSync({ module: readFileSync(join(ROOT, 'www/pkg/planarium_bg.wasm')) });
/** The built-in `puma-rbo-wall`'s scenario. */
export const puma = JSON.parse(builtins()).find((b) => b.id === 'puma-rbo-wall').scenario;
/** The core's Scene on it (skeleton, link frames, collisions). */
export const core = new Scene(JSON.stringify(puma));
/** Its name in the scenario picker. */
export const PUMA_NAME = "Puma 560 through a window (report 001's course)";

/** `#rrggbb` as [r, g, b]. */
export const rgbOf = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));

/** Whether pixel [r, g, b] is a shade (k·colour, lit by the head light) of colour `hex`. */
export function shadeOf([r, g, b], hex) {
  const [R, G, B] = rgbOf(hex);
  const k = (r + g + b) / (R + G + B);
  return k > 0.2 && k < 1.05 && [r - k * R, g - k * G, b - k * B].every((d) => Math.abs(d) <= 4);
}

/**
 * The pixels of the 3-D view within `r` css px of world point `p`: {at (css px), out: [[r, g, b], …]},
 * or null when the point is behind the camera.
 */
export function pixelsNear(page, p, r) {
  return page.evaluate(({ p, r }) => {
    const v = window.planarium.view3d;
    const at = v.toCanvas(p);
    if (!at) return null;
    const px = v.pixels(at[0], at[1], r);
    const out = [];
    for (let i = 0; i < px.length; i += 4) out.push([px[i], px[i + 1], px[i + 2]]);
    return { at, out };
  }, { p, r });
}

// The overlay box: one checkbox per switchable overlay of palette.js's OVERLAYS, each with its legend
// marks, so the box is also the legend of what it switches. The boxes are built once per page and
// never rebuilt, so their state stays when the scenario or the planner changes.

import { el } from '../ui/dom.js';
import { OVERLAYS } from './palette.js';
import { plannerCaps } from './capabilities.js';

/** A legend mark (styled by .swatch in style.css, coloured by --c). */
export function swatch({ color, shape }) {
  const sw = el('span', { className: `swatch ${shape}` });
  sw.style.setProperty('--c', color);
  sw.setAttribute('aria-hidden', 'true');
  return sw;
}

/**
 * Build the overlay checkboxes into `root` (ids `${prefix}show-…`); `onChange(options)` gets the
 * view options {showAccepted, ...} after every change. Returns options(): the current options.
 */
export function createOverlays(root, onChange, { prefix = '' } = {}) {
  const boxes = OVERLAYS.map((o) => {
    const input = el('input', { id: `${prefix}${o.id}`, type: 'checkbox', checked: o.on });
    const label = el('label', { className: 'overlay', htmlFor: input.id, title: o.doc || '' },
      input, el('span', { className: 'marks' }, ...o.swatches.map(swatch)), el('span', { text: o.label }));
    label.dataset.option = o.option;
    return { o, input, label };
  });
  root.replaceChildren(...boxes.map((b) => b.label));
  const options = () => Object.fromEntries(boxes.map(({ o, input }) => [o.option, input.checked]));
  for (const { input } of boxes) input.addEventListener('change', () => { input.dataset.touched = '1'; onChange(options()); });
  /**
   * Show only the overlays that apply to `context` (see overlayApplies); returns how many are hidden.
   * A box nobody set (no click, no link: `dataset.touched`) takes the planner's default: a planner
   * that draws a field shows its heat map from the start.
   */
  options.fit = (context) => {
    let hidden = 0;
    const field = !!context?.config?.planner && plannerCaps(context.config.planner).draws === 'field';
    for (const { o, label, input } of boxes) {
      label.hidden = !overlayApplies(o.option, context);
      if (label.hidden) hidden++;
      if (o.option === 'showHeat' && !input.dataset.touched) input.checked = o.on || field;
    }
    return hidden;
  };
  return options;
}

const CHECKING_SAMPLERS = new Set(['gaussian', 'bridge', 'obstacle']);

/** The overlays a planner offers by its registry's `caps.overlays` keys (the rest follow its sampler). */
export const OFFERED = Object.freeze({
  showRewires: 'rewires', showBest: 'best', showSeen: 'seen', showFov: 'fov', showCells: 'cells',
  showRegion: 'region', showDensity: 'density', showHeat: 'heat', showArrows: 'arrows', showInformed: 'informed',
});

/**
 * Whether overlay `option` can show anything for `context` = {config: {planner, params}, robot,
 * inspection}, by the planner's capabilities (capabilities.js): sampling overlays for a planner that
 * takes the sampler, the tree variants' when they are on, the overlays its registry entry offers
 * (cells and fields for the workspace planners), the sensor's for an inspection scenario too.
 * Unknown: shown.
 */
/** @param {string} option @param {{config?: {planner: string, params?: Record<string, any>}, robot?: string, inspection?: boolean}} [context] */
export function overlayApplies(option, { config, inspection = false } = {}) {
  const planner = config?.planner;
  if (!planner) return true;
  const p = config.params || {};
  const caps = plannerCaps(planner);
  const sampling = caps.samples;
  switch (option) {
    case 'showAccepted': case 'showRejected': case 'showCollisions': return sampling;
    case 'showTries': return sampling && CHECKING_SAMPLERS.has(p.sampler);
    case 'showDomains': return sampling && Number(p.dd_radius) > 0;
    case 'showExhausted': return sampling && Number(p.exhausted) > 0;
    case 'showSeen': case 'showFov': return inspection || caps.overlays.includes(OFFERED[option]);
    default: return option in OFFERED ? caps.overlays.includes(OFFERED[option]) : true;
  }
}

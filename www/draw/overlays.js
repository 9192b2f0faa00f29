// The overlay box: one checkbox per switchable overlay of palette.js's OVERLAYS, each with its legend
// marks, so the box is also the legend of what it switches. The boxes are built once per page and
// never rebuilt, so their state stays when the scenario or the planner changes.

import { el } from '../ui/dom.js';
import { OVERLAYS } from './palette.js';

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
  for (const { input } of boxes) input.addEventListener('change', () => onChange(options()));
  /** Show only the overlays that apply to `context` (see overlayApplies); returns how many are hidden. */
  options.fit = (context) => {
    let hidden = 0;
    for (const { o, label } of boxes) {
      label.hidden = !overlayApplies(o.option, context);
      if (label.hidden) hidden++;
    }
    return hidden;
  };
  return options;
}

const SAMPLING = new Set(['rrt', 'rrt-connect', 'rrt-star', 'inspection', 'prm', 'prm-star', 'lazy-prm']);
const CHECKING_SAMPLERS = new Set(['gaussian', 'bridge', 'obstacle']);

/**
 * Whether overlay `option` can show anything for `context` = {config: {planner, params}, robot,
 * inspection}: sampling overlays for the sampling planners, the tree variants' when they are on,
 * cells and fields for the workspace planners, the sensor's for inspection. Unknown: shown.
 */
/** @param {string} option @param {{config?: {planner: string, params?: Record<string, any>}, robot?: string, inspection?: boolean}} [context] */
export function overlayApplies(option, { config, inspection = false } = {}) {
  const planner = config?.planner;
  if (!planner) return true;
  const p = config.params || {};
  const sampling = SAMPLING.has(planner);
  switch (option) {
    case 'showAccepted': case 'showRejected': case 'showCollisions': return sampling;
    case 'showTries': return sampling && CHECKING_SAMPLERS.has(p.sampler);
    case 'showDomains': return sampling && Number(p.dd_radius) > 0;
    case 'showExhausted': return sampling && Number(p.exhausted) > 0;
    case 'showRewires': case 'showBest': return planner === 'rrt-star' || planner === 'inspection';
    case 'showSeen': case 'showFov': return inspection || planner === 'inspection';
    case 'showCells': return planner === 'hex-potential' || planner === 'grid-search';
    case 'showRegion': return planner === 'hex-potential';
    case 'showDensity': return planner === 'est' || planner === 'bi-est';
    case 'showHeat': case 'showArrows': return planner === 'hex-potential' || planner === 'potential-field';
    default: return true;
  }
}

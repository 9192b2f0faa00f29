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
  return options;
}

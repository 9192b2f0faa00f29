// The Share box's "Copy embed code": an <iframe src="…embed.html#…"> for course notes and slides,
// with the state shown (the share link's hash) and the embed's own keys: the controls chosen,
// autoplay, and the frame's width × height in pixels (bounded; an error names the field). "Copy
// element code" gives the same state as a <script type="module"> and a <planarium-playground>
// element (the link's keys as its attributes, the planner's parameters in `params`), for a page on
// the same site. Built with DOM methods into the element `root`; the code is text in a read-only
// textarea (and the clipboard), never HTML put into the page; attribute values are escaped.

import { CONTROLS, DEFAULT_CONTROLS, MAX_LINK_CHARS, RESERVED, parsePairs } from './links.js';

/** @type {{readonly width: readonly number[], readonly height: readonly number[]}} */
export const EMBED_LIMITS = Object.freeze({ width: Object.freeze([200, 2000]), height: Object.freeze([150, 2000]) });
const LABELS = { run: 'Run', pause: 'Pause', step: 'Step', back: 'Step back', reset: 'Reset', speed: 'Speed', seed: 'Seed' };

/** `s` safe inside a double-quoted HTML attribute. */
const attr = (s) => String(s).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

/**
 * A size field's value: {value} a whole number of pixels within its bounds, or {why} naming the field.
 * @param {string} name the field's label ("Width")
 * @param {string} text what it holds
 * @param {readonly number[]} bounds [min, max]
 */
export function readSize(name, text, [min, max]) {
  const t = String(text).trim();
  const n = /^\d{1,6}$/.test(t) ? Number(t) : NaN;
  if (!Number.isInteger(n) || n < min || n > max) {
    const shown = t.length > 20 ? `${t.slice(0, 20)}…` : t;
    return { why: `${name}: "${shown}" is not a whole number of pixels from ${min} to ${max}.` };
  }
  return { value: n };
}

/**
 * The embed code for `link` (the playground's full link, "https://…/index.html#hash"): an iframe
 * on embed.html next to it with `controls` (names from links.js CONTROLS), `autoplay`, `width`, `height`.
 * @param {{link: string, controls: string[], autoplay: boolean, width: number, height: number, title?: string}} o
 */
export function embedCode({ link, controls, autoplay, width, height, title = 'Planarium' }) {
  const at = link.indexOf('#');
  const page = at < 0 ? link : link.slice(0, at);
  const hash = at < 0 ? '' : link.slice(at + 1);
  const base = page.slice(0, page.lastIndexOf('/') + 1);
  const keys = [hash];
  if (autoplay) keys.push('autoplay');
  const same = controls.length === DEFAULT_CONTROLS.length && controls.every((c, i) => c === DEFAULT_CONTROLS[i]);
  if (!same) keys.push(`controls=${controls.join(',')}`);
  const src = `${base}embed.html#${keys.filter(Boolean).join('&')}`;
  const code = `<iframe src="${attr(src)}" title="${attr(title)}" width="${width}" height="${height}" style="border: 0" loading="lazy"></iframe>`;
  return { src, code };
}

/**
 * The element code for `link` (as embedCode): the module next to the playground and one
 * <planarium-playground> whose attributes are the link's keys (a flag as a bare attribute), the
 * planner's parameters in `params` (link form), then `autoplay` and `controls` (when not the default).
 * @param {{link: string, controls: string[], autoplay: boolean}} o
 */
export function elementCode({ link, controls, autoplay }) {
  const at = link.indexOf('#');
  const page = at < 0 ? link : link.slice(0, at);
  const base = page.slice(0, page.lastIndexOf('/') + 1);
  const attrs = [];
  const params = [];
  for (const [key, value] of parsePairs(at < 0 ? '' : link.slice(at + 1))) {
    if (key === 'autoplay' || key === 'controls' || key === 'click') continue; // the options below say these
    if (RESERVED.includes(key)) attrs.push(value === null ? key : `${key}="${attr(value)}"`);
    else params.push(value === null ? encodeURIComponent(key) : `${encodeURIComponent(key)}=${encodeURIComponent(value)}`);
  }
  if (params.length) attrs.push(`params="${attr(params.join('&'))}"`);
  if (autoplay) attrs.push('autoplay');
  const same = controls.length === DEFAULT_CONTROLS.length && controls.every((c, i) => c === DEFAULT_CONTROLS[i]);
  if (!same) attrs.push(`controls="${attr(controls.join(','))}"`);
  const script = `${base}planarium-playground.js`;
  const code = `<script type="module" src="${attr(script)}"></script>\n`
    + `<planarium-playground${attrs.map((a) => ` ${a}`).join('')}></planarium-playground>`;
  return { script, code };
}

/**
 * Wire the options and the button into `root`. `link()`: a promise of the playground's full link to
 * the state shown; `title()`: the scenario's name.
 * @param {{root: HTMLElement, link: () => Promise<string>, title: () => string}} options
 */
export function wireEmbedCode({ root, link, title }) {
  const el = (tag, props = {}) => Object.assign(document.createElement(tag), props);
  const heading = el('p', { className: 'hint', textContent: 'Embed in course notes or slides: an iframe on embed.html with this state, '
    + 'or the <planarium-playground> element for a page on the same site as Planarium (it takes the width of its column).' });
  const boxes = el('div', { className: 'row embed-controls' });
  boxes.setAttribute('role', 'group');
  boxes.setAttribute('aria-label', 'Controls shown in the embed');
  const checks = {};
  for (const name of CONTROLS) {
    const box = el('input', { type: 'checkbox', checked: DEFAULT_CONTROLS.includes(name) });
    box.dataset.control = name;
    checks[name] = box;
    const label = el('label', { title: `Show ${LABELS[name]} in the embed` });
    label.append(box, ` ${LABELS[name]}`);
    boxes.append(label);
  }
  const autoplay = el('input', { type: 'checkbox', id: 'embed-autoplay', checked: true });
  const autoLabel = el('label', { title: 'Run when at least half the embed is on screen' });
  autoLabel.append(autoplay, ' Autoplay');
  /** @param {string} id @param {string} text @param {number} value @param {readonly number[]} bounds */
  const size = (id, text, value, [min, max]) => {
    const input = el('input', { type: 'number', id, min: String(min), max: String(max), step: '10', value: String(value) });
    const label = el('label', { className: 'field', title: `${text} of the frame in pixels, ${min} to ${max}` });
    label.append(el('span', { textContent: text }), input);
    return { input, label };
  };
  const w = size('embed-width', 'Width', 480, EMBED_LIMITS.width);
  const h = size('embed-height', 'Height', 520, EMBED_LIMITS.height);
  const button = el('button', { type: 'button', id: 'copy-embed', textContent: 'Copy embed code',
    title: 'Copy an <iframe> that shows this state in course notes or slides, with the options above' });
  const elementButton = el('button', { type: 'button', id: 'copy-element', textContent: 'Copy element code',
    title: 'Copy a <script> and a <planarium-playground> element that show this state, with the controls and autoplay above, '
      + 'for a page on the same site as Planarium (its worker comes from there); the size fields are the iframe\'s' });
  const row = el('div', { className: 'row' });
  row.append(autoLabel, w.label, h.label, button, elementButton);
  const status = el('p', { className: 'hint', id: 'embed-status' });
  status.setAttribute('role', 'status');
  const code = el('textarea', { id: 'embed-code', className: 'share-url', readOnly: true, rows: 3, spellcheck: false });
  code.setAttribute('aria-label', 'Embed code');
  root.append(heading, boxes, row, status, code);

  /** Write the iframe (`element` false) or the element code into the box and the clipboard. */
  const copy = async (element) => {
    status.textContent = '';
    const what = element ? 'element code' : 'embed code';
    const ws = readSize('Width', w.input.value, EMBED_LIMITS.width);
    const hs = readSize('Height', h.input.value, EMBED_LIMITS.height);
    const why = element ? [] : [ws.why, hs.why].filter(Boolean); // the element takes its column's width
    if (why.length) { code.value = ''; status.textContent = `No ${what}: ${why.join(' ')}`; return; }
    const href = await link();
    const controls = CONTROLS.filter((c) => checks[c].checked);
    // the iframe's address bounds both: the element carries the same state
    const made = embedCode({ link: href, controls, autoplay: autoplay.checked, width: ws.value ?? 0, height: hs.value ?? 0, title: title() });
    if (!href.includes('#') || made.src.length > MAX_LINK_CHARS) {
      code.value = '';
      status.textContent = `No ${what}: the embed's address would be ${made.src.length.toLocaleString('en')} characters long, more than the `
        + `${MAX_LINK_CHARS.toLocaleString('en')} a page can carry. Save the scenario as a JSON file instead.`;
      return;
    }
    const text = element ? elementCode({ link: href, controls, autoplay: autoplay.checked }).code : made.code;
    code.value = text;
    try {
      await navigator.clipboard.writeText(text);
      status.textContent = element ? 'Copied the element code.' : 'Copied.';
    } catch {
      code.select();
      status.textContent = 'Copy the selected code (the clipboard is not available here).';
    }
  };
  button.addEventListener('click', () => copy(false));
  elementButton.addEventListener('click', () => copy(true));
}

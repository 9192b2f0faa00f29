// XML as rl's rlkin and rlplan files write it (scripts/convert-rl.mjs): elements, attributes and
// text; no DTD, no CDATA. Every error names the file, line and column.
import { relative } from 'node:path';
import { fail, MAX_DEPTH, position, rad, readText, root } from './text.mjs';

/**
 * @typedef {object} XmlElement
 * @property {string} name
 * @property {Record<string, string>} attrs
 * @property {XmlElement[]} children
 * @property {string} text
 * @property {number} at  offset of its `<` in the file
 */

/** @type {Record<string, string>} */
const ENTITIES = { lt: '<', gt: '>', amp: '&', quot: '"', apos: "'" };

/** @param {string} file @returns {{root: XmlElement, where: (at: number) => string, file: string, text: string}} */
export function parseXml(file) {
  const text = readText(file);
  /** @param {number} at @param {string} message @returns {never} */
  const err = (at, message) => fail(file, ...position(text, at), message);
  const decode = (/** @type {string} */ s, /** @type {number} */ at) => s.replace(/&(\w+);/g, (m, name) => {
    if (!(name in ENTITIES)) err(at, `unknown entity &${name};`);
    return ENTITIES[name];
  });
  /** @type {XmlElement} */
  const top = { name: '', attrs: {}, children: [], text: '', at: 0 };
  const stack = [top];
  let i = 0;
  while (i < text.length) {
    const lt = text.indexOf('<', i);
    const chunk = text.slice(i, lt < 0 ? text.length : lt);
    if (chunk.trim()) {
      if (stack.length === 1) err(i, 'text outside the root element');
      stack[stack.length - 1].text += decode(chunk, i);
    }
    if (lt < 0) break;
    if (text.startsWith('<?', lt) || text.startsWith('<!--', lt) || text.startsWith('<!', lt)) {
      const close = text.startsWith('<?', lt) ? '?>' : text.startsWith('<!--', lt) ? '-->' : '>';
      const end = text.indexOf(close, lt + 2);
      if (end < 0) err(lt, 'unclosed declaration or comment');
      i = end + close.length;
      continue;
    }
    const gt = text.indexOf('>', lt);
    if (gt < 0) err(lt, 'unclosed tag');
    const tag = text.slice(lt + 1, gt);
    if (tag.startsWith('/')) {
      const name = tag.slice(1).trim();
      const open = stack[stack.length - 1];
      if (stack.length === 1) err(lt, `</${name}> closes nothing`);
      if (open.name !== name) err(lt, `</${name}> does not close <${open.name}>`);
      stack.pop();
    } else {
      const selfClosing = tag.endsWith('/');
      const body = selfClosing ? tag.slice(0, -1) : tag;
      const m = /^([A-Za-z_][\w:.-]*)/.exec(body);
      if (!m) err(lt, 'a tag without a name');
      /** @type {Record<string, string>} */
      const attrs = {};
      const rest = body.slice(m[1].length);
      const attr = /\s+([A-Za-z_][\w:.-]*)\s*=\s*"([^"<]*)"/y;
      let k = 0;
      for (;;) {
        attr.lastIndex = k;
        const a = attr.exec(rest);
        if (!a) break;
        attrs[a[1]] = decode(a[2], lt);
        k = attr.lastIndex;
      }
      if (rest.slice(k).trim()) err(lt, `cannot read the attributes of <${m[1]}>`);
      if (stack.length === 1 && top.children.length) err(lt, 'a second root element');
      if (stack.length > MAX_DEPTH) err(lt, `nested deeper than ${MAX_DEPTH}`);
      /** @type {XmlElement} */
      const el = { name: m[1], attrs, children: [], text: '', at: lt };
      stack[stack.length - 1].children.push(el);
      if (!selfClosing) stack.push(el);
    }
    i = gt + 1;
  }
  if (stack.length !== 1) err(stack[stack.length - 1].at, `<${stack[stack.length - 1].name}> is never closed`);
  if (top.children.length !== 1) err(0, 'no root element');
  return { root: top.children[0], where: (at) => `${relative(root, file)}:${position(text, at).join(':')}`, file, text };
}

/** @typedef {ReturnType<typeof parseXml>} XmlDoc */

/** The children of `el` named `name`. @param {XmlElement} el @param {string} name */
export const all = (el, name) => el.children.filter((c) => c.name === name);

/** The one child of `el` named `name`. @param {XmlDoc} doc @param {XmlElement} el @param {string} name */
export function one(doc, el, name) {
  const found = all(el, name);
  if (found.length !== 1) throw new Error(`${doc.where(el.at)}: <${el.name}> has ${found.length} <${name}>, expected one`);
  return found[0];
}

/** The element's text as a finite number. @param {XmlDoc} doc @param {XmlElement} el */
export function num(doc, el) {
  const t = el.text.trim();
  const v = Number(t);
  if (!t || !Number.isFinite(v)) throw new Error(`${doc.where(el.at)}: <${el.name}> is not a number: ${JSON.stringify(t.slice(0, 40))}`);
  return v;
}

/** The element's text as an angle in radians, from its `unit` attribute (rl's default for these: degrees). */
export function angle(/** @type {XmlDoc} */ doc, /** @type {XmlElement} */ el) {
  const unit = el.attrs.unit ?? 'deg';
  if (unit === 'deg') return rad(num(doc, el));
  if (unit === 'rad') return num(doc, el);
  throw new Error(`${doc.where(el.at)}: <${el.name}> has unit ${JSON.stringify(unit)} (deg or rad)`);
}

/** x, y, z children as numbers. @param {XmlDoc} doc @param {XmlElement} el */
export const xyz = (doc, el) => ['x', 'y', 'z'].map((c) => num(doc, one(doc, el, c)));

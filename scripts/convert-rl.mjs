// Writes the built-in scenarios made from the Robotics Library's Puma 560 (data/rl-puma560/, BSD
// 2-Clause, data/rl-puma560/SOURCE.md says where it comes from):
//   scenarios/puma-rbo-wall.json  the course of report 001: the arm with the course's tool threaded
//                                 through a 16 cm window in a wall (the tool and the wall are the
//                                 course's numbers, below; they are not in rl's files);
//   scenarios/puma-boxes.json     rl's own example: the arm in a room with three cubes.
//
//   node scripts/convert-rl.mjs                 write both files
//   node scripts/convert-rl.mjs --check         exit 1 when the committed files are not what it writes
//   node scripts/convert-rl.mjs --out DIR       write to (or with --check, compare with) DIR instead
//
// Read from rl's files:
// - rlkin/unimation-puma560.xml: the revolute joints in classic Denavit–Hartenberg form (d, theta, a,
//   alpha; metres and degrees), their limits (degrees), the link pairs never tested against each
//   other (`<ignore idref>` on a link) and the links never tested against the scene (`<ignore/>`);
// - rlsg/unimation-puma560.convex/linkN.wrl: each link's convex hull, the `point` list of a VRML 2.0
//   IndexedFaceSet, put through the Transforms around it in that file (rotation, translation, scale,
//   center, scaleOrientation) so that the points are in the link's own frame;
// - rlsg/boxes.wrl: each Box shape (its Transforms' translation and scale; no rotation) as an
//   axis-aligned box named by the DEF around it;
// - rlplan/unimation-puma560_boxes_rrtConCon.xml: start and goal, the world rotation of the arm's
//   base, the connect step `delta`, `epsilon` and the time limit (`duration`).
// Degrees become radians as `deg * Math.PI / 180`; every number is written as JSON.stringify writes
// the double (shortest text that reads back to the same double). Anything the converter does not
// understand is an error naming the file, line and column: a new rl file is never half-read.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
export const DATA_DIR = join(root, 'data', 'rl-puma560');
export const SCENARIOS_DIR = join(root, 'scenarios');

const MAX_FILE_BYTES = 1 << 20;
const MAX_DEPTH = 64;
const MAX_TOKENS = 200000;
const MAX_HULL_POINTS = 1024;

/** @param {number} deg */
const rad = (deg) => deg * Math.PI / 180;

/** @param {string} file @param {number} line @param {number} col @param {string} message @returns {never} */
function fail(file, line, col, message) {
  throw new Error(`${relative(root, file)}:${line}:${col}: ${message}`);
}

/** @param {string} file */
function readText(file) {
  if (!existsSync(file)) throw new Error(`${relative(root, file)}: missing`);
  const text = readFileSync(file, 'utf8');
  if (text.length > MAX_FILE_BYTES) throw new Error(`${relative(root, file)}: over ${MAX_FILE_BYTES} bytes`);
  return text;
}

/** Line and column (1-based) of offset `at` in `text`. @param {string} text @param {number} at @returns {[number, number]} */
function position(text, at) {
  let line = 1;
  let start = 0;
  for (let i = 0; i < at; i++) if (text.charCodeAt(i) === 10) { line++; start = i + 1; }
  return [line, at - start + 1];
}

// ---------------------------------------------------------------------------------------------
// XML (rl's rlkin and rlplan files): elements, attributes and text; no DTD, no CDATA.

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
function parseXml(file) {
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
const all = (el, name) => el.children.filter((c) => c.name === name);

/** The one child of `el` named `name`. @param {XmlDoc} doc @param {XmlElement} el @param {string} name */
function one(doc, el, name) {
  const found = all(el, name);
  if (found.length !== 1) throw new Error(`${doc.where(el.at)}: <${el.name}> has ${found.length} <${name}>, expected one`);
  return found[0];
}

/** The element's text as a finite number. @param {XmlDoc} doc @param {XmlElement} el */
function num(doc, el) {
  const t = el.text.trim();
  const v = Number(t);
  if (!t || !Number.isFinite(v)) throw new Error(`${doc.where(el.at)}: <${el.name}> is not a number: ${JSON.stringify(t.slice(0, 40))}`);
  return v;
}

/** The element's text as an angle in radians, from its `unit` attribute (rl's default for these: degrees). */
function angle(/** @type {XmlDoc} */ doc, /** @type {XmlElement} */ el) {
  const unit = el.attrs.unit ?? 'deg';
  if (unit === 'deg') return rad(num(doc, el));
  if (unit === 'rad') return num(doc, el);
  throw new Error(`${doc.where(el.at)}: <${el.name}> has unit ${JSON.stringify(unit)} (deg or rad)`);
}

/** x, y, z children as numbers. @param {XmlDoc} doc @param {XmlElement} el */
const xyz = (doc, el) => ['x', 'y', 'z'].map((c) => num(doc, one(doc, el, c)));

// ---------------------------------------------------------------------------------------------
// VRML 2.0 (rl's rlsg files): nodes, fields and their values; PROTO, ROUTE and USE are not read.

/**
 * @typedef {object} VrmlNode
 * @property {string} type
 * @property {string | null} def
 * @property {Map<string, Array<number | string | boolean | VrmlNode>>} fields
 * @property {number} at
 */

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$|^0[xX][0-9a-fA-F]+$/;

/** @param {string} file @returns {{nodes: VrmlNode[], where: (at: number) => string}} */
function parseVrml(file) {
  const text = readText(file);
  if (!text.startsWith('#VRML V2.0 utf8')) fail(file, 1, 1, 'not a VRML 2.0 file (#VRML V2.0 utf8)');
  /** @type {{t: string, at: number, str?: boolean}[]} */
  const tokens = [];
  const lexer = /[\s,]+|#[^\n\r]*|([{}[\]])|"((?:[^"\\]|\\.)*)"|([^\s,{}[\]"#]+)/gy;
  while (lexer.lastIndex < text.length) {
    const at = lexer.lastIndex;
    const m = lexer.exec(text);
    if (!m) fail(file, ...position(text, at), 'cannot read this');
    if (m[1]) tokens.push({ t: m[1], at });
    else if (m[2] !== undefined) tokens.push({ t: m[2].replace(/\\(.)/g, '$1'), at, str: true });
    else if (m[3]) tokens.push({ t: m[3], at });
    if (tokens.length > MAX_TOKENS) fail(file, ...position(text, at), `over ${MAX_TOKENS} tokens`);
  }
  let i = 0;
  /** @param {number} at @param {string} message @returns {never} */
  const err = (at, message) => fail(file, ...position(text, at), message);
  const peek = () => tokens[i];
  const take = () => {
    const tok = tokens[i++];
    if (!tok) err(text.length, 'unexpected end of file');
    return tok;
  };
  const isWord = (/** @type {{t: string, str?: boolean} | undefined} */ tok) => tok && !tok.str && /^[A-Za-z_][\w-]*$/.test(tok.t);

  /** @param {number} depth @returns {VrmlNode} */
  function node(depth) {
    if (depth > MAX_DEPTH) err(peek().at, `nested deeper than ${MAX_DEPTH}`);
    let tok = take();
    let def = null;
    if (tok.t === 'USE' || tok.t === 'PROTO' || tok.t === 'EXTERNPROTO' || tok.t === 'ROUTE') err(tok.at, `${tok.t} is not read`);
    if (tok.t === 'DEF') {
      const name = take();
      if (name.str) err(name.at, 'a DEF name');
      def = name.t;
      tok = take();
    }
    if (!isWord(tok)) err(tok.at, `a node type, not ${JSON.stringify(tok.t)}`);
    const open = take();
    if (open.t !== '{' || open.str) err(open.at, `{ after ${tok.t}`);
    /** @type {VrmlNode} */
    const n = { type: tok.t, def, fields: new Map(), at: tok.at };
    for (;;) {
      const f = take();
      if (f.t === '}' && !f.str) break;
      if (!isWord(f)) err(f.at, `a field name in ${tok.t}, not ${JSON.stringify(f.t)}`);
      if (n.fields.has(f.t)) err(f.at, `${f.t} given twice in ${tok.t}`);
      n.fields.set(f.t, value(depth));
    }
    return n;
  }

  /** One field's value: numbers, strings, booleans, a node, NULL, or a [ list ] of those. @param {number} depth */
  function value(depth) {
    /** @type {Array<number | string | boolean | VrmlNode>} */
    const out = [];
    const scalar = (/** @type {{t: string, at: number, str?: boolean}} */ tok) => {
      if (tok.str) return tok.t;
      if (NUMBER.test(tok.t)) return Number(tok.t);
      if (tok.t === 'TRUE' || tok.t === 'FALSE') return tok.t === 'TRUE';
      return null;
    };
    const first = peek();
    if (!first) err(text.length, 'unexpected end of file');
    if (first.t === '[' && !first.str) {
      take();
      while (!(peek() && peek().t === ']' && !peek().str)) {
        const tok = peek();
        if (!tok) err(first.at, 'unclosed [');
        const s = scalar(tok);
        if (s !== null) { take(); out.push(s); } else out.push(node(depth + 1));
      }
      take();
      return out;
    }
    if (first.t === 'NULL') { take(); return out; }
    if (first.t === 'DEF' || (isWord(first) && tokens[i + 1]?.t === '{')) return [node(depth + 1)];
    while (peek()) {
      const s = scalar(peek());
      if (s === null) break;
      take();
      out.push(s);
    }
    if (!out.length) err(first.at, `cannot read a value from ${JSON.stringify(first.t)}`);
    return out;
  }

  const nodes = [];
  while (i < tokens.length) nodes.push(node(0));
  return { nodes, where: (at) => `${relative(root, file)}:${position(text, at).join(':')}` };
}

/** @typedef {number[][]} Affine  3 rows of 4: linear part and translation */

const IDENTITY = () => [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]];

/** a·b for affine maps. @param {Affine} a @param {Affine} b @returns {Affine} */
function compose(a, b) {
  return a.map((row) => [0, 1, 2, 3].map((c) => row[0] * b[0][c] + row[1] * b[1][c] + row[2] * b[2][c] + (c === 3 ? row[3] : 0)));
}

/** @param {Affine} m @param {number[]} p */
const apply = (m, p) => m.map((row) => row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3]);

/** Rotation by `angle` about the axis (x, y, z), normalised (Rodrigues). @returns {Affine} */
function axisAngle(/** @type {number[]} */ [x, y, z, angle], /** @type {() => never} */ bad) {
  const n = Math.hypot(x, y, z);
  if (angle === 0) return IDENTITY();
  if (!(n > 0)) bad();
  const [u, v, w] = [x / n, y / n, z / n];
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const t = 1 - c;
  return [
    [t * u * u + c, t * u * v - s * w, t * u * w + s * v, 0],
    [t * u * v + s * w, t * v * v + c, t * v * w - s * u, 0],
    [t * u * w - s * v, t * v * w + s * u, t * w * w + c, 0],
  ];
}

/** @param {number[]} t @returns {Affine} */
const translate = (t) => [[1, 0, 0, t[0]], [0, 1, 0, t[1]], [0, 0, 1, t[2]]];

/** @param {number[]} s @returns {Affine} */
const scale = (s) => [[s[0], 0, 0, 0], [0, s[1], 0, 0], [0, 0, s[2], 0]];

/**
 * The Shapes under `nodes` with the map from their coordinates to the file's, VRML's Transform being
 * T·C·R·SR·S·SR⁻¹·C⁻¹, and the nearest DEF name around each.
 * @param {ReturnType<typeof parseVrml>} doc @param {VrmlNode[]} nodes @param {Affine} m @param {string | null} name
 * @returns {{shape: VrmlNode, m: Affine, name: string | null}[]}
 */
function shapes(doc, nodes, m = IDENTITY(), name = null) {
  const out = [];
  for (const n of nodes) {
    const here = n.def ?? name;
    /** @param {string} field @param {number[]} dflt */
    const vec = (field, dflt) => {
      const v = n.fields.get(field);
      if (v === undefined) return dflt;
      if (v.length !== dflt.length || v.some((x) => typeof x !== 'number')) {
        throw new Error(`${doc.where(n.at)}: ${n.type}.${field} must be ${dflt.length} numbers`);
      }
      return /** @type {number[]} */ (v);
    };
    if (n.type === 'Transform' || n.type === 'Group') {
      const known = n.type === 'Transform'
        ? ['children', 'translation', 'rotation', 'scale', 'center', 'scaleOrientation', 'bboxCenter', 'bboxSize']
        : ['children', 'bboxCenter', 'bboxSize'];
      for (const f of n.fields.keys()) if (!known.includes(f)) throw new Error(`${doc.where(n.at)}: ${n.type}.${f} is not read`);
      let local = IDENTITY();
      if (n.type === 'Transform') {
        const bad = () => { throw new Error(`${doc.where(n.at)}: a rotation about a zero axis`); };
        const c = vec('center', [0, 0, 0]);
        const so = axisAngle(vec('scaleOrientation', [0, 0, 1, 0]), bad);
        const soInv = axisAngle(vec('scaleOrientation', [0, 0, 1, 0]).map((x, k) => (k === 3 ? -x : x)), bad);
        local = [translate(vec('translation', [0, 0, 0])), translate(c), axisAngle(vec('rotation', [0, 0, 1, 0]), bad),
          so, scale(vec('scale', [1, 1, 1])), soInv, translate(c.map((x) => -x))].reduce(compose);
      }
      const kids = n.fields.get('children') ?? [];
      if (kids.some((k) => typeof k !== 'object')) throw new Error(`${doc.where(n.at)}: ${n.type}.children must be nodes`);
      out.push(...shapes(doc, /** @type {VrmlNode[]} */ (kids), compose(m, local), here));
    } else if (n.type === 'Shape') {
      out.push({ shape: n, m, name: here });
    } else {
      throw new Error(`${doc.where(n.at)}: ${n.type} is not read (Transform, Group and Shape are)`);
    }
  }
  return out;
}

/** The one field of node `n` that is one node. @param {ReturnType<typeof parseVrml>} doc @param {VrmlNode} n @param {string} field */
function childNode(doc, n, field) {
  const v = n.fields.get(field);
  if (!v || v.length !== 1 || typeof v[0] !== 'object') throw new Error(`${doc.where(n.at)}: ${n.type}.${field} must be one node`);
  return v[0];
}

/** A link's hull: the points of the file's one IndexedFaceSet, in the link's frame. @param {string} file */
export function readHull(file) {
  const doc = parseVrml(file);
  const found = shapes(doc, doc.nodes);
  if (found.length !== 1) throw new Error(`${relative(root, file)}: ${found.length} shapes, expected one`);
  const { shape, m } = found[0];
  const geometry = childNode(doc, shape, 'geometry');
  if (geometry.type !== 'IndexedFaceSet') throw new Error(`${doc.where(geometry.at)}: ${geometry.type}, expected an IndexedFaceSet`);
  const coord = childNode(doc, geometry, 'coord');
  const point = coord.fields.get('point') ?? [];
  if (coord.type !== 'Coordinate' || point.length % 3 || point.some((x) => typeof x !== 'number')) {
    throw new Error(`${doc.where(coord.at)}: a Coordinate with point [x y z, …] expected`);
  }
  const count = point.length / 3;
  if (count < 4 || count > MAX_HULL_POINTS) throw new Error(`${doc.where(coord.at)}: ${count} points (4..=${MAX_HULL_POINTS})`);
  const hull = [];
  for (let k = 0; k < count; k++) hull.push(apply(m, /** @type {number[]} */ (point.slice(3 * k, 3 * k + 3))));
  return hull;
}

/** Every Box of the file as an axis-aligned box in the file's frame, named by the DEF around it. @param {string} file */
export function readBoxes(file) {
  const doc = parseVrml(file);
  return shapes(doc, doc.nodes).map(({ shape, m, name }) => {
    const geometry = childNode(doc, shape, 'geometry');
    if (geometry.type !== 'Box') throw new Error(`${doc.where(geometry.at)}: ${geometry.type}, expected a Box`);
    const size = geometry.fields.get('size') ?? [2, 2, 2];
    if (size.length !== 3 || size.some((x) => typeof x !== 'number' || !(x > 0))) {
      throw new Error(`${doc.where(geometry.at)}: Box.size must be 3 positive numbers`);
    }
    for (let r = 0; r < 3; r++) {
      for (let c = 0; c < 3; c++) {
        if (r !== c && m[r][c] !== 0) throw new Error(`${doc.where(shape.at)}: a rotated Box (only axis-aligned boxes are read)`);
      }
    }
    if (!name) throw new Error(`${doc.where(shape.at)}: a Box without a DEF name around it`);
    return { name, box: { center: apply(m, [0, 0, 0]), size: [0, 1, 2].map((k) => Math.abs(m[k][k]) * /** @type {number} */ (size[k])) } };
  });
}

// ---------------------------------------------------------------------------------------------
// The files.

/** The arm from rlkin: joints, link names, ignored pairs, exempt links, the tool point. @param {string} file */
export function readKinematics(file) {
  const doc = parseXml(file);
  if (doc.root.name !== 'rlkin' || doc.root.children.length !== 1) throw new Error(`${doc.where(doc.root.at)}: <rlkin> with one robot expected`);
  const robot = doc.root.children[0];
  const zero = (/** @type {XmlElement} */ el) => {
    for (const part of ['rotation', 'translation']) {
      if (xyz(doc, one(doc, el, part)).some((v) => v !== 0)) throw new Error(`${doc.where(el.at)}: a ${part} here is not read (zero expected)`);
    }
  };
  const links = all(robot, 'link');
  const ids = links.map((l) => l.attrs.id);
  const index = (/** @type {XmlElement} */ el) => {
    const k = ids.indexOf(el.attrs.idref);
    if (k < 0) throw new Error(`${doc.where(el.at)}: no link ${JSON.stringify(el.attrs.idref)}`);
    return k;
  };
  for (const el of robot.children) {
    if (['prismatic', 'spherical', 'fixed', 'sixDof', 'cylindrical', 'helical'].includes(el.name)) {
      throw new Error(`${doc.where(el.at)}: <${el.name}> is not read (revolute joints only)`);
    }
  }
  zero(one(doc, robot, 'world'));
  const transforms = all(robot, 'transform');
  const base = transforms.find((t) => t.attrs.id === 'base');
  if (!base || index(one(doc, one(doc, base, 'frame'), 'b')) !== 0) throw new Error(`${doc.where(robot.at)}: a base transform onto the first link expected`);
  zero(base);
  const revolutes = all(robot, 'revolute');
  if (revolutes.length + 1 !== links.length) throw new Error(`${doc.where(robot.at)}: ${links.length} links for ${revolutes.length} joints`);
  const joints = revolutes.map((j, k) => {
    const frame = one(doc, j, 'frame');
    if (index(one(doc, frame, 'a')) !== k || index(one(doc, frame, 'b')) !== k + 1) {
      throw new Error(`${doc.where(j.at)}: joint ${k} must join ${ids[k]} to ${ids[k + 1]}`);
    }
    const dh = one(doc, j, 'dh');
    const [d, theta, a, alpha] = ['d', 'theta', 'a', 'alpha'].map((f) => num(doc, one(doc, dh, f)));
    const lo = num(doc, one(doc, j, 'min'));
    const hi = num(doc, one(doc, j, 'max'));
    if (!(lo < hi)) throw new Error(`${doc.where(j.at)}: min ${lo} is not below max ${hi}`);
    return { d, theta: rad(theta), a, alpha: rad(alpha), limits: [rad(lo), rad(hi)] };
  });
  const pairs = new Set();
  /** @type {number[]} */
  const exempt = [];
  links.forEach((l, k) => {
    for (const ig of all(l, 'ignore')) {
      if (ig.attrs.idref === undefined) {
        if (!exempt.includes(k)) exempt.push(k);
      } else {
        const j = index(ig);
        if (j === k) throw new Error(`${doc.where(ig.at)}: a link ignoring itself`);
        pairs.add(`${Math.min(j, k)},${Math.max(j, k)}`);
      }
    }
  });
  const ignore = [...pairs].map((p) => p.split(',').map(Number)).sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  const toolTransform = transforms.find((t) => t.attrs.id === 'tool');
  let tool = [0, 0, 0];
  if (toolTransform) {
    if (index(one(doc, one(doc, toolTransform, 'frame'), 'a')) !== links.length - 1) {
      throw new Error(`${doc.where(toolTransform.at)}: the tool must sit on the last link`);
    }
    tool = xyz(doc, one(doc, toolTransform, 'translation'));
  }
  return { joints, names: ids, ignore, exempt: exempt.sort((p, q) => p - q), tool };
}

/** rl's planning problem: start, goal, the base's world rotation, delta, epsilon, duration. @param {string} file */
export function readPlan(file) {
  const doc = parseXml(file);
  if (doc.root.name !== 'rlplan' || doc.root.children.length !== 1) throw new Error(`${doc.where(doc.root.at)}: <rlplan> with one planner expected`);
  const planner = doc.root.children[0];
  if (planner.name !== 'rrtConCon') throw new Error(`${doc.where(planner.at)}: <${planner.name}>, expected <rrtConCon>`);
  const kinematics = one(doc, one(doc, planner, 'model'), 'kinematics');
  if (!/(^|\/)unimation-puma560\.xml$/.test(kinematics.attrs.href ?? '')) throw new Error(`${doc.where(kinematics.at)}: another arm's kinematics`);
  const world = one(doc, kinematics, 'world');
  const rotation = one(doc, world, 'rotation');
  const translation = xyz(doc, one(doc, world, 'translation'));
  const q = (/** @type {string} */ name) => all(one(doc, planner, name), 'q').map((el) => angle(doc, el));
  const epsilon = num(doc, one(doc, planner, 'epsilon'));
  const duration = num(doc, one(doc, planner, 'duration'));
  const delta = angle(doc, one(doc, planner, 'delta'));
  if (!(epsilon > 0 && duration > 0 && delta > 0)) throw new Error(`${doc.where(planner.at)}: epsilon, duration and delta must be positive`);
  return {
    start: q('start'),
    goal: q('goal'),
    base: { translation, rotation: ['x', 'y', 'z'].map((c) => angle(doc, one(doc, rotation, c))) },
    delta,
    epsilon,
    duration,
  };
}

// ---------------------------------------------------------------------------------------------
// The course's scene (report 001, "rbo_wall"), as the course gives it: metres, world frame, boxes by
// centre and full size. Not in rl's files.

const COURSE_TOOL = {
  boxes: [
    { name: 'rod', center: [0, 0, 0.125], size: [0.02, 0.02, 0.25] },
    { name: 'bar', center: [0.125, 0, 0.26], size: [0.27, 0.02, 0.02] },
  ],
  tcp: [0.26, 0, 0.26],
};
const COURSE_WALL = [
  { name: 'slab', box: { center: [0.85, 0, 0.05], size: [0.08, 0.64, 1.5] } },
  { name: 'block-left', box: { center: [0.85, 0.2, 0.88], size: [0.08, 0.24, 0.16] } },
  { name: 'block-right', box: { center: [0.85, -0.2, 0.88], size: [0.08, 0.24, 0.16] } },
  { name: 'lintel', box: { center: [0.85, 0, 1.04], size: [0.08, 0.64, 0.16] } },
];
const COURSE_START_DEG = [0, 0, 90, 0, 0, 0];
const COURSE_GOAL_DEG = [-98, 7, 44, 0, 44, 0];
const COURSE_DELTA_DEG = 1;

// ---------------------------------------------------------------------------------------------
// Writing.

/**
 * JSON with two-space indentation, a value kept on one line when it fits (hull points one a line).
 * @param {unknown} v @param {string} indent @returns {string}
 */
function format(v, indent = '') {
  const flat = JSON.stringify(v, null, 1).replace(/\n\s*/g, ' ').replace(/\[ /g, '[').replace(/ \]/g, ']')
    .replace(/\{ /g, '{').replace(/ \}/g, '}');
  if (v === null || typeof v !== 'object' || indent.length + flat.length <= 130) return flat;
  const inner = `${indent}  `;
  if (Array.isArray(v)) return `[\n${v.map((x) => `${inner}${format(x, inner)}`).join(',\n')}\n${indent}]`;
  return `{\n${Object.entries(v).map(([k, x]) => `${inner}${JSON.stringify(k)}: ${format(x, inner)}`).join(',\n')}\n${indent}}`;
}

/** Both scenario files' text, keyed by file name. @param {string} data */
export function convert(data = DATA_DIR) {
  const kin = readKinematics(join(data, 'rlkin', 'unimation-puma560.xml'));
  const hulls = kin.names.map((name) => readHull(join(data, 'rlsg', 'unimation-puma560.convex', `${name}.wrl`)));
  const plan = readPlan(join(data, 'rlplan', 'unimation-puma560_boxes_rrtConCon.xml'));
  const room = readBoxes(join(data, 'rlsg', 'boxes.wrl'));
  const n = kin.joints.length;
  /** @type {{what: string, q: number[]}[]} */
  const states = [{ what: 'start', q: plan.start }, { what: 'goal', q: plan.goal },
    { what: 'the course\'s start', q: COURSE_START_DEG.map(rad) }, { what: 'the course\'s goal', q: COURSE_GOAL_DEG.map(rad) }];
  for (const { what, q } of states) {
    if (q.length !== n) throw new Error(`${what} has ${q.length} angles for ${n} joints`);
    q.forEach((x, k) => {
      const [lo, hi] = kin.joints[k].limits;
      if (!(x >= lo && x <= hi)) throw new Error(`${what}: joint ${k} at ${x} is outside its limits [${lo}, ${hi}]`);
    });
  }
  /** @param {{name: string, center: number[], size: number[]}[]} toolBoxes @param {number[]} tool */
  const robot = (toolBoxes, tool) => ({
    kind: 'spatial-arm',
    base: plan.base,
    joints: kin.joints,
    links: kin.names.map((name, k) => ({ name, hull: hulls[k], ...(k === n && toolBoxes.length ? { boxes: toolBoxes } : {}) })),
    ignore: kin.ignore,
    exempt: kin.exempt,
    tool,
    metric: 'joint',
  });
  const wall = {
    format: 'planarium-scenario/1',
    name: 'Puma 560 through a window (report 001\'s course)',
    notes: 'The scene of the RRT-extensions assignment of report 001, a robotics course\'s RRT-Connect planner for a '
      + '6-joint arm: a Unimation Puma 560 carries a tool on its last link (a 25 cm rod and a 27 cm bar at its end, the tool '
      + 'centre point at the end of the bar) and must thread the tool through a 16 cm x 16 cm window in a wall 85 cm in '
      + 'front of it (four boxes: a slab, two blocks, a lintel). It starts stretched out level to its side with the bar '
      + 'hanging down, and ends with the rod through the window and the tool centre point behind the wall. Every link collides as its convex hull; the base is not tested against the wall. Angles are in '
      + 'radians; RRT-Connect steps 1 degree of the six-joint distance and keeps only the last free configuration, as the '
      + 'course\'s planner did. The arm\'s kinematics and link hulls are the Robotics Library\'s data (BSD 2-Clause, '
      + '(c) 2009 Markus Rickert; see THIRD_PARTY_NOTICES.md).',
    // The top view's extent: the arm with the tool reaches 1.28 m from the base's axis.
    bounds: [-1.3, -1.3, 1.3, 1.3],
    robot: robot(COURSE_TOOL.boxes, COURSE_TOOL.tcp),
    obstacles3d: COURSE_WALL,
    start: COURSE_START_DEG.map(rad),
    goal: COURSE_GOAL_DEG.map(rad),
    resolution: rad(COURSE_DELTA_DEG),
    planner: { name: 'rrt-connect', seed: 1, connect: 'last-free', epsilon: 1e-8, time_limit: 1200 },
  };
  const boxes = {
    format: 'planarium-scenario/1',
    name: 'Puma 560 among boxes (the Robotics Library\'s example)',
    notes: 'The Robotics Library\'s own planning example for the Unimation Puma 560 (rrtConCon): a room 5.2 m square '
      + 'with a floor, four walls and three 1 m cubes around the arm. Start and goal both hold the arm stretched out level '
      + 'at shoulder height, a quarter turn apart and with the shoulder turned over (joint 2 at -180 and 0 degrees). Every link collides as its convex hull; the base is not tested against the room. Angles are in radians; '
      + 'RRT-Connect steps 1 degree of the six-joint distance and keeps only the last free configuration, as rl\'s planner '
      + 'does. Data of the Robotics Library (BSD 2-Clause, (c) 2009 Markus Rickert; see THIRD_PARTY_NOTICES.md).',
    // The room's outer faces (the arm reaches 0.93 m).
    bounds: [-2.6, -2.6, 2.6, 2.6],
    robot: robot([], kin.tool),
    obstacles3d: room,
    start: plan.start,
    goal: plan.goal,
    resolution: plan.delta,
    planner: { name: 'rrt-connect', seed: 1, connect: 'last-free', epsilon: plan.epsilon, time_limit: plan.duration },
  };
  return { 'puma-rbo-wall.json': `${format(wall)}\n`, 'puma-boxes.json': `${format(boxes)}\n` };
}

/** The files of `dir` that are not what `convert` writes, each with a reason. @param {string} dir */
export function stale(dir = SCENARIOS_DIR, data = DATA_DIR) {
  return Object.entries(convert(data)).flatMap(([name, text]) => {
    const file = join(dir, name);
    if (!existsSync(file)) return [`${relative(root, file)} is missing`];
    return readFileSync(file, 'utf8') === text ? [] : [`${relative(root, file)} is not what scripts/convert-rl.mjs writes`];
  });
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2);
  const outAt = args.indexOf('--out');
  const dir = outAt >= 0 ? resolve(args[outAt + 1] ?? '') : SCENARIOS_DIR;
  const unknown = args.filter((a, k) => a !== '--check' && a !== '--out' && !(outAt >= 0 && k === outAt + 1));
  if (unknown.length || (outAt >= 0 && !args[outAt + 1])) {
    console.error('usage: node scripts/convert-rl.mjs [--check] [--out DIR]');
    process.exit(2);
  }
  try {
    if (args.includes('--check')) {
      const problems = stale(dir);
      if (problems.length) {
        console.error(`[convert-rl] ${problems.join('; ')}: run node scripts/convert-rl.mjs and commit them`);
        process.exit(1);
      }
      console.log('[convert-rl] the Puma 560 scenarios are current');
    } else {
      for (const [name, text] of Object.entries(convert())) {
        writeFileSync(join(dir, name), text);
        console.log(`[convert-rl] wrote ${join(dir, name)}`);
      }
    }
  } catch (e) {
    console.error(`[convert-rl] ${e instanceof Error ? e.message : e}`);
    process.exit(1);
  }
}

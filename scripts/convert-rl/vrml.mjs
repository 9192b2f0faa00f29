// VRML 2.0 as rl's rlsg files write it (scripts/convert-rl.mjs): nodes, fields and their values,
// and the Transforms around each Shape; PROTO, ROUTE and USE are not read. Every error names the
// file, line and column.
import { relative } from 'node:path';
import { fail, MAX_DEPTH, position, readText, root } from './text.mjs';

const MAX_TOKENS = 200000;
const MAX_HULL_POINTS = 1024;

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

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
// understand is an error naming the file, line and column: a new rl file is never half-read. The
// readers of the two file formats are scripts/convert-rl/xml.mjs and scripts/convert-rl/vrml.mjs.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseXml, all, one, num, angle, xyz } from './convert-rl/xml.mjs';
import { readBoxes, readHull } from './convert-rl/vrml.mjs';
import { rad, root } from './convert-rl/text.mjs';

/** @typedef {import('./convert-rl/xml.mjs').XmlElement} XmlElement */

export const DATA_DIR = join(root, 'data', 'rl-puma560');
export const SCENARIOS_DIR = join(root, 'scenarios');

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

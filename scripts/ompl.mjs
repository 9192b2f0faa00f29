// OMPL beside Planarium in the benchmark suite: find OMPL 1.5 (Debian's libompl-dev), build the
// project's harness (bench/ompl/harness.cpp) with g++ -O3 into target/ompl/, write a suite problem
// in the harness's problem file form from its scenario, and run the harness seed by seed.
// Without OMPL the suite says so and goes on: nothing here is needed by the tests of the product.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';

/** Where Debian's libompl-dev puts OMPL 1.5's headers. */
export const OMPL_INCLUDE = '/usr/include/ompl-1.5';
/** What the suite prints when OMPL cannot be measured here. */
export const NOT_INSTALLED = "OMPL not installed (Debian's libompl-dev): OMPL not measured";

/** What the suite prints when `PLANARIUM_OMPL=0` tells it to leave OMPL out. */
export const SWITCHED_OFF = 'OMPL left out (PLANARIUM_OMPL=0): OMPL not measured';

/**
 * Whether OMPL can be measured here: its headers and a C++ compiler, unless the environment's
 * `PLANARIUM_OMPL=0` leaves it out (the suite then runs as on a machine without OMPL).
 * @param {{ include?: string, compiler?: string, env?: Record<string, string | undefined> }} [where]
 * @returns {{ installed: boolean, message: string }}
 */
export function detectOmpl({ include = OMPL_INCLUDE, compiler = 'g++', env = process.env } = {}) {
  if (env.PLANARIUM_OMPL === '0') return { installed: false, message: SWITCHED_OFF };
  if (!existsSync(join(include, 'ompl', 'geometric', 'SimpleSetup.h'))) return { installed: false, message: NOT_INSTALLED };
  try {
    execFileSync(compiler, ['--version'], { stdio: 'ignore' });
  } catch {
    return { installed: false, message: `OMPL found in ${include} but no ${compiler} to build the harness: OMPL not measured` };
  }
  return { installed: true, message: `OMPL found in ${include}` };
}

/**
 * Build the harness into target/ompl/harness unless it is newer than its source; its path.
 * @param {string} root the repository
 * @param {{ include?: string, compiler?: string }} [where]
 */
export function buildHarness(root, { include = OMPL_INCLUDE, compiler = 'g++' } = {}) {
  const src = join(root, 'bench', 'ompl', 'harness.cpp');
  const bin = join(root, 'target', 'ompl', 'harness');
  if (existsSync(bin) && statSync(bin).mtimeMs >= statSync(src).mtimeMs) return bin;
  mkdirSync(dirname(bin), { recursive: true });
  // OMPL's headers include Eigen's (Debian's libeigen3-dev, a dependency of libompl-dev).
  execFileSync(compiler, ['-O3', '-std=c++17', `-I${include}`, '-I/usr/include/eigen3', src, '-o', bin, '-lompl'], { stdio: ['ignore', 'ignore', 'inherit'] });
  return bin;
}

/** Set-up parameters the harness reproduces; any other makes the set-up one OMPL has no match for. */
const KNOWN = new Set(['range', 'goal_bias', 'time_limit']);
/**
 * RRT*'s too: OMPL's default near set (k-nearest, rewire factor 1.1) is Planarium's, and OMPL's
 * RRT* improves until its time limit, which Planarium's does when `improve_for` (iterations after
 * the first solution) is more than the limit allows. OMPL's has no node limit: a set-up's
 * `max_nodes` must be more than the time allows (the suite's table shows the nodes made).
 */
const KNOWN_STAR = new Set([...KNOWN, 'improve_for', 'max_nodes']);
const STAR_UNTIL_LIMIT = 1e8;

const nums = (xs) => xs.map((v) => {
  if (!Number.isFinite(v)) throw new Error(`not a finite number: ${v}`);
  return String(v);
});

/**
 * The harness's problem file for `scenario` (a parsed scenario document) under a set-up's
 * parameters, or why OMPL has no match for it.
 * @param {any} scenario
 * @param {string} planner
 * @param {Record<string, unknown>} params the set-up's explicit parameters, the scenario's planner
 *   block's included (as the CLI's bench reports them); range 0 or unset: 0.2 × the space's extent
 *   in both
 * @returns {{ text: string } | { skip: string }}
 */
export function problemText(scenario, planner, params) {
  if (planner !== 'rrt' && planner !== 'rrt-connect' && planner !== 'rrt-star') return { skip: `OMPL harness runs rrt, rrt-connect and rrt-star, not ${planner}` };
  const other = Object.keys(params).filter((k) => !(planner === 'rrt-star' ? KNOWN_STAR : KNOWN).has(k));
  if (other.length) return { skip: `set-up parameters OMPL has no match for: ${other.join(', ')}` };
  if (planner === 'rrt-star' && !(Number(params.improve_for) >= STAR_UNTIL_LIMIT)) {
    return { skip: `OMPL's RRT* improves until its time limit: set improve_for to ${STAR_UNTIL_LIMIT} or more` };
  }
  if (planner === 'rrt-connect' && Number(params.goal_bias ?? 0) !== 0) return { skip: "OMPL's RRT-Connect has no goal bias" };
  if (scenario.touching_allowed) return { skip: 'touching_allowed: the harness treats obstacles as closed sets' };
  const r = scenario.robot;
  const [x0, y0, x1, y1] = scenario.bounds;
  const lines = [
    `robot ${{ point: 'point', rigid: 'rigid', arm: 'chain' }[r.kind] ?? '?'}`,
    `bounds ${nums(scenario.bounds).join(' ')}`,
    `resolution ${nums([scenario.resolution ?? 0.002 * Math.max(x1 - x0, y1 - y0)])}`,
    `range ${nums([Number(params.range ?? 0)])}`,
    `goal_bias ${nums([Number(params.goal_bias ?? (planner === 'rrt-connect' ? 0 : 0.05))])}`,
    `goal_tolerance ${nums([scenario.goal_tolerance ?? 0])}`,
    `start ${scenario.start.length} ${nums(scenario.start).join(' ')}`,
    `goal ${scenario.goal.length} ${nums(scenario.goal).join(' ')}`,
  ];
  if (r.kind === 'rigid') {
    if (r.body_in_bounds) return { skip: 'body_in_bounds: the harness keeps the reference point in bounds' };
    const radius = Math.max(...r.footprint.map(([x, y]) => Math.hypot(x, y)));
    lines.push(`footprint ${r.footprint.length} ${nums(r.footprint.flat()).join(' ')}`, `rotation_weight ${nums([r.rotation_weight ?? radius])}`);
  } else if (r.kind === 'arm') {
    if ((r.metric ?? 'chain') !== 'chain') return { skip: `the arm's metric ${r.metric}: the harness has the chain metric` };
    if (Array.isArray(r.limits) && r.limits.some((l) => l !== null)) return { skip: 'joint limits: the harness has joints that all wrap' };
    lines.push(`base ${nums(r.base ?? [0, 0]).join(' ')}`, `links ${r.links.length} ${nums(r.links).join(' ')}`,
      `tip ${nums([r.tip ?? 0])}`, `self_collision ${r.self_collision === false ? 0 : 1}`);
  } else if (r.kind !== 'point') {
    return { skip: `the harness has no ${r.kind} robot` };
  }
  for (const o of scenario.obstacles ?? []) {
    if (o.rect) {
      const [a, b, c, d] = o.rect;
      const [lx, hx, ly, hy] = [Math.min(a, c), Math.max(a, c), Math.min(b, d), Math.max(b, d)];
      lines.push(`polygon 4 ${nums([lx, ly, hx, ly, hx, hy, lx, hy]).join(' ')}`);
    } else if (o.polygon) {
      lines.push(`polygon ${o.polygon.length} ${nums(o.polygon.flat()).join(' ')}`);
    } else if (o.segment) {
      lines.push(`segment ${nums(o.segment).join(' ')}`);
    } else {
      return { skip: `an obstacle the harness does not model (${Object.keys(o).join(', ')})` };
    }
  }
  return { text: `${lines.join('\n')}\n` };
}

/**
 * Run the harness on a problem file for seeds first..last; one row per seed. With `paths`, a solved
 * seed's row also has its solution's states (`path`), for `planarium check-path`.
 * @returns {{ seed: number, planner: string, solved: boolean, time_ms: number, checks: number, nodes: number, cost: number, path?: number[][] }[]}
 */
export function runHarness(bin, file, planner, first, last, timeLimitS, { paths = false } = {}) {
  const out = execFileSync(bin, [file, planner, String(first), String(last), String(timeLimitS), ...(paths ? ['--paths'] : [])], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'], maxBuffer: 64 << 20 });
  const rows = out.trim().split('\n').map((l) => JSON.parse(l));
  if (rows.length !== last - first + 1) throw new Error(`OMPL harness: ${rows.length} runs for seeds ${first}..${last}`);
  return rows;
}

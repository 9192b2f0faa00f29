// The workers' protocol, both directions, as JSDoc types: the planning worker's (www/worker/worker.js
// describes each message in its header) and the benchmark worker's (www/worker/bench-worker.js).
// Both sides import these types, so `tsc --checkJs` (npm test) checks what the page sends and reads
// (run/session.js, ui/seed-pool.js, the pages' hooks) against what the workers read and post.
// No code: types only.

/**
 * One dimension of the planning space (src/space: the core's `space_json`).
 * @typedef {{lo: number, hi: number, wraps: boolean}} SpaceDim
 */

/**
 * A planner set-up's parameters as the page sends them (the registry's names; numbers, or a
 * choice's name).
 * @typedef {Record<string, number | string | boolean>} SetupParams
 */

/**
 * The planning worker's requests (the page → worker.js).
 * @typedef {{type: 'load', text: string}
 *   | {type: 'import', text: string, name: string, bytes?: ArrayBuffer | null, yaml?: string | null, yamlName?: string | null}
 *   | {type: 'configure', planner: string, params: SetupParams, seed: number}
 *   | {type: 'run' | 'pause' | 'reset' | 'cancel' | 'asv-solution' | 'ping' | 'fresh-seed'}
 *   | {type: 'step', iterations: number}
 *   | {type: 'query', start: number[], goal: number[]}
 *   | {type: 'debug-panic', message?: string}
 *   | {type: 'debug-hang', ms: number}} WorkerRequest
 * @typedef {WorkerRequest & {ack?: number, run?: number}} WorkerIn
 */

/**
 * The run's statistics as the core reports them (src/run/result.rs; a few of the fields).
 * @typedef {{time_ms: number, iterations: number, nodes: number, checks: number, cost?: number | null,
 *   smoothed_cost?: number | null, smoothing_ms?: number,
 *   sampler?: {name: string, used?: boolean, draws_per_sample: number, checks_per_sample: number}}} RunStats
 */

/**
 * A run's result, the contract's result JSON (src/run/result.rs; a few of the fields).
 * @typedef {{solved: boolean, status: string, stats: RunStats, reason?: string}} RunResult
 */

/**
 * Another query on a finished roadmap run (src/run/session.rs QueryAnswer), or why it failed.
 * @typedef {{path?: number[][], points?: number[][], cost?: number, error?: string}} QueryAnswer
 */

/**
 * The visibility graph's shortest path (the core's `optimum_json`): its cost (null: no path) and
 * whether that is the robot's optimum (a point, a round footprint); or, alone, why there is none.
 * @typedef {{cost?: number | null, exact?: boolean, error?: string}} Optimum
 */

/**
 * What the core decided for a loaded scene (src/scene_caps.rs): the robot kind's record, whether the
 * page gets a configuration-space view, the optimum, a solution file, and which pose can be dragged.
 * @typedef {{robot: any, cspace: boolean, optimum: boolean, solution_file: boolean, pose: string, view3d?: boolean}} SceneCaps
 */

/**
 * A scenario the worker validated: the normalised scenario; the robot's outlines at start and goal,
 * flat (the core's `Scene::outline`: `[n_polygons, n_1, x, y, …]`; the goal's empty without a
 * goal); the planning space; for a 2-joint arm the configuration-space validity grid (n × n, rows
 * from the lowest second coordinate, over the space's two dimensions); for a point or rigid robot
 * the visibility graph's optimum; what the core decided for it (`caps`, the core's `scene_caps`).
 * @typedef {{type: 'loaded', scenario: any, start: Float64Array, goal: Float64Array, space: SpaceDim[],
 *   cspace?: {n: number, grid: Uint8Array, dims: SpaceDim[]}, optimum?: Optimum, caps?: SceneCaps,
 *   spatial?: Spatial}} LoadedReply
 */

/**
 * A part or an obstacle as a triangle mesh (flat: `vertices` x, y, z…, `triangles` i, j, k…).
 * @typedef {{vertices: number[], triangles: number[], name: string, link?: number}} Mesh3d
 */

/**
 * What the 3-D view draws of a scene (`caps.view3d`): the core's `Scene.spatial_json` (links, the
 * tool centre point in the last link's frame, the parts' meshes in their links' frames, the 3-D
 * obstacles' in the world) and the link frames at start and goal (`Scene.link_frames`, 16 numbers
 * a link, column-major; the goal's empty without a goal).
 * @typedef {{links: number, tool: number[], parts: Mesh3d[], obstacles: Mesh3d[], start: Float64Array,
 *   goal: Float64Array}} Spatial
 */

/**
 * A solved path for the 3-D view: the tool's curve through every animation frame (x, y, z…) and
 * the link frames of `count` poses (`links` × 16 numbers each): pose k is animation frame
 * min(k·stride, frames − 1).
 * @typedef {{tool: Float64Array, frames: Float64Array, count: number, links: number, stride: number,
 *   lengths: Float64Array}} Path3d
 */

/**
 * Why a scenario was refused: a JSON path or a line and column, and the message.
 * @typedef {{path?: string | null, message?: string, line?: number | null, column?: number | null, text?: string}} ScenarioError
 */

/**
 * The planning worker's replies (worker.js → the page).
 * @typedef {{type: 'ready', builtins: any[], planners: any, eventKinds: Record<string, number>, robotKinds?: any[]}
 *   | LoadedReply
 *   | {type: 'invalid', error: ScenarioError}
 *   | {type: 'events', data: Float64Array, stats: RunStats, status: string, tries?: {seen: number, sent: number},
 *       tree3d?: Float64Array, states?: Float64Array}
 *   | {type: 'result', result: RunResult, frames: Float64Array, rawFrames: Float64Array, path3d?: Path3d,
 *       rawPath3d?: Path3d}
 *   | {type: 'status', status: string}
 *   | {type: 'ack', ack: number}
 *   | {type: 'asv-solution', text: string}
 *   | {type: 'query', data: Float64Array, answer: QueryAnswer, states?: Float64Array}
 *   | {type: 'seed', seed: number}
 *   | {type: 'error' | 'crashed', message: string}} WorkerReply
 * @typedef {WorkerReply & {run?: number}} WorkerOut
 */

/**
 * A benchmark worker's job (the page's pool, ui/seed-pool.js → bench-worker.js): one seeded run
 * of a set-up on a scenario's JSON text, to its end.
 * @typedef {{id: number, text: string, planner: string, params: SetupParams, seed: number}} BenchJob
 */

/**
 * The benchmark worker's replies: ready once its core is loaded; per job its result (for RRT*,
 * `curve`: the best cost against planning time, [[ms, cost], …]; else null), or why it failed (a
 * bad set-up: the worker stays usable) or crashed (the core panicked: the pool drops the worker).
 * @typedef {{type: 'ready'}
 *   | {type: 'done', id: number, result: RunResult, curve: Array<[number, number]> | null}
 *   | {type: 'failed' | 'crashed', id: number, message: string}} BenchReply
 */

export {};

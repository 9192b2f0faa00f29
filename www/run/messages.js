// The planning worker's messages, as JSDoc types (www/worker/worker.js describes each): checked by
// `tsc --checkJs` in npm test where the page sends and reads them (session.js) and where the worker
// reads them (worker.js). No code: types only.

/**
 * @typedef {{type: 'load', text: string}
 *   | {type: 'import', text: string, name: string, bytes?: ArrayBuffer | null, yaml?: string | null, yamlName?: string | null}
 *   | {type: 'configure', planner: string, params: Record<string, number | string>, seed: number}
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
 *   smoothed_cost?: number | null, sampler?: {name: string, used?: boolean, draws_per_sample: number, checks_per_sample: number}}} RunStats
 */

/**
 * Another query on a finished roadmap run (src/run/session.rs QueryAnswer), or why it failed.
 * @typedef {{path?: number[][], points?: number[][], cost?: number, error?: string}} QueryAnswer
 */

/**
 * @typedef {{robot: any, cspace: boolean, optimum: boolean, solution_file: boolean, pose: string}} SceneCaps
 */

/**
 * @typedef {{type: 'ready', builtins: any[], planners: any, eventKinds: Record<string, number>, robotKinds?: any[]}
 *   | {type: 'loaded', scenario: any, start: number[], goal: number[], space: Array<{lo: number, hi: number, wraps: boolean}>,
 *      caps?: SceneCaps, cspace?: {n: number, grid: Uint8Array, dims: number}}
 *   | {type: 'invalid', error: {path?: string, message?: string, line?: number, column?: number, text?: string}}
 *   | {type: 'events', data: Float64Array, stats: RunStats, status: string, tries?: {seen: number, sent: number}}
 *   | {type: 'result', result: {solved: boolean, status: string, stats: RunStats, reason?: string}, frames: Float64Array, rawFrames: Float64Array}
 *   | {type: 'status', status: string}
 *   | {type: 'ack', ack: number}
 *   | {type: 'asv-solution', text: string}
 *   | {type: 'query', data: Float64Array, answer: QueryAnswer}
 *   | {type: 'seed', seed: number}
 *   | {type: 'error' | 'crashed', message: string}} WorkerReply
 * @typedef {WorkerReply & {run?: number}} WorkerOut
 */

export {};

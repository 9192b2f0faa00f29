// Types for <planarium-playground> (planarium-playground.js): its attributes, the events it fires
// with their detail, and what scripts may read and call. Shipped in the static copy next to the
// module; `tsc -p .` checks it against tests/types/planarium-playground.ts.
//
//   import type { PlanariumPlayground, PlaygroundSolvedDetail } from './planarium/planarium-playground.js';
//   const el = document.querySelector('planarium-playground');
//   el?.addEventListener('solved', (e) => console.log(e.detail.iterations, e.detail.cost));

/** A control of the bar, in the order given by the `controls` attribute. */
export type PlaygroundControl = 'run' | 'pause' | 'step' | 'back' | 'reset' | 'speed' | 'seed';

/** The player's state (the page's controller). */
export type PlaygroundState = 'loading' | 'idle' | 'running' | 'paused' | 'finished' | 'invalid' | 'stopped';

/**
 * The attributes, as strings (the share link's grammar, docs/embedding.md). Flags (`autoplay`,
 * `click`, `raw-path`, `fill`) count when present, whatever their value.
 */
export interface PlaygroundAttributes {
  /** A built-in scenario's id ("narrow"), or a share link's packed scenario. */
  scenario?: string;
  /** A planner's id in the registry ("rrt-connect"). */
  planner?: string;
  /** A whole number from 0 to 9007199254740991. */
  seed?: string;
  /** Playback speed, 0 to 100 (100: every event at once). */
  speed?: string;
  /** Robot animation speed, 0 to 100. */
  anim?: string;
  /** Comma-separated `+id` / `-id` of overlays ("+show-rejected"). */
  overlays?: string;
  /** Iterations per Step and Step back, 1 to 1000000. */
  'step-size'?: string;
  'raw-path'?: string;
  /** A spatial arm's 3-D camera: `tx,ty,tz,yaw,pitch,distance`. */
  camera?: string;
  /** The top view zoomed in: `zoom,cx,cy` (zoom 1 … 256 times the fitted scale, the world point at its centre). */
  zoom?: string;
  /** Run once at least half the element is on screen. */
  autoplay?: string;
  /** A ▶ Run button over the canvas; the run starts on the first click. */
  click?: string;
  /** Comma-separated controls; empty: none. */
  controls?: string;
  /** Planner parameters in link form ("range=0.1&goal_bias=0.2"). */
  params?: string;
  /** A whole share link's hash; the other attributes win over it. */
  link?: string;
  /** Fill the height the element is given instead of following the scenario's aspect ratio. */
  fill?: string;
}

/** `loaded`: a scenario and its planner set-up are ready to run (after each attribute change too). */
export interface PlaygroundLoadedDetail {
  /** The scenario's name ("Narrow passage"). */
  scenario: string;
  /** The planner's registry name ("rrt-connect"). */
  planner: string;
  /** The planner's label as the page shows it ("RRT-Connect"). */
  plannerLabel: string;
  seed: number | null;
}

/** `run`: a run starts (Run, autoplay, click to start) or resumes after a pause. */
export interface PlaygroundRunDetail {
  /** The scenario's name ("Narrow passage"). */
  scenario: string;
  planner: string;
  seed: number | null;
  /** The run goes on from a pause. */
  resumed: boolean;
  /** Started by `autoplay`, no control used yet. */
  autoplay: boolean;
}

/** `step`: the answer to a Step (the button, → or step()) is shown; the run is paused there. */
export interface PlaygroundStepDetail {
  /** Iterations and nodes drawn. */
  iterations: number;
  nodes: number;
  /** Iterations per step (the `step-size` attribute). */
  stepSize: number;
  /** The status word: "paused", or the planner's terminal status ("solved") when the step ended the run. */
  status: string;
}

/** `solved`: a run ended with a path, all its events shown. */
export interface PlaygroundSolvedDetail {
  scenario: string;
  planner: string;
  seed: number | null;
  iterations: number;
  nodes: number;
  /** The path's cost as the planner reports it; null when it reports none. */
  cost: number | null;
}

export interface PlaygroundEventMap {
  loaded: CustomEvent<PlaygroundLoadedDetail>;
  run: CustomEvent<PlaygroundRunDetail>;
  step: CustomEvent<PlaygroundStepDetail>;
  solved: CustomEvent<PlaygroundSolvedDetail>;
}

/** A spatial arm's 3-D view. */
export interface PlaygroundView3dState {
  active: boolean;
  ready: boolean;
  camera: { target: [number, number, number]; yaw: number; pitch: number; distance: number } | null;
}

export class PlanariumPlayground extends HTMLElement {
  static readonly observedAttributes: string[];
  /** The player's state. */
  readonly state: PlaygroundState;
  /** The status word: the state, or the planner's terminal status ("solved", "no_path", …) once finished. */
  readonly status: string;
  /** Tree nodes drawn. */
  readonly nodeCount: number;
  /** Planner iterations whose events are all drawn. */
  readonly shownIterations: number;
  /** The controls shown (Reset joins them once an autoplay run has ended). */
  readonly controls: PlaygroundControl[];
  /** The finished run's result (a copy), null before. */
  result(): Record<string, unknown> | null;
  /** The status line's numbers and the worker's stats. */
  stats(): Record<string, unknown> | null;
  view3dState(): PlaygroundView3dState;
  /** The top view's zoom and centre, null while the workspace is fitted. */
  readonly zoom: { zoom: number; cx: number; cy: number } | null;
  /** Each returns whether it acted (false when the state does not allow it). */
  run(): boolean;
  pause(): boolean;
  /** From a finished run: replay it from its start, one step. */
  step(): boolean;
  back(): boolean;
  reset(): boolean;

  addEventListener<K extends keyof PlaygroundEventMap>(type: K, listener: (this: PlanariumPlayground, ev: PlaygroundEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions): void;
  addEventListener<K extends keyof HTMLElementEventMap>(type: K, listener: (this: PlanariumPlayground, ev: HTMLElementEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  removeEventListener<K extends keyof PlaygroundEventMap>(type: K, listener: (this: PlanariumPlayground, ev: PlaygroundEventMap[K]) => unknown,
    options?: boolean | EventListenerOptions): void;
  removeEventListener<K extends keyof HTMLElementEventMap>(type: K, listener: (this: PlanariumPlayground, ev: HTMLElementEventMap[K]) => unknown,
    options?: boolean | EventListenerOptions): void;
  removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
}

declare global {
  interface HTMLElementTagNameMap {
    'planarium-playground': PlanariumPlayground;
  }
}

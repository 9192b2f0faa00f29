// A type test of www/planarium-playground.d.ts (tsc -p . checks it; nothing runs it): the element's
// events carry their detail types, its methods and properties are typed, and misuse is an error.
import type { PlanariumPlayground, PlaygroundLoadedDetail, PlaygroundRunDetail, PlaygroundSolvedDetail, PlaygroundStepDetail, PlaygroundState } from '../../www/planarium-playground.js';

const el = document.querySelector('planarium-playground');
if (el) {
  const typed: PlanariumPlayground = el;
  typed.addEventListener('run', (e) => {
    const d: PlaygroundRunDetail = e.detail;
    const seed: number | null = d.seed;
    const resumed: boolean = d.resumed;
    void [seed, resumed];
  });
  typed.addEventListener('step', (e) => {
    const d: PlaygroundStepDetail = e.detail;
    const n: number = d.iterations + d.nodes + d.stepSize;
    void n;
  });
  typed.addEventListener('solved', (e) => {
    const d: PlaygroundSolvedDetail = e.detail;
    const cost: number | null = d.cost;
    // @ts-expect-error the cost is a number, not text
    const sure: string = d.cost;
    void [cost, sure];
  });
  typed.addEventListener('loaded', (e) => {
    const d: PlaygroundLoadedDetail = e.detail;
    const name: string = d.scenario;
    const label: string = d.plannerLabel;
    void [name, label];
  });
  typed.addEventListener('click', (e) => { const x: number = e.clientX; void x; });
  const state: PlaygroundState = typed.state;
  const acted: boolean = typed.run() && typed.step() && typed.reset();
  // @ts-expect-error not a state
  const wrong: PlaygroundState = 'sleeping';
  // @ts-expect-error the step event's detail has no cost
  typed.addEventListener('step', (e) => e.detail.cost);
  void [state, acted, wrong];
}

// More queries on a finished roadmap run (PRM, PRM*, Lazy PRM): "New query" asks for two clicks on
// the map, the query's start and its goal; the worker answers on the same roadmap (the core's
// Run.query: the two states join the roadmap by the planner's rule, no milestone is added, and the
// roadmap is searched; Lazy PRM checks the edges the search uses). The query's events are shown as
// the run's are (the terminals' edges, the checks, the search's path), and the answer is drawn over
// the run's path with its cost in the status line. Point and rigid robots only (a rigid robot keeps
// the scenario start's heading); arms and vehicle chains are not offered it. Every text shown is
// built from numbers and fixed words (textContent).

import { dragsHeading, plannerCaps } from '../draw/capabilities.js';

/** Whether planner `name` answers further queries on what it built (the registry's `caps.queries`). */
export const answersQueries = (name) => plannerCaps(name).queries;

const fmt = (v) => (Math.abs(v) >= 100 ? v.toFixed(1) : v.toFixed(3));

/**
 * Wire the button and status line. `applies()`: whether a query can be asked now (a finished
 * roadmap run of a point or rigid robot); `scenario()`: the scenario shown; `lane`: the playground's
 * lane. Returns sync(): call it when the page's state changes.
 * @param {{button: HTMLButtonElement, status: HTMLElement, canvas: HTMLCanvasElement, view: any,
 *   lane: any, applies: () => boolean, scenario: () => any}} options
 */
export function wireRoadmapQuery({ button, status, canvas, view, lane, applies, scenario }) {
  /** @type {null | number[][]} the clicked points while picking */
  let picking = null;
  let asked = 0;
  let picks = []; // the latest query's two clicks
  const say = (text) => { status.textContent = text; reveal(); };

  // On a phone the run bar is one row that scrolls sideways (style.css), and the status, last in
  // it, would be off screen: scroll the bar (not the page) until it shows.
  function reveal() {
    const bar = status.parentElement;
    if (!bar || status.hidden || !status.textContent || bar.scrollWidth <= bar.clientWidth) return;
    const b = bar.getBoundingClientRect(), s = status.getBoundingClientRect();
    if (s.right > b.right) bar.scrollLeft += Math.min(s.right - b.right, s.left - b.left);
    else if (s.left < b.left) bar.scrollLeft -= b.left - s.left;
  }

  function sync() {
    const on = applies();
    button.hidden = !on;
    status.hidden = !on;
    if (!on) {
      picking = null;
      asked = 0;
      view.setQuery?.(null);
      say('');
    }
  }

  function stop(text) {
    picking = null;
    view.setQuery?.(view.query ? { ...view.query, picks: [] } : null);
    say(text);
  }

  button.addEventListener('click', () => {
    if (!applies()) return;
    picking = [];
    view.setQuery?.({ points: [], picks: [] });
    say("Click the query's start on the map (Escape cancels).");
  });

  // On the canvas's parent, capturing: it runs before the canvas's own listeners (the editors'),
  // so the query's clicks are not edits: the start/goal drag and the drawing tools never see them.
  (canvas.parentElement ?? canvas).addEventListener('pointerdown', (e) => {
    const L = view.layout;
    if (!picking || !L || e.target !== canvas) return;
    e.preventDefault();
    e.stopImmediatePropagation();
    const p = [L.wx(e.offsetX * L.dpr), L.wy(e.offsetY * L.dpr)];
    picking.push(p);
    view.setQuery?.({ points: [], picks: [...picking] });
    if (picking.length < 2) { say(`Start (${fmt(p[0])}, ${fmt(p[1])}): now click the goal.`); return; }
    const sc = scenario();
    const state = (/** @type {number[]} */ [x, y]) => (dragsHeading(sc?.robot) ? [x, y, Number(sc.start?.[2]) || 0] : [x, y]);
    const [a, b] = picking;
    picks = picking;
    picking = null;
    asked++;
    say(`Query ${asked}: searching the roadmap…`);
    lane.query(state(a), state(b));
  }, true);

  document.addEventListener('keydown', (e) => {
    if (e.key === 'Escape' && picking) stop('Query cancelled.');
  });

  /** The worker's answer (lane hook). */
  function answered(answer) {
    if (answer.error) {
      view.setQuery?.({ points: [], picks });
      say(`Query ${asked}: ${answer.error}`);
      return;
    }
    const points = answer.points || [];
    view.setQuery?.({ points, picks, cost: answer.cost });
    say(points.length
      ? `Query ${asked}: ${points.length} states, cost ${fmt(answer.cost)}, on the same roadmap.`
      : `Query ${asked}: the roadmap does not join these two states (yet).`);
  }

  return { sync, answered };
}

// The stats panel: a <dl> built from one field table, filled from Lane.statsFor(). The playground
// and each lane of the compare page use it, with an id prefix. Rows marked `optional` are hidden
// while they have no value (the best cost only exists for planners that keep improving, the
// coverage only for inspection, the sampler's rows only for planners that draw through it, raw
// tries and the checks per sample only for validity-checking samplers, the edges only for roadmaps,
// the optimum only where the visibility graph's path is the robot's optimum, the course's and the
// continuous coverage and the fk cost only in a finished result that has them). While the replay
// is behind the planner, iterations and nodes are those drawn ("112 of 349") and the numbers only
// the planner knows are marked "(final)" (or "(planner)" while it still runs). The iteration and
// "Checks" rows say, on hover, what the chosen planner counts (the core's registry). Counts are
// grouped as the status strip groups them ("13,909"); times and costs are shown as they are.

import { el } from './dom.js';
import { shown } from './text.js';
import { formatValue } from '../draw/chart.js';

const fixed = (v, n) => (v === undefined || v === null || !Number.isFinite(v) ? undefined : v.toFixed(n));

/** The run's sampler summary, or undefined when the planner draws no samples through one (EST, grid). */
const sampler = (s) => (s.sampler?.used === false ? undefined : s.sampler);

/** "112 of 349" while the replay is behind the planner, else the number. */
const ofPlanner = (shown, planner) => (planner === undefined || planner === shown ? count(shown) : `${count(shown)} of ${count(planner)}`);

/** An integer count grouped as the status strip groups it ("13,909"); decimals keep `fixed`. */
const count = (v) => (Number.isFinite(v) ? v.toLocaleString('en') : undefined);

/** "12.1 (visibility graph): this path +6.7%" (the path's raw cost against the optimum). */
function optimumText(s) {
  if (!Number.isFinite(s.optimum)) return undefined;
  const above = Number.isFinite(s.cost) && s.optimum > 0 ? 100 * (s.cost / s.optimum - 1) : null;
  const pct = above === null ? '' : Math.abs(above) < 0.05 ? '0.0' : `${above > 0 ? '+' : ''}${above.toFixed(1)}`;
  return `${formatValue(s.optimum)} (visibility graph)${pct ? `: this path ${pct}%` : ''}`;
}

// Status words shown differently from the worker's (the rest are shown as they are).
const STATUS_TEXT = Object.freeze({ no_path: 'no path' });

export const STAT_FIELDS = Object.freeze([
  { key: 'reason', label: 'Why', optional: true, className: 'reason', value: (s) => s.reason || undefined,
    title: 'Why the run ended: the planner can tell, by its method, that it finds no path (no path), or what holds the memory a run may use and what to change (memory_limit)' },
  { key: 'time', label: 'Time (ms)', planner: true, value: (s) => fixed(s.time_ms, 1) },
  { key: 'iterations', label: 'Iterations', value: (s) => ofPlanner(s.iterations, s.planner_iterations),
    title: 'Iterations drawn (of the planner\'s, while the replay is behind it)' },
  { key: 'nodes', label: 'Nodes', value: (s) => ofPlanner(s.nodes, s.planner_nodes),
    title: 'Nodes drawn (of the planner\'s, while the replay is behind it)' },
  { key: 'checks', label: 'Checks', planner: true, value: (s) => count(s.checks),
    title: 'State validity checks, those inside motion checks included' },
  { key: 'edges-checked', label: 'Edges checked', optional: true, planner: true,
    value: (s) => (s.roadmap ? `${count(s.roadmap.edges_checked)} (${count(s.roadmap.edges_invalid)} blocked)` : undefined),
    title: 'Edge motions checked (PRM, PRM*: every candidate edge; Lazy PRM: those a query path used), and of those, found blocked' },
  { key: 'edges', label: 'Edges in roadmap', optional: true, planner: true, value: (s) => count(s.roadmap?.edges),
    title: 'Edges the roadmap holds: checked valid, or (Lazy PRM) not yet checked' },
  { key: 'cost', label: 'Cost', planner: true, value: (s) => fixed(s.cost, 4) },
  { key: 'smoothed-cost', label: 'Smoothed cost', planner: true, value: (s) => fixed(s.smoothed_cost, 4) },
  { key: 'optimum', label: 'Optimum', optional: true, value: optimumText,
    title: "The shortest path's cost, from the visibility graph (a point or a disc robot), and how far above it this run's raw path is" },
  { key: 'best-cost', label: 'Best cost so far', optional: true, value: (s) => fixed(s.best_cost, 4),
    title: 'The cost of the best solution in the events shown (it keeps improving)' },
  { key: 'coverage', label: 'Coverage', optional: true,
    value: (s) => (s.coverage == null ? undefined
      : `${(100 * s.coverage).toFixed(1)}%${s.points_seen != null ? ` (${count(s.points_seen) ?? s.points_seen} seen)` : ''}`),
    title: "The best branch's share of inspection points seen, in the events shown" },
  { key: 'coverage-both', label: 'Course / continuous', optional: true,
    value: (s) => (s.course_coverage == null || s.continuous_coverage == null ? undefined
      : `${(100 * s.course_coverage).toFixed(1)}% / ${(100 * s.continuous_coverage).toFixed(1)}%`),
    title: "The path's coverage counted at its vertices with touching hiding (the Technion course's) / along its edges (Planarium's continuous count)" },
  { key: 'cost-fk', label: 'Cost (fk)', optional: true,
    value: (s) => (s.cost_fk == null ? undefined
      : `${fixed(s.cost_fk, 1)} (smoothed ${fixed(s.smoothed_cost_fk, 1) ?? '–'})`),
    title: "An arm's path cost in report 004's unit: the norm of the stacked link-end differences, summed" },
  { key: 'sampler', label: 'Sampler', optional: true, value: (s) => sampler(s)?.name },
  { key: 'draws', label: 'Draws / sample', optional: true, value: (s) => fixed(sampler(s)?.draws_per_sample, 2),
    title: "The sampler's raw draws per sample it handed to the planner" },
  { key: 'sampler-checks', label: 'Checks / sample', optional: true,
    value: (s) => (sampler(s)?.checks_per_sample > 0 ? fixed(sampler(s).checks_per_sample, 2) : undefined),
    title: 'State checks the sampler spent per sample it handed to the planner' },
  { key: 'tries', label: 'Raw tries shown', optional: true,
    value: (s) => (s.tries_seen ? `${count(s.tries_sent)} of ${count(s.tries_seen)}` : undefined),
    title: 'Raw tries sent to the page / drawn by the sampler (after the first 50 000 the worker thins them)' },
  { key: 'shown', label: 'Nodes shown', value: (s) => `${count(s.shown_nodes) ?? s.shown_nodes} (${count(s.queued_events) ?? s.queued_events} events queued)` },
]);

/**
 * Build the stats list into `dl` (ids `${prefix}status`, `${prefix}stat-<key>`); returns
 * update(stats) which fills it, and update.setPlanner(spec) which puts the registry planner's
 * words on the iteration and "Checks" rows' hover text.
 */
export function createStats(dl, prefix = '') {
  const statusDd = el('dd', { id: `${prefix}status`, text: 'idle' });
  statusDd.setAttribute('aria-live', 'polite');
  const rows = [el('div', {}, el('dt', { text: 'Status' }), statusDd)];
  const cells = STAT_FIELDS.map((f) => {
    const dd = el('dd', { id: `${prefix}stat-${f.key}`, text: '–', className: f.className || '' });
    const dt = el('dt', { text: f.label, title: f.title || '' });
    const row = el('div', { className: 'stat-row' }, dt, dd);
    row.dataset.stat = f.key;
    rows.push(row);
    return { f, dd, dt, row };
  });
  dl.replaceChildren(...rows);
  // row key → the registry's words, and whether the row's own hover text follows them
  const said = { iterations: ['iteration', true], checks: ['checks', false] };
  function update(s) {
    const word = STATUS_TEXT[s.status] || s.status;
    if (statusDd.textContent !== word) statusDd.textContent = word; // a live region: written when it changes
    statusDd.dataset.status = s.status;
    for (const { f, dd, row } of cells) {
      let v;
      try { v = f.value(s); } catch { v = undefined; }
      const none = v === undefined || v === null || Number.isNaN(v);
      const mark = !none && f.planner && s.behind ? ` (${s.behind})` : '';
      dd.textContent = none ? '–' : shown(String(v)) + mark; // a reason may echo the scenario
      if (f.optional) row.hidden = none;
    }
  }
  update.setPlanner = (spec) => {
    for (const { f, dt } of cells) {
      const [word, keep] = said[f.key] ?? [];
      const words = word && spec?.[word];
      dt.title = words ? [`${spec.label}: ${words}`, keep ? f.title : ''].filter(Boolean).join('\n') : f.title || '';
    }
  };
  return update;
}

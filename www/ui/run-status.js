// The status strip above the playground's canvas: what the replay shows against what the planner
// did ("replaying ≈9 of 50 iterations · planner finished in 8.3 ms"; ≈ marks an interpolation
// inside a worker batch).

const n = (v) => (Number.isFinite(v) ? v : 0).toLocaleString('en');

/**
 * The strip's text. `state`: the controller's; `config`: the panel's {planner, seed} (or none);
 * `label`: the planner's label; `planner`: the planner's stats so far; `done`, `finalStatus`,
 * `solved`: the run's end; `replay`: {iteration, exact} shown; `nodes`: the stats panel's node count (the
 * planner's once the replay has caught up), so the two never disagree.
 */
export function runStatusText({ state, config, label, planner, done, finalStatus, solved, replay, nodes }) {
  const total = planner?.iterations ?? 0;
  const ms = planner && Number.isFinite(planner.time_ms) ? `${planner.time_ms.toFixed(1)} ms` : '';
  const plannerPart = done ? `planner finished in ${ms}` : planner ? `planner at ${n(total)} iterations` : '';
  switch (state) {
    case 'loading': return 'Loading…';
    case 'invalid': return 'No valid scenario: pick a built-in or open a file.';
    case 'idle': return config ? `Ready: Run starts ${label || config.planner}, seed ${config.seed}.` : 'Ready.';
    case 'finished': {
      const word = finalStatus || (solved ? 'solved' : 'finished');
      return `${word.replace('_', ' ')} · ${n(total)} iterations · ${n(nodes)} nodes · ${plannerPart}`;
    }
    default: {
      const verb = state === 'paused' ? 'paused at' : 'replaying';
      return `${verb} ${replay.exact ? '' : '≈'}${n(replay.iteration)} of ${n(total)} iterations${plannerPart ? ` · ${plannerPart}` : ''}`;
    }
  }
}

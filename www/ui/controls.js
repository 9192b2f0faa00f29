// Small helpers the playground and the compare page share: the scenario picker, the
// playback-speed and animation sliders, and which live chart a planner gets.

import { EventKind } from '../run/events.js';
import { shown } from './text.js';

/**
 * Seconds the whole run's replay takes for the playback slider `input` (0 to its maximum: 60 s
 * down to 1 s, evenly in the logarithm; its maximum: 0, all at once). Slow, Normal and Fast are
 * its values 10, 33 and 60: 40, 15 and 5 s (playback.js paces by them: pace.js).
 */
export function speedSeconds(input) {
  const v = Number(input.value);
  const max = Number(input.max);
  if (!(v < max)) return 0;
  const s = 60 * 60 ** (-Math.max(0, v) / (max - 1));
  return s >= 10 ? Math.round(s) : Math.round(s * 10) / 10;
}

/** The playback slider's value in words. */
export function describeSpeed(input) {
  const s = speedSeconds(input);
  return s > 0 ? `whole run in ${s} s` : 'all at once';
}

/** Robot animation frames per second for the animation slider `input`. */
export function animFps(input) { return 10 ** (0.5 + (2.5 * Number(input.value)) / 100); }

// Parameters that only a planner which keeps improving its solution takes (RRT*'s).
const ANYTIME_PARAMS = ['rewire', 'rewire_factor', 'improve_for'];

/**
 * The live chart for registry planner `p`: 'coverage' for an inspection planner, 'cost' for one
 * that keeps improving (it has an anytime parameter, or the run already reported a cost in
 * `model`), else null.
 */
export function chartKind(p, model = null) {
  if (!p) return null;
  if (p.task === 'inspection') return 'coverage';
  if (p.params.some((s) => ANYTIME_PARAMS.includes(s.name))) return 'cost';
  if (model && model.costs.length) return 'cost';
  return null;
}

/** What the shown events say, for tests and the console (window.planarium.model()). */
export function modelSummary(model, chart = null) {
  const count = (kind) => model.counts[kind] || 0;
  return {
    chart: chart ? chart.kind : null,
    optimum: chart ? chart.optimum : null,
    trees: model.trees.map((t) => ({ nodes: t.n, domains: t.domains, exhausted: t.exhausted })),
    tries: count(EventKind.SAMPLE_TRY),
    rewires: count(EventKind.REWIRE),
    roadmap: { edges: count(EventKind.ROADMAP_EDGE), checked: count(EventKind.EDGE_CHECKED), pathEdges: count(EventKind.QUERY_PATH) },
    costs: model.costs.map((c) => c.slice()),
    coverage: model.coverage.map((c) => c.slice()),
    informed: model.informed.map((e) => e.slice()),
    seen: [...model.seen],
    best: model.best ? { ...model.best } : null,
    bestBranch: model.bestBranch().length,
  };
}

/**
 * Fill the scenario `<select>` with the built-ins grouped by course (in the order given) and select
 * the one named by the page's `?scenario=` (else the first). Returns the selected built-in.
 */
export function fillScenarioPicker(select, builtins) {
  const groups = new Map(); // course → optgroup
  for (const b of builtins) {
    if (!groups.has(b.course)) {
      const g = document.createElement('optgroup');
      g.label = b.course || 'Other';
      groups.set(b.course, g);
      select.append(g);
    }
    groups.get(b.course).append(new Option(b.name, b.id));
  }
  const first = builtins.find((b) => b.id === new URLSearchParams(location.search).get('scenario')) || builtins[0];
  select.value = first.id;
  return first;
}

/** Fill the legend list `ul` with items [{label, color, shape}] (a swatch and its words). */
export function fillLegend(ul, items) {
  ul.replaceChildren(...items.map(({ label, color, shape }) => {
    const li = document.createElement('li');
    const sw = document.createElement('span');
    sw.className = `swatch ${shape}`;
    sw.style.setProperty('--c', color);
    sw.setAttribute('aria-hidden', 'true');
    li.append(sw, document.createTextNode(label));
    return li;
  }));
}

/**
 * The page's error box: `show(text)` (as text, never HTML, bidirectional controls written out:
 * text.js shown) and `clear()`.
 */
export function errorBox(box, textEl) {
  return {
    show(text) {
      textEl.textContent = shown(text);
      box.hidden = false;
    },
    clear() {
      box.hidden = true;
      textEl.textContent = '';
    },
  };
}

/** Take out of scenario picker `select` the entries of scenarios that are not built-ins. */
export function removeCustomScenarios(select) {
  for (const o of [...select.options]) if (o.dataset.file) o.remove();
}

/** Show `label` in scenario picker `select`, chosen, for a scenario that is not a built-in. */
export function markCustomScenario(select, label) {
  removeCustomScenarios(select);
  const opt = new Option(shown(label), '', true, true);
  opt.dataset.file = 'yes';
  opt.disabled = true;
  select.append(opt);
  select.value = '';
  opt.selected = true;
}

/**
 * What the playground says about a scenario the core refused: `error` {path, line, column,
 * message}; `edit`: it came from an edit of the start or goal (which can be undone or dragged back).
 */
export function invalidText(error, edit) {
  const where = [error.path, error.line != null ? `line ${error.line}` : null,
    error.column != null ? `column ${error.column}` : null].filter(Boolean).join(', ');
  if (edit) {
    const which = /^(start|goal)\b/.exec(error.path || '')?.[1] || 'start or goal';
    return `After this edit the ${which} is not valid${/^(start|goal)$/.test(error.path) ? '' : ` at ${where}`}: `
      + `${error.message || error.text}\nUndo it (ctrl+Z), move it to a free place, or pick another scenario.`;
  }
  return `This scenario has an error${where ? ` at ${where}` : ''}: ${error.message || error.text}`;
}

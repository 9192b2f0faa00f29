// The planner panel, generated from the registry the worker posts in `ready`
// ({planners: [{name, label, summary, params: [ParamSpec], groups: [{name, label, params}],
// task: 'goal' | 'inspection'}], run_params: [ParamSpec]}), as OMPL generates parameter UIs from
// declareParam. No planner is named in this file.
//
// ParamSpec: {name, label, kind: 'real' | 'int' | 'choice', min, max, default, options, doc, applies}.
// `applies` (null: always) is when the parameter acts: a parameter that does not act under the
// values chosen is hidden, its value kept (see `applies`).
// A planner's own parameters come first, then one fieldset per shared group (the sampler, the tree
// variants), then the run's limits. Values set in a group are shared by every planner that has
// the group (a planner's own parameter of the same name is already left out of its group).
// Only values the user set (or the scenario's `planner` block supplied) are sent; the rest keep
// the core's defaults.
//
// Planners are offered by task: goal planners only when the scenario has a goal, inspection
// planners only when it has inspection points (setTask); a note says what is left out and why.

import { el } from './dom.js';
import { readSeed, blockSeedProblem } from './seed.js';

/** How many of a planner's own parameters the panel shows before "More parameters". */
export const MAIN_PARAMS = 3;

/**
 * Whether a parameter applies under the values chosen, from its spec's `applies` (the core's
 * condition: `{param, one_of: [names]}` or `{param, above: 0}`; null: always). `value(name)` gives
 * a parameter's value (set, or its default).
 * @param {{applies?: {param: string, one_of?: string[], above?: number} | null}} spec
 * @param {(name: string) => any} value
 */
export function applies(spec, value) {
  const c = spec.applies;
  if (!c) return true;
  if (Array.isArray(c.one_of)) return c.one_of.includes(value(c.param));
  if (typeof c.above === 'number') return Number(value(c.param)) > c.above;
  return true;
}

/** Parse an input's text for `spec`: {ok, value} or {ok: false, why}. Empty text: {ok, value: undefined}. */
export function parseParam(spec, text) {
  if (spec.kind === 'choice') {
    return spec.options.includes(text) ? { ok: true, value: text } : { ok: false, why: `one of ${spec.options.join(', ')}` };
  }
  if (String(text).trim() === '') return { ok: true, value: undefined };
  const v = Number(text);
  if (!Number.isFinite(v)) return { ok: false, why: 'a number' };
  if (spec.kind === 'int' && !Number.isInteger(v)) return { ok: false, why: 'a whole number' };
  if (v < spec.min || v > spec.max) return { ok: false, why: `between ${spec.min} and ${spec.max}` };
  return { ok: true, value: v };
}

/** What a scenario offers planners: {goal, inspection}. */
export function taskOf(scenario) {
  return { goal: !!(scenario && scenario.goal), inspection: !!(scenario?.inspection?.points?.length) };
}

/** Whether planner spec `p` can run on a scenario offering `task` ({goal, inspection}). */
export function plannerFits(p, task) {
  return (p.task || 'goal') === 'inspection' ? task.inspection : task.goal;
}

/**
 * Build the panel into `root`. `onChange(config)` is called after every valid change, with
 * config = {planner, params, seed}. Options: `prefix` for every element id (two panels on one
 * page), `seed: false` to leave the seed out (the caller supplies it), `title` for the planner
 * picker's label, `freshSeed` (a function) to offer a "New seed" button that calls it (the page asks
 * the core for a fresh seed and gives it back with setSeed). Returns {config(), apply(block),
 * setTask(task), planner(), setDisabled(bool), setSeed(n)}.
 */
export function createPanel(root, registry, onChange, { prefix = '', seed: withSeed = true, title = 'Planner', freshSeed = null } = {}) {
  const planners = registry.planners;
  const runParams = registry.run_params || [];
  const groupsOf = (p) => p.groups || [];
  const state = {
    planner: planners[0].name,
    seed: 1,
    task: { goal: true, inspection: true },
    set: Object.fromEntries(planners.map((p) => [p.name, {}])), // per-planner values the user set
    groups: {},                                                 // per-group values, shared
    run: {},                                                    // run-level values the user set
  };
  for (const p of planners) for (const g of groupsOf(p)) state.groups[g.name] ||= {};
  const controls = [];
  const fields = new Map(); // parameter name → {label, spec}, for `applies`
  const id = (name) => `${prefix}${name}`;

  const plannerSelect = el('select', { id: id('planner') });
  const note = el('p', { className: 'hint task-note', id: id('planner-note'), hidden: true, role: 'status' });
  const summary = el('p', { className: 'summary', id: id('planner-summary') });
  const params = el('fieldset', { className: 'params', id: id('planner-params') });
  const groupBox = el('div', { className: 'param-groups', id: id('param-groups') });
  const limits = el('fieldset', { className: 'params', id: id('run-params') });
  // The planner's first MAIN_PARAMS parameters stay in view; the rest, the groups (sampler, tree
  // variants) and the limits open on demand.
  const more = el('details', { className: 'more-params', id: id('more-params') });
  const moreSummary = el('summary', { text: 'More parameters' });
  const moreOwn = el('fieldset', { className: 'params', id: id('planner-more-params') });
  const seed = el('input', { id: id('seed'), type: 'number', min: '0', step: '1', value: '1', inputMode: 'numeric' });
  const seedHint = el('span', { className: 'hint' });
  const newSeed = el('button', { id: id('new-seed'), type: 'button', className: 'new-seed', text: 'New seed',
    title: 'A fresh random seed from the browser\'s entropy. It is shown here and goes into share links, so the run can be replayed.' });
  controls.push(plannerSelect, seed, newSeed);

  root.replaceChildren(
    el('label', { className: 'field', htmlFor: id('planner') }, el('span', { text: title }), plannerSelect),
    note,
    summary,
    params,
    more,
    ...(withSeed ? [el('label', { className: 'field', htmlFor: id('seed'), title: 'Random seed: the same seed replays the same run.' },
      el('span', { text: 'Seed' }), seed, ...(freshSeed ? [newSeed] : []), seedHint)] : []), // (replaceChildren would write a null as "null")
  );

  const emit = () => onChange(config());
  const current = () => planners.find((q) => q.name === state.planner);

  function config() {
    const p = current();
    const shared = {};
    for (const g of groupsOf(p)) {
      const store = state.groups[g.name] || {};
      for (const spec of g.params) if (Object.hasOwn(store, spec.name)) shared[spec.name] = store[spec.name];
    }
    return {
      planner: state.planner,
      params: { ...shared, ...state.set[state.planner], ...state.run },
      seed: state.seed,
    };
  }

  // One input per ParamSpec; `store` is the object its set values live in.
  function field(spec, store, kind) {
    const fid = id(`${kind}-${spec.name}`);
    let input;
    if (spec.kind === 'choice') {
      input = el('select', { id: fid, name: spec.name });
      for (const o of spec.options) input.append(el('option', { value: o, text: o }));
      input.value = store[spec.name] ?? spec.default;
    } else {
      input = el('input', {
        id: fid, name: spec.name, type: 'number', min: String(spec.min), max: String(spec.max),
        step: spec.kind === 'int' ? '1' : 'any', placeholder: String(spec.default),
        value: String(store[spec.name] ?? spec.default),
      });
    }
    const hint = el('span', { className: 'hint', text: spec.doc || '' });
    input.title = spec.doc || '';
    input.addEventListener('change', () => {
      const parsed = parseParam(spec, input.value);
      if (!parsed.ok) {
        input.setAttribute('aria-invalid', 'true');
        hint.textContent = `${spec.label} must be ${parsed.why}.`;
        hint.classList.add('bad');
        return;
      }
      input.removeAttribute('aria-invalid');
      hint.textContent = spec.doc || '';
      hint.classList.remove('bad');
      if (parsed.value === undefined) {
        delete store[spec.name];
        input.value = String(spec.default);
      } else {
        store[spec.name] = parsed.value;
      }
      syncApplies();
      emit();
    });
    controls.push(input);
    const label = el('label', { className: 'field', htmlFor: fid }, el('span', { text: spec.label }), input, hint);
    fields.set(spec.name, { label, spec });
    return label;
  }

  /** Show only the parameters that act under the values chosen (their specs' `applies`). */
  function syncApplies() {
    const p = current();
    const value = (name) => {
      const own = p.params.find((q) => q.name === name);
      if (own) return state.set[p.name][name] ?? own.default;
      for (const g of groupsOf(p)) {
        const spec = g.params.find((q) => q.name === name);
        if (spec) return state.groups[g.name][name] ?? spec.default;
      }
      return undefined;
    };
    const run = (name) => {
      const spec = runParams.find((q) => q.name === name);
      return spec ? state.run[name] ?? spec.default : undefined;
    };
    const any = (name) => value(name) ?? run(name);
    for (const { label, spec } of fields.values()) label.hidden = !applies(spec, any);
  }

  function renderOptions() {
    const fits = planners.filter((p) => plannerFits(p, state.task));
    plannerSelect.replaceChildren(...fits.map((p) => el('option', { value: p.name, text: p.label })));
    const left = planners.filter((p) => !plannerFits(p, state.task));
    const names = (list) => list.map((p) => p.label).join(', ');
    let text = '';
    if (!fits.length) {
      text = 'No planner fits this scenario: it has neither a goal nor inspection points.';
    } else if (left.length) {
      // Only the goal planners left out are said: every map without inspection points leaves the
      // inspection planner out, and a note on every map says nothing.
      const goalLeft = left.filter((p) => (p.task || 'goal') === 'goal');
      const need = goalLeft.length === 1 ? 'needs' : 'need';
      if (goalLeft.length) text = `Not offered here: ${names(goalLeft)} ${need} a goal, and this scenario has none.`;
    }
    note.textContent = text;
    note.hidden = !text;
    return fits;
  }

  function renderParams() {
    const p = current();
    plannerSelect.value = p.name;
    summary.textContent = p.summary || '';
    const keep = new Set([plannerSelect, seed]);
    controls.splice(0, controls.length, ...keep);
    fields.clear();
    params.replaceChildren(el('legend', { text: `${p.label} parameters` }));
    if (!p.params.length) params.append(el('p', { className: 'hint', text: 'No parameters.' }));
    const main = p.params.slice(0, MAIN_PARAMS), rest = p.params.slice(MAIN_PARAMS);
    for (const spec of main) params.append(field(spec, state.set[p.name], 'param'));
    moreOwn.replaceChildren(el('legend', { text: `More ${p.label} parameters` }));
    for (const spec of rest) moreOwn.append(field(spec, state.set[p.name], 'param'));
    moreOwn.hidden = !rest.length;
    groupBox.replaceChildren(...groupsOf(p).filter((g) => g.params.length).map((g) => {
      const box = el('fieldset', { className: 'params group-params', id: id(`group-${g.name}`) });
      box.dataset.group = g.name;
      box.append(el('legend', { text: g.label }));
      for (const spec of g.params) box.append(field(spec, state.groups[g.name], 'param'));
      return box;
    }));
    limits.replaceChildren(el('legend', { text: 'Limits and smoothing' }));
    for (const spec of runParams) limits.append(field(spec, state.run, 'run'));
    const n = rest.length + groupsOf(p).reduce((k, g) => k + g.params.length, 0) + runParams.length;
    moreSummary.textContent = `More parameters (${n}): ${[rest.length ? 'planner' : '', ...groupsOf(p).filter((g) => g.params.length).map((g) => g.label.toLowerCase()), 'limits'].filter(Boolean).join(', ')}`;
    more.replaceChildren(moreSummary, moreOwn, groupBox, limits);
    syncApplies();
    seed.value = String(state.seed);
  }

  plannerSelect.addEventListener('change', () => {
    state.planner = plannerSelect.value;
    renderParams();
    emit();
  });
  newSeed.addEventListener('click', () => freshSeed?.());
  /** Set the seed (a whole number ≥ 0, exact as a JavaScript number) and call onChange. */
  function setSeed(n) {
    if (!Number.isSafeInteger(n) || n < 0) return;
    state.seed = n;
    seed.value = String(n);
    seed.removeAttribute('aria-invalid');
    seedHint.textContent = '';
    emit();
  }
  seed.addEventListener('change', () => {
    const r = readSeed(seed.value);
    if (r.why) { // refused: the field shows the seed that runs, the hint why
      seedHint.textContent = `Seed: ${r.why}; the seed stays ${state.seed}.`;
      seed.value = String(state.seed);
      return;
    }
    seed.removeAttribute('aria-invalid');
    seedHint.textContent = '';
    state.seed = r.seed;
    emit();
  });

  /**
   * Offer the planners that fit `task` ({goal, inspection}, see taskOf). When the chosen planner
   * no longer fits, the first that does is chosen. Does not call onChange. Returns whether the
   * planner changed.
   */
  function setTask(task) {
    state.task = { goal: !!task.goal, inspection: !!task.inspection };
    const fits = renderOptions();
    const before = state.planner;
    if (fits.length && !fits.some((p) => p.name === state.planner)) state.planner = fits[0].name;
    renderParams();
    return state.planner !== before;
  }

  /**
   * Apply a scenario's `planner` block {name, seed, ...params}: it replaces what the user set.
   * Keys that are neither a parameter of that planner (its own or its groups') nor a run
   * parameter are ignored. A planner that does not fit the scenario's task is replaced by one that
   * does. Does not call onChange (the caller configures the worker once, after loading).
   */
  function apply(block) {
    if (!block) return;
    const fits = (q) => plannerFits(q, state.task);
    let p = planners.find((q) => q.name === block.name);
    if (!p || !fits(p)) {
      if (p) console.warn(`scenario planner block: ${p.name} does not fit this scenario's task`);
      p = planners.find((q) => q.name === state.planner && fits(q)) || planners.find(fits) || current();
    }
    state.planner = p.name;
    for (const name of Object.keys(state.set)) state.set[name] = {};
    for (const name of Object.keys(state.groups)) state.groups[name] = {};
    state.run = {};
    const unusable = blockSeedProblem(block.seed);
    if (unusable) {
      seedHint.textContent = `${unusable}; the seed stays ${state.seed}.`;
      seed.value = String(state.seed);
    } else if (block.seed !== undefined && block.seed !== null) {
      state.seed = block.seed;
      seedHint.textContent = '';
    }
    for (const [key, value] of Object.entries(block)) {
      if (key === 'name' || key === 'seed') continue;
      const spec = p.params.find((s) => s.name === key);
      const group = groupsOf(p).find((g) => g.params.some((s) => s.name === key));
      const runSpec = runParams.find((s) => s.name === key);
      if (spec) state.set[p.name][key] = value;
      else if (group) state.groups[group.name][key] = value;
      else if (runSpec) state.run[key] = value;
      else console.warn(`scenario planner block: ignoring ${key} (not a parameter of ${p.name})`);
    }
    renderParams();
  }

  function setDisabled(disabled) {
    for (const c of controls) c.disabled = disabled;
  }

  renderOptions();
  renderParams();
  return { config, apply, setTask, setDisabled, setSeed, planner: () => current() };
}

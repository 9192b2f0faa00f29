// The planner panel, generated from the registry the worker posts in `ready`
// ({planners: [{name, label, summary, params: [ParamSpec]}], run_params: [ParamSpec]}), as OMPL
// generates parameter UIs from declareParam. No planner is named in this file.
//
// ParamSpec: {name, label, kind: 'real' | 'int' | 'choice', min, max, default, options, doc}.
// Only values the user set (or the scenario's `planner` block supplied) are sent; the rest keep
// the core's defaults.

import { el } from './dom.js';

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

/**
 * Build the panel into `root`. `onChange(config)` is called after every valid change, with
 * config = {planner, params, seed}. Returns {config(), apply(block), setDisabled(bool)}.
 */
export function createPanel(root, registry, onChange) {
  const planners = registry.planners;
  const runParams = registry.run_params || [];
  const state = {
    planner: planners[0].name,
    seed: 1,
    set: Object.fromEntries(planners.map((p) => [p.name, {}])), // per-planner values the user set
    run: {},                                                    // run-level values the user set
  };
  const controls = [];

  const plannerSelect = el('select', { id: 'planner' });
  for (const p of planners) plannerSelect.append(el('option', { value: p.name, text: p.label }));
  const summary = el('p', { className: 'summary', id: 'planner-summary' });
  const params = el('fieldset', { className: 'params', id: 'planner-params' });
  const limits = el('fieldset', { className: 'params', id: 'run-params' });
  const seed = el('input', { id: 'seed', type: 'number', min: '0', step: '1', value: '1', inputMode: 'numeric' });
  const seedHint = el('span', { className: 'hint' });
  controls.push(plannerSelect, seed);

  root.replaceChildren(
    el('label', { className: 'field', htmlFor: 'planner' }, el('span', { text: 'Planner' }), plannerSelect),
    summary,
    params,
    limits,
    el('label', { className: 'field', htmlFor: 'seed', title: 'Random seed: the same seed replays the same run.' },
      el('span', { text: 'Seed' }), seed, seedHint),
  );

  const emit = () => onChange(config());

  function config() {
    return {
      planner: state.planner,
      params: { ...state.set[state.planner], ...state.run },
      seed: state.seed,
    };
  }

  // One input per ParamSpec; `store` is the object its set values live in.
  function field(spec, store, prefix) {
    const id = `${prefix}-${spec.name}`;
    let input;
    if (spec.kind === 'choice') {
      input = el('select', { id, name: spec.name });
      for (const o of spec.options) input.append(el('option', { value: o, text: o }));
      input.value = store[spec.name] ?? spec.default;
    } else {
      input = el('input', {
        id, name: spec.name, type: 'number', min: String(spec.min), max: String(spec.max),
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
      emit();
    });
    controls.push(input);
    return el('label', { className: 'field', htmlFor: id }, el('span', { text: spec.label }), input, hint);
  }

  function renderParams() {
    const p = planners.find((q) => q.name === state.planner);
    plannerSelect.value = p.name;
    summary.textContent = p.summary || '';
    const keep = new Set([plannerSelect, seed]);
    controls.splice(0, controls.length, ...keep);
    params.replaceChildren(el('legend', { text: `${p.label} parameters` }));
    if (!p.params.length) params.append(el('p', { className: 'hint', text: 'No parameters.' }));
    for (const spec of p.params) params.append(field(spec, state.set[p.name], 'param'));
    limits.replaceChildren(el('legend', { text: 'Limits and smoothing' }));
    for (const spec of runParams) limits.append(field(spec, state.run, 'run'));
    seed.value = String(state.seed);
  }

  plannerSelect.addEventListener('change', () => {
    state.planner = plannerSelect.value;
    renderParams();
    emit();
  });
  seed.addEventListener('change', () => {
    const v = Number(seed.value);
    if (seed.value.trim() === '' || !Number.isSafeInteger(v) || v < 0) {
      seed.setAttribute('aria-invalid', 'true');
      seedHint.textContent = 'The seed must be a whole number ≥ 0.';
      return;
    }
    seed.removeAttribute('aria-invalid');
    seedHint.textContent = '';
    state.seed = v;
    emit();
  });

  /**
   * Apply a scenario's `planner` block {name, seed, ...params}: it replaces what the user set.
   * Keys that are neither a parameter of that planner nor a run parameter are ignored.
   * Does not call onChange (the caller configures the worker once, after loading).
   */
  function apply(block) {
    if (!block) return;
    const p = planners.find((q) => q.name === block.name) || planners.find((q) => q.name === state.planner);
    state.planner = p.name;
    for (const name of Object.keys(state.set)) state.set[name] = {};
    state.run = {};
    if (Number.isSafeInteger(block.seed) && block.seed >= 0) state.seed = block.seed;
    for (const [key, value] of Object.entries(block)) {
      if (key === 'name' || key === 'seed') continue;
      const spec = p.params.find((s) => s.name === key);
      const runSpec = runParams.find((s) => s.name === key);
      if (spec) state.set[p.name][key] = value;
      else if (runSpec) state.run[key] = value;
      else console.warn(`scenario planner block: ignoring ${key} (not a parameter of ${p.name})`);
    }
    renderParams();
  }

  function setDisabled(disabled) {
    for (const c of controls) c.disabled = disabled;
  }

  renderParams();
  return { config, apply, setDisabled };
}

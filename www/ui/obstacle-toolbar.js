// The obstacle editor's toolbar (obstacle-editor.js is its `host`): the tools, the actions (Delete,
// Undo, Redo, Save JSON, New map, Clear walls, Clear obstacles), the tool's hint, the status line
// and the bounds' fields. It is built once, so a button pressed while a field's change re-renders
// is still there on release, and brought up to date from the editor's state by renderBar(). A
// bound that is not a number or crosses its opposite one is refused and says so.

import { el } from './dom.js';

/**
 * The toolbar, built once (a button pressed while a field's change re-renders must still be
 * there on release, so that its click arrives): tools, actions, the hint and the bounds.
 */
export function buildBar(host) {
  const tool = (id, label, title) => {
    const b = el('button', { id: `tool-${id}`, type: 'button', text: label, title });
    b.addEventListener('click', () => host.setTool(id));
    return b;
  };
  const act = (id, label, fn, title) => {
    const b = el('button', { id, type: 'button', text: label, title });
    b.addEventListener('click', fn);
    return b;
  };
  const tools = { select: tool('select', 'Select', 'Select, move and resize obstacles'), rect: tool('rect', 'Rectangle', 'Draw a rectangle'),
    circle: tool('circle', 'Circle', 'Draw a circle'), polygon: tool('polygon', 'Polygon', 'Draw a polygon'),
    cells: tool('cells', 'Cells', 'Paint walls on grid cells: drag from a free cell to paint, from a wall to erase') };
  const buttons = {
    del: act('obstacle-delete', 'Delete', () => host.deleteSelected(), 'Delete the selected obstacle (Delete)'),
    undo: act('undo', 'Undo', () => host.undo(), 'Undo (ctrl+Z)'),
    redo: act('redo', 'Redo', () => host.redo(), 'Redo (ctrl+shift+Z)'),
    save: act('save-scenario', 'Save JSON', () => host.save(), 'Download the scenario as JSON'),
    newMap: act('new-map', 'New map', () => host.newMap(), 'An empty map: the same bounds and robot, no obstacles (undo brings the old one back)'),
    walls: act('clear-walls', 'Clear walls', () => host.clearWalls(), 'Remove the painted cells; drawn shapes stay (undo brings them back)'),
    clear: act('clear-obstacles', 'Clear obstacles', () => host.clearObstacles(), 'Delete every obstacle (undo brings them back)'),
  };
  const bounds = el('div', { className: 'row bounds' });
  const boundsError = el('p', { id: 'bounds-error', className: 'hint bad', role: 'alert' });
  boundsError.hidden = true;
  const boundInputs = ['x min', 'y min', 'x max', 'y max'].map((label, i) => {
    const id = `bounds-${i}`;
    const input = el('input', { id, type: 'number', step: 'any' });
    input.addEventListener('change', () => {
      const s = host.scenario;
      const v = Number(input.value);
      boundsError.hidden = true;
      if (!s || host.editor.stale) return;
      const other = s.bounds[(i + 2) % 4];
      const why = input.value.trim() === '' || !Number.isFinite(v) ? `${label} must be a number`
        : (i < 2 ? v >= other : v <= other) ? `${label} must be ${i < 2 ? 'below' : 'above'} ${['x max', 'y max', 'x min', 'y min'][i]} (${other})` : '';
      if (why) {
        boundsError.textContent = `${why[0].toUpperCase()}${why.slice(1)}; it stays ${s.bounds[i]}.`;
        boundsError.hidden = false;
        input.value = String(s.bounds[i]);
        return;
      }
      s.bounds[i] = v;
      host.preview();
      host.commit();
    });
    bounds.append(el('label', { className: 'bound', htmlFor: id }, el('span', { text: label }), input));
    return input;
  });
  const hint = el('p', { className: 'hint' });
  const status = el('p', { id: 'edit-status', className: 'hint bad', role: 'status' });
  status.hidden = true;
  host.barParts = { tools, buttons, boundInputs, hint, status };
  host.bar.replaceChildren(
    el('div', { className: 'row tools', role: 'toolbar', 'aria-label': 'Obstacle tools' }, ...Object.values(tools)),
    el('div', { className: 'row' }, buttons.del, buttons.undo, buttons.redo, buttons.save),
    el('div', { className: 'row' }, buttons.newMap, buttons.walls, buttons.clear),
    hint,
    status,
    bounds,
    boundsError,
  );
}

/** The toolbar from the state: the pressed tool, what can be done, the hint, the bounds. */
export function renderBar(host) {
  const s = host.scenario;
  const { tools, buttons: b, boundInputs, hint } = host.barParts;
  for (const [id, button] of Object.entries(tools)) button.setAttribute('aria-pressed', String(host.tool === id));
  b.del.disabled = host.selected < 0;
  b.undo.disabled = !host.undoStack.length;
  b.redo.disabled = !host.redoStack.length;
  b.save.disabled = !s;
  b.newMap.disabled = !s;
  b.clear.disabled = !s?.obstacles?.length;
  const lat = s ? host.cells.lattice() : null;
  b.walls.disabled = !s?.obstacles?.some((ob) => host.cells.isPiece(ob, lat));
  boundInputs.forEach((input, i) => {
    input.disabled = !s;
    if (document.activeElement !== input) input.value = s ? String(s.bounds[i]) : '';
  });
  hint.textContent = {
    select: 'Click an obstacle to select it; drag it to move it, drag a square handle to resize it.',
    rect: 'Drag on the canvas to draw a rectangle.',
    circle: 'Drag from the centre to draw a circle.',
    polygon: 'Click the corners; double-click, press Enter or click the first corner to close it. Escape drops it.',
    cells: 'Drag from a free cell to paint walls, from a wall to erase them; drag the start or goal to move it. The cells are grid search\'s.',
  }[host.tool];
}

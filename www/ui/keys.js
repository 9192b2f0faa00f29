// The playground's keyboard and hover: Space runs or pauses, → steps (held: repeats), ← steps back,
// R resets, '.' steps one event, ? opens the keyboard help (a modal dialog: Escape or its button
// closes it, focus returns); never while typing in a field. Over the canvas, the decomposition cell
// or field tile under the pointer is described in a small box (text only).

/**
 * `actions`: the page's {run, pause, step, back, reset, stepEvent}; `running()`: whether a run is
 * playing; `help`: the help <dialog>, `open`/`close`: its buttons.
 */
export function wireKeys({ actions, running, help, open, close }) {
  const toggleHelp = () => { if (help.open) help.close(); else help.showModal(); };
  open.addEventListener('click', toggleHelp);
  close.addEventListener('click', () => help.close());
  document.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || e.repeat && e.key !== 'ArrowRight') return;
    if (e.shiftKey && e.key.startsWith('Arrow')) return; // shift + an arrow pans the map (plane-zoom.js)
    const t = e.target;
    if (t instanceof Element && t.closest('input, select, textarea, [contenteditable]')) return;
    if (e.key === ' ') {
      e.preventDefault(); // also keeps a focused button from being clicked by the same key
      if (running()) actions.pause(); else actions.run();
    } else if (e.key === 'ArrowRight') {
      e.preventDefault();
      actions.step();
    } else if (e.key === 'ArrowLeft') {
      e.preventDefault();
      actions.back();
    } else if (e.key === 'r' || e.key === 'R') {
      actions.reset();
    } else if (e.key === '.') {
      actions.stepEvent();
    } else if (e.key === '?') {
      e.preventDefault();
      toggleHelp();
    }
  });
}

/** The hover box over `canvas` (inside `stage`): `view.cells.describe` of the point under the pointer. */
export function wireCellTip({ canvas, stage, tip, view }) {
  const hide = () => { tip.hidden = true; };
  canvas.addEventListener('pointermove', (e) => {
    const L = view.layout;
    const lines = L && !e.buttons ? view.cells.describe(L.wx(e.offsetX * L.dpr), L.wy(e.offsetY * L.dpr), view.options) : null;
    if (!lines) { hide(); return; }
    tip.textContent = lines.join('\n');
    tip.hidden = false;
    const box = stage.getBoundingClientRect();
    const x = e.clientX - box.left + 14, y = e.clientY - box.top + 14;
    const w = tip.offsetWidth, h = tip.offsetHeight;
    tip.style.left = `${Math.max(0, x + w > box.width ? x - w - 28 : x)}px`;
    tip.style.top = `${Math.max(0, y + h > box.height ? y - h - 28 : y)}px`;
  });
  canvas.addEventListener('pointerleave', hide);
  canvas.addEventListener('pointerdown', hide);
}

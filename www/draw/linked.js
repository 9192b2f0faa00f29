// Linked views: what the pointer is over in one view, shown in the other.
//   c-space → workspace: hovering (q1, q2) on the configuration-space canvas of a 2-joint arm
//     draws a ghost arm in that pose on the workspace canvas, red where the c-space grid (the
//     core's answer, as drawn) says the pose collides, purple where it is free, and a small label
//     of the angles near its end effector;
//   workspace → c-space: hovering the workspace, the tree node, path pose, start or goal whose
//     end effector (where the workspace draws it) lies within a few pixels of the pointer is
//     marked in the c-space by a crosshair (and drawn as a ghost arm), labelled;
//   the heat map's scale: while the potential heat map is shown, a bar of its colours with the
//     lowest, middle (median) and highest value and the quantity's name, beside the workspace
//     canvas (right, else left) when the stage has room, else over its top-right corner.
// Leaving a canvas (or pressing on it) removes the ghost. Everything is drawn through the views'
// hooks (view.topHooks, cspace.hooks); the labels are DOM elements set with textContent.

import { el } from '../ui/dom.js';
import { PALETTE } from './palette.js';
import { outlineOf, sensorPose } from './robots.js';
import { fmt, HEAT_CAP } from './cells.js';
import { robotCaps } from './capabilities.js';

/** The ghost's colours: free (purple), colliding (red), the crosshair's (purple), casings. */
// Free is purple, the linked hover's colour (the crosshair's too), not green: the goal arm is green.
export const GHOST = Object.freeze({
  free: '#7b3294',
  collides: '#d7301f',
  cross: '#7b3294',
  casing: '#ffffff',
});

const NEAR_PX = 8; // css px: how close the pointer must be to a pose's end effector

/** Whether `robot` is an arm of two joints (its kind has a c-space view, and it has two links). */
export function isArm2(robot) {
  return robotCaps(robot).cspace && Array.isArray(robot.links) && robot.links.length === 2;
}

/** "q1 0.52 (30°), q2 −1.20 (−69°)": joint angles in radians and degrees. */
export function formatAngles(q) {
  const one = (v) => `${v.toFixed(2)} (${Math.round((v * 180) / Math.PI)}°)`.replaceAll('-', '−');
  return `q1 ${one(q[0])}, q2 ${one(q[1])}`;
}

/**
 * The pose among `candidates` ([{q, what}]) whose end effector, at css px `at(x, y)` on the
 * workspace canvas, is nearest the css point (px, py) and within `radius`; null if none.
 */
export function nearestPose(robot, candidates, at, px, py, radius = NEAR_PX) {
  let best = null, bd = radius * radius;
  for (const c of candidates) {
    const tip = sensorPose(robot, c.q);
    if (!tip) continue;
    const [sx, sy] = at(tip.x, tip.y);
    const d = (sx - px) ** 2 + (sy - py) ** 2;
    if (d <= bd) { best = c; bd = d; }
  }
  return best;
}

/**
 * The value range of a heat map's field samples ([{v}]): {min, median, max} of the finite values,
 * `cap` their HEAT_CAP quantile (where the classic field's colours stop),
 * `infinite` (how many collide), or null when no value is finite.
 */
export function heatRange(field) {
  const vals = Float64Array.from(field.map((s) => s.v).filter(Number.isFinite)).sort();
  if (!vals.length) return null;
  const cap = vals[Math.floor(HEAT_CAP * (vals.length - 1))];
  return { min: vals[0], median: vals[vals.length >> 1], max: vals[vals.length - 1], cap, infinite: field.length - vals.length };
}

/**
 * Wire the linked views: `view` (view.js) on `canvas`, `cspace` (cspace.js) on `cspaceCanvas`,
 * the labels and the scale placed in `stage` (the canvases' positioned parent). `model`: the run
 * model (playback.js), whose trees are searched for hovered nodes. Returns {clear()}.
 */
export function linkViews({ view, cspace, canvas, cspaceCanvas, stage, model }) {
  let ghost = null; // {q, free, from: 'cspace' | 'workspace', text}
  const label = el('div', { id: 'ghost-label', className: 'ghost-label', role: 'status', hidden: true });
  const scale = heatScaleBox();
  stage.append(label, scale.root);

  const arm = () => (cspace.active && isArm2(view.scenario?.robot) ? view.scenario.robot : null);
  const css = (c, x, y) => { // css px of canvas c's point (x, y) within the stage
    const r = c.getBoundingClientRect(), s = stage.getBoundingClientRect();
    return [r.left - s.left + x, r.top - s.top + y];
  };

  function show(next) {
    ghost = next;
    view.dirty = true;
    cspace.dirty = true;
    if (!ghost) { label.hidden = true; return; }
    label.textContent = ghost.text;
    label.classList.toggle('collides', !ghost.free);
    label.hidden = false;
    // near the ghost's end effector (c-space hover) or the crosshair (workspace hover)
    let at;
    if (ghost.from === 'cspace') {
      const tip = sensorPose(view.scenario.robot, ghost.q);
      const L = view.layout;
      at = css(canvas, L.sx(tip.x) / L.dpr, L.sy(tip.y) / L.dpr);
    } else {
      at = css(cspaceCanvas, cspace.sx(ghost.q[0]) / cspace.dpr, cspace.sy(ghost.q[1]) / cspace.dpr);
    }
    const sw = stage.clientWidth, w = label.offsetWidth, h = label.offsetHeight;
    const x = at[0] + 12 + w > sw ? at[0] - w - 12 : at[0] + 12;
    label.style.left = `${Math.max(0, x)}px`;
    label.style.top = `${Math.max(0, at[1] - h - 10)}px`;
  }

  cspaceCanvas.addEventListener('pointermove', (e) => {
    const robot = arm();
    const q = robot && !e.buttons ? cspace.qAt(e.offsetX, e.offsetY) : null;
    if (!q) { if (ghost) show(null); return; }
    const free = cspace.isFree(q);
    show({ q, free, from: 'cspace', text: `${formatAngles(q)}: ${free ? 'free' : 'collides'}` });
  });

  canvas.addEventListener('pointermove', (e) => {
    const robot = arm();
    const L = view.layout;
    const hit = robot && L && !e.buttons
      ? nearestPose(robot, candidates(), (x, y) => [L.sx(x) / L.dpr, L.sy(y) / L.dpr], e.offsetX, e.offsetY) : null;
    if (!hit) { if (ghost) show(null); return; }
    const free = cspace.isFree(hit.q);
    show({ q: hit.q, free, from: 'workspace', text: `${hit.what}: ${formatAngles(hit.q)}${free ? '' : ' (collides)'}` });
  });

  /** The poses a workspace hover can pick: start, goal, the shown path's poses, the trees' nodes. */
  function candidates() {
    const out = [];
    for (const which of ['start', 'goal']) {
      const q = view.stateOf(which);
      if (q) out.push({ q, what: which });
    }
    if (cspace.showResult) {
      const path = cspace.smoothed || cspace.path || [];
      path.forEach((q, i) => out.push({ q, what: `path pose ${i + 1} of ${path.length}` }));
    }
    (model?.trees || []).forEach((t, k) => {
      for (let i = 0; i < t.n; i++) {
        if (t.known(i)) out.push({ q: [t.c0[i], t.c1[i]], what: `tree ${k} node ${i}` });
      }
    });
    return out;
  }

  for (const [c, ev] of [[canvas, 'pointerleave'], [canvas, 'pointerdown'], [cspaceCanvas, 'pointerleave'], [cspaceCanvas, 'pointerdown']]) {
    c.addEventListener(ev, () => { if (ghost) show(null); });
  }

  const placeScale = () => { // beside the workspace canvas when the stage has room, else over its top-right corner
    const w = scale.root.offsetWidth, gap = 8;
    const [left, top] = css(canvas, 0, 0), right = left + canvas.clientWidth;
    const room = !cspace.active; // the c-space canvas takes the stage's other half
    const x = room && right + gap + w <= stage.clientWidth ? right + gap
      : room && left - gap - w >= 0 ? left - gap - w : right - w - gap;
    scale.root.style.left = `${Math.max(0, x)}px`;
    scale.root.style.top = `${Math.max(0, top + (x >= right || x + w <= left ? 0 : gap))}px`;
  };
  view.topHooks.push((ctx, L) => {
    scale.sync(view, placeScale);
    const robot = arm();
    if (ghost && !robot) { ghost = null; label.hidden = true; } // another scenario came in under it
    if (!ghost || !robot) return;
    drawGhost(ctx, L, robot, ghost.q, ghost.free ? GHOST.free : GHOST.collides);
  });
  cspace.hooks.push((ctx, cs) => {
    if (!ghost || ghost.from !== 'workspace' || !arm()) return;
    drawCrosshair(ctx, cs, ghost.q);
  });

  return { clear: () => show(null) };
}

/** The arm at `q`: white casing, the links in `color`, dark joints. */
function drawGhost(ctx, L, robot, q, color) {
  const [p] = outlineOf(robot, q);
  if (!p || p.length < 4) return;
  ctx.save();
  ctx.beginPath();
  for (let i = 0; i < p.length; i += 2) {
    if (i) ctx.lineTo(L.sx(p[i]), L.sy(p[i + 1])); else ctx.moveTo(L.sx(p[i]), L.sy(p[i + 1]));
  }
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = GHOST.casing;
  ctx.lineWidth = L.px(8);
  ctx.stroke();
  ctx.strokeStyle = color;
  ctx.lineWidth = L.px(5);
  ctx.stroke();
  ctx.beginPath();
  for (let i = 2; i < p.length; i += 2) {
    ctx.moveTo(L.sx(p[i]) + L.px(3), L.sy(p[i + 1]));
    ctx.arc(L.sx(p[i]), L.sy(p[i + 1]), L.px(3), 0, 2 * Math.PI);
  }
  ctx.fillStyle = PALETTE.robotEdge;
  ctx.fill();
  ctx.restore();
}

/** A crosshair at (q1, q2) across the c-space square, with a ring at the point. */
function drawCrosshair(ctx, cs, q) {
  const x = cs.sx(q[0]), y = cs.sy(q[1]);
  const { x: x0, y: y0, s } = cs.plot;
  const r = cs.px(7);
  ctx.save();
  cs.clipToPlot(ctx);
  ctx.beginPath();
  ctx.moveTo(x0, y); ctx.lineTo(x - r, y); ctx.moveTo(x + r, y); ctx.lineTo(x0 + s, y);
  ctx.moveTo(x, y0); ctx.lineTo(x, y - r); ctx.moveTo(x, y + r); ctx.lineTo(x, y0 + s);
  ctx.moveTo(x + r, y);
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.strokeStyle = GHOST.casing;
  ctx.lineWidth = cs.px(4);
  ctx.stroke();
  ctx.strokeStyle = GHOST.cross;
  ctx.lineWidth = cs.px(2);
  ctx.stroke();
  ctx.restore();
}

/**
 * The heat map's scale: a box (#heat-scale) with the quantity's name, a bar of the palette's heat
 * colours (the map colours by rank, so each colour is one ninth of the samples, not of the
 * range), the lowest, median and highest finite value under it, and the obstacle colour for
 * colliding samples when there are any. `sync(view, place)` shows, updates or hides it (`place()` puts it in the stage).
 */
function heatScaleBox() {
  const name = el('div', { className: 'heat-scale-name' });
  const bar = el('canvas', { id: 'heat-scale-bar', className: 'heat-scale-bar', width: 180, height: 12 });
  bar.setAttribute('aria-hidden', 'true');
  const lo = el('span', { id: 'heat-scale-min' }), mid = el('span', { id: 'heat-scale-median' }), hi = el('span', { id: 'heat-scale-max' });
  const ticks = el('div', { className: 'heat-scale-ticks' }, lo, mid, hi);
  const note = el('div', { className: 'heat-scale-note' });
  const root = el('div', { id: 'heat-scale', className: 'heat-scale', hidden: true }, name, bar, ticks, note);
  root.setAttribute('role', 'img');
  let key = '';

  function draw() {
    const ctx = bar.getContext('2d');
    const colors = PALETTE.heat;
    const w = bar.width / colors.length;
    colors.forEach((c, k) => {
      ctx.fillStyle = c;
      ctx.fillRect(Math.round(k * w), 0, Math.round((k + 1) * w) - Math.round(k * w), bar.height);
    });
  }

  function sync(view, place) {
    const m = view.cells.mirror;
    const shown = !!(m && view.scenario && view.options.showHeat && m.field.length);
    const next = shown ? `${m.fieldVersion}:${m.field.length}:${m.cells.size > 0}:${view.css}` : '';
    if (next === key) return;
    key = next;
    const range = shown ? heatRange(m.field) : null;
    root.hidden = !range;
    if (!range) return;
    // the quantity: hex-potential colours its cells by their obstacle terms, the classic field by U
    name.textContent = m.cells.size > 0 ? 'obstacle potential: repulsion + trap term' : 'potential U: attraction + repulsion';
    const byValue = m.cells.size === 0; // the classic field colours by value (cells.js's heatScale)
    lo.textContent = fmt(range.min);
    mid.textContent = fmt(byValue ? (range.min + range.cap) / 2 : range.median);
    hi.textContent = byValue ? `${fmt(range.cap)}+` : fmt(range.max);
    note.textContent = (byValue
      ? `light low, dark high, by value (evenly from ${fmt(range.min)} to ${fmt(range.cap)}; the highest tenth, up to ${fmt(range.max)}, in the darkest colour)`
      : `light low, dark high, by rank: each colour holds a ninth of the ${m.field.length - range.infinite} samples`)
      + (range.infinite ? `; ${range.infinite} colliding (∞) in the obstacle colour` : '');
    root.setAttribute('aria-label', `Heat map scale of the ${name.textContent}: from ${lo.textContent} (light) to ${hi.textContent} (dark)`);
    draw();
    place();
  }

  return { root, sync };
}

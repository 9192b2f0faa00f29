// Each robot drawn as its kind's record says (the core's robot kinds, `drawn`, mapped to a drawing by
// capabilities.js), from the outlines the core sends (a flat list of polygons or polylines, see
// transform.js parseOutline) and the scenario state:
//   dot       a dot at (x, y) (no outline: a point robot);
//   polygons  closed polygons, filled (a rigid body);
//   linkage   ONE open polyline: base, every joint, then the end effector (and, for the horn chain, a
//             tiny tip point): thick segments, joint dots, the base as a small square;
//   chain     ONE closed chain, the vehicles in chain order (a vehicle chain): brooms solid, the
//             closing edge (last vehicle back to the first) dashed, vehicles as dots.
//   skeleton  a spatial arm seen from above: ONE open polyline through its link frames to the tool
//             centre point, drawn as a linkage (no preview outline: only the core knows its kinematics).
// outlineOf() computes the same outlines in JS, only to preview a start or goal being dragged
// (the core's outline replaces it once the edited scenario has loaded).

import { robotDrawing } from './capabilities.js';

/** How a robot is drawn: the start, the goal, or the animated robot. */
export function robotStyle(color, role, palette) {
  if (role === 'robot') {
    return { line: palette.robot, fill: palette.robot, alpha: 1, stroke: palette.robotEdge, strokeWidth: 1.5,
             edge: palette.robotEdge, width: 4, dot: 5 };
  }
  return { line: color, fill: color, alpha: 0.45, stroke: color, strokeWidth: 2, edge: palette.robotEdge, width: 5, dot: 6 };
}

/**
 * Draw a robot with outline `polys` (arrays of x, y, x, y, ...) at `state`, as its kind's record
 * says it is drawn (capabilities.js: a dot, polygons, an arm's open chain, a closed chain).
 */
export function drawRobotShape(ctx, L, robot, polys, state, st) {
  const drawing = robotDrawing(robot);
  if (!polys || !polys.length) {
    if (!state || state.length < 2) return;
    ctx.beginPath();
    ctx.arc(L.sx(state[0]), L.sy(state[1]), L.px(st.dot), 0, 2 * Math.PI);
    ctx.fillStyle = st.fill;
    ctx.fill();
    ctx.strokeStyle = st.edge;
    ctx.lineWidth = L.px(1);
    ctx.stroke();
    return;
  }
  if (drawing === 'linkage' || drawing === 'skeleton') drawArm(ctx, L, polys[0], st);
  else if (drawing === 'chain') drawChain(ctx, L, polys[0], st);
  else drawPolygons(ctx, L, polys, st);
}

function drawPolygons(ctx, L, polys, st) {
  ctx.beginPath();
  for (const p of polys) {
    for (let i = 0; i < p.length; i += 2) {
      if (i) ctx.lineTo(L.sx(p[i]), L.sy(p[i + 1])); else ctx.moveTo(L.sx(p[i]), L.sy(p[i + 1]));
    }
    ctx.closePath();
  }
  ctx.globalAlpha = st.alpha;
  ctx.fillStyle = st.fill;
  ctx.fill();
  ctx.globalAlpha = 1;
  ctx.strokeStyle = st.stroke;
  ctx.lineWidth = L.px(st.strokeWidth);
  ctx.stroke();
}

function drawArm(ctx, L, p, st) {
  if (p.length < 4) return;
  ctx.beginPath();
  for (let i = 0; i < p.length; i += 2) {
    if (i) ctx.lineTo(L.sx(p[i]), L.sy(p[i + 1])); else ctx.moveTo(L.sx(p[i]), L.sy(p[i + 1]));
  }
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = st.line;
  ctx.lineWidth = L.px(st.width);
  ctx.stroke();
  ctx.lineCap = 'butt';
  // joints (every vertex after the base; smaller on a chain of short links), then the base
  let len = 0;
  for (let i = 2; i < p.length; i += 2) len += Math.hypot(p[i] - p[i - 2], p[i + 1] - p[i - 1]);
  const avg = (len * L.scale) / L.px(1) / Math.max(1, p.length / 2 - 1); // css px per link
  const r = L.px(Math.max(1.2, Math.min(3, st.width * 0.6, avg * 0.12)));
  ctx.beginPath();
  for (let i = 2; i < p.length; i += 2) {
    const x = L.sx(p[i]), y = L.sy(p[i + 1]);
    ctx.moveTo(x + r, y);
    ctx.arc(x, y, r, 0, 2 * Math.PI);
  }
  ctx.fillStyle = st.edge;
  ctx.fill();
  const b = L.px(9);
  ctx.fillStyle = st.edge;
  ctx.fillRect(L.sx(p[0]) - b / 2, L.sy(p[1]) - b / 2, b, b);
}

function drawChain(ctx, L, p, st) {
  const n = p.length / 2;
  if (n < 1) return;
  ctx.lineCap = 'round';
  ctx.strokeStyle = st.stroke;
  if (n >= 2) {
    ctx.beginPath();
    for (let i = 0; i < n; i++) {
      if (i) ctx.lineTo(L.sx(p[2 * i]), L.sy(p[2 * i + 1])); else ctx.moveTo(L.sx(p[0]), L.sy(p[1]));
    }
    ctx.lineWidth = L.px(2.5);
    ctx.stroke();
  }
  if (n >= 3) { // the closing edge
    ctx.beginPath();
    ctx.moveTo(L.sx(p[2 * n - 2]), L.sy(p[2 * n - 1]));
    ctx.lineTo(L.sx(p[0]), L.sy(p[1]));
    ctx.setLineDash([L.px(4), L.px(3)]);
    ctx.lineWidth = L.px(1.5);
    ctx.stroke();
    ctx.setLineDash([]);
  }
  ctx.lineCap = 'butt';
  const r = L.px(st.dot * 0.6);
  ctx.beginPath();
  for (let i = 0; i < n; i++) {
    const x = L.sx(p[2 * i]), y = L.sy(p[2 * i + 1]);
    ctx.moveTo(x + r, y);
    ctx.arc(x, y, r, 0, 2 * Math.PI);
  }
  ctx.fillStyle = st.fill;
  ctx.fill();
  ctx.strokeStyle = st.edge;
  ctx.lineWidth = L.px(1);
  ctx.stroke();
}

/**
 * Inspection points: small diamonds; the numbers in `seen` (a Set, optional) are lit: drawn larger,
 * in `lit`, with a halo.
 */
export function drawInspection(ctx, L, points, fill, edge, seen = null, lit = null) {
  if (!points || !points.length) return;
  const diamonds = (r, pick) => {
    ctx.beginPath();
    points.forEach(([x, y], i) => {
      if (!pick(i)) return;
      const sx = L.sx(x), sy = L.sy(y);
      ctx.moveTo(sx, sy - r); ctx.lineTo(sx + r, sy); ctx.lineTo(sx, sy + r); ctx.lineTo(sx - r, sy);
      ctx.closePath();
    });
  };
  const isLit = (i) => !!(seen && lit && seen.has(i));
  diamonds(L.px(4), (i) => !isLit(i));
  ctx.fillStyle = fill;
  ctx.fill();
  ctx.strokeStyle = edge;
  ctx.lineWidth = L.px(1);
  ctx.stroke();
  if (!seen || !lit || !seen.size) return;
  ctx.beginPath();
  points.forEach(([x, y], i) => {
    if (!isLit(i)) return;
    ctx.moveTo(L.sx(x) + L.px(9), L.sy(y));
    ctx.arc(L.sx(x), L.sy(y), L.px(9), 0, 2 * Math.PI);
  });
  ctx.fillStyle = 'rgba(255, 212, 0, 0.3)';
  ctx.fill();
  diamonds(L.px(6), isLit);
  ctx.fillStyle = lit;
  ctx.fill();
  ctx.strokeStyle = edge;
  ctx.lineWidth = L.px(1);
  ctx.stroke();
}

/**
 * Where the inspection sensor is and where it looks, for `robot` at scenario state `q`:
 * {x, y, heading} (heading in radians from the x axis, null when the robot has none).
 * by how the robot is drawn (capabilities.js):
 *   linkage  the end effector (the last link's end; joint angles are relative to the previous link,
 *            the first to the x axis, so the heading is their sum);
 *   polygons the reference point, heading θ;
 *   dot      the point, no heading; chain: the vehicles' centroid, no heading.
 */
export function sensorPose(robot, q) {
  if (!q || q.length < 2) return null;
  switch (robotDrawing(robot)) {
    case 'linkage': {
      if (!robot.links || q.length < robot.links.length) return null;
      let [x, y] = robot.base || [0, 0];
      let a = 0;
      robot.links.forEach((len, i) => {
        a += q[i];
        x += len * Math.cos(a);
        y += len * Math.sin(a);
      });
      return { x, y, heading: a };
    }
    case 'polygons':
      return { x: q[0], y: q[1], heading: q.length > 2 ? q[2] : null };
    case 'chain': {
      let x = 0, y = 0;
      const n = Math.floor(q.length / 2);
      for (let i = 0; i < n; i++) { x += q[2 * i]; y += q[2 * i + 1]; }
      return { x: x / n, y: y / n, heading: null };
    }
    default:
      return { x: q[0], y: q[1], heading: null };
  }
}

/** The outline of `robot` at scenario state `q`, as the core would give it (for previews). */
export function outlineOf(robot, q) {
  if (!robot || !q) return [];
  switch (robotDrawing(robot)) {
    case 'polygons': {
      const [x, y, th] = q;
      const c = Math.cos(th), s = Math.sin(th);
      return [robot.footprint.flatMap(([u, v]) => [x + c * u - s * v, y + s * u + c * v])];
    }
    case 'linkage': {
      let [x, y] = robot.base;
      let a = 0;
      const out = [x, y];
      robot.links.forEach((len, i) => {
        a += q[i];
        x += len * Math.cos(a);
        y += len * Math.sin(a);
        out.push(x, y);
      });
      return [out];
    }
    case 'chain':
      return [Array.from(q)];
    default:
      return [];
  }
}

/** The farthest footprint vertex from the reference point (a rigid body's radius). */
export function footprintRadius(robot) {
  if (!robot || robotDrawing(robot) !== 'polygons') return 0;
  return Math.max(0, ...robot.footprint.map(([u, v]) => Math.hypot(u, v)));
}

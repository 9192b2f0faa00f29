// Marks of the top layer that view.js draws every frame over the composited layers: rewire flashes
// (fading out), the inspection sensor's wedge and a rigid body's rotation handle. Pure drawing: the
// view passes its layout and what it holds.

import { EventKind } from '../run/events.js';
import { PALETTE, STYLE } from './palette.js';
import { sensorPose } from './robots.js';
import { isArm2 } from './linked.js';

const FLASH_MS = 600;        // a rewire flashes this long

/**
 * Rewired edges ([t, x, y, px, py], t in performance.now() ms), fading out. Returns the flashes
 * not yet expired.
 */
export function drawFlashes(ctx, L, flashes, time) {
  const now = Math.max(time, performance.now());
  const live = flashes.filter(([t]) => now - t < FLASH_MS);
  const st = STYLE[EventKind.REWIRE];
  for (const [t, x, y, px, py] of live) {
    ctx.globalAlpha = Math.max(0, 1 - (now - t) / FLASH_MS);
    ctx.beginPath();
    ctx.moveTo(L.sx(px), L.sy(py));
    ctx.lineTo(L.sx(x), L.sy(y));
    ctx.strokeStyle = st.color;
    ctx.lineWidth = L.px(st.width);
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(L.sx(x), L.sy(y), L.px(st.size), 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.globalAlpha = 1;
  return live;
}

/**
 * The inspection sensor: its wedge (radius `range`, half-angle fov/2) at the end effector of the
 * robot shown at `state`; during a run (`showResult` false), a dashed ring of the range at the best
 * branch's tip (a wedge when the tip's heading is known: a 2-joint arm, whose two planning
 * coordinates are its whole state). The view's `scenario`, `model` and `showResult` are read.
 */
export function drawSensor(ctx, L, { scenario, model, showResult }, state, best) {
  const { range, fov } = scenario.inspection;
  if (!(range > 0)) return;
  const wedge = (pose) => {
    const cx = L.sx(pose.x), cy = L.sy(pose.y), r = range * L.scale;
    ctx.beginPath();
    if (pose.heading == null || !(fov > 0) || fov >= 2 * Math.PI) {
      ctx.arc(cx, cy, r, 0, 2 * Math.PI);
    } else { // screen y points down: world angle a is screen angle −a
      ctx.moveTo(cx, cy);
      ctx.arc(cx, cy, r, -(pose.heading + fov / 2), -(pose.heading - fov / 2));
      ctx.closePath();
    }
    ctx.fillStyle = PALETTE.fovFill;
    ctx.fill();
    ctx.strokeStyle = PALETTE.fov;
    ctx.lineWidth = L.px(1.5);
    ctx.stroke();
  };
  const robot = scenario.robot;
  const pose = state ? sensorPose(robot, state) : null;
  if (pose) wedge(pose);
  if (!showResult && best.length && model?.best) {
    const t = model.trees[model.best.tree];
    const id = model.best.id;
    const [x, y] = best[best.length - 1];
    if (isArm2(robot) && t?.known(id)) {
      const tip = sensorPose(robot, [t.c0[id], t.c1[id]]);
      if (tip) { wedge(tip); return; }
    }
    ctx.beginPath();
    ctx.arc(L.sx(x), L.sy(y), range * L.scale, 0, 2 * Math.PI);
    ctx.setLineDash([L.px(5), L.px(4)]);
    ctx.strokeStyle = PALETTE.fov;
    ctx.lineWidth = L.px(1.25);
    ctx.stroke();
    ctx.setLineDash([]);
  }
}

/** A rigid body's rotation handle `h` (View.handlePoint: device px), in `color`; nothing for null. */
export function drawHandle(ctx, L, h, color) {
  if (!h) return;
  ctx.beginPath();
  ctx.moveTo(h.cx, h.cy);
  ctx.lineTo(h.x, h.y);
  ctx.strokeStyle = color;
  ctx.lineWidth = L.px(1.5);
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(h.x, h.y, L.px(5), 0, 2 * Math.PI);
  ctx.fillStyle = PALETTE.handle;
  ctx.fill();
  ctx.stroke();
}

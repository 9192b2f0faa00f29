// The 3-D view's camera in a share link: `camera=tx,ty,tz,yaw,pitch,distance`, the orbit camera's
// target (metres, the world's x, y, z), its yaw (azimuth about the world's z, radians from +x), its
// pitch (elevation above the floor, radians) and its distance from the target (metres). The link's
// numbers are bounded here, and the orbit camera (draw3d/camera.js) takes the same bounds, so a
// link cannot put the camera where dragging could not.

/** The bounds a camera's numbers must be within (the orbit camera's own). */
export const CAMERA = Object.freeze({
  maxTarget: 1e6,        // |tx|, |ty|, |tz|
  maxYaw: 1000,          // |yaw| read (it is written within ±π)
  minPitch: -1.45,
  maxPitch: 1.55,
  minDistance: 1e-3,
  maxDistance: 1e4,
});

/** The longest camera value read (six numbers of 24 characters and the commas). */
const MAX_CHARS = 160;

/** An angle wrapped into (-π, π]. */
export function wrapAngle(a) {
  const t = 2 * Math.PI;
  const w = a - t * Math.floor((a + Math.PI) / t);
  return w <= -Math.PI ? w + t : w;
}

/**
 * A link's camera value → {camera: {target: [x, y, z], yaw, pitch, distance}} or {why} (in words,
 * naming the number that is out of bounds).
 */
export function readCamera(text) {
  const r = readNumbers(text, ['tx', 'ty', 'tz', 'yaw', 'pitch', 'distance'], MAX_CHARS);
  if (r.why !== undefined) return { why: r.why };
  const v = r.values, names = ['tx', 'ty', 'tz'];
  const C = CAMERA;
  for (let i = 0; i < 3; i++) {
    if (Math.abs(v[i]) > C.maxTarget) return { why: `${names[i]} must be within ±${C.maxTarget.toExponential()} metres` };
  }
  if (Math.abs(v[3]) > C.maxYaw) return { why: `yaw must be within ±${C.maxYaw} radians` };
  if (v[4] < C.minPitch || v[4] > C.maxPitch) return { why: `pitch must be from ${C.minPitch} to ${C.maxPitch} radians` };
  if (v[5] < C.minDistance || v[5] > C.maxDistance) return { why: `distance must be from ${C.minDistance} to ${C.maxDistance} metres` };
  return { camera: { target: v.slice(0, 3), yaw: wrapAngle(v[3]), pitch: v[4], distance: v[5] } };
}

const WORDS = ['no', 'one', 'two', 'three', 'four', 'five', 'six', 'seven', 'eight'];

/**
 * A link's value of comma-separated numbers named `names` (at most `maxChars` characters, each a
 * plain decimal, an exponent allowed) → {values} or {why} in words, naming the first that is not
 * a number. The camera's and the plane's zoom (ui/plane-zoom.js) read their values with it.
 * @param {unknown} text @param {string[]} names @param {number} maxChars
 * @returns {{values: number[], why?: undefined} | {why: string, values?: undefined}}
 */
export function readNumbers(text, names, maxChars) {
  const s = String(text ?? '');
  const n = WORDS[names.length] ?? String(names.length);
  if (s.length > maxChars) return { why: `it is ${s.length} characters long (${n} numbers need at most ${maxChars})` };
  const parts = s.split(',');
  if (parts.length !== names.length) return { why: `it needs ${n} numbers ${names.join(',')}, found ${parts.length}` };
  const values = [];
  for (let i = 0; i < names.length; i++) {
    const t = parts[i].trim();
    const x = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i.test(t) ? Number(t) : NaN;
    if (!Number.isFinite(x)) return { why: `${names[i]} is not a number` };
    values.push(x);
  }
  return { values };
}

/** A number as written in a link: 10 significant digits, no trailing zeros. */
const num = (x) => String(Number(x.toPrecision(10)));

/** A camera {target, yaw, pitch, distance} as a link's value (what readCamera reads back). */
export function writeCamera(c) {
  const C = CAMERA;
  const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));
  return [...c.target.map((v) => clamp(v, -C.maxTarget, C.maxTarget)), wrapAngle(c.yaw),
    clamp(c.pitch, C.minPitch, C.maxPitch), clamp(c.distance, C.minDistance, C.maxDistance)].map(num).join(',');
}

/** A camera as written and read back (what a page opening the link gets). */
export function roundCamera(c) {
  return readCamera(writeCamera(c)).camera ?? null;
}

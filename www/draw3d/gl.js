// The 3-D view's WebGL2 plumbing, with no library: 4×4 matrices (column-major, WebGL's order, as
// the core's `Scene.link_frames` gives them), two shader programs (flat-shaded triangles lit by a
// head light; unlit lines and points in one colour), and buffers. Shader sources are constants of
// this file; nothing from data reaches them.

/** @typedef {Float32Array | Float64Array | number[]} Mat4 */

/** The identity. @returns {Float64Array} */
export function identity() {
  const m = new Float64Array(16);
  m[0] = m[5] = m[10] = m[15] = 1;
  return m;
}

/** `a · b`. @param {Mat4} a @param {Mat4} b @returns {Float64Array} */
export function multiply(a, b) {
  const out = new Float64Array(16);
  for (let c = 0; c < 4; c++) {
    for (let r = 0; r < 4; r++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
      out[c * 4 + r] = s;
    }
  }
  return out;
}

/** A perspective projection (field of view `fovy` radians, aspect w/h, near and far planes). */
export function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2);
  const m = new Float64Array(16);
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (far + near) / (near - far);
  m[11] = -1;
  m[14] = (2 * far * near) / (near - far);
  return m;
}

/** The view matrix of an eye at `eye` looking at `at`, `up` the world's up. */
export function lookAt(eye, at, up) {
  const z = normalise(sub(eye, at));
  const x = normalise(cross(up, z));
  const y = cross(z, x);
  const m = identity();
  for (let i = 0; i < 3; i++) {
    m[i * 4] = x[i];
    m[i * 4 + 1] = y[i];
    m[i * 4 + 2] = z[i];
  }
  m[12] = -dot(x, eye);
  m[13] = -dot(y, eye);
  m[14] = -dot(z, eye);
  return m;
}

/** `m · (p, 1)` as a point (no division). @param {Mat4} m @param {ArrayLike<number>} p */
export function transformPoint(m, p, out = [0, 0, 0], at = 0) {
  const [x, y, z] = [p[at], p[at + 1], p[at + 2]];
  for (let r = 0; r < 3; r++) out[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
  return out;
}

/** `m · (p, 1)` with the perspective division: clip space to normalised device coordinates [x, y, z, w]. */
export function project(m, p) {
  const v = [0, 1, 2, 3].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
  return [v[0] / v[3], v[1] / v[3], v[2] / v[3], v[3]];
}

export const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export function normalise(a) {
  const n = Math.hypot(a[0], a[1], a[2]) || 1;
  return [a[0] / n, a[1] / n, a[2] / n];
}

/** '#rrggbb' as [r, g, b] in 0..1. */
export function rgb(hex) {
  return [1, 3, 5].map((i) => parseInt(String(hex).slice(i, i + 2), 16) / 255 || 0);
}

// Triangles: position and flat normal per vertex (each triangle's own three vertices), in the
// model's frame; lit by a light at the eye (a head light), so what faces the camera is bright.
const MESH_VS = `#version 300 es
in vec3 position;
in vec3 normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 proj;
out vec3 vNormal;
out vec3 vEye;
void main() {
  vec4 w = view * model * vec4(position, 1.0);
  vNormal = mat3(view * model) * normal;
  vEye = -w.xyz;
  gl_Position = proj * w;
}`;
const MESH_FS = `#version 300 es
precision mediump float;
in vec3 vNormal;
in vec3 vEye;
uniform vec3 colour;
uniform float alpha;
out vec4 outColour;
void main() {
  float lit = abs(dot(normalize(vNormal), normalize(vEye)));
  outColour = vec4(colour * (0.45 + 0.55 * lit), alpha);
}`;
// Lines and points in one colour (trees, the path, the grid, the axes).
const LINE_VS = `#version 300 es
in vec3 position;
uniform mat4 view;
uniform mat4 proj;
uniform float pointSize;
void main() {
  gl_Position = proj * view * vec4(position, 1.0);
  gl_PointSize = pointSize;
}`;
const LINE_FS = `#version 300 es
precision mediump float;
uniform vec3 colour;
uniform float alpha;
out vec4 outColour;
void main() { outColour = vec4(colour, alpha); }`;

/** Compile and link a program; throws with the driver's log. */
export function program(gl, vs, fs) {
  const p = gl.createProgram();
  for (const [type, src] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
    const s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(`3-D view shader: ${gl.getShaderInfoLog(s)}`);
    gl.attachShader(p, s);
  }
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(`3-D view program: ${gl.getProgramInfoLog(p)}`);
  const uniforms = {};
  const n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < n; i++) {
    const name = gl.getActiveUniform(p, i).name;
    uniforms[name] = gl.getUniformLocation(p, name);
  }
  return { p, u: uniforms, position: gl.getAttribLocation(p, 'position'), normal: gl.getAttribLocation(p, 'normal') };
}

/** The two programs of a context. */
export function programs(gl) {
  return { mesh: program(gl, MESH_VS, MESH_FS), line: program(gl, LINE_VS, LINE_FS) };
}

/**
 * A triangle mesh for the GPU: flat normals, so each triangle gets its own three vertices.
 * `vertices` flat x, y, z…; `triangles` flat i, j, k… (counter-clockwise seen from outside).
 * @returns {{vao: WebGLVertexArrayObject, count: number, buffers: WebGLBuffer[]}}
 */
export function meshBuffers(gl, prog, vertices, triangles) {
  const n = Math.floor(triangles.length / 3);
  const pos = new Float32Array(n * 9);
  const nor = new Float32Array(n * 9);
  for (let t = 0; t < n; t++) {
    const [a, b, c] = [0, 1, 2].map((k) => [0, 1, 2].map((d) => vertices[triangles[t * 3 + k] * 3 + d] ?? 0));
    const nm = normalise(cross(sub(b, a), sub(c, a)));
    [a, b, c].forEach((v, k) => { pos.set(v, t * 9 + k * 3); nor.set(nm, t * 9 + k * 3); });
  }
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  const buffers = [[prog.position, pos], [prog.normal, nor]].map(([loc, data]) => {
    const b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
    gl.enableVertexAttribArray(loc);
    gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 0, 0);
    return b;
  });
  gl.bindVertexArray(null);
  return { vao, count: n * 3, buffers };
}

/**
 * A growable list of points for lines or points (a tree's segments grow with the replay): the CPU
 * copy doubles, the GPU buffer is refilled when it changed.
 */
export class LineBuffer {
  constructor(gl, prog) {
    this.gl = gl;
    this.data = new Float32Array(3 * 1024);
    this.length = 0; // points
    this.vao = gl.createVertexArray();
    this.buffer = gl.createBuffer();
    gl.bindVertexArray(this.vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    gl.enableVertexAttribArray(prog.position);
    gl.vertexAttribPointer(prog.position, 3, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
    this.uploaded = -1;
    this.capacity = 0;
  }

  clear() { this.length = 0; this.uploaded = -1; }

  /** Add points `pts` (flat x, y, z…, any array). */
  push(pts, from = 0, to = pts.length) {
    const need = (this.length * 3) + (to - from);
    if (need > this.data.length) {
      let size = this.data.length;
      while (size < need) size *= 2;
      const grown = new Float32Array(size);
      grown.set(this.data.subarray(0, this.length * 3));
      this.data = grown;
    }
    for (let i = from; i < to; i++) this.data[this.length * 3 + i - from] = pts[i];
    this.length += (to - from) / 3;
  }

  /** Send what changed to the GPU. */
  upload() {
    if (this.uploaded === this.length) return;
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffer);
    if (this.data.length > this.capacity) {
      gl.bufferData(gl.ARRAY_BUFFER, this.data.byteLength, gl.DYNAMIC_DRAW);
      this.capacity = this.data.length;
      this.uploaded = 0;
    }
    const from = Math.max(0, this.uploaded);
    gl.bufferSubData(gl.ARRAY_BUFFER, from * 12, this.data, from * 3, (this.length - from) * 3);
    this.uploaded = this.length;
  }
}

// The faded trees of a solved run, drawn once and reused. Once a path is shown the 3-D view draws
// the trees at 2% opacity under everything else, and a solved course run holds some 14,000 nodes
// drawn through their `delta` steps: rasterised on the CPU (SwiftShader, a browser without a GPU)
// that took most of a second a frame, so the path's playback, the scrubber and the sliders ran at
// about one frame a second and the page waited on each. The trees only change when the camera, the
// canvas or the trees do; so they are drawn into a texture of the canvas's size (premultiplied:
// blended into transparent black, the same sum as blending over the picture) and each frame lays
// that texture over the floor in one triangle. The composite is the same "over" as drawing the
// lines there, multisampled like the canvas (drawn into a multisampled buffer, resolved into the
// texture), up to 8-bit rounding; what the layer lacks is the floor's depth, which never hid a
// tree (the floor lies under all).

import { program } from './gl.js';

const QUAD_VS = `#version 300 es
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}`;
const QUAD_FS = `#version 300 es
precision mediump float;
uniform sampler2D layer;
out vec4 outColour;
void main() { outColour = texelFetch(layer, ivec2(gl_FragCoord.xy), 0); }`;

export class Backdrop {
  /** @param {WebGL2RenderingContext} gl */
  constructor(gl) {
    this.gl = gl;
    this.prog = program(gl, QUAD_VS, QUAD_FS);
    this.vao = gl.createVertexArray(); // no attributes: the triangle comes from gl_VertexID
    this.texture = gl.createTexture();
    this.fbo = gl.createFramebuffer();
    // drawn multisampled, as the canvas (antialias), then resolved into the texture
    this.samples = Math.min(4, gl.getParameter(gl.MAX_SAMPLES) || 0);
    this.ms = this.samples > 1 ? { fbo: gl.createFramebuffer(), colour: gl.createRenderbuffer() } : null;
    this.size = [0, 0];
    /** what the layer holds (the camera, the canvas and the trees), or null */
    this.key = null;
    /** times the layer was drawn (tests) */
    this.painted = 0;
  }

  /** The layer must be drawn again. */
  invalidate() { this.key = null; }

  /**
   * Lay the layer over the picture, drawing it first with `paint()` when `key` differs from what
   * it holds. `paint` draws into a transparent layer with no depth buffer, its program in use,
   * and must blend premultiplied (`premultipliedBlend`). Afterwards the picture's framebuffer and
   * viewport are bound again, with the depth test on, depth written, no blending, and the layer's
   * program in use.
   * @param {string} key @param {() => void} paint
   */
  draw(key, paint) {
    const gl = this.gl;
    const [w, h] = [gl.drawingBufferWidth, gl.drawingBufferHeight];
    if (this.key !== key || this.size[0] !== w || this.size[1] !== h) {
      if (this.size[0] !== w || this.size[1] !== h) {
        gl.bindTexture(gl.TEXTURE_2D, this.texture);
        gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, w, h, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
        for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
        gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.texture, 0);
        if (this.ms) {
          gl.bindRenderbuffer(gl.RENDERBUFFER, this.ms.colour);
          gl.renderbufferStorageMultisample(gl.RENDERBUFFER, this.samples, gl.RGBA8, w, h);
          gl.bindFramebuffer(gl.FRAMEBUFFER, this.ms.fbo);
          gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, this.ms.colour);
        }
        this.size = [w, h];
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.ms ? this.ms.fbo : this.fbo);
      gl.viewport(0, 0, w, h);
      gl.clearColor(0, 0, 0, 0);
      gl.clear(gl.COLOR_BUFFER_BIT);
      paint();
      if (this.ms) {
        gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.ms.fbo);
        gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.fbo);
        gl.blitFramebuffer(0, 0, w, h, 0, 0, w, h, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.viewport(0, 0, w, h);
      this.key = key;
      this.painted++;
    }
    gl.useProgram(this.prog.p);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.uniform1i(this.prog.u.layer, 0);
    gl.disable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.depthMask(false);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.depthMask(true);
    gl.disable(gl.BLEND);
    gl.enable(gl.DEPTH_TEST);
  }
}

/**
 * Blending for a layer drawn into transparent black: straight colour in, premultiplied out
 * (colour · a + dst · (1 − a); alpha a + dst · (1 − a)), so the layer laid over a picture with
 * (ONE, ONE_MINUS_SRC_ALPHA) gives what drawing there would.
 * @param {WebGL2RenderingContext} gl
 */
export function premultipliedBlend(gl) {
  gl.blendFuncSeparate(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA, gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
}

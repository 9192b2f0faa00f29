// Exports for slides: a PNG at a chosen width, an SVG drawn like the canvas, a WebM at a chosen
// width with a real (seekable) duration, and an animated GIF of the playback. Each is drawn by an
// ExportView: a second View over the same records and run model, on canvases of its own at the
// export's size, so the visible canvas is never resized or redrawn for an export. Options: a
// legend under the picture (PNG, SVG, GIF) and a transparent background (PNG, SVG; a GIF has no
// alpha, a WebM neither). No HTML from data: the SVG is built with DOM calls and serialised.
//
// A run of a million nodes takes seconds to draw, so an export never draws it in one go: the
// ExportView owes a full redraw and catchUp() draws it in steps of EXPORT_BATCH records or nodes
// (draw/redraw.js), the SVG likewise (export-svg.js sceneSvgSteps), yielding to the page between
// steps: the page keeps drawing frames, the status shows how far it got, and pressing the export's
// button again cancels it.

import { PALETTE } from '../draw/palette.js';
import { View } from '../draw/view.js';
import { drawObstacle } from '../draw/transform.js';
import { downloadBlob } from '../draw/stage.js';
import { fixWebm } from './webm.js';
import { GifWriter, hexRgb } from './gif.js';
import { LEGEND_TEXT, frameShown, legendLayout, measure } from './export-legend.js';
import { sceneSvgSteps } from './export-svg.js';
import { render3d, beside } from './export3d.js';
import { EXPORT_BATCH, redrawSteps } from '../draw/redraw.js';
import { shown } from './text.js';
import { TimeLapse } from './timelapse.js';

/** Thrown when the user cancelled an export in progress. */
export class ExportCancelled extends Error {
  constructor(what) { super(`${what} cancelled`); this.name = 'ExportCancelled'; }
}

/** Let the page run (draw a frame, read a click) before the next step of an export. */
const breathe = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/**
 * Run drawing `steps` (a generator yielding the share done), pausing for the page after each:
 * `progress(share)` is told; `cancelled()` true stops with ExportCancelled(`what`). Returns the
 * generator's value.
 */
export async function runSteps(steps, { what = 'The export', progress = null, cancelled = () => false } = {}) {
  for (;;) {
    const s = steps.next();
    if (s.done) return s.value;
    progress?.(s.value);
    await breathe();
    if (cancelled()) throw new ExportCancelled(what);
  }
}

/** Bounds of what a user may ask for (the fields say so too). */
export const LIMITS = Object.freeze({
  png: { min: 100, max: 8000, pixels: 16e6 }, // an export draws seven layers at this size: ~450 MB at the most
  video: { min: 320, max: 3840, pixels: 3840 * 2160 },
  gif: { min: 160, max: 1024, frames: [2, 150], fps: 10 },
});

/**
 * A View that follows another (`source`) at its own size: the same scenario, records, run model,
 * options and result, laid out `width` pixels wide. `transparent`: no background and no white
 * free space (the obstacles, bounds and run on nothing).
 */
export class ExportView extends View {
  /**
   * `lapse`: a time-lapse (timelapse.js) whose replay is drawn instead of the source's records; the
   * source's result is shown once the replay reached its end.
   */
  constructor(source, transparent = false, lapse = null) {
    const run = lapse ? lapse.playback : source;
    super(document.createElement('canvas'), run.store, run.model);
    this.lapse = lapse;
    this.source = source;
    this.transparent = transparent;
    this.drawnTo = 0;
    this.seenMarkers = null;
    this.owed = false; // a full redraw of the run's layers, which catchUp() draws in steps
  }

  /** A full redraw is owed, not drawn: catchUp() draws it in steps. */
  redrawTree() {
    if (this.layout) this.owed = true;
  }

  /**
   * Draw the redraw follow() left owed, EXPORT_BATCH records or nodes a step, yielding to the page
   * between steps (runSteps: `progress`, `cancelled`, `what`).
   */
  async catchUp(options = {}) {
    if (!this.owed) return;
    this.owed = false;
    this.drawnTo = this.store.length; // later records are drawn by the next follow()
    await runSteps(redrawSteps(this, EXPORT_BATCH, this.drawnTo), options);
  }

  drawScene() {
    if (!this.transparent) { super.drawScene(); return; }
    const { ctx } = this.sceneLayer;
    const L = this.layout;
    ctx.clearRect(0, 0, L.width, L.height);
    if (!this.scenario) return;
    const [x0, y0, x1, y1] = this.scenario.bounds;
    for (const ob of this.scenario.obstacles) drawObstacle(ctx, L, ob);
    ctx.strokeStyle = PALETTE.bounds;
    ctx.lineWidth = L.px(1.5);
    ctx.strokeRect(L.sx(x0), L.sy(y1), (x1 - x0) * L.scale, (y1 - y0) * L.scale);
  }

  /** Whether the source shows its result (a time-lapse's view waits for its end). */
  sourceShowsResult() { return this.source.showResult && (!this.lapse || this.lapse.atEnd); }

  /** The source's result and state shown (no drawing; a time-lapse keeps its own latest sample). */
  copyResult() {
    const s = this.source;
    this.frames = s.frames;
    this.rawFrames = s.rawFrames;
    this.path = s.path;
    this.smoothed = s.smoothed;
    this.preview = s.preview;
    if (!this.lapse) this.lastSample = s.lastSample;
  }

  /**
   * Catch up with the source: laid out `width` px wide on the first call (the box is kept after
   * that, so a recording keeps its size when the page is resized), new records drawn; a cleared
   * or redrawn run is owed (catchUp() draws it).
   */
  follow(width) {
    const s = this.source;
    if (!s.layout || !s.box || !s.scenario) throw new Error('nothing to export yet: load a scenario first');
    const rebuild = !this.layout || this.scenario !== s.scenario || this.start !== s.start || this.goal !== s.goal;
    if (rebuild) {
      this.scenario = s.scenario;
      this.start = s.start;
      this.goal = s.goal;
      this.clearRun();
      Object.assign(this.options, s.options);
      this.copyResult();
      this.showResult = this.sourceShowsResult();
      this.seenMarkers = s.markers;
      // lays out, draws the scene and every record (a later scenario keeps the first box and scale)
      if (!this.box) this.resize(s.box[0], s.box[1], width / s.css[0]); else this.relayout();
      this.drawnTo = this.store.length;
      return;
    }
    this.setOptions(s.options);
    if (s.markers !== this.seenMarkers || this.store.length < this.drawnTo) {
      // the source cleared its run (a new run) or redrew it: so do we
      this.clearRun();
      this.copyResult();
      this.showResult = this.sourceShowsResult();
      this.seenMarkers = s.markers;
      this.redrawTree();
      this.drawnTo = this.store.length;
      return;
    }
    if (this.store.length > this.drawnTo && !this.owed) {
      this.drawRecords(this.drawnTo, this.store.length);
      this.drawnTo = this.store.length;
    }
    this.copyResult();
    const show = this.sourceShowsResult();
    if (show && !this.showResult) {
      this.showResult = true;
      this.finishRun();
    } else this.showResult = show;
  }

  /** Render the picture at `time` (ms) with `animFps` robot frames a second. */
  draw(time, animFps) {
    this.dirty = true;
    this.render(time, animFps);
  }

  /** Render the robot where the source last showed it (PNG and SVG are stills). */
  drawLikeSource() {
    const k = frameShown(this.source);
    this.draw(k >= 0 ? (k + 0.5) * 1000 : performance.now(), 1);
  }

  /** Free the canvases' memory. */
  dispose() {
    for (const c of [this.canvas, this.sceneLayer.canvas, ...this.runLayers.map((l) => l.canvas)]) { c.width = 0; c.height = 0; }
  }
}



/** One legend mark on a canvas (css px scaled by `s`), as the page's legend swatches. */
function drawMark(ctx, s, x, y, { color, shape }) {
  ctx.save();
  ctx.fillStyle = color;
  ctx.strokeStyle = color;
  ctx.lineCap = 'round';
  const line = (w, dash = []) => {
    ctx.beginPath();
    ctx.setLineDash(dash.map((d) => d * s));
    ctx.moveTo((x + 1) * s, y * s);
    ctx.lineTo((x + 15) * s, y * s);
    ctx.lineWidth = w * s;
    ctx.stroke();
  };
  if (shape === 'line') line(2);
  else if (shape === 'dash') line(2, [3, 3]);
  else if (shape === 'thick') line(4);
  else if (shape === 'dot' || shape === 'ring') {
    ctx.beginPath();
    ctx.arc((x + 8) * s, y * s, 4 * s, 0, 2 * Math.PI);
    if (shape === 'dot') ctx.fill(); else { ctx.lineWidth = 2 * s; ctx.stroke(); }
  } else if (shape === 'cross') {
    ctx.beginPath();
    ctx.moveTo((x + 4) * s, (y - 4) * s); ctx.lineTo((x + 12) * s, (y + 4) * s);
    ctx.moveTo((x + 4) * s, (y + 4) * s); ctx.lineTo((x + 12) * s, (y - 4) * s);
    ctx.lineWidth = 2 * s;
    ctx.stroke();
  } else ctx.fillRect((x + 2) * s, (y - 5) * s, 12 * s, 10 * s);
  ctx.restore();
}

/**
 * `picture` (a canvas) with the legend `items` drawn under it (css px scaled like the picture,
 * `pictureScale` device px per css px, but never smaller than css px), on the
 * page's background unless `transparent`. Returns a new canvas (the picture when there is no legend).
 */
function withLegend(picture, items, pictureScale, transparent) {
  if (!items?.length) return picture;
  const scale = Math.max(1, pictureScale); // a small picture keeps a legend one can read
  const cssWidth = picture.width / scale;
  const lay = legendLayout(items, cssWidth, measure);
  const out = document.createElement('canvas');
  out.width = picture.width;
  out.height = picture.height + Math.round(lay.height * scale);
  const ctx = out.getContext('2d');
  if (!transparent) { ctx.fillStyle = PALETTE.background; ctx.fillRect(0, 0, out.width, out.height); }
  ctx.drawImage(picture, 0, 0);
  ctx.translate(0, picture.height);
  ctx.font = `${12 * scale}px system-ui, sans-serif`;
  ctx.textBaseline = 'middle';
  for (const { x, y, item } of lay.at) {
    drawMark(ctx, scale, x, y, item);
    ctx.fillStyle = LEGEND_TEXT;
    ctx.fillText(item.label, (x + 22) * scale, y * scale);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// PNG

/** `n` clamped to [min, max] and rounded; `what` names the field in the note when it was changed. */
export function bounded(value, min, max, fallback, what) {
  const n = Number(value);
  if (String(value).trim() === '' || !Number.isFinite(n)) return { value: fallback, note: `${what}: not a number, ${fallback} used` };
  const v = Math.round(Math.min(max, Math.max(min, n)));
  return { value: v, note: v !== Math.round(n) ? `${what} is ${min} to ${max}: ${v} used` : '' };
}

/** The largest width ≤ `width` whose picture (at the source's aspect) has at most `pixels` pixels. */
function capArea(view, width, pixels) {
  const aspect = view.css[1] / view.css[0];
  return Math.max(1, Math.min(width, Math.floor(Math.sqrt(pixels / aspect))));
}

/**
 * The picture redrawn `width` pixels wide (height by the scene's aspect) as a PNG Blob, drawn by
 * an ExportView (the visible canvas is untouched). `legend`: items [{label, color, shape}] drawn
 * under it; `transparent`: no background.
 */
export async function pngBlob(view, width, { legend = null, transparent = false, progress = null, cancelled = () => false, view3d = null } = {}) {
  const ev = new ExportView(view, transparent);
  try {
    ev.follow(width);
    await ev.catchUp({ what: 'The PNG', progress, cancelled });
    ev.follow(width); // what came meanwhile (a run still going)
    await ev.catchUp({ what: 'The PNG', progress, cancelled });
    ev.drawLikeSource();
    // a spatial arm's 3-D view beside it, rendered now at the picture's height (export3d.js)
    const out = withLegend(beside(ev.canvas, render3d(view3d, ev.canvas.height), transparent), legend, ev.dpr, transparent);
    return await new Promise((resolve, reject) => out.toBlob((b) => (b ? resolve(b) : reject(new Error('the PNG could not be made (too big for this browser?)'))), 'image/png'));
  } finally { ev.dispose(); }
}


// ---------------------------------------------------------------------------------------------
// WebM and GIF

/** A MIME type this browser's MediaRecorder writes WebM in, or null. */
export function webmType() {
  if (typeof MediaRecorder === 'undefined') return null;
  return ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'].find((t) => MediaRecorder.isTypeSupported(t)) ?? null;
}

/**
 * What a canvas recording gives once `rec` stops: its `chunks` as a WebM with its duration and
 * cues written (fixWebm), or as recorded when that fails, at `size`; `failed()` is an error met
 * while drawing (named in the note). The stream's tracks are stopped and `dispose` runs first.
 * @param {MediaRecorder} rec @param {MediaStream} stream @param {Blob[]} chunks
 * @param {{width: number, height: number}} size @param {() => Error | null | undefined} failed
 * @param {() => void} [dispose]
 * @returns {Promise<{blob: Blob, width: number, height: number, note: string}>}
 */
export function recordedWebm(rec, stream, chunks, size, failed, dispose = () => {}) {
  return new Promise((resolve) => {
    rec.onstop = async () => {
      stream.getTracks().forEach((t) => t.stop());
      dispose();
      const raw = new Blob(chunks, { type: 'video/webm' });
      try {
        const fixed = fixWebm(new Uint8Array(await raw.arrayBuffer()));
        const err = failed();
        resolve({ blob: new Blob([fixed], { type: 'video/webm' }), ...size, note: err ? `drawing stopped: ${err.message}` : '' });
      } catch (e) {
        resolve({ blob: raw, ...size, note: `saved as recorded (no duration): ${e.message}` });
      }
    };
  });
}

/**
 * Record the picture as WebM `width` px wide (even; height by the scene) until `stop()`: an
 * ExportView follows `view` and is drawn `fps` times a second, each drawing a frame of the
 * stream. The run so far is drawn first, in steps (`progress`, `cancelled` as runSteps's); a
 * redraw the source makes while recording (a new run) is drawn in steps too, the video holding
 * its last frame meanwhile. Resolves, once recording, to {width, height, stop()}; `stop()`
 * resolves to {blob, width, height, note}: the WebM made seekable (webm.js), or as recorded with
 * a note when that failed.
 */
export async function recordWebm(view, { width, fps = 30, animFps = () => 10, progress = null, cancelled = () => false, view3d = null, lapse = null }) {
  const type = webmType();
  if (!type) throw new Error('this browser cannot record WebM (no MediaRecorder)');
  const ev = new ExportView(view, false, lapse); // lapse: a time-lapse (timelapse.js)
  try {
    ev.follow(width);
    await ev.catchUp({ what: 'The recording', progress, cancelled });
  } catch (e) { ev.dispose(); throw e; }
  ev.draw(performance.now(), animFps());
  // a spatial arm's 3-D view beside the top view: each frame composed on a canvas of their own
  // (the 3-D view as the page draws it, scaled to the video's height; an even width for the encoder)
  const side = () => render3d(view3d, ev.canvas.height, true);
  const first = side();
  const frameCanvas = first ? document.createElement('canvas') : ev.canvas;
  if (first) { // the size of the first frame for the whole video (the page's 3-D view may be resized meanwhile)
    const pic = beside(ev.canvas, first);
    frameCanvas.width = pic.width & ~1;
    frameCanvas.height = pic.height & ~1;
  }
  const compose = () => {
    if (frameCanvas === ev.canvas) return;
    const pic = beside(ev.canvas, side() ?? first);
    frameCanvas.getContext('2d').drawImage(pic, 0, 0, frameCanvas.width, frameCanvas.height);
  };
  compose();
  const stream = frameCanvas.captureStream(0);
  const track = stream.getVideoTracks()[0];
  const pixels = frameCanvas.width * frameCanvas.height;
  const rec = new MediaRecorder(stream, { mimeType: type, videoBitsPerSecond: Math.round(Math.min(25e6, Math.max(1e6, pixels * 2.5))) });
  const chunks = [];
  rec.ondataavailable = (e) => { if (e.data.size) chunks.push(e.data); };
  let failed = null, drawing = false, stopped = false;
  const frame = async () => {
    if (drawing) return; // a redraw in steps is under way: the video holds its last frame
    drawing = true;
    try {
      lapse?.advance();
      ev.follow(width);
      await ev.catchUp({ what: 'The recording', cancelled: () => stopped });
      ev.draw(performance.now(), animFps());
      compose();
      track.requestFrame();
    } catch (e) { if (!(e instanceof ExportCancelled)) failed ??= e; }
    drawing = false;
  };
  rec.start(250);
  track.requestFrame();
  const timer = setInterval(frame, 1000 / fps);
  return {
    width: frameCanvas.width,
    height: frameCanvas.height,
    stop: () => {
      clearInterval(timer);
      stopped = true;
      const done = recordedWebm(rec, stream, chunks, { width: frameCanvas.width, height: frameCanvas.height }, () => failed, () => ev.dispose());
      if (!drawing) {
        ev.follow(width);
        if (!ev.owed) { ev.draw(performance.now(), animFps()); compose(); track.requestFrame(); }
      }
      rec.stop();
      return done;
    },
  };
}

/** The page's fixed colours ('#rrggbb' of the palette and the legend text) as [r, g, b]. */
export function paletteColours() {
  const hex = [PALETTE.background, PALETTE.free, LEGEND_TEXT];
  for (const v of Object.values(PALETTE)) (Array.isArray(v) ? v : [v]).forEach((c) => hex.push(c));
  return hex.map(hexRgb).filter(Boolean);
}

/**
 * An animated GIF of the playback: `frames` pictures `width` px wide taken `fps` times a second
 * (the robot's animation at the times they stand for, so a slow machine does not stutter it),
 * looping forever. `legend`: items drawn under each picture. The run so far is drawn first, in
 * steps (`progress(share)` after each); `onFrame(k)` after each frame; `cancelled()` stops early
 * (while drawing the run: ExportCancelled; while taking frames: what was taken is kept).
 * Resolves to {blob, width, height, frames}.
 */
export async function recordGif(view, { width, frames, fps = LIMITS.gif.fps, animFps = () => 10, legend = null, onFrame = null, progress = null, cancelled = () => false, lapse = null }) {
  const ev = new ExportView(view, false, lapse); // lapse: a time-lapse, frames not waited for (timelapse.js)
  try {
    ev.follow(width);
    await ev.catchUp({ what: 'The GIF', progress, cancelled });
    const t0 = performance.now(), step = 1000 / fps;
    let writer = null, taken = 0, reader = null, readCtx = null;
    for (let k = 0; k < frames && !cancelled(); k++) {
      const due = t0 + k * step;
      const wait = due - performance.now();
      if (lapse) { lapse.to((k + 1) / frames); await breathe(); } else if (wait > 0) await new Promise((r) => setTimeout(r, wait));
      ev.follow(width);
      if (ev.owed) { // the source redrew its run (a new run): drawn in steps, then the frame
        try { await ev.catchUp({ what: 'The GIF', cancelled }); } catch (e) { if (e instanceof ExportCancelled) break; throw e; }
      }
      ev.draw(due, animFps());
      const pic = withLegend(ev.canvas, legend, ev.dpr, false);
      if (!reader) {
        reader = document.createElement('canvas');
        reader.width = pic.width;
        reader.height = pic.height;
        readCtx = reader.getContext('2d', { willReadFrequently: true });
      }
      readCtx.drawImage(pic, 0, 0);
      writer ??= new GifWriter(pic.width, pic.height, paletteColours());
      writer.add(readCtx.getImageData(0, 0, pic.width, pic.height), Math.round(100 / fps));
      taken++;
      onFrame?.(taken);
    }
    if (!writer) throw new Error('the GIF was cancelled before its first frame');
    return { blob: new Blob([writer.finish()], { type: 'image/gif' }), width: writer.width, height: writer.height, frames: taken };
  } finally { ev.dispose(); }
}

// ---------------------------------------------------------------------------------------------
// The page's controls

/**
 * Wire the page's export controls (#png-width, #video-width, #gif-width, #gif-frames,
 * #export-legend, #export-transparent, #export-png, #export-svg, #export-gif, #record,
 * #export-status) to `view`. `stem()` names the files, `legend()` gives the legend's items,
 * `animFps()` the robot animation's frames per second.
 */
export function wireExports({ view, stem, legend = () => [], animFps = () => 10, view3d = () => null }) {
  /** @param {string} id @returns {any} the page's element (an input or button) */
  const $ = (id) => document.getElementById(id);
  const status = $('export-status');
  const say = (...parts) => { status.textContent = shown(parts.filter(Boolean).join('. ')); };
  const options = () => ({ legend: $('export-legend').checked ? legend() : null, transparent: $('export-transparent').checked });
  const field = (id, min, max, fallback, what) => {
    const r = bounded($(id).value, min, max, fallback, what);
    if (r.note) $(id).value = String(r.value);
    return r;
  };
  const fail = (what, e) => say(`${what} failed: ${e?.message ?? e}`);
  // GIF and WebM: real time (0: what the page shows, as it plays) or the whole run in so many seconds
  const lapseSeconds = () => Number($('export-lapse')?.value) || 0;

  const pct = (share) => `${Math.floor(share * 100)}%`;

  /**
   * A button whose export draws in steps: a click starts `run({progress, cancelled})` (the
   * button then reads `busyText` and a second click cancels it); `run` resolves to the status
   * line's parts. While it draws, the status says how far it got.
   */
  const stepped = (button, what, run) => {
    const label = button.textContent;
    let busy = false, cancel = false;
    button.addEventListener('click', async () => {
      if (busy) { cancel = true; return; }
      busy = true;
      cancel = false;
      button.textContent = `Cancel ${label}`;
      button.setAttribute('aria-pressed', 'true');
      try {
        say(...await run({
          progress: (share) => { if (!cancel) say(`Drawing the ${what}: ${pct(share)}… (press Cancel ${label} to stop)`); },
          cancelled: () => cancel,
        }));
      } catch (e) {
        if (e instanceof ExportCancelled) say(`${e.message}: nothing was saved.`); else fail(what, e);
      }
      busy = false;
      button.textContent = label;
      button.setAttribute('aria-pressed', 'false');
    });
  };

  stepped($('export-png'), 'PNG', async (ctl) => {
    const asked = field('png-width', LIMITS.png.min, LIMITS.png.max, 1600, 'PNG width');
    const side = view3d();
    // with the 3-D view beside it, the top view is the width asked and the picture about twice as wide
    const width = capArea(view, asked.value, LIMITS.png.pixels / (side ? 2 : 1));
    const capped = width < asked.value ? `at most ${LIMITS.png.pixels / 1e6} million pixels: ${width} px wide` : '';
    const o = options();
    downloadBlob(await pngBlob(view, width, { ...o, ...ctl, view3d: side }), `${stem()}-${width}.png`);
    return [`PNG, ${width} px wide${side ? ', the 3-D view beside the top view' : ''}${o.legend ? ', with legend' : ''}${o.transparent ? ', transparent' : ''}`, asked.note, capped];
  });

  stepped($('export-svg'), 'SVG', async (ctl) => {
    const o = options();
    const { text, notes } = await runSteps(sceneSvgSteps(view, o), { what: 'The SVG', ...ctl });
    downloadBlob(new Blob([text], { type: 'image/svg+xml' }), `${stem()}.svg`);
    return [`SVG of the current picture${o.legend ? ', with legend' : ''}${o.transparent ? ', transparent' : ''}${notes.length ? ` (${notes.join('; ')})` : ''}`];
  });

  const gif = $('export-gif');
  let gifBusy = false, gifStop = false;
  gif.addEventListener('click', async () => {
    if (gifBusy) { gifStop = true; return; }
    const w = field('gif-width', LIMITS.gif.min, LIMITS.gif.max, 480, 'GIF width');
    const n = field('gif-frames', LIMITS.gif.frames[0], LIMITS.gif.frames[1], 40, 'GIF frames');
    const secs = lapseSeconds();
    let lapse = null;
    try { lapse = secs ? new TimeLapse(view.store, secs) : null; } catch (e) { fail('GIF', e); return; }
    // a time-lapse: 10 frames a second, at most the GIF's most frames (fewer a second beyond 15 s)
    const frames = lapse ? Math.min(LIMITS.gif.frames[1], secs * LIMITS.gif.fps) : n.value;
    const fps = lapse ? frames / secs : LIMITS.gif.fps;
    gifBusy = true;
    gifStop = false;
    gif.setAttribute('aria-pressed', 'true');
    gif.textContent = 'Stop GIF';
    try {
      const o = options();
      const r = await recordGif(view, {
        width: w.value, frames, fps, lapse, animFps, legend: o.legend, cancelled: () => gifStop,
        progress: (share) => { if (!gifStop) say(`Drawing the run for the GIF: ${pct(share)}… (press Stop GIF to cancel)`); },
        onFrame: (k) => { gif.textContent = `Stop GIF (${k}/${frames})`; },
      });
      downloadBlob(r.blob, `${stem()}.gif`);
      say(`GIF, ${r.width} × ${r.height}, ${r.frames} frames at ${+fps.toFixed(2)} fps${lapse ? `, the whole run in ${secs} s` : ''}, ${(r.blob.size / 1024).toFixed(0)} kB`,
        w.note, lapse ? '' : n.note,
        o.transparent ? 'a GIF has no transparent background' : '');
    } catch (e) {
      if (e instanceof ExportCancelled) say(`${e.message}: nothing was saved.`); else fail('GIF', e);
    }
    gifBusy = false;
    gif.textContent = 'GIF';
    gif.setAttribute('aria-pressed', 'false');
  });

  const record = $('record');
  let recording = null, preparing = null; // preparing: {cancel} while the run is drawn before recording
  let lapseTimer = 0; // a time-lapse stops and saves by itself, a second after the run's end
  record.disabled = !webmType();
  if (!webmType()) record.title = 'This browser cannot record WebM';
  record.addEventListener('click', async () => {
    if (recording) {
      clearTimeout(lapseTimer);
      const r = recording;
      recording = null;
      record.disabled = true;
      say('Saving the WebM…');
      const out = await r.stop();
      record.disabled = false;
      record.textContent = 'Record WebM';
      record.setAttribute('aria-pressed', 'false');
      downloadBlob(out.blob, `${stem()}-${out.width}.webm`);
      say(`WebM, ${out.width} × ${out.height}, ${(out.blob.size / 1024).toFixed(0)} kB`, out.note);
      return;
    }
    if (preparing) { preparing.cancel = true; return; }
    const asked = field('video-width', LIMITS.video.min, LIMITS.video.max, 1280, 'Video width');
    const secs = lapseSeconds();
    let lapse = null;
    try { lapse = secs ? new TimeLapse(view.store, secs) : null; } catch (e) { fail('Recording', e); return; }
    const prep = { cancel: false };
    preparing = prep;
    record.textContent = 'Cancel recording';
    record.setAttribute('aria-pressed', 'true');
    try {
      const side = view3d();
      let width = capArea(view, asked.value, LIMITS.video.pixels / (side ? 2 : 1));
      width -= width % 2; // video encoders want even sizes
      recording = await recordWebm(view, {
        width, animFps, cancelled: () => prep.cancel, view3d: side, lapse,
        progress: (share) => { if (!prep.cancel) say(`Drawing the run before recording: ${pct(share)}… (press Cancel recording to stop)`); },
      });
      record.textContent = 'Stop and save';
      if (lapse) lapseTimer = setTimeout(() => { if (recording) record.click(); }, secs * 1000 + 1000);
      say(`Recording ${recording.width} × ${recording.height}${lapse ? `, the whole run in ${secs} s (it saves by itself)` : ''}…`, asked.note,
        width < asked.value - 1 ? `at most ${(LIMITS.video.pixels / 1e6).toFixed(1)} million pixels` : '');
    } catch (e) {
      record.textContent = 'Record WebM';
      record.setAttribute('aria-pressed', 'false');
      if (e instanceof ExportCancelled) say(`${e.message}: nothing was saved.`); else fail('Recording', e);
    }
    preparing = null;
  });
}

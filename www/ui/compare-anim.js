// Compare's animations for a slide: both lanes side by side in one animated GIF or one WebM, each
// lane under its title and above its key numbers as in the PNG of both lanes (compare-export.js
// composeLanes). Each lane is drawn by an export view of its own (exports.js ExportView, at
// LANE_WIDTH px), so the page's canvases are never resized or redrawn for it. Its pace is the
// playground's (exports.js, timelapse.js): real time (both lanes as the page shows them as they
// play) or a time-lapse of both runs so far, each whole run in N s, both replays advancing
// together (the same share of each lane's steps in every frame). The GIF and WebM encoders are the
// playground's (gif.js, webm.js). A lane showing an arm in 3-D has no top view to film: refused.

import { ExportView, ExportCancelled, LIMITS, paletteColours, recordedWebm, webmType } from './exports.js';
import { TimeLapse } from './timelapse.js';
import { GifWriter } from './gif.js';
import { composeLanes } from './compare-export.js';
import { downloadBlob } from '../draw/stage.js';
import { shown } from './text.js';

/** Each lane's width in the animation, px: a GIF stays small, a WebM is sharp. */
export const LANE_WIDTH = Object.freeze({ gif: 320, webm: 640 });
/** A GIF in real time: this many frames at LIMITS.gif.fps (4 s). */
export const REAL_TIME_GIF_FRAMES = 40;
const WEBM_FPS = 30;

const breathe = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/**
 * Both lanes filmed together: `lanes` [{key, title, view, numbers: () => [[label, value]]}] (view:
 * the lane's top view), each `width` px wide; `seconds` > 0: a time-lapse of each lane's run so
 * far in that many seconds (0: real time). `even`: the frame's size rounded down to even (video).
 */
export class LanesFilm {
  constructor(lanes, width, seconds, even = false) {
    this.width = width;
    this.even = even;
    this.parts = lanes.map((l) => {
      const lapse = seconds ? new TimeLapse(l.view.store, seconds) : null;
      return { ...l, lapse, ev: new ExportView(l.view, false, lapse) };
    });
    this.out = null; // the frame canvas, sized by the first frame
  }

  /** Lay out both export views and draw each lane's run so far, in steps (runSteps options). */
  async prepare(options) {
    for (const p of this.parts) {
      p.ev.follow(this.width);
      await p.ev.catchUp(options);
    }
  }

  /** A time-lapse: show the share `f` of each lane's steps. */
  to(f) { for (const p of this.parts) p.lapse?.to(f); }

  /** A time-lapse: show the share of its seconds gone since the first call. */
  advance(now) { for (const p of this.parts) p.lapse?.advance(now); }

  /**
   * Draw both lanes at `time` (ms; the robots' animation, `animFps` frames a second) into the
   * frame canvas; a lane whose source redrew its run is drawn in steps first (`cancelled`).
   * @returns {Promise<HTMLCanvasElement>}
   */
  async frame(time, animFps, cancelled = () => false) {
    for (const p of this.parts) {
      p.ev.follow(this.width);
      if (p.ev.owed) await p.ev.catchUp({ what: 'The animation', cancelled });
      p.ev.draw(time, animFps);
    }
    const dpr = Math.max(1, this.parts[0].ev.dpr); // text one can read on a small frame
    const pic = composeLanes(this.parts.map((p) => ({ key: p.key, title: p.title, canvas: p.ev.canvas, numbers: p.numbers() })), dpr);
    if (!this.out) {
      this.out = document.createElement('canvas');
      this.out.width = this.even ? pic.width & ~1 : pic.width;
      this.out.height = this.even ? pic.height & ~1 : pic.height;
    }
    const ctx = this.out.getContext('2d', { willReadFrequently: !this.even });
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, this.out.width, this.out.height);
    ctx.drawImage(pic, 0, 0); // the first frame's size for all: numbers that wrap later are cut
    return this.out;
  }

  dispose() { for (const p of this.parts) p.ev.dispose(); }
}

/**
 * An animated GIF of both lanes: `frames` frames at `fps` (a time-lapse: the share k/frames of
 * both runs in frame k, not waited for; real time: taken as the page plays). `onFrame(k)` after
 * each; `cancelled()` stops (what was taken is kept). Resolves to {blob, width, height, frames}.
 */
export async function recordLanesGif(film, { frames, fps, animFps, progress = null, onFrame = null, cancelled = () => false }) {
  await film.prepare({ what: 'The GIF', progress, cancelled });
  const lapse = film.parts.some((p) => p.lapse);
  const t0 = performance.now(), step = 1000 / fps;
  let writer = null, taken = 0;
  for (let k = 0; k < frames && !cancelled(); k++) {
    const due = t0 + k * step;
    const wait = due - performance.now();
    if (lapse) { film.to((k + 1) / frames); await breathe(); } else if (wait > 0) await new Promise((r) => setTimeout(r, wait));
    let out;
    try { out = await film.frame(due, animFps(), cancelled); } catch (e) { if (e instanceof ExportCancelled) break; throw e; }
    writer ??= new GifWriter(out.width, out.height, paletteColours());
    writer.add(out.getContext('2d', { willReadFrequently: true }).getImageData(0, 0, out.width, out.height), Math.round(100 / fps));
    taken++;
    onFrame?.(taken);
  }
  if (!writer) throw new Error('the GIF was cancelled before its first frame');
  return { blob: new Blob([writer.finish()], { type: 'image/gif' }), width: writer.width, height: writer.height, frames: taken };
}

/**
 * Record both lanes as WebM until `stop()`: drawn WEBM_FPS times a second (a time-lapse advances
 * by the clock). Resolves, once recording, to {width, height, stop()}; stop() resolves to {blob,
 * width, height, note}: made seekable (webm.js), or as recorded with a note when that failed.
 */
export async function recordLanesWebm(film, { animFps, progress = null, cancelled = () => false }) {
  const type = webmType();
  if (!type) throw new Error('this browser cannot record WebM (no MediaRecorder)');
  await film.prepare({ what: 'The recording', progress, cancelled });
  const out = await film.frame(performance.now(), animFps());
  const stream = out.captureStream(0);
  const track = stream.getVideoTracks()[0];
  const rec = new MediaRecorder(stream, { mimeType: type, videoBitsPerSecond: Math.round(Math.min(25e6, Math.max(1e6, out.width * out.height * 2.5))) });
  const chunks = [];
  rec.ondataavailable = (e) => { if (e.data.size) chunks.push(e.data); };
  let failed = null, drawing = false, stopped = false;
  const draw = async () => {
    if (drawing) return; // a redraw in steps is under way: the video holds its last frame
    drawing = true;
    try {
      film.advance(performance.now());
      await film.frame(performance.now(), animFps(), () => stopped);
      track.requestFrame();
    } catch (e) { if (!(e instanceof ExportCancelled)) failed ??= e; }
    drawing = false;
  };
  rec.start(250);
  film.advance(performance.now());
  track.requestFrame();
  const timer = setInterval(draw, 1000 / WEBM_FPS);
  return {
    width: out.width,
    height: out.height,
    stop: () => {
      clearInterval(timer);
      stopped = true;
      const done = recordedWebm(rec, stream, chunks, { width: out.width, height: out.height }, () => failed);
      rec.stop();
      return done;
    },
  };
}

/**
 * Wire Compare's "GIF of both lanes" and "WebM of both lanes" buttons and its pace (`lapse`, a
 * select: 0 real time, else seconds). `lanes()` gives [{key, title, view, view3d, numbers}] (view3d
 * true: the lane shows an arm in 3-D); `animFps()` the robots' animation; `status` tells what was
 * saved or why not.
 * @param {{gif: HTMLButtonElement, webm: HTMLButtonElement, lapse: HTMLSelectElement, status: HTMLElement, lanes: () => any[], animFps: () => number}} o
 */
export function wireLanesAnimations({ gif, webm, lapse, status, lanes, animFps }) {
  const say = (...parts) => { status.textContent = shown(parts.filter(Boolean).join('. ')); };
  const seconds = () => {
    const v = Number(lapse.value);
    if (!Number.isFinite(v) || v < 0) throw new Error(`GIF and WebM pace: ${lapse.value} is not a number of seconds`);
    return v;
  };
  /** A film of both lanes, or an error naming why there is none. */
  const filmOf = (width, even) => {
    const ls = lanes();
    const arm = ls.find((l) => l.view3d);
    if (arm) throw new Error(`lane ${arm.key.toUpperCase()} shows an arm in 3-D, which has no top view to animate: use the PNG of both lanes`);
    return new LanesFilm(ls, width, seconds(), even);
  };
  const pct = (share) => `${Math.floor(share * 100)}%`;

  let gifBusy = false, gifStop = false;
  gif.addEventListener('click', async () => {
    if (gifBusy) { gifStop = true; return; }
    let film;
    try { film = filmOf(LANE_WIDTH.gif, false); } catch (e) { say(`The GIF of both lanes failed: ${e.message}`); return; }
    const secs = seconds();
    const frames = secs ? Math.min(LIMITS.gif.frames[1], secs * LIMITS.gif.fps) : REAL_TIME_GIF_FRAMES;
    const fps = secs ? frames / secs : LIMITS.gif.fps;
    gifBusy = true;
    gifStop = false;
    const label = gif.textContent;
    gif.setAttribute('aria-pressed', 'true');
    gif.textContent = 'Stop GIF';
    try {
      const r = await recordLanesGif(film, {
        frames, fps, animFps, cancelled: () => gifStop,
        progress: (share) => { if (!gifStop) say(`Drawing both runs for the GIF: ${pct(share)}… (press Stop GIF to cancel)`); },
        onFrame: (k) => { gif.textContent = `Stop GIF (${k}/${frames})`; },
      });
      downloadBlob(r.blob, 'planarium-compare.gif');
      say(`Saved planarium-compare.gif, ${r.width} × ${r.height}, ${r.frames} frames at ${+fps.toFixed(2)} fps${secs ? `, both whole runs in ${secs} s` : ''}, ${(r.blob.size / 1024).toFixed(0)} kB`);
    } catch (e) {
      say(e instanceof ExportCancelled ? `${e.message}: nothing was saved.` : `The GIF of both lanes failed: ${e?.message ?? e}`);
    } finally { film.dispose(); }
    gifBusy = false;
    gif.textContent = label;
    gif.setAttribute('aria-pressed', 'false');
  });

  const webmLabel = webm.textContent;
  let recording = null, preparing = null, film = null, lapseTimer = 0;
  webm.disabled = !webmType();
  if (!webmType()) webm.title = 'This browser cannot record WebM';
  webm.addEventListener('click', async () => {
    if (recording) {
      clearTimeout(lapseTimer);
      const r = recording;
      recording = null;
      webm.disabled = true;
      say('Saving the WebM of both lanes…');
      const out = await r.stop();
      film?.dispose();
      film = null;
      webm.disabled = false;
      webm.textContent = webmLabel;
      webm.setAttribute('aria-pressed', 'false');
      downloadBlob(out.blob, 'planarium-compare.webm');
      say(`Saved planarium-compare.webm, ${out.width} × ${out.height}, ${(out.blob.size / 1024).toFixed(0)} kB`, out.note);
      return;
    }
    if (preparing) { preparing.cancel = true; return; }
    try { film = filmOf(LANE_WIDTH.webm, true); } catch (e) { say(`The WebM of both lanes failed: ${e.message}`); return; }
    const secs = seconds();
    const prep = { cancel: false };
    preparing = prep;
    webm.textContent = 'Cancel recording';
    webm.setAttribute('aria-pressed', 'true');
    try {
      recording = await recordLanesWebm(film, {
        animFps, cancelled: () => prep.cancel,
        progress: (share) => { if (!prep.cancel) say(`Drawing both runs before recording: ${pct(share)}… (press Cancel recording to stop)`); },
      });
      webm.textContent = 'Stop and save';
      if (secs) lapseTimer = setTimeout(() => { if (recording) webm.click(); }, secs * 1000 + 1000);
      say(`Recording both lanes, ${recording.width} × ${recording.height}${secs ? `, both whole runs in ${secs} s (it saves by itself)` : ''}…`);
    } catch (e) {
      film?.dispose();
      film = null;
      webm.textContent = webmLabel;
      webm.setAttribute('aria-pressed', 'false');
      say(e instanceof ExportCancelled ? `${e.message}: nothing was saved.` : `The WebM of both lanes failed: ${e?.message ?? e}`);
    }
    preparing = null;
  });
}

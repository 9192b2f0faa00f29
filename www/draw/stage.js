// The stage: the workspace canvas, and beside it (or below it) the configuration-space canvas
// when the scenario has one. Each keeps its own aspect ratio inside its half of the stage.

/**
 * Size `view` (and `cspace` when it is active) to the stage now and whenever the stage or the
 * device pixel ratio changes. Returns the function that does it (call it after a load).
 */
export function fitViews(stage, view, cspace) {
  function resize() {
    const r = stage.getBoundingClientRect();
    const cs = getComputedStyle(stage);
    const w = r.width - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
    const h = r.height - parseFloat(cs.paddingTop) - parseFloat(cs.paddingBottom);
    const dpr = window.devicePixelRatio || 1;
    if (!cspace.active) {
      stage.classList.remove('stacked');
      view.resize(Math.max(40, w), Math.max(40, h), dpr);
      return;
    }
    // side by side or stacked, whichever leaves the larger pictures
    const gap = parseFloat(cs.columnGap) || 0;
    const row = Math.min((w - gap) / 2, h) >= Math.min(w, (h - gap) / 2);
    stage.classList.toggle('stacked', !row);
    const [bw, bh] = row ? [(w - gap) / 2, h] : [w, (h - gap) / 2];
    view.resize(Math.max(40, bw), Math.max(40, bh), dpr);
    cspace.resize(Math.max(40, bw), Math.max(40, bh), dpr);
  }
  let dprQuery = null;
  function watchDpr() {
    dprQuery?.removeEventListener('change', onDprChange);
    dprQuery = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
    dprQuery.addEventListener('change', onDprChange);
  }
  function onDprChange() { watchDpr(); resize(); }
  new ResizeObserver(resize).observe(stage);
  watchDpr();
  resize();
  return resize;
}

/** Offer `text` as a file download named `name`. */
export function downloadText(text, name) {
  downloadBlob(new Blob([text], { type: 'text/plain' }), name);
}

/** Offer `blob` as a file download named `name`. */
export function downloadBlob(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** On a narrow screen (a phone) the stage may be scrolled away: bring it back into view. */
export function keepInView(stage) {
  if (!matchMedia('(max-width: 760px)').matches) return;
  const r = stage.getBoundingClientRect();
  if (r.top < 0 || r.bottom > innerHeight) stage.scrollIntoView({ block: 'start', behavior: 'smooth' });
}

// The stage: the workspace canvas, and beside it (or below it) the configuration-space canvas
// when the scenario has one. Each keeps its own aspect ratio inside its half of the stage.

/**
 * Size `view` (and `second`, the c-space's or the 3-D view, when it is active) to the stage now
 * and whenever the stage or the device pixel ratio changes. `second.share` is the second view's
 * part of the stage (a half unless said: the 3-D view takes the larger share); `second.solo()`,
 * when it gives 'first' or 'second', shows that view alone in the whole stage (a phone showing the
 * 3-D view or the view from above, see `PhoneStage`). Returns the function that does it (call it
 * after a load).
 */
export function fitViews(stage, view, second) {
  function resize() {
    const r = stage.getBoundingClientRect();
    const cs = getComputedStyle(stage);
    const w = r.width - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
    const h = r.height - parseFloat(cs.paddingTop) - parseFloat(cs.paddingBottom);
    const dpr = window.devicePixelRatio || 1;
    const solo = second.active ? second.solo?.() : 'first';
    if (!second.active || solo) {
      stage.classList.remove('stacked');
      (solo === 'second' ? second : view).resize(Math.max(40, w), Math.max(40, h), dpr);
      return;
    }
    // side by side or stacked, whichever leaves the second view the larger picture
    const gap = parseFloat(cs.columnGap) || 0;
    const share = Math.min(0.8, Math.max(0.2, second.share ?? 0.5));
    const row = Math.min((w - gap) * share, h) >= Math.min(w, (h - gap) * share);
    stage.classList.toggle('stacked', !row);
    const along = (row ? w : h) - gap;
    const [a, b] = [along * (1 - share), along * share];
    const [aw, ah, bw, bh] = row ? [a, h, b, h] : [w, a, w, b];
    view.resize(Math.max(40, aw), Math.max(40, ah), dpr);
    second.resize(Math.max(40, bw), Math.max(40, bh), dpr);
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

/** The width up to which the page is laid out for a phone (style.css's narrow layout). */
export const PHONE = '(max-width: 760px)';

/**
 * A phone's stage for a 3-D scene: one view at a time (the 3-D view first, a button turns to the
 * view from above and back), the stage as high as the first screen leaves below what is above it
 * and above the run bar, so the scenario, the planner, Run and the arm are all in the first screen.
 */
export class PhoneStage {
  /**
   * @param {HTMLElement} stage
   * @param {HTMLButtonElement} toggle the button that turns between the two views
   * @param {HTMLElement} runBar
   * @param {() => void} onChange the views are to be sized again
   */
  constructor(stage, toggle, runBar, onChange) {
    this.stage = stage;
    this.toggle = toggle;
    this.runBar = runBar;
    this.onChange = onChange;
    this.spatial = false; // the scene has a 3-D view
    this.above = false;   // the view from above is shown instead of the 3-D view
    this.query = matchMedia(PHONE);
    this.query.addEventListener('change', () => this.sync());
    toggle.addEventListener('click', () => { this.above = !this.above; this.sync(); });
    new ResizeObserver(() => this.fitHeight()).observe(document.body);
  }

  /** Which view is alone on the stage: 'first' (from above), 'second' (3-D) or null (both). */
  solo() {
    if (!this.spatial || !this.query.matches) return null;
    return this.above ? 'first' : 'second';
  }

  /** The scene has a 3-D view (`spatial`) or not. */
  setSpatial(spatial) {
    if (spatial !== this.spatial) this.above = false;
    this.spatial = spatial;
    this.sync();
  }

  sync() {
    const solo = this.solo();
    this.stage.classList.toggle('spatial', this.spatial);
    this.stage.classList.toggle('solo-first', solo === 'first');
    this.stage.classList.toggle('solo-second', solo === 'second');
    this.toggle.hidden = !solo;
    this.toggle.textContent = solo === 'first' ? 'View in 3-D' : 'View from above';
    this.toggle.setAttribute('aria-pressed', String(solo === 'first'));
    this.fitHeight();
    this.onChange();
  }

  /** On a phone with a 3-D scene, the stage ends above the run bar at the foot of the first screen. */
  fitHeight() {
    const style = this.stage.style;
    if (!this.solo()) { if (style.height) style.height = ''; return; }
    const top = this.stage.getBoundingClientRect().top + window.scrollY;
    const bar = this.runBar.getBoundingClientRect().height;
    const most = Math.min(0.92 * innerWidth, 0.75 * innerHeight);
    const h = `${Math.round(Math.max(192, Math.min(most, innerHeight - top - bar - 16)))}px`;
    if (style.height !== h) style.height = h;
  }
}

/** On a narrow screen (a phone) the stage may be scrolled away: bring it back into view. */
export function keepInView(stage) {
  if (!matchMedia(PHONE).matches) return;
  const r = stage.getBoundingClientRect();
  if (r.top < 0 || r.bottom > innerHeight) stage.scrollIntoView({ block: 'start', behavior: 'smooth' });
}

/**
 * On a phone the cost chart and the step's caption (`boxes`, in this order) sit right under the
 * run bar (`after`), compact, instead of far below in the explanation and the stats; back in their
 * places on a wider screen.
 */
export function underRunBar(boxes, after) {
  const homes = boxes.map((box) => [box, box.parentElement, box.nextElementSibling]);
  const query = matchMedia(PHONE);
  const place = () => {
    if (query.matches) after.after(...boxes);
    else for (const [box, home, next] of homes) home.insertBefore(box, next);
  };
  query.addEventListener('change', place);
  place();
}

/**
 * On a phone, scroll the least that brings `box` whole into the screen when it is not (the step's
 * caption under the run bar after a step); the focus stays where it is.
 */
export function showWhole(box) {
  if (!matchMedia(PHONE).matches) return;
  const r = box.getBoundingClientRect();
  if (r.top < 0 || r.bottom > innerHeight) box.scrollIntoView({ block: 'nearest', behavior: 'smooth' });
}

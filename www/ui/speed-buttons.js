// Slow / Normal / Fast / Instant: presets of a page's replay-length slider (controls.js
// speedSeconds: the whole run in about 40, 15 and 5 s, or every event at once), as radio buttons
// that show which preset the slider is at. The playground's run bar and Compare's "Run both" use
// the same ids (speed-slow, speed-normal, speed-fast, speed-instant).

/** The slider's value for each preset button's id. */
export const SPEED_PRESETS = Object.freeze({ 'speed-slow': 10, 'speed-normal': 33, 'speed-fast': 60, 'speed-instant': 100 });

/**
 * Wire the preset buttons to `speed` (a range input): a click sets it and calls `changed()`.
 * Returns sync(), which marks the button the slider is at (call it when the slider moves).
 * @param {HTMLInputElement} speed
 * @param {() => void} changed
 * @returns {() => void}
 */
export function wireSpeedButtons(speed, changed) {
  /** @type {[HTMLElement, number][]} */
  const buttons = Object.entries(SPEED_PRESETS).map(([id, v]) => {
    const b = document.getElementById(id);
    if (!b) throw new Error(`speed presets: the page has no #${id}`);
    b.addEventListener('click', () => {
      speed.value = String(v);
      changed();
    });
    return /** @type {[HTMLElement, number]} */ ([b, v]);
  });
  return () => {
    for (const [b, v] of buttons) b.setAttribute('aria-checked', String(Number(speed.value) === v));
  };
}

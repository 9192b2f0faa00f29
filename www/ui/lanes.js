// The compare page's two lanes as one: their views from above zoom and pan together, and on a
// phone they are tabs A / B, one shown at a time.

import { wirePlaneZoom, zoomBar } from './plane-zoom.js';

/**
 * Zoom and pan on the plane (plane-zoom.js: wheel, middle drag, pinch, − Fit +, keys over a lane)
 * for every lane, linked: whatever one lane shows, the others show (the same region of the same
 * scenario side by side). Each lane gets its bar in its `stage`; `onChange` is called 200 ms after
 * the last change (the page's link).
 * @param {{canvas: HTMLCanvasElement, view: any, stage: HTMLElement}[]} lanes
 * @param {() => void} onChange
 */
export function wireLinkedZoom(lanes, onChange) {
  let linking = false;
  let timer = 0;
  for (const lane of lanes) {
    const bar = zoomBar();
    lane.stage.append(bar);
    wirePlaneZoom({
      canvas: lane.canvas, view: lane.view, bar,
      onChange: () => {
        if (!linking) {
          linking = true;
          try {
            for (const o of lanes) if (o !== lane) o.view.setViewport(lane.view.viewport);
          } finally {
            linking = false;
          }
        }
        clearTimeout(timer);
        timer = setTimeout(onChange, 200);
      },
    });
  }
}

/**
 * The phone's tabs: `tabA` and `tabB` show lane a or b (`lanes.dataset.tab`, which the CSS reads);
 * the left and right arrows move between them.
 * @param {{lanes: HTMLElement, tabA: HTMLElement, tabB: HTMLElement}} elements
 */
export function wireLaneTabs({ lanes, tabA, tabB }) {
  const show = (key) => {
    lanes.dataset.tab = key;
    tabA.setAttribute('aria-selected', String(key === 'a'));
    tabB.setAttribute('aria-selected', String(key === 'b'));
  };
  tabA.addEventListener('click', () => show('a'));
  tabB.addEventListener('click', () => show('b'));
  for (const tab of [tabA, tabB]) {
    tab.addEventListener('keydown', (e) => {
      if (e.key !== 'ArrowLeft' && e.key !== 'ArrowRight') return;
      const next = tab === tabA ? tabB : tabA;
      show(next === tabA ? 'a' : 'b');
      next.focus();
    });
  }
}

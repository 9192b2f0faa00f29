// embed.html: one <planarium-playground> filling the frame, set up by the page's hash (the share-link
// grammar of ui/links.js, plus autoplay, click and controls), e.g.
//   embed.html#scenario=narrow&planner=rrt-connect&autoplay&controls=step,reset
// A new hash (the frame's src changed only after the #) sets it up again. No key listener is put on
// the document: keys reach the embed only while it has focus. The page's main landmark holds the
// element; its heading (read by screen readers only) and title name the scenario and the planner.
import '../planarium-playground.js';

const main = /** @type {HTMLElement} */ (document.getElementById('embed'));
const title = /** @type {HTMLElement} */ (document.getElementById('embed-title'));
const player = document.createElement('planarium-playground');
player.setAttribute('fill', '');
player.setAttribute('link', location.hash.replace(/^#/, ''));
main.append(player);

player.addEventListener('loaded', (e) => {
  const { scenario, plannerLabel } = e.detail;
  title.textContent = `${scenario || 'A scenario'}${plannerLabel ? ` with ${plannerLabel}` : ''} — Planarium`;
  document.title = title.textContent;
});
window.addEventListener('hashchange', () => player.setAttribute('link', location.hash.replace(/^#/, '')));

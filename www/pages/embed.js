// embed.html: one <planarium-playground> filling the frame, set up by the page's hash (the share-link
// grammar of ui/links.js, plus autoplay, click and controls), e.g.
//   embed.html#scenario=narrow&planner=rrt-connect&autoplay&controls=step,reset
// A new hash (the frame's src changed only after the #) sets it up again. No key listener is put on
// the document: keys reach the embed only while it has focus.
import '../planarium-playground.js';

const player = document.createElement('planarium-playground');
player.setAttribute('fill', '');
player.setAttribute('link', location.hash.replace(/^#/, ''));
document.body.append(player);

window.addEventListener('hashchange', () => player.setAttribute('link', location.hash.replace(/^#/, '')));

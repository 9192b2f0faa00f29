// The playground's share link, written (pages/main.js restores one): the state shown (scenario,
// planner set-up, overlays, the view's sliders) is kept in the URL hash a moment after each change
// (links.js writeShare), with the Copy link box and Save JSON (a scenario too large for a link) and
// the Compare / Benchmark links, which open on the same state. A link opened with problems stays in
// the address bar as pasted (and its problems are shown with it, cut) until the state shown changes.

import { writeShare, checkLink, boundedProblems, MAX_LINK_CHARS } from './links.js';
import { MAX_HASH_CHARS, MAX_SCENARIO_BYTES } from './scenario-codec.js';
import { cut } from './text.js';

/**
 * Wire the hash writer. `writable()`: whether the state shown may be written now (the first state
 * is in place, a valid scenario is loaded); `source()`: where the scenario came from ({id}: a
 * built-in as shipped; {custom}); `scenarioText()`: the scenario as the worker normalised it;
 * `state()`: {config, overlays, view} for writeShare; `registry()`; `saveName()`: the Save JSON
 * file's stem; `bench`: the link to the benchmark page. Returns {schedule, write, stateHash, showProblems, cancel} and the `pasted` and
 * `lastHash` state the restoring side reads and resets.
 * @param {{ui: any, bench: HTMLAnchorElement, writable: () => boolean, ready: () => boolean, source: () => any,
 *   scenarioText: () => string | null, state: () => any, registry: () => any, saveName: () => string,
 *   download: (text: string, name: string) => void, showError: (text: string) => void}} options
 */
export function wireShareHash({ ui, bench, writable, ready, source, scenarioText, state, registry, saveName, download, showError }) {
  let shareTimer = 0;
  let shareGen = 0;
  let lastHash = null;          // the hash this page wrote last (a hashchange to it is ours)
  // A link opened with problems stays in the address bar, as pasted, until the state shown changes
  // (the hash of the state it restored is `state`), so it can be copied back to whoever sent it.
  let pasted = null;            // {hash, state: a promise of the restored state's hash}
  const encodedScenarios = new Map();

  /** Keep the hash up to date, a moment after the last change. */
  function schedule() {
    if (!ready()) return;
    clearTimeout(shareTimer);
    shareTimer = setTimeout(() => { write(); }, 250);
  }

  /**
   * Write the current state into the hash now; resolves to the page's full link. A hash too long to
   * be read back is not written (the address bar loses its hash: a reload shows the first built-in);
   * `force`: write it even over a pasted link with problems (Copy link).
   */
  async function write({ force = false } = {}) {
    clearTimeout(shareTimer);
    if (!writable()) return location.href;
    const gen = ++shareGen;
    const hash = await stateHash();
    const restored = pasted && !force ? await pasted.state : null;
    if (gen !== shareGen) return location.href; // a newer write is on its way
    const here = `${location.origin}${location.pathname}${location.search}`;
    const readable = hash.length <= MAX_HASH_CHARS && (source().id || scenarioText().length <= MAX_SCENARIO_BYTES);
    ui.shareUrl.value = readable && here.length + hash.length < MAX_LINK_CHARS ? `${here}#${hash}` : '';
    syncPageLinks(ui.shareUrl.value ? hash : '');
    if (restored === hash) return `${here}#${hash}`; // the link as pasted stays in the address bar
    pasted = null;
    lastHash = readable ? `#${hash}` : '';
    if (location.hash !== lastHash) history.replaceState(history.state, '', `${location.pathname}${location.search}${lastHash}`);
    return `${here}#${hash}`;
  }

  /** The hash (without `#`) of the state shown. */
  function stateHash() {
    const s = source();
    return writeShare({ scenario: s.id ? { id: s.id } : { text: scenarioText() }, ...state() }, registry(), encodedScenarios);
  }

  /** A link's problems (at most a screenful, repeats once), and the link as it was opened, cut. */
  function showProblems(notes) {
    const lines = boundedProblems(notes, 12);
    const link = pasted ? `${location.origin}${location.pathname}${location.search}${pasted.hash}` : '';
    showError(`Some of this link could not be used:\n• ${lines.join('\n• ')}`
      + (link ? `\nThe link you opened (${link.length.toLocaleString('en')} characters; it stays in the address bar until you change something):\n${cut(link, 300)}` : ''));
  }

  // Compare and Benchmark open on the state shown here (they read the playground's share hash:
  // scenario, even an edited or opened one, and the planner set-up)
  function syncPageLinks(hash) {
    ui.compare.href = hash ? `compare.html#${hash}` : 'compare.html';
    bench.href = hash ? `bench.html#${hash}` : 'bench.html';
  }

  wireCopyLink({
    button: ui.copyLink, url: ui.shareUrl, status: ui.copyStatus, saveJson: ui.saveJson,
    link: () => write({ force: true }), scenarioText: () => (source()?.id ? null : scenarioText()),
  });

  // a scenario too large for a link: offered as a file (the scenario as the worker normalised it)
  ui.saveJson.addEventListener('click', () => {
    const text = scenarioText();
    if (!text) return;
    const name = saveName().replace(/[^\w.-]+/g, '-').toLowerCase().slice(0, 60) || 'scenario';
    download(`${JSON.stringify(JSON.parse(text), null, 2)}\n`, `${name}.json`);
  });

  return {
    schedule, write, stateHash, showProblems,
    cancel: () => clearTimeout(shareTimer),
    get pasted() { return pasted; },
    set pasted(v) { pasted = v; },
    get lastHash() { return lastHash; },
    set lastHash(v) { lastHash = v; },
  };
}

/**
 * The playground's Copy link button: `link()` writes the state's link (a promise); it is copied
 * only when it reads back as it is (the reader's limits, `scenarioText()` for a scenario carried
 * in it) and survives pasting (its length). Otherwise `status` says why and `saveJson` (the
 * scenario as a file) is offered instead; without a clipboard the link is selected in `url`.
 */
export function wireCopyLink({ button, url, status, saveJson, link, scenarioText }) {
  button.addEventListener('click', async () => {
    status.textContent = '';
    saveJson.hidden = true;
    const href = await link();
    const why = await checkLink(href, scenarioText());
    if (why) {
      url.value = '';
      status.textContent = `No link copied: ${why}. Save the scenario as a JSON file instead and share the file `
        + '(Open file… opens it).';
      saveJson.hidden = false;
      return;
    }
    url.value = href;
    try {
      await navigator.clipboard.writeText(href);
      status.textContent = 'Copied.';
    } catch {
      url.select();
      status.textContent = 'Copy the selected link (the clipboard is not available here).';
    }
  });
}

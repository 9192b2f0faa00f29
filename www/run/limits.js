// The page's own limits, in one place, each with why it has the value it has. The core has its
// own (its ParamSpec ranges, docs/limits.md); these are what the page, its worker session and its
// stores can hold or wait for.

/**
 * How long a worker may take to acknowledge cancel, reset, configure or load/import (the `ack`
 * reply, posted as soon as the message is read) before it is terminated and replaced. A worker
 * reads messages between batches of BATCH_MS (12 ms) planning, so a healthy one answers within a
 * few tens of milliseconds even on a loaded machine; one second is long enough never to replace a
 * healthy worker and short enough that Cancel, then Run, starts a fresh run at once.
 */
export const WATCHDOG_MS = 1000;

// The largest file Open file… reads (the core's limits::MAX_TEXT_BYTES, 16 MiB: it refuses more
// anyway; the page refuses before reading, so a huge file never fills the tab's memory).
export const MAX_FILE_BYTES = 16 * 1024 * 1024;

/**
 * Worker deaths (crashes and watchdog replacements) within CRASH_WINDOW_MS after which the page
 * stops replacing the worker on its own (the `stopped` state): a scenario that crashes the core
 * on load would otherwise be reloaded, and crash it, forever. Any user action that loads a
 * scenario starts a fresh worker again.
 */
export const CRASH_LIMIT = 3;
export const CRASH_WINDOW_MS = 10000;

/**
 * The page's ceiling on the `max_nodes` run parameter, from a memory budget. Measured in chromium
 * (tests/js/page-recovery.test.mjs, "reproduction 7"): RRT* on narrow grown to 20,000 nodes
 * reveals about 3 records per node (samples, rejections, nodes; 96 bytes each) and keeps 45 bytes
 * per node in the tree mirror: 336 bytes per node in use, 388 held (chunks are allocated whole),
 * and the JS heap grew by about 508 bytes per node. At 500 bytes per node, 1,000,000 nodes keep the
 * page's stores near 0.5 GB, what a laptop's renderer can hold beside the worker's own copy of the
 * trees; a run of 9.7 M nodes once took 5.2 GB. The ceiling equals the core's own maximum for
 * `max_nodes`, and it stays here so that the figure, and a lower ceiling if the stores ever grow,
 * live in one place (panel fields and links are held to it: applyPageLimits).
 */
export const PAGE_BYTES_PER_NODE = 500;
export const PAGE_MAX_NODES = 1000000;

/**
 * Records per chunk of the page's record store (playback.js RecordStore): 16,384 records of 12
 * numbers are 1.5 MB. The store grows by adding chunks, never by copying what it holds, so a run of
 * millions of records never freezes the page while the store grows.
 */
export const STORE_CHUNK_RECORDS = 16384;

/**
 * The most records the playback reveals (and the views draw) in one animation frame, at any speed:
 * at "all at once" a frame shows everything queued up to this many, the rest in the next frames.
 * When the worker sends records faster than the page draws them (grid search on a 998×998 map
 * sends two million cell records in a few seconds), an unbounded frame grew with the queue and
 * froze the tab for seconds; 50,000 records take some tens of milliseconds to store, mirror and
 * draw, and at 60 frames a second that is 3 million records a second, more than any planner sends.
 */
export const REVEAL_PER_FRAME = 50000;

/**
 * Within REVEAL_PER_FRAME, what a frame reveals follows what drawing costs on this machine: the
 * records the last frame took REVEAL_MS to store, mirror and draw (nextRevealCap), never fewer than
 * MIN_REVEAL_PER_FRAME. Measured in headless chromium (tests/js/page-zoom.test.mjs, a walled-in
 * RRT at "all at once"): 50,000 records a frame gave frames of 33 ms median, 83 ms at the 95th
 * percentile while a tree grew; 8 ms of records a frame keeps the page near 60 frames a second
 * and still shows about a million records a second on a laptop, a million-node tree within seconds.
 */
export const REVEAL_MS = 8;
export const MIN_REVEAL_PER_FRAME = 10000; // a busy machine still shows 600,000 records a second at 60 frames

/**
 * The next frame's cap on records revealed, after `n` records took `ms` to reveal and draw under
 * cap `cap` (halfway to the count that fits REVEAL_MS; too few records to measure keep the cap).
 */
export function nextRevealCap(cap, n, ms) {
  if (n < 1000 || !(ms > 0)) return cap;
  const fit = (n * REVEAL_MS) / ms;
  return Math.round(Math.min(REVEAL_PER_FRAME, Math.max(MIN_REVEAL_PER_FRAME, (cap + fit) / 2)));
}

/**
 * The registry the worker posted, with the page's ceilings applied to the run parameters (the
 * panel and share links then refuse larger values with the parameter's range in words).
 */
export function applyPageLimits(registry) {
  const clamp = (spec) => (spec.name === 'max_nodes' && spec.max > PAGE_MAX_NODES
    ? { ...spec, max: PAGE_MAX_NODES, default: Math.min(spec.default, PAGE_MAX_NODES),
      doc: `${spec.doc} This page holds at most ${PAGE_MAX_NODES.toLocaleString('en')} (memory).` }
    : spec);
  return { ...registry, run_params: (registry.run_params || []).map(clamp) };
}

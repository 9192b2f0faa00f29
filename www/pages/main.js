// Wiring: one player (player.js: the controller's table, a lane with the worker session, its
// playback, the views and the chart, the actions and the frame loop), the panel, the overlay box
// and the stats; the hover text of cells and potential fields (cells.js), and the note under the
// canvas when a planner finds no path; the share link (ui/links.js; written by ui/share-hash.js):
// the state is kept in the URL hash, and a page opened with a hash restores it. A link with
// problems stays in the address bar as pasted (and is shown with them) until the state changes;
// Copy link checks the link reads back and is short enough to paste (ui/links.js checkLink), else
// offers Save JSON. When the worker crashed or was replaced (the session's watchdog), the message
// says so and offers "Open the default scenario instead", which leaves the hash's state (a
// crashing scenario would otherwise come back with every reload).
// Read-only state for tests is exposed as window.planarium (nothing else is global).

import { BUTTONS } from '../run/controller.js';
import { View } from '../draw/view.js';
import { PALETTE } from '../draw/palette.js';
import { CSpaceView } from '../draw/cspace.js';
import { View3dSlot, view3dHooks } from '../draw/view3d-slot.js';
import { Editor } from '../ui/editor.js';
import { ObstacleEditor } from '../ui/obstacle-editor.js';
import { PosePanel } from '../ui/pose3d.js';
import { BoxesPanel } from '../ui/boxes3d.js';
import { PathPanel } from '../ui/path3d.js';
import { wireExports } from '../ui/exports.js';
import { fitViews, downloadText, keepInView, PhoneStage, underRunBar } from '../draw/stage.js';
import { createPanel, taskOf } from '../ui/panel.js';
import { Playback } from '../run/playback.js';
import { Chart } from '../draw/chart.js';
import { Player } from '../run/player.js';
import { wireRoadmapQuery, answersQueries } from '../ui/roadmap-query.js';
import { createStats } from '../ui/stats.js';
import { createOverlays } from '../draw/overlays.js';
import { cellLegend, cellSummary } from '../draw/cells.js';
import { linkViews } from '../draw/linked.js';
import { wirePlaneZoom } from '../ui/plane-zoom.js';
import { ExplainPanel } from '../ui/explain-panel.js';
import { createTrials } from '../ui/trials.js';
import { wireKeys, wireCellTip } from '../ui/keys.js';
import { runStatusText } from '../ui/run-status.js';
import { wireA11y } from '../ui/a11y.js';
import { wireSpeedButtons } from '../ui/speed-buttons.js';
import { chartKind, speedSeconds, animFps, describeSpeed, modelSummary, fillScenarioPicker, errorBox, fillLegend, removeCustomScenarios, markCustomScenario, invalidText } from '../ui/controls.js';
import { readShare, setupFor, VIEW_DEFAULTS } from '../ui/links.js';
import { wireShareHash } from '../ui/share-hash.js';
import { wireEmbedCode } from '../ui/embed-code.js';
import { wireOpenFile } from '../ui/open-file.js';
import { OVERLAYS } from '../draw/palette.js';
import { applyPageLimits } from '../run/limits.js';
import { shown } from '../ui/text.js';
import { ScenarioSource } from '../run/scenario-source.js';
import { dragsPosition } from '../draw/capabilities.js';

/**
 * The page's element `id`. Its kind is the HTML's (input, select, button, canvas, dialog…), so it
 * is typed loosely here and checked by the browser tests.
 * @param {string} id
 * @returns {any}
 */
const $ = (id) => document.getElementById(id);
const ui = {
  scenario: $('scenario'), file: $('file'), error: $('error'), errorText: $('error-text'), errorClose: $('error-close'),
  stage: $('stage'), canvas: $('canvas'), cspace: $('cspace'), view3d: $('view3d'), course: $('scenario-course'), name: $('scenario-name'),
  notes: $('scenario-notes'), legend: $('legend'), endpoints: $('endpoints'), download: $('download-solution'),
  panel: $('panel'), stepSize: $('step-size'), speed: $('speed'), speedOut: $('speed-out'),
  animSpeed: $('anim-speed'), animOut: $('anim-speed-out'), animRaw: $('anim-raw'), overlays: $('overlays'),
  stats: $('stats'), chartBox: $('chart-box'), chart: $('chart'), chartTitle: $('chart-title'), compare: $('to-compare'),
  tip: $('cell-tip'), runNote: $('run-note'), back: $('step-back'), copyLink: $('copy-link'), shareUrl: $('share-url'),
  copyStatus: $('copy-status'), saveJson: $('save-json'), defaultScenario: $('error-default'),
};
const errors = errorBox(ui.error, ui.errorText);
const showError = (text) => { ui.defaultScenario.hidden = true; errors.show(text); };
const clearError = () => { ui.defaultScenario.hidden = true; errors.clear(); };

const playback = new Playback();
const view = new View(ui.canvas, playback.store, playback.model);
view.onLegend = () => buildLegend(); // a new query's answer gets its legend entry
const cspace = new CSpaceView(ui.cspace, playback.store, PALETTE, playback.model);
// A robot in 3-D (the core's caps.view3d) gets a 3-D view beside the top view; www/draw3d/ is
// imported only then.
const view3d = new View3dSlot(ui.view3d, playback.store, PALETTE, () => syncStage());
view3d.onCamera = () => scheduleShare(); // the camera goes in the share link
const chart = new Chart(ui.chart, playback.model, PALETTE);
const updateStatsList = createStats(ui.stats);
const explain = new ExplainPanel($('explain'), playback.store, view);

let registry = null;     // {planners, run_params} from the first `ready`
let panel = null;
let builtins = [];
// The scenario and why it was loaded (built-in, edit, file, link, reload), where it came from (a
// link carries a built-in's id, else its text) and a link's state waiting for its scenario.
const src = new ScenarioSource({ matchBuiltins: true });
let loaded = null;       // the latest `loaded` message's scenario
let loadedCaps = null;   // and what the core decided for it (scene_caps: solution file, c-space view, pose)
let optimum = null;      // its shortest path's cost when that is the robot's optimum (the cost chart's line)

const player = new Player({
  playback,
  views: [view, cspace, explain, view3d],
  chart,
  duration: () => speedSeconds(ui.speed),
  fps: () => animFps(ui.animSpeed),
  hooks: {
    ready: onReady,
    /** @param {import('../run/messages.js').LoadedReply} msg */
    loaded(msg) {
      // an edit that gives back a built-in exactly (say, "Restore start and goal") is that built-in again
      const { restore, defaults } = src.loaded(msg.scenario);
      showScenario(msg);
      panel.setTask(taskOf(msg.scenario));
      if (restore) {
        const { block, problems } = setupFor(restore, msg.scenario, registry, panel.planner().name);
        panel.apply(block);
        const notes = [...src.takeNotes(), ...problems];
        if (notes.length) {
          share.showProblems(notes);
          if (share.pasted) share.pasted.state = share.stateHash(); // the state the link restored: the pasted link stays until it changes
        } else share.pasted = null;
      } else if (defaults) {
        panel.apply(msg.scenario.planner);
      }
      configure(); // fires 'configure' only from states that allow it; then 'loaded' below
      controller.fire('loaded');
    },
    invalid(error) {
      const link = src.refused();
      if (link) { // a link's scenario the core refuses: say why, show the first built-in instead
        const where = error.path ? ` at ${error.path}` : error.line != null ? ` at line ${error.line}` : '';
        src.notes.push(`The link's scenario is not valid${where}: ${error.message || error.text}. The first built-in is shown instead.`);
        link.scenario = null;
        restoreScenario(link);
        return;
      }
      boxesPanel.refused(error);
      showInvalid(error, src.edit);
    },
    error(message) { showError(message); },
    seed(seed) { panel?.setSeed(seed); },
    asv(text) { downloadText(text, `${(loaded?.name || 'solution').replace(/[^\w.-]+/g, '_')}-solution.txt`); },
    query(answer) { roadmapQuery.answered(answer); },
    stopped: showStopped,
    changed: () => { updateStats(); syncDownload(); },
    frame() {
      if (!chart.kind && playback.model.costs.length) syncChart(); // a planner that reports costs
      cspace.render(view.robotState);
      view3d.render(performance.now(), player.fps());
      pathPanel.frame();
      chart.render(lane.iterationNow);
      updateRunStatus();
      a11y.update();
      // the stats say what is drawn: refreshed when the playback revealed more
      if (playback.store.length !== statsShown) { statsShown = playback.store.length; updateStats(); }
    },
  },
});
const { controller, lane } = player;

function onReady(msg) {
  if (!registry) {
    registry = applyPageLimits(msg.planners);
    builtins = msg.builtins;
    panel = createPanel(ui.panel, registry, () => { configure(); clearError(); syncChart(); obstacleEditor.plannerChanged(); },
      { freshSeed: () => lane.session.send({ type: 'fresh-seed' }) });
    const first = fillScenarioPicker(ui.scenario, builtins);
    if (location.hash.length > 1) restoreHash(location.hash);
    else send('builtin', JSON.stringify(first.scenario), { id: first.id, course: first.course, defaults: true });
  } else if (!lane.session.loadsPending) { // after a crash (unless the user's load is on its way)
    if (src.text) send('reload', src.text); // same scenario, same configuration
    else if (src.pending) restoreScenario(src.pending); // a link's scenario crashed on load: again (a crash
    // each time ends in `stopped`, where the picker and "Open the default scenario instead" work)
  }
}

/**
 * The worker crashed or was replaced (why: 'crashed' | 'hung'): say so, and offer the default
 * scenario in one click (a scenario from a link that crashes the core would otherwise come back
 * with every reload, restored from the hash). `fatal`: it kept crashing; nothing runs until the
 * user loads a scenario (that starts a fresh worker).
 */
function showStopped(message, fatal, why) {
  const text = why === 'hung' ? message : `The planning worker stopped: ${message}`;
  showError(fatal ? `The planning worker keeps stopping (${message}). Pick a scenario or open a file to start it again.`
    : text);
  ui.defaultScenario.hidden = false;
}

/** "Open the default scenario instead": forget the link's state, load the first built-in as shipped. */
function openDefaultScenario() {
  history.replaceState(history.state, '', `${location.pathname}${location.search}`);
  share.lastHash = null;
  src.forget();
  clearError();
  removeCustomOptions();
  const b = builtins[0];
  ui.scenario.value = b.id;
  send('builtin', JSON.stringify(b.scenario), { id: b.id, course: b.course, defaults: true });
}

// Requests

/**
 * Send a scenario (or, with `file`, any file the core imports) to the worker, saying why
 * (run/scenario-source.js: a built-in `id` as shipped, an edit, a file, a link's JSON, a reload
 * after a crash). `course`: shown above the name (kept when left out); `defaults`: apply the
 * scenario's planner block; `map`: an occupancy map's image bytes and YAML text (the worker's
 * `import` message).
 * @param {import('../run/scenario-source.js').LoadReason} reason
 * @param {string} text
 * @param {{id?: string, course?: string, defaults?: boolean, file?: string | null,
 *   map?: {bytes: ArrayBuffer | null, yaml?: string | null, yamlName?: string | null} | null}} [options]
 */
function send(reason, text, { id, course, defaults = false, file = null, map = null } = {}) {
  src.sent(reason, { id, course, file, defaults });
  if (reason !== 'edit') editor.loading();
  player.load(text, file, map);
}

function configure() {
  if (!panel || !lane.session.alive) return;
  player.configure(panel.config());
  explain.setPlanner(panel.config(), loaded?.robot?.kind, { vertices: loaded?.inspection?.coverage_mode === 'vertices' });
  syncChart();
  syncOptions();
  buildLegend();
  scheduleShare();
}

const stepSize = () => Math.max(1, Math.floor(Number(ui.stepSize.value)) || 1);

const actions = {
  run() {
    if (controller.can('run')) clearError();
    if (player.run()) keepInView(ui.stage); // on a phone the canvas may be scrolled away
  },
  pause() { player.pause(); },
  step() { player.step(stepSize()); },
  back() { player.back(stepSize()); },
  stepEvent() { player.stepEvent(); explain.revealNext(); }, // on a phone the caption scrolls into sight
  reset() { player.reset(); },
  cancel() { player.cancel(); },
};

// Share links

/** Restore the state a link's hash describes (bad values are reported and left at defaults). */
async function restoreHash(hash) {
  src.read();
  share.cancel();
  const read = await readShare(hash, { builtins });
  share.pasted = { hash, state: null };
  src.restore(read, read.problems);
  applyView(read);
  restoreScenario(read);
}

/** Load the scenario a share names: a built-in, a link's JSON, or (none) the first built-in. */
function restoreScenario(share) {
  removeCustomOptions();
  clearError();
  if (share.scenario?.text) {
    markCustom('Scenario from a link');
    send('link', share.scenario.text, { course: 'Shared link' });
    return;
  }
  const b = builtins.find((x) => x.id === share.scenario?.id) || builtins.find((x) => x.id === ui.scenario.value) || builtins[0];
  ui.scenario.value = b.id;
  send('builtin', JSON.stringify(b.scenario), { id: b.id, course: b.course });
}

/** The view options of a share (overlays, sliders, step size): its values, else the defaults. */
function applyView(share) {
  const on = Object.fromEntries(OVERLAYS.map((o) => [o.option, share.overlays[o.option] ?? o.on]));
  for (const o of OVERLAYS) Object.assign($(o.id), { checked: on[o.option] }).dataset.touched = o.option in share.overlays ? '1' : '';
  ui.speed.value = String(share.view.speed ?? VIEW_DEFAULTS.speed);
  ui.animSpeed.value = String(share.view.anim ?? VIEW_DEFAULTS.anim);
  ui.animRaw.checked = share.view.rawPath ?? VIEW_DEFAULTS.rawPath;
  ui.stepSize.value = String(share.view.stepSize ?? VIEW_DEFAULTS.stepSize);
  view3d.setCamera(share.view.camera ?? null);
  view.pendingViewport = share.view.zoom ?? null; // the plane's zoom, once the link's scenario is shown
  pathPanel.setSpacing(share.view.ghosts); // the 3-D path's ghost spacing (its default when the link has none)
  updateOutputs();
  syncOptions();
}

const share = wireShareHash({
  ui, bench: $('to-bench'), ready: () => src.settled,
  writable: () => !!(src.settled && panel && src.text && src.source) && controller.state !== 'invalid' && controller.state !== 'loading',
  source: () => src.source, scenarioText: () => src.text, registry: () => registry,
  state: () => ({
    config: panel.config(),
    overlays: overlayOptions(),
    view: {
      speed: Number(ui.speed.value), anim: Number(ui.animSpeed.value), rawPath: ui.animRaw.checked,
      stepSize: stepSize(), camera: view3d.camera(), zoom: view.viewport, ghosts: pathPanel.spacing,
    },
  }),
  saveName: () => loaded?.name || 'scenario', download: downloadText, showError,
});
const scheduleShare = () => share.schedule();
wireEmbedCode({ root: $('embed-options'), link: () => share.write({ force: true }), title: () => loaded?.name || 'Planarium' });

// someone pastes another link into the address bar of this tab
window.addEventListener('hashchange', () => {
  if (!registry || location.hash === share.lastHash) return;
  if (location.hash.length > 1) restoreHash(location.hash);
});

const removeCustomOptions = () => removeCustomScenarios(ui.scenario);
const markCustom = (label) => markCustomScenario(ui.scenario, label);

// Display

/** @param {import('../run/messages.js').LoadedReply} msg */
function showScenario({ scenario, start, goal, space, cspace: grid, optimum: best, caps, spatial }) {
  loaded = scenario;
  loadedCaps = caps || null;
  optimum = best && best.exact && Number.isFinite(best.cost) ? best.cost : null;
  ui.course.textContent = src.course;
  ui.name.textContent = shown(scenario.name || 'Untitled scenario');
  ui.notes.textContent = shown(scenario.notes || '');
  view.setScenario(scenario, start, goal);
  cspace.setSpace(grid || null, scenario.start, scenario.goal);
  editor.setScenario(scenario, space, src.edit);
  obstacleEditor.loaded(src.edit);
  ui.cspace.hidden = !cspace.active;
  view3d.setScene(spatial || null, !!caps?.view3d, src.edit);
  posePanel.setScene(scenario, space, caps, src.edit);
  boxesPanel.setScene(scenario, caps, src.edit);
  buildLegend();
  syncStage();
}

/**
 * The stage holds the top view and, beside it, the c-space or the 3-D view when there is one (on
 * a phone, the 3-D view alone with a button for the view from above: `phoneStage`).
 */
function syncStage() {
  ui.stage.classList.toggle('dual', cspace.active || view3d.active);
  $('export-3d-note').hidden = !view3d.active;
  phoneStage.setSpatial(view3d.active); // sizes the views again
}

function showInvalid(error, edit) {
  showError(invalidText(error, edit));
  lane.clearRun();
  if (!edit) { // an edit keeps the scene on screen, so the start or goal can be dragged back
    loaded = null;
    loadedCaps = null;
    optimum = null;
    ui.course.textContent = '';
    ui.name.textContent = 'No valid scenario';
    ui.notes.textContent = 'Fix the file and open it again, or pick a built-in scenario.';
    view.setScenario(null);
    cspace.setSpace(null);
    editor.setScenario(null, null, false);
    obstacleEditor.loaded(false);
    ui.cspace.hidden = true;
    view3d.setScene(null, false);
    posePanel.setScene(null, null, null, false);
    boxesPanel.setScene(null, null, false);
    syncStage();
  }
  controller.fire('invalid');
}

// the optimum line's cost too: the stats say how far above it the path is
function currentStats() { return { ...player.stats(), optimum }; }

let lastRunStatus = '';
let statsShown = -1; // the records revealed when the stats were last filled
function updateRunStatus() {
  const config = panel?.config();
  const text = registry ? runStatusText({
    state: controller.state, config, label: config ? registry.planners.find((p) => p.name === config.planner)?.label : '',
    planner: lane.result?.stats || lane.stats, done: lane.done, finalStatus: lane.finalStatus, solved: !!lane.result?.solved,
    replay: player.replayIteration(), nodes: player.stats().nodes, // the stats' count, to match
  }) : 'Loading the planning core…';
  if (text === lastRunStatus) return;
  lastRunStatus = text;
  $('run-status').textContent = text;
}

function updateStats() {
  const s = currentStats();
  updateStatsList(s);
  // a planner that gave up says why: under the canvas too, where it is seen
  const why = s.status === 'no_path' ? (lane.result?.reason || 'the planner gave up') : '';
  const note = why ? `No path: ${why.replace(/^no path:\s*/i, '')}` : '';
  if (ui.runNote.textContent !== note) ui.runNote.textContent = note; // a live region: written when it changes
  ui.runNote.hidden = !why;
}

/** The chart that fits the chosen planner: best cost, coverage, or none. */
function syncChart() {
  updateStatsList.setPlanner(panel?.planner());
  const kind = panel ? chartKind(panel.planner(), playback.model) : null;
  chart.setKind(kind, { target: loaded?.inspection?.coverage ?? null, optimum });
  ui.chartBox.hidden = !kind;
  ui.chartTitle.textContent = kind === 'cost' ? 'Best cost against iterations'
    : kind === 'coverage' ? 'Coverage of the best branch against iterations' : '';
  ui.chart.setAttribute('aria-label', ui.chartTitle.textContent);
}

function syncButtons() {
  const enabled = controller.buttons();
  for (const id of Object.keys(BUTTONS)) $(id).disabled = !enabled[id];
  ui.back.disabled = !player.canBack();
  const busy = controller.state === 'loading';
  ui.scenario.disabled = busy;
  ui.file.disabled = busy;
  panel?.setDisabled(busy);
  document.body.dataset.state = controller.state;
  a11y.refocus(); // Run → Pause: the focus stays in the run bar
}

controller.onChange(() => { syncButtons(); updateStats(); updateRunStatus(); syncSpeedButtons(); syncDownload(); a11y.update(); });

function buildLegend() {
  const name = panel?.planner()?.name;
  fillLegend(ui.legend, [...view.legend(name), ...cellLegend(name), ...explain.legend(name)]);
}

// Start / goal editing and the solution file

const editor = new Editor({
  canvas: ui.canvas, view, root: ui.endpoints, palette: PALETTE,
  onPreview(which, state) {
    view.preview[which] = state.slice();
    view.dirty = true;
    cspace.setStartGoal(view.stateOf('start'), view.stateOf('goal'));
  },
  onCommit(scenario) {
    clearError();
    send('edit', JSON.stringify(scenario));
  },
});

// A spatial arm posed by hand under the 3-D view (pose3d.js): its sliders, whether the pose is
// free, and Set as start / goal through the editor above.
const posePanel = new PosePanel({ root: $('pose3d'), slot: view3d, editor, palette: PALETTE });
// Its scene's boxes as numbers (boxes3d.js), each edit checked by the core and sent through the editor.
const boxesPanel = new BoxesPanel({ root: $('boxes3d'), editor });
// The explain panel tells a spatial arm's step in its joints and shows it in the 3-D view, with the
// pose panel's copy of the core (link frames, what collides and where).
explain.setArm(() => posePanel.scene, view3d);
// The solved path under the 3-D view (path3d.js): scrubber, ghosts, joint-angle timeline; poses from the panel's core.
const pathPanel = new PathPanel({ root: $('path3d'), slot: view3d, linkFrames: (q) => posePanel.linkFrames(q), onSpacing: scheduleShare });

// Obstacles and bounds: drawn, moved, resized, deleted; undo/redo; saved as JSON (obstacle-editor.js)

const obstacleEditor = new ObstacleEditor({ canvas: ui.canvas, view, editor, root: $('obstacle-tools'), download: downloadText,
  config: () => panel?.config() ?? null, idle: () => controller.state === 'idle' }); // Cells: on grid search's cells

// Exports for slides (exports.js): PNG at a width, SVG, GIF, WebM at a width; legend and transparency options
wireExports({
  view, stem: () => (loaded?.name || 'planarium').replace(/[^\w.-]+/g, '-').toLowerCase(),
  legend: () => [...view.legend(panel?.planner()?.name), ...cellLegend(panel?.planner()?.name), ...explain.legend(panel?.planner()?.name)],
  animFps: () => player.fps(),
  view3d: () => (view3d.active ? view3d : null), // PNG and WebM: the 3-D view beside the top view
});

function syncDownload() {
  ui.download.hidden = !(loadedCaps?.solution_file && lane.result?.solved && controller.state === 'finished');
  roadmapQuery.sync();
}

// More queries on a finished roadmap run (roadmap-query.js): two clicks, the same roadmap
const roadmapQuery = wireRoadmapQuery({
  button: $('query-button'), status: $('query-status'), canvas: ui.canvas, view, lane, scenario: () => loaded,
  applies: () => answersQueries(panel?.planner()?.name) && controller.state === 'finished' && !!lane.result
    && dragsPosition(loaded?.robot),
});

ui.download.addEventListener('click', () => { if (lane.session.alive && lane.result?.solved) lane.session.send({ type: 'asv-solution' }); });

// Inputs

for (const [id, event] of Object.entries(BUTTONS)) $(id).addEventListener('click', () => actions[event]());
ui.back.addEventListener('click', () => actions.back());
ui.errorClose.addEventListener('click', clearError);
ui.defaultScenario.addEventListener('click', openDefaultScenario);

ui.scenario.addEventListener('change', () => {
  const b = builtins.find((x) => x.id === ui.scenario.value);
  if (!b) return;
  clearError();
  removeCustomOptions();
  send('builtin', JSON.stringify(b.scenario), { id: b.id, course: b.course, defaults: true });
});

// Open file (open-file.js): a scenario, or an occupancy map's YAML and image; read here, decoded in the worker.
wireOpenFile({ input: ui.file, clearError, showError, markCustom,
  load: (text, defaults, { course, file, map }) => send('file', text, { course, file, map, defaults }) });

// Slow / Normal / Fast / Instant: presets of the replay-length slider, wired as Compare's
const syncPresets = wireSpeedButtons(ui.speed, () => { updateOutputs(); scheduleShare(); });
function syncSpeedButtons() { syncPresets(); }

function updateOutputs() {
  syncSpeedButtons();
  ui.speedOut.textContent = describeSpeed(ui.speed);
  ui.animOut.textContent = `${Math.round(animFps(ui.animSpeed))} frames/s`;
}
ui.speed.addEventListener('input', () => { updateOutputs(); scheduleShare(); });
ui.animSpeed.addEventListener('input', () => { updateOutputs(); scheduleShare(); });
ui.stepSize.addEventListener('change', scheduleShare);
const overlayOptions = createOverlays(ui.overlays, () => { syncOptions(); scheduleShare(); });
// An inspection planner's smoothed path need not see what its branch saw: its robot follows the raw path.
const syncOptions = () => {
  const hidden = overlayOptions.fit?.({ config: panel?.config(), robot: loaded?.robot?.kind, inspection: !!loaded?.inspection }) ?? 0;
  $('overlays-note').textContent = hidden ? `${hidden} more apply to other planners or set-ups.` : '';
  const o = overlayOptions();
  const animateRaw = ui.animRaw.checked || panel?.planner().task === 'inspection';
  view.setOptions({ ...o, animateRaw });
  pathPanel.setRaw(animateRaw);
  cspace.setOptions({ showRejected: o.showRejected, showCollisions: o.showCollisions });
};
ui.animRaw.addEventListener('change', () => { syncOptions(); scheduleShare(); });

// The skip link, focus in the run bar, the live region and the canvas's text (ui/a11y.js).
const a11y = wireA11y({ skip: $('skip-to-run'), bar: $('run-bar'), live: $('run-announce'), canvas: ui.canvas,
  read: () => ({ state: controller.state, status: lastRunStatus, caption: explain.state().caption, name: loaded?.name,
    nodes: currentStats().nodes, result: lane.result, bestCost: playback.model.bestCost }) });

// Keys (Space, arrows, R, '.', ?) and the keyboard help (ui/keys.js).
wireKeys({ actions, running: () => controller.state === 'running', help: $('help'), open: $('help-button'), close: $('help-close') });

// Hover: the cell or field tile under the pointer, described in a small box (ui/keys.js).
wireCellTip({ canvas: ui.canvas, stage: ui.stage, tip: ui.tip, view });

// Run 20 seeds (trials.js): this set-up on seeds s … s+19, in background workers; a dot opens its seed.
createTrials({
  button: $('run-seeds'), cancel: $('cancel-seeds'), status: $('trials-status'), table: $('trials'), dots: $('trial-dots'),
  setup: () => (panel && src.text && controller.state !== 'invalid' ? { text: src.text, ...panel.config() } : null),
  open: (seed) => {
    panel.apply({ ...panel.config().params, name: panel.config().planner, seed });
    configure();
  },
});

// Linked views (linked.js): the arm's c-space ↔ workspace under the pointer; the heat map's scale.
linkViews({ view, cspace, canvas: ui.canvas, cspaceCanvas: ui.cspace, stage: ui.stage, model: playback.model });

// Zoom and pan on the plane: wheel, middle drag, pinch, the bar's buttons (ui/plane-zoom.js).
wirePlaneZoom({ canvas: ui.canvas, view, bar: $('plane-zoom'), onChange: () => scheduleShare() });

// Size: the views follow the stage (and the device pixel ratio).
// The second view is the c-space's or the 3-D view's (never both: a spatial arm has no c-space view).
// The 3-D view takes the larger share of the stage: the top view of a spatial arm is a sketch.
const onResize = fitViews(ui.stage, view, {
  get active() { return cspace.active || view3d.active; },
  get share() { return view3d.active ? 0.64 : 0.5; },
  solo: () => phoneStage.solo(),
  resize(w, h, dpr) { if (cspace.active) cspace.resize(w, h, dpr); if (view3d.active) view3d.resize(w, h, dpr); },
});
const phoneStage = new PhoneStage(ui.stage, $('view-swap'), $('run-bar'), () => onResize());
underRunBar([ui.chartBox, explain.now], $('run-bar')); // on a phone: the chart, the step's caption

Object.defineProperty(window, 'planarium', {
  value: Object.freeze({
    state: () => controller.state,
    stats: () => currentStats(),
    result: () => (lane.result ? structuredClone(lane.result) : null),
    scenario: () => (editor.scenario ? structuredClone(editor.scenario) : null),
    nodeCount: () => playback.nodeCount,
    /** Bytes held by the page's stores for the run: {records, trees, queued}. */
    memory: () => playback.bytes(),
    /** Iterations whose events are all shown (step back goes back from here). */
    shownIterations: () => player.shownIterations,
    /** The link to this state (the hash is kept up to date a moment after each change). */
    shareLink: () => share.write(),
    model: () => modelSummary(playback.model, chart),
    /** The explain panel: {line, caption, events} of the last event shown. */
    explain: () => explain.state(),
    /** The explain panel's step in the 3-D view: {sample, step, collision: {links, at, words} | null}, or null. */
    explain3d: () => explain.state3d(),
    /** The last record revealed, as numbers (null before any). */
    /** The replay's pacing plan: {duration, clock, frames, lastSteps, steps, pendingSteps, records, pending} (pace.js). */
    pace: () => playback.plan(),
    lastEvent: () => (playback.store.length ? [...playback.store.record(playback.store.length - 1)] : null),
    cells: () => cellSummary(playback.model.cells),
    /** Another query on the finished roadmap, as drawn: {points, picks}, or null. */
    query: () => (view.query ? structuredClone(view.query) : null),
    /** Css px within the workspace canvas of the world point (x, y), or null. */
    toCanvas: (x, y) => (view.layout ? [view.layout.sx(x) / view.layout.dpr, view.layout.sy(y) / view.layout.dpr] : null),
    /** The plane's zoom and centre (null: fitted), and whether its layers are drawn at what it shows. */
    viewport: () => ({ zoom: view.zoom, viewport: view.viewport && { ...view.viewport },
      settled: view.settled }),
    /** The 3-D view, for tests (view3d-slot.js). */
    view3d: view3dHooks(view3d, { pose: posePanel, boxes: boxesPanel, path: pathPanel }),
  }),
  writable: false,
  configurable: false,
});

buildLegend();
updateOutputs();
syncOptions();
syncButtons();
updateStats();
player.start();

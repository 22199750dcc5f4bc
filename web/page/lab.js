// The physics lab tab: set up balls on a rectangular or polygonal table,
// run them with the engine's exact playback and watch trajectories,
// momentum arrows and a live kinetic-energy graph.
//
//   import { mountLab } from './lab.js';
//   mountLab(document.getElementById('lab'), engine);   // engine: loadEngine()'s API
//
// Nothing physical is computed here: positions, energies and momenta all
// come from pb.frame(t) (docs/web.md). This file builds the lab's page from
// the lab-*.js modules and wires them: it holds the lab's state (the
// scenario being edited, the selection, the options, the errors) and passes
// it to them as plain data. The scenario is the contract's format
// (lab-scenario.js); the examples are bundled from examples/lab/*.json by
// web/tools/bundle-examples.mjs. Test hooks: docs/web.md, "The lab and its
// test hooks".

import { EXAMPLES } from './lab-examples.js';
import { el, errText } from './lab-dom.js';
import { ballColours } from './lab-colours.js';
import { EMPTY_SCENARIO, clone, normalise, buildScenario, removeBallAt, setBallCount, setDefaults } from './lab-scenario.js';
import { Player } from './lab-player.js';
import { VEL_TAU, layoutTable, drawTable as paintTable } from './lab-table-drawing.js';
import { drawEnergy as paintEnergy } from './lab-energy-graph.js';
import { createToolbar } from './lab-toolbar.js';
import { createStats } from './lab-stats.js';
import { renderPhysicsPanel } from './lab-physics-panel.js';
import { renderTablePanel } from './lab-table-panel.js';
import { renderBallsPanel, markSelected, showBall } from './lab-balls-panel.js';
import { attachEditor } from './lab-editor.js';

export function mountLab(root, engine) {
  if (!root) throw new Error('mountLab: no root element');
  setDefaults(engine && engine.defaults);
  if (root.__breakshotLab) return root.__breakshotLab;
  addStylesheet();

  // ---- state
  let setup = null;             // the scenario being edited (contract format)
  let colours = [];
  let example = null;           // name of the loaded example, if unchanged since
  let speedLog = 0;             // log10 of the speed factor
  let mode = 'move';            // drag mode: 'move' or 'velocity'
  let showTraces = true;
  let showArrows = true;
  let selected = -1;
  let showAllRows = false;
  let engineError = null;       // the engine's verdict on the setup
  let runError = null;          // an error during a run
  const fieldErrors = new Map();  // input label -> message
  let initialFrame = null;      // frame(0) of the setup, for the numbers and arrows
  let validateTimer = 0;
  let view = null;              // world -> canvas transform of the last drawing
  let ballRows = [];            // the Balls panel's rows
  let destroyed = false;

  const player = new Player({
    speed: () => 10 ** speedLog,
    frame: () => drawAll(),
    stop: (error) => { if (error) runError = error; finish(); },
  });
  // What the panels' fields need to report their errors (lab-form.js).
  const form = {
    errors: fieldErrors,
    showErrors: () => updateError(),
    fail: (message) => { runError = message; updateError(); },
  };

  // ---- DOM
  const bars = createToolbar(EXAMPLES, {
    loadExample: (name) => loadExample(name),
    run: () => startRun(),
    pause: () => togglePause(),
    reset: () => resetRun(),
    speed: (log) => { speedLog = log; },
    mode: (m) => { mode = m; },
    traces: (on) => { showTraces = on; drawAll(); },
    arrows: (on) => { showArrows = on; drawAll(); },
  });
  const errorBox = el('div', { id: 'lab-error', class: 'bs-lab-error', role: 'alert', 'aria-live': 'polite' });
  const canvas = el('canvas', { id: 'lab-canvas', class: 'bs-lab-canvas' });
  const canvasBox = el('div', { class: 'bs-lab-canvasbox' }, canvas);
  const stats = createStats();
  const hint = el('div', { class: 'bs-lab-hint' },
    'Drag a ball to move it; Shift-drag from its centre (or "drag: velocity") to set its velocity; ' +
    'drag an arrow tip to change it; double-click the table to add a ball. ' +
    `Setup arrows: velocity, ending where the ball would be after ${VEL_TAU} s. ` +
    'During a run: momentum arrows, and the system momentum at the right.');

  const energyCanvas = el('canvas', { id: 'lab-energy', class: 'bs-lab-energy' });
  const energyBox = el('div', { class: 'bs-lab-energybox' }, energyCanvas);

  const physicsPanel = el('div', { class: 'bs-lab-panel-body' });
  const tablePanel = el('div', { class: 'bs-lab-panel-body' });
  const ballsPanel = el('div', { class: 'bs-lab-panel-body' });
  const panel = (title, body) => el('details', { class: 'bs-lab-panel', open: true },
    el('summary', { text: title }), body);

  const left = el('div', { class: 'bs-lab-left' }, bars.toolbar, bars.options, errorBox, canvasBox, stats.element, hint);
  const right = el('div', { class: 'bs-lab-right' }, energyBox,
    panel('Physics', physicsPanel), panel('Table', tablePanel), panel('Balls', ballsPanel));
  const container = el('div', { class: 'bs-lab' }, bars.exampleBar, el('div', { class: 'bs-lab-main' }, left, right));
  root.append(container);

  // ---------------------------------------------------------- the setup

  function loadScenario(sc, name) {
    resetRun(true);
    setup = normalise(clone(sc));
    example = name ?? null;
    selected = -1;
    showAllRows = false;
    fieldErrors.clear();
    runError = null;
    colours = ballColours(setup.balls);
    bars.markExample(example);
    // A run much shorter than a second plays slowed down so it lasts a few seconds.
    const T = setup.until && typeof setup.until === 'object' ? setup.until.time : null;
    speedLog = T > 0 && T < 0.2 ? Math.max(-7, Math.round(Math.log10(T / 4) * 20) / 20) : 0;
    bars.showSpeed(speedLog);
    renderPanels();
    validateNow();
    drawAll();
  }

  function loadExample(name) {
    const ex = EXAMPLES.find((e) => e.name === name);
    if (!ex) { runError = `no example named ${name}`; updateError(); return; }
    loadScenario(ex.scenario, name);
  }

  // Called after every edit of the setup.
  function changed({ panels = false, colour = false } = {}) {
    if (player.run) resetRun(true);
    example = null;
    bars.markExample(example);
    if (colour) colours = ballColours(setup.balls);
    if (panels) renderPanels();
    runError = null;
    scheduleValidate();
    drawAll();
  }

  function scheduleValidate() {
    clearTimeout(validateTimer);
    validateTimer = setTimeout(validateNow, 120);
  }

  // Asks the engine whether the setup is valid, and for its state at t = 0.
  function validateNow() {
    clearTimeout(validateTimer);
    validateTimer = 0;
    if (destroyed) return;
    initialFrame = null;
    if (!engine || typeof engine.playback !== 'function') {
      engineError = 'the engine is not loaded';
    } else {
      let pb = null;
      try {
        pb = engine.playback(buildScenario(setup));
        initialFrame = pb.frame(0);
        engineError = null;
      } catch (e) {
        engineError = errText(e);
      } finally {
        if (pb) { try { pb.free(); } catch (e) { /* already gone */ } }
      }
    }
    updateError();
    updateStats();
    drawAll();
  }

  function updateError() {
    let text = '';
    if (fieldErrors.size) {
      const [k, v] = fieldErrors.entries().next().value;
      text = `${k}: ${v}`;
    } else if (runError) {
      text = runError;
    } else if (engineError) {
      text = `Invalid setup: ${engineError}`;
    }
    errorBox.textContent = text;
    errorBox.classList.toggle('bs-lab-has-error', text !== '');
  }

  // ------------------------------------------------------------ panels

  function renderPanels() {
    fieldErrors.clear();
    updateError();
    renderPhysicsPanel(physicsPanel, setup, form, changed);
    renderTable();
    renderBalls();
  }

  function renderTable() {
    renderTablePanel(tablePanel, setup, EXAMPLES, form, changed);
  }

  function renderBalls() {
    ballRows = renderBallsPanel(ballsPanel, setup, { colours, selected, showAllRows }, form, {
      changed, select, removeBall, setCount,
      showAll: () => { showAllRows = true; renderBalls(); },
    });
  }

  function select(i) {
    if (selected === i) return;
    markSelected(ballRows, selected, i);
    selected = i;
    drawAll();
  }

  function removeBall(i) {
    removeBallAt(setup, i);
    if (selected === i) selected = -1; else if (selected > i) selected--;
    changed({ panels: true, colour: true });
  }

  function setCount(n) {
    setBallCount(setup, n);
    if (selected >= n) selected = -1;
    changed({ panels: true, colour: true });
  }

  // ---------------------------------------------------------------- runs

  function startRun() {
    try {
      resetRun(true);
      runError = null;
      if (fieldErrors.size) { updateError(); return; }
      if (!engine || typeof engine.playback !== 'function') { engineError = 'the engine is not loaded'; updateError(); return; }
      const sc = buildScenario(setup);
      let pb;
      try {
        pb = engine.playback(sc);
      } catch (e) {
        engineError = errText(e);
        updateError();
        drawAll();
        return;
      }
      engineError = null;
      const f0 = player.begin(engine, pb, sc);
      updateError();
      updateButtons();
      drawAll();
      if (player.run.rest && f0.at_rest) { finish(); return; }
      player.play();
    } catch (e) {
      runError = `run failed: ${errText(e)}`;
      finish();
    }
  }

  function finish() {
    if (!player.finish()) { updateButtons(); updateError(); return; }
    updateButtons();
    updateError();
    drawAll();
  }

  function togglePause() {
    if (!player.togglePause()) return;
    updateButtons();
    drawAll();
  }

  // Back to the setup. `quiet` skips the redraw (the caller draws).
  function resetRun(quiet) {
    player.reset();
    if (!quiet) { runError = null; updateError(); }
    updateButtons();
    if (!quiet) drawAll();
  }

  function updateButtons() {
    bars.showRun(player.run);
    stats.showState(player.run);
  }

  function updateStats() {
    const run = player.run;
    stats.show(run ? run.frame : initialFrame, run ? run.t : 0);
  }

  // ------------------------------------------------------------- drawing

  function drawAll() {
    if (destroyed || !setup) return;
    try {
      drawTable();
      drawEnergy();
      updateStats();
    } catch (e) {
      runError = `drawing failed: ${errText(e)}`;
      updateError();
    }
  }

  // The drawing's inputs, as plain data.
  function scene() {
    return { setup, run: player.run, colours, selected, showTraces, showArrows, drag: editor.drag(), initialFrame };
  }

  function drawTable() {
    const cssW = canvasBox.clientWidth;
    if (!cssW) return;
    const { ctx, w, h, view: v } = layoutTable(canvas, cssW, setup);
    view = v;
    paintTable(ctx, w, h, v, scene());
  }

  function drawEnergy() {
    paintEnergy(energyCanvas, energyBox.clientWidth, scene());
  }

  // ------------------------------------------------------- table editing

  const editor = attachEditor(canvas, {
    get setup() { return setup; },
    get view() { return view; },
    get mode() { return mode; },
    get selected() { return selected; },
    get running() { return !!player.run; },
    endRun: () => resetRun(),
    drawTable,
    drawAll,
    select,
    changed,
    dragged: (i, what) => showBall(ballRows, i, setup.balls[i], what),
    vertexMoved: () => renderTable(),
    validateNow,
    addedBall: (i) => { selected = i; changed({ panels: true, colour: true }); },
    fail: (err) => { runError = errText(err); updateError(); },
  });

  let resizeObs = null;
  if (typeof ResizeObserver === 'function') {
    let pending = 0;
    resizeObs = new ResizeObserver(() => {
      if (pending) return;
      pending = requestAnimationFrame(() => { pending = 0; if (!player.animating()) drawAll(); });
    });
    resizeObs.observe(canvasBox);
    resizeObs.observe(energyBox);
  }

  // ---------------------------------------------------------------- API

  const api = {
    scenario: () => buildScenario(setup),
    running: () => !!player.run && !player.run.paused && !player.run.done,
    time: () => (player.run ? player.run.t : 0),
    frames: () => player.frames,
    load: (what) => {
      if (typeof what === 'string') loadExample(what);
      else loadScenario(what, null);
    },
    error: () => errorBox.textContent,
    destroy: () => {
      resetRun(true);
      destroyed = true;
      clearTimeout(validateTimer);
      if (resizeObs) resizeObs.disconnect();
      container.remove();
      delete root.__breakshotLab;
      if (window.breakshotLab === api) delete window.breakshotLab;
    },
  };
  root.__breakshotLab = api;
  window.breakshotLab = api;

  const first = EXAMPLES.find((e) => e.name === 'two_balls') || EXAMPLES[0];
  if (first) loadScenario(first.scenario, first.name);
  else loadScenario(EMPTY_SCENARIO, null);
  return api;
}

function addStylesheet() {
  if (document.getElementById('bs-lab-css')) return;
  const link = document.createElement('link');
  link.id = 'bs-lab-css';
  link.rel = 'stylesheet';
  link.href = new URL('./lab.css', import.meta.url).href;
  document.head.append(link);
}

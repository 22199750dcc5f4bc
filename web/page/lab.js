// The physics lab tab: set up balls on a rectangular or polygonal table,
// run them with the engine's exact playback and watch trajectories,
// momentum arrows and a live kinetic-energy graph.
//
//   import { mountLab } from './lab.js';
//   mountLab(document.getElementById('lab'), engine);   // engine: loadEngine()'s API
//
// Nothing physical is computed here: positions, energies and momenta all
// come from pb.frame(t) (docs/web.md). The scenario this file builds is the
// contract's scenario format (../shared/contract/scenario-format.md); the
// examples are bundled from examples/lab/*.json by
// web/tools/bundle-examples.mjs. Test hooks: docs/web.md, "Lab test hooks".

import { EXAMPLES } from './lab-examples.js';
import { el, errText } from './lab-dom.js';
import { fmtSI, fmtNum, roundTo, roundSig } from './lab-format.js';
import { ballColours } from './lab-colours.js';
import {
  EMPTY_SCENARIO, clone, normalise, buildScenario, radiusOf, tableStep, addBall, spotForNewBall,
  removeBallAt, setBallCount,
} from './lab-scenario.js';
import { Player } from './lab-player.js';
import { VEL_TAU, layoutTable, drawTable as paintTable, velocityTip } from './lab-table-drawing.js';
import { drawEnergy as drawEnergyGraph } from './lab-energy-graph.js';
import { renderPhysicsPanel } from './lab-physics-panel.js';
import { renderTablePanel } from './lab-table-panel.js';
import { renderBallsPanel, markSelected, showBall } from './lab-balls-panel.js';

// ------------------------------------------------------------------ mount

export function mountLab(root, engine) {
  if (!root) throw new Error('mountLab: no root element');
  if (root.__breakshotLab) return root.__breakshotLab;
  addStylesheet();

  // ---- state
  let setup = null;             // the scenario being edited (contract format)
  let colours = [];
  let example = null;           // name of the loaded example, if unchanged since
  const player = new Player({
    speed: () => speed(),
    frame: () => drawAll(),
    stop: (error) => { if (error) runError = error; finish(); },
  });
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
  let drag = null;
  let view = null;              // world -> canvas transform of the last drawing
  let ballRows = [];            // the Balls panel's rows
  let destroyed = false;

  // What the panels' fields need to report their errors (lab-form.js).
  const form = {
    errors: fieldErrors,
    showErrors: () => updateError(),
    fail: (message) => { runError = message; updateError(); },
  };

  // ---- DOM
  const exampleBar = el('div', { id: 'lab-examples', class: 'bs-lab-examples' },
    el('span', { class: 'bs-lab-label', text: 'Examples:' }));
  for (const ex of EXAMPLES) {
    exampleBar.append(el('button', {
      type: 'button', class: 'bs-lab-example', dataset: { example: ex.name }, text: ex.name,
      title: `load examples/lab/${ex.name}.json`, onclick: () => loadExample(ex.name),
    }));
  }

  const runBtn = el('button', { id: 'lab-run', type: 'button', class: 'bs-lab-primary', text: 'Run', onclick: () => startRun() });
  const pauseBtn = el('button', { id: 'lab-pause', type: 'button', text: 'Pause', disabled: true, onclick: () => togglePause() });
  const resetBtn = el('button', { id: 'lab-reset', type: 'button', text: 'Reset', onclick: () => resetRun() });
  const speedInput = el('input', {
    id: 'lab-speed', type: 'range', min: '-7', max: '1', step: '0.05', value: '0',
    title: 'simulated seconds per real second (logarithmic)',
    oninput: () => { speedLog = Number(speedInput.value); speedOut.textContent = speedText(); },
  });
  const speedOut = el('output', { class: 'bs-lab-speed', text: '×1' });
  const modeMove = el('input', { type: 'radio', name: 'bs-lab-mode', value: 'move', checked: true,
    onchange: () => { mode = 'move'; } });
  const modeVel = el('input', { type: 'radio', name: 'bs-lab-mode', value: 'velocity',
    onchange: () => { mode = 'velocity'; } });
  const tracesBox = el('input', { type: 'checkbox', checked: true,
    onchange: () => { showTraces = tracesBox.checked; drawAll(); } });
  const arrowsBox = el('input', { type: 'checkbox', checked: true,
    onchange: () => { showArrows = arrowsBox.checked; drawAll(); } });

  const toolbar = el('div', { class: 'bs-lab-toolbar' },
    runBtn, pauseBtn, resetBtn,
    el('label', { class: 'bs-lab-speedbox' }, 'speed ', speedInput, speedOut));
  const options = el('div', { class: 'bs-lab-toolbar bs-lab-options' },
    el('span', { class: 'bs-lab-modes', title: 'what dragging a ball does (Shift-drag always sets the velocity)' },
      'drag: ', el('label', null, modeMove, 'move'), el('label', null, modeVel, 'velocity')),
    el('label', null, tracesBox, 'traces'),
    el('label', null, arrowsBox, 'arrows'));

  const errorBox = el('div', { id: 'lab-error', class: 'bs-lab-error', role: 'alert', 'aria-live': 'polite' });
  const canvas = el('canvas', { id: 'lab-canvas', class: 'bs-lab-canvas' });
  const canvasBox = el('div', { class: 'bs-lab-canvasbox' }, canvas);
  const stat = (id, label, unit) => {
    const b = el('b', { id, text: '–' });
    return [el('span', { class: 'bs-lab-stat' }, el('span', { class: 'bs-lab-statlabel', text: label }), b,
      unit ? el('span', { class: 'bs-lab-unit', text: unit }) : null), b];
  };
  const [tStat, tVal] = stat('lab-time', 't', '');
  const [evStat, evVal] = stat('lab-events', 'events', '');
  const [eStat, eVal] = stat('lab-energy-total', 'total kinetic energy', '');
  const [pStat, pVal] = stat('lab-momentum', 'total momentum (px, py)', 'kg·m/s');
  const stateVal = el('span', { class: 'bs-lab-state', text: 'setup' });
  const stats = el('div', { class: 'bs-lab-stats' }, stateVal, tStat, evStat, eStat, pStat);
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

  const left = el('div', { class: 'bs-lab-left' }, toolbar, options, errorBox, canvasBox, stats, hint);
  const right = el('div', { class: 'bs-lab-right' }, energyBox,
    panel('Physics', physicsPanel), panel('Table', tablePanel), panel('Balls', ballsPanel));
  const container = el('div', { class: 'bs-lab' }, exampleBar, el('div', { class: 'bs-lab-main' }, left, right));
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
    for (const b of exampleBar.querySelectorAll('button')) {
      b.setAttribute('aria-pressed', String(b.dataset.example === example));
    }
    // A run much shorter than a second plays slowed down so it lasts a few seconds.
    const T = setup.until && typeof setup.until === 'object' ? setup.until.time : null;
    speedLog = T > 0 && T < 0.2 ? Math.max(-7, Math.round(Math.log10(T / 4) * 20) / 20) : 0;
    speedInput.value = String(speedLog);
    speedOut.textContent = speedText();
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
    for (const b of exampleBar.querySelectorAll('button')) b.setAttribute('aria-pressed', 'false');
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

  function speed() { return 10 ** speedLog; }

  function speedText() {
    const s = speed();
    return `×${s >= 1 ? roundSig(s, 3) : s.toPrecision(2).replace(/\.?0+e/, 'e')}`;
  }

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
    const run = player.run;
    const active = !!run && !run.done;
    pauseBtn.disabled = !active;
    pauseBtn.textContent = run && run.paused ? 'Resume' : 'Pause';
    runBtn.textContent = run ? 'Run again' : 'Run';
    stateVal.textContent = !run ? 'setup' : run.done ? 'finished' : run.paused ? 'paused' : 'running';
    stateVal.dataset.state = stateVal.textContent;
  }

  function updateStats() {
    const run = player.run;
    const f = run ? run.frame : initialFrame;
    const t = run ? run.t : 0;
    tVal.textContent = fmtSI(t, 's', 6);
    if (f) {
      evVal.textContent = String(f.events);
      eVal.textContent = fmtSI(f.energy, 'J', 6);
      pVal.textContent = `(${fmtNum(f.momentum[0], 6)}, ${fmtNum(f.momentum[1], 6)})`;
    } else {
      evVal.textContent = '–'; eVal.textContent = '–'; pVal.textContent = '–';
    }
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
    return { setup, run: player.run, colours, selected, showTraces, showArrows, drag, initialFrame };
  }

  function drawTable() {
    const cssW = canvasBox.clientWidth;
    if (!cssW) return;
    const { ctx, w, h, view: v } = layoutTable(canvas, cssW, setup);
    view = v;
    paintTable(ctx, w, h, v, scene());
  }

  function drawEnergy() {
    drawEnergyGraph(energyCanvas, energyBox.clientWidth, scene());
  }

  // ------------------------------------------------------- table editing

  function toWorld(e) {
    const r = canvas.getBoundingClientRect();
    const px = e.clientX - r.left, py = e.clientY - r.top;
    if (!view) return null;
    return { px, py, x: (px - view.ox) / view.s, y: (view.oy - py) / view.s };
  }

  function hitBall(px, py) {
    let best = -1, bestD = Infinity;
    const balls = setup.balls;
    for (let i = 0; i < balls.length; i++) {
      const p = balls[i].position;
      if (!Array.isArray(p)) continue;
      const d = Math.hypot(view.X(p[0]) - px, view.Y(p[1]) - py);
      const r = Math.max(7, radiusOf(balls[i]) * view.s);
      if (d <= r && d < bestD) { best = i; bestD = d; }
    }
    return best;
  }

  function hitTip(px, py) {
    const n = setup.balls.length;
    const candidates = n <= 100 ? [...Array(n).keys()] : selected >= 0 ? [selected] : [];
    for (const i of candidates) {
      const b = setup.balls[i];
      if (!Array.isArray(b.velocity) || !(Math.hypot(b.velocity[0], b.velocity[1]) > 0)) continue;
      const t = velocityTip(view, b);
      if (t && Math.hypot(t[0] - px, t[1] - py) <= 7) return i;
    }
    return -1;
  }

  function hitVertex(px, py) {
    if (setup.table.shape !== 'polygon' || !Array.isArray(setup.table.vertices)) return -1;
    const vs = setup.table.vertices;
    for (let k = 0; k < vs.length; k++) {
      if (Math.hypot(view.X(vs[k][0]) - px, view.Y(vs[k][1]) - py) <= 7) return k;
    }
    return -1;
  }

  function onPointerDown(e) {
    try {
      if (e.button !== 0) return;
      if (player.run) { resetRun(); }
      drawTable();
      const w = toWorld(e);
      if (!w) return;
      let i = hitTip(w.px, w.py);
      if (i >= 0) {
        drag = { kind: 'velocity', i };
      } else if ((i = hitBall(w.px, w.py)) >= 0) {
        const p = setup.balls[i].position;
        drag = mode === 'velocity' || e.shiftKey
          ? { kind: 'velocity', i }
          : { kind: 'move', i, dx: w.x - p[0], dy: w.y - p[1] };
      } else if ((i = hitVertex(w.px, w.py)) >= 0) {
        drag = { kind: 'vertex', i };
      } else {
        select(-1);
        return;
      }
      if (drag.kind !== 'vertex') select(drag.i);
      drag.moved = false;
      canvas.setPointerCapture(e.pointerId);
      e.preventDefault();
    } catch (err) {
      runError = errText(err);
      updateError();
    }
  }

  function onPointerMove(e) {
    try {
      const w = toWorld(e);
      if (!w) return;
      if (!drag) {
        if (player.run || !setup) { canvas.style.cursor = 'default'; return; }
        const overTip = hitTip(w.px, w.py) >= 0 || hitVertex(w.px, w.py) >= 0;
        const overBall = hitBall(w.px, w.py) >= 0;
        canvas.style.cursor = overTip ? 'pointer' : overBall ? (mode === 'velocity' || e.shiftKey ? 'crosshair' : 'grab') : 'default';
        return;
      }
      const step = tableStep(setup);
      if (drag.kind === 'move') {
        const b = setup.balls[drag.i];
        b.position = [roundTo(w.x - drag.dx, step), roundTo(w.y - drag.dy, step)];
        showBall(ballRows, drag.i, b, 'position');
      } else if (drag.kind === 'velocity') {
        const b = setup.balls[drag.i];
        const p = b.position;
        const vx = (w.x - p[0]) / VEL_TAU, vy = (w.y - p[1]) / VEL_TAU;
        const vstep = 10 ** Math.ceil(Math.log10(step / VEL_TAU) - 1e-9);
        b.velocity = [roundTo(vx, vstep), roundTo(vy, vstep)];
        showBall(ballRows, drag.i, b, 'velocity');
      } else if (drag.kind === 'vertex') {
        const vs = setup.table.vertices;
        vs[drag.i] = [roundTo(w.x, step), roundTo(w.y, step)];
      }
      drag.moved = true;
      changed();
    } catch (err) {
      runError = errText(err);
      updateError();
    }
  }

  function onPointerUp(e) {
    if (!drag) return;
    const d = drag;
    drag = null;
    try { canvas.releasePointerCapture(e.pointerId); } catch (err) { /* not captured */ }
    if (d.moved && d.kind === 'vertex') renderTable();
    if (d.moved) validateNow();
    drawAll();
  }

  function onDoubleClick(e) {
    try {
      if (player.run) return;
      const w = toWorld(e);
      if (!w || hitBall(w.px, w.py) >= 0) return;
      const b = addBall(setup, spotForNewBall(setup, [w.x, w.y]));
      selected = setup.balls.indexOf(b);
      changed({ panels: true, colour: true });
    } catch (err) {
      runError = errText(err);
      updateError();
    }
  }

  canvas.addEventListener('pointerdown', onPointerDown);
  canvas.addEventListener('pointermove', onPointerMove);
  canvas.addEventListener('pointerup', onPointerUp);
  canvas.addEventListener('pointercancel', onPointerUp);
  canvas.addEventListener('dblclick', onDoubleClick);

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

// The lab's bars above the table: the examples, Run / Pause / Reset with
// the speed, and the options (what dragging does, traces, arrows).

import { el } from './lab-dom.js';
import { roundSig } from './lab-format.js';

// examples: [{name, scenario}]. actions: loadExample(name), run(), pause(),
// reset(), speed(log10 of the factor), mode('move' | 'velocity'),
// traces(shown), arrows(shown). Returns the three bars and the functions
// that show the lab's state in them.
export function createToolbar(examples, actions) {
  const exampleBar = el('div', { id: 'lab-examples', class: 'bs-lab-examples' },
    el('span', { class: 'bs-lab-label', text: 'Examples:' }));
  for (const ex of examples) {
    exampleBar.append(el('button', {
      type: 'button', class: 'bs-lab-example', dataset: { example: ex.name }, text: ex.name,
      title: `load examples/lab/${ex.name}.json`, onclick: () => actions.loadExample(ex.name),
    }));
  }

  const runBtn = el('button', { id: 'lab-run', type: 'button', class: 'bs-lab-primary', text: 'Run', onclick: () => actions.run() });
  const pauseBtn = el('button', { id: 'lab-pause', type: 'button', text: 'Pause', disabled: true, onclick: () => actions.pause() });
  const resetBtn = el('button', { id: 'lab-reset', type: 'button', text: 'Reset', onclick: () => actions.reset() });
  const speedInput = el('input', {
    id: 'lab-speed', type: 'range', min: '-7', max: '1', step: '0.05', value: '0',
    title: 'simulated seconds per real second (logarithmic)',
    oninput: () => { actions.speed(Number(speedInput.value)); speedOut.textContent = speedText(Number(speedInput.value)); },
  });
  const speedOut = el('output', { class: 'bs-lab-speed', text: '×1' });
  const modeMove = el('input', { type: 'radio', name: 'bs-lab-mode', value: 'move', checked: true,
    onchange: () => { actions.mode('move'); } });
  const modeVel = el('input', { type: 'radio', name: 'bs-lab-mode', value: 'velocity',
    onchange: () => { actions.mode('velocity'); } });
  const tracesBox = el('input', { type: 'checkbox', checked: true,
    onchange: () => { actions.traces(tracesBox.checked); } });
  const arrowsBox = el('input', { type: 'checkbox', checked: true,
    onchange: () => { actions.arrows(arrowsBox.checked); } });

  const toolbar = el('div', { class: 'bs-lab-toolbar' },
    runBtn, pauseBtn, resetBtn,
    el('label', { class: 'bs-lab-speedbox' }, 'speed ', speedInput, speedOut));
  const options = el('div', { class: 'bs-lab-toolbar bs-lab-options' },
    el('span', { class: 'bs-lab-modes', title: 'what dragging a ball does (Shift-drag always sets the velocity)' },
      'drag: ', el('label', null, modeMove, 'move'), el('label', null, modeVel, 'velocity')),
    el('label', null, tracesBox, 'traces'),
    el('label', null, arrowsBox, 'arrows'));

  return {
    exampleBar, toolbar, options,
    // The example loaded and unchanged since (null: none).
    markExample(name) {
      for (const b of exampleBar.querySelectorAll('button')) {
        b.setAttribute('aria-pressed', String(b.dataset.example === name));
      }
    },
    // The speed, as log10 of simulated seconds per real second.
    showSpeed(speedLog) {
      speedInput.value = String(speedLog);
      speedOut.textContent = speedText(speedLog);
    },
    // The buttons for a run (lab-run.js), or null in the setup.
    showRun(run) {
      const active = !!run && !run.done;
      pauseBtn.disabled = !active;
      pauseBtn.textContent = run && run.paused ? 'Resume' : 'Pause';
      runBtn.textContent = run ? 'Run again' : 'Run';
    },
  };
}

function speedText(speedLog) {
  const s = 10 ** speedLog;
  return `×${s >= 1 ? roundSig(s, 3) : s.toPrecision(2).replace(/\.?0+e/, 'e')}`;
}

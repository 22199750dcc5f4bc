// The lab's numbers under the table: the state (setup, running, paused,
// finished), the time, the events, the total kinetic energy and the total
// momentum, all from an engine frame.

import { el } from './lab-dom.js';
import { fmtSI, fmtNum } from './lab-format.js';

// Returns the element and the functions that fill it.
export function createStats() {
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
  const element = el('div', { class: 'bs-lab-stats' }, stateVal, tStat, evStat, eStat, pStat);
  return {
    element,
    // Frame f (pb.frame(t)'s reply, or null: no valid setup) at time t.
    show(f, t) {
      tVal.textContent = fmtSI(t, 's', 6);
      if (f) {
        evVal.textContent = String(f.events);
        eVal.textContent = fmtSI(f.energy, 'J', 6);
        pVal.textContent = `(${fmtNum(f.momentum[0], 6)}, ${fmtNum(f.momentum[1], 6)})`;
      } else {
        evVal.textContent = '–'; eVal.textContent = '–'; pVal.textContent = '–';
      }
    },
    // The state of a run (lab-run.js), or null in the setup.
    showState(run) {
      stateVal.textContent = !run ? 'setup' : run.done ? 'finished' : run.paused ? 'paused' : 'running';
      stateVal.dataset.state = stateVal.textContent;
    },
  };
}

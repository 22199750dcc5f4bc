// The lab's Physics panel: the model, its physics fields (blank: the
// engine's documented default), cluster impacts and the run's end.

import { el, present } from './lab-dom.js';
import { row, numField } from './lab-form.js';
import { MODELS, PHYSICS_FIELDS, FIELD_INFO, defaultFor, setModel } from './lab-scenario.js';

// Fills `body` with the fields of scenario `setup`, which they edit in
// place; changed(options) follows every edit (options.panels: the panels
// must be drawn again). form: lab-form.js.
export function renderPhysicsPanel(body, setup, form, changed) {
  const p = setup.physics;
  const modelSel = el('select', { id: 'lab-model', 'aria-label': 'model',
    onchange: () => {
      setModel(setup, modelSel.value);
      changed({ panels: true });
    } },
  MODELS.map((m) => el('option', { value: m, text: m })));
  if (!MODELS.includes(p.model)) modelSel.append(el('option', { value: p.model, text: p.model }));
  modelSel.value = p.model;

  const fields = (PHYSICS_FIELDS[p.model] || []).map((f) => row(FIELD_INFO[f].label, numField(form, {
    value: p[f], placeholder: defaultFor(p, f), label: `physics.${f}`,
    onSet: (v) => { if (v === undefined) delete p[f]; else p[f] = v; changed(); },
  }), FIELD_INFO[f].unit));

  // Cluster impacts (physics.ball_clusters, docs/scenario.md): off is
  // the default, so unticking leaves the field out.
  const clustersBox = el('input', { type: 'checkbox', id: 'lab-clusters', checked: p.ball_clusters === true,
    'aria-label': 'physics.ball_clusters',
    onchange: () => {
      if (clustersBox.checked) p.ball_clusters = true;
      else delete p.ball_clusters;
      changed();
    } });
  const clustersRow = row('cluster impacts', clustersBox, '');
  clustersRow.title = 'an impact on balls within 0.5 mm of each other is resolved at once with ' +
    'Hertz contacts (a break spreads the rack); off: every impact is pairwise';

  // Duration: a time, or "rest" for the models with friction.
  const isRest = setup.until === 'rest' || (setup.until === undefined && p.model !== 'ideal');
  const untilSel = el('select', { 'aria-label': 'run until',
    onchange: () => {
      if (untilSel.value === 'rest') setup.until = 'rest';
      else setup.until = { time: Number(timeIn.value) > 0 ? Number(timeIn.value) : 5 };
      changed({ panels: true });
    } },
  el('option', { value: 'time', text: 'a time' }),
  el('option', { value: 'rest', text: 'every ball rests' }));
  untilSel.value = isRest ? 'rest' : 'time';
  const timeIn = numField(form, {
    value: !isRest && setup.until && typeof setup.until === 'object' ? setup.until.time : '',
    placeholder: 5, label: 'until.time', required: true,
    onSet: (v) => { setup.until = { time: v }; changed(); },
  });
  if (isRest) timeIn.disabled = true;

  body.replaceChildren(...present(
    row('model', modelSel, ''),
    ...fields,
    clustersRow,
    row('run until', untilSel, ''),
    isRest ? null : row('time', timeIn, 's'),
    el('div', { class: 'bs-lab-note', text: 'Blank fields take the engine\'s documented default (shown in grey).' })));
}

// The lab's Table panel: a box's size, or a polygon's vertices and presets.

import { el, present } from './lab-dom.js';
import { row, numField } from './lab-form.js';
import { roundSig } from './lab-format.js';
import { clone, tableAs, resizeTable, addVertex, polygonPresets } from './lab-scenario.js';

// Fills `body` with the fields of the table of scenario `setup`, which they
// edit in place; changed(options) follows every edit (options.panels: the
// panels must be drawn again). examples: the lab's examples, whose polygons
// are presets. form: lab-form.js.
export function renderTablePanel(body, setup, examples, form, changed) {
  const t = setup.table;
  const shapeSel = el('select', { id: 'lab-shape', 'aria-label': 'table shape',
    onchange: () => {
      setup.table = tableAs(t, shapeSel.value);
      changed({ panels: true });
    } },
  el('option', { value: 'rectangle', text: 'box (rectangle)' }),
  el('option', { value: 'polygon', text: 'polygon' }));
  const supported = t.shape === 'rectangle' || t.shape === 'polygon';
  if (!supported) shapeSel.append(el('option', { value: t.shape, text: String(t.shape) }));
  shapeSel.value = t.shape;

  const parts = [row('shape', shapeSel, '')];
  if (t.shape === 'rectangle') {
    if (!Array.isArray(t.min)) t.min = [-0.5, -0.5];
    if (!Array.isArray(t.max)) t.max = [0.5, 0.5];
    const positive = (label, axis) => numField(form, {
      value: roundSig(t.max[axis] - t.min[axis], 12), label, required: true,
      onSet: (v) => { if (!(v > 0)) throw new Error(`${label} must be above 0`); resizeTable(t, axis, v); changed({ panels: true }); },
    });
    parts.push(row('width', positive('table width', 0), 'm'));
    parts.push(row('height', positive('table height', 1), 'm'));
    parts.push(el('div', { class: 'bs-lab-note',
      text: `from (${t.min[0]}, ${t.min[1]}) to (${t.max[0]}, ${t.max[1]}); resizing keeps the centre` }));
  } else if (t.shape === 'polygon') {
    if (!Array.isArray(t.vertices)) t.vertices = [];
    const presetSel = el('select', { 'aria-label': 'polygon preset',
      onchange: () => {
        const p = polygonPresets(setup.table, examples).find((q) => q.name === presetSel.value);
        if (p) { t.vertices = clone(p.vertices); changed({ panels: true }); }
      } },
    el('option', { value: '', text: 'preset…' }),
    polygonPresets(setup.table, examples).map((p) => el('option', { value: p.name, text: p.name })));
    parts.push(row('preset', presetSel, ''));
    const list = el('table', { class: 'bs-lab-grid bs-lab-vertices' },
      el('thead', null, el('tr', null, el('th', { text: '#' }), el('th', { text: 'x (m)' }), el('th', { text: 'y (m)' }), el('th'))));
    const tbody = el('tbody');
    t.vertices.forEach((v, k) => {
      tbody.append(el('tr', null,
        el('td', { class: 'bs-lab-idx', text: String(k) }),
        el('td', null, numField(form, { value: v[0], required: true, label: `table.vertices[${k}] x`,
          onSet: (x) => { v[0] = x; changed(); } })),
        el('td', null, numField(form, { value: v[1], required: true, label: `table.vertices[${k}] y`,
          onSet: (y) => { v[1] = y; changed(); } })),
        el('td', null, el('button', { type: 'button', class: 'bs-lab-x', title: `remove vertex ${k}`, text: '×',
          disabled: t.vertices.length <= 3,
          onclick: () => { t.vertices.splice(k, 1); changed({ panels: true }); } }))));
    });
    list.append(tbody);
    parts.push(list);
    parts.push(el('button', { type: 'button', text: '+ vertex', title: 'add a vertex halfway along the last edge',
      onclick: () => { addVertex(t.vertices); changed({ panels: true }); } }));
    parts.push(el('div', { class: 'bs-lab-note', text: 'Vertices in either order; drag the white handles on the table to move them.' }));
  } else {
    parts.push(el('div', { class: 'bs-lab-note', text: `The lab edits boxes and polygons; this "${t.shape}" table is sent to the engine as it is and not drawn.` }));
  }
  body.replaceChildren(...present(parts));
}

// The lab's Balls panel: the ball count, the table of balls (id, position,
// velocity, radius, mass, wall restitution; the first TABLE_ROWS rows
// until "show all") and the pair restitutions.

import { el, present } from './lab-dom.js';
import { row, numField } from './lab-form.js';
import {
  DEFAULT_RADIUS, DEFAULT_MASS, wallDefault, addBall, renameBall, addPairRestitution,
} from './lab-scenario.js';

// Ball rows shown in the table before "show all".
const TABLE_ROWS = 60;

// Fills `body` with the balls of scenario `setup`, which the fields edit in
// place. view: {colours, selected, showAllRows}. form: lab-form.js.
// actions: changed(options) after every edit (options.panels: the panels
// must be drawn again, options.colour: the colours too), select(i),
// removeBall(i), setCount(n), showAll().
// Returns the shown rows, for markSelected and showBall.
export function renderBallsPanel(body, setup, { colours, selected, showAllRows }, form, actions) {
  const { changed } = actions;
  const balls = setup.balls;
  const n = balls.length;
  const countIn = numField(form, { value: n, label: 'ball count', required: true,
    onSet: (v) => {
      if (!Number.isInteger(v) || v < 0 || v > 5000) throw new Error('ball count: a whole number from 0 to 5000');
      actions.setCount(v);
    } });
  countIn.id = 'lab-count';
  countIn.classList.add('bs-short');
  const head = el('div', { class: 'bs-lab-ballhead' },
    row('count', countIn, ''),
    el('button', { type: 'button', text: '+ ball', onclick: () => { addBall(setup); changed({ panels: true, colour: true }); } }));

  const cols = [['', ''], ['id', ''], ['x', 'm'], ['y', 'm'], ['vx', 'm/s'], ['vy', 'm/s'],
    ['radius', 'm'], ['mass', 'kg'], ['wall e', ''], ['', '']];
  const table = el('table', { class: 'bs-lab-grid bs-lab-balls', id: 'lab-balls' },
    el('thead', null, el('tr', null, cols.map(([c, u]) => el('th', { title: u ? `${c} (${u})` : c },
      c, u ? el('span', { class: 'bs-lab-unit', text: ` ${u}` }) : null)))));
  const tbody = el('tbody');
  const rows = [];   // per shown ball row: {x, y, vx, vy, tr}
  const shown = showAllRows ? n : Math.min(n, TABLE_ROWS);
  const wd = wallDefault(setup);
  for (let i = 0; i < shown; i++) {
    const b = balls[i];
    const name = `balls[${i}]`;
    const idIn = el('input', { type: 'text', class: 'bs-id', value: b.id ?? '', 'aria-label': `${name}.id`, spellcheck: 'false' });
    idIn.addEventListener('change', () => {
      renameBall(setup, b, idIn.value);
      changed({ panels: true, colour: true });
    });
    const pos = () => { if (!Array.isArray(b.position)) b.position = [0, 0]; return b.position; };
    const vel = () => { if (!Array.isArray(b.velocity)) b.velocity = [0, 0]; return b.velocity; };
    const x = numField(form, { value: b.position?.[0], required: true, label: `${name}.position x`, onSet: (v) => { pos()[0] = v; changed(); } });
    const y = numField(form, { value: b.position?.[1], required: true, label: `${name}.position y`, onSet: (v) => { pos()[1] = v; changed(); } });
    const vx = numField(form, { value: b.velocity?.[0], placeholder: 0, label: `${name}.velocity x`, onSet: (v) => { vel()[0] = v ?? 0; changed(); } });
    const vy = numField(form, { value: b.velocity?.[1], placeholder: 0, label: `${name}.velocity y`, onSet: (v) => { vel()[1] = v ?? 0; changed(); } });
    const opt = (key, def) => numField(form, { value: b[key], placeholder: def, label: `${name}.${key}`,
      onSet: (v) => { if (v === undefined) delete b[key]; else b[key] = v; changed(); } });
    const tr = el('tr', { class: i === selected ? 'bs-selected' : '', onclick: () => actions.select(i) },
      el('td', null, el('span', { class: 'bs-swatch', style: `background:${colours[i]}` })),
      el('td', null, idIn), el('td', null, x), el('td', null, y), el('td', null, vx), el('td', null, vy),
      el('td', null, opt('radius', DEFAULT_RADIUS)), el('td', null, opt('mass', DEFAULT_MASS)),
      el('td', null, opt('wall_restitution', wd)),
      el('td', null, el('button', { type: 'button', class: 'bs-lab-x', text: '×', title: `remove ball ${b.id}`,
        onclick: (e) => { e.stopPropagation(); actions.removeBall(i); } })));
    rows.push({ x, y, vx, vy, tr });
    tbody.append(tr);
  }
  table.append(tbody);
  const more = n > shown
    ? el('button', { type: 'button', class: 'bs-lab-more', text: `show all ${n} balls (${n - shown} more rows)`,
      onclick: () => actions.showAll() })
    : null;

  // Pair restitution: overrides of the ball-ball restitution.
  const pairs = setup.pair_restitution || [];
  const pairList = el('datalist', { id: 'bs-lab-ids' },
    balls.slice(0, 200).map((b) => el('option', { value: String(b.id) })));
  const pairRows = pairs.map((pr, k) => {
    const idField = (j) => {
      const inp = el('input', { type: 'text', class: 'bs-id', list: 'bs-lab-ids', value: pr.balls?.[j] ?? '',
        'aria-label': `pair_restitution[${k}].balls[${j}]` });
      inp.addEventListener('change', () => {
        if (!Array.isArray(pr.balls)) pr.balls = ['', ''];
        pr.balls[j] = inp.value; changed();
      });
      return inp;
    };
    return el('div', { class: 'bs-lab-pair' }, idField(0), '–', idField(1), ' e ',
      numField(form, { value: pr.restitution, required: true, label: `pair_restitution[${k}].restitution`,
        onSet: (v) => { pr.restitution = v; changed(); } }),
      el('button', { type: 'button', class: 'bs-lab-x', text: '×', title: 'remove this pair',
        onclick: () => { pairs.splice(k, 1); changed({ panels: true }); } }));
  });
  const addPair = el('button', { type: 'button', text: '+ pair restitution',
    onclick: () => {
      addPairRestitution(setup);
      changed({ panels: true });
    } });

  body.replaceChildren(...present(head, el('div', { class: 'bs-lab-tablewrap' }, table), more,
    el('div', { class: 'bs-lab-sub', text: 'Pair restitution (overrides the ball-ball restitution for two balls)' }),
    pairList, ...pairRows, addPair,
    el('div', { class: 'bs-lab-note', text: `Blank radius, mass and wall e take the defaults ${DEFAULT_RADIUS} m, ${DEFAULT_MASS} kg and ${wd}.` })));
  return rows;
}

// Moves the highlight from row `from` to row `to` (either may be hidden or -1).
export function markSelected(rows, from, to) {
  const old = rows[from];
  if (old) old.tr.classList.remove('bs-selected');
  const cur = rows[to];
  if (cur) cur.tr.classList.add('bs-selected');
}

// Shows ball b's position or velocity (what: 'position' | 'velocity') in
// its row, if shown, after a drag on the table.
export function showBall(rows, i, b, what) {
  const r = rows[i];
  if (!r) return;
  if (what === 'position') { r.x.value = String(b.position[0]); r.y.value = String(b.position[1]); }
  else { r.vx.value = String(b.velocity[0]); r.vy.value = String(b.velocity[1]); }
}

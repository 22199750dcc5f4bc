// The lab's scenario: a plain object in the contract's scenario format
// (docs/contract.md, docs/scenario.md), edited in
// place by the lab's forms and table, and the text Run sends to the engine.
// Every function here works on the scenario passed to it; nothing physical
// is computed (placing a new ball only avoids the walls and the other balls).

import { tableVertices, bbox, fits, regularPolygon, posStep } from './lab-geometry.js';
import { roundTo, roundSig } from './lab-format.js';

// The engine's defaults (engine.defaults: default_physics for each model,
// the default ball), the one home of them; mountLab sets them from the
// engine before anything is built or shown.
let defaults = null;
export let DEFAULT_RADIUS = NaN;
export let DEFAULT_MASS = NaN;
export function setDefaults(d) {
  if (!d || !d.ball || !d.physics) throw new Error('the engine gave no defaults');
  defaults = d;
  DEFAULT_RADIUS = d.ball.radius;
  DEFAULT_MASS = d.ball.mass;
}

export const MODELS = ['ideal', 'friction', 'pool'];
// Physics fields shown for each model, with their documented defaults
// (docs/scenario.md, "Defaults"). A blank field is left out of the
// scenario, so the engine applies the default itself.
export const PHYSICS_FIELDS = {
  ideal: ['ball_ball_restitution'],
  friction: ['ball_ball_restitution', 'deceleration'],
  pool: ['ball_ball_restitution', 'ball_ball_friction', 'gravity',
         'sliding_friction', 'rolling_friction', 'spinning_friction'],
};
export const FIELD_INFO = {
  ball_ball_restitution: { label: 'ball-ball restitution', unit: '' },
  ball_ball_friction: { label: 'ball-ball friction', unit: '' },
  deceleration: { label: 'deceleration', unit: 'm/s²' },
  gravity: { label: 'gravity', unit: 'm/s²' },
  sliding_friction: { label: 'sliding friction', unit: '' },
  rolling_friction: { label: 'rolling friction', unit: '' },
  spinning_friction: { label: 'spinning friction', unit: '' },
};

// The scenario the lab starts with when there is no example.
export const EMPTY_SCENARIO = {
  physics: { model: 'ideal' }, table: { shape: 'rectangle', min: [-0.5, -0.5], max: [0.5, 0.5] },
  balls: [], until: { time: 5 },
};

const ANY_TABLE = [[-0.5, -0.5], [0.5, 0.5]];

export function clone(x) { return x === undefined ? undefined : JSON.parse(JSON.stringify(x)); }

// Makes the editable parts present; everything else passes through.
export function normalise(sc) {
  if (!sc || typeof sc !== 'object' || Array.isArray(sc)) sc = {};
  if (!sc.physics || typeof sc.physics !== 'object') sc.physics = { model: 'ideal' };
  if (!sc.physics.model) sc.physics.model = 'ideal';
  if (!sc.table || typeof sc.table !== 'object') sc.table = { shape: 'rectangle', min: [-0.5, -0.5], max: [0.5, 0.5] };
  if (!Array.isArray(sc.balls)) sc.balls = [];
  if (sc.until === undefined && sc.physics.model === 'ideal') sc.until = { time: 5 };
  return sc;
}

// The scenario Run sends: a fresh copy, without an empty pair list.
export function buildScenario(setup) {
  const sc = clone(setup);
  if (Array.isArray(sc.pair_restitution) && sc.pair_restitution.length === 0) delete sc.pair_restitution;
  return sc;
}

// The run's end: a time T, or rest.
export function untilOf(sc) {
  if (sc.until === 'rest') return { T: null, rest: true };
  if (sc.until && typeof sc.until === 'object' && Number.isFinite(sc.until.time)) return { T: sc.until.time, rest: false };
  return { T: null, rest: sc.physics && sc.physics.model !== 'ideal' };
}

export function radiusOf(b) { return Number.isFinite(b.radius) && b.radius > 0 ? b.radius : DEFAULT_RADIUS; }

// The documented default of a physics field (shown in a blank field).
export function defaultFor(p, field) {
  const d = defaults.physics[p.model] || defaults.physics.ideal;
  switch (field) {
    case 'ball_ball_restitution': return d.ball_ball_restitution;
    case 'ball_ball_friction': return d.ball_ball_friction_fit ? 'mu(v) fit' : d.ball_ball_friction;
    case 'gravity': return d.gravity;
    case 'sliding_friction': return d.sliding_friction;
    case 'rolling_friction': return d.rolling_friction;
    case 'spinning_friction': return d.spinning_friction;
    case 'deceleration': return `${roundSig((p.rolling_friction ?? d.rolling_friction) * (p.gravity ?? d.gravity), 6)}`;
    default: return '';
  }
}

// A ball's wall restitution when it has none of its own.
export function wallDefault(setup) {
  if (setup.table && typeof setup.table.cushion_restitution === 'number') return setup.table.cushion_restitution;
  return setup.physics.model === 'pool' ? defaults.pool_cushion_restitution : defaults.ball.wall_restitution;
}

export function setModel(setup, model) {
  setup.physics.model = model;
  if (model === 'ideal' && (setup.until === 'rest' || setup.until === undefined)) setup.until = { time: 5 };
}

// ---------------------------------------------------------------- table

// The table as a box or a polygon with the same corners (or bounds); its
// other fields are kept.
export function tableAs(t, shape) {
  const vs = tableVertices(t);
  const keep = { ...t };
  delete keep.shape; delete keep.min; delete keep.max; delete keep.vertices; delete keep.size;
  if (shape === 'polygon') {
    return { shape: 'polygon', vertices: clone(vs || [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]), ...keep };
  }
  const bb = bbox(vs || ANY_TABLE);
  return { shape: 'rectangle', min: [bb.x0, bb.y0], max: [bb.x1, bb.y1], ...keep };
}

// Sets a box's size along an axis (0: x, 1: y), keeping its centre.
export function resizeTable(t, axis, v) {
  const c = (t.min[axis] + t.max[axis]) / 2;
  t.min[axis] = roundSig(c - v / 2, 12) + 0;
  t.max[axis] = roundSig(c + v / 2, 12) + 0;
}

// Adds a vertex halfway along a polygon's last edge.
export function addVertex(vs) {
  if (vs.length === 0) { vs.push([0, 0]); } else {
    const a = vs[vs.length - 1], b = vs[0];
    vs.push([roundSig((a[0] + b[0]) / 2, 8) + 0, roundSig((a[1] + b[1]) / 2, 8) + 0]);
  }
}

// Polygons to choose from: the examples' and regular ones the size of the table.
export function polygonPresets(table, examples) {
  const list = [];
  for (const ex of examples) {
    const t = ex.scenario && ex.scenario.table;
    if (t && t.shape === 'polygon' && Array.isArray(t.vertices)) {
      const name = /star/.test(ex.name) ? 'star' : /l_shape/.test(ex.name) ? 'L shape' : ex.name;
      list.push({ name: `${name} (${ex.name})`, vertices: t.vertices });
    }
  }
  const bb = bbox(tableVertices(table) || ANY_TABLE);
  const r = Math.min(bb.x1 - bb.x0, bb.y1 - bb.y0) / 2;
  const cx = (bb.x0 + bb.x1) / 2, cy = (bb.y0 + bb.y1) / 2;
  const shift = (vs) => vs.map(([x, y]) => [roundSig(x + cx, 6) + 0, roundSig(y + cy, 6) + 0]);
  list.push({ name: 'triangle', vertices: shift(regularPolygon(3, r, Math.PI / 2)) });
  list.push({ name: 'hexagon', vertices: shift(regularPolygon(6, r, 0)) });
  list.push({ name: 'octagon', vertices: shift(regularPolygon(8, r, Math.PI / 8)) });
  list.push({ name: 'box (current bounds)', vertices: [[bb.x0, bb.y0], [bb.x1, bb.y0], [bb.x1, bb.y1], [bb.x0, bb.y1]] });
  return list;
}

// The step a position on this table is rounded to.
export function tableStep(setup) {
  return posStep(bbox(tableVertices(setup.table) || ANY_TABLE));
}

// ---------------------------------------------------------------- balls

function uniqueId(setup) {
  const ids = new Set(setup.balls.map((b) => String(b.id)));
  for (let k = setup.balls.length + 1; ; k++) if (!ids.has(`b${k}`)) return `b${k}`;
}

// Spots inside the table clear of the walls, of the other balls and of
// each other, nearest the table's centre first (geometry only).
function freeSpots(setup, r, count) {
  const vs = tableVertices(setup.table);
  const bb = bbox(vs || ANY_TABLE);
  const gap = r * 0.2;
  const step = Math.max(2 * r + gap, Math.min(bb.x1 - bb.x0, bb.y1 - bb.y0) / 60);
  const cx = (bb.x0 + bb.x1) / 2, cy = (bb.y0 + bb.y1) / 2;
  const cands = [];
  for (let x = bb.x0 + r + gap; x <= bb.x1 - r - gap; x += step) {
    for (let y = bb.y0 + r + gap; y <= bb.y1 - r - gap; y += step) cands.push([x, y]);
  }
  cands.sort((a, b) => Math.hypot(a[0] - cx, a[1] - cy) - Math.hypot(b[0] - cx, b[1] - cy));
  const taken = [];
  for (const b of setup.balls) {
    if (Array.isArray(b.position)) taken.push([b.position[0], b.position[1], radiusOf(b)]);
  }
  const out = [];
  for (const [x, y] of cands) {
    if (out.length >= count) break;
    if (vs && !fits(x, y, r + gap, vs)) continue;
    let clear = true;
    for (const [bx, by, br] of taken) {
      if (Math.hypot(bx - x, by - y) < r + br + gap) { clear = false; break; }
    }
    if (!clear) continue;
    out.push([x, y]);
    taken.push([x, y, r]);
  }
  while (out.length < count) out.push([cx, cy]);  // no room: the engine will say so
  return out;
}

// Adds `count` balls like the last one, at rest, at the given point or in free spots.
export function addBalls(setup, count, at) {
  const last = setup.balls[setup.balls.length - 1];
  const proto = {};
  if (last && last.radius !== undefined) proto.radius = last.radius;
  if (last && last.mass !== undefined) proto.mass = last.mass;
  const r = radiusOf(proto);
  const step = tableStep(setup);
  const spots = at ? [at] : freeSpots(setup, r, count);
  const added = [];
  for (const p of spots) {
    const b = { id: uniqueId(setup), position: [roundTo(p[0], step), roundTo(p[1], step)], velocity: [0, 0], ...proto };
    setup.balls.push(b);
    added.push(b);
  }
  return added;
}

export function addBall(setup, at) { return addBalls(setup, 1, at)[0]; }

// Where a ball added at point `at` goes: in a box, clear of its walls (it
// takes the last ball's radius).
export function spotForNewBall(setup, at) {
  const t = setup.table;
  if (t.shape === 'rectangle' && Array.isArray(t.min) && Array.isArray(t.max)) {
    const last = setup.balls[setup.balls.length - 1];
    const r = last ? radiusOf(last) : DEFAULT_RADIUS;
    const m = r + posStep(bbox(tableVertices(t)));
    return at.map((v, k) => (t.max[k] - t.min[k] > 2 * m ? Math.min(Math.max(v, t.min[k] + m), t.max[k] - m) : v));
  }
  return at;
}

function dropPairsOf(setup, b) {
  if (setup.pair_restitution) {
    setup.pair_restitution = setup.pair_restitution.filter((pr) => !(Array.isArray(pr.balls) && pr.balls.includes(b.id)));
  }
}

// Removes ball i and the pair restitutions that name it.
export function removeBallAt(setup, i) {
  const [b] = setup.balls.splice(i, 1);
  if (b) dropPairsOf(setup, b);
}

// Removes balls from the end, or adds balls in free spots, to n balls.
export function setBallCount(setup, n) {
  const balls = setup.balls;
  while (balls.length > n) dropPairsOf(setup, balls.pop());
  if (balls.length < n) addBalls(setup, n - balls.length);
}

// Renames a ball, in the pair restitutions too.
export function renameBall(setup, b, id) {
  const old = b.id;
  b.id = id;
  for (const pr of setup.pair_restitution || []) {
    if (Array.isArray(pr.balls)) pr.balls = pr.balls.map((x) => (x === old ? b.id : x));
  }
}

// A pair restitution for the first two balls, at the ball-ball restitution.
export function addPairRestitution(setup) {
  const balls = setup.balls;
  if (!setup.pair_restitution) setup.pair_restitution = [];
  setup.pair_restitution.push({ balls: [balls[0]?.id ?? '', balls[1]?.id ?? ''],
    restitution: setup.physics.ball_ball_restitution ?? defaultFor(setup.physics, 'ball_ball_restitution') });
}

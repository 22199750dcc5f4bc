// Editing the setup on the lab's table canvas with the pointer: drag a ball
// to move it, Shift-drag (or drag in "velocity" mode) to set its velocity,
// drag an arrow tip to change it, drag a polygon's vertex, double-click the
// felt to add a ball. Positions are rounded to a step that suits the table.
//
// lab: the lab's side, read at each event:
//   setup, view (the drawing's transform, lab-table-drawing.js), mode
//   ('move' | 'velocity'), selected, running: the current values;
//   endRun(), drawTable(), drawAll(), select(i), changed(options),
//   dragged(i, 'position' | 'velocity'), vertexMoved(), validateNow(),
//   addedBall(i), fail(error).
// Returns {drag()}: the drag under way ({kind, i, ...}) or null.

import { roundTo } from './lab-format.js';
import { radiusOf, tableStep, addBall, spotForNewBall } from './lab-scenario.js';
import { VEL_TAU, velocityTip } from './lab-table-drawing.js';

export function attachEditor(canvas, lab) {
  let drag = null;

  function toWorld(e) {
    const r = canvas.getBoundingClientRect();
    const px = e.clientX - r.left, py = e.clientY - r.top;
    const view = lab.view;
    if (!view) return null;
    return { px, py, x: (px - view.ox) / view.s, y: (view.oy - py) / view.s };
  }

  function hitBall(px, py) {
    const view = lab.view;
    let best = -1, bestD = Infinity;
    const balls = lab.setup.balls;
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
    const setup = lab.setup, selected = lab.selected;
    const n = setup.balls.length;
    const candidates = n <= 100 ? [...Array(n).keys()] : selected >= 0 ? [selected] : [];
    for (const i of candidates) {
      const b = setup.balls[i];
      if (!Array.isArray(b.velocity) || !(Math.hypot(b.velocity[0], b.velocity[1]) > 0)) continue;
      const t = velocityTip(lab.view, b);
      if (t && Math.hypot(t[0] - px, t[1] - py) <= 7) return i;
    }
    return -1;
  }

  function hitVertex(px, py) {
    const setup = lab.setup, view = lab.view;
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
      if (lab.running) { lab.endRun(); }
      lab.drawTable();
      const w = toWorld(e);
      if (!w) return;
      let i = hitTip(w.px, w.py);
      if (i >= 0) {
        drag = { kind: 'velocity', i };
      } else if ((i = hitBall(w.px, w.py)) >= 0) {
        const p = lab.setup.balls[i].position;
        drag = lab.mode === 'velocity' || e.shiftKey
          ? { kind: 'velocity', i }
          : { kind: 'move', i, dx: w.x - p[0], dy: w.y - p[1] };
      } else if ((i = hitVertex(w.px, w.py)) >= 0) {
        drag = { kind: 'vertex', i };
      } else {
        lab.select(-1);
        return;
      }
      if (drag.kind !== 'vertex') lab.select(drag.i);
      drag.moved = false;
      canvas.setPointerCapture(e.pointerId);
      e.preventDefault();
    } catch (err) {
      lab.fail(err);
    }
  }

  function onPointerMove(e) {
    try {
      const w = toWorld(e);
      if (!w) return;
      const setup = lab.setup;
      if (!drag) {
        if (lab.running || !setup) { canvas.style.cursor = 'default'; return; }
        const overTip = hitTip(w.px, w.py) >= 0 || hitVertex(w.px, w.py) >= 0;
        const overBall = hitBall(w.px, w.py) >= 0;
        canvas.style.cursor = overTip ? 'pointer' : overBall ? (lab.mode === 'velocity' || e.shiftKey ? 'crosshair' : 'grab') : 'default';
        return;
      }
      const step = tableStep(setup);
      if (drag.kind === 'move') {
        const b = setup.balls[drag.i];
        b.position = [roundTo(w.x - drag.dx, step), roundTo(w.y - drag.dy, step)];
        lab.dragged(drag.i, 'position');
      } else if (drag.kind === 'velocity') {
        const b = setup.balls[drag.i];
        const p = b.position;
        const vx = (w.x - p[0]) / VEL_TAU, vy = (w.y - p[1]) / VEL_TAU;
        const vstep = 10 ** Math.ceil(Math.log10(step / VEL_TAU) - 1e-9);
        b.velocity = [roundTo(vx, vstep), roundTo(vy, vstep)];
        lab.dragged(drag.i, 'velocity');
      } else if (drag.kind === 'vertex') {
        const vs = setup.table.vertices;
        vs[drag.i] = [roundTo(w.x, step), roundTo(w.y, step)];
      }
      drag.moved = true;
      lab.changed();
    } catch (err) {
      lab.fail(err);
    }
  }

  function onPointerUp(e) {
    if (!drag) return;
    const d = drag;
    drag = null;
    try { canvas.releasePointerCapture(e.pointerId); } catch (err) { /* not captured */ }
    if (d.moved && d.kind === 'vertex') lab.vertexMoved();
    if (d.moved) lab.validateNow();
    lab.drawAll();
  }

  function onDoubleClick(e) {
    try {
      if (lab.running) return;
      const w = toWorld(e);
      if (!w || hitBall(w.px, w.py) >= 0) return;
      const setup = lab.setup;
      const b = addBall(setup, spotForNewBall(setup, [w.x, w.y]));
      lab.addedBall(setup.balls.indexOf(b));
    } catch (err) {
      lab.fail(err);
    }
  }

  canvas.addEventListener('pointerdown', onPointerDown);
  canvas.addEventListener('pointermove', onPointerMove);
  canvas.addEventListener('pointerup', onPointerUp);
  canvas.addEventListener('pointercancel', onPointerUp);
  canvas.addEventListener('dblclick', onDoubleClick);

  return { drag: () => drag };
}

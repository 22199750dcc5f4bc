// The game tab's input: the controls under the table (power, elevation,
// aim angle, tip reset, Shoot, Undo, Share, the call and nomination
// selects), the keys (space shoots, arrows aim and set the speed, Escape
// lets go), and the pointer on the table: hovering aims, a press holds
// the aim (or calls a pocket, or nominates a ball), a drag moves the cue
// ball in hand, and a press on the cue ball or the stick draws the cue
// back for a stroke (game-stroke.js turns its pull into the speed).
// Functions of the GameUI (game.js).

import { $ } from './game-dom.js';
import {
  MIN_PULL, normDeg, onStick, speedFromPower, speedFromPull, strokePull,
} from './game-stroke.js';

export function bindControls(ui) {
  $('power').addEventListener('input', () => {
    ui.aim.speed = speedFromPower(Number($('power').value));
    $('power-out').textContent = `${ui.aim.speed.toFixed(2)} m/s`;
    ui.requestRender();
  });
  $('elevation').addEventListener('input', () => {
    ui.aim.theta = Number($('elevation').value);
    $('elevation-out').textContent = `${Math.round(ui.aim.theta)}°`;
    ui.requestRender();  // the stick shows the elevation
  });
  $('phi').addEventListener('input', () => {
    const v = Number($('phi').value);
    if (Number.isFinite(v)) {
      ui.aim.phi = normDeg(v);
      ui.requestRender();
    }
  });
  $('phi').addEventListener('change', () => { $('phi').value = ui.aim.phi.toFixed(2); });
  $('tip-reset').addEventListener('click', () => {
    ui.aim.a = 0;
    ui.aim.b = 0;
    ui.syncControls();
  });
  $('shoot').addEventListener('click', () => ui.shoot());
  $('undo').addEventListener('click', () => ui.undo());
  $('share').addEventListener('click', () => { ui.share(); });  // the whole game
  const choose = (id, key) => $(id).addEventListener('change', () => {
    const v = $(id).value;
    ui.flow.override[key] = v === '' ? null : Number(v);
    ui.requestRender();
  });
  choose('call-ball', 'ball');
  choose('nominate', 'nominate');
  choose('call-pocket', 'pocket');
  $('concede').addEventListener('click', () => ui.decide('concede'));
  // a safety or a push-out has no call: the call drawn goes and comes back
  for (const id of ['safety', 'push-out']) $(id).addEventListener('change', () => ui.requestRender());
  $('playback-speed').addEventListener('change', () => $('table').focus({ preventScroll: true }));
  document.addEventListener('keydown', (ev) => onKey(ui, ev));
  document.addEventListener('keyup', (ev) => {
    if ((ev.key === ' ' || ev.code === 'Space') && ev.target && ev.target.tagName === 'BUTTON' && !$('game').hidden) {
      ev.preventDefault();
    }
  });
}

function onKey(ui, ev) {
  if ($('game').hidden) return;
  const t = ev.target;
  const tag = t && t.tagName;
  if (tag === 'INPUT' && t.type !== 'range') return;
  if (tag === 'SELECT' || tag === 'TEXTAREA') return;
  if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
  if (ev.key === 'Escape') {
    if (ui.stroke) endStroke(ui, true);
    else ui.aimHeld = false;
    ui.updatePanel();
    return;
  }
  if (ev.key === ' ' || ev.code === 'Space') {
    // space shoots, even with a button focused (its keyup is cancelled too)
    ev.preventDefault();
    if (!ev.repeat) ui.shoot();
  } else if ((ev.key === 'ArrowLeft' || ev.key === 'ArrowRight') && tag !== 'INPUT') {
    ev.preventDefault();
    const step = ev.shiftKey ? 1 : 0.1;
    ui.aim.phi = normDeg(ui.aim.phi + (ev.key === 'ArrowLeft' ? step : -step));
    ui.syncControls();
    ui.requestRender();
  } else if ((ev.key === 'ArrowUp' || ev.key === 'ArrowDown') && tag !== 'INPUT') {
    ev.preventDefault();
    const step = ev.shiftKey ? 0.5 : 0.1;
    const v = ui.aim.speed + (ev.key === 'ArrowUp' ? step : -step);
    ui.aim.speed = speedFromPower(Math.round(v * 100) / 100);
    ui.syncControls();
    ui.requestRender();
  }
}

export function bindCanvas(ui) {
  const c = ui.canvas;
  c.addEventListener('pointerdown', (ev) => onDown(ui, ev));
  c.addEventListener('pointermove', (ev) => onMove(ui, ev));
  c.addEventListener('pointerup', (ev) => onUp(ui, ev, false));
  c.addEventListener('pointercancel', (ev) => onUp(ui, ev, true));
  c.addEventListener('pointerleave', () => setGrabCursor(ui, false));
  c.addEventListener('contextmenu', (ev) => ev.preventDefault());
}

/** The grab radius around the cue ball (m): larger for a finger. */
function grabRadius(ui, ev) {
  const touch = ev && ev.pointerType && ev.pointerType !== 'mouse';
  return Math.max(ui.R * 1.6, (touch ? 24 : 14) / ui.view.scale);
}

function placing(ui) {
  const legal = ui.flow.legal();
  return !!legal.place && legal.place !== 'none';
}

function setGrabCursor(ui, on) { ui.canvas.classList.toggle('cue-grab', !!on); }

/** The mouse moving with no button down: the aim follows it (unless a
 *  press has fixed it), but not over the cue ball or the stick. */
function onHover(ui, ev) {
  if (ev.pointerType !== 'mouse' || ev.buttons !== 0 || !ui.table || !ui.canAct() || !ui.flow.shotDue()) {
    setGrabCursor(ui, false);
    return;
  }
  const p = ui.view.toTable(ev.clientX, ev.clientY);
  const cue = ui.cuePos();
  if (!cue) return;
  const inHand = placing(ui);
  const grab = grabRadius(ui, ev);
  const overCue = Math.hypot(p.x - cue.x, p.y - cue.y) <= grab;
  const takes = onStick(p, cue, ui.aim.phi, ui.R, grab, inHand);
  setGrabCursor(ui, takes || (inHand && overCue));
  if (takes || overCue || ui.aimHeld) return;
  ui.setAimToward(p);
}

/** Releases a stroke: a pull strikes (the stick pushed through, then
 *  the shot), none puts the speed back. */
export function endStroke(ui, cancelled) {
  const st = ui.stroke;
  if (!st) return;
  ui.stroke = null;
  try { ui.canvas.releasePointerCapture(st.id); } catch (e) { /* not captured */ }
  if (cancelled || st.pull < MIN_PULL || !ui.canAct()) {
    ui.aim.speed = st.speed0;
    ui.syncControls();
    ui.requestRender();
    return;
  }
  ui.aim.speed = speedFromPull(st.pull);
  ui.syncControls();
  ui.strike = { t0: performance.now(), pull: st.pull };
  ui.updatePanel();
  ui.requestRender();
}

function onDown(ui, ev) {
  if (!ui.table || (ev.pointerType === 'mouse' && ev.button !== 0)) return;
  if (!ui.canAct() || ui.stroke) return;
  ev.preventDefault();
  ui.canvas.focus({ preventScroll: true });
  const flow = ui.flow;
  const p = ui.view.toTable(ev.clientX, ev.clientY);
  const cue = ui.cuePos();
  const grab = grabRadius(ui, ev);
  const inHand = placing(ui);
  if (inHand && cue && Math.hypot(p.x - cue.x, p.y - cue.y) <= grab) {
    ui.drag = { kind: 'cue', id: ev.pointerId, dx: cue.x - p.x, dy: cue.y - p.y, x: cue.x, y: cue.y, ok: true, reason: '' };
    ui.canvas.classList.add('dragging');
    try { ui.canvas.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
    ui.requestRender();
    return;
  }
  if (!flow.shotDue()) return;
  // the drag-back stroke: a press on the cue ball or the stick takes the cue
  if (cue && onStick(p, cue, ui.aim.phi, ui.R, grab, inHand)) {
    ui.stroke = { id: ev.pointerId, from: p, pull: 0, speed0: ui.aim.speed };
    try { ui.canvas.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
    ui.requestRender();
    return;
  }
  // a click on a ball that may be nominated nominates it (and aims at
  // it, as any click does)
  if (flow.nominateDue()) {
    const b = flow.objectBalls().find((q) => flow.nominable(q.n) && Math.hypot(q.x - p.x, q.y - p.y) <= ui.R * 1.1);
    if (b) {
      flow.override.nominate = b.n;
      ui.updatePanel();
    }
  }
  // calls: a click on a pocket calls that pocket
  if (flow.callDue()) {
    const onBall = flow.objectBalls().some((b) => Math.hypot(b.x - p.x, b.y - p.y) <= ui.R * 1.1);
    if (!onBall) {
      const i = ui.table.pockets.findIndex((k) => Math.hypot(k.centre[0] - p.x, k.centre[1] - p.y) <= k.radius + ui.R);
      if (i >= 0) {
        flow.override.pocket = flow.override.pocket === i ? null : i;
        ui.updatePanel();
        ui.requestRender();
        return;
      }
    }
  }
  ui.drag = { kind: 'aim', id: ev.pointerId };
  ui.aimHeld = true;  // a press fixes the aim (Escape: follow the pointer again)
  ui.updatePanel();
  try { ui.canvas.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
  ui.setAimToward(p);
}

function onMove(ui, ev) {
  const st = ui.stroke;
  if (st && st.id === ev.pointerId) {
    ev.preventDefault();
    st.pull = strokePull(ui.aim.phi, st.from, ui.view.toTable(ev.clientX, ev.clientY));
    ui.aim.speed = st.pull >= MIN_PULL ? speedFromPull(st.pull) : st.speed0;
    ui.syncControls();
    ui.requestRender();
    return;
  }
  const d = ui.drag;
  if (!d) {
    onHover(ui, ev);
    return;
  }
  if (d.id !== ev.pointerId) return;
  ev.preventDefault();
  const p = ui.view.toTable(ev.clientX, ev.clientY);
  if (d.kind === 'aim') {
    ui.setAimToward(p);
    return;
  }
  dragTo(ui, d, p);
  ui.requestRender();
}

/** Moves the cue ball in hand being dragged to pointer p, and asks the
 *  engine whether it may go there. */
function dragTo(ui, d, p) {
  const t = ui.table;
  d.x = Math.max(-0.05, Math.min(t.length + 0.05, p.x + d.dx));
  d.y = Math.max(-0.05, Math.min(t.width + 0.05, p.y + d.dy));
  const r = ui.flow.checkPlacement(d.x, d.y);
  d.ok = r.ok;
  d.reason = r.reason;
}

function onUp(ui, ev, cancelled) {
  if (ui.stroke && ui.stroke.id === ev.pointerId) {
    if (!cancelled) ui.stroke.pull = strokePull(ui.aim.phi, ui.stroke.from, ui.view.toTable(ev.clientX, ev.clientY));
    endStroke(ui, cancelled);
    return;
  }
  const d = ui.drag;
  if (!d || d.id !== ev.pointerId) return;
  ui.drag = null;
  ui.canvas.classList.remove('dragging');
  try { ui.canvas.releasePointerCapture(ev.pointerId); } catch (e) { /* not captured */ }
  if (d.kind === 'cue' && !cancelled) {
    dragTo(ui, d, ui.view.toTable(ev.clientX, ev.clientY));
    if (d.ok) {
      ui.placePos = { x: d.x, y: d.y };
      ui.clearError();
    } else {
      ui.showError(`The cue ball cannot go there: ${d.reason}`);
    }
  }
  ui.updatePanel();
  ui.requestRender();
}

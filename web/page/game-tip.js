// The cue tip widget: a cue ball on which a press or a drag sets where
// the tip strikes (a: right of centre, b: above, in ball radii, within
// TIP_LIMIT of the centre); a double click centres it. tipWords is its
// reading in words ("follow 0.20, left 0.10").

import { drawBall } from './draw-ball.js';
import { $ } from './game-dom.js';

export const TIP_LIMIT = 0.48;   // largest tip offset the widget allows (miscue limit 0.5)

/** The tip offset of a point (dx, dy: from the widget's centre, in its
 *  radii, y down), limited to TIP_LIMIT and rounded to hundredths. */
export function tipOffset(dx, dy) {
  let a = dx;
  let b = -dy;
  const m = Math.hypot(a, b);
  if (m > TIP_LIMIT) {
    a *= TIP_LIMIT / m;
    b *= TIP_LIMIT / m;
  }
  return { a: Math.round(a * 100) / 100, b: Math.round(b * 100) / 100 };
}

export function tipWords({ a, b }) {
  if (Math.abs(a) < 0.005 && Math.abs(b) < 0.005) return 'centre';
  const parts = [];
  if (Math.abs(b) >= 0.005) parts.push(`${b > 0 ? 'follow' : 'draw'} ${Math.abs(b).toFixed(2)}`);
  if (Math.abs(a) >= 0.005) parts.push(`${a > 0 ? 'right' : 'left'} ${Math.abs(a).toFixed(2)}`);
  return parts.join(', ');
}

/** Wires the #tip canvas to `ui.aim` (ui.syncControls redraws it). */
export function bindTip(ui) {
  const c = $('tip');
  let down = null;
  const set = (ev) => {
    const r = c.getBoundingClientRect();
    const rad = (Math.min(r.width, r.height) / 2) * 0.9;
    const t = tipOffset((ev.clientX - (r.left + r.width / 2)) / rad, (ev.clientY - (r.top + r.height / 2)) / rad);
    ui.aim.a = t.a;
    ui.aim.b = t.b;
    ui.syncControls();
  };
  c.addEventListener('pointerdown', (ev) => {
    if (ev.pointerType === 'mouse' && ev.button !== 0) return;
    ev.preventDefault();
    down = ev.pointerId;
    try { c.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
    set(ev);
  });
  c.addEventListener('pointermove', (ev) => { if (down === ev.pointerId) set(ev); });
  const up = (ev) => {
    if (down !== ev.pointerId) return;
    down = null;
    try { c.releasePointerCapture(ev.pointerId); } catch (e) { /* not captured */ }
  };
  c.addEventListener('pointerup', up);
  c.addEventListener('pointercancel', up);
  c.addEventListener('dblclick', () => {
    ui.aim.a = 0;
    ui.aim.b = 0;
    ui.syncControls();
  });
  drawTip(ui.aim);
}

/** Draws the widget for the aim's tip offset. */
export function drawTip(aim) {
  const c = $('tip');
  if (!c) return;
  const dpr = Math.min(3, window.devicePixelRatio || 1);
  const size = 96;
  if (c.width !== Math.round(size * dpr)) {
    c.width = Math.round(size * dpr);
    c.height = Math.round(size * dpr);
  }
  const ctx = c.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, size, size);
  const cx = size / 2;
  const cy = size / 2;
  const r = (size / 2) * 0.9;
  drawBall(ctx, 0, cx, cy, r, { shadow: false });
  ctx.strokeStyle = 'rgba(0, 0, 0, 0.35)';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.moveTo(cx - r, cy);
  ctx.lineTo(cx + r, cy);
  ctx.moveTo(cx, cy - r);
  ctx.lineTo(cx, cy + r);
  ctx.stroke();
  ctx.setLineDash([3, 3]);
  ctx.strokeStyle = 'rgba(200, 40, 40, 0.55)';
  ctx.beginPath();
  ctx.arc(cx, cy, r * 0.5, 0, Math.PI * 2);
  ctx.stroke();
  ctx.setLineDash([]);
  const tx = cx + aim.a * r;
  const ty = cy - aim.b * r;
  ctx.fillStyle = '#2f6fc0';
  ctx.strokeStyle = '#0d2748';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.arc(tx, ty, r * 0.13, 0, Math.PI * 2);
  ctx.fill();
  ctx.stroke();
}

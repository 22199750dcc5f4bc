// The drawing of the lab's table canvas: the table, the balls, the traces,
// the velocity arrows of the setup, the momentum arrows of a run, and the
// strip at the right with the system momentum. Positions and momenta are
// the engine's (the run's frame), or the setup's for the setup.

import { fitCanvas } from './lab-dom.js';
import { niceCeil, fmtNum } from './lab-format.js';
import { FELT, RAIL, TOTAL_COLOUR, luminance } from './lab-colours.js';
import { tableVertices, bbox } from './lab-geometry.js';
import { radiusOf } from './lab-scenario.js';
import { TRACE_LIMIT } from './lab-run.js';
import { flightScale, flightLift, drawFlightShadow } from './draw-ball.js';

// A setup velocity arrow ends where the ball would be after this many seconds.
export const VEL_TAU = 0.25;
// Width (CSS px) of the strip right of the table with the system momentum.
const STRIP = 150;

// The world -> canvas transform that fits box bb in a w x h canvas, left
// of the strip: X(x), Y(y) in CSS pixels, s pixels per metre.
export function computeView(w, h, bb) {
  const pad = 22;
  const aw = Math.max(10, w - STRIP - 2 * pad), ah = Math.max(10, h - 2 * pad);
  const s = Math.min(aw / (bb.x1 - bb.x0), ah / (bb.y1 - bb.y0));
  const ox = pad + (aw - s * (bb.x1 - bb.x0)) / 2 - s * bb.x0;
  const oy = pad + (ah - s * (bb.y1 - bb.y0)) / 2 + s * bb.y1;
  return { s, ox, oy, X: (x) => ox + s * x, Y: (y) => oy - s * y };
}

// Sizes the table's canvas to the table's shape at CSS width cssW; returns
// its context, its size and the view (the transform the drawing and the
// pointer use).
export function layoutTable(canvas, cssW, setup) {
  const vs = tableVertices(setup.table);
  const bb = bbox(vs || setup.balls.map((b) => b.position || [0, 0]));
  const aspect = (bb.y1 - bb.y0) / (bb.x1 - bb.x0);
  const cssH = Math.max(240, Math.min(560, (cssW - STRIP - 44) * aspect + 44));
  const { ctx, w, h } = fitCanvas(canvas, cssW, cssH);
  return { ctx, w, h, view: computeView(w, h, bb) };
}

// Draws the table, the traces, the balls, the arrows and the strip.
// scene: {setup, run, colours, selected, showTraces, showArrows, drag,
// initialFrame}: the setup when run is null, else the run (lab-run.js).
export function drawTable(ctx, w, h, v, scene) {
  const { setup, run, colours, selected, showTraces, showArrows, drag } = scene;
  const vs = tableVertices(setup.table);
  ctx.clearRect(0, 0, w, h);
  ctx.fillStyle = RAIL;
  ctx.fillRect(0, 0, w, h);

  if (vs && vs.length >= 3) {
    ctx.beginPath();
    vs.forEach((p, k) => (k ? ctx.lineTo(v.X(p[0]), v.Y(p[1])) : ctx.moveTo(v.X(p[0]), v.Y(p[1]))));
    ctx.closePath();
    ctx.fillStyle = FELT;
    ctx.fill();
    ctx.lineWidth = 2;
    ctx.strokeStyle = '#c9d3da';
    ctx.lineJoin = 'round';
    ctx.stroke();
  }
  const inSetup = !run;
  if (inSetup && setup.table.shape === 'polygon' && vs) {
    ctx.fillStyle = '#ffffff';
    ctx.strokeStyle = '#222';
    ctx.lineWidth = 1;
    for (const p of vs) {
      ctx.beginPath();
      ctx.rect(v.X(p[0]) - 3.5, v.Y(p[1]) - 3.5, 7, 7);
      ctx.fill(); ctx.stroke();
    }
  }

  const n = run ? run.n : setup.balls.length;
  const radii = (run ? run.sc.balls : setup.balls).map(radiusOf);

  // traces
  if (run && run.traces && showTraces) {
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
    for (let i = 0; i < n; i++) {
      const tr = run.traces[i];
      if (tr.length < 4) continue;
      ctx.beginPath();
      ctx.moveTo(v.X(tr[0]), v.Y(tr[1]));
      for (let k = 2; k < tr.length; k += 2) ctx.lineTo(v.X(tr[k]), v.Y(tr[k + 1]));
      ctx.strokeStyle = colours[i];
      ctx.globalAlpha = 0.9;
      ctx.lineWidth = 1.6;
      ctx.stroke();
      ctx.globalAlpha = 1;
    }
  }

  // balls
  const pos = (i) => {
    if (run && run.frame) { const b = run.frame.balls[i]; return b[2] ? [b[0], b[1]] : null; }
    const p = setup.balls[i].position;
    return Array.isArray(p) && Number.isFinite(p[0]) && Number.isFinite(p[1]) ? p : null;
  };
  if (n > 200) {
    const groups = new Map();
    for (let i = 0; i < n; i++) {
      if (!groups.has(colours[i])) groups.set(colours[i], []);
      groups.get(colours[i]).push(i);
    }
    for (const [c, idx] of groups) {
      ctx.beginPath();
      for (const i of idx) {
        const p = pos(i);
        if (!p) continue;
        const x = v.X(p[0]), y = v.Y(p[1]), r = Math.max(1.2, radii[i] * v.s);
        ctx.moveTo(x + r, y);
        ctx.arc(x, y, r, 0, 2 * Math.PI);
      }
      ctx.fillStyle = c;
      ctx.fill();
    }
  } else {
    // A ball in flight (its z, the frame's b[8] when a ball is off the
    // cloth): its shadow on the cloth, then the ball drawn after the others
    // with the game's projection (draw.js: flightScale, flightLift).
    const zOf = (i) => (run && run.frame && run.frame.balls[i].length > 8 ? run.frame.balls[i][8] : 0);
    const order = [...Array(n).keys()].sort((a, b) => zOf(a) - zOf(b));
    for (const i of order) {
      const p = pos(i);
      if (p && zOf(i) > 0) drawFlightShadow(ctx, v.X(p[0]), v.Y(p[1]), Math.max(1.5, radii[i] * v.s), zOf(i));
    }
    for (const i of order) {
      const p = pos(i);
      if (!p) continue;
      const z = zOf(i);
      const x = v.X(p[0]), y = v.Y(p[1]) - flightLift(z) * v.s, r = Math.max(1.5, radii[i] * v.s) * flightScale(z);
      ctx.beginPath();
      ctx.arc(x, y, r, 0, 2 * Math.PI);
      ctx.fillStyle = colours[i];
      ctx.fill();
      ctx.lineWidth = i === selected && inSetup ? 2.5 : 1;
      ctx.strokeStyle = i === selected && inSetup ? '#ffe14d' : (luminance(colours[i]) < 0.2 ? '#d0d6db' : '#15191d');
      ctx.stroke();
    }
    if (n <= 12) {
      ctx.font = '11px system-ui, sans-serif';
      ctx.textBaseline = 'bottom';
      for (let i = 0; i < n; i++) {
        const p = pos(i);
        if (!p) continue;
        const r = Math.max(1.5, radii[i] * v.s);
        const label = String((run ? run.sc : setup).balls[i].id ?? i);
        const x = v.X(p[0]) + r * 0.75 + 2, y = v.Y(p[1]) - r * 0.75 - 1;
        ctx.lineWidth = 3;
        ctx.strokeStyle = 'rgba(0,0,0,0.6)';
        ctx.strokeText(label, x, y);
        ctx.fillStyle = '#ffffff';
        ctx.fillText(label, x, y);
      }
    }
  }

  // arrows
  if (showArrows) {
    if (inSetup) drawVelocityArrows(ctx, v, n, radii, scene);
    else drawMomentumArrows(ctx, v, n, radii, scene);
  }
  if (drag && drag.kind === 'velocity') drawVelocityArrow(ctx, v, setup.balls[drag.i], true);

  drawStrip(ctx, w, h, scene);
}

function arrow(ctx, x0, y0, x1, y1, colour, width, head) {
  const dx = x1 - x0, dy = y1 - y0;
  const L = Math.hypot(dx, dy);
  if (L < 0.5) return;
  const hl = Math.min(head, L * 0.6);
  const ux = dx / L, uy = dy / L;
  const bx = x1 - ux * hl, by = y1 - uy * hl;
  const path = () => {
    ctx.beginPath();
    ctx.moveTo(x0, y0);
    ctx.lineTo(bx, by);
    ctx.moveTo(x1, y1);
    ctx.lineTo(bx - uy * hl * 0.5, by + ux * hl * 0.5);
    ctx.lineTo(bx + uy * hl * 0.5, by - ux * hl * 0.5);
    ctx.closePath();
  };
  ctx.lineCap = 'round';
  ctx.lineJoin = 'round';
  path();
  ctx.lineWidth = width + 2.5;
  ctx.strokeStyle = luminance(colour) < 0.2 ? 'rgba(255,255,255,0.8)' : 'rgba(0,0,0,0.7)';
  ctx.stroke();
  ctx.fillStyle = ctx.strokeStyle;
  ctx.fill();
  path();
  ctx.lineWidth = width;
  ctx.strokeStyle = colour;
  ctx.stroke();
  ctx.fillStyle = colour;
  ctx.fill();
}

// A setup velocity arrow of ball b, in canvas pixels: [tip x, tip y, x, y].
export function velocityTip(v, b) {
  const p = b.position, vel = Array.isArray(b.velocity) ? b.velocity : [0, 0];
  if (!Array.isArray(p)) return null;
  return [v.X(p[0] + vel[0] * VEL_TAU), v.Y(p[1] + vel[1] * VEL_TAU), v.X(p[0]), v.Y(p[1])];
}

function drawVelocityArrow(ctx, v, b, active) {
  const tip = velocityTip(v, b);
  if (!tip) return;
  const [x1, y1, x0, y0] = tip;
  if (Math.hypot(x1 - x0, y1 - y0) < 0.5) return;
  ctx.save();
  ctx.setLineDash(active ? [] : [5, 3]);
  arrow(ctx, x0, y0, x1, y1, active ? '#ffe14d' : '#ffffff', active ? 2 : 1.5, 9);
  ctx.restore();
}

function drawVelocityArrows(ctx, v, n, radii, { setup, drag, selected }) {
  if (n <= 100) {
    for (let i = 0; i < n; i++) if (!(drag && drag.kind === 'velocity' && drag.i === i)) drawVelocityArrow(ctx, v, setup.balls[i], false);
  } else {
    ctx.beginPath();
    for (let i = 0; i < n; i++) {
      const b = setup.balls[i];
      if (!Array.isArray(b.position) || !Array.isArray(b.velocity)) continue;
      const sp = Math.hypot(b.velocity[0], b.velocity[1]);
      if (!(sp > 0)) continue;
      const L = Math.max(4, radii[i] * v.s * 2.5);
      const x = v.X(b.position[0]), y = v.Y(b.position[1]);
      ctx.moveTo(x, y);
      ctx.lineTo(x + (b.velocity[0] / sp) * L, y - (b.velocity[1] / sp) * L);
    }
    ctx.strokeStyle = 'rgba(255,255,255,0.7)';
    ctx.lineWidth = 1;
    ctx.stroke();
    if (selected >= 0 && selected < n) drawVelocityArrow(ctx, v, setup.balls[selected], false);
  }
}

function ballArrowLength(w, h) {
  return Math.max(40, Math.min(140, 0.2 * Math.min(w - STRIP, h)));
}

function drawMomentumArrows(ctx, v, n, radii, { run, colours }) {
  const f = run.frame;
  if (!f || !(run.pRef > 0)) return;
  const canvasW = ctx.canvas.width / (window.devicePixelRatio || 1), canvasH = ctx.canvas.height / (window.devicePixelRatio || 1);
  if (n <= TRACE_LIMIT) {
    const k = ballArrowLength(canvasW, canvasH) / run.pRef;   // px per kg m/s
    for (let i = 0; i < n; i++) {
      const b = f.balls[i];
      if (!b[2]) continue;
      const x = v.X(b[0]), y = v.Y(b[1]);
      arrow(ctx, x, y, x + b[6] * k, y - b[7] * k, colours[i], 2, 8);
    }
  } else {
    // Many balls: thin lines without heads, one path.
    ctx.beginPath();
    for (let i = 0; i < n; i++) {
      const b = f.balls[i];
      if (!b[2]) continue;
      const k = Math.max(5, radii[i] * v.s * 2.5) / run.pRef;
      const x = v.X(b[0]), y = v.Y(b[1]);
      ctx.moveTo(x, y);
      ctx.lineTo(x + b[6] * k, y - b[7] * k);
    }
    ctx.strokeStyle = 'rgba(255,255,255,0.75)';
    ctx.lineWidth = 1;
    ctx.stroke();
  }
}

// The strip right of the table: the system's momentum on a dial, and the scales.
function drawStrip(ctx, w, h, { run, initialFrame }) {
  const x0 = w - STRIP;
  ctx.fillStyle = '#1f2327';
  ctx.fillRect(x0, 0, STRIP, h);
  ctx.fillStyle = '#e8ecef';
  ctx.font = '600 12px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.textAlign = 'center';
  const cx = x0 + STRIP / 2;
  ctx.fillText('system momentum', cx, 10);
  const R = Math.min(52, (STRIP - 24) / 2, (h - 110) / 2);
  const cy = 30 + R + 6;
  ctx.strokeStyle = '#59626b';
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.arc(cx, cy, R, 0, 2 * Math.PI);
  ctx.moveTo(cx - R, cy); ctx.lineTo(cx + R, cy);
  ctx.moveTo(cx, cy - R); ctx.lineTo(cx, cy + R);
  ctx.stroke();
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillStyle = '#aab3bb';
  const f = run ? run.frame : initialFrame;
  const lines = [];
  let barLength = 0;
  if (f) {
    const P = f.momentum;
    let ref = run ? run.pSys : 0;
    if (!run) {
      let m = 0;
      for (const b of f.balls) m = Math.max(m, Math.hypot(b[6], b[7]));
      ref = Math.max(niceCeil(Math.max(m, Math.hypot(P[0], P[1]))), 0);
    }
    if (ref > 0) {
      const k = R / ref;
      arrow(ctx, cx, cy, cx + P[0] * k, cy - P[1] * k, TOTAL_COLOUR, 2.5, 10);
      lines.push(`circle: ${fmtNum(ref, 3)} kg·m/s`);
    }
    lines.push(`px ${fmtNum(P[0], 4)}`, `py ${fmtNum(P[1], 4)}`);
  } else {
    lines.push('(no valid setup)');
  }
  if (run && run.pRef > 0) {
    const L = run.n <= TRACE_LIMIT ? ballArrowLength(w, h) : null;
    lines.push('', 'ball arrows: momentum');
    lines.push(L ? `${Math.round(L)} px = ${fmtNum(run.pRef, 3)} kg·m/s` : `scaled to ball size`);
    if (L) barLength = Math.min(L, STRIP - 16);
  } else if (!run) {
    lines.push('', 'arrows on the table:', 'velocity (setup)', `tip = position after ${VEL_TAU} s`);
  }
  let y = cy + R + 10;
  for (const s of lines) { ctx.fillText(s, cx, y); y += 14; }
  if (barLength) {
    ctx.strokeStyle = '#cfd6dc';
    ctx.lineWidth = 2;
    const by = y + 4, bx = cx - barLength / 2;
    ctx.beginPath();
    ctx.moveTo(bx, by); ctx.lineTo(bx + barLength, by);
    ctx.moveTo(bx, by - 4); ctx.lineTo(bx, by + 4);
    ctx.moveTo(bx + barLength, by - 4); ctx.lineTo(bx + barLength, by + 4);
    ctx.stroke();
  }
  ctx.textAlign = 'left';
}

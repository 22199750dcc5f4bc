// The lab's energy graph: the kinetic energy of each ball (up to
// TRACE_LIMIT balls) and the total against time, from the run's history of
// engine frames; in the setup, the energies at t = 0 as dots.

import { fitCanvas } from './lab-dom.js';
import { niceAxis, niceStep, prefixFor, tickLabel } from './lab-format.js';
import { FELT, TOTAL_COLOUR, GRAPH_BG, luminance } from './lab-colours.js';
import { untilOf } from './lab-scenario.js';
import { TRACE_LIMIT } from './lab-run.js';

// Draws the graph on `canvas`, cssW CSS pixels wide (nothing when 0).
// scene: {setup, run, colours, initialFrame}: the run's history when there
// is a run (lab-run.js), else the setup's energies at t = 0.
export function drawEnergy(canvas, cssW, { setup, run, colours, initialFrame }) {
  if (!cssW) return;
  const { ctx, w, h } = fitCanvas(canvas, cssW, 270);
  ctx.clearRect(0, 0, w, h);
  ctx.fillStyle = GRAPH_BG;
  ctx.fillRect(0, 0, w, h);

  const sc = run ? run.sc : setup;
  const n = sc.balls.length;
  const perBall = n <= TRACE_LIMIT;
  const f0 = run ? null : initialFrame;

  // Legend (wrapping rows at the top).
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'middle';
  const entries = [];
  if (perBall) for (let i = 0; i < n; i++) entries.push({ label: String(sc.balls[i].id ?? i), colour: colours[i], width: 2 });
  entries.push({ label: 'total', colour: TOTAL_COLOUR, width: 3.5 });
  let lx = 48, ly = 10;
  const rowsY = [];
  for (const e of entries) {
    const tw = ctx.measureText(e.label).width + 30;
    if (lx + tw > w - 8) { lx = 48; ly += 16; }
    e.x = lx; e.y = ly;
    lx += tw + 6;
    rowsY.push(ly);
  }
  for (const e of entries) {
    drawLineSample(ctx, e.x, e.y, e.colour, e.width);
    ctx.fillStyle = '#dfe4e8';
    ctx.fillText(e.label, e.x + 24, e.y);
  }
  if (!perBall) {
    ctx.fillStyle = '#9aa5b1';
    ctx.fillText(`(${n} balls: per-ball lines only up to ${TRACE_LIMIT})`, lx, ly);
  }

  // Ball ids at the ends of their lines, when there are few.
  const endLabels = run && perBall && n <= 8;
  let labelW = 0;
  if (endLabels) {
    ctx.font = '11px system-ui, sans-serif';
    labelW = ctx.measureText('total').width;
    for (let i = 0; i < n; i++) labelW = Math.max(labelW, ctx.measureText(String(sc.balls[i].id ?? i)).width);
  }
  const top = ly + 16, left = 62, right = endLabels ? Math.min(96, labelW + 14) : 14, bottom = 40;
  const pw = w - left - right, ph = h - top - bottom;
  if (pw < 20 || ph < 20) return;

  const { T } = untilOf(sc);
  const tNow = run ? run.t : 0;
  const tMax = T != null ? T : niceAxis(Math.max(tNow, 1e-9) * 1.05);
  let eMax = run ? run.eMax : f0 ? f0.energy : 0;
  if (f0) for (const b of f0.balls) eMax = Math.max(eMax, b[5]);
  const yMax = niceAxis(eMax > 0 ? eMax * 1.05 : 1);

  const [tf, tp] = prefixFor(tMax);
  const [ef, ep] = prefixFor(yMax);
  const X = (t) => left + (t / tMax) * pw;
  const Y = (e) => top + ph - (e / yMax) * ph;

  // plot area (the felt's colour, where white and black lines both show), grid and ticks
  ctx.fillStyle = FELT;
  ctx.fillRect(left, top, pw, ph);
  ctx.strokeStyle = 'rgba(255,255,255,0.12)';
  ctx.lineWidth = 1;
  ctx.fillStyle = '#b7c0c8';
  const xs = niceStep(tMax, Math.max(2, Math.floor(pw / 70)));
  const ys = niceStep(yMax, Math.max(2, Math.floor(ph / 40)));
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  for (let k = 0; k * xs <= tMax * (1 + 1e-9); k++) {
    const t = k * xs, x = X(t);
    ctx.beginPath(); ctx.moveTo(x + 0.5, top); ctx.lineTo(x + 0.5, top + ph); ctx.stroke();
    ctx.fillText(tickLabel(t / tf, xs / tf), x, top + ph + 4);
  }
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (let k = 0; k * ys <= yMax * (1 + 1e-9); k++) {
    const e = k * ys, y = Y(e);
    ctx.beginPath(); ctx.moveTo(left, y + 0.5); ctx.lineTo(left + pw, y + 0.5); ctx.stroke();
    ctx.fillText(tickLabel(e / ef, ys / ef), left - 5, y);
  }
  ctx.strokeStyle = '#7d8893';
  ctx.beginPath();
  ctx.moveTo(left + 0.5, top); ctx.lineTo(left + 0.5, top + ph + 0.5); ctx.lineTo(left + pw, top + ph + 0.5);
  ctx.stroke();
  ctx.fillStyle = '#dfe4e8';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  ctx.font = '12px system-ui, sans-serif';
  ctx.fillText(`time (${tp}s)`, left + pw / 2, h - 4);
  ctx.save();
  ctx.translate(13, top + ph / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textBaseline = 'middle';
  ctx.fillText(`kinetic energy (${ep}J)`, 0, 0);
  ctx.restore();

  ctx.save();
  ctx.beginPath();
  ctx.rect(left, top - 2, pw + 2, ph + 4);
  ctx.clip();
  if (run) {
    const h0 = run.hist;
    if (h0.e) for (let i = 0; i < n; i++) plotLine(ctx, h0.t, h0.e[i], X, Y, colours[i], 2);
    plotLine(ctx, h0.t, h0.E, X, Y, TOTAL_COLOUR, 3.5);
    ctx.strokeStyle = 'rgba(255,255,255,0.3)';
    ctx.setLineDash([3, 3]);
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(X(run.t) + 0.5, top); ctx.lineTo(X(run.t) + 0.5, top + ph);
    ctx.stroke();
    ctx.setLineDash([]);
  } else if (f0) {
    // The setup: the energies at t = 0 as dots.
    const dot = (e, c, r) => {
      ctx.beginPath(); ctx.arc(X(0) + 1, Y(e), r, 0, 2 * Math.PI);
      ctx.fillStyle = c; ctx.fill(); ctx.strokeStyle = '#dfe4e8'; ctx.lineWidth = 1; ctx.stroke();
    };
    if (perBall) f0.balls.forEach((b, i) => dot(b[5], colours[i], 3.5));
    dot(f0.energy, TOTAL_COLOUR, 4.5);
  }
  ctx.restore();
  if (endLabels && run.hist.t.length) {
    const k = run.hist.t.length - 1;
    const xs0 = X(run.hist.t[k]) + 5;
    const items = [];
    for (let i = 0; i < n; i++) items.push({ y: Y(run.hist.e[i][k]), text: String(sc.balls[i].id ?? i), colour: colours[i] });
    items.push({ y: Y(run.hist.E[k]), text: 'total', colour: TOTAL_COLOUR });
    items.sort((a, b) => a.y - b.y);
    for (let j = 1; j < items.length; j++) items[j].y = Math.max(items[j].y, items[j - 1].y + 11);
    const over = items.length ? items[items.length - 1].y - (top + ph) : 0;
    if (over > 0) for (const it of items) it.y -= over;
    ctx.font = '11px system-ui, sans-serif';
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    for (const it of items) {
      ctx.lineWidth = 3;
      ctx.strokeStyle = 'rgba(20,24,28,0.85)';
      ctx.strokeText(it.text, xs0, it.y);
      ctx.fillStyle = luminance(it.colour) < 0.03 ? '#c9d1d8' : it.colour;
      ctx.fillText(it.text, xs0, it.y);
    }
  }
  if (!run) {
    ctx.fillStyle = '#d5dce2';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.font = '13px system-ui, sans-serif';
    ctx.fillText('Run to plot the kinetic energy against time', left + pw / 2, top + ph / 2);
  }
  ctx.textAlign = 'left';
}

function drawLineSample(ctx, x, y, colour, width) {
  if (luminance(colour) < 0.03) {
    ctx.strokeStyle = FELT;
    ctx.lineWidth = width + 4;
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 20, y); ctx.stroke();
  }
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 20, y); ctx.stroke();
}

// A polyline of (t, e), thinned to at most four points per pixel column
// (first, lowest, highest, last) so long histories draw fast and jumps stay sharp.
function plotLine(ctx, ts, es, X, Y, colour, width) {
  const m = ts.length;
  if (m === 0) return;
  ctx.beginPath();
  let col = null, first = 0, lo = 0, hi = 0, last = 0, started = false;
  const flush = () => {
    const x = col;
    const pts = [first, lo, hi, last].sort((a, b) => a - b);
    let prev = -1;
    for (const k of pts) {
      if (k === prev) continue;
      prev = k;
      const px = X(ts[k]), py = Y(es[k]);
      if (!started) { ctx.moveTo(px, py); started = true; } else ctx.lineTo(px, py);
    }
    return x;
  };
  for (let k = 0; k < m; k++) {
    const c = Math.floor(X(ts[k]));
    if (c !== col) {
      if (col !== null) flush();
      col = c; first = lo = hi = last = k;
    } else {
      if (es[k] < es[lo]) lo = k;
      if (es[k] > es[hi]) hi = k;
      last = k;
    }
  }
  flush();
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.stroke();
}

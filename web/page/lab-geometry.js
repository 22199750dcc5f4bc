// The lab's plane geometry: of the drawing and of placing a new ball,
// never of the motion (the engine computes that).

import { roundSig } from './lab-format.js';

// A box's or a polygon's corners, or null for any other table.
export function tableVertices(table) {
  if (!table) return null;
  if (table.shape === 'rectangle' && Array.isArray(table.min) && Array.isArray(table.max)) {
    const [x0, y0] = table.min, [x1, y1] = table.max;
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
  }
  if (table.shape === 'polygon' && Array.isArray(table.vertices)) return table.vertices;
  return null;
}

// The bounding box of points, at least 1 m wide and high when they are not.
export function bbox(pts) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const p of pts) {
    if (!Array.isArray(p) || !Number.isFinite(p[0]) || !Number.isFinite(p[1])) continue;
    x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
    y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
  }
  if (!(x1 > x0)) { x0 = Number.isFinite(x0) ? x0 - 0.5 : -0.5; x1 = x0 + 1; }
  if (!(y1 > y0)) { y0 = Number.isFinite(y0) ? y0 - 0.5 : -0.5; y1 = y0 + 1; }
  return { x0, y0, x1, y1 };
}

function insidePolygon(x, y, vs) {
  let inside = false;
  for (let i = 0, j = vs.length - 1; i < vs.length; j = i++) {
    const [xi, yi] = vs[i], [xj, yj] = vs[j];
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

function segDist(x, y, a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1];
  const l2 = dx * dx + dy * dy;
  let t = l2 > 0 ? ((x - a[0]) * dx + (y - a[1]) * dy) / l2 : 0;
  t = Math.max(0, Math.min(1, t));
  return Math.hypot(x - a[0] - t * dx, y - a[1] - t * dy);
}

// Whether a disk of radius r at (x, y) lies inside polygon vs.
export function fits(x, y, r, vs) {
  if (!insidePolygon(x, y, vs)) return false;
  for (let k = 0; k < vs.length; k++) if (segDist(x, y, vs[k], vs[(k + 1) % vs.length]) < r) return false;
  return true;
}

export function regularPolygon(n, r, phase) {
  const out = [];
  for (let k = 0; k < n; k++) {
    const a = phase + (2 * Math.PI * k) / n;
    out.push([roundSig(r * Math.cos(a), 4) + 0, roundSig(r * Math.sin(a), 4) + 0]);
  }
  return out;
}

// The step (a power of ten) a dragged or placed coordinate is rounded to.
export function posStep(bb) {
  const size = Math.max(bb.x1 - bb.x0, bb.y1 - bb.y0);
  return 10 ** Math.floor(Math.log10(size / 2000));
}

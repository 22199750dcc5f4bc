// The aim's geometry: where the cue ball sent along the aim first meets
// a ball or a cushion, the ghost ball, and the directions the two balls
// leave in. A ray cast for drawing only (the engine decides what the shot
// does); no DOM, so node imports it for the unit tests.

/**
 * Where a cue ball at `cue` sent along `phi` degrees first touches a ball
 * of `balls` ([{n, x, y}], the cue ball excluded) or, failing that, where
 * its centre reaches a cushion (the noses inset by R). Geometry for
 * drawing the aim only.
 */
export function aimGeometry(table, cue, phi, balls, R) {
  const rad = (phi * Math.PI) / 180;
  const dx = Math.cos(rad);
  const dy = Math.sin(rad);
  let best = Infinity;
  let hit = null;
  for (const b of balls) {
    const fx = cue.x - b.x;
    const fy = cue.y - b.y;
    const B = fx * dx + fy * dy;
    const C = fx * fx + fy * fy - 4 * R * R;
    const disc = B * B - C;
    if (disc < 0) continue;
    const t = -B - Math.sqrt(disc);
    if (t > 1e-9 && t < best) {
      best = t;
      hit = b;
    }
  }
  // the cushions, as a rectangle inset by R
  let tw = Infinity;
  let wallNormal = null;
  const lo = [R, R];
  const hi = [table.length - R, table.width - R];
  if (dx > 1e-12) { const t = (hi[0] - cue.x) / dx; if (t < tw) { tw = t; wallNormal = [-1, 0]; } }
  if (dx < -1e-12) { const t = (lo[0] - cue.x) / dx; if (t < tw) { tw = t; wallNormal = [1, 0]; } }
  if (dy > 1e-12) { const t = (hi[1] - cue.y) / dy; if (t < tw) { tw = t; wallNormal = [0, -1]; } }
  if (dy < -1e-12) { const t = (lo[1] - cue.y) / dy; if (t < tw) { tw = t; wallNormal = [0, 1]; } }
  tw = Math.max(0, tw);
  const out = { dir: { x: dx, y: dy }, hit: null };
  if (hit && best <= tw + 1e-12) {
    const gx = cue.x + best * dx;
    const gy = cue.y + best * dy;
    let nx = hit.x - gx;
    let ny = hit.y - gy;
    const nl = Math.hypot(nx, ny) || 1;
    nx /= nl;
    ny /= nl;
    const cosCut = Math.max(0, Math.min(1, dx * nx + dy * ny));
    // the cue ball leaves along the tangent line (stun shot)
    let tx = dx - cosCut * nx;
    let ty = dy - cosCut * ny;
    const tl = Math.hypot(tx, ty);
    if (tl > 1e-9) { tx /= tl; ty /= tl; } else { tx = 0; ty = 0; }
    out.hit = hit;
    out.ghost = { x: gx, y: gy };
    out.objectDir = { x: nx, y: ny };
    out.cueDir = { x: tx, y: ty };
    out.cosCut = cosCut;
    out.end = { x: gx, y: gy };
  } else {
    out.end = { x: cue.x + tw * dx, y: cue.y + tw * dy };
    if (wallNormal) {
      const d = dx * wallNormal[0] + dy * wallNormal[1];
      out.bounce = { x: dx - 2 * d * wallNormal[0], y: dy - 2 * d * wallNormal[1] };
    }
  }
  return out;
}

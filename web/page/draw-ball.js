// A ball on a canvas: the flat sprite (drawBall, every game's balls,
// the tray and the tip widget), the pool balls that roll (an orientation
// per ball turned by the engine's spins, painted pixel by pixel) and the
// projection of balls in flight. Drawing only: no physics.

import { ballColour, caromColour, snookerColour } from './draw-colours.js';

// Balls in flight (physics.airborne) as seen by a camera above the
// table: a ball whose centre is z above its resting height is drawn
// flightScale(z) = 1 + z / CAMERA_HEIGHT times larger (a pinhole camera
// CAMERA_HEIGHT above the resting centres sees a size H / (H - z); this is
// its first-order form, and it never blows up), and lifted up the screen by
// flightLift(z) = TILT * z (a camera tilted toward the player, so that
// height reads as a shift as well as a size). Its shadow stays on the cloth
// under its ground position, softer and fainter the higher the ball. The
// cue drawn at an elevation uses the same projection.
export const CAMERA_HEIGHT = 1.0;  // m
export const TILT = 0.5;           // screen shift per metre of height

export function flightScale(z) {
  return 1 + Math.max(0, z) / CAMERA_HEIGHT;
}

export function flightLift(z) {
  return TILT * Math.max(0, z);
}

/** A soft round shadow of radius r at (cx, cy) for a ball z above the cloth. */
export function drawFlightShadow(ctx, cx, cy, r, z) {
  const h = Math.max(0, z);
  const rr = r * (1.1 + h / 0.25);         // wider the higher it flies
  const alpha = 0.55 / (1 + h / 0.15);     // and fainter
  const g = ctx.createRadialGradient(cx, cy, 0, cx, cy, rr);
  g.addColorStop(0, `rgba(0, 0, 0, ${alpha.toFixed(3)})`);
  g.addColorStop(0.55, `rgba(0, 0, 0, ${(alpha * 0.6).toFixed(3)})`);
  g.addColorStop(1, 'rgba(0, 0, 0, 0)');
  ctx.save();
  ctx.fillStyle = g;
  ctx.beginPath();
  ctx.arc(cx, cy, rr, 0, Math.PI * 2);
  ctx.fill();
  ctx.restore();
}

/** Draws ball n at (cx, cy) in the current canvas units with radius r. */
export function drawBall(ctx, n, cx, cy, r, opts = {}) {
  const alpha = opts.alpha ?? 1;
  ctx.save();
  ctx.globalAlpha = alpha;
  if (opts.shadow !== false) {
    ctx.fillStyle = 'rgba(0, 0, 0, 0.32)';
    ctx.beginPath();
    ctx.ellipse(cx + r * 0.16, cy + r * 0.2, r * 1.02, r * 0.98, 0, 0, Math.PI * 2);
    ctx.fill();
  }
  ctx.beginPath();
  ctx.arc(cx, cy, r, 0, Math.PI * 2);
  ctx.save();
  ctx.clip();
  // snooker and carom balls: plain colours, no numbers
  const plain = !!opts.snooker || !!opts.carom;
  const stripe = !plain && n >= 9;
  const plainColour = opts.carom ? caromColour(n) : snookerColour(n);
  ctx.fillStyle = stripe ? '#f6f3ea' : (opts.colour || (plain ? plainColour : ballColour(n)));
  ctx.fillRect(cx - r, cy - r, 2 * r, 2 * r);
  if (stripe) {
    ctx.fillStyle = ballColour(n);
    ctx.fillRect(cx - r, cy - r * 0.56, 2 * r, r * 1.12);
  }
  if (n > 0 && !plain) {
    const nr = r * 0.5;
    ctx.fillStyle = '#fbfaf5';
    ctx.beginPath();
    ctx.arc(cx, cy, nr, 0, Math.PI * 2);
    ctx.fill();
    if (r >= 5) {
      ctx.fillStyle = '#111';
      const size = r * (n >= 10 ? 0.58 : 0.66);
      ctx.font = `700 ${size.toFixed(2)}px system-ui, -apple-system, "Segoe UI", Arial, sans-serif`;
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.fillText(String(n), cx, cy + size * 0.06);
    }
  }
  // shading: a highlight up and to the left, darker toward the lower right
  const g = ctx.createRadialGradient(cx - r * 0.38, cy - r * 0.42, r * 0.05, cx, cy, r * 1.05);
  g.addColorStop(0, 'rgba(255, 255, 255, 0.55)');
  g.addColorStop(0.25, 'rgba(255, 255, 255, 0.08)');
  g.addColorStop(0.7, 'rgba(0, 0, 0, 0.0)');
  g.addColorStop(1, 'rgba(0, 0, 0, 0.38)');
  ctx.fillStyle = g;
  ctx.fillRect(cx - r, cy - r, 2 * r, 2 * r);
  ctx.restore();
  if (opts.ring) {
    ctx.strokeStyle = opts.ring;
    ctx.lineWidth = Math.max(1.5, r * 0.16);
    ctx.beginPath();
    ctx.arc(cx, cy, r + ctx.lineWidth, 0, Math.PI * 2);
    ctx.stroke();
  }
  ctx.restore();
}

// ---- balls that roll ----
//
// A pool ball's markings (its stripe, its two number discs) turn with the
// ball: the page keeps each ball's orientation, a rotation matrix from the
// ball's own axes to the table's (x along the length, y across, z up),
// integrated from the engine's spins (rotate), and paints the ball pixel
// by pixel: each visible point of the sphere is taken back to the ball's
// axes, where the stripe is the band |y| < STRIPE and the number discs
// the caps around +z and -z. Drawing only.

const STRIPE = 0.56;                 // half width of a stripe's band (ball radii)
const CAP = 0.5;                     // radius of a number disc, seen face on
const CAP_COS = Math.sqrt(1 - CAP * CAP);
const GLYPH = 48;                    // glyph texture size (px)

/** A fresh orientation: the identity (numbers up, stripes across). */
export function identityOrientation() {
  return { m: new Float64Array([1, 0, 0, 0, 1, 0, 0, 0, 1]), v: 0 };
}

/** Turns orientation `o` by the spin w = [wx, wy, wz] (rad/s, table
 *  axes) for dt seconds: m <- R(w dt) m (Rodrigues), re-orthonormalised. */
export function rotate(o, wx, wy, wz, dt) {
  const w = Math.hypot(wx, wy, wz);
  const ang = w * dt;
  if (!(ang > 1e-9) || !Number.isFinite(ang)) return;
  const x = wx / w;
  const y = wy / w;
  const z = wz / w;
  const c = Math.cos(ang);
  const s = Math.sin(ang);
  const k = 1 - c;
  const r = [c + x * x * k, x * y * k - z * s, x * z * k + y * s,
    y * x * k + z * s, c + y * y * k, y * z * k - x * s,
    z * x * k - y * s, z * y * k + x * s, c + z * z * k];
  const m = o.m;
  const out = new Float64Array(9);
  for (let i = 0; i < 3; i++) {
    for (let j = 0; j < 3; j++) out[3 * i + j] = r[3 * i] * m[j] + r[3 * i + 1] * m[3 + j] + r[3 * i + 2] * m[6 + j];
  }
  // columns stay orthonormal (Gram-Schmidt on the first two, the third their cross product)
  let n0 = Math.hypot(out[0], out[3], out[6]);
  out[0] /= n0; out[3] /= n0; out[6] /= n0;
  const d = out[0] * out[1] + out[3] * out[4] + out[6] * out[7];
  out[1] -= d * out[0]; out[4] -= d * out[3]; out[7] -= d * out[6];
  n0 = Math.hypot(out[1], out[4], out[7]);
  out[1] /= n0; out[4] /= n0; out[7] /= n0;
  out[2] = out[3] * out[7] - out[6] * out[4];
  out[5] = out[6] * out[1] - out[0] * out[7];
  out[8] = out[0] * out[4] - out[3] * out[1];
  o.m = out;
  o.v += 1;
}

function rgbOf(hex) {
  const h = hex.replace('#', '');
  return [parseInt(h.slice(0, 2), 16), parseInt(h.slice(2, 4), 16), parseInt(h.slice(4, 6), 16)];
}

const glyphs = new Map();
/** Ball n's number disc as pixels (GLYPH x GLYPH, the disc filling it). */
function glyph(n) {
  let g = glyphs.get(n);
  if (g) return g;
  const c = document.createElement('canvas');
  c.width = GLYPH;
  c.height = GLYPH;
  const ctx = c.getContext('2d');
  ctx.fillStyle = '#fbfaf5';
  ctx.fillRect(0, 0, GLYPH, GLYPH);
  ctx.fillStyle = '#111';
  // as drawBall writes it: the number's size over the disc's radius
  const size = (GLYPH / 2) * (n >= 10 ? 0.58 : 0.66) / CAP;
  ctx.font = `700 ${size.toFixed(1)}px system-ui, -apple-system, "Segoe UI", Arial, sans-serif`;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText(String(n), GLYPH / 2, GLYPH / 2 + size * 0.06);
  g = ctx.getImageData(0, 0, GLYPH, GLYPH).data;
  glyphs.set(n, g);
  return g;
}

/**
 * Paints pool ball n (1-15) turned by orientation m onto a new canvas of
 * side 2 rd + 2 device pixels (rd: the radius in device pixels), lit from
 * `light` (a unit vector in the drawing's axes: x right, y down, z toward
 * the viewer); `upright`: the numbers printed for a table drawn turned
 * (TableView.fit's portrait).
 */
export function paintRollingBall(n, m, rd, light, canvas, upright = false) {
  const size = 2 * Math.ceil(rd) + 2;
  const c = canvas || document.createElement('canvas');
  if (c.width !== size) { c.width = size; c.height = size; }
  const ctx = c.getContext('2d');
  // the pixels are kept with the canvas: a new ImageData per ball and
  // frame would be garbage for the collector
  let img = c.bsPixels;
  if (!img || img.width !== size) {
    img = ctx.createImageData(size, size);
    c.bsPixels = img;
  }
  const d = img.data;
  const base = rgbOf(ballColour(n));
  const white = [246, 243, 234];
  const stripe = n >= 9;
  const tex = glyph(n);
  const [lx, ly, lz] = light;
  let hx = lx;
  let hy = ly;
  let hz = lz + 1;
  const hl = Math.hypot(hx, hy, hz);
  hx /= hl; hy /= hl; hz /= hl;
  const ctr = size / 2;
  for (let py = 0; py < size; py++) {
    for (let px = 0; px < size; px++) {
      const X0 = (px + 0.5 - ctr) / rd;
      const Y0 = (py + 0.5 - ctr) / rd;
      const dist = Math.hypot(X0, Y0);
      const cover = Math.max(0, Math.min(1, (1 - dist) * rd + 0.5));
      if (cover <= 0) {
        d[4 * (py * size + px) + 3] = 0;
        continue;
      }
      let X = X0;
      let Y = Y0;
      if (dist > 0.999) { X /= dist / 0.999; Y /= dist / 0.999; }
      const Z = Math.sqrt(Math.max(0, 1 - X * X - Y * Y));
      // the point in the table's axes (x right, y up, z up out of the cloth),
      // then in the ball's: p_b = m^T p
      const tx = X;
      const ty = -Y;
      const bx = m[0] * tx + m[3] * ty + m[6] * Z;
      const by = m[1] * tx + m[4] * ty + m[7] * Z;
      const bz = m[2] * tx + m[5] * ty + m[8] * Z;
      let col;
      if (bz > CAP_COS || bz < -CAP_COS) {
        // a number disc: the glyph, read from outside the ball on either side
        // (upright: printed a quarter turn round, so that a ball at the
        // identity reads upright on a table turned for a portrait screen)
        const u0 = upright ? -by / CAP : bx / CAP;
        const u = bz > 0 ? u0 : -u0;
        const v = upright ? -bx / CAP : -by / CAP;
        const gx = Math.max(0, Math.min(GLYPH - 1, Math.floor((u + 1) * 0.5 * GLYPH)));
        const gy = Math.max(0, Math.min(GLYPH - 1, Math.floor((v + 1) * 0.5 * GLYPH)));
        const k = 4 * (gy * GLYPH + gx);
        col = [tex[k], tex[k + 1], tex[k + 2]];
      } else if (stripe) {
        col = Math.abs(by) < STRIPE ? base : white;
      } else {
        col = base;
      }
      const diff = Math.max(0, X * lx + Y * ly + Z * lz);
      const shade = 0.42 + 0.62 * diff;
      const spec = Math.pow(Math.max(0, X * hx + Y * hy + Z * hz), 36) * 190;
      const k = 4 * (py * size + px);
      d[k] = Math.min(255, col[0] * shade + spec);
      d[k + 1] = Math.min(255, col[1] * shade + spec);
      d[k + 2] = Math.min(255, col[2] * shade + spec);
      d[k + 3] = 255 * cover;
    }
  }
  ctx.putImageData(img, 0, 0);
  return c;
}

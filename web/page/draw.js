// Drawing the pool table and the balls on a canvas, to scale from the
// engine's table geometry (E.newGame(...).table()). Pure drawing: no
// physics. Table coordinates: metres, x along the length, y along the
// width, origin at the lower-left corner of the playing surface at the
// cushion noses. On screen x runs to the right and y up, so angles
// counter-clockwise from +x look counter-clockwise. The table view
// only: the balls are draw-ball.js's, the colours draw-colours.js's, the
// aim's ray cast draw-aim.js's.

import { drawBall, drawFlightShadow, flightLift, flightScale, paintRollingBall } from './draw-ball.js';

const FRAME = 0.165;      // cushion nose to the outer edge of the wooden rail (m)
const CUSHION = 0.048;    // cushion nose to the wood (m)
const DIAMOND = 0.011;    // half diagonal of a rail diamond (m)

export class TableView {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.table = null;
    this.cssW = 0;
    this.cssH = 0;
    this.dpr = 1;
    this.scale = 1;
    this.staticLayer = null;
    this.rolled = new Map();   // ball n -> {key, canvas}: its last painting
  }

  /** Draws pool ball n (1-15) turned by orientation o ({m, v}) at (cx, cy),
   *  radius r (CSS px), with its drop shadow; opts as drawBall's. */
  drawRolling(ctx, n, o, cx, cy, r, opts = {}) {
    const rd = r * this.dpr;
    const light = this.light();
    const key = `${o.v}|${rd.toFixed(2)}|${light.join(',')}`;
    let cached = this.rolled.get(n);
    if (!cached || cached.key !== key || cached.o !== o) {
      const canvas = paintRollingBall(n, o.m, rd, light, cached ? cached.canvas : null, !!this.rot);
      cached = { key, o, canvas };
      this.rolled.set(n, cached);
    }
    ctx.save();
    ctx.globalAlpha = opts.alpha ?? 1;
    if (opts.shadow !== false) {
      ctx.fillStyle = 'rgba(0, 0, 0, 0.32)';
      ctx.beginPath();
      ctx.ellipse(cx + r * 0.16, cy + r * 0.2, r * 1.02, r * 0.98, 0, 0, Math.PI * 2);
      ctx.fill();
    }
    const side = cached.canvas.width / this.dpr;
    ctx.drawImage(cached.canvas, cx - side / 2, cy - side / 2, side, side);
    if (opts.ring) {
      ctx.strokeStyle = opts.ring;
      ctx.lineWidth = Math.max(1.5, r * 0.16);
      ctx.beginPath();
      ctx.arc(cx, cy, r + ctx.lineWidth, 0, Math.PI * 2);
      ctx.stroke();
    }
    ctx.restore();
    this.painted = (this.painted || 0) + 1;
  }

  /** The light on the balls, in the drawing's axes: from the screen's upper left. */
  light() {
    // turned with the drawing when the table is turned
    return this.rot ? [0.48, -0.42, 0.77] : [-0.42, -0.48, 0.77];
  }

  setTable(table) {
    this.table = table;
    this.staticLayer = null;
    // the snooker table's markings (bs_web_game_table's "snooker"), or null
    this.snooker = table && table.snooker ? table.snooker : null;
    // the carom table's markings (bs_web_game_table's "carom"), or null
    this.carom = table && table.carom ? table.carom : null;
  }

  /** Width over height of the whole table, rails included. */
  aspect() {
    const t = this.table;
    if (!t) return 2;
    return (t.length + 2 * FRAME) / (t.width + 2 * FRAME);
  }

  /**
   * Sizes the canvas to fit in maxW x maxH CSS pixels, high-DPI aware.
   * With `portrait`, the table is turned a quarter turn (the head of the
   * table, x = 0, at the bottom of the screen): the drawing is made in the
   * table's own "landscape" axes (sx, sy below, landW x landH CSS px) and
   * the canvas's transform turns it (base()); text is drawn upright.
   */
  fit(maxW, maxH, portrait = false) {
    const rot = !!portrait;
    const a = rot ? 1 / this.aspect() : this.aspect();  // screen width over height
    let w = Math.max(200, maxW);
    let h = w / a;
    if (h > maxH && maxH > 120) {
      h = maxH;
      w = h * a;
    }
    w = Math.floor(w);
    h = Math.floor(w / a);
    const dpr = Math.min(3, window.devicePixelRatio || 1);
    if (w === this.cssW && h === this.cssH && dpr === this.dpr && rot === !!this.rot) return false;
    this.rot = rot;
    this.cssW = w;
    this.cssH = h;
    this.landW = rot ? h : w;
    this.landH = rot ? w : h;
    this.dpr = dpr;
    this.canvas.style.width = `${w}px`;
    this.canvas.style.height = `${h}px`;
    this.canvas.width = Math.round(w * dpr);
    this.canvas.height = Math.round(h * dpr);
    this.canvas.dataset.rotated = rot ? '1' : '0';
    this.scale = this.table ? this.landW / (this.table.length + 2 * FRAME) : 1;
    this.staticLayer = null;
    this.rolled.clear();
    return true;
  }

  /** The canvas transform from the landscape drawing (CSS px) to device pixels. */
  base(ctx, unit = this.dpr) {
    if (this.rot) ctx.setTransform(0, -unit, unit, 0, 0, this.canvas.height);
    else ctx.setTransform(unit, 0, 0, unit, 0, 0);
  }

  /** A point of the landscape drawing on the screen (CSS px in the canvas). */
  screenOf(lx, ly) {
    return this.rot ? { x: ly, y: this.landW - lx } : { x: lx, y: ly };
  }

  /** Table coordinates (m) to CSS pixels within the canvas. */
  sx(x) { return (x + FRAME) * this.scale; }
  sy(y) { return (this.table.width + FRAME - y) * this.scale; }
  px(m) { return m * this.scale; }

  /** Client (pointer event) coordinates to table coordinates. */
  toTable(clientX, clientY) {
    const r = this.canvas.getBoundingClientRect();
    // the canvas may be drawn at another size than cssW (CSS zoom, transforms)
    const kx = r.width > 0 ? this.cssW / r.width : 1;
    const ky = r.height > 0 ? this.cssH / r.height : 1;
    const px = (clientX - r.left) * kx;
    const py = (clientY - r.top) * ky;
    // back to the landscape drawing (screenOf's inverse)
    const cx = this.rot ? this.landW - py : px;
    const cy = this.rot ? px : py;
    return { x: cx / this.scale - FRAME, y: this.table.width + FRAME - cy / this.scale };
  }

  /** Table coordinates to client coordinates (for tests and overlays). */
  toClient(x, y) {
    const r = this.canvas.getBoundingClientRect();
    const kx = this.cssW > 0 ? r.width / this.cssW : 1;
    const ky = this.cssH > 0 ? r.height / this.cssH : 1;
    const p = this.screenOf(this.sx(x), this.sy(y));
    return { x: r.left + p.x * kx, y: r.top + p.y * ky };
  }

  pathOutline(ctx) {
    const o = this.table.outline;
    ctx.beginPath();
    for (let i = 0; i < o.length; i++) {
      const X = this.sx(o[i][0]);
      const Y = this.sy(o[i][1]);
      if (i === 0) ctx.moveTo(X, Y); else ctx.lineTo(X, Y);
    }
    ctx.closePath();
  }

  buildStatic() {
    const t = this.table;
    const layer = document.createElement('canvas');
    layer.width = Math.round(this.landW * this.dpr);
    layer.height = Math.round(this.landH * this.dpr);
    const ctx = layer.getContext('2d');
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    const L = t.length;
    const W = t.width;
    const s = this.scale;

    // wooden rails
    const x0 = this.sx(-FRAME);
    const y0 = this.sy(W + FRAME);
    const fw = this.px(L + 2 * FRAME);
    const fh = this.px(W + 2 * FRAME);
    roundRect(ctx, x0, y0, fw, fh, this.px(0.045));
    const wood = ctx.createLinearGradient(0, y0, 0, y0 + fh);
    wood.addColorStop(0, '#7a4424');
    wood.addColorStop(0.5, '#5e3119');
    wood.addColorStop(1, '#4a2512');
    ctx.fillStyle = wood;
    ctx.fill();
    // grain
    ctx.save();
    ctx.clip();
    ctx.lineWidth = Math.max(0.5, s * 0.0015);
    for (let i = 0; i < 26; i++) {
      const f = (i * 0.6180339887) % 1;
      ctx.strokeStyle = `rgba(${i % 2 ? '255, 220, 170' : '30, 10, 0'}, ${0.05 + 0.05 * f})`;
      const yy = this.sy(W + FRAME) + fh * ((i + 0.5) / 26);
      ctx.beginPath();
      ctx.moveTo(x0, yy);
      ctx.bezierCurveTo(x0 + fw * 0.3, yy + s * 0.004 * (f - 0.5), x0 + fw * 0.7, yy - s * 0.006 * (f - 0.5), x0 + fw, yy);
      ctx.stroke();
    }
    ctx.restore();
    // bevel of the outer edge and of the rail cap
    ctx.strokeStyle = 'rgba(255, 225, 190, 0.18)';
    ctx.lineWidth = Math.max(1, s * 0.003);
    roundRect(ctx, x0 + ctx.lineWidth, y0 + ctx.lineWidth, fw - 2 * ctx.lineWidth, fh - 2 * ctx.lineWidth, this.px(0.04));
    ctx.stroke();

    // pocket liners on the wood
    for (const p of t.pockets) {
      ctx.fillStyle = '#241b16';
      ctx.beginPath();
      ctx.arc(this.sx(p.centre[0]), this.sy(p.centre[1]), this.px(p.radius + 0.016), 0, Math.PI * 2);
      ctx.fill();
    }

    // cushions: the band out to CUSHION beyond the noses, cut by the cloth
    ctx.fillStyle = this.carom ? '#1d4a8c' : '#15603c';
    ctx.fillRect(this.sx(-CUSHION), this.sy(W + CUSHION), this.px(L + 2 * CUSHION), this.px(W + 2 * CUSHION));
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.45)';
    ctx.lineWidth = Math.max(1, s * 0.003);
    ctx.strokeRect(this.sx(-CUSHION), this.sy(W + CUSHION), this.px(L + 2 * CUSHION), this.px(W + 2 * CUSHION));

    // the cloth: the playing surface with its pocket mouths (the outline)
    this.pathOutline(ctx);
    const cloth = ctx.createRadialGradient(this.sx(L / 2), this.sy(W / 2), this.px(0.1),
      this.sx(L / 2), this.sy(W / 2), this.px(L * 0.62));
    // carom cloth is blue, pool and snooker cloth green
    cloth.addColorStop(0, this.carom ? '#2f6cc4' : '#22925c');
    cloth.addColorStop(1, this.carom ? '#255aa8' : '#1a7a4b');
    ctx.fillStyle = cloth;
    ctx.fill();
    // the noses' shadow on the cloth
    ctx.save();
    this.pathOutline(ctx);
    ctx.clip();
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.28)';
    ctx.lineWidth = Math.max(2, s * 0.012);
    this.pathOutline(ctx);
    ctx.stroke();
    ctx.restore();
    // the cushion noses themselves, from the wall pieces
    ctx.strokeStyle = 'rgba(170, 235, 200, 0.35)';
    ctx.lineWidth = Math.max(0.75, s * 0.0022);
    ctx.lineCap = 'round';
    for (const w of t.walls) {
      ctx.beginPath();
      if (w.kind === 'segment') {
        ctx.moveTo(this.sx(w.a[0]), this.sy(w.a[1]));
        ctx.lineTo(this.sx(w.b[0]), this.sy(w.b[1]));
      } else if (w.kind === 'arc' && w.radius > 0) {
        // from direction b counter-clockwise to normal (table coordinates);
        // the screen flips y, so angles change sign
        const a0 = Math.atan2(w.b[1], w.b[0]);
        const n = w.normal || w.b;
        const a1 = Math.atan2(n[1], n[0]);
        ctx.arc(this.sx(w.a[0]), this.sy(w.a[1]), this.px(w.radius), -a0, -a1, true);
      } else {
        continue;
      }
      ctx.stroke();
    }

    // pockets: the holes
    for (const p of t.pockets) {
      const cx = this.sx(p.centre[0]);
      const cy = this.sy(p.centre[1]);
      const r = this.px(p.radius);
      const g = ctx.createRadialGradient(cx, cy, r * 0.2, cx, cy, r);
      g.addColorStop(0, '#000');
      g.addColorStop(0.8, '#070707');
      g.addColorStop(1, '#1c1c1c');
      ctx.fillStyle = g;
      ctx.beginPath();
      ctx.arc(cx, cy, r, 0, Math.PI * 2);
      ctx.fill();
    }

    if (this.snooker) {
      this.drawSnookerMarks(ctx);
      this.staticLayer = layer;
      return;
    }
    if (this.carom) {
      this.drawCaromMarks(ctx);
      this.staticLayer = layer;
      return;
    }

    // diamonds: 1/8 of the length on the long rails, 1/4 of the width on the short
    const d = CUSHION + (FRAME - CUSHION) * 0.5;
    const spots = [];
    for (let k = 1; k <= 7; k++) {
      if (k === 4) continue;
      spots.push([(L * k) / 8, -d], [(L * k) / 8, W + d]);
    }
    for (let k = 1; k <= 3; k++) spots.push([-d, (W * k) / 4], [L + d, (W * k) / 4]);
    for (const [x, y] of spots) {
      this.drawDiamond(ctx, x, y);
    }

    // head string and spots, faint
    const hs = t.head_string ?? L / 4;
    ctx.strokeStyle = 'rgba(255, 255, 255, 0.16)';
    ctx.lineWidth = Math.max(1, s * 0.002);
    ctx.setLineDash([this.px(0.02), this.px(0.016)]);
    ctx.beginPath();
    ctx.moveTo(this.sx(hs), this.sy(0));
    ctx.lineTo(this.sx(hs), this.sy(W));
    ctx.stroke();
    ctx.setLineDash([]);
    const spot = (p, r) => {
      ctx.fillStyle = 'rgba(255, 255, 255, 0.32)';
      ctx.beginPath();
      ctx.arc(this.sx(p[0]), this.sy(p[1]), Math.max(1.5, this.px(r)), 0, Math.PI * 2);
      ctx.fill();
    };
    if (t.foot_spot) spot(t.foot_spot, 0.006);
    if (t.head_spot) spot(t.head_spot, 0.004);
    this.staticLayer = layer;
  }

  /** A sight diamond on the rail at table point (x, y). */
  drawDiamond(ctx, x, y) {
    const cx = this.sx(x);
    const cy = this.sy(y);
    const r = Math.max(2, this.px(DIAMOND));
    ctx.beginPath();
    ctx.moveTo(cx, cy - r);
    ctx.lineTo(cx + r * 0.62, cy);
    ctx.lineTo(cx, cy + r);
    ctx.lineTo(cx - r * 0.62, cy);
    ctx.closePath();
    ctx.fillStyle = '#efe8d6';
    ctx.fill();
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.35)';
    ctx.lineWidth = 0.75;
    ctx.stroke();
  }

  /** The carom table's diamonds (on the rails, level with the engine's
   *  points on the cushion noses) and its five spots: top, centre, bottom
   *  and the two starting spots. */
  drawCaromMarks(ctx) {
    const m = this.carom;
    const L = this.table.length;
    const W = this.table.width;
    const d = CUSHION + (FRAME - CUSHION) * 0.5;
    const eps = 1e-6;
    for (const [px, py] of m.diamonds || []) {
      let x = px;
      let y = py;
      if (py <= eps) y = -d;
      else if (py >= W - eps) y = W + d;
      else if (px <= eps) x = -d;
      else if (px >= L - eps) x = L + d;
      this.drawDiamond(ctx, x, y);
    }
    const spots = [m.top_spot, m.centre_spot, m.bottom_spot, ...(m.starting_spots || [])];
    ctx.fillStyle = 'rgba(255, 255, 255, 0.7)';
    for (const p of spots) {
      if (!p) continue;
      ctx.beginPath();
      ctx.arc(this.sx(p[0]), this.sy(p[1]), Math.max(1.6, this.px(0.0055)), 0, Math.PI * 2);
      ctx.fill();
    }
  }

  /** The baulk line, the D and the six colour spots (snooker), to scale. */
  drawSnookerMarks(ctx) {
    const m = this.snooker;
    const W = this.table.width;
    ctx.save();
    ctx.strokeStyle = 'rgba(255, 255, 255, 0.55)';
    ctx.lineWidth = Math.max(1, this.scale * 0.0025);
    ctx.beginPath();
    ctx.moveTo(this.sx(m.baulk_line), this.sy(0));
    ctx.lineTo(this.sx(m.baulk_line), this.sy(W));
    ctx.stroke();
    // the D: the half circle on the baulk side of the line
    ctx.beginPath();
    ctx.arc(this.sx(m.d_centre[0]), this.sy(m.d_centre[1]), this.px(m.d_radius), Math.PI / 2, (3 * Math.PI) / 2);
    ctx.stroke();
    for (const p of Object.values(m.spots)) {
      ctx.fillStyle = 'rgba(255, 255, 255, 0.6)';
      ctx.beginPath();
      ctx.arc(this.sx(p[0]), this.sy(p[1]), Math.max(1.2, this.px(0.004)), 0, Math.PI * 2);
      ctx.fill();
    }
    ctx.restore();
  }

  /**
   * Draws a frame. scene: {
   *   balls: [{n, x, y, z?, alpha?, scale?}], R (ball radius, m); z > 0:
   *     in flight (drawn with flightScale and flightLift over its shadow),
   *   kitchen: bool (shade the area behind the head string),
   *   d: bool (snooker: shade the D, where the cue ball may be placed),
   *   nominated: {ball, auto} | null (snooker: the nominated ball, ringed),
   *   aim: {cue: {x, y}, phi, geo (aimGeometry), power (0..1), stick: bool} | null,
   *   call: {ball, pocket, auto} | null, place: {x, y, ok, reason} | null,
   *   banner: text | null }
   */
  render(scene) {
    if (!this.table || this.cssW === 0) return;
    if (!this.staticLayer) this.buildStatic();
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    this.base(ctx, 1);
    ctx.drawImage(this.staticLayer, 0, 0);
    this.base(ctx);
    const t = this.table;
    const R = scene.R || t.ball_radius;
    const rpx = this.px(R);

    if (scene.kitchen) {
      const hs = t.head_string ?? t.length / 4;
      ctx.fillStyle = 'rgba(255, 255, 255, 0.06)';
      ctx.fillRect(this.sx(0), this.sy(t.width), this.px(hs), this.px(t.width));
      ctx.strokeStyle = 'rgba(255, 255, 255, 0.35)';
      ctx.lineWidth = 1.2;
      ctx.beginPath();
      ctx.moveTo(this.sx(hs), this.sy(0));
      ctx.lineTo(this.sx(hs), this.sy(t.width));
      ctx.stroke();
    }

    if (scene.d && this.snooker) {
      const m = this.snooker;
      ctx.save();
      ctx.fillStyle = 'rgba(255, 255, 255, 0.09)';
      ctx.beginPath();
      ctx.arc(this.sx(m.d_centre[0]), this.sy(m.d_centre[1]), this.px(m.d_radius), Math.PI / 2, (3 * Math.PI) / 2);
      ctx.closePath();
      ctx.fill();
      ctx.restore();
    }

    // called pocket
    if (scene.call && scene.call.pocket != null && t.pockets[scene.call.pocket]) {
      const p = t.pockets[scene.call.pocket];
      ctx.save();
      ctx.strokeStyle = scene.call.pocketAuto ? 'rgba(255, 214, 90, 0.55)' : '#ffd65a';
      ctx.lineWidth = scene.call.pocketAuto ? 2 : 3;
      ctx.setLineDash(scene.call.pocketAuto ? [5, 4] : []);
      ctx.beginPath();
      ctx.arc(this.sx(p.centre[0]), this.sy(p.centre[1]), this.px(p.radius) + 4, 0, Math.PI * 2);
      ctx.stroke();
      ctx.restore();
    }

    const aim = scene.aim;
    if (aim && aim.geo) this.drawAim(aim, rpx);

    // balls: those on the cloth, then those in flight over their shadows,
    // lowest first
    const callBall = scene.call ? scene.call.ball : null;
    const nom = scene.nominated && scene.nominated.ball != null ? scene.nominated : null;
    const snooker = !!this.snooker;
    const carom = !!this.carom;
    const ringOf = (n) => {
      if (callBall != null && n === callBall) return scene.call.ballAuto ? 'rgba(255, 214, 90, 0.6)' : '#ffd65a';
      if (nom && n === nom.ball) return nom.auto ? 'rgba(255, 214, 90, 0.6)' : '#ffd65a';
      return null;
    };
    const flying = [];
    for (const b of scene.balls) {
      if (scene.place && b.n === 0) continue;
      if (b.z > 0) {
        flying.push(b);
        continue;
      }
      const opts = { alpha: b.alpha, ring: ringOf(b.n), snooker, carom };
      if (b.o && !snooker && !carom && b.n > 0) this.drawRolling(ctx, b.n, b.o, this.sx(b.x), this.sy(b.y), rpx * (b.scale ?? 1), opts);
      else drawBall(ctx, b.n, this.sx(b.x), this.sy(b.y), rpx * (b.scale ?? 1), opts);
    }
    flying.sort((p, q) => p.z - q.z);
    for (const b of flying) drawFlightShadow(ctx, this.sx(b.x), this.sy(b.y), rpx, b.z);
    for (const b of flying) {
      const opts = { alpha: b.alpha, shadow: false, snooker, carom };
      const fx = this.sx(b.x);
      const fy = this.sy(b.y) - this.px(flightLift(b.z));
      const fr = rpx * (b.scale ?? 1) * flightScale(b.z);
      if (b.o && !snooker && !carom && b.n > 0) this.drawRolling(ctx, b.n, b.o, fx, fy, fr, opts);
      else drawBall(ctx, b.n, fx, fy, fr, opts);
    }
    // What the last frame drew in flight (the page's tests read it).
    this.flight = { count: flying.length, maxZ: flying.reduce((m, b) => Math.max(m, b.z), 0) };
    this.canvas.dataset.flight = String(flying.length);

    if (scene.place) {
      const p = scene.place;
      const cx = this.sx(p.x);
      const cy = this.sy(p.y);
      drawBall(ctx, 0, cx, cy, rpx, { alpha: p.ok ? 1 : 0.85, snooker });
      ctx.strokeStyle = p.ok ? 'rgba(255, 255, 255, 0.7)' : '#ff4d4d';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(cx, cy, rpx + 3, 0, Math.PI * 2);
      ctx.stroke();
      if (!p.ok) {
        ctx.fillStyle = 'rgba(255, 60, 60, 0.35)';
        ctx.beginPath();
        ctx.arc(cx, cy, rpx, 0, Math.PI * 2);
        ctx.fill();
        if (p.reason) this.label(p.reason, cx, cy - rpx - 10, '#ffb3b3');
      }
    }

    if (aim && aim.stick) this.drawStick(aim, rpx);

    // three-cushion: the cushions of the struck ball so far, while it runs
    if (scene.counter) {
      ctx.save();
      const fs = Math.max(13, Math.min(22, this.cssW / 45));
      ctx.font = `700 ${fs}px system-ui, -apple-system, "Segoe UI", Arial, sans-serif`;
      ctx.textAlign = 'left';
      ctx.textBaseline = 'middle';
      const w = ctx.measureText(scene.counter.text).width + fs;
      // upright, at the cloth's top-left corner on the screen
      const a = this.screenOf(this.sx(0), this.sy(this.table.width));
      const b = this.screenOf(this.sx(this.table.length), this.sy(0));
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      const x = Math.min(a.x, b.x) + fs * 0.5;
      const y = Math.min(a.y, b.y) + fs * 1.1;
      ctx.fillStyle = 'rgba(10, 14, 18, 0.7)';
      roundRect(ctx, x, y - fs * 0.8, w, fs * 1.6, fs * 0.35);
      ctx.fill();
      ctx.fillStyle = scene.counter.colour || '#ffe9a8';
      ctx.fillText(scene.counter.text, x + fs * 0.5, y + 1);
      ctx.restore();
    }

    if (scene.banner) {
      ctx.save();
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);  // upright
      const fs = Math.max(16, Math.min(36, this.cssW / 28));
      ctx.font = `700 ${fs}px system-ui, -apple-system, "Segoe UI", Arial, sans-serif`;
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      const w = ctx.measureText(scene.banner).width + fs * 1.4;
      const cx = this.cssW / 2;
      const cy = this.cssH / 2;
      ctx.fillStyle = 'rgba(10, 14, 18, 0.72)';
      roundRect(ctx, cx - w / 2, cy - fs * 0.95, w, fs * 1.9, fs * 0.4);
      ctx.fill();
      ctx.fillStyle = '#ffe9a8';
      ctx.fillText(scene.banner, cx, cy + 1);
      ctx.restore();
    }
  }

  /** A text label at (cx, cy) of the landscape drawing, upright on the screen. */
  label(text, lx, ly, colour) {
    const ctx = this.ctx;
    ctx.save();
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    const { x: cx, y: cy } = this.screenOf(lx, ly);
    ctx.font = '600 13px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    const w = ctx.measureText(text).width + 12;
    let x = Math.max(w / 2 + 2, Math.min(this.cssW - w / 2 - 2, cx));
    let y = Math.max(12, cy);
    ctx.fillStyle = 'rgba(15, 10, 10, 0.82)';
    roundRect(ctx, x - w / 2, y - 10, w, 20, 5);
    ctx.fill();
    ctx.fillStyle = colour;
    ctx.fillText(text, x, y + 0.5);
    ctx.restore();
  }

  drawAim(aim, rpx) {
    const ctx = this.ctx;
    const geo = aim.geo;
    const c = aim.cue;
    ctx.save();
    this.pathOutline(ctx);
    ctx.clip();
    ctx.lineCap = 'round';
    ctx.strokeStyle = 'rgba(255, 255, 255, 0.55)';
    ctx.lineWidth = 1.4;
    ctx.setLineDash([6, 5]);
    ctx.beginPath();
    ctx.moveTo(this.sx(c.x), this.sy(c.y));
    ctx.lineTo(this.sx(geo.end.x), this.sy(geo.end.y));
    ctx.stroke();
    ctx.setLineDash([]);
    if (geo.hit) {
      const gx = this.sx(geo.ghost.x);
      const gy = this.sy(geo.ghost.y);
      ctx.strokeStyle = 'rgba(255, 255, 255, 0.8)';
      ctx.lineWidth = 1.4;
      ctx.beginPath();
      ctx.arc(gx, gy, rpx, 0, Math.PI * 2);
      ctx.stroke();
      ctx.fillStyle = 'rgba(255, 255, 255, 0.12)';
      ctx.fill();
      // object ball's rough direction, longer for a fuller hit
      const ox = this.sx(geo.hit.x);
      const oy = this.sy(geo.hit.y);
      const len = this.px(0.08 + 0.42 * geo.cosCut);
      ctx.strokeStyle = 'rgba(255, 220, 110, 0.9)';
      ctx.lineWidth = 2;
      arrow(ctx, ox, oy, ox + geo.objectDir.x * len, oy - geo.objectDir.y * len, 7);
      // cue ball's tangent line
      if (geo.cueDir.x || geo.cueDir.y) {
        const clen = this.px(0.05 + 0.25 * Math.sqrt(Math.max(0, 1 - geo.cosCut * geo.cosCut)));
        ctx.strokeStyle = 'rgba(200, 230, 255, 0.55)';
        ctx.lineWidth = 1.3;
        ctx.setLineDash([3, 4]);
        ctx.beginPath();
        ctx.moveTo(gx, gy);
        ctx.lineTo(gx + geo.cueDir.x * clen, gy - geo.cueDir.y * clen);
        ctx.stroke();
        ctx.setLineDash([]);
      }
    } else if (geo.bounce) {
      const ex = this.sx(geo.end.x);
      const ey = this.sy(geo.end.y);
      const len = this.px(0.25);
      ctx.strokeStyle = 'rgba(255, 255, 255, 0.25)';
      ctx.lineWidth = 1.2;
      ctx.setLineDash([4, 5]);
      ctx.beginPath();
      ctx.moveTo(ex, ey);
      ctx.lineTo(ex + geo.bounce.x * len, ey - geo.bounce.y * len);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.strokeStyle = 'rgba(255, 255, 255, 0.55)';
      ctx.beginPath();
      ctx.arc(ex, ey, rpx, 0, Math.PI * 2);
      ctx.stroke();
    }
    ctx.restore();
  }

  drawStick(aim, rpx) {
    const ctx = this.ctx;
    const c = aim.cue;
    const rad = (aim.phi * Math.PI) / 180;
    // screen direction of the shot (y flipped)
    const ux = Math.cos(rad);
    const uy = -Math.sin(rad);
    const vx = -uy;
    const vy = ux;
    const cx = this.sx(c.x);
    const cy = this.sy(c.y);
    // drawn back by the pull (the stroke's, or the speed's), and to the
    // side by the tip's offset a (right english: to the shooter's right)
    const gap = rpx + this.px(0.004 + (aim.pull ?? 0.013 + 0.13 * (aim.power ?? 0.3)));
    const side = this.px((aim.a ?? 0) * (aim.R ?? 0));
    const len = this.px(1.45);
    const tipW = this.px(0.0065);
    const buttW = this.px(0.015);
    // Raised by the elevation theta, the stick rises from the tip: a point s
    // along it (px) is s cos(theta) back on the cloth and s sin(theta) up,
    // drawn with the balls' projection (flightLift, flightScale).
    const th = (Math.max(0, Math.min(89, aim.theta ?? 0)) * Math.PI) / 180;
    const cosT = Math.cos(th);
    const sinT = Math.sin(th);
    const height = (s) => (s * sinT) / this.scale;  // m
    // the stick lies on the side opposite the shot: p(s) = c - u (gap + s cos) + lift
    const at = (s, w) => {
      const lift = this.px(flightLift(height(s)));
      const ww = w * flightScale(height(s));
      return [cx - ux * (gap + s * cosT) + vx * (ww + side), cy - uy * (gap + s * cosT) + vy * (ww + side) - lift];
    };
    const width = (s) => tipW + (buttW - tipW) * (s / len);
    const quad = (s0, s1, fill) => {
      const a = at(s0, width(s0));
      const b = at(s1, width(s1));
      const c2 = at(s1, -width(s1));
      const d = at(s0, -width(s0));
      ctx.beginPath();
      ctx.moveTo(a[0], a[1]);
      ctx.lineTo(b[0], b[1]);
      ctx.lineTo(c2[0], c2[1]);
      ctx.lineTo(d[0], d[1]);
      ctx.closePath();
      ctx.fillStyle = fill;
      ctx.fill();
    };
    ctx.save();
    // shadow: on the cloth under the stick (its plan), a little offset
    const ground = (s, w) => [cx - ux * (gap + s * cosT) + vx * (w + side), cy - uy * (gap + s * cosT) + vy * (w + side)];
    ctx.translate(this.px(0.01), this.px(0.014));
    {
      const a = ground(0, width(0));
      const b = ground(len, width(len));
      const c2 = ground(len, -width(len));
      const d = ground(0, -width(0));
      ctx.beginPath();
      ctx.moveTo(a[0], a[1]);
      ctx.lineTo(b[0], b[1]);
      ctx.lineTo(c2[0], c2[1]);
      ctx.lineTo(d[0], d[1]);
      ctx.closePath();
      ctx.fillStyle = `rgba(0, 0, 0, ${(0.28 * (1 - 0.5 * sinT)).toFixed(3)})`;
      ctx.fill();
    }
    ctx.restore();
    ctx.save();
    const tip = this.px(0.008);
    const ferrule = this.px(0.022);
    const shaftEnd = len * 0.52;
    const wrapEnd = len * 0.86;
    quad(0, tip, '#3b78c2');
    quad(tip, tip + ferrule, '#f3efe6');
    const sa = at(tip + ferrule, 0);
    const sb = at(shaftEnd, 0);
    const maple = ctx.createLinearGradient(sa[0], sa[1], sb[0], sb[1]);
    maple.addColorStop(0, '#efdcb3');
    maple.addColorStop(1, '#d9b57a');
    quad(tip + ferrule, shaftEnd, maple);
    quad(shaftEnd, shaftEnd + this.px(0.012), '#1d1d1d');
    quad(shaftEnd + this.px(0.012), wrapEnd, '#5a2d16');
    quad(wrapEnd, len - this.px(0.03), '#262626');
    quad(len - this.px(0.03), len, '#111');
    ctx.restore();
    this.drawTipInset(aim);
    if (aim.stroke) {
      // the speed of the stroke being drawn, beside the butt's side of the ball
      const bx = cx - ux * (gap + this.px(0.12));
      const by = cy - uy * (gap + this.px(0.12));
      this.label(aim.stroke, bx + vx * this.px(0.07), by + vy * this.px(0.07), '#ffe9a8');
    }
  }

  /** Where the tip meets the cue ball (a to the right, b up, as the #tip
   *  widget shows it), on a small ball drawn on the bottom rail. */
  drawTipInset(aim) {
    const ctx = this.ctx;
    const r = Math.max(9, this.px(0.05));
    const at = this.screenOf(this.sx(0.2), this.sy(-(CUSHION + (FRAME - CUSHION) * 0.5)));
    const cx = at.x;
    const cy = at.y;
    ctx.save();
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);  // upright: the ball as the player sees it
    ctx.globalAlpha = 0.92;
    drawBall(ctx, 0, cx, cy, r, { shadow: false });
    ctx.strokeStyle = 'rgba(0, 0, 0, 0.3)';
    ctx.lineWidth = 0.75;
    ctx.beginPath();
    ctx.moveTo(cx - r, cy);
    ctx.lineTo(cx + r, cy);
    ctx.moveTo(cx, cy - r);
    ctx.lineTo(cx, cy + r);
    ctx.stroke();
    ctx.fillStyle = '#2f6fc0';
    ctx.strokeStyle = '#0d2748';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.arc(cx + (aim.a ?? 0) * r, cy - (aim.b ?? 0) * r, Math.max(2, r * 0.2), 0, Math.PI * 2);
    ctx.fill();
    ctx.stroke();
    ctx.restore();
  }
}

function roundRect(ctx, x, y, w, h, r) {
  ctx.beginPath();
  ctx.moveTo(x + r, y);
  ctx.lineTo(x + w - r, y);
  ctx.quadraticCurveTo(x + w, y, x + w, y + r);
  ctx.lineTo(x + w, y + h - r);
  ctx.quadraticCurveTo(x + w, y + h, x + w - r, y + h);
  ctx.lineTo(x + r, y + h);
  ctx.quadraticCurveTo(x, y + h, x, y + h - r);
  ctx.lineTo(x, y + r);
  ctx.quadraticCurveTo(x, y, x + r, y);
  ctx.closePath();
}

function arrow(ctx, x0, y0, x1, y1, head) {
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  const a = Math.atan2(y1 - y0, x1 - x0);
  ctx.beginPath();
  ctx.moveTo(x1, y1);
  ctx.lineTo(x1 - head * Math.cos(a - 0.45), y1 - head * Math.sin(a - 0.45));
  ctx.moveTo(x1, y1);
  ctx.lineTo(x1 - head * Math.cos(a + 0.45), y1 - head * Math.sin(a + 0.45));
  ctx.stroke();
}

// A shot played back: the engine's frames at the page's clock (times the
// playback speed), the balls that drop fading into their pocket, the
// sounds of the events as loud as their impacts, the pool balls' markings
// turned by their spins, and three-cushion's count as the ball goes (the
// facade's, bs_web_playback_carom_count). Also the sound's mute button.
// Functions of the GameUI (game.js) that owns the animation (ui.anim).

import { rotate } from './draw-ball.js';
import { CAROM_NAMES } from './draw-colours.js';
import { $ } from './game-dom.js';
import { message } from './game-flow.js';

export const FADE = 0.3;   // seconds a pocketed ball takes to vanish

const SOUND_OF = { ball_ball: 'ball', ball_cushion: 'cushion', ball_pocket: 'pocket', cue_strike: 'cue' };

/** The ball number of an event's ball id (the games' scenarios name
 *  balls "cue", "1", "2", ..., carom balls "white", "yellow", "red"). */
export function numberOfId(id) {
  if (id === 'cue') return 0;
  const carom = CAROM_NAMES.indexOf(id);
  if (carom >= 0) return carom;
  const n = Number(id);
  return Number.isInteger(n) ? n : -1;
}

/** The impact speed (m/s) of an event, from the balls' velocities in the
 *  frames before (prev) and after (cur) it: the normal speed of a contact
 *  from the velocity changes it made (equal masses: the two changes add
 *  up to (1 + e) times it), a cushion's from the ball's change, a pocket's
 *  the ball's speed before it dropped, the tip's the cue ball's speed
 *  after. For sounds only. */
export function impactSpeed(type, idx, prev, cur) {
  const v = (f, i) => (f && f.balls[i] ? [f.balls[i][3], f.balls[i][4]] : [0, 0]);
  const dv = (i) => {
    const a = v(prev || cur, i);
    const b = v(cur, i);
    return Math.hypot(b[0] - a[0], b[1] - a[1]);
  };
  const speed = (f, i) => Math.hypot(...v(f, i));
  if (type === 'ball_ball' && idx.length === 2) return (dv(idx[0]) + dv(idx[1])) / 1.95;
  if (type === 'ball_cushion') return dv(idx[0]) / 1.8;
  if (type === 'ball_pocket') return speed(prev || cur, idx[0]);
  if (type === 'cue_strike') return speed(cur, idx[0]);
  return 0;
}

/** Starts the playback of shot `index` (the balls `numbers` by scenario
 *  index); `done` runs once the balls stop. */
export function animate(ui, index, numbers, done, replay = false, ruling = null) {
  let pb;
  try {
    pb = ui.g.shotPlayback(index);
  } catch (e) {
    ui.showError(`Cannot play the shot back: ${message(e)}`);
    done();
    return;
  }
  ui.anim = { pb, numbers: numbers || [], t: 0, last: null, frame: null, done, index, gone: new Map(), replay: !!replay, heard: 0 };
  // three-cushion: the struck ball's count as the events come
  const game = ui.flow.game();
  if (game.counts && ruling && ruling.carom) {
    ui.anim.count = { struck: ruling.carom.cue_ball, ruling, now: { cushions: 0, hit: [], done: false, made: false } };
    game.showCount($, ui.anim.count.now, ruling, false);
  }
  try {
    ui.anim.frame = pb.frame(0);
  } catch (e) {
    finishAnimation(ui, e);
    return;
  }
  ui.updatePanel();
  ui.requestRender();
}

export function stepAnimation(ui, now) {
  const a = ui.anim;
  if (!a) return;
  if (a.last != null) {
    const dt = Math.min(0.1, Math.max(0, (now - a.last) / 1000));
    a.t += dt * Number($('playback-speed').value || 1);
  }
  a.last = now;
  const prev = a.frame;
  try {
    a.frame = a.pb.frame(a.t);
  } catch (e) {
    finishAnimation(ui, e);
    return;
  }
  // balls that just dropped: fade them into their pocket
  if (prev) {
    a.frame.balls.forEach((b, i) => {
      if (!b[2] && prev.balls[i] && prev.balls[i][2] && !a.gone.has(i)) {
        // Off the table (place 2): it fades where it left, from the
        // height it had; into a pocket: it slides to the pocket's centre.
        const off = b.length > 8 && b[9] === 2;
        const p = off ? null : nearestPocket(ui.table, b[0], b[1]);
        const z = prev.balls[i].length > 8 ? prev.balls[i][8] : 0;
        a.gone.set(i, { x: b[0], y: b[1], z: off ? z : 0, t: a.t, px: p ? p.centre[0] : b[0], py: p ? p.centre[1] : b[1] });
      }
    });
  }
  soundEvents(ui, a, prev);
  roll(ui, a, prev);
  if (a.count && (!prev || a.frame.events > prev.events)) {
    try {
      a.count.now = a.pb.caromCount();
    } catch (e) { /* the last count stays */ }
    ui.flow.game().showCount($, a.count.now, a.count.ruling, false);
  }
  const fading = [...a.gone.values()].some((g) => a.t - g.t < FADE);
  if (a.frame.at_rest && !fading) finishAnimation(ui, null);
}

/** The sounds of the events since the last frame, each as loud as its
 *  impact speed (from this frame's and the previous frame's states). */
function soundEvents(ui, a, prev) {
  if (a.frame.events <= a.heard) return;
  let evs = [];
  try {
    evs = a.pb.events(a.heard).events || [];
  } catch (e) { /* no sounds */ }
  a.heard = a.frame.events;
  if (!a.index_of) {
    a.index_of = new Map();
    a.numbers.forEach((n, i) => a.index_of.set(n, i));
  }
  ui.sounds.newFrame();
  // the loudest first: a frame's budget of sounds keeps those
  const list = [];
  for (const e of evs) {
    const kind = SOUND_OF[e.type];
    if (!kind) continue;
    const idx = (e.balls || []).map((id) => {
      const n = numberOfId(id);
      return a.index_of.has(n) ? a.index_of.get(n) : n;
    });
    list.push({ kind, speed: impactSpeed(e.type, idx, prev, a.frame), dt: Math.max(0, (e.time || 0) - (prev ? prev.t : 0)) });
  }
  list.sort((p, q) => q.speed - p.speed);
  for (const x of list) ui.sounds.play(x.kind, x.speed, x.dt);
}

/** Turns the pool balls' orientations by their spins over the frame's
 *  time step (the mean of the spins at its two ends). Drawing only. */
function roll(ui, a, prev) {
  if (!ui.flow.game().rolls) return;
  const n = a.frame.balls.length;
  let w;
  try {
    w = a.pb.spins(n);
  } catch (e) {
    return;
  }
  const dt = prev ? a.frame.t - prev.t : 0;
  const w0 = a.spins || w;
  a.spins = w;
  if (!(dt > 0)) return;
  for (let i = 0; i < n; i++) {
    if (!a.frame.balls[i][2] && !(prev && prev.balls[i][2])) continue;
    const num = a.numbers[i] ?? i;
    const o = ui.orientation(num);
    rotate(o, (w0[3 * i] + w[3 * i]) / 2, (w0[3 * i + 1] + w[3 * i + 1]) / 2, (w0[3 * i + 2] + w[3 * i + 2]) / 2, dt);
  }
}

function nearestPocket(table, x, y) {
  let best = null;
  let bestD = Infinity;
  for (const p of table.pockets) {
    const d = Math.hypot(p.centre[0] - x, p.centre[1] - y);
    if (d < bestD) { bestD = d; best = p; }
  }
  return best;
}

export function finishAnimation(ui, err) {
  const a = ui.anim;
  if (!a) return;
  ui.anim = null;
  if (a.count) {
    // what the page counted as the ball went (the tests compare it with
    // the engine's ruling)
    ui.lastCount = { cushions: a.count.now.cushions, hit: [...a.count.now.hit] };
    ui.flow.game().showCount($, a.count.now, a.count.ruling, true);
  }
  try { a.pb.free(); } catch (e) { /* gone */ }
  if (err) ui.showError(`Playback: ${message(err)}`);
  a.done();
  ui.updatePanel();
  ui.requestRender();
}

export function stopAnimation(ui) {
  const a = ui.anim;
  if (!a) return;
  ui.anim = null;
  try { a.pb.free(); } catch (e) { /* gone */ }
}

/** The mute button, and the sound unlocked by the first press or key. */
export function bindSound(ui) {
  const b = $('mute');
  const show = () => {
    if (!b) return;
    b.setAttribute('aria-pressed', String(ui.sounds.muted));
    b.textContent = ui.sounds.muted ? 'Sound off' : 'Sound on';
    b.title = ui.sounds.muted ? 'the sounds are off: click to hear them' : 'click to mute the sounds';
  };
  if (b) {
    b.addEventListener('click', () => {
      ui.sounds.setMuted(!ui.sounds.muted);
      show();
    });
  }
  show();
  // browsers let a page play sound after a gesture: the first press or key
  const unlock = () => ui.sounds.unlock();
  document.addEventListener('pointerdown', unlock, true);
  document.addEventListener('keydown', unlock, true);
}

// What the table canvas shows, as a scene for draw.js's TableView: the
// balls (at the playback's frame while a shot runs, fading into their
// pockets), the cue ball in hand, the aim and the stick, the call and the
// nomination, three-cushion's count, the winner's banner; and the layout
// that sizes the canvas (a phone held upright turns the table).
// Functions of the GameUI (game.js).

import { countWords } from './game-carom.js';
import { $ } from './game-dom.js';
import { FADE } from './game-playback.js';
import { POCKET_WORDS } from './game-words.js';
import { MAX_SPEED, MIN_SPEED, STRIKE_MS, pullFromSpeed, strikePull } from './game-stroke.js';

export function layout(ui) {
  if (!ui.table) return;
  const area = $('table-area');
  if (!area || area.offsetParent === null) return;  // hidden tab
  const top = ui.canvas.getBoundingClientRect().top + window.scrollY;
  const maxW = area.clientWidth;
  // A phone held upright: the table turned to the screen's length, as
  // large as leaves the status under it and the controls docked at the
  // bottom (style.css) in view.
  const phone = window.matchMedia('(max-width: 560px)').matches;
  const portrait = phone && window.innerHeight > window.innerWidth * 1.2;
  let maxH;
  if (portrait) {
    const status = $('status');
    const dock = 84;
    maxH = Math.max(240, window.innerHeight - top - dock - (status ? status.offsetHeight : 60) - 20);
  } else {
    maxH = Math.max(240, window.innerHeight - Math.max(0, top - window.scrollY) - 80);
  }
  if (ui.view.fit(maxW, maxH, portrait)) ui.requestRender();
}

/** How far the stick is drawn back from the cue ball (m): the stroke's
 *  pull while one is drawn, going through the ball after the release,
 *  else the pull of the speed set. */
export function stickPull(ui) {
  if (ui.stroke) return ui.stroke.pull;
  if (ui.strike) return strikePull(ui.strike.pull, (performance.now() - ui.strike.t0) / STRIKE_MS);
  return pullFromSpeed(ui.aim.speed);
}

/** The balls of the playback's frame (those dropping fade into their pocket). */
function playbackBalls(ui, scene) {
  const { frame, numbers, gone, t } = ui.anim;
  frame.balls.forEach((b, i) => {
    const n = numbers[i] ?? i;
    if (b[2]) {
      // z (b[8]) only when a ball of the frame is off the cloth
      scene.balls.push({ n, x: b[0], y: b[1], z: b.length > 8 ? b[8] : 0, o: ui.orientation(n) });
    } else if (gone.has(i)) {
      const g = gone.get(i);
      const f = (t - g.t) / FADE;
      if (f < 1) {
        const k = Math.min(1, f * 1.5);
        scene.balls.push({ n, x: g.x + (g.px - g.x) * k, y: g.y + (g.py - g.y) * k, z: g.z, alpha: 1 - f, scale: 1 - 0.35 * f, o: ui.orientation(n) });
      }
    }
  });
  const count = ui.anim.count;
  const cue = count ? count.struck : 0;
  scene.balls.sort((p, q) => (p.n === cue) - (q.n === cue));
  if (count) scene.counter = { text: countWords(count.now) };
}

export function scene(ui) {
  const flow = ui.flow;
  const out = { balls: [], R: ui.R, kitchen: false, d: false, aim: null, call: null, nominated: null, place: null, banner: null };
  const st = flow.st;
  if (!st) return out;
  if (ui.anim && ui.anim.frame) {
    playbackBalls(ui, out);
    return out;
  }
  st.position.forEach((p, n) => {
    if (st.on_table[n]) out.balls.push({ n, x: p[0], y: p[1], o: ui.orientation(n) });
  });
  const legal = flow.legal();
  const canAct = ui.canAct();
  if (canAct && legal.place && legal.place !== 'none') {
    out.kitchen = legal.place === 'kitchen';
    out.d = legal.place === 'd';
    if (ui.drag && ui.drag.kind === 'cue') {
      out.place = { x: ui.drag.x, y: ui.drag.y, ok: ui.drag.ok, reason: ui.drag.reason };
    } else if (flow.placePos) {
      out.place = { x: flow.placePos.x, y: flow.placePos.y, ok: true };
    }
  }
  if ((canAct || ui.strike) && flow.shotDue() && flow.cuePos() && !(ui.drag && ui.drag.kind === 'cue')) {
    const geo = flow.geometry();
    out.aim = {
      cue: flow.cuePos(),
      phi: ui.aim.phi,
      theta: ui.aim.theta,
      geo,
      power: (ui.aim.speed - MIN_SPEED) / (MAX_SPEED - MIN_SPEED),
      pull: stickPull(ui),
      a: ui.aim.a,
      b: ui.aim.b,
      R: ui.R,
      stroke: ui.stroke ? `${ui.aim.speed.toFixed(2)} m/s` : null,
      stick: true,
    };
    out.call = flow.currentCall(geo);
    out.nominated = flow.currentNomination(geo);
  }
  if (st.phase === 'game_over') {
    out.banner = st.winner >= 0 ? `${flow.shortName(st.winner)} wins` : 'Draw';
  }
  return out;
}

/** The "auto" entries of the call selects name what the aim picks. */
export function autoCallLabels(ui, call) {
  const bs = $('call-ball');
  const ps = $('call-pocket');
  if (bs.options.length) {
    const t = call.ballAuto ? (call.ball != null ? `auto: ball ${call.ball}` : 'auto: none') : 'auto (aim)';
    if (bs.options[0].text !== t) bs.options[0].text = t;
  }
  if (ps.options.length) {
    const p = call.pocket != null ? ui.table.pockets[call.pocket] : null;
    const t = call.pocketAuto ? (p ? `auto: ${POCKET_WORDS[p.name] || p.name}` : 'auto: none') : 'auto';
    if (ps.options[0].text !== t) ps.options[0].text = t;
  }
}

/** The "auto" entry of the nominate select names what the aim picks. */
export function nominateLabel(ui, nom) {
  const sel = $('nominate');
  const game = ui.flow.game();
  if (!sel || !sel.options.length || $('nominate-box').hidden || !game.nominationLabel) return;
  const t = game.nominationLabel(nom);
  if (sel.options[0].text !== t) sel.options[0].text = t;
  const v = ui.flow.override.nominate == null ? '' : String(ui.flow.override.nominate);
  if (sel.value !== v) sel.value = v;
}

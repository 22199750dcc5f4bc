// The game tab: a game of 8-ball, 9-ball, 10-ball, snooker or three-cushion
// against an AI level or the baseline player (the computer players the
// engine says play the game) or a friend on the same screen. The
// engine (engine.js over the wasm build) does every bit of physics and
// every ruling; this file takes input, draws the engine's positions and
// keeps the log. Nothing here reaches
// the engine through Math.random: the seed comes from the URL, the form
// or the clock at new-game time, and the link keeps it.

import { TableView, aimGeometry, drawBall, snookerName, caromName, identityOrientation, rotate } from './draw.js';
import { Sounds } from './sound.js';

export const AI_LEVELS = ['beginner', 'amateur', 'club', 'expert', 'champion'];

const MIN_SPEED = 0.3;
const MAX_SPEED = 10;
const BREAK_SPEED = 8.5;
const SNOOKER_BREAK_SPEED = 5;
const DEFAULT_SPEED = 3;
const TIP_LIMIT = 0.48;
const FADE = 0.3;          // seconds a pocketed ball takes to vanish    // largest tip offset the widget allows (miscue limit 0.5)
// The drag-back stroke: the cue drawn back PULL_MAX (m, on the table)
// gives MAX_SPEED, none MIN_SPEED, linearly between; a pull under
// MIN_PULL on release strikes nothing. The stick drawn while aiming is
// drawn back by the pull of the speed set.
export const PULL_MAX = 0.35;
const MIN_PULL = 0.01;
const STRIKE_MS = 90;      // the stick's push through on release
const STICK_REACH = 0.7;   // how far behind the cue ball a press takes the stick (m)

/** The speed (m/s) of a stroke drawn back `pull` metres, in the slider's steps. */
export function speedFromPull(pull) {
  const f = Math.max(0, Math.min(1, pull / PULL_MAX));
  return Math.round((MIN_SPEED + (MAX_SPEED - MIN_SPEED) * f) * 20) / 20;
}

/** The pull (m) that gives `speed`. */
export function pullFromSpeed(speed) {
  return PULL_MAX * Math.max(0, Math.min(1, (speed - MIN_SPEED) / (MAX_SPEED - MIN_SPEED)));
}

/** Ball n of an engine state (position and on_table by ball number, as in
 *  game records): {x, y, on}, or null for a number the game does not have. */
function ballOf(st, n) {
  const p = st && st.position ? st.position[n] : null;
  return p ? { x: p[0], y: p[1], on: !!st.on_table[n] } : null;
}

const POCKET_WORDS = {
  bottom_left: 'bottom-left corner',
  side_bottom: 'bottom side',
  bottom_right: 'bottom-right corner',
  top_right: 'top-right corner',
  side_top: 'top side',
  top_left: 'top-left corner',
};

const CHOICE_WORDS = {
  shoot: 'Take the table and shoot',
  pass_back: 'Pass it back: the other player must shoot',
  accept_table: 'Accept the table and shoot',
  rerack_and_break: 'Re-rack, and I break',
  rerack_opponent_breaks: 'Re-rack, and the other player breaks again',
  respot_eight: 'Spot the 8 and play on',
  play_on: 'Play on from here',
  offender_again: 'Make the other player play again',
  replace_balls: 'Replace the balls: the other player plays again',
  concede: 'Concede the frame',
};

const PHASE_WORDS = {
  push_out_choice: 'after the push-out: take the table or pass it back',
  illegal_break_choice: 'after the illegal break: accept the table or re-rack',
  eight_on_break_choice: 'the 8 fell on the break: spot it or re-rack',
  foul_choice: 'after the foul: play on, or have the other player play again',
};

// 10-ball's choice after a ball pocketed wrongly (not the ball called, or
// not in the pocket called): the rules reuse the push-out's phase and
// choices, and the state's after_push_out (false) tells the two apart.
const WRONG_POT_WORDS = 'a ball was pocketed wrongly: shoot from here or hand the shot back';
const WRONG_POT_CHOICES = {
  shoot: 'Shoot from here',
  pass_back: 'Hand the shot back: the other player shoots again',
};

/** The choice a state offers is 10-ball's after a wrong pot. */
function wrongPotChoice(st) {
  return !!st && st.phase === 'push_out_choice' && !st.after_push_out;
}

/** The decision on offer in words ("after the push-out: ..."). */
function phaseWords(st) {
  if (wrongPotChoice(st)) return WRONG_POT_WORDS;
  return PHASE_WORDS[st.phase] || st.phase;
}

/** A choice's button text in the state `st`. */
function choiceWords(st, c) {
  if (wrongPotChoice(st) && WRONG_POT_CHOICES[c]) return WRONG_POT_CHOICES[c];
  return CHOICE_WORDS[c] || c.replace(/_/g, ' ');
}

const CALL_HOW = 'Call a ball and a pocket: aim at the ball on (the pocket nearest its line is called), or choose them under "Call ball" and "Call pocket", or press a pocket; or tick "safety".';

const GAME_NAMES = { eight_ball: '8-ball', nine_ball: '9-ball', ten_ball: '10-ball', snooker: 'Snooker', three_cushion: 'Three-cushion' };

/** The rotation games' game ball (9-ball's 9, 10-ball's 10), or null. */
function gameBall(game) {
  return game === 'nine_ball' ? 9 : game === 'ten_ball' ? 10 : null;
}

const CAROM_BALL = { white: 0, yellow: 1, red: 2 };

/** Three-cushion's count as the ball goes, from the playback's events
 *  (result-file form: carom balls are "white", "yellow", "red"): the
 *  cushions the struck ball touched before its first contact with the
 *  second object ball, and the object balls it touched, in order. The
 *  rules count the same way (docs/rules.md, "Three-cushion"). */
export function caromCount(events, struck, count = { cushions: 0, hit: [], done: false }) {
  for (const e of events) {
    if (count.done) break;
    const balls = (e.balls || []).map((id) => CAROM_BALL[id]);
    if (e.type === 'ball_cushion' && balls[0] === struck) {
      count.cushions += 1;
    } else if (e.type === 'ball_ball' && balls.includes(struck)) {
      const other = balls[0] === struck ? balls[1] : balls[0];
      if (other != null && other !== struck && !count.hit.includes(other)) {
        count.hit.push(other);
        if (count.hit.length === 2) count.done = true;
      }
    }
  }
  return count;
}

/** The live count in words: "2 cushions", "3 cushions · red, then yellow". */
/** A shot's ruling in a word or two: "Point", "No point", "Foul: no point". */
function caromCall(ruling) {
  const k = ruling.carom || {};
  if (k.point) return 'Point';
  if (ruling.fouls && ruling.fouls.length) return 'Foul: no point';
  return 'No point';
}

function countWords(c) {
  const n = `${c.cushions} cushion${c.cushions === 1 ? '' : 's'}`;
  if (!c.hit.length) return n;
  return `${n} · ${c.hit.map(caromName).join(', then ')}`;
}

/** The ball number of an event's ball id (the games' scenarios name
 *  balls "cue", "1", "2", ..., carom balls "white", "yellow", "red"). */
function numberOfId(id) {
  if (id === 'cue') return 0;
  if (id in CAROM_BALL) return CAROM_BALL[id];
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

const SOUND_OF = { ball_ball: 'ball', ball_cushion: 'cushion', ball_pocket: 'pocket', cue_strike: 'cue' };

/** The #power slider's value is the cue speed in m/s. */
export function speedFromPower(p) {
  const v = Number(p);
  if (!Number.isFinite(v)) return DEFAULT_SPEED;
  return Math.max(MIN_SPEED, Math.min(MAX_SPEED, v));
}

export function powerFromSpeed(s) {
  return Math.max(MIN_SPEED, Math.min(MAX_SPEED, s));
}

function message(e) {
  if (e && typeof e.message === 'string') return e.message;
  return String(e);
}

function linkText(r) {
  if (typeof r === 'string') return r;
  return r && typeof r.link === 'string' ? r.link : '';
}

function normDeg(phi) {
  let p = phi % 360;
  if (p < 0) p += 360;
  return p;
}

function $(id) { return document.getElementById(id); }

export class GameUI {
  constructor(E) {
    this.E = E;
    this.g = null;
    this.table = null;
    this.R = E.defaults.ball.radius;
    this.st = null;
    this.players = ['human', 'club'];
    this.config = null;
    this.aim = { phi: 0, speed: DEFAULT_SPEED, theta: 0, a: 0, b: 0 };
    this.override = { ball: null, pocket: null, nominate: null };
    this.placePos = null;   // where the cue ball will be placed before the shot
    this.drag = null;       // {kind: 'cue' | 'aim', id, dx, dy, x, y, ok, reason}
    this.stroke = null;     // the drag-back stroke: {id, from, pull, speed0}
    this.strike = null;     // the stick pushed through after a stroke: {t0, pull}
    this.aimHeld = false;   // a press fixed the aim: hovering no longer moves it
    this.anim = null;
    this.thinking = false;
    this.reqId = 0;
    this.worker = null;
    this.log = [];
    this.rafPending = false;
    this.shareNote = '';
    this.online = null;     // online play (online.js), or null

    this.canvas = $('table');
    this.view = new TableView(this.canvas);
    this.sounds = new Sounds();
    this.orient = new Map();  // ball n -> its orientation, for drawing (draw.js rotate)
    this.bindSound();
    this.bindControls();
    this.bindCanvas();
    this.bindTip();
    this.layoutObserver = new ResizeObserver(() => this.layout());
    this.layoutObserver.observe($('table-area'));
    window.addEventListener('resize', () => this.layout());
  }

  // ---- public (app.js and the test hooks) ----

  busy() { return !!this.anim || this.thinking || !!this.strike; }

  state() {
    if (!this.g) return null;
    try {
      return this.g.state();
    } catch (e) {
      this.showError(message(e));
      return null;
    }
  }

  /** Plays an action for the seat to act; returns the reply or {error}. */
  act(action) {
    if (!this.g) return { error: 'no game' };
    if (this.busy()) return { error: 'the page is busy (a shot is running or the AI is thinking)' };
    return this.doAct(action);
  }

  /** Starts a new game; config as E.newGame. Returns true on success. */
  newGame(config) {
    let g;
    try {
      g = this.E.newGame(config);
    } catch (e) {
      this.showError(`Cannot start the game: ${message(e)}`);
      return false;
    }
    this.config = { ...config };
    this.install(g);
    return true;
  }

  /** Opens a game from a link; with shot = k, replays action k's shot.
   *  Returns true, or the reason the link was refused. */
  openLink(link, shot) {
    let g;
    try {
      g = this.E.gameFromLink(link);
    } catch (e) {
      this.showError(`Cannot open the link: ${message(e)}`);
      return message(e);
    }
    this.config = null;
    const replay = shot != null && Number.isInteger(shot);
    this.install(g, { deferAI: replay });
    if (replay) {
      const entry = this.log.find((x) => x.index === shot && x.kind === 'shoot');
      if (entry) {
        this.replay(entry.index);
      } else {
        this.showError(`The link has no shot ${shot}`);
        this.maybeAI();
      }
    }
    return true;
  }

  /** The game's physics (its record's "physics"), or null. */
  physics() {
    if (!this.g) return null;
    try {
      return this.g.record().physics || null;
    } catch (e) {
      return null;
    }
  }

  link() {
    if (!this.g) return '';
    try {
      return linkText(this.g.link());
    } catch (e) {
      this.showError(message(e));
      return '';
    }
  }

  // ---- game set-up ----

  install(g, opts = {}) {
    // a game of its own leaves online play; an online game comes with it
    if (this.online && this.online !== opts.online) this.online.leave();
    this.online = opts.online || null;
    this.cancelAI();
    this.stopAnimation();
    this.stroke = null;
    this.strike = null;
    if (this.g) {
      try { this.g.free(); } catch (e) { /* already gone */ }
    }
    this.g = g;
    this.clearError();
    this.shareNote = '';
    try {
      this.table = g.table();
      this.st = g.state();
    } catch (e) {
      this.showError(message(e));
      return;
    }
    this.R = this.table.ball_radius;
    this.players = this.st.players || this.players;
    this.orient = new Map();
    this.view.setTable(this.table);
    this.rebuildLog();
    this.newTurn(true);
    this.layout();
    this.updatePanel();
    this.requestRender();
    if (!opts.deferAI) this.maybeAI();
  }

  rebuildLog() {
    this.log = [];
    let rec = null;
    try {
      rec = this.g.record();
    } catch (e) {
      this.showError(`Cannot read the game record: ${message(e)}`);
    }
    if (rec && Array.isArray(rec.actions)) {
      let before = rec.start;
      rec.actions.forEach((a, i) => {
        const kind = a.action && a.action.type === 'place_cue_ball' ? 'place'
          : a.action && a.action.type === 'decide' ? 'decide' : 'shoot';
        const entry = { index: i, player: a.player, kind, ruling: a.ruling || {}, action: a.action };
        if (kind === 'shoot' && before && before.on_table) {
          entry.numbers = before.on_table.map((on, n) => (on ? n : -1)).filter((n) => n >= 0);
        }
        this.log.push(entry);
        before = a.after;
      });
    }
    this.renderLog();
  }

  seatName(seat) {
    const p = this.players[seat];
    const human = this.players.filter((x) => x === 'human').length;
    if (p === 'human') return human === 2 ? `Player ${seat + 1}` : `Player ${seat + 1} (you)`;
    return `Player ${seat + 1} (${p} AI)`;
  }

  shortName(seat) {
    const p = this.players[seat];
    if (p === 'human') return `Player ${seat + 1}`;
    return `${p[0].toUpperCase()}${p.slice(1)} AI`;
  }

  // ---- the turn ----

  legal() { return (this.st && this.st.legal) || {}; }

  /** A shot is due: legal now, or once the cue ball that must be placed is placed. */
  shotDue() {
    const legal = this.legal();
    return !!legal.shoot || (!!legal.must_place && !!legal.place && legal.place !== 'none');
  }

  /** The coming shot carries a call (8-ball, 10-ball): now, or after the placement. */
  callDue() {
    const legal = this.legal();
    if (legal.call) return true;
    const calling = this.st.game === 'eight_ball' || this.st.game === 'ten_ball';
    return !legal.shoot && this.shotDue() && calling && this.st.phase === 'shot';
  }

  /** The rotation games' ball on: the lowest-numbered object ball on the
   *  table (also while a choice is due, when the state lists no targets). */
  lowestBall() {
    const on = this.st ? this.st.on_table : [];
    for (let n = 1; n < on.length; n++) if (on[n]) return n;
    return null;
  }

  /** Every shot but the break must be called or declared safe (10-ball). */
  callRequired() { return !!this.st && this.st.game === 'ten_ball' && this.callDue(); }

  /** The coming shot may be a push-out (9-ball, 10-ball): now, or after the placement. */
  pushOutDue() {
    const legal = this.legal();
    if (legal.push_out) return true;
    return !legal.shoot && this.shotDue() && gameBall(this.st.game) != null && !!this.st.push_out_allowed;
  }

  /** The coming shot is declared a safety or a push-out: it has no call. */
  uncalled() {
    return (this.callDue() && $('safety').checked) || (this.pushOutDue() && $('push-out').checked);
  }

  /** The balls a call may name: the targets (8-ball: the player's group);
   *  in 10-ball any object ball on the table (the lowest is still hit first). */
  callable() {
    if (this.st && this.st.game === 'ten_ball') return this.objectBalls().map((b) => b.n).sort((p, q) => p - q);
    return this.legal().targets || [];
  }

  snooker() { return !!this.st && this.st.game === 'snooker'; }

  carom() { return !!this.st && this.st.game === 'three_cushion'; }

  /** The ball the player to act strikes: the cue ball (0); in
   *  three-cushion the player's own ball (the state's carom_figures). */
  cueN() {
    if (this.carom() && this.st.carom_figures) return this.st.carom_figures.cue_ball;
    return 0;
  }

  /** The decisions on offer now (snooker's concede, which a shooter may
   *  always take, aside while a shot is due). */
  decisions() {
    const legal = this.legal();
    const list = legal.choices || [];
    return legal.shoot || this.shotDue() ? list.filter((c) => c !== 'concede') : list;
  }

  /** Snooker: the coming shot nominates a ball: a colour after a red
   *  (must_nominate), or a free ball may be taken. Otherwise a nomination
   *  could only name a ball that is on anyway, and the page leaves it out. */
  nominateDue() {
    if (!this.snooker() || !this.shotDue()) return false;
    const legal = this.legal();
    if (!Array.isArray(legal.nominate) || legal.nominate.length === 0) return false;
    return !!legal.must_nominate || !!(this.st.snooker && this.st.snooker.free_ball);
  }

  /** Snooker: the ball the shot nominates: the player's choice, else by
   *  the aim: the first ball the aim line hits when it is one that may be
   *  nominated and needs to be (a colour after a red; a free ball: a ball
   *  not otherwise on). {ball, auto}, ball null for none. */
  currentNomination(geo) {
    if (!this.nominateDue()) return null;
    const legal = this.legal();
    const allowed = legal.nominate || [];
    const o = this.override.nominate;
    if (o != null && allowed.includes(o)) return { ball: o, auto: false };
    const hit = geo && geo.hit ? geo.hit.n : null;
    if (hit == null || !allowed.includes(hit)) return { ball: null, auto: true };
    if (legal.must_nominate) return { ball: hit, auto: true };
    const on = (this.st.snooker_figures && this.st.snooker_figures.balls_on) || [];
    return { ball: on.includes(hit) ? null : hit, auto: true };
  }

  humanToAct() {
    return !!this.st && this.st.phase !== 'game_over' && this.players[this.st.player] === 'human' &&
      (!this.online || this.online.mayAct(this.st));
  }

  canAct() { return !!this.g && !this.busy() && this.humanToAct(); }

  objectBalls() {
    const out = [];
    if (!this.st) return out;
    const cue = this.cueN();
    this.st.position.forEach((p, n) => {
      if (n !== cue && this.st.on_table[n]) out.push({ n, x: p[0], y: p[1] });
    });
    return out;
  }

  cuePos() {
    if (this.placePos) return this.placePos;
    const c = ballOf(this.st, this.cueN());
    if (c && c.on) return { x: c.x, y: c.y };
    return null;
  }

  /** Sets up the controls for the turn after an action. */
  newTurn(fresh) {
    const legal = this.legal();
    this.override = { ball: null, pocket: null, nominate: null };
    $('safety').checked = false;
    $('push-out').checked = false;
    this.drag = null;
    this.stroke = null;
    this.aimHeld = false;
    this.placePos = null;
    if (legal.place && legal.place !== 'none') this.placePos = this.defaultPlacement(legal);
    if (!this.st) return;
    if (this.st.phase === 'break_shot') {
      this.aim.speed = this.snooker() ? SNOOKER_BREAK_SPEED : this.carom() ? DEFAULT_SPEED : BREAK_SPEED;
    } else if (fresh || this.aim.speed > 6.5) {
      this.aim.speed = DEFAULT_SPEED;
    }
    this.aim.theta = 0;
    this.aim.a = 0;
    this.aim.b = 0;
    this.aimAtDefault();
    this.syncControls();
  }

  defaultPlacement(legal) {
    const c = ballOf(this.st, 0);
    const tryAt = (x, y) => {
      try {
        return this.g.checkPlacement(x, y).ok;
      } catch (e) {
        return false;
      }
    };
    if (c && c.on && !legal.must_place) return { x: c.x, y: c.y };
    const t = this.table;
    if (legal.place === 'd' && t.snooker) {
      // in the D: on the baulk line between the brown and the yellow
      // spots (the usual break-off), else the D's centre line
      const m = t.snooker;
      for (const [dx, dy] of [[0, -0.18], [0, 0.18], [-0.15, -0.1], [-0.15, 0.1], [-0.2, 0]]) {
        if (tryAt(m.d_centre[0] + dx, m.d_centre[1] + dy)) return { x: m.d_centre[0] + dx, y: m.d_centre[1] + dy };
      }
    }
    const hs = t.head_spot || [t.length / 4, t.width / 2];
    if (tryAt(hs[0], hs[1])) return { x: hs[0], y: hs[1] };
    // a spiral of candidates around the head spot, kitchen first
    const step = this.R * 1.5;
    for (let ring = 1; ring < 40; ring++) {
      for (let k = 0; k < 8 * ring; k++) {
        const a = (2 * Math.PI * k) / (8 * ring);
        const x = hs[0] - Math.abs(Math.cos(a)) * ring * step * (legal.place === 'kitchen' ? 1 : Math.sign(Math.cos(a)) || 1);
        const y = hs[1] + Math.sin(a) * ring * step;
        if (tryAt(x, y)) return { x, y };
      }
    }
    return { x: hs[0], y: hs[1] };
  }

  /** Aims at the nearest legal target (the apex ball on the break). */
  aimAtDefault() {
    const cue = this.cuePos();
    if (!cue) return;
    const legal = this.legal();
    // three-cushion: the break is played at the red (2), directly
    const targets = new Set(this.carom() ? (this.st.phase === 'break_shot' ? [2] : []) : legal.targets || []);
    let best = null;
    let bestD = Infinity;
    for (const b of this.objectBalls()) {
      if (targets.size && !targets.has(b.n)) continue;
      const d = Math.hypot(b.x - cue.x, b.y - cue.y);
      if (d < bestD) { bestD = d; best = b; }
    }
    if (best) this.aim.phi = normDeg((Math.atan2(best.y - cue.y, best.x - cue.x) * 180) / Math.PI);
  }

  setAimToward(p) {
    const cue = this.cuePos();
    if (!cue) return;
    const dx = p.x - cue.x;
    const dy = p.y - cue.y;
    if (Math.hypot(dx, dy) < 1e-4) return;
    this.aim.phi = normDeg((Math.atan2(dy, dx) * 180) / Math.PI);
    this.syncControls();
    this.requestRender();
  }

  geometry() {
    const cue = this.cuePos();
    if (!cue) return null;
    return aimGeometry(this.table, cue, this.aim.phi, this.objectBalls(), this.R);
  }

  /** The call the shot will carry (8-ball, 10-ball): overrides, else from
   *  the aim (the target the aim line reaches first, into the pocket
   *  nearest the direction it is sent); none for a safety or a push-out. */
  currentCall(geo) {
    const legal = this.legal();
    if (!this.callDue() || this.uncalled()) return null;
    const targets = legal.targets || [];
    let ball = this.override.ball;
    if (ball != null && !this.callable().includes(ball)) ball = null;
    const ballAuto = ball == null;
    if (ball == null && geo && geo.hit && targets.includes(geo.hit.n)) ball = geo.hit.n;
    let pocket = this.override.pocket;
    const pocketAuto = pocket == null;
    if (ball == null) return { ball: null, pocket, ballAuto, pocketAuto };
    if (pocket == null) {
      const b = this.st.position[ball];
      let dir;
      if (geo && geo.hit && geo.hit.n === ball) dir = geo.objectDir;
      else {
        const cue = this.cuePos() || { x: b[0], y: b[1] };
        const l = Math.hypot(b[0] - cue.x, b[1] - cue.y) || 1;
        dir = { x: (b[0] - cue.x) / l, y: (b[1] - cue.y) / l };
      }
      let bestCos = -2;
      this.table.pockets.forEach((p, i) => {
        const px = p.centre[0] - b[0];
        const py = p.centre[1] - b[1];
        const l = Math.hypot(px, py) || 1;
        const c = (px * dir.x + py * dir.y) / l;
        if (c > bestCos) { bestCos = c; pocket = i; }
      });
    }
    return { ball, pocket, ballAuto, pocketAuto };
  }

  shotAction() {
    const legal = this.legal();
    const s = this.aim;
    // the records' form of an action (src/io/game_json.hpp), every field given
    const action = {
      type: 'shoot',
      strike: { speed: s.speed, phi: s.phi, theta: s.theta, a: s.a, b: s.b },
      call: null,
      safety: false,
      push_out: false,
    };
    // a safety or a push-out carries no call (the rules refuse one with it)
    if (legal.push_out && $('push-out').checked) {
      action.push_out = true;
    } else if (legal.call && $('safety').checked) {
      action.safety = true;
    } else if (legal.call) {
      const call = this.currentCall(this.geometry());
      if (call && call.ball != null && call.pocket != null) action.call = { ball: call.ball, pocket: call.pocket };
    }
    const nom = this.currentNomination(this.geometry());
    if (nom && nom.ball != null) action.nominate = nom.ball;
    return action;
  }

  shoot() {
    if (!this.canAct()) return;
    let legal = this.legal();
    if (!this.shotDue()) {
      this.showError(legal.choices && legal.choices.length ? 'Choose one of the options first.' : 'No shot is due now.');
      return;
    }
    if (this.placePos && legal.place && legal.place !== 'none') {
      const c = ballOf(this.st, 0);
      const moved = !c || !c.on || c.x !== this.placePos.x || c.y !== this.placePos.y;
      if (legal.must_place || moved) {
        const keepAim = { ...this.aim };
        const r = this.doAct({ type: 'place_cue_ball', position: [this.placePos.x, this.placePos.y] }, { keepAim: true });
        if (r.error) return;
        this.aim = keepAim;
        legal = this.legal();
      }
    }
    if (!legal.shoot) {
      this.showError('No shot is due now.');
      return;
    }
    const action = this.shotAction();
    if (legal.must_nominate && action.nominate == null) {
      this.showError('Nominate a colour: click it, aim at it, or choose it under "Nominate".');
      this.updatePanel();
      return;
    }
    const r = this.doAct(action);
    // 10-ball: the rules refuse a shot with no call and no safety; the
    // page shows their reason and how to make a call
    if (r && r.error && this.callRequired() && !action.call && !action.safety && !action.push_out) {
      this.showError(`${r.error}. ${CALL_HOW}`);
    }
  }

  decide(choice) {
    if (!this.canAct()) return;
    this.doAct({ type: 'decide', choice });
  }

  /** g.act with logging, animation and the AI's turn after it. */
  doAct(action, opts = {}) {
    if (this.online && !opts.remote && !this.online.mayAct(this.st)) {
      this.showError('It is not your turn.');
      return { error: 'not your turn' };
    }
    let reply;
    try {
      reply = this.g.act(action);
    } catch (e) {
      this.showError(message(e));
      this.updatePanel();
      this.requestRender();
      return { error: message(e) };
    }
    if (!reply || typeof reply !== 'object') return { error: 'no reply' };
    if (reply.error) {
      this.showError(reply.error);
      return reply;
    }
    this.clearError();
    this.shareNote = '';
    if (this.online && !opts.remote) this.online.played(reply.index, reply.executed);
    const entry = {
      index: reply.index,
      player: reply.player,
      kind: reply.kind,
      ruling: reply.ruling || {},
      numbers: reply.numbers,
      action: reply.executed,
    };
    const prevPhase = this.st ? this.st.phase : '';
    this.st = reply.state;
    const addLog = () => {
      this.log.push(entry);
      this.renderLog();
    };
    // a shot's ruling is shown once its balls have stopped
    if (reply.kind !== 'shoot') addLog();
    const settle = () => {
      if (reply.kind === 'shoot') addLog();
      if (opts.keepAim && reply.kind === 'place') {
        const legal = this.legal();
        this.placePos = null;
        if (legal.place && legal.place !== 'none') this.placePos = this.defaultPlacement(legal);
        this.syncControls();
      } else {
        this.newTurn(prevPhase === 'break_shot' && this.st.phase !== 'break_shot');
      }
      this.updatePanel();
      this.requestRender();
      this.maybeAI();
    };
    if (reply.kind === 'shoot') {
      this.animate(reply.index, reply.numbers, settle, false, entry.ruling);
    } else {
      settle();
    }
    this.updatePanel();
    return reply;
  }

  undo() {
    if (!this.g || this.anim) return;
    if (this.online) {
      this.showError('An online game has no undo.');
      return;
    }
    // back to before the last shot taken by a human (the AI's replies go too)
    let target = -1;
    for (let i = this.log.length - 1; i >= 0; i--) {
      const e = this.log[i];
      if (e.kind === 'shoot' && this.players[e.player] === 'human') { target = e.index; break; }
    }
    if (target < 0) {
      this.showError('There is no shot of yours to undo.');
      return;
    }
    this.cancelAI();
    try {
      this.g.undoTo(target);
      this.st = this.g.state();
    } catch (e) {
      this.showError(message(e));
      return;
    }
    this.clearError();
    this.rebuildLog();
    this.newTurn(false);
    this.updatePanel();
    this.requestRender();
    this.maybeAI();
  }

  // ---- the AI ----

  ensureWorker() {
    if (this.worker) return this.worker;
    const w = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    w.addEventListener('message', (ev) => this.onWorker(ev.data));
    w.addEventListener('error', (ev) => {
      if (ev && ev.preventDefault) ev.preventDefault();
      this.thinking = false;
      this.worker = null;
      try { w.terminate(); } catch (e) { /* gone */ }
      this.showError(`The AI worker failed${ev && ev.message ? `: ${ev.message}` : ''}`);
      this.updatePanel();
    });
    w.addEventListener('messageerror', () => {
      this.thinking = false;
      this.showError('The AI worker sent a message that could not be read');
      this.updatePanel();
    });
    this.worker = w;
    return w;
  }

  maybeAI() {
    if (!this.g || !this.st || this.anim || this.thinking) return;
    if (this.st.phase === 'game_over') return;
    const level = this.players[this.st.player];
    if (!level || level === 'human') return;
    let link;
    try {
      link = linkText(this.g.link());
    } catch (e) {
      this.showError(message(e));
      return;
    }
    const id = ++this.reqId;
    this.thinking = true;
    this.updatePanel();
    try {
      this.ensureWorker().postMessage({ id, link, level });
    } catch (e) {
      this.thinking = false;
      this.showError(`Cannot start the AI: ${message(e)}`);
      this.updatePanel();
    }
  }

  onWorker(data) {
    if (!data || data.id !== this.reqId || !this.thinking) return;
    this.thinking = false;
    if (data.error) {
      this.showError(`The AI failed: ${data.error}`);
      this.updatePanel();
      return;
    }
    this.doAct(data.action);
  }

  cancelAI() {
    this.reqId++;
    if (this.thinking && this.worker) {
      // a long search cannot be interrupted: start a fresh worker next time
      try { this.worker.terminate(); } catch (e) { /* gone */ }
      this.worker = null;
    }
    this.thinking = false;
  }

  // ---- animation ----

  animate(index, numbers, done, replay = false, ruling = null) {
    let pb;
    try {
      pb = this.g.shotPlayback(index);
    } catch (e) {
      this.showError(`Cannot play the shot back: ${message(e)}`);
      done();
      return;
    }
    this.anim = { pb, numbers: numbers || [], t: 0, last: null, frame: null, done, index, gone: new Map(), replay: !!replay, heard: 0 };
    // three-cushion: the struck ball's cushions counted as the events come
    const k = ruling && ruling.carom;
    if (this.carom() && k) {
      this.anim.carom = { struck: k.cue_ball, seen: 0, count: caromCount([], k.cue_ball), ruling };
      this.showCount(this.anim.carom);
    }
    try {
      this.anim.frame = pb.frame(0);
    } catch (e) {
      this.finishAnimation(e);
      return;
    }
    this.updatePanel();
    this.requestRender();
  }

  stepAnimation(now) {
    const a = this.anim;
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
      this.finishAnimation(e);
      return;
    }
    // balls that just dropped: fade them into their pocket
    if (prev) {
      a.frame.balls.forEach((b, i) => {
        if (!b[2] && prev.balls[i] && prev.balls[i][2] && !a.gone.has(i)) {
          // Off the table (place 2): it fades where it left, from the
          // height it had; into a pocket: it slides to the pocket's centre.
          const off = b.length > 8 && b[9] === 2;
          const p = off ? null : this.nearestPocket(b[0], b[1]);
          const z = prev.balls[i].length > 8 ? prev.balls[i][8] : 0;
          a.gone.set(i, { x: b[0], y: b[1], z: off ? z : 0, t: a.t, px: p ? p.centre[0] : b[0], py: p ? p.centre[1] : b[1] });
        }
      });
    }
    this.soundEvents(a, prev);
    this.roll(a, prev);
    if (a.carom && a.frame.events > a.carom.seen) {
      const evs = a.pb.events(a.carom.seen).events || [];
      a.carom.seen = a.frame.events;
      caromCount(evs, a.carom.struck, a.carom.count);
      this.showCount(a.carom);
    }
    const fading = [...a.gone.values()].some((g) => a.t - g.t < FADE);
    if (a.frame.at_rest && !fading) this.finishAnimation(null);
  }

  /** The sounds of the events since the last frame, each as loud as its
   *  impact speed (from this frame's and the previous frame's states). */
  soundEvents(a, prev) {
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
    this.sounds.newFrame();
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
    for (const x of list) this.sounds.play(x.kind, x.speed, x.dt);
  }

  /** Turns the pool balls' orientations by their spins over the frame's
   *  time step (the mean of the spins at its two ends). Drawing only. */
  roll(a, prev) {
    if (this.snooker() || this.carom()) return;
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
      const o = this.orientation(num);
      rotate(o, (w0[3 * i] + w[3 * i]) / 2, (w0[3 * i + 1] + w[3 * i + 1]) / 2, (w0[3 * i + 2] + w[3 * i + 2]) / 2, dt);
    }
  }

  orientation(n) {
    let o = this.orient.get(n);
    if (!o) {
      o = identityOrientation();
      this.orient.set(n, o);
    }
    return o;
  }

  nearestPocket(x, y) {
    let best = null;
    let bestD = Infinity;
    for (const p of this.table.pockets) {
      const d = Math.hypot(p.centre[0] - x, p.centre[1] - y);
      if (d < bestD) { bestD = d; best = p; }
    }
    return best;
  }

  /** Three-cushion's live count in the score panel; once the balls stop,
   *  the engine's ruling: its cushions and point or no point. */
  showCount(c, final = false) {
    const el = $('carom-cushions');
    const call = $('carom-call');
    if (!el || !call) return;
    const k = c.ruling.carom;
    if (final) {
      el.textContent = countWords({ cushions: k.cushions, hit: k.hit || [] });
      call.textContent = caromCall(c.ruling);
      call.className = k.point ? 'point' : 'no-point';
    } else {
      el.textContent = countWords(c.count);
      call.textContent = c.count.done ? (c.count.cushions >= 3 ? 'three cushions first…' : 'too few cushions…') : 'running…';
      call.className = '';
    }
  }

  finishAnimation(err) {
    const a = this.anim;
    if (!a) return;
    this.anim = null;
    if (a.carom) {
      // what the page counted as the ball went (the tests compare it with
      // the engine's ruling)
      this.lastCount = { cushions: a.carom.count.cushions, hit: [...a.carom.count.hit] };
      this.showCount(a.carom, true);
    }
    try { a.pb.free(); } catch (e) { /* gone */ }
    if (err) this.showError(`Playback: ${message(err)}`);
    a.done();
    this.updatePanel();
    this.requestRender();
  }

  stopAnimation() {
    const a = this.anim;
    if (!a) return;
    this.anim = null;
    try { a.pb.free(); } catch (e) { /* gone */ }
  }

  replay(index) {
    if (!this.g || this.busy()) return;
    const entry = this.log.find((e) => e.index === index && e.kind === 'shoot');
    if (!entry) return;
    this.clearError();
    this.animate(index, entry.numbers, () => {
      this.updatePanel();
      this.requestRender();
      this.maybeAI();
    }, true, entry.ruling);
  }

  // ---- drawing ----

  layout() {
    if (!this.table) return;
    const area = $('table-area');
    if (!area || area.offsetParent === null) return;  // hidden tab
    const top = this.canvas.getBoundingClientRect().top + window.scrollY;
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
    if (this.view.fit(maxW, maxH, portrait)) this.requestRender();
  }

  requestRender() {
    if (this.rafPending) return;
    this.rafPending = true;
    requestAnimationFrame((now) => {
      this.rafPending = false;
      try {
        this.frame(now);
      } catch (e) {
        this.anim = null;
        this.showError(`Drawing failed: ${message(e)}`);
      }
    });
  }

  frame(now) {
    if (this.strike && performance.now() - this.strike.t0 >= STRIKE_MS) {
      // the stick has gone through: the shot
      this.strike = null;
      this.shoot();
    }
    if (this.anim) this.stepAnimation(now);
    const scene = this.scene();
    this.view.render(scene);
    if (scene.call) this.autoCallLabels(scene.call);
    this.nominateLabel(scene.nominated);
    if (this.anim || this.strike) this.requestRender();
  }

  /** The "auto" entries of the call selects name what the aim picks. */
  autoCallLabels(call) {
    const bs = $('call-ball');
    const ps = $('call-pocket');
    if (bs.options.length) {
      const t = call.ballAuto ? (call.ball != null ? `auto: ball ${call.ball}` : 'auto: none') : 'auto (aim)';
      if (bs.options[0].text !== t) bs.options[0].text = t;
    }
    if (ps.options.length) {
      const p = call.pocket != null ? this.table.pockets[call.pocket] : null;
      const t = call.pocketAuto ? (p ? `auto: ${POCKET_WORDS[p.name] || p.name}` : 'auto: none') : 'auto';
      if (ps.options[0].text !== t) ps.options[0].text = t;
    }
  }

  /** The "auto" entry of the nominate select names what the aim picks. */
  nominateLabel(nom) {
    const sel = $('nominate');
    if (!sel || !sel.options.length || $('nominate-box').hidden) return;
    const t = nom && nom.auto ? (nom.ball != null ? `auto: ${snookerName(nom.ball)}` : 'auto: none') : 'auto (aim)';
    if (sel.options[0].text !== t) sel.options[0].text = t;
    const v = this.override.nominate == null ? '' : String(this.override.nominate);
    if (sel.value !== v) sel.value = v;
  }

  scene() {
    const scene = { balls: [], R: this.R, kitchen: false, d: false, aim: null, call: null, nominated: null, place: null, banner: null };
    if (!this.st) return scene;
    if (this.anim && this.anim.frame) {
      const { frame, numbers, gone, t } = this.anim;
      frame.balls.forEach((b, i) => {
        if (b[2]) {
          // z (b[8]) only when a ball of the frame is off the cloth
          const n = numbers[i] ?? i;
          scene.balls.push({ n, x: b[0], y: b[1], z: b.length > 8 ? b[8] : 0, o: this.orientation(n) });
        } else if (gone.has(i)) {
          const g = gone.get(i);
          const f = (t - g.t) / FADE;
          if (f < 1) {
            const k = Math.min(1, f * 1.5);
            const n = numbers[i] ?? i;
            scene.balls.push({ n, x: g.x + (g.px - g.x) * k, y: g.y + (g.py - g.y) * k, z: g.z, alpha: 1 - f, scale: 1 - 0.35 * f, o: this.orientation(n) });
          }
        }
      });
      const cue = this.anim.carom ? this.anim.carom.struck : 0;
      scene.balls.sort((p, q) => (p.n === cue) - (q.n === cue));
      if (this.anim.carom) scene.counter = { text: countWords(this.anim.carom.count) };
      return scene;
    }
    this.st.position.forEach((p, n) => {
      if (this.st.on_table[n]) scene.balls.push({ n, x: p[0], y: p[1], o: this.orientation(n) });
    });
    const legal = this.legal();
    const canAct = this.canAct();
    const placing = canAct && legal.place && legal.place !== 'none';
    if (placing) {
      scene.kitchen = legal.place === 'kitchen';
      scene.d = legal.place === 'd';
      if (this.drag && this.drag.kind === 'cue') {
        scene.place = { x: this.drag.x, y: this.drag.y, ok: this.drag.ok, reason: this.drag.reason };
      } else if (this.placePos) {
        scene.place = { x: this.placePos.x, y: this.placePos.y, ok: true };
      }
    }
    if ((canAct || this.strike) && this.shotDue() && this.cuePos() && !(this.drag && this.drag.kind === 'cue')) {
      const geo = this.geometry();
      scene.aim = {
        cue: this.cuePos(),
        phi: this.aim.phi,
        theta: this.aim.theta,
        geo,
        power: (this.aim.speed - MIN_SPEED) / (MAX_SPEED - MIN_SPEED),
        pull: this.stickPull(),
        a: this.aim.a,
        b: this.aim.b,
        R: this.R,
        stroke: this.stroke ? `${this.aim.speed.toFixed(2)} m/s` : null,
        stick: true,
      };
      scene.call = this.currentCall(geo);
      scene.nominated = this.currentNomination(geo);
    }
    if (this.st.phase === 'game_over') {
      scene.banner = this.st.winner >= 0 ? `${this.shortName(this.st.winner)} wins` : 'Draw';
    }
    return scene;
  }

  /** How far the stick is drawn back from the cue ball (m): the stroke's
   *  pull while one is drawn, going through the ball after the release,
   *  else the pull of the speed set. */
  stickPull() {
    if (this.stroke) return this.stroke.pull;
    if (this.strike) {
      const f = Math.min(1, (performance.now() - this.strike.t0) / STRIKE_MS);
      return this.strike.pull * (1 - f * f) - 0.004 * f;
    }
    return pullFromSpeed(this.aim.speed);
  }

  // ---- the panel ----

  syncControls() {
    const a = this.aim;
    $('power').value = String(powerFromSpeed(a.speed));
    $('power-out').textContent = `${a.speed.toFixed(2)} m/s`;
    $('elevation').value = String(a.theta);
    $('elevation-out').textContent = `${Math.round(a.theta)}°`;
    const phiInput = $('phi');
    if (document.activeElement !== phiInput) phiInput.value = a.phi.toFixed(2);
    $('tip-out').textContent = this.tipWords();
    this.drawTip();
  }

  tipWords() {
    const { a, b } = this.aim;
    if (Math.abs(a) < 0.005 && Math.abs(b) < 0.005) return 'centre';
    const parts = [];
    if (Math.abs(b) >= 0.005) parts.push(`${b > 0 ? 'follow' : 'draw'} ${Math.abs(b).toFixed(2)}`);
    if (Math.abs(a) >= 0.005) parts.push(`${a > 0 ? 'right' : 'left'} ${Math.abs(a).toFixed(2)}`);
    return parts.join(', ');
  }

  updatePanel() {
    const st = this.st;
    const legal = this.legal();
    const canAct = this.canAct();
    $('thinking').hidden = !this.thinking;
    this.canvas.classList.toggle('waiting', this.busy());
    this.canvas.classList.toggle('placing', canAct && !!legal.place && legal.place !== 'none');
    $('shoot').disabled = !(canAct && this.shotDue());
    $('undo').disabled = !this.g || this.busy() || !!this.online || !this.log.some((e) => e.kind === 'shoot' && this.players[e.player] === 'human');
    $('share').disabled = !this.g;

    // call, safety and push-out
    const callBox = $('call-box');
    callBox.hidden = !(canAct && this.shotDue() && this.callDue());
    if (!callBox.hidden) this.fillCallSelects();
    $('push-out-box').hidden = !(canAct && this.shotDue() && this.pushOutDue());
    const nomBox = $('nominate-box');
    nomBox.hidden = !(canAct && this.nominateDue());
    if (!nomBox.hidden) this.fillNominateSelect();
    const concede = $('concede');
    concede.hidden = !(canAct && this.shotDue() && (legal.choices || []).includes('concede'));

    // decisions
    const choices = $('choices');
    const list = canAct ? this.decisions() : [];
    choices.hidden = list.length === 0;
    const key = list.length ? `${phaseWords(st)}:${list.join(',')}` : '';
    if (choices.dataset.key !== key) {
      choices.dataset.key = key;
      choices.textContent = '';
      if (list.length) {
        const p = document.createElement('p');
        p.textContent = phaseWords(st);
        choices.appendChild(p);
      }
      for (const c of list) {
        const b = document.createElement('button');
        b.type = 'button';
        b.id = `choice-${c}`;
        b.dataset.choice = c;
        b.textContent = choiceWords(st, c);
        b.addEventListener('click', () => this.decide(c));
        choices.appendChild(b);
      }
    }

    // how to aim and strike, while a shot of a player on this screen is due
    const hint = $('aim-hint');
    if (hint) {
      let text = '';
      if (canAct && this.shotDue()) {
        const hover = window.matchMedia && window.matchMedia('(hover: hover)').matches;
        if (!hover) text = 'Touch the table to aim. Pull the cue back from behind the cue ball and let go to strike.';
        else if (this.aimHeld) text = 'Aim held: press on the table to aim again, Esc to aim by pointing. Drag the cue back from behind the cue ball and release to strike.';
        else text = 'Point to aim, press to hold the aim. Drag the cue back from behind the cue ball and release to strike.';
      }
      if (hint.textContent !== text) hint.textContent = text;
    }

    // status
    const turn = $('status-turn');
    const info = $('status-info');
    if (!st) {
      turn.textContent = 'No game';
      info.textContent = '';
      return;
    }
    const gameName = GAME_NAMES[st.game] || st.game;
    if (this.anim) {
      // the state is already the one after the shot: keep it for the end
      turn.textContent = `${gameName}: ${this.anim.replay ? 'replaying a shot…' : 'the balls are rolling…'}`;
      return;
    }
    this.drawTray();
    this.updateScore();
    this.updateCaromScore();
    if (st.phase === 'game_over') {
      const who = st.winner >= 0 ? `${this.seatName(st.winner)} wins` : 'Draw';
      turn.textContent = `Game over: ${who}.${st.result ? ` ${capital(st.result)}.` : ''}`;
    } else {
      const who = this.seatName(st.player);
      let what;
      if (this.thinking && this.decisions().length) what = `${gameName}: ${who} is choosing (${phaseWords(st)})…`;
      else if (this.thinking) what = `${gameName}: ${who} is thinking…`;
      else if (st.phase === 'break_shot') what = `${gameName}: ${who} to break`;
      else if (this.decisions().length) what = `${gameName}: ${who} to decide (${phaseWords(st)})`;
      else what = `${gameName}: ${who} to shoot`;
      if (!this.thinking) {
        if (legal.place === 'kitchen') what += ' — cue ball in hand behind the head string';
        else if (legal.place === 'anywhere') what += ' — cue ball in hand anywhere';
        else if (legal.place === 'd') what += ' — cue ball in hand in the D';
        if (this.carom() && st.carom_figures) what += ` — plays the ${caromName(st.carom_figures.cue_ball)}`;
      }
      turn.textContent = what;
    }
    const bits = [];
    if (st.game === 'eight_ball') {
      const g = st.group || ['none', 'none'];
      if (g[0] === 'none' && g[1] === 'none') bits.push('table open');
      else bits.push(`${this.shortName(0)}: ${g[0]}, ${this.shortName(1)}: ${g[1]}`);
    } else if (st.game === 'snooker') {
      if (st.phase !== 'game_over') bits.push(`on: ${this.ballOnWords()}`);
    } else if (st.game === 'three_cushion') {
      const k = st.carom || { score: [0, 0], innings: [0, 0] };
      bits.push(`score ${k.score[0]} – ${k.score[1]}`);
      if (k.equalizing && st.phase !== 'game_over') bits.push('the equalizing inning');
    } else {
      const lowest = this.lowestBall();
      if (lowest != null && st.phase !== 'game_over') bits.push(`ball on: ${lowest}`);
      if (st.game === 'ten_ball' && st.phase !== 'game_over') bits.push('the 10 wins when called');
      if (st.push_out_allowed && st.phase !== 'game_over') bits.push('push-out allowed');
    }
    const f = st.fouls_in_a_row || [0, 0];
    if (st.game !== 'snooker' && st.game !== 'three_cushion') bits.push(`fouls in a row: ${f[0]} – ${f[1]}`);
    bits.push(`shots: ${st.shots}`);
    if (this.shareNote) bits.push(this.shareNote);
    info.textContent = bits.join(' · ');
  }

  /** Snooker: the ball on in words. */
  ballOnWords() {
    const st = this.st;
    const k = st.snooker || {};
    const on = (st.snooker_figures && st.snooker_figures.balls_on) || [];
    let words;
    if (k.colour_on) words = 'a colour (nominate it)';
    else if (on.length && on.every((n) => n >= 1 && n <= 15)) words = 'a red';
    else if (on.length) words = on.map(snookerName).join(', ');
    else words = 'none';
    if (k.respotted_black) words += ' (re-spotted black)';
    if (k.free_ball) words += ' — free ball: any ball may be nominated';
    return words;
  }

  /** Snooker's score panel: both scores, the break, the ball on, the
   *  points remaining and the snookers each player requires. */
  updateScore() {
    const box = $('score');
    const st = this.st;
    if (!box) return;
    const snooker = !!st && st.game === 'snooker' && !!st.snooker;
    box.hidden = !snooker;
    if (!snooker) return;
    const k = st.snooker;
    const fig = st.snooker_figures || { points_remaining: 0, snookers_required: [0, 0] };
    for (const seat of [0, 1]) {
      $(`score-name-${seat}`).textContent = this.shortName(seat);
      $(`score-${seat}`).textContent = String(k.score[seat]);
      $(`score-row-${seat}`).classList.toggle('to-play', st.phase !== 'game_over' && st.player === seat);
      const need = fig.snookers_required[seat];
      $(`score-snookers-${seat}`).textContent = need > 0 ? `needs ${need} snooker${need > 1 ? 's' : ''}` : '';
    }
    $('score-break').textContent = String(k.break);
    $('score-on').textContent = st.phase === 'game_over' ? '—' : this.ballOnWords();
    $('score-remaining').textContent = String(fig.points_remaining);
    const needs = [0, 1].filter((seat) => fig.snookers_required[seat] > 0)
      .map((seat) => `${this.shortName(seat)}: ${fig.snookers_required[seat]}`);
    $('score-snookers').textContent = needs.length ? needs.join(', ') : 'none';
  }

  /** Three-cushion's score panel: each player's points, innings, general
   *  average and highest run (the state's carom part and carom_figures),
   *  the target, the run in progress. */
  updateCaromScore() {
    const box = $('carom-score');
    const st = this.st;
    if (!box) return;
    const carom = !!st && st.game === 'three_cushion' && !!st.carom;
    box.hidden = !carom;
    if (!carom) return;
    const k = st.carom;
    const fig = st.carom_figures || { cue_ball: 0, general_average: [0, 0], highest_run: [0, 0] };
    for (const seat of [0, 1]) {
      // the breaker plays the white, the other player the yellow
      const ball = seat === st.breaker ? 0 : 1;
      const dot = $(`carom-ball-${seat}`);
      dot.style.background = ball === 0 ? '#f6f3ea' : '#f2c81a';
      dot.title = caromName(ball);
      $(`carom-name-${seat}`).textContent = this.shortName(seat);
      $(`carom-points-${seat}`).textContent = String(k.score[seat]);
      $(`carom-innings-${seat}`).textContent = String(k.innings[seat]);
      $(`carom-average-${seat}`).textContent = fig.general_average[seat].toFixed(3);
      $(`carom-high-${seat}`).textContent = String(fig.highest_run[seat]);
      $(`carom-row-${seat}`).classList.toggle('to-play', st.phase !== 'game_over' && st.player === seat);
    }
    const rules = this.caromRules();
    $('carom-target').textContent = rules ? `${rules.target} points${rules.innings_limit ? `, ${rules.innings_limit} innings` : ''}` : '—';
    $('carom-run').textContent = st.phase === 'game_over' ? '—' : String(k.run);
    // the last shot's count and ruling (the live count while a shot runs)
    const last = [...this.log].reverse().find((e) => e.kind === 'shoot' && e.ruling && e.ruling.carom);
    if (last) {
      this.showCount({ ruling: last.ruling }, true);
    } else {
      $('carom-cushions').textContent = '–';
      $('carom-call').textContent = '–';
      $('carom-call').className = '';
    }
  }

  /** The game's three-cushion rules (the record's config "carom"), or null. */
  caromRules() {
    if (this.caromRulesOf === this.g) return this.caromRulesCache;
    let rules = null;
    try {
      const rec = this.g.record();
      rules = (rec.config && rec.config.carom) || null;
    } catch (e) { /* none */ }
    this.caromRulesOf = this.g;
    this.caromRulesCache = rules;
    return rules;
  }

  fillNominateSelect() {
    const sel = $('nominate');
    const list = this.legal().nominate || [];
    const key = list.join(',');
    if (sel.dataset.key !== key) {
      sel.dataset.key = key;
      sel.textContent = '';
      sel.appendChild(new Option('auto (aim)', ''));
      // the reds as one entry (any red is the same nomination in effect)
      for (const n of list) {
        if (n >= 1 && n <= 15 && list.some((m) => m >= 1 && m <= 15 && m < n)) continue;
        sel.appendChild(new Option(n <= 15 ? 'a red' : snookerName(n), String(n)));
      }
    }
    sel.value = this.override.nominate == null ? '' : String(this.override.nominate);
  }

  /** The balls still to play: by group in 8-ball, 1-9 in 9-ball. */
  drawTray() {
    const c = $('tray');
    if (!c || !this.st) return;
    c.hidden = this.st.game === 'snooker' || this.st.game === 'three_cushion';
    if (c.hidden) return;
    const dpr = Math.min(3, window.devicePixelRatio || 1);
    const W = 320;
    const H = 60;
    if (c.width !== Math.round(W * dpr)) {
      c.width = Math.round(W * dpr);
      c.height = Math.round(H * dpr);
    }
    const ctx = c.getContext('2d');
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, W, H);
    const st = this.st;
    const on = (n) => !!st.on_table[n];
    const r = 10;
    const row = (y, label, balls, colour) => {
      ctx.fillStyle = colour;
      ctx.font = '600 12px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.textAlign = 'left';
      ctx.fillText(label, 0, y, 64);  // squeezed to fit before the balls
      balls.forEach((n, i) => {
        drawBall(ctx, n, 78 + i * (2 * r + 3), y, r, { alpha: on(n) ? 1 : 0.18, shadow: false });
      });
    };
    const solids = [1, 2, 3, 4, 5, 6, 7];
    const stripes = [9, 10, 11, 12, 13, 14, 15];
    if (st.game === 'eight_ball') {
      const g = st.group || ['none', 'none'];
      if (g[0] === 'none' || g[1] === 'none') {
        row(16, 'solids', [...solids, 8], '#9aa5b1');
        row(44, 'stripes', [...stripes, 8], '#9aa5b1');
      } else {
        for (const seat of [0, 1]) {
          const set = g[seat] === 'solids' ? solids : stripes;
          row(16 + 28 * seat, `${this.shortName(seat)}`, [...set, 8], seat === 0 ? '#f2d16b' : '#8cc3ff');
        }
      }
    } else {
      // the rotation games: the balls 1 to the game ball (9 or 10), those
      // down faded; the ball on (the lowest) ringed and marked "on", the
      // game ball marked as the one that wins
      const last = gameBall(st.game) || 9;
      const lowest = st.phase === 'game_over' ? null : this.lowestBall();
      const y = 22;
      ctx.fillStyle = '#9aa5b1';
      ctx.font = '600 12px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.textAlign = 'left';
      ctx.fillText('on the table', 0, y);
      for (let n = 1; n <= last; n++) {
        const x = 98 + (n - 1) * (2 * r + 2);
        drawBall(ctx, n, x, y, r, { alpha: on(n) ? 1 : 0.18, shadow: false });
        const words = [];
        if (n === lowest) words.push('on');
        if (n === last) words.push(st.game === 'ten_ball' ? 'money' : 'wins');
        if (n === lowest) {
          ctx.strokeStyle = '#ffd65a';
          ctx.lineWidth = 2;
          ctx.beginPath();
          ctx.arc(x, y, r + 2.5, 0, Math.PI * 2);
          ctx.stroke();
        }
        if (words.length) {
          ctx.fillStyle = n === lowest ? '#ffd65a' : '#9aa5b1';
          ctx.font = '600 10px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
          ctx.textAlign = n === last ? 'right' : 'center';
          ctx.fillText(words.join(' · '), n === last ? x + r : x, y + r + 12);
          ctx.textAlign = 'left';
        }
      }
    }
  }

  fillCallSelects() {
    const bs = $('call-ball');
    const ps = $('call-pocket');
    const targets = this.callable();
    const key = targets.join(',');
    if (bs.dataset.key !== key) {
      bs.dataset.key = key;
      bs.textContent = '';
      bs.appendChild(new Option('auto (aim)', ''));
      for (const n of targets) bs.appendChild(new Option(`ball ${n}`, String(n)));
    }
    if (ps.options.length === 0) {
      ps.appendChild(new Option('auto', ''));
      this.table.pockets.forEach((p, i) => ps.appendChild(new Option(POCKET_WORDS[p.name] || p.name, String(i))));
    }
    bs.value = this.override.ball == null ? '' : String(this.override.ball);
    ps.value = this.override.pocket == null ? '' : String(this.override.pocket);
  }

  renderLog() {
    const ol = $('ruling-log');
    ol.textContent = '';
    for (const e of this.log) ol.appendChild(this.logItem(e));
    ol.scrollTop = ol.scrollHeight;
  }

  logItem(e) {
    const li = document.createElement('li');
    li.className = `p${e.player}`;
    li.dataset.index = String(e.index);
    if (e.kind === 'shoot') {
      const b = document.createElement('button');
      b.type = 'button';
      b.className = 'small replay';
      b.textContent = 'replay';
      b.title = `replay shot ${e.index}`;
      b.dataset.index = String(e.index);
      b.addEventListener('click', () => this.replay(e.index));
      li.appendChild(b);
      const l = document.createElement('button');
      l.type = 'button';
      l.className = 'small replay shot-link';
      l.textContent = 'link';
      l.title = `a link that opens this game and replays shot ${e.index + 1}`;
      l.dataset.index = String(e.index);
      l.addEventListener('click', () => this.share(e.index));
      li.appendChild(l);
    }
    const who = document.createElement('span');
    who.className = 'who';
    who.textContent = `${e.index + 1}. ${this.players[e.player] === 'human' ? `Player ${e.player + 1}` : `Player ${e.player + 1} (${this.players[e.player]})`}: `;
    li.appendChild(who);
    const r = e.ruling || {};
    let text = r.text || (e.kind === 'place' ? 'places the cue ball' : e.kind === 'decide' ? 'decides' : 'shoots');
    if (e.kind === 'decide' && e.action && e.action.choice && !r.text) text = `chooses: ${e.action.choice.replace(/_/g, ' ')}`;
    // The ruling's words name its fouls; a foul's are shown in the foul colour.
    const words = document.createElement('span');
    if (r.fouls && r.fouls.length) words.className = 'foul';
    words.textContent = `${capital(text)} `;
    li.appendChild(words);
    if (r.winner != null && r.winner >= 0) {
      const w = document.createElement('span');
      w.className = 'win';
      w.textContent = `${this.shortName(r.winner)} wins. `;
      li.appendChild(w);
    } else if (e.kind === 'shoot' && !/(shoots again|plays on|to shoot|to break|breaks|cue ball in hand|wins|drawn|passes|decides|chooses|may push out|shoots from here)/.test(text)
      && !(this.snooker() && /(to play|is on |may play on|awarded)/.test(text))
      && !(this.carom() && /(plays inning|plays on|equalizing)/.test(text))) {
      // the ruling's words usually say whose turn it is; if not, say it
      const m = document.createElement('span');
      m.className = 'meta';
      m.textContent = r.turn_continues ? 'Turn continues.' : `Player ${2 - e.player} to play.`;
      li.appendChild(m);
    }
    return li;
  }

  showError(text) {
    const el = $('status-error');
    el.textContent = text;
    el.hidden = false;
  }

  clearError() {
    const el = $('status-error');
    el.textContent = '';
    el.hidden = true;
  }

  /** Puts the game's link in the address bar (and the clipboard); with
   *  `shot`, the link also replays that action's shot when opened. */
  async share(shot) {
    if (!this.g) return;
    let link = this.link();
    if (!link) return;
    if (Number.isInteger(shot)) {
      // The game up to and including that shot: the link opens on the
      // table the shot left, after replaying it.
      let g2 = null;
      try {
        g2 = this.E.gameFromLink(link);
        g2.undoTo(shot + 1);
        link = linkText(g2.link());
      } catch (e) {
        this.showError(message(e));
        return;
      } finally {
        if (g2) { try { g2.free(); } catch (e) { /* gone */ } }
      }
    }
    const frag = Number.isInteger(shot) ? `#game=${link}&shot=${shot}` : `#game=${link}`;
    try {
      history.replaceState(null, '', frag);
    } catch (e) {
      location.hash = frag;
    }
    const url = location.href;
    const out = $('share-out');
    out.hidden = false;
    out.textContent = 'The link is in the address bar.';
    try {
      if (navigator.clipboard && window.isSecureContext) {
        await navigator.clipboard.writeText(url);
        out.textContent = 'Link copied (and in the address bar).';
      }
    } catch (e) {
      out.textContent = 'The link is in the address bar (copying was not allowed).';
    }
  }

  // ---- input ----

  bindControls() {
    $('power').addEventListener('input', () => {
      this.aim.speed = speedFromPower(Number($('power').value));
      $('power-out').textContent = `${this.aim.speed.toFixed(2)} m/s`;
      this.requestRender();
    });
    $('elevation').addEventListener('input', () => {
      this.aim.theta = Number($('elevation').value);
      $('elevation-out').textContent = `${Math.round(this.aim.theta)}°`;
      this.requestRender();  // the stick shows the elevation
    });
    $('phi').addEventListener('input', () => {
      const v = Number($('phi').value);
      if (Number.isFinite(v)) {
        this.aim.phi = normDeg(v);
        this.requestRender();
      }
    });
    $('phi').addEventListener('change', () => { $('phi').value = this.aim.phi.toFixed(2); });
    $('tip-reset').addEventListener('click', () => {
      this.aim.a = 0;
      this.aim.b = 0;
      this.syncControls();
    });
    $('shoot').addEventListener('click', () => this.shoot());
    $('undo').addEventListener('click', () => this.undo());
    $('share').addEventListener('click', () => { this.share(); });  // the whole game
    $('call-ball').addEventListener('change', () => {
      const v = $('call-ball').value;
      this.override.ball = v === '' ? null : Number(v);
      this.requestRender();
    });
    $('nominate').addEventListener('change', () => {
      const v = $('nominate').value;
      this.override.nominate = v === '' ? null : Number(v);
      this.requestRender();
    });
    $('concede').addEventListener('click', () => this.decide('concede'));
    $('call-pocket').addEventListener('change', () => {
      const v = $('call-pocket').value;
      this.override.pocket = v === '' ? null : Number(v);
      this.requestRender();
    });
    // a safety or a push-out has no call: the call drawn goes and comes back
    for (const id of ['safety', 'push-out']) $(id).addEventListener('change', () => this.requestRender());
    $('playback-speed').addEventListener('change', () => $('table').focus({ preventScroll: true }));
    document.addEventListener('keydown', (ev) => this.onKey(ev));
    document.addEventListener('keyup', (ev) => {
      if ((ev.key === ' ' || ev.code === 'Space') && ev.target && ev.target.tagName === 'BUTTON' && !$('game').hidden) {
        ev.preventDefault();
      }
    });
  }

  onKey(ev) {
    if ($('game').hidden) return;
    const t = ev.target;
    const tag = t && t.tagName;
    if (tag === 'INPUT' && t.type !== 'range') return;
    if (tag === 'SELECT' || tag === 'TEXTAREA') return;
    if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
    if (ev.key === 'Escape') {
      if (this.stroke) this.endStroke(true);
      else this.aimHeld = false;
      this.updatePanel();
      return;
    }
    if (ev.key === ' ' || ev.code === 'Space') {
      // space shoots, even with a button focused (its keyup is cancelled too)
      ev.preventDefault();
      if (!ev.repeat) this.shoot();
    } else if ((ev.key === 'ArrowLeft' || ev.key === 'ArrowRight') && tag !== 'INPUT') {
      ev.preventDefault();
      const step = ev.shiftKey ? 1 : 0.1;
      this.aim.phi = normDeg(this.aim.phi + (ev.key === 'ArrowLeft' ? step : -step));
      this.syncControls();
      this.requestRender();
    } else if ((ev.key === 'ArrowUp' || ev.key === 'ArrowDown') && tag !== 'INPUT') {
      ev.preventDefault();
      const step = ev.shiftKey ? 0.5 : 0.1;
      const v = this.aim.speed + (ev.key === 'ArrowUp' ? step : -step);
      this.aim.speed = speedFromPower(Math.round(v * 100) / 100);
      this.syncControls();
      this.requestRender();
    }
  }

  bindCanvas() {
    const c = this.canvas;
    c.addEventListener('pointerdown', (ev) => this.onDown(ev));
    c.addEventListener('pointermove', (ev) => this.onMove(ev));
    c.addEventListener('pointerup', (ev) => this.onUp(ev, false));
    c.addEventListener('pointercancel', (ev) => this.onUp(ev, true));
    c.addEventListener('pointerleave', () => this.setGrabCursor(false));
    c.addEventListener('contextmenu', (ev) => ev.preventDefault());
  }

  /** The grab radius around the cue ball (m): larger for a finger. */
  grabRadius(ev) {
    const touch = ev && ev.pointerType && ev.pointerType !== 'mouse';
    return Math.max(this.R * 1.6, (touch ? 24 : 14) / this.view.scale);
  }

  /** A press at p takes the cue (starts a drag-back stroke): on the cue
   *  ball (unless it is in hand: then a press on it moves it), or on the
   *  stick behind it. */
  onStick(p, cue, grab, placing) {
    const rad = (this.aim.phi * Math.PI) / 180;
    const ux = Math.cos(rad);
    const uy = Math.sin(rad);
    const dx = p.x - cue.x;
    const dy = p.y - cue.y;
    if (!placing && Math.hypot(dx, dy) <= grab) return true;
    const back = -(dx * ux + dy * uy);      // distance behind the ball, along the stick
    const side = Math.abs(dx * uy - dy * ux);
    return back > this.R && back < STICK_REACH && side <= Math.max(grab * 0.8, this.R);
  }

  setGrabCursor(on) { this.canvas.classList.toggle('cue-grab', !!on); }

  /** The mouse moving with no button down: the aim follows it (unless a
   *  press has fixed it), but not over the cue ball or the stick. */
  onHover(ev) {
    if (ev.pointerType !== 'mouse' || ev.buttons !== 0 || !this.table || !this.canAct() || !this.shotDue()) {
      this.setGrabCursor(false);
      return;
    }
    const p = this.view.toTable(ev.clientX, ev.clientY);
    const cue = this.cuePos();
    if (!cue) return;
    const legal = this.legal();
    const placing = !!legal.place && legal.place !== 'none';
    const grab = this.grabRadius(ev);
    const overCue = Math.hypot(p.x - cue.x, p.y - cue.y) <= grab;
    const takes = this.onStick(p, cue, grab, placing);
    this.setGrabCursor(takes || (placing && overCue));
    if (takes || overCue || this.aimHeld) return;
    this.setAimToward(p);
  }

  /** The stroke's pull (m): how far the pointer has gone back along the
   *  aim from where it pressed. */
  strokePull(p) {
    const st = this.stroke;
    const rad = (this.aim.phi * Math.PI) / 180;
    const back = -((p.x - st.from.x) * Math.cos(rad) + (p.y - st.from.y) * Math.sin(rad));
    return Math.max(0, Math.min(PULL_MAX, back));
  }

  /** Releases a stroke: a pull strikes (the stick pushed through, then
   *  the shot), none puts the speed back. */
  endStroke(cancelled) {
    const st = this.stroke;
    if (!st) return;
    this.stroke = null;
    try { this.canvas.releasePointerCapture(st.id); } catch (e) { /* not captured */ }
    if (cancelled || st.pull < MIN_PULL || !this.canAct()) {
      this.aim.speed = st.speed0;
      this.syncControls();
      this.requestRender();
      return;
    }
    this.aim.speed = speedFromPull(st.pull);
    this.syncControls();
    this.strike = { t0: performance.now(), pull: st.pull };
    this.updatePanel();
    this.requestRender();
  }

  onDown(ev) {
    if (!this.table || (ev.pointerType === 'mouse' && ev.button !== 0)) return;
    if (!this.canAct() || this.stroke) return;
    ev.preventDefault();
    this.canvas.focus({ preventScroll: true });
    const p = this.view.toTable(ev.clientX, ev.clientY);
    const legal = this.legal();
    const cue = this.cuePos();
    const grab = this.grabRadius(ev);
    const placing = !!legal.place && legal.place !== 'none';
    if (placing && cue && Math.hypot(p.x - cue.x, p.y - cue.y) <= grab) {
      this.drag = { kind: 'cue', id: ev.pointerId, dx: cue.x - p.x, dy: cue.y - p.y, x: cue.x, y: cue.y, ok: true, reason: '' };
      this.canvas.classList.add('dragging');
      try { this.canvas.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
      this.requestRender();
      return;
    }
    if (!this.shotDue()) return;
    // the drag-back stroke: a press on the cue ball or the stick takes the cue
    if (cue && this.onStick(p, cue, grab, placing)) {
      this.stroke = { id: ev.pointerId, from: p, pull: 0, speed0: this.aim.speed };
      try { this.canvas.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
      this.requestRender();
      return;
    }
    // snooker: a click on a ball that may be nominated nominates it (and
    // aims at it, as any click does)
    if (this.nominateDue()) {
      const allowed = this.legal().nominate || [];
      const b = this.objectBalls().find((q) => allowed.includes(q.n) && Math.hypot(q.x - p.x, q.y - p.y) <= this.R * 1.1);
      const on = (this.st.snooker_figures && this.st.snooker_figures.balls_on) || [];
      if (b && (this.legal().must_nominate || !on.includes(b.n))) {
        this.override.nominate = b.n;
        this.updatePanel();
      }
    }
    // 8-ball's and 10-ball's calls: a click on a pocket calls that pocket
    if (this.callDue()) {
      const onBall = this.objectBalls().some((b) => Math.hypot(b.x - p.x, b.y - p.y) <= this.R * 1.1);
      if (!onBall) {
        const i = this.table.pockets.findIndex((k) => Math.hypot(k.centre[0] - p.x, k.centre[1] - p.y) <= k.radius + this.R);
        if (i >= 0) {
          this.override.pocket = this.override.pocket === i ? null : i;
          this.updatePanel();
          this.requestRender();
          return;
        }
      }
    }
    this.drag = { kind: 'aim', id: ev.pointerId };
    this.aimHeld = true;  // a press fixes the aim (Escape: follow the pointer again)
    this.updatePanel();
    try { this.canvas.setPointerCapture(ev.pointerId); } catch (e) { /* synthetic */ }
    this.setAimToward(p);
  }

  onMove(ev) {
    const st = this.stroke;
    if (st && st.id === ev.pointerId) {
      ev.preventDefault();
      st.pull = this.strokePull(this.view.toTable(ev.clientX, ev.clientY));
      this.aim.speed = st.pull >= MIN_PULL ? speedFromPull(st.pull) : st.speed0;
      this.syncControls();
      this.requestRender();
      return;
    }
    const d = this.drag;
    if (!d) {
      this.onHover(ev);
      return;
    }
    if (d.id !== ev.pointerId) return;
    ev.preventDefault();
    const p = this.view.toTable(ev.clientX, ev.clientY);
    if (d.kind === 'aim') {
      this.setAimToward(p);
      return;
    }
    const t = this.table;
    d.x = Math.max(-0.05, Math.min(t.length + 0.05, p.x + d.dx));
    d.y = Math.max(-0.05, Math.min(t.width + 0.05, p.y + d.dy));
    this.checkDrag(d);
    this.requestRender();
  }

  checkDrag(d) {
    try {
      const r = this.g.checkPlacement(d.x, d.y);
      d.ok = !!r.ok;
      d.reason = r.ok ? '' : r.reason || 'not allowed';
    } catch (e) {
      d.ok = false;
      d.reason = message(e);
    }
  }

  onUp(ev, cancelled) {
    if (this.stroke && this.stroke.id === ev.pointerId) {
      if (!cancelled) this.stroke.pull = this.strokePull(this.view.toTable(ev.clientX, ev.clientY));
      this.endStroke(cancelled);
      return;
    }
    const d = this.drag;
    if (!d || d.id !== ev.pointerId) return;
    this.drag = null;
    this.canvas.classList.remove('dragging');
    try { this.canvas.releasePointerCapture(ev.pointerId); } catch (e) { /* not captured */ }
    if (d.kind === 'cue' && !cancelled) {
      const p = this.view.toTable(ev.clientX, ev.clientY);
      const t = this.table;
      d.x = Math.max(-0.05, Math.min(t.length + 0.05, p.x + d.dx));
      d.y = Math.max(-0.05, Math.min(t.width + 0.05, p.y + d.dy));
      this.checkDrag(d);
      if (d.ok) {
        this.placePos = { x: d.x, y: d.y };
        this.clearError();
      } else {
        this.showError(`The cue ball cannot go there: ${d.reason}`);
      }
    }
    this.updatePanel();
    this.requestRender();
  }

  // ---- sound ----

  bindSound() {
    const b = $('mute');
    const show = () => {
      if (!b) return;
      b.setAttribute('aria-pressed', String(this.sounds.muted));
      b.textContent = this.sounds.muted ? 'Sound off' : 'Sound on';
      b.title = this.sounds.muted ? 'the sounds are off: click to hear them' : 'click to mute the sounds';
    };
    if (b) {
      b.addEventListener('click', () => {
        this.sounds.setMuted(!this.sounds.muted);
        show();
      });
    }
    show();
    // browsers let a page play sound after a gesture: the first press or key
    const unlock = () => this.sounds.unlock();
    document.addEventListener('pointerdown', unlock, true);
    document.addEventListener('keydown', unlock, true);
  }

  // ---- the cue tip widget ----

  bindTip() {
    const c = $('tip');
    this.tipCanvas = c;
    let down = null;
    const set = (ev) => {
      const r = c.getBoundingClientRect();
      const cx = r.left + r.width / 2;
      const cy = r.top + r.height / 2;
      const rad = (Math.min(r.width, r.height) / 2) * 0.9;
      let a = (ev.clientX - cx) / rad;
      let b = -(ev.clientY - cy) / rad;
      const m = Math.hypot(a, b);
      if (m > TIP_LIMIT) {
        a *= TIP_LIMIT / m;
        b *= TIP_LIMIT / m;
      }
      this.aim.a = Math.round(a * 100) / 100;
      this.aim.b = Math.round(b * 100) / 100;
      this.syncControls();
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
      this.aim.a = 0;
      this.aim.b = 0;
      this.syncControls();
    });
    this.drawTip();
  }

  drawTip() {
    const c = this.tipCanvas;
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
    const tx = cx + this.aim.a * r;
    const ty = cy - this.aim.b * r;
    ctx.fillStyle = '#2f6fc0';
    ctx.strokeStyle = '#0d2748';
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.arc(tx, ty, r * 0.13, 0, Math.PI * 2);
    ctx.fill();
    ctx.stroke();
  }
}

function capital(s) {
  if (!s) return s;
  return s[0].toUpperCase() + s.slice(1);
}

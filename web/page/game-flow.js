// The game tab's flow, without the DOM: the game (an engine game object,
// engine.js's Game: act, state, table, record, turns, checkPlacement,
// undoTo, free), the state, the log, the seats, the aim and what the
// coming shot carries (its call, its nomination, its placement), and
// undo. game.js wires it to the page; node drives it with a fake engine
// object in the unit tests (web/tests/unit/). Rule knowledge stays in
// the engine: this file asks the state's "legal" part, the facade's
// figures and game-games.js's table.

import { aimGeometry } from './draw-aim.js';
import { gameOf } from './game-games.js';
import { lowestBall } from './game-rotation.js';
import { seatName, shortName } from './game-words.js';
import { DEFAULT_SPEED, aimToward } from './game-stroke.js';

export function message(e) {
  if (e && typeof e.message === 'string') return e.message;
  return String(e);
}

export function linkText(r) {
  if (typeof r === 'string') return r;
  return r && typeof r.link === 'string' ? r.link : '';
}

/** Ball n of an engine state (position and on_table by ball number, as in
 *  game records): {x, y, on}, or null for a number the game does not have. */
export function ballOf(st, n) {
  const p = st && st.position ? st.position[n] : null;
  return p ? { x: p[0], y: p[1], on: !!st.on_table[n] } : null;
}

export class GameFlow {
  /** `onError(text)` is told what went wrong (the page shows it). */
  constructor(onError = () => {}) {
    this.onError = onError;
    this.g = null;
    this.table = null;
    this.R = 0;
    this.st = null;
    this.players = ['human', 'club'];
    this.log = [];
    this.aim = { phi: 0, speed: DEFAULT_SPEED, theta: 0, a: 0, b: 0 };
    this.override = { ball: null, pocket: null, nominate: null };
    this.declared = { safety: false, pushOut: false };  // the boxes ticked for the coming shot
    this.placePos = null;   // where the cue ball will be placed before the shot
    this.online = null;     // online play (online.js), or null
  }

  /** The game's part of the tab (game-games.js). */
  game() { return gameOf(this.st ? this.st.game : ''); }

  /** Takes game `g` (freeing the one before); false if it cannot be read. */
  install(g) {
    if (this.g && this.g !== g) {
      try { this.g.free(); } catch (e) { /* already gone */ }
    }
    this.g = g;
    try {
      this.table = g.table();
      this.st = g.state();
    } catch (e) {
      this.onError(message(e));
      return false;
    }
    this.R = this.table.ball_radius;
    this.players = this.st.players || this.players;
    this.rebuildLog();
    this.newTurn(true);
    return true;
  }

  /** The log from the game's record and the facade's turns: one entry per
   *  action, {index, player, kind, ruling, action, turn, numbers (shots:
   *  the balls on the table before it, by number)}. */
  rebuildLog() {
    this.log = [];
    let rec = null;
    let turns = [];
    try {
      rec = this.g.record();
      turns = this.g.turns();
    } catch (e) {
      this.onError(`Cannot read the game record: ${message(e)}`);
    }
    if (rec && Array.isArray(rec.actions)) {
      let before = rec.start;
      rec.actions.forEach((a, i) => {
        const kind = a.action && a.action.type === 'place_cue_ball' ? 'place'
          : a.action && a.action.type === 'decide' ? 'decide' : 'shoot';
        const entry = { index: i, player: a.player, kind, ruling: a.ruling || {}, action: a.action, turn: turns[i] || null };
        if (kind === 'shoot' && before && before.on_table) {
          entry.numbers = before.on_table.map((on, n) => (on ? n : -1)).filter((n) => n >= 0);
        }
        this.log.push(entry);
        before = a.after;
      });
    }
  }

  seatName(seat) { return seatName(this.players, seat); }

  shortName(seat) { return shortName(this.players, seat); }

  // ---- the turn ----

  legal() { return (this.st && this.st.legal) || {}; }

  /** A shot is due: legal now, or once the cue ball that must be placed is placed. */
  shotDue() {
    const legal = this.legal();
    return !!legal.shoot || (!!legal.must_place && !!legal.place && legal.place !== 'none');
  }

  /** The coming shot carries a call: now, or after the placement. */
  callDue() {
    const legal = this.legal();
    if (legal.call) return true;
    return !legal.shoot && this.shotDue() && !!this.game().calls && this.st.phase === 'shot';
  }

  /** The rotation games' ball on: the lowest-numbered object ball on the table. */
  lowestBall() { return lowestBall(this.st); }

  /** Every shot but the break must be called or declared safe (10-ball). */
  callRequired() { return !!this.st && !!this.game().callRequired && this.callDue(); }

  /** The coming shot may be a push-out: now, or after the placement. */
  pushOutDue() {
    const legal = this.legal();
    if (legal.push_out) return true;
    return !legal.shoot && this.shotDue() && !!this.game().pushOut && !!this.st.push_out_allowed;
  }

  /** The coming shot is declared a safety or a push-out: it has no call. */
  uncalled() {
    return (this.callDue() && this.declared.safety) || (this.pushOutDue() && this.declared.pushOut);
  }

  /** The balls a call may name: the targets (8-ball: the player's group),
   *  or the game's own list (10-ball: any object ball on the table). */
  callable() {
    const game = this.game();
    if (this.st && game.callable) return game.callable(this.objectBalls());
    return this.legal().targets || [];
  }

  /** The ball the player to act strikes: the cue ball (0), or the game's
   *  (three-cushion: the player's own ball). */
  cueN() {
    const game = this.game();
    return this.st && game.cueBall ? game.cueBall(this.st) : 0;
  }

  /** The decisions on offer now (snooker's concede, which a shooter may
   *  always take, aside while a shot is due). */
  decisions() {
    const legal = this.legal();
    const list = legal.choices || [];
    return legal.shoot || this.shotDue() ? list.filter((c) => c !== 'concede') : list;
  }

  /** The coming shot nominates a ball: a colour after a red
   *  (must_nominate), or a free ball may be taken. Otherwise a nomination
   *  could only name a ball that is on anyway, and the page leaves it out. */
  nominateDue() {
    if (!this.st || !this.game().nominates || !this.shotDue()) return false;
    const legal = this.legal();
    if (!Array.isArray(legal.nominate) || legal.nominate.length === 0) return false;
    return !!legal.must_nominate || !!(this.st.snooker && this.st.snooker.free_ball);
  }

  /** The balls on that need no nomination (snooker_figures' balls_on). */
  ballsOn() { return (this.st && this.st.snooker_figures && this.st.snooker_figures.balls_on) || []; }

  /** Ball n may be nominated by pointing at it: one the legal list allows
   *  that is not on anyway (or any allowed one after a red). */
  nominable(n) {
    const legal = this.legal();
    return (legal.nominate || []).includes(n) && (!!legal.must_nominate || !this.ballsOn().includes(n));
  }

  /** The ball the shot nominates: the player's choice, else by the aim:
   *  the first ball the aim line hits when it is one that may be
   *  nominated and needs to be. {ball, auto}, ball null for none. */
  currentNomination(geo) {
    if (!this.nominateDue()) return null;
    const allowed = this.legal().nominate || [];
    const o = this.override.nominate;
    if (o != null && allowed.includes(o)) return { ball: o, auto: false };
    const hit = geo && geo.hit ? geo.hit.n : null;
    if (hit == null || !allowed.includes(hit)) return { ball: null, auto: true };
    return { ball: this.nominable(hit) ? hit : null, auto: true };
  }

  humanToAct() {
    return !!this.st && this.st.phase !== 'game_over' && this.players[this.st.player] === 'human' &&
      (!this.online || this.online.mayAct(this.st));
  }

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

  /** Sets up the aim and the placement for the turn after an action;
   *  `fresh`: a new game or the first shot after the break. */
  newTurn(fresh) {
    const legal = this.legal();
    this.override = { ball: null, pocket: null, nominate: null };
    this.declared = { safety: false, pushOut: false };
    this.placePos = null;
    if (legal.place && legal.place !== 'none') this.placePos = this.defaultPlacement(legal);
    if (!this.st) return;
    if (this.st.phase === 'break_shot') {
      this.aim.speed = this.game().breakSpeed ?? DEFAULT_SPEED;
    } else if (fresh || this.aim.speed > 6.5) {
      this.aim.speed = DEFAULT_SPEED;
    }
    this.aim.theta = 0;
    this.aim.a = 0;
    this.aim.b = 0;
    this.aimAtDefault();
  }

  /** After a placement the shot keeps its aim: only the placement is set again. */
  replaced() {
    const legal = this.legal();
    this.placePos = null;
    if (legal.place && legal.place !== 'none') this.placePos = this.defaultPlacement(legal);
  }

  checkPlacement(x, y) {
    try {
      const r = this.g.checkPlacement(x, y);
      return { ok: !!r.ok, reason: r.ok ? '' : r.reason || 'not allowed' };
    } catch (e) {
      return { ok: false, reason: message(e) };
    }
  }

  defaultPlacement(legal) {
    const c = ballOf(this.st, 0);
    const tryAt = (x, y) => this.checkPlacement(x, y).ok;
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

  /** Aims at the nearest legal target (the game's own first aim: the red
   *  on three-cushion's break). */
  aimAtDefault() {
    const cue = this.cuePos();
    if (!cue) return;
    const game = this.game();
    const targets = new Set(game.aimTargets ? game.aimTargets(this.st) : this.legal().targets || []);
    let best = null;
    let bestD = Infinity;
    for (const b of this.objectBalls()) {
      if (targets.size && !targets.has(b.n)) continue;
      const d = Math.hypot(b.x - cue.x, b.y - cue.y);
      if (d < bestD) { bestD = d; best = b; }
    }
    if (best) this.aim.phi = aimToward(cue, best) ?? this.aim.phi;
  }

  /** Aims from the cue ball toward table point p; false if p is on it. */
  aimAt(p) {
    const cue = this.cuePos();
    if (!cue) return false;
    const phi = aimToward(cue, p);
    if (phi == null) return false;
    this.aim.phi = phi;
    return true;
  }

  geometry() {
    const cue = this.cuePos();
    if (!cue) return null;
    return aimGeometry(this.table, cue, this.aim.phi, this.objectBalls(), this.R);
  }

  /** The call the shot will carry: overrides, else from the aim (the
   *  target the aim line reaches first, into the pocket nearest the
   *  direction it is sent); none for a safety or a push-out. */
  currentCall(geo) {
    if (!this.callDue() || this.uncalled()) return null;
    const targets = this.legal().targets || [];
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

  /** The shot as an action in the records' form (src/io/game_json.hpp),
   *  every field given. */
  shotAction() {
    const legal = this.legal();
    const s = this.aim;
    const action = {
      type: 'shoot',
      strike: { speed: s.speed, phi: s.phi, theta: s.theta, a: s.a, b: s.b },
      call: null,
      safety: false,
      push_out: false,
    };
    // a safety or a push-out carries no call (the rules refuse one with it)
    if (legal.push_out && this.declared.pushOut) {
      action.push_out = true;
    } else if (legal.call && this.declared.safety) {
      action.safety = true;
    } else if (legal.call) {
      const call = this.currentCall(this.geometry());
      if (call && call.ball != null && call.pocket != null) action.call = { ball: call.ball, pocket: call.pocket };
    }
    const nom = this.currentNomination(this.geometry());
    if (nom && nom.ball != null) action.nominate = nom.ball;
    return action;
  }

  /** The placement to play before the shot, or null: the cue ball in hand
   *  moved from where it lies (or off the table). */
  placementDue() {
    const legal = this.legal();
    if (!this.placePos || !legal.place || legal.place === 'none') return null;
    const c = ballOf(this.st, 0);
    const moved = !c || !c.on || c.x !== this.placePos.x || c.y !== this.placePos.y;
    return legal.must_place || moved ? { type: 'place_cue_ball', position: [this.placePos.x, this.placePos.y] } : null;
  }

  /**
   * Plays `action` through the engine: {reply, entry, prevPhase} with the
   * state and log entry of the action (the entry is not yet in the log:
   * a shot's goes in once its balls stop, addToLog), or {error}.
   */
  play(action) {
    let reply;
    try {
      reply = this.g.act(action);
    } catch (e) {
      return { error: message(e) };
    }
    if (!reply || typeof reply !== 'object') return { error: 'no reply' };
    if (reply.error) return { error: reply.error };
    const entry = {
      index: reply.index,
      player: reply.player,
      kind: reply.kind,
      ruling: reply.ruling || {},
      numbers: reply.numbers,
      action: reply.executed,
      turn: reply.turn || null,
    };
    const prevPhase = this.st ? this.st.phase : '';
    this.st = reply.state;
    return { reply, entry, prevPhase };
  }

  addToLog(entry) { this.log.push(entry); }

  /** A shot of a human on this screen is in the log: undo has something to take back. */
  canUndo() { return this.log.some((e) => e.kind === 'shoot' && this.players[e.player] === 'human'); }

  /** The action to take the game back to: before the last shot taken
   *  by a human (the AI's replies go too). {index}, or {error} saying
   *  why there is none. */
  undoTarget() {
    if (this.online) return { error: 'An online game has no undo.' };
    for (let i = this.log.length - 1; i >= 0; i--) {
      const e = this.log[i];
      if (e.kind === 'shoot' && this.players[e.player] === 'human') return { index: e.index };
    }
    return { error: 'There is no shot of yours to undo.' };
  }

  /** Keeps the game's first n actions (undoTarget's index): null, or
   *  what went wrong. */
  undoTo(n) {
    try {
      this.g.undoTo(n);
      this.st = this.g.state();
    } catch (e) {
      return message(e);
    }
    this.rebuildLog();
    this.newTurn(false);
    return null;
  }

  /** The log entry of shot `index`, or undefined. */
  shotEntry(index) { return this.log.find((e) => e.index === index && e.kind === 'shoot'); }

  /** The last shot's entry with a three-cushion count, or null. */
  lastCount() { return [...this.log].reverse().find((e) => e.kind === 'shoot' && e.ruling && e.ruling.carom) || null; }

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
}

// breakshot, the npm package (docs/js.md): the engine, the rules and the
// AI compiled to WebAssembly, for node 20 and browsers.
//
//   import { simulate, Game, Player } from 'breakshot';
//
// A thin layer of classes over engine.js (the page's JS API over the
// wasm facade, web/page/engine.js, shipped as it is): every call goes
// through it, so the page and the package share one JS layer. The engine
// is instantiated when this module is imported (a top-level await), so
// every call below but Player.decide is synchronous.
//
// Memory: the wasm heap is not garbage collected. A Simulation, a
// Playback and a Game hold engine memory until their free(); a
// FinalizationRegistry frees what the garbage collector finds unfreed,
// as a safety net only (when it runs is up to the collector).

import { FRAME_LAYOUT, MOTIONS, loadEngine, parse, toJson } from './engine.js';
import { Player } from './player.js';

const E = await loadEngine();

export { Player };

/** The engine's version ("0.1.0"), the package's. */
export const version = E.version();
/** The AI levels, weakest first. */
export const levels = Object.freeze(E.levels.slice());
/** The names of the motion states, by the codes of States.motion:
 *  stationary, moving, sliding, rolling, spinning, pocketed, airborne,
 *  off_table (the result file's "state" names). */
export const motions = MOTIONS;
/** The games a Game plays. */
export const games = Object.freeze(['eight_ball', 'nine_ball', 'ten_ball', 'snooker', 'three_cushion']);
/** The computer players a seat of `game` may be (AI levels, and "baseline" where it plays). */
export function players(game) { return E.gamePlayers(game); }
/** The engine.js API that the classes are built on (docs/web.md, "The JS API"). */
export const engine = E;

const registry = typeof FinalizationRegistry === 'function'
  ? new FinalizationRegistry((inner) => { try { inner.free(); } catch (e) { /* gone */ } })
  : null;

function track(owner, inner) {
  if (registry) registry.register(owner, inner, owner);
}
function untrack(owner) {
  if (registry) registry.unregister(owner);
}

function finiteTime(t) {
  if (typeof t !== 'number' || !Number.isFinite(t)) throw new Error(`t: expected a finite number of seconds, not ${String(t)}`);
  if (t < 0) throw new Error(`t: must be at least 0, not ${t}`);
  return t;
}

// The layout of bs_web_playback_frame_data's doubles (web_api.hpp), as
// engine.js reads it.
const { header: HEADER, stride: STRIDE, flightStride: FLIGHT_STRIDE } = FRAME_LAYOUT;

function newStates(n) {
  return {
    t: 0, events: 0, atRest: false, complete: true, energy: 0, momentum: [0, 0], count: n,
    position: new Float64Array(2 * n), velocity: new Float64Array(2 * n),
    spin: new Float64Array(3 * n), height: new Float64Array(n),
    onTable: new Uint8Array(n), place: new Uint8Array(n), motion: new Uint8Array(n),
    ballEnergy: new Float64Array(n), ballMomentum: new Float64Array(2 * n),
  };
}

/**
 * A shot played back: the exact state of every ball at any time.
 * Frames at increasing times are cheap (the simulation advances to each);
 * a time earlier than the last frame's plays the shot again from its start.
 */
export class Playback {
  /** make: a function giving a new engine.js playback; first: one made already (internal). */
  constructor(make, first = null) {
    this._make = make;
    this._pb = first;
    this._t = -Infinity;
    this._freed = false;
    if (first) track(this, first);
  }

  _at(t) {
    if (this._freed) throw new Error('this playback has been freed');
    finiteTime(t);
    if (this._pb && t < this._t) {
      untrack(this);
      this._pb.free();
      this._pb = null;
    }
    if (!this._pb) {
      this._pb = this._make();
      this._t = -Infinity;
      track(this, this._pb);
    }
    const d = this._pb.frameData(t);
    this._t = t;
    return d;
  }

  /**
   * The balls' states at time t (s) as typed arrays, in the scenario's
   * order: position and velocity [x0, y0, x1, y1, ...], spin [wx, wy, wz]
   * per ball, height (m above resting), onTable (1|0), place (0 on the
   * cloth or in a pocket, 1 in flight, 2 off the table), motion (each
   * ball's motion state: an index of `motions`, 0 stationary, 1 moving,
   * 2 sliding, 3 rolling, 4 spinning, 5 pocketed, 6 airborne, 7 off the
   * table), each ball's energy and momentum. `into` (a States of the same number of balls)
   * is filled instead of a new one: a 60 fps loop reuses its arrays.
   */
  states(t, into) {
    const d = this._at(t);
    const n = d[7];
    const s = into && into.count === n ? into : newStates(n);
    s.t = d[0];
    s.events = d[1];
    s.atRest = d[2] !== 0;
    s.complete = d[3] !== 0;
    s.energy = d[4];
    s.momentum[0] = d[5];
    s.momentum[1] = d[6];
    const flight = HEADER + STRIDE * n + 1;
    for (let i = 0, o = HEADER; i < n; i++, o += STRIDE) {
      s.position[2 * i] = d[o];
      s.position[2 * i + 1] = d[o + 1];
      s.onTable[i] = d[o + 2];
      s.velocity[2 * i] = d[o + 3];
      s.velocity[2 * i + 1] = d[o + 4];
      s.ballEnergy[i] = d[o + 5];
      s.ballMomentum[2 * i] = d[o + 6];
      s.ballMomentum[2 * i + 1] = d[o + 7];
      s.height[i] = d[flight + FLIGHT_STRIDE * i];
      s.place[i] = d[flight + FLIGHT_STRIDE * i + 1];
    }
    this._pb.spins(n, s.spin);
    this._pb.motions(n, s.motion);
    return s;
  }

  /**
   * The frame at time t for drawing, the page's: {t, balls: [[x, y,
   * on_table, vx, vy, energy, px, py(, z, place)], ...], energy, momentum,
   * events, at_rest, complete} (engine.js frameObject).
   */
  frame(t) {
    this._at(t);
    return this._pb.frame(t);
  }

  /** The events played back so far (up to the last frame's time), from index `from`, in the result file's form. */
  playedEvents(from = 0) {
    if (!this._pb) this._at(0);
    return this._pb.events(from).events;
  }

  /** A three-cushion shot's count up to the last frame: {cushions, hit, done, made}. */
  caromCount() {
    if (!this._pb) this._at(0);
    return this._pb.caromCount();
  }

  /** Releases the engine memory; later calls throw. Safe to call twice. */
  free() {
    if (this._pb) {
      untrack(this);
      this._pb.free();
      this._pb = null;
    }
    this._freed = true;
  }
}

/**
 * A simulated scenario: the result file, exactly as `breakshot simulate`
 * writes it (text), and, as a Playback, the states at any time.
 */
export class Simulation extends Playback {
  constructor(scenarioText, resultText) {
    super(() => E.playback(scenarioText));
    this._text = resultText;
    this._result = null;
  }
  /** The result file's text, byte for byte the command's. */
  get text() { return this._text; }
  /** The result file (docs/contract.md), parsed once. */
  get result() {
    if (!this._result) this._result = JSON.parse(this._text);
    return this._result;
  }
  /** Every event of the run, in time order. */
  get events() { return this.result.events; }
  /** False when the max_events guard stopped the run. */
  get complete() { return this.result.complete; }
  /** The time the run ended (at rest, or the scenario's until time). */
  get duration() { return this.result.final.time; }
  /** The balls' ids in the order of states() and frames. */
  get ids() { return this.result.final.balls.map((b) => b.id); }
}

/**
 * Simulates a scenario (an object or the JSON text of the scenario
 * format, docs/contract.md). Throws Error with the engine's message,
 * naming the field, when the scenario is refused.
 */
export function simulate(scenario) {
  const text = toJson(scenario);
  const result = E.raw.simulate(text);
  parse(result);  // throws the engine's {"error"}
  return new Simulation(text, result);
}

/**
 * A game between two seats: eight_ball, nine_ball, ten_ball, snooker or
 * three_cushion. config: {game, players: [seat, seat], table?, seed?,
 * breaker?, physics?: {airborne?}, carom? (three_cushion), ai_budget?};
 * a seat is "human" or a computer player ("club", "champion@0.5x").
 */
export class Game {
  constructor(config, inner) {
    this._g = inner || E.newGame(config);
    track(this, this._g);
  }
  /** The game of a link (game.link()'s text). */
  static fromLink(link) {
    if (typeof link !== 'string') throw new Error(`link: expected the link's text, not ${typeof link}`);
    return new Game(null, E.gameFromLink(link));
  }
  _inner() {
    if (!this._g) throw new Error('this game has been freed');
    return this._g;
  }
  /** The state: phase, player to act, positions, score, legal actions, ... */
  state() { return this._inner().state(); }
  /** The legal actions of the seat to act (the state's "legal"). */
  legalActions() { return this.state().legal; }
  /** The number of actions played. */
  get actions() { return this.state().actions; }
  /** The table: size, pockets, cushions, the rack's geometry. */
  table() { return this._inner().table(); }
  /** {ok: true} or {ok: false, reason}: may the cue ball be placed at (x, y)? */
  checkPlacement(x, y) { return this._inner().checkPlacement(x, y); }
  /** Plays an action of the seat to act; returns {index, player, kind, executed, ruling, turn, facts, state, ...}. */
  act(action) { return this._inner().act(action); }
  /** The AI's decision for the seat to act, in this thread (blocking): its own level, or `level`. */
  aiAction(level) { return this._inner().aiAction(level).action; }
  /** Takes back the last n actions (default 1); returns the state. */
  undo(n = 1) {
    const count = this.actions;
    if (!Number.isInteger(n) || n < 0 || n > count) throw new Error(`undo: n must be an integer in [0, ${count}], not ${String(n)}`);
    return this._inner().undoTo(count - n);
  }
  /** Keeps the first n actions; returns the state. */
  undoTo(n) { return this._inner().undoTo(n); }
  /** The playback of the shot of action `index` (free it). */
  shot(index) {
    const first = this._inner().shotPlayback(index);  // throws for a bad index
    return new Playback(() => this._inner().shotPlayback(index), first);
  }
  /** The link text: the whole game in a URL-safe string. */
  link() { return this._inner().link(); }
  /** The game record, as `breakshot replay` reads it (an object). */
  record() { return this._inner().record(); }
  /** The game record's text. */
  recordText() { return this._inner().recordText(); }
  /** Whose turn it is after each action, and why: [{next, why}, ...]. */
  turns() { return this._inner().turns(); }
  /** Releases the engine memory; later calls throw. Safe to call twice. */
  free() {
    if (this._g) {
      untrack(this);
      this._g.free();
      this._g = null;
    }
  }
}

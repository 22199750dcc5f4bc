// The engine in JavaScript: the wasm build of the C++ engine, rules and AI
// (build/web/dist/breakshot.js) behind the API of docs/web.md ("The JS
// API"). The only file that talks to the wasm module: the page's, and
// the npm package's core (scripts/npm.sh ships this file as it is; the
// package's index.js builds its classes on it, docs/js.md).
//
//   import { loadEngine } from './engine.js';
//   const E = await loadEngine();
//
// breakshot.js is built as an ES module (-sEXPORT_ES6=1, -sSINGLE_FILE=1:
// the wasm is inside it, -sENVIRONMENT=web,worker): the static import
// below works the same in a page (<script type="module">), in a module
// worker (new Worker(url, {type: 'module'})) and in node 20 (which has
// the web globals it needs), and needs no fetch of a second file.
//
// Every method parses the facade's JSON reply and throws an Error with
// the reply's "error" text. Playback frames are the exception: pb.frame(t)
// reads bs_web_playback_frame_data's doubles from the wasm heap (a 1000-ball
// frame as JSON text costs ~10 ms to write in wasm, as doubles nothing
// but the physics) and builds the object JSON.parse would give of
// bs_web_playback_frame's reply, which is written from the same doubles.
// Strings go to the wasm heap through malloc (not the stack: a scenario
// can be megabytes). Numbers go as JSON text:
// exact both ways (shortest round-trip digits on each side), and -0 is
// written as -0.0 so that its sign survives (JSON.stringify drops it).

import createBreakshot from './breakshot.js';

const NEG_ZERO = '__breakshot_negative_zero__';

// bs_web_playback_frame_data's layout: [t, events, at_rest, complete, energy,
// px, py, n], then [x, y, on_table, vx, vy, energy, px, py] per ball, then
// the flight block: a flag (1 when a ball is off the cloth) and [z, place]
// per ball (place: 0 on the cloth or in a pocket, 1 in flight, 2 off the
// table), which the frame object carries only when the flag is 1.
const FRAME_HEADER = 8;
const FRAME_STRIDE = 8;
const FLIGHT_STRIDE = 2;
/** That layout, for readers of the doubles (the npm package's states). */
export const FRAME_LAYOUT = Object.freeze({ header: FRAME_HEADER, stride: FRAME_STRIDE, flightStride: FLIGHT_STRIDE });

/** The names of the motion states (breakshot.h's BsMotion), by code. */
export const MOTIONS = Object.freeze(['stationary', 'moving', 'sliding', 'rolling', 'spinning', 'pocketed', 'airborne', 'off_table']);

/** The length of a frame's buffer of n balls, flight block included. */
export function frameLength(n) {
  return FRAME_HEADER + FRAME_STRIDE * n + 1 + FLIGHT_STRIDE * n;
}

/**
 * The frame object of bs_web_playback_frame_data's doubles (an array-like):
 * what JSON.parse gives of bs_web_playback_frame's reply for the same frame.
 */
export function frameObject(d) {
  const n = d[7];
  const balls = new Array(n);
  for (let i = 0, o = FRAME_HEADER; i < n; i++, o += FRAME_STRIDE) {
    balls[i] = [d[o], d[o + 1], d[o + 2], d[o + 3], d[o + 4], d[o + 5], d[o + 6], d[o + 7]];
  }
  const flight = FRAME_HEADER + FRAME_STRIDE * n;
  if (d[flight] !== 0) {
    for (let i = 0, o = flight + 1; i < n; i++, o += FLIGHT_STRIDE) balls[i].push(d[o], d[o + 1]);
  }
  return {
    t: d[0],
    balls,
    energy: d[4],
    momentum: [d[5], d[6]],
    events: d[1],
    at_rest: d[2] !== 0,
    complete: d[3] !== 0,
  };
}

/** JSON text of a value, keeping -0 (a string is passed as it is). */
export function toJson(value) {
  if (typeof value === 'string') return value;
  const text = JSON.stringify(value, (key, v) => (typeof v === 'number' && Object.is(v, -0) ? NEG_ZERO : v));
  if (text === undefined) throw new Error('cannot write this value as JSON');
  return text.includes(NEG_ZERO) ? text.split(`"${NEG_ZERO}"`).join('-0.0') : text;
}

/** The facade's JSON reply, parsed; throws Error(reply.error) (with the
 *  parsed reply as the error's `reply`) when it is {"error"}. */
export function parse(text) {
  let reply;
  try {
    reply = JSON.parse(text);
  } catch (e) {
    throw new Error(`the engine's reply is not JSON: ${String(text).slice(0, 200)}`);
  }
  if (reply !== null && typeof reply === 'object' && !Array.isArray(reply) && typeof reply.error === 'string') {
    const err = new Error(reply.error);
    err.reply = reply;
    throw err;
  }
  return reply;
}

/** The raw facade: the C functions with strings in and out, no parsing. */
function rawApi(M) {
  const c = (name, ret, args) => M.cwrap(name, ret, args);
  const fn = {
    version: c('bs_web_version', 'number', []),
    gamePlayers: c('bs_web_game_players', 'number', ['number']),
    simulate: c('bs_web_simulate', 'number', ['number']),
    free: c('bs_web_free', null, ['number']),
    playbackNew: c('bs_web_playback_new', 'number', ['number']),
    frame: c('bs_web_playback_frame', 'number', ['number', 'number']),
    frameData: c('bs_web_playback_frame_data', 'number', ['number', 'number']),
    spins: c('bs_web_playback_spins', 'number', ['number']),
    motions: c('bs_web_playback_motions', 'number', ['number']),
    events: c('bs_web_playback_events', 'number', ['number', 'number']),
    caromCount: c('bs_web_playback_carom_count', 'number', ['number']),
    playbackFree: c('bs_web_playback_free', null, ['number']),
    gameNew: c('bs_web_game_new', 'number', ['number']),
    gameFromLink: c('bs_web_game_from_link', 'number', ['number']),
    table: c('bs_web_game_table', 'number', ['number']),
    state: c('bs_web_game_state', 'number', ['number']),
    checkPlacement: c('bs_web_game_check_placement', 'number', ['number', 'number', 'number']),
    act: c('bs_web_game_act', 'number', ['number', 'number']),
    aiAction: c('bs_web_game_ai_action', 'number', ['number', 'number']),
    shotPlayback: c('bs_web_game_shot_playback', 'number', ['number', 'number']),
    link: c('bs_web_game_link', 'number', ['number']),
    record: c('bs_web_game_record', 'number', ['number']),
    turns: c('bs_web_game_turns', 'number', ['number']),
    undoTo: c('bs_web_game_undo_to', 'number', ['number', 'number']),
    gameFree: c('bs_web_game_free', null, ['number']),
    lastError: c('bs_web_last_error', 'number', []),
    malloc: c('malloc', 'number', ['number']),
    mfree: c('free', null, ['number']),
  };
  const str = (ptr) => M.UTF8ToString(ptr);
  // Calls f with a C copy of each string argument (null stays NULL).
  const withStrings = (strings, f) => {
    const ptrs = strings.map((s) => {
      if (s === null || s === undefined) return 0;
      const text = String(s);
      const n = M.lengthBytesUTF8(text) + 1;
      const p = fn.malloc(n);
      if (!p) throw new Error('out of memory in the engine');
      M.stringToUTF8(text, p, n);
      return p;
    });
    try {
      return f(...ptrs);
    } finally {
      for (const p of ptrs) if (p) fn.mfree(p);
    }
  };
  return {
    version: () => str(fn.version()),
    gamePlayers: (game) => withStrings([game], (p) => str(fn.gamePlayers(p))),
    simulate: (text) =>
      withStrings([text], (p) => {
        const out = fn.simulate(p);
        if (!out) throw new Error('out of memory in the engine');
        try {
          return str(out);
        } finally {
          fn.free(out);
        }
      }),
    playbackNew: (text) => withStrings([text], (p) => fn.playbackNew(p)),
    frame: (h, t) => str(fn.frame(h, t)),
    // The frame's doubles (web_api.hpp, bs_web_playback_frame_data): a
    // Float64Array view of the wasm heap, valid until the next call on the
    // handle; null on error (then lastError()). The view is taken after the
    // call: the call may grow the memory (ALLOW_MEMORY_GROWTH), which
    // detaches the views taken before it.
    frameData: (h, t) => {
      const p = fn.frameData(h, t);
      if (!p) return null;
      if (p % 8 !== 0) throw new Error('bs_web_playback_frame_data: a misaligned buffer');
      const heap = M.HEAPF64;
      const at = p / 8;
      const n = heap[at + FRAME_HEADER - 1];
      return heap.subarray(at, at + frameLength(n));
    },
    // The balls' spins at the last frame (bs_web_playback_spins): a copy, 3
    // doubles per ball of the n the caller knows from the frame, into
    // `into` when given (a typed array of that length) or a new array;
    // null on error (then lastError()).
    spins: (h, n, into) => {
      const p = fn.spins(h);
      if (!p) return null;
      const at = p / 8;
      return copyOut(M.HEAPF64.subarray(at, at + 3 * n), into);
    },
    // The balls' motion states at the last frame (bs_web_playback_motions):
    // a copy, 1 per ball (breakshot.h's BsMotion) of the n the caller
    // knows from the frame, into `into` when given; null on error (then
    // lastError()).
    motions: (h, n, into) => {
      const p = fn.motions(h);
      if (!p) return null;
      const at = p / 8;
      return copyOut(M.HEAPF64.subarray(at, at + n), into);
    },
    events: (h, from) => str(fn.events(h, from)),
    caromCount: (h) => str(fn.caromCount(h)),
    playbackFree: (h) => fn.playbackFree(h),
    gameNew: (text) => withStrings([text], (p) => fn.gameNew(p)),
    gameFromLink: (text) => withStrings([text], (p) => fn.gameFromLink(p)),
    table: (h) => str(fn.table(h)),
    state: (h) => str(fn.state(h)),
    checkPlacement: (h, x, y) => str(fn.checkPlacement(h, x, y)),
    act: (h, text) => withStrings([text], (p) => str(fn.act(h, p))),
    aiAction: (h, level) => withStrings([level], (p) => str(fn.aiAction(h, p))),
    shotPlayback: (h, index) => fn.shotPlayback(h, index),
    link: (h) => str(fn.link(h)),
    record: (h) => str(fn.record(h)),
    turns: (h) => str(fn.turns(h)),
    undoTo: (h, n) => str(fn.undoTo(h, n)),
    gameFree: (h) => fn.gameFree(h),
    lastError: () => str(fn.lastError()),
  };
}

function intArg(v, what) {
  const n = Number(v);
  if (!Number.isInteger(n) || n < -2147483648 || n > 2147483647) throw new Error(`${what}: expected an integer, not ${v}`);
  return n;
}

// `into` of a copy out of the wasm heap: undefined (a new array), or a
// typed array of exactly `length` elements.
function intoArg(into, length, what) {
  if (into === undefined || into === null) return undefined;
  if (!ArrayBuffer.isView(into) || into instanceof DataView || into.length !== length) {
    throw new Error(`${what}: expected a typed array of ${length} elements`);
  }
  return into;
}

// A view of the wasm heap copied into `into` (returned), or into a new
// Float64Array.
function copyOut(view, into) {
  if (!into) return view.slice();
  into.set(view);
  return into;
}

function numArg(v, what) {
  const n = Number(v);
  if (typeof v !== 'number' && typeof v !== 'string') throw new Error(`${what}: expected a number, not ${typeof v}`);
  return n;
}

class Playback {
  constructor(raw, handle) {
    this._raw = raw;
    this._h = handle;
  }
  _handle() {
    if (!this._h) throw new Error('this playback has been freed');
    return this._h;
  }
  /**
   * The exact state at time t (never earlier than the previous frame):
   * {t, balls: [[x, y, on_table, vx, vy, energy, px, py], ...], energy,
   * momentum: [px, py], events, at_rest, complete}, from the frame's
   * doubles (no JSON text); the same object as frameJson(t).
   */
  frame(t) { return frameObject(this.frameData(t)); }
  /**
   * The frame at time t as bs_web_playback_frame_data's doubles (the layout of
   * frameObject): a Float64Array view of the wasm heap, valid until the
   * next call on the engine (copy it to keep it).
   */
  frameData(t) {
    const d = this._raw.frameData(this._handle(), numArg(t, 't'));
    if (!d) {
      parse(this._raw.lastError());  // throws the error
      throw new Error('bs_web_playback_frame_data failed');
    }
    return d;
  }
  /** The balls' spins at the last frame's time (bs_web_playback_spins; the
   *  start's before any frame): a Float64Array of wx, wy, wz (rad/s) per
   *  ball, for drawing. n: the number of balls (a frame's balls.length);
   *  into: a typed array of 3 n to copy into (it is returned), else a new
   *  Float64Array. */
  spins(n, into) {
    const w = this._raw.spins(this._handle(), intArg(n, 'n'), intoArg(into, 3 * n, 'into'));
    if (!w) parse(this._raw.lastError());
    return w;
  }
  /** The balls' motion states at the last frame's time (the start's
   *  before any frame): a Float64Array of one BsMotion code per ball (0
   *  stationary, 1 moving, 2 sliding, 3 rolling, 4 spinning, 5 pocketed,
   *  6 airborne, 7 off the table; MOTIONS names them). n: the number of
   *  balls; into: a typed array of n to copy into (it is returned), else a
   *  new Float64Array. */
  motions(n, into) {
    const m = this._raw.motions(this._handle(), intArg(n, 'n'), intoArg(into, n, 'into'));
    if (!m) parse(this._raw.lastError());
    return m;
  }
  /** The same frame from bs_web_playback_frame's JSON text (for tests). */
  frameJson(t) { return parse(this._raw.frame(this._handle(), numArg(t, 't'))); }
  /** {from, events: [...]}: the events from index `from` on, in result-file form. */
  events(from = 0) { return parse(this._raw.events(this._handle(), intArg(from, 'from'))); }
  /** A three-cushion shot's count over its events so far (its last
   *  frame's): {cushions, hit, done, made} (bs_web_playback_carom_count). */
  caromCount() { return parse(this._raw.caromCount(this._handle())); }
  free() {
    if (this._h) this._raw.playbackFree(this._h);
    this._h = 0;
  }
}

function newPlayback(raw, handle) {
  if (!handle) parse(raw.lastError());
  return new Playback(raw, handle);
}

class Game {
  constructor(raw, handle) {
    this._raw = raw;
    this._h = handle;
  }
  _handle() {
    if (!this._h) throw new Error('this game has been freed');
    return this._h;
  }
  table() { return parse(this._raw.table(this._handle())); }
  state() { return parse(this._raw.state(this._handle())); }
  /** bs_web_game_state's reply as text (online play hashes its bytes). */
  stateText() { return this._raw.state(this._handle()); }
  /** {ok: true} or {ok: false, reason}. */
  checkPlacement(x, y) { return parse(this._raw.checkPlacement(this._handle(), numArg(x, 'x'), numArg(y, 'y'))); }
  /**
   * Plays an action for the seat to act, in the records' form, every field given:
   * {type: 'place_cue_ball', position: [x, y]},
   * {type: 'shoot', strike: {speed, phi, theta, a, b}, call: {ball, pocket} | null, safety, push_out}
   * or {type: 'decide', choice}.
   */
  act(action) { return parse(this._raw.act(this._handle(), toJson(action))); }
  /** {action}: the AI's decision for the seat to act (its own level, or `level` for a hint), in the form act() takes. */
  aiAction(level) { return parse(this._raw.aiAction(this._handle(), level === undefined || level === null || level === '' ? null : String(level))); }
  /** The playback of the shot of action `index`, from the state before it. */
  shotPlayback(index) { return newPlayback(this._raw, this._raw.shotPlayback(this._handle(), intArg(index, 'index'))); }
  /** The link text ("v2.…"; "v1.…" links still open). */
  link() { return parse(this._raw.link(this._handle())).link; }
  /** The game record (the object of write_record's JSON). */
  record() { return parse(this._raw.record(this._handle())); }
  /** The game record as text, exactly as `breakshot replay` reads it. */
  recordText() {
    const text = this._raw.record(this._handle());
    parse(text);
    return text;
  }
  /** Whose turn it is after each action, and why: [{next, why}, ...]
   *  (bs_web_game_turns; act()'s reply carries its action's as "turn"). */
  turns() { return parse(this._raw.turns(this._handle())).turns; }
  /** Keeps the first n actions; returns the state. */
  undoTo(n) { return parse(this._raw.undoTo(this._handle(), intArg(n, 'n'))); }
  free() {
    if (this._h) this._raw.gameFree(this._h);
    this._h = 0;
  }
}

function newGame(raw, handle) {
  if (!handle) parse(raw.lastError());
  return new Game(raw, handle);
}

async function instantiate(options) {
  const M = await createBreakshot(options || {});
  const raw = rawApi(M);
  const info = parse(raw.version());
  return {
    raw,
    levels: info.levels,
    aiBudgets: info.ai_budgets,
    // the computer players of a snooker seat
    snookerPlayers: info.snooker_players,
    // the computer players a seat of `game` may be (bs_web_game_players): the
    // AI levels that play it, and "baseline" where it plays
    gamePlayers: (game) => parse(raw.gamePlayers(String(game))).players,
    // The engine's defaults (default_physics per model, the default ball):
    // the one home of them, so the page never keeps its own copy.
    defaults: info.defaults,
    version: () => info.version,
    simulate: (scenario) => parse(raw.simulate(toJson(scenario))),
    playback: (scenario) => newPlayback(raw, raw.playbackNew(toJson(scenario))),
    newGame: (config) => newGame(raw, raw.gameNew(toJson(config))),
    gameFromLink: (link) => newGame(raw, raw.gameFromLink(String(link))),
  };
}

let shared = null;

/**
 * The engine API. One instance per page or worker is shared by all
 * callers; {fresh: true} makes a new one. Other options go to the
 * emscripten module factory.
 */
export function loadEngine(options = {}) {
  const { fresh, ...moduleOptions } = options || {};
  if (fresh) return instantiate(moduleOptions);
  if (!shared) {
    shared = instantiate(moduleOptions);
    shared.catch(() => { shared = null; });
  }
  return shared;
}

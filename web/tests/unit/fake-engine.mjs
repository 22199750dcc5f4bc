// A fake engine game for the page's unit tests: engine.js's Game
// interface (table, state, record, turns, act, undoTo, checkPlacement,
// link, free) over states the test writes, so that game-flow.js runs in
// node without the wasm build. act() answers from a list of replies the
// test gives, in order, and records what it was asked.

/** A 9 ft pool table as bs_web_game_table gives it (the fields the flow reads). */
export function poolTable() {
  const L = 2.54;
  const W = 1.27;
  const pocket = (x, y, name) => ({ centre: [x, y], radius: 0.06, name });
  return {
    size: '9ft',
    length: L,
    width: W,
    ball_radius: 0.028575,
    head_spot: [L / 4, W / 2],
    foot_spot: [(3 * L) / 4, W / 2],
    pockets: [
      pocket(0, 0, 'bottom_left'), pocket(L / 2, -0.02, 'side_bottom'), pocket(L, 0, 'bottom_right'),
      pocket(L, W, 'top_right'), pocket(L / 2, W + 0.02, 'side_top'), pocket(0, W, 'top_left'),
    ],
  };
}

/** A state of `game` with the balls at `position` (by number; null: off
 *  the table), seat `player` to act and `legal` as the rules allow. */
export function state(game, position, { player = 0, phase = 'shot', legal = { shoot: true, place: 'none', targets: [] }, players = ['human', 'human'], ...more } = {}) {
  return {
    game,
    phase,
    player,
    players,
    breaker: 0,
    winner: -1,
    shots: 0,
    position: position.map((p) => p || [0, 0]),
    on_table: position.map((p) => !!p),
    legal,
    ...more,
  };
}

export class FakeGame {
  constructor({ table = poolTable(), start, actions = [], turns = [], replies = [], placement = () => ({ ok: true }) }) {
    this._table = table;
    this._start = start;
    this._actions = actions;     // the record's actions: {player, action, ruling, after}
    this._turns = turns;
    this._replies = replies;     // act()'s replies, in order
    this._placement = placement;
    this.asked = [];             // the actions act() was given
    this.undone = [];            // undoTo's arguments
    this.freed = false;
  }

  table() { return this._table; }

  state() { return this._actions.length ? this._actions[this._actions.length - 1].after : this._start; }

  record() { return { start: this._start, actions: this._actions, config: { game: this._start.game } }; }

  turns() { return this._turns.slice(0, this._actions.length); }

  checkPlacement(x, y) { return this._placement(x, y); }

  link() { return 'v2.fake'; }

  act(action) {
    this.asked.push(action);
    const reply = this._replies.shift();
    if (!reply) throw new Error('the fake game has no reply left');
    if (reply.error) return reply;
    this._actions.push({ player: reply.player, action: reply.executed, ruling: reply.ruling, after: reply.state });
    this._turns.push(reply.turn);
    return reply;
  }

  undoTo(n) {
    this.undone.push(n);
    this._actions = this._actions.slice(0, n);
    return this.state();
  }

  free() { this.freed = true; }
}

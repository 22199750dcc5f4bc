// Online play on the page (docs/web.md, "Online play"): a game with a
// friend on another computer through `breakshot serve`'s WebSocket (/ws).
//
// Lockstep: the page plays every action on its own engine, as it does
// off-line (GameUI.doAct), and sends its own actions to the server; the
// server plays them with the same rules and sends every action of the
// room, with the hash of the state after it, to both players and the
// watchers. The page compares that hash with its own and shows a
// difference. The room code is in the link (#room=CODE). A seat's token
// is kept twice: in sessionStorage, the tab's own (a reload or a broken
// connection takes the seat back, replacing a connection the server has
// not yet seen go), and in localStorage, the browser's tokens of the room
// (a closed tab opened again takes its seat back). A tab without a token
// of its own tries the browser's without replacing anyone: a seat another
// tab plays is refused ("seat_in_use"), and the tab takes the free seat,
// or watches.

const TOKEN_KEY = 'breakshot.online.';

/** FNV-1a, 64 bits, of the UTF-8 bytes of `text`, as 16 hex digits
 *  (rooms.hpp's state_hash). */
export function stateHash(text) {
  const bytes = new TextEncoder().encode(text);
  let h = 0xcbf29ce484222325n;
  const prime = 0x100000001b3n;
  const mask = 0xffffffffffffffffn;
  for (const b of bytes) {
    h ^= BigInt(b);
    h = (h * prime) & mask;
  }
  return h.toString(16).padStart(16, '0');
}

const $ = (id) => document.getElementById(id);

export class Online {
  /** ui: the GameUI; E: the engine. */
  constructor(ui, E) {
    this.ui = ui;
    this.E = E;
    this.ws = null;
    this.room = null;
    this.seat = null;       // 0, 1, or null (watching)
    this.connected = false;
    this.mismatch = null;   // the first index whose hash differs
    this.hashes = [];       // this page's hash after each action
    this.inbox = [];        // the room's actions not yet played here
    this.unconfirmed = 0;   // own actions sent, not yet echoed by the server
    this.closedByUs = false;
    this.retry = null;
    this.presence = null;
    this.over = null;
    this.trying = null;     // the token of the rejoin awaiting its answer
    this.candidates = [];   // the browser's tokens of the room not tried yet
    this.displaced = false;
    this.pump = setInterval(() => this.playQueued(), 50);
  }

  // ---- starting ----

  /** Creates a room for a game of `config` (the form's: game, table,
   *  breaker, carom, physics). */
  create(config) {
    const game = {};
    for (const k of ['game', 'table', 'breaker', 'carom', 'physics']) {
      if (config[k] !== undefined) game[k] = config[k];
    }
    this.open(() => this.send({ type: 'create', game }));
  }

  /** Joins the room `code`: takes back this browser's seat if it has its
   *  token, else the free seat, else watches. */
  join(code) {
    this.room = String(code).toUpperCase();
    this.open(() => this.hello());
  }

  hello() {
    const own = this.ownToken(this.room);
    if (own) {
      this.trying = own;
      this.candidates = [];
      this.send({ type: 'rejoin', room: this.room, token: own, replace: true });
      return;
    }
    this.candidates = this.browserTokens(this.room);
    this.tryNext();
  }

  /** Rejoins with the browser's next token of the room, without taking a
   *  seat from another tab; when none is left, joins (the free seat, or
   *  watching). */
  tryNext() {
    const token = this.candidates.shift();
    this.trying = token || null;
    if (token) this.send({ type: 'rejoin', room: this.room, token });
    else this.send({ type: 'join', room: this.room });
  }

  /** This tab's token of room `code` (sessionStorage), or null. */
  ownToken(code) {
    try { return sessionStorage.getItem(TOKEN_KEY + code); } catch (e) { return null; }
  }

  /** The browser's tokens of room `code` (localStorage: a list, or one
   *  token as older pages kept it). */
  browserTokens(code) {
    let v = null;
    try { v = localStorage.getItem(TOKEN_KEY + code); } catch (e) { return []; }
    if (!v) return [];
    try {
      const list = JSON.parse(v);
      if (Array.isArray(list)) return list.filter((t) => typeof t === 'string');
    } catch (e) { /* an older page's single token */ }
    return [v];
  }

  keepToken(code, token) {
    try { sessionStorage.setItem(TOKEN_KEY + code, token); } catch (e) { /* private mode */ }
    const list = this.browserTokens(code).filter((t) => t !== token);
    list.push(token);
    try { localStorage.setItem(TOKEN_KEY + code, JSON.stringify(list.slice(-2))); } catch (e) { /* private mode */ }
  }

  forgetToken(code, token) {
    try { if (sessionStorage.getItem(TOKEN_KEY + code) === token) sessionStorage.removeItem(TOKEN_KEY + code); } catch (e) { /* ignore */ }
    const list = this.browserTokens(code).filter((t) => t !== token);
    try {
      if (list.length) localStorage.setItem(TOKEN_KEY + code, JSON.stringify(list));
      else localStorage.removeItem(TOKEN_KEY + code);
    } catch (e) { /* ignore */ }
  }

  open(first) {
    this.closedByUs = false;
    const url = `${location.protocol === 'https:' ? 'wss:' : 'ws:'}//${location.host}/ws`;
    let ws;
    try {
      ws = new WebSocket(url);
    } catch (e) {
      this.status(`Cannot reach the server: ${e.message || e}`);
      return;
    }
    this.ws = ws;
    ws.addEventListener('open', () => { this.connected = true; first(); });
    // a socket this page has left behind (resync) speaks no more for it
    ws.addEventListener('message', (ev) => { if (this.ws === ws) this.receive(ev.data); });
    ws.addEventListener('close', () => {
      this.connected = false;
      if (this.ws !== ws || this.closedByUs) return;
      // The network or the server went away: try again, with the token.
      this.status('The connection to the server was lost; reconnecting…');
      if (this.room) this.retry = setTimeout(() => this.open(() => this.hello()), 2000);
    });
  }

  /** Leaves online play (a new game on this page). */
  leave() {
    this.closedByUs = true;
    clearTimeout(this.retry);
    clearInterval(this.pump);
    if (this.ws) { try { this.ws.close(); } catch (e) { /* gone */ } }
    this.ws = null;
    const box = $('online-box');
    if (box) box.hidden = true;
  }

  send(msg) {
    if (this.ws && this.ws.readyState === WebSocket.OPEN) this.ws.send(JSON.stringify(msg));
  }

  // ---- the page's own actions ----

  /** Whether the page may play for the seat to act. */
  mayAct(st) {
    const started = !!this.presence && this.presence.taken[0] && this.presence.taken[1];
    return this.seat !== null && started && !!st && st.player === this.seat && !this.over;
  }

  /** After the page played its own action `index` (GameUI.doAct): send it. */
  played(index, action) {
    this.hashes[index] = stateHash(this.ui.g.stateText());
    this.unconfirmed += 1;
    this.send({ type: 'act', index, action });
  }

  // ---- the server's messages ----

  receive(text) {
    let m;
    try { m = JSON.parse(text); } catch (e) { return; }
    if (m.type === 'joined') this.joined(m);
    else if (m.type === 'action') { this.inbox.push(m); this.playQueued(); }
    else if (m.type === 'seats') { this.presence = m; this.show(); this.ui.updatePanel(); }
    else if (m.type === 'over') { this.over = m; this.show(); this.ui.updatePanel(); }
    else if (m.type === 'refused') this.refused(m.reason, m);
    else if (m.type === 'replaced') this.replaced();
    else if (m.type === 'error') this.status(`The server: ${m.reason}`);
  }

  refused(reason, m = {}) {
    if (m.seat_in_use && this.room && this.trying) {
      // another tab of this browser plays that seat: try the next token,
      // then the free seat, then watch
      this.tryNext();
      return;
    }
    if (/token holds no seat/.test(reason) && this.room && this.trying) {
      // a token of an older room of the same code: forget it
      this.forgetToken(this.room, this.trying);
      this.tryNext();
      return;
    }
    this.ui.showError(`The server refused: ${reason}`);
    // the page played its action already: go back to the server's game
    if (this.unconfirmed > 0) this.resync();
  }

  /** The seat was taken by another page with its token (this tab's
   *  duplicate, say): this page stops, without reconnecting, so that the
   *  two never take it from each other in turn. */
  replaced() {
    this.closedByUs = true;
    clearTimeout(this.retry);
    this.seat = null;
    this.displaced = true;
    this.status(`Room ${this.room}: this seat is now played in another tab or window; reload this page to take it back.`);
  }

  /** Takes the game from the server again: a new connection, which
   *  rejoins the seat (or watches) and gets the log. */
  resync() {
    if (!this.room) return;
    const old = this.ws;
    this.ws = null;
    if (old) { try { old.close(); } catch (e) { /* gone */ } }
    this.open(() => this.hello());
  }

  joined(m) {
    this.room = m.room;
    this.seat = m.seat === null || m.seat === undefined ? null : m.seat;
    this.trying = null;
    this.candidates = [];
    if (m.token) this.keepToken(m.room, m.token);
    let g;
    try {
      g = this.E.newGame(m.config);
      this.hashes = [];
      m.actions.forEach((a, i) => {
        const r = g.act(a);
        if (r.error) throw new Error(`action ${i} of the log: ${r.error}`);
        this.hashes[i] = null;
      });
    } catch (e) {
      this.ui.showError(`Cannot follow the online game: ${e.message || e}`);
      return;
    }
    this.inbox = [];
    this.unconfirmed = 0;
    this.ui.install(g, { online: this });
    const mine = stateHash(g.stateText());
    if (mine !== m.hash) this.differs(m.actions.length - 1, mine, m.hash);
    const link = `${location.origin}${location.pathname}#room=${m.room}`;
    try { history.replaceState(null, '', `#room=${m.room}`); } catch (e) { /* ignore */ }
    $('online-link').value = link;
    this.show();
  }

  /** Plays the room's next action here when the page is not busy. */
  playQueued() {
    if (!this.inbox.length || this.ui.busy() || !this.ui.g) return;
    const m = this.inbox.shift();
    const n = this.ui.st ? this.ui.st.actions : 0;
    if (m.index < n) {
      // this page's own action, played already: compare
      const mine = this.hashes[m.index];
      if (this.unconfirmed > 0) this.unconfirmed -= 1;
      if (mine && mine !== m.hash) this.differs(m.index, mine, m.hash);
      this.show();
      return;
    }
    if (m.index > n) {
      this.resync();  // a gap: take the log again
      return;
    }
    const r = this.ui.doAct(m.action, { remote: true });
    if (r.error) {
      this.ui.showError(`This page's rules refuse the server's action ${m.index}: ${r.error}`);
      this.differs(m.index, 'refused', m.hash);
      return;
    }
    const mine = stateHash(this.ui.g.stateText());
    this.hashes[m.index] = mine;
    if (mine !== m.hash) this.differs(m.index, mine, m.hash);
    this.show();
  }

  differs(index, mine, theirs) {
    if (this.mismatch === null) this.mismatch = { index, mine, theirs };
    this.show();
  }

  // ---- what the page shows ----

  status(text) {
    const el = $('online-status');
    if (el) el.textContent = text;
    const box = $('online-box');
    if (box) box.hidden = false;
  }

  show() {
    if (this.displaced) return;  // replaced() said why this page stopped
    const who = this.seat === null ? 'You are watching' : `You are Player ${this.seat + 1}`;
    let friend = '';
    if (this.presence) {
      const c = this.presence.connected;
      if (this.seat === null) friend = `players here: ${c.filter(Boolean).length} of 2`;
      else if (!this.presence.taken[1 - this.seat]) friend = 'waiting for your friend to open the link';
      else friend = c[1 - this.seat] ? 'your friend is here' : 'your friend is away';
    }
    let over = '';
    if (this.over) {
      over = this.over.forfeit ? ` Game over: ${this.over.result}.` : '';
    }
    this.status(`Room ${this.room}. ${who}; ${friend}.${over}`);
    const bad = $('online-mismatch');
    if (this.mismatch) {
      bad.hidden = false;
      bad.textContent = `The table here differs from the server's after action ${this.mismatch.index} ` +
        `(hash ${this.mismatch.mine} here, ${this.mismatch.theirs} on the server).`;
    } else {
      bad.hidden = true;
    }
  }
}

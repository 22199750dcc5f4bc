// The AI as a player (docs/js.md, "Player"): decide(game) hands the game's
// link to worker.js (the page's AI worker, shipped as it is), which
// rebuilds the game with an engine of its own and asks the AI of the
// player's level; the reply is the action, which the caller plays with
// game.act(). In a browser the worker is a module Web Worker, in node a
// worker_thread, so the caller's thread never blocks; {inline: true}
// decides in the calling thread instead (the same action: the AI's
// seeds are the game's). One worker per Player, started at the first
// decision and kept until close(); in node it does not keep the process
// alive while no decision is pending.

import { loadEngine } from './engine.js';

const isNode = typeof process !== 'undefined' && process.versions != null &&
  typeof process.versions.node === 'string' && typeof window === 'undefined';

function linkOf(game) {
  if (typeof game === 'string') return game;
  if (game && typeof game.link === 'function') return game.link();
  throw new Error('decide: expected a Game or a link, not ' + (game === null ? 'null' : typeof game));
}

// A worker behind one interface: post(message), onMessage, onError, ref/unref, terminate.
async function startWorker(onMessage, onError) {
  const url = new URL('./worker.js', import.meta.url);
  if (isNode) {
    const { Worker } = await import('node:worker_threads');
    const w = new Worker(url);
    w.on('message', onMessage);
    w.on('error', (e) => onError(e && e.message ? e.message : String(e)));
    w.on('exit', (code) => { if (code !== 0) onError(`the worker exited with code ${code}`); });
    return { post: (m) => w.postMessage(m), ref: () => w.ref(), unref: () => w.unref(), terminate: () => w.terminate() };
  }
  const w = new Worker(url, { type: 'module' });
  w.addEventListener('message', (ev) => onMessage(ev.data));
  w.addEventListener('error', (ev) => {
    if (ev && ev.preventDefault) ev.preventDefault();
    onError(ev && ev.message ? ev.message : 'the worker could not be started');
  });
  w.addEventListener('messageerror', () => onError('a message from the worker could not be read'));
  return { post: (m) => w.postMessage(m), ref: () => {}, unref: () => {}, terminate: () => w.terminate() };
}

export class Player {
  /**
   * level: an AI level ("beginner" ... "champion"), at a noise
   * ("champion@0.5x"), or "baseline" where the game has it; checked
   * against the game at each decision. options.inline: decide in the
   * calling thread.
   */
  constructor(level, options = {}) {
    if (typeof level !== 'string' || level === '') throw new Error(`level: expected an AI level's name, not ${JSON.stringify(level)}`);
    this._level = level;
    this._inline = Boolean(options && options.inline);
    this._worker = null;
    this._starting = null;
    this._pending = new Map();
    this._next = 0;
    this._closed = false;
  }

  get level() { return this._level; }
  get inline() { return this._inline; }

  /**
   * The player's action for the seat to act in `game` (a Game or its
   * link), in the form game.act() takes. Rejects with the engine's
   * message (an unknown level, a game that is over).
   */
  async decide(game) {
    if (this._closed) throw new Error('this player has been closed');
    const link = linkOf(game);
    if (this._inline) {
      const E = await loadEngine();
      const g = E.gameFromLink(link);
      try {
        return g.aiAction(this._level).action;
      } finally {
        g.free();
      }
    }
    const w = await this._ensureWorker();
    if (this._closed) throw new Error('this player has been closed');
    const id = ++this._next;
    return new Promise((resolve, reject) => {
      this._pending.set(id, { resolve, reject });
      if (this._pending.size === 1) w.ref();
      w.post({ id, link, level: this._level });
    });
  }

  _ensureWorker() {
    if (this._worker) return Promise.resolve(this._worker);
    if (!this._starting) {
      this._starting = startWorker((m) => this._reply(m), (why) => this._fail(why)).then((w) => {
        this._worker = w;
        this._starting = null;
        if (this._closed) w.terminate();
        return w;
      }, (e) => {
        this._starting = null;
        throw new Error(`the AI worker could not be started: ${e && e.message ? e.message : e}`);
      });
    }
    return this._starting;
  }

  _reply(m) {
    const p = m && this._pending.get(m.id);
    if (!p) return;
    this._pending.delete(m.id);
    if (this._pending.size === 0 && this._worker) this._worker.unref();
    if (typeof m.error === 'string') p.reject(new Error(m.error));
    else p.resolve(m.action);
  }

  _fail(why) {
    const pending = [...this._pending.values()];
    this._pending.clear();
    if (this._worker) {
      try { this._worker.terminate(); } catch (e) { /* gone */ }
    }
    this._worker = null;
    for (const p of pending) p.reject(new Error(`the AI worker failed: ${why}`));
  }

  /** Stops the worker; decisions still pending reject. Safe to call twice. */
  close() {
    if (this._closed) return;
    this._closed = true;
    const pending = [...this._pending.values()];
    this._pending.clear();
    if (this._worker) this._worker.terminate();
    this._worker = null;
    for (const p of pending) p.reject(new Error('this player has been closed'));
  }
}

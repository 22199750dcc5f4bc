// The AI worker client: posts the game's link and the level to
// worker.js (its own engine) and hands back the action it chose. One
// request at a time; a newer request or a cancel makes the older reply
// stale, and a cancelled search (which cannot be interrupted) leaves the
// worker for a fresh one.

import { message } from './game-flow.js';

export class AiClient {
  /** onAction(action) plays the AI's choice; onError(text) reports a failure. */
  constructor({ onAction, onError }) {
    this.onAction = onAction;
    this.onError = onError;
    this.worker = null;
    this.reqId = 0;
    this.thinking = false;
  }

  ensureWorker() {
    if (this.worker) return this.worker;
    const w = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    w.addEventListener('message', (ev) => this.onReply(ev.data));
    w.addEventListener('error', (ev) => {
      if (ev && ev.preventDefault) ev.preventDefault();
      this.thinking = false;
      this.worker = null;
      try { w.terminate(); } catch (e) { /* gone */ }
      this.onError(`The AI worker failed${ev && ev.message ? `: ${ev.message}` : ''}`);
    });
    w.addEventListener('messageerror', () => {
      this.thinking = false;
      this.onError('The AI worker sent a message that could not be read');
    });
    this.worker = w;
    return w;
  }

  /** Asks the worker for `level`'s action in the game of `link`; false if
   *  the worker could not be started (onError was told). */
  request(link, level) {
    const id = ++this.reqId;
    this.thinking = true;
    try {
      this.ensureWorker().postMessage({ id, link, level });
      return true;
    } catch (e) {
      this.thinking = false;
      this.onError(`Cannot start the AI: ${message(e)}`);
      return false;
    }
  }

  onReply(data) {
    if (!data || data.id !== this.reqId || !this.thinking) return;
    this.thinking = false;
    if (data.error) {
      this.onError(`The AI failed: ${data.error}`);
      return;
    }
    this.onAction(data.action);
  }

  cancel() {
    this.reqId++;
    if (this.thinking && this.worker) {
      // a long search cannot be interrupted: start a fresh worker next time
      try { this.worker.terminate(); } catch (e) { /* gone */ }
      this.worker = null;
    }
    this.thinking = false;
  }
}

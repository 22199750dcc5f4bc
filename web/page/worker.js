// The AI worker: a module worker with its own engine, the page's
// (game-ai.js) and the npm package's Player's (docs/js.md). Message in:
// {id, link, level}; it rebuilds the game from the link, asks the AI of
// `level` for the decision of the seat to act and posts {id, action}, or
// {id, error} when something fails. The caller plays the action on its
// own game, so both hold the same game by construction (docs/web.md).
// It runs as a browser's Web Worker (self) or a node worker_thread
// (parentPort), the same code behind either.

import { loadEngine } from './engine.js';

let enginePromise = null;

function engine() {
  if (!enginePromise) enginePromise = loadEngine();
  return enginePromise;
}

async function reply(data, post) {
  const id = data && data.id;
  let g = null;
  try {
    const E = await engine();
    g = E.gameFromLink(String(data.link));
    const answer = g.aiAction(data.level || undefined);
    const action = answer && typeof answer === 'object' && 'action' in answer ? answer.action : answer;
    post({ id, action });
  } catch (e) {
    post({ id, error: e && e.message ? e.message : String(e) });
  } finally {
    if (g) {
      try { g.free(); } catch (e) { /* already freed */ }
    }
  }
}

if (typeof self !== 'undefined' && typeof self.postMessage === 'function') {
  // a Web Worker: the listener is added at once, before any message arrives
  self.addEventListener('message', (ev) => reply(ev.data || {}, (m) => self.postMessage(m)));
} else {
  // a node worker_thread: parentPort keeps messages until a listener is added
  import('node:worker_threads').then(({ parentPort }) => {
    if (parentPort) parentPort.on('message', (data) => reply(data || {}, (m) => parentPort.postMessage(m)));
  });
}

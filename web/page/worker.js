// The AI worker: a module worker with its own engine. Message in:
// {id, link, level}; it rebuilds the game from the link, asks the AI of
// `level` for the decision of the seat to act and posts {id, action}, or
// {id, error} when something fails. The page plays the action on its own
// game, so both hold the same game by construction (docs/web.md).

import { loadEngine } from './engine.js';

let enginePromise = null;

function engine() {
  if (!enginePromise) enginePromise = loadEngine();
  return enginePromise;
}

self.addEventListener('message', async (ev) => {
  const data = ev.data || {};
  const id = data.id;
  let g = null;
  try {
    const E = await engine();
    g = E.gameFromLink(String(data.link));
    const reply = g.aiAction(data.level || undefined);
    const action = reply && typeof reply === 'object' && 'action' in reply ? reply.action : reply;
    self.postMessage({ id, action });
  } catch (e) {
    self.postMessage({ id, error: e && e.message ? e.message : String(e) });
  } finally {
    if (g) {
      try { g.free(); } catch (e) { /* already freed */ }
    }
  }
});

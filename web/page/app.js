// The page shell: loads the engine, switches between the Game and Lab
// tabs, routes the URL fragment (#game=<link>[&shot=k], #lab) and exposes
// the test hooks (window.breakshot, docs/web.md).

import { GameUI } from './game.js';
import { Online } from './online.js';

const $ = (id) => document.getElementById(id);

let engine = null;
let ui = null;
let labMounted = false;
let labLoading = null;
let seedCounter = 0;

function setError(text) {
  const el = $('status-error');
  if (!el) return;
  el.textContent = text;
  el.hidden = false;
}

/** The fragment as key/value pairs: "#game=v2.abc&shot=3". */
function parseFragment() {
  const h = location.hash.replace(/^#/, '');
  const out = {};
  if (!h) return out;
  for (const part of h.split('&')) {
    const i = part.indexOf('=');
    if (i < 0) out[decodeURIComponent(part)] = '';
    else out[decodeURIComponent(part.slice(0, i))] = decodeURIComponent(part.slice(i + 1));
  }
  return out;
}

function selectTab(name) {
  const game = name !== 'lab';
  $('tab-game').setAttribute('aria-selected', String(game));
  $('tab-lab').setAttribute('aria-selected', String(!game));
  $('game').hidden = !game;
  const lab = $('lab');
  if (lab) lab.hidden = game;
  if (game) {
    if (ui) ui.layout();
  } else {
    openLab();
  }
}

function openLab() {
  let lab = $('lab');
  if (!lab) {
    lab = document.createElement('section');
    lab.id = 'lab';
    lab.className = 'view';
    $('views').appendChild(lab);
  }
  lab.hidden = false;
  if (labMounted || labLoading) return;
  if (!engine) {
    lab.textContent = 'The engine is still loading…';
    return;
  }
  lab.textContent = 'Loading the lab…';
  labLoading = import('./lab.js')
    .then((mod) => {
      lab.textContent = '';
      if (typeof mod.mountLab !== 'function') throw new Error('lab.js has no mountLab');
      mod.mountLab(lab, engine);
      labMounted = true;
    })
    .catch((e) => {
      lab.textContent = '';
      const p = document.createElement('p');
      p.className = 'lab-missing';
      p.textContent = `The lab is not available: ${e && e.message ? e.message : e}`;
      lab.appendChild(p);
    })
    .finally(() => { labLoading = null; });
}

function formConfig() {
  const opponent = $('opponent').value;
  let seed = $('seed').value.trim();
  if (!/^\d{1,19}$/.test(seed)) {
    // the clock and a counter, at new-game time only; the link keeps it
    seedCounter += 1;
    seed = String(Date.now() * 16 + (seedCounter % 16));
  }
  const config = {
    game: $('game-type').value,
    table: $('table-size').value,
    seed,
    breaker: Number($('breaker').value),
    players: ['human', opponent === 'friend' ? 'human' : opponent],
    physics: { airborne: $('airborne').checked },
  };
  // three-cushion: the distance; the innings limit and the equalizing
  // inning keep the engine's defaults
  if (config.game === 'three_cushion') config.carom = { target: Number($('carom-target-points').value) };
  return config;
}

/** The engine's default of a game's physics.airborne (GamePhysics), from
 *  the record of a game made without a physics: the page keeps no copy. */
function defaultAirborne() {
  let g = null;
  try {
    g = engine.newGame({ game: 'eight_ball', players: ['human', 'human'], seed: '0' });
    return !!g.record().physics.airborne;
  } catch (e) {
    return false;
  } finally {
    if (g) { try { g.free(); } catch (e) { /* gone */ } }
  }
}

function startFromForm() {
  if (!ui) return;
  const cfg = formConfig();
  if (ui.newGame(cfg)) {
    // a fresh game has no link in the address bar until it is shared
    if (location.hash.startsWith('#game=') || location.hash.startsWith('#room=')) {
      try { history.replaceState(null, '', location.pathname + location.search); } catch (e) { /* ignore */ }
    }
  }
}

/** Online play: creates a room for the form's game, or joins `code`. */
let online = null;
function startOnline(code) {
  if (!ui) return;
  if (online && ui.online === online && code && online.room === code.toUpperCase()) return;
  if (online) online.leave();
  online = new Online(ui, engine);
  if (code) online.join(code);
  else online.create(formConfig());
}

function route() {
  const f = parseFragment();
  if (f.room && /^[A-Za-z0-9]{1,12}$/.test(f.room)) {
    selectTab('game');
    if (!ui.g) ui.newGame(formConfig());  // a table to show while the room answers
    startOnline(f.room);
    return 'game';
  }
  if ('lab' in f) {
    selectTab('lab');
    return 'lab';
  }
  if (f.game) {
    selectTab('game');
    let shot = null;
    if (f.shot != null && /^\d+$/.test(f.shot)) shot = Number(f.shot);
    const why = ui.openLink(f.game, shot);
    if (why !== true) {
      // a broken link: keep (or start) a game and say what is wrong
      if (!ui.g) startFromForm();
      ui.showError(`Cannot open the link: ${why}`);
    }
    syncForm();
    return 'game';
  }
  return false;
}

/** The computer players of `game` as the engine gives them
 *  (bs_web_game_players), else `fallback`. */
function computerPlayers(game, fallback) {
  try {
    const list = engine && engine.gamePlayers ? engine.gamePlayers(game) : null;
    if (Array.isArray(list) && list.length) return list;
  } catch (e) { /* an engine that cannot say: the fallback */ }
  return fallback;
}

/** The opponents and tables the form offers for the chosen game: the AI
 *  levels and the pool tables; in snooker the engine's snooker players
 *  (bs_web_version's "snooker_players") and the 12 ft table; in three-cushion
 *  the players the engine says play it (bs_web_game_players; the baseline
 *  when it cannot say), the strongest chosen unless the opponent chosen
 *  before plays it too, and the 10 ft carom table. */
let poolOpponents = null;
let poolTables = null;
function gameOptions() {
  const opp = $('opponent');
  const table = $('table-size');
  if (!poolOpponents) {
    poolOpponents = [...opp.options].map((o) => [o.value, o.text, o.defaultSelected]);
    poolTables = [...table.options].map((o) => [o.value, o.text, o.defaultSelected]);
  }
  const game = $('game-type').value;
  const snooker = game === 'snooker';
  const carom = game === 'three_cushion';
  let want = poolOpponents;
  if (snooker) {
    want = [...((engine && engine.snookerPlayers) || ['club']).map((p) => [p, p === 'baseline' ? 'Computer: baseline' : `AI: ${p}`, p === 'club']), ['friend', 'A friend (same screen)', false]];
  } else if (carom) {
    // the AI levels that play three-cushion run from the weakest; with
    // none, the baseline is the only computer player (and the strongest)
    const players = computerPlayers('three_cushion', ['baseline']);
    const levels = players.filter((p) => p !== 'baseline');
    const strongest = levels.length ? levels[levels.length - 1] : 'baseline';
    want = [...players.map((p) => [p, p === 'baseline' ? 'Computer: baseline' : `AI: ${p}`, p === strongest]),
      ['friend', 'A friend (same screen)', false]];
  }
  const tables = snooker ? [['12ft', '12 ft', true]] : carom ? [['10ft', '10 ft carom', true]] : poolTables;
  const fill = (sel, list) => {
    const key = list.map((x) => x[0]).join(',');
    if (sel.dataset.key === key) return;
    const keep = sel.value;
    sel.dataset.key = key;
    sel.textContent = '';
    for (const [v, t, d] of list) sel.appendChild(new Option(t, v, d, d));
    if (list.some((x) => x[0] === keep)) sel.value = keep;
  };
  fill(opp, want);
  fill(table, tables);
  $('carom-target-box').hidden = !carom;
}

function syncForm() {
  if (!ui || !ui.st) return;
  const st = ui.st;
  $('game-type').value = st.game;
  gameOptions();
  if (st.players && st.players[1]) $('opponent').value = st.players[1] === 'human' ? 'friend' : st.players[1];
  const physics = ui.physics();
  if (physics) $('airborne').checked = !!physics.airborne;
  if (st.game === 'three_cushion') {
    const rules = ui.caromRules();
    const sel = $('carom-target-points');
    if (rules && [...sel.options].some((o) => o.value === String(rules.target))) sel.value = String(rules.target);
  }
  // the table's size as the engine names it (bs_web_game_table's "size")
  const size = ui.table && ui.table.size;
  if (size && [...$('table-size').options].some((o) => o.value === size)) $('table-size').value = size;
}

async function main() {
  $('tab-game').addEventListener('click', () => selectTab('game'));
  $('tab-lab').addEventListener('click', () => selectTab('lab'));
  $('new-game').addEventListener('click', () => {
    selectTab('game');
    const box = $('new-game-box');
    box.open = true;
    box.scrollIntoView({ block: 'nearest' });
    $('game-type').focus({ preventScroll: true });
  });
  $('game-type').addEventListener('change', () => gameOptions());
  $('online-create').addEventListener('click', () => startOnline(null));
  $('new-game-form').addEventListener('submit', (ev) => {
    ev.preventDefault();
    startFromForm();
    // the form may be below the table (a phone): back to the table
    const top = $('table').getBoundingClientRect().top;
    if (top < 0 || top > window.innerHeight / 2) window.scrollTo({ top: 0 });
  });
  window.addEventListener('unhandledrejection', (ev) => {
    ev.preventDefault();
    setError(`Error: ${ev.reason && ev.reason.message ? ev.reason.message : ev.reason}`);
  });

  let loadEngine;
  try {
    ({ loadEngine } = await import('./engine.js'));
    engine = await loadEngine();
  } catch (e) {
    $('status-turn').textContent = 'The engine did not load.';
    setError(e && e.message ? e.message : String(e));
    return;
  }
  try {
    const v = engine.version();
    $('version').textContent = `engine ${typeof v === 'string' ? v : (v && v.version) || ''}`;
  } catch (e) { /* no version */ }
  ui = new GameUI(engine);
  gameOptions();  // the form may come back with snooker chosen
  $('airborne').checked = defaultAirborne();

  window.breakshot = {
    engine,
    get game() { return ui.g; },
    state: () => ui.state(),
    act: (action) => ui.act(action),
    busy: () => ui.busy(),
    ui,
    toClient: (x, y) => ui.view.toClient(x, y),
    aim: () => ({ ...ui.aim }),
    link: () => ui.link(),
    // the sounds asked for since the page loaded, by kind, and how many
    // an audio device played (none when muted or without a device)
    sounds: () => {
      const S = ui.sounds;
      return {
        muted: S.muted,
        counts: { ...S.counts },
        played: S.log.filter((e) => e.played).length,
        context: S.ctx ? S.ctx.state : (S.failed ? 'failed' : 'none'),
        last: S.log.slice(-200).map((e) => ({ ...e })),
      };
    },
    online: () => ui.online,
  };

  window.addEventListener('hashchange', () => { route(); });
  const where = route();
  if (where !== 'game') {
    if (!where) selectTab('game');
    startFromForm();  // the game tab always has a game, even when the lab opens first
  }
}

main().catch((e) => setError(e && e.message ? e.message : String(e)));

// The game tab: a game of 8-ball, 9-ball, 10-ball, snooker or three-cushion
// against an AI level or the baseline player (the computer players the
// engine says play the game) or a friend on the same screen. The
// engine (engine.js over the wasm build) does every bit of physics and
// every ruling; the tab takes input, draws the engine's positions and
// keeps the log. Nothing here reaches the engine through Math.random: the
// seed comes from the URL, the form or the clock at new-game time, and
// the link keeps it.
//
// This file wires the tab's modules (docs/web.md, "The game page"):
//   game-flow.js      the game, the turn, the shot's action and undo (no DOM)
//   game-games.js     what each game shows (game-eight.js, game-nine.js,
//                     game-ten.js, game-snooker.js, game-carom.js)
//   game-words.js     the words of the log, the decisions and the seats
//   game-ai.js        the AI worker client
//   game-playback.js  a shot played back, its sounds, the balls rolling
//   game-input.js     the controls, the keys and the pointer
//   game-stroke.js    the stroke's pull-to-speed (no DOM)
//   game-tip.js       the cue tip widget
//   game-panel.js     the panel, the status line and the game's panel
//   game-log.js       the ruling log
//   game-scene.js     the scene drawn and the layout

import { TableView } from './draw.js';
import { identityOrientation } from './draw-ball.js';
import { AiClient } from './game-ai.js';
import { $ } from './game-dom.js';
import { GameFlow, linkText, message } from './game-flow.js';
import { bindCanvas, bindControls } from './game-input.js';
import { renderLog } from './game-log.js';
import { clearError, showError, syncControls, updatePanel } from './game-panel.js';
import { animate, bindSound, stepAnimation, stopAnimation } from './game-playback.js';
import { autoCallLabels, layout, nominateLabel, scene } from './game-scene.js';
import { STRIKE_MS } from './game-stroke.js';
import { bindTip } from './game-tip.js';
import { CALL_HOW } from './game-words.js';
import { Sounds } from './sound.js';

export class GameUI {
  constructor(E) {
    this.E = E;
    this.flow = new GameFlow((text) => this.showError(text));
    this.config = null;
    this.drag = null;       // {kind: 'cue' | 'aim', id, dx, dy, x, y, ok, reason}
    this.stroke = null;     // the drag-back stroke: {id, from, pull, speed0}
    this.strike = null;     // the stick pushed through after a stroke: {t0, pull}
    this.aimHeld = false;   // a press fixed the aim: hovering no longer moves it
    this.anim = null;
    this.rafPending = false;
    this.shareNote = '';
    this.ai = new AiClient({
      onAction: (action) => this.doAct(action),
      onError: (text) => {
        this.showError(text);
        this.updatePanel();
      },
    });

    this.canvas = $('table');
    this.view = new TableView(this.canvas);
    this.sounds = new Sounds();
    this.orient = new Map();  // ball n -> its orientation, for drawing (draw-ball.js rotate)
    bindSound(this);
    bindControls(this);
    bindCanvas(this);
    bindTip(this);
    this.layoutObserver = new ResizeObserver(() => this.layout());
    this.layoutObserver.observe($('table-area'));
    window.addEventListener('resize', () => this.layout());
  }

  // The flow's game, state and aim, as the page and its tests read them.
  get g() { return this.flow.g; }
  get st() { return this.flow.st; }
  get table() { return this.flow.table; }
  get R() { return this.flow.R; }
  get players() { return this.flow.players; }
  get log() { return this.flow.log; }
  get online() { return this.flow.online; }
  set online(o) { this.flow.online = o; }
  get aim() { return this.flow.aim; }
  set aim(a) { this.flow.aim = a; }
  get placePos() { return this.flow.placePos; }
  set placePos(p) { this.flow.placePos = p; }

  // ---- public (app.js, online.js and the test hooks) ----

  thinking() { return this.ai.thinking; }

  busy() { return !!this.anim || this.ai.thinking || !!this.strike; }

  state() {
    if (!this.g) return null;
    try {
      return this.g.state();
    } catch (e) {
      this.showError(message(e));
      return null;
    }
  }

  /** Plays an action for the seat to act; returns the reply or {error}. */
  act(action) {
    if (!this.g) return { error: 'no game' };
    if (this.busy()) return { error: 'the page is busy (a shot is running or the AI is thinking)' };
    return this.doAct(action);
  }

  /** Starts a new game; config as E.newGame. Returns true on success. */
  newGame(config) {
    let g;
    try {
      g = this.E.newGame(config);
    } catch (e) {
      this.showError(`Cannot start the game: ${message(e)}`);
      return false;
    }
    this.config = { ...config };
    this.install(g);
    return true;
  }

  /** Opens a game from a link; with shot = k, replays action k's shot.
   *  Returns true, or the reason the link was refused. */
  openLink(link, shot) {
    let g;
    try {
      g = this.E.gameFromLink(link);
    } catch (e) {
      this.showError(`Cannot open the link: ${message(e)}`);
      return message(e);
    }
    this.config = null;
    const replay = shot != null && Number.isInteger(shot);
    this.install(g, { deferAI: replay });
    if (replay) {
      if (this.flow.shotEntry(shot)) {
        this.replay(shot);
      } else {
        this.showError(`The link has no shot ${shot}`);
        this.maybeAI();
      }
    }
    return true;
  }

  /** The game's physics (its record's "physics"), or null. */
  physics() {
    if (!this.g) return null;
    try {
      return this.g.record().physics || null;
    } catch (e) {
      return null;
    }
  }

  link() {
    if (!this.g) return '';
    try {
      return linkText(this.g.link());
    } catch (e) {
      this.showError(message(e));
      return '';
    }
  }

  caromRules() { return this.flow.caromRules(); }

  // ---- game set-up ----

  install(g, opts = {}) {
    // a game of its own leaves online play; an online game comes with it
    if (this.online && this.online !== opts.online) this.online.leave();
    this.online = opts.online || null;
    this.ai.cancel();
    stopAnimation(this);
    this.stroke = null;
    this.strike = null;
    this.clearError();
    this.shareNote = '';
    this.orient = new Map();
    if (!this.flow.install(g)) return;
    this.view.setTable(this.table);
    renderLog(this);
    this.resetControls();   // flow.install set up the first turn
    this.layout();
    this.updatePanel();
    this.requestRender();
    if (!opts.deferAI) this.maybeAI();
  }

  // ---- the turn ----

  canAct() { return !!this.g && !this.busy() && this.flow.humanToAct(); }

  cuePos() { return this.flow.cuePos(); }

  geometry() { return this.flow.geometry(); }

  currentNomination(geo) { return this.flow.currentNomination(geo); }

  /** The boxes ticked under the table (safety, push-out) into the flow. */
  readDeclared() {
    this.flow.declared = { safety: $('safety').checked, pushOut: $('push-out').checked };
  }

  shotAction() {
    this.readDeclared();
    return this.flow.shotAction();
  }

  /** Sets up the aim and the controls for the turn after an action. */
  newTurn(fresh) {
    this.flow.newTurn(fresh);
    this.resetControls();
  }

  /** The controls for a new turn (the flow has set its aim). */
  resetControls() {
    $('safety').checked = false;
    $('push-out').checked = false;
    this.drag = null;
    this.stroke = null;
    this.aimHeld = false;
    this.syncControls();
  }

  setAimToward(p) {
    if (!this.flow.aimAt(p)) return;
    this.syncControls();
    this.requestRender();
  }

  shoot() {
    if (!this.canAct()) return;
    const flow = this.flow;
    if (!flow.shotDue()) {
      const legal = flow.legal();
      this.showError(legal.choices && legal.choices.length ? 'Choose one of the options first.' : 'No shot is due now.');
      return;
    }
    const place = flow.placementDue();
    if (place) {
      const keepAim = { ...this.aim };
      const r = this.doAct(place, { keepAim: true });
      if (r.error) return;
      this.aim = keepAim;
    }
    if (!flow.legal().shoot) {
      this.showError('No shot is due now.');
      return;
    }
    const action = this.shotAction();
    if (flow.legal().must_nominate && action.nominate == null) {
      this.showError('Nominate a colour: click it, aim at it, or choose it under "Nominate".');
      this.updatePanel();
      return;
    }
    const r = this.doAct(action);
    // a game whose every shot is called refuses a shot with no call and
    // no safety; the page shows the rules' reason and how to make a call
    if (r && r.error && flow.callRequired() && !action.call && !action.safety && !action.push_out) {
      this.showError(`${r.error}. ${CALL_HOW}`);
    }
  }

  decide(choice) {
    if (!this.canAct()) return;
    this.doAct({ type: 'decide', choice });
  }

  /** Plays an action with logging, animation and the AI's turn after it. */
  doAct(action, opts = {}) {
    if (this.online && !opts.remote && !this.online.mayAct(this.st)) {
      this.showError('It is not your turn.');
      return { error: 'not your turn' };
    }
    const played = this.flow.play(action);
    if (played.error) {
      this.showError(played.error);
      this.updatePanel();
      this.requestRender();
      return { error: played.error };
    }
    const { reply, entry, prevPhase } = played;
    this.clearError();
    this.shareNote = '';
    if (this.online && !opts.remote) this.online.played(reply.index, reply.executed);
    const addLog = () => {
      this.flow.addToLog(entry);
      renderLog(this);
    };
    // a shot's ruling is shown once its balls have stopped
    if (reply.kind !== 'shoot') addLog();
    const settle = () => {
      if (reply.kind === 'shoot') addLog();
      if (opts.keepAim && reply.kind === 'place') {
        this.flow.replaced();
        this.syncControls();
      } else {
        this.newTurn(prevPhase === 'break_shot' && this.st.phase !== 'break_shot');
      }
      this.updatePanel();
      this.requestRender();
      this.maybeAI();
    };
    if (reply.kind === 'shoot') {
      animate(this, reply.index, reply.numbers, settle, false, entry.ruling);
    } else {
      settle();
    }
    this.updatePanel();
    return reply;
  }

  undo() {
    if (!this.g || this.anim) return;
    const target = this.flow.undoTarget();
    if (target.error) {
      this.showError(target.error);
      return;
    }
    this.ai.cancel();
    const why = this.flow.undoTo(target.index);
    if (why) {
      this.showError(why);
      return;
    }
    this.clearError();
    renderLog(this);
    this.newTurn(false);
    this.updatePanel();
    this.requestRender();
    this.maybeAI();
  }

  // ---- the AI ----

  maybeAI() {
    const st = this.st;
    if (!this.g || !st || this.anim || this.ai.thinking) return;
    if (st.phase === 'game_over') return;
    const level = this.players[st.player];
    if (!level || level === 'human') return;
    let link;
    try {
      link = linkText(this.g.link());
    } catch (e) {
      this.showError(message(e));
      return;
    }
    this.ai.request(link, level);
    this.updatePanel();
  }

  // ---- playback ----

  orientation(n) {
    let o = this.orient.get(n);
    if (!o) {
      o = identityOrientation();
      this.orient.set(n, o);
    }
    return o;
  }

  replay(index) {
    if (!this.g || this.busy()) return;
    const entry = this.flow.shotEntry(index);
    if (!entry) return;
    this.clearError();
    animate(this, index, entry.numbers, () => {
      this.updatePanel();
      this.requestRender();
      this.maybeAI();
    }, true, entry.ruling);
  }

  // ---- drawing ----

  layout() { layout(this); }

  requestRender() {
    if (this.rafPending) return;
    this.rafPending = true;
    requestAnimationFrame((now) => {
      this.rafPending = false;
      try {
        this.frame(now);
      } catch (e) {
        this.anim = null;
        this.showError(`Drawing failed: ${message(e)}`);
      }
    });
  }

  frame(now) {
    if (this.strike && performance.now() - this.strike.t0 >= STRIKE_MS) {
      // the stick has gone through: the shot
      this.strike = null;
      this.shoot();
    }
    if (this.anim) stepAnimation(this, now);
    this.readDeclared();
    const s = scene(this);
    this.view.render(s);
    if (s.call) autoCallLabels(this, s.call);
    nominateLabel(this, s.nominated);
    if (this.anim || this.strike) this.requestRender();
  }

  // ---- the panel ----

  syncControls() { syncControls(this); }

  updatePanel() { updatePanel(this); }

  showError(text) { showError(text); }

  clearError() { clearError(); }

  /** Puts the game's link in the address bar (and the clipboard); with
   *  `shot`, the link also replays that action's shot when opened. */
  async share(shot) {
    if (!this.g) return;
    let link = this.link();
    if (!link) return;
    if (Number.isInteger(shot)) {
      // The game up to and including that shot: the link opens on the
      // table the shot left, after replaying it.
      let g2 = null;
      try {
        g2 = this.E.gameFromLink(link);
        g2.undoTo(shot + 1);
        link = linkText(g2.link());
      } catch (e) {
        this.showError(message(e));
        return;
      } finally {
        if (g2) { try { g2.free(); } catch (e) { /* gone */ } }
      }
    }
    const frag = Number.isInteger(shot) ? `#game=${link}&shot=${shot}` : `#game=${link}`;
    try {
      history.replaceState(null, '', frag);
    } catch (e) {
      location.hash = frag;
    }
    const url = location.href;
    const out = $('share-out');
    out.hidden = false;
    out.textContent = 'The link is in the address bar.';
    try {
      if (navigator.clipboard && window.isSecureContext) {
        await navigator.clipboard.writeText(url);
        out.textContent = 'Link copied (and in the address bar).';
      }
    } catch (e) {
      out.textContent = 'The link is in the address bar (copying was not allowed).';
    }
  }
}

// The panel around the table: the controls' values (power, elevation,
// aim, tip), what may be chosen now (Shoot, Undo, the call, safety and
// push-out boxes, the nomination, concede, the decisions), the hint on
// how to aim, the status line (whose turn, the game's words from
// game-games.js) and the game's panel (the tray, snooker's or
// three-cushion's score). Functions of the GameUI (game.js).

import { $ } from './game-dom.js';
import { POCKET_WORDS, capital, choiceWords, phaseWords } from './game-words.js';
import { powerFromSpeed } from './game-stroke.js';
import { drawTip, tipWords } from './game-tip.js';

export function syncControls(ui) {
  const a = ui.aim;
  $('power').value = String(powerFromSpeed(a.speed));
  $('power-out').textContent = `${a.speed.toFixed(2)} m/s`;
  $('elevation').value = String(a.theta);
  $('elevation-out').textContent = `${Math.round(a.theta)}°`;
  const phiInput = $('phi');
  if (document.activeElement !== phiInput) phiInput.value = a.phi.toFixed(2);
  $('tip-out').textContent = tipWords(a);
  drawTip(a);
}

function choicesBox(ui, st, canAct) {
  const flow = ui.flow;
  const choices = $('choices');
  const list = canAct ? flow.decisions() : [];
  choices.hidden = list.length === 0;
  const key = list.length ? `${phaseWords(st)}:${list.join(',')}` : '';
  if (choices.dataset.key === key) return;
  choices.dataset.key = key;
  choices.textContent = '';
  if (list.length) {
    const p = document.createElement('p');
    p.textContent = phaseWords(st);
    choices.appendChild(p);
  }
  for (const c of list) {
    const b = document.createElement('button');
    b.type = 'button';
    b.id = `choice-${c}`;
    b.dataset.choice = c;
    b.textContent = choiceWords(st, c);
    b.addEventListener('click', () => ui.decide(c));
    choices.appendChild(b);
  }
}

function aimHint(ui, canAct) {
  const hint = $('aim-hint');
  if (!hint) return;
  let text = '';
  if (canAct && ui.flow.shotDue()) {
    const hover = window.matchMedia && window.matchMedia('(hover: hover)').matches;
    if (!hover) text = 'Touch the table to aim. Pull the cue back from behind the cue ball and let go to strike.';
    else if (ui.aimHeld) text = 'Aim held: press on the table to aim again, Esc to aim by pointing. Drag the cue back from behind the cue ball and release to strike.';
    else text = 'Point to aim, press to hold the aim. Drag the cue back from behind the cue ball and release to strike.';
  }
  if (hint.textContent !== text) hint.textContent = text;
}

/** The status line: whose turn and what is due, then the game's words. */
function status(ui, st) {
  const flow = ui.flow;
  const legal = flow.legal();
  const game = flow.game();
  const turn = $('status-turn');
  const gameName = game.name || st.game;
  if (st.phase === 'game_over') {
    const who = st.winner >= 0 ? `${flow.seatName(st.winner)} wins` : 'Draw';
    turn.textContent = `Game over: ${who}.${st.result ? ` ${capital(st.result)}.` : ''}`;
  } else {
    const who = flow.seatName(st.player);
    const deciding = flow.decisions().length > 0;
    let what;
    if (ui.thinking() && deciding) what = `${gameName}: ${who} is choosing (${phaseWords(st)})…`;
    else if (ui.thinking()) what = `${gameName}: ${who} is thinking…`;
    else if (st.phase === 'break_shot') what = `${gameName}: ${who} to break`;
    else if (deciding) what = `${gameName}: ${who} to decide (${phaseWords(st)})`;
    else what = `${gameName}: ${who} to shoot`;
    if (!ui.thinking()) {
      if (legal.place === 'kitchen') what += ' — cue ball in hand behind the head string';
      else if (legal.place === 'anywhere') what += ' — cue ball in hand anywhere';
      else if (legal.place === 'd') what += ' — cue ball in hand in the D';
      if (game.turnNote) what += game.turnNote(st);
    }
    turn.textContent = what;
  }
  const bits = game.statusBits(st, flow.players);
  const f = st.fouls_in_a_row || [0, 0];
  if (game.foulsInARow) bits.push(`fouls in a row: ${f[0]} – ${f[1]}`);
  bits.push(`shots: ${st.shots}`);
  if (ui.shareNote) bits.push(ui.shareNote);
  $('status-info').textContent = bits.join(' · ');
}

/** The game's own panel: the tray of balls, or snooker's or
 *  three-cushion's score (game-games.js's "panel"). */
function gamePanel(ui, st) {
  const flow = ui.flow;
  const game = flow.game();
  const tray = $('tray');
  if (tray) {
    tray.hidden = game.panel !== 'tray';
    if (!tray.hidden) drawTray(tray, game, st, flow.players);
  }
  const score = $('score');
  if (score) {
    score.hidden = !(game.panel === 'score' && st.snooker);
    if (!score.hidden) game.showPanel($, st, flow.players);
  }
  const carom = $('carom-score');
  if (carom) {
    carom.hidden = !(game.panel === 'carom' && st.carom);
    if (!carom.hidden) game.showPanel($, st, flow.players, { rules: flow.caromRules(), last: flow.lastCount() });
  }
}

function drawTray(c, game, st, players) {
  const dpr = Math.min(3, window.devicePixelRatio || 1);
  const W = 320;
  const H = 60;
  if (c.width !== Math.round(W * dpr)) {
    c.width = Math.round(W * dpr);
    c.height = Math.round(H * dpr);
  }
  const ctx = c.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, W, H);
  if (game.drawTray) game.drawTray(ctx, st, players);
}

export function updatePanel(ui) {
  const flow = ui.flow;
  const st = flow.st;
  const legal = flow.legal();
  const canAct = ui.canAct();
  $('thinking').hidden = !ui.thinking();
  ui.canvas.classList.toggle('waiting', ui.busy());
  ui.canvas.classList.toggle('placing', canAct && !!legal.place && legal.place !== 'none');
  const shotNow = canAct && flow.shotDue();
  $('shoot').disabled = !shotNow;
  $('undo').disabled = !flow.g || ui.busy() || !!flow.online || !flow.canUndo();
  $('share').disabled = !flow.g;

  // call, safety and push-out
  const callBox = $('call-box');
  callBox.hidden = !(shotNow && flow.callDue());
  if (!callBox.hidden) fillCallSelects(ui);
  $('push-out-box').hidden = !(shotNow && flow.pushOutDue());
  const nomBox = $('nominate-box');
  nomBox.hidden = !(canAct && flow.nominateDue());
  if (!nomBox.hidden) fillNominateSelect(ui);
  $('concede').hidden = !(shotNow && (legal.choices || []).includes('concede'));

  choicesBox(ui, st, canAct);
  aimHint(ui, canAct);

  if (!st) {
    $('status-turn').textContent = 'No game';
    $('status-info').textContent = '';
    return;
  }
  if (ui.anim) {
    // the state is already the one after the shot: keep it for the end
    $('status-turn').textContent = `${flow.game().name || st.game}: ${ui.anim.replay ? 'replaying a shot…' : 'the balls are rolling…'}`;
    return;
  }
  gamePanel(ui, st);
  status(ui, st);
}

function fillNominateSelect(ui) {
  const sel = $('nominate');
  const list = ui.flow.legal().nominate || [];
  const key = list.join(',');
  if (sel.dataset.key !== key) {
    sel.dataset.key = key;
    sel.textContent = '';
    sel.appendChild(new Option('auto (aim)', ''));
    for (const [text, value] of ui.flow.game().nominateOptions(list)) sel.appendChild(new Option(text, value));
  }
  sel.value = ui.flow.override.nominate == null ? '' : String(ui.flow.override.nominate);
}

function fillCallSelects(ui) {
  const bs = $('call-ball');
  const ps = $('call-pocket');
  const targets = ui.flow.callable();
  const key = targets.join(',');
  if (bs.dataset.key !== key) {
    bs.dataset.key = key;
    bs.textContent = '';
    bs.appendChild(new Option('auto (aim)', ''));
    for (const n of targets) bs.appendChild(new Option(`ball ${n}`, String(n)));
  }
  if (ps.options.length === 0) {
    ps.appendChild(new Option('auto', ''));
    ui.table.pockets.forEach((p, i) => ps.appendChild(new Option(POCKET_WORDS[p.name] || p.name, String(i))));
  }
  bs.value = ui.flow.override.ball == null ? '' : String(ui.flow.override.ball);
  ps.value = ui.flow.override.pocket == null ? '' : String(ui.flow.override.pocket);
}

export function showError(text) {
  const el = $('status-error');
  el.textContent = text;
  el.hidden = false;
}

export function clearError() {
  const el = $('status-error');
  el.textContent = '';
  el.hidden = true;
}

// Snooker's part of the game tab: the ball on in words, the nominations,
// and the score panel (both scores, the break, the points remaining and
// the snookers each player needs). Chosen through game-games.js.

import { snookerName } from './draw-colours.js';
import { shortName } from './game-words.js';

/** Snooker: the ball on in words (the state's snooker part and figures). */
export function ballOnWords(st) {
  const k = st.snooker || {};
  const on = (st.snooker_figures && st.snooker_figures.balls_on) || [];
  let words;
  if (k.colour_on) words = 'a colour (nominate it)';
  else if (on.length && on.every((n) => n >= 1 && n <= 15)) words = 'a red';
  else if (on.length) words = on.map(snookerName).join(', ');
  else words = 'none';
  if (k.respotted_black) words += ' (re-spotted black)';
  if (k.free_ball) words += ' — free ball: any ball may be nominated';
  return words;
}

export const snooker = {
  name: 'Snooker',
  breakSpeed: 5,
  rolls: false,
  calls: false,
  pushOut: false,
  foulsInARow: false,
  nominates: true,
  panel: 'score',

  statusBits(st) { return st.phase !== 'game_over' ? [`on: ${ballOnWords(st)}`] : []; },

  /** The nominate select's entries: the reds as one ("a red": any red is
   *  the same nomination in effect), then the colours by name. */
  nominateOptions(list) {
    const out = [];
    for (const n of list) {
      if (n >= 1 && n <= 15 && list.some((m) => m >= 1 && m <= 15 && m < n)) continue;
      out.push([n <= 15 ? 'a red' : snookerName(n), String(n)]);
    }
    return out;
  },

  nominationLabel(nom) {
    return nom && nom.auto ? (nom.ball != null ? `auto: ${snookerName(nom.ball)}` : 'auto: none') : 'auto (aim)';
  },

  /** The score panel (#score). */
  showPanel($, st, players) {
    const k = st.snooker;
    const fig = st.snooker_figures || { points_remaining: 0, snookers_required: [0, 0] };
    for (const seat of [0, 1]) {
      $(`score-name-${seat}`).textContent = shortName(players, seat);
      $(`score-${seat}`).textContent = String(k.score[seat]);
      $(`score-row-${seat}`).classList.toggle('to-play', st.phase !== 'game_over' && st.player === seat);
      const need = fig.snookers_required[seat];
      $(`score-snookers-${seat}`).textContent = need > 0 ? `needs ${need} snooker${need > 1 ? 's' : ''}` : '';
    }
    $('score-break').textContent = String(k.break);
    $('score-on').textContent = st.phase === 'game_over' ? '—' : ballOnWords(st);
    $('score-remaining').textContent = String(fig.points_remaining);
    const needs = [0, 1].filter((seat) => fig.snookers_required[seat] > 0)
      .map((seat) => `${shortName(players, seat)}: ${fig.snookers_required[seat]}`);
    $('score-snookers').textContent = needs.length ? needs.join(', ') : 'none';
  },
};

// Three-cushion's part of the game tab: the player's own cue ball, the
// break at the red, the score panel (points, innings, general average,
// highest run, the target, the run), and the count of the shot as the
// ball goes (cushions and balls hit, as the facade counts them:
// bs_web_playback_carom_count) and once it stops (the engine's ruling).
// Chosen through game-games.js.

import { caromName } from './draw-colours.js';
import { shortName } from './game-words.js';

/** The count in words: "2 cushions", "3 cushions · red, then yellow". */
export function countWords(c) {
  const n = `${c.cushions} cushion${c.cushions === 1 ? '' : 's'}`;
  if (!c.hit.length) return n;
  return `${n} · ${c.hit.map(caromName).join(', then ')}`;
}

/** A shot's ruling in a word or two: "Point", "No point", "Foul: no point". */
export function caromCall(ruling) {
  const k = ruling.carom || {};
  if (k.point) return 'Point';
  if (ruling.fouls && ruling.fouls.length) return 'Foul: no point';
  return 'No point';
}

/** The count while the ball runs ({cushions, hit, done, made}, the
 *  facade's): its words and a word on how it stands. */
export function liveCall(count) {
  if (!count.done) return 'running…';
  return count.made ? 'three cushions first…' : 'too few cushions…';
}

export const threeCushion = {
  name: 'Three-cushion',
  breakSpeed: 3,
  rolls: false,
  calls: false,
  pushOut: false,
  foulsInARow: false,
  counts: true,                // the shot's count as the ball goes
  panel: 'carom',

  /** The ball the player to act strikes: the state's carom_figures. */
  cueBall(st) { return st.carom_figures ? st.carom_figures.cue_ball : 0; },

  /** The break is played at the red (2), directly; later shots at the
   *  nearest ball. */
  aimTargets(st) { return st.phase === 'break_shot' ? [2] : []; },

  statusBits(st) {
    const k = st.carom || { score: [0, 0], innings: [0, 0] };
    const bits = [`score ${k.score[0]} – ${k.score[1]}`];
    if (k.equalizing && st.phase !== 'game_over') bits.push('the equalizing inning');
    return bits;
  },

  turnNote(st) { return st.carom_figures ? ` — plays the ${caromName(st.carom_figures.cue_ball)}` : ''; },

  /** The count and call of a shot in #carom-cushions and #carom-call:
   *  the ruling's once the balls stop (final), else the live count. */
  showCount($, count, ruling, final) {
    const el = $('carom-cushions');
    const call = $('carom-call');
    if (!el || !call) return;
    if (final) {
      const k = ruling.carom;
      el.textContent = countWords({ cushions: k.cushions, hit: k.hit || [] });
      call.textContent = caromCall(ruling);
      call.className = k.point ? 'point' : 'no-point';
    } else {
      el.textContent = countWords(count);
      call.textContent = liveCall(count);
      call.className = '';
    }
  },

  /** The score panel (#carom-score); `rules`: the record's config "carom";
   *  `last`: the last shot's log entry with a carom ruling, or null. */
  showPanel($, st, players, { rules, last }) {
    const k = st.carom;
    const fig = st.carom_figures || { cue_ball: 0, general_average: [0, 0], highest_run: [0, 0] };
    for (const seat of [0, 1]) {
      // the breaker plays the white, the other player the yellow
      const ball = seat === st.breaker ? 0 : 1;
      const dot = $(`carom-ball-${seat}`);
      dot.style.background = ball === 0 ? '#f6f3ea' : '#f2c81a';
      dot.title = caromName(ball);
      $(`carom-name-${seat}`).textContent = shortName(players, seat);
      $(`carom-points-${seat}`).textContent = String(k.score[seat]);
      $(`carom-innings-${seat}`).textContent = String(k.innings[seat]);
      $(`carom-average-${seat}`).textContent = fig.general_average[seat].toFixed(3);
      $(`carom-high-${seat}`).textContent = String(fig.highest_run[seat]);
      $(`carom-row-${seat}`).classList.toggle('to-play', st.phase !== 'game_over' && st.player === seat);
    }
    $('carom-target').textContent = rules ? `${rules.target} points${rules.innings_limit ? `, ${rules.innings_limit} innings` : ''}` : '—';
    $('carom-run').textContent = st.phase === 'game_over' ? '—' : String(k.run);
    if (last) {
      this.showCount($, null, last.ruling, true);
    } else {
      $('carom-cushions').textContent = '–';
      $('carom-call').textContent = '–';
      $('carom-call').className = '';
    }
  },
};

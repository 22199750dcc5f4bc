// What 9-ball and 10-ball (the rotation games) show alike: the ball on
// (the lowest on the table), the game ball, and the tray of the balls
// from 1 to the game ball. game-nine.js and game-ten.js build on it.

import { drawBall } from './draw-ball.js';

/** The rotation games' ball on: the lowest-numbered object ball on the
 *  table (also while a choice is due, when the state lists no targets). */
export function lowestBall(st) {
  const on = st ? st.on_table : [];
  for (let n = 1; n < on.length; n++) if (on[n]) return n;
  return null;
}

/** A rotation game whose game ball is `last`; `extra` adds or replaces fields. */
export function rotationGame(last, extra) {
  return {
    breakSpeed: 8.5,
    rolls: true,
    calls: false,
    pushOut: true,
    foulsInARow: true,
    panel: 'tray',
    gameBall: last,
    gameBallWord: 'wins',

    statusBits(st) {
      const bits = [];
      const lowest = lowestBall(st);
      if (lowest != null && st.phase !== 'game_over') bits.push(`ball on: ${lowest}`);
      bits.push(...this.moreBits(st));
      if (st.push_out_allowed && st.phase !== 'game_over') bits.push('push-out allowed');
      return bits;
    },

    moreBits() { return []; },

    /** The tray: the balls 1 to the game ball, those down faded; the ball
     *  on ringed and marked "on", the game ball marked as the one that wins. */
    drawTray(ctx, st) {
      const on = (n) => !!st.on_table[n];
      const r = 10;
      const lowest = st.phase === 'game_over' ? null : lowestBall(st);
      const y = 22;
      ctx.fillStyle = '#9aa5b1';
      ctx.font = '600 12px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.textAlign = 'left';
      ctx.fillText('on the table', 0, y);
      for (let n = 1; n <= last; n++) {
        const x = 98 + (n - 1) * (2 * r + 2);
        drawBall(ctx, n, x, y, r, { alpha: on(n) ? 1 : 0.18, shadow: false });
        const words = [];
        if (n === lowest) words.push('on');
        if (n === last) words.push(this.gameBallWord);
        if (n === lowest) {
          ctx.strokeStyle = '#ffd65a';
          ctx.lineWidth = 2;
          ctx.beginPath();
          ctx.arc(x, y, r + 2.5, 0, Math.PI * 2);
          ctx.stroke();
        }
        if (words.length) {
          ctx.fillStyle = n === lowest ? '#ffd65a' : '#9aa5b1';
          ctx.font = '600 10px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
          ctx.textAlign = n === last ? 'right' : 'center';
          ctx.fillText(words.join(' · '), n === last ? x + r : x, y + r + 12);
          ctx.textAlign = 'left';
        }
      }
    },
    ...extra,
  };
}

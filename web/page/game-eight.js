// 8-ball's part of the game tab: the groups in the status line and the
// tray of the balls still to play by group. Chosen through game-games.js.

import { drawBall } from './draw-ball.js';
import { shortName } from './game-words.js';

const SOLIDS = [1, 2, 3, 4, 5, 6, 7];
const STRIPES = [9, 10, 11, 12, 13, 14, 15];

export const eightBall = {
  name: '8-ball',
  breakSpeed: 8.5,
  rolls: true,                 // pool balls: their markings turn
  calls: true,                 // shots carry a call
  pushOut: false,
  foulsInARow: true,
  panel: 'tray',

  statusBits(st, players) {
    const g = st.group || ['none', 'none'];
    if (g[0] === 'none' && g[1] === 'none') return ['table open'];
    return [`${shortName(players, 0)}: ${g[0]}, ${shortName(players, 1)}: ${g[1]}`];
  },

  /** The tray: solids and stripes (each with the 8), by player once the
   *  groups are set; the balls down faded. */
  drawTray(ctx, st, players) {
    const on = (n) => !!st.on_table[n];
    const r = 10;
    const row = (y, label, balls, colour) => {
      ctx.fillStyle = colour;
      ctx.font = '600 12px system-ui, -apple-system, "Segoe UI", Arial, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.textAlign = 'left';
      ctx.fillText(label, 0, y, 64);  // squeezed to fit before the balls
      balls.forEach((n, i) => {
        drawBall(ctx, n, 78 + i * (2 * r + 3), y, r, { alpha: on(n) ? 1 : 0.18, shadow: false });
      });
    };
    const g = st.group || ['none', 'none'];
    if (g[0] === 'none' || g[1] === 'none') {
      row(16, 'solids', [...SOLIDS, 8], '#9aa5b1');
      row(44, 'stripes', [...STRIPES, 8], '#9aa5b1');
    } else {
      for (const seat of [0, 1]) {
        const set = g[seat] === 'solids' ? SOLIDS : STRIPES;
        row(16 + 28 * seat, `${shortName(players, seat)}`, [...set, 8], seat === 0 ? '#f2d16b' : '#8cc3ff');
      }
    }
  },
};

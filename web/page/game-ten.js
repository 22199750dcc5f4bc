// 10-ball's part of the game tab: a rotation game (game-rotation.js)
// whose every shot but the break is called (any object ball may be
// named; the lowest is still hit first), and whose 10 wins when called.
// Chosen through game-games.js.

import { rotationGame } from './game-rotation.js';

export const tenBall = rotationGame(10, {
  name: '10-ball',
  calls: true,
  callRequired: true,
  gameBallWord: 'money',

  /** The balls a call may name: every object ball on the table. */
  callable(objectBalls) { return objectBalls.map((b) => b.n).sort((p, q) => p - q); },

  moreBits(st) { return st.phase !== 'game_over' ? ['the 10 wins when called'] : []; },
});

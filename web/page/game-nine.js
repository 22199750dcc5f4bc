// 9-ball's part of the game tab: a rotation game (game-rotation.js)
// whose 9 wins. Chosen through game-games.js.

import { rotationGame } from './game-rotation.js';

export const nineBall = rotationGame(9, { name: '9-ball' });

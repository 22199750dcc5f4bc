// The games the tab plays, by the engine's name, each with what only it
// shows (game-eight.js, game-nine.js, game-ten.js, game-snooker.js,
// game-carom.js). The rest of the tab asks this table instead of naming
// a game. A game's fields, each optional but name:
//   name           its name in the status line ("8-ball")
//   breakSpeed     the cue speed set for the break (m/s)
//   rolls          its balls' markings turn as they roll (pool balls)
//   calls          shots carry a call (a ball and a pocket)
//   callRequired   every shot but the break is called or declared safe
//   callable(objectBalls)  the balls a call may name (default: the targets)
//   pushOut        the shot after the break may be a push-out
//   gameBall       the rotation games' game ball (9, 10)
//   nominates      shots nominate a ball (snooker)
//   counts         the shot's count runs as the ball goes (three-cushion)
//   foulsInARow    the status line shows the fouls in a row
//   cueBall(st)    the ball the player to act strikes (default 0)
//   aimTargets(st) the balls the first aim goes to (default: the targets)
//   statusBits(st, players)  the status line's game words
//   turnNote(st)   words after "X to shoot"
//   panel          the panel beside the log: 'tray', 'score' or 'carom'
//   drawTray(ctx, st, players), showPanel($, st, players, extra)

import { eightBall } from './game-eight.js';
import { nineBall } from './game-nine.js';
import { tenBall } from './game-ten.js';
import { snooker } from './game-snooker.js';
import { threeCushion } from './game-carom.js';

export const GAMES = {
  eight_ball: eightBall,
  nine_ball: nineBall,
  ten_ball: tenBall,
  snooker,
  three_cushion: threeCushion,
};

const UNKNOWN = { breakSpeed: 8.5, rolls: true, foulsInARow: true, statusBits: () => [] };

/** The game `name`'s part ({name: name} and no extras for a name the
 *  table does not know). */
export function gameOf(name) {
  return GAMES[name] || { ...UNKNOWN, name };
}

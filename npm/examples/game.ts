// A game of 9-ball against the AI for a few shots: seat 0 is a champion
// at half its noise, seat 1 a club player, each a Player whose
// decisions run in a worker thread (or inline, --inline: the same game).
// Then the game's link, a game opened from it, an undo and a shot's
// playback.
//
//   node game.js [--inline] [--actions N]
import { Game, Player, levels, players } from 'breakshot';
import type { Action, ActReply, GameState } from 'breakshot';

const args = process.argv.slice(2);
const inline = args.includes('--inline');
const at = args.indexOf('--actions');
const maxActions = at >= 0 ? Number(args[at + 1]) : 6;

console.log(`levels: ${levels.join(', ')}; 9-ball seats: ${players('nine_ball').join(', ')}`);
const game = new Game({ game: 'nine_ball', players: ['champion@0.5x', 'club'], seed: 7 });
const seats = [new Player('champion@0.5x', { inline }), new Player('club', { inline })];
try {
  let state: GameState = game.state();
  let firstShot = -1;
  while (state.phase !== 'game_over' && state.actions < maxActions) {
    const seat = state.player;
    const action: Action = await seats[seat].decide(game);
    const reply: ActReply = game.act(action);
    const what = action.type === 'shoot'
      ? `shoots at ${action.strike.speed.toFixed(3)} m/s, phi ${action.strike.phi.toFixed(3)}`
      : action.type === 'place_cue_ball' ? `places the cue ball at (${action.position[0].toFixed(3)}, ${action.position[1].toFixed(3)})`
        : `decides ${action.choice}`;
    console.log(`${reply.index}: seat ${seat} ${what}: ${reply.ruling.text} (${reply.turn.why})`);
    if (reply.kind === 'shoot' && firstShot < 0) firstShot = reply.index;
    state = reply.state;
  }
  const link = game.link();
  console.log(`link: ${link.length} characters`);
  const copy = Game.fromLink(link);
  console.log(`from the link: ${copy.actions} actions, the same state ${JSON.stringify(copy.state()) === JSON.stringify(game.state())}`);
  copy.free();

  console.log(`turns: ${game.turns().map((t) => t.why).join(', ')}`);
  if (firstShot >= 0) {
    const pb = game.shot(firstShot);  // the break
    const s = pb.states(0.5);
    console.log(`the break (action ${firstShot}) at t = 0.5 s: ${s.count} balls, ${s.events} events, ${pb.playedEvents().length} played back`);
    pb.free();
  }

  const after = game.undo();
  console.log(`undo: ${after.actions} actions, seat ${after.player} to act`);
  const record = game.record();
  console.log(`the record: ${Object.keys(record).join(', ')}`);
} finally {
  for (const p of seats) p.close();
  game.free();
}

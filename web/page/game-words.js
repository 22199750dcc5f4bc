// The game tab's words: the pockets, the decisions on offer and their
// buttons, the seats' names, and the log's sentence for each action (the
// engine's ruling, which names its fouls and whose turn it is, the
// winner, and the facade's turn where the engine has no words). Words only, no DOM: node imports it
// for the page's unit tests.

export const POCKET_WORDS = {
  bottom_left: 'bottom-left corner',
  side_bottom: 'bottom side',
  bottom_right: 'bottom-right corner',
  top_right: 'top-right corner',
  side_top: 'top side',
  top_left: 'top-left corner',
};

export const CHOICE_WORDS = {
  shoot: 'Take the table and shoot',
  pass_back: 'Pass it back: the other player must shoot',
  accept_table: 'Accept the table and shoot',
  rerack_and_break: 'Re-rack, and I break',
  rerack_opponent_breaks: 'Re-rack, and the other player breaks again',
  respot_eight: 'Spot the 8 and play on',
  play_on: 'Play on from here',
  offender_again: 'Make the other player play again',
  replace_balls: 'Replace the balls: the other player plays again',
  concede: 'Concede the frame',
};

export const PHASE_WORDS = {
  push_out_choice: 'after the push-out: take the table or pass it back',
  illegal_break_choice: 'after the illegal break: accept the table or re-rack',
  eight_on_break_choice: 'the 8 fell on the break: spot it or re-rack',
  foul_choice: 'after the foul: play on, or have the other player play again',
};

// 10-ball's choice after a ball pocketed wrongly (not the ball called, or
// not in the pocket called): the rules reuse the push-out's phase and
// choices, and the state's after_push_out (false) tells the two apart.
export const WRONG_POT_WORDS = 'a ball was pocketed wrongly: shoot from here or hand the shot back';
export const WRONG_POT_CHOICES = {
  shoot: 'Shoot from here',
  pass_back: 'Hand the shot back: the other player shoots again',
};

export const CALL_HOW = 'Call a ball and a pocket: aim at the ball on (the pocket nearest its line is called), or choose them under "Call ball" and "Call pocket", or press a pocket; or tick "safety".';

// Whose turn it is after an action, by the facade's reason (bs_web_game_act's
// and bs_web_game_turns's "turn": {"next", "why"}, docs/web.md).
export const TURN_WORDS = {
  continues: () => 'Turn continues.',
  passes: (who) => `${who} to play.`,
  foul: (who) => `${who} to play.`,
  decides: (who) => `${who} to decide.`,
  breaks: (who) => `${who} to break.`,
  game_over: () => '',
};

/** The choice a state offers is 10-ball's after a wrong pot. */
export function wrongPotChoice(st) {
  return !!st && st.phase === 'push_out_choice' && !st.after_push_out;
}

/** The decision on offer in words ("after the push-out: ..."). */
export function phaseWords(st) {
  if (wrongPotChoice(st)) return WRONG_POT_WORDS;
  return PHASE_WORDS[st.phase] || st.phase;
}

/** A choice's button text in the state `st`. */
export function choiceWords(st, c) {
  if (wrongPotChoice(st) && WRONG_POT_CHOICES[c]) return WRONG_POT_CHOICES[c];
  return CHOICE_WORDS[c] || c.replace(/_/g, ' ');
}

export function capital(s) {
  if (!s) return s;
  return s[0].toUpperCase() + s.slice(1);
}

/** A seat as the status line names it: "Player 1 (you)", "Player 2 (club AI)". */
export function seatName(players, seat) {
  const p = players[seat];
  const human = players.filter((x) => x === 'human').length;
  if (p === 'human') return human === 2 ? `Player ${seat + 1}` : `Player ${seat + 1} (you)`;
  return `Player ${seat + 1} (${p} AI)`;
}

/** A seat in a word or two: "Player 1", "Club AI". */
export function shortName(players, seat) {
  const p = players[seat];
  if (p === 'human') return `Player ${seat + 1}`;
  return `${p[0].toUpperCase()}${p.slice(1)} AI`;
}

/** The sentence after a ruling that says whose turn it is, from the
 *  facade's turn ({next, why}); '' when there is none to say. */
export function turnSentence(turn) {
  if (!turn || !(turn.why in TURN_WORDS)) return '';
  return TURN_WORDS[turn.why](`Player ${turn.next + 1}`);
}

/**
 * The log's line for an action (entry: {index, player, kind, ruling,
 * action, turn}) as parts: who acted, the ruling's words (which name its
 * fouls and whose turn it is), whether it is a foul (the line's colour),
 * the winner, and whose turn it is next from the facade where the engine
 * gave no words (shots only; none when the game ended). Each text part is
 * '' when absent.
 */
export function logLine(entry, players) {
  const p = players[entry.player];
  const who = `${entry.index + 1}. ${p === 'human' ? `Player ${entry.player + 1}` : `Player ${entry.player + 1} (${p})`}: `;
  const r = entry.ruling || {};
  let text = r.text || (entry.kind === 'place' ? 'places the cue ball' : entry.kind === 'decide' ? 'decides' : 'shoots');
  if (entry.kind === 'decide' && entry.action && entry.action.choice && !r.text) text = `chooses: ${entry.action.choice.replace(/_/g, ' ')}`;
  const foul = !!(r.fouls && r.fouls.length);
  const won = r.winner != null && r.winner >= 0;
  const win = won ? `${shortName(players, r.winner)} wins.` : '';
  const next = !won && entry.kind === 'shoot' && !r.text ? turnSentence(entry.turn) : '';
  return { who, text: capital(text), foul, win, next };
}

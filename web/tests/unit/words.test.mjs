// game-words.js: the page's words for every ruling kind of every game
// (the log's line: the engine's text, which names the fouls and whose
// turn it is, the foul colour, the winner, the facade's turn where the
// engine said nothing), every choice and phase the engine names, and the
// seats. The engine's names are read from its sources, so that a name
// added there without words here fails.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import {
  CHOICE_WORDS, PHASE_WORDS, TURN_WORDS, choiceWords, logLine, phaseWords, seatName, shortName, turnSentence,
} from '../../page/game-words.js';
import { GAMES, gameOf } from '../../page/game-games.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const source = (rel) => fs.readFileSync(path.join(root, rel), 'utf8');

/** The names of a `constexpr std::array<std::string_view, N> NAME{...}` in rules_names.cpp. */
function engineNames(array) {
  const text = source('src/game/rules_names.cpp');
  const m = text.match(new RegExp(`${array}\\{([^}]*)\\}`));
  assert.ok(m, `no ${array} in src/game/rules_names.cpp`);
  return [...m[1].matchAll(/"([a-z_0-9]+)"/g)].map((x) => x[1]);
}

/** The reasons the C API gives for whose turn it is (capi/page.cpp's turn_json). */
function turnReasons() {
  const text = source('capi/page.cpp');
  const start = text.indexOf('ojson turn_json(');
  const body = text.slice(start, text.indexOf('\n}\n', start));
  return [...new Set([...body.matchAll(/why = "([a-z_]+)"/g), ...body.matchAll(/const char\* why = "([a-z_]+)"/g)].map((x) => x[1]))];
}

test('every choice, phase and game the engine names has its words', () => {
  for (const c of engineNames('kChoiceNames')) assert.ok(CHOICE_WORDS[c], `no words for the choice ${c}`);
  const decisions = engineNames('kPhaseNames').filter((p) => p.endsWith('_choice'));
  assert.ok(decisions.length >= 4);
  for (const p of decisions) assert.ok(PHASE_WORDS[p], `no words for the phase ${p}`);
  for (const g of engineNames('kGameNames')) assert.ok(GAMES[g] && GAMES[g].name, `the game ${g} has no part in game-games.js`);
  const reasons = turnReasons();
  assert.deepEqual([...reasons].sort(), ['breaks', 'continues', 'decides', 'foul', 'game_over', 'passes']);
  for (const why of reasons) assert.ok(why in TURN_WORDS, `no words for the turn reason ${why}`);
});

test('whose turn it is, in words', () => {
  assert.equal(turnSentence({ next: 0, why: 'continues' }), 'Turn continues.');
  assert.equal(turnSentence({ next: 1, why: 'passes' }), 'Player 2 to play.');
  assert.equal(turnSentence({ next: 0, why: 'foul' }), 'Player 1 to play.');
  assert.equal(turnSentence({ next: 1, why: 'decides' }), 'Player 2 to decide.');
  assert.equal(turnSentence({ next: 0, why: 'breaks' }), 'Player 1 to break.');
  assert.equal(turnSentence({ next: -1, why: 'game_over' }), '');
  assert.equal(turnSentence(null), '');
  assert.equal(turnSentence({ next: 0, why: 'unheard_of' }), '');
});

// A shot of each ruling kind in each game: the ruling (the engine's words
// name its fouls and whose turn it is: tests/test_ruling_words.cpp) and the
// line the log shows. The facade's turn is said only where the engine gave
// no words, so that no sentence is said twice.
const KINDS = [
  // [kind, ruling, turn, the line's parts after "who"]
  ['continues', { text: 'Player 1 pots the 3; Player 1 shoots again.' }, { next: 0, why: 'continues' },
    { text: 'Player 1 pots the 3; Player 1 shoots again.', foul: false, win: '', next: '' }],
  ['passes', { text: 'Player 1 pots nothing. Player 2 to shoot.' }, { next: 1, why: 'passes' },
    { text: 'Player 1 pots nothing. Player 2 to shoot.', foul: false, win: '', next: '' }],
  ['foul', { text: 'Foul: a scratch. Player 2 has the cue ball in hand.', fouls: ['scratch'] }, { next: 1, why: 'foul' },
    { text: 'Foul: a scratch. Player 2 has the cue ball in hand.', foul: true, win: '', next: '' }],
  ['wins', { text: 'pots the last ball.', winner: 0 }, { next: -1, why: 'game_over' },
    { text: 'Pots the last ball.', foul: false, win: 'Player 1 wins.', next: '' }],
  ['loses on a foul', { text: 'fouls on the last ball.', fouls: ['wrong_ball_first'], winner: 1 }, { next: -1, why: 'game_over' },
    { text: 'Fouls on the last ball.', foul: true, win: 'Player 2 wins.', next: '' }],
  ['draw', { text: 'the game is drawn.' }, { next: -1, why: 'game_over' },
    { text: 'The game is drawn.', foul: false, win: '', next: '' }],
  // no words from the engine: the facade's turn is said
  ['no words, passes', {}, { next: 1, why: 'passes' },
    { text: 'Shoots', foul: false, win: '', next: 'Player 2 to play.' }],
  ['no words, foul', { fouls: ['no_contact'] }, { next: 1, why: 'foul' },
    { text: 'Shoots', foul: true, win: '', next: 'Player 2 to play.' }],
  ['no words, decides', {}, { next: 1, why: 'decides' },
    { text: 'Shoots', foul: false, win: '', next: 'Player 2 to decide.' }],
  ['no words, breaks', {}, { next: 0, why: 'breaks' },
    { text: 'Shoots', foul: false, win: '', next: 'Player 1 to break.' }],
];

test('the log\'s line for each ruling kind of each game', () => {
  for (const game of Object.keys(GAMES)) {
    for (const [kind, ruling, turn, want] of KINDS) {
      const line = logLine({ index: 4, player: 0, kind: 'shoot', ruling, turn, action: { type: 'shoot' } }, ['human', 'human']);
      assert.deepEqual(line, { who: '5. Player 1: ', ...want }, `${game}, ${kind}`);
    }
    const line = logLine({ index: 0, player: 1, kind: 'shoot', ruling: { text: 'x', fouls: ['in_off'] }, turn: { next: 0, why: 'foul' } }, ['club', 'human']);
    assert.equal(line.who, '1. Player 2: ');
    assert.equal(line.foul, true);
  }
});

test('placements and decisions: the engine\'s words, else the page\'s; no turn line', () => {
  const players = ['human', 'expert'];
  const place = logLine({ index: 0, player: 0, kind: 'place', ruling: {}, turn: { next: 0, why: 'continues' } }, players);
  assert.deepEqual(place, { who: '1. Player 1: ', text: 'Places the cue ball', foul: false, win: '', next: '' });
  const decide = logLine({ index: 2, player: 1, kind: 'decide', ruling: {}, action: { type: 'decide', choice: 'pass_back' }, turn: { next: 0, why: 'passes' } }, players);
  assert.deepEqual(decide, { who: '3. Player 2 (expert): ', text: 'Chooses: pass back', foul: false, win: '', next: '' });
  const said = logLine({ index: 2, player: 1, kind: 'decide', ruling: { text: 'takes the table.' }, action: { type: 'decide', choice: 'shoot' } }, players);
  assert.equal(said.text, 'Takes the table.');
  const bare = logLine({ index: 3, player: 0, kind: 'shoot', ruling: {} }, players);
  assert.equal(bare.text, 'Shoots');
  assert.equal(bare.next, '', 'no turn from the facade: nothing said');
});

test('the decisions on offer and their buttons', () => {
  for (const phase of Object.keys(PHASE_WORDS)) {
    assert.equal(phaseWords({ phase, after_push_out: true }), PHASE_WORDS[phase]);
  }
  // 10-ball's choice after a wrong pot reuses the push-out's phase
  const wrongPot = { phase: 'push_out_choice', after_push_out: false };
  assert.match(phaseWords(wrongPot), /pocketed wrongly/);
  assert.equal(choiceWords(wrongPot, 'shoot'), 'Shoot from here');
  assert.equal(choiceWords({ phase: 'push_out_choice', after_push_out: true }, 'shoot'), CHOICE_WORDS.shoot);
  assert.equal(choiceWords(wrongPot, 'concede'), CHOICE_WORDS.concede);
  assert.equal(choiceWords({ phase: 'shot' }, 'a_new_choice'), 'a new choice');
  assert.equal(phaseWords({ phase: 'a_new_phase' }), 'a_new_phase');
});

test('the seats\' names', () => {
  assert.equal(seatName(['human', 'human'], 1), 'Player 2');
  assert.equal(seatName(['human', 'club'], 0), 'Player 1 (you)');
  assert.equal(seatName(['human', 'club'], 1), 'Player 2 (club AI)');
  assert.equal(shortName(['champion@0.5x', 'human'], 0), 'Champion@0.5x AI');
  assert.equal(shortName(['baseline', 'human'], 1), 'Player 2');
});

test('each game\'s status words', () => {
  const players = ['human', 'club'];
  const base = { phase: 'shot', on_table: [true, false, true, true], push_out_allowed: true };
  assert.deepEqual(gameOf('eight_ball').statusBits({ ...base, group: ['none', 'none'] }, players), ['table open']);
  assert.deepEqual(gameOf('eight_ball').statusBits({ ...base, group: ['solids', 'stripes'] }, players), ['Player 1: solids, Club AI: stripes']);
  assert.deepEqual(gameOf('nine_ball').statusBits(base, players), ['ball on: 2', 'push-out allowed']);
  assert.deepEqual(gameOf('ten_ball').statusBits(base, players), ['ball on: 2', 'the 10 wins when called', 'push-out allowed']);
  assert.deepEqual(gameOf('ten_ball').statusBits({ ...base, phase: 'game_over' }, players), []);
  const snooker = { phase: 'shot', snooker: { colour_on: false }, snooker_figures: { balls_on: [1, 2, 3] } };
  assert.deepEqual(gameOf('snooker').statusBits(snooker, players), ['on: a red']);
  assert.deepEqual(gameOf('snooker').statusBits({ ...snooker, snooker: { free_ball: true }, snooker_figures: { balls_on: [16, 21] } }, players),
    ['on: yellow, black — free ball: any ball may be nominated']);
  assert.deepEqual(gameOf('three_cushion').statusBits({ phase: 'shot', carom: { score: [3, 2], equalizing: true } }, players), ['score 3 – 2', 'the equalizing inning']);
  assert.equal(gameOf('three_cushion').turnNote({ carom_figures: { cue_ball: 1 } }), ' — plays the yellow');
  assert.equal(gameOf('snooker').foulsInARow, false);
  assert.equal(gameOf('nine_ball').foulsInARow, true);
  assert.equal(gameOf('a_new_game').name, 'a_new_game');
});

// game-flow.js in node, over a fake engine game (fake-engine.mjs): the
// log and its turns, the turn's set-up by game, the shot's action (call,
// safety, push-out, nomination, placement) and undo.

import { test } from 'node:test';
import assert from 'node:assert/strict';

import { GameFlow } from '../../page/game-flow.js';
import { FakeGame, poolTable, state } from './fake-engine.mjs';

const shotLegal = (targets, more = {}) => ({ shoot: true, place: 'none', targets, ...more });

/** A flow with the game installed; errors collected. */
function flowWith(game) {
  const errors = [];
  const flow = new GameFlow((e) => errors.push(e));
  assert.equal(flow.install(game), true);
  return { flow, errors };
}

/** The reply of a shot by `player` leading to `after`. */
function shotReply(index, player, after, { turn = { next: after.player, why: 'passes' }, ruling = { text: 'shoots' }, numbers = [0, 1] } = {}) {
  return {
    index, player, kind: 'shoot', executed: { type: 'shoot' }, numbers, ruling, turn, state: after,
  };
}

test('install reads the table, the state and the log with its turns and balls', () => {
  const start = state('eight_ball', [[0.6, 0.4], [1.9, 0.4], [2.0, 0.9]], { legal: shotLegal([1, 2]) });
  const after = state('eight_ball', [[0.7, 0.4], null, [2.0, 0.9]], { player: 1, legal: shotLegal([2]) });
  const g = new FakeGame({
    start,
    actions: [{ player: 0, action: { type: 'shoot' }, ruling: { text: 'Player 1 pots the 1' }, after }],
    turns: [{ next: 0, why: 'continues' }],
  });
  const { flow, errors } = flowWith(g);
  assert.deepEqual(errors, []);
  assert.equal(flow.R, 0.028575);
  assert.equal(flow.log.length, 1);
  assert.deepEqual(flow.log[0].turn, { next: 0, why: 'continues' });
  assert.deepEqual(flow.log[0].numbers, [0, 1, 2], 'the balls on the table before the shot');
  assert.equal(flow.log[0].kind, 'shoot');
  // a second game frees the first
  const g2 = new FakeGame({ start });
  flow.install(g2);
  assert.equal(g.freed, true);
  assert.equal(flow.log.length, 0);
});

test('an engine that cannot answer is reported, not thrown', () => {
  const g = new FakeGame({ start: state('nine_ball', [[0.6, 0.6]]) });
  g.table = () => { throw new Error('gone'); };
  const errors = [];
  const flow = new GameFlow((e) => errors.push(e));
  assert.equal(flow.install(g), false);
  assert.deepEqual(errors, ['gone']);
});

test('the break speed and the first aim are the game\'s', () => {
  const balls = [[0.6, 0.635], [1.9, 0.635], [1.95, 0.6]];
  const cases = [
    ['eight_ball', 8.5], ['nine_ball', 8.5], ['ten_ball', 8.5], ['snooker', 5], ['three_cushion', 3],
  ];
  for (const [game, speed] of cases) {
    const { flow } = flowWith(new FakeGame({ start: state(game, balls, { phase: 'break_shot', legal: shotLegal([1]) }) }));
    assert.equal(flow.aim.speed, speed, game);
  }
  // three-cushion's break goes at the red (2), not the nearer yellow
  const carom = state('three_cushion', [[0.6, 0.4], [0.9, 0.4], [2.0, 1.0]], { phase: 'break_shot', legal: shotLegal([]), carom_figures: { cue_ball: 0 } });
  const { flow } = flowWith(new FakeGame({ start: carom }));
  const toRed = (Math.atan2(0.6, 1.4) * 180) / Math.PI;
  assert.ok(Math.abs(flow.aim.phi - toRed) < 1e-9, `aimed at ${flow.aim.phi}, not the red at ${toRed}`);
  // and a later shot from the yellow (the other player's ball) at the nearest
  const later = state('three_cushion', [[0.6, 0.4], [0.9, 0.4], [2.0, 1.0]], { player: 1, legal: shotLegal([]), carom_figures: { cue_ball: 1 } });
  const f2 = flowWith(new FakeGame({ start: later })).flow;
  assert.equal(f2.cueN(), 1);
  assert.deepEqual(f2.cuePos(), { x: 0.9, y: 0.4 });
  assert.equal(Math.round(f2.aim.phi), 180, 'from the yellow to the white');
});

test('a calling game\'s shot carries the ball aimed at and the pocket it is sent to', () => {
  const start = state('eight_ball', [[0.6, 0.4], [1.9, 0.4], [1.2, 1.0]], { legal: shotLegal([1, 2], { call: true }) });
  const { flow } = flowWith(new FakeGame({ start }));
  flow.aim.phi = 0;
  const a = flow.shotAction();
  assert.deepEqual(a.call, { ball: 1, pocket: 2 }, 'ball 1 into the bottom-right corner');
  assert.equal(a.safety, false);
  // the pocket chosen by hand wins; a ball not callable is ignored
  flow.override.pocket = 3;
  flow.override.ball = 9;
  assert.deepEqual(flow.shotAction().call, { ball: 1, pocket: 3 });
  // a safety has no call
  flow.declared.safety = true;
  const safe = flow.shotAction();
  assert.equal(safe.safety, true);
  assert.equal(safe.call, null);
  // aimed at nothing: no call
  flow.declared.safety = false;
  flow.override = { ball: null, pocket: null, nominate: null };
  flow.aim.phi = 180;
  assert.equal(flow.shotAction().call, null);
});

test('10-ball may call any ball on the table and needs a call; 9-ball may push out', () => {
  const ten = state('ten_ball', [[0.6, 0.4], [1.9, 0.4], [1.2, 1.0], null, [2.2, 0.3]], { legal: shotLegal([1], { call: true }) });
  const { flow } = flowWith(new FakeGame({ start: ten }));
  assert.deepEqual(flow.callable(), [1, 2, 4]);
  assert.equal(flow.callRequired(), true);
  const nine = state('nine_ball', [[0.6, 0.4], [1.9, 0.4]], { legal: shotLegal([1], { push_out: true }), push_out_allowed: true });
  const f9 = flowWith(new FakeGame({ start: nine })).flow;
  assert.equal(f9.callDue(), false);
  assert.equal(f9.pushOutDue(), true);
  f9.declared.pushOut = true;
  const a = f9.shotAction();
  assert.equal(a.push_out, true);
  assert.equal(a.call, null);
  // the call is due after a placement too (the cue ball in hand, no shot yet)
  const inHand = state('eight_ball', [null, [1.9, 0.4]], { legal: { shoot: false, place: 'anywhere', must_place: true, targets: [1] } });
  const f8 = flowWith(new FakeGame({ start: inHand })).flow;
  assert.equal(f8.shotDue(), true);
  assert.equal(f8.callDue(), true);
  assert.deepEqual(f8.placementDue(), { type: 'place_cue_ball', position: [2.54 / 4, 1.27 / 2] });
});

test('the cue ball in hand goes to the first place the engine allows', () => {
  const inHand = state('nine_ball', [null, [1.9, 0.4]], { legal: { shoot: false, place: 'kitchen', must_place: true, targets: [1] } });
  const asked = [];
  const g = new FakeGame({ start: inHand, placement: (x, y) => { asked.push([x, y]); return { ok: asked.length > 3, reason: 'a ball is there' }; } });
  const { flow } = flowWith(g);
  assert.equal(asked.length, 4);
  assert.deepEqual(flow.placePos, { x: asked[3][0], y: asked[3][1] });
  assert.ok(flow.placePos.x <= 2.54 / 4, 'in the kitchen: not past the head spot');
  assert.deepEqual(flow.checkPlacement(0.1, 0.1), { ok: true, reason: '' });
  g._placement = () => { throw new Error('outside the table'); };
  assert.deepEqual(flow.checkPlacement(-1, 0), { ok: false, reason: 'outside the table' });
});

test('snooker nominates the colour aimed at after a red, and not a ball on', () => {
  const pos = [[0.6, 0.4], [1.9, 0.4]];
  for (let n = 2; n <= 15; n++) pos.push(null);
  pos.push([1.2, 1.0], [1.5, 0.4], null, null, null, [3.0, 0.4]);  // 16 yellow, 17 green (behind the red), 21 black
  const legal = shotLegal([16, 17, 21], { nominate: [16, 17, 21], must_nominate: true });
  const st = state('snooker', pos, { legal, snooker: { free_ball: false }, snooker_figures: { balls_on: [16, 17, 21] } });
  const { flow } = flowWith(new FakeGame({ start: st }));
  flow.aim.phi = 0;   // the green is first on the line
  assert.deepEqual(flow.currentNomination(flow.geometry()), { ball: 17, auto: true });
  assert.equal(flow.shotAction().nominate, 17);
  flow.override.nominate = 21;
  assert.deepEqual(flow.currentNomination(flow.geometry()), { ball: 21, auto: false });
  // a free ball: a ball on needs no nomination, another does
  const free = { ...st, legal: shotLegal([1], { nominate: [1, 17], must_nominate: false }), snooker: { free_ball: true }, snooker_figures: { balls_on: [1] } };
  const f2 = flowWith(new FakeGame({ start: free })).flow;
  assert.equal(f2.nominable(1), false);
  assert.equal(f2.nominable(17), true);
  f2.aim.phi = 0;
  assert.deepEqual(f2.currentNomination(f2.geometry()), { ball: 17, auto: true });
  // 8-ball nominates nothing
  const eight = flowWith(new FakeGame({ start: state('eight_ball', pos.slice(0, 2), { legal: { ...legal } }) })).flow;
  assert.equal(eight.nominateDue(), false);
});

test('playing an action keeps the reply\'s turn; a refused one changes nothing', () => {
  const start = state('nine_ball', [[0.6, 0.4], [1.9, 0.4]], { legal: shotLegal([1]) });
  const after = state('nine_ball', [[1.0, 0.4], [2.2, 0.4]], { player: 1, legal: shotLegal([1]) });
  const g = new FakeGame({ start, replies: [{ error: 'no shot is due' }, shotReply(0, 0, after, { turn: { next: 1, why: 'foul' } })] });
  const { flow } = flowWith(g);
  const refused = flow.play({ type: 'shoot' });
  assert.deepEqual(refused, { error: 'no shot is due' });
  assert.equal(flow.st, start);
  const r = flow.play({ type: 'shoot' });
  assert.equal(r.prevPhase, 'shot');
  assert.equal(flow.st, after);
  assert.deepEqual(r.entry.turn, { next: 1, why: 'foul' });
  assert.equal(flow.log.length, 0, 'a shot goes into the log once its balls stop');
  flow.addToLog(r.entry);
  assert.equal(flow.log.length, 1);
  // an engine that throws is an error too
  assert.match(flow.play({ type: 'shoot' }).error, /no reply left/);
});

test('undo goes back to before the last human shot, the AI\'s replies with it', () => {
  const s0 = state('eight_ball', [[0.6, 0.4], [1.9, 0.4]], { players: ['human', 'club'], legal: shotLegal([1]) });
  const s1 = { ...s0, player: 1 };
  const s2 = { ...s0, player: 1 };
  const s3 = { ...s0, player: 0 };
  const g = new FakeGame({
    start: s0,
    actions: [
      { player: 0, action: { type: 'shoot' }, ruling: {}, after: s1 },
      { player: 1, action: { type: 'shoot' }, ruling: {}, after: s2 },
      { player: 1, action: { type: 'shoot' }, ruling: {}, after: s3 },
    ],
    turns: [{ next: 1, why: 'passes' }, { next: 1, why: 'continues' }, { next: 0, why: 'passes' }],
  });
  const { flow } = flowWith(g);
  assert.equal(flow.canUndo(), true);
  assert.deepEqual(flow.undoTarget(), { index: 0 });
  assert.equal(flow.undoTo(0), null);
  assert.deepEqual(g.undone, [0]);
  assert.equal(flow.log.length, 0);
  assert.equal(flow.st, s0);
  assert.deepEqual(flow.undoTarget(), { error: 'There is no shot of yours to undo.' });
  assert.equal(flow.canUndo(), false);
  flow.online = { mayAct: () => true };
  assert.deepEqual(flow.undoTarget(), { error: 'An online game has no undo.' });
});

test('the seat to act: a human on this screen, not over, online only on its turn', () => {
  const st = state('nine_ball', [[0.6, 0.4], [1.9, 0.4]], { players: ['human', 'club'], legal: shotLegal([1]) });
  const { flow } = flowWith(new FakeGame({ start: st }));
  assert.equal(flow.humanToAct(), true);
  assert.equal(flow.seatName(0), 'Player 1 (you)');
  assert.equal(flow.shortName(1), 'Club AI');
  flow.st = { ...st, player: 1 };
  assert.equal(flow.humanToAct(), false);
  flow.st = { ...st, phase: 'game_over' };
  assert.equal(flow.humanToAct(), false);
  flow.st = st;
  flow.online = { mayAct: () => false };
  assert.equal(flow.humanToAct(), false);
});

test('the decisions on offer leave snooker\'s concede aside while a shot is due', () => {
  const pos = [[0.6, 0.4], [1.9, 0.4]];
  const shoot = state('snooker', pos, { legal: shotLegal([1], { choices: ['concede'] }) });
  assert.deepEqual(flowWith(new FakeGame({ start: shoot })).flow.decisions(), []);
  const choose = state('snooker', pos, { phase: 'foul_choice', legal: { shoot: false, place: 'none', choices: ['play_on', 'offender_again', 'concede'] } });
  assert.deepEqual(flowWith(new FakeGame({ start: choose })).flow.decisions(), ['play_on', 'offender_again', 'concede']);
});

test('the table is the engine\'s', () => {
  const { flow } = flowWith(new FakeGame({ start: state('nine_ball', [[0.6, 0.4]]) }));
  assert.deepEqual(flow.table, poolTable());
});

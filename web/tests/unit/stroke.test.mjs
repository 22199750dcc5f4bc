// game-stroke.js: the stroke's pull-to-speed and back, the slider's
// speed, and the geometry of a press that takes the stick; the tip
// widget's offset (game-tip.js) and the playback's sounds' speeds
// (game-playback.js).

import { test } from 'node:test';
import assert from 'node:assert/strict';

import {
  MAX_SPEED, MIN_SPEED, PULL_MAX, DEFAULT_SPEED, STICK_REACH, aimToward, normDeg, onStick, powerFromSpeed, pullFromSpeed,
  speedFromPower, speedFromPull, strikePull, strokePull,
} from '../../page/game-stroke.js';
import { tipOffset, tipWords, TIP_LIMIT } from '../../page/game-tip.js';
import { impactSpeed, numberOfId } from '../../page/game-playback.js';

test('a pull gives a speed from MIN_SPEED to MAX_SPEED, in the slider\'s steps', () => {
  assert.equal(speedFromPull(0), MIN_SPEED);
  assert.equal(speedFromPull(-0.2), MIN_SPEED);
  assert.equal(speedFromPull(PULL_MAX), MAX_SPEED);
  assert.equal(speedFromPull(2 * PULL_MAX), MAX_SPEED);
  assert.equal(speedFromPull(PULL_MAX / 2), 5.15);
  assert.equal(speedFromPull(0.1), 3.05);  // 0.3 + 9.7 * 0.1 / 0.35 = 3.071... in steps of 0.05
  for (let pull = 0; pull <= PULL_MAX; pull += 0.0123) {
    const s = speedFromPull(pull);
    assert.ok(Math.abs(s * 20 - Math.round(s * 20)) < 1e-9, `${s} is not a step of 0.05`);
    assert.ok(s >= speedFromPull(pull - 0.0123), 'the speed grows with the pull');
    assert.ok(Math.abs(speedFromPull(pullFromSpeed(s)) - s) < 1e-9, `pullFromSpeed(${s}) does not give it back`);
  }
  assert.equal(pullFromSpeed(MIN_SPEED), 0);
  assert.equal(pullFromSpeed(MAX_SPEED), PULL_MAX);
  assert.equal(pullFromSpeed(99), PULL_MAX);
});

test('the slider\'s speed is clamped; what is not a number is the default', () => {
  assert.equal(speedFromPower('4.5'), 4.5);
  assert.equal(speedFromPower(0), MIN_SPEED);
  assert.equal(speedFromPower(50), MAX_SPEED);
  assert.equal(speedFromPower('fast'), DEFAULT_SPEED);
  assert.equal(powerFromSpeed(12), MAX_SPEED);
});

test('the pull is measured back along the aim', () => {
  const from = { x: 1, y: 0.5 };
  assert.ok(Math.abs(strokePull(0, from, { x: 0.9, y: 0.5 }) - 0.1) < 1e-12, 'straight back');
  assert.ok(Math.abs(strokePull(0, from, { x: 0.9, y: 0.7 }) - 0.1) < 1e-12, 'sideways counts for nothing');
  assert.equal(strokePull(0, from, { x: 1.2, y: 0.5 }), 0, 'forward is no pull');
  assert.equal(strokePull(0, from, { x: 0, y: 0.5 }), PULL_MAX);
  assert.ok(Math.abs(strokePull(90, from, { x: 1, y: 0.3 }) - 0.2) < 1e-12, 'aimed up the table: back is down');
});

test('a press takes the stick on the cue ball or behind it', () => {
  const cue = { x: 1, y: 0.5 };
  const R = 0.028;
  assert.equal(onStick({ x: 1.01, y: 0.5 }, cue, 0, R, 0.05, false), true, 'on the ball');
  assert.equal(onStick({ x: 1.01, y: 0.5 }, cue, 0, R, 0.05, true), false, 'on the ball in hand: it moves');
  assert.equal(onStick({ x: 0.7, y: 0.51 }, cue, 0, R, 0.05, true), true, 'on the stick behind it');
  assert.equal(onStick({ x: 1.3, y: 0.5 }, cue, 0, R, 0.05, false), false, 'in front of it');
  assert.equal(onStick({ x: 1 - STICK_REACH - 0.01, y: 0.5 }, cue, 0, R, 0.05, false), false, 'beyond the stick');
  assert.equal(onStick({ x: 0.7, y: 0.7 }, cue, 0, R, 0.05, false), false, 'beside the stick');
});

test('the stick goes through the ball after a release', () => {
  assert.equal(strikePull(0.2, 0), 0.2);
  assert.ok(strikePull(0.2, 1) < 0, 'through the ball');
  assert.equal(strikePull(0.2, 5), strikePull(0.2, 1));
});

test('angles and aims', () => {
  assert.equal(normDeg(-90), 270);
  assert.equal(normDeg(720.5), 0.5);
  assert.equal(aimToward({ x: 0, y: 0 }, { x: 0, y: 1 }), 90);
  assert.equal(aimToward({ x: 0, y: 0 }, { x: 0.00001, y: 0 }), null);
});

test('the tip widget\'s offset stays within the miscue limit', () => {
  assert.deepEqual(tipOffset(0.2, -0.1), { a: 0.2, b: 0.1 });
  const far = tipOffset(1, 0);
  assert.equal(far.a, TIP_LIMIT);
  assert.equal(far.b + 0, 0);  // -0 from a press on the centre line, as the page always sent it
  const corner = tipOffset(1, 1);
  assert.ok(Math.hypot(corner.a, corner.b) <= TIP_LIMIT + 0.01);
  assert.equal(tipWords({ a: 0, b: 0 }), 'centre');
  assert.equal(tipWords({ a: -0.1, b: 0.2 }), 'follow 0.20, left 0.10');
  assert.equal(tipWords({ a: 0.3, b: -0.25 }), 'draw 0.25, right 0.30');
});

test('the sounds\' impact speeds and the events\' balls', () => {
  const frame = (v) => ({ balls: v.map(([vx, vy]) => [0, 0, 1, vx, vy]) });
  const prev = frame([[2, 0], [0, 0]]);
  const cur = frame([[0, 0], [1.9, 0]]);
  assert.ok(Math.abs(impactSpeed('ball_ball', [0, 1], prev, cur) - 3.9 / 1.95) < 1e-12);
  assert.ok(Math.abs(impactSpeed('ball_cushion', [1], prev, frame([[2, 0], [-1.8, 0]])) - 1) < 1e-12);
  assert.equal(impactSpeed('ball_pocket', [0], prev, cur), 2);
  assert.equal(impactSpeed('cue_strike', [1], prev, cur), 1.9);
  assert.equal(impactSpeed('state_change', [0], prev, cur), 0);
  assert.deepEqual(['cue', '7', 'white', 'yellow', 'red', 'x'].map(numberOfId), [0, 7, 0, 1, 2, -1]);
});

// game-carom.js: three-cushion's count in words, as the ball goes (the
// facade's count) and once it stops (the engine's ruling).

import { test } from 'node:test';
import assert from 'node:assert/strict';

import { caromCall, countWords, liveCall, threeCushion } from '../../page/game-carom.js';

test('the count in words', () => {
  assert.equal(countWords({ cushions: 0, hit: [] }), '0 cushions');
  assert.equal(countWords({ cushions: 1, hit: [2] }), '1 cushion · red');
  assert.equal(countWords({ cushions: 3, hit: [2, 1] }), '3 cushions · red, then yellow');
});

test('the call while the ball runs is the facade\'s count\'s', () => {
  assert.equal(liveCall({ cushions: 4, hit: [2], done: false, made: false }), 'running…');
  assert.equal(liveCall({ cushions: 3, hit: [2, 1], done: true, made: true }), 'three cushions first…');
  assert.equal(liveCall({ cushions: 2, hit: [2, 1], done: true, made: false }), 'too few cushions…');
});

test('the call once the balls stop is the ruling\'s', () => {
  assert.equal(caromCall({ carom: { point: true } }), 'Point');
  assert.equal(caromCall({ carom: { point: false }, fouls: ['push_through'] }), 'Foul: no point');
  assert.equal(caromCall({ carom: { point: false }, fouls: [] }), 'No point');
});

test('the panel shows the count and the call', () => {
  const els = {};
  const $ = (id) => (els[id] ||= { textContent: '', className: '' });
  threeCushion.showCount($, { cushions: 2, hit: [1], done: false, made: false }, null, false);
  assert.equal(els['carom-cushions'].textContent, '2 cushions · yellow');
  assert.equal(els['carom-call'].textContent, 'running…');
  threeCushion.showCount($, null, { carom: { point: true, cushions: 3, hit: [1, 2] } }, true);
  assert.equal(els['carom-cushions'].textContent, '3 cushions · yellow, then red');
  assert.equal(els['carom-call'].textContent, 'Point');
  assert.equal(els['carom-call'].className, 'point');
});

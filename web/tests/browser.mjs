// Browser tests of the breakshot page (issue 6): playwright-core drives
// Debian's Chromium (/usr/bin/chromium, headless) against the page served
// by `breakshot serve`. Nothing is downloaded.
//
//   node web/tests/browser.mjs --cli build/release/breakshot --root build/web/dist \
//        [--shots DIR] [--only NAME] [--frames N]
//
// --frames N: the frame-time test measures N breaks (default 1).
//
// Prints one line per test and ends with "N passed, M failed"; exits 1 on
// any failure. Screenshots of the game and the lab go to --shots
// (default build/web/screenshots).
//
// The tests are here (the page, the pool games, the feel, online play)
// and in browser-games.mjs (snooker, three-cushion, 10-ball) and
// browser-lab.mjs (the lab); browser-lib.mjs has what they share.
import path from 'node:path';
import { chromium } from 'playwright-core';
import { speedFromPull } from '../page/game-stroke.js';
import {
  args, balls, ballsOf, check, idle, newGame, openPage, shots, startServer, test, tests, toPage,
} from './browser-lib.mjs';
import { register as registerGames } from './browser-games.mjs';
import { register as registerLab } from './browser-lab.mjs';

// --- the tests ----------------------------------------------------------

test('page loads with no console errors', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await idle(page);
  check(await page.isVisible('#table'), 'the table canvas is not visible');
  const st = await page.evaluate(() => window.breakshot.state());
  check(st.phase === 'break_shot', 'a new page waits for the break, not ' + st.phase);
  await page.waitForTimeout(500);
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('a shot made with the mouse moves the balls and ends with a ruling', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  const before = await balls(page);
  // Aim at the apex ball by pointing the mouse at it, then shoot hard.
  const t = await page.evaluate(() => window.breakshot.game.table());
  const apex = before[1][2] ? before[1] : before.find((b, i) => i > 0 && b[2]);
  const target = await toPage(page, apex[0], apex[1]);
  await page.mouse.move(target.x, target.y);
  await page.mouse.click(target.x, target.y);
  await page.fill('#power', '9');
  await page.dispatchEvent('#power', 'input');
  await page.click('#shoot');
  await page.waitForFunction(() => window.breakshot.busy(), null, { timeout: 5000 }).catch(() => {});
  await idle(page);
  const after = await balls(page);
  const moved = after.filter((b, i) => b[0] !== before[i][0] || b[1] !== before[i][1] || b[2] !== before[i][2]).length;
  check(moved >= 5, `a break moved only ${moved} balls`);
  const log = await page.textContent('#ruling-log');
  check(log && log.trim().length > 0, 'no ruling in the log after the shot');
  await page.screenshot({ path: path.join(shots, 'game-after-break.png') });
  check(t.length > 2 && t.width > 1, 'table size');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// --- the feel: aiming, the stroke, sounds, rolling, the phone ------------

// The aim's direction (degrees, [0, 360)) from the cue ball to table point (x, y).
const phiTo = (cue, x, y) => ((Math.atan2(y - cue[1], x - cue[0]) * 180 / Math.PI) + 360) % 360;
const angleGap = (a, b) => Math.abs(((a - b + 540) % 360) - 180);

// A digest of the table canvas's pixels (to see that a drawing changed).
const canvasDigest = (page) => page.evaluate(() => {
  const c = document.querySelector('#table');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let h = 0;
  for (let i = 0; i < d.length; i += 7) h = (h * 31 + d[i]) >>> 0;
  return h;
});

// The speed of a stroke drawn back `pull` metres: the page's own (game-stroke.js).
const speedOfPull = speedFromPull;

test('hovering aims the cue, a press holds the aim, Escape lets the hover aim again', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  const st = await page.evaluate(() => window.breakshot.state());
  const cue = st.position[0];
  const before = await canvasDigest(page);
  // The mouse over the table, no button: the aim follows it.
  const p1 = [cue[0] + 0.6, cue[1] + 0.3];
  let at = await toPage(page, p1[0], p1[1]);
  await page.mouse.move(at.x, at.y, { steps: 4 });
  await page.waitForTimeout(100);
  let aim = await page.evaluate(() => window.breakshot.aim());
  check(angleGap(aim.phi, phiTo(cue, ...p1)) < 0.5, `hovering at ${p1} aims at ${aim.phi}, not ${phiTo(cue, ...p1)}`);
  check(await canvasDigest(page) !== before, 'the drawing did not change with the aim (the cue did not move)');
  const p2 = [cue[0] + 0.5, cue[1] - 0.35];
  at = await toPage(page, p2[0], p2[1]);
  await page.mouse.move(at.x, at.y, { steps: 4 });
  aim = await page.evaluate(() => window.breakshot.aim());
  check(angleGap(aim.phi, phiTo(cue, ...p2)) < 0.5, `hovering at ${p2} aims at ${aim.phi}`);
  // A press (a click) aims there and holds the aim: hovering no longer moves it.
  const p3 = [cue[0] + 1.2, cue[1] + 0.05];
  at = await toPage(page, p3[0], p3[1]);
  await page.mouse.click(at.x, at.y);
  const held = (await page.evaluate(() => window.breakshot.aim())).phi;
  check(angleGap(held, phiTo(cue, ...p3)) < 0.5, `the click at ${p3} aims at ${held}`);
  at = await toPage(page, p1[0], p1[1]);
  await page.mouse.move(at.x, at.y, { steps: 4 });
  check((await page.evaluate(() => window.breakshot.aim())).phi === held, 'hovering moved a held aim');
  check(/Aim held/.test(await page.textContent('#aim-hint')), 'the hint does not say the aim is held: ' + await page.textContent('#aim-hint'));
  await page.keyboard.press('Escape');
  await page.mouse.move(at.x + 3, at.y + 3, { steps: 2 });
  aim = await page.evaluate(() => window.breakshot.aim());
  check(angleGap(aim.phi, phiTo(cue, ...p1)) < 2, 'after Escape hovering does not aim: ' + aim.phi);
  await page.locator('#table').screenshot({ path: path.join(shots, 'game-hover-aim.png') });
  check((await page.evaluate(() => window.breakshot.state())).actions === 0, 'hovering and clicking played something');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('a drag back from the cue ball and a release strike with the power of the pull', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await page.click('#new-game');
  await page.fill('#seed', '5');
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  await page.fill('#phi', '0');
  await page.dispatchEvent('#phi', 'input');
  await page.fill('#power', '2');
  await page.dispatchEvent('#power', 'input');
  const cue = (await page.evaluate(() => window.breakshot.state())).position[0];
  // The cue ball is in hand for the break (a press on it moves it): the
  // stroke starts on the stick, 12 cm behind the ball.
  const grip = 0.12;
  const from = await toPage(page, cue[0] - grip, cue[1]);
  // A pull under a centimetre strikes nothing and keeps the speed.
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x - 1, from.y, { steps: 2 });
  await page.mouse.up();
  await page.waitForTimeout(200);
  check((await page.evaluate(() => window.breakshot.state())).actions === 0, 'a release without a pull shot');
  check((await page.evaluate(() => window.breakshot.aim())).speed === 2, 'a release without a pull changed the speed');
  // Pulled back 0.2 m along the aim (phi 0: toward -x), released.
  const pull = 0.2;
  const want = speedOfPull(pull);
  const to = await toPage(page, cue[0] - grip - pull, cue[1]);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 8 });
  const shown = await page.textContent('#power-out');
  check(Math.abs(parseFloat(shown) - want) < 0.051, `drawn back ${pull} m the power shows ${shown}, not ${want}`);
  await page.locator('#table').screenshot({ path: path.join(shots, 'game-stroke.png') });
  await page.mouse.up();
  await page.waitForFunction(() => window.breakshot.state().actions === 1, null, { timeout: 5000 });
  await idle(page);
  const rec = await page.evaluate(() => window.breakshot.game.record());
  const strike = rec.actions[0].action.strike;
  check(Math.abs(strike.speed - want) < 0.051, `the stroke shot at ${strike.speed} m/s, the pull gives ${want}`);
  check(strike.phi === 0, 'the stroke moved the aim: ' + strike.phi);
  // With the cue ball on the table (not in hand), a press on the ball itself
  // takes the cue.
  const st = await page.evaluate(() => window.breakshot.state());
  if (st.legal.shoot && st.legal.place === 'none' && st.phase !== 'game_over') {
    const c = st.position[0];
    const aim = await page.evaluate(() => window.breakshot.aim());
    const rad = aim.phi * Math.PI / 180;
    const a = await toPage(page, c[0], c[1]);
    const b = await toPage(page, c[0] - 0.1 * Math.cos(rad), c[1] - 0.1 * Math.sin(rad));
    await page.mouse.move(a.x, a.y);
    await page.mouse.down();
    await page.mouse.move(b.x, b.y, { steps: 6 });
    await page.mouse.up();
    await page.waitForFunction(() => window.breakshot.state().actions === 2, null, { timeout: 5000 });
    await idle(page);
    const s2 = (await page.evaluate(() => window.breakshot.game.record())).actions[1].action.strike;
    check(Math.abs(s2.speed - speedOfPull(0.1)) < 0.051, `the stroke from the cue ball shot at ${s2.speed}, not ${speedOfPull(0.1)}`);
  } else {
    console.log('      (the break left the cue ball in hand: no stroke from the ball itself)');
  }
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('the mute switch is remembered across a reload', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  check(await page.getAttribute('#mute', 'aria-pressed') === 'false', 'a new page is muted');
  await page.click('#mute');
  check(await page.getAttribute('#mute', 'aria-pressed') === 'true', 'the switch did not mute');
  await page.reload();
  await page.waitForFunction(() => window.breakshot && window.breakshot.engine, null, { timeout: 30000 });
  check(await page.getAttribute('#mute', 'aria-pressed') === 'true', 'the page forgot it was muted');
  check((await page.evaluate(() => window.breakshot.sounds())).muted, 'the sounds are not muted after the reload');
  await page.click('#mute');
  await page.reload();
  await page.waitForFunction(() => window.breakshot && window.breakshot.engine, null, { timeout: 30000 });
  check(await page.getAttribute('#mute', 'aria-pressed') === 'false', 'the page forgot the sound was on');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('a break and a scratch schedule sounds scaled by their impacts, with no audio device', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url, { speed: '1' });
  await newGame(page, { game: 'nine_ball', opponent: 'friend' });
  await page.click('#table');   // a gesture: the page may start its audio
  const s0 = await page.evaluate(() => window.breakshot.sounds());
  await scratchBreak(page);     // the cue ball alone into a corner pocket
  let s = await page.evaluate(() => window.breakshot.sounds());
  check(s.counts.cue === s0.counts.cue + 1 && s.counts.pocket === s0.counts.pocket + 1 && s.counts.ball === s0.counts.ball,
    'the scratch: ' + JSON.stringify(s.counts));
  // The break of a new game: the tip, many contacts and cushions.
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  await page.fill('#power', '9');
  await page.dispatchEvent('#power', 'input');
  const c0 = (await page.evaluate(() => window.breakshot.sounds())).counts;
  await page.click('#shoot');
  await page.waitForFunction(() => window.breakshot.busy(), null, { timeout: 5000 }).catch(() => {});
  await idle(page);
  s = await page.evaluate(() => window.breakshot.sounds());
  const d = Object.fromEntries(Object.keys(s.counts).map((k) => [k, s.counts[k] - c0[k]]));
  check(d.cue === 1 && d.ball >= 6 && d.cushion >= 3, 'the break\'s sounds: ' + JSON.stringify(d));
  check(s.last.every((e) => e.gain > 0 && e.gain <= 1 && e.speed > 0), 'a sound without an impact speed: ' + JSON.stringify(s.last));
  // the tip's: the cue ball's speed as it leaves the tip (the cue's 9 m/s
  // times (1 + e) m_cue / (m_cue + m_ball), a little more than 9)
  const cueHit = s.last.filter((e) => e.kind === 'cue').pop();
  check(cueHit && cueHit.speed > 9 && cueHit.speed < 9 * 1.6, 'the tip\'s sound is not the cue ball\'s speed: ' + JSON.stringify(cueHit));
  // Scaled: the loudest contact of the break is louder than the softest.
  const balls = s.last.filter((e) => e.kind === 'ball').map((e) => e.gain);
  check(Math.max(...balls) > 2 * Math.min(...balls), 'the contacts are all as loud: ' + balls);
  console.log(`      sounds: ${JSON.stringify(d)}; audio context ${s.context}, ${s.played} played`);
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('the pool balls\' markings roll with their spin', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url, { speed: '1' });
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  const orient = () => page.evaluate(() => Object.fromEntries([...window.breakshot.ui.orient].map(([n, o]) => [n, { v: o.v, m: [...o.m] }])));
  const o0 = await orient();
  check(Object.values(o0).every((o) => o.v === 0), 'balls turned before the break');
  const before = await balls(page);
  // The most each ball's number disc (its +z axis) has tipped from facing
  // up, read at every frame: a ball that rolled a whole number of turns
  // in a line faces up again at the end, and the page turns the balls
  // frame by frame (drawing only), so where each ends depends on the
  // frame times.
  await page.evaluate(() => {
    const tilt = (window.__tilt = {});
    const watch = () => {
      for (const [n, o] of window.breakshot.ui.orient) tilt[n] = Math.max(tilt[n] ?? 0, 1 - o.m[8]);
      if (!window.__tiltStop) requestAnimationFrame(watch);
    };
    requestAnimationFrame(watch);
  });
  await page.fill('#power', '9');
  await page.dispatchEvent('#power', 'input');
  await page.click('#shoot');
  await page.waitForFunction(() => window.breakshot.busy(), null, { timeout: 5000 }).catch(() => {});
  await page.waitForTimeout(250);
  await page.locator('#table').screenshot({ path: path.join(shots, 'game-rolling.png') });
  await idle(page);
  const after = await balls(page);
  const o1 = await orient();
  const tilt = await page.evaluate(() => { window.__tiltStop = true; return window.__tilt; });
  // every object ball that moved has turned: its number disc left the up
  // position during the shot
  let turned = 0;
  let moved = 0;
  for (let n = 1; n < 16; n++) {
    const far = Math.hypot(after[n][0] - before[n][0], after[n][1] - before[n][1]);
    if (far < 0.05) continue;
    moved++;
    if (o1[n] && o1[n].v > 0 && (tilt[n] ?? 0) > 0.001) turned++;
  }
  check(moved >= 5 && turned === moved, `${turned} of the ${moved} balls that moved have turned`);
  // a spin the engine gives: the playback's spins are those of the result
  const w = await page.evaluate(() => {
    const pb = window.breakshot.game.shotPlayback(0);
    try {
      const f = pb.frame(0.5);
      return [...pb.spins(f.balls.length)];
    } finally { pb.free(); }
  });
  check(w.length === 48 && w.some((x) => Math.abs(x) > 5), 'the playback has no spins: ' + w.slice(0, 6));
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// Frame times (requestAnimationFrame) during the break's animation at 1x:
// the intervals between frames, and the page's own work in each frame.
async function breakFrames(page) {
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  await page.fill('#power', '9');
  await page.dispatchEvent('#power', 'input');
  await page.evaluate(() => {
    const ui = window.breakshot.ui;
    const stats = { gaps: [], work: [], running: true };
    window.__frames = stats;
    const frame = ui.frame.bind(ui);
    ui.frame = (now) => {
      const t0 = performance.now();
      frame(now);
      if (ui.anim) stats.work.push(performance.now() - t0);
    };
    let last = null;
    const tick = (now) => {
      if (ui.anim) {
        if (last != null) stats.gaps.push(now - last);
        last = now;
      } else {
        last = null;
      }
      if (stats.running) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  await page.click('#shoot');
  await page.waitForFunction(() => window.breakshot.busy(), null, { timeout: 5000 }).catch(() => {});
  await idle(page);
  return page.evaluate(() => {
    const s = window.__frames;
    s.running = false;
    return { gaps: s.gaps, work: s.work };
  });
}

function frameFigures(gaps, work) {
  const sorted = (a) => [...a].sort((x, y) => x - y);
  const q = (a, f) => a[Math.min(a.length - 1, Math.floor(f * a.length))];
  const g = sorted(gaps);
  const w = sorted(work);
  // a gap of k frame periods (16.7 ms) dropped k - 1 frames
  const dropped = gaps.reduce((n, x) => n + Math.max(0, Math.round(x / (1000 / 60)) - 1), 0);
  return {
    frames: gaps.length, median: q(g, 0.5), p95: q(g, 0.95), max: g[g.length - 1], dropped,
    workMedian: q(w, 0.5), workP95: q(w, 0.95), workMax: w[w.length - 1],
  };
}

test('a break animates, its frame times printed', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url, { speed: '1' });
  const runs = Number(args.frames ?? 1);
  const gaps = [];
  const work = [];
  for (let k = 0; k < runs; k++) {
    const r = await breakFrames(page);
    gaps.push(...r.gaps);
    work.push(...r.work);
  }
  const f = frameFigures(gaps, work);
  const ms = (x) => x.toFixed(1);
  console.log(`      frames ${f.frames} (${runs} break${runs > 1 ? 's' : ''}): interval median ${ms(f.median)} ms, p95 ${ms(f.p95)}, max ${ms(f.max)}, ` +
    `dropped ${f.dropped}; the page's work per frame median ${ms(f.workMedian)} ms, p95 ${ms(f.workP95)}, max ${ms(f.workMax)}`);
  // The figures are a measurement (docs/web.md), not a pass mark: they
  // move with the machine and its load, and tests never assert timings.
  // What is checked is that the break animated at all, without errors.
  check(f.frames > 60, 'the break animated only ' + f.frames + ' frames');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// A touch drag through the DevTools protocol (playwright's touchscreen only taps).
async function touchDrag(page, from, to, steps = 8) {
  const cdp = await page.context().newCDPSession(page);
  const point = (p) => [{ x: p.x, y: p.y, id: 1, radiusX: 4, radiusY: 4, force: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: point(from) });
  for (let i = 1; i <= steps; i++) {
    const p = { x: from.x + (to.x - from.x) * i / steps, y: from.y + (to.y - from.y) * i / steps };
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: point(p) });
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}

test('a phone held upright: the table turned to fit, no sideways scroll, touch aiming and a stroke', async ({ browser, url }) => {
  const context = await browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.breakshot && window.breakshot.engine && window.breakshot.game, null, { timeout: 30000 });
  await page.waitForTimeout(300);
  const wide = await page.evaluate(() => document.documentElement.scrollWidth);
  check(wide <= 390, 'the page scrolls sideways: ' + wide + ' px');
  check(await page.getAttribute('#table', 'data-rotated') === '1', 'the table is not turned on an upright phone');
  const box = await page.locator('#table').boundingBox();
  check(box.x >= 0 && box.x + box.width <= 390 && box.height > box.width && box.y + box.height <= 844,
    'the table does not fit the screen: ' + JSON.stringify(box));
  check(box.width >= 300, 'the table is small: ' + box.width + ' px wide');
  // The controls a thumb reaches: the power and Shoot on the screen, at the bottom.
  for (const sel of ['#shoot', '#power']) {
    const b = await page.locator(sel).boundingBox();
    check(b && b.y >= 844 / 2 && b.y + b.height <= 844 && b.x >= 0 && b.x + b.width <= 390, `${sel} is not in reach: ${JSON.stringify(b)}`);
  }
  const st = await page.evaluate(() => window.breakshot.state());
  const cue = st.position[0];
  // A tap on the 1 ball aims at it.
  const target = st.position[1];
  const at = await toPage(page, target[0], target[1]);
  check(at.x > box.x && at.x < box.x + box.width && at.y > box.y && at.y < box.y + box.height, 'the ball is off the table on the screen');
  await page.touchscreen.tap(at.x, at.y);
  const aim = await page.evaluate(() => window.breakshot.aim());
  check(angleGap(aim.phi, phiTo(cue, target[0], target[1])) < 1, `the tap aims at ${aim.phi}, not at the 1 ball (${phiTo(cue, target[0], target[1])})`);
  check(await page.evaluate(() => window.breakshot.state().actions) === 0, 'the tap shot');
  await page.screenshot({ path: path.join(shots, 'phone.png'), scale: 'css' });
  // A stroke: the finger on the stick (the cue ball is in hand for the
  // break), pulled back 0.25 m, let go.
  const pull = 0.25;
  const rad = aim.phi * Math.PI / 180;
  const back = (d) => toPage(page, cue[0] - d * Math.cos(rad), cue[1] - d * Math.sin(rad));
  const from = await back(0.12);
  const to = await back(0.12 + pull);
  await touchDrag(page, from, to);
  await page.waitForFunction(() => window.breakshot.state().actions === 1, null, { timeout: 5000 });
  await page.waitForTimeout(400);
  await page.screenshot({ path: path.join(shots, 'phone-break.png') });
  // The break is seen; the rest of it plays at the tests' speed.
  await page.evaluate(() => { document.getElementById('playback-speed').value = '4'; });
  await idle(page);
  const rec = await page.evaluate(() => window.breakshot.game.record());
  const strike = rec.actions[0].action.strike;
  check(Math.abs(strike.speed - speedOfPull(pull)) < 0.051, `the touch stroke shot at ${strike.speed}, not ${speedOfPull(pull)}`);
  check(angleGap(strike.phi, aim.phi) < 1e-9, 'the stroke changed the aim');
  await page.screenshot({ path: path.join(shots, 'phone-after.png') });
  check(await page.evaluate(() => document.documentElement.scrollWidth) <= 390, 'the page scrolls sideways after the shot');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// The break from the kitchen straight into the bottom-left corner pocket:
// the cue ball touches nothing and drops, a foul in 9-ball that gives the
// opponent ball in hand anywhere.
async function scratchBreak(page) {
  const t = await page.evaluate(() => window.breakshot.game.table());
  const pocket = t.pockets.find((p) => p.name === 'bottom_left');
  const cue = [t.head_string - 0.1, 0.35];
  const place = await page.evaluate((p) => window.breakshot.act({ type: 'place_cue_ball', position: p }), cue);
  check(!place.error, 'placement refused: ' + place.error);
  const phi = Math.atan2(pocket.centre[1] - cue[1], pocket.centre[0] - cue[0]) * 180 / Math.PI;
  const reply = await page.evaluate((s) => window.breakshot.act(s),
    { type: 'shoot', strike: { speed: 2.0, phi, theta: 0, a: 0, b: 0 }, call: null, safety: false, push_out: false });
  check(!reply.error, 'shot refused: ' + reply.error);
  await idle(page);
  return reply;
}

test('with "balls may leave the cloth" a high-elevation shot jumps the cue ball, drawn in flight', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  // The box starts as the engine's default (GamePhysics: on the cloth).
  // The box starts at the engine's default, on (GamePhysics::airborne).
  check(await page.isChecked('#airborne'), 'the airborne box is not ticked on a new page');
  await page.click('#new-game');
  await page.check('#airborne');
  await newGame(page, { game: 'eight_ball', opponent: 'friend' });
  check(await page.evaluate(() => window.breakshot.ui.physics().airborne === true),
    'the game made with the box ticked does not have physics.airborne');
  // The cue ball in the kitchen, aimed up the table, 3 m/s, the cue raised 45 degrees.
  const place = await page.evaluate(() => window.breakshot.act({ type: 'place_cue_ball', position: [0.6, 0.635] }));
  check(!place.error, 'placement refused: ' + place.error);
  await idle(page);
  await page.fill('#phi', '0');
  await page.dispatchEvent('#phi', 'input');
  await page.fill('#power', '3');
  await page.dispatchEvent('#power', 'input');
  await page.fill('#elevation', '45');
  await page.dispatchEvent('#elevation', 'input');
  check(await page.textContent('#elevation-out') === '45°', 'the elevation shows ' + await page.textContent('#elevation-out'));
  check(Number(await page.getAttribute('#elevation', 'max')) >= 60, 'the elevation slider stops below 60 degrees');
  const aim = await page.evaluate(() => window.breakshot.aim());
  check(aim.theta === 45 && aim.speed === 3, 'the aim is ' + JSON.stringify(aim));
  await page.screenshot({ path: path.join(shots, 'game-jump-aim.png') });
  await page.selectOption('#playback-speed', '0.25');
  await page.click('#shoot');
  // The page draws the cue ball in flight (the canvas' data-flight counts
  // the balls drawn off the cloth in the last frame).
  await page.waitForFunction(() => Number(document.querySelector('#table').dataset.flight) > 0, null, { timeout: 10000 });
  await page.waitForFunction(() => window.breakshot.ui.view.flight.maxZ > 0.09, null, { timeout: 10000 });
  await page.locator('#table').screenshot({ path: path.join(shots, 'game-jump.png') });
  // The flight is seen; the rest of the shot plays at the tests' speed.
  await page.selectOption('#playback-speed', '4');
  await idle(page);
  check(await page.evaluate(() => document.querySelector('#table').dataset.flight) === '0',
    'a ball is still drawn in flight after the shot');
  // The link carries the physics: opened, the game has it and the box shows it.
  const link = await page.evaluate(() => window.breakshot.link());
  const two = await openPage(browser, url + '#game=' + link);
  await idle(two.page);
  check(await two.page.evaluate(() => window.breakshot.ui.physics().airborne === true), 'the link lost physics.airborne');
  check(await two.page.isChecked('#airborne'), 'the box does not show the linked game\'s physics');
  const all = problems.concat(two.problems);
  check(all.length === 0, all.join('\n'));
  await two.context.close();
  await context.close();
});

test('a scripted scratch shows the foul and ball in hand', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await newGame(page, { game: 'nine_ball', opponent: 'friend' });
  const reply = await scratchBreak(page);
  check(reply.ruling.fouls.includes('scratch'), 'no scratch in the ruling: ' + JSON.stringify(reply.ruling));
  const st = await page.evaluate(() => window.breakshot.state());
  check(st.legal.place === 'anywhere', 'ball in hand is ' + st.legal.place);
  check(st.player === 1, 'the turn did not pass');
  const status = (await page.textContent('#status')) + (await page.textContent('#ruling-log'));
  check(/scratch/i.test(status), 'the page does not say scratch: ' + status);
  check(/ball in hand/i.test(status), 'the page does not say ball in hand: ' + status);
  // The log says the ruling once, in words: no foul's identifier, no
  // second "Foul: ..." after the ruling's own.
  const entries = await page.$$eval('#ruling-log li', (li) => li.map((x) => x.textContent));
  const scratch = entries.find((t) => /scratch/i.test(t)) || '';
  check(/Foul: a scratch\b/.test(scratch), 'the log entry of the scratch is: ' + scratch);
  check((scratch.match(/Foul/g) || []).length === 1, 'the log says the foul more than once: ' + scratch);
  check(!entries.some((t) => t.includes('_')), 'the log shows an identifier: ' + entries.join(' | '));
  await page.screenshot({ path: path.join(shots, 'game-scratch.png') });
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('the AI takes its turn and plays a legal shot', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await newGame(page, { game: 'nine_ball', opponent: 'beginner' });
  await scratchBreak(page);  // the AI now has ball in hand
  await page.waitForFunction(() => window.breakshot.state().actions >= 4 || window.breakshot.state().player === 0,
    null, { timeout: 60000 });
  await idle(page);
  const st = await page.evaluate(() => window.breakshot.state());
  check(st.actions >= 3, `the AI did not act (${st.actions} actions)`);
  const log = await page.textContent('#ruling-log');
  check(!/refused|error/i.test(log), 'the log shows an error: ' + log);
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('a shared link reproduces the shot', async ({ browser, url }) => {
  const one = await openPage(browser, url);
  await newGame(one.page, { game: 'eight_ball', opponent: 'friend' });
  const cue = await one.page.evaluate(() => window.breakshot.state().position[0]);
  await one.page.evaluate((c) => window.breakshot.act({ type: 'shoot', strike: { speed: 8.5, phi: 0.3, theta: 0, a: 0.1, b: -0.1 }, call: null, safety: false, push_out: false }), cue);
  await idle(one.page);
  const want = await one.page.evaluate(() => window.breakshot.state());
  await one.page.click('#share');
  const hash = await one.page.evaluate(() => location.hash);
  check(hash.startsWith('#game='), 'share did not put a link in the address: ' + hash);
  const two = await openPage(browser, url + hash);
  await idle(two.page);
  const got = await two.page.evaluate(() => window.breakshot.state());
  check(ballsOf(got) === ballsOf(want), 'the balls differ after the link');
  check(got.actions === want.actions && got.player === want.player, 'the game differs after the link');
  // The shot's own link (its log entry's "link" button) replays it when opened.
  await one.page.click('#ruling-log .shot-link');
  const shotHash = await one.page.evaluate(() => location.hash);
  check(/^#game=[^&]+&shot=0$/.test(shotHash), 'the shot link is ' + shotHash);
  const three = await openPage(browser, url + shotHash);
  await three.page.waitForFunction(() => window.breakshot.busy(), null, { timeout: 10000 });  // the replay runs
  await idle(three.page);
  const again = await three.page.evaluate(() => window.breakshot.state());
  check(ballsOf(again) === ballsOf(want), 'the balls differ after the shot link');
  const problems = one.problems.concat(two.problems, three.problems);
  check(problems.length === 0, problems.join('\n'));
  await one.context.close();
  await two.context.close();
  await three.context.close();
});

registerGames();
registerLab();

// Online play: two pages (two browser contexts, as two computers) play
// three-cushion through the server's WebSocket; the second is closed
// mid-game and opened again from the link, takes its seat back with the
// token the page kept, and the game goes on. Each page plays every action
// on its own engine and compares the hash with the server's.
test('online: two pages play each other through the server; one closes and comes back', async ({ browser, url }) => {
  const one = await openPage(browser, url);
  await idle(one.page);
  await one.page.click('#new-game');
  await one.page.selectOption('#game-type', 'three_cushion');
  await one.page.click('#online-create');
  await one.page.waitForFunction(() => /#room=/.test(document.getElementById('online-link').value), null, { timeout: 20000 });
  const link = await one.page.inputValue('#online-link');
  check(/#room=[A-Z2-9]{6}$/.test(link), 'the room link is ' + link);
  check(await one.page.evaluate(() => window.breakshot.online().seat) === 0, 'the creator is not Player 1');
  check(await one.page.evaluate(() => window.breakshot.state().game) === 'three_cushion', 'the room does not play three-cushion');

  const two = await openPage(browser, link);
  const seated = (page, seat) => page.waitForFunction((k) => {
    const o = window.breakshot.online();
    return o && o.seat === k && window.breakshot.state();
  }, seat, { timeout: 20000 });
  await seated(two.page, 1);
  await one.page.waitForFunction(() => /your friend is here/.test(document.getElementById('online-status').textContent), null, { timeout: 20000 });

  const shot = (phi) => ({ type: 'shoot', strike: { speed: 3, phi, theta: 0, a: 0, b: 0 }, call: null, safety: false, push_out: false });
  const actions = (page, n) => page.waitForFunction((k) => window.breakshot.state().actions === k && !window.breakshot.busy(), n, { timeout: 60000 });
  const hash = (page) => page.evaluate(async () => {
    const { stateHash } = await import('./online.js');
    return stateHash(window.breakshot.game.stateText());
  });
  // The page of the seat to act plays; the other is refused, then follows.
  async function play(pages, phi, n) {
    const toAct = await pages[0].evaluate(() => window.breakshot.state().player);
    const actor = pages[toAct];
    const other = pages[1 - toAct];
    const refused = await other.evaluate((a) => window.breakshot.act(a), shot(phi));
    check(refused.error, 'the page not to act played: ' + JSON.stringify(refused).slice(0, 200));
    const r = await actor.evaluate((a) => window.breakshot.act(a), shot(phi));
    check(!r.error, 'the shot was refused: ' + r.error);
    for (const p of pages) await actions(p, n);
    const [h0, h1] = [await hash(pages[0]), await hash(pages[1])];
    check(h0 === h1, `the two pages' tables differ after action ${n - 1}: ${h0} ${h1}`);
  }
  await play([one.page, two.page], 90, 1);

  // The second page closes; the first sees its friend away.
  await two.page.close();
  await one.page.waitForFunction(() => /your friend is away/.test(document.getElementById('online-status').textContent), null, { timeout: 20000 });
  // It is opened again from the link, in the same browser: its seat back.
  const again = await two.context.newPage();
  again.on('pageerror', (e) => two.problems.push('page error: ' + e.message));
  await again.goto(link);
  await again.waitForFunction(() => window.breakshot && window.breakshot.online && window.breakshot.online(), null, { timeout: 30000 });
  await seated(again, 1);
  await actions(again, 1);
  await one.page.waitForFunction(() => /your friend is here/.test(document.getElementById('online-status').textContent), null, { timeout: 20000 });
  await play([one.page, again], 200, 2);
  await play([one.page, again], 20, 3);
  for (const p of [one.page, again]) {
    check(await p.isHidden('#online-mismatch'), 'a page shows a mismatch: ' + await p.textContent('#online-mismatch'));
  }
  await one.page.screenshot({ path: path.join(shots, 'online.png') });

  // A hash from the server that differs from the page's own is shown.
  await one.page.evaluate(() => window.breakshot.online().receive(JSON.stringify({
    type: 'action', index: 0, seat: 0, action: {}, hash: '0000000000000000' })));
  await one.page.waitForFunction(() => !document.getElementById('online-mismatch').hidden, null, { timeout: 10000 });
  check(/differs from the server's after action 0/.test(await one.page.textContent('#online-mismatch')),
    'the mismatch says: ' + await one.page.textContent('#online-mismatch'));
  check(one.problems.length === 0, one.problems.join('\n'));
  check(two.problems.length === 0, two.problems.join('\n'));
  await one.context.close();
  await two.context.close();
});

// The room link opened in more tabs of the same browser (one context, so
// one localStorage): the second tab takes the free seat, the third watches,
// and the first keeps its seat; none loops on a lost connection. A reload
// keeps the tab's seat (its token in sessionStorage).
test('online: tabs of one browser take the free seat, then watch', async ({ browser, url }) => {
  const one = await openPage(browser, url);
  await idle(one.page);
  await one.page.click('#new-game');
  await one.page.selectOption('#game-type', 'three_cushion');
  await one.page.click('#online-create');
  await one.page.waitForFunction(() => /#room=/.test(document.getElementById('online-link').value), null, { timeout: 20000 });
  const link = await one.page.inputValue('#online-link');
  const tab = async () => {
    const p = await one.context.newPage();
    p.on('pageerror', (e) => one.problems.push('page error: ' + e.message));
    await p.goto(link);
    await p.waitForFunction(() => window.breakshot && window.breakshot.online && window.breakshot.online()
      && window.breakshot.online().room && window.breakshot.state(), null, { timeout: 30000 });
    return p;
  };
  const status = (p) => p.textContent('#online-status');
  const seatOf = (p) => p.evaluate(() => window.breakshot.online().seat);
  const second = await tab();
  await second.waitForFunction(() => /You are Player 2/.test(document.getElementById('online-status').textContent), null, { timeout: 20000 });
  await one.page.waitForFunction(() => /your friend is here/.test(document.getElementById('online-status').textContent), null, { timeout: 20000 });
  const third = await tab();
  await third.waitForFunction(() => /You are watching/.test(document.getElementById('online-status').textContent), null, { timeout: 20000 });
  // A while later, nobody has lost a seat or a connection.
  await one.page.waitForTimeout(3000);
  for (const [p, seat] of [[one.page, 0], [second, 1], [third, null]]) {
    check(await seatOf(p) === seat, `a tab holds seat ${await seatOf(p)}, not ${seat}: ${await status(p)}`);
    check(!/lost|reconnecting|another tab/.test(await status(p)), 'a tab says: ' + await status(p));
    check(await p.evaluate(() => window.breakshot.online().connected), 'a tab is not connected: ' + await status(p));
  }
  // The two seats play each other.
  const shot = { type: 'shoot', strike: { speed: 3, phi: 90, theta: 0, a: 0, b: 0 }, call: null, safety: false, push_out: false };
  const r = await one.page.evaluate((a) => window.breakshot.act(a), shot);
  check(!r.error, 'the shot was refused: ' + r.error);
  for (const p of [second, third]) {
    await p.waitForFunction(() => window.breakshot.state().actions === 1 && !window.breakshot.busy(), null, { timeout: 60000 });
  }
  // A reload keeps the tab's seat.
  await second.reload();
  await second.waitForFunction(() => window.breakshot && window.breakshot.online && window.breakshot.online()
    && window.breakshot.online().seat === 1 && window.breakshot.state().actions === 1, null, { timeout: 30000 });
  await one.page.waitForTimeout(1000);
  check(await seatOf(one.page) === 0, 'the first tab lost its seat: ' + await status(one.page));
  check(!/lost|reconnecting/.test(await status(one.page)), 'the first tab says: ' + await status(one.page));
  check(one.problems.length === 0, one.problems.join('\n'));
  await one.context.close();
});

// --- run ----------------------------------------------------------------
const { proc, url } = await startServer();
// playwright's launch() starts Chromium with a fresh profile folder of its
// own (it refuses a --user-data-dir argument) and removes it at close.
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
let passed = 0;
let failed = 0;
for (const t of tests) {
  if (args.only && !t.name.includes(args.only)) continue;
  const t0 = Date.now();
  try {
    await t.fn({ browser, url });
    passed++;
    console.log(`ok    ${t.name} (${Date.now() - t0} ms)`);
  } catch (e) {
    failed++;
    console.log(`FAIL  ${t.name} (${Date.now() - t0} ms)\n      ${String(e.message).split('\n').join('\n      ')}`);
  }
}
await browser.close();
proc.kill('SIGTERM');
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);

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
import { spawn } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((acc, a, i, all) => {
    if (a.startsWith('--')) acc.push([a.slice(2), all[i + 1]]);
    return acc;
  }, []));
const cli = args.cli ?? 'build/release/breakshot';
const root = args.root ?? 'build/web/dist';
const shots = args.shots ?? 'build/web/screenshots';
mkdirSync(shots, { recursive: true });

// --- the server ---------------------------------------------------------
function startServer() {
  return new Promise((resolve, reject) => {
    const proc = spawn(cli, ['serve', '--port', '0', '--root', root, '--quiet'],
      { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    let err = '';
    const timer = setTimeout(() => reject(new Error('breakshot serve did not start: ' + err)), 10000);
    proc.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (m) { clearTimeout(timer); resolve({ proc, url: m[0] }); }
    });
    proc.stderr.on('data', (d) => { err += d; });
    proc.on('exit', (code) => { clearTimeout(timer); reject(new Error(`breakshot serve exited ${code}: ${err}`)); });
  });
}

// --- helpers ------------------------------------------------------------
function check(cond, what) {
  if (!cond) throw new Error(what);
}

// A page with console errors, page errors and failed requests collected.
async function openPage(browser, url) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 900 } });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push('console: ' + m.text()); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));
  page.on('requestfailed', (r) => problems.push('request failed: ' + r.url()));
  // Anything not from our own server is a failure: the page loads nothing from elsewhere.
  await page.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith(new URL(url).origin) || u.startsWith('data:') || u.startsWith('blob:')) return route.continue();
    problems.push('request outside the server: ' + u);
    return route.abort();
  });
  await page.goto(url);
  await page.waitForFunction(() => window.breakshot && window.breakshot.engine, null, { timeout: 30000 });
  return { page, context, problems };
}

async function idle(page, timeout = 60000) {
  await page.waitForFunction(() => !window.breakshot.busy(), null, { timeout });
}

// Starts a new game through the form.
async function newGame(page, { game = 'eight_ball', opponent = 'friend', table = '9ft' } = {}) {
  await page.click('#new-game');
  await page.selectOption('#game-type', game);
  await page.selectOption('#opponent', opponent);
  await page.selectOption('#table-size', table);
  await page.click('#start');
  await page.waitForFunction(() => window.breakshot.state().actions === 0);
  await idle(page);
}

// [x, y, on_table] by ball number, from the state's position and on_table.
const balls = (page) => page.evaluate(() => {
  const s = window.breakshot.state();
  return s.position.map((p, n) => [p[0], p[1], s.on_table[n]]);
});
const ballsOf = (s) => JSON.stringify([s.position, s.on_table]);

// Table coordinates (m) to page pixels, from the canvas' drawing transform
// that the page exposes.
async function toPage(page, x, y) {
  return page.evaluate(([px, py]) => window.breakshot.toClient(px, py), [x, y]);
}

// --- the tests ----------------------------------------------------------
const tests = [];
const test = (name, fn) => tests.push({ name, fn });

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

// The speed of a stroke drawn back `pull` metres (game.js speedFromPull).
const speedOfPull = (pull) => Math.round((0.3 + 9.7 * Math.min(1, pull / 0.35)) * 20) / 20;

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
  const { page, context, problems } = await openPage(browser, url);
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
  const { page, context, problems } = await openPage(browser, url);
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
  const { page, context, problems } = await openPage(browser, url);
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

test('snooker: the D, a red potted, the score panel and the nomination of a colour', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  // Snooker in the form: its opponents are the engine's snooker players
  // and its table the 12 ft one.
  await page.click('#new-game');
  await page.selectOption('#game-type', 'snooker');
  const opponents = await page.$$eval('#opponent option', (os) => os.map((o) => o.value));
  check(JSON.stringify(opponents) === JSON.stringify(['beginner', 'amateur', 'club', 'expert', 'champion', 'baseline', 'friend']), 'snooker opponents: ' + opponents);
  check(JSON.stringify(await page.$$eval('#table-size option', (os) => os.map((o) => o.value))) === '["12ft"]',
    'snooker tables are not 12ft only');
  await page.fill('#seed', '1');
  await newGame(page, { game: 'snooker', opponent: 'friend', table: '12ft' });
  await page.selectOption('#playback-speed', '2');
  const t = await page.evaluate(() => window.breakshot.game.table());
  check(t.snooker && t.snooker.d_radius === 0.292 && t.snooker.baulk_line === 0.737, 'the table has no snooker markings');
  let st = await page.evaluate(() => window.breakshot.state());
  check(st.legal.place === 'd', 'the break-off is not from the D: ' + st.legal.place);
  check(await page.isVisible('#score') && !(await page.isVisible('#tray')), 'the score panel is not shown');
  check(await page.textContent('#score-remaining') === '147', 'remaining at the start: ' + await page.textContent('#score-remaining'));
  check(/a red/.test(await page.textContent('#score-on')), 'the ball on at the start: ' + await page.textContent('#score-on'));
  check(/in the D/.test(await page.textContent('#status-turn')), 'the status does not say in hand in the D');
  // The page's default placement is in the D (the engine accepts it).
  await page.locator('#table').screenshot({ path: path.join(shots, 'snooker-start.png') });
  const place = await page.evaluate(() => window.breakshot.ui.placePos);
  const ok = await page.evaluate((p) => window.breakshot.game.checkPlacement(p.x, p.y), place);
  check(ok.ok, 'the default placement is not in the D: ' + JSON.stringify(place));
  await page.evaluate((p) => window.breakshot.act({ type: 'place_cue_ball', position: [p.x, p.y] }), place);
  await idle(page);
  // Shots as the baseline would play them, through the page, until a red
  // falls and a colour is to be nominated.
  for (let k = 0; k < 8 && !st.legal.must_nominate; k++) {
    const hint = await page.evaluate(() => window.breakshot.game.aiAction('baseline'));
    const a = hint.action || hint;
    const r = await page.evaluate((x) => window.breakshot.act(x), a);
    check(!r.error, 'a shot was refused: ' + r.error);
    await idle(page);
    st = await page.evaluate(() => window.breakshot.state());
    if (st.phase === 'foul_choice') {
      await page.click('#choice-play_on');
      await idle(page);
      st = await page.evaluate(() => window.breakshot.state());
    }
  }
  check(st.legal.must_nominate, 'no red was potted in 8 shots');
  // The score panel shows the engine's figures.
  for (const seat of [0, 1]) {
    check(await page.textContent(`#score-${seat}`) === String(st.snooker.score[seat]), `score ${seat}: ` + await page.textContent(`#score-${seat}`));
  }
  check(st.snooker.break >= 1 && await page.textContent('#score-break') === String(st.snooker.break), 'the break: ' + await page.textContent('#score-break'));
  check(await page.textContent('#score-remaining') === String(st.snooker_figures.points_remaining), 'remaining: ' + await page.textContent('#score-remaining'));
  const needs = st.snooker_figures.snookers_required;
  check((await page.textContent('#score-snookers') === 'none') === (needs[0] === 0 && needs[1] === 0),
    'snookers required: ' + await page.textContent('#score-snookers') + ' for ' + needs);
  check(/colour/.test(await page.textContent('#score-on')), 'the ball on after a red: ' + await page.textContent('#score-on'));
  check(await page.isVisible('#nominate-box'), 'no nomination box after a red');
  // By the aim: aimed straight at a colour the line reaches first, the
  // nomination is that colour.
  const byAim = await page.evaluate(() => {
    const ui = window.breakshot.ui;
    const cue = ui.cuePos();
    for (const n of [21, 20, 19, 18, 17, 16]) {
      const p = ui.st.position[n];
      ui.setAimToward({ x: p[0], y: p[1] });
      const geo = ui.geometry();
      if (geo.hit && geo.hit.n === n) return { n, nom: ui.currentNomination(geo), shot: ui.shotAction().nominate };
    }
    return { cue };
  });
  check(byAim.n != null, 'no colour could be aimed at directly');
  check(byAim.nom.ball === byAim.n && byAim.nom.auto && byAim.shot === byAim.n,
    'the aim does not nominate the colour it hits: ' + JSON.stringify(byAim));
  await page.locator('#table').screenshot({ path: path.join(shots, 'snooker-nominate.png') });
  await page.screenshot({ path: path.join(shots, 'snooker-page.png') });
  // By a click: the click on another colour nominates it.
  const other = byAim.n === 21 ? 20 : 21;
  const p = await page.evaluate((n) => window.breakshot.state().position[n], other);
  const at = await toPage(page, p[0], p[1]);
  await page.mouse.click(at.x, at.y);
  check(await page.inputValue('#nominate') === String(other), 'the click did not nominate ball ' + other);
  check(await page.evaluate(() => window.breakshot.ui.shotAction().nominate) === other, 'the shot does not carry the clicked nomination');
  await page.fill('#power', '1.5');
  await page.dispatchEvent('#power', 'input');
  await page.click('#shoot');
  await page.waitForFunction((n) => window.breakshot.state().actions > n, st.actions, { timeout: 10000 });
  await idle(page);
  const log = await page.$$eval('#ruling-log li', (li) => li.map((x) => x.textContent));
  const rec = await page.evaluate(() => window.breakshot.game.record());
  const last = rec.actions[rec.actions.length - 1];
  check(last.action.nominate === other && last.ruling.snooker.nominated === other,
    'the shot played did not nominate ' + other + ': ' + JSON.stringify(last.action));
  check(log.length === rec.actions.length, 'the log has no entry for the shot');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// Three-cushion's panel against the state: points, innings, general
// average (3 decimals) and highest run of each player.
// An aim from the player's ball that meets no ball (the page's aim geometry).
const missPhi = (page) => page.evaluate(() => {
  const ui = window.breakshot.ui;
  const keep = ui.aim.phi;
  let phi = null;
  for (let p = 0; p < 360 && phi == null; p += 7.5) {
    ui.aim.phi = p;
    if (!ui.geometry().hit) phi = p;
  }
  ui.aim.phi = keep;
  return phi;
});

async function checkCaromPanel(page, what) {
  const st = await page.evaluate(() => window.breakshot.state());
  for (const seat of [0, 1]) {
    const got = await page.evaluate((s) => ['points', 'innings', 'average', 'high'].map((k) => document.getElementById(`carom-${k}-${s}`).textContent), seat);
    const want = [String(st.carom.score[seat]), String(st.carom.innings[seat]),
      st.carom_figures.general_average[seat].toFixed(3), String(st.carom_figures.highest_run[seat])];
    check(JSON.stringify(got) === JSON.stringify(want), `${what}: the panel shows ${got} for player ${seat + 1}, the engine ${want}`);
  }
  return st;
}

test('three-cushion: the carom table, a point counted cushion by cushion, the score, innings and average, a link', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  // Three-cushion in the form: its opponents are the players the engine
  // says play it (the strongest chosen), its table the 10 ft carom table.
  await page.click('#new-game');
  const before = await page.inputValue('#opponent');
  await page.selectOption('#game-type', 'three_cushion');
  const players = await page.evaluate(() => window.breakshot.engine.gamePlayers('three_cushion'));
  check(players.includes('baseline'), 'the engine has no baseline for three-cushion: ' + players);
  const opponents = await page.$$eval('#opponent option', (os) => os.map((o) => o.value));
  check(JSON.stringify(opponents) === JSON.stringify([...players, 'friend']), 'three-cushion opponents: ' + opponents);
  const levels = players.filter((p) => p !== 'baseline');
  // The opponent chosen before stays chosen when it plays three-cushion
  // too; otherwise the strongest is chosen.
  const strongest = levels.length ? levels[levels.length - 1] : 'baseline';
  const expected = players.includes(before) ? before : strongest;
  check(await page.inputValue('#opponent') === expected,
    `the opponent chosen is ${await page.inputValue('#opponent')}, not ${expected} (before: ${before})`);
  check(JSON.stringify(await page.$$eval('#table-size option', (os) => os.map((o) => o.value))) === '["10ft"]',
    'three-cushion tables are not 10ft only');
  check(await page.isVisible('#carom-target-points'), 'no target for three-cushion in the form');
  await page.selectOption('#carom-target-points', '10');
  await page.fill('#seed', '11');
  await newGame(page, { game: 'three_cushion', opponent: 'friend', table: '10ft' });
  await page.selectOption('#playback-speed', '0.5');

  // The carom table: no pockets, its spots and diamonds; carom balls.
  const t = await page.evaluate(() => window.breakshot.game.table());
  check(t.pockets.length === 0 && t.carom && t.carom.diamonds.length === 20, 'the table is not the carom table: ' + JSON.stringify(t.carom));
  check(t.ball_radius === 0.03075, 'the balls are not 61.5 mm: ' + t.ball_radius);
  let st = await checkCaromPanel(page, 'at the start');
  check(await page.isVisible('#carom-score') && !(await page.isVisible('#score')) && !(await page.isVisible('#tray')),
    'the three-cushion panel is not the one shown');
  check(await page.textContent('#carom-target') === '10 points, 50 innings', 'the target shows ' + await page.textContent('#carom-target'));
  check(/plays the white/.test(await page.textContent('#status-turn')), 'the status does not say the breaker plays the white: ' + await page.textContent('#status-turn'));
  check(await page.evaluate(() => window.breakshot.ui.cuePos().x === window.breakshot.state().position[0][0]), 'the aim is not from the white');

  // A scoring shot: the baseline's choice for this human seat (no noise),
  // played through the page's aim and Shoot button.
  const hint = await page.evaluate(() => window.breakshot.game.aiAction('baseline').action);
  await page.evaluate((s) => {
    const ui = window.breakshot.ui;
    ui.aim = { ...s };
    ui.syncControls();
    ui.requestRender();
  }, hint.strike);
  await page.click('#shoot');
  // While the balls run the cushions are counted as the events come.
  await page.waitForFunction(() => window.breakshot.busy() && /^[1-9]\d* cushion/.test(document.getElementById('carom-cushions').textContent), null, { timeout: 20000 });
  const live = await page.textContent('#carom-cushions');
  check(await page.textContent('#carom-call') !== 'Point' && await page.textContent('#carom-call') !== 'No point',
    'the ruling is shown before the balls stop');
  await page.screenshot({ path: path.join(shots, 'carom-running.png') });
  await idle(page);
  let rec = await page.evaluate(() => window.breakshot.game.record());
  let k = rec.actions[0].ruling.carom;
  check(k && k.cue_ball === 0, 'the shot did not strike the white: ' + JSON.stringify(k));
  const counted = await page.evaluate(() => window.breakshot.ui.lastCount);
  check(counted.cushions === k.cushions && JSON.stringify(counted.hit) === JSON.stringify(k.hit),
    `the page counted ${JSON.stringify(counted)} as the ball went, the engine ruled ${JSON.stringify(k)} (live: ${live})`);
  check(k.point, 'the baseline\'s shot did not score: ' + rec.actions[0].ruling.text);
  check((await page.textContent('#carom-cushions')).startsWith(`${k.cushions} cushion`), 'the count after the shot: ' + await page.textContent('#carom-cushions'));
  check(await page.textContent('#carom-call') === 'Point', 'the ruling in words: ' + await page.textContent('#carom-call'));
  st = await checkCaromPanel(page, 'after the point');
  check(st.carom.score[0] === 1 && st.carom_figures.highest_run[0] === 1 && st.player === 0, 'a point did not score 1 and keep the turn');
  check(await page.textContent('#carom-run') === '1', 'the run: ' + await page.textContent('#carom-run'));
  const log = await page.textContent('#ruling-log');
  check(/point/i.test(log), 'the log has no point: ' + log);

  // A shot that touches nothing ends the inning: the other player plays
  // the yellow, and the averages follow.
  const away = await missPhi(page);
  check(away != null, 'no aim misses every ball');
  const miss = await page.evaluate((phi) => window.breakshot.act({ type: 'shoot', strike: { speed: 0.4, phi, theta: 0, a: 0, b: 0 }, call: null, safety: false, push_out: false }), away);
  check(!miss.error, 'the miss was refused: ' + miss.error);
  await idle(page);
  st = await checkCaromPanel(page, 'after the miss');
  check(st.player === 1 && st.carom_figures.cue_ball === 1, 'the turn did not pass to the yellow');
  check(await page.textContent('#carom-call') === 'No point', 'the miss is ruled ' + await page.textContent('#carom-call'));
  check(/plays the yellow/.test(await page.textContent('#status-turn')), 'the status does not say the yellow: ' + await page.textContent('#status-turn'));
  await page.screenshot({ path: path.join(shots, 'carom-page.png') });
  await page.locator('#table').screenshot({ path: path.join(shots, 'carom-table.png') });

  // The link reproduces the game, the rules with it.
  const link = await page.evaluate(() => window.breakshot.link());
  const two = await openPage(browser, url + '#game=' + link);
  await idle(two.page);
  const got = await checkCaromPanel(two.page, 'opened from the link');
  check(ballsOf(got) === ballsOf(st) && JSON.stringify(got.carom) === JSON.stringify(st.carom), 'the linked game differs');
  check(await two.page.inputValue('#game-type') === 'three_cushion' && await two.page.inputValue('#carom-target-points') === '10',
    'the form does not show the linked game');
  // A phone-sized page.
  await two.page.setViewportSize({ width: 390, height: 844 });
  await two.page.waitForTimeout(300);
  await two.page.screenshot({ path: path.join(shots, 'carom-phone.png'), fullPage: true });
  const wide = await two.page.evaluate(() => document.documentElement.scrollWidth);
  check(wide <= 390, 'the phone page scrolls sideways: ' + wide + ' px');
  const all = problems.concat(two.problems);
  check(all.length === 0, all.join('\n'));
  await two.context.close();
  await context.close();
});

test('three-cushion against the computer: its shot is played and ruled', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await page.click('#new-game');
  await page.selectOption('#game-type', 'three_cushion');
  const opponent = await page.inputValue('#opponent');
  await page.fill('#seed', '12');
  await newGame(page, { game: 'three_cushion', opponent, table: '10ft' });
  // Player 1 misses on purpose; the computer plays the yellow.
  const miss = await page.evaluate((phi) => window.breakshot.act({ type: 'shoot', strike: { speed: 0.4, phi, theta: 0, a: 0, b: 0 }, call: null, safety: false, push_out: false }),
    await missPhi(page));
  check(!miss.error, 'the miss was refused: ' + miss.error);
  await page.waitForFunction(() => window.breakshot.state().actions >= 2, null, { timeout: 60000 });
  await idle(page);
  const rec = await page.evaluate(() => window.breakshot.game.record());
  const ai = rec.actions[1];
  check(ai.player === 1 && ai.ruling.carom && ai.ruling.carom.cue_ball === 1, 'the computer did not play the yellow: ' + JSON.stringify(ai.ruling));
  await checkCaromPanel(page, 'after the computer\'s shot');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// 10-ball, seed 10 on the 9 ft table: the expert's break (Player 1
// pockets the 2, 3, 9 and 10; the 10 is spotted and he shoots again), then
// a shot at the 1 called in the bottom-left corner pocket (0) that drops
// the 1 in another pocket: a ball pocketed wrongly (tests/test_web_api.cpp
// and the identity test play the same shots).
const TEN_BREAK = { type: 'shoot', strike: { speed: 11.0, phi: -0.25782926747071394, theta: 0, a: 0, b: -0.2 }, call: null, safety: false, push_out: false };
const TEN_WRONG_POT = { speed: 1.562406799667897, phi: 23.351333367801768, theta: 0, a: 0, b: 0.4 };

// A 10-ball game through the form, Player 1 human, and its break.
async function tenBallBreak(page, opponent) {
  await page.click('#new-game');
  await page.selectOption('#game-type', 'ten_ball');
  const opponents = await page.$$eval('#opponent option', (os) => os.map((o) => o.value));
  check(JSON.stringify(opponents) === JSON.stringify(['beginner', 'amateur', 'club', 'expert', 'champion', 'friend']), '10-ball opponents: ' + opponents);
  check(JSON.stringify(await page.$$eval('#table-size option', (os) => os.map((o) => o.value))) === '["7ft","8ft","9ft"]',
    '10-ball tables: not the pool tables');
  await page.fill('#seed', '10');
  await newGame(page, { game: 'ten_ball', opponent, table: '9ft' });
  let st = await page.evaluate(() => window.breakshot.state());
  check(st.game === 'ten_ball' && st.position.length === 11, 'not a 10-ball rack: ' + st.game + ', ' + st.position.length + ' balls');
  check(/^10-ball: Player 1( \(you\))? to break/.test(await page.textContent('#status-turn')), 'the status: ' + await page.textContent('#status-turn'));
  check(await page.isHidden('#call-box'), 'the break offers a call');
  await page.locator('#table').screenshot({ path: path.join(shots, 'ten-ball-rack.png') });
  const r = await page.evaluate((a) => window.breakshot.act(a), TEN_BREAK);
  check(!r.error && r.ruling.spotted.includes(10) && r.ruling.turn_continues, 'the break: ' + JSON.stringify(r.error || r.ruling));
  await idle(page);
  st = await page.evaluate(() => window.breakshot.state());
  check(st.player === 0 && st.legal.call && st.legal.push_out, 'after the break: ' + JSON.stringify(st.legal));
  return st;
}

// The human's called shot at the 1, the call chosen in the panel.
async function tenBallCalledShot(page) {
  await page.selectOption('#call-ball', '1');
  await page.selectOption('#call-pocket', '0');
  await page.evaluate((s) => { Object.assign(window.breakshot.ui.aim, s); window.breakshot.ui.syncControls(); }, TEN_WRONG_POT);
  const shot = await page.evaluate(() => window.breakshot.ui.shotAction());
  check(shot.call && shot.call.ball === 1 && shot.call.pocket === 0 && !shot.safety && !shot.push_out, 'the shot carries ' + JSON.stringify(shot));
  await page.click('#shoot');
  await page.waitForFunction(() => window.breakshot.state().actions >= 2, null, { timeout: 10000 });
  await idle(page);
}

test('10-ball: the rack and the tray, a shot without a call refused, a called shot, the choice after a wrong pot', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await tenBallBreak(page, 'friend');
  check(await page.isVisible('#tray') && await page.isHidden('#score'), 'the tray is not shown');
  check(await page.isVisible('#call-box') && await page.isVisible('#push-out-box'), 'no call or push-out box after the break');
  check(/ball on: 1/.test(await page.textContent('#status-info')) && /the 10 wins when called/.test(await page.textContent('#status-info')),
    'the status: ' + await page.textContent('#status-info'));
  // The call-ball select names every object ball on the table (any may be called).
  const callable = await page.$$eval('#call-ball option', (os) => os.map((o) => o.value));
  check(JSON.stringify(callable) === JSON.stringify(['', '1', '4', '5', '6', '7', '8', '10']), 'callable balls: ' + callable);
  // Aimed where no ball is hit first, the call is none: the rules refuse
  // the shot, and the page says why and how to call.
  const before = await page.evaluate(() => window.breakshot.state());
  const none = await page.evaluate(() => {
    const ui = window.breakshot.ui;
    for (let p = 0; p < 360; p += 5) {
      ui.aim.phi = p;
      const g = ui.geometry();
      if (!g.hit) return { phi: p, call: ui.shotAction().call };
    }
    return null;
  });
  check(none && none.call === null, 'no aim without a call: ' + JSON.stringify(none));
  await page.click('#shoot');
  const error = await page.textContent('#status-error');
  check(await page.isVisible('#status-error') && /every shot but the break calls a ball and a pocket, or is a safety/.test(error) && /Call a ball and a pocket/.test(error),
    'the refusal shown: ' + error);
  check(ballsOf(await page.evaluate(() => window.breakshot.state())) === ballsOf(before), 'the refused shot moved the balls');
  check((await page.evaluate(() => window.breakshot.state())).actions === before.actions, 'the refused shot was played');
  // Aimed at the 1, the aim calls it; a safety calls nothing.
  const aimed = await page.evaluate(() => {
    const ui = window.breakshot.ui;
    const p = ui.st.position[1];
    ui.setAimToward({ x: p[0], y: p[1] });
    const auto = ui.shotAction();
    document.getElementById('safety').checked = true;
    const safe = ui.shotAction();
    document.getElementById('safety').checked = false;
    return { auto, safe };
  });
  check(aimed.auto.call && aimed.auto.call.ball === 1 && !aimed.auto.safety, 'the aim at the 1 calls ' + JSON.stringify(aimed.auto.call));
  check(aimed.safe.call === null && aimed.safe.safety, 'a safety carries ' + JSON.stringify(aimed.safe));
  // The called shot, the 1 into another pocket: Player 2 chooses, in the
  // words of a wrong pot, not of a push-out.
  await tenBallCalledShot(page);
  const st = await page.evaluate(() => window.breakshot.state());
  check(st.phase === 'push_out_choice' && !st.after_push_out && st.player === 1, 'after the wrong pot: ' + st.phase + ', player ' + st.player);
  check(await page.isHidden('#status-error'), 'an error is still shown: ' + await page.textContent('#status-error'));
  const choices = await page.textContent('#choices');
  check(/a ball was pocketed wrongly/.test(choices) && !/push-out/.test(choices), 'the choice says: ' + choices);
  check(await page.textContent('#choice-shoot') === 'Shoot from here', 'the shoot button: ' + await page.textContent('#choice-shoot'));
  check(/^Hand the shot back/.test(await page.textContent('#choice-pass_back')), 'the pass-back button: ' + await page.textContent('#choice-pass_back'));
  check(/Player 2 to decide \(a ball was pocketed wrongly/.test(await page.textContent('#status-turn')), 'the status: ' + await page.textContent('#status-turn'));
  const log = await page.$$eval('#ruling-log li', (li) => li.map((x) => x.textContent));
  check(/Not the call: Player 2 shoots from here or hands the shot back/.test(log[log.length - 1]), 'the log: ' + log[log.length - 1]);
  await page.screenshot({ path: path.join(shots, 'ten-ball-choice.png') });
  await page.click('#choice-pass_back');
  await idle(page);
  const back = await page.evaluate(() => window.breakshot.state());
  check(back.phase === 'shot' && back.player === 0 && back.legal.call, 'after the pass back: ' + back.phase + ', player ' + back.player);
  const last = await page.$$eval('#ruling-log li', (li) => li[li.length - 1].textContent);
  check(/Player 2 hands the shot back to Player 1/.test(last), 'the log: ' + last);
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('10-ball against the computer: a called shot, the computer chooses after the wrong pot and plays', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await tenBallBreak(page, 'club');
  // Every text the status takes, from here on.
  await page.evaluate(() => {
    window.__turns = [];
    new MutationObserver(() => window.__turns.push(document.getElementById('status-turn').textContent))
      .observe(document.getElementById('status-turn'), { childList: true, characterData: true, subtree: true });
  });
  await tenBallCalledShot(page);
  // The computer chooses, then shoots (its shots called or declared safe)
  // until the turn comes back or the game ends.
  await page.waitForFunction(() => { const s = window.breakshot.state(); return s.actions >= 3 && (s.player === 0 || s.phase === 'game_over'); },
    null, { timeout: 120000 });
  await idle(page);
  const turns = await page.evaluate(() => window.__turns);
  check(turns.some((t) => /^10-ball: Player 2 \(club AI\) is choosing \(a ball was pocketed wrongly: shoot from here or hand the shot back\)/.test(t)),
    'the status never said the computer chooses after a wrong pot: ' + JSON.stringify([...new Set(turns)]));
  const rec = await page.evaluate(() => window.breakshot.game.record());
  const choice = rec.actions[2];
  check(choice.player === 1 && choice.action.type === 'decide' && /Player 2 (takes the table|hands the shot back to Player 1)\./.test(choice.ruling.text),
    'the computer\'s choice: ' + JSON.stringify(choice));
  const computerShots = rec.actions.filter((a, i) => i > 2 && a.player === 1 && a.action.type === 'shoot');
  check(computerShots.length >= 1 || choice.action.choice === 'pass_back', 'the computer did not shoot');
  for (const a of computerShots) check(a.action.call || a.action.safety, 'a computer shot neither called nor safe: ' + JSON.stringify(a.action));
  const log = await page.$$eval('#ruling-log li', (li) => li.map((x) => x.textContent));
  check(log.length === rec.actions.length, `the log has ${log.length} entries for ${rec.actions.length} actions`);
  check(/takes the table|hands the shot back/.test(log[2]), 'the log of the choice: ' + log[2]);
  check(!/refused|error/i.test(log.join('\n')), 'the log shows an error');
  // The tray: the balls 1 to 10, the ball on and the money ball marked.
  await page.locator('#tray').screenshot({ path: path.join(shots, 'ten-ball-tray.png') });
  await page.screenshot({ path: path.join(shots, 'ten-ball-page.png') });
  // The link opens the same game.
  await page.click('#share');
  const hash = await page.evaluate(() => location.hash);
  const two = await openPage(browser, url + hash);
  await idle(two.page);
  const want = await page.evaluate(() => window.breakshot.state());
  const got = await two.page.evaluate(() => window.breakshot.state());
  check(got.game === 'ten_ball' && ballsOf(got) === ballsOf(want) && got.actions === want.actions && got.player === want.player,
    'the link gives another game');
  check(await two.page.inputValue('#game-type') === 'ten_ball', 'the form does not show 10-ball after the link');
  const all = problems.concat(two.problems);
  check(all.length === 0, all.join('\n'));
  await two.context.close();
  await context.close();
});

test('the lab runs the two-ball example and draws its energy graph', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await page.click('#tab-lab');
  await page.waitForSelector('#lab-examples [data-example="two_balls"]', { timeout: 20000 });
  await page.click('#lab-examples [data-example="two_balls"]');
  await page.click('#lab-run');
  await page.waitForFunction(() => window.breakshotLab.frames() > 60 && window.breakshotLab.time() > 1,
    null, { timeout: 30000 });
  const err = await page.textContent('#lab-error');
  check(!err || err.trim() === '', 'lab error: ' + err);
  // The energy graph has drawn something: count coloured pixels.
  const inked = await page.evaluate(() => {
    const c = document.querySelector('#lab-energy');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    for (let i = 0; i < d.length; i += 4) {
      if (d[i + 3] > 0) colours.add((d[i] >> 4) * 256 + (d[i + 1] >> 4) * 16 + (d[i + 2] >> 4));
    }
    return colours.size;
  });
  check(inked >= 4, `the energy graph has ${inked} colours: nothing drawn`);
  await page.screenshot({ path: path.join(shots, 'lab-two-balls.png') });
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('the lab\'s cluster impacts box sets physics.ball_clusters and the run accepts it', async ({ browser, url }) => {
  const { page, context, problems } = await openPage(browser, url);
  await page.click('#tab-lab');
  await page.waitForSelector('#lab-examples [data-example="newtons_cradle"]', { timeout: 20000 });
  await page.click('#lab-examples [data-example="newtons_cradle"]');
  const field = () => page.evaluate(() => window.breakshotLab.scenario().physics.ball_clusters);
  check(await field() === undefined, 'the cradle example sets ball_clusters already');
  check(!(await page.isChecked('#lab-clusters')), 'the box is ticked for a scenario without the field');
  await page.click('#lab-clusters');
  check(await field() === true, 'ticking the box did not set physics.ball_clusters');
  await page.click('#lab-run');
  await page.waitForFunction(() => window.breakshotLab.frames() > 30 && window.breakshotLab.time() > 0.5,
    null, { timeout: 30000 });
  const err = await page.textContent('#lab-error');
  check(!err || err.trim() === '', 'lab error with cluster impacts: ' + err);
  await page.screenshot({ path: path.join(shots, 'lab-clusters.png') });
  await page.click('#lab-clusters');
  check(await field() === undefined, 'unticking the box did not leave the field out');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('the lab\'s blank physics fields show the engine\'s defaults for each model', async ({ browser, url }) => {
  const { page, context, problems } = await openLab(browser, url, 'two_balls');
  const placeholder = (f) => page.getAttribute(`[aria-label="physics.${f}"]`, 'placeholder');
  // The page asks the engine (bs_version's "defaults", default_physics in
  // C++) and keeps no copy: the blank fields must show exactly those.
  const defaults = await page.evaluate(async () => (await (await import('./engine.js')).loadEngine()).defaults);
  check(defaults && defaults.physics && defaults.physics.pool, 'the engine gave no defaults');
  for (const model of ['ideal', 'pool']) {
    await page.selectOption('#lab-model', model);
    const d = defaults.physics[model];
    const shown = Number(await placeholder('ball_ball_restitution'));
    check(shown === d.ball_ball_restitution,
      `${model}: ball_ball_restitution shows ${shown}, the engine's default is ${d.ball_ball_restitution}`);
  }
  check(defaults.physics.pool.ball_ball_restitution === 0.95, 'the pool default is not 0.95');
  check(await placeholder('ball_ball_friction') === 'mu(v) fit', 'the pool friction default is not the fit');
  check(Number(await placeholder('spinning_friction')) === defaults.physics.pool.spinning_friction,
    'spinning_friction does not show the engine\'s default');
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

// The lab's numbers: "1.23456 mJ" -> 0.00123456, "(1.5, -2)" -> [1.5, -2].
const SI = { k: 1e3, '': 1, m: 1e-3, 'µ': 1e-6, n: 1e-9, p: 1e-12 };
function parseSI(text, unit) {
  const m = String(text).match(new RegExp(`^(\\S+) (k|m|µ|n|p)?${unit}$`));
  return m ? Number(m[1]) * SI[m[2] ?? ''] : NaN;
}
function near(a, b, rel = 1e-5) {
  return Number.isFinite(a) && Math.abs(a - b) <= rel * Math.max(Math.abs(a), Math.abs(b)) + 1e-15;
}

// The numbers under the lab's table, compared with the engine's frame.
async function checkLabNumbers(page, want, t, when) {
  const got = await page.evaluate(() => ['#lab-time', '#lab-events', '#lab-energy-total', '#lab-momentum']
    .map((s) => document.querySelector(s).textContent));
  check(near(parseSI(got[0], 's'), t) || (t === 0 && got[0] === '0 s'), `${when}: #lab-time is ${got[0]}, not ${t} s`);
  check(got[1] === String(want.events), `${when}: #lab-events is ${got[1]}, the engine says ${want.events}`);
  check(near(parseSI(got[2], 'J'), want.energy), `${when}: #lab-energy-total is ${got[2]}, the engine says ${want.energy} J`);
  const p = got[3].match(/^\((\S+), (\S+)\)$/);
  check(p && near(Number(p[1]), want.momentum[0]) && near(Number(p[2]), want.momentum[1]),
    `${when}: #lab-momentum is ${got[3]}, the engine says (${want.momentum})`);
}

// The engine's frame at time t of the lab's scenario.
function engineFrame(page, t) {
  return page.evaluate((tt) => {
    const pb = window.breakshot.engine.playback(window.breakshotLab.scenario());
    try { return pb.frame(tt); } finally { pb.free(); }
  }, t);
}

// Pixels of an exact colour on a canvas, in a column range: their count and
// the span of their x.
function pixelsOf(page, selector, rgb, fromX = 0, fromY = 0) {
  return page.evaluate(([sel, c, x0, y0]) => {
    const cv = document.querySelector(sel);
    const d = cv.getContext('2d').getImageData(0, 0, cv.width, cv.height).data;
    let n = 0, lo = Infinity, hi = -Infinity, sx = 0, sy = 0;
    for (let y = y0; y < cv.height; y++) {
      for (let x = x0; x < cv.width; x++) {
        const k = 4 * (y * cv.width + x);
        if (d[k] === c[0] && d[k + 1] === c[1] && d[k + 2] === c[2]) {
          n++; sx += x; sy += y; lo = Math.min(lo, x); hi = Math.max(hi, x);
        }
      }
    }
    const r = cv.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    return { n, span: n ? hi - lo : 0, width: cv.width,
      client: n ? { x: r.left + sx / n / dpr, y: r.top + sy / n / dpr } : null };
  }, [selector, rgb, fromX, fromY]);
}

const GOLD = [0xe0, 0xb2, 0x4a];      // the lab's colour of the system's total energy and momentum
const WHITE_BALL = [0xf4, 0xf4, 0xef];
const BLACK_BALL = [0x1c, 0x1c, 0x1c];

async function openLab(browser, url, example) {
  const opened = await openPage(browser, url);
  await opened.page.click('#tab-lab');
  await opened.page.waitForSelector(`#lab-examples [data-example="${example}"]`, { timeout: 20000 });
  await opened.page.click(`#lab-examples [data-example="${example}"]`);
  return opened;
}

test('the lab\'s numbers, ball table and energy graph follow the engine', async ({ browser, url }) => {
  const { page, context, problems } = await openLab(browser, url, 'two_balls');
  const rows = () => page.$$eval('#lab-balls tbody tr', (trs) => trs.map((tr) => [...tr.querySelectorAll('input')].map((i) => i.value)));
  const setup = await rows();
  check(JSON.stringify(setup) === JSON.stringify([
    ['white', '-0.05', '0', '0.3', '0.05', '0.012', '0.02', '0.9'],
    ['black', '0.05', '0.01', '0', '0', '0.02', '0.05', '0.8']]), 'the ball table shows ' + JSON.stringify(setup));
  await checkLabNumbers(page, await engineFrame(page, 0), 0, 'setup');
  // The setup's energy graph: dots at t = 0 only; the strip shows the system momentum.
  const dots = await pixelsOf(page, '#lab-energy', GOLD, 0, 24);
  check(dots.n > 0 && dots.span < dots.width / 10, `the setup's total energy dot: ${JSON.stringify(dots)}`);
  const strip = await pixelsOf(page, '#lab-canvas', GOLD, (await page.$eval('#lab-canvas', (c) => c.width)) - 150);
  check(strip.n >= 10, `no system momentum arrow in the setup (${strip.n} gold pixels)`);

  // Ten times faster, to the end (until 5 s).
  await page.evaluate(() => { const s = document.querySelector('#lab-speed'); s.value = '1'; s.dispatchEvent(new Event('input')); });
  await page.click('#lab-run');
  await page.waitForFunction(() => document.querySelector('.bs-lab-state').dataset.state === 'finished', null, { timeout: 30000 });
  check(await page.evaluate(() => window.breakshotLab.time()) === 5, 'the run did not end at 5 s');
  const end = await engineFrame(page, 5);
  check(end.events > 0, 'the two balls had no event');
  await checkLabNumbers(page, end, 5, 'after the run');
  // The total energy's line runs across the plot.
  const line = await pixelsOf(page, '#lab-energy', GOLD, 0, 24);
  check(line.n > 300 && line.span > 0.7 * line.width, `the total energy line: ${JSON.stringify(line)}`);
  check((await page.textContent('#lab-pause')) === 'Pause' && await page.isDisabled('#lab-pause'), 'Pause is not off after the run');
  check((await page.textContent('#lab-run')) === 'Run again', 'Run does not say Run again');

  // An edit in the ball table goes back to the setup and into the scenario.
  const x = page.locator('#lab-balls [aria-label="balls[1].position x"]');
  await x.fill('0.04');
  await x.dispatchEvent('change');
  check(await page.evaluate(() => window.breakshotLab.scenario().balls[1].position[0]) === 0.04, 'the x edit is not in the scenario');
  check(await page.evaluate(() => document.querySelector('.bs-lab-state').dataset.state) === 'setup', 'an edit did not end the run');
  const count = page.locator('#lab-count');
  await count.fill('4');
  await count.dispatchEvent('change');
  check((await rows()).length === 4, 'the ball table does not have 4 rows after count 4');
  const sc = await page.evaluate(() => JSON.stringify(window.breakshotLab.scenario()));
  check(sc === '{"physics":{"model":"ideal","ball_ball_restitution":1},' +
    '"table":{"shape":"rectangle","min":[-0.1,-0.1],"max":[0.1,0.1]},"balls":[' +
    '{"id":"white","position":[-0.05,0],"velocity":[0.3,0.05],"radius":0.012,"mass":0.02,"wall_restitution":0.9},' +
    '{"id":"black","position":[0.04,0.01],"velocity":[0,0],"radius":0.02,"mass":0.05,"wall_restitution":0.8},' +
    '{"id":"b3","position":[0.012,-0.032],"velocity":[0,0],"radius":0.02,"mass":0.05},' +
    '{"id":"b4","position":[-0.032,-0.032],"velocity":[0,0],"radius":0.02,"mass":0.05}],' +
    '"pair_restitution":[{"balls":["white","black"],"restitution":0.95}],"until":{"time":5},"samples":{"dt":0.5}}',
  'the scenario after the edits is ' + sc);
  await page.waitForTimeout(400);   // the engine checks the setup 120 ms after an edit
  check(await page.evaluate(() => window.breakshotLab.error()) === '', 'lab error: ' + await page.textContent('#lab-error'));
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

test('dragging on the lab\'s table moves a ball, sets its velocity and a double-click adds one', async ({ browser, url }) => {
  const { page, context, problems } = await openLab(browser, url, 'two_balls');
  const white = await pixelsOf(page, '#lab-canvas', WHITE_BALL);
  const black = await pixelsOf(page, '#lab-canvas', BLACK_BALL);
  check(white.n > 50 && black.n > 50, `the balls are not drawn (${white.n}, ${black.n} pixels)`);
  // The drawing's scale (px per m), from the two balls 0.1 m apart in x.
  const s = (black.client.x - white.client.x) / 0.1;
  check(s > 100 && Math.abs(white.client.y - black.client.y - 0.01 * s) < 3, `the balls are not where the setup puts them (${s} px/m)`);
  const ball = () => page.evaluate(() => window.breakshotLab.scenario().balls[0]);
  const input = (label) => page.inputValue(`#lab-balls [aria-label="${label}"]`);

  await page.mouse.move(white.client.x, white.client.y);
  await page.mouse.down();
  await page.mouse.move(white.client.x + 0.02 * s, white.client.y, { steps: 5 });
  await page.mouse.up();
  let b = await ball();
  check(Math.abs(b.position[0] - -0.03) < 0.002 && Math.abs(b.position[1]) < 0.002, 'the dragged ball is at ' + b.position);
  check(await input('balls[0].position x') === String(b.position[0]), 'the ball table does not show the dragged x');

  const at = { x: white.client.x + 0.02 * s, y: white.client.y };
  await page.keyboard.down('Shift');
  await page.mouse.move(at.x, at.y);
  await page.mouse.down();
  await page.mouse.move(at.x - 0.01 * s, at.y - 0.005 * s, { steps: 5 });   // the tip 0.25 s ahead
  await page.mouse.up();
  await page.keyboard.up('Shift');
  b = await ball();
  check(Math.abs(b.velocity[0] - -0.04) < 0.005 && Math.abs(b.velocity[1] - 0.02) < 0.005, 'the shift-drag set the velocity ' + b.velocity);
  check(await input('balls[0].velocity y') === String(b.velocity[1]), 'the ball table does not show the dragged vy');

  await page.mouse.dblclick(white.client.x + 0.05 * s, white.client.y - 0.07 * s);   // (0, 0.07): empty felt
  const sc = await page.evaluate(() => window.breakshotLab.scenario());
  check(sc.balls.length === 3 && sc.balls[2].id === 'b3', 'no ball b3 after the double-click');
  check(Math.abs(sc.balls[2].position[0]) < 0.003 && Math.abs(sc.balls[2].position[1] - 0.07) < 0.003,
    'the new ball is at ' + sc.balls[2].position);
  check((await page.$$('#lab-balls tbody tr')).length === 3, 'the ball table does not have the new ball');
  await page.screenshot({ path: path.join(shots, 'lab-edited.png') });
  check(problems.length === 0, problems.join('\n'));
  await context.close();
});

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

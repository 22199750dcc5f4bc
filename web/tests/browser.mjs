// Browser tests of the breakshot page (issue 6): playwright-core drives
// Debian's Chromium (/usr/bin/chromium, headless) against the page served
// by `breakshot serve`. Nothing is downloaded.
//
//   node web/tests/browser.mjs --cli build/release/breakshot --root build/web/dist \
//        [--shots DIR] [--only NAME]
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

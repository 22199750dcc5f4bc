// What the browser tests share (browser.mjs runs them): the arguments,
// the server, the checks and the helpers that open a page and start a
// game, and the list the tests register in.
import { spawn } from 'node:child_process';
import { mkdirSync } from 'node:fs';

export const args = Object.fromEntries(
  process.argv.slice(2).reduce((acc, a, i, all) => {
    if (a.startsWith('--')) acc.push([a.slice(2), all[i + 1]]);
    return acc;
  }, []));
const cli = args.cli ?? 'build/release/breakshot';
const root = args.root ?? 'build/web/dist';
export const shots = args.shots ?? 'build/web/screenshots';
mkdirSync(shots, { recursive: true });

// --- the server ---------------------------------------------------------
export function startServer() {
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
export function check(cond, what) {
  if (!cond) throw new Error(what);
}

// A page with console errors, page errors and failed requests collected.
export async function openPage(browser, url, { speed = '4' } = {}) {
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
  // Shots play back at the page's fastest speed unless a test picks
  // another: the tests wait for outcomes, not for the seconds a ball rolls.
  await page.evaluate((v) => { document.getElementById('playback-speed').value = v; }, speed);
  return { page, context, problems };
}

export async function idle(page, timeout = 60000) {
  await page.waitForFunction(() => !window.breakshot.busy(), null, { timeout });
}

// Starts a new game through the form.
export async function newGame(page, { game = 'eight_ball', opponent = 'friend', table = '9ft' } = {}) {
  await page.click('#new-game');
  await page.selectOption('#game-type', game);
  await page.selectOption('#opponent', opponent);
  await page.selectOption('#table-size', table);
  await page.click('#start');
  await page.waitForFunction(() => window.breakshot.state().actions === 0);
  await idle(page);
}

// [x, y, on_table] by ball number, from the state's position and on_table.
export const balls = (page) => page.evaluate(() => {
  const s = window.breakshot.state();
  return s.position.map((p, n) => [p[0], p[1], s.on_table[n]]);
});
export const ballsOf = (s) => JSON.stringify([s.position, s.on_table]);

// Table coordinates (m) to page pixels, from the canvas' drawing transform
// that the page exposes.
export async function toPage(page, x, y) {
  return page.evaluate(([px, py]) => window.breakshot.toClient(px, py), [x, y]);
}

// The tests, in the order they run: each module's register() adds its own.
export const tests = [];
export const test = (name, fn) => tests.push({ name, fn });

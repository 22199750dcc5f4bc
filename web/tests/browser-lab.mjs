// The browser tests of the lab tab (browser.mjs runs them after the
// game tab's).
import path from 'node:path';

import { balls, check, openPage, shots, test } from './browser-lib.mjs';

export function register() {
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
    // The page asks the engine (bs_web_version's "defaults", default_physics in
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
}

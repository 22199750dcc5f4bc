// The browser tests of snooker, three-cushion and 10-ball (browser.mjs
// runs them after the pool tests).
import path from 'node:path';

import { balls, ballsOf, check, idle, newGame, openPage, shots, test, toPage } from './browser-lib.mjs';

export function register() {
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
}

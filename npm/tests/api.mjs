// The package's API checked in node (run.mjs registers these after the
// install; ctx.api is the installed package's index.js): states and
// frames against the result file, time going back, determinism, games,
// players, and an Error naming what is wrong for bad input, also for
// inputs mutated at random.
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';

const BREAK = {
  physics: { model: 'pool', ball_clusters: true },
  table: { shape: 'pool', size: '9ft' },
  rack: { game: 'eight_ball', seed: 1 },
  cue: { ball: 'cue', speed: 7.5, phi: 0.0, theta: 0.0, a: 0.0, b: 0.0 },
};

// f() must throw an Error whose message matches `re`.
function throws(check, f, re, what) {
  let err = null;
  try {
    f();
  } catch (e) {
    err = e;
  }
  check(err !== null, `${what}: no error`);
  check(err instanceof Error, `${what}: threw ${typeof err}, not an Error`);
  check(re.test(err.message), `${what}: the message "${err.message}" does not match ${re}`);
  return err.message;
}

async function rejects(check, p, re, what) {
  let err = null;
  try {
    await p;
  } catch (e) {
    err = e;
  }
  check(err instanceof Error, `${what}: ${err === null ? 'no error' : 'not an Error'}`);
  check(re.test(err.message), `${what}: the message "${err.message}" does not match ${re}`);
  return err.message;
}

const same = (a, b) => a.length === b.length && a.every((v, i) => Object.is(v, b[i]));

export function register(test, ctx) {
  const { check } = ctx;

  test('simulate: the same scenario twice, the same bytes; text and object alike', () => {
    const { simulate } = ctx.api;
    const a = simulate(BREAK);
    const b = simulate(JSON.stringify(BREAK));
    check(a.text === b.text, 'two runs of the break differ');
    if (ctx.breakText) check(a.text === ctx.breakText, 'in-process and the example differ');
    check(a.complete === true && a.events.length === a.result.events.length && a.events[0].type === 'cue_strike', 'events');
    check(a.ids.length === 16 && a.ids.includes('cue'), `ids ${a.ids}`);
    a.free();
    b.free();
  });

  test('states at the end are the result file\'s final states; frame() and states() agree', () => {
    const sim = ctx.api.simulate(BREAK);
    const s = sim.states(sim.duration);
    const final = sim.result.final.balls;
    check(s.count === final.length, 'ball count');
    final.forEach((b, i) => {
      check(b.id === sim.ids[i], 'ids order');
      check(Object.is(s.position[2 * i], b.position[0]) && Object.is(s.position[2 * i + 1], b.position[1]),
        `ball ${b.id}: states ${s.position[2 * i]}, ${s.position[2 * i + 1]} but the result ${b.position}`);
      check(s.onTable[i] === (['pocketed', 'off_table'].includes(b.state) ? 0 : 1), `ball ${b.id} on the table: ${s.onTable[i]} / ${b.state}`);
      check(same(Array.from(s.spin.subarray(3 * i, 3 * i + 3)), b.spin), `ball ${b.id}: spin ${Array.from(s.spin.subarray(3 * i, 3 * i + 3))} / ${b.spin}`);
      check(ctx.api.motions[s.motion[i]] === b.state, `ball ${b.id}: motion ${s.motion[i]} (${ctx.api.motions[s.motion[i]]}) / ${b.state}`);
    });
    check(s.atRest && s.events === sim.events.length, `at rest ${s.atRest}, events ${s.events} of ${sim.events.length}`);
    const f = sim.frame(sim.duration);
    check(f.balls.length === 16 && f.balls.every((b, i) => b[0] === s.position[2 * i] && b[1] === s.position[2 * i + 1]), 'frame and states');
    check(sim.playedEvents().length === sim.events.length, 'played events');
    check(s.position instanceof Float64Array && s.velocity.length === 32 && s.spin.length === 48 && s.onTable instanceof Uint8Array, 'typed arrays');
    sim.free();
  });

  test('states carry each ball\'s motion state: the cue ball slides, then rolls; the rack stands', () => {
    const sim = ctx.api.simulate(BREAK);
    const names = (t) => Array.from(sim.states(t).motion, (m) => ctx.api.motions[m]);
    const start = names(0);
    check(start[0] === 'sliding' && start.slice(1).every((m) => m === 'stationary'), `at 0: ${start}`);
    check(sim.states(0).motion instanceof Uint8Array, 'a Uint8Array');
    const seen = new Set();
    for (let k = 0; k * 0.01 <= sim.duration; k++) for (const m of names(k * 0.01)) seen.add(m);
    check(['sliding', 'rolling', 'stationary'].every((m) => seen.has(m)), `states seen: ${[...seen]}`);
    const end = names(sim.duration);
    check(end.every((m) => m === 'stationary' || m === 'pocketed'), `at the end: ${end}`);
    check(Object.isFrozen(ctx.api.motions) && ctx.api.motions.length === 8, 'motions');
    sim.free();
  });

  test('states at any time: going back plays the shot again, the same numbers', () => {
    const sim = ctx.api.simulate(BREAK);
    const at = (t) => Array.from(sim.states(t).position);
    const direct = at(0.8);
    at(1.9);
    const back = at(0.8);
    check(same(direct, back), 'states(0.8) after states(1.9) differ from the first states(0.8)');
    const into = sim.states(0.1);
    const again = sim.states(0.2, into);
    check(again === into && into.t === 0.2, 'states(t, into) fills into');
    sim.free();
    // frames of 1/60 s up to 0.8, and 0.8 at once, on two simulations
    const stepped = ctx.api.simulate(BREAK);
    for (let k = 1; k * (1 / 60) < 0.8; k++) stepped.states(k / 60);
    const s = Array.from(stepped.states(0.8).position);
    stepped.free();
    check(same(s, direct), 'the state at 0.8 s after 60 fps frames differs from the state reached at once');
  });

  test('bad scenarios throw an Error naming what is wrong, and the engine goes on', () => {
    const { simulate } = ctx.api;
    const msgs = [
      throws(check, () => simulate('{"balls": ['), /line|column|JSON|parse/i, 'text that is not JSON'),
      throws(check, () => simulate({ ...BREAK, cue: { ...BREAK.cue, speed: -1 } }), /cue\.speed/, 'a negative speed'),
      throws(check, () => simulate({ ...BREAK, table: { shape: 'pool', size: '99ft' } }), /table\.size/, 'an unknown table size'),
      throws(check, () => simulate({ ...BREAK, physics: { model: 'pool', gravity: 'down' } }), /physics\.gravity/, 'a string for a number'),
      throws(check, () => simulate(42), /scenario|object/i, 'a number'),
      throws(check, () => simulate(undefined), /JSON/, 'undefined'),
      throws(check, () => simulate('{"rack": "\uD800"}'), /.+/, 'a lone surrogate (bytes that are not UTF-8)'),
    ];
    console.log(msgs.map((m) => `    ${m}`).join('\n'));
    const sim = simulate(BREAK);
    throws(check, () => sim.states(Number.NaN), /^t: /, 'states(NaN)');
    throws(check, () => sim.states('1'), /^t: /, 'states of a string');
    throws(check, () => sim.states(-1), /^t: must be at least 0/, 'a negative time');
    sim.free();
    sim.free();
    throws(check, () => sim.states(1), /freed/, 'a freed simulation');
    check(simulate(BREAK).events.length > 50, 'the engine fails after bad input');
  });

  test('Game: every game starts; act, undo, link, record; bad configs and actions throw', () => {
    const { Game, games } = ctx.api;
    check(games.length === 5, 'five games');
    for (const game of games) {
      const g = new Game({ game, players: ['human', 'human'], seed: 3 });
      const st = g.state();
      check(st.game === game && st.actions === 0 && typeof st.legal === 'object', `${game}: state`);
      check(g.table().length > 1, `${game}: table`);
      g.free();
    }
    const g = new Game({ game: 'nine_ball', players: ['human', 'club'], seed: 7 });
    const action = g.aiAction('club');
    const reply = g.act(action);
    check(reply.index === 0 && typeof reply.ruling.text === 'string' && g.actions === 1, 'act');
    const link = g.link();
    const h = ctx.api.Game.fromLink(link);
    check(JSON.stringify(h.state()) === JSON.stringify(g.state()), 'the game from its link');
    h.free();
    check(JSON.parse(g.recordText()).actions.length === 1, 'record');
    check(g.undo().actions === 0 && g.actions === 0, 'undo');
    const m = [
      throws(check, () => new Game({ game: 'pool', players: ['human', 'human'] }), /^game: /, 'an unknown game'),
      throws(check, () => new Game({ game: 'nine_ball', players: ['human', 'grandmaster'] }), /players\[1\]/, 'an unknown level'),
      throws(check, () => new Game({ game: 'nine_ball', players: ['human'] }), /players/, 'one seat'),
      throws(check, () => g.act({ type: 'shoot' }), /strike|call|safety/, 'a shot without a strike'),
      throws(check, () => g.act({ type: 'decide', choice: 'pass' }), /.+/, 'an illegal action'),
      throws(check, () => g.undo(1), /^undo: /, 'undo past the start'),
      throws(check, () => g.shot(0), /^index: /, 'the shot of no action'),
      throws(check, () => ctx.api.Game.fromLink('v2.garbage'), /link/, 'a bad link'),
      throws(check, () => g.aiAction('champ'), /level/, 'an unknown AI level'),
    ];
    console.log(m.map((x) => `    ${x}`).join('\n'));
    g.free();
    throws(check, () => g.state(), /freed/, 'a freed game');
  });

  test('mutated links, scenarios and actions: each refused with an Error, never a crash', () => {
    const { Game, simulate } = ctx.api;
    let seed = 12345;  // a fixed sequence: the same inputs every run
    const rnd = () => { seed = (seed * 1103515245 + 12345) >>> 0; return seed / 4294967296; };
    const pick = (a) => a[Math.floor(rnd() * a.length)];
    const dir = path.join(ctx.root, 'examples/pool');
    const scenarios = readdirSync(dir).filter((f) => f.endsWith('.json')).sort().map((f) => readFileSync(path.join(dir, f), 'utf8'));
    const g = new Game({ game: 'nine_ball', players: ['club', 'club'], seed: 3 });
    for (let k = 0; k < 3; k++) g.act(g.aiAction());
    const link = g.link();
    g.free();
    const chars = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_.';
    let refused = 0;
    let accepted = 0;
    const attempt = (what, f) => {
      try {
        f();
        accepted++;
      } catch (e) {
        check(e instanceof Error && !(e instanceof WebAssembly.RuntimeError), `${what}: threw ${e}`);
        check(!/internal error/.test(e.message), `${what}: ${e.message}`);
        refused++;
      }
    };
    for (let n = 0; n < 600; n++) {
      const l = link.split('');
      const i = Math.floor(rnd() * l.length);
      const m = rnd();
      if (m < 0.4) l[i] = pick(chars);
      else if (m < 0.7) l.length = i;
      else l.splice(i, 0, pick(chars));
      const text = l.join('');
      attempt(`the link ${text}`, () => { const h = Game.fromLink(text); try { h.state(); } finally { h.free(); } });
      const s = pick(scenarios).split('');
      s[Math.floor(rnd() * s.length)] = pick('0123456789-.e{}[]",: truefalsn');
      const st = s.join('');
      attempt(`the scenario ${st}`, () => simulate(st));
      const act = {
        type: pick(['shoot', 'place_cue_ball', 'decide', 'x']),
        strike: { speed: rnd() * 20 - 2, phi: rnd() * 720 - 360, theta: rnd() * 100 - 5, a: rnd() * 2 - 1, b: rnd() * 2 - 1 },
        call: rnd() < 0.5 ? null : { ball: Math.floor(rnd() * 12) - 1, pocket: pick(['top_left', 'x', 'side_bottom']) },
        safety: rnd() < 0.5, push_out: rnd() < 0.5,
        position: [rnd() * 3 - 0.2, rnd() * 1.5 - 0.1], choice: pick(['pass_back', 'shoot', 'zz']),
      };
      attempt(`the action ${JSON.stringify(act)}`, () => { const h = Game.fromLink(link); try { h.act(act); } finally { h.free(); } });
    }
    check(refused > 1000 && accepted > 10, `refused ${refused}, accepted ${accepted}: the mutations are not doing their job`);
    console.log(`    1800 inputs: ${refused} refused with an Error, ${accepted} accepted`);
  });

  test('Player: worker and inline agree; LEVEL@NOISE; bad levels reject; close', async () => {
    const { Game, Player } = ctx.api;
    const g = new Game({ game: 'eight_ball', players: ['human', 'human'], seed: 5 });
    const w = new Player('expert@0.5x');
    const i = new Player('expert@0.5x', { inline: true });
    const [a, b] = await Promise.all([w.decide(g), i.decide(g)]);
    check(JSON.stringify(a) === JSON.stringify(b), `worker ${JSON.stringify(a)} / inline ${JSON.stringify(b)}`);
    check(JSON.stringify(a) === JSON.stringify(g.aiAction('expert@0.5x')), 'Game.aiAction differs');
    check(g.act(a).index === 0, 'the decision is legal');
    const bad = new Player('grandmaster');
    await rejects(check, bad.decide(g), /level/, 'an unknown level');
    await rejects(check, w.decide(42), /^decide: /, 'not a game');
    throws(check, () => new Player(''), /^level: /, 'an empty level');
    const pending = w.decide(g);
    w.close();
    await rejects(check, pending, /closed/, 'a decision pending at close');
    await rejects(check, w.decide(g), /closed/, 'a closed player');
    bad.close();
    i.close();
    g.free();
  });
}

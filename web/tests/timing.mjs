// Times the wasm engine in node (the figures of docs/web.md, "Speed"):
// an 8-ball break simulated, the lab's 1000-ball gas played back frame by
// frame (JSON frames and binary frames), and AI decisions at each level.
//
//   node web/tests/timing.mjs [--engine build/web/dist/breakshot.js]
//                             [--decisions N] [--levels a,b,...] [--budget N]
//
// Decisions: a game between two seats of the level (seed 7, 8-ball, 9 ft,
// then seed 7, 9-ball) is played by the AI for N decisions each (default
// 20), every bs_game_ai_action call timed; the median, 90th percentile and
// maximum are printed per level, in wall-clock time and in the process's
// CPU time (the better figure on a busy machine: another process's work
// does not count). --budget overrides the levels' budgets (the game's
// ai_budget).

import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '..', '..');
let engine = path.join(root, 'build', 'web', 'dist', 'breakshot.js');
let decisions = 20;
let levels = null;
let budget = null;
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; ++i) {
  if (argv[i] === '--engine') engine = path.resolve(argv[++i]);
  else if (argv[i] === '--decisions') decisions = Number(argv[++i]);
  else if (argv[i] === '--levels') levels = argv[++i].split(',');
  else if (argv[i] === '--budget') budget = Number(argv[++i]);
  else {
    console.error(`timing.mjs: unknown argument '${argv[i]}'`);
    process.exit(2);
  }
}

const { loadEngine } = await import(pathToFileURL(path.join(path.dirname(engine), 'engine.js')).href);
let t0 = performance.now();
const E = await loadEngine({ fresh: true });
console.log(`load: ${(performance.now() - t0).toFixed(0)} ms, breakshot.js ${fs.statSync(engine).size} bytes`);
levels ??= E.levels;

const quantile = (v, q) => {
  const s = [...v].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.round(q * (s.length - 1)))];
};

// The break: simulate() of examples/pool/break_8ball.json, and the
// physics alone (a playback to rest, no result text).
const scenario = fs.readFileSync(path.join(root, 'examples', 'pool', 'break_8ball.json'), 'utf8');
for (let k = 0; k < 20; ++k) E.raw.simulate(scenario);  // warm up
const sim = [];
const phys = [];
for (let k = 0; k < 200; ++k) {
  t0 = performance.now();
  E.raw.simulate(scenario);
  sim.push(performance.now() - t0);
  t0 = performance.now();
  const h = E.raw.playbackNew(scenario);
  E.raw.frame(h, 1e6);
  E.raw.playbackFree(h);
  phys.push(performance.now() - t0);
}
console.log(`8-ball break: simulate (with the result text) median ${quantile(sim, 0.5).toFixed(3)} ms; ` +
            `playback to rest median ${quantile(phys, 0.5).toFixed(3)} ms`);

// examples/lab/gas_1000.json frame by frame, a sixtieth of a second apart
// over its two seconds, as the lab plays it at speed 1: the JSON frame
// (bs_playback_frame, then JSON.parse: pb.frameJson) against the binary
// frame (bs_playback_frame_data read from the heap: pb.frame); each
// includes the physics of the step. Twice each, the second timed.
{
  const gas = fs.readFileSync(path.join(root, 'examples', 'lab', 'gas_1000.json'), 'utf8');
  const run = (frame) => {
    const pb = E.playback(gas);
    const times = [];
    for (let k = 0; k <= 120; ++k) {
      t0 = performance.now();
      frame(pb, k / 60);
      times.push(performance.now() - t0);
    }
    pb.free();
    return times;
  };
  const mean = (v) => v.reduce((a, b) => a + b, 0) / v.length;
  for (const [label, frame] of [['JSON frame (call + JSON.parse)', (pb, t) => pb.frameJson(t)],
                                ['binary frame (pb.frame)', (pb, t) => pb.frame(t)]]) {
    run(frame);
    const times = run(frame);
    console.log(`gas_1000, ${label}: median ${quantile(times, 0.5).toFixed(2)} ms, ` +
                `p90 ${quantile(times, 0.9).toFixed(2)} ms, mean ${mean(times).toFixed(2)} ms a frame`);
  }
}

// The first decisions after loading run partly unoptimized (V8 compiles
// wasm in tiers): time one apart, then warm up before the figures.
{
  const g = E.newGame({ game: 'eight_ball', seed: '1', players: ['club', 'club'] });
  t0 = performance.now();
  let reply = E.raw.aiAction(g._h, null);
  console.log(`first decision after load (club, the break): ${(performance.now() - t0).toFixed(0)} ms`);
  for (let k = 0; k < 10 && g.state().phase !== 'game_over'; ++k) {
    g.act(JSON.parse(reply).action);
    reply = E.raw.aiAction(g._h, null);
  }
  g.free();
}

for (const level of levels) {
  const times = [];
  const cpu = [];
  for (const game of ['eight_ball', 'nine_ball']) {
    const config = { game, table: '9ft', seed: '7', breaker: 0, players: [level, level] };
    if (budget) config.ai_budget = budget;
    const g = E.newGame(config);
    for (let k = 0; k < decisions; ++k) {
      if (g.state().phase === 'game_over') break;
      t0 = performance.now();
      const c0 = process.cpuUsage();
      const reply = E.raw.aiAction(g._h, null);
      const c = process.cpuUsage(c0);
      times.push(performance.now() - t0);
      cpu.push((c.user + c.system) / 1000);
      g.act(JSON.parse(reply).action);
    }
    g.free();
  }
  console.log(`${level.padEnd(9)} budget ${String(budget ?? E.aiBudgets[level]).padStart(5)}: ${times.length} decisions, ` +
              `wall median ${quantile(times, 0.5).toFixed(0)} ms, p90 ${quantile(times, 0.9).toFixed(0)} ms, max ${Math.max(...times).toFixed(0)} ms; ` +
              `CPU median ${quantile(cpu, 0.5).toFixed(0)} ms, p90 ${quantile(cpu, 0.9).toFixed(0)} ms, max ${Math.max(...cpu).toFixed(0)} ms`);
}

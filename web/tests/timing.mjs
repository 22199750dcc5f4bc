// Times the wasm engine in node (the figures of docs/web.md, "Build and
// speed"): shots per second against native, an 8-ball break simulated,
// the lab's 1000-ball gas played back frame by frame (JSON frames and
// binary frames), and AI decisions at each level.
//
//   node web/tests/timing.mjs [--engine build/web/dist/breakshot.js]
//                             [--native build/release] [--rounds N] [--repeat K]
//                             [--shots-only]
//                             [--decisions N] [--levels a,b,...] [--budget N]
//
// Per shot: three workloads of shots, each shot a different one (cycled
// inputs): 8-ball and 9-ball breaks with rack seeds 1 to 60 (cluster
// impacts on, as the games have them), and the first 300 layouts and
// strikes of bench_pool's BM_RandomShot15 (written by
// NATIVE/bench/export_random_shots; left out when it is missing). A
// shot is bs_web_playback_new of its scenario text, bs_web_playback_frame_data
// at t = 1e9 (the physics to rest) and bs_web_playback_free, through
// engine.js's raw API; a pass without the frame gives the set-up alone
// ("new": the text read and the simulation set up; "run" is the rest).
// The native program NATIVE/web_timing (web/tests/web_timing.cpp) plays
// the same shots, written to a file, the same way through the native
// facade; both must end on the same frames (the event counts and a hash
// of the final frames are compared). A round makes both passes over
// every workload, after one untimed round; the native program and the
// wasm engine take turns, --repeat times (default 3), --rounds rounds
// each (default 5). Printed per workload: the median over the rounds of
// the process's CPU microseconds per shot (the steadier figure on a busy
// machine) and of the wall-clock ones, wasm and native, and their
// ratios; then the mean over all shots. --shots-only stops there.
//
// Decisions: a game between two seats of the level (seed 7, 8-ball, 9 ft,
// then seed 7, 9-ball) is played by the AI for N decisions each (default
// 20), every bs_web_game_ai_action call timed; the median, 90th percentile and
// maximum are printed per level, in wall-clock time and in the process's
// CPU time (the better figure on a busy machine: another process's work
// does not count). --budget overrides the levels' budgets (the game's
// ai_budget).

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '..', '..');
let engine = path.join(root, 'build', 'web', 'dist', 'breakshot.js');
let decisions = 20;
let levels = null;
let budget = null;
let native = path.join(root, 'build', 'release');
let rounds = 5;
let repeat = 3;
let shotsOnly = false;
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; ++i) {
  if (argv[i] === '--engine') engine = path.resolve(argv[++i]);
  else if (argv[i] === '--native') native = path.resolve(argv[++i]);
  else if (argv[i] === '--rounds') rounds = Number(argv[++i]);
  else if (argv[i] === '--repeat') repeat = Number(argv[++i]);
  else if (argv[i] === '--shots-only') shotsOnly = true;
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

// Per shot, wasm and native (see the top of this file).
{
  const shots = [];
  for (const game of ['eight_ball', 'nine_ball']) {
    for (let seed = 1; seed <= 60; ++seed) {
      shots.push([game === 'eight_ball' ? 'break8' : 'break9', JSON.stringify({
        physics: { model: 'pool', ball_clusters: true },
        table: { shape: 'pool', size: '9ft' },
        rack: { game, seed },
        cue: { ball: 'cue', speed: 7.5, phi: 0, theta: 0, a: 0, b: 0 },
      })]);
    }
  }
  const exporter = path.join(native, 'bench', 'export_random_shots');
  if (fs.existsSync(exporter)) {
    const out = spawnSync(exporter, ['300'], { encoding: 'utf8', maxBuffer: 1 << 26 });
    if (out.status !== 0) throw new Error(`${exporter} failed: ${out.stderr}`);
    const { scenarios, strikes } = JSON.parse(out.stdout);
    scenarios.forEach((sc, k) => {
      const [phi, theta, speed, a, b] = strikes[k];
      shots.push(['random15', JSON.stringify({ ...sc, cue: { ball: 'cue', phi, theta, speed, a, b } })]);
    });
  } else {
    console.log(`per shot: ${exporter} is missing, so no random15 workload`);
  }
  const names = [...new Set(shots.map(([w]) => w))];
  const count = Object.fromEntries(names.map((w) => [w, shots.filter(([x]) => x === w).length]));
  const fnv = (h, d) => {
    const b = new Uint8Array(d.buffer, d.byteOffset, d.length * 8);
    for (let k = 0; k < b.length; ++k) h = Math.imul(h ^ b[k], 16777619) >>> 0;
    return h;
  };
  const empty = () => ({ events: 0, hash: 2166136261, new_us: [], shot_us: [], new_cpu: [], shot_cpu: [] });
  // As web_timing.cpp's pass(): new and free of each shot, with the
  // physics to rest between them when `run`.
  const pass = (w, o, run, timed, check) => {
    const c0 = process.cpuUsage();
    const t0 = performance.now();
    for (const [name, text] of shots) {
      if (name !== w) continue;
      const h = E.raw.playbackNew(text);
      if (!h) throw new Error(`${w}: ${E.raw.lastError()}`);
      if (run) {
        const d = E.raw.frameData(h, 1e9);
        if (!d) throw new Error(`${w}: ${E.raw.lastError()}`);
        if (check) {
          o.events += d[1];
          o.hash = fnv(o.hash, d);
        }
      }
      E.raw.playbackFree(h);
    }
    const wall = (performance.now() - t0) * 1000;
    const c = process.cpuUsage(c0);
    if (timed) {
      (run ? o.shot_us : o.new_us).push(wall);
      (run ? o.shot_cpu : o.new_cpu).push(c.user + c.system);
    }
  };
  const wasmRounds = (n) => {
    const res = Object.fromEntries(names.map((w) => [w, empty()]));
    for (let r = 0; r < 1 + n; ++r) {
      for (const w of names) {
        pass(w, res[w], false, r > 0, false);
        pass(w, res[w], true, r > 0, r === 0);
      }
    }
    return res;
  };
  const nativeProgram = path.join(native, 'web_timing');
  const haveNative = fs.existsSync(nativeProgram);
  if (!haveNative) console.log(`per shot: ${nativeProgram} is missing (cmake --build --preset release --target web_timing), so no native figures`);
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'breakshot-timing-')), 'shots.txt');
  fs.writeFileSync(file, shots.map(([w, t]) => `${w}\t${t}\n`).join(''));
  const keys = ['new_us', 'shot_us', 'new_cpu', 'shot_cpu'];
  const all = { wasm: {}, native: {} };
  const add = (side, res) => {
    for (const [w, o] of Object.entries(res)) {
      const a = (all[side][w] ??= { ...empty(), events: o.events, hash: o.hash });
      for (const key of keys) a[key].push(...o[key]);
    }
  };
  for (let k = 0; k < repeat; ++k) {
    if (haveNative) {
      const out = spawnSync(nativeProgram, ['--shots', file, '--rounds', String(rounds)], { encoding: 'utf8' });
      if (out.status !== 0) throw new Error(`${nativeProgram} failed: ${out.stderr}`);
      const res = {};
      for (const line of out.stdout.trim().split('\n')) {
        const o = JSON.parse(line);
        res[o.workload] = { ...o, hash: parseInt(o.hash, 16) };
      }
      add('native', res);
    }
    add('wasm', wasmRounds(rounds));
  }
  fs.rmSync(path.dirname(file), { recursive: true });
  // Microseconds per shot: the median over the rounds.
  const per = (side, w) => {
    const a = all[side][w];
    if (!a) return null;
    const m = (key) => quantile(a[key], 0.5) / count[w];
    const run = a.shot_cpu.map((v, k) => v - a.new_cpu[k]);
    return { shot: m('shot_cpu'), new: m('new_cpu'), run: quantile(run, 0.5) / count[w], wall: m('shot_us') };
  };
  const fmt = (f) => `${f.shot.toFixed(1)} us (new ${f.new.toFixed(1)} + run ${f.run.toFixed(1)}; wall ${f.wall.toFixed(1)})`;
  let same = true;
  const sums = { wasm: 0, native: 0 };
  for (const w of names) {
    const x = per('wasm', w);
    const y = per('native', w);
    let line = `per shot, ${w} (${count[w]} shots, ${all.wasm[w].events} events), CPU: wasm ${fmt(x)}`;
    sums.wasm += x.shot * count[w];
    if (y) {
      sums.native += y.shot * count[w];
      line += `; native ${fmt(y)}; ratio ${(x.shot / y.shot).toFixed(2)} (new ${(x.new / y.new).toFixed(2)}, run ${(x.run / y.run).toFixed(2)}; wall ${(x.wall / y.wall).toFixed(2)})`;
      const n = all.native[w];
      if (all.wasm[w].events !== n.events || all.wasm[w].hash !== n.hash) {
        line += ` -- DIFFERENT RESULTS (native ${n.events} events, hash ${n.hash.toString(16)}; wasm hash ${all.wasm[w].hash.toString(16)})`;
        same = false;
      }
    }
    console.log(line);
  }
  const total = shots.length;
  console.log(`per shot, all ${total} shots, CPU: wasm ${(sums.wasm / total).toFixed(1)} us` +
              (haveNative ? `, native ${(sums.native / total).toFixed(1)} us, ratio ${(sums.wasm / sums.native).toFixed(2)}` : ''));
  if (!same) process.exit(1);
  if (shotsOnly) process.exit(0);
}

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
// (bs_web_playback_frame, then JSON.parse: pb.frameJson) against the binary
// frame (bs_web_playback_frame_data read from the heap: pb.frame); each
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

// The time from `import('breakshot')` to the first simulated shot in node
// (docs/js.md, "Size and speed"): each run a fresh node process that
// imports the installed package (the engine instantiated by the import)
// and simulates one 8-ball break, the racks cycled (seed 1, 2, ... one a
// run), so no run repeats another's shot. Prints the median and range of
// the runs: import, first shot, both; and the shots after it in the same
// process (250 more breaks: the first 50, and 50 once V8 has optimized
// the wasm), and a 60 fps frame's states(t, into) over 20 breaks drawn
// three times (the first pass, and the third once V8 has optimized the
// path). Wall-clock times, and the CPU time of the process (every
// thread: V8 compiles the wasm on threads of its own) from the import to
// the first shot, which a busy machine changes less.
//
//   node npm/bench/first-shot.mjs [--package DIR] [--runs N]
//
// --package: the installed package (node_modules/breakshot) or the
// assembled one (default build/npm/package, of scripts/npm.sh).
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const argv = process.argv.slice(2);
const opt = (name, def) => { const i = argv.indexOf(name); return i >= 0 ? argv[i + 1] : def; };

const scenario = (seed) => ({
  physics: { model: 'pool', ball_clusters: true },
  table: { shape: 'pool', size: '9ft' },
  rack: { game: 'eight_ball', seed },
  cue: { ball: 'cue', speed: 7.5, phi: 0.0, theta: 0.0, a: 0.0, b: 0.0 },
});

if (argv[0] === '--child') {
  const [, pkg, seedText] = argv;
  const seed = Number(seedText);
  const c0 = process.cpuUsage();
  const t0 = performance.now();
  const { simulate } = await import(pathToFileURL(path.join(pkg, 'index.js')).href);
  const t1 = performance.now();
  const sim = simulate(scenario(seed));
  const t2 = performance.now();
  const c1 = process.cpuUsage(c0);
  const events = sim.events.length;
  sim.free();
  // the next shots: V8 compiles the wasm in a baseline tier first and
  // optimizes what runs hot in the background, so shots get faster for a
  // while; the median of the first 50 after the first, then of 50 after 200
  const times = [];
  for (let k = 1; k <= 250; k++) {
    const s0 = performance.now();
    simulate(scenario(seed + 1000 + k)).free();
    times.push(performance.now() - s0);
  }
  const median = (v) => v.slice().sort((a, b) => a - b)[v.length >> 1];
  // one frame's states (16 balls) at 60 fps steps through 20 breaks, warm:
  // the physics from the last frame to this one, and the copy out
  // The same 20 breaks drawn three times: the first pass as a game that
  // has just loaded meets it, the third once V8 has optimized the path.
  const framePass = () => {
    let frames = 0;
    let time = 0;
    for (let k = 1; k <= 20; k++) {
      const sim = simulate(scenario(seed + 2000 + k));
      let into;
      const f0 = performance.now();
      for (let t = 0; t <= sim.duration; t += 1 / 60, frames++) into = sim.states(t, into);
      time += performance.now() - f0;
      sim.free();
    }
    return (time / frames) * 1000;
  };
  const frame = framePass();
  framePass();
  const frameWarm = framePass();
  process.stdout.write(JSON.stringify({
    import: t1 - t0, shot: t2 - t1, total: t2 - t0, cpu: (c1.user + c1.system) / 1000, events, next: median(times.slice(0, 50)), warm: median(times.slice(200)),
    frame, frameWarm,
  }) + '\n');
  process.exit(0);
}

const pkg = path.resolve(opt('--package', path.join(root, 'build/npm/package')));
const runs = Number(opt('--runs', 11));
const results = [];
for (let r = 0; r < runs; r++) {
  const out = spawnSync(process.execPath, [fileURLToPath(import.meta.url), '--child', pkg, String(r + 1)], { encoding: 'utf8' });
  if (out.status !== 0) {
    console.error(out.stderr);
    process.exit(1);
  }
  results.push(JSON.parse(out.stdout));
}
const stat = (key) => {
  const v = results.map((x) => x[key]).sort((a, b) => a - b);
  return `${v[v.length >> 1].toFixed(1)} ms (${v[0].toFixed(1)}-${v[v.length - 1].toFixed(1)})`;
};
console.log(`node ${process.version}, ${runs} runs (racks 1-${runs} of the 8-ball break), ${pkg}`);
console.log(`import('breakshot') (the engine instantiated): ${stat('import')}`);
console.log(`the first shot (simulate, result text):       ${stat('shot')}`);
console.log(`import to the first shot:                      ${stat('total')}`);
console.log(`the same, the process's CPU time (all threads): ${stat('cpu')}`);
console.log(`shots 2-51 (median per run):                   ${stat('next')}`);
console.log(`shots 202-251, warm (median per run):          ${stat('warm')}`);
for (const [key, what] of [['frame', "a frame's states(t, into), 16 balls, 60 fps:  "],
  ['frameWarm', 'the same, the third pass over those breaks:   ']]) {
  const v = results.map((x) => x[key]).sort((a, b) => a - b);
  console.log(`${what} ${v[v.length >> 1].toFixed(1)} us (${v[0].toFixed(1)}-${v[v.length - 1].toFixed(1)})`);
}

// The identity test (docs/web.md, "Bit identity"): the wasm build and the
// native build give the same replies, byte for byte, to the same calls.
//
//   node web/tests/identity.mjs [--probe PATH | --expected FILE]
//                               [--engine build/web/dist/breakshot.js]
//                               [--root DIR] [--script FILE]
//                               [--skip-if-missing] [--skip-if-stale] [--save FILE]
//
// It runs the steps of web/tests/probe_script.json through the wasm
// engine (loaded with the engine.js next to --engine, as the page loads
// it) and compares every reply line with the native one: the output of
// the web_api_probe program given by --probe (run here), or a file it
// wrote (--expected). The step interpreter below must do exactly what
// web/tests/web_api_probe.cpp does; see the list of steps there.
//
// Prints the first line that differs (label, position and both texts
// around the first differing character) and ends with
// "N passed, M failed" (one check per reply line); exit status 0 when
// all match, 1 otherwise, 2 for bad arguments. --skip-if-missing and
// --skip-if-stale (ctest) exit with 77 when the wasm build is absent or
// older than the engine's sources, instead of failing.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const opts = {
  root: path.resolve(here, '..', '..'),
  engine: null,
  probe: null,
  expected: null,
  script: null,
  save: null,
  skipIfMissing: false,
  skipIfStale: false,
};

function usage(msg) {
  console.error(`identity.mjs: ${msg}`);
  console.error('usage: node web/tests/identity.mjs [--probe PATH | --expected FILE] [--engine breakshot.js] [--root DIR] [--script FILE] [--skip-if-missing] [--skip-if-stale] [--save FILE]');
  process.exit(2);
}

const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; ++i) {
  const a = argv[i];
  const value = () => {
    if (i + 1 >= argv.length) usage(`${a} needs a value`);
    return argv[++i];
  };
  if (a === '--probe') opts.probe = path.resolve(value());
  else if (a === '--expected') opts.expected = path.resolve(value());
  else if (a === '--engine') opts.engine = path.resolve(value());
  else if (a === '--root') opts.root = path.resolve(value());
  else if (a === '--script') opts.script = path.resolve(value());
  else if (a === '--save') opts.save = path.resolve(value());
  else if (a === '--skip-if-missing') opts.skipIfMissing = true;
  else if (a === '--skip-if-stale') opts.skipIfStale = true;
  else usage(`unknown argument '${a}'`);
}
if (!opts.probe && !opts.expected) usage('give --probe PATH (the native web_api_probe) or --expected FILE (its output)');
opts.engine ??= path.join(opts.root, 'build', 'web', 'dist', 'breakshot.js');
opts.script ??= path.join(opts.root, 'web', 'tests', 'probe_script.json');

const SKIP = 77;

if (!fs.existsSync(opts.engine)) {
  const msg = `the wasm build ${opts.engine} does not exist (run scripts/web.sh)`;
  if (opts.skipIfMissing) {
    console.log(`skipped: ${msg}`);
    process.exit(SKIP);
  }
  usage(msg);
}

// The newest source the wasm build depends on.
function newestSource() {
  let newest = 0;
  const walk = (dir) => {
    if (!fs.existsSync(dir)) return;
    for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
      const p = path.join(dir, e.name);
      if (e.isDirectory()) walk(p);
      else if (/\.(cpp|hpp|h|js|txt)$/.test(e.name)) newest = Math.max(newest, fs.statSync(p).mtimeMs);
    }
  };
  for (const d of ['src/physics', 'src/game', 'src/ai', 'src/io', 'include', 'web/api', 'web/compat']) walk(path.join(opts.root, d));
  const cmake = path.join(opts.root, 'web', 'CMakeLists.txt');
  if (fs.existsSync(cmake)) newest = Math.max(newest, fs.statSync(cmake).mtimeMs);
  return newest;
}
const mtime = (p) => (fs.existsSync(p) ? fs.statSync(p).mtimeMs : 0);
if (opts.skipIfStale && (mtime(opts.engine) < newestSource() ||
    mtime(path.join(path.dirname(opts.engine), 'engine.js')) < mtime(path.join(opts.root, 'web', 'page', 'engine.js')))) {
  console.log(`skipped: ${opts.engine} or the engine.js next to it is older than its sources (run scripts/web.sh)`);
  process.exit(SKIP);
}

// ---------------------------------------------------------------------------
// The native replies.

let t0 = performance.now();
let nativeText;
if (opts.probe) {
  const r = spawnSync(opts.probe, ['--root', opts.root, '--script', opts.script], { maxBuffer: 1 << 30, encoding: 'utf8' });
  if (r.error || r.status !== 0) {
    console.error(`identity.mjs: ${opts.probe} failed: ${r.error ? r.error.message : `exit ${r.status}`}\n${r.stderr || ''}`);
    process.exit(1);
  }
  nativeText = r.stdout;
} else {
  nativeText = fs.readFileSync(opts.expected, 'utf8');
}
const nativeMs = performance.now() - t0;
const nativeLines = nativeText.split('\n');
if (nativeLines.length && nativeLines[nativeLines.length - 1] === '') nativeLines.pop();

// ---------------------------------------------------------------------------
// The wasm replies: the same steps as web_api_probe.cpp.

const engineJs = path.join(path.dirname(opts.engine), 'engine.js');
if (!fs.existsSync(engineJs)) usage(`${engineJs} does not exist (scripts/web.sh copies web/page/ next to breakshot.js)`);
const { loadEngine, frameObject } = await import(pathToFileURL(engineJs).href);
t0 = performance.now();
const E = await loadEngine({ fresh: true });
const loadMs = performance.now() - t0;
const raw = E.raw;

const lines = [];
const print = (label, reply) => lines.push(`${label}\t${reply.split('\n').join('\\n')}`);
const OK = '{"ok":true}';
const playbacks = new Map();
const games = new Map();

function need(map, name, what) {
  if (!map.has(name)) throw new Error(`no ${what} ${JSON.stringify(name)}`);
  return map.get(name);
}
const pbOf = (step) => need(playbacks, step.pb, 'playback');
const gameOf = (step) => need(games, step.game, 'game');

// bs_web_playback_frame_data's doubles as web_api_probe prints them: the hex
// of their bits, 16 digits each, separated by spaces (the header and the
// balls, and the flight block when its flag is 1); null (an error) as
// bs_web_last_error.
function frameDataText(d) {
  if (!d) return raw.lastError();
  // The header and the balls, and the flight block when its flag is 1.
  const head = 8 + 8 * d[7];
  const bits = new BigUint64Array(Float64Array.from(d[head] !== 0 ? d : d.subarray(0, head)).buffer);
  let out = '';
  for (let i = 0; i < bits.length; ++i) out += (i ? ' ' : '') + bits[i].toString(16).padStart(16, '0');
  return out;
}

// The same numbers with the same sign of zero, the same keys in the same order.
function sameValue(a, b) {
  if (typeof a === 'number') return typeof b === 'number' && Object.is(a, b);
  if (Array.isArray(a)) return Array.isArray(b) && a.length === b.length && a.every((x, i) => sameValue(x, b[i]));
  if (a !== null && typeof a === 'object') {
    if (b === null || typeof b !== 'object' || Array.isArray(b)) return false;
    const ka = Object.keys(a);
    return ka.join(',') === Object.keys(b).join(',') && ka.every((k) => sameValue(a[k], b[k]));
  }
  return a === b;
}

// frames_data: bs_web_playback_frame_data then bs_web_playback_frame at the same t.
// The wasm side also checks that engine.js's frame object (pb.frame's, built
// from the doubles) is JSON.parse of the JSON frame; if not, it prints that
// instead of the JSON frame, so the line differs from the native one.
function framesData(h, count, dt) {
  for (let k = 0; k < count; ++k) {
    const t = k * dt;
    const d = raw.frameData(h, t);
    const object = d ? frameObject(d) : null;
    print(`frame_data ${k}`, frameDataText(d));
    const json = raw.frame(h, t);
    if (object && !sameValue(object, JSON.parse(json))) {
      print(`frame ${k}`, `engine.js frame object differs from the JSON frame: ${JSON.stringify(object).slice(0, 300)}`);
    } else {
      print(`frame ${k}`, json);
    }
  }
}

function frames(h, count, dt) {
  for (let k = 0; k < count; ++k) print(`frame ${k}`, raw.frame(h, k * dt));
}

function newPlayback(label, name, h) {
  print(label, h ? OK : raw.lastError());
  if (h) {
    if (playbacks.has(name)) raw.playbackFree(playbacks.get(name));
    playbacks.set(name, h);
  }
}

function newGame(label, name, h) {
  print(label, h ? raw.state(h) : raw.lastError());
  if (h) {
    if (games.has(name)) raw.gameFree(games.get(name));
    games.set(name, h);
  }
}

function ai(step, level, play) {
  const g = gameOf(step);
  const reply = raw.aiAction(g, level || null);
  print(`ai ${step.game}`, reply);
  const head = '{"action":';
  if (play && reply.startsWith(head)) {
    print(`act ${step.game}`, raw.act(g, reply.slice(head.length, reply.length - 1)));
  }
}

const read = (rel) => fs.readFileSync(path.join(opts.root, rel), 'utf8');
const script = JSON.parse(fs.readFileSync(opts.script, 'utf8'));
const aiTimes = [];

t0 = performance.now();
for (const step of script.steps) {
  switch (step.do) {
    case 'version':
      print('version', raw.version());
      break;
    case 'players':
      print('players', raw.gamePlayers(step.game));
      break;
    case 'simulate_dir': {
      const names = fs.readdirSync(path.join(opts.root, step.dir)).filter((n) => n.length > 5 && n.endsWith('.json'));
      names.sort((a, b) => Buffer.compare(Buffer.from(a), Buffer.from(b)));  // bytes, as std::sort
      for (const n of names) print(`simulate ${step.dir}/${n}`, raw.simulate(read(`${step.dir}/${n}`)));
      break;
    }
    case 'simulate_text':
      print('simulate_text', raw.simulate(step.text));
      break;
    case 'playback_new':
    case 'playback_new_text': {
      const text = step.do === 'playback_new' ? read(step.file) : step.text;
      newPlayback(`${step.do} ${step.as}`, step.as, raw.playbackNew(text));
      break;
    }
    case 'frames':
      frames(pbOf(step), step.count, step.dt);
      break;
    case 'frame':
      print('frame', raw.frame(pbOf(step), step.t));
      break;
    case 'frames_data':
      framesData(pbOf(step), step.count, step.dt);
      break;
    case 'frame_data':
      print('frame_data', frameDataText(raw.frameData(step.pb === null ? 0 : pbOf(step), step.t)));
      break;
    case 'events':
      print(`events ${step.from}`, raw.events(pbOf(step), step.from));
      break;
    case 'playback_free':
      raw.playbackFree(pbOf(step));
      playbacks.delete(step.pb);
      break;
    case 'game_new':
    case 'game_new_text': {
      const text = step.do === 'game_new' ? JSON.stringify(step.config) : step.text;
      newGame(`${step.do} ${step.as}`, step.as, raw.gameNew(text));
      break;
    }
    case 'table':
    case 'state':
    case 'link':
    case 'record':
    case 'turns':
      print(`${step.do} ${step.game}`, raw[step.do](gameOf(step)));
      break;
    case 'check_placement':
      print(`check_placement ${step.game}`, raw.checkPlacement(gameOf(step), step.x, step.y));
      break;
    case 'act':
      print(`act ${step.game}`, raw.act(gameOf(step), JSON.stringify(step.action)));
      break;
    case 'ai': {
      const s = performance.now();
      ai(step, step.level, step.play);
      aiTimes.push(performance.now() - s);
      break;
    }
    case 'ai_until':
      for (let k = 0; k < step.count; ++k) {
        const state = JSON.parse(raw.state(gameOf(step)));
        if (state.phase === 'game_over') break;
        const seat = state.players[state.player];
        ai(step, seat === 'human' ? step.level : null, true);
      }
      break;
    case 'shot_playback': {
      const h = raw.shotPlayback(gameOf(step), step.index);
      print(`shot_playback ${step.game} ${step.index}`, h ? OK : raw.lastError());
      if (h) {
        frames(h, step.count, step.dt);
        print('events 0', raw.events(h, 0));
        raw.playbackFree(h);
      }
      break;
    }
    case 'carom_playback': {
      const h = raw.shotPlayback(gameOf(step), step.index);
      print(`carom_playback ${step.game} ${step.index}`, h ? OK : raw.lastError());
      if (h) {
        for (let k = 0; k < step.count; ++k) {
          print(`frame ${k}`, raw.frame(h, k * step.dt));
          print(`carom_count ${k}`, raw.caromCount(h));
        }
        raw.playbackFree(h);
      }
      break;
    }
    case 'from_link': {
      const link = JSON.parse(raw.link(gameOf(step))).link;
      newGame(`from_link ${step.as}`, step.as, raw.gameFromLink(link));
      break;
    }
    case 'from_link_text':
      newGame(`from_link_text ${step.as}`, step.as, raw.gameFromLink(step.text));
      break;
    case 'undo':
      print(`undo ${step.game}`, raw.undoTo(gameOf(step), step.n));
      break;
    case 'game_free':
      raw.gameFree(gameOf(step));
      games.delete(step.game);
      break;
    default:
      throw new Error(`unknown step "${step.do}"`);
  }
}
const wasmMs = performance.now() - t0;
for (const h of playbacks.values()) raw.playbackFree(h);
for (const h of games.values()) raw.gameFree(h);
if (opts.save) fs.writeFileSync(opts.save, lines.map((l) => `${l}\n`).join(''));

// ---------------------------------------------------------------------------
// Comparison.

function around(text, at, width = 100) {
  const from = Math.max(0, at - width);
  return `${from > 0 ? '…' : ''}${text.slice(from, at + width)}${at + width < text.length ? '…' : ''}`;
}

let passed = 0;
let failed = 0;
let first = null;
const n = Math.max(lines.length, nativeLines.length);
for (let i = 0; i < n; ++i) {
  const w = lines[i];
  const nat = nativeLines[i];
  if (w === nat) {
    ++passed;
    continue;
  }
  ++failed;
  if (first !== null) continue;
  first = i;
  if (w === undefined || nat === undefined) {
    console.log(`line ${i + 1}: ${w === undefined ? 'wasm' : 'native'} output ended; the other has\n  ${(w ?? nat).slice(0, 300)}`);
    continue;
  }
  let k = 0;
  while (k < w.length && k < nat.length && w[k] === nat[k]) ++k;
  const label = nat.slice(0, nat.indexOf('\t'));
  console.log(`first difference: line ${i + 1} (${label}), character ${k + 1}`);
  console.log(`  native: ${around(nat, k)}`);
  console.log(`  wasm:   ${around(w, k)}`);
}
console.log(`native ${nativeMs.toFixed(0)} ms (${nativeLines.length} replies), wasm load ${loadMs.toFixed(0)} ms, wasm run ${wasmMs.toFixed(0)} ms (${lines.length} replies)`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);

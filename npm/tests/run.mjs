// Tests of the npm package (docs/js.md): the tarball of scripts/npm.sh
// installed into an empty folder, its TypeScript examples checked with
// `tsc --strict --noEmit` and run in node, results against the native
// command's, bad input, and the HTML example in Chromium (browser.mjs).
//
//   node npm/tests/run.mjs [--tarball build/npm/breakshot-X.tgz] [--native build/release]
//        [--playwright web/tests] [--shots build/npm/screenshots] [--keep]
//
// --native: the build whose `breakshot simulate` the results must equal
// byte for byte (the check is skipped, and not counted, when it is
// missing). --playwright: the folder whose node_modules has
// playwright-core (web/tests: `npm ci` there). --keep: leave the folder.
// Prints one line per test and ends with "N passed, M failed"; exits 1 on
// a failure.
import { execFile, execFileSync, spawnSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { register as registerApi } from './api.mjs';
import { runBrowser } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => {
  if (a.startsWith('--')) acc.push([a.slice(2), all[i + 1] && !all[i + 1].startsWith('--') ? all[i + 1] : true]);
  return acc;
}, []));
const version = /kVersion = "([0-9.]+)"/.exec(readFileSync(path.join(root, 'include/breakshot/version.hpp'), 'utf8'))[1];
const tarball = path.resolve(args.tarball ?? path.join(root, `build/npm/breakshot-${version}.tgz`));
const native = path.resolve(root, args.native ?? 'build/release', 'breakshot');
const shots = path.resolve(root, args.shots ?? 'build/npm/screenshots');
const playwright = path.resolve(root, args.playwright ?? 'web/tests');

let passed = 0;
let failed = 0;
let skipped = 0;
const tests = [];
const test = (name, fn) => tests.push({ name, fn });
const skip = (why) => { const e = new Error(why); e.skip = true; throw e; };
function check(cond, what) {
  if (!cond) throw new Error(what);
}

// What the tests share: the folder, the installed package, the native bytes.
const ctx = { root, version, native: existsSync(native) ? native : null, shots, playwright, check, skip };

function run(cmd, argv, opts = {}) {
  const r = spawnSync(cmd, argv, { encoding: 'utf8', maxBuffer: 64 << 20, timeout: 120000, ...opts });
  if (r.error) throw r.error;
  if (r.status !== 0) throw new Error(`${cmd} ${argv.join(' ')} exited ${r.status}: ${(r.stderr || '').slice(0, 2000)}`);
  return r.stdout;
}
ctx.run = run;
const runAsync = (cmd, argv, cwd) => new Promise((resolve, reject) => {
  execFile(cmd, argv, { cwd, encoding: 'utf8', maxBuffer: 64 << 20, timeout: 120000 }, (err, stdout, stderr) => {
    if (err) reject(new Error(`${cmd} ${argv.join(' ')}: ${err.message}\n${String(stderr).slice(0, 2000)}`));
    else resolve(stdout);
  });
});

test('the tarball installs into an empty folder, offline', () => {
  check(existsSync(tarball), `no tarball ${tarball} (run scripts/npm.sh)`);
  ctx.dir = mkdtempSync(path.join(tmpdir(), 'breakshot-npm-'));
  writeFileSync(path.join(ctx.dir, 'package.json'), JSON.stringify({ name: 'breakshot-npm-test', private: true, type: 'module' }));
  run('npm', ['install', tarball, '--no-audit', '--no-fund', '--offline', '--loglevel=error'], { cwd: ctx.dir });
  ctx.pkg = path.join(ctx.dir, 'node_modules/breakshot');
  const meta = JSON.parse(readFileSync(path.join(ctx.pkg, 'package.json'), 'utf8'));
  check(meta.name === 'breakshot' && meta.version === version, `installed ${meta.name} ${meta.version}, not breakshot ${version}`);
  check(meta.type === 'module' && meta.types === './index.d.ts' && meta.exports['.'].default === './index.js', 'package.json: type, types, exports');
  const files = readdirSync(ctx.pkg).sort().join(' ');
  check(files === 'README.md breakshot-wasm.js breakshot-wasm.wasm breakshot.js engine.js index.d.ts index.js package.json player.js worker.js',
    `the package's files: ${files}`);
  // one JS layer over the facade: the page's engine.js and worker.js, as they are
  for (const f of ['engine.js', 'worker.js']) {
    check(readFileSync(path.join(ctx.pkg, f), 'utf8') === readFileSync(path.join(root, 'web/page', f), 'utf8'), `${f} is not web/page/${f}`);
  }
});

test('the TypeScript examples pass tsc --strict --noEmit', () => {
  check(ctx.dir, 'no install');
  for (const f of ['break.ts', 'game.ts', 'node.d.ts', 'tsconfig.json']) {
    copyFileSync(path.join(root, 'npm/examples', f), path.join(ctx.dir, f));
  }
  run('tsc', ['--strict', '--noEmit', '-p', 'tsconfig.json'], { cwd: ctx.dir });
});

test('tsc refuses a misuse of the declarations; the examples compiled to run', () => {
  // bad.ts next to the examples: the same tsc run writes out/*.js (it
  // emits despite errors) and must find every error in bad.ts alone
  writeFileSync(path.join(ctx.dir, 'bad.ts'), [
    "import { simulate, Game, Player } from 'breakshot';",
    'simulate(42);',
    "new Game({ game: 'pool', players: ['human', 'human'] });",
    "new Player('club').decide(7);",
    "const n: number = simulate('{}').text;",
    '',
  ].join('\n'));
  const config = JSON.parse(readFileSync(path.join(ctx.dir, 'tsconfig.json'), 'utf8'));
  config.files.push('bad.ts');
  writeFileSync(path.join(ctx.dir, 'tsconfig.all.json'), JSON.stringify(config));
  const r = spawnSync('tsc', ['--strict', '-p', 'tsconfig.all.json'], { cwd: ctx.dir, encoding: 'utf8' });
  const errors = r.stdout.split('\n').filter((l) => / error TS\d+/.test(l));
  check(r.status !== 0, 'tsc accepted bad.ts');
  check(errors.every((l) => l.startsWith('bad.ts(')), `errors outside bad.ts:\n${errors.join('\n')}`);
  const lines = new Set(errors.map((l) => /^bad\.ts\((\d+),/.exec(l)[1]));
  check(['2', '3', '4', '5'].every((n) => lines.has(n)), `tsc found errors on lines ${[...lines]} of bad.ts, not 2-5:\n${errors.join('\n')}`);
  check(existsSync(path.join(ctx.dir, 'out/break.js')) && existsSync(path.join(ctx.dir, 'out/game.js')), 'tsc wrote no out/*.js');
});

test('the break example prints the break (node)', () => {
  const out = run('node', ['out/break.js'], { cwd: ctx.dir });
  check(/^breakshot \d+\.\d+\.\d+: \d+ events, at rest at t = [0-9.]+ s$/m.test(out), `no summary line:\n${out}`);
  check(/ball-ball \d+, cushions \d+, pockets \d+/.test(out), 'no counts');
  const lines = out.split('\n').filter((l) => l.includes('cue ball at'));
  check(lines.length === 4, `expected 4 state lines, got ${lines.length}`);
  check(run('node', ['out/break.js'], { cwd: ctx.dir }) === out, 'a second run prints something else');
  ctx.breakSummary = out;
  console.log(out.trimEnd().split('\n').map((l) => '    ' + l).join('\n'));
});

test('the break example gives the native command\'s bytes', () => {
  const file = path.join(root, 'examples/pool/break_8ball.json');
  const inline = run('node', ['out/break.js', '--result'], { cwd: ctx.dir });
  const fromFile = run('node', ['out/break.js', file, '--result'], { cwd: ctx.dir });
  check(inline === fromFile, 'the inline scenario and examples/pool/break_8ball.json differ');
  check(JSON.parse(inline).events.length > 50, 'a break with few events');
  ctx.breakText = inline;
  if (!ctx.native) skip(`no native build (${native})`);
  const nat = execFileSync(ctx.native, ['simulate', file], { encoding: 'utf8', maxBuffer: 64 << 20 });
  check(inline === nat, `the package's result differs from ${ctx.native} simulate (${inline.length} and ${nat.length} bytes)`);
});

test('the package\'s wasm gives the native facade\'s replies byte for byte (web/tests/identity.mjs)', () => {
  const probe = path.join(path.dirname(native), 'web_api_probe');
  if (!existsSync(probe)) skip(`no ${probe}`);
  // the assembled package next to the tarball: its files are as new as their sources
  const engine = path.join(path.dirname(tarball), 'package', 'breakshot.js');
  const out = run('node', [path.join(root, 'web/tests/identity.mjs'), '--probe', probe, '--engine', engine], { cwd: root });
  const last = out.trimEnd().split('\n').pop();
  check(/^[1-9]\d* passed, 0 failed$/.test(last), `identity.mjs: ${last}`);
  console.log(`    ${last}`);
});

test('the game example plays against the AI, in worker threads and inline alike', async () => {
  // the two runs at once (each is mostly one thread)
  const argv = ['out/game.js', '--actions', '3'];
  const [workers, inline] = await Promise.all([runAsync('node', argv, ctx.dir), runAsync('node', [...argv, '--inline'], ctx.dir)]);
  const actions = workers.split('\n').filter((l) => /^\d+: seat [01] /.test(l));
  check(actions.length >= 2, `only ${actions.length} actions:\n${workers}`);
  check(/from the link: \d+ actions, the same state true/.test(workers), 'the game from its link differs');
  check(/^undo: \d+ actions/m.test(workers), 'no undo line');
  check(workers === inline, `worker threads and inline decisions differ:\n${workers}\n---\n${inline}`);
  console.log(workers.trimEnd().split('\n').map((l) => '    ' + l).join('\n'));
});

let api = null;
test('the package imports by its path (its API for the checks below)', async () => {
  api = await import(pathToFileURL(path.join(ctx.pkg, 'index.js')).href);
  check(api.version === version, `version ${api.version}`);
  ctx.api = api;
});

registerApi(test, ctx);

test('the HTML example draws a break in Chromium, its AI in a Web Worker', async () => {
  for (const f of ['index.html', 'break.js']) copyFileSync(path.join(root, 'npm/examples/html', f), path.join(ctx.dir, f));
  await runBrowser(ctx);
});

for (const { name, fn } of tests) {
  const t0 = Date.now();
  try {
    await fn();
    passed++;
    console.log(`ok    ${name} (${Date.now() - t0} ms)`);
  } catch (e) {
    if (e && e.skip) {
      skipped++;
      console.log(`skip  ${name}: ${e.message}`);
      continue;
    }
    failed++;
    console.log(`FAIL  ${name}: ${e && e.stack ? e.stack : e}`);
  }
}
if (ctx.dir && !args.keep) rmSync(ctx.dir, { recursive: true, force: true });
else if (ctx.dir) console.log(`kept ${ctx.dir}`);
if (skipped) console.log(`${skipped} skipped`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);

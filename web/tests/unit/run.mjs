// Runs the page's unit tests (web/tests/unit/*.test.mjs) with node's test
// runner and ends with the line scripts/test.sh adds up: "N passed, M
// failed". No DOM, no browser, no wasm: the modules of web/page/ that
// hold the tab's logic, imported as they are.
//
//   node web/tests/unit/run.mjs

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const dir = path.dirname(fileURLToPath(import.meta.url));
const files = fs.readdirSync(dir).filter((f) => f.endsWith('.test.mjs')).sort().map((f) => path.join(dir, f));
if (!files.length) {
  console.error(`run.mjs: no *.test.mjs in ${dir}`);
  process.exit(2);
}
const r = spawnSync(process.execPath, ['--test', '--test-reporter=tap', ...files], { encoding: 'utf8' });
process.stdout.write(r.stdout);
process.stderr.write(r.stderr);
const count = (name) => {
  const m = r.stdout.match(new RegExp(`^# ${name} (\\d+)$`, 'm'));
  return m ? Number(m[1]) : null;
};
const pass = count('pass');
const fail = count('fail');
if (pass == null || fail == null) {
  console.error(`run.mjs: node --test gave no summary (exit ${r.status})`);
  console.log(`0 passed, 1 failed`);
  process.exit(1);
}
const failed = fail + (r.status !== 0 && fail === 0 ? 1 : 0);
console.log(`${pass} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);

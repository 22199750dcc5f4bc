// The HTML example (npm/examples/html) in Chromium: the folder where the
// tarball was installed served over HTTP (a small server here: module
// scripts and workers are not loaded from file: URLs), Debian's
// /usr/bin/chromium driven by playwright-core (web/tests's; nothing is
// downloaded; a fresh profile), the page's break checked against node's and the native
// command's bytes, its AI decided in a Web Worker while the canvas kept
// drawing, and a screenshot.
import { createServer } from 'node:http';
import { mkdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json', '.wasm': 'application/wasm' };

function serve(dir) {
  const server = createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    const file = path.join(dir, decodeURIComponent(url.pathname));
    if (!file.startsWith(dir + path.sep)) {
      res.writeHead(403).end();
      return;
    }
    try {
      const body = readFileSync(file);
      res.writeHead(200, { 'content-type': TYPES[path.extname(file)] || 'application/octet-stream' }).end(body);
    } catch (e) {
      res.writeHead(404).end();
    }
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

export async function runBrowser(ctx) {
  const { check } = ctx;
  check(ctx.dir, 'no install');
  let chromium;
  try {
    ({ chromium } = createRequire(path.join(ctx.playwright, 'package.json'))('playwright-core'));
  } catch (e) {
    throw new Error(`playwright-core is not installed in ${ctx.playwright} (cd web/tests && npm ci): ${e.message}`);
  }
  const server = await serve(ctx.dir);
  const url = `http://127.0.0.1:${server.address().port}/index.html?speed=3`;
  // launch() gives Chromium a fresh profile folder of its own (it refuses
  // a --user-data-dir argument) and removes it at close.
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = await browser.newPage({ viewport: { width: 1040, height: 660 } });
    const problems = [];
    // errors, and emscripten's warning that the wasm was not compiled as it streamed in
    page.on('console', (m) => {
      if (m.type() === 'error' || /wasm/i.test(m.text())) problems.push(`console ${m.type()}: ${m.text()}`);
    });
    const wasmRequests = [];
    page.on('request', (r) => { if (r.url().endsWith('.wasm')) wasmRequests.push(r.url()); });
    page.on('pageerror', (e) => problems.push('page error: ' + e.message));
    page.on('requestfailed', (r) => problems.push('request failed: ' + r.url()));
    const origin = new URL(url).origin;
    await page.route('**/*', (route) => {
      const u = route.request().url();
      if (u.startsWith(origin) || u.startsWith('data:') || u.startsWith('blob:')) return route.continue();
      problems.push('request outside the server: ' + u);
      return route.abort();
    });
    await page.goto(url);
    try {
      await page.waitForFunction(() => window.example && (window.example.error || (window.example.done && window.example.aiAction)),
        null, { timeout: 60000 });
    } catch (e) {
      const seen = await page.evaluate(() => JSON.stringify(window.example || null, (k, v) => (k === 'text' ? undefined : v)));
      throw new Error(`${e.message}\nthe page: ${seen}\n${problems.join('\n')}`);
    }
    const ex = await page.evaluate(() => window.example);
    check(!ex.error, `the page's AI failed: ${ex.error}`);
    check(problems.length === 0, problems.join('\n'));
    check(ex.version === ctx.version, `version ${ex.version}`);
    // the wasm file next to its loader (the page's engine; the worker's may come from the cache)
    check(wasmRequests.length >= 1 && wasmRequests.every((u) => u.endsWith('/node_modules/breakshot/breakshot-wasm.wasm')),
      `the wasm requests: ${wasmRequests.join(', ')}`);
    check(ex.text === ctx.breakText, 'the page\'s break differs from node\'s (and so from the native command\'s)');
    const sim = ctx.api.simulate(readFileSync(path.join(ctx.root, 'examples/pool/break_8ball.json'), 'utf8'));
    const final = Array.from(sim.states(sim.duration).position);
    sim.free();
    check(ex.final.length === 32 && ex.final.every((v, i) => Object.is(v, final[i])), 'the page\'s final states differ from node\'s');
    check(ex.frames >= 10, `only ${ex.frames} frames drawn`);
    check(ex.framesWhileThinking >= 1, 'no frame was drawn while the AI decided: the page blocked');
    check(['shoot', 'place_cue_ball'].includes(ex.aiAction.type), `the AI's action ${JSON.stringify(ex.aiAction)}`);
    // the drawing: the cloth's green and balls on it
    const pixels = await page.evaluate(() => {
      const c = document.getElementById('table');
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let green = 0;
      let light = 0;
      for (let i = 0; i < d.length; i += 4) {
        if (d[i + 1] > 90 && d[i] < 40 && d[i + 2] < 80) green++;
        if (d[i] > 200 && d[i + 1] > 200 && d[i + 2] > 200) light++;
      }
      return { green, light, total: d.length / 4 };
    });
    check(pixels.green > pixels.total * 0.4, `the cloth covers ${pixels.green} of ${pixels.total} pixels`);
    check(pixels.light > 50, 'no white ball drawn');
    mkdirSync(ctx.shots, { recursive: true });
    await page.screenshot({ path: path.join(ctx.shots, 'npm-break.png') });
    console.log(`    ${ex.frames} frames (${ex.framesWhileThinking} while the AI decided); the AI: ${JSON.stringify(ex.aiAction).slice(0, 120)}`);
    console.log(`    screenshot: ${path.join(ctx.shots, 'npm-break.png')}`);
  } finally {
    await browser.close();
    server.close();
  }
}

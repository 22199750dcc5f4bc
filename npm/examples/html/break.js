// A canvas that draws an 8-ball break (index.html): the break simulated
// with simulate(), its balls drawn from states(t) at every animation
// frame, the table from a Game's table(). Meanwhile a Player decides a
// break for the same game in a Web Worker, so the animation never stops.
// ?speed=K plays the break K times faster. window.example holds what the
// page did (npm/tests/browser.mjs reads it).
import { simulate, Game, Player, version } from 'breakshot';

const speed = Number(new URLSearchParams(location.search).get('speed') || 1);
const canvas = document.getElementById('table');
const ctx = canvas.getContext('2d');
const status = document.getElementById('status');
const example = { version, frames: 0, framesWhileThinking: 0, done: false, error: null };
window.example = example;

const game = new Game({ game: 'eight_ball', players: ['human', 'club'], seed: 1 });
const table = game.table();
const sim = simulate({
  physics: { model: 'pool', ball_clusters: true },
  table: { shape: 'pool', size: table.size },
  rack: { game: 'eight_ball', seed: 1 },
  cue: { ball: 'cue', speed: 7.5, phi: 0.0, theta: 0.0, a: 0.0, b: 0.0 },
});
example.text = sim.text;
const ids = sim.ids;

// Table metres to canvas pixels: y up.
const margin = 40;
const scale = Math.min((canvas.width - 2 * margin) / table.length, (canvas.height - 2 * margin) / table.width);
const px = (x) => margin + x * scale;
const py = (y) => canvas.height - margin - y * scale;

const colours = ['#f4f4f0', '#f2c200', '#1f4fd0', '#d42020', '#5a2a8a', '#f07a10', '#1a8a3a', '#7a1e1e', '#101010'];
function colour(id) {
  const n = Number(id);
  if (!Number.isInteger(n)) return colours[0];
  return colours[n > 8 ? n - 8 : n];
}

function drawTable() {
  ctx.fillStyle = '#4a2c17';  // the rails
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = '#0f6b3a';  // the cloth: the cushions' outline, the pockets' mouths included
  ctx.beginPath();
  table.outline.forEach(([x, y], i) => (i ? ctx.lineTo(px(x), py(y)) : ctx.moveTo(px(x), py(y))));
  ctx.closePath();
  ctx.fill();
  ctx.fillStyle = '#050505';
  for (const p of table.pockets) {
    ctx.beginPath();
    ctx.arc(px(p.centre[0]), py(p.centre[1]), p.radius * scale, 0, 2 * Math.PI);
    ctx.fill();
  }
}

function drawBalls(s) {
  const r = table.ball_radius * scale;
  for (let i = 0; i < s.count; i++) {
    if (!s.onTable[i]) continue;
    const x = px(s.position[2 * i]);
    const y = py(s.position[2 * i + 1]);
    ctx.fillStyle = colour(ids[i]);
    ctx.beginPath();
    ctx.arc(x, y, r, 0, 2 * Math.PI);
    ctx.fill();
    if (Number(ids[i]) > 8) {  // stripes: a white band
      ctx.fillStyle = '#f4f4f0';
      ctx.fillRect(x - r * 0.9, y - r * 0.35, r * 1.8, r * 0.7);
    }
  }
}

let states;
let thinking = false;
const start = performance.now();
function draw(now) {
  // (an animation frame's time may be a little before `start`)
  const t = Math.min(Math.max(0, ((now - start) / 1000) * speed), sim.duration);
  states = sim.states(t, states);
  drawTable();
  drawBalls(states);
  example.frames++;
  if (thinking) example.framesWhileThinking++;
  status.textContent = `breakshot ${version}: t = ${t.toFixed(2)} s, ${states.events} of ${sim.events.length} events`;
  if (t < sim.duration || thinking) {
    requestAnimationFrame(draw);
  } else {
    example.final = Array.from(states.position);
    example.done = true;
  }
}
requestAnimationFrame(draw);

// The AI's break, decided in a worker while the break plays.
const player = new Player('club');
thinking = true;
player.decide(game).then((action) => {
  example.aiAction = action;
  document.getElementById('ai').textContent = action.type === 'shoot'
    ? `the club player would break at ${action.strike.speed.toFixed(2)} m/s, phi ${action.strike.phi.toFixed(2)} degrees`
    : `the club player's first action: ${action.type}`;
}, (e) => {
  example.error = e.message;
}).finally(() => {
  thinking = false;
  player.close();
});

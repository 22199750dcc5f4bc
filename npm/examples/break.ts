// An 8-ball break: simulated, its events printed, the balls' states at
// a few times. Run from a folder where breakshot is installed:
//
//   node break.js              a summary of the break
//   node break.js --result     the result file's text (`breakshot simulate`'s bytes)
//   node break.js FILE.json    another scenario
import { readFileSync } from 'node:fs';
import { simulate, version } from 'breakshot';
import type { Scenario, SimEvent, States } from 'breakshot';

const args = process.argv.slice(2);
const file = args.find((a) => !a.startsWith('--'));
const scenario: Scenario | string = file !== undefined ? readFileSync(file, 'utf8') : {
  physics: { model: 'pool', ball_clusters: true },
  table: { shape: 'pool', size: '9ft' },
  rack: { game: 'eight_ball', seed: 1 },
  cue: { ball: 'cue', speed: 7.5, phi: 0.0, theta: 0.0, a: 0.0, b: 0.0 },
};

const sim = simulate(scenario);
try {
  if (args.includes('--result')) {
    process.stdout.write(sim.text);
  } else {
    console.log(`breakshot ${version}: ${sim.events.length} events, at rest at t = ${sim.duration} s`);
    const count = (type: string): number => sim.events.filter((e: SimEvent) => e.type === type).length;
    console.log(`ball-ball ${count('ball_ball')}, cushions ${count('ball_cushion')}, pockets ${count('ball_pocket')}`);
    for (const e of sim.events.filter((ev: SimEvent) => ev.type === 'ball_pocket')) {
      console.log(`  t = ${e.time.toFixed(4)} s: ball ${e.balls[0]} into ${e.pocket}`);
    }
    // The states at times in any order, into one reused States.
    let s: States | undefined;
    for (const t of [0.5, 1.0, 0.25, sim.duration]) {
      s = sim.states(t, s);
      const i = sim.ids.indexOf('cue');
      console.log(`  t = ${t.toFixed(4)} s: cue ball at (${s.position[2 * i].toFixed(4)}, ${s.position[2 * i + 1].toFixed(4)}),` +
        ` ${s.events} events so far, energy ${s.energy.toFixed(6)} J`);
    }
    const frame = sim.frame(sim.duration);
    console.log(`  the last frame: ${frame.balls.length} balls, at rest ${frame.at_rest}`);
  }
} finally {
  sim.free();
}

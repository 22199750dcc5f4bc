// The lab's playback loop: one step of the run (lab-run.js) per animation
// frame, at the speed the lab chooses, with pause, finish and reset.
//
//   const player = new Player({speed, frame, stop});
//     speed(): simulated seconds per real second
//     frame(): after each animation frame (the lab draws)
//     stop(error): the run has ended (error: a message, or null)
//   const f0 = player.begin(engine, pb, sc); player.play();

import { newRun, startRun, stepRun, freePlaybacks } from './lab-run.js';
import { errText } from './lab-dom.js';

export class Player {
  constructor(hooks) {
    this.hooks = hooks;
    this.run = null;     // the current run (lab-run.js), null in the setup
    this.frames = 0;     // animation frames drawn since the run began
    this.rafId = 0;
    this.tick = this.tick.bind(this);
  }

  // Whether an animation frame is pending.
  animating() { return this.rafId !== 0; }

  // A new run of `sc` on playback `pb`, sampled at t = 0; returns that frame.
  begin(engine, pb, sc) {
    this.run = newRun(engine, pb, sc);
    this.frames = 0;
    return startRun(this.run);
  }

  play() { this.rafId = requestAnimationFrame(this.tick); }

  tick(now) {
    this.rafId = 0;
    const run = this.run;
    if (!run || run.paused || run.done) return;
    try {
      const { stop, error } = stepRun(run, now, this.hooks.speed());
      if (stop) this.hooks.stop(error);
    } catch (e) {
      this.hooks.stop(`The engine stopped: ${errText(e)}`);
    }
    this.frames++;
    this.hooks.frame();
    if (this.run && !this.run.done && !this.run.paused) this.rafId = requestAnimationFrame(this.tick);
  }

  // Ends the run, which keeps its last frame; false when there is none.
  finish() {
    if (!this.run) return false;
    this.run.done = true;
    freePlaybacks(this.run);
    if (this.rafId) { cancelAnimationFrame(this.rafId); this.rafId = 0; }
    return true;
  }

  // Pauses or resumes a run that has not ended; false when there is none.
  togglePause() {
    const run = this.run;
    if (!run || run.done) return false;
    run.paused = !run.paused;
    run.last = null;
    if (!run.paused && !this.rafId) this.rafId = requestAnimationFrame(this.tick);
    return true;
  }

  // Back to the setup: no run.
  reset() {
    if (this.rafId) { cancelAnimationFrame(this.rafId); this.rafId = 0; }
    if (this.run) { freePlaybacks(this.run); this.run = null; }
    this.frames = 0;
  }
}

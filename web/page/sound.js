// The game's sounds, made in the page with WebAudio (nothing is
// downloaded): the cue tip, ball on ball, ball on cushion and a ball into
// a pocket, each as loud as the impact was hard. The impact speeds come
// from the engine's states around each event (game.js); this file only
// makes noise. Muted or without an audio device (a headless browser), the
// page works the same: sounds are still counted (the tests read the
// count), and nothing is played.

const STORE = 'breakshot.sound';   // localStorage: "off" when muted
const MAX_PER_FRAME = 8;           // a break's first frame has dozens of contacts

// Impact speeds (m/s) that make a full-strength sound of each kind.
const FULL = { cue: 12, ball: 5, cushion: 3, pocket: 2.5 };

function stored() {
  try {
    return window.localStorage.getItem(STORE);
  } catch (e) {
    return null;  // storage refused (a sandboxed frame)
  }
}

export class Sounds {
  constructor() {
    this.muted = stored() === 'off';
    this.ctx = null;
    this.failed = false;
    this.noise = null;
    this.master = null;
    // what was asked for: {kind, speed, gain, played} (the tests read it)
    this.log = [];
    this.counts = { cue: 0, ball: 0, cushion: 0, pocket: 0 };
    this.frameCount = 0;
  }

  setMuted(m) {
    this.muted = !!m;
    try {
      window.localStorage.setItem(STORE, this.muted ? 'off' : 'on');
    } catch (e) { /* not remembered */ }
    if (this.muted && this.ctx && this.ctx.state === 'running') this.ctx.suspend().catch(() => {});
    if (!this.muted) this.unlock();
  }

  /** Makes (or resumes) the audio context; called on a user gesture, as
   *  browsers require before a page may play. */
  unlock() {
    if (this.muted || this.failed) return;
    try {
      if (!this.ctx) {
        const AC = window.AudioContext || window.webkitAudioContext;
        if (!AC) { this.failed = true; return; }
        this.ctx = new AC({ latencyHint: 'interactive' });
        this.master = this.ctx.createGain();
        this.master.gain.value = 0.8;
        // a soft limiter: a break's many clicks at once must not clip
        const comp = this.ctx.createDynamicsCompressor();
        comp.threshold.value = -12;
        comp.ratio.value = 6;
        this.master.connect(comp);
        comp.connect(this.ctx.destination);
        const n = Math.floor(this.ctx.sampleRate * 0.5);
        this.noise = this.ctx.createBuffer(1, n, this.ctx.sampleRate);
        const d = this.noise.getChannelData(0);
        // a fixed pseudo-random sequence (no Math.random anywhere in the page)
        let x = 0x9e3779b9;
        for (let i = 0; i < n; i++) {
          x ^= x << 13; x ^= x >>> 17; x ^= x << 5;
          d[i] = ((x >>> 0) / 4294967296) * 2 - 1;
        }
      }
      if (this.ctx.state === 'suspended') this.ctx.resume().catch(() => {});
    } catch (e) {
      this.failed = true;
      this.ctx = null;
    }
  }

  /** A new animation frame: the per-frame budget starts again. */
  newFrame() { this.frameCount = 0; }

  /** A sound of `kind` ("cue", "ball", "cushion", "pocket") for an impact
   *  at `speed` m/s, `delay` seconds from now. */
  play(kind, speed, delay = 0) {
    if (!(kind in FULL)) return;
    const v = Math.max(0, Number(speed) || 0);
    const gain = Math.min(1, Math.pow(v / FULL[kind], 0.8));
    if (gain < 0.02) return;            // a touch: silent
    if (this.frameCount >= MAX_PER_FRAME) return;
    this.frameCount += 1;
    const entry = { kind, speed: v, gain, played: false };
    this.counts[kind] += 1;
    this.log.push(entry);
    if (this.log.length > 400) this.log.splice(0, this.log.length - 400);
    if (this.muted || this.failed || !this.ctx || this.ctx.state !== 'running') return;
    try {
      const t = this.ctx.currentTime + 0.005 + Math.max(0, Math.min(0.05, delay));
      this[kind](t, gain);
      entry.played = true;
    } catch (e) { /* an audio graph that failed: silence */ }
  }

  // ---- the voices ----

  env(t, peak, decay, attack = 0.0015) {
    const g = this.ctx.createGain();
    g.gain.setValueAtTime(0.0001, t);
    g.gain.linearRampToValueAtTime(peak, t + attack);
    g.gain.exponentialRampToValueAtTime(0.0001, t + attack + decay);
    g.connect(this.master);
    return g;
  }

  tone(t, freq, peak, decay, type = 'sine', endFreq = null) {
    const o = this.ctx.createOscillator();
    o.type = type;
    o.frequency.setValueAtTime(freq, t);
    if (endFreq) o.frequency.exponentialRampToValueAtTime(endFreq, t + decay);
    o.connect(this.env(t, peak, decay));
    o.start(t);
    o.stop(t + decay + 0.02);
  }

  burst(t, filterType, freq, q, peak, decay, offset = 0) {
    const src = this.ctx.createBufferSource();
    src.buffer = this.noise;
    const f = this.ctx.createBiquadFilter();
    f.type = filterType;
    f.frequency.value = freq;
    f.Q.value = q;
    src.connect(f);
    f.connect(this.env(t, peak, decay));
    src.start(t, offset % 0.4);
    src.stop(t + decay + 0.02);
  }

  // phenolic on phenolic: a bright, very short click
  ball(t, g) {
    this.tone(t, 3900, 0.5 * g, 0.035);
    this.tone(t, 2350, 0.35 * g, 0.05);
    this.burst(t, 'bandpass', 5200, 1.2, 0.35 * g, 0.012, g * 0.1);
  }

  // rubber and cloth: a dull thump
  cushion(t, g) {
    this.tone(t, 170, 0.55 * g, 0.09, 'sine', 90);
    this.burst(t, 'lowpass', 900, 0.7, 0.3 * g, 0.05, 0.2);
  }

  // the drop, then the ball rattling down the pocket
  pocket(t, g) {
    this.tone(t, 110, 0.6 * g, 0.22, 'sine', 60);
    this.burst(t, 'lowpass', 700, 0.8, 0.45 * g, 0.12, 0.1);
    this.burst(t + 0.07, 'bandpass', 2200, 3, 0.25 * g, 0.03, 0.3);
    this.burst(t + 0.13, 'bandpass', 1800, 3, 0.18 * g, 0.03, 0.05);
  }

  // leather tip on the cue ball: a short, woody tock
  cue(t, g) {
    this.tone(t, 1150, 0.35 * g, 0.03, 'triangle');
    this.burst(t, 'bandpass', 1600, 1.5, 0.5 * g, 0.025, 0.25);
  }
}

// A run of the lab: the engine's playbacks of the scenario and what the
// lab keeps of them (the latest frame, the traces, the energy history and
// the momentum scales), as a plain object. Every number comes from
// pb.frame(t); advance() samples just before and at every event, so that
// traces turn exactly at the collisions and the energy graph jumps where
// the energy does.
//
//   run = newRun(engine, pb, sc); startRun(run);   // sample t = 0
//   stepRun(run, now, speed) -> {stop, error}       // once per animation frame
//   freePlaybacks(run)

import { untilOf } from './lab-scenario.js';
import { niceCeil, fmtSI } from './lab-format.js';

// Per-ball traces, per-ball energy lines and event-exact sampling are kept
// up to this many balls; beyond it only the total energy is plotted.
export const TRACE_LIMIT = 20;
// History points kept before thinning by half.
const MAX_POINTS = 40000;
// Events in one animation frame beyond which the frame is not split at each event.
const MAX_EVENT_SAMPLES = 64;

// A run of scenario `sc` on playback `pb` (engine.playback(sc)); a second
// playback runs ahead to find the events, up to TRACE_LIMIT balls.
export function newRun(engine, pb, sc) {
  const n = sc.balls.length;
  let ahead = null;
  if (n <= TRACE_LIMIT) {
    try { ahead = engine.playback(sc); } catch (e) { ahead = null; }
  }
  const { T, rest } = untilOf(sc);
  return {
    pb, ahead, sc, n, T, rest, pool: sc.physics.model === 'pool',
    t: 0, sampled: -Infinity, last: null, paused: false, done: false,
    frame: null, aheadEvents: 0,
    traces: n <= TRACE_LIMIT ? Array.from({ length: n }, () => []) : null,
    hist: { t: [], E: [], e: n <= TRACE_LIMIT ? Array.from({ length: n }, () => []) : null },
    eMax: 0, pRef: 0, pSys: 0,
  };
}

// Samples t = 0 and sets the momentum scales; returns the frame.
export function startRun(run) {
  const f0 = sample(run, 0);
  run.frame = f0;
  run.t = 0;
  setMomentumScale(run, f0);
  return f0;
}

// The scales of the momentum arrows: pRef for the balls', pSys for the system's.
function setMomentumScale(run, f) {
  let m = 0;
  for (const b of f.balls) m = Math.max(m, Math.hypot(b[6], b[7]));
  run.pRef = m > 0 ? niceCeil(m) : 0;
  const P = Math.hypot(f.momentum[0], f.momentum[1]);
  run.pSys = Math.max(run.n <= TRACE_LIMIT ? run.pRef : 0, P > 0 ? niceCeil(P) : 0);
}

function sample(run, t) {
  const f = run.pb.frame(t);
  run.sampled = t;
  const h = run.hist;
  h.t.push(f.t ?? t);
  h.E.push(f.energy);
  let eMax = Math.max(run.eMax, f.energy);
  if (h.e) {
    for (let i = 0; i < run.n; i++) {
      const e = f.balls[i][5];
      h.e[i].push(e);
      if (e > eMax) eMax = e;
    }
  }
  run.eMax = eMax;
  if (run.traces) {
    for (let i = 0; i < run.n; i++) {
      const b = f.balls[i];
      if (b[2]) run.traces[i].push(b[0], b[1]);
    }
  }
  if (h.t.length > MAX_POINTS) thin(run);
  return f;
}

function thin(run) {
  const h = run.hist;
  const keep = (a) => a.filter((_, k) => k % 2 === 0 || k === a.length - 1);
  h.t = keep(h.t); h.E = keep(h.E);
  if (h.e) h.e = h.e.map(keep);
  if (run.traces) {
    run.traces = run.traces.map((tr) => {
      if (tr.length <= 2 * MAX_POINTS) return tr;
      const out = [];
      for (let k = 0; k < tr.length; k += 4) out.push(tr[k], tr[k + 1]);
      out.push(tr[tr.length - 2], tr[tr.length - 1]);
      return out;
    });
  }
}

// Moves the run to `target`, sampling just before and at every event on
// the way (found by the look-ahead playback) so that traces turn exactly
// at the collisions and the energy graph jumps where the energy does.
function advance(run, target) {
  const times = [];
  if (run.ahead) {
    const fa = run.ahead.frame(target);
    if (fa.events > run.aheadEvents) {
      if (fa.events - run.aheadEvents <= MAX_EVENT_SAMPLES) {
        const reply = run.ahead.events(run.aheadEvents);
        const evs = Array.isArray(reply) ? reply : (reply && reply.events) || [];
        for (const ev of evs) {
          const te = ev && ev.time;
          if (Number.isFinite(te) && te > run.t && te <= target && !(times.length && te <= times[times.length - 1])) {
            times.push(te);
          }
        }
      }
      run.aheadEvents = fa.events;
    }
  }
  const list = [];
  const push = (t) => { if (t > (list.length ? list[list.length - 1] : run.sampled)) list.push(t); };
  if (run.pool && run.traces) {
    // Curved paths: a few evenly spaced points between frames too.
    const steps = 3;
    const t0 = run.t;
    let k = 0;
    for (let s = 1; s < steps; s++) {
      const ts = t0 + ((target - t0) * s) / steps;
      while (k < times.length && times[k] <= ts) { push(times[k] - Math.abs(times[k]) * 1e-12); push(times[k]); k++; }
      push(ts);
    }
    while (k < times.length) { push(times[k] - Math.abs(times[k]) * 1e-12); push(times[k]); k++; }
  } else {
    for (const te of times) { push(te - Math.abs(te) * 1e-12); push(te); }
  }
  push(target);
  let f = run.frame;
  for (const t of list) f = sample(run, t);
  run.frame = f;
  run.t = target;
  if (run.pRef === 0 || run.pSys === 0) setMomentumScale(run, f);
  const P = Math.hypot(f.momentum[0], f.momentum[1]);
  if (P > run.pSys) run.pSys = niceCeil(P);
}

// One animation frame at time `now` (ms): advances by the real time since
// the last one (at most 0.1 s) times `speed`. Returns whether the run has
// ended (its time, rest, or the engine's max_events guard, with a message).
export function stepRun(run, now, speed) {
  if (run.last == null) run.last = now;
  const dt = Math.min(Math.max(now - run.last, 0), 100) / 1000;
  run.last = now;
  let target = run.t + dt * speed;
  if (run.T != null && target >= run.T) target = run.T;
  if (target > run.t) advance(run, target);
  if (run.frame && run.frame.complete === false) {
    return { stop: true, error: `The run stopped at the max_events guard, after ${run.frame.events} events, at t = ${fmtSI(run.frame.t ?? run.t, 's', 6)}.` };
  }
  if (run.T != null && run.t >= run.T) return { stop: true, error: null };
  if (run.rest && run.frame && run.frame.at_rest) return { stop: true, error: null };
  return { stop: false, error: null };
}

export function freePlaybacks(run) {
  if (!run) return;
  for (const k of ['pb', 'ahead']) {
    if (run[k]) { try { run[k].free(); } catch (e) { /* ignore */ } run[k] = null; }
  }
}

// The stroke: the cue's speed from the power slider, the keys, or the
// cue drawn back on the table (pull-to-speed), and the geometry of a
// press that takes the stick. Numbers only, no DOM: node imports it for
// the page's unit tests (web/tests/unit/).

export const MIN_SPEED = 0.3;
export const MAX_SPEED = 10;
export const DEFAULT_SPEED = 3;
// The drag-back stroke: the cue drawn back PULL_MAX (m, on the table)
// gives MAX_SPEED, none MIN_SPEED, linearly between; a pull under
// MIN_PULL on release strikes nothing. The stick drawn while aiming is
// drawn back by the pull of the speed set.
export const PULL_MAX = 0.35;
export const MIN_PULL = 0.01;
export const STRIKE_MS = 90;      // the stick's push through on release
export const STICK_REACH = 0.7;   // how far behind the cue ball a press takes the stick (m)

/** The speed (m/s) of a stroke drawn back `pull` metres, in the slider's steps. */
export function speedFromPull(pull) {
  const f = Math.max(0, Math.min(1, pull / PULL_MAX));
  return Math.round((MIN_SPEED + (MAX_SPEED - MIN_SPEED) * f) * 20) / 20;
}

/** The pull (m) that gives `speed`. */
export function pullFromSpeed(speed) {
  return PULL_MAX * Math.max(0, Math.min(1, (speed - MIN_SPEED) / (MAX_SPEED - MIN_SPEED)));
}

/** The #power slider's value is the cue speed in m/s. */
export function speedFromPower(p) {
  const v = Number(p);
  if (!Number.isFinite(v)) return DEFAULT_SPEED;
  return Math.max(MIN_SPEED, Math.min(MAX_SPEED, v));
}

export function powerFromSpeed(s) {
  return Math.max(MIN_SPEED, Math.min(MAX_SPEED, s));
}

/** An angle in degrees in [0, 360). */
export function normDeg(phi) {
  let p = phi % 360;
  if (p < 0) p += 360;
  return p;
}

/** The aim (degrees) from `from` toward `to`, or null when they meet. */
export function aimToward(from, to) {
  const dx = to.x - from.x;
  const dy = to.y - from.y;
  if (Math.hypot(dx, dy) < 1e-4) return null;
  return normDeg((Math.atan2(dy, dx) * 180) / Math.PI);
}

/** The stroke's pull (m): how far the pointer at `p` has gone back along
 *  the aim `phi` (degrees) from where it pressed (`from`), in [0, PULL_MAX]. */
export function strokePull(phi, from, p) {
  const rad = (phi * Math.PI) / 180;
  const back = -((p.x - from.x) * Math.cos(rad) + (p.y - from.y) * Math.sin(rad));
  return Math.max(0, Math.min(PULL_MAX, back));
}

/** A press at p takes the cue (starts a drag-back stroke): on the cue
 *  ball within `grab` (unless it is in hand: then a press on it moves
 *  it), or on the stick behind it (aim `phi`, ball radius R). */
export function onStick(p, cue, phi, R, grab, placing) {
  const rad = (phi * Math.PI) / 180;
  const ux = Math.cos(rad);
  const uy = Math.sin(rad);
  const dx = p.x - cue.x;
  const dy = p.y - cue.y;
  if (!placing && Math.hypot(dx, dy) <= grab) return true;
  const back = -(dx * ux + dy * uy);      // distance behind the ball, along the stick
  const side = Math.abs(dx * uy - dy * ux);
  return back > R && back < STICK_REACH && side <= Math.max(grab * 0.8, R);
}

/** How far the stick is drawn back (m) `f` (0..1) of the way through
 *  its push after a release of `pull`: through the ball at the end. */
export function strikePull(pull, f) {
  const k = Math.min(1, f);
  return pull * (1 - k * k) - 0.004 * k;
}

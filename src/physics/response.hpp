// Rules every collision response follows (collide_balls.cpp,
// collide_walls.cpp), so that the loop never stalls: docs/physics-core.md,
// "Rules that keep the loop going".
#pragma once

namespace breakshot::detail {

// The separating normal speed after an impact with closing speed
// `closing`. Inelastic collapse (Luding & McNamara 1998; McNamara &
// Falcon 2005 use a restitution that tends to 1 at low impact speed): an
// impact slower than collapse_speed is elastic, so a cluster cannot make
// infinitely many ever-softer collisions in finite time. It never adds
// energy: the result is at most `closing`.
inline double outgoing_speed(double closing, double restitution, double collapse_speed) {
  if (closing <= 0.0) return 0.0;
  if (closing < collapse_speed) return closing;
  return restitution * closing;
}

// True if a contact left at normal speed `out` with normal acceleration
// `acc_n` (negative: back into contact) closes again before `window`
// ends, at a speed too low for the collapse rule to end the sequence.
// With the friction model's deceleration a ball never turns back, so a
// single ball leaving a wall is never pressed; two balls whose
// decelerations differ can be.
inline bool pressed(double out, double acc_n, double window, double collapse_speed) {
  if (out >= collapse_speed || !(acc_n < 0.0)) return false;
  return 2.0 * out < -acc_n * window;
}

}  // namespace breakshot::detail

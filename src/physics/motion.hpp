// The motion laws: how a ball moves between its events, per model. Each
// phase of a ball's motion is a polynomial of degree two in time (a
// Simulation::Trajectory); docs/physics-core.md ("Motion between events")
// and docs/physics.md (the pool model's phases) have the equations.
// The evaluations are inline: the predictor and the loop call them for
// every candidate, and the responses start a new phase at every impact.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "breakshot/ball.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/vec.hpp"

namespace breakshot::detail {

using Trajectory = Simulation::Trajectory;

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Does a ball in this state change position?
inline bool translating(MotionState s) {
  return s == MotionState::moving || s == MotionState::sliding || s == MotionState::rolling ||
         s == MotionState::airborne;
}

// Has the ball left play (into a pocket or off the table)?
inline bool out_of_play(MotionState s) {
  return s == MotionState::pocketed || s == MotionState::off_table;
}

// Is a ball in this state done (nothing more will happen by itself)?
inline bool resting(MotionState s) { return s == MotionState::stationary || out_of_play(s); }

// Height above the resting height and vertical velocity: nonzero only in
// flight. The landing (t_end) is exactly at z = 0.
inline double z_at(const Trajectory& tr, double t) {
  if (tr.state != MotionState::airborne || t >= tr.t_end) return 0.0;
  const double dt = t - tr.t0;
  return tr.z0 + tr.vz0 * dt - 0.5 * tr.gravity * dt * dt;
}

inline double vz_at(const Trajectory& tr, double t) {
  if (tr.state != MotionState::airborne) return 0.0;
  return tr.vz0 - tr.gravity * (std::min(t, tr.t_end) - tr.t0);
}

inline Vec2 position_at(const Trajectory& tr, double t) {
  const double dt = std::min(t, tr.t_end) - tr.t0;
  return tr.p0 + tr.v0 * dt + tr.acc * (0.5 * dt * dt);
}

inline Vec2 velocity_at(const Trajectory& tr, double t) {
  if (t >= tr.t_end) {
    // A ball of the friction model stops at t_end; a pool ball's phase
    // ends there with the velocity the phase reached.
    if (tr.state == MotionState::moving) return {};
    t = tr.t_end;
  }
  return tr.v0 + tr.acc * (t - tr.t0);
}

inline Vec3 spin_at(const Trajectory& tr, double t) {
  const double dt = std::min(t, tr.t_end) - tr.t0;
  Vec3 w = tr.w0;
  w.x += tr.alpha.x * dt;
  w.y += tr.alpha.y * dt;
  // w_z decays linearly to zero and stays there.
  const double left = std::max(0.0, std::abs(tr.w0.z) - tr.wz_rate * dt);
  w.z = tr.w0.z < 0.0 ? -left : (tr.w0.z > 0.0 ? left : 0.0);
  return w;
}

inline BallState state_at(const Trajectory& tr, double t) {
  BallState s;
  s.position = position_at(tr, t);
  s.velocity = velocity_at(tr, t);
  s.spin = spin_at(tr, t);
  s.state = (t >= tr.t_end && tr.state == MotionState::moving) ? MotionState::stationary : tr.state;
  if (tr.state == MotionState::airborne) {
    s.z = z_at(tr, t);
    s.vz = vz_at(tr, t);
  }
  return s;
}

// Moves the origin of the trajectory to t without changing the motion.
void move_to(Trajectory& tr, double t);

// The box that holds the ball's centre from t0 until its motion changes
// by itself (Trajectory::box_lo, box_hi).
void update_box(Trajectory& tr);

// The friction model's deceleration along minus the velocity (zero in
// the other models, which set their own).
inline Vec2 acceleration_for(Vec2 v, const PhysicsParams& ph) {
  if (ph.model == Model::friction) {
    const double s = norm(v);
    if (s > 0.0) return v * (-ph.deceleration / s);
  }
  return {};
}

// The ideal and friction models: constant velocity, or a constant
// deceleration along minus the velocity until the ball stops.
inline void start_plain_motion(Trajectory& tr, Vec2 v, const PhysicsParams& ph) {
  tr.w0 = {};
  tr.acc = acceleration_for(v, ph);
  const double speed = norm(v);
  tr.state = speed > 0.0 ? MotionState::moving : MotionState::stationary;
  if (speed > 0.0 && ph.model == Model::friction && ph.deceleration > 0.0) {
    tr.t_end = tr.t0 + speed / ph.deceleration;
  }
}

// The pool model's phases (docs/physics.md):
//   sliding  contact point slips (u != 0): friction -mu_s m g u/|u| until
//            the slip stops at 2|u| / (7 mu_s g);
//   rolling  u = 0: rolling resistance -mu_r m g v/|v| until the ball
//            stops at |v| / (mu_r g); the spin follows the velocity;
//   spinning in place about z until w_z has decayed;
// and w_z decays at 5 mu_sp g / (2 R) in every state.
inline void start_pool_motion(Trajectory& tr, Vec2 v, Vec3 w, bool rolls,
                              const PhysicsParams& ph, double r) {
  tr.w0 = w;
  tr.wz_rate = 2.5 * ph.spinning_friction * ph.gravity / r;
  const Vec2 u{v.x - r * w.y, v.y + r * w.x};  // slip of the contact point
  const double slip = norm(u);
  const double speed = norm(v);
  // `rolls`: the slip has just stopped. w = z x v / R is exact only up
  // to rounding, so the state is set, not inferred from the slip.
  if (slip > 0.0 && !rolls) {
    tr.state = MotionState::sliding;
    const Vec2 uh = u / slip;
    const double f = ph.sliding_friction * ph.gravity;
    tr.acc = uh * -f;
    tr.alpha = perp(uh) * (2.5 * f / r);
    if (f > 0.0) tr.t_end = tr.t0 + slip / (3.5 * f);
  } else if (speed > 0.0) {
    tr.state = MotionState::rolling;
    const double f = ph.rolling_friction * ph.gravity;
    tr.acc = v * (-f / speed);
    tr.alpha = perp(tr.acc) / r;
    if (f > 0.0) tr.t_end = tr.t0 + speed / f;
  } else if (w.z != 0.0) {
    tr.state = MotionState::spinning;
    if (tr.wz_rate > 0.0) tr.t_end = tr.t0 + std::abs(w.z) / tr.wz_rate;
  } else {
    tr.state = MotionState::stationary;
  }
}

// A flight from tr.t0 on, from tr.p0 at height z >= 0 with vertical
// velocity vz (z > 0 or vz > 0): no friction acts, so the velocity along
// the cloth and the spin stay as they are, and the height is a parabola
// until the landing at z = 0, t_end = t0 + (vz + sqrt(vz^2 + 2 g z)) / g.
inline void start_airborne(Trajectory& tr, Vec2 v, double vz, double z, Vec3 w,
                           const PhysicsParams& ph) {
  tr.v0 = v;
  tr.w0 = w;
  tr.acc = {};
  tr.alpha = {};
  tr.wz_rate = 0.0;
  tr.state = MotionState::airborne;
  tr.z0 = z;
  tr.vz0 = vz;
  tr.gravity = ph.gravity;
  // The positive root of z + vz T - g T^2 / 2 = 0, without cancellation.
  const double root = std::sqrt(vz * vz + 2.0 * ph.gravity * z);
  tr.t_end = tr.t0 + (vz > 0.0 ? (vz + root) / ph.gravity : 2.0 * z / (root - vz));
  update_box(tr);
}

// A new motion from tr.t0 on, from tr.p0 with velocity v and spin w:
// picks the state and the polynomial of the phase for the scenario's
// model, and the box around its path. `rolls` says that a pool ball's
// slip has just stopped.
inline void start_motion(Trajectory& tr, Vec2 v, Vec3 w, bool rolls, const PhysicsParams& ph,
                         double radius) {
  tr.v0 = v;
  tr.acc = {};
  tr.alpha = {};
  tr.wz_rate = 0.0;
  tr.t_end = kInf;
  tr.z0 = 0.0;
  tr.vz0 = 0.0;
  if (ph.model != Model::pool) {
    start_plain_motion(tr, v, ph);
  } else {
    start_pool_motion(tr, v, w, rolls, ph, radius);
  }
  update_box(tr);
}

}  // namespace breakshot::detail

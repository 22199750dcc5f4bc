// The motion laws: the phase a ball's motion is in and its polynomial, for
// each model, and the end of a phase (a state_change event).
#include "physics/motion.hpp"

#include "physics/engine.hpp"

namespace breakshot::detail {


void move_to(Trajectory& tr, double t) {
  if (t == tr.t0) return;
  const Vec2 p = position_at(tr, t);
  const Vec2 v = velocity_at(tr, t);
  const Vec3 w = spin_at(tr, t);
  if (tr.state == MotionState::airborne) {
    const double z = z_at(tr, t);
    tr.vz0 = vz_at(tr, t);
    tr.z0 = z;
  }
  tr.p0 = p;
  tr.v0 = v;
  tr.w0 = w;
  tr.t0 = t;
}

// Widened a little against round-off. Two balls whose boxes stay further
// apart than their radii cannot meet before one of them has an event, so
// most pairs need no quartic at all.
void update_box(Trajectory& tr) {
  if (!translating(tr.state)) {
    tr.box_lo = tr.p0;
    tr.box_hi = tr.p0;
    return;
  }
  if (!(tr.t_end < kInf)) {
    tr.box_lo = {-kInf, -kInf};
    tr.box_hi = {kInf, kInf};
    return;
  }
  const double T = tr.t_end - tr.t0;
  const double p[2] = {tr.p0.x, tr.p0.y};
  const double v[2] = {tr.v0.x, tr.v0.y};
  const double a[2] = {tr.acc.x, tr.acc.y};
  double lo[2], hi[2];
  for (int k = 0; k < 2; ++k) {
    const double end = p[k] + v[k] * T + 0.5 * a[k] * T * T;
    lo[k] = std::min(p[k], end);
    hi[k] = std::max(p[k], end);
    if (a[k] != 0.0) {
      const double s = -v[k] / a[k];
      if (s > 0.0 && s < T) {
        const double x = p[k] + v[k] * s + 0.5 * a[k] * s * s;
        lo[k] = std::min(lo[k], x);
        hi[k] = std::max(hi[k], x);
      }
    }
    const double margin = 1e-9 * (1.0 + std::abs(lo[k]) + std::abs(hi[k]));
    lo[k] -= margin;
    hi[k] += margin;
  }
  tr.box_lo = {lo[0], lo[1]};
  tr.box_hi = {hi[0], hi[1]};
}

// A stop event at time t: the phase ends exactly where its closed-form
// motion ends, and the next one starts. Returns the state the ball left.
MotionState Engine::end_phase(std::int32_t i, double t) {
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& tr = traj_[ui];
  const MotionState from = tr.state;
  Vec2 v = velocity_at(tr, tr.t_end);
  Vec3 w = spin_at(tr, tr.t_end);
  tr.p0 = position_at(tr, tr.t_end);
  tr.t0 = t;
  const double r = radius_[ui];
  switch (from) {
    case MotionState::sliding:  // the slip has stopped: roll exactly
      w.x = -v.y / r;
      w.y = v.x / r;
      break;
    case MotionState::rolling:  // stopped; maybe still spinning
      v = {};
      w.x = 0.0;
      w.y = 0.0;
      break;
    case MotionState::spinning:
      w = {};
      break;
    default:  // the friction model's stop
      v = {};
      break;
  }
  set_motion(i, v, w, from == MotionState::sliding);
  return from;
}

}  // namespace breakshot::detail

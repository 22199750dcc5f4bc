// Prediction against the other balls: every pair, or with the grid of
// cells only the balls of the 3 x 3 cells around the ball's own. For two
// balls the squared distance minus the squared sum of radii is a
// quadratic in time (neither accelerates) or a quartic (roots.cpp). The
// ideal model's quadratic and the choice of partners are inline, in
// predict_balls.hpp.
#include "physics/predict_balls.hpp"

#include <algorithm>
#include <cmath>

#include "physics/roots.hpp"

namespace breakshot::detail {

void Engine::predict_accelerating_pair(const Kinematics& ki, std::int32_t j,
                                       Prediction& best) const {
  // predict_ball_pair has rejected the pairs out of play, both still, or
  // whose paths never come within reach.
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const double sigma = ki.radius + radius_[static_cast<std::size_t>(j)];
  const double t = origin_;
  // B's kinematics at t, inline (this is the innermost loop).
  const double dt = std::min(t, B.t_end) - B.t0;
  const Vec2 pb = B.p0 + B.v0 * dt + B.acc * (0.5 * dt * dt);
  const bool b_moves = t < B.t_end;
  const Vec2 dp = pb - ki.p;
  const Vec2 dv = (b_moves ? B.v0 + B.acc * dt : Vec2{}) - ki.v;
  const Vec2 da = (b_moves ? B.acc : Vec2{}) - ki.a;
  const double dist2 = norm2(dp);
  double tau = kInf;
  if (ki.airborne || B.state == MotionState::airborne) {
    // In three dimensions: the heights of the centres differ by
    // dz(s) = dz + dvz s + daz s^2 / 2 (each ball's radius plus its
    // height; gravity pulls only the one in flight).
    const double window = within_best(best, t, std::max(0.0, std::min(ki.t_end, B.t_end) - t));
    // A phase of B that ends right now (a slip that stops at once) still
    // moves B: its velocity at the end is the one to compare with, or a
    // pair in contact would be seen approaching when it parts.
    const Vec2 dv3 = velocity_at(B, t) - ki.v;
    const double gap = std::sqrt(dist2) - sigma;
    if (gap > 0.0 && window < kInf && norm(dv3) * window + 0.5 * norm(da) * window * window < gap) {
      return;  // even the distance along the cloth stays too large
    }
    const double rb = radius_[static_cast<std::size_t>(j)];
    const bool b_flies = B.state == MotionState::airborne;
    const double dz = (rb + (b_flies ? z_at(B, t) : 0.0)) - (ki.radius + ki.z);
    const double dvz = (b_flies ? vz_at(B, t) : 0.0) - ki.vz;
    const double daz = (b_flies ? -B.gravity : 0.0) + ki.g;
    const double c[5] = {dist2 + dz * dz - sigma * sigma, 2.0 * (dot(dp, dv3) + dz * dvz),
                         norm2(dv3) + dot(dp, da) + dvz * dvz + dz * daz, dot(dv3, da) + dvz * daz,
                         0.25 * (norm2(da) + daz * daz)};
    tau = first_contact(c, 4, window);
    if (!(tau < kInf)) return;
  } else if (da.x == 0.0 && da.y == 0.0) {
    const double b = dot(dp, dv);
    if (b >= 0.0) return;  // moving apart or not at all: never closer
    tau = first_contact_quadratic(dist2 - sigma * sigma, b, norm2(dv));
    if (!(tau <= std::min(ki.t_end, B.t_end) - t)) return;
  } else {
    const double window = within_best(best, t, std::max(0.0, std::min(ki.t_end, B.t_end) - t));
    // Cheap rejection: the gap can close by at most |dv| w + |da| w^2 / 2.
    const double gap = std::sqrt(dist2) - sigma;
    const double w = window;
    if (gap > 0.0 && w < kInf && norm(dv) * w + 0.5 * norm(da) * w * w < gap) return;
    // Bounds on the distance that prove no contact (prediction.hpp).
    if (gap > 0.0 && stays_apart(dp, dv, da, gap + sigma, sigma, w)) return;
    // |dp + dv s + da s^2 / 2|^2 - sigma^2 as a quartic in s.
    const double c[5] = {dist2 - sigma * sigma, 2.0 * dot(dp, dv), norm2(dv) + dot(dp, da),
                         dot(dv, da), 0.25 * norm2(da)};
    tau = first_contact(c, 4, window);
    if (!(tau < kInf)) return;
  }
  consider(best, t + tau, EventKind::ball, j, counter_[static_cast<std::size_t>(j)]);
}

// The balls of cells [x0, x1] x [y0, y1] (clamped to the grid).
void Engine::predict_cells(std::int32_t i, const Kinematics& ki, std::int32_t x0, std::int32_t x1,
                           std::int32_t y0, std::int32_t y1, Prediction& best) const {
  x0 = std::max(0, x0);
  y0 = std::max(0, y0);
  x1 = std::min(grid_.nx() - 1, x1);
  y1 = std::min(grid_.ny() - 1, y1);
  // The candidates first, in the order they are examined, each one's
  // trajectory asked for from memory as it is found: in a large scene
  // they lie far apart in memory, and the loads then overlap instead of
  // each waiting for the last. The order, and so every result, is that
  // of walking the cells' lists directly (which is done past kBatch).
  constexpr int kBatch = 64;
  std::int32_t batch[kBatch];
  int count = 0;
  bool full = false;
  for (std::int32_t y = y0; y <= y1 && !full; ++y) {
    for (std::int32_t x = x0; x <= x1 && !full; ++x) {
      for (std::int32_t j = grid_.first(y * grid_.nx() + x); j >= 0; j = grid_.next(j)) {
        if (j == i) continue;
        if (count == kBatch) {
          full = true;
          break;
        }
        const auto uj = static_cast<std::size_t>(j);
        __builtin_prefetch(&traj_[uj]);
        __builtin_prefetch(reinterpret_cast<const char*>(&traj_[uj]) + 39);  // the line of v0's end
        __builtin_prefetch(&radius_[uj]);
        if (!ideal_) __builtin_prefetch(&sweep_[uj]);
        batch[count++] = j;
      }
    }
  }
  if (!full) {
    for (int k = 0; k < count; ++k) predict_ball_pair(ki, batch[k], best);
    return;
  }
  for (std::int32_t y = y0; y <= y1; ++y) {
    for (std::int32_t x = x0; x <= x1; ++x) {
      for (std::int32_t j = grid_.first(y * grid_.nx() + x); j >= 0; j = grid_.next(j)) {
        if (j != i) predict_ball_pair(ki, j, best);
      }
    }
  }
}

}  // namespace breakshot::detail

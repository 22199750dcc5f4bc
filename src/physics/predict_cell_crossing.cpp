// Prediction of a cell crossing (scenes with a grid of cells): when a
// ball's centre leaves its cell. The loop takes that event
// (event_loop.cpp, take_cell_crossing).
#include <algorithm>

#include "physics/engine.hpp"
#include "physics/prediction.hpp"
#include "physics/roots.hpp"

namespace breakshot::detail {

void Engine::predict_cell_crossing(std::int32_t i, Prediction& best) const {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  if (!translating(A.state)) return;
  const double t = origin_;
  const double window = std::max(0.0, A.t_end - t);
  const Vec2 p = position_at(A, t);
  const Vec2 v = velocity_at(A, t);
  const Vec2 a = t < A.t_end ? A.acc : Vec2{};
  const std::int32_t cell = grid_.cell_of(i);
  const std::int32_t cx = cell % grid_.nx();
  const std::int32_t cy = cell / grid_.nx();
  const double size = grid_.cell_size();
  const double lo[2] = {grid_.origin().x + size * cx, grid_.origin().y + size * cy};
  const double pos[2] = {p.x, p.y};
  const double vel[2] = {v.x, v.y};
  const double acc[2] = {a.x, a.y};
  const std::int32_t idx[2] = {cx, cy};
  const std::int32_t count[2] = {grid_.nx(), grid_.ny()};
  // Direction codes: 0 = +x, 1 = -x, 2 = +y, 3 = -y (as CellGrid's
  // kStepX, kStepY). Leaving a cell is a "contact" of the ball's centre
  // with the cell's edge, found with the same root finder as the
  // collisions.
  for (int axis = 0; axis < 2; ++axis) {
    if (acc[axis] == 0.0) {
      // Straight motion along this axis (always so in the ideal model):
      // the crossing time is a division.
      if (vel[axis] > 0.0 && idx[axis] + 1 < count[axis]) {
        const double tau = std::max(0.0, (lo[axis] + size - pos[axis]) / vel[axis]);
        if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis, 0);
      } else if (vel[axis] < 0.0 && idx[axis] > 0) {
        const double tau = std::max(0.0, (lo[axis] - pos[axis]) / vel[axis]);
        if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis + 1, 0);
      }
      continue;
    }
    if (idx[axis] + 1 < count[axis]) {
      const double c[3] = {lo[axis] + size - pos[axis], -vel[axis], -0.5 * acc[axis]};
      const double tau = first_contact(c, 2, window);
      if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis, 0);
    }
    if (idx[axis] > 0) {
      const double c[3] = {pos[axis] - lo[axis], vel[axis], 0.5 * acc[axis]};
      const double tau = first_contact(c, 2, window);
      if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis + 1, 0);
    }
  }
}

}  // namespace breakshot::detail

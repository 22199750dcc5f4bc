// Prediction: each ball's earliest event, from the time of the last event
// (origin_), never from the clock. The candidates of each kind are
// searched in the files named below; this file puts them together.
#include "physics/engine.hpp"
#include "physics/predict_balls.hpp"
#include "physics/prediction.hpp"

namespace breakshot::detail {

Kinematics Engine::kinematics(std::int32_t i) const {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const double t = origin_;
  Kinematics k;
  k.p = position_at(A, t);
  k.v = velocity_at(A, t);
  k.a = t < A.t_end ? A.acc : Vec2{};
  k.t_end = A.t_end;
  k.radius = radius_[static_cast<std::size_t>(i)];  // the packed copy: no reach into the scenario
  k.still = !translating(A.state);
  k.box_lo = A.box_lo;
  k.box_hi = A.box_hi;
  if (A.state == MotionState::airborne) {
    k.airborne = true;
    k.z = z_at(A, t);
    k.vz = vz_at(A, t);
    k.g = A.gravity;
  }
  return k;
}

void Engine::predict(std::int32_t i) {
  const auto ui = static_cast<std::size_t>(i);
  Prediction best{kInf, EventKind::none, -1, 0};
  if (out_of_play(traj_[ui].state)) {
    event_[ui] = best;
    queue_.set(i, best);
    return;
  }
  const Kinematics ki = kinematics(i);

  // The order does not change the result (consider() breaks ties by kind
  // and index), but each search stops at the best candidate so far, so
  // the cheap ones go first.
  const Trajectory& tr = traj_[ui];
  if (!resting(tr.state) && tr.t_end < kInf) {
    consider(best, tr.t_end, EventKind::stop, -1, 0);
  }
  predict_partners(i, ki, best);  // predict_balls.hpp
  if (!ki.still) {  // a ball in place meets no wall and no pocket
    predict_walls(ki, best);  // predict_walls.cpp
    if (!scenario_.table.pockets.empty()) predict_pockets(ki, best);  // predict_pockets.cpp
  }
  event_[ui] = best;
  finish_prediction(i);
}

}  // namespace breakshot::detail

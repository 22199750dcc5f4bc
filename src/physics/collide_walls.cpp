// Ball-wall collision responses: reflection with the ball's wall
// restitution in the ideal and friction models, the cushion model
// (cushion.cpp: table.cushion_model) in the pool model.
#include <algorithm>
#include <limits>

#include "breakshot/pool.hpp"
#include "physics/engine.hpp"
#include "physics/response.hpp"

namespace breakshot::detail {

void Engine::collide_wall(std::int32_t i, std::int32_t w) {
  if (scenario_.physics.model == Model::pool) {
    if (traj_[static_cast<std::size_t>(i)].state == MotionState::airborne) {
      collide_airborne_wall(i, w);  // engine_airborne.cpp
    } else {
      collide_pool_wall(i, w);
    }
    return;
  }
  Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const Wall& wall = scenario_.table.walls[static_cast<std::size_t>(w)];
  const double vc = scenario_.physics.collapse_speed;
  Vec2 n = wall.normal;
  if (wall.kind != WallKind::segment) {
    n = A.p0 - wall.a;
    const double len = norm(n);
    n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  }
  const Vec2 v = A.v0;
  const double closing = -dot(v, n);
  const double e = scenario_.balls[static_cast<std::size_t>(i)].wall_restitution;
  const double out = outgoing_speed(closing, e, vc);
  double dv = std::max(0.0, closing + out);
  set_velocity(i, v + n * dv);
  // A ball that keeps being pressed into the wall leaves at
  // collapse_speed, as a pressed pair of balls does.
  if (pressed(out, dot(A.acc, n), A.t_end - A.t0, vc)) {
    dv = std::max(0.0, closing + vc);
    set_velocity(i, v + n * dv);
  }
  // As for two balls: leave the wall in the predictor's own arithmetic.
  double extra = 4.0 * std::numeric_limits<double>::epsilon() * std::max(norm(v), vc);
  const Vec2 away = wall.kind != WallKind::segment ? A.p0 - wall.a : wall.normal;
  for (int k = 0; k < 64 && dot(away, A.v0) < 0.0; ++k, extra *= 2.0) {
    dv += extra;
    set_velocity(i, v + n * dv);
  }
}

// The pool model's cushions, with the same collapse and parting rules.
void Engine::collide_pool_wall(std::int32_t i, std::int32_t w) {
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& A = traj_[ui];
  const Wall& wall = scenario_.table.walls[static_cast<std::size_t>(w)];
  Vec2 n = wall.normal;
  if (wall.kind != WallKind::segment) {
    n = A.p0 - wall.a;
    const double len = norm(n);
    n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  }
  const double closing = -dot(A.v0, n);
  const double vc = scenario_.physics.collapse_speed;
  CushionParams cp = scenario_.table.cushion;
  cp.restitution = closing < vc ? 1.0 : scenario_.balls[ui].wall_restitution;
  cp.cloth_friction = scenario_.physics.sliding_friction;  // the same cloth (mathavan_2010)
  const CushionImpact r = cushion_impact(A.v0, A.w0, n, scenario_.balls[ui].mass, radius_[ui], cp);
  set_motion(i, r.velocity, r.spin);
  const double out = dot(A.v0, n);
  if (pressed(out, dot(A.acc, n), A.t_end - A.t0, vc)) set_motion(i, A.v0 + n * (vc - out), A.w0);
  const Vec2 away = wall.kind == WallKind::segment ? wall.normal : A.p0 - wall.a;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() * std::max(norm(A.v0), vc);
  for (int k = 0; k < 64 && dot(away, A.v0) < 0.0; ++k, extra *= 2.0) {
    set_motion(i, A.v0 + n * extra, A.w0);
  }
}

}  // namespace breakshot::detail

// Ball-ball collision responses: the normal impulse of the ideal and
// friction models, the pool model's impact with friction between the
// balls (ball_impact.cpp), and the restitution of each pair.
#include <algorithm>
#include <limits>
#include <utility>

#include "breakshot/pool.hpp"
#include "physics/engine.hpp"
#include "physics/response.hpp"

namespace breakshot::detail {

// Pair restitutions, sorted for binary search at collision time.
void Engine::set_up_pair_restitution() {
  const std::size_t n = scenario_.balls.size();
  std::vector<std::pair<std::uint64_t, double>> pairs;
  for (const PairRestitution& p : scenario_.pair_restitution) {
    const auto a = static_cast<std::uint64_t>(std::min(p.a, p.b));
    const auto b = static_cast<std::uint64_t>(std::max(p.a, p.b));
    pairs.emplace_back(a * n + b, p.restitution);
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [k, e] : pairs) {
    pair_keys_.push_back(k);
    pair_values_.push_back(e);
  }
}

double Engine::pair_restitution(std::int32_t i, std::int32_t j) const {
  if (pair_keys_.empty()) return scenario_.physics.ball_ball_restitution;
  const auto n = static_cast<std::uint64_t>(traj_.size());
  const auto a = static_cast<std::uint64_t>(std::min(i, j));
  const auto b = static_cast<std::uint64_t>(std::max(i, j));
  const auto it = std::lower_bound(pair_keys_.begin(), pair_keys_.end(), a * n + b);
  if (it != pair_keys_.end() && *it == a * n + b) {
    return pair_values_[static_cast<std::size_t>(it - pair_keys_.begin())];
  }
  return scenario_.physics.ball_ball_restitution;
}

void Engine::collide_balls(std::int32_t i, std::int32_t j) {
  if (scenario_.physics.model == Model::pool) {
    collide_pool_balls(i, j);
    return;
  }
  Trajectory& A = traj_[static_cast<std::size_t>(i)];
  Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const double ma = scenario_.balls[static_cast<std::size_t>(i)].mass;
  const double mb = scenario_.balls[static_cast<std::size_t>(j)].mass;
  const double vc = scenario_.physics.collapse_speed;
  Vec2 n = B.p0 - A.p0;
  const double len = norm(n);
  n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  const Vec2 va = A.v0;
  const Vec2 vb = B.v0;
  const double closing = dot(va - vb, n);
  const double reduced = ma * mb / (ma + mb);
  double out = outgoing_speed(closing, pair_restitution(i, j), vc);
  double impulse = std::max(0.0, reduced * (closing + out));
  set_velocity(i, va - n * (impulse / ma));
  set_velocity(j, vb + n * (impulse / mb));
  // A pair that leaves (nearly) together while friction pushes the two
  // into each other would meet again at once, forever. Such a pair leaves
  // at collapse_speed: the only case where an impact may add energy, at
  // most reduced * collapse_speed^2 / 2 (docs/physics-core.md).
  if (pressed(out, dot(B.acc - A.acc, n), std::min(A.t_end, B.t_end) - A.t0, vc)) {
    out = vc;
    impulse = std::max(0.0, reduced * (closing + out));
    set_velocity(i, va - n * (impulse / ma));
    set_velocity(j, vb + n * (impulse / mb));
  }
  // Round-off can leave a pair that should part (or move on together)
  // approaching by a hair in the very arithmetic the predictor uses; it
  // would then collide again at once, forever. Add the least impulse that
  // makes them part in floating point: the energy it adds is of the order
  // of the round-off itself.
  const Vec2 dp = B.p0 - A.p0;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() * std::max({norm(va), norm(vb), vc});
  for (int k = 0; k < 64 && dot(dp, B.v0 - A.v0) < 0.0; ++k, extra *= 2.0) {
    impulse += reduced * extra;
    set_velocity(i, va - n * (impulse / ma));
    set_velocity(j, vb + n * (impulse / mb));
  }
}

// The pool model's impacts: friction between the balls (throw, spin
// transfer), with the same collapse and parting rules as the simpler
// models.
void Engine::collide_pool_balls(std::int32_t i, std::int32_t j) {
  const auto ui = static_cast<std::size_t>(i);
  const auto uj = static_cast<std::size_t>(j);
  Trajectory& A = traj_[ui];
  Trajectory& B = traj_[uj];
  if (A.state == MotionState::airborne || B.state == MotionState::airborne) {
    collide_airborne_balls(i, j);  // engine_airborne.cpp
    return;
  }
  const double ma = scenario_.balls[ui].mass;
  const double mb = scenario_.balls[uj].mass;
  Vec2 n = B.p0 - A.p0;
  const double len = norm(n);
  n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  const double closing = dot(A.v0 - B.v0, n);
  const double vc = scenario_.physics.collapse_speed;
  const double e = closing < vc ? 1.0 : pair_restitution(i, j);
  const PhysicsParams& ph = scenario_.physics;
  const FrictionCurve& curve = ph.ball_ball_friction_curve;
  const BallFriction friction = ph.ball_ball_friction_fit
                                    ? BallFriction{curve.a, curve.b, curve.c}
                                    : BallFriction{ph.ball_ball_friction, 0.0, 0.0};
  const BallImpact r =
      ph.ball_ball_model == BallBallModel::mathavan_2014
          ? ball_ball_impact_mathavan(A.p0, A.v0, A.w0, ma, radius_[ui], B.p0, B.v0, B.w0, mb,
                                      radius_[uj], e, friction, ph.sliding_friction)
          : ball_ball_impact(A.p0, A.v0, A.w0, ma, radius_[ui], B.p0, B.v0, B.w0, mb,
                             radius_[uj], e, friction);
  set_motion(i, r.v1, r.w1);
  set_motion(j, r.v2, r.w2);
  const double reduced = ma * mb / (ma + mb);
  auto push = [&](double dv) {  // extra normal impulse reduced * dv
    const double impulse = reduced * dv;
    set_motion(i, A.v0 - n * (impulse / ma), A.w0);
    set_motion(j, B.v0 + n * (impulse / mb), B.w0);
  };
  const double out = dot(B.v0 - A.v0, n);
  // A pool ball's phase can end within a nanosecond (a tiny slip), while
  // the push goes on in the next phase: any inward push counts here.
  if (pressed(out, dot(B.acc - A.acc, n), kInf, vc)) push(vc - out);
  const Vec2 dp = B.p0 - A.p0;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max({norm(A.v0), norm(B.v0), vc});
  for (int k = 0; k < 64 && dot(dp, B.v0 - A.v0) < 0.0; ++k, extra *= 2.0) push(extra);
}

}  // namespace breakshot::detail

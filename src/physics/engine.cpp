// The event loop: predict each ball's earliest event, pop the earliest of
// all, re-check it, advance only the balls involved, resolve, re-predict.
// docs/architecture.md follows one scenario through this file.
#include <algorithm>
#include <cmath>
#include <limits>

#include "breakshot/pool.hpp"
#include "physics/engine.hpp"
#include "physics/prediction.hpp"

namespace breakshot::detail {

namespace {

// With ball_clusters, the working memory of cluster impacts is reserved at
// set-up for up to this many balls (any pool game); larger scenes grow it
// when a cluster first needs it.
constexpr std::size_t kClusterReserveBalls = 64;

}  // namespace

// ---------------------------------------------------------------------------
// Set-up

Engine::Engine(const Scenario& scenario) : scenario_(scenario) {
  const std::size_t n = scenario_.balls.size();
  traj_.resize(n);
  radius_.resize(n);
  for (std::size_t i = 0; i < n; ++i) radius_[i] = scenario_.balls[i].radius;
  ideal_ = scenario_.physics.model == Model::ideal;
  counter_.assign(n, 0);
  // Room for the events of a typical shot, so that simulating one
  // allocates nothing after set-up (a break has about 100 events).
  events_.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(scenario_.max_events, 64 + 16 * n)));
  if (scenario_.physics.ball_clusters && n <= kClusterReserveBalls) {
    // A cluster holds at most every ball; each impact on one adds an
    // event per pair that touched (about three per ball in a rack), and
    // the events of a spread rack come on top.
    events_.reserve(events_.capacity() + 4 * n);
    const std::size_t pairs = n * (n - 1) / 2;
    cluster_group_.reserve(n);
    cluster_place_.reserve(n);
    cluster_place_index_.reserve(n);
    cluster_bodies_.reserve(n);
    cluster_scratch_.position.reserve(n);
    cluster_scratch_.velocity.reserve(n);
    cluster_scratch_.pairs.reserve(pairs);
    cluster_out_.velocity.reserve(n);
    cluster_out_.touched.reserve(pairs);
  }
  event_.resize(n);
  queue_.reset(n);
  for (std::size_t i = 0; i < n; ++i) {
    Trajectory& tr = traj_[i];
    tr.t0 = 0.0;
    tr.p0 = scenario_.start[i].position;
    tr.w0 = scenario_.start[i].spin;
    tr.state = MotionState::stationary;
    tr.t_end = kInf;
    set_motion(static_cast<std::int32_t>(i), scenario_.start[i].velocity, scenario_.start[i].spin);
  }

  set_up_walls();

  // Pair restitutions, sorted for binary search at collision time.
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

  if (n >= kCellThreshold) {
    // With many balls, the grid of cells.
    double max_r = 0.0;
    for (const BallSpec& b : scenario_.balls) max_r = std::max(max_r, b.radius);
    if (grid_.build(scenario_.table.min, scenario_.table.max, n, max_r)) {
      for (std::size_t i = 0; i < n; ++i) {
        const auto bi = static_cast<std::int32_t>(i);
        grid_.link(bi, grid_.index(traj_[i].p0));
      }
      // Cluster impacts gather the balls within kClusterGap of a member:
      // their cells are at most this many away, one more for a ball on a
      // cell's edge whose crossing falls at the impact's time.
      cluster_reach_ =
          static_cast<std::int32_t>(std::ceil((2.0 * max_r + kClusterGap) / grid_.cell_size())) + 1;
    }
  }

  // The cue strike: the shot's first event, at t = 0. A miscue is
  // reported (cue_result) and not played.
  if (scenario_.cue && scenario_.cue->ball >= 0 &&
      static_cast<std::size_t>(scenario_.cue->ball) < n) {
    const CueSpec& cue = *scenario_.cue;
    const auto ub = static_cast<std::size_t>(cue.ball);
    cue_result_ = strike(cue.strike, scenario_.balls[ub].mass, radius_[ub], cue.params);
    if (!cue_result_->miscue) {
      set_motion(cue.ball, cue_result_->velocity, cue_result_->spin);
      Event ev;
      ev.time = 0.0;
      ev.type = EventType::cue_strike;
      ev.ball = cue.ball;
      events_.push_back(ev);
      ++event_count_;
      ++counter_[ub];
    }
  }

  for (std::size_t i = 0; i < n; ++i) predict(static_cast<std::int32_t>(i));
  queue_.build();
}

// ---------------------------------------------------------------------------
// The state of the balls

std::vector<BallState> Engine::balls() const {
  std::vector<BallState> out;
  out.reserve(traj_.size());
  for (std::size_t i = 0; i < traj_.size(); ++i) out.push_back(ball(i));
  return out;
}

// ---------------------------------------------------------------------------
// Collisions

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

// The separating normal speed after an impact with closing speed
// `closing`. Inelastic collapse (Luding & McNamara 1998; McNamara &
// Falcon 2005 use a restitution that tends to 1 at low impact speed): an
// impact slower than collapse_speed is elastic, so a cluster cannot make
// infinitely many ever-softer collisions in finite time. It never adds
// energy: the result is at most `closing`.
double Engine::outgoing_speed(double closing, double restitution) const {
  if (closing <= 0.0) return 0.0;
  if (closing < scenario_.physics.collapse_speed) return closing;
  return restitution * closing;
}

// True if a contact left at normal speed `out` with normal acceleration
// `acc_n` (negative: back into contact) closes again before `window`
// ends, at a speed too low for the collapse rule to end the sequence.
// With the friction model's deceleration a ball never turns back, so a
// single ball leaving a wall is never pressed; two balls whose
// decelerations differ can be.
bool Engine::pressed(double out, double acc_n, double window) const {
  if (out >= scenario_.physics.collapse_speed || !(acc_n < 0.0)) return false;
  return 2.0 * out < -acc_n * window;
}

// The pool model's impacts: friction between the balls (throw, spin
// transfer) and the cushion model, with the same collapse and parting
// rules as the simpler models.
void Engine::collide_pool_balls(std::int32_t i, std::int32_t j) {
  const auto ui = static_cast<std::size_t>(i);
  const auto uj = static_cast<std::size_t>(j);
  Trajectory& A = traj_[ui];
  Trajectory& B = traj_[uj];
  const double ma = scenario_.balls[ui].mass;
  const double mb = scenario_.balls[uj].mass;
  Vec2 n = B.p0 - A.p0;
  const double len = norm(n);
  n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  const double closing = dot(A.v0 - B.v0, n);
  const double vc = scenario_.physics.collapse_speed;
  const double e = closing < vc ? 1.0 : pair_restitution(i, j);
  const PhysicsParams& ph = scenario_.physics;
  const BallFriction friction = ph.ball_ball_friction_fit
                                    ? BallFriction{}
                                    : BallFriction{ph.ball_ball_friction, 0.0, 0.0};
  const BallImpact r = ball_ball_impact(A.p0, A.v0, A.w0, ma, radius_[ui], B.p0, B.v0, B.w0, mb,
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
  if (pressed(out, dot(B.acc - A.acc, n), kInf)) push(vc - out);
  const Vec2 dp = B.p0 - A.p0;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max({norm(A.v0), norm(B.v0), vc});
  for (int k = 0; k < 64 && dot(dp, B.v0 - A.v0) < 0.0; ++k, extra *= 2.0) push(extra);
}

// An impact of i on j (both moved to t) when more balls lie within
// kClusterGap of them, or of each other, in a chain: the whole cluster is
// resolved at once (cluster_impact.hpp). Returns false, doing nothing,
// for a lone pair or a contact slower than collapse_speed; else applies
// the new velocities (spins unchanged; the pairwise impact on top when
// i and j still close), records a ball_ball event for
// (i, j) and then one for every other pair that exchanged an impulse, and
// predicts again for every ball of the cluster.
bool Engine::collide_cluster(std::int32_t i, std::int32_t j, double t) {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const Vec2 d = B.p0 - A.p0;
  const double len = norm(d);
  if (!(len > 0.0) || dot(A.v0 - B.v0, d) / len < scenario_.physics.collapse_speed) return false;
  std::vector<std::int32_t>& group = cluster_group_;
  group.clear();
  group.push_back(i);
  group.push_back(j);
  const auto n = static_cast<std::int32_t>(traj_.size());
  // Ball k joins when its place at t is within kClusterGap of group
  // member g's. Members are taken in order and, for each, the candidates
  // in increasing index, so the group (and so the result) is the same
  // whether every ball is a candidate or only those of the cells nearby.
  const auto join = [&](std::size_t ug, Vec2 pg, std::int32_t k, Vec2 pk) {
    const auto uk = static_cast<std::size_t>(k);
    if (norm(pk - pg) - radius_[uk] - radius_[ug] < kClusterGap &&
        std::find(group.begin(), group.end(), k) == group.end()) {
      move_to(traj_[uk], t);
      group.push_back(k);
    }
  };
  if (grid_.used()) {
    // Only the balls of the cells within reach: a large scene pays for
    // the balls near the impact, not for all of them.
    std::vector<std::int32_t>& near = cluster_place_index_;
    for (std::size_t g = 0; g < group.size(); ++g) {
      const auto ug = static_cast<std::size_t>(group[g]);
      const Vec2 pg = traj_[ug].p0;
      const std::int32_t cx = grid_.cell_of(group[g]) % grid_.nx();
      const std::int32_t cy = grid_.cell_of(group[g]) / grid_.nx();
      near.clear();
      for (std::int32_t y = std::max(0, cy - cluster_reach_);
           y <= std::min(grid_.ny() - 1, cy + cluster_reach_); ++y) {
        for (std::int32_t x = std::max(0, cx - cluster_reach_);
             x <= std::min(grid_.nx() - 1, cx + cluster_reach_); ++x) {
          for (std::int32_t k = grid_.first(y * grid_.nx() + x); k >= 0; k = grid_.next(k)) {
            if (traj_[static_cast<std::size_t>(k)].state != MotionState::pocketed) {
              near.push_back(k);
            }
          }
        }
      }
      std::sort(near.begin(), near.end());
      for (std::int32_t k : near) {
        join(ug, pg, k, position_at(traj_[static_cast<std::size_t>(k)], t));
      }
    }
  } else {
    // Every ball's place at t, once (pocketed balls are never gathered).
    std::vector<Vec2>& at = cluster_place_;
    at.clear();
    for (std::int32_t k = 0; k < n; ++k) {
      const Trajectory& tk = traj_[static_cast<std::size_t>(k)];
      at.push_back(tk.state == MotionState::pocketed ? Vec2{} : position_at(tk, t));
    }
    for (std::size_t g = 0; g < group.size(); ++g) {
      const auto ug = static_cast<std::size_t>(group[g]);
      const Vec2 pg = traj_[ug].p0;
      for (std::int32_t k = 0; k < n; ++k) {
        if (traj_[static_cast<std::size_t>(k)].state == MotionState::pocketed) continue;
        join(ug, pg, k, at[static_cast<std::size_t>(k)]);
      }
    }
  }
  if (group.size() < 3) return false;
  std::vector<ClusterBody>& bodies = cluster_bodies_;
  bodies.clear();
  for (std::int32_t k : group) {
    const auto uk = static_cast<std::size_t>(k);
    bodies.push_back({traj_[uk].p0, traj_[uk].v0, radius_[uk], scenario_.balls[uk].mass});
  }
  struct Restitution final : ClusterRestitution {
    const Engine* sim;
    const std::vector<std::int32_t>* ids;
    Restitution(const Engine* s, const std::vector<std::int32_t>* g) : sim(s), ids(g) {}
    double at(int a, int b) const override {
      return sim->pair_restitution((*ids)[static_cast<std::size_t>(a)], (*ids)[static_cast<std::size_t>(b)]);
    }
  };
  const Restitution restitution(this, &group);
  ClusterOutcome& r = cluster_out_;
  cluster_impact(bodies, restitution, cluster_scratch_, r);
  for (std::size_t g = 0; g < group.size(); ++g) {
    const std::int32_t k = group[g];
    if (scenario_.physics.model == Model::pool) {
      set_motion(k, r.velocity[g], traj_[static_cast<std::size_t>(k)].w0);
    } else {
      set_velocity(k, r.velocity[g]);
    }
    ++counter_[static_cast<std::size_t>(k)];
  }
  // A grazing contact (closing far slower than the balls slide past each
  // other) can leave the cluster's contacts with next to no impulse while
  // the pair, frozen where it touched, still closes: the pairwise impact
  // then settles that pair, so the same contact never comes up again.
  if (dot(traj_[static_cast<std::size_t>(j)].v0 - traj_[static_cast<std::size_t>(i)].v0, d) < 0.0) {
    collide_balls(i, j);
  }
  Event ev;
  ev.time = t;
  ev.type = EventType::ball_ball;
  ev.ball = std::min(i, j);
  ev.other = std::max(i, j);
  events_.push_back(ev);
  ++event_count_;
  for (const auto& [a, b] : r.touched) {
    const std::int32_t x = group[static_cast<std::size_t>(a)];
    const std::int32_t y = group[static_cast<std::size_t>(b)];
    if (std::min(x, y) == ev.ball && std::max(x, y) == ev.other) continue;
    Event e2 = ev;
    e2.ball = std::min(x, y);
    e2.other = std::max(x, y);
    events_.push_back(e2);
    ++event_count_;
  }
  for (std::int32_t k : group) {
    predict(k);
    queue_.fix(k);
  }
  return true;
}

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
  const CushionImpact r = cushion_impact(A.v0, A.w0, n, scenario_.balls[ui].mass, radius_[ui], cp);
  set_motion(i, r.velocity, r.spin);
  const double out = dot(A.v0, n);
  if (pressed(out, dot(A.acc, n), A.t_end - A.t0)) set_motion(i, A.v0 + n * (vc - out), A.w0);
  const Vec2 away = wall.kind == WallKind::segment ? wall.normal : A.p0 - wall.a;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() * std::max(norm(A.v0), vc);
  for (int k = 0; k < 64 && dot(away, A.v0) < 0.0; ++k, extra *= 2.0) {
    set_motion(i, A.v0 + n * extra, A.w0);
  }
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
  Vec2 n = B.p0 - A.p0;
  const double len = norm(n);
  n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  const Vec2 va = A.v0;
  const Vec2 vb = B.v0;
  const double closing = dot(va - vb, n);
  const double reduced = ma * mb / (ma + mb);
  double out = outgoing_speed(closing, pair_restitution(i, j));
  double impulse = std::max(0.0, reduced * (closing + out));
  set_velocity(i, va - n * (impulse / ma));
  set_velocity(j, vb + n * (impulse / mb));
  // A pair that leaves (nearly) together while friction pushes the two
  // into each other would meet again at once, forever. Such a pair leaves
  // at collapse_speed: the only case where an impact may add energy, at
  // most reduced * collapse_speed^2 / 2 (docs/physics-core.md).
  if (pressed(out, dot(B.acc - A.acc, n), std::min(A.t_end, B.t_end) - A.t0)) {
    out = scenario_.physics.collapse_speed;
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
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max({norm(va), norm(vb), scenario_.physics.collapse_speed});
  for (int k = 0; k < 64 && dot(dp, B.v0 - A.v0) < 0.0; ++k, extra *= 2.0) {
    impulse += reduced * extra;
    set_velocity(i, va - n * (impulse / ma));
    set_velocity(j, vb + n * (impulse / mb));
  }
}

void Engine::collide_wall(std::int32_t i, std::int32_t w) {
  if (scenario_.physics.model == Model::pool) {
    collide_pool_wall(i, w);
    return;
  }
  Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const Wall& wall = scenario_.table.walls[static_cast<std::size_t>(w)];
  Vec2 n = wall.normal;
  if (wall.kind != WallKind::segment) {
    n = A.p0 - wall.a;
    const double len = norm(n);
    n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  }
  const Vec2 v = A.v0;
  const double closing = -dot(v, n);
  const double e = scenario_.balls[static_cast<std::size_t>(i)].wall_restitution;
  const double out = outgoing_speed(closing, e);
  double dv = std::max(0.0, closing + out);
  set_velocity(i, v + n * dv);
  // A ball that keeps being pressed into the wall leaves at
  // collapse_speed, as a pressed pair of balls does.
  if (pressed(out, dot(A.acc, n), A.t_end - A.t0)) {
    dv = std::max(0.0, closing + scenario_.physics.collapse_speed);
    set_velocity(i, v + n * dv);
  }
  // As for two balls: leave the wall in the predictor's own arithmetic.
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max(norm(v), scenario_.physics.collapse_speed);
  const Vec2 away = wall.kind != WallKind::segment ? A.p0 - wall.a : wall.normal;
  for (int k = 0; k < 64 && dot(away, A.v0) < 0.0; ++k, extra *= 2.0) {
    dv += extra;
    set_velocity(i, v + n * dv);
  }
}

// ---------------------------------------------------------------------------
// The loop

bool Engine::step(double limit) {
  if (queue_.empty()) return false;
  const std::int32_t i = queue_.top();
  const Prediction p = queue_.next(i);
  if (p.kind == EventKind::none || p.time > limit) return false;
  const auto ui = static_cast<std::size_t>(i);

  if (p.kind == EventKind::ball && counter_[static_cast<std::size_t>(p.other)] != p.other_counter) {
    // The partner had an event since this was predicted: predict again.
    origin_ = std::max(origin_, p.time);
    predict(i);
    queue_.fix(i);
    return true;
  }
  if (p.kind == EventKind::cell) {
    // Crossing into a neighbouring cell changes no motion, so no one
    // else's prediction is affected; only this ball looks around again.
    origin_ = std::max(origin_, p.time);
    const std::int32_t cell = grid_.cell_of(i);
    const std::int32_t cx = cell % grid_.nx() + kStepX[p.other];
    const std::int32_t cy = cell / grid_.nx() + kStepY[p.other];
    grid_.unlink(i);
    grid_.link(i, cy * grid_.nx() + cx);
    // Only the row or column of cells that just came into the
    // neighbourhood holds new partners; the best event found before still
    // stands (if its partner has moved on since, it is found stale when it
    // comes up, as any other).
    const Kinematics ki = kinematics(i);
    Prediction best = event_[ui];
    const std::int32_t fx = cx + kStepX[p.other];
    const std::int32_t fy = cy + kStepY[p.other];
    if (kStepX[p.other] != 0) {
      predict_cells(i, ki, fx, fx, cy - 1, cy + 1, best);
    } else {
      predict_cells(i, ki, cx - 1, cx + 1, fy, fy, best);
    }
    event_[ui] = best;
    finish_prediction(i);
    queue_.fix(i);
    return true;
  }
  if (event_count_ >= scenario_.max_events) {
    limit_hit_ = true;
    return false;
  }

  const double t = std::max(origin_, p.time);
  origin_ = t;
  now_ = std::max(now_, t);
  Event ev;
  ev.time = t;
  ev.ball = i;
  switch (p.kind) {
    case EventKind::ball: {
      const std::int32_t j = p.other;
      move_to(traj_[ui], t);
      move_to(traj_[static_cast<std::size_t>(j)], t);
      if (scenario_.physics.ball_clusters && collide_cluster(i, j, t)) return true;
      collide_balls(i, j);
      ++counter_[ui];
      ++counter_[static_cast<std::size_t>(j)];
      ev.type = EventType::ball_ball;
      ev.ball = std::min(i, j);
      ev.other = std::max(i, j);
      events_.push_back(ev);
      ++event_count_;
      predict(i);
      queue_.fix(i);
      predict(j);
      queue_.fix(j);
      return true;
    }
    case EventKind::wall:
      move_to(traj_[ui], t);
      collide_wall(i, p.other);
      ev.type = EventType::ball_cushion;
      ev.wall = p.other;
      break;
    case EventKind::stop:
      ev.type = EventType::state_change;
      ev.from = end_phase(i, t);
      ev.to = traj_[ui].state;
      break;
    case EventKind::pocket: {
      Trajectory& tr = traj_[ui];
      move_to(tr, t);
      set_motion(i, {}, {});  // at rest (counted as such) ...
      tr.state = MotionState::pocketed;  // ... and out of play
      update_box(tr);
      if (grid_.used()) grid_.unlink(i);
      ev.type = EventType::ball_pocket;
      ev.pocket = p.other;
      break;
    }
    default:
      return false;
  }
  ++counter_[ui];
  events_.push_back(ev);
  ++event_count_;
  predict(i);
  queue_.fix(i);
  return true;
}

StopReason Engine::advance_to(double t) {
  if (!(t >= now_)) return StopReason::reached;  // the clock never goes back
  limit_hit_ = false;
  while (step(t)) {
  }
  if (limit_hit_) return StopReason::event_limit;
  now_ = t;
  return StopReason::reached;
}

StopReason Engine::advance_to_rest() {
  limit_hit_ = false;
  while (moving_ > 0 && step(kInf)) {
  }
  return limit_hit_ ? StopReason::event_limit : StopReason::reached;
}

double Engine::next_event_time() {
  // Resolve stale predictions and cell crossings at the top so that the
  // answer is the time of a real event. Doing that early changes nothing:
  // they are handled in the same order whenever they are handled.
  for (;;) {
    if (queue_.empty()) return kInf;
    const std::int32_t i = queue_.top();
    const Prediction& p = queue_.next(i);
    if (p.kind == EventKind::none) return kInf;
    const bool stale =
        p.kind == EventKind::ball && counter_[static_cast<std::size_t>(p.other)] != p.other_counter;
    if (!stale && p.kind != EventKind::cell) return p.time;
    step(p.time);
  }
}

}  // namespace breakshot::detail

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
  reserve_cluster_work();
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
  set_up_pair_restitution();

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
      cluster_.reach =
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

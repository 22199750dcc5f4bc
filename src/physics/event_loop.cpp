// The event loop: pop the ball with the earliest prediction, re-check it,
// advance only the balls involved, resolve, re-predict; and the clock
// around it (advance_to, advance_to_rest).
#include <algorithm>

#include "physics/engine.hpp"
#include "physics/prediction.hpp"

namespace breakshot::detail {

// A ball crosses into a neighbouring cell. That changes no motion, so no
// one else's prediction is affected; only this ball looks around again.
[[gnu::always_inline]] inline void Engine::take_cell_crossing(std::int32_t i,
                                                              std::int32_t direction,
                                                              double time) {
  const auto ui = static_cast<std::size_t>(i);
  origin_ = std::max(origin_, time);
  const std::int32_t cell = grid_.cell_of(i);
  const std::int32_t cx = cell % grid_.nx() + kStepX[direction];
  const std::int32_t cy = cell / grid_.nx() + kStepY[direction];
  grid_.unlink(i);
  grid_.link(i, cy * grid_.nx() + cx);
  // Only the row or column of cells that just came into the
  // neighbourhood holds new partners; the best event found before still
  // stands (if its partner has moved on since, it is found stale when it
  // comes up, as any other).
  const Kinematics ki = kinematics(i);
  Prediction best = event_[ui];
  const std::int32_t fx = cx + kStepX[direction];
  const std::int32_t fy = cy + kStepY[direction];
  if (kStepX[direction] != 0) {
    predict_cells(i, ki, fx, fx, cy - 1, cy + 1, best);
  } else {
    predict_cells(i, ki, cx - 1, cx + 1, fy, fy, best);
  }
  event_[ui] = best;
  finish_prediction(i);
  queue_.fix(i);
}

// Two balls meet at t: a cluster impact if they are part of one (which
// records its own events), else a pairwise impact.
[[gnu::always_inline]] inline void Engine::take_ball_ball(std::int32_t i, std::int32_t j,
                                                          double t) {
  move_to(traj_[static_cast<std::size_t>(i)], t);
  move_to(traj_[static_cast<std::size_t>(j)], t);
  if (scenario_.physics.ball_clusters && traj_[static_cast<std::size_t>(i)].state != MotionState::airborne &&
      traj_[static_cast<std::size_t>(j)].state != MotionState::airborne && collide_cluster(i, j, t)) {
    return;
  }
  collide_balls(i, j);
  ++counter_[static_cast<std::size_t>(i)];
  ++counter_[static_cast<std::size_t>(j)];
  note_change(i, t);
  note_change(j, t);
  add_event(ball_ball_event(t, i, j));
  predict(i);
  queue_.fix(i);
  predict(j);
  queue_.fix(j);
}

// A ball drops into a pocket at t: at rest (counted as such) and out of
// play, never predicted again.
void Engine::take_pocket(std::int32_t i, double t) {
  Trajectory& tr = traj_[static_cast<std::size_t>(i)];
  move_to(tr, t);
  set_motion(i, {}, {});
  tr.state = MotionState::pocketed;
  update_box(tr);
  sync_sweep(static_cast<std::size_t>(i));
  if (grid_.used()) grid_.unlink(i);
}

// The end of an event of ball i alone: count and record it, predict the
// ball again.
[[gnu::always_inline]] inline void Engine::finish_event(std::int32_t i, const Event& ev) {
  ++counter_[static_cast<std::size_t>(i)];
  note_change(i, ev.time);
  add_event(ev);
  predict(i);
  queue_.fix(i);
}

// One step: the event at the top of the queue. Returns false, doing
// nothing, when that is later than `limit`, when there is none, or when
// max_events stops it (limit_hit_ is then set).
bool Engine::step(double limit) {
  if (queue_.empty()) return false;
  const std::int32_t i = queue_.top();
  const Prediction p = queue_.next(i);
  if (p.kind == EventKind::none || p.time > limit) return false;

  if (p.kind == EventKind::ball &&
      counter_[static_cast<std::size_t>(p.other)] != p.other_counter) {
    // The partner had an event since this was predicted: predict again.
    origin_ = std::max(origin_, p.time);
    predict(i);
    queue_.fix(i);
    return true;
  }
  if (p.kind == EventKind::cell) {
    take_cell_crossing(i, p.other, p.time);
    return true;
  }
  if (event_count_ >= scenario_.max_events) {
    limit_hit_ = true;
    return false;
  }

  const double t = std::max(origin_, p.time);
  origin_ = t;
  now_ = std::max(now_, t);
  if (p.kind == EventKind::ball) {
    take_ball_ball(i, p.other, t);
    return true;
  }
  Event ev;
  ev.time = t;
  ev.ball = i;
  switch (p.kind) {
    case EventKind::wall:
      move_to(traj_[static_cast<std::size_t>(i)], t);
      collide_wall(i, p.other);
      ev.type = EventType::ball_cushion;
      ev.wall = p.other;
      break;
    case EventKind::stop:
      if (traj_[static_cast<std::size_t>(i)].state == MotionState::airborne) {
        take_landing(i, t, ev);  // engine_airborne.cpp
        break;
      }
      ev.type = EventType::state_change;
      ev.from = end_phase(i, t);
      ev.to = traj_[static_cast<std::size_t>(i)].state;
      break;
    case EventKind::off:
      take_off_table(i, t);
      ev.type = EventType::ball_off_table;
      ev.wall = p.other;
      break;
    case EventKind::pocket:
      take_pocket(i, t);
      ev.type = EventType::ball_pocket;
      ev.pocket = p.other;
      break;
    default:
      return false;
  }
  finish_event(i, ev);
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

bool Engine::rest_by(double t) {
  for (;;) {
    limit_hit_ = false;
    while (moving_ > 0 && step(t)) {
    }
    if (moving_ == 0 || event_count_ >= scenario_.max_events) return true;
    // Every event up to t is taken; is one still to come? (This takes
    // stale predictions and cell crossings at the top early, which
    // changes nothing: see next_event_time.)
    const double next = next_event_time();
    if (!(next < kInf)) return true;
    if (next > t) return false;
  }
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

std::vector<BallState> Engine::balls() const {
  std::vector<BallState> out;
  out.reserve(traj_.size());
  for (std::size_t i = 0; i < traj_.size(); ++i) out.push_back(ball(i));
  return out;
}

}  // namespace breakshot::detail

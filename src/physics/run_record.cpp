// Recording a run, and reading it back (run_record.hpp).
//
// Why a replay is exact: advance_to(t) takes the steps of one fixed
// sequence (events, stale predictions, cell crossings) for as long as
// each one's predicted time is <= t. Only events change trajectories, and
// an event's time is the latest predicted time of every step so far
// (origin_), so advance_to(t) has taken an event exactly when the event's
// time is <= t. The states are then evaluated from the same trajectories
// with the same functions (motion.hpp).
#include "physics/run_record.hpp"

#include <algorithm>

#include "physics/engine.hpp"

namespace breakshot::detail {

void Engine::start_record(RunRecord& record) {
  record_ = &record;
  record.start = traj_;
  record.changes.clear();
  record.refused.reset();
}

void Engine::record_change(std::int32_t i, double t) {
  record_->changes.push_back({t, i, traj_[static_cast<std::size_t>(i)]});
}

void Engine::finish_record() {
  if (record_ == nullptr) return;
  // The last advance stopped at max_events: the event it refused is still
  // at the top of the queue, and a step is reached once t is past the
  // predicted times of every step before it.
  if (limit_hit_) record_->refused = std::max(origin_, queue_.next(queue_.top()).time);
  record_ = nullptr;
}

Replay::Replay(const RunRecord& record) : record_(&record), traj_(record.start) {}

StopReason Replay::advance_to(double t) {
  if (!(t >= now_)) return StopReason::reached;  // the clock never goes back
  const std::vector<RunRecord::Change>& changes = record_->changes;
  while (next_ < changes.size() && changes[next_].time <= t) {
    const RunRecord::Change& c = changes[next_++];
    traj_[static_cast<std::size_t>(c.ball)] = c.trajectory;
    now_ = std::max(now_, c.time);
  }
  if (record_->refused && *record_->refused <= t) return StopReason::event_limit;
  now_ = t;
  return StopReason::reached;
}

std::vector<BallState> Replay::balls() const {
  std::vector<BallState> out;
  out.reserve(traj_.size());
  for (const Trajectory& tr : traj_) out.push_back(state_at(tr, now_));
  return out;
}

}  // namespace breakshot::detail

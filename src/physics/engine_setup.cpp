// Set-up of a run: every ball's first trajectory, working memory, the cue
// strike and the first predictions. The set-up of the walls' boxes, the
// pair restitutions and the clusters' working memory is in the files of
// those concepts.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include "physics/engine.hpp"
#include "physics/large_pages.hpp"

namespace breakshot::detail {

Engine::Engine(const Scenario& scenario) : scenario_(scenario) { set_up(); }

Engine::Engine(Scenario&& scenario) : scenario_(std::move(scenario)) { set_up(); }

namespace {

// Do two lists of walls have the same geometry (names aside)? The walls'
// boxes and runs depend on nothing else.
bool same_wall_geometry(const std::vector<Wall>& a, const std::vector<Wall>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Wall& x = a[k];
    const Wall& y = b[k];
    if (x.kind != y.kind || x.a != y.a || x.b != y.b || x.normal != y.normal ||
        x.radius != y.radius) {
      return false;
    }
  }
  return true;
}

}  // namespace

void Engine::reset(const Scenario& scenario) {
  // A new shot on the same table (the usual case: play_shots, the AI's
  // rollouts) keeps the walls' boxes and runs.
  const bool same_walls = same_wall_geometry(scenario_.table.walls, scenario.table.walls);
  scenario_ = scenario;  // assignment reuses the vectors' and strings' memory
  // Everything else as a new engine has it, every container emptied but
  // keeping its capacity.
  cluster_.group.clear();
  cluster_.place.clear();
  cluster_.member.clear();
  cluster_.near.clear();
  cluster_.reach = 1;
  cluster_.bodies.clear();
  now_ = 0.0;
  origin_ = 0.0;
  event_count_ = 0;
  limit_hit_ = false;
  left_cloth_ = false;
  moving_ = 0;
  // traj_ and radius_ keep their elements: set_up_balls overwrites
  // every one of them.
  ideal_ = false;
  counter_.clear();
  event_.clear();
  events_.clear();
  cue_result_.reset();
  if (!same_walls) {
    convex_ = false;
    wall_box_.clear();
    wall_runs_.clear();
  }
  pair_keys_.clear();
  pair_values_.clear();
  grid_.clear();
  record_ = nullptr;
  set_up(!same_walls);
}

void Engine::set_up(bool walls) {
  set_up_balls();
  reserve_events();
  reserve_cluster_work();
  if (walls) set_up_walls();
  set_up_pair_restitution();
  set_up_cells();
  strike_cue();
  predict_all();
}

// Each ball's trajectory from its state at t = 0.
void Engine::set_up_balls() {
  const std::size_t n = scenario_.balls.size();
  // Each trajectory as a new engine has it: the new elements are made
  // clear, those that reset kept are cleared below.
  const std::size_t kept = std::min(traj_.size(), n);
  reserve_large(traj_, n);
  reserve_large(radius_, n);
  reserve_large(counter_, n);
  traj_.resize(n);
  radius_.resize(n);
  for (std::size_t i = 0; i < n; ++i) radius_[i] = scenario_.balls[i].radius;
  ideal_ = scenario_.physics.model == Model::ideal;
  if (!ideal_) reserve_large(sweep_, n);
  sweep_.resize(ideal_ ? 0 : n);
  in_play_bits_ = 0;
  translating_bits_ = 0;
  counter_.assign(n, 0);
  // A ball at rest (every component of its motion +0.0) starts the same
  // trajectory wherever it is: the first one of each radius is worked
  // out, the others copy it and take their own place (a rack's balls).
  const auto at_rest = [](const BallState& s) {
    const double parts[6] = {s.velocity.x, s.velocity.y, s.vz, s.spin.x, s.spin.y, s.spin.z};
    for (double x : parts) {
      if (std::bit_cast<std::uint64_t>(x) != 0) return false;
    }
    return true;
  };
  std::size_t rest_model = n;  // a ball at rest worked out, if any
  for (std::size_t i = 0; i < n; ++i) {
    Trajectory& tr = traj_[i];
    const BallState& start = scenario_.start[i];
    if (rest_model < n && radius_[i] == radius_[rest_model] && at_rest(start)) {
      tr = traj_[rest_model];
      tr.p0 = start.position;
      tr.box_lo = start.position;  // the box of a ball in place (update_box)
      tr.box_hi = start.position;
      sync_sweep(i);
      continue;
    }
    if (i < kept) tr = Trajectory{};
    tr.t0 = 0.0;
    tr.p0 = scenario_.start[i].position;
    tr.w0 = scenario_.start[i].spin;
    tr.state = MotionState::stationary;
    tr.t_end = kInf;
    set_motion3(static_cast<std::int32_t>(i), start.velocity, start.vz, start.spin);
    if (rest_model == n && at_rest(start) && !translating(tr.state)) rest_model = i;
  }
}

// Room for the events of a typical shot, so that simulating one allocates
// nothing after set-up (a break has about 100 events), and for the events
// of cluster impacts (reserve_cluster_work).
void Engine::reserve_events() {
  const std::size_t n = scenario_.balls.size();
  std::size_t want =
      static_cast<std::size_t>(std::min<std::uint64_t>(scenario_.max_events, 64 + 16 * n));
  if (scenario_.physics.ball_clusters && n <= kClusterReserveBalls) want += 4 * n;
  events_.reserve(want);
}

// With many balls, the grid of cells.
void Engine::set_up_cells() {
  const std::size_t n = scenario_.balls.size();
  if (n < kCellThreshold) return;
  double max_r = 0.0;
  for (const BallSpec& b : scenario_.balls) max_r = std::max(max_r, b.radius);
  if (!grid_.build(scenario_.table.min, scenario_.table.max, n, max_r)) return;
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

// The cue strike: the shot's first event, at t = 0. A miscue is reported
// (cue_result) and not played.
void Engine::strike_cue() {
  const std::size_t n = scenario_.balls.size();
  if (!scenario_.cue || scenario_.cue->ball < 0 ||
      static_cast<std::size_t>(scenario_.cue->ball) >= n) {
    return;
  }
  const CueSpec& cue = *scenario_.cue;
  const auto ub = static_cast<std::size_t>(cue.ball);
  cue_result_ = strike(cue.strike, scenario_.balls[ub].mass, radius_[ub], cue.params);
  if (cue_result_->miscue) return;
  // With physics.airborne the downward part goes into the slate
  // (set_motion3); without, it is dropped.
  set_motion3(cue.ball, cue_result_->velocity, cue_result_->vertical, cue_result_->spin);
  Event ev;
  ev.time = 0.0;
  ev.type = EventType::cue_strike;
  ev.ball = cue.ball;
  events_.push_back(ev);
  ++event_count_;
  ++counter_[ub];
}

// Every ball's earliest event, and the queue in order.
void Engine::predict_all() {
  const std::size_t n = scenario_.balls.size();
  reserve_large(event_, n);
  event_.resize(n);
  queue_.reset(n);
  for (std::size_t i = 0; i < n; ++i) predict(static_cast<std::int32_t>(i));
  queue_.build();
}

}  // namespace breakshot::detail

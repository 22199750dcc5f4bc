// The engine behind Simulation: the working state of a run and the event
// loop. Predict each ball's earliest event, pop the earliest of all,
// re-check it, advance only the balls involved, resolve, re-predict.
// docs/architecture.md follows one scenario through it.
//
// The concepts live in files of their own, as in DynamO:
//   engine_setup.cpp           set-up: the constructor, in steps
//   event_loop.cpp             the loop: step() and the events it takes
//   event_queue.hpp/.cpp       the indexed heap of the balls' next events
//   cell_grid.hpp/.cpp         the grid of cells (neighbour list)
//   motion.hpp/.cpp            the motion laws of each model
//   prediction.hpp, predict.cpp  each ball's earliest event
//   predict_balls.hpp/.cpp     ... against the other balls
//   predict_walls.cpp          ... against the walls
//   predict_pockets.cpp        ... into a pocket
//   predict_cell_crossing.cpp  ... out of its cell
//   response.hpp               rules the collision responses share
//   collide_balls.cpp          ball-ball responses, pair restitutions
//   collide_walls.cpp          ball-wall (cushion) responses
//   collide_cluster.cpp        gathering a cluster and resolving it at once
//   run_record.hpp/.cpp        recording a run to read its states afterwards
// Not installed: the public face is include/breakshot/simulation.hpp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "breakshot/ball.hpp"
#include "breakshot/event.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"
#include "physics/cell_grid.hpp"
#include "physics/cluster_impact.hpp"
#include "physics/event_queue.hpp"
#include "physics/motion.hpp"

namespace breakshot::detail {

struct Kinematics;  // prediction.hpp
struct RunRecord;   // run_record.hpp

// With ball_clusters, the working memory of cluster impacts is reserved at
// set-up for up to this many balls (any pool game); larger scenes grow it
// when a cluster first needs it.
constexpr std::size_t kClusterReserveBalls = 64;

class Engine {
 public:
  // The scenario must be valid (see validate()).
  explicit Engine(const Scenario& scenario);
  /// Takes the scenario over instead of copying it.
  explicit Engine(Scenario&& scenario);
  /// Starts again on `scenario` (valid) exactly as Engine(scenario) does,
  /// keeping the memory this engine holds (Simulation::reset).
  void reset(const Scenario& scenario);

  // What Simulation offers, with the same meaning (simulation.hpp).
  double time() const { return now_; }
  StopReason advance_to(double t);
  StopReason advance_to_rest();
  double next_event_time();
  bool at_rest() const { return moving_ == 0; }
  BallState ball(std::size_t i) const { return state_at(traj_[i], now_); }
  std::vector<BallState> balls() const;
  std::size_t ball_count() const { return traj_.size(); }
  const std::vector<Event>& events() const { return events_; }
  std::vector<Event>& events() { return events_; }  // simulate() moves them out
  std::uint64_t event_count() const { return event_count_; }
  const Scenario& scenario() const { return scenario_; }
  const std::optional<StrikeResult>& cue_result() const { return cue_result_; }
  const Trajectory& trajectory(std::size_t i) const { return traj_[i]; }
  // Has any ball left the cloth (risen more than 1e-9 m) so far?
  bool left_cloth() const { return left_cloth_; }

  // advance_to_rest() up to time t: takes every event up to t unless the
  // run to rest ends first. Returns true once that run is over: every
  // ball at rest, max_events reached, or no event left to come. Then the
  // events are exactly those advance_to_rest() takes (simulate.cpp).
  bool rest_by(double t);

  // From now on, writes every change of a ball's trajectory to `record`
  // (run_record.hpp); finish_record() notes how the run ended. When not
  // recording, the cost is one test per event.
  void start_record(RunRecord& record);
  void finish_record();

 private:
  // --- set-up (engine_setup.cpp, and the files named)
  // Everything the constructors do after taking the scenario; `walls`
  // false keeps the walls' boxes and runs (reset on the same walls).
  void set_up(bool walls = true);
  void set_up_balls();
  void reserve_events();
  void reserve_cluster_work();     // collide_cluster.cpp
  void set_up_walls();             // predict_walls.cpp
  void set_up_pair_restitution();  // collide_balls.cpp
  void set_up_cells();
  void strike_cue();
  void predict_all();

  // --- the loop (event_loop.cpp)
  bool step(double limit);
  void take_cell_crossing(std::int32_t i, std::int32_t direction, double time);
  void take_ball_ball(std::int32_t i, std::int32_t j, double t);
  void take_pocket(std::int32_t i, double t);
  void take_off_table(std::int32_t i, double t);
  void take_landing(std::int32_t i, double t, Event& ev);  // airborne.cpp's engine part
  void finish_event(std::int32_t i, const Event& ev);

  // --- motion (set_motion, set_velocity below; end_phase in motion.cpp)
  void set_motion(std::int32_t i, Vec2 v, Vec3 w, bool rolls = false);
  void set_velocity(std::int32_t i, Vec2 v);
  // A new motion with a vertical velocity vz, from the ball's present
  // height (physics.airborne; engine_airborne.cpp): a flight, a push into
  // the slate (which bounces it), or motion on the cloth.
  void set_motion3(std::int32_t i, Vec2 v, double vz, Vec3 w);
  // The height of the nose of every wall for ball i (m above the slate).
  double rail_height(std::int32_t i) const;
  MotionState end_phase(std::int32_t i, double t);

  // --- prediction (predict*.cpp)
  Kinematics kinematics(std::int32_t i) const;
  void predict(std::int32_t i);
  void finish_prediction(std::int32_t i) {
    // The ball's next event: the earliest predict() found, or leaving its
    // cell if that comes first.
    Prediction best = event_[static_cast<std::size_t>(i)];
    if (grid_.used()) predict_cell_crossing(i, best);
    queue_.set(i, best);
  }
  void predict_partners(std::int32_t i, const Kinematics& ki, Prediction& best) const;
  void predict_cells(std::int32_t i, const Kinematics& ki, std::int32_t x0, std::int32_t x1,
                     std::int32_t y0, std::int32_t y1, Prediction& best) const;
  void predict_ball_pair(const Kinematics& ki, std::int32_t j, Prediction& best) const;
  void predict_ideal_pair(const Kinematics& ki, std::int32_t j, Prediction& best) const;
  void predict_moving_pair(const Kinematics& ki, std::int32_t j, std::uint32_t need,
                           Prediction& best) const;
  // After predict_ball_pair's cheap rejections only.
  void predict_accelerating_pair(const Kinematics& ki, std::int32_t j, Prediction& best) const;
  void predict_walls(const Kinematics& ki, Prediction& best) const;
  void predict_wall(const Kinematics& ki, std::size_t w, double window, Prediction& best) const;
  void predict_pockets(const Kinematics& ki, Prediction& best) const;
  void predict_wall_airborne(const Kinematics& ki, std::size_t w, double window,
                             Prediction& best) const;  // engine_airborne.cpp
  void predict_cell_crossing(std::int32_t i, Prediction& best) const;

  // --- collision responses (collide_*.cpp)
  double pair_restitution(std::int32_t i, std::int32_t j) const;
  void collide_balls(std::int32_t i, std::int32_t j);
  void collide_pool_balls(std::int32_t i, std::int32_t j);
  bool collide_cluster(std::int32_t i, std::int32_t j, double t);
  void gather_cluster(std::int32_t i, std::int32_t j, double t);
  void collide_wall(std::int32_t i, std::int32_t w);
  void collide_pool_wall(std::int32_t i, std::int32_t w);
  void collide_airborne_wall(std::int32_t i, std::int32_t w);      // engine_airborne.cpp
  void collide_airborne_balls(std::int32_t i, std::int32_t j);     // engine_airborne.cpp

  // --- the run's events
  // Appends ev to the run's events and counts it.
  void add_event(const Event& ev) {
    events_.push_back(ev);
    ++event_count_;
  }
  // The ball_ball event of balls i and j at time t (the lower index first).
  static Event ball_ball_event(double t, std::int32_t i, std::int32_t j) {
    Event ev;
    ev.time = t;
    ev.type = EventType::ball_ball;
    ev.ball = std::min(i, j);
    ev.other = std::max(i, j);
    return ev;
  }

  // --- recording (run_record.cpp)
  // Ball i's trajectory changed at an event at time t.
  void note_change(std::int32_t i, double t) {
    if (record_ != nullptr) record_change(i, t);
  }
  void record_change(std::int32_t i, double t);

  Scenario scenario_;
  // Working memory of collide_cluster (reserved when the scenario has
  // ball_clusters, so that an impact allocates nothing).
  struct ClusterWork {
    std::vector<std::int32_t> group;
    std::vector<Vec2> place;
    std::vector<std::uint8_t> member;  // 1 for the balls of the group (no grid)
    std::vector<std::int32_t> near;  // candidates of the cells nearby
    std::int32_t reach = 1;          // cells searched on each side
    std::vector<ClusterBody> bodies;
    ClusterScratch scratch;
    ClusterOutcome out;
  };
  ClusterWork cluster_;
  double now_ = 0.0;     // the clock
  double origin_ = 0.0;  // time of the last event: origin of predictions
  std::uint64_t event_count_ = 0;
  bool limit_hit_ = false;  // set when max_events stopped a step
  bool left_cloth_ = false; // some ball has risen above the cloth
  std::size_t moving_ = 0;  // balls not at rest
  std::vector<Trajectory> traj_;
  std::vector<double> radius_;  // a copy of each ball's radius, packed
  // What the partner search reads of each ball (predict_balls.hpp),
  // packed: its trajectory's box, its radius (twice, for both axes at
  // once) and whether it is in play and moving; for the first 32 balls
  // the last two also as bits 2j of two words. sync_sweep(i) writes them
  // wherever ball i's state or box changes (set_motion, set_motion3,
  // take_pocket, take_off_table, set_up_balls). Not kept in the ideal
  // model, whose partner test reads the trajectories.
  static constexpr std::uint32_t kInPlay = 1;
  static constexpr std::uint32_t kTranslating = 2;
  struct Sweep {
    Vec2 lo, hi;
    double radius[2] = {0.0, 0.0};
    std::uint32_t flags = 0;
  };
  std::vector<Sweep> sweep_;
  std::uint64_t in_play_bits_ = 0;
  std::uint64_t translating_bits_ = 0;
  void sync_sweep(std::size_t i) {
    if (ideal_) return;  // the ideal model's partner test reads the trajectories
    const Trajectory& tr = traj_[i];
    Sweep& s = sweep_[i];
    s.lo = tr.box_lo;
    s.hi = tr.box_hi;
    s.radius[0] = radius_[i];
    s.radius[1] = radius_[i];
    const bool in_play = !out_of_play(tr.state);
    const bool moves = translating(tr.state);
    s.flags = (in_play ? kInPlay : 0u) | (moves ? kTranslating : 0u);
    if (i < 32) {
      const std::uint64_t bit = std::uint64_t{1} << (2 * i);
      in_play_bits_ = in_play ? in_play_bits_ | bit : in_play_bits_ & ~bit;
      translating_bits_ = moves ? translating_bits_ | bit : translating_bits_ & ~bit;
    }
  }
  bool ideal_ = false;          // no ball ever accelerates
  bool convex_ = false;         // the table has no corner walls
  std::vector<std::uint64_t> counter_;  // events each ball took part in
  std::vector<Prediction> event_;       // each ball's earliest event, cell crossings left out
  EventQueue queue_;                    // the same with cell crossings, ordered
  std::vector<Event> events_;
  std::optional<StrikeResult> cue_result_;
  struct Box {
    Vec2 lo, hi;
  };
  std::vector<Box> wall_box_;  // bounds of each wall of the table
  struct WallRun {
    Box box;  // bounds of walls [begin, end)
    std::uint32_t begin = 0, end = 0;
  };
  std::vector<WallRun> wall_runs_;
  // Pairs with a restitution of their own: sorted keys a * n + b (a < b).
  std::vector<std::uint64_t> pair_keys_;
  std::vector<double> pair_values_;
  CellGrid grid_;  // used when there are many balls
  // Where changes go while recording (simulate_recorded); never set in
  // the engine of a Simulation, so copies do not share it.
  RunRecord* record_ = nullptr;
};

// A new motion for ball i, keeping count of the balls in motion. Inline,
// as the motion laws (motion.hpp) are: the responses call it at every
// impact.
inline void Engine::set_motion(std::int32_t i, Vec2 v, Vec3 w, bool rolls) {
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& tr = traj_[ui];
  const bool was_active = !resting(tr.state);
  start_motion(tr, v, w, rolls, scenario_.physics, radius_[ui]);
  const bool active = !resting(tr.state);
  if (active && !was_active) ++moving_;
  if (!active && was_active) --moving_;
  sync_sweep(ui);
}

inline void Engine::set_velocity(std::int32_t i, Vec2 v) {
  set_motion(i, v, traj_[static_cast<std::size_t>(i)].w0);
}

}  // namespace breakshot::detail

// The event-driven simulation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "breakshot/ball.hpp"
#include "breakshot/event.hpp"
#include "breakshot/scenario.hpp"

/// Simulation::reset exists (for programs built against several versions
/// of breakshot, such as bench/shot_workloads.cpp).
#define BREAKSHOT_SIMULATION_RESET 1

namespace breakshot {

/// Why advance() returned.
enum class StopReason : std::uint8_t {
  reached,     ///< the requested time (or rest) was reached
  event_limit, ///< Scenario::max_events events were processed
};

class Simulation;

namespace detail {
class Engine;
}  // namespace detail

/// The whole result of a run: every event, the final state and the
/// samples, if asked for.
struct Sample {
  double time = 0.0;
  std::vector<BallState> balls;
};

struct RunResult {
  bool complete = true;
  std::optional<StrikeResult> cue;  ///< what the cue strike did, if any
  std::vector<Event> events;
  double final_time = 0.0;
  std::vector<BallState> final_balls;
  std::vector<Sample> samples;
  /// Some ball left the cloth (rose more than 1e-9 m): the result file
  /// then gives every ball's height "z".
  bool airborne = false;
};

/// Runs a validated scenario to its `until` (or the event limit).
RunResult simulate(const Scenario& scenario);

/// The simulation as a copyable value: copy it to save the state,
/// assign the copy back to restore it. Advancing to frame times or
/// straight to the end gives exactly the same events.
class Simulation {
 public:
  /// The scenario must be valid (see validate()).
  explicit Simulation(const Scenario& scenario);
  /// The same, taking the scenario over instead of copying it.
  explicit Simulation(Scenario&& scenario);

  /// Starts again on `scenario` (valid), exactly as Simulation(scenario)
  /// would, keeping this simulation's memory: the AI's rollouts and batch
  /// shots re-arm one simulation for shot after shot. It allocates
  /// nothing when the scenario is no larger than one this simulation has
  /// held (balls, walls, pockets, ball id lengths) and its run fits the
  /// events reserved (about 64 + 16 per ball, more with ball clusters);
  /// a larger one grows the memory once. A moved-from Simulation cannot
  /// be reset.
  void reset(const Scenario& scenario);

  /// Copying saves the whole state; assigning a copy back restores it
  /// (and reuses this one's memory).
  Simulation(const Simulation& other);
  Simulation& operator=(const Simulation& other);
  /// Moving is cheap. A moved-from Simulation may only be assigned to or
  /// destroyed.
  Simulation(Simulation&& other) noexcept;
  Simulation& operator=(Simulation&& other) noexcept;
  ~Simulation();

  /// Current clock.
  double time() const;

  /// Processes every event with time <= t in time order, then moves the
  /// clock to t. Returns event_limit if max_events stopped it first (the
  /// clock then stays at the last event).
  StopReason advance_to(double t);

  /// Advances until every ball is at rest (or pocketed). With a model
  /// or input where that never happens it stops at max_events.
  StopReason advance_to_rest();

  /// Time of the next event, +infinity if none is coming.
  double next_event_time();

  /// True if no ball moves.
  bool at_rest() const;

  /// True once some ball has left the cloth (risen more than 1e-9 m).
  bool left_cloth() const;

  /// State of ball i at the current clock.
  BallState ball(std::size_t i) const;
  std::vector<BallState> balls() const;
  std::size_t ball_count() const;

  /// Every event so far, in order.
  const std::vector<Event>& events() const;
  std::uint64_t event_count() const;

  const Scenario& scenario() const;

  /// The cue strike's outcome (set when the scenario has a cue).
  const std::optional<StrikeResult>& cue_result() const;

  /// A ball's motion from t0 on: p(t) = p0 + v0 dt + acc dt^2 / 2 with
  /// dt = t - t0, valid until t_end (its next change of state by itself).
  struct Trajectory {
    double t0 = 0.0;
    Vec2 p0;
    Vec2 v0;
    Vec2 acc;
    Vec3 w0;
    Vec2 alpha;            ///< angular acceleration about x and y (pool)
    double wz_rate = 0.0;  ///< decay of |w_z| per second (pool)
    double t_end = 0.0;  ///< +inf if the motion never changes by itself
    MotionState state = MotionState::stationary;
    /// Airborne only: height above the resting height and vertical
    /// velocity at t0, z(t) = z0 + vz0 dt - g dt^2 / 2 until the landing
    /// at t_end (gravity from the scenario's physics).
    double z0 = 0.0;
    double vz0 = 0.0;
    double gravity = 0.0;
    Vec2 box_lo;  ///< bounds of the centre's path from t0 to t_end
    Vec2 box_hi;
  };

  /// The trajectory a ball follows now (for tools and tests).
  const Trajectory& trajectory(std::size_t i) const;

 private:
  // The working state and the event loop (src/physics/engine.hpp).
  std::unique_ptr<detail::Engine> engine_;
};

}  // namespace breakshot

// A record of one run: every ball's trajectory after set-up and each
// change of a trajectory at an event. From it, Replay gives the state of
// every ball at any time of the run, bit for bit what a Simulation
// advanced to that time gives, without running the physics again. One
// run of a shot thus gives both its result and the frames of its plots
// (simulate_traced in lab.cpp). It takes about 170 bytes for each ball
// an event changes (two at an impact of two balls).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "breakshot/ball.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"
#include "physics/motion.hpp"

namespace breakshot::detail {

struct RunRecord {
  struct Change {
    double time = 0.0;  // the event's time
    std::int32_t ball = -1;
    Trajectory trajectory;  // the ball's trajectory from the event on
  };
  std::vector<Trajectory> start;  // after set-up (and the cue strike)
  std::vector<Change> changes;    // in the order of the events
  // Set when max_events stopped the run: advance_to(t) meets the event it
  // refused for any t >= this time.
  std::optional<double> refused;
};

// Runs a scenario as simulate() does and records it: the result is
// simulate()'s.
RunResult simulate_recorded(const Scenario& scenario, RunRecord& record);

// A recorded run read back: advance_to, time and balls as a Simulation's,
// for times up to the end of the recorded run.
class Replay {
 public:
  explicit Replay(const RunRecord& record);
  StopReason advance_to(double t);
  double time() const { return now_; }
  std::vector<BallState> balls() const;

 private:
  const RunRecord* record_;
  std::vector<Trajectory> traj_;
  std::size_t next_ = 0;  // the first change not applied yet
  double now_ = 0.0;
};

}  // namespace breakshot::detail

// The physics lab: energy, momentum and dense traces of a run.
#pragma once

#include <cstddef>
#include <vector>

#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"

namespace breakshot {

/// Kinetic energy of one ball, translational plus rotational (a solid
/// sphere, I = 2/5 m r^2), in joules.
double kinetic_energy(const BallSpec& spec, const BallState& state);

/// Linear momentum m v of one ball (kg m/s).
Vec2 momentum(const BallSpec& spec, const BallState& state);

/// A dense record of a run for plotting: the state of every ball at the
/// time of every event (just after it) and at `points` evenly spaced
/// times from 0 to the end, merged in time order. It runs the scenario
/// once, on its own, and never changes the events.
std::vector<Sample> trace(const Scenario& scenario, std::size_t points = 2000,
                          std::size_t max_frames = 200000);

/// simulate() and trace() of one scenario from a single run of it:
/// `result` is what simulate() returns, `frames` what trace() returns.
struct TracedRun {
  RunResult result;
  std::vector<Sample> frames;
};
TracedRun simulate_traced(const Scenario& scenario, std::size_t points = 2000,
                          std::size_t max_frames = 200000);

}  // namespace breakshot

// A scenario: everything the engine needs to simulate, as plain values.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "breakshot/ball.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/table.hpp"

namespace breakshot {

/// A restitution for one pair of balls (indices into Scenario::balls).
struct PairRestitution {
  std::int32_t a = 0;
  std::int32_t b = 0;
  double restitution = 1.0;
};

/// When a run ends: at a time, or when every ball is at rest.
struct Until {
  bool rest = true;
  double time = 0.0;  ///< used when rest is false
};

/// A cue strike at t = 0 (pool model).
struct CueSpec {
  std::int32_t ball = -1;  ///< index into Scenario::balls
  CueStrike strike;
  CueParams params;
};

struct Scenario {
  PhysicsParams physics;
  Table table;
  std::vector<BallSpec> balls;   ///< fixed properties, in scenario order
  std::vector<BallState> start;  ///< state at t = 0, same order
  std::vector<PairRestitution> pair_restitution;
  Until until;
  std::optional<double> sample_dt;  ///< report the state every dt seconds
  std::optional<CueSpec> cue;       ///< pool model: the shot
  std::uint64_t max_events = 10'000'000;
};

/// A problem found in a scenario: `path` is a JSON path such as
/// "balls[1].radius", `reason` says what is wrong with it.
struct ScenarioError {
  std::string path;
  std::string reason;
  /// True when the scenario asks for something valid that the engine
  /// does not implement yet (the pool model, pool tables, racks): the
  /// command line reports that as exit 1, not as an invalid scenario.
  bool unsupported = false;
};

/// Checks what a scenario built in code (not read from a file) must
/// satisfy before it is simulated: positive finite radii and masses,
/// restitutions in [0, 1], unique ids, a run that ends (check_run_ends),
/// balls inside the table and not overlapping a wall or each other.
/// Returns the first problem found.
std::optional<ScenarioError> validate(const Scenario& scenario);

/// Whether a run until "rest" ever ends: in the ideal model, the
/// friction model without deceleration, or the pool model without one of
/// its frictions (or gravity), a ball that moves or spins never stops and
/// the run would only end at max_events. Returns the problem at "until"
/// ("\"rest\" never comes: ..."), or nothing for a run to a time.
/// validate() includes this check; the ball indices and the cue must be
/// valid (validate() checks them first).
std::optional<ScenarioError> check_run_ends(const Scenario& scenario);

}  // namespace breakshot

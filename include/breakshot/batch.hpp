// Batch shots: many cue strikes on pool scenarios, run to their end on
// several threads, summarised in flat arrays (the Python package's
// breakshot.shots is this function).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "breakshot/noise.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/scenario.hpp"

namespace breakshot {

/// In ShotBatch::pockets: the ball left the table (physics.airborne).
inline constexpr std::int32_t kLeftTable = -2;

/// How a batch is run.
struct ShotBatchOptions {
  /// Threads to use; 0 uses every core. The results do not depend on it.
  unsigned threads = 0;
  /// Execution noise (parse_noise; none by default): shot k is played as
  /// perturb(strike k, noise, radius of the cue ball, mix_seed(seed, k)),
  /// so a shot's noise depends on the seed and its index only.
  NoiseModel noise;
  std::uint64_t seed = 0;
};

/// What k shots did, shot-major: the entry of shot k and ball i is at
/// k * balls + i. Balls are in scenario order.
struct ShotBatch {
  std::size_t shots = 0;
  std::size_t balls = 0;
  std::vector<Vec2> final_positions;      ///< shots x balls, at the run's end
  std::vector<std::int32_t> pockets;      ///< shots x balls: pocket index, -1 if not pocketed, kLeftTable if it left the table
  std::vector<std::int32_t> cushions;     ///< shots x balls: ball_cushion events of the ball
  std::vector<std::int32_t> cue_index;    ///< shots: index of the ball "cue"
  /// shots: the first ball the cue ball touches (a ball_ball event), -1
  /// if it touches none.
  std::vector<std::int32_t> first_hit;
  /// shots: cushions the cue ball touches before its first ball contact
  /// (all of them when it touches no ball).
  std::vector<std::int32_t> cushions_before_hit;
  std::vector<std::uint64_t> event_counts;  ///< shots
  std::vector<double> final_times;          ///< shots
  std::vector<std::uint8_t> complete;       ///< shots: 0 if max_events stopped the run
  std::vector<std::uint8_t> miscue;         ///< shots: the strike was a miscue
  std::vector<CueStrike> played;            ///< shots: the strike played (after noise)
};

/// Checks a valid scenario (validate(); read_scenario's are) for a batch:
/// the pool model, a ball with id "cue" at rest, no cue strike of its
/// own, and, when it runs until rest, frictions that stop a struck ball.
/// `where` prefixes the paths (e.g. "scenarios[3]."). Returns the first
/// problem.
std::optional<ScenarioError> check_shot_scenario(const Scenario& scenario,
                                                 const std::string& where = "");

/// Checks strike `k` as the scenario reader checks a "cue": speed finite
/// and > 0, phi finite, theta in [0, 90), a and b finite. Paths are
/// "strikes[k].speed" etc.
std::optional<ScenarioError> check_strike(const CueStrike& strike, std::size_t k);

/// Plays strikes[k] on scenarios[k] (or on scenarios[0] for every k when
/// one scenario is given) with the ball "cue" struck, each to the
/// scenario's `until` exactly as simulate() runs it with that "cue"
/// (default cue stick parameters; samples are not taken): the final
/// positions are simulate()'s, bit for bit. The shots are shared among
/// the threads and each writes its own entries, so the result is the same
/// for any thread count. The scenarios must be valid, as for Simulation,
/// and have the same number of balls. Throws std::invalid_argument ("path: reason") for what the
/// checks above refuse, or for a count mismatch.
ShotBatch play_shots(std::span<const Scenario* const> scenarios,
                     std::span<const CueStrike> strikes, const ShotBatchOptions& options = {});

/// All strikes on one scenario.
ShotBatch play_shots(const Scenario& scenario, std::span<const CueStrike> strikes,
                     const ShotBatchOptions& options = {});

}  // namespace breakshot

// Pot maps: how often a computer player pots one ball in one pocket, from
// one cue-ball position or from every point of a grid (docs/python.md,
// "Pot maps").
//
// A level plays the pot the way it plays in a game, limited to that ball
// and that pocket: its own shot generation (direct, bank, kick and
// combination pots of the ball into the pocket, with its own speeds and
// spins; no safeties), its own shortlist size and, for the levels that
// do it, its own centred aims; the shortlisted shots are sampled under
// its own noise and the one that pots most often is its best shot (the
// shortlist ranks by the pot's prior, not by the leave as in a game). How
// often that shot pots is then measured on fresh noise draws, so the
// figure is not flattered by the choice.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"

namespace breakshot {

struct PotMapOptions {
  /// Noisy plays per sampled candidate, and plays that measure the best
  /// shot (0: the level's own `samples`, or 16 for a level that does not
  /// sample).
  int samples = 0;
  /// Candidates sampled (0: the level's own `candidates`).
  int candidates = 0;
  std::uint64_t seed = 0;
  /// Worker threads (0: all cores). pot_chance spreads its plays over
  /// them, pot_map its cells (each cell then runs on one thread). The
  /// numbers are the same for any count.
  int threads = 0;
};

/// What one cue-ball position gives.
struct PotChance {
  /// The cue ball can be placed there (Rules::check_placement with the
  /// ball in hand anywhere: on the playing surface clear of the cushions
  /// and of every ball).
  bool placeable = false;
  /// Share of `plays` noisy plays of `aim` that potted the ball in the
  /// pocket with no foul; 0 when no shot was found, NaN where the cue
  /// ball cannot be placed.
  double probability = std::numeric_limits<double>::quiet_NaN();
  /// Candidate shots the level's generation found for the ball and pocket
  /// (each noiselessly pots it there).
  int shots = 0;
  /// The best shot (meaningful when shots > 0) and its kind.
  CueStrike aim;
  ShotKind kind = ShotKind::direct;
  /// The plays `probability` counts (0 when there was nothing to play).
  int plays = 0;
  /// Simulations run for this position, generation's not counted.
  std::int64_t simulations = 0;
};

/// The chance that `level` pots `ball` (its number) in `pocket` (an index
/// into rules.table().pockets) with the cue ball at `cue` and the other
/// balls as in `state` (phase shot; the state's own cue-ball position and
/// ball in hand are ignored; whose turn and the 8-ball groups decide which
/// balls may be hit first, so in 9-ball a ball other than the lowest can
/// only be potted by a combination). Deterministic for `options.seed`.
/// Throws std::invalid_argument naming the problem for a state not in
/// phase shot, a ball number that is not an object ball on the table, a
/// pocket index out of range, or options out of range.
PotChance pot_chance(const Rules& rules, const GameState& state, Vec2 cue, int ball, int pocket,
                     const AiLevel& level, const PotMapOptions& options = {});

/// pot_chance at every point (xs[i], ys[j]) of a grid.
struct PotMap {
  std::vector<double> xs;
  std::vector<double> ys;
  /// Row-major: cells[j * xs.size() + i] is the point (xs[i], ys[j]).
  std::vector<PotChance> cells;
};

/// The map over the grid xs by ys. Cell k (row-major, as in
/// PotMap::cells) is pot_chance with the seed mix_seed(options.seed, k)
/// and one thread, so any cell can be reproduced alone; the cells run in
/// parallel on options.threads threads. Throws as pot_chance does (before
/// any work), and for an empty grid or a coordinate that is not finite.
PotMap pot_map(const Rules& rules, const GameState& state, int ball, int pocket,
               const AiLevel& level, const std::vector<double>& xs,
               const std::vector<double>& ys, const PotMapOptions& options = {});

}  // namespace breakshot

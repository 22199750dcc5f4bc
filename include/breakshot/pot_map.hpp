// Pot maps: how often a computer player pots one ball in one pocket, from
// one cue-ball position or from every point of a grid (docs/python.md,
// "Pot maps"), in any game played on a table with pockets: 8-ball,
// 9-ball, 10-ball and snooker.
//
// A level plays the pot the way it plays in a game, limited to that ball
// and that pocket: its own shot generation (direct, bank, kick and
// combination pots of the ball into the pocket, with its own speeds and
// spins, each carrying the call or the nomination the game's rules ask
// for; no safeties), its own shortlist size and, for the levels that
// do it, its own centred aims; the shortlisted shots are sampled under
// its own noise and the one that pots most often is its best shot (the
// shortlist ranks by the pot's prior, not by the leave as in a game). How
// often that shot pots is then measured on fresh noise draws, so the
// figure is not flattered by the choice. Whether a play potted the ball
// is the game's own ruling of it (counts_as_pot).
#pragma once

#include <cstdint>
#include <string>
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

/// What one cue-ball position gives. Every field is a number (never NaN).
struct PotChance {
  /// The cue ball can lie there: on the playing surface clear of the
  /// cushions and of every ball (Rules::check_placement with the ball in
  /// hand anywhere, which asks the same of every game with pockets), and
  /// not inside a pocket (its centre within the pocket's radius of the
  /// pocket's centre, where the physics has a ball fall in).
  bool placeable = false;
  /// Why it cannot (Rules::check_placement's words, or the pocket it
  /// would lie in); empty when it can.
  std::string unplaceable;
  /// Share of `plays` noisy plays of `aim` that potted the ball in the
  /// pocket (counts_as_pot); 0 when no shot was found, and 0 where the
  /// cue ball cannot be placed (`placeable` false says so).
  double probability = 0.0;
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

/// Whether the shot ruled in `outcome` (Rules::apply from `before`)
/// potted `ball` in `pocket` as the game counts a pot: the ball fell in
/// that pocket, the ruling has no foul, and the shot did not end the game
/// with the shooter losing it. So the 8 pocketed before its time in
/// 8-ball (a lost game, no foul) is no pot, nor is a ball that drops
/// with it; in snooker a ball not on that drops is a foul
/// (Foul::wrong_ball_potted), so potting a colour while the ball on is a
/// red is no pot.
bool counts_as_pot(const GameState& before, const Outcome& outcome, int ball, int pocket);

/// The chance that `level` pots `ball` (its number) in `pocket` (an index
/// into rules.table().pockets) with the cue ball lying at `cue` and the
/// other balls as in `state` (phase shot). The state's own cue-ball
/// position and ball in hand (the kitchen, snooker's D) are ignored: the
/// map asks about the cue ball lying at any point, as a shot may leave
/// it, so in every game the point is checked as a ball in hand anywhere
/// is (on the surface, clear of the cushions and of every ball), and not
/// in a pocket; the state with the cue ball there has no ball in hand.
/// Everything else the rules read stays the state's: whose turn it is,
/// the 8-ball groups, the lowest ball in 9-ball and 10-ball (a ball other
/// than the lowest can only be potted by a combination), snooker's ball
/// on (the reds; after a red a colour, nominated; the lowest colour once
/// the reds are gone) and score. Deterministic for `options.seed`. Throws
/// std::invalid_argument naming the problem for a game without pockets
/// (three-cushion), a state not in phase shot or of another game, a ball
/// number that is not an object ball on the table, a pocket index out of
/// range, or options out of range.
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
/// any work), and for an empty grid or a coordinate that is not finite;
/// a point where the cue ball cannot lie is a cell with `placeable` false.
PotMap pot_map(const Rules& rules, const GameState& state, int ball, int pocket,
               const AiLevel& level, const std::vector<double>& xs,
               const std::vector<double>& ys, const PotMapOptions& options = {});

}  // namespace breakshot

// The judge (internal): a shot's noiseless play ruled by the game's own
// rules, as shot generation rules every candidate it keeps. The ruling
// is the ruleset's (Rules::apply_events on the events the simulation
// gave, the path Rules::apply takes), never a copy of a rule.
#pragma once

#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/simulation.hpp"
#include "geometry.hpp"

namespace breakshot::ai_detail {

/// What the judge found: the facts shot generation ranks by and the
/// state the ruling leaves.
struct Judged {
  /// No foul, and the game not lost (8-ball: no 8 before its time).
  bool legal = false;
  std::vector<Foul> fouls;  ///< the ruling's fouls, in its order
  bool wins = false;  ///< the shot wins the game for the shooter
  int first_hit = -1;
  std::vector<int> pocketed;
  std::vector<int> pocket_of;
  ai::Layout after;
  GameState next;  ///< the state the ruling leaves
};

/// Runs `sim` to rest and rules `shot`, played from `state`, on what it
/// did. `sim` is a run of `rules.shot_scenario(state, shot.strike,
/// &numbers)` (or of that scenario re-armed with the same strike),
/// started and possibly stepped part of the way; `numbers` maps its ball
/// indices to ball numbers. A shot the rules refuse, or a run that does
/// not come to rest, is judged not legal (and nothing else is filled in).
Judged judge(const Rules& rules, const GameState& state, const Shoot& shot, Simulation& sim,
             const std::vector<int>& numbers);

/// The pocket `ball` fell into in `j`'s shot, -1 if it did not.
int pocket_of(const Judged& j, int ball);

}  // namespace breakshot::ai_detail

// Helpers for the snooker tests (test_rules_snooker.cpp,
// test_ai_snooker.cpp): the rules on the 12 ft table, a frame with only
// the cue ball on the table, and balls put on it by hand.
#pragma once

#include <algorithm>
#include <cstdint>

#include "breakshot/game.hpp"

namespace snooker_fixtures {

using namespace breakshot;

inline const Rules& rules() {
  static const Rules r(snooker_config());
  return r;
}

/// A frame in progress (racked from `rack_seed`) with only the cue ball on
/// the table at `cue`: player 0 to shoot, on a red, 0-0.
inline GameState bare(Vec2 cue, std::uint64_t rack_seed) {
  GameState s = rules().start(rack_seed, 0);
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  s.on_table[0] = 1;
  s.position[0] = cue;
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.shots = 1;
  return s;
}

inline void put(GameState& s, int ball, Vec2 p) {
  s.position[static_cast<std::size_t>(ball)] = p;
  s.on_table[static_cast<std::size_t>(ball)] = 1;
}

}  // namespace snooker_fixtures

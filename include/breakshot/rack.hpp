// Racks: the regulation starting positions of the object balls.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "breakshot/scenario.hpp"
#include "breakshot/table.hpp"

namespace breakshot {

struct RackedBall {
  std::string id;  ///< "1" ... "15"
  Vec2 position;
};

/// The balls of `game` ("eight_ball" or "nine_ball") racked on a pool
/// table: apex ball on the foot spot, rows toward the foot rail, balls
/// frozen with the tiny random gaps (from `seed`) that real racks have,
/// never overlapping. 8-ball: 15 balls, the 8 in the middle of the third
/// row, a solid and a stripe in the back corners. 9-ball: 9 balls in a
/// diamond, the 1 at the apex and the 9 in the middle. Throws
/// std::invalid_argument for an unknown game.
std::vector<RackedBall> make_rack(const std::string& game, const Table& table, double radius,
                                  std::uint64_t seed);

/// A break as the pool examples describe it: the pool model with its
/// defaults (docs/scenario.md), a `size` table, the rack of `game` from
/// `seed`, a cue ball "cue" on the head spot (first in the ball list), and
/// a level centre-ball strike at `cue_speed` m/s toward the apex, run to
/// rest. Tests, benchmarks and programs change what they need from there.
Scenario make_break_scenario(const std::string& game, const std::string& size,
                             std::uint64_t seed, double cue_speed);

}  // namespace breakshot

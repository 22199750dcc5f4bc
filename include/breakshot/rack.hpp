// Racks: the regulation starting positions of the object balls.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "breakshot/scenario.hpp"
#include "breakshot/table.hpp"

namespace breakshot {

struct RackedBall {
  std::string id;  ///< "1" ... "15"; snooker "red1" ... "red15", "yellow" ... "black";
                   ///< three-cushion "white", "yellow", "red"
  Vec2 position;
};

/// The balls of `game` ("eight_ball", "nine_ball", "snooker" or
/// "three_cushion") racked on a pool table (eight_ball, nine_ball), the
/// snooker table (snooker) or the carom table (three_cushion):
/// balls frozen with the tiny random gaps (from `seed`) that real racks
/// have, never overlapping. 8-ball: apex ball on the foot spot, rows
/// toward the foot rail, 15 balls, the 8 in the middle of the third row, a
/// solid and a stripe in the back corners; listed by number. 9-ball: 9
/// balls in a diamond, the 1 at the apex and the 9 in the middle; listed
/// by number. Snooker: 15 reds in a triangle whose apex red stands just
/// behind the pink spot (kSnookerPyramidGap away), rows toward the top
/// cushion, then the six colours on their spots; listed red1 (the apex),
/// red2 ... red15 row by row (toward +y within a row), yellow, green,
/// brown, blue, pink, black. Three-cushion: UMB's starting position, the
/// red on the top spot, the yellow (the opponent's ball) on the bottom
/// spot and the white (the breaker's) on the starting spot the seed draws
/// (CaromMarks::starting_spots), exactly on the spots; listed white,
/// yellow, red. Throws std::invalid_argument for an unknown game or a rack
/// on the wrong table.
std::vector<RackedBall> make_rack(const std::string& game, const Table& table, double radius,
                                  std::uint64_t seed);

/// Where the snooker break-off scenario puts the cue ball: on the baulk
/// line halfway between the brown and yellow spots (in the D).
Vec2 snooker_break_off_spot();

/// A break as the pool examples describe it: the pool model with its
/// defaults (docs/scenario.md), a `size` table, the rack of `game` from
/// `seed`, a cue ball "cue" on the head spot (first in the ball list), and
/// a level centre-ball strike at `cue_speed` m/s toward the apex, run to
/// rest. Tests, benchmarks and programs change what they need from there.
/// For "snooker" (size "12ft"): the snooker table and balls, "cue" on
/// snooker_break_off_spot(), then red1 ... red15 and the colours as
/// make_rack lists them, and a level centre-ball strike that takes a
/// quarter of red11 (the yellow-side end of the back row) on its outer
/// side. For "three_cushion" (size "10ft"): the carom table and balls,
/// white, yellow and red as make_rack lists them, and a level centre-ball
/// strike of the white straight at the red. Throws std::invalid_argument
/// for an unknown game or size.
Scenario make_break_scenario(const std::string& game, const std::string& size,
                             std::uint64_t seed, double cue_speed);

}  // namespace breakshot

// The snooker table (WPBSA 12 ft), its balls and its markings. Figures and
// their sources: docs/physics.md, "Snooker table".
#pragma once

#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"

namespace breakshot {

/// A snooker ball: 52.5 mm across (WPBSA Official Rules, Section 1, 2:
/// 52.5 mm +/- 0.05 mm).
inline constexpr double kSnookerBallRadius = 0.02625;  ///< m
/// WPBSA gives no mass (only that a set agrees within 3 g). 140.6 g is
/// the measured mass of the snooker balls of Mathavan, Jackson and Parkin
/// 2014 (Sports Eng. 17), the ball-ball experiments this engine checks
/// its Mathavan impact against.
inline constexpr double kSnookerBallMass = 0.1406;  ///< kg
/// The gap left between the pink and the apex red of the triangle (the
/// rules say only "as close as possible without touching"), and the gap
/// between neighbouring reds before the rack's tiny random offsets: the
/// pool racks' lattice gap (src/game/rack.cpp).
inline constexpr double kSnookerPyramidGap = 0.2e-3;  ///< m

/// The markings of a snooker table, in the table's coordinates (x along
/// the length, the baulk end at x = 0 as the pool table's head; y across).
/// Seen from the baulk end looking up the table (toward +x), +y is to the
/// left: the yellow spot, on the right of the D, has the smaller y.
struct SnookerMarks {
  double baulk_x;   ///< the baulk line, 737 mm from the bottom (baulk) cushion
  Vec2 d_centre;    ///< centre of the D (on the baulk line, mid-table)
  double d_radius;  ///< 292 mm
  Vec2 yellow, green, brown, blue, pink, black;  ///< the colour spots
  Vec2 pyramid_apex;  ///< where the apex red sits: behind the pink, not touching
};

/// The WPBSA 12 ft table: playing area 3569 x 1778 mm, six pockets with
/// round jaws, the pool table's cushion defaults (CushionParams{}: the
/// default law and its nose height, 0.635 of the diameter, fitted together
/// to Mathavan et al. 2010's snooker-cushion model). Shape "snooker";
/// head_spot is the brown spot, foot_spot the pink (pyramid) spot. Names
/// of pockets and cushions as on the pool table (docs/physics.md).
Table make_snooker_table();

/// The markings of make_snooker_table().
SnookerMarks snooker_marks();

}  // namespace breakshot

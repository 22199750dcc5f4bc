// The carom table (the UMB match table), its balls and its markings.
// Figures and their sources: docs/physics.md, "Carom table".
#pragma once

#include <array>
#include <vector>

#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"

namespace breakshot {

/// A carom ball: 61.5 mm across, the upper end of UMB's 61 to 61.5 mm.
inline constexpr double kCaromBallRadius = 0.03075;  ///< m
/// 210 g, within UMB's 205 to 220 g.
inline constexpr double kCaromBallMass = 0.210;  ///< kg
/// The height of the cushion's nose above the cloth: 37 mm (UMB), 0.6016
/// of the carom ball's diameter. The carom table's nose_height is this
/// fraction, so that any ball meets the rail at the same fraction of its
/// diameter and a carom ball at 37 mm.
inline constexpr double kCaromCushionHeight = 0.037;  ///< m

/// The markings of the carom table, in the table's coordinates (x along
/// the length, the bottom (head) cushion at x = 0; y across). UMB's names:
/// the top spot (where the red starts), the bottom spot (the opponent's
/// ball at the start) on the starting line, the centre spot, and the two
/// starting spots beside the bottom spot on the starting line.
struct CaromMarks {
  Vec2 top_spot;     ///< on the long string, a quarter of the length from the top cushion
  Vec2 centre_spot;  ///< the middle of the table
  Vec2 bottom_spot;  ///< on the long string, a quarter of the length from the bottom cushion
  /// The starting spots, 182 mm either side of the bottom spot on the
  /// starting line: [0] at the smaller y, [1] at the larger.
  std::array<Vec2, 2> starting_spots;
  /// The diamonds on the rails, as points on the cushion noses' lines:
  /// the long cushions at every eighth of the length, the short ones at
  /// every quarter of the width (seven and three a cushion, corners left
  /// out). Bottom cushion, right, top, left, each in order along +x or +y.
  std::vector<Vec2> diamonds;
};

/// The carom match table: playing area 2840 x 1420 mm within the cushion
/// noses, no pockets, four straight cushions named `rail_left` (the bottom
/// or head cushion, x = 0), `rail_right` (the top or foot cushion),
/// `rail_bottom` (y = 0) and `rail_top`. Shape "carom"; head_spot is the
/// bottom spot, foot_spot the top spot. The cushions are the pool table's
/// (CushionParams{}) but for the nose height, kCaromCushionHeight over the
/// carom ball's diameter.
Table make_carom_table();

/// The markings of make_carom_table().
CaromMarks carom_marks();

}  // namespace breakshot

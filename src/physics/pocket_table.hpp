// The six-pocket table both pocket tables are built from (pool_table.cpp,
// snooker_table.cpp): straight cushion noses, pockets whose jaws are a
// straight facing and a round piece where the nose turns into the facing,
// and the pocket circles that capture a ball. Internal to the physics
// layer.
//
// Coordinates (docs/scenario.md): the origin is the lower-left corner of
// the playing surface at the cushion noses, x runs along the length L and
// y along the width W, so the playing surface is [0, L] x [0, W].
//
// Pockets, by name, at the nominal corners of the playing surface:
//   bottom_left (0, 0)   side_bottom (L/2, 0)   bottom_right (L, 0)
//   top_left    (0, W)   side_top    (L/2, W)   top_right    (L, W)
// Cushion noses (straight walls between pockets):
//   rail_bottom_left   y = 0, from bottom_left to side_bottom
//   rail_bottom_right  y = 0, from side_bottom to bottom_right
//   rail_top_left      y = W, from top_left to side_top
//   rail_top_right     y = W, from side_top to top_right
//   rail_left          x = 0, rail_right  x = L
// Jaws: every pocket mouth lies between two jaws. A corner pocket's jaws
// are <pocket>_jaw_x (the one on the long rail, along x) and
// <pocket>_jaw_y (on the short rail, along y); a side pocket's are
// <pocket>_jaw_left and <pocket>_jaw_right (smaller and larger x). Each
// jaw is a straight facing (a segment wall named after the jaw) and a
// rounded piece where the cushion nose turns into the facing (an arc wall
// named <jaw>_tip), tangent to both.
//
// Geometry of one pocket (PocketSpec):
// - The mouth is measured between the two "pointed lips", the points where
//   the cushion nose line meets the facing line. The round piece is
//   tangent to the nose and to the facing, so the nominal lip stays
//   exactly where the mouth is measured, whatever the radius.
// - The cut angle, between the cushion nose (pointing away from the
//   pocket) and the facing (pointing into the pocket), measured through
//   the cushion, sets the facing's direction.
// - The shelf is the distance from the mouth line to the drop point of the
//   slate, along the pocket axis.
// - Capture: a ball has fallen when its centre is over the slate hole,
//   modelled as a circle whose nearest point to the table lies on the
//   pocket axis at the shelf depth behind the mouth line and whose radius
//   is half the width between the facings at that depth. The facings run
//   on into the pocket until they leave that circle again, so the walls and
//   the pocket circles close the table: a ball centre can leave the
//   playing area only through a pocket circle.
#pragma once

#include "breakshot/table.hpp"

namespace breakshot::pocket_table {

struct PocketSpec {
  double mouth;    ///< lip to lip (m)
  double cos_cut;  ///< cut angle between nose and facing, through the cushion
  double sin_cut;
  double shelf;       ///< mouth line to the drop point, along the axis (m)
  double tip_radius;  ///< radius of the round piece from nose to facing (m)
  /// The outline follows each round piece with 2^tip_depth - 1 points
  /// between its ends (drawing and containment only; the walls are exact).
  int tip_depth;
};

/// The six-pocket table of length L and width W with `corner` pockets at
/// the four corners and `side` pockets in the middle of the long rails:
/// outline, walls, pockets, length, width and the bounding box (min, max)
/// of everything a ball centre can reach. The caller sets the shape, the
/// spots and the cushion parameters.
Table six_pocket_table(double L, double W, const PocketSpec& corner, const PocketSpec& side);

}  // namespace breakshot::pocket_table

// Pocket billiards tables (WPA): cushion noses, pocket jaws with rounded
// tips, and the pocket circles that capture a ball. The six-pocket layout,
// the names and the construction are shared with the snooker table
// (pocket_table.hpp).
//
// The head is the short rail at x = 0 (head spot (L/4, W/2)), the foot the
// short rail at x = L (foot spot (3L/4, W/2)).
//
// Geometry (WPA Equipment Specifications, "Pocket Openings and
// Measurements"; docs/physics.md has the full derivation):
// - The mouth is measured between the two "pointed lips", the points where
//   the cushion nose line meets the facing line. Corner 4.5 in, side 5 in
//   (the smallest WPA values; WPA allows up to 4.625 and 5.125 in).
// - The horizontal cut angle, between the cushion nose (pointing away from
//   the pocket) and the facing (pointing into the pocket), measured through
//   the cushion, is 142 degrees at corner pockets and 104 degrees at side
//   pockets. So a corner facing is 38 degrees off its rail, 7 degrees
//   steeper than the 45-degree pocket axis, and a side facing is 14
//   degrees off the perpendicular: both pairs of facings converge into
//   the pocket.
// - The shelf (mouth line to the drop point of the slate, along the pocket
//   axis): corner 1.75 in (WPA 1 to 2.25 in; BCA 1 5/8 to 1 7/8 in), side
//   3/16 in (WPA and BCA 0 to 3/8 in).
// - The lip is rounded with a radius of 1/8 in (a modelling choice: WPA
//   calls the lip pointed; 1/8 in is the WPA-preferred facing thickness).
//   The arc is tangent to the nose and to the facing, so the nominal lip
//   point stays exactly where the mouth is measured.
// - Capture: a ball has fallen when its centre is over the slate hole,
//   modelled as a circle whose nearest point to the table lies on the
//   pocket axis at the shelf depth behind the mouth line and whose radius
//   is half the width between the facings at that depth. The facings run
//   on into the pocket until they leave that circle again, so the walls and
//   the pocket circles close the table: a ball centre can leave the
//   playing area only through a pocket circle.
// - The same pockets on every size (WPA gives one set of pocket
//   dimensions; it does not specify 7 ft tables).
// - The vertical pocket angle (12-15 degrees of back draft on the facings)
//   is a 3-D feature and is not modelled in the plan view.
#include <cmath>
#include <stdexcept>
#include <string>

#include "breakshot/table.hpp"
#include "physics/pocket_table.hpp"

namespace breakshot {

namespace {

constexpr double kInch = 0.0254;

// cos and sin of the cut angles, written out so that the geometry is the
// same bit for bit whatever the maths library.
constexpr double kCos142 = -0.7880107536067219;
constexpr double kSin142 = 0.6156614753256584;
constexpr double kCos104 = -0.24192189559966779;
constexpr double kSin104 = 0.9702957262759965;

constexpr double kTipRadius = 0.125 * kInch;
constexpr pocket_table::PocketSpec kCorner{4.5 * kInch,  kCos142,    kSin142,
                                           1.75 * kInch, kTipRadius, 3};
constexpr pocket_table::PocketSpec kSide{5.0 * kInch,    kCos104,    kSin104,
                                         0.1875 * kInch, kTipRadius, 3};

}  // namespace

Table make_pool_table(const std::string& size) {
  double L = 0.0;
  double W = 0.0;
  // Playing surfaces as the scenario contract gives them (WPA: 9 ft 100 x
  // 50 in; 8 ft 92 x 46 in; 7 ft tables, 78 x 39 in, are not WPA sizes).
  if (size == "9ft") {
    L = 2.54;
    W = 1.27;
  } else if (size == "8ft") {
    L = 2.34;
    W = 1.17;
  } else if (size == "7ft") {
    L = 1.98;
    W = 0.99;
  } else {
    throw std::invalid_argument("unknown pool table size \"" + size +
                                "\" (expected \"7ft\", \"8ft\" or \"9ft\")");
  }

  Table t = pocket_table::six_pocket_table(L, W, kCorner, kSide);
  t.shape = TableShape::pool;
  t.head_spot = {0.25 * L, 0.5 * W};
  t.foot_spot = {0.75 * L, 0.5 * W};
  return t;
}

}  // namespace breakshot

// The snooker table (WPBSA 12 ft) and its markings. The six-pocket layout,
// the names and the construction are the pool table's (pocket_table.hpp);
// what differs is the size and the pockets' shape. Figures and sources in
// full: docs/physics.md, "Snooker table".
//
// Published (WPBSA Official Rules of Snooker, Section 1 "Equipment"):
// - playing area within the cushion faces 3569 x 1778 mm (11 ft 8.5 in x
//   5 ft 10 in, +/- 13 mm);
// - the baulk line 737 mm (29 in) from the face of the bottom cushion; the
//   D a semicircle in baulk of radius 292 mm (11.5 in) about the middle of
//   the baulk line;
// - spots: black 324 mm (12.75 in) from the face of the top cushion, blue
//   midway between the top and bottom cushions, pink midway between the
//   blue spot and the top cushion, brown the middle of the baulk line,
//   yellow and green the corners of the D, yellow on the right seen from
//   the baulk end;
// - "the pocket openings shall conform to the templates authorised by the
//   WPBSA": the templates themselves are not published.
//
// Chosen (no published figure; docs/physics.md says why):
// - corner mouth 83 mm and middle mouth 87 mm between the pointed lips
//   (pooltool's SnookerTableSpecs defaults, corner_pocket_width and
//   side_pocket_width, measured the same way);
// - the round jaws: the nose turns into the facing on an arc of radius
//   4 in (101.6 mm) at the corners and 2.5 in (63.5 mm) at the middle
//   pockets (pooltool's corner_jaw_radius and side_jaw_radius);
// - facings converging into the pocket by 2 degrees on each side (cut
//   angles 137 and 92 degrees), so that the throat narrows slightly behind
//   the mouth as a template-cut jaw does, and the capture circle meets the
//   facings at a clean angle;
// - shelves (mouth line to the fall): corner 32 mm, middle 16 mm;
// - the cushions: the pool table's defaults (CushionParams{}), nose height
//   0.635 of the diameter included (33.3 mm here): the default law's
//   restitution and nose height were fitted together so that a rolling ball
//   driven straight in comes back as in Mathavan et al. 2010's model of a
//   snooker cushion (0.914 of its speed); at the paper's own nose height,
//   7R/5 (36.75 mm), the default law would return 0.940. The mathavan_2010
//   law takes 7R/5 itself.
#include "breakshot/snooker.hpp"
#include "physics/pocket_table.hpp"

namespace breakshot {

namespace {

constexpr double kLength = 3.569;
constexpr double kWidth = 1.778;
constexpr double kInch = 0.0254;

// cos and sin of the cut angles, written out so that the geometry is the
// same bit for bit whatever the maths library.
constexpr double kCos137 = -0.7313537016191705;
constexpr double kSin137 = 0.6819983600624986;
constexpr double kCos92 = -0.034899496702500955;
constexpr double kSin92 = 0.9993908270190958;

constexpr pocket_table::PocketSpec kCorner{0.083, kCos137, kSin137, 0.032, 4.0 * kInch, 5};
constexpr pocket_table::PocketSpec kMiddle{0.087, kCos92, kSin92, 0.016, 2.5 * kInch, 5};

}  // namespace

SnookerMarks snooker_marks() {
  SnookerMarks m{};
  const double mid = 0.5 * kWidth;
  m.baulk_x = 0.737;
  m.d_centre = {m.baulk_x, mid};
  m.d_radius = 0.292;
  m.brown = m.d_centre;
  m.yellow = {m.baulk_x, mid - m.d_radius};
  m.green = {m.baulk_x, mid + m.d_radius};
  m.blue = {0.5 * kLength, mid};
  m.pink = {0.75 * kLength, mid};
  m.black = {kLength - 0.324, mid};
  m.pyramid_apex = {m.pink.x + 2.0 * kSnookerBallRadius + kSnookerPyramidGap, mid};
  return m;
}

Table make_snooker_table() {
  Table t = pocket_table::six_pocket_table(kLength, kWidth, kCorner, kMiddle);
  t.shape = TableShape::snooker;
  const SnookerMarks m = snooker_marks();
  t.head_spot = m.brown;
  t.foot_spot = m.pink;
  return t;
}

}  // namespace breakshot

// The carom match table and its markings. Figures and sources in full:
// docs/physics.md, "Carom table".
//
// Published (UMB, World Rules of Carom Billiard, chapter "Equipment"):
// - playing area within the cushion noses 2840 x 1420 mm (+/- 5 mm);
// - cushion nose 37 mm above the cloth;
// - spots on the long string: the top spot and the bottom spot a quarter
//   of the length from the top and the bottom cushion (710 mm), the centre
//   spot midway; the starting line through the bottom spot, with a
//   starting spot 182 mm to either side of it.
//
// Chosen (no published figure):
// - the cushions' restitution and friction: the pool table's defaults
//   (CushionParams{}); only the nose height differs;
// - the diamonds as points on the noses' lines (the rail's own diamonds sit
//   on the rail top, outside; the lines through them meet the nose at the
//   same eighths and quarters).
#include <string>

#include "breakshot/carom.hpp"

namespace breakshot {

namespace {

constexpr double kLength = 2.84;
constexpr double kWidth = 1.42;
constexpr double kStartingSpotOffset = 0.182;

Wall cushion(Vec2 a, Vec2 b, Vec2 normal, std::string name) {
  Wall w;
  w.kind = WallKind::segment;
  w.a = a;
  w.b = b;
  w.normal = normal;
  w.name = std::move(name);
  return w;
}

}  // namespace

CaromMarks carom_marks() {
  CaromMarks m;
  const double mid = 0.5 * kWidth;
  m.top_spot = {0.75 * kLength, mid};
  m.centre_spot = {0.5 * kLength, mid};
  m.bottom_spot = {0.25 * kLength, mid};
  m.starting_spots = {Vec2{m.bottom_spot.x, mid - kStartingSpotOffset},
                      Vec2{m.bottom_spot.x, mid + kStartingSpotOffset}};
  for (int k = 1; k < 8; ++k) m.diamonds.push_back({kLength * k / 8.0, 0.0});
  for (int k = 1; k < 4; ++k) m.diamonds.push_back({kLength, kWidth * k / 4.0});
  for (int k = 1; k < 8; ++k) m.diamonds.push_back({kLength * k / 8.0, kWidth});
  for (int k = 1; k < 4; ++k) m.diamonds.push_back({0.0, kWidth * k / 4.0});
  return m;
}

Table make_carom_table() {
  Table t;
  t.shape = TableShape::carom;
  t.length = kLength;
  t.width = kWidth;
  t.outline = {{0.0, 0.0}, {kLength, 0.0}, {kLength, kWidth}, {0.0, kWidth}};
  t.walls.push_back(cushion({0.0, kWidth}, {0.0, 0.0}, {1.0, 0.0}, "rail_left"));
  t.walls.push_back(cushion({kLength, 0.0}, {kLength, kWidth}, {-1.0, 0.0}, "rail_right"));
  t.walls.push_back(cushion({0.0, 0.0}, {kLength, 0.0}, {0.0, 1.0}, "rail_bottom"));
  t.walls.push_back(cushion({kLength, kWidth}, {0.0, kWidth}, {0.0, -1.0}, "rail_top"));
  t.min = {0.0, 0.0};
  t.max = {kLength, kWidth};
  const CaromMarks m = carom_marks();
  t.head_spot = m.bottom_spot;
  t.foot_spot = m.top_spot;
  t.cushion.nose_height = kCaromCushionHeight / (2.0 * kCaromBallRadius);
  return t;
}

}  // namespace breakshot

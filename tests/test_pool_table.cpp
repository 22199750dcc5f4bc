// The pool tables (make_pool_table) and the racks (make_rack): WPA
// dimensions, the pocket geometry, closure (no ball can leave the table
// but through a pocket), and the racks' layout and determinism. Plain
// geometry: no simulator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/rack.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"
#include "table_geometry.hpp"

namespace breakshot::test_pool_table {
namespace {

using namespace table_geometry;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInch = 0.0254;
constexpr double kBallR = 0.028575;  // 2.25 in diameter

struct Size {
  const char* name;
  double length;
  double width;
};
constexpr Size kSizes[] = {{"9ft", 2.54, 1.27}, {"8ft", 2.34, 1.17}, {"7ft", 1.98, 0.99}};

const char* const kCornerPockets[] = {"bottom_left", "bottom_right", "top_right", "top_left"};
const char* const kSidePockets[] = {"side_bottom", "side_top"};

// ---------------------------------------------------------------------------
// Tables

// The shapes' names are the scenario format's text ("table.shape").
TEST(TableShapes, NamesRoundTripAndOthersAreRefused) {
  const std::pair<TableShape, const char*> names[] = {{TableShape::rectangle, "rectangle"},
                                                      {TableShape::polygon, "polygon"},
                                                      {TableShape::pool, "pool"},
                                                      {TableShape::snooker, "snooker"},
                                                      {TableShape::carom, "carom"}};
  for (const auto& [shape, name] : names) {
    EXPECT_EQ(to_string(shape), name);
    TableShape read = TableShape::rectangle;
    ASSERT_TRUE(parse_table_shape(name, read)) << name;
    EXPECT_EQ(read, shape) << name;
  }
  for (const char* other : {"", "Pool", "pool ", "billiards"}) {
    TableShape read = TableShape::carom;
    EXPECT_FALSE(parse_table_shape(other, read)) << other;
    EXPECT_EQ(read, TableShape::carom) << "left alone on a refusal: " << other;
  }
  EXPECT_EQ(make_rectangle({0, 0}, {1, 1}).shape, TableShape::rectangle);
}

TEST(PoolTable, DimensionsAndSpots) {
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    EXPECT_EQ(t.shape, TableShape::pool);
    EXPECT_DOUBLE_EQ(t.length, s.length);
    EXPECT_DOUBLE_EQ(t.width, s.width);
    EXPECT_DOUBLE_EQ(t.head_spot.x, s.length / 4);
    EXPECT_DOUBLE_EQ(t.head_spot.y, s.width / 2);
    EXPECT_DOUBLE_EQ(t.foot_spot.x, 3 * s.length / 4);
    EXPECT_DOUBLE_EQ(t.foot_spot.y, s.width / 2);
    EXPECT_EQ(t.pockets.size(), 6U);
    // The rails lie on the edges of the playing surface.
    EXPECT_DOUBLE_EQ(wall_named(t, "rail_left").a.x, 0.0);
    EXPECT_DOUBLE_EQ(wall_named(t, "rail_right").a.x, s.length);
    for (const char* r : {"rail_bottom_left", "rail_bottom_right"}) {
      EXPECT_DOUBLE_EQ(wall_named(t, r).a.y, 0.0);
      EXPECT_DOUBLE_EQ(wall_named(t, r).b.y, 0.0);
    }
    for (const char* r : {"rail_top_left", "rail_top_right"}) {
      EXPECT_DOUBLE_EQ(wall_named(t, r).a.y, s.width);
      EXPECT_DOUBLE_EQ(wall_named(t, r).b.y, s.width);
    }
    // The box holds the playing surface, the outline and the pockets.
    EXPECT_LT(t.min.x, 0.0);
    EXPECT_LT(t.min.y, 0.0);
    EXPECT_GT(t.max.x, s.length);
    EXPECT_GT(t.max.y, s.width);
    for (const Vec2 p : t.outline) EXPECT_TRUE(in_box(t, p));
    for (const Pocket& k : t.pockets) {
      EXPECT_LE(t.min.x, k.centre.x - k.radius);
      EXPECT_GE(t.max.x, k.centre.x + k.radius);
      EXPECT_LE(t.min.y, k.centre.y - k.radius);
      EXPECT_GE(t.max.y, k.centre.y + k.radius);
    }
    // And not much more: the pockets reach about 13 cm out at most.
    EXPECT_GT(t.min.x, -0.15);
    EXPECT_LT(t.max.y, s.width + 0.15);
  }
}

TEST(PoolTable, UnknownSizeThrows) {
  for (const char* s : {"", "6ft", "10ft", "9FT", "9 ft", "snooker"}) {
    EXPECT_THROW(make_pool_table(s), std::invalid_argument) << s;
  }
}

TEST(PoolTable, NamesUniqueAndStable) {
  const Table t = make_pool_table("9ft");
  std::vector<std::string> walls;
  for (const Wall& w : t.walls) walls.push_back(w.name);
  // The boundary, counter-clockwise from the bottom-left pocket.
  const std::vector<std::string> expected = {
      "bottom_left_jaw_y_tip",     "bottom_left_jaw_y",     "bottom_left_jaw_x",
      "bottom_left_jaw_x_tip",     "rail_bottom_left",      "side_bottom_jaw_left_tip",
      "side_bottom_jaw_left",      "side_bottom_jaw_right", "side_bottom_jaw_right_tip",
      "rail_bottom_right",         "bottom_right_jaw_x_tip", "bottom_right_jaw_x",
      "bottom_right_jaw_y",        "bottom_right_jaw_y_tip", "rail_right",
      "top_right_jaw_y_tip",       "top_right_jaw_y",       "top_right_jaw_x",
      "top_right_jaw_x_tip",       "rail_top_right",        "side_top_jaw_right_tip",
      "side_top_jaw_right",        "side_top_jaw_left",     "side_top_jaw_left_tip",
      "rail_top_left",             "top_left_jaw_x_tip",    "top_left_jaw_x",
      "top_left_jaw_y",            "top_left_jaw_y_tip",    "rail_left"};
  EXPECT_EQ(walls, expected);
  EXPECT_EQ(std::set<std::string>(walls.begin(), walls.end()).size(), walls.size());
  int arcs = 0;
  for (const Wall& w : t.walls) {
    const bool tip = w.name.size() > 4 && w.name.substr(w.name.size() - 4) == "_tip";
    EXPECT_EQ(w.kind == WallKind::arc, tip) << w.name;
    arcs += tip ? 1 : 0;
  }
  EXPECT_EQ(arcs, 12);
  std::vector<std::string> pockets;
  for (const Pocket& p : t.pockets) pockets.push_back(p.name);
  EXPECT_EQ(pockets, (std::vector<std::string>{"bottom_left", "side_bottom", "bottom_right",
                                               "top_right", "side_top", "top_left"}));
  // The same names, in the same order, on every size and every call.
  for (const Size& s : kSizes) {
    const Table u = make_pool_table(s.name);
    ASSERT_EQ(u.walls.size(), t.walls.size());
    for (std::size_t i = 0; i < u.walls.size(); ++i) EXPECT_EQ(u.walls[i].name, t.walls[i].name);
  }
  const Table again = make_pool_table("9ft");
  for (std::size_t i = 0; i < t.walls.size(); ++i) {
    EXPECT_EQ(again.walls[i].a, t.walls[i].a);
    EXPECT_EQ(again.walls[i].b, t.walls[i].b);
  }
}

TEST(PoolTable, WallsJoinSmoothly) {
  // Each wall ends where the next one along the boundary starts, and the
  // contact normal carries on there (no kinks): rail -> tip -> facing at
  // one jaw, facing -> tip -> rail at the other. Only the facings' far
  // ends, inside the pocket circles, are free.
  const Table t = make_pool_table("9ft");
  // Where a wall starts and ends, following the boundary, and its contact
  // normal there. An arc runs clockwise, from `normal` to `b`.
  auto start = [](const Wall& w) { return w.kind == WallKind::arc ? w.a + w.normal * w.radius : w.a; };
  auto end = [](const Wall& w) { return w.kind == WallKind::arc ? w.a + w.b * w.radius : w.b; };
  auto n_start = [](const Wall& w) { return w.normal; };
  auto n_end = [](const Wall& w) { return w.kind == WallKind::arc ? w.b : w.normal; };
  int joins = 0;
  for (const Wall& w : t.walls) {
    int next = 0;
    for (const Wall& v : t.walls) {
      if (&v == &w || norm(start(v) - end(w)) > 1e-12) continue;
      ++next;
      EXPECT_LT(norm(n_start(v) - n_end(w)), 1e-12) << w.name << " -> " << v.name;
    }
    const bool facing = w.kind == WallKind::segment && w.name.rfind("rail", 0) != 0;
    // A jaw's facing that runs into the pocket ends inside the circle.
    if (next == 0) {
      EXPECT_TRUE(facing) << w.name;
      EXPECT_TRUE(in_a_pocket(t, end(w) + (start(w) - end(w)) * 1e-9)) << w.name;
    }
    joins += next;
  }
  EXPECT_EQ(joins, 24);  // 4 per pocket
}

TEST(PoolTable, SegmentsAndArcsWellFormed) {
  for (const Size& s : kSizes) {
    const Table t = make_pool_table(s.name);
    for (const Wall& w : t.walls) {
      SCOPED_TRACE(w.name);
      if (w.kind == WallKind::segment) {
        EXPECT_NEAR(norm(w.normal), 1.0, 1e-15);
        EXPECT_NEAR(dot(w.normal, w.b - w.a), 0.0, 1e-15);
        // Into the table: left of a -> b for a counter-clockwise boundary.
        EXPECT_GT(cross(w.b - w.a, w.normal), 0.0);
        EXPECT_GT(norm(w.b - w.a), 0.01);
      } else {
        ASSERT_EQ(w.kind, WallKind::arc);
        EXPECT_DOUBLE_EQ(w.radius, 0.125 * kInch);
        EXPECT_NEAR(norm(w.b), 1.0, 1e-15);
        EXPECT_NEAR(norm(w.normal), 1.0, 1e-15);
        // Less than half a turn from b counter-clockwise to normal.
        EXPECT_GT(cross(w.b, w.normal), 0.0);
        // The tip is rounded inside the cushion: its centre is off the
        // playing surface.
        const bool inside = w.a.x > 0 && w.a.x < s.length && w.a.y > 0 && w.a.y < s.width;
        EXPECT_FALSE(inside);
      }
    }
  }
}

TEST(PoolTable, MouthWidths) {
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    for (const char* p : kCornerPockets) {
      const auto j = jaws_of(p);
      EXPECT_NEAR(norm(lip(t, j[0]) - lip(t, j[1])), 4.5 * kInch, 1e-12) << p;
      EXPECT_NEAR(norm(lip(t, j[0]) - lip(t, j[1])), 0.1143, 1e-12) << p;
    }
    for (const char* p : kSidePockets) {
      const auto j = jaws_of(p);
      const Vec2 l = lip(t, j[0]);
      const Vec2 r = lip(t, j[1]);
      EXPECT_NEAR(norm(l - r), 0.127, 1e-12) << p;
      // Centred on the side pocket, on the rail.
      EXPECT_NEAR(0.5 * (l.x + r.x), s.length / 2, 1e-12);
      EXPECT_LT(l.x, r.x);
    }
    // Corner lips lie equally far from the corner along both rails.
    const Vec2 bx = lip(t, "bottom_left_jaw_x");
    const Vec2 by = lip(t, "bottom_left_jaw_y");
    EXPECT_NEAR(bx.y, 0.0, 1e-15);
    EXPECT_NEAR(by.x, 0.0, 1e-15);
    EXPECT_NEAR(bx.x, by.y, 1e-15);
    const Vec2 tr = lip(t, "top_right_jaw_x");
    EXPECT_NEAR(s.length - tr.x, bx.x, 1e-12);
    EXPECT_NEAR(tr.y, s.width, 1e-12);
  }
}

TEST(PoolTable, JawAngles) {
  // WPA: the cut angle between the cushion nose and the facing, through
  // the cushion, is 142 degrees at corner pockets and 104 at side pockets.
  const Table t = make_pool_table("9ft");
  auto check = [&](const std::string& jaw, double degrees) {
    SCOPED_TRACE(jaw);
    const Wall& rail = wall_named(t, rail_of(jaw));
    const Wall& face = wall_named(t, jaw);
    const Vec2 at = lip(t, jaw);
    // Along the nose, away from the pocket: toward the rail's far end.
    const Vec2 r_far = norm(rail.a - at) > norm(rail.b - at) ? rail.a : rail.b;
    const Vec2 f_far = norm(face.a - at) > norm(face.b - at) ? face.a : face.b;
    const Vec2 r = unit(r_far - at);
    const Vec2 f = unit(f_far - at);
    const double angle = std::acos(dot(r, f)) * 180.0 / kPi;
    EXPECT_NEAR(angle, degrees, 1e-9);
    // The facing runs off the playing surface, into the cushion's side.
    EXPECT_LT(dot(f, rail.normal), 0.0);
  };
  for (const char* p : kCornerPockets) {
    for (const auto& j : jaws_of(p)) check(j, 142.0);
  }
  for (const char* p : kSidePockets) {
    for (const auto& j : jaws_of(p)) check(j, 104.0);
  }
  // The facings of a pocket converge: the throat narrows behind the mouth.
  for (const auto& p : {"bottom_left", "side_bottom", "top_right", "side_top"}) {
    const auto j = jaws_of(p);
    const Wall& f0 = wall_named(t, j[0]);
    const Wall& f1 = wall_named(t, j[1]);
    const double mouth = norm(lip(t, j[0]) - lip(t, j[1]));
    const Vec2 deep0 = norm(f0.a - lip(t, j[0])) > norm(f0.b - lip(t, j[0])) ? f0.a : f0.b;
    const Vec2 deep1 = norm(f1.a - lip(t, j[1])) > norm(f1.b - lip(t, j[1])) ? f1.a : f1.b;
    EXPECT_LT(norm(deep0 - deep1), mouth) << p;
    // Still wide enough for a ball where they end.
    EXPECT_GT(norm(deep0 - deep1), 2.0 * kBallR) << p;
  }
}

TEST(PoolTable, PocketsBehindTheMouthAtShelfDepth) {
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    for (const Pocket& k : t.pockets) {
      SCOPED_TRACE(k.name);
      const bool side = k.name.rfind("side", 0) == 0;
      const double shelf = side ? 0.1875 * kInch : 1.75 * kInch;
      const auto j = jaws_of(k.name);
      const Vec2 l0 = lip(t, j[0]);
      const Vec2 l1 = lip(t, j[1]);
      const Vec2 mid = (l0 + l1) * 0.5;
      // Unit normal of the mouth line, pointing away from the table.
      Vec2 e = unit(perp(l1 - l0));
      if (dot(e, Vec2{s.length / 2, s.width / 2} - mid) > 0) e = -e;
      // The circle's nearest point to the mouth line lies on the axis at
      // the shelf depth.
      EXPECT_NEAR(dot(k.centre - mid, e) - k.radius, shelf, 1e-12);
      EXPECT_NEAR(cross(e, k.centre - mid), 0.0, 1e-12);
      // The ball centre's lanes along both facings (a ball radius off
      // them) run into the circle: a ball rubbing a facing falls too.
      for (const auto& jaw : j) {
        const Wall& f = wall_named(t, jaw);
        const double off = std::abs(dot(k.centre - f.a, f.normal) - kBallR);
        EXPECT_LT(off, k.radius - 0.005) << jaw;
        // And the facing reaches into the circle.
        EXPECT_LT(segment_distance(k.centre, f.a, f.b), k.radius - 0.005) << jaw;
      }
      // A capture circle of plausible size (a little narrower than the
      // mouth).
      EXPECT_GT(k.radius, 0.040);
      EXPECT_LT(2.0 * k.radius, norm(l1 - l0));
    }
  }
}

TEST(PoolTable, OutlineIsASimpleCounterClockwisePolygon) {
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    const auto& v = t.outline;
    const std::size_t n = v.size();
    ASSERT_GT(n, 24U);
    double area = 0.0;
    for (std::size_t i = 0; i < n; ++i) area += cross(v[i], v[(i + 1) % n]);
    area *= 0.5;
    EXPECT_GT(area, s.length * s.width);  // the pockets add a little
    EXPECT_LT(area, s.length * s.width + 0.1);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_GT(norm(v[(i + 1) % n] - v[i]), 0.0) << i;
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // neighbours across the start
        EXPECT_FALSE(segments_cross(v[i], v[i + 1], v[j], v[(j + 1) % n])) << i << " " << j;
      }
    }
    // Every wall lies on the outline.
    auto on_outline = [&](Vec2 p) {
      double d = kInf;
      for (std::size_t i = 0; i < n; ++i) d = std::min(d, segment_distance(p, v[i], v[(i + 1) % n]));
      return d;
    };
    for (const Wall& w : t.walls) {
      if (w.kind == WallKind::segment) {
        EXPECT_LT(on_outline(w.a), 1e-12) << w.name;
        EXPECT_LT(on_outline(w.b), 1e-12) << w.name;
        EXPECT_LT(on_outline((w.a + w.b) * 0.5), 1e-12) << w.name;
      } else {
        EXPECT_LT(on_outline(w.a + unit(w.b + w.normal) * w.radius), 1e-12) << w.name;
      }
    }
    EXPECT_TRUE(contains(t, {s.length / 2, s.width / 2}));
    EXPECT_TRUE(contains(t, t.head_spot));
    EXPECT_TRUE(contains(t, t.foot_spot));
  }
}

TEST(PoolTable, NoRayEscapes) {
  // From random places a ball centre can be, in random directions, a ball
  // always meets a wall or falls into a pocket first, inside the box.
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    std::mt19937_64 rng(12345);
    int pocketed = 0;
    int walls = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec2 p = random_free_point(t, rng, kBallR, 0.2);
      const Vec2 v = random_direction(rng);
      const Hit h = cast(t, p, v, kBallR);
      ASSERT_LT(h.t, kInf) << "escapes from (" << p.x << ", " << p.y << ") along (" << v.x
                           << ", " << v.y << ")";
      const Vec2 q = p + v * h.t;
      ASSERT_TRUE(in_box(t, q));
      ASSERT_LT(h.t, std::hypot(t.max.x - t.min.x, t.max.y - t.min.y));
      // Nothing was crossed on the way: the contact point is clear.
      ASSERT_GE(wall_distance(t, q), kBallR - 1e-9);
      (h.pocket >= 0 ? pocketed : walls) += 1;
    }
    EXPECT_GT(pocketed, 100);
    EXPECT_GT(walls, 10000);
  }
}

TEST(PoolTable, NoBouncingBallEscapes) {
  // Frictionless billiard paths, reflected at every wall: each one stays
  // in the box and clear of the walls until it falls into a pocket.
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    std::mt19937_64 rng(777);
    int pocketed = 0;
    for (int i = 0; i < 1000; ++i) {
      Vec2 p = random_free_point(t, rng, kBallR, 0.2);
      Vec2 v = random_direction(rng);
      for (int bounce = 0; bounce < 200; ++bounce) {
        const Hit h = cast(t, p, v, kBallR);
        ASSERT_LT(h.t, kInf) << "path " << i << " escapes after " << bounce << " bounces";
        p = p + v * h.t;
        ASSERT_TRUE(in_box(t, p));
        ASSERT_GE(wall_distance(t, p), kBallR - 1e-9) << "path " << i << " bounce " << bounce;
        if (h.pocket >= 0) {
          ++pocketed;
          break;
        }
        v = unit(v - h.normal * (2.0 * dot(v, h.normal)));
      }
    }
    EXPECT_GT(pocketed, 500);
  }
}

TEST(PoolTable, EveryPocketTakesAStraightShot) {
  // A ball sent along the pocket's axis from 30 cm in front of the mouth,
  // or from the middle of the table to a side pocket, falls in without
  // touching anything.
  for (const Size& s : kSizes) {
    SCOPED_TRACE(s.name);
    const Table t = make_pool_table(s.name);
    for (std::size_t k = 0; k < t.pockets.size(); ++k) {
      const Pocket& pk = t.pockets[k];
      SCOPED_TRACE(pk.name);
      const auto j = jaws_of(pk.name);
      const Vec2 mid = (lip(t, j[0]) + lip(t, j[1])) * 0.5;
      const Vec2 e = unit(pk.centre - mid);
      const Vec2 start = mid - e * 0.3;
      ASSERT_TRUE(contains(t, start));
      const Hit h = cast(t, start, e, kBallR);
      EXPECT_EQ(h.pocket, static_cast<int>(k));
      EXPECT_EQ(h.wall, -1);
      // Captured past the mouth line, by the shelf.
      const double shelf = pk.name.rfind("side", 0) == 0 ? 0.1875 * kInch : 1.75 * kInch;
      EXPECT_NEAR(h.t, 0.3 + shelf, 1e-9);
      // Slightly off the axis (a quarter inch at the mouth) still goes in.
      for (double off : {-0.25 * kInch, 0.25 * kInch}) {
        const Vec2 o = perp(e) * off;
        const Hit g = cast(t, start + o, e, kBallR);
        EXPECT_EQ(g.pocket, static_cast<int>(k)) << off;
      }
    }
    for (const char* side : kSidePockets) {
      const Pocket& pk = pocket_named(t, side);
      const Vec2 c{s.length / 2, s.width / 2};
      const Hit h = cast(t, c, unit(pk.centre - c), kBallR);
      ASSERT_GE(h.pocket, 0);
      EXPECT_EQ(t.pockets[static_cast<std::size_t>(h.pocket)].name, side);
    }
  }
}

TEST(PoolTable, DownTheRailShotHitsTheFarJawOrFalls) {
  // A ball frozen to the bottom rail rolling into the bottom-left corner
  // pocket: its centre runs a ball radius off the nose and meets either
  // the far (y) jaw or the pocket circle; never the near tip.
  const Table t = make_pool_table("9ft");
  const Hit h = cast(t, {0.5, kBallR}, {-1, 0}, kBallR);
  if (h.pocket >= 0) {
    EXPECT_EQ(t.pockets[static_cast<std::size_t>(h.pocket)].name, "bottom_left");
  } else {
    ASSERT_GE(h.wall, 0);
    EXPECT_EQ(t.walls[static_cast<std::size_t>(h.wall)].name.rfind("bottom_left_jaw_y", 0), 0U);
  }
}

// ---------------------------------------------------------------------------
// Racks

/// The ideal spot (row k, place j of c) of a rack of touching balls.
Vec2 ideal(const Table& t, int k, int j, int c) {
  const double d = 2.0 * kBallR;
  return {t.foot_spot.x + k * d * std::sqrt(3.0) / 2, t.foot_spot.y + (j - 0.5 * (c - 1)) * d};
}

const RackedBall& ball(const std::vector<RackedBall>& rack, const std::string& id) {
  for (const RackedBall& b : rack) {
    if (b.id == id) return b;
  }
  throw std::runtime_error("no ball " + id);
}

constexpr double kRackTol = 1.5e-3;  // lattice gaps add up to about 1 mm at the back

TEST(Rack, EightBall) {
  const Table t = make_pool_table("9ft");
  const auto rack = make_rack("eight_ball", t, kBallR, 1);
  ASSERT_EQ(rack.size(), 15U);
  for (int n = 1; n <= 15; ++n) EXPECT_EQ(rack[static_cast<std::size_t>(n - 1)].id, std::to_string(n));
  // Every ball on a spot of the triangle, one per spot.
  const int counts[] = {1, 2, 3, 4, 5};
  std::set<std::pair<int, int>> taken;
  for (const RackedBall& b : rack) {
    int found = 0;
    for (int k = 0; k < 5; ++k) {
      for (int j = 0; j < counts[k]; ++j) {
        if (norm(b.position - ideal(t, k, j, counts[k])) < kRackTol) {
          ++found;
          taken.insert({k, j});
        }
      }
    }
    EXPECT_EQ(found, 1) << b.id;
  }
  EXPECT_EQ(taken.size(), 15U);
  // The apex on the foot spot; the 8 in the middle of the third row.
  int apex = 0;
  for (const RackedBall& b : rack) apex += norm(b.position - t.foot_spot) < 1e-12 ? 1 : 0;
  EXPECT_EQ(apex, 1);
  EXPECT_LT(norm(ball(rack, "8").position - ideal(t, 2, 1, 3)), kRackTol);
  // A solid and a stripe in the back corners.
  int solids = 0;
  int stripes = 0;
  for (const RackedBall& b : rack) {
    if (norm(b.position - ideal(t, 4, 0, 5)) < kRackTol ||
        norm(b.position - ideal(t, 4, 4, 5)) < kRackTol) {
      const int n = std::stoi(b.id);
      solids += n < 8 ? 1 : 0;
      stripes += n > 8 ? 1 : 0;
    }
  }
  EXPECT_EQ(solids, 1);
  EXPECT_EQ(stripes, 1);
}

TEST(Rack, NineBall) {
  const Table t = make_pool_table("9ft");
  const auto rack = make_rack("nine_ball", t, kBallR, 1);
  ASSERT_EQ(rack.size(), 9U);
  for (int n = 1; n <= 9; ++n) EXPECT_EQ(rack[static_cast<std::size_t>(n - 1)].id, std::to_string(n));
  EXPECT_EQ(ball(rack, "1").position, t.foot_spot);
  EXPECT_LT(norm(ball(rack, "9").position - ideal(t, 2, 1, 3)), kRackTol);
  const int counts[] = {1, 2, 3, 2, 1};
  std::set<std::pair<int, int>> taken;
  for (const RackedBall& b : rack) {
    for (int k = 0; k < 5; ++k) {
      for (int j = 0; j < counts[k]; ++j) {
        if (norm(b.position - ideal(t, k, j, counts[k])) < kRackTol) taken.insert({k, j});
      }
    }
  }
  EXPECT_EQ(taken.size(), 9U);
}

TEST(Rack, NoOverlapsSmallGapsOnTheTable) {
  for (const Size& s : kSizes) {
    const Table t = make_pool_table(s.name);
    for (const char* game : {"eight_ball", "nine_ball"}) {
      for (std::uint64_t seed = 0; seed < 200; ++seed) {
        SCOPED_TRACE(std::string(s.name) + " " + game + " seed " + std::to_string(seed));
        const auto rack = make_rack(game, t, kBallR, seed);
        for (std::size_t i = 0; i < rack.size(); ++i) {
          const Vec2 p = rack[i].position;
          EXPECT_GE(p.x, kBallR);
          EXPECT_LE(p.x, s.length - kBallR);
          EXPECT_GE(p.y, kBallR);
          EXPECT_LE(p.y, s.width - kBallR);
          EXPECT_GE(wall_distance(t, p), kBallR);
          EXPECT_TRUE(contains(t, p));
          double nearest = kInf;
          for (std::size_t j = 0; j < rack.size(); ++j) {
            if (j == i) continue;
            const double d = norm(p - rack[j].position);
            EXPECT_GT(d, 2.0 * kBallR + 1e-5) << rack[i].id << " " << rack[j].id;
            nearest = std::min(nearest, d);
          }
          // Frozen, nearly: a neighbour at most 0.4 mm away.
          EXPECT_LT(nearest, 2.0 * kBallR + 0.4e-3) << rack[i].id;
        }
      }
    }
  }
}

TEST(Rack, DeterministicPerSeed) {
  const Table t = make_pool_table("9ft");
  for (const char* game : {"eight_ball", "nine_ball"}) {
    const auto a = make_rack(game, t, kBallR, 42);
    const auto b = make_rack(game, t, kBallR, 42);
    const auto c = make_rack(game, t, kBallR, 43);
    ASSERT_EQ(a.size(), b.size());
    bool differ = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].id, b[i].id);
      EXPECT_EQ(a[i].position, b[i].position);  // bit for bit
      differ = differ || !(a[i].position == c[i].position);
    }
    EXPECT_TRUE(differ) << game;
  }
}

TEST(Rack, OrderVariesWithTheSeed) {
  const Table t = make_pool_table("8ft");
  std::set<std::string> at_apex_8;
  std::set<std::string> back_corner;
  std::set<std::string> next_to_1;
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    const auto r8 = make_rack("eight_ball", t, kBallR, seed);
    for (const RackedBall& b : r8) {
      if (norm(b.position - t.foot_spot) < 1e-12) at_apex_8.insert(b.id);
      if (norm(b.position - ideal(t, 4, 0, 5)) < kRackTol) back_corner.insert(b.id);
    }
    EXPECT_LT(norm(ball(r8, "8").position - ideal(t, 2, 1, 3)), kRackTol);
    const auto r9 = make_rack("nine_ball", t, kBallR, seed);
    EXPECT_EQ(ball(r9, "1").position, t.foot_spot);
    EXPECT_LT(norm(ball(r9, "9").position - ideal(t, 2, 1, 3)), kRackTol);
    for (const RackedBall& b : r9) {
      if (norm(b.position - ideal(t, 1, 0, 2)) < kRackTol) next_to_1.insert(b.id);
    }
  }
  EXPECT_GE(at_apex_8.size(), 8U);
  EXPECT_EQ(at_apex_8.count("8"), 0U);
  EXPECT_GE(back_corner.size(), 10U);
  EXPECT_EQ(back_corner.count("8"), 0U);
  EXPECT_GE(next_to_1.size(), 6U);
  EXPECT_EQ(next_to_1.count("1") + next_to_1.count("9"), 0U);
}

TEST(Rack, RejectsBadInput) {
  const Table t = make_pool_table("7ft");
  EXPECT_THROW(make_rack("straight_pool", t, kBallR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("", t, kBallR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("eight_ball", t, 0.0, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("eight_ball", t, -kBallR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("eight_ball", t, std::nan(""), 1), std::invalid_argument);
  EXPECT_THROW(make_rack("eight_ball", t, kInf, 1), std::invalid_argument);
  // Balls far too big for the table.
  EXPECT_THROW(make_rack("eight_ball", t, 0.2, 1), std::invalid_argument);
  // A table that is not a pool table.
  EXPECT_THROW(make_rack("eight_ball", make_rectangle({0, 0}, {1, 1}), kBallR, 1),
               std::invalid_argument);
}

// contains() answers for the bed of a pool or snooker table without the
// walk around its outline: that shortcut must agree with the walk, which
// a "polygon" copy of the table still takes, at points all over the bed
// and right up to its edges and pocket mouths.
TEST(PoolTable, BedInsideOutline) {
  std::vector<Table> tables{make_pool_table("7ft"), make_pool_table("8ft"),
                            make_pool_table("9ft"), make_snooker_table()};
  for (const Table& t : tables) {
    Table walked = t;
    walked.shape = TableShape::polygon;
    int checked = 0;
    for (int i = 0; i <= 400; ++i) {
      for (int j = 0; j <= 200; ++j) {
        const Vec2 p{t.length * (i == 0 ? 1e-9 : i == 400 ? 1.0 - 1e-9 : i / 400.0),
                     t.width * (j == 0 ? 1e-9 : j == 200 ? 1.0 - 1e-9 : j / 200.0)};
        ASSERT_TRUE(contains(walked, p)) << to_string(t.shape) << " " << p.x << " " << p.y;
        EXPECT_TRUE(contains(t, p));
        ++checked;
      }
    }
    EXPECT_EQ(checked, 401 * 201);
    // Outside the bed both still walk the outline: in a pocket's mouth
    // and beyond the cushion.
    for (const Pocket& pk : t.pockets) {
      EXPECT_EQ(contains(t, pk.centre), contains(walked, pk.centre)) << pk.name;
    }
    EXPECT_FALSE(contains(t, Vec2{-0.5, 0.5 * t.width}));
  }
}

}  // namespace
}  // namespace breakshot::test_pool_table

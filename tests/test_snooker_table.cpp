// The snooker table (make_snooker_table), its markings, its balls and the
// snooker rack: the WPBSA figures (Official Rules of Snooker, Section 1),
// the pocket geometry breakshot chose (docs/physics.md, "Snooker table"),
// closure (no ball can leave the table but through a pocket), balls that
// fall into each pocket or come off a rounded jaw, the rack on many seeds,
// the break-off scenario, and the scenario contract for the snooker table.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot/pool.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"
#include "table_geometry.hpp"

namespace breakshot {
namespace {

using namespace table_geometry;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInch = 0.0254;
constexpr double kR = 0.02625;  // WPBSA: 52.5 mm balls
constexpr double kL = 3.569;    // WPBSA: playing area 3569 x 1778 mm
constexpr double kW = 1.778;

const char* const kCornerPockets[] = {"bottom_left", "bottom_right", "top_right", "top_left"};
const char* const kSidePockets[] = {"side_bottom", "side_top"};

int wall_index(const Table& t, const std::string& name) {
  for (std::size_t i = 0; i < t.walls.size(); ++i) {
    if (t.walls[i].name == name) return static_cast<int>(i);
  }
  throw std::runtime_error("no wall " + name);
}

bool is_side(const std::string& pocket) { return pocket.rfind("side", 0) == 0; }

/// The mouth's midpoint and the pocket axis (unit, away from the table).
struct Axis {
  Vec2 mid;
  Vec2 e;
};

Axis axis_of(const Table& t, const std::string& pocket) {
  const auto j = jaws_of(pocket);
  const Vec2 mid = (lip(t, j[0]) + lip(t, j[1])) * 0.5;
  return {mid, unit(pocket_named(t, pocket).centre - mid)};
}

// ---------------------------------------------------------------------------
// The table and its markings

TEST(SnookerTable, PlayingAreaAndBall) {
  const Table t = make_snooker_table();
  EXPECT_EQ(t.shape, TableShape::snooker);
  // WPBSA Section 1, 1(a): 11 ft 8.5 in x 5 ft 10 in (3569 x 1778 mm).
  EXPECT_DOUBLE_EQ(t.length, kL);
  EXPECT_DOUBLE_EQ(t.width, kW);
  EXPECT_NEAR(t.length, (11 * 12 + 8.5) * kInch, 0.013);  // the rules' tolerance
  EXPECT_NEAR(t.width, (5 * 12 + 10) * kInch, 0.013);
  // The cushion noses are the playing area's edges.
  EXPECT_DOUBLE_EQ(wall_named(t, "rail_left").a.x, 0.0);
  EXPECT_DOUBLE_EQ(wall_named(t, "rail_right").a.x, kL);
  EXPECT_DOUBLE_EQ(wall_named(t, "rail_bottom_left").a.y, 0.0);
  EXPECT_DOUBLE_EQ(wall_named(t, "rail_top_left").a.y, kW);
  // WPBSA Section 1, 2: 52.5 mm balls.
  EXPECT_DOUBLE_EQ(2.0 * kSnookerBallRadius, 0.0525);
  // Mathavan et al. 2014's measured snooker ball, 140.6 g ("about 142 g").
  EXPECT_DOUBLE_EQ(kSnookerBallMass, 0.1406);
  // The cushions are the pool table's: the default law with the nose
  // height and restitution fitted together to Mathavan et al. 2010's
  // snooker-cushion model, so a rolling snooker ball driven straight in
  // comes back at that model's 0.914 of its speed (within 0.003, as on the
  // pool table; docs/physics.md, "Cushions").
  EXPECT_EQ(t.cushion.nose_height, CushionParams{}.nose_height);
  EXPECT_EQ(t.cushion.height, 0.0);
  const CushionImpact back = cushion_impact({-1.0, 0.0}, {0.0, -1.0 / kR, 0.0}, {1.0, 0.0},
                                            kSnookerBallMass, kR, t.cushion);
  EXPECT_NEAR(norm(back.velocity), 0.914, 0.003);
  EXPECT_EQ(t.cushion.model, CushionParams{}.model);
  EXPECT_EQ(t.cushion.restitution, CushionParams{}.restitution);
  EXPECT_EQ(t.cushion.friction, CushionParams{}.friction);
}

TEST(SnookerTable, MarkingsAsTheRulesGiveThem) {
  const SnookerMarks m = snooker_marks();
  // WPBSA Section 1, 1(d)-(f).
  EXPECT_DOUBLE_EQ(m.baulk_x, 0.737);
  EXPECT_NEAR(m.baulk_x, 29 * kInch, 0.0005);
  EXPECT_DOUBLE_EQ(m.d_radius, 0.292);
  EXPECT_NEAR(m.d_radius, 11.5 * kInch, 0.0005);
  EXPECT_DOUBLE_EQ(m.d_centre.x, m.baulk_x);
  EXPECT_DOUBLE_EQ(m.d_centre.y, kW / 2);
  // Brown: the middle of the baulk line. Yellow and green: the corners of
  // the D, yellow on the right seen from the baulk end. Looking from x < 0
  // toward +x with z up, the right-hand side is -y.
  EXPECT_EQ(m.brown, m.d_centre);
  EXPECT_DOUBLE_EQ(m.yellow.x, m.baulk_x);
  EXPECT_DOUBLE_EQ(m.green.x, m.baulk_x);
  EXPECT_DOUBLE_EQ(m.d_centre.y - m.yellow.y, m.d_radius);
  EXPECT_DOUBLE_EQ(m.green.y - m.d_centre.y, m.d_radius);
  const Vec2 looking{1, 0};
  const Vec2 up_cross_looking_right = -perp(looking);  // (0, -1): the right hand
  EXPECT_GT(dot(m.yellow - m.brown, up_cross_looking_right), 0.0);
  EXPECT_LT(dot(m.green - m.brown, up_cross_looking_right), 0.0);
  // Blue: the centre spot; pink: midway between it and the top cushion;
  // black: 324 mm (12.75 in) from the top cushion.
  EXPECT_EQ(m.blue, (Vec2{kL / 2, kW / 2}));
  EXPECT_DOUBLE_EQ(m.pink.x, 0.5 * (m.blue.x + kL));
  EXPECT_DOUBLE_EQ(m.pink.y, kW / 2);
  EXPECT_NEAR(kL - m.black.x, 0.324, 1e-15);
  EXPECT_NEAR(kL - m.black.x, 12.75 * kInch, 0.0005);
  EXPECT_DOUBLE_EQ(m.black.y, kW / 2);
  // The apex red: behind the pink (toward the top cushion), on the long
  // axis, as near as possible without touching.
  EXPECT_DOUBLE_EQ(m.pyramid_apex.y, kW / 2);
  const double gap = norm(m.pyramid_apex - m.pink) - 2.0 * kR;
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, 0.5e-3);
  EXPECT_GT(m.pyramid_apex.x, m.pink.x);
  // The table's spots.
  const Table t = make_snooker_table();
  EXPECT_EQ(t.head_spot, m.brown);
  EXPECT_EQ(t.foot_spot, m.pink);
  for (Vec2 p : {m.yellow, m.green, m.brown, m.blue, m.pink, m.black, m.pyramid_apex}) {
    EXPECT_TRUE(contains(t, p));
    EXPECT_GT(wall_clearance(t, p, kR), 0.1);
  }
}

TEST(SnookerTable, NamesAsOnThePoolTable) {
  const Table t = make_snooker_table();
  const Table pool = make_pool_table("9ft");
  ASSERT_EQ(t.walls.size(), pool.walls.size());
  ASSERT_EQ(t.pockets.size(), 6U);
  for (std::size_t i = 0; i < t.walls.size(); ++i) {
    EXPECT_EQ(t.walls[i].name, pool.walls[i].name);
    EXPECT_EQ(t.walls[i].kind, pool.walls[i].kind);
  }
  for (std::size_t i = 0; i < t.pockets.size(); ++i) {
    EXPECT_EQ(t.pockets[i].name, pool.pockets[i].name);
  }
}

TEST(SnookerTable, MouthsBetweenThePointedLips) {
  // breakshot's choice (WPBSA does not publish its templates): 83 mm
  // corner and 87 mm middle mouths, measured between the pointed lips
  // where each nose line meets its facing line.
  const Table t = make_snooker_table();
  for (const char* p : kCornerPockets) {
    const auto j = jaws_of(p);
    EXPECT_NEAR(norm(lip(t, j[0]) - lip(t, j[1])), 0.083, 1e-12) << p;
  }
  for (const char* p : kSidePockets) {
    const auto j = jaws_of(p);
    const Vec2 l = lip(t, j[0]);
    const Vec2 r = lip(t, j[1]);
    EXPECT_NEAR(norm(l - r), 0.087, 1e-12) << p;
    EXPECT_NEAR(0.5 * (l.x + r.x), kL / 2, 1e-12);
    EXPECT_LT(l.x, r.x);
  }
  const Vec2 bx = lip(t, "bottom_left_jaw_x");
  const Vec2 by = lip(t, "bottom_left_jaw_y");
  EXPECT_NEAR(bx.y, 0.0, 1e-15);
  EXPECT_NEAR(by.x, 0.0, 1e-15);
  EXPECT_NEAR(bx.x, by.y, 1e-15);
  EXPECT_NEAR(bx.x, 0.083 / std::sqrt(2.0), 1e-15);
}

TEST(SnookerTable, RoundJawsTangentToNoseAndFacing) {
  // Every jaw turns from the nose into the facing on one arc, 4 in radius
  // at the corners and 2.5 in at the middle pockets, tangent to both: the
  // walls join without a kink, and the arc's centre lies in the cushion.
  const Table t = make_snooker_table();
  auto start = [](const Wall& w) {
    return w.kind == WallKind::arc ? w.a + w.normal * w.radius : w.a;
  };
  auto end = [](const Wall& w) { return w.kind == WallKind::arc ? w.a + w.b * w.radius : w.b; };
  auto n_end = [](const Wall& w) { return w.kind == WallKind::arc ? w.b : w.normal; };
  int joins = 0;
  int arcs = 0;
  for (const Wall& w : t.walls) {
    SCOPED_TRACE(w.name);
    for (const Wall& v : t.walls) {
      if (&v == &w || norm(start(v) - end(w)) > 1e-12) continue;
      ++joins;
      EXPECT_LT(norm(v.normal - n_end(w)), 1e-12) << " -> " << v.name;
    }
    if (w.kind != WallKind::arc) continue;
    ++arcs;
    const bool side = w.name.rfind("side", 0) == 0;
    EXPECT_DOUBLE_EQ(w.radius, side ? 2.5 * kInch : 4.0 * kInch);
    EXPECT_NEAR(norm(w.b), 1.0, 1e-15);
    EXPECT_NEAR(norm(w.normal), 1.0, 1e-15);
    EXPECT_GT(cross(w.b, w.normal), 0.0);
    EXPECT_FALSE(w.a.x > 0 && w.a.x < kL && w.a.y > 0 && w.a.y < kW);
    // The arc's ends: one on the nose line, one on the facing line.
    const std::string jaw = w.name.substr(0, w.name.size() - 4);  // strip "_tip"
    const Wall& rail = wall_named(t, rail_of(jaw));
    const Wall& facing = wall_named(t, jaw);
    const double d_rail_start = std::abs(dot(start(w) - rail.a, rail.normal));
    const double d_rail_end = std::abs(dot(end(w) - rail.a, rail.normal));
    const double d_face_start = std::abs(dot(start(w) - facing.a, facing.normal));
    const double d_face_end = std::abs(dot(end(w) - facing.a, facing.normal));
    EXPECT_LT(std::min(d_rail_start + d_face_end, d_rail_end + d_face_start), 1e-12);
  }
  EXPECT_EQ(arcs, 12);
  EXPECT_EQ(joins, 24);
}

TEST(SnookerTable, JawAngles) {
  // Chosen: facings 2 degrees steeper than the pocket axis (cut angles
  // 137 degrees at the corners, 92 at the middle pockets), so both pairs
  // of facings converge into the pocket.
  const Table t = make_snooker_table();
  auto check = [&](const std::string& jaw, double degrees) {
    SCOPED_TRACE(jaw);
    const Wall& rail = wall_named(t, rail_of(jaw));
    const Wall& facing = wall_named(t, jaw);
    const Vec2 l = lip(t, jaw);
    // Along the nose away from the pocket; along the facing into it.
    Vec2 r = unit(rail.b - rail.a);
    if (dot(r, (rail.a + rail.b) * 0.5 - l) < 0) r = -r;
    Vec2 f = unit(facing.b - facing.a);
    if (dot(f, (facing.a + facing.b) * 0.5 - l) < 0) f = -f;
    const double angle = std::acos(dot(r, f)) * 180.0 / kPi;
    EXPECT_NEAR(angle, degrees, 1e-9);
  };
  for (const char* p : kCornerPockets) {
    for (const auto& j : jaws_of(p)) check(j, 137.0);
  }
  for (const char* p : kSidePockets) {
    for (const auto& j : jaws_of(p)) check(j, 92.0);
  }
}

TEST(SnookerTable, FallsBehindTheMouthAtShelfDepth) {
  // The capture circle's nearest point lies on the axis a shelf behind the
  // mouth (corner 32 mm, middle 16 mm); its diameter is the width between
  // the facings there: the mouth less 2 shelf tan(2 degrees).
  const Table t = make_snooker_table();
  const double tan2 = std::tan(2.0 * kPi / 180.0);
  for (const Pocket& k : t.pockets) {
    SCOPED_TRACE(k.name);
    const bool side = is_side(k.name);
    const double shelf = side ? 0.016 : 0.032;
    const double mouth = side ? 0.087 : 0.083;
    const Axis a = axis_of(t, k.name);
    EXPECT_NEAR(dot(k.centre - a.mid, a.e) - k.radius, shelf, 1e-12);
    EXPECT_NEAR(cross(a.e, k.centre - a.mid), 0.0, 1e-12);
    EXPECT_NEAR(2.0 * k.radius, mouth - 2.0 * shelf * tan2, 1e-12);
    // A ball passes between the jaws with room to spare.
    EXPECT_GT(2.0 * k.radius, 2.0 * kR + 0.025);
    // The lanes of a ball rubbing either facing run into the circle.
    for (const auto& jaw : jaws_of(k.name)) {
      const Wall& f = wall_named(t, jaw);
      const double off = std::abs(dot(k.centre - f.a, f.normal) - kR);
      EXPECT_LT(off, k.radius - 0.005) << jaw;
      EXPECT_LT(segment_distance(k.centre, f.a, f.b), k.radius - 0.001) << jaw;
    }
  }
}

TEST(SnookerTable, OutlineIsASimpleCounterClockwisePolygon) {
  const Table t = make_snooker_table();
  const auto& v = t.outline;
  const std::size_t n = v.size();
  ASSERT_GT(n, 24U);
  double area = 0.0;
  for (std::size_t i = 0; i < n; ++i) area += cross(v[i], v[(i + 1) % n]);
  area *= 0.5;
  EXPECT_GT(area, kL * kW - 0.05);  // round jaws take a little, pockets add a little
  EXPECT_LT(area, kL * kW + 0.05);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_GT(norm(v[(i + 1) % n] - v[i]), 0.0) << i;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      EXPECT_FALSE(segments_cross(v[i], v[i + 1], v[j], v[(j + 1) % n])) << i << " " << j;
    }
  }
  auto on_outline = [&](Vec2 p) {
    double d = kInf;
    for (std::size_t i = 0; i < n; ++i) d = std::min(d, segment_distance(p, v[i], v[(i + 1) % n]));
    return d;
  };
  for (const Wall& w : t.walls) {
    if (w.kind == WallKind::segment) {
      EXPECT_LT(on_outline(w.a), 1e-12) << w.name;
      EXPECT_LT(on_outline(w.b), 1e-12) << w.name;
    } else {
      // The outline follows the arc by chords: within 0.1 mm of it.
      EXPECT_LT(on_outline(w.a + unit(w.b + w.normal) * w.radius), 1e-4) << w.name;
    }
  }
}

TEST(SnookerTable, NoRayEscapes) {
  const Table t = make_snooker_table();
  std::mt19937_64 rng(2468);
  int pocketed = 0;
  int walls = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec2 p = random_free_point(t, rng, kR, 0.25);
    const Vec2 v = random_direction(rng);
    const Hit h = cast(t, p, v, kR);
    ASSERT_LT(h.t, kInf) << "escapes from (" << p.x << ", " << p.y << ") along (" << v.x << ", "
                         << v.y << ")";
    const Vec2 q = p + v * h.t;
    ASSERT_TRUE(in_box(t, q));
    ASSERT_GE(wall_distance(t, q), kR - 1e-9);
    (h.pocket >= 0 ? pocketed : walls) += 1;
  }
  EXPECT_GT(pocketed, 100);
  EXPECT_GT(walls, 10000);
}

TEST(SnookerTable, NoBouncingBallEscapes) {
  const Table t = make_snooker_table();
  std::mt19937_64 rng(1357);
  int pocketed = 0;
  for (int i = 0; i < 1000; ++i) {
    Vec2 p = random_free_point(t, rng, kR, 0.25);
    Vec2 v = random_direction(rng);
    for (int bounce = 0; bounce < 200; ++bounce) {
      const Hit h = cast(t, p, v, kR);
      ASSERT_LT(h.t, kInf) << "path " << i << " escapes after " << bounce << " bounces";
      p = p + v * h.t;
      ASSERT_TRUE(in_box(t, p));
      ASSERT_GE(wall_distance(t, p), kR - 1e-9) << "path " << i << " bounce " << bounce;
      if (h.pocket >= 0) {
        ++pocketed;
        break;
      }
      v = unit(v - h.normal * (2.0 * dot(v, h.normal)));
    }
  }
  EXPECT_GT(pocketed, 400);
}

TEST(SnookerTable, StraightShotsFallAndOffLineOnesMeetTheJaws) {
  // Along the axis from 30 cm out: captured a shelf behind the mouth
  // without touching anything. The room a ball has at the mouth is half
  // the width between the round jaws less its radius: a ball 5 mm off the
  // axis still falls, one 30 mm off meets a jaw.
  const Table t = make_snooker_table();
  for (std::size_t k = 0; k < t.pockets.size(); ++k) {
    const Pocket& pk = t.pockets[k];
    SCOPED_TRACE(pk.name);
    const Axis a = axis_of(t, pk.name);
    const Vec2 start = a.mid - a.e * 0.3;
    const Hit h = cast(t, start, a.e, kR);
    EXPECT_EQ(h.pocket, static_cast<int>(k));
    const double shelf = is_side(pk.name) ? 0.016 : 0.032;
    EXPECT_NEAR(h.t, 0.3 + shelf, 1e-9);
    for (double off : {-0.005, 0.005}) {
      EXPECT_EQ(cast(t, start + perp(a.e) * off, a.e, kR).pocket, static_cast<int>(k)) << off;
    }
    for (double off : {-0.030, 0.030}) {
      const Hit g = cast(t, start + perp(a.e) * off, a.e, kR);
      ASSERT_GE(g.wall, 0) << off;
      EXPECT_EQ(t.walls[static_cast<std::size_t>(g.wall)].name.rfind(pk.name, 0), 0U) << off;
    }
  }
}

// ---------------------------------------------------------------------------
// Balls on the table (the pool model)

Scenario one_ball(Vec2 p, Vec2 v) {
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.table = make_snooker_table();
  BallState st;
  st.position = p;
  st.velocity = v;
  // Rolling: the contact point at rest, w = z x v / R.
  st.spin = {-v.y / kSnookerBallRadius, v.x / kSnookerBallRadius, 0.0};
  st.state = MotionState::rolling;
  s.balls.push_back({"ball", kSnookerBallRadius, kSnookerBallMass, CushionParams{}.restitution});
  s.start.push_back(st);
  s.until.rest = true;
  return s;
}

TEST(SnookerTable, ARolledBallFallsIntoEveryPocket) {
  const Table t = make_snooker_table();
  for (std::size_t k = 0; k < t.pockets.size(); ++k) {
    const Pocket& pk = t.pockets[k];
    SCOPED_TRACE(pk.name);
    const Axis a = axis_of(t, pk.name);
    const Scenario s = one_ball(a.mid - a.e * 0.5, a.e * 1.0);
    ASSERT_FALSE(validate(s).has_value());
    const RunResult r = simulate(s);
    ASSERT_TRUE(r.complete);
    EXPECT_EQ(r.final_balls[0].state, MotionState::pocketed);
    int pockets = 0;
    int cushions = 0;
    for (const Event& e : r.events) {
      if (e.type == EventType::ball_pocket) {
        ++pockets;
        EXPECT_EQ(e.pocket, static_cast<int>(k));
      }
      if (e.type == EventType::ball_cushion) ++cushions;
    }
    EXPECT_EQ(pockets, 1);
    EXPECT_EQ(cushions, 0);
  }
}

TEST(SnookerTable, ABallIntoTheRoundJawComesBack) {
  // A ball rolled straight at a jaw's round piece, a third of the way
  // round from the nose, along the arc's normal there, meets that arc
  // first and comes back off it: it does not fall.
  const Table t = make_snooker_table();
  for (const Wall& w : t.walls) {
    if (w.kind != WallKind::arc) continue;
    SCOPED_TRACE(w.name);
    const std::string jaw = w.name.substr(0, w.name.size() - 4);  // strip "_tip"
    const Vec2 nose = wall_named(t, rail_of(jaw)).normal;
    const Vec2 other = norm(w.b - nose) < 1e-12 ? w.normal : w.b;
    const Vec2 m = unit(nose * 2.0 + other);
    ASSERT_GT(cross(w.b, m), 0.0);
    ASSERT_GT(cross(m, w.normal), 0.0);
    const Vec2 p = w.a + m * (w.radius + kR + 0.15);
    const Scenario s = one_ball(p, m * -0.8);
    const auto problem = validate(s);
    ASSERT_FALSE(problem.has_value()) << problem->path << ": " << problem->reason;
    const RunResult r = simulate(s);
    ASSERT_TRUE(r.complete);
    const Event* first = nullptr;
    for (const Event& e : r.events) {
      if (e.type == EventType::ball_cushion || e.type == EventType::ball_pocket) {
        first = &e;
        break;
      }
    }
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(first->type, EventType::ball_cushion);
    EXPECT_EQ(first->wall, wall_index(t, w.name));
    EXPECT_NE(r.final_balls[0].state, MotionState::pocketed);
    // It ends on the table side of where it met the jaw.
    EXPECT_GT(dot(r.final_balls[0].position - (w.a + m * (w.radius + kR)), m), 0.05);
  }
}

// ---------------------------------------------------------------------------
// The rack

const std::vector<std::string> kIds = {"red1",  "red2",  "red3",  "red4",   "red5",  "red6",
                                       "red7",  "red8",  "red9",  "red10",  "red11", "red12",
                                       "red13", "red14", "red15", "yellow", "green", "brown",
                                       "blue",  "pink",  "black"};

TEST(SnookerRack, TriangleBehindThePinkColoursOnTheirSpots) {
  const Table t = make_snooker_table();
  const SnookerMarks m = snooker_marks();
  const auto rack = make_rack("snooker", t, kR, 1);
  ASSERT_EQ(rack.size(), kIds.size());
  for (std::size_t i = 0; i < kIds.size(); ++i) EXPECT_EQ(rack[i].id, kIds[i]);
  // The apex red exactly on the pyramid spot, the others on a triangle of
  // touching balls (rows of 1-2-3-4-5 toward the top cushion) within the
  // rack's small gaps.
  EXPECT_EQ(rack[0].position, m.pyramid_apex);
  const int counts[] = {1, 2, 3, 4, 5};
  std::size_t i = 0;
  for (int row = 0; row < 5; ++row) {
    for (int j = 0; j < counts[row]; ++j, ++i) {
      const Vec2 ideal{m.pyramid_apex.x + row * 2.0 * kR * std::sqrt(3.0) / 2.0,
                       m.pyramid_apex.y + (j - 0.5 * (counts[row] - 1)) * 2.0 * kR};
      EXPECT_LT(norm(rack[i].position - ideal), 1.5e-3) << rack[i].id;
    }
  }
  // red11 ... red15 make the back row, red11 at the yellow side.
  EXPECT_LT(rack[10].position.y, rack[14].position.y);
  EXPECT_EQ(rack[15].position, m.yellow);
  EXPECT_EQ(rack[16].position, m.green);
  EXPECT_EQ(rack[17].position, m.brown);
  EXPECT_EQ(rack[18].position, m.blue);
  EXPECT_EQ(rack[19].position, m.pink);
  EXPECT_EQ(rack[20].position, m.black);
  // The back row stays clear of the black.
  for (std::size_t k = 0; k < 15; ++k) EXPECT_GT(norm(rack[k].position - m.black), 2.0 * kR + 0.05);
}

TEST(SnookerRack, ValidOnEverySeed) {
  // No overlaps (the reds frozen with tiny gaps, never touching), every
  // ball on the table clear of the cushions, neighbours within a
  // millimetre of touching.
  const Table t = make_snooker_table();
  for (std::uint64_t seed = 0; seed < 500; ++seed) {
    const auto rack = make_rack("snooker", t, kR, seed);
    ASSERT_EQ(rack.size(), 21U);
    double closest_red = kInf;
    for (std::size_t i = 0; i < rack.size(); ++i) {
      EXPECT_GT(wall_clearance(t, rack[i].position, kR), 0.0) << seed << " " << rack[i].id;
      for (std::size_t j = i + 1; j < rack.size(); ++j) {
        const double d = norm(rack[i].position - rack[j].position);
        EXPECT_GT(d, 2.0 * kR) << seed << " " << rack[i].id << " " << rack[j].id;
        if (i < 15 && j < 15) closest_red = std::min(closest_red, d);
      }
    }
    EXPECT_LT(closest_red, 2.0 * kR + 0.4e-3) << seed;
  }
}

TEST(SnookerRack, DeterministicPerSeedAndJittered) {
  const Table t = make_snooker_table();
  const auto a = make_rack("snooker", t, kR, 7);
  const auto b = make_rack("snooker", t, kR, 7);
  const auto c = make_rack("snooker", t, kR, 8);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, b[i].position);
    differs = differs || !(a[i].position == c[i].position);
  }
  EXPECT_TRUE(differs);
}

TEST(SnookerRack, WrongTableOrGameThrows) {
  const Table snooker = make_snooker_table();
  const Table pool = make_pool_table("9ft");
  EXPECT_THROW(make_rack("snooker", pool, kR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("eight_ball", snooker, kR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("nine_ball", snooker, kR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("three_cushion", snooker, kR, 1), std::invalid_argument);
}

TEST(SnookerBreak, TheBreakOffScenario) {
  const Scenario s = make_break_scenario("snooker", "12ft", 3, 7.0);
  ASSERT_FALSE(validate(s).has_value());
  ASSERT_EQ(s.balls.size(), 22U);
  EXPECT_EQ(s.balls[0].id, "cue");
  for (std::size_t i = 0; i < kIds.size(); ++i) EXPECT_EQ(s.balls[i + 1].id, kIds[i]);
  for (const BallSpec& b : s.balls) {
    EXPECT_EQ(b.radius, kSnookerBallRadius);
    EXPECT_EQ(b.mass, kSnookerBallMass);
  }
  EXPECT_EQ(s.table.shape, TableShape::snooker);
  // The cue ball in the D: in baulk, within the semicircle.
  const SnookerMarks m = snooker_marks();
  const Vec2 cue = s.start[0].position;
  EXPECT_LE(cue.x, m.baulk_x);
  EXPECT_LE(norm(cue - m.d_centre), m.d_radius);
  EXPECT_EQ(cue, snooker_break_off_spot());
  EXPECT_GT(norm(cue - m.brown), 2.0 * kR);
  EXPECT_GT(norm(cue - m.yellow), 2.0 * kR);
  // The cue ball's first contact is a thin one on red11.
  const RunResult r = simulate(s);
  ASSERT_TRUE(r.complete);
  const Event* first = nullptr;
  for (const Event& e : r.events) {
    if (e.type == EventType::ball_ball || e.type == EventType::ball_cushion) {
      first = &e;
      break;
    }
  }
  ASSERT_NE(first, nullptr);
  ASSERT_EQ(first->type, EventType::ball_ball);
  EXPECT_EQ(first->ball, 0);
  EXPECT_EQ(s.balls[static_cast<std::size_t>(first->other)].id, "red11");
  EXPECT_THROW(make_break_scenario("snooker", "9ft", 1, 7.0), std::invalid_argument);
  EXPECT_THROW(make_break_scenario("eight_ball", "12ft", 1, 7.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// The scenario contract

using nlohmann::json;

std::variant<Scenario, ScenarioError> read(const json& doc) { return read_scenario(doc.dump()); }

Scenario read_ok(const json& doc) {
  auto r = read(doc);
  if (const auto* e = std::get_if<ScenarioError>(&r)) {
    ADD_FAILURE() << "unexpected error: " << e->path << ": " << e->reason;
    return {};
  }
  return std::get<Scenario>(r);
}

void expect_invalid(const json& doc, const std::string& path, const std::string& part) {
  auto r = read(doc);
  ASSERT_TRUE(std::holds_alternative<ScenarioError>(r)) << doc.dump();
  const ScenarioError& e = std::get<ScenarioError>(r);
  EXPECT_EQ(e.path, path) << e.reason;
  EXPECT_FALSE(e.unsupported);
  EXPECT_NE(e.reason.find(part), std::string::npos) << e.reason;
}

json snooker_doc() {
  return json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "snooker"},
    "balls": [{"id": "cue", "position": [0.6, 0.8]}]
  })");
}

TEST(SnookerScenario, TheTableAndItsDefaultBall) {
  const Scenario s = read_ok(snooker_doc());
  EXPECT_EQ(s.table.shape, TableShape::snooker);
  EXPECT_EQ(s.table.length, kL);
  EXPECT_EQ(s.table.pockets.size(), 6U);
  ASSERT_EQ(s.balls.size(), 1U);
  EXPECT_EQ(s.balls[0].radius, kSnookerBallRadius);
  EXPECT_EQ(s.balls[0].mass, kSnookerBallMass);
  EXPECT_EQ(s.table.cushion.nose_height, CushionParams{}.nose_height);
  // A ball that gives its size keeps it; the pool table keeps the pool ball.
  json doc = snooker_doc();
  doc["balls"][0]["radius"] = 0.028575;
  EXPECT_EQ(read_ok(doc).balls[0].radius, 0.028575);
  doc = snooker_doc();
  doc["table"] = {{"shape", "pool"}, {"size", "9ft"}};
  EXPECT_EQ(read_ok(doc).balls[0].radius, kPoolBallRadius);
  // Every model, and the cushion fields as on a pool table.
  doc = snooker_doc();
  doc["physics"]["model"] = "ideal";
  doc["until"] = {{"time", 1.0}};
  EXPECT_EQ(read_ok(doc).balls[0].radius, kSnookerBallRadius);
  doc = snooker_doc();
  doc["table"]["cushion_restitution"] = 0.8;
  doc["table"]["cushion_friction"] = 0.2;
  doc["table"]["nose_height"] = 0.65;
  doc["table"]["cushion_model"] = "mathavan_2010";
  const Scenario c = read_ok(doc);
  EXPECT_EQ(c.table.cushion.restitution, 0.8);
  EXPECT_EQ(c.table.cushion.friction, 0.2);
  EXPECT_EQ(c.table.cushion.nose_height, 0.65);
  // Mathavan's law takes the paper's nose, h = 7R/5 (36.75 mm here).
  doc["table"].erase("nose_height");
  const Scenario mathavan = read_ok(doc);
  EXPECT_NEAR(cushion_nose_height(mathavan.table.cushion, kSnookerBallRadius), 1.4 * kR, 1e-15);
  doc = snooker_doc();
  doc["table"]["size"] = "12ft";
  expect_invalid(doc, "table.size", "unknown field");
  doc = snooker_doc();
  doc["balls"][0]["position"] = {0.01, 0.8};
  expect_invalid(doc, "balls[0].position", "");
}

TEST(SnookerScenario, TheRack) {
  json doc = snooker_doc();
  doc.erase("balls");
  doc["rack"] = {{"game", "snooker"}, {"seed", 5}};
  const Scenario s = read_ok(doc);
  ASSERT_EQ(s.balls.size(), 22U);
  EXPECT_EQ(s.balls[0].id, "cue");
  EXPECT_EQ(s.start[0].position, snooker_break_off_spot());
  const auto rack = make_rack("snooker", s.table, kR, 5);
  for (std::size_t i = 0; i < kIds.size(); ++i) {
    EXPECT_EQ(s.balls[i + 1].id, kIds[i]);
    EXPECT_EQ(s.start[i + 1].position, rack[i].position);
    EXPECT_EQ(s.balls[i + 1].radius, kSnookerBallRadius);
  }
  // A given cue ball replaces the placed one.
  doc["balls"] = json::array({{{"id", "cue"}, {"position", {0.5, 0.9}}}});
  const Scenario g = read_ok(doc);
  ASSERT_EQ(g.balls.size(), 22U);
  EXPECT_EQ(g.start[0].position, (Vec2{0.5, 0.9}));
  // A given ball may not take a rack id or sit on a spot.
  doc["balls"] = json::array({{{"id", "pink"}, {"position", {0.5, 0.9}}}});
  expect_invalid(doc, "balls[0].id", "the rack places a ball with the id 'pink'");
  doc["balls"] = json::array({{{"id", "extra"}, {"position", {1.7845, 0.889}}}});
  expect_invalid(doc, "balls[0].position", "overlaps ball 'blue'");
}

TEST(SnookerScenario, RacksOnTheWrongTable) {
  json doc = snooker_doc();
  doc.erase("balls");
  doc["rack"] = {{"game", "eight_ball"}};
  expect_invalid(doc, "rack.game", "needs a pool table");
  doc["rack"] = {{"game", "nine_ball"}};
  expect_invalid(doc, "rack.game", "needs a pool table");
  doc["table"] = {{"shape", "pool"}, {"size", "9ft"}};
  doc["rack"] = {{"game", "snooker"}};
  expect_invalid(doc, "rack.game", "the snooker rack needs the snooker table");
  doc["table"] = {{"shape", "rectangle"}, {"min", {0.0, 0.0}}, {"max", {3.0, 1.5}}};
  expect_invalid(doc, "rack", "a rack needs a pool table");
  doc["table"] = {{"shape", "snooker"}};
  doc["rack"] = {{"game", "pyramid"}};
  expect_invalid(doc, "rack.game", "unknown game \"pyramid\"");
}

// ---------------------------------------------------------------------------
// The command on the examples

#ifdef BREAKSHOT_CLI

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// `breakshot simulate FILE`, standard output and error to files.
CliRun simulate_file(const std::string& file) {
  const std::string base =
      (std::filesystem::temp_directory_path() / ("breakshot-snooker-" + std::to_string(::getpid())))
          .string();
  const std::string cmd = std::string("'") + BREAKSHOT_CLI + "' simulate '" + file + "' >'" + base +
                          ".out' 2>'" + base + ".err'";
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(base + ".out");
  r.err = slurp(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

std::string example(const std::string& name) {
  return std::string(BREAKSHOT_SOURCE_DIR) + "/examples/snooker/" + name;
}

TEST(SnookerCli, TheBreakOff) {
  const CliRun r = simulate_file(example("break_off.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_TRUE(out["complete"].get<bool>());
  const json& balls = out["final"]["balls"];
  ASSERT_EQ(balls.size(), 22U);
  EXPECT_EQ(balls[0]["id"], "cue");
  for (std::size_t i = 0; i < kIds.size(); ++i) EXPECT_EQ(balls[i + 1]["id"], kIds[i]);
  // The cue ball takes red11 first, as the break-off aims it, and every
  // ball comes to rest (or falls).
  for (const json& e : out["events"]) {
    if (e["type"] == "ball_ball" || e["type"] == "ball_cushion") {
      EXPECT_EQ(e["type"], "ball_ball");
      EXPECT_EQ(e["balls"], json::array({"cue", "red11"}));
      break;
    }
  }
  for (const json& b : balls) {
    const std::string state = b["state"];
    EXPECT_TRUE(state == "stationary" || state == "pocketed") << b["id"] << " " << state;
  }
}

TEST(SnookerCli, PotsIntoACornerAndAMiddlePocket) {
  for (const auto& [file, pocket] :
       {std::pair<std::string, std::string>{"pot_corner.json", "top_right"},
        {"pot_middle.json", "side_top"}}) {
    SCOPED_TRACE(file);
    const CliRun r = simulate_file(example(file));
    ASSERT_EQ(r.status, 0) << r.err;
    const json out = json::parse(r.out);
    EXPECT_TRUE(out["complete"].get<bool>());
    int falls = 0;
    for (const json& e : out["events"]) {
      if (e["type"] != "ball_pocket") continue;
      ++falls;
      EXPECT_EQ(e["balls"], json::array({"red1"}));
      EXPECT_EQ(e["pocket"], pocket);
    }
    EXPECT_EQ(falls, 1);
    EXPECT_EQ(out["final"]["balls"][0]["state"], "stationary");
  }
}

TEST(SnookerCli, ARackOnTheWrongTableExitsTwo) {
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("breakshot-snooker-rack-" + std::to_string(::getpid()) + ".json"))
                               .string();
  std::ofstream(file)
      << R"({"physics": {"model": "pool"}, "table": {"shape": "pool", "size": "9ft"},
                             "rack": {"game": "snooker"}})";
  const CliRun r = simulate_file(file);
  std::remove(file.c_str());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("invalid scenario: rack.game: the snooker rack needs the snooker table"),
            std::string::npos)
      << r.err;
}

#endif  // BREAKSHOT_CLI

}  // namespace
}  // namespace breakshot

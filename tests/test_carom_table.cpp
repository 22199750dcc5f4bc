// The carom table (make_carom_table), its markings, its balls and the
// three-cushion rack: UMB's figures (docs/physics.md, "Carom table"), the
// scenario contract for the carom table, and paths round the cushions
// against the mirror construction: with a frictionless cushion and cloth
// and no spin, the engine's cushion law must send a ball along the
// straight line to the image of its goal in the unfolded table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/carom.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"

namespace breakshot::test_carom_table {
namespace {

using json = nlohmann::json;

constexpr double kL = 2.84;  // UMB: playing area 2840 x 1420 mm
constexpr double kW = 1.42;
constexpr double kR = 0.03075;  // 61.5 mm

std::variant<Scenario, ScenarioError> read(const json& doc) { return read_scenario(doc.dump()); }

Scenario read_ok(const json& doc) {
  auto r = read(doc);
  if (const auto* e = std::get_if<ScenarioError>(&r)) {
    ADD_FAILURE() << e->path << ": " << e->reason;
    return {};
  }
  return std::get<Scenario>(r);
}

ScenarioError read_bad(const json& doc) {
  auto r = read(doc);
  if (!std::holds_alternative<ScenarioError>(r)) {
    ADD_FAILURE() << "accepted: " << doc.dump();
    return {};
  }
  return std::get<ScenarioError>(r);
}

TEST(CaromTable, GeometryAndMarkings) {
  const Table t = make_carom_table();
  EXPECT_EQ(t.shape, TableShape::carom);
  EXPECT_DOUBLE_EQ(t.length, kL);
  EXPECT_DOUBLE_EQ(t.width, kW);
  EXPECT_TRUE(t.pockets.empty());
  ASSERT_EQ(t.walls.size(), 4u);
  std::set<std::string> names;
  for (const Wall& w : t.walls) {
    names.insert(w.name);
    EXPECT_EQ(w.kind, WallKind::segment);
    EXPECT_DOUBLE_EQ(norm(w.normal), 1.0);
    // The normal points into the table: the centre is on its side.
    EXPECT_GT(dot(Vec2{kL / 2, kW / 2} - w.a, w.normal), 0.0) << w.name;
  }
  EXPECT_EQ(names, (std::set<std::string>{"rail_left", "rail_right", "rail_bottom", "rail_top"}));
  // The nose 37 mm above the cloth for a carom ball.
  EXPECT_NEAR(t.cushion.nose_height * 2.0 * kCaromBallRadius, 0.037, 1e-15);
  EXPECT_DOUBLE_EQ(kCaromBallRadius, kR);
  EXPECT_DOUBLE_EQ(kCaromBallMass, 0.210);

  const CaromMarks m = carom_marks();
  EXPECT_DOUBLE_EQ(m.top_spot.x, 2.13);
  EXPECT_DOUBLE_EQ(m.bottom_spot.x, 0.71);
  EXPECT_DOUBLE_EQ(m.centre_spot.x, 1.42);
  for (const Vec2 p : {m.top_spot, m.bottom_spot, m.centre_spot}) EXPECT_DOUBLE_EQ(p.y, 0.71);
  EXPECT_DOUBLE_EQ(m.starting_spots[0].x, 0.71);
  EXPECT_DOUBLE_EQ(m.starting_spots[1].x, 0.71);
  EXPECT_NEAR(m.bottom_spot.y - m.starting_spots[0].y, 0.182, 1e-12);
  EXPECT_NEAR(m.starting_spots[1].y - m.bottom_spot.y, 0.182, 1e-12);
  EXPECT_EQ(t.head_spot, m.bottom_spot);
  EXPECT_EQ(t.foot_spot, m.top_spot);
  // Seven diamonds on each long cushion, three on each short one, every
  // eighth of the length and quarter of the width (355 mm apart).
  ASSERT_EQ(m.diamonds.size(), 20u);
  for (const Vec2 d : m.diamonds) {
    const bool on_long = d.y == 0.0 || d.y == kW;
    const bool on_short = d.x == 0.0 || d.x == kL;
    EXPECT_NE(on_long, on_short);
    const double along = on_long ? d.x : d.y;
    EXPECT_NEAR(std::fmod(along + 1e-9, 0.355), 0.0, 1e-8) << along;
  }
  // The bed is inside; the cushion lines and beyond are not.
  EXPECT_TRUE(contains(t, {0.01, 0.01}));
  EXPECT_FALSE(contains(t, {-0.01, 0.5}));
  EXPECT_FALSE(contains(t, {1.0, kW + 0.001}));
  EXPECT_NEAR(wall_clearance(t, {kR, 0.7}, kR), 0.0, 1e-15);
}

TEST(CaromTable, RackFromTheRules) {
  const Table t = make_carom_table();
  const CaromMarks m = carom_marks();
  std::set<double> sides;
  for (std::uint64_t seed = 0; seed < 16; ++seed) {
    const std::vector<RackedBall> rack = make_rack("three_cushion", t, kR, seed);
    ASSERT_EQ(rack.size(), 3u);
    EXPECT_EQ(rack[0].id, "white");
    EXPECT_EQ(rack[1].id, "yellow");
    EXPECT_EQ(rack[2].id, "red");
    EXPECT_TRUE(rack[0].position == m.starting_spots[0] ||
                rack[0].position == m.starting_spots[1]);
    EXPECT_EQ(rack[1].position, m.bottom_spot);
    EXPECT_EQ(rack[2].position, m.top_spot);
    sides.insert(rack[0].position.y);
    EXPECT_EQ(make_rack("three_cushion", t, kR, seed)[0].position, rack[0].position);
  }
  EXPECT_EQ(sides.size(), 2u) << "the seed draws either starting spot";
  EXPECT_THROW(make_rack("three_cushion", make_pool_table("9ft"), kR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("eight_ball", t, kR, 1), std::invalid_argument);
  EXPECT_THROW(make_rack("three_cushion", t, 0.2, 1), std::invalid_argument);

  const Scenario s = make_break_scenario("three_cushion", "10ft", 3, 4.0);
  ASSERT_EQ(s.balls.size(), 3u);
  EXPECT_EQ(s.balls[0].id, "white");
  ASSERT_TRUE(s.cue);
  EXPECT_EQ(s.cue->ball, 0);
  EXPECT_THROW(make_break_scenario("three_cushion", "9ft", 3, 4.0), std::invalid_argument);
  Simulation sim(s);
  sim.advance_to_rest();
  ASSERT_TRUE(sim.at_rest());
  bool red_first = false;
  for (const Event& e : sim.events()) {
    if (e.type == EventType::ball_ball) {
      red_first = (e.ball == 0 && e.other == 2) || (e.ball == 2 && e.other == 0);
      break;
    }
  }
  EXPECT_TRUE(red_first) << "the break scenario drives the white straight at the red";
}

TEST(CaromScenario, TheTableTheDefaultBallAndTheRack) {
  json doc = json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "carom"},
    "balls": [{"id": "a", "position": [1.0, 0.5]}]
  })");
  Scenario s = read_ok(doc);
  EXPECT_EQ(s.table.shape, TableShape::carom);
  ASSERT_EQ(s.balls.size(), 1u);
  EXPECT_DOUBLE_EQ(s.balls[0].radius, kCaromBallRadius);
  EXPECT_DOUBLE_EQ(s.balls[0].mass, kCaromBallMass);
  // Every model, as on the snooker table.
  doc["physics"]["model"] = "friction";
  EXPECT_DOUBLE_EQ(read_ok(doc).balls[0].radius, kCaromBallRadius);
  doc["physics"]["model"] = "pool";
  // The cushion fields of the pool model's cushions.
  doc["table"]["cushion_friction"] = 0.1;
  doc["table"]["nose_height"] = 0.62;
  s = read_ok(doc);
  EXPECT_DOUBLE_EQ(s.table.cushion.friction, 0.1);
  EXPECT_DOUBLE_EQ(s.table.cushion.nose_height, 0.62);
  doc["table"]["size"] = "10ft";
  EXPECT_EQ(read_bad(doc).path, "table.size");

  json rack = json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "carom"},
    "rack": {"game": "three_cushion", "seed": 2},
    "cue": {"ball": "white", "speed": 3.0}
  })");
  s = read_ok(rack);
  ASSERT_EQ(s.balls.size(), 3u);
  EXPECT_EQ(s.balls[0].id, "white");
  EXPECT_EQ(s.balls[1].id, "yellow");
  EXPECT_EQ(s.balls[2].id, "red");
  EXPECT_EQ(s.start[2].position, carom_marks().top_spot);
  // A given ball comes first and may not take a rack id or a placed spot.
  rack["balls"] = json::array({{{"id", "extra"}, {"position", {2.5, 1.2}}}});
  s = read_ok(rack);
  EXPECT_EQ(s.balls[0].id, "extra");
  rack["balls"][0]["id"] = "red";
  EXPECT_EQ(read_bad(rack).path, "balls[0].id");
  rack["balls"][0] = {{"id", "x"}, {"position", {2.13, 0.72}}};
  EXPECT_EQ(read_bad(rack).path, "balls[0].position");
  rack.erase("balls");
  // The rack on another table, and another rack on the carom table.
  rack["table"] = {{"shape", "pool"}, {"size", "9ft"}};
  ScenarioError e = read_bad(rack);
  EXPECT_EQ(e.path, "rack.game");
  EXPECT_NE(e.reason.find("needs the carom table"), std::string::npos) << e.reason;
  rack["table"] = {{"shape", "carom"}};
  rack["rack"]["game"] = "nine_ball";
  e = read_bad(rack);
  EXPECT_EQ(e.path, "rack.game");
  EXPECT_NE(e.reason.find("needs a pool table"), std::string::npos) << e.reason;
  rack["rack"]["game"] = "three_cushion";
  rack["table"] = {{"shape", "rectangle"}, {"min", {0, 0}}, {"max", {2, 1}}};
  EXPECT_EQ(read_bad(rack).path, "rack");
}

// --- Paths round the cushions against the mirror construction --------------

/// A ball without spin on a frictionless cloth, the engine's default
/// cushion law with no friction and restitution 1, on the cloth.
json mirror_scenario(Vec2 p, Vec2 v, double until) {
  json doc;
  doc["physics"] = {{"model", "pool"},
                    {"sliding_friction", 0.0},
                    {"rolling_friction", 0.0},
                    {"spinning_friction", 0.0},
                    {"airborne", false}};
  doc["table"] = {{"shape", "carom"}, {"cushion_friction", 0.0}, {"cushion_restitution", 1.0}};
  doc["balls"] = json::array({{{"id", "b"}, {"position", {p.x, p.y}}, {"velocity", {v.x, v.y}}}});
  doc["until"] = {{"time", until}};
  return doc;
}

/// The image of q in the unfolded table of ball centres after i
/// reflections across the short cushions and j across the long ones.
Vec2 image(Vec2 q, int i, int j) {
  const auto c = [](double v, double lo, double hi, int k) {
    const double span = hi - lo;
    return lo + k * span + (std::abs(k) % 2 == 0 ? v - lo : hi - v);
  };
  return {c(q.x, kR, kL - kR, i), c(q.y, kR, kW - kR, j)};
}

struct MirrorCase {
  Vec2 from;
  Vec2 to;
  int i;
  int j;
};

TEST(CaromMirror, OneAndThreeRailPathsFollowTheUnfoldedLine) {
  const MirrorCase cases[] = {
      {{0.5, 0.4}, {1.9, 0.5}, 0, 1},    // one rail: the top cushion
      {{0.6, 0.9}, {0.9, 0.3}, -1, 0},   // one rail: the bottom (head) cushion
      {{0.5, 0.4}, {1.9, 0.5}, 2, 1},    // three rails: right, top, left
      {{2.2, 1.1}, {0.8, 0.6}, -1, -2},  // three rails: bottom, left, top (in some order)
      {{1.0, 0.3}, {1.6, 0.9}, 1, 2},
  };
  for (const MirrorCase& c : cases) {
    const Vec2 target = image(c.to, c.i, c.j);
    const Vec2 d = target - c.from;
    const double speed = 1.5;
    const double t = norm(d) / speed;
    const Vec2 v = d / norm(d) * speed;
    const Scenario sc = read_ok(mirror_scenario(c.from, v, t));
    Simulation sim(sc);
    sim.advance_to(t);
    const BallState b = sim.ball(0);
    EXPECT_NEAR(b.position.x, c.to.x, 1e-9) << c.i << "," << c.j;
    EXPECT_NEAR(b.position.y, c.to.y, 1e-9) << c.i << "," << c.j;
    // The speed is kept and the path has turned at each cushion as a mirror.
    EXPECT_NEAR(norm(b.velocity), speed, 1e-9);
    int rails = 0;
    for (const Event& e : sim.events()) {
      if (e.type != EventType::ball_cushion) continue;
      ++rails;
      // Where the unfolded line crosses a cushion line, in time.
      const Vec2 at = c.from + v * e.time;
      const double fx = (at.x - kR) / (kL - 2 * kR);
      const double fy = (at.y - kR) / (kW - 2 * kR);
      const double ex = std::abs(fx - std::round(fx));
      const double ey = std::abs(fy - std::round(fy));
      EXPECT_LT(std::min(ex, ey), 1e-9) << "a cushion at t = " << e.time << " off the lattice";
    }
    EXPECT_EQ(rails, std::abs(c.i) + std::abs(c.j));
  }
}

}  // namespace
}  // namespace breakshot::test_carom_table

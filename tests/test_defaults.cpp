// default_physics (physics.hpp): the one home of each model's defaults.
// The scenario reader, the racks and the games start from it; these tests
// hold them to it, and it to the values docs/scenario.md documents.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <variant>

#include "breakshot/game.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario_io.hpp"

using namespace breakshot;

namespace {

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expect_same(const PhysicsParams& a, const PhysicsParams& b, const std::string& what) {
  EXPECT_EQ(a.model, b.model) << what;
  EXPECT_TRUE(same(a.ball_ball_restitution, b.ball_ball_restitution)) << what;
  EXPECT_TRUE(same(a.ball_ball_friction, b.ball_ball_friction)) << what;
  EXPECT_EQ(a.ball_ball_friction_fit, b.ball_ball_friction_fit) << what;
  EXPECT_TRUE(same(a.ball_ball_friction_curve.a, b.ball_ball_friction_curve.a)) << what;
  EXPECT_TRUE(same(a.ball_ball_friction_curve.b, b.ball_ball_friction_curve.b)) << what;
  EXPECT_TRUE(same(a.ball_ball_friction_curve.c, b.ball_ball_friction_curve.c)) << what;
  EXPECT_EQ(a.ball_ball_model, b.ball_ball_model) << what;
  EXPECT_TRUE(same(a.gravity, b.gravity)) << what;
  EXPECT_TRUE(same(a.deceleration, b.deceleration)) << what;
  EXPECT_TRUE(same(a.sliding_friction, b.sliding_friction)) << what;
  EXPECT_TRUE(same(a.rolling_friction, b.rolling_friction)) << what;
  EXPECT_TRUE(same(a.spinning_friction, b.spinning_friction)) << what;
  EXPECT_TRUE(same(a.collapse_speed, b.collapse_speed)) << what;
  EXPECT_EQ(a.ball_clusters, b.ball_clusters) << what;
}

PhysicsParams read_physics(const std::string& model) {
  const std::string text = R"({"physics": {"model": ")" + model +
                           R"("}, "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1]},
      "balls": [{"id": "a", "position": [0.5, 0.5]}], "until": {"time": 1}})";
  auto parsed = read_scenario(text);
  if (const auto* e = std::get_if<ScenarioError>(&parsed)) {
    ADD_FAILURE() << e->path << ": " << e->reason;
    return {};
  }
  return std::get<Scenario>(parsed).physics;
}

}  // namespace

TEST(Defaults, AreTheDocumentedValues) {
  // docs/scenario.md, "Defaults".
  const PhysicsParams ideal = default_physics(Model::ideal);
  EXPECT_EQ(ideal.ball_ball_restitution, 1.0);
  EXPECT_EQ(ideal.gravity, 9.81);
  EXPECT_EQ(ideal.sliding_friction, 0.2);
  EXPECT_EQ(ideal.rolling_friction, 0.01);
  EXPECT_EQ(ideal.spinning_friction, 0.0117);
  EXPECT_EQ(ideal.deceleration, 0.01 * 9.81);
  EXPECT_EQ(ideal.collapse_speed, 1e-5);
  const PhysicsParams pool = default_physics(Model::pool);
  EXPECT_EQ(pool.ball_ball_restitution, 0.95);  // Alciatore: 0.92-0.98
  EXPECT_TRUE(pool.ball_ball_friction_fit);
  // Alciatore's TP B-3 refit to Colenso's measured throw.
  EXPECT_EQ(pool.ball_ball_friction_curve, (FrictionCurve{0.016, 0.219, 0.691}));
  EXPECT_TRUE(pool.airborne);
  EXPECT_EQ(pool.slate_restitution, 0.5);
  EXPECT_EQ(pool.min_bounce_height, 0.001);
  EXPECT_FALSE(ideal.airborne);
  EXPECT_EQ(pool.ball_ball_model, BallBallModel::friction);
  EXPECT_EQ(pool.collapse_speed, 1e-3);
  EXPECT_FALSE(pool.ball_clusters);
  // The struct's own initial values are the ideal model's.
  expect_same(PhysicsParams{}, ideal, "PhysicsParams{}");
}

TEST(Defaults, TheReaderStartsFromThem) {
  for (const Model m : {Model::ideal, Model::friction, Model::pool}) {
    const std::string name(to_string(m));
    expect_same(read_physics(name), default_physics(m), name);
  }
}

TEST(Defaults, TheRacksAndTheGamesUseThePoolDefaults) {
  PhysicsParams expected = default_physics(Model::pool);
  expected.ball_clusters = true;  // the games' one change: the break spreads the rack
  expect_same(make_break_scenario("eight_ball", "9ft", 1, 7.5).physics, expected, "break");
  const Rules rules(GameConfig{});
  const GameState start = rules.start(1, 0);
  expect_same(rules.shot_scenario(start, CueStrike{}).physics, expected, "game shot");
  EXPECT_EQ(GameConfig{}.ball_radius, kPoolBallRadius);
  EXPECT_EQ(GameConfig{}.ball_mass, kPoolBallMass);
}

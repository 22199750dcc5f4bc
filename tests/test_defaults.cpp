// default_physics (physics.hpp): the one home of each model's defaults.
// The scenario reader, the racks and the games start from it; these tests
// hold them to it, and it to the values docs/scenario.md documents.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "breakshot/game.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario_io.hpp"
#include "physics_fields.hpp"

namespace test_defaults {

using namespace breakshot;

namespace {

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

/// Every field of PhysicsParams (physics_fields.hpp lists them all: a
/// field it does not list fails to compile), doubles by their bits.
void expect_same(const PhysicsParams& a, const PhysicsParams& b, const std::string& what) {
  for (const physics_fields::Field& f : physics_fields::kFields) {
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(a.*member)>;
          if constexpr (std::is_same_v<T, double>) {
            EXPECT_TRUE(same(a.*member, b.*member)) << what << ": " << f.name;
          } else if constexpr (std::is_same_v<T, FrictionCurve>) {
            EXPECT_TRUE(same((a.*member).a, (b.*member).a)) << what << ": " << f.name << ".a";
            EXPECT_TRUE(same((a.*member).b, (b.*member).b)) << what << ": " << f.name << ".b";
            EXPECT_TRUE(same((a.*member).c, (b.*member).c)) << what << ": " << f.name << ".c";
          } else {
            EXPECT_EQ(a.*member, b.*member) << what << ": " << f.name;
          }
        },
        f.member);
  }
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

TEST(Defaults, TheComparisonSeesEveryField) {
  // Each field changed alone is a difference expect_same reports.
  for (const physics_fields::Field& f : physics_fields::kFields) {
    PhysicsParams changed = default_physics(Model::pool);
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(changed.*member)>;
          if constexpr (std::is_same_v<T, double>) {
            changed.*member += 0.5;
          } else if constexpr (std::is_same_v<T, bool>) {
            changed.*member = !(changed.*member);
          } else if constexpr (std::is_same_v<T, FrictionCurve>) {
            (changed.*member).c += 0.5;
          } else if constexpr (std::is_same_v<T, Model>) {
            changed.*member = Model::ideal;
          } else {
            changed.*member = BallBallModel::mathavan_2014;
          }
        },
        f.member);
    ::testing::TestPartResultArray failures;
    {
      ::testing::ScopedFakeTestPartResultReporter reporter(
          ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
      expect_same(changed, default_physics(Model::pool), "changed");
    }
    EXPECT_EQ(failures.size(), 1) << f.name;
  }
}

TEST(Defaults, GamePhysicsTakesThemFromDefaultPhysics) {
  const PhysicsParams pool = default_physics(Model::pool);
  const GamePhysics g;
  EXPECT_EQ(g.cushion_model, CushionParams{}.model);
  EXPECT_EQ(g.ball_ball_model, pool.ball_ball_model);
  EXPECT_EQ(g.ball_ball_friction_fit, pool.ball_ball_friction_fit);
  EXPECT_EQ(g.ball_ball_friction_curve, pool.ball_ball_friction_curve);
  EXPECT_TRUE(same(g.ball_ball_friction, pool.ball_ball_friction));
  EXPECT_EQ(g.airborne, pool.airborne);
  EXPECT_TRUE(same(g.spinning_friction, pool.spinning_friction));
  EXPECT_EQ(game_physics_preset("default"), g);
  EXPECT_EQ(game_physics_preset("legacy"), kLegacyGamePhysics);
  EXPECT_FALSE(game_physics_preset("modern").has_value());
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

TEST(Defaults, TheWallRestitutionIsTheCushionLaws) {
  // docs/scenario.md, docs/contract.md and docs/physics.md: a pool ball
  // that gives no wall_restitution takes the table's cushion_restitution,
  // else its cushion law's own default restitution; outside the pool
  // model, 1.0.
  const auto wall = [](const std::string& physics, const std::string& cushion) {
    const std::string text = R"({"physics": {"model": ")" + physics +
                             R"("}, "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1])" +
                             cushion + R"(}, "balls": [{"id": "a", "position": [0.5, 0.5]}],
        "until": {"time": 1}})";
    auto parsed = read_scenario(text);
    if (const auto* e = std::get_if<ScenarioError>(&parsed)) {
      ADD_FAILURE() << e->path << ": " << e->reason;
      return -1.0;
    }
    return std::get<Scenario>(parsed).balls.at(0).wall_restitution;
  };
  EXPECT_EQ(wall("pool", ""), 0.84);  // han_2005, the default law
  EXPECT_EQ(default_cushion_restitution(CushionParams{}.model), 0.84);
  EXPECT_EQ(CushionParams{}.model, CushionModel::han_2005);
  const std::pair<const char*, double> laws[] = {{"han_2005", 0.84},
                                                 {"han_2005_v0", 0.75},
                                                 {"mathavan_2010", 0.98},
                                                 {"impulse_frictional", 0.914},
                                                 {"stronge_compliant", 0.85}};
  for (const auto& [name, e] : laws) {
    EXPECT_EQ(wall("pool", std::string(R"(, "cushion_model": ")") + name + "\""), e) << name;
  }
  EXPECT_EQ(wall("pool", R"(, "cushion_restitution": 0.6)"), 0.6);
  EXPECT_EQ(wall("friction", ""), 1.0);
  EXPECT_EQ(wall("ideal", ""), 1.0);
}

}  // namespace test_defaults

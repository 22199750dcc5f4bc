// Reading and writing the pool model's scenarios and results: the pool
// model's defaults, pool tables and their cushion fields, racks, the cue
// strike, balls in pockets and against the pocket jaws, and the result's
// pool events and "cue" object (docs/contract.md;
// docs/scenario.md has the project's choices).

#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"

namespace test_pool_io {

namespace {

using nlohmann::json;
namespace bs = breakshot;

/// A pool-model scenario on a 9 ft table, with one ball and no cue.
json pool_base() {
  return json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "pool", "size": "9ft"},
    "balls": [{"id": "cue", "position": [0.635, 0.635]}]
  })");
}

/// A break: the rack, the cue ball on the head spot, a cue strike.
json pool_break() {
  return json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "pool", "size": "9ft"},
    "rack": {"game": "eight_ball", "seed": 1},
    "cue": {"speed": 8.0}
  })");
}

std::variant<bs::Scenario, bs::ScenarioError> read(const json& doc) {
  return bs::read_scenario(doc.dump());
}

bs::Scenario read_ok(const json& doc) {
  auto r = read(doc);
  if (const auto* e = std::get_if<bs::ScenarioError>(&r)) {
    ADD_FAILURE() << "unexpected error: " << e->path << ": " << e->reason;
    return {};
  }
  return std::get<bs::Scenario>(r);
}

bs::ScenarioError read_error(const json& doc) {
  auto r = read(doc);
  if (!std::holds_alternative<bs::ScenarioError>(r)) {
    ADD_FAILURE() << "expected an error for: " << doc.dump();
    return {};
  }
  return std::get<bs::ScenarioError>(r);
}

/// Rejected as invalid (not unsupported) at `path`, the reason containing
/// `reason_part`.
void expect_invalid(const json& doc, const std::string& path,
                    const std::string& reason_part = "") {
  const bs::ScenarioError e = read_error(doc);
  EXPECT_EQ(e.path, path) << "reason: " << e.reason;
  EXPECT_FALSE(e.unsupported) << e.path << ": " << e.reason;
  EXPECT_NE(e.reason.find(reason_part), std::string::npos)
      << "reason '" << e.reason << "' lacks '" << reason_part << "'";
}

// --- the pool model ------------------------------------------------------

TEST(PoolRead, ModelDefaults) {
  json doc = pool_base();
  doc["table"] = {{"shape", "rectangle"}, {"min", {0.0, 0.0}}, {"max", {2.0, 1.0}}};
  doc["balls"][0]["position"] = {1.0, 0.5};
  const bs::Scenario s = read_ok(doc);
  const bs::PhysicsParams& p = s.physics;
  EXPECT_EQ(p.model, bs::Model::pool);
  EXPECT_EQ(p.ball_ball_restitution, 0.95);
  EXPECT_TRUE(p.ball_ball_friction_fit);
  EXPECT_EQ(p.gravity, 9.81);
  EXPECT_EQ(p.sliding_friction, 0.2);
  EXPECT_EQ(p.rolling_friction, 0.01);
  EXPECT_EQ(p.spinning_friction, 0.0117);  // docs/physics.md, "Spin about the vertical"
  EXPECT_TRUE(s.until.rest);  // "rest" by default
  EXPECT_FALSE(s.cue.has_value());
  EXPECT_EQ(s.balls[0].radius, 0.028575);
  EXPECT_EQ(s.balls[0].mass, 0.170);
  // The pool model's rails are not perfectly elastic.
  EXPECT_EQ(s.balls[0].wall_restitution, bs::CushionParams{}.restitution);
  EXPECT_EQ(s.start[0].state, bs::MotionState::stationary);
}

TEST(PoolRead, GivenBallFrictionIsAConstant) {
  json doc = pool_base();
  doc["physics"]["ball_ball_friction"] = 0.06;
  doc["physics"]["ball_ball_restitution"] = 0.93;
  bs::Scenario s = read_ok(doc);
  EXPECT_FALSE(s.physics.ball_ball_friction_fit);
  EXPECT_EQ(s.physics.ball_ball_friction, 0.06);
  EXPECT_EQ(s.physics.ball_ball_restitution, 0.93);
  doc["physics"]["ball_ball_friction"] = 0.0;  // frictionless impacts
  s = read_ok(doc);
  EXPECT_FALSE(s.physics.ball_ball_friction_fit);
  EXPECT_EQ(s.physics.ball_ball_friction, 0.0);
}

TEST(PoolRead, BallFrictionAsACurve) {
  // Extension: {"a", "b", "c"} is mu(v) = a + b exp(-c v) of the slip speed.
  json doc = pool_base();
  doc["physics"]["ball_ball_friction"] = {{"a", 0.016}, {"b", 0.219}, {"c", 0.691}};
  bs::Scenario s = read_ok(doc);
  EXPECT_TRUE(s.physics.ball_ball_friction_fit);
  EXPECT_EQ(s.physics.ball_ball_friction_curve, bs::kThrowFitTPB3);
  // b < 0 (friction rising with the slip) and c = 0 (a constant a + b)
  // are curves too, while mu stays in [0, 1].
  doc["physics"]["ball_ball_friction"] = {{"a", 0.2}, {"b", -0.1}, {"c", 0.0}};
  s = read_ok(doc);
  EXPECT_EQ(s.physics.ball_ball_friction_curve, (bs::FrictionCurve{0.2, -0.1, 0.0}));

  const auto bad = [&](json curve, const std::string& path, const std::string& why) {
    json d = pool_base();
    d["physics"]["ball_ball_friction"] = std::move(curve);
    expect_invalid(d, path, why);
  };
  bad({{"a", 0.01}, {"b", 0.1}}, "physics.ball_ball_friction.c", "missing");
  bad({{"a", 0.01}, {"b", 0.1}, {"c", 1.0}, {"d", 1.0}}, "physics.ball_ball_friction.d", "unknown");
  bad({{"a", 0.01}, {"b", 0.1}, {"c", -1.0}}, "physics.ball_ball_friction.c", ">= 0");
  bad({{"a", -0.01}, {"b", 0.1}, {"c", 1.0}}, "physics.ball_ball_friction.a", "[0, 1]");
  bad({{"a", 1.5}, {"b", -1.0}, {"c", 1.0}}, "physics.ball_ball_friction.a", "[0, 1]");
  bad({{"a", 0.5}, {"b", 0.6}, {"c", 1.0}}, "physics.ball_ball_friction.b", "a + b");
  bad({{"a", 0.2}, {"b", -0.3}, {"c", 1.0}}, "physics.ball_ball_friction.b", "a + b");
  bad({{"a", "x"}, {"b", 0.1}, {"c", 1.0}}, "physics.ball_ball_friction.a", "number");
  bad("0.05", "physics.ball_ball_friction", "a number or an object");

  // The same rules for a scenario built in code (validate()).
  bs::Scenario code = read_ok(pool_base());
  code.physics.ball_ball_friction_curve.c = -2.0;
  const auto e = bs::validate(code);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->path, "physics.ball_ball_friction.c");
  code.physics.ball_ball_friction_fit = false;  // a constant mu: the curve is not used
  EXPECT_FALSE(bs::validate(code).has_value());
}

TEST(PoolRead, TheDefaultCurveGivenExplicitlyIsTheSamePhysics) {
  json doc = pool_break();
  const bs::Scenario implicit = read_ok(doc);
  doc["physics"]["ball_ball_friction"] = {{"a", 0.016}, {"b", 0.219}, {"c", 0.691}};
  doc["physics"]["ball_ball_model"] = "friction";
  const bs::Scenario explicit_ = read_ok(doc);
  EXPECT_EQ(bs::write_result(implicit, bs::simulate(implicit)),
            bs::write_result(explicit_, bs::simulate(explicit_)));
}

TEST(PoolRead, BallBallModel) {
  json doc = pool_break();
  EXPECT_EQ(read_ok(doc).physics.ball_ball_model, bs::BallBallModel::friction);
  doc["physics"]["ball_ball_model"] = "mathavan_2014";
  const bs::Scenario s = read_ok(doc);
  EXPECT_EQ(s.physics.ball_ball_model, bs::BallBallModel::mathavan_2014);
  // A break under Mathavan's impacts runs to rest, repeatably, and differs
  // from the default impact law.
  const bs::RunResult r = bs::simulate(s);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(bs::write_result(s, r), bs::write_result(s, bs::simulate(s)));
  const bs::Scenario d = read_ok(pool_break());
  EXPECT_NE(bs::write_result(s, r), bs::write_result(d, bs::simulate(d)));

  doc["physics"]["ball_ball_model"] = "stronge";
  expect_invalid(doc, "physics.ball_ball_model", "mathavan_2014");
  doc["physics"]["ball_ball_model"] = 1;
  expect_invalid(doc, "physics.ball_ball_model", "string");
  json lab = json::parse(R"({"physics": {"model": "ideal", "ball_ball_model": "mathavan_2014"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1]},
    "balls": [{"id": "a", "position": [0.5, 0.5]}], "until": {"time": 1}})");
  expect_invalid(lab, "physics.ball_ball_model", "needs the pool model");
  lab["physics"]["ball_ball_model"] = "friction";  // the default: allowed anywhere
  EXPECT_EQ(read_ok(lab).physics.ball_ball_model, bs::BallBallModel::friction);
}

TEST(PoolRead, TheOtherModelsKeepTheirDefaults) {
  json doc = pool_base();
  doc["physics"]["model"] = "friction";
  const bs::Scenario s = read_ok(doc);
  EXPECT_EQ(s.physics.ball_ball_restitution, 1.0);
  EXPECT_FALSE(s.physics.ball_ball_friction_fit);
  EXPECT_EQ(s.balls[0].wall_restitution, 1.0);
  EXPECT_EQ(s.start[0].state, bs::MotionState::stationary);
}

TEST(PoolRead, EveryPhysicsFieldOfTheContractExampleIsAccepted) {
  json doc = pool_base();
  doc["physics"] = json::parse(R"({"model": "pool", "ball_ball_restitution": 0.95,
    "ball_ball_friction": 0.05, "gravity": 9.81, "deceleration": 0.0,
    "sliding_friction": 0.2, "rolling_friction": 0.01, "spinning_friction": 0.044})");
  const bs::Scenario s = read_ok(doc);  // deceleration means nothing here, but is allowed
  EXPECT_EQ(s.physics.model, bs::Model::pool);
  EXPECT_EQ(s.physics.ball_ball_friction, 0.05);
}

TEST(PoolRead, SpinAndTheStartingStates) {
  json doc = pool_base();
  const double r = 0.028575;
  doc["balls"] = json::parse(R"([
    {"id": "slide", "position": [0.3, 0.3], "velocity": [1.0, 0.0]},
    {"id": "still", "position": [0.6, 0.3]},
    {"id": "twirl", "position": [0.9, 0.3], "spin": [0.0, 0.0, 20.0]},
    {"id": "lift", "position": [1.2, 0.3], "spin": [5.0, 0.0, 0.0]}
  ])");
  // Rolling: the contact point is at rest, v = w x (R z) (w_y = v_x / R).
  doc["balls"].push_back({{"id", "roll"}, {"position", {1.5, 0.3}},
                          {"velocity", {1.0, 0.0}}, {"spin", {0.0, 1.0 / r, 0.0}}});
  const bs::Scenario s = read_ok(doc);
  EXPECT_EQ(s.start[0].state, bs::MotionState::sliding);
  EXPECT_EQ(s.start[1].state, bs::MotionState::stationary);
  EXPECT_EQ(s.start[2].state, bs::MotionState::spinning);
  EXPECT_EQ(s.start[2].spin, (bs::Vec3{0.0, 0.0, 20.0}));
  EXPECT_EQ(s.start[3].state, bs::MotionState::sliding);  // spins in place: slips
  EXPECT_EQ(s.start[4].state, bs::MotionState::rolling);

  doc["balls"][0]["spin"] = {0.0, std::nan(""), 0.0};
  expect_invalid(json::parse(doc.dump()), "balls[0].spin[1]", "");  // NaN is not JSON: null
  doc["balls"][0]["spin"] = {0.0, 1e13, 0.0};
  expect_invalid(doc, "balls[0].spin[1]", "too large");
}

// --- pool tables ----------------------------------------------------------

TEST(PoolRead, TableSizes) {
  struct Size {
    const char* name;
    double length;
    double width;
  };
  for (const Size& z : {Size{"7ft", 1.98, 0.99}, Size{"8ft", 2.34, 1.17}, Size{"9ft", 2.54, 1.27}}) {
    json doc = pool_base();
    doc["table"]["size"] = z.name;
    const bs::Scenario s = read_ok(doc);
    EXPECT_EQ(s.table.shape, bs::TableShape::pool) << z.name;
    EXPECT_EQ(s.table.length, z.length) << z.name;
    EXPECT_EQ(s.table.width, z.width) << z.name;
    EXPECT_EQ(s.table.pockets.size(), 6u) << z.name;
    EXPECT_EQ(s.table.head_spot, (bs::Vec2{z.length / 4, z.width / 2})) << z.name;
  }
}

TEST(PoolRead, PoolTableWorksWithEveryModel) {
  json doc = pool_base();
  doc["physics"]["model"] = "friction";
  doc["balls"][0]["velocity"] = {1.0, 0.0};
  EXPECT_EQ(read_ok(doc).table.shape, bs::TableShape::pool);
  doc["physics"]["model"] = "ideal";
  doc["until"] = {{"time", 1.0}};
  EXPECT_EQ(read_ok(doc).table.shape, bs::TableShape::pool);
}

TEST(PoolInvalid, TableSize) {
  json doc = pool_base();
  doc["table"].erase("size");
  expect_invalid(doc, "table.size", "missing required field");
  doc["table"]["size"] = "10ft";
  expect_invalid(doc, "table.size", "unknown table size \"10ft\" (expected \"7ft\", \"8ft\" or \"9ft\")");
  doc["table"]["size"] = 9;
  expect_invalid(doc, "table.size", "expected a string");
  doc["table"]["size"] = "9ft";
  doc["table"]["min"] = {0.0, 0.0};
  expect_invalid(doc, "table.min", "unknown field");
}

TEST(PoolRead, CushionFields) {
  json doc = pool_base();
  doc["table"]["cushion_restitution"] = 0.7;
  doc["table"]["cushion_friction"] = 0.14;
  doc["table"]["nose_height"] = 0.6;
  doc["balls"].push_back({{"id", "own"}, {"position", {1.5, 0.6}}, {"wall_restitution", 0.9}});
  const bs::Scenario s = read_ok(doc);
  EXPECT_EQ(s.table.cushion.friction, 0.14);
  EXPECT_EQ(s.table.cushion.nose_height, 0.6);
  EXPECT_EQ(s.table.cushion.restitution, 0.7);
  EXPECT_EQ(s.balls[0].wall_restitution, 0.7);  // the table's default
  EXPECT_EQ(s.balls[1].wall_restitution, 0.9);  // a ball's own wins

  // Without the fields: the documented defaults.
  const bs::Scenario d = read_ok(pool_base());
  EXPECT_EQ(d.table.cushion.friction, bs::CushionParams{}.friction);
  EXPECT_EQ(d.table.cushion.nose_height, bs::CushionParams{}.nose_height);
}

TEST(PoolRead, CushionRestitutionOnAnyTable) {
  json doc = json::parse(R"({
    "physics": {"model": "friction"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1], "cushion_restitution": 0.5},
    "balls": [{"id": "a", "position": [1, 0.5]}]
  })");
  EXPECT_EQ(read_ok(doc).balls[0].wall_restitution, 0.5);
  doc["table"] = {{"shape", "polygon"},
                  {"vertices", {{0, 0}, {2, 0}, {1, 2}}},
                  {"cushion_restitution", 0.25}};
  EXPECT_EQ(read_ok(doc).balls[0].wall_restitution, 0.25);
}

TEST(PoolInvalid, CushionFields) {
  json doc = pool_base();
  doc["table"]["cushion_restitution"] = 1.5;
  expect_invalid(doc, "table.cushion_restitution", "[0, 1]");
  doc = pool_base();
  doc["table"]["cushion_friction"] = -0.1;
  expect_invalid(doc, "table.cushion_friction", ">= 0");
  doc = pool_base();
  for (const double h : {0.5, 1.0, 0.2, 1.3}) {
    doc["table"]["nose_height"] = h;
    expect_invalid(doc, "table.nose_height", "between 0.5 and 1");
  }
  doc["table"]["nose_height"] = "high";
  expect_invalid(doc, "table.nose_height", "expected a number");

  // Rail friction, nose height, cushion model and cushion height belong
  // to the pool model's cushions: a pool table, or any table (the lab's)
  // when the physics model is "pool"; elsewhere they are refused.
  json rect = json::parse(R"({
    "physics": {"model": "friction"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1]},
    "balls": [{"id": "a", "position": [1, 0.5]}]
  })");
  for (const auto& [key, value] : {std::pair<const char*, json>{"cushion_friction", 0.2},
                                   {"nose_height", 0.6},
                                   {"cushion_model", "han_2005"},
                                   {"cushion_height", 0.036}}) {
    json d = rect;
    d["table"][key] = value;
    expect_invalid(d, std::string("table.") + key, "only the pool model's cushions");
    d["physics"]["model"] = "pool";
    read_ok(d);
  }
}

// table.cushion_model: the four laws by name, han_2005 by default; each
// brings its own restitution, mathavan_2010 also the paper's contact
// height, unless they are given.
TEST(PoolRead, CushionModel) {
  const bs::Scenario d = read_ok(pool_base());
  EXPECT_EQ(d.table.cushion.model, bs::CushionModel::han_2005);
  EXPECT_EQ(d.table.cushion.restitution, 0.84);
  EXPECT_EQ(d.table.cushion.height, 0.0);
  for (const char* name :
       {"han_2005_v0", "han_2005", "mathavan_2010", "impulse_frictional", "stronge_compliant"}) {
    json doc = pool_base();
    doc["table"]["cushion_model"] = name;
    const bs::Scenario s = read_ok(doc);
    EXPECT_EQ(bs::cushion_model_name(s.table.cushion.model), name);
  }
  json doc = pool_base();
  doc["table"]["cushion_model"] = "mathavan_2010";
  bs::Scenario m = read_ok(doc);
  EXPECT_EQ(m.table.cushion.restitution, 0.98);
  EXPECT_EQ(m.balls[0].wall_restitution, 0.98);
  EXPECT_EQ(m.table.cushion.nose_height, 0.7);
  EXPECT_EQ(m.table.cushion.friction, 0.14);
  doc["table"]["cushion_restitution"] = 0.9;
  doc["table"]["nose_height"] = 0.64;
  m = read_ok(doc);
  EXPECT_EQ(m.balls[0].wall_restitution, 0.9);
  EXPECT_EQ(m.table.cushion.nose_height, 0.64);

  doc = pool_base();
  doc["table"]["cushion_model"] = "han";
  expect_invalid(doc, "table.cushion_model",
                 "unknown cushion model \"han\" (expected \"han_2005_v0\", \"han_2005\", "
                 "\"mathavan_2010\", \"impulse_frictional\" or \"stronge_compliant\")");
  doc["table"]["cushion_model"] = 2005;
  expect_invalid(doc, "table.cushion_model", "expected a string");
}

// table.cushion_height in metres: above every ball's centre and below its
// top.
TEST(PoolRead, CushionHeight) {
  json doc = pool_base();
  doc["table"]["cushion_height"] = 0.0363;
  EXPECT_EQ(read_ok(doc).table.cushion.height, 0.0363);
  for (const json& bad : {json(0.0), json(-0.01), json("high")}) {
    doc["table"]["cushion_height"] = bad;
    expect_invalid(doc, "table.cushion_height");
  }
  // 57.15 mm balls: 28.575 mm < h < 57.15 mm.
  doc["table"]["cushion_height"] = 0.028;
  expect_invalid(doc, "table.cushion_height", "ball 'cue'");
  doc["table"]["cushion_height"] = 0.06;
  expect_invalid(doc, "table.cushion_height", "below the top");
  // A smaller ball on the same rail: the nose passes over its top.
  doc["table"]["cushion_height"] = 0.05;
  read_ok(doc);
  doc["balls"].push_back({{"id", "small"}, {"position", {1.5, 0.6}}, {"radius", 0.02}});
  expect_invalid(doc, "table.cushion_height", "ball 'small'");
}

// --- racks ---------------------------------------------------------------

TEST(PoolRead, EightBallRack) {
  const bs::Scenario s = read_ok(pool_break());
  ASSERT_EQ(s.balls.size(), 16u);
  ASSERT_EQ(s.start.size(), 16u);
  // The cue ball first (it was not given), then "1" ... "15" by number.
  EXPECT_EQ(s.balls[0].id, "cue");
  for (std::size_t k = 1; k <= 15; ++k) EXPECT_EQ(s.balls[k].id, std::to_string(k));
  EXPECT_EQ(s.start[0].position, s.table.head_spot);
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    EXPECT_EQ(s.balls[i].radius, 0.028575);
    EXPECT_EQ(s.balls[i].mass, 0.170);
    EXPECT_EQ(s.balls[i].wall_restitution, bs::CushionParams{}.restitution);
    EXPECT_EQ(s.start[i].velocity, (bs::Vec2{}));
    EXPECT_EQ(s.start[i].state, bs::MotionState::stationary);
  }
  // The apex ball is on the foot spot; the 8 is in the middle of the rack.
  bool apex = false;
  for (std::size_t i = 1; i < 16; ++i) apex = apex || s.start[i].position == s.table.foot_spot;
  EXPECT_TRUE(apex);
  EXPECT_NEAR(s.start[8].position.y, s.table.foot_spot.y, 1e-3);
  EXPECT_FALSE(bs::validate(s));
}

TEST(PoolRead, NineBallRack) {
  json doc = pool_break();
  doc["rack"]["game"] = "nine_ball";
  const bs::Scenario s = read_ok(doc);
  ASSERT_EQ(s.balls.size(), 10u);
  EXPECT_EQ(s.balls[0].id, "cue");
  for (std::size_t k = 1; k <= 9; ++k) EXPECT_EQ(s.balls[k].id, std::to_string(k));
  EXPECT_EQ(s.start[1].position, s.table.foot_spot);  // the 1 at the apex
}

std::vector<bs::Vec2> positions(const bs::Scenario& s) {
  std::vector<bs::Vec2> p;
  for (const bs::BallState& b : s.start) p.push_back(b.position);
  return p;
}

TEST(PoolRead, RackSeeds) {
  json doc = pool_break();
  const auto a = positions(read_ok(doc));
  EXPECT_EQ(a, positions(read_ok(doc))) << "a seed gives the same rack every time";
  doc["rack"]["seed"] = 2;
  EXPECT_NE(a, positions(read_ok(doc)));
  doc["rack"].erase("seed");  // 0 by default
  const auto d = positions(read_ok(doc));
  doc["rack"]["seed"] = 0;
  EXPECT_EQ(positions(read_ok(doc)), d);
  doc["rack"]["seed"] = json::parse("1000.0");  // a whole number written as a float
  const auto e = positions(read_ok(doc));
  doc["rack"]["seed"] = 1000;
  EXPECT_EQ(positions(read_ok(doc)), e);
}

TEST(PoolRead, GivenCueBallIsRespected) {
  json doc = pool_break();
  doc["balls"] = json::parse(R"([
    {"id": "spare", "position": [0.2, 0.2]},
    {"id": "cue", "position": [0.5, 0.4], "mass": 0.16}
  ])");
  const bs::Scenario s = read_ok(doc);
  ASSERT_EQ(s.balls.size(), 17u);  // no second cue ball
  // Given balls first, in their order; then the rack's balls by number.
  EXPECT_EQ(s.balls[0].id, "spare");
  EXPECT_EQ(s.balls[1].id, "cue");
  EXPECT_EQ(s.balls[2].id, "1");
  EXPECT_EQ(s.balls[16].id, "15");
  EXPECT_EQ(s.start[1].position, (bs::Vec2{0.5, 0.4}));
  EXPECT_EQ(s.balls[1].mass, 0.16);
  ASSERT_TRUE(s.cue.has_value());
  EXPECT_EQ(s.cue->ball, 1);
}

TEST(PoolRead, RackBallsFollowTheTableCushionRestitution) {
  json doc = pool_break();
  doc["table"]["cushion_restitution"] = 0.6;
  const bs::Scenario s = read_ok(doc);
  for (const bs::BallSpec& b : s.balls) EXPECT_EQ(b.wall_restitution, 0.6) << b.id;
}

TEST(PoolRead, PairRestitutionCanNameRackBalls) {
  json doc = pool_break();
  doc["pair_restitution"] = {{{"balls", {"cue", "1"}}, {"restitution", 0.9}}};
  const bs::Scenario s = read_ok(doc);
  ASSERT_EQ(s.pair_restitution.size(), 1u);
  EXPECT_EQ(s.pair_restitution[0].a, 0);
  EXPECT_EQ(s.pair_restitution[0].b, 1);
}

TEST(PoolRead, RackWithTheFrictionModel) {
  json doc = pool_break();
  doc.erase("cue");
  doc["physics"]["model"] = "friction";
  const bs::Scenario s = read_ok(doc);
  EXPECT_EQ(s.balls.size(), 16u);
  EXPECT_EQ(s.balls[0].wall_restitution, 1.0);
  EXPECT_EQ(s.start[0].state, bs::MotionState::stationary);
}

TEST(PoolInvalid, Racks) {
  json doc = pool_break();
  doc["table"] = {{"shape", "rectangle"}, {"min", {0.0, 0.0}}, {"max", {2.54, 1.27}}};
  expect_invalid(doc, "rack", "a rack needs a pool table");

  doc = pool_break();
  doc["rack"]["game"] = "straight_pool";
  expect_invalid(doc, "rack.game",
                 "unknown game \"straight_pool\" (expected \"eight_ball\", \"nine_ball\", "
                 "\"ten_ball\", \"snooker\" or \"three_cushion\")");
  doc["rack"].erase("game");
  expect_invalid(doc, "rack.game", "missing required field");
  doc = pool_break();
  doc["rack"]["seed"] = -1;
  expect_invalid(doc, "rack.seed", "whole number >= 0");
  doc["rack"]["seed"] = 1.5;
  expect_invalid(doc, "rack.seed", "whole number >= 0");
  doc["rack"]["seed"] = "one";
  expect_invalid(doc, "rack.seed", "expected a whole number");
  doc = pool_break();
  doc["rack"]["balls"] = 15;
  expect_invalid(doc, "rack.balls", "unknown field");
  doc["rack"] = "eight_ball";
  expect_invalid(doc, "rack", "expected an object");

  // A given ball may not take an object ball's id.
  doc = pool_break();
  doc["balls"] = {{{"id", "3"}, {"position", {0.3, 0.3}}}};
  expect_invalid(doc, "balls[0].id", "the rack places a ball with the id '3'");

  // Nor stand where the rack puts a ball, or on the head spot.
  doc = pool_break();
  doc["balls"] = {{{"id", "spare"}, {"position", {2.54 * 0.75 + 0.01, 0.635}}}};
  expect_invalid(doc, "balls[0].position", "placed by the rack");
  doc["balls"] = {{{"id", "spare"}, {"position", {2.54 * 0.25, 0.66}}}};
  expect_invalid(doc, "balls[0].position", "overlaps ball 'cue' placed by the rack");

  // Without a rack, balls are required.
  doc = pool_base();
  doc.erase("balls");
  expect_invalid(doc, "balls", "missing required field");
}

// --- the cue ---------------------------------------------------------------

TEST(PoolRead, CueDefaults) {
  const bs::Scenario s = read_ok(pool_break());
  ASSERT_TRUE(s.cue.has_value());
  EXPECT_EQ(s.cue->ball, 0);
  EXPECT_EQ(s.cue->strike.speed, 8.0);
  EXPECT_EQ(s.cue->strike.phi, 0.0);
  EXPECT_EQ(s.cue->strike.theta, 0.0);
  EXPECT_EQ(s.cue->strike.a, 0.0);
  EXPECT_EQ(s.cue->strike.b, 0.0);
  EXPECT_EQ(s.cue->params.mass, bs::CueParams{}.mass);
  EXPECT_EQ(s.cue->params.tip_restitution, bs::CueParams{}.tip_restitution);
  EXPECT_TRUE(s.until.rest);
}

TEST(PoolRead, CueEveryField) {
  json doc = pool_base();
  doc["balls"].push_back({{"id", "white"}, {"position", {1.0, 0.3}}});
  doc["cue"] = json::parse(R"({"ball": "white", "speed": 2.5, "phi": -30.0, "theta": 12.0,
                               "a": 0.2, "b": -0.3, "cue_mass": 0.6, "tip_restitution": 0.7})");
  const bs::Scenario s = read_ok(doc);
  ASSERT_TRUE(s.cue.has_value());
  EXPECT_EQ(s.cue->ball, 1);
  EXPECT_EQ(s.cue->strike.speed, 2.5);
  EXPECT_EQ(s.cue->strike.phi, -30.0);
  EXPECT_EQ(s.cue->strike.theta, 12.0);
  EXPECT_EQ(s.cue->strike.a, 0.2);
  EXPECT_EQ(s.cue->strike.b, -0.3);
  EXPECT_EQ(s.cue->params.mass, 0.6);
  EXPECT_EQ(s.cue->params.tip_restitution, 0.7);
  // The rest of the cue's parameters keep their defaults.
  EXPECT_EQ(s.cue->params.miscue_limit, bs::CueParams{}.miscue_limit);
  EXPECT_EQ(s.cue->params.end_mass, bs::CueParams{}.end_mass);
}

TEST(PoolRead, AMiscueIsNotAnInputError) {
  json doc = pool_base();
  doc["cue"] = {{"speed", 3.0}, {"a", 0.9}, {"b", 0.6}};
  const bs::Scenario s = read_ok(doc);
  EXPECT_EQ(s.cue->strike.a, 0.9);
}

TEST(PoolInvalid, Cue) {
  json doc = pool_base();
  doc["physics"]["model"] = "friction";
  doc["cue"] = {{"speed", 3.0}};
  expect_invalid(doc, "cue", "a cue strike needs the pool model");

  doc = pool_base();
  doc["cue"] = {{"ball", "ghost"}, {"speed", 3.0}};
  expect_invalid(doc, "cue.ball", "no ball has the id 'ghost'");
  doc["balls"][0]["id"] = "white";
  doc["cue"] = {{"speed", 3.0}};  // the default ball "cue" is not there
  expect_invalid(doc, "cue.ball", "no ball has the id 'cue'");
  doc["cue"] = {{"ball", 0}, {"speed", 3.0}};
  expect_invalid(doc, "cue.ball", "expected a ball id");

  doc = pool_base();
  doc["cue"] = json::object();
  expect_invalid(doc, "cue.speed", "missing required field");
  doc["cue"] = {{"speed", -3.0}};
  expect_invalid(doc, "cue.speed", "positive");
  doc["cue"] = {{"speed", 0.0}};
  expect_invalid(doc, "cue.speed", "positive");
  doc["cue"] = {{"speed", 3.0}, {"theta", 90.0}};
  expect_invalid(doc, "cue.theta", "[0, 90)");
  doc["cue"] = {{"speed", 3.0}, {"theta", -1.0}};
  expect_invalid(doc, "cue.theta", "[0, 90)");
  doc["cue"] = {{"speed", 3.0}, {"phi", "north"}};
  expect_invalid(doc, "cue.phi", "expected a number");
  doc["cue"] = {{"speed", 3.0}, {"a", 1e13}};
  expect_invalid(doc, "cue.a", "too large");
  doc["cue"] = {{"speed", 3.0}, {"cue_mass", 0.0}};
  expect_invalid(doc, "cue.cue_mass", "positive");
  doc["cue"] = {{"speed", 3.0}, {"tip_restitution", 1.5}};
  expect_invalid(doc, "cue.tip_restitution", "[0, 1]");
  doc["cue"] = {{"speed", 3.0}, {"english", 0.2}};
  expect_invalid(doc, "cue.english", "unknown field");
  doc["cue"] = 3.0;
  expect_invalid(doc, "cue", "expected an object");

  // The strike sets the ball's motion: one given in the file would be lost.
  doc = pool_base();
  doc["balls"][0]["velocity"] = {0.5, 0.0};
  doc["cue"] = {{"speed", 3.0}};
  expect_invalid(doc, "cue.ball", "must be at rest");
}

// --- "rest" must come --------------------------------------------------

TEST(PoolInvalid, RestThatNeverComes) {
  json moving = pool_base();
  moving["balls"][0]["velocity"] = {1.0, 0.0};
  for (const char* field : {"sliding_friction", "rolling_friction", "gravity"}) {
    json doc = moving;
    doc["physics"][field] = 0.0;
    expect_invalid(doc, "until", std::string("physics.") + field + " is 0");
    doc["until"] = "rest";
    expect_invalid(doc, "until", "\"rest\" never comes");
    doc["until"] = {{"time", 2.0}};
    read_ok(doc);  // a time always comes
    doc = pool_break();  // the cue ball moves once struck
    doc["physics"][field] = 0.0;
    expect_invalid(doc, "until", "the cue strikes ball 'cue'");
  }

  json spinning = pool_base();
  spinning["balls"][0]["spin"] = {0.0, 0.0, 30.0};
  spinning["physics"]["spinning_friction"] = 0.0;
  expect_invalid(spinning, "until", "spins about the vertical");
  json english = pool_break();
  english["physics"]["spinning_friction"] = 0.0;
  read_ok(english);  // a centre hit gives no spin about the vertical
  english["cue"]["a"] = 0.2;
  expect_invalid(english, "until", "side english");

  json tiny = moving;
  tiny["physics"]["rolling_friction"] = 1e-320;
  expect_invalid(tiny, "until", "too small");

  json still = pool_base();  // nothing moves: at rest from the start
  still["physics"]["sliding_friction"] = 0.0;
  still["physics"]["rolling_friction"] = 0.0;
  still["physics"]["spinning_friction"] = 0.0;
  read_ok(still);
}

// --- geometry: pockets and jaws ------------------------------------------

TEST(PoolInvalid, BallInAPocket) {
  const bs::Scenario s = read_ok(pool_base());
  for (const bs::Pocket& p : s.table.pockets) {
    json doc = pool_base();
    doc["balls"].push_back({{"id", "lost"}, {"position", {p.centre.x, p.centre.y}}});
    expect_invalid(doc, "balls[1].position", "inside pocket '" + p.name + "'");
  }
}

TEST(PoolInvalid, BallAgainstRailsAndJaws) {
  const bs::Scenario s = read_ok(pool_base());
  const double r = 0.028575;
  // Against the bottom rail, between the pockets.
  json doc = pool_base();
  doc["balls"][0]["position"] = {0.6, r - 0.001};
  expect_invalid(doc, "balls[0].position", "overlaps the wall 'rail_bottom_left'");
  doc["balls"][0]["position"] = {0.6, r};  // touching is fine
  read_ok(doc);

  // Against the round tip of every jaw: straight out from the middle of
  // the arc, a little closer than a ball's radius. There the tangent
  // points where the arc meets the straight walls are more than a radius
  // away, so only the arc itself shows the overlap.
  int arcs = 0;
  for (const bs::Wall& w : s.table.walls) {
    if (w.kind != bs::WallKind::arc) continue;
    ++arcs;
    bs::Vec2 mid = w.b + w.normal;
    mid = mid / bs::norm(mid);
    const bs::Vec2 near = w.a + mid * (w.radius + r - 5e-5);
    EXPECT_GT(bs::wall_clearance(s.table, near, r), 0.0) << w.name << ": not a test of the arc";
    doc = pool_base();
    doc["balls"][0]["position"] = {near.x, near.y};
    expect_invalid(doc, "balls[0].position", "overlaps the wall '" + w.name + "'");
    const bs::Vec2 clear = w.a + mid * (w.radius + r + 1e-7);
    doc["balls"][0]["position"] = {clear.x, clear.y};
    read_ok(doc);
  }
  EXPECT_EQ(arcs, 12);  // two jaws a pocket, one round tip each
}

TEST(PoolValidate, CodeBuiltCueAndCushion) {
  bs::Scenario s = read_ok(pool_break());
  ASSERT_FALSE(bs::validate(s));
  bs::Scenario t = s;
  t.cue->ball = 99;
  EXPECT_EQ(bs::validate(t)->path, "cue.ball");
  t = s;
  t.cue->strike.theta = 90.0;
  EXPECT_EQ(bs::validate(t)->path, "cue.theta");
  t = s;
  t.cue->strike.speed = std::nan("");
  EXPECT_EQ(bs::validate(t)->path, "cue.speed");
  t = s;
  t.cue->params.tip_restitution = -0.1;
  EXPECT_EQ(bs::validate(t)->path, "cue.tip_restitution");
  t = s;
  t.physics.model = bs::Model::friction;
  EXPECT_EQ(bs::validate(t)->path, "cue");
  t = s;
  t.table.cushion.nose_height = 0.4;
  EXPECT_EQ(bs::validate(t)->path, "table.nose_height");
  t = s;
  t.start[5].position = t.table.pockets[0].centre;
  const auto e = bs::validate(t);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "balls[5].position");
  EXPECT_NE(e->reason.find("inside pocket 'bottom_left'"), std::string::npos) << e->reason;
}

// --- results ----------------------------------------------------------------

TEST(PoolWrite, PoolEventsAndTheCueObject) {
  const bs::Scenario s = read_ok(pool_break());
  bs::RunResult r;
  bs::StrikeResult strike;
  strike.velocity = {4.5, 0.25};
  strike.spin = {0.0, 12.0, -3.0};
  strike.squirt = 1.5;
  r.cue = strike;
  bs::Event e;
  e.time = 0.0;
  e.type = bs::EventType::cue_strike;
  e.ball = 0;
  r.events.push_back(e);
  e = {};
  e.time = 0.2;
  e.type = bs::EventType::state_change;
  e.ball = 0;
  e.from = bs::MotionState::sliding;
  e.to = bs::MotionState::rolling;
  r.events.push_back(e);
  e = {};
  e.time = 0.5;
  e.type = bs::EventType::ball_cushion;
  e.ball = 3;
  std::size_t tip = 0;
  while (s.table.walls[tip].kind != bs::WallKind::arc) ++tip;
  e.wall = static_cast<std::int32_t>(tip);
  r.events.push_back(e);
  e = {};
  e.time = 0.75;
  e.type = bs::EventType::ball_pocket;
  e.ball = 3;
  e.pocket = 4;
  r.events.push_back(e);
  e.pocket = 6;  // no such pocket: still valid JSON
  r.events.push_back(e);
  r.final_time = 1.0;
  r.final_balls = s.start;
  r.final_balls[0].spin = {1.0, 2.0, 3.0};
  r.final_balls[0].state = bs::MotionState::spinning;
  r.final_balls[3].state = bs::MotionState::pocketed;

  const std::string text = bs::write_result(s, r);
  EXPECT_EQ(text, bs::write_result(s, r));
  const json out = json::parse(text);
  ASSERT_TRUE(out.contains("cue"));
  EXPECT_EQ(out["cue"]["miscue"], false);
  EXPECT_EQ(out["cue"]["velocity"], json({4.5, 0.25}));
  EXPECT_EQ(out["cue"]["spin"], json({0.0, 12.0, -3.0}));
  EXPECT_EQ(out["cue"]["squirt"].get<double>(), 1.5);

  const json& ev = out["events"];
  ASSERT_EQ(ev.size(), 5u);
  EXPECT_EQ(ev[0], json::parse(R"({"time": 0.0, "type": "cue_strike", "balls": ["cue"]})"));
  EXPECT_EQ(ev[1]["from"], "sliding");
  EXPECT_EQ(ev[1]["to"], "rolling");
  EXPECT_EQ(ev[2]["type"], "ball_cushion");
  EXPECT_EQ(ev[2]["balls"], json({"3"}));
  EXPECT_EQ(ev[2]["cushion"], s.table.walls[tip].name);
  EXPECT_NE(ev[2]["cushion"].get<std::string>().find("_tip"), std::string::npos);
  EXPECT_EQ(ev[3]["type"], "ball_pocket");
  EXPECT_EQ(ev[3]["pocket"], s.table.pockets[4].name);
  EXPECT_TRUE(ev[4]["pocket"].is_null());

  const json& fin = out["final"]["balls"];
  ASSERT_EQ(fin.size(), 16u);
  EXPECT_EQ(fin[0]["spin"], json({1.0, 2.0, 3.0}));
  EXPECT_EQ(fin[0]["state"], "spinning");
  EXPECT_EQ(fin[3]["state"], "pocketed");
  EXPECT_EQ(fin[1]["state"], "stationary");

  // A miscue is reported as such.
  r.cue->miscue = true;
  EXPECT_EQ(json::parse(bs::write_result(s, r))["cue"]["miscue"], true);
  // No strike, no "cue" object.
  r.cue.reset();
  EXPECT_FALSE(json::parse(bs::write_result(s, r)).contains("cue"));
}

// --- through the engine -----------------------------------------------------

TEST(PoolRun, AStrikeStartsTheRun) {
  json doc = pool_base();
  doc["cue"] = {{"speed", 2.0}, {"phi", 45.0}};
  doc["until"] = {{"time", 0.05}};
  doc["samples"] = {{"dt", 0.025}};
  const bs::Scenario s = read_ok(doc);
  const bs::RunResult r = bs::simulate(s);
  const json out = json::parse(bs::write_result(s, r));
  EXPECT_EQ(out["complete"], true);
  ASSERT_FALSE(out["events"].empty());
  EXPECT_EQ(out["events"][0], json::parse(R"({"time": 0.0, "type": "cue_strike", "balls": ["cue"]})"));
  ASSERT_TRUE(out.contains("cue"));
  EXPECT_EQ(out["cue"]["miscue"], false);
  const double vx = out["cue"]["velocity"][0].get<double>();
  const double vy = out["cue"]["velocity"][1].get<double>();
  EXPECT_GT(vx, 0.0);
  EXPECT_NEAR(vx, vy, 1e-9 * vx);  // straight along phi = 45 degrees, no squirt
  EXPECT_EQ(out["final"]["balls"][0]["state"], "sliding");
  ASSERT_EQ(out["samples"].size(), 3u);
  EXPECT_EQ(out["samples"][0]["balls"][0]["spin"].size(), 3u);
}

}  // namespace

}  // namespace test_pool_io

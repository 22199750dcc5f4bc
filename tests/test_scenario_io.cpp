// Reading scenarios, validating them and writing results: the contract in
// docs/contract.md. Every kind of invalid input the
// contract lists is checked with the exact path it must be reported at.

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "breakshot/lab.hpp"
#include "breakshot/scenario_io.hpp"

namespace test_scenario_io {

namespace {

using nlohmann::json;
namespace bs = breakshot;

/// A small valid ideal-model scenario that each test changes a little.
json base() {
  return json::parse(R"({
    "physics": {"model": "ideal"},
    "table": {"shape": "rectangle", "min": [-1.0, -0.5], "max": [1.0, 0.5]},
    "balls": [
      {"id": "a", "position": [-0.5, 0.0], "velocity": [1.0, 0.0]},
      {"id": "b", "position": [0.0, 0.0]},
      {"id": "c", "position": [0.5, 0.2], "radius": 0.03, "mass": 0.2}
    ],
    "until": {"time": 2.0}
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

bs::ScenarioError read_error_text(const std::string& text) {
  auto r = bs::read_scenario(text);
  if (!std::holds_alternative<bs::ScenarioError>(r)) {
    ADD_FAILURE() << "expected an error for: " << text;
    return {};
  }
  return std::get<bs::ScenarioError>(r);
}

bs::ScenarioError read_error(const json& doc) { return read_error_text(doc.dump()); }

/// The scenario is rejected as invalid (not unsupported) at `path`, and
/// the reason contains `reason_part`.
void expect_invalid(const json& doc, const std::string& path,
                    const std::string& reason_part = "") {
  const bs::ScenarioError e = read_error(doc);
  EXPECT_EQ(e.path, path) << "reason: " << e.reason;
  EXPECT_FALSE(e.unsupported) << e.path << ": " << e.reason;
  EXPECT_NE(e.reason.find(reason_part), std::string::npos)
      << "reason '" << e.reason << "' lacks '" << reason_part << "'";
}

// --- reading valid scenarios ------------------------------------------

TEST(ScenarioRead, ContractExample) {
  const auto s = read_ok(json::parse(R"({
    "physics": {"model": "ideal", "ball_ball_restitution": 1.0, "ball_ball_friction": 0.0,
                "gravity": 9.81, "deceleration": 0.0, "sliding_friction": 0.2,
                "rolling_friction": 0.01, "spinning_friction": 0.044},
    "table": {"shape": "rectangle", "min": [-0.1, -0.1], "max": [0.1, 0.1]},
    "balls": [
      {"id": "white", "position": [-0.05, 0.0], "velocity": [0.3, 0.05],
       "radius": 0.012, "mass": 0.02, "wall_restitution": 0.9},
      {"id": "black", "position": [0.05, 0.01], "velocity": [0.0, 0.0],
       "radius": 0.02, "mass": 0.05, "wall_restitution": 0.8}
    ],
    "pair_restitution": [{"balls": ["white", "black"], "restitution": 0.95}],
    "until": {"time": 5.0},
    "samples": {"dt": 0.01},
    "max_events": 1000000
  })"));
  EXPECT_EQ(s.physics.model, bs::Model::ideal);
  EXPECT_EQ(s.physics.deceleration, 0.0);
  ASSERT_EQ(s.balls.size(), 2u);
  ASSERT_EQ(s.start.size(), 2u);
  EXPECT_EQ(s.balls[0].id, "white");
  EXPECT_EQ(s.balls[0].radius, 0.012);
  EXPECT_EQ(s.balls[0].mass, 0.02);
  EXPECT_EQ(s.balls[0].wall_restitution, 0.9);
  EXPECT_EQ(s.start[0].position, (bs::Vec2{-0.05, 0.0}));
  EXPECT_EQ(s.start[0].velocity, (bs::Vec2{0.3, 0.05}));
  EXPECT_EQ(s.start[0].state, bs::MotionState::moving);
  EXPECT_EQ(s.start[1].state, bs::MotionState::stationary);
  ASSERT_EQ(s.pair_restitution.size(), 1u);
  EXPECT_EQ(s.pair_restitution[0].a, 0);
  EXPECT_EQ(s.pair_restitution[0].b, 1);
  EXPECT_EQ(s.pair_restitution[0].restitution, 0.95);
  EXPECT_FALSE(s.until.rest);
  EXPECT_EQ(s.until.time, 5.0);
  ASSERT_TRUE(s.sample_dt.has_value());
  EXPECT_EQ(*s.sample_dt, 0.01);
  EXPECT_EQ(s.max_events, 1000000u);
  EXPECT_EQ(s.table.shape, bs::TableShape::rectangle);
  ASSERT_EQ(s.table.walls.size(), 4u);
}

TEST(ScenarioRead, Defaults) {
  json doc = base();
  const auto s = read_ok(doc);
  const bs::PhysicsParams& p = s.physics;
  EXPECT_EQ(p.ball_ball_restitution, 1.0);
  EXPECT_EQ(p.ball_ball_friction, 0.0);
  EXPECT_EQ(p.gravity, 9.81);
  EXPECT_EQ(p.sliding_friction, 0.2);
  EXPECT_EQ(p.rolling_friction, 0.01);
  EXPECT_EQ(p.spinning_friction, 0.0117);  // docs/physics.md, "Spin about the vertical"
  EXPECT_EQ(p.deceleration, 0.01 * 9.81);
  EXPECT_EQ(p.collapse_speed, 1e-5);
  EXPECT_EQ(s.balls[1].radius, 0.028575);
  EXPECT_EQ(s.balls[1].mass, 0.170);
  EXPECT_EQ(s.balls[1].wall_restitution, 1.0);
  EXPECT_EQ(s.start[1].velocity, (bs::Vec2{0.0, 0.0}));
  EXPECT_EQ(s.start[1].spin, (bs::Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(s.start[1].state, bs::MotionState::stationary);
  EXPECT_EQ(s.start[0].state, bs::MotionState::moving);
  EXPECT_TRUE(s.pair_restitution.empty());
  EXPECT_FALSE(s.sample_dt.has_value());
  EXPECT_EQ(s.max_events, 10'000'000u);
}

TEST(ScenarioRead, FrictionDefaultsToRestAndDerivedDeceleration) {
  json doc = base();
  doc["physics"] = {{"model", "friction"}, {"rolling_friction", 0.02}, {"gravity", 10.0}};
  doc.erase("until");
  const auto s = read_ok(doc);
  EXPECT_EQ(s.physics.model, bs::Model::friction);
  EXPECT_TRUE(s.until.rest);
  EXPECT_EQ(s.physics.deceleration, 0.02 * 10.0);

  doc["physics"]["deceleration"] = 0.5;
  doc["until"] = "rest";
  EXPECT_EQ(read_ok(doc).physics.deceleration, 0.5);
}

TEST(ScenarioRead, CollapseSpeedAndMaxEvents) {
  json doc = base();
  doc["physics"]["collapse_speed"] = 1e-3;
  doc["max_events"] = 5;
  auto s = read_ok(doc);
  EXPECT_EQ(s.physics.collapse_speed, 1e-3);
  EXPECT_EQ(s.max_events, 5u);
  // 1e6 is a float in JSON but an integral count.
  EXPECT_EQ(read_ok(json::parse(R"({"physics": {"model": "ideal"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [1, 1]},
    "balls": [], "until": {"time": 1}, "max_events": 1e6})")).max_events,
            1000000u);
}

TEST(ScenarioRead, PolygonTable) {
  json doc = base();
  // An L shape, clockwise: one reflex corner.
  doc["table"] = {{"shape", "polygon"},
                  {"vertices", {{-1.0, -0.5}, {-1.0, 0.5}, {0.0, 0.5}, {0.0, 0.0},
                                {1.0, 0.0}, {1.0, -0.5}}}};
  doc["balls"] = {{{"id", "a"}, {"position", {-0.5, 0.0}}, {"velocity", {1.0, 0.0}}},
                  {{"id", "b"}, {"position", {0.5, -0.25}}}};
  const auto s = read_ok(doc);
  EXPECT_EQ(s.table.shape, bs::TableShape::polygon);
  EXPECT_EQ(s.table.walls.front().name, "edge0");
}

TEST(ScenarioRead, PairRestitutionIsStoredLowerIndexFirst) {
  json doc = base();
  doc["pair_restitution"] = {{{"balls", {"c", "a"}}, {"restitution", 0.5}},
                             {{"balls", {"a", "b"}}, {"restitution", 0.0}}};
  const auto s = read_ok(doc);
  ASSERT_EQ(s.pair_restitution.size(), 2u);
  EXPECT_EQ(s.pair_restitution[0].a, 0);
  EXPECT_EQ(s.pair_restitution[0].b, 2);
  EXPECT_EQ(s.pair_restitution[0].restitution, 0.5);
  EXPECT_EQ(s.pair_restitution[1].restitution, 0.0);
}

TEST(ScenarioRead, ExtraObjectsAreIgnoredEverywhere) {
  json doc = base();
  doc["extra"] = {{"anything", {1, 2, 3}}, {"nested", {{"deep", true}}}};
  doc["physics"]["extra"] = {{"note", "x"}};
  doc["table"]["extra"] = {{"colour", "green"}};
  doc["balls"][0]["extra"] = {{"colour", "white"}};
  doc["until"]["extra"] = json::object();
  // Repeated keys are the user's business inside "extra".
  const std::string text = R"({"physics": {"model": "ideal"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [1, 1]},
    "balls": [], "until": {"time": 1},
    "extra": {"k": 1, "k": 2, "o": {"z": 1, "z": 2}}})";
  read_ok(doc);
  EXPECT_TRUE(std::holds_alternative<bs::Scenario>(bs::read_scenario(text)));
}

TEST(ScenarioRead, ZeroSpinIsAllowedOutsideThePoolModel) {
  json doc = base();
  doc["balls"][0]["spin"] = {0.0, 0.0, 0.0};
  read_ok(doc);
}

TEST(ScenarioRead, TouchingBallsAreValid) {
  // A Newton's cradle: balls exactly a diameter apart, and one whose
  // coordinates only round to touching.
  json doc = base();
  const double r = 0.028575;
  doc["balls"] = json::array();
  for (int i = 0; i < 5; ++i) {
    doc["balls"].push_back({{"id", "n" + std::to_string(i)}, {"position", {i * 2 * r, 0.0}}});
  }
  // 0.1 * 3 - 0.3 is 5.6e-17, not 0: this one is a hair off touching.
  doc["balls"].push_back({{"id", "t"}, {"position", {0.1 * 3 - 0.3 - 2 * r, 0.0}}});
  doc["balls"][0]["velocity"] = {1.0, 0.0};
  read_ok(doc);
  // Touching a wall is fine too.
  doc = base();
  doc["balls"][1]["position"] = {1.0 - 0.028575, 0.0};
  read_ok(doc);
}

TEST(ScenarioRead, IdealRestWithNothingMovingIsFine) {
  json doc = base();
  doc["balls"][0]["velocity"] = {0.0, 0.0};
  doc["until"] = "rest";
  EXPECT_TRUE(read_ok(doc).until.rest);
}

TEST(ScenarioRead, TinySampleStepWithRestIsAllowed) {
  json doc = base();
  doc["physics"] = {{"model", "friction"}};
  doc["until"] = "rest";
  doc["samples"] = {{"dt", 1e-9}};
  EXPECT_EQ(*read_ok(doc).sample_dt, 1e-9);
}

// --- invalid input: every kind the contract lists ---------------------

TEST(ScenarioInvalid, BallOverlapsBall) {
  json doc = base();
  doc["balls"][2]["position"] = {0.03, 0.0};
  expect_invalid(doc, "balls[2].position", "overlaps ball 'b'");
}

TEST(ScenarioInvalid, OverlapByAMicrometreIsAnOverlap) {
  json doc = base();
  doc["balls"][1]["position"] = {-0.5 + 2 * 0.028575 - 1e-6, 0.0};
  expect_invalid(doc, "balls[1].position", "overlaps ball 'a'");
}

TEST(ScenarioInvalid, FirstOverlapInScenarioOrderIsReported) {
  json doc = base();
  doc["balls"].push_back({{"id", "d"}, {"position", {0.5, 0.21}}});  // on c
  doc["balls"].push_back({{"id", "e"}, {"position", {-0.5, 0.01}}});  // on a
  expect_invalid(doc, "balls[3].position", "overlaps ball 'c'");
}

TEST(ScenarioInvalid, BallOverlapsWall) {
  json doc = base();
  doc["balls"][0]["position"] = {-0.99, 0.0};
  expect_invalid(doc, "balls[0].position", "the wall 'left'");
  doc = base();
  doc["balls"][2]["position"] = {0.5, 0.49};
  expect_invalid(doc, "balls[2].position", "the wall 'top'");
}

TEST(ScenarioInvalid, BallOutsideTable) {
  json doc = base();
  doc["balls"][1]["position"] = {3.0, 0.0};
  expect_invalid(doc, "balls[1].position", "outside the table");
}

TEST(ScenarioInvalid, BallInTheNotchOfAnLShapedTable) {
  json doc = base();
  doc["table"] = {{"shape", "polygon"},
                  {"vertices", {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.0}, {0.0, 0.0},
                                {0.0, 0.5}, {-1.0, 0.5}}}};
  doc["balls"][1]["position"] = {0.5, -0.25};
  doc["balls"][2]["position"] = {0.5, 0.3};
  expect_invalid(doc, "balls[2].position", "outside the table");
  doc["balls"][2]["position"] = {0.02, -0.02};  // inside, but on the reflex corner
  expect_invalid(doc, "balls[2].position", "overlaps");
}

TEST(ScenarioInvalid, RadiusAndMassMustBePositive) {
  json doc = base();
  doc["balls"][1]["radius"] = 0.0;
  expect_invalid(doc, "balls[1].radius", "positive");
  doc["balls"][1]["radius"] = -0.01;
  expect_invalid(doc, "balls[1].radius", "positive");
  doc = base();
  doc["balls"][2]["mass"] = 0;
  expect_invalid(doc, "balls[2].mass", "positive");
  doc["balls"][2]["mass"] = -1;
  expect_invalid(doc, "balls[2].mass", "positive");
}

TEST(ScenarioInvalid, NonFiniteNumbers) {
  // JSON has no NaN or infinity: the literals are syntax errors and a
  // number beyond the double range overflows. Both name the document.
  const std::string good = base().dump();
  auto with_radius = [&](const std::string& value) {
    std::string text = good;
    const std::string key = "\"id\":\"b\"";
    text.replace(text.find(key), key.size(), key + ",\"radius\":" + value);
    return text;
  };
  for (const char* v : {"NaN", "Infinity", "-Infinity", "nan", "inf"}) {
    const auto e = read_error_text(with_radius(v));
    EXPECT_EQ(e.path, "(document)") << v;
    EXPECT_NE(e.reason.find("line 1"), std::string::npos) << e.reason;
  }
  const auto e = read_error_text(with_radius("1e400"));
  EXPECT_EQ(e.path, "(document)");
  EXPECT_NE(e.reason.find("1e400"), std::string::npos) << e.reason;
  // Finite but too large for the engine to square safely.
  json doc = base();
  doc["balls"][1]["position"] = {1e13, 0.0};
  expect_invalid(doc, "balls[1].position[0]", "too large");
}

TEST(ScenarioInvalid, RestitutionOutsideUnitInterval) {
  json doc = base();
  doc["balls"][0]["wall_restitution"] = 1.5;
  expect_invalid(doc, "balls[0].wall_restitution", "[0, 1]");
  doc["balls"][0]["wall_restitution"] = -0.1;
  expect_invalid(doc, "balls[0].wall_restitution", "[0, 1]");
  doc = base();
  doc["physics"]["ball_ball_restitution"] = 1.01;
  expect_invalid(doc, "physics.ball_ball_restitution", "[0, 1]");
  doc = base();
  doc["pair_restitution"] = {{{"balls", {"a", "b"}}, {"restitution", -0.5}}};
  expect_invalid(doc, "pair_restitution[0].restitution", "[0, 1]");
}

TEST(ScenarioInvalid, SelfCrossingPolygon) {
  json doc = base();
  doc["table"] = {{"shape", "polygon"},
                  {"vertices", {{-1.0, -0.5}, {1.0, 0.5}, {1.0, -0.5}, {-1.0, 0.8}}}};
  expect_invalid(doc, "table.vertices", "cross");
  doc["table"]["vertices"] = {{0, 0}, {1, 0}};
  expect_invalid(doc, "table.vertices", "3 vertices");
  doc["table"]["vertices"] = {{0, 0}, {1, 0}, {2, 0}};
  expect_invalid(doc, "table.vertices");
  doc["table"]["vertices"] = {{0, 0}, {1, 0}, {1, "x"}};
  expect_invalid(doc, "table.vertices[2][1]", "expected a number");
  doc["table"]["vertices"] = {{0, 0}, {1, 0}, {1}};
  expect_invalid(doc, "table.vertices[2]", "2 numbers");
}

TEST(ScenarioInvalid, DuplicateId) {
  json doc = base();
  doc["balls"][2]["id"] = "a";
  expect_invalid(doc, "balls[2].id", "duplicate id 'a'");
}

TEST(ScenarioInvalid, MissingRequiredFields) {
  json doc = base();
  doc.erase("physics");
  expect_invalid(doc, "physics", "missing");
  doc = base();
  doc["physics"].erase("model");
  expect_invalid(doc, "physics.model", "missing");
  doc = base();
  doc.erase("table");
  expect_invalid(doc, "table", "missing");
  doc = base();
  doc["table"].erase("shape");
  expect_invalid(doc, "table.shape", "missing");
  doc = base();
  doc["table"].erase("min");
  expect_invalid(doc, "table.min", "missing");
  doc = base();
  doc.erase("balls");
  expect_invalid(doc, "balls", "missing");
  doc = base();
  doc["balls"][1].erase("id");
  expect_invalid(doc, "balls[1].id", "missing");
  doc = base();
  doc["balls"][1].erase("position");
  expect_invalid(doc, "balls[1].position", "missing");
  doc = base();
  doc.erase("until");  // required for the ideal model
  expect_invalid(doc, "until", "missing");
  doc = base();
  doc["until"] = json::object();
  expect_invalid(doc, "until.time", "missing");
  doc = base();
  doc["samples"] = json::object();
  expect_invalid(doc, "samples.dt", "missing");
  doc = base();
  doc["pair_restitution"] = {{{"balls", {"a", "b"}}}};
  expect_invalid(doc, "pair_restitution[0].restitution", "missing");
}

TEST(ScenarioInvalid, UnknownFields) {
  json doc = base();
  doc["bals"] = json::array();
  expect_invalid(doc, "bals", "unknown field");
  doc = base();
  doc["physics"]["frction"] = 0.1;
  // The message lists the fields the object may have.
  expect_invalid(doc, "physics.frction",
                 "unknown field (known: model, ball_ball_restitution, ball_ball_friction, "
                 "gravity, deceleration, sliding_friction, rolling_friction, spinning_friction, "
                 "collapse_speed, ball_clusters, ball_ball_model, airborne, slate_restitution, min_bounce_height)");
  doc = base();
  doc["table"]["cushion_restitutoin"] = 0.9;  // cushion_restitution is a field of any table
  expect_invalid(doc, "table.cushion_restitutoin", "unknown field");
  doc = base();
  doc["balls"][1]["colour"] = "red";
  expect_invalid(doc, "balls[1].colour", "unknown field");
  doc = base();
  doc["until"]["tme"] = 1.0;
  expect_invalid(doc, "until.tme", "unknown field");
  doc = base();
  doc["samples"] = {{"dt", 0.1}, {"step", 0.1}};
  expect_invalid(doc, "samples.step", "unknown field");
  doc = base();
  doc["pair_restitution"] = {{{"balls", {"a", "b"}}, {"restitution", 0.5}, {"e", 1}}};
  expect_invalid(doc, "pair_restitution[0].e", "unknown field");
  doc = base();
  doc["balls"][0]["odd key"] = 1;
  expect_invalid(doc, "balls[0][\"odd key\"]", "unknown field");
}

TEST(ScenarioInvalid, WrongTypes) {
  json doc = base();
  doc["balls"][1]["radius"] = "0.03";
  expect_invalid(doc, "balls[1].radius", "expected a number, not a string");
  doc["balls"][1]["radius"] = true;
  expect_invalid(doc, "balls[1].radius", "expected a number, not a boolean");
  doc["balls"][1]["radius"] = nullptr;
  expect_invalid(doc, "balls[1].radius", "expected a number, not null");
  doc = base();
  doc["balls"][0]["position"] = {0.0};
  expect_invalid(doc, "balls[0].position", "2 numbers");
  doc["balls"][0]["position"] = {0.0, 0.0, 0.0};
  expect_invalid(doc, "balls[0].position", "2 numbers");
  doc["balls"][0]["position"] = {0.0, "1"};
  expect_invalid(doc, "balls[0].position[1]", "expected a number");
  doc["balls"][0]["position"] = {{"x", 0.0}};
  expect_invalid(doc, "balls[0].position", "an array");
  doc = base();
  doc["balls"][0]["velocity"] = "fast";
  expect_invalid(doc, "balls[0].velocity", "an array");
  doc = base();
  doc["balls"][0]["spin"] = {0.0, 0.0};
  expect_invalid(doc, "balls[0].spin", "3 numbers");
  doc = base();
  doc["balls"][0]["id"] = 7;
  expect_invalid(doc, "balls[0].id", "expected a string");
  doc["balls"][0]["id"] = "";
  expect_invalid(doc, "balls[0].id", "empty");
  doc = base();
  doc["balls"] = {{"a", 1}};
  expect_invalid(doc, "balls", "an array");
  doc = base();
  doc["balls"][1] = 3;
  expect_invalid(doc, "balls[1]", "an object");
  doc = base();
  doc["physics"]["model"] = 1;
  expect_invalid(doc, "physics.model", "a string");
  doc = base();
  doc["physics"] = "ideal";
  expect_invalid(doc, "physics", "an object");
  doc = base();
  doc["table"] = json::array();
  expect_invalid(doc, "table", "an object");
  doc = base();
  doc["physics"]["gravity"] = "9.81";
  expect_invalid(doc, "physics.gravity", "a number");
  doc = base();
  doc["until"] = 5.0;
  expect_invalid(doc, "until", "\"rest\"");
  doc["until"] = "forever";
  expect_invalid(doc, "until", "forever");
  doc = base();
  doc["samples"] = 0.1;
  expect_invalid(doc, "samples", "an object");
  doc = base();
  doc["pair_restitution"] = {{{"balls", {"a", 2}}, {"restitution", 0.5}}};
  expect_invalid(doc, "pair_restitution[0].balls[1]", "a ball id");
  doc["pair_restitution"] = {{{"balls", {"a"}}, {"restitution", 0.5}}};
  expect_invalid(doc, "pair_restitution[0].balls", "2 ball ids");
}

TEST(ScenarioInvalid, NotJsonOrNotAnObject) {
  auto e = read_error_text("{\"physics\": {\"model\": \"ideal\"},\n  \"table\": ");
  EXPECT_EQ(e.path, "(document)");
  EXPECT_NE(e.reason.find("line 2"), std::string::npos) << e.reason;
  EXPECT_EQ(read_error_text("").path, "(document)");
  EXPECT_EQ(read_error_text("[]").path, "(document)");
  EXPECT_EQ(read_error_text("42").path, "(document)");
  EXPECT_EQ(read_error_text("{} {}").path, "(document)");
  EXPECT_EQ(read_error_text("{\"a\": 1,}").path, "(document)");
  EXPECT_EQ(read_error_text(std::string("{\"a\": \"\xff\"}")).path, "(document)");
}

TEST(ScenarioInvalid, DeepNestingDoesNotCrash) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(read_error_text(deep).path, "(document)");
  json doc = base();
  std::string text = doc.dump();
  text.insert(text.size() - 1, ",\"extra\":" + deep);
  EXPECT_TRUE(std::holds_alternative<bs::Scenario>(bs::read_scenario(text)));
  // A repeated key at the bottom of it all is still found and named.
  const std::string deep_dup = "{\"a\":" + std::string(50000, '[') + "{\"k\":1,\"k\":2}" +
                               std::string(50000, ']') + "}";
  const auto e = read_error_text(deep_dup);
  EXPECT_EQ(e.reason, "duplicate key");
  EXPECT_EQ(e.path.size(), std::string("a").size() + 50000 * 3 + 2);
}

TEST(ScenarioInvalid, DuplicateKeys) {
  auto e = read_error_text(R"({"physics": {"model": "ideal"}, "physics": {"model": "friction"}})");
  EXPECT_EQ(e.path, "physics");
  EXPECT_EQ(e.reason, "duplicate key");
  e = read_error_text(R"({"physics": {"model": "ideal"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [1, 1]},
    "balls": [{"id": "a", "position": [0.5, 0.5]},
              {"id": "b", "position": [0.2, 0.2], "radius": 0.1, "radius": 0.01}],
    "until": {"time": 1}})");
  EXPECT_EQ(e.path, "balls[1].radius");
}

TEST(ScenarioInvalid, Models) {
  json doc = base();
  doc["physics"]["model"] = "quantum";
  expect_invalid(doc, "physics.model", "unknown model");
  doc["physics"]["model"] = "Ideal";
  expect_invalid(doc, "physics.model", "unknown model");
}

TEST(ScenarioInvalid, RacksAndShapes) {
  // The pool model, pool tables and racks are supported (test_pool_io.cpp);
  // so are the snooker table (test_snooker_table.cpp) and the carom table
  // (test_carom_table.cpp). A rack is valid, but only on a table of its game.
  json doc = base();
  doc.erase("balls");
  doc["rack"] = {{"game", "eight_ball"}, {"seed", 1}};
  expect_invalid(doc, "rack", "a rack needs a pool table");

  doc = base();
  doc["table"]["shape"] = "hexagon";
  expect_invalid(doc, "table.shape", "unknown shape");
}

TEST(ScenarioInvalid, PoolOnlyFeaturesInOtherModels) {
  json doc = base();
  doc["balls"][0]["spin"] = {0.0, 0.0, 10.0};
  expect_invalid(doc, "balls[0].spin", "spin needs the pool model");
  doc = base();
  doc["cue"] = {{"ball", "a"}, {"speed", 3.0}};
  expect_invalid(doc, "cue", "pool model");
}

TEST(ScenarioInvalid, RestThatNeverComes) {
  json doc = base();
  doc["until"] = "rest";
  expect_invalid(doc, "until", "ball 'a' moves");
  doc["physics"] = {{"model", "friction"}, {"deceleration", 0.0}};
  expect_invalid(doc, "until", "deceleration is 0");
  doc.erase("until");  // the default is "rest" too
  expect_invalid(doc, "until", "no \"until\" given");
  doc["physics"] = {{"model", "friction"}, {"deceleration", 0.0}};
  doc["balls"][0]["velocity"] = {0.0, 0.0};
  read_ok(doc);  // nothing moves: at rest from the start
}

TEST(ScenarioInvalid, TimesAndSamples) {
  json doc = base();
  doc["until"]["time"] = 0.0;
  expect_invalid(doc, "until.time", "positive");
  doc["until"]["time"] = -1.0;
  expect_invalid(doc, "until.time", "positive");
  doc = base();
  doc["samples"] = {{"dt", 0.0}};
  expect_invalid(doc, "samples.dt", "positive");
  doc["samples"] = {{"dt", -0.1}};
  expect_invalid(doc, "samples.dt", "positive");
  doc["samples"] = {{"dt", 1e-7}};  // 2 / 1e-7 = 2e7 samples
  expect_invalid(doc, "samples.dt", "10,000,000");
  doc["samples"] = {{"dt", 1e-6}};  // 2e6: fine
  read_ok(doc);
}

TEST(ScenarioInvalid, MaxEvents) {
  json doc = base();
  doc["max_events"] = 0;
  expect_invalid(doc, "max_events", "positive integer");
  doc["max_events"] = -3;
  expect_invalid(doc, "max_events", "positive integer");
  doc["max_events"] = 2.5;
  expect_invalid(doc, "max_events", "positive integer");
  doc["max_events"] = "10";
  expect_invalid(doc, "max_events", "positive integer");
  doc["max_events"] = 1e30;
  expect_invalid(doc, "max_events", "positive integer");
}

TEST(ScenarioInvalid, PhysicsRanges) {
  json doc = base();
  doc["physics"]["gravity"] = -9.81;
  expect_invalid(doc, "physics.gravity", ">= 0");
  doc = base();
  doc["physics"]["deceleration"] = -1;
  expect_invalid(doc, "physics.deceleration", ">= 0");
  doc = base();
  doc["physics"]["collapse_speed"] = 0.0;
  expect_invalid(doc, "physics.collapse_speed", "positive");
  doc = base();
  doc["physics"]["ball_ball_friction"] = -0.1;
  expect_invalid(doc, "physics.ball_ball_friction", ">= 0");
}

TEST(ScenarioInvalid, RectangleBounds) {
  json doc = base();
  doc["table"]["max"] = {-1.0, 1.0};
  expect_invalid(doc, "table.max", "greater than");
  doc["table"]["max"] = {1.0, -0.5};
  expect_invalid(doc, "table.max", "greater than");
}

TEST(ScenarioInvalid, PairRestitution) {
  json doc = base();
  doc["pair_restitution"] = {{{"balls", {"a", "z"}}, {"restitution", 0.5}}};
  expect_invalid(doc, "pair_restitution[0].balls[1]", "'z'");
  doc["pair_restitution"] = {{{"balls", {"a", "a"}}, {"restitution", 0.5}}};
  expect_invalid(doc, "pair_restitution[0].balls", "differ");
  doc["pair_restitution"] = {{{"balls", {"a", "b"}}, {"restitution", 0.5}},
                             {{"balls", {"b", "a"}}, {"restitution", 0.7}}};
  expect_invalid(doc, "pair_restitution[1].balls", "already listed at pair_restitution[0]");
  doc["pair_restitution"] = {{"balls", {"a", "b"}}};
  expect_invalid(doc, "pair_restitution", "an array");
}

// --- validate() on scenarios built in code ---------------------------

bs::Scenario code_scenario() {
  bs::Scenario s;
  s.physics.model = bs::Model::ideal;
  s.table = bs::make_rectangle({0.0, 0.0}, {2.0, 1.0});
  s.balls = {{"a", 0.03, 0.17, 1.0}, {"b", 0.03, 0.17, 1.0}};
  s.start.resize(2);
  s.start[0].position = {0.5, 0.5};
  s.start[1].position = {1.5, 0.5};
  s.until.rest = false;
  s.until.time = 1.0;
  return s;
}

TEST(Validate, AcceptsAGoodScenario) { EXPECT_FALSE(bs::validate(code_scenario())); }

TEST(Validate, RejectsWhatAFileCannotSay) {
  auto s = code_scenario();
  s.balls[1].radius = std::numeric_limits<double>::quiet_NaN();
  auto e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "balls[1].radius");

  s = code_scenario();
  s.start[0].position.x = std::numeric_limits<double>::infinity();
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "balls[0].position");

  s = code_scenario();
  s.balls[0].mass = std::numeric_limits<double>::infinity();
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "balls[0].mass");

  s = code_scenario();
  s.balls[1].id = "a";
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "balls[1].id");

  s = code_scenario();
  s.start.pop_back();
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "balls");

  s = code_scenario();
  s.pair_restitution = {{0, 5, 0.5}};
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "pair_restitution[0].balls");

  s = code_scenario();
  s.pair_restitution = {{0, 1, 0.5}, {1, 0, 0.5}};
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "pair_restitution");

  s = code_scenario();
  s.physics.collapse_speed = 0.0;
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "physics.collapse_speed");

  s = code_scenario();
  s.sample_dt = -1.0;
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "samples.dt");
}

/// A scenario built in code is refused a run to rest that never ends,
/// with the reader's words (tests/test_pool_io.cpp reads the same from
/// files).
TEST(Validate, RefusesARunToRestThatNeverEnds) {
  auto s = code_scenario();
  s.start[0].velocity = {1.0, 0.0};
  s.until.rest = true;
  auto e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "until");
  EXPECT_EQ(e->reason,
            "\"rest\" never comes: nothing slows a ball in the ideal model and ball 'a' "
            "moves; give {\"time\": T}");
  EXPECT_EQ(bs::check_run_ends(s)->reason, e->reason);

  // The friction model stops it, given a deceleration.
  s.physics = bs::default_physics(bs::Model::friction);
  EXPECT_FALSE(bs::validate(s));
  s.physics.deceleration = 0.0;
  e = bs::validate(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->path, "until");
  EXPECT_NE(e->reason.find("physics.deceleration is 0 and ball 'a' moves"), std::string::npos)
      << e->reason;

  // The pool model: a cue strike with side english and no spinning friction.
  s.physics = bs::default_physics(bs::Model::pool);
  s.start[0].velocity = {};
  s.cue = bs::CueSpec{};
  s.cue->ball = 0;
  s.cue->strike.speed = 1.0;
  s.cue->strike.a = 0.2;
  EXPECT_FALSE(bs::check_run_ends(s));
  s.physics.spinning_friction = 0.0;
  e = bs::check_run_ends(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->reason,
            "\"rest\" never comes: physics.spinning_friction is 0 and the cue strike's side "
            "english (cue.a) spins ball 'a' about the vertical; give {\"time\": T}");

  // A run to a time always ends.
  s.until.rest = false;
  EXPECT_FALSE(bs::check_run_ends(s));
}

/// A file without "until" is told that "rest" is the default.
TEST(ReadScenario, SaysRestIsTheDefaultWhenUntilIsMissing) {
  json doc = {{"physics", {{"model", "friction"}, {"deceleration", 0.0}}},
              {"table", {{"shape", "rectangle"}, {"min", {0, 0}}, {"max", {2, 1}}}},
              {"balls", {{{"id", "a"}, {"position", {0.5, 0.5}}, {"velocity", {1, 0}}}}}};
  auto read = bs::read_scenario(doc.dump());
  ASSERT_TRUE(std::holds_alternative<bs::ScenarioError>(read));
  const auto& e = std::get<bs::ScenarioError>(read);
  EXPECT_EQ(e.path, "until");
  EXPECT_EQ(e.reason,
            "no \"until\" given and the default \"rest\" never comes: physics.deceleration is "
            "0 and ball 'a' moves; give {\"time\": T} or a positive deceleration");
}

/// 10,000 balls: the overlap check must not compare every pair.
bs::Scenario many_balls(bool column) {
  bs::Scenario s;
  s.physics.model = bs::Model::ideal;
  s.until.rest = false;
  s.until.time = 1.0;
  const double r = 0.01;
  const double gap = 2 * r;  // touching neighbours: the hardest case
  if (column) {
    s.table = bs::make_rectangle({-1.0, -1.0}, {1.0, 10000 * gap + 1.0});
  } else {
    s.table = bs::make_rectangle({-1.0, -1.0}, {100 * gap + 1.0, 100 * gap + 1.0});
  }
  for (int k = 0; k < 10000; ++k) {
    bs::BallSpec spec;
    spec.id = "b" + std::to_string(k);
    spec.radius = r;
    s.balls.push_back(spec);
    bs::BallState st;
    st.position = column ? bs::Vec2{0.0, k * gap} : bs::Vec2{(k % 100) * gap, (k / 100) * gap};
    s.start.push_back(st);
  }
  return s;
}

TEST(Validate, ManyBallsAreCheckedQuickly) {
  for (const bool column : {false, true}) {
    auto s = many_balls(column);
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_FALSE(bs::validate(s));
    // One overlap, far from the start of the list.
    (column ? s.start[9000].position.y : s.start[9000].position.x) += 0.001;
    const auto e = bs::validate(s);
    const auto elapsed = std::chrono::steady_clock::now() - t0;
    ASSERT_TRUE(e);
    EXPECT_EQ(e->path, "balls[9001].position");
    EXPECT_NE(e->reason.find("overlaps ball 'b9000'"), std::string::npos) << e->reason;
    // An all-pairs check takes several times this even when optimised.
    EXPECT_LT(std::chrono::duration<double>(elapsed).count(), 1.0);
  }
}

// --- writing results ---------------------------------------------------

TEST(ResultWrite, EveryEventTypeAndField) {
  auto s = read_ok(json::parse(R"({
    "physics": {"model": "friction"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1]},
    "balls": [{"id": "cue \"ball\"", "position": [0.5, 0.5], "velocity": [1, 0]},
              {"id": "3", "position": [1.5, 0.5], "mass": 0.2}],
    "samples": {"dt": 0.5}
  })"));
  bs::RunResult r;
  r.complete = true;
  bs::Event e;
  e.time = 0.1 + 0.2;  // not a short decimal: must round-trip exactly
  e.type = bs::EventType::ball_ball;
  e.ball = 0;
  e.other = 1;
  r.events.push_back(e);
  e = {};
  e.time = 0.5;
  e.type = bs::EventType::ball_cushion;
  e.ball = 1;
  e.wall = 1;
  r.events.push_back(e);
  e = {};
  e.time = 1.0;
  e.type = bs::EventType::state_change;
  e.ball = 1;
  e.from = bs::MotionState::moving;
  e.to = bs::MotionState::stationary;
  r.events.push_back(e);
  r.final_time = 2.0;
  r.final_balls = s.start;
  r.final_balls[1].velocity = {-0.25, 1e-300};
  bs::Sample smp;
  smp.time = 0.0;
  smp.balls = s.start;
  r.samples.push_back(smp);

  const std::string text = bs::write_result(s, r);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text, bs::write_result(s, r));  // same bytes every time
  const json out = json::parse(text);

  EXPECT_EQ(out["complete"], true);
  ASSERT_EQ(out["events"].size(), 3u);
  EXPECT_EQ(out["events"][0]["time"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(out["events"][0]["type"], "ball_ball");
  EXPECT_EQ(out["events"][0]["balls"], json({"cue \"ball\"", "3"}));
  EXPECT_EQ(out["events"][1]["type"], "ball_cushion");
  EXPECT_EQ(out["events"][1]["balls"], json({"3"}));
  EXPECT_EQ(out["events"][1]["cushion"], "right");
  EXPECT_EQ(out["events"][2]["from"], "moving");
  EXPECT_EQ(out["events"][2]["to"], "stationary");

  EXPECT_EQ(out["final"]["time"].get<double>(), 2.0);
  ASSERT_EQ(out["final"]["balls"].size(), 2u);
  EXPECT_EQ(out["final"]["balls"][0]["id"], "cue \"ball\"");
  EXPECT_EQ(out["final"]["balls"][0]["state"], "moving");
  EXPECT_EQ(out["final"]["balls"][0]["spin"], json({0.0, 0.0, 0.0}));
  EXPECT_EQ(out["final"]["balls"][1]["velocity"][1].get<double>(), 1e-300);
  EXPECT_TRUE(out["final"]["time"].is_number_float());

  ASSERT_EQ(out["samples"].size(), 1u);
  const json& sm = out["samples"][0];
  EXPECT_EQ(sm["time"].get<double>(), 0.0);
  ASSERT_EQ(sm["balls"].size(), 2u);
  const double ke0 = bs::kinetic_energy(s.balls[0], s.start[0]);
  EXPECT_EQ(sm["balls"][0]["kinetic_energy"].get<double>(), ke0);
  EXPECT_EQ(sm["kinetic_energy"].get<double>(), ke0 + bs::kinetic_energy(s.balls[1], s.start[1]));
  EXPECT_DOUBLE_EQ(sm["momentum"][0].get<double>(), 0.17 * 1.0);
  EXPECT_EQ(sm["momentum"][1].get<double>(), 0.0);
}

TEST(ResultWrite, IncompleteEmptyAndBroken) {
  auto s = read_ok(base());
  bs::RunResult r;
  r.complete = false;
  r.final_time = std::numeric_limits<double>::infinity();
  bs::Event e;
  e.ball = 42;  // not a ball of this scenario
  r.events.push_back(e);
  const json out = json::parse(bs::write_result(s, r));
  EXPECT_EQ(out["complete"], false);
  EXPECT_TRUE(out["final"]["time"].is_null());
  EXPECT_TRUE(out["final"]["balls"].empty());
  EXPECT_TRUE(out["events"][0]["balls"][0].is_null());
  EXPECT_FALSE(out.contains("samples"));
}

}  // namespace

}  // namespace test_scenario_io

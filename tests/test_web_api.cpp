// The facade of the browser version (web/api/web_api.hpp, docs/web.md),
// natively: every bad input answered with an error naming its field,
// playback frames that are the simulation's states, games whose records
// replay identical and whose links reproduce them bit for bit, AI games
// that are the games play_game plays with the same seeds, and the
// floating-point <charconv> stand-in of the wasm build
// (web/compat/portable_charconv.hpp) giving libstdc++'s bytes.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "../web/compat/portable_charconv.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/match.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/players.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/version.hpp"
#include "physics_fields.hpp"
#include "web_api.hpp"

namespace test_web_api {

namespace {

using nlohmann::json;
using ojson = nlohmann::ordered_json;
namespace bs = breakshot;

std::string read_example(const std::string& rel) {
  std::ifstream in(std::string(BREAKSHOT_SOURCE_DIR) + "/" + rel, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

json J(const char* text) { return json::parse(text); }

/// The "error" text of a reply ("" if it is not an error).
std::string error_of(const char* text) {
  const json j = J(text);
  return j.is_object() && j.contains("error") ? j["error"].get<std::string>() : std::string();
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

struct GameDeleter {
  void operator()(BsWebGame* g) const { bs_web_game_free(g); }
};
struct PlaybackDeleter {
  void operator()(BsWebPlayback* p) const { bs_web_playback_free(p); }
};
using GamePtr = std::unique_ptr<BsWebGame, GameDeleter>;
using PlaybackPtr = std::unique_ptr<BsWebPlayback, PlaybackDeleter>;

GamePtr new_game(const std::string& config) {
  GamePtr g(bs_web_game_new(config.c_str()));
  EXPECT_NE(g, nullptr) << bs_web_last_error();
  return g;
}

std::string state_of(BsWebGame* g) { return bs_web_game_state(g); }
std::string link_of(BsWebGame* g) { return J(bs_web_game_link(g))["link"].get<std::string>(); }
std::string record_of(BsWebGame* g) { return bs_web_game_record(g); }

/// The action placing the cue ball at (x, y), in the records' form.
std::string place_json(double x, double y) {
  return R"({"type": "place_cue_ball", "position": [)" + json(x).dump() + ", " + json(y).dump() +
         "]}";
}

/// A shot in the records' form: the strike's members, the call (JSON)
/// and the safety flag (JSON).
std::string shoot_json(const std::string& strike, const std::string& call = "null",
                       const std::string& safety = "false") {
  return R"({"type": "shoot", "strike": {)" + strike + R"(}, "call": )" + call +
         R"(, "safety": )" + safety + R"(, "push_out": false})";
}

/// Acts; fails the test on an error reply.
json act(BsWebGame* g, const std::string& action) {
  const std::string reply = bs_web_game_act(g, action.c_str());
  EXPECT_EQ(error_of(reply.c_str()), "") << action;
  return json::parse(reply);
}

/// The AI's decision (for a human seat, the hint of `level`), played as
/// the reply gives it: its exact text, so nothing is re-encoded.
json ai_act(BsWebGame* g, const char* level = nullptr) {
  const std::string reply = bs_web_game_ai_action(g, level);
  const std::string head = "{\"action\":";
  EXPECT_TRUE(starts_with(reply, head)) << reply;
  if (!starts_with(reply, head)) return json();
  return act(g, reply.substr(head.size(), reply.size() - head.size() - 1));
}

/// For a seat that may be human: its own AI, or the hint of `level`.
json step_ai(BsWebGame* g, const char* level_for_humans) {
  const json s = json::parse(state_of(g));
  const bool human = s["players"][s["player"].get<std::size_t>()] == "human";
  return ai_act(g, human ? level_for_humans : nullptr);
}

/// A short game with human shots and AI actions at two levels:
/// human (seat 0) against club (seat 1) with a small budget.
GamePtr short_game(int ai_actions) {
  GamePtr g = new_game(
      R"({"game": "eight_ball", "table": "8ft", "seed": "2026", "breaker": 0,
          "players": ["human", "club"], "ai_budget": 40})");
  act(g.get(), place_json(0.5, 0.6));
  act(g.get(), shoot_json(R"("speed": 9.0, "phi": -1.5, "theta": 0, "a": 0, "b": -0.2)"));
  for (int k = 0; k < ai_actions; ++k) {
    if (json::parse(state_of(g.get()))["phase"] == "game_over") break;
    step_ai(g.get(), "beginner");
  }
  return g;
}

// ---------------------------------------------------------------------------

TEST(WebApi, VersionListsTheLevelsAndTheirBudgets) {
  const json v = J(bs_web_version());
  EXPECT_FALSE(v["version"].get<std::string>().empty());
  EXPECT_EQ(v["levels"].size(), bs::ai_level_names().size());
  for (const std::string& l : bs::ai_level_names()) EXPECT_GE(v["ai_budgets"][l].get<int>(), 1) << l;
}

TEST(WebApi, TheDefaultsAreDefaultPhysicsEveryField) {
  // Every field of PhysicsParams (physics_fields.hpp: a field it does not
  // list fails to compile), by name, and nothing else.
  const json d = J(bs_web_version())["defaults"];
  for (const bs::Model m : {bs::Model::ideal, bs::Model::friction, bs::Model::pool}) {
    const std::string name(bs::to_string(m));
    const bs::PhysicsParams p = bs::default_physics(m);
    const json& got = d["physics"][name];
    ASSERT_TRUE(got.is_object()) << name;
    EXPECT_EQ(got.size(), std::size(physics_fields::kFields)) << name << ": " << got.dump();
    for (const physics_fields::Field& f : physics_fields::kFields) {
      ASSERT_TRUE(got.contains(f.name)) << name << ": no " << f.name;
      const json expected = std::visit(
          [&](auto member) -> json {
            using T = std::remove_cvref_t<decltype(p.*member)>;
            if constexpr (std::is_same_v<T, bs::FrictionCurve>) {
              return {{"a", (p.*member).a}, {"b", (p.*member).b}, {"c", (p.*member).c}};
            } else if constexpr (std::is_same_v<T, bs::Model> ||
                                 std::is_same_v<T, bs::BallBallModel>) {
              return std::string(bs::to_string(p.*member));
            } else {
              return p.*member;
            }
          },
          f.member);
      EXPECT_EQ(got[f.name], expected) << name << "." << f.name;
    }
  }
  EXPECT_EQ(d["pool_cushion_restitution"],
            bs::default_cushion_restitution(bs::CushionParams{}.model));
  EXPECT_EQ(d["physics"]["pool"]["ball_ball_friction_curve"],
            json::parse(R"({"a": 0.016, "b": 0.219, "c": 0.691})"));
  EXPECT_EQ(d["physics"]["pool"]["airborne"], true);
}

TEST(WebApi, SimulateIsTheResultFile) {
  for (const char* f : {"examples/pool/break_9ball.json", "examples/lab/two_balls.json"}) {
    const std::string text = read_example(f);
    const auto parsed = bs::read_scenario(text);
    ASSERT_TRUE(std::holds_alternative<bs::Scenario>(parsed)) << f;
    const bs::Scenario& s = std::get<bs::Scenario>(parsed);
    char* reply = bs_web_simulate(text.c_str());
    EXPECT_EQ(std::string(reply), bs::write_result(s, bs::simulate(s))) << f;
    bs_web_free(reply);
  }
}

TEST(WebApi, ErrorsNameTheField) {
  // simulate: the scenario reader's path, or the document.
  char* r = bs_web_simulate("{\"physics\": {\"model\": \"pool\"}, \"table\": 7}");
  EXPECT_TRUE(starts_with(error_of(r), "table")) << r;
  bs_web_free(r);
  r = bs_web_simulate(nullptr);
  EXPECT_TRUE(starts_with(error_of(r), "scenario:")) << r;
  bs_web_free(r);

  // Game configs.
  const std::pair<const char*, const char*> configs[] = {
      {R"({"players": ["human", "human"]})", "game: missing required field"},
      {R"({"game": "snooker", "players": ["human", "shark"]})", "players[1]: "},
      {R"({"game": "snooker", "players": ["human", "human"], "table": "9ft"})",
       "table: unknown table size \"9ft\" (expected \"12ft\")"},
      {R"({"game": "eight_ball"})", "players: missing required field"},
      {R"({"game": "eight_ball", "players": ["human"]})", "players:"},
      {R"({"game": "eight_ball", "players": ["human", "wizard"]})", "players[1]:"},
      {R"({"game": "eight_ball", "players": ["human", 3]})", "players[1]:"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "seed": "12x"})", "seed:"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "seed": "18446744073709551616"})", "seed:"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "breaker": 2})", "breaker:"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "table": "6ft"})", "table:"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "ai_budget": 0})", "ai_budget:"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "colour": "red"})", "colour: unknown field (known: game, table, seed, breaker, players, ai_budget, physics)"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "seed": "1", "seed": "2"})", "seed: duplicate key"},
      {R"({"game": "eight_ball", "players": ["human", "club"], "table": "6ft"})",
       "table: unknown table size \"6ft\" (expected \"7ft\", \"8ft\" or \"9ft\")"},
      {R"([1, 2])", "(document):"},
      {R"({"game": )", "config: not valid JSON"},
  };
  for (const auto& [config, prefix] : configs) {
    EXPECT_EQ(bs_web_game_new(config), nullptr) << config;
    EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), prefix)) << config << " -> " << bs_web_last_error();
  }
  EXPECT_EQ(bs_web_game_new(nullptr), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "config:"));

  // Actions: the field, or the rules' reason; the game is unchanged.
  GamePtr g = new_game(R"({"game": "eight_ball", "seed": "1", "players": ["human", "beginner"]})");
  const std::string before = state_of(g.get());
  const std::pair<std::string, const char*> actions[] = {
      {shoot_json(R"("speed": "fast", "phi": 0, "theta": 0, "a": 0, "b": 0)"),
       "strike.speed: expected a number, not a string"},
      {shoot_json(R"("phi": 0, "theta": 0, "a": 0, "b": 0)"), "strike.speed: missing required field"},
      {shoot_json(R"("speed": 1, "phi": 0, "theta": 0, "a": 0, "b": 0, "spin": 2)"),
       "strike.spin: unknown field (known: speed, phi, theta, a, b)"},
      {shoot_json(R"("speed": 1, "phi": 0, "theta": 0, "a": 0, "b": 0)", R"({"ball": "x", "pocket": 1})"),
       "call.ball: expected an integer in [-1, 21], not a string"},
      {shoot_json(R"("speed": 1, "phi": 0, "theta": 0, "a": 0, "b": 0)", "null", "1"),
       "safety: expected true or false, not a number"},
      {R"({"type": "shoot", "strike": {"speed": 1, "phi": 0, "theta": 0, "a": 0, "b": 0}})",
       "call: missing required field"},
      {R"({"type": "place_cue_ball", "position": [1]})",
       "position: expected an array of 2 numbers, not an array of 1"},
      {R"({"type": "place_cue_ball", "position": [0.5, "y"]})", "position[1]: expected a number"},
      {R"({"type": "decide", "choice": "maybe"})", "choice: unknown choice \"maybe\" (expected \"shoot\", "},
      {R"({"type": "jump"})", "type: unknown action type \"jump\""},
      {R"({"place": [0.5, 0.6]})", "type: missing required field"},
      {R"([1, 2])", "(document): expected an object, not an array"},
      {R"({"type": "place_cue_ball", "position": [0.5, 0.6], "extra": 1})",
       "extra: unknown field (known: type, position)"},
      {R"({"type": "place_cue_ball", "position": [0.5, 0.6], "position": [0.5, 0.7]})",
       "position: duplicate key"},
      {R"(not json)", "action: not valid JSON"},
  };
  for (const auto& [action, prefix] : actions) {
    const char* reply = bs_web_game_act(g.get(), action.c_str());
    EXPECT_TRUE(starts_with(error_of(reply), prefix)) << action << " -> " << reply;
  }
  // The rules' reasons (check()).
  EXPECT_NE(error_of(bs_web_game_act(g.get(), R"({"type": "decide", "choice": "shoot"})")), "");
  EXPECT_NE(error_of(bs_web_game_act(g.get(), shoot_json(R"("speed": 25, "phi": 0, "theta": 0, "a": 0, "b": 0)").c_str())), "");
  EXPECT_NE(error_of(bs_web_game_act(g.get(), place_json(2.0, 0.6).c_str())), "");
  EXPECT_EQ(state_of(g.get()), before);

  // AI: a human seat needs a level for a hint; unknown levels are named.
  EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), nullptr)), "level:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), "grandmaster")), "level:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), "human")), "level:"));

  // Undo, shot playback, null handles.
  EXPECT_TRUE(starts_with(error_of(bs_web_game_undo_to(g.get(), 1)), "n:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_game_undo_to(g.get(), -1)), "n:"));
  EXPECT_EQ(bs_web_game_shot_playback(g.get(), 0), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "index:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_game_state(nullptr)), "handle:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_playback_frame(nullptr, 0.0)), "handle:"));
  EXPECT_EQ(bs_web_game_shot_playback(nullptr, 0), nullptr);

  // Links.
  for (const char* link : {"", "v2.e30", "v1.!!!", "v1.e30", "v1.W10"}) {
    EXPECT_EQ(bs_web_game_from_link(link), nullptr) << link;
    EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "link")) << link << " -> " << bs_web_last_error();
  }
  EXPECT_EQ(bs_web_game_from_link(nullptr), nullptr);

  // Playbacks.
  EXPECT_EQ(bs_web_playback_new("{\"physics\": 1}"), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "physics")) << bs_web_last_error();
  const std::string scenario = read_example("examples/pool/stop_shot.json");
  PlaybackPtr pb(bs_web_playback_new(scenario.c_str()));
  ASSERT_NE(pb, nullptr) << bs_web_last_error();
  EXPECT_EQ(error_of(bs_web_playback_frame(pb.get(), 0.5)), "");
  EXPECT_TRUE(starts_with(error_of(bs_web_playback_frame(pb.get(), 0.25)), "t:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_playback_frame(pb.get(), std::nan(""))), "t:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_playback_events(pb.get(), -1)), "from:"));
  EXPECT_TRUE(starts_with(error_of(bs_web_playback_events(pb.get(), 100000)), "from:"));
}

TEST(WebApi, ASuccessfulCallClearsTheLastError) {
  const std::string none = R"({"error":"no error"})";
  const std::string scenario = read_example("examples/pool/stop_shot.json");
  // A constructor that fails, then one that succeeds.
  EXPECT_EQ(bs_web_playback_new("{\"physics\": 1}"), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "physics")) << bs_web_last_error();
  PlaybackPtr pb(bs_web_playback_new(scenario.c_str()));
  ASSERT_NE(pb, nullptr);
  EXPECT_EQ(std::string(bs_web_last_error()), none);
  // A call on a handle that fails, then one that succeeds.
  ASSERT_NE(bs_web_playback_frame_data(pb.get(), 0.5), nullptr);
  EXPECT_EQ(bs_web_playback_frame_data(pb.get(), 0.25), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "t:")) << bs_web_last_error();
  ASSERT_NE(bs_web_playback_frame_data(pb.get(), 0.75), nullptr);
  EXPECT_EQ(std::string(bs_web_last_error()), none);
  // A failure, then a success of a call that replies text.
  EXPECT_EQ(bs_web_game_from_link("v2.e30"), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "link")) << bs_web_last_error();
  char* result = bs_web_simulate(scenario.c_str());
  EXPECT_EQ(error_of(result), "");
  bs_web_free(result);
  EXPECT_EQ(std::string(bs_web_last_error()), none);
}

/// A link holding `body`: `prefix` ("v1." by default) and its base64url.
std::string link_of_body(const std::string& body, const std::string& prefix = "v1.") {
  static constexpr char kB64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  std::string enc;
  std::uint32_t acc = 0;
  int bits = 0;
  for (const char c : body) {
    acc = (acc << 8) | static_cast<unsigned char>(c);
    bits += 8;
    while (bits >= 6) {
      bits -= 6;
      enc.push_back(kB64[(acc >> bits) & 63]);
    }
  }
  if (bits > 0) enc.push_back(kB64[(acc << (6 - bits)) & 63]);
  return prefix + enc;
}

/// The JSON body of a link (after its "vN.").
json body_of_link(const std::string& link) {
  static const std::string kB64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  std::string out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (const char c : link.substr(link.find('.') + 1)) {
    acc = (acc << 6) | static_cast<std::uint32_t>(kB64.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xff));
    }
  }
  return json::parse(out);
}

TEST(WebApi, LinksSayTheEngineAndThePhysicsAndV1LinksReadAsLegacy) {
  GamePtr g = short_game(3);
  const std::string link = link_of(g.get());
  ASSERT_TRUE(starts_with(link, "v2.")) << link;
  const json body = body_of_link(link);
  EXPECT_EQ(body["e"], std::string(bs::kVersion));
  EXPECT_EQ(body["ph"], json::parse(R"({"cushion_model":"han_2005","ball_ball_model":"friction",
                                        "ball_ball_friction":{"a":0.016,"b":0.219,"c":0.691},
                                        "airborne":true,"spinning_friction":0.0117})"));
  // The same actions as a link of before (no engine, no physics): played
  // on the legacy physics, which its record and its new link then name.
  const json legacy = json::parse(R"({"cushion_model":"han_2005_v0","ball_ball_model":"friction",
                                      "ball_ball_friction":{"a":0.009951,"b":0.108,"c":1.088}})");
  json old = body;
  old.erase("e");
  old.erase("ph");
  // The break (the cue ball placed and struck): later actions were chosen
  // on the default physics and need not be legal on the legacy one.
  old["a"] = json::array({body["a"][0], body["a"][1]});
  GamePtr h(bs_web_game_from_link(link_of_body(old.dump()).c_str()));
  ASSERT_NE(h, nullptr) << bs_web_last_error();
  EXPECT_EQ(J(record_of(h.get()).c_str())["physics"], legacy);
  EXPECT_EQ(body_of_link(link_of(h.get()))["ph"], legacy);
  // Its v2 link gives the same game again.
  GamePtr h2(bs_web_game_from_link(link_of(h.get()).c_str()));
  ASSERT_NE(h2, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(h2.get()), record_of(h.get()));

  // Another physics is played and kept.
  json other = body;
  other["ph"] = json::parse(R"({"cushion_model":"mathavan_2010","ball_ball_model":"mathavan_2014",
                                "ball_ball_friction":{"a":0.016,"b":0.219,"c":0.691}})");
  other["a"] = json::array();
  GamePtr m(bs_web_game_from_link(link_of_body(other.dump(), "v2.").c_str()));
  ASSERT_NE(m, nullptr) << bs_web_last_error();
  EXPECT_EQ(body_of_link(link_of(m.get()))["ph"], other["ph"]);
  EXPECT_NE(record_of(m.get()).find("\"cushion_model\":\"mathavan_2010\""), std::string::npos);
  // A v2 link without "spinning_friction" (written before it was recorded)
  // was played with breakshot 0.1's, and its record says so by leaving it out.
  EXPECT_EQ(record_of(m.get()).find("spinning_friction"), std::string::npos);
  json measured = other;
  measured["ph"]["spinning_friction"] = 0.0117;
  GamePtr ms(bs_web_game_from_link(link_of_body(measured.dump(), "v2.").c_str()));
  ASSERT_NE(ms, nullptr) << bs_web_last_error();
  EXPECT_EQ(body_of_link(link_of(ms.get()))["ph"], measured["ph"]);

  // Physics this build does not have: refused, naming the link's engine.
  json future = other;
  future["e"] = "0.3.0";
  future["ph"]["cushion_model"] = "cushion_law_of_2099";
  EXPECT_EQ(bs_web_game_from_link(link_of_body(future.dump(), "v2.").c_str()), nullptr);
  const std::string err = error_of(bs_web_last_error());
  EXPECT_TRUE(starts_with(err, "link.ph.cushion_model: unknown cushion model \"cushion_law_of_2099\""))
      << err;
  EXPECT_NE(err.find("made by breakshot 0.3.0"), std::string::npos) << err;
  // A link format of a later version is named.
  EXPECT_EQ(bs_web_game_from_link("v3.e30"), nullptr);
  EXPECT_NE(error_of(bs_web_last_error()).find("not \"v3\""), std::string::npos) << bs_web_last_error();
}

TEST(WebApi, LinkErrorsNameTheActionRefused) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"g":"eight_ball","t":"9ft","s":"1","b":0,"p":["human","human"],"a":[["d","shoot"]]})",
       "link.a[0]: refused:"},
      // Read as strictly as a record: repeated keys, unknown names.
      {R"({"g":"eight_ball","t":"9ft","s":"1","b":0,"b":1,"p":["human","human"],"a":[]})",
       "link.b: duplicate key"},
      {R"({"g":"eight_ball","t":"9ft","s":"1","b":0,"p":["human","human"],"a":[["d","x"],["d","x"]]})",
       "link.a[0][1]: unknown choice \"x\" (expected \"shoot\", "},
      {R"({"g":"snooker","t":"9ft","s":"1","b":0,"p":["human","human"],"a":[]})",
       "link.t: unknown table size \"9ft\" (expected \"12ft\")"},
      {R"({"g":"snooker","t":"12ft","s":"1","b":0,"p":["human","shark"],"a":[]})", "link.p[1]: "},
      {R"({"g":"bowls","t":"9ft","s":"1","b":0,"p":["human","human"],"a":[]})",
       "link.g: unknown game \"bowls\" (expected \"eight_ball\", \"nine_ball\", \"ten_ball\", "
       "\"snooker\" or \"three_cushion\")"},
      {R"({"g":"eight_ball","t":"9ft","s":"1","b":0,"p":["human","human"],"c":{"target":5},"a":[]})",
       "link.c: unknown field"},
      {R"({"g":"three_cushion","t":"9ft","s":"1","b":0,"p":["human","human"],"a":[]})",
       "link.t: unknown table size \"9ft\" (expected \"10ft\")"},
      {R"({"g":"three_cushion","t":"10ft","s":"1","b":0,"p":["human","shark"],"a":[]})",
       "link.p[1]: \"human\" or a player of three_cushion ("},
      {R"({"g":"eight_ball","t":"9ft","s":"x1","b":0,"p":["human","human"],"a":[]})",
       "link.s: expected a seed: a decimal integer in [0, 2^64), not \"x1\""},
  };
  for (const auto& [body, prefix] : cases) {
    EXPECT_EQ(bs_web_game_from_link(link_of_body(body).c_str()), nullptr) << body;
    EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), prefix)) << body << " -> " << bs_web_last_error();
  }
}

TEST(WebApi, PlaybackFramesAreTheSimulationsStates) {
  for (const char* file : {"examples/pool/break_8ball.json", "examples/lab/newtons_cradle.json",
                           "examples/lab/l_shaped_friction.json"}) {
    const std::string text = read_example(file);
    const auto parsed = bs::read_scenario(text);
    ASSERT_TRUE(std::holds_alternative<bs::Scenario>(parsed)) << file;
    const bs::Scenario& s = std::get<bs::Scenario>(parsed);
    const bs::RunResult result = bs::simulate(s);

    PlaybackPtr pb(bs_web_playback_new(text.c_str()));
    ASSERT_NE(pb, nullptr) << bs_web_last_error();
    bs::Simulation sim(s);
    double end = result.final_time;
    for (int k = 0; k < 30; ++k) {
      const double t = std::fmin(static_cast<double>(k) * 0.2, end);
      sim.advance_to(t);
      const json f = J(bs_web_playback_frame(pb.get(), t));
      ASSERT_EQ(f["balls"].size(), s.balls.size()) << file;
      EXPECT_EQ(f["t"].get<double>(), sim.time());
      EXPECT_EQ(f["events"].get<std::size_t>(), sim.events().size());
      EXPECT_EQ(f["at_rest"].get<bool>(), sim.at_rest());
      double energy = 0.0;
      for (std::size_t i = 0; i < s.balls.size(); ++i) {
        const bs::BallState b = sim.ball(i);
        const json& fb = f["balls"][i];
        EXPECT_EQ(fb[0].get<double>(), b.position.x) << file << " t=" << t << " ball " << i;
        EXPECT_EQ(fb[1].get<double>(), b.position.y);
        EXPECT_EQ(fb[2].get<int>(), b.state == bs::MotionState::pocketed ? 0 : 1);
        EXPECT_EQ(fb[3].get<double>(), b.velocity.x);
        EXPECT_EQ(fb[4].get<double>(), b.velocity.y);
        EXPECT_EQ(fb[5].get<double>(), bs::kinetic_energy(s.balls[i], b));
        EXPECT_EQ(fb[6].get<double>(), bs::momentum(s.balls[i], b).x);
        EXPECT_EQ(fb[7].get<double>(), bs::momentum(s.balls[i], b).y);
        energy += bs::kinetic_energy(s.balls[i], b);
      }
      EXPECT_EQ(f["energy"].get<double>(), energy);
    }
    // The last frame: simulate()'s final state and events.
    const json last = J(bs_web_playback_frame(pb.get(), end));
    EXPECT_EQ(last["t"].get<double>(), result.final_time) << file;
    EXPECT_EQ(last["events"].get<std::size_t>(), result.events.size());
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      EXPECT_EQ(last["balls"][i][0].get<double>(), result.final_balls[i].position.x) << file << " ball " << i;
      EXPECT_EQ(last["balls"][i][1].get<double>(), result.final_balls[i].position.y);
      EXPECT_EQ(last["balls"][i][3].get<double>(), result.final_balls[i].velocity.x);
    }
    const std::string ev_text = bs_web_playback_events(pb.get(), 0);
    // The events are the result file's, byte for byte: one encoding.
    {
      const std::string res = bs::write_result(s, result);
      std::string want = "{\"from\":0,\"events\":[";
      std::size_t at = res.find("\"events\": [");
      ASSERT_NE(at, std::string::npos);
      for (std::size_t k = 0; k < result.events.size(); ++k) {
        const std::size_t open = res.find("\n    {", at) + 5;
        const std::size_t close = res.find('\n', open);
        std::string line = res.substr(open, close - open);
        if (line.back() == ',') line.pop_back();
        want += (k == 0 ? "" : ",") + line;
        at = close;
      }
      want += "]}";
      EXPECT_EQ(ev_text, want) << file;
    }
    const json ev = J(ev_text.c_str());
    ASSERT_EQ(ev["events"].size(), result.events.size());
    for (std::size_t k = 0; k < result.events.size(); ++k) {
      EXPECT_EQ(ev["events"][k]["time"].get<double>(), result.events[k].time);
      EXPECT_EQ(ev["events"][k]["type"].get<std::string>(), bs::to_string(result.events[k].type));
    }
    // A run that ends at a time (the lab) stops there, as simulate() does.
    if (!s.until.rest) {
      const json after = J(bs_web_playback_frame(pb.get(), end + 100.0));
      EXPECT_EQ(after["t"].get<double>(), result.final_time);
    }
  }
}

/// Whether two doubles have the same bits (-0 is not +0).
bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

/// Checks that bs_web_playback_frame_data's doubles `d` are the numbers of the
/// JSON frame `f`, bit for bit.
void expect_frame_data_is(const double* d, const json& f, const std::string& what) {
  ASSERT_NE(d, nullptr) << what << ": " << bs_web_last_error();
  ASSERT_EQ(error_of(f.dump().c_str()), "") << what;
  EXPECT_TRUE(same_bits(d[0], f["t"].get<double>())) << what;
  EXPECT_EQ(d[1], static_cast<double>(f["events"].get<std::size_t>())) << what;
  EXPECT_EQ(d[2], f["at_rest"].get<bool>() ? 1.0 : 0.0) << what;
  EXPECT_EQ(d[3], f["complete"].get<bool>() ? 1.0 : 0.0) << what;
  EXPECT_TRUE(same_bits(d[4], f["energy"].get<double>())) << what;
  EXPECT_TRUE(same_bits(d[5], f["momentum"][0].get<double>())) << what;
  EXPECT_TRUE(same_bits(d[6], f["momentum"][1].get<double>())) << what;
  ASSERT_EQ(d[7], static_cast<double>(f["balls"].size())) << what;
  const std::size_t n = f["balls"].size();
  // The flight block's flag: 1 exactly when the JSON's balls carry z and
  // their place (10 numbers, else 8).
  const double flag = d[8 + 8 * n];
  ASSERT_TRUE(flag == 0.0 || flag == 1.0) << what;
  for (std::size_t i = 0; i < n; ++i) {
    const json& b = f["balls"][i];
    const double* db = d + 8 + 8 * i;
    ASSERT_EQ(b.size(), flag != 0.0 ? 10U : 8U) << what;
    EXPECT_EQ(db[2], static_cast<double>(b[2].get<int>())) << what << " ball " << i;
    for (const std::size_t k : {0U, 1U, 3U, 4U, 5U, 6U, 7U}) {
      EXPECT_TRUE(same_bits(db[k], b[k].get<double>())) << what << " ball " << i << " [" << k << "]";
    }
    const double* fl = d + 8 + 8 * n + 1 + 2 * i;
    if (flag != 0.0) {
      EXPECT_TRUE(same_bits(fl[0], b[8].get<double>())) << what << " ball " << i << " z";
      EXPECT_EQ(fl[1], static_cast<double>(b[9].get<int>())) << what << " ball " << i << " place";
    } else {
      // Balls on the cloth or in pockets: no height.
      EXPECT_EQ(fl[0], 0.0) << what << " ball " << i;
      EXPECT_EQ(fl[1], 0.0) << what << " ball " << i;
    }
  }
}

TEST(WebApi, FrameDataIsTheJsonFramesNumbers) {
  // The 8-ball break, the 1000-ball gas, and a run that max_events stops
  // (complete turns false): two playbacks, one asked for doubles and one
  // for JSON at the same times, and the same playback asked for both.
  json capped = json::parse(read_example("examples/lab/newtons_cradle.json"));
  capped["max_events"] = 3;
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"break_8ball", read_example("examples/pool/break_8ball.json")},
      {"gas_1000", read_example("examples/lab/gas_1000.json")},
      {"newtons_cradle, max_events 3", capped.dump()}};
  for (const auto& [name, text] : runs) {
    PlaybackPtr a(bs_web_playback_new(text.c_str()));
    PlaybackPtr b(bs_web_playback_new(text.c_str()));
    ASSERT_NE(a, nullptr) << bs_web_last_error();
    ASSERT_NE(b, nullptr) << bs_web_last_error();
    bool saw_incomplete = false;
    for (const double t : {0.0, 0.0, 0.01, 1.0 / 60.0, 0.25, 0.5, 1.0, 1.5, 2.0, 2.75, 4.0, 10.0, 1000.0}) {
      const std::string what = name + " t=" + std::to_string(t);
      const double* d = bs_web_playback_frame_data(a.get(), t);
      expect_frame_data_is(d, J(bs_web_playback_frame(b.get(), t)), what + " (two playbacks)");
      if (d != nullptr && d[3] == 0.0) saw_incomplete = true;
      // The same handle at the same t: the JSON is written from the same doubles.
      const json f = J(bs_web_playback_frame(a.get(), t));
      expect_frame_data_is(bs_web_playback_frame_data(a.get(), t), f, what + " (one playback)");
    }
    EXPECT_EQ(saw_incomplete, name.find("max_events") != std::string::npos) << name;
  }
}

TEST(WebApi, PlaybackSpinsAreTheResultFilesSpins) {
  // The 8-ball break sampled every 0.25 s by simulate, and a playback's
  // spins after frames at the same times.
  json s = json::parse(read_example("examples/pool/break_8ball.json"));
  s["samples"] = {{"dt", 0.25}};
  char* out = bs_web_simulate(s.dump().c_str());
  ASSERT_NE(out, nullptr);
  const json result = json::parse(out);
  bs_web_free(out);
  ASSERT_TRUE(result.contains("samples")) << result.dump().substr(0, 200);
  PlaybackPtr pb(bs_web_playback_new(s.dump().c_str()));
  ASSERT_NE(pb, nullptr) << bs_web_last_error();
  EXPECT_NE(bs_web_playback_spins(pb.get()), nullptr);  // before any frame: the start's
  EXPECT_EQ(bs_web_playback_spins(nullptr), nullptr);
  int compared = 0;
  double largest = 0.0;
  for (const json& sample : result["samples"]) {
    const double t = sample["time"].get<double>();
    if (t > 3.0) break;
    ASSERT_NE(bs_web_playback_frame_data(pb.get(), t), nullptr) << bs_web_last_error();
    const double* w = bs_web_playback_spins(pb.get());
    ASSERT_NE(w, nullptr) << bs_web_last_error();
    const json& balls = sample["balls"];
    for (std::size_t i = 0; i < balls.size(); ++i) {
      for (std::size_t k = 0; k < 3; ++k) {
        const double want = balls[i]["spin"][k].get<double>();
        EXPECT_NEAR(w[3 * i + k], want, 1e-9 * (1.0 + std::abs(want))) << "t=" << t << " ball " << i << " axis " << k;
        largest = std::max(largest, std::abs(want));
      }
    }
    ++compared;
  }
  EXPECT_GE(compared, 8);
  EXPECT_GT(largest, 10.0);  // the balls spun
}

/// A game of 8-ball on a 9 ft table between two humans whose physics lets
/// balls leave the cloth (or not), with the cue ball placed at (0.6,
/// 0.635) and shot straight up the table at 3 m/s with the cue raised 45
/// degrees: a jump shot when the physics allows it.
GamePtr jump_game(bool airborne) {
  GamePtr g = new_game(std::string(R"({"game": "eight_ball", "table": "9ft", "seed": "7",
      "players": ["human", "human"], "physics": {"airborne": )") +
                       (airborne ? "true" : "false") + "}}");
  if (g == nullptr) return g;
  act(g.get(), place_json(0.6, 0.635));
  act(g.get(), shoot_json(R"("speed": 3.0, "phi": 0, "theta": 45, "a": 0, "b": 0)"));
  return g;
}

TEST(WebApi, JumpShotFramesCarryTheCueBallsFlight) {
  GamePtr g = jump_game(true);
  ASSERT_NE(g, nullptr);
  // The game's physics is in its record and its link.
  EXPECT_TRUE(J(record_of(g.get()).c_str())["physics"]["airborne"].get<bool>());
  GamePtr again(bs_web_game_from_link(link_of(g.get()).c_str()));
  ASSERT_NE(again, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(again.get()), record_of(g.get()));

  PlaybackPtr pb(bs_web_game_shot_playback(g.get(), 1));
  PlaybackPtr twin(bs_web_game_shot_playback(g.get(), 1));
  ASSERT_NE(pb, nullptr) << bs_web_last_error();
  // Frames every 5 ms over the first half second: the cue ball (index 0
  // of the shot's balls, the cue ball first) rises and falls.
  constexpr double kDt = 0.005;
  std::vector<double> z;
  std::vector<int> place;
  double top = 0.0;
  for (int k = 0; k <= 100; ++k) {
    const double t = kDt * k;
    const json f = J(bs_web_playback_frame(pb.get(), t));
    ASSERT_EQ(error_of(f.dump().c_str()), "") << t;
    expect_frame_data_is(bs_web_playback_frame_data(twin.get(), t), f, "jump t=" + std::to_string(t));
    const json& cue = f["balls"][0];
    if (cue.size() == 10) {
      z.push_back(cue[8].get<double>());
      place.push_back(cue[9].get<int>());
      EXPECT_EQ(cue[2].get<int>(), 1) << "in flight is on the table (in play) at t=" << t;
    } else {
      z.push_back(0.0);
      place.push_back(0);
    }
    top = std::max(top, z.back());
  }
  // A flight: at least a few frames in the air, and a height of centimetres
  // (here only its order).
  int in_air = 0;
  for (const int p : place) in_air += p == 1 ? 1 : 0;
  EXPECT_GE(in_air, 10);
  EXPECT_GT(top, 0.02);
  EXPECT_LT(top, 1.0);
  // In flight the height is a parabola under gravity: the second difference
  // of z at a step dt is -g dt^2 (g = 9.81 m/s^2, the pool default), as for
  // any projectile without drag, between events (a bounce on the slate
  // starts another parabola).
  std::vector<double> events;
  const json reply = J(bs_web_playback_events(pb.get(), 0));
  for (const json& e : reply["events"]) {
    events.push_back(e["time"].get<double>());
  }
  const auto event_between = [&](double t0, double t1) {
    return std::any_of(events.begin(), events.end(), [&](double t) { return t > t0 && t < t1; });
  };
  int parabolas = 0;
  for (std::size_t k = 0; k + 2 < z.size(); ++k) {
    if (place[k] != 1 || place[k + 1] != 1 || place[k + 2] != 1) continue;
    if (event_between(kDt * static_cast<double>(k), kDt * static_cast<double>(k + 2))) continue;
    const double second = z[k] - 2.0 * z[k + 1] + z[k + 2];
    EXPECT_NEAR(second, -9.81 * kDt * kDt, 1e-9) << "k=" << k;
    ++parabolas;
  }
  EXPECT_GE(parabolas, 5);
}

TEST(WebApi, JumpShotOnTheClothKeepsEightNumbersPerBall) {
  // The same strike where balls stay on the cloth ("airborne": false): no
  // frame carries heights. A game config without "physics" has
  // GamePhysics's default, on which the ball flies.
  for (const bool explicit_off : {true, false}) {
    GamePtr g = explicit_off ? jump_game(false)
                             : new_game(R"({"game": "eight_ball", "table": "9ft", "seed": "7",
                                           "players": ["human", "human"]})");
    ASSERT_NE(g, nullptr);
    if (!explicit_off) {
      act(g.get(), place_json(0.6, 0.635));
      act(g.get(), shoot_json(R"("speed": 3.0, "phi": 0, "theta": 45, "a": 0, "b": 0)"));
    }
    EXPECT_EQ(J(record_of(g.get()).c_str())["physics"].contains("airborne"), !explicit_off);
    PlaybackPtr pb(bs_web_game_shot_playback(g.get(), 1));
    ASSERT_NE(pb, nullptr) << bs_web_last_error();
    std::size_t widest = 0;
    for (int k = 0; k <= 100; ++k) {
      const json f = J(bs_web_playback_frame(pb.get(), 0.005 * k));
      for (const json& b : f["balls"]) widest = std::max(widest, b.size());
    }
    EXPECT_EQ(widest, explicit_off ? 8U : 10U);
  }
  // A physics option the facade does not know, or not a bool, is refused.
  EXPECT_EQ(bs_web_game_new(R"({"game": "eight_ball", "players": ["human", "human"],
                            "physics": {"airborne": 1}})"),
            nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "physics.airborne:")) << bs_web_last_error();
  EXPECT_EQ(bs_web_game_new(R"({"game": "eight_ball", "players": ["human", "human"],
                            "physics": {"gravity": 1}})"),
            nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "physics")) << bs_web_last_error();
}

TEST(WebApi, FrameDataErrorsAreThoseOfTheJsonFrame) {
  const std::string scenario = read_example("examples/pool/break_8ball.json");
  PlaybackPtr pb(bs_web_playback_new(scenario.c_str()));
  ASSERT_NE(pb, nullptr) << bs_web_last_error();
  const double* d = bs_web_playback_frame_data(pb.get(), 0.5);
  ASSERT_NE(d, nullptr) << bs_web_last_error();
  const std::vector<double> before(d, d + 8 + 8 * static_cast<std::size_t>(d[7]));
  // Time going backwards: NULL, bs_web_last_error as the JSON frame's error,
  // and the playback unchanged.
  EXPECT_EQ(bs_web_playback_frame_data(pb.get(), 0.25), nullptr);
  const std::string err = bs_web_last_error();
  EXPECT_TRUE(starts_with(error_of(err.c_str()), "t: the frame time goes backwards")) << err;
  EXPECT_EQ(std::string(bs_web_playback_frame(pb.get(), 0.25)), err);
  EXPECT_EQ(bs_web_playback_frame_data(pb.get(), std::nan("")), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "t:")) << bs_web_last_error();
  EXPECT_EQ(bs_web_playback_frame_data(pb.get(), std::numeric_limits<double>::infinity()), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "t:")) << bs_web_last_error();
  d = bs_web_playback_frame_data(pb.get(), 0.5);
  ASSERT_NE(d, nullptr) << bs_web_last_error();
  for (std::size_t k = 0; k < before.size(); ++k) EXPECT_TRUE(same_bits(d[k], before[k])) << k;
  // A null handle.
  EXPECT_EQ(bs_web_playback_frame_data(nullptr, 0.0), nullptr);
  EXPECT_EQ(error_of(bs_web_last_error()), "handle: a null handle");
  // The buffer belongs to the playback: a later frame overwrites it.
  const double* later = bs_web_playback_frame_data(pb.get(), 1.0);
  ASSERT_NE(later, nullptr) << bs_web_last_error();
  EXPECT_EQ(later[0], 1.0);
}

TEST(WebApi, ShotPlaybackIsTheShotAsTheRulesPlayedIt) {
  GamePtr g = short_game(6);
  const bs::GameRecord rec = std::get<bs::GameRecord>(bs::read_record(record_of(g.get())));
  int shots = 0;
  for (std::size_t i = 0; i < rec.actions.size(); ++i) {
    const bs::RecordedAction& ra = rec.actions[i];
    PlaybackPtr pb(bs_web_game_shot_playback(g.get(), static_cast<int>(i)));
    if (!std::holds_alternative<bs::Shoot>(ra.action)) {
      EXPECT_EQ(pb, nullptr);
      continue;
    }
    ++shots;
    ASSERT_NE(pb, nullptr) << bs_web_last_error();
    const bs::GameState& before = i == 0 ? rec.start : rec.actions[i - 1].after;
    std::vector<int> numbers;
    for (std::size_t b = 0; b < before.on_table.size(); ++b) {
      if (before.on_table[b]) numbers.push_back(static_cast<int>(b));
    }
    const json f = J(bs_web_playback_frame(pb.get(), 1000.0));
    ASSERT_TRUE(f["at_rest"].get<bool>());
    ASSERT_EQ(f["balls"].size(), numbers.size());
    for (std::size_t k = 0; k < numbers.size(); ++k) {
      const auto b = static_cast<std::size_t>(numbers[k]);
      const bool spotted = std::count(ra.ruling.spotted.begin(), ra.ruling.spotted.end(), numbers[k]) > 0;
      if (spotted) continue;
      const bool on = f["balls"][k][2].get<int>() == 1;
      EXPECT_EQ(ra.after.on_table[b] != 0, on) << "action " << i << " ball " << b;
      if (on && ra.after.racks == before.racks) {
        EXPECT_EQ(f["balls"][k][0].get<double>(), ra.after.position[b].x) << "action " << i << " ball " << b;
        EXPECT_EQ(f["balls"][k][1].get<double>(), ra.after.position[b].y);
      }
    }
  }
  EXPECT_GE(shots, 3);
}

TEST(WebApi, RecordReplaysIdentical) {
  GamePtr g = short_game(8);
  const std::string text = record_of(g.get());
  const auto parsed = bs::read_record(text);
  ASSERT_TRUE(std::holds_alternative<bs::GameRecord>(parsed))
      << std::get<bs::RecordError>(parsed).path << ": " << std::get<bs::RecordError>(parsed).reason;
  const bs::GameRecord& rec = std::get<bs::GameRecord>(parsed);
  EXPECT_EQ(rec.actions.size(), json::parse(state_of(g.get()))["actions"].get<std::size_t>());
  EXPECT_GE(rec.actions.size(), 8u);
  EXPECT_EQ(rec.players[0], "human");
  EXPECT_EQ(rec.players[1], "club");
  EXPECT_EQ(rec.noise[1], bs::ai_level("club").noise);
  const bs::ReplayReport report = bs::replay(rec);
  EXPECT_TRUE(report.identical) << report.message;
  EXPECT_EQ(report.actions_identical, rec.actions.size());
  EXPECT_EQ(bs::write_record(rec), text);

#ifdef BREAKSHOT_CLI
  // And `breakshot replay` says so (exit status 0).
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "breakshot-web-api-record.json";
  std::ofstream(file, std::ios::binary) << text;
  const std::string cmd = std::string(BREAKSHOT_CLI) + " replay '" + file.string() + "' > /dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  std::filesystem::remove(file);
#endif
}

TEST(WebApi, RepliesUseTheRecordsEncoding) {
  // One JSON per type: an act reply's action, strike, ruling and state
  // are the record's, byte for byte, and the AI's action is that form too.
  GamePtr g = new_game(R"({"game": "nine_ball", "seed": "9", "players": ["human", "club"], "ai_budget": 30})");
  std::vector<std::string> replies;
  replies.push_back(bs_web_game_act(g.get(), place_json(0.4, 0.5).c_str()));
  replies.push_back(bs_web_game_act(g.get(), shoot_json(R"("speed": 8, "phi": 0.01, "theta": 0, "a": 0, "b": 0)").c_str()));
  for (int k = 0; k < 2 && json::parse(state_of(g.get()))["phase"] != "game_over"; ++k) {
    const std::string reply = bs_web_game_ai_action(g.get(), "beginner");
    const json action = json::parse(reply)["action"];
    EXPECT_TRUE(action.contains("type")) << reply;
    replies.push_back(bs_web_game_act(g.get(), action.dump().c_str()));
  }
  const ojson record = ojson::parse(record_of(g.get()));
  ASSERT_EQ(record["actions"].size(), replies.size());
  for (std::size_t i = 0; i < replies.size(); ++i) {
    const ojson reply = ojson::parse(replies[i]);
    const ojson& recorded = record["actions"][i];
    EXPECT_EQ(reply["executed"].dump(), recorded["action"].dump()) << i;
    EXPECT_EQ(reply["ruling"].dump(), recorded["ruling"].dump()) << i;
    EXPECT_EQ(reply.contains("intended"), !recorded["intended"].is_null()) << i;
    if (reply.contains("intended")) {
      EXPECT_EQ(reply["intended"].dump(), recorded["intended"].dump()) << i;
    }
    // The state: the record's, then the seats, the actions and what is legal.
    ojson state = reply["state"];
    EXPECT_EQ(state["players"], ojson::array({"human", "club"})) << i;
    EXPECT_EQ(state["actions"], i + 1) << i;
    EXPECT_TRUE(state["legal"].is_object()) << i;
    for (const char* extra : {"players", "actions", "legal"}) state.erase(extra);
    EXPECT_EQ(state.dump(), recorded["after"].dump()) << i;
  }
  ojson start = ojson::parse(bs_web_game_undo_to(g.get(), 0));
  for (const char* extra : {"players", "actions", "legal"}) start.erase(extra);
  EXPECT_EQ(start.dump(), record["start"].dump());
}

TEST(WebApi, LinkRoundTripReproducesTheGameExactly) {
  GamePtr g = short_game(6);
  // A human shot whose numbers only survive as bits: -0, a subnormal,
  // and digits beyond what a decimal would keep.
  const json s = json::parse(state_of(g.get()));
  if (s["phase"] != "game_over" && s["legal"]["must_place"] == false && s["legal"]["choices"].empty()) {
    act(g.get(), shoot_json(R"("speed": 2.0000000000000004, "phi": -0.0, "theta": 4.9e-324,
                             "a": 0.1, "b": -1e-310)", "null", "true"));
  }
  const std::string link = link_of(g.get());
  ASSERT_TRUE(starts_with(link, "v2."));
  GamePtr h(bs_web_game_from_link(link.c_str()));
  ASSERT_NE(h, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
  EXPECT_EQ(state_of(h.get()), state_of(g.get()));
  EXPECT_EQ(link_of(h.get()), link);
  // The same game goes on the same way.
  for (int k = 0; k < 2; ++k) {
    if (json::parse(state_of(g.get()))["phase"] == "game_over") break;
    EXPECT_EQ(step_ai(g.get(), "beginner").dump(), step_ai(h.get(), "beginner").dump());
  }
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
  // A link inside a page address works too.
  GamePtr u(bs_web_game_from_link(("http://127.0.0.1:8000/#game=" + link + "&shot=2").c_str()));
  ASSERT_NE(u, nullptr) << bs_web_last_error();
}

TEST(WebApi, UndoKeepsTheFirstActions) {
  GamePtr g = short_game(0);
  const std::string link2 = link_of(g.get());
  const std::string state2 = state_of(g.get());
  for (int k = 0; k < 3; ++k) step_ai(g.get(), "beginner");
  const json st = J(bs_web_game_undo_to(g.get(), 2));
  EXPECT_EQ(st.dump(), json::parse(state2).dump());
  EXPECT_EQ(link_of(g.get()), link2);
  EXPECT_EQ(state_of(g.get()), state2);
}

TEST(WebApi, AiGameIsTheGamePlayGamePlays) {
  // Both seats AI: the facade's game is play_game's, action for action,
  // because the seeds are derived the same way.
  const std::uint64_t seed = 4242;
  for (const auto& game :
       {std::string("nine_ball"), std::string("eight_ball"), std::string("ten_ball")}) {
    GamePtr g = new_game(R"({"game": ")" + game + R"(", "table": "7ft", "seed": ")" +
                         std::to_string(seed) +
                         R"(", "breaker": 1, "players": ["amateur", "beginner"], "ai_budget": 30})");
    for (int k = 0; k < 800 && json::parse(state_of(g.get()))["phase"] != "game_over"; ++k) ai_act(g.get());
    ASSERT_EQ(json::parse(state_of(g.get()))["phase"], "game_over") << game;

    bs::GameConfig config;
    config.game = *bs::parse_game_type(game);
    config.table_size = "7ft";
    const bs::Rules rules(config);
    std::vector<std::unique_ptr<bs::Player>> players;
    for (const char* name : {"amateur", "beginner"}) {
      bs::AiLevel l = bs::ai_level(name);
      l.threads = 1;
      l.time_budget = 0.0;
      l.simulation_budget = 30;
      players.push_back(bs::make_ai_player(l));
    }
    const bs::GameRecord expected = bs::play_game(rules, *players[0], *players[1], 1, seed, bs::NoiseModel{});
    const bs::GameRecord got = std::get<bs::GameRecord>(bs::read_record(record_of(g.get())));
    EXPECT_EQ(got.actions.size(), expected.actions.size()) << game;
    EXPECT_TRUE(got == expected) << game;
  }
}

TEST(WebApi, CheckPlacementRefusals) {
  GamePtr g = new_game(R"({"game": "nine_ball", "table": "9ft", "seed": "5", "players": ["human", "human"]})");
  const json table = J(bs_web_game_table(g.get()));
  const double head = table["head_string"].get<double>();
  const double width = table["width"].get<double>();
  EXPECT_TRUE(J(bs_web_game_check_placement(g.get(), head - 0.1, width / 2))["ok"].get<bool>());
  // The break: behind the head string, on the cloth.
  json r = J(bs_web_game_check_placement(g.get(), head + 0.1, width / 2));
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["reason"].get<std::string>().find("head string"), std::string::npos) << r;
  r = J(bs_web_game_check_placement(g.get(), -0.5, width / 2));
  EXPECT_FALSE(r["ok"].get<bool>());
  r = J(bs_web_game_check_placement(g.get(), 0.01, width / 2));  // into the cushion
  EXPECT_FALSE(r["ok"].get<bool>());
  r = J(bs_web_game_check_placement(g.get(), std::nan(""), 0.5));
  EXPECT_FALSE(r["ok"].get<bool>());

  // A feeble break that reaches nothing: a foul, the cue ball in hand
  // anywhere for the other player; not on a ball.
  act(g.get(), shoot_json(R"("speed": 0.2, "phi": 0, "theta": 0, "a": 0, "b": 0)"));
  const json s = json::parse(state_of(g.get()));
  ASSERT_EQ(s["ball_in_hand"], "anywhere") << s;
  const json& one = s["position"][1];
  r = J(bs_web_game_check_placement(g.get(), one[0].get<double>(), one[1].get<double>() + 0.01));
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["reason"].get<std::string>().find("overlap"), std::string::npos) << r;
  EXPECT_TRUE(J(bs_web_game_check_placement(g.get(), head + 0.3, width / 2))["ok"].get<bool>());

  // Once the cue ball is on the table it is not in hand any more.
  act(g.get(), place_json(1.0, 0.3));
  r = J(bs_web_game_check_placement(g.get(), 1.2, 0.3));
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["reason"].get<std::string>().find("not in hand"), std::string::npos) << r;
}

TEST(WebApi, TableDescribesTheGamesTable) {
  GamePtr g = new_game(R"({"game": "eight_ball", "table": "7ft", "players": ["human", "human"]})");
  const json t = J(bs_web_game_table(g.get()));
  const bs::Table table = bs::make_pool_table("7ft");
  EXPECT_EQ(t["size"], "7ft");
  EXPECT_EQ(t["length"].get<double>(), table.length);
  EXPECT_EQ(t["walls"].size(), table.walls.size());
  EXPECT_EQ(t["pockets"].size(), 6u);
  EXPECT_EQ(t["outline"].size(), table.outline.size());
  for (const json& w : t["walls"]) {
    const std::string kind = w["kind"].get<std::string>();
    EXPECT_TRUE(kind == "segment" || kind == "corner" || kind == "arc") << kind;
  }
}

// Whose turn it is after each action, and why: the act reply's "turn"
// and bs_web_game_turns's list agree, and follow the state after each action.
TEST(WebApi, TurnsSayWhoIsNextAndWhy) {
  GamePtr g = new_game(
      R"({"game": "nine_ball", "table": "9ft", "seed": "5", "players": ["human", "human"], "ai_budget": 40})");
  EXPECT_EQ(J(bs_web_game_turns(g.get())), json::parse(R"({"turns": []})"));
  EXPECT_EQ(J(bs_web_game_table(g.get()))["size"], "9ft");
  std::vector<json> replies;
  std::set<std::string> seen;
  for (int k = 0; k < 60; ++k) {
    const json s = J(bs_web_game_state(g.get()));
    if (s["phase"] == "game_over") break;
    const json r = step_ai(g.get(), "club");
    ASSERT_TRUE(r.contains("turn")) << r.dump();
    const json& t = r["turn"];
    const std::string why = t["why"].get<std::string>();
    seen.insert(why);
    const json& after = r["state"];
    if (after["phase"] == "game_over") {
      EXPECT_EQ(why, "game_over");
      EXPECT_EQ(t["next"], -1);
    } else {
      EXPECT_EQ(t["next"], after["player"]);
      if (r["kind"] == "shoot" && after["phase"] == "shot") {
        EXPECT_EQ(why == "continues", r["ruling"]["turn_continues"].get<bool>()) << r.dump();
        EXPECT_EQ(why == "foul",
                  !r["ruling"]["turn_continues"].get<bool>() && !r["ruling"]["fouls"].empty())
            << r.dump();
      }
      if (after["phase"] == "push_out_choice") {
        EXPECT_EQ(why, "decides");
      }
    }
    replies.push_back(t);
  }
  const json turns = J(bs_web_game_turns(g.get()))["turns"];
  ASSERT_EQ(turns.size(), replies.size());
  for (std::size_t i = 0; i < replies.size(); ++i) EXPECT_EQ(turns[i], replies[i]) << i;
  EXPECT_TRUE(seen.count("continues") && seen.count("passes")) << json(seen).dump();
  EXPECT_EQ(error_of(bs_web_game_turns(nullptr)), "handle: a null handle");
}

// A three-cushion shot's playback counts the struck ball's cushions and
// balls as the frames go, as the rules count them at the end.
TEST(WebApi, ThreeCushionPlaybackCountsAsTheBallGoes) {
  GamePtr g =
      new_game(R"({"game": "three_cushion", "seed": "2026", "players": ["human", "baseline"]})");
  EXPECT_EQ(J(bs_web_game_table(g.get()))["size"], "10ft");
  const json r = ai_act(g.get(), "baseline");
  const json k = r["ruling"]["carom"];
  PlaybackPtr pb(bs_web_game_shot_playback(g.get(), 0));
  ASSERT_NE(pb, nullptr) << bs_web_last_error();
  json c = J(bs_web_playback_carom_count(pb.get()));
  EXPECT_EQ(c, json::parse(R"({"cushions": 0, "hit": [], "done": false, "made": false})"));
  int cushions = 0;
  std::size_t hits = 0;
  for (int f = 0; f < 400; ++f) {
    const json fr = J(bs_web_playback_frame(pb.get(), 0.05 * f));
    c = J(bs_web_playback_carom_count(pb.get()));
    EXPECT_GE(c["cushions"].get<int>(), cushions);
    EXPECT_GE(c["hit"].size(), hits);
    cushions = c["cushions"].get<int>();
    hits = c["hit"].size();
    if (fr["at_rest"].get<bool>()) break;
  }
  EXPECT_EQ(c["cushions"], k["cushions"]);
  EXPECT_EQ(c["hit"], k["hit"]);
  EXPECT_EQ(c["made"], k["point"]) << r.dump();
  EXPECT_EQ(c["done"], k["hit"].size() == 2);
  // Another playback has no count.
  GamePtr pool = new_game(R"({"game": "nine_ball", "seed": "1", "players": ["human", "human"]})");
  act(pool.get(), shoot_json(R"("speed": 8.0, "phi": 0, "theta": 0, "a": 0, "b": 0)"));
  PlaybackPtr other(bs_web_game_shot_playback(pool.get(), 0));
  ASSERT_NE(other, nullptr);
  EXPECT_EQ(error_of(bs_web_playback_carom_count(other.get())),
            "playback: not the playback of a three-cushion shot");
  EXPECT_EQ(error_of(bs_web_playback_carom_count(nullptr)), "handle: a null handle");
}

TEST(WebApi, SnookerGameShowsTheScoreTheBallOnAndTheTable) {
  GamePtr g = new_game(R"({"game": "snooker", "seed": "2026", "players": ["human", "baseline"]})");
  // The table: the 12 ft table's markings (WPBSA: baulk line 737 mm from
  // the bottom cushion, the D of radius 292 mm), as snooker.hpp has them.
  const json t = J(bs_web_game_table(g.get()));
  const bs::SnookerMarks m = bs::snooker_marks();
  EXPECT_EQ(t["length"].get<double>(), 3.569);
  EXPECT_EQ(t["ball_radius"].get<double>(), bs::kSnookerBallRadius);
  EXPECT_EQ(t["snooker"]["baulk_line"].get<double>(), 0.737);
  EXPECT_EQ(t["snooker"]["d_radius"].get<double>(), 0.292);
  EXPECT_EQ(t["snooker"]["spots"]["black"][0].get<double>(), m.black.x);
  EXPECT_EQ(t["snooker"]["spots"].size(), 6u);
  // The pool games' tables have no snooker markings.
  GamePtr pool = new_game(R"({"game": "nine_ball", "players": ["human", "human"]})");
  EXPECT_FALSE(J(bs_web_game_table(pool.get())).contains("snooker"));
  EXPECT_FALSE(J(bs_web_game_state(pool.get())).contains("snooker_figures"));
  EXPECT_FALSE(J(bs_web_game_state(pool.get()))["legal"].contains("nominate"));

  // At the start: on a red, 15 reds each with a black and the six colours
  // left (15 x 8 + 27 = 147, the maximum break), no snookers needed.
  json s = J(bs_web_game_state(g.get()));
  EXPECT_EQ(s["phase"], "break_shot");
  EXPECT_EQ(s["ball_in_hand"], "d");
  EXPECT_EQ(s["snooker"]["score"], json::array({0, 0}));
  EXPECT_EQ(s["snooker_figures"]["balls_on"].size(), 15u);
  EXPECT_EQ(s["snooker_figures"]["points_remaining"], 147);
  EXPECT_EQ(s["snooker_figures"]["snookers_required"], json::array({0, 0}));
  EXPECT_EQ(s["legal"]["place"], "d");
  EXPECT_EQ(s["legal"]["must_nominate"], false);
  EXPECT_EQ(s["legal"]["choices"], json::array({"concede"}));
  // The D: in it, on the baulk line; not beyond it.
  EXPECT_TRUE(
      J(bs_web_game_check_placement(g.get(), m.baulk_x, m.d_centre.y - 0.18))["ok"].get<bool>());
  EXPECT_FALSE(
      J(bs_web_game_check_placement(g.get(), m.baulk_x + 0.05, m.d_centre.y))["ok"].get<bool>());
  EXPECT_FALSE(
      J(bs_web_game_check_placement(g.get(), m.baulk_x - 0.1, m.d_centre.y + 0.3))["ok"].get<bool>());

  // A hint from an AI level and from the baseline is given; an unknown
  // level is refused by name.
  EXPECT_EQ(error_of(bs_web_game_ai_action(g.get(), "beginner")), "");
  EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), "shark")), "level:"));
  // seat 0 is human: a hint needs a level
  EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), nullptr)), "level:"));

  // Play until a shot nominates a colour: after a red the state says a
  // colour must be nominated, and the nominating shot's link keeps it.
  act(g.get(), place_json(m.baulk_x, m.d_centre.y - 0.18));
  bool nominated = false;
  for (int k = 0; k < 60 && !nominated; ++k) {
    const json st = J(bs_web_game_state(g.get()));
    if (st["phase"] == "game_over") break;
    if (st["legal"]["must_nominate"] == true) {
      EXPECT_EQ(st["snooker"]["colour_on"], true);
      EXPECT_EQ(st["legal"]["nominate"], json::array({16, 17, 18, 19, 20, 21}));
      EXPECT_GT(st["snooker"]["break"].get<int>(), 0);
      const json r = ai_act(g.get(), "baseline");
      nominated = r["executed"].contains("nominate");
    } else {
      step_ai(g.get(), "baseline");
    }
  }
  ASSERT_TRUE(nominated);
  const std::string link = link_of(g.get());
  GamePtr h(bs_web_game_from_link(link.c_str()));
  ASSERT_NE(h, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
  EXPECT_EQ(state_of(h.get()), state_of(g.get()));
  // Its record replays.
  const auto rec = bs::read_record(record_of(g.get()));
  ASSERT_TRUE(std::holds_alternative<bs::GameRecord>(rec));
  EXPECT_TRUE(bs::replay(std::get<bs::GameRecord>(rec)).identical);
}

TEST(WebApi, ThreeCushionGameShowsTheScoreTheInningsAndTheTable) {
  // Who plays three-cushion: the baseline, and the AI levels that do
  // (players.hpp decides); the other games' players are unchanged.
  const json players = J(bs_web_game_players("three_cushion"));
  EXPECT_EQ(players["game"], "three_cushion");
  ASSERT_FALSE(players["players"].empty());
  EXPECT_EQ(players["players"].back(), "baseline");
  for (const auto& p : players["players"]) {
    EXPECT_FALSE(bs::check_player(p.get<std::string>(), bs::GameType::three_cushion).has_value())
        << p;
  }
  EXPECT_EQ(J(bs_web_game_players("snooker"))["players"], J(bs_web_version())["snooker_players"]);
  EXPECT_EQ(J(bs_web_game_players("eight_ball"))["players"], J(bs_web_version())["levels"]);
  EXPECT_TRUE(starts_with(error_of(bs_web_game_players("bowls")), "game: unknown game \"bowls\""));
  EXPECT_TRUE(starts_with(error_of(bs_web_game_players(nullptr)), "game: "));

  // Bad configs name the field.
  const std::pair<const char*, const char*> configs[] = {
      {R"({"game": "three_cushion", "players": ["human", "human"], "table": "9ft"})",
       "table: unknown table size \"9ft\" (expected \"10ft\")"},
      {R"({"game": "three_cushion", "players": ["human", "shark"]})",
       "players[1]: \"human\" or a player of three_cushion ("},
      {R"({"game": "three_cushion", "players": ["human", "human"], "carom": {"target": 0}})",
       "carom.target: "},
      {R"({"game": "three_cushion", "players": ["human", "human"], "carom": {"points": 3}})",
       "carom.points: unknown field"},
      {R"({"game": "three_cushion", "players": ["human", "human"], "carom": {"equalizing_inning": 1}})",
       "carom.equalizing_inning: expected true or false"},
      {R"({"game": "eight_ball", "players": ["human", "human"], "carom": {"target": 5}})",
       "carom: unknown field (known: game, table, seed, breaker, players, ai_budget, physics)"},
  };
  for (const auto& [config, prefix] : configs) {
    EXPECT_EQ(bs_web_game_new(config), nullptr) << config;
    EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), prefix))
        << config << " -> " << bs_web_last_error();
  }

  GamePtr g = new_game(
      R"({"game": "three_cushion", "seed": "40", "players": ["human", "baseline"],
          "carom": {"target": 3, "innings_limit": 4}})");
  // The carom table: no pockets, its spots and diamonds (carom.hpp).
  const json t = J(bs_web_game_table(g.get()));
  const bs::CaromMarks m = bs::carom_marks();
  EXPECT_EQ(t["pockets"].size(), 0u);
  EXPECT_EQ(t["ball_radius"].get<double>(), bs::kCaromBallRadius);
  EXPECT_EQ(t["carom"]["top_spot"][0].get<double>(), m.top_spot.x);
  EXPECT_EQ(t["carom"]["starting_spots"].size(), 2u);
  EXPECT_EQ(t["carom"]["diamonds"].size(), m.diamonds.size());
  EXPECT_FALSE(t.contains("snooker"));
  // The other games have neither.
  GamePtr pool = new_game(R"({"game": "nine_ball", "players": ["human", "human"]})");
  EXPECT_FALSE(J(bs_web_game_table(pool.get())).contains("carom"));
  EXPECT_FALSE(J(bs_web_game_state(pool.get())).contains("carom_figures"));

  // The start: the breaker plays the white, the score and the figures at 0.
  json s = J(bs_web_game_state(g.get()));
  EXPECT_EQ(s["game"], "three_cushion");
  EXPECT_EQ(s["carom"]["score"], json::array({0, 0}));
  EXPECT_EQ(s["carom_figures"]["cue_ball"], 0);
  EXPECT_EQ(s["carom_figures"]["general_average"], json::array({0.0, 0.0}));
  EXPECT_EQ(s["carom_figures"]["highest_run"], json::array({0, 0}));
  EXPECT_EQ(s["legal"]["place"], "none");
  const json rec = J(bs_web_game_record(g.get()));
  EXPECT_EQ(rec["config"]["carom"]["target"], 3);
  EXPECT_EQ(rec["config"]["carom"]["innings_limit"], 4);

  // A human shot at the red: its ruling has the carom part; the shot's
  // playback has the struck ball's events.
  const json r =
      act(g.get(), shoot_json(R"("speed": 3.0, "phi": 0.0, "theta": 0, "a": 0, "b": 0)"));
  ASSERT_TRUE(r["ruling"].contains("carom")) << r.dump();
  EXPECT_EQ(r["ruling"]["carom"]["cue_ball"], 0);
  PlaybackPtr pb(bs_web_game_shot_playback(g.get(), 0));
  ASSERT_NE(pb, nullptr) << bs_web_last_error();
  EXPECT_TRUE(starts_with(bs_web_playback_events(pb.get(), 0), R"({"from":0,"events":[)"));
  // A hint from the baseline; a level that does not play the game is
  // refused by name.
  for (int k = 0; k < 200; ++k) {
    s = J(bs_web_game_state(g.get()));
    if (s["phase"] == "game_over") break;
    const bool human = s["players"][s["player"].get<std::size_t>()] == "human";
    EXPECT_EQ(s["carom_figures"]["cue_ball"], s["player"] == s["breaker"] ? 0 : 1);
    if (human && !bs::check_player("club", bs::GameType::three_cushion)) {
      EXPECT_EQ(error_of(bs_web_game_ai_action(g.get(), "club")), "");
    } else if (human) {
      EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), "club")), "level: ")) << k;
    }
    step_ai(g.get(), "baseline");
  }
  s = J(bs_web_game_state(g.get()));
  ASSERT_EQ(s["phase"], "game_over");
  // The figures: points over innings begun; the highest run as the match
  // summary counts it.
  for (std::size_t p = 0; p < 2; ++p) {
    const int innings = s["carom"]["innings"][p].get<int>();
    const int score = s["carom"]["score"][p].get<int>();
    EXPECT_EQ(s["carom_figures"]["general_average"][p].get<double>(),
              innings > 0 ? static_cast<double>(score) / innings : 0.0);
    EXPECT_LE(s["carom_figures"]["highest_run"][p].get<int>(), score);
  }

  // The link holds the rules and reproduces the game; the record replays.
  const std::string link = link_of(g.get());
  GamePtr h(bs_web_game_from_link(link.c_str()));
  ASSERT_NE(h, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
  EXPECT_EQ(state_of(h.get()), state_of(g.get()));
  const auto back = bs::read_record(record_of(g.get()));
  ASSERT_TRUE(std::holds_alternative<bs::GameRecord>(back));
  EXPECT_TRUE(bs::replay(std::get<bs::GameRecord>(back)).identical);
}

TEST(WebApi, ThreeCushionLinkKeepsTheBallStruck) {
  // A shot that names the ball struck (here the opponent's: a foul) is
  // kept by the link.
  GamePtr g = new_game(R"({"game": "three_cushion", "seed": "3", "players": ["human", "human"]})");
  const json r = act(
      g.get(),
      R"({"type": "shoot", "strike": {"speed": 2.0, "phi": 90.0, "theta": 0, "a": 0, "b": 0}, "call": null, "safety": false, "push_out": false, "cue_ball": 1})");
  EXPECT_EQ(r["ruling"]["carom"]["cue_ball"], 1);
  const std::string link = link_of(g.get());
  GamePtr h(bs_web_game_from_link(link.c_str()));
  ASSERT_NE(h, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
}

// ---------------------------------------------------------------------------
// The wasm build's floating-point <charconv> (web/compat).

std::string std_text(double v) {
  char buf[400];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string compat_text(double v) {
  char buf[400];
  const auto r = breakshot_compat::to_chars_shortest(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

TEST(WebCompat, ShortestTextIsLibstdcxxs) {
  std::uint64_t x = 0x853c49e6748fea9bULL;
  const auto next = [&] {
    // SplitMix64: a fixed stream of 64-bit patterns.
    x += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = x;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  std::vector<double> values = {0.0, -0.0, 1.0, 0.1, 1e22, 1e23, 5e-324, 1e-5, 1e-4, 123456.0,
                                1.2345678901234568e20, 9007199254740993.0,
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity()};
  for (int e = -1074; e <= 1023; ++e) {
    values.push_back(std::ldexp(1.0, e));
    values.push_back(std::nextafter(std::ldexp(1.0, e), 0.0));
  }
  for (int i = 0; i < 100000; ++i) {
    values.push_back(std::bit_cast<double>(next()));
    // Numbers of the size physics gives: |v| in [1e-8, 1e4).
    const double u = static_cast<double>(next() >> 11) * 0x1.0p-53;
    values.push_back((u - 0.5) * std::pow(10.0, static_cast<double>(next() % 12) - 8.0));
  }
  int bad = 0;
  for (const double v : values) {
    if (std::isnan(v)) continue;
    const std::string a = std_text(v);
    const std::string b = compat_text(v);
    if (a != b && ++bad <= 10) ADD_FAILURE() << std::hexfloat << v << ": std " << a << ", compat " << b;
    double back = 0.0;
    const auto r = breakshot_compat::from_chars_decimal(a.data(), a.data() + a.size(), back);
    if (std::isfinite(v)) {
      EXPECT_EQ(r.ptr, a.data() + a.size());
      EXPECT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << a;
    }
  }
  EXPECT_EQ(bad, 0);
}

TEST(WebCompat, FromCharsIsTheStandards) {
  for (const std::string text : {"1.5", "4", "0.5x", "-", "", "1e", "1e+", "abc", "1.", ".5", "+1",
                                 "1e400", "-1e400", "1e-400", "5e-324", "  1", "1E5", "0x10", "inf",
                                 "-nan", "2.5e-3junk"}) {
    double a = 7.0, b = 7.0;
    const auto ra = std::from_chars(text.data(), text.data() + text.size(), a);
    const auto rb = breakshot_compat::from_chars_decimal(text.data(), text.data() + text.size(), b);
    EXPECT_EQ(ra.ptr - text.data(), rb.ptr - text.data()) << "'" << text << "'";
    EXPECT_EQ(ra.ec, rb.ec) << "'" << text << "'";
    if (ra.ec == std::errc() && !std::isnan(a)) {
      EXPECT_EQ(a, b) << "'" << text << "'";
    }
  }
  char buf[64];
  auto r = breakshot_compat::to_chars_precision(buf, buf + sizeof buf, 3.14159, std::chars_format::fixed, 2);
  EXPECT_EQ(std::string(buf, r.ptr), "3.14");
  r = breakshot_compat::to_chars_precision(buf, buf + sizeof buf, 1234.5, std::chars_format::general, 6);
  char ref[64];
  const auto rr = std::to_chars(ref, ref + sizeof ref, 1234.5, std::chars_format::general, 6);
  EXPECT_EQ(std::string(buf, r.ptr), std::string(ref, rr.ptr));
}

}  // namespace

// A seat at a named noise (LEVEL@NOISE, players.hpp): the seat shoots with
// that noise, which its record carries, and the AI plans with it; a bad
// name is an error naming the seat and what is wrong.
TEST(WebApi, SeatsAtANamedNoise) {
  GamePtr g = new_game(
      R"({"game": "nine_ball", "seed": "5", "players": ["club@0.5x", "beginner@none"],
          "ai_budget": 40})");
  ASSERT_NE(g, nullptr);
  for (int k = 0; k < 4; ++k) {
    if (json::parse(state_of(g.get()))["phase"] == "game_over") break;
    step_ai(g.get(), nullptr);
  }
  const auto parsed = bs::read_record(record_of(g.get()));
  ASSERT_TRUE(std::holds_alternative<bs::GameRecord>(parsed));
  const bs::GameRecord& rec = std::get<bs::GameRecord>(parsed);
  EXPECT_EQ(rec.players[0], "club@0.5x");
  EXPECT_EQ(rec.noise[0], bs::parse_noise("0.5x"));
  EXPECT_EQ(rec.noise[1], bs::NoiseModel{});
  EXPECT_GE(rec.actions.size(), 2u);
  EXPECT_TRUE(bs::replay(rec).identical);
  // A hint at a named noise, for the seat to act.
  if (json::parse(state_of(g.get()))["phase"] != "game_over") {
    const json hint = J(bs_web_game_ai_action(g.get(), "beginner@0.5x"));
    EXPECT_TRUE(hint.contains("action")) << hint.dump();
  }
  EXPECT_TRUE(starts_with(error_of(bs_web_game_ai_action(g.get(), "beginner@")), "level: player"))
      << bs_web_last_error();

  const std::pair<const char*, const char*> bad[] = {
      {R"(["club@fast", "human"])", "players[0]: player \"club@fast\": noise: unknown spec"},
      {R"(["human", "@1x"])", "players[1]: player \"@1x\": no player before the '@'"},
      {R"(["clubb@1x", "human"])", "players[0]: \"human\" or unknown"},
  };
  for (const auto& [players, message] : bad) {
    const std::string config = std::string(R"({"game": "nine_ball", "players": )") + players + "}";
    EXPECT_EQ(bs_web_game_new(config.c_str()), nullptr) << players;
    EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), message))
        << players << ": " << bs_web_last_error();
  }
}

// ---------------------------------------------------------------------------
// 10-ball through the facade (docs/rules.md, "10-ball"; docs/web.md): a
// game the page plays, its calls refused with the rules' reasons, the
// incoming player's choice after a ball pocketed wrongly, and its links.

namespace {

/// The action of a hint of `level` for the seat to act (its exact JSON).
json hint_of(BsWebGame* g, const char* level) {
  const json reply = J(bs_web_game_ai_action(g, level));
  EXPECT_TRUE(reply.contains("action")) << reply.dump();
  return reply.contains("action") ? reply["action"] : json();
}

/// A shot in the records' form with a call (null: none) and the flags.
std::string ten_shot(double speed, double phi, const std::string& call, bool safety,
                     bool push_out) {
  return R"({"type": "shoot", "strike": {"speed": )" + json(speed).dump() + R"(, "phi": )" +
         json(phi).dump() + R"(, "theta": 0, "a": 0, "b": 0}, "call": )" + call +
         R"(, "safety": )" + (safety ? "true" : "false") + R"(, "push_out": )" +
         (push_out ? "true" : "false") + "}";
}

}  // namespace

TEST(WebApi, TenBallIsAGameOfThePage) {
  // Its computer players are the AI levels (no baseline), at a named noise too.
  const json players = J(bs_web_game_players("ten_ball"));
  EXPECT_EQ(players["game"], "ten_ball");
  EXPECT_EQ(players["players"], json(bs::ai_level_names()));
  EXPECT_EQ(bs_web_game_new(R"({"game": "ten_ball", "players": ["human", "baseline"]})"), nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()), "players[1]: \"human\" or unknown"))
      << bs_web_last_error();
  EXPECT_EQ(bs_web_game_new(R"({"game": "ten_ball", "table": "12ft", "players": ["human", "human"]})"),
            nullptr);
  EXPECT_TRUE(starts_with(error_of(bs_web_last_error()),
                          "table: unknown table size \"12ft\" (expected \"7ft\", \"8ft\" or \"9ft\")"))
      << bs_web_last_error();

  // The start: ten object balls racked, the 1 on, the break not called.
  GamePtr g = new_game(
      R"({"game": "ten_ball", "table": "8ft", "seed": "10", "players": ["human", "club"]})");
  const json t = J(bs_web_game_table(g.get()));
  EXPECT_EQ(t["pockets"].size(), 6u);
  EXPECT_FALSE(t.contains("snooker"));
  EXPECT_FALSE(t.contains("carom"));
  const json s = J(bs_web_game_state(g.get()));
  EXPECT_EQ(s["game"], "ten_ball");
  EXPECT_EQ(s["phase"], "break_shot");
  EXPECT_EQ(s["position"].size(), 11u);
  EXPECT_EQ(s["on_table"], json::array({1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(s["legal"]["targets"], json::array({1}));
  EXPECT_EQ(s["legal"]["call"], false);
  EXPECT_EQ(s["legal"]["place"], "kitchen");
  // The 1 on the foot spot, the 10 in the middle of the third row: on the
  // table's long axis, behind the 1.
  EXPECT_EQ(s["position"][1], t["foot_spot"]);
  EXPECT_NEAR(s["position"][10][1].get<double>(), t["foot_spot"][1].get<double>(), 1e-3);
  EXPECT_GT(s["position"][10][0].get<double>(), t["foot_spot"][0].get<double>() + 0.09);
  EXPECT_FALSE(s.contains("snooker_figures"));
  EXPECT_FALSE(s.contains("carom_figures"));
  EXPECT_FALSE(s["legal"].contains("nominate"));
}

TEST(WebApi, TenBallComputersAtANamedNoiseCallEveryShot) {
  // Both seats computers, one at a named noise (the game as play_game
  // plays it: AiGameIsTheGamePlayGamePlays): the game ends, its record
  // carries the noise and replays identical, and every shot but the
  // break is called, declared safe or a push-out.
  GamePtr g = new_game(R"({"game": "ten_ball", "table": "7ft", "seed": "1010", "breaker": 0,
                           "players": ["amateur@0.5x", "beginner"], "ai_budget": 30})");
  for (int k = 0; k < 800 && json::parse(state_of(g.get()))["phase"] != "game_over"; ++k) ai_act(g.get());
  const json end = json::parse(state_of(g.get()));
  ASSERT_EQ(end["phase"], "game_over");
  EXPECT_GE(end["winner"].get<int>(), 0);
  const bs::GameRecord rec = std::get<bs::GameRecord>(bs::read_record(record_of(g.get())));
  EXPECT_EQ(rec.config.game, bs::GameType::ten_ball);
  EXPECT_EQ(rec.players[0], "amateur@0.5x");
  EXPECT_EQ(rec.noise[0], bs::parse_noise("0.5x"));
  EXPECT_EQ(rec.noise[1], bs::ai_level("beginner").noise);
  const bs::ReplayReport report = bs::replay(rec);
  EXPECT_TRUE(report.identical) << report.message;
  int called = 0;
  for (std::size_t i = 0; i < rec.actions.size(); ++i) {
    const auto* shot = std::get_if<bs::Shoot>(&rec.actions[i].action);
    if (shot == nullptr) continue;
    const bs::GameState& before = i == 0 ? rec.start : rec.actions[i - 1].after;
    if (before.phase == bs::Phase::break_shot) {
      EXPECT_FALSE(shot->call || shot->safety || shot->push_out) << i;
    } else {
      EXPECT_TRUE(shot->call || shot->safety || shot->push_out) << i;
      called += shot->call ? 1 : 0;
    }
  }
  EXPECT_GE(called, 1);
}

TEST(WebApi, TenBallRefusesAShotWithoutACallWithTheRulesReason) {
  GamePtr g = new_game(R"({"game": "ten_ball", "seed": "10", "players": ["human", "human"]})");
  // The break is not called.
  std::string before = state_of(g.get());
  const std::string called_break = ten_shot(9.0, 0.0, R"({"ball": 1, "pocket": 3})", false, false);
  EXPECT_EQ(error_of(bs_web_game_act(g.get(), called_break.c_str())),
            "the break is neither called, a safety nor a push-out");
  EXPECT_EQ(state_of(g.get()), before);
  // A legal break (the expert's placement and break, played as chosen:
  // the seats are human).
  json brk;
  for (int k = 0; k < 2 && json::parse(state_of(g.get()))["phase"] == "break_shot"; ++k) {
    brk = act(g.get(), hint_of(g.get(), "expert").dump());
  }
  ASSERT_EQ(brk["kind"], "shoot");
  ASSERT_TRUE(brk["ruling"]["fouls"].empty()) << brk["ruling"].dump();
  EXPECT_EQ(brk["ruling"]["legal_break"], true);
  ASSERT_FALSE(brk["facts"]["pocketed"].empty()) << "this break pockets balls";
  json s = json::parse(state_of(g.get()));
  ASSERT_EQ(s["phase"], "shot");
  EXPECT_EQ(s["legal"]["call"], true);
  EXPECT_EQ(s["legal"]["push_out"], true);

  // Each refused with the rules' words, the game unchanged.
  before = state_of(g.get());
  const std::pair<std::string, std::string> refused[] = {
      {ten_shot(2.0, 0.0, "null", false, false),
       "10-ball: every shot but the break calls a ball and a pocket, or is a safety"},
      {ten_shot(2.0, 0.0, R"({"ball": 2, "pocket": 0})", true, false), "a declared safety has no call"},
      {ten_shot(2.0, 0.0, R"({"ball": 2, "pocket": 0})", false, true),
       "a push-out has no call and is no safety"},
      {ten_shot(2.0, 0.0, R"({"ball": 11, "pocket": 0})", false, false),
       "called ball 11 is not on the table"},
      {R"({"type": "shoot", "strike": {"speed": 2, "phi": 0, "theta": 0, "a": 0, "b": 0},
           "call": {"ball": 2, "pocket": 0}, "safety": false, "push_out": false, "nominate": 16})",
       "10-ball has no nominated ball (nominate is snooker's)"},
  };
  for (const auto& [action, reason] : refused) {
    EXPECT_EQ(error_of(bs_web_game_act(g.get(), action.c_str())), reason) << action;
    EXPECT_EQ(state_of(g.get()), before) << action;
  }
  // A ball pocketed on the break cannot be called either.
  for (const json& down : brk["facts"]["pocketed"]) {
    const int n = down.get<int>();
    if (n == 10) continue;  // spotted
    const std::string call = R"({"ball": )" + std::to_string(n) + R"(, "pocket": 0})";
    EXPECT_EQ(error_of(bs_web_game_act(g.get(), ten_shot(2.0, 0.0, call, false, false).c_str())),
              "called ball " + std::to_string(n) + " is not on the table");
  }
  EXPECT_EQ(state_of(g.get()), before);

  // The push-out (no call) is accepted, and its choice says so: the state's
  // after_push_out is what tells it from the choice after a wrong pot.
  const int pusher = s["player"].get<int>();
  const json push = act(g.get(), ten_shot(0.8, 90.0, "null", false, true));
  EXPECT_NE(push["ruling"]["text"].get<std::string>().find("Push-out"), std::string::npos)
      << push["ruling"].dump();
  s = json::parse(state_of(g.get()));
  EXPECT_EQ(s["phase"], "push_out_choice");
  EXPECT_EQ(s["after_push_out"], true);
  EXPECT_EQ(s["player"], 1 - pusher);
  EXPECT_EQ(s["legal"]["choices"], json::array({"shoot", "pass_back"}));
  EXPECT_EQ(s["legal"]["shoot"], false);
  // A shot before the choice is refused, and so is a choice not on offer.
  const std::string called = ten_shot(2.0, 0.0, R"({"ball": 2, "pocket": 0})", false, false);
  EXPECT_NE(error_of(bs_web_game_act(g.get(), called.c_str())), "");
  EXPECT_NE(error_of(bs_web_game_act(g.get(), R"({"type": "decide", "choice": "play_on"})")), "");
  const json took = act(g.get(), R"({"type": "decide", "choice": "shoot"})");
  EXPECT_EQ(took["ruling"]["text"], "Player " + std::to_string(2 - pusher) + " takes the table.");
  s = json::parse(state_of(g.get()));
  EXPECT_EQ(s["phase"], "shot");
  EXPECT_EQ(s["legal"]["call"], true);
  EXPECT_EQ(s["legal"]["push_out"], false);
  // Called now: an expert's called pot is played.
  const json hint = hint_of(g.get(), "expert");
  EXPECT_TRUE(hint["call"].is_object() || hint["safety"] == true) << hint.dump();
  const json shot = act(g.get(), hint.dump());
  EXPECT_TRUE(shot["ruling"].contains("call_made")) << shot["ruling"].dump();
}

TEST(WebApi, TenBallWrongPotLetsTheIncomingPlayerChooseAndItsLinkReplays) {
  // Human seats play the expert's hints as chosen, but one called pot is
  // played with its call moved to another pocket: when the ball drops, it
  // is pocketed wrongly.
  GamePtr g = new_game(
      R"({"game": "ten_ball", "table": "9ft", "seed": "10", "players": ["human", "human"]})");
  json wrong;
  int shooter = -1;
  for (int k = 0; k < 60 && wrong.is_null(); ++k) {
    const json s = json::parse(state_of(g.get()));
    if (s["phase"] == "game_over") break;
    json a = hint_of(g.get(), "expert");
    const bool called = a["type"] == "shoot" && a["call"].is_object();
    if (called) a["call"]["pocket"] = (a["call"]["pocket"].get<int>() + 3) % 6;
    const json reply = act(g.get(), a.dump());
    if (called && reply["ruling"]["fouls"].empty() && !reply["facts"]["pocketed"].empty() &&
        reply["ruling"]["call_made"] == false) {
      wrong = reply;
      shooter = reply["player"].get<int>();
    }
  }
  ASSERT_FALSE(wrong.is_null()) << "no called pot dropped in 60 actions";
  const std::string incoming = "Player " + std::to_string(2 - shooter);
  const std::string offender = "Player " + std::to_string(shooter + 1);
  EXPECT_EQ(wrong["ruling"]["turn_continues"], false);
  const std::string text = wrong["ruling"]["text"].get<std::string>();
  EXPECT_NE(text.find("Not the call"), std::string::npos) << text;
  EXPECT_NE(text.find(incoming + " shoots from here or hands the shot back."), std::string::npos)
      << text;
  json s = wrong["state"];
  EXPECT_EQ(s["phase"], "push_out_choice");
  EXPECT_EQ(s["after_push_out"], false);  // not a push-out: the page words it so
  EXPECT_EQ(s["player"], 1 - shooter);
  EXPECT_EQ(s["legal"]["choices"], json::array({"shoot", "pass_back"}));
  // The balls pocketed stay down, but the 10, which is spotted.
  for (const json& n : wrong["facts"]["pocketed"]) {
    EXPECT_EQ(s["on_table"][n.get<std::size_t>()], n == 10 ? 1 : 0) << n;
  }
  const int chosen_at = s["actions"].get<int>();

  // Handed back: the offender shoots, and must call.
  const json back = act(g.get(), R"({"type": "decide", "choice": "pass_back"})");
  EXPECT_EQ(back["ruling"]["text"], incoming + " hands the shot back to " + offender + ".");
  EXPECT_EQ(back["state"]["player"], shooter);
  EXPECT_EQ(back["state"]["phase"], "shot");
  EXPECT_EQ(back["state"]["legal"]["call"], true);
  // Taken: the incoming player shoots from there.
  J(bs_web_game_undo_to(g.get(), chosen_at));
  const json took = act(g.get(), R"({"type": "decide", "choice": "shoot"})");
  EXPECT_EQ(took["ruling"]["text"], incoming + " takes the table.");
  EXPECT_EQ(took["state"]["player"], 1 - shooter);
  EXPECT_EQ(took["state"]["phase"], "shot");

  // The link: the 10-ball game, its calls as ball and pocket, its
  // decision; opened, the same record, state and link, and the same game
  // after it.
  const std::string link = link_of(g.get());
  const json body = body_of_link(link);
  EXPECT_EQ(body["g"], "ten_ball");
  EXPECT_EQ(body["t"], "9ft");
  EXPECT_FALSE(body.contains("c"));
  const json& actions = body["a"];
  ASSERT_EQ(actions.size(), static_cast<std::size_t>(chosen_at + 1));
  const json& entry = actions[static_cast<std::size_t>(chosen_at - 1)];
  ASSERT_EQ(entry.size(), 9u) << entry.dump();
  EXPECT_EQ(entry[6], wrong["executed"]["call"]["ball"]);
  EXPECT_EQ(entry[7], wrong["executed"]["call"]["pocket"]);
  EXPECT_EQ(entry[8], 0);
  EXPECT_EQ(actions.back(), json::array({"d", "shoot"}));
  GamePtr h(bs_web_game_from_link(link.c_str()));
  ASSERT_NE(h, nullptr) << bs_web_last_error();
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
  EXPECT_EQ(state_of(h.get()), state_of(g.get()));
  EXPECT_EQ(link_of(h.get()), link);
  for (int k = 0; k < 2; ++k) {
    if (json::parse(state_of(g.get()))["phase"] == "game_over") break;
    EXPECT_EQ(step_ai(g.get(), "club").dump(), step_ai(h.get(), "club").dump());
  }
  EXPECT_EQ(record_of(h.get()), record_of(g.get()));
  const bs::GameRecord rec = std::get<bs::GameRecord>(bs::read_record(record_of(g.get())));
  EXPECT_TRUE(bs::replay(rec).identical);
}

}  // namespace test_web_api

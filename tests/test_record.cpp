// Game records: the JSON round trip, the reader's errors, and replay()
// finding every kind of tampering (include/breakshot/record.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/record.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record_io.hpp"

namespace test_record {

namespace {

using namespace breakshot;
using ojson = nlohmann::ordered_json;

/// A record exercising every field with values other than the defaults:
/// not a game anyone played (read_record checks the form only), but
/// every enum, optional and awkward double is there.
GameRecord sample_record() {
  GameRecord r;
  r.config.game = GameType::nine_ball;
  r.config.table_size = "8ft";
  r.config.ball_radius = 0.0286;
  r.config.ball_mass = 0.1701;
  r.config.max_shots = 123;
  r.players = {"baseline", "a \"quoted\" name \xc3\xa9\\"};
  r.seed = std::numeric_limits<std::uint64_t>::max();
  r.noise = {NoiseModel{0.125, 0.1, 0.075, 0.0005, 0.0005}, NoiseModel{0.25, 0.0, 1e-300, 0.0, 0.001}};

  GameState s;
  s.game = GameType::nine_ball;
  for (int b = 0; b < 10; ++b) {
    s.position.push_back({0.1 * b + 0.2, -0.0 + 1.0 / (3.0 + b)});
    s.on_table.push_back(static_cast<std::uint8_t>(b % 3 == 0 ? 0 : 1));
  }
  s.position[1] = {-0.0, 1e-300};
  s.position[2] = {0.1 + 0.2, std::numeric_limits<double>::denorm_min()};
  s.phase = Phase::push_out_choice;
  s.player = 1;
  s.breaker = 1;
  s.ball_in_hand = BallInHand::anywhere;
  s.kitchen_shot = true;
  s.group = {Group::solids, Group::stripes};
  s.fouls_in_a_row = {2, 1};
  s.push_out_allowed = true;
  s.after_push_out = true;
  s.scratch_on_break = true;
  s.winner = 1;
  s.result = "line one\nline two \t\"tab\"";
  s.shots = 17;
  s.innings = 9;
  s.rack_seed = (std::uint64_t{1} << 63) + 5;
  s.racks = 2;
  r.start = s;

  RecordedAction place;
  place.player = 1;
  place.action = PlaceCueBall{{0.5, -0.25}};
  place.noise_seed = 0;
  place.ruling.text = "places";
  place.ruling.turn_continues = true;
  place.after = s;
  place.after.phase = Phase::shot;
  r.actions.push_back(place);

  RecordedAction shot;
  shot.player = 1;
  Shoot sh;
  sh.strike = {3.0000000000000004, -179.99, 12.5, -0.25, 0.125};
  sh.call = Call{8, 5};
  sh.safety = true;
  sh.push_out = true;
  shot.action = sh;
  shot.intended = CueStrike{3.0, -180.0, 12.0, -0.2, 0.1};
  shot.noise_seed = (std::uint64_t{1} << 53) + 1;  // not a double
  shot.ruling.fouls = {Foul::scratch, Foul::no_rail, Foul::behind_head_string};
  shot.ruling.legal_break = false;
  shot.ruling.assigned = Group::stripes;
  shot.ruling.spotted = {9, 8};
  shot.ruling.winner = 0;
  shot.ruling.text = "fouls";
  shot.after = place.after;
  shot.after.on_table[4] = 0;
  shot.after.phase = Phase::game_over;
  r.actions.push_back(shot);

  RecordedAction decide;
  decide.player = 0;
  decide.action = Decide{Choice::rerack_opponent_breaks};
  decide.noise_seed = 42;
  decide.after = shot.after;
  r.actions.push_back(decide);
  return r;
}

GameRecord read_ok(const std::string& text) {
  auto parsed = read_record(text);
  if (const auto* err = std::get_if<RecordError>(&parsed)) {
    ADD_FAILURE() << err->path << ": " << err->reason;
    return {};
  }
  return std::get<GameRecord>(parsed);
}

/// The error for `text`, which must be refused.
RecordError read_error(const std::string& text) {
  auto parsed = read_record(text);
  if (const auto* err = std::get_if<RecordError>(&parsed)) return *err;
  ADD_FAILURE() << "accepted: " << text.substr(0, 200);
  return {};
}

TEST(RecordIo, RoundTripGivesAnEqualRecord) {
  const GameRecord r = sample_record();
  const std::string text = write_record(r);
  const GameRecord back = read_ok(text);
  EXPECT_TRUE(back == r);
  // Field by field for a readable failure, and the awkward values exactly.
  EXPECT_EQ(back.seed, std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(back.start.rack_seed, (std::uint64_t{1} << 63) + 5);
  EXPECT_EQ(back.actions[1].noise_seed, (std::uint64_t{1} << 53) + 1);
  EXPECT_EQ(back.players, r.players);
  EXPECT_EQ(back.noise[0], r.noise[0]);  // per seat, in seat order
  EXPECT_EQ(back.noise[1], r.noise[1]);
  EXPECT_TRUE(back.start == r.start);
  EXPECT_TRUE(std::signbit(back.start.position[1].x));
  EXPECT_EQ(back.start.position[1].y, 1e-300);
  EXPECT_EQ(back.start.position[2].x, 0.1 + 0.2);
  EXPECT_EQ(back.start.position[2].y, std::numeric_limits<double>::denorm_min());
  ASSERT_EQ(back.actions.size(), 3u);
  EXPECT_TRUE(identical(back.actions[1].action, r.actions[1].action));
  ASSERT_TRUE(back.actions[1].intended.has_value());
  EXPECT_TRUE(identical(*back.actions[1].intended, *r.actions[1].intended));
  EXPECT_FALSE(back.actions[0].intended.has_value());
  EXPECT_TRUE(back.actions[1].ruling == r.actions[1].ruling);
  EXPECT_EQ(std::get<Decide>(back.actions[2].action).choice, Choice::rerack_opponent_breaks);
}

TEST(RecordIo, SameRecordSameBytes) {
  const GameRecord r = sample_record();
  const std::string a = write_record(r);
  EXPECT_EQ(write_record(r), a);
  EXPECT_EQ(write_record(read_ok(a)), a);  // and again after reading back
  EXPECT_EQ(a.back(), '\n');
}

TEST(RecordIo, OneActionPerLine) {
  const std::string text = write_record(sample_record());
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  // "{", 9 header lines, "actions": [, 3 actions, "]", "}".
  EXPECT_EQ(lines, 1u + 9u + 1u + 3u + 1u + 1u) << text;
  EXPECT_NE(text.find("\n  \"seed\": \"18446744073709551615\",\n"), std::string::npos);
  // The noise per seat, on one line.
  EXPECT_NE(text.find("\n  \"noise\": [{\"phi\":0.125,"), std::string::npos) << text;
  EXPECT_NE(text.find("},{\"phi\":0.25,"), std::string::npos) << text;
}

TEST(RecordIo, RecordWithoutActions) {
  GameRecord r = sample_record();
  r.actions.clear();
  const std::string text = write_record(r);
  EXPECT_TRUE(read_ok(text) == r);
  EXPECT_EQ(write_record(read_ok(text)), text);
}

// ---------------------------------------------------------------------------
// The ending (version 3): a forfeit of online play

GameEnding forfeit_of(int player) {
  GameEnding e;
  e.kind = GameEnding::Kind::forfeit;
  e.player = player;
  e.winner = 1 - player;
  e.text = "Player " + std::to_string(player + 1) + " left the table for 120 s and forfeits";
  return e;
}

TEST(RecordEnding, ARecordWithAnEndingIsVersion3AndRoundTrips) {
  GameRecord r = sample_record();
  const std::string without = write_record(r);
  EXPECT_NE(without.find("\n  \"version\": 2,\n"), std::string::npos);
  EXPECT_EQ(without.find("ending"), std::string::npos);
  r.ending = forfeit_of(1);
  const std::string text = write_record(r);
  EXPECT_NE(text.find("\n  \"version\": 3,\n"), std::string::npos) << text;
  // The same bytes but the version and a last line for the ending.
  std::string expected = without;
  expected.replace(expected.find("\"version\": 2"), 12, "\"version\": 3");
  expected.insert(expected.size() - 3,
                  ",\n  \"ending\": {\"kind\":\"forfeit\",\"player\":1,\"winner\":0,\"text\":"
                  "\"Player 2 left the table for 120 s and forfeits\"}");
  EXPECT_EQ(text, expected);
  const GameRecord back = read_ok(text);
  EXPECT_TRUE(back == r);
  ASSERT_TRUE(back.ending.has_value());
  EXPECT_EQ(*back.ending, forfeit_of(1));
  EXPECT_EQ(write_record(back), text);
  // Without actions, and abandoned.
  r.actions.clear();
  r.ending = GameEnding{GameEnding::Kind::abandoned, -1, -1, "both players left the table"};
  EXPECT_TRUE(read_ok(write_record(r)) == r);
  // The ending is part of a record's equality.
  GameRecord other = r;
  other.ending.reset();
  EXPECT_FALSE(other == r);
}

TEST(RecordEnding, BadEndingsAreRefusedByName) {
  GameRecord r = sample_record();
  r.ending = forfeit_of(0);
  const ojson good = ojson::parse(write_record(r));
  struct Case {
    const char* name;
    void (*mutate)(ojson&);
    const char* path;
    const char* said;
  };
  const Case cases[] = {
      {"version 3 without an ending", [](ojson& j) { j.erase("ending"); }, "ending",
       "missing required field"},
      {"an ending in version 2", [](ojson& j) { j["version"] = 2; }, "ending", "unknown field"},
      {"unknown kind", [](ojson& j) { j["ending"]["kind"] = "resigned"; }, "ending.kind",
       "\"forfeit\" or \"abandoned\""},
      {"seat out of range", [](ojson& j) { j["ending"]["player"] = 2; }, "ending.player",
       "must be"},
      {"forfeit without a seat", [](ojson& j) { j["ending"]["player"] = -1; }, "ending.player",
       "names the seat"},
      {"forfeit won by the one who left", [](ojson& j) { j["ending"]["winner"] = 0; },
       "ending.winner", "the other seat (1), not 0"},
      {"abandoned with a winner",
       [](ojson& j) {
         j["ending"]["kind"] = "abandoned";
         j["ending"]["player"] = -1;
       },
       "ending.winner", "no winner"},
      {"no words", [](ojson& j) { j["ending"]["text"] = ""; }, "ending.text", "in words"},
      {"unknown field", [](ojson& j) { j["ending"]["when"] = 3; }, "ending.when", "unknown field"},
  };
  for (const Case& c : cases) {
    ojson doc = good;
    c.mutate(doc);
    const RecordError err = read_error(doc.dump());
    EXPECT_EQ(err.path, c.path) << c.name << ": " << err.reason;
    EXPECT_NE(err.reason.find(c.said), std::string::npos) << c.name << ": " << err.reason;
  }
  // The writer refuses what the reader would.
  GameRecord bad = sample_record();
  bad.ending = forfeit_of(0);
  bad.ending->winner = 0;
  EXPECT_THROW((void)write_record(bad), std::invalid_argument);
}

TEST(RecordIo, EqualityIsBitwise) {
  const GameRecord r = sample_record();
  GameRecord other = r;
  std::get<Shoot>(other.actions[1].action).strike.a = -0.0;
  GameRecord zero = r;
  std::get<Shoot>(zero.actions[1].action).strike.a = 0.0;
  EXPECT_FALSE(other == zero);  // -0 and +0 differ in a record
  other = r;
  other.actions[2].noise_seed += 1;
  EXPECT_FALSE(other == r);
  other = r;
  other.config.max_shots += 1;
  EXPECT_FALSE(other == r);
  other = r;
  other.noise[1].theta = -0.0;  // -0 is not +0 here either
  EXPECT_FALSE(other == r);
  other = r;
  std::swap(other.noise[0], other.noise[1]);
  EXPECT_FALSE(other == r);
}

TEST(RecordIo, WriteRefusesNonFiniteNumbers) {
  GameRecord r = sample_record();
  r.actions[1].after.position[3].y = std::numeric_limits<double>::quiet_NaN();
  try {
    (void)write_record(r);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("actions[1].after.position[3][1]"), std::string::npos)
        << e.what();
  }
}

TEST(RecordIo, MalformedRecordsNameThePath) {
  const ojson good = ojson::parse(write_record(sample_record()));
  struct Case {
    const char* name;
    void (*mutate)(ojson&);
    const char* path;
    const char* reason;  // a part of it
  };
  const Case cases[] = {
      {"missing field", [](ojson& j) { j["actions"][1]["ruling"].erase("text"); },
       "actions[1].ruling.text", "missing required field"},
      {"missing top field", [](ojson& j) { j.erase("noise"); }, "noise", "missing"},
      {"unknown field", [](ojson& j) { j["config"]["colour"] = "green"; }, "config.colour",
       "unknown field (known: game, table_size, ball_radius, ball_mass, max_shots)"},
      {"unknown field, odd key", [](ojson& j) { j["config"]["ball size"] = 1; },
       "config[\"ball size\"]", "unknown field"},
      {"wrong type", [](ojson& j) { j["actions"][0]["player"] = "zero"; }, "actions[0].player",
       "expected an integer in [0, 1], not a string"},
      {"wrong type bool", [](ojson& j) { j["start"]["kitchen_shot"] = 1; }, "start.kitchen_shot",
       "expected true or false"},
      {"unknown phase", [](ojson& j) { j["start"]["phase"] = "warm_up"; }, "start.phase",
       "unknown phase \"warm_up\""},
      {"unknown foul", [](ojson& j) { j["actions"][1]["ruling"]["fouls"][1] = "spitting"; },
       "actions[1].ruling.fouls[1]", "unknown foul"},
      {"unknown group", [](ojson& j) { j["actions"][1]["after"]["group"][0] = "spots"; },
       "actions[1].after.group[0]", "unknown group"},
      {"unknown choice", [](ojson& j) { j["actions"][2]["action"]["choice"] = "resign"; },
       "actions[2].action.choice", "unknown choice"},
      {"unknown ball in hand", [](ojson& j) { j["start"]["ball_in_hand"] = "kitchenette"; },
       "start.ball_in_hand", "unknown ball_in_hand"},
      {"unknown game", [](ojson& j) { j["config"]["game"] = "bowls"; }, "config.game",
       "unknown game \"bowls\" (expected \"eight_ball\", \"nine_ball\", \"snooker\", "
       "\"three_cushion\" or \"ten_ball\")"},
      {"unknown action", [](ojson& j) { j["actions"][0]["action"]["type"] = "jump"; },
       "actions[0].action.type", "unknown action type"},
      {"field of another action type",
       [](ojson& j) { j["actions"][0]["action"]["choice"] = "shoot"; }, "actions[0].action.choice",
       "unknown field"},
      {"unknown table", [](ojson& j) { j["config"]["table_size"] = "10ft"; }, "config.table_size",
       "unknown table size \"10ft\" (expected \"7ft\", \"8ft\" or \"9ft\")"},
      {"seed as a number", [](ojson& j) { j["seed"] = 12; }, "seed", "decimal string"},
      {"bad seed", [](ojson& j) { j["actions"][2]["noise_seed"] = "-1"; }, "actions[2].noise_seed",
       "decimal integer"},
      {"seed too large", [](ojson& j) { j["seed"] = "18446744073709551616"; }, "seed",
       "decimal integer"},
      {"player out of range", [](ojson& j) { j["actions"][0]["player"] = 2; }, "actions[0].player",
       "[0, 1]"},
      {"short position", [](ojson& j) { j["start"]["position"][4] = {0.5}; }, "start.position[4]",
       "expected an array of 2 numbers, not an array of 1"},
      {"null number", [](ojson& j) { j["actions"][1]["action"]["strike"]["speed"] = nullptr; },
       "actions[1].action.strike.speed", "expected a number, not null"},
      {"on_table length", [](ojson& j) { j["start"]["on_table"].erase(0); }, "start.on_table",
       "one per ball"},
      {"intended on a decision",
       [](ojson& j) { j["actions"][2]["intended"] = j["actions"][1]["intended"]; },
       "actions[2].intended", "only a shot"},
      {"negative noise", [](ojson& j) { j["noise"][1]["speed"] = -1; }, "noise[1].speed",
       "must be >= 0, not -1.0"},
      {"one noise for both seats", [](ojson& j) { j["noise"] = j["noise"][0]; }, "noise",
       "expected an array, not an object"},
      {"noise of one seat", [](ojson& j) { j["noise"].erase(1); }, "noise",
       "expected an array of 2"},
      {"noise field missing", [](ojson& j) { j["noise"][0].erase("b"); }, "noise[0].b",
       "missing required field"},
      {"format", [](ojson& j) { j["format"] = "breakshot-scenario"; }, "format",
       "breakshot-game-record"},
      {"version", [](ojson& j) { j["version"] = 4; }, "version", "not version 4"},
      {"players", [](ojson& j) { j["players"].push_back("third"); }, "players", "an array of 2"},
      {"not an object", [](ojson& j) { j = ojson::array(); }, "(document)", "expected an object"},
  };
  for (const Case& c : cases) {
    ojson doc = good;
    c.mutate(doc);
    const RecordError err = read_error(doc.dump());
    EXPECT_EQ(err.path, c.path) << c.name << ": " << err.reason;
    EXPECT_NE(err.reason.find(c.reason), std::string::npos) << c.name << ": " << err.reason;
  }
}

TEST(RecordIo, TruncatedJsonIsAnErrorAtTheDocument) {
  const std::string text = write_record(sample_record());
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, text.size() / 3, text.size() / 2,
                              text.size() - 3}) {
    const RecordError err = read_error(text.substr(0, n));
    EXPECT_EQ(err.path, "(document)") << n;
    EXPECT_FALSE(err.reason.empty()) << n;
  }
}

TEST(RecordIo, RepeatedKeyIsAnError) {
  std::string text = write_record(sample_record());
  const std::string key = "\"kitchen_shot\":true,";
  const std::size_t at = text.find(key, text.find("\"actions\""));
  ASSERT_NE(at, std::string::npos);
  text.insert(at, key);
  const RecordError err = read_error(text);
  EXPECT_EQ(err.path, "actions[0].after.kitchen_shot");
  EXPECT_EQ(err.reason, "duplicate key");
}

// ---------------------------------------------------------------------------
// Replay

/// A real game, played once for all the replay tests: 9-ball (push-outs,
/// spotted balls) between baseline players with tournament noise.
const GameRecord& played_game() {
  static const GameRecord record = [] {
    GameConfig config;
    config.game = GameType::nine_ball;
    const Rules rules(config);
    auto p0 = make_player("baseline");
    auto p1 = make_player("baseline");
    return play_game(rules, *p0, *p1, 0, 20240602, parse_noise("tournament"));
  }();
  return record;
}

/// Index of the first shot (the break).
std::size_t first_shot(const GameRecord& r) {
  for (std::size_t i = 0; i < r.actions.size(); ++i) {
    if (std::holds_alternative<Shoot>(r.actions[i].action)) return i;
  }
  ADD_FAILURE() << "no shot in the record";
  return 0;
}

/// Index of the first shot after the break, or of the break if it is the only one.
std::size_t a_shot(const GameRecord& r) {
  const std::size_t b = first_shot(r);
  for (std::size_t i = b + 1; i < r.actions.size(); ++i) {
    if (std::holds_alternative<Shoot>(r.actions[i].action)) return i;
  }
  return b;
}

std::string action_path(std::size_t i) { return "actions[" + std::to_string(i) + "]"; }

TEST(RecordReplay, PlayedGameReplaysIdentical) {
  const GameRecord& r = played_game();
  ASSERT_FALSE(r.actions.empty());
  EXPECT_EQ(r.actions.back().after.phase, Phase::game_over);
  const ReplayReport rep = replay(r);
  EXPECT_TRUE(rep.identical) << rep.message;
  EXPECT_EQ(rep.actions_identical, r.actions.size());
  EXPECT_FALSE(rep.action.has_value());
  EXPECT_TRUE(rep.final_state == r.actions.back().after);
  // Through the file too.
  const ReplayReport again = replay(read_ok(write_record(r)));
  EXPECT_TRUE(again.identical) << again.message;
}

TEST(RecordReplay, TamperedRulingIsNamed) {
  GameRecord r = played_game();
  const std::size_t k = a_shot(r);
  r.actions[k].ruling.turn_continues = !r.actions[k].ruling.turn_continues;
  const ReplayReport rep = replay(r);
  EXPECT_FALSE(rep.identical);
  ASSERT_TRUE(rep.action.has_value());
  EXPECT_EQ(*rep.action, k);
  EXPECT_EQ(rep.actions_identical, k);
  EXPECT_EQ(rep.where, action_path(k) + ".ruling.turn_continues");
  EXPECT_EQ(rep.recorded, r.actions[k].ruling.turn_continues ? "true" : "false");
  EXPECT_EQ(rep.replayed, r.actions[k].ruling.turn_continues ? "false" : "true");
  EXPECT_NE(rep.message.find("action " + std::to_string(k)), std::string::npos) << rep.message;

  r = played_game();
  r.actions[k].ruling.fouls.push_back(Foul::no_rail);
  const ReplayReport fouls = replay(r);
  EXPECT_EQ(fouls.action, k);
  EXPECT_EQ(fouls.where.substr(0, (action_path(k) + ".ruling.fouls").size()),
            action_path(k) + ".ruling.fouls")
      << fouls.where;
}

TEST(RecordReplay, RulingsAreComparedNotTheirWords) {
  // The words of a ruling and of a game's result are put better from one
  // version to the next: a record whose words differ, and no more, still
  // replays identical (records written before the words changed).
  GameRecord r = played_game();
  for (RecordedAction& a : r.actions) {
    a.ruling.text = "Older words.";
    a.after.result = a.after.result.empty() ? "" : "older words";
  }
  const ReplayReport rep = replay(r);
  EXPECT_TRUE(rep.identical) << rep.message;
  EXPECT_EQ(rep.actions_identical, r.actions.size());
  // The replayed state has today's words.
  EXPECT_EQ(rep.final_state.result, played_game().actions.back().after.result);
}

TEST(RecordReplay, TamperedPositionIsNamed) {
  GameRecord r = played_game();
  const std::size_t k = a_shot(r);
  // The smallest change there is: one ulp of one coordinate.
  Vec2& p = r.actions[k].after.position[0];
  p.y = std::nextafter(p.y, 1.0);
  const ReplayReport rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.action, k);
  EXPECT_EQ(rep.where, action_path(k) + ".after.position[0][1]");
  EXPECT_NE(rep.recorded, rep.replayed);
}

TEST(RecordReplay, TamperedStrikeIsNamed) {
  GameRecord r = played_game();
  const std::size_t k = a_shot(r);
  double& speed = std::get<Shoot>(r.actions[k].action).strike.speed;
  speed = std::nextafter(speed, 0.0);
  ReplayReport rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.action, k);
  EXPECT_EQ(rep.where, action_path(k) + ".action.strike.speed");
  EXPECT_NE(rep.message.find("noise"), std::string::npos) << rep.message;

  // A different noise seed gives a different executed strike.
  r = played_game();
  r.actions[k].noise_seed += 1;
  rep = replay(r);
  EXPECT_EQ(rep.action, k);
  EXPECT_EQ(rep.where.substr(0, (action_path(k) + ".action.strike").size()),
            action_path(k) + ".action.strike");

  // So does a different noise model of the acting seat (at the first shot).
  r = played_game();
  const std::size_t b = first_shot(r);
  r.noise[static_cast<std::size_t>(r.actions[b].player)].phi *= 2.0;
  rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.where, action_path(b) + ".action.strike.phi");
  EXPECT_NE(rep.message.find("noise[" + std::to_string(r.actions[b].player) + "]"),
            std::string::npos)
      << rep.message;
}

TEST(RecordReplay, TamperedNoiseOfTheOtherSeatIsNamedAtItsFirstShot) {
  GameRecord r = played_game();
  const int breaker = r.actions[first_shot(r)].player;
  const int other = 1 - breaker;
  std::size_t k = r.actions.size();
  for (std::size_t i = 0; i < r.actions.size(); ++i) {
    if (r.actions[i].player == other && std::holds_alternative<Shoot>(r.actions[i].action)) {
      k = i;
      break;
    }
  }
  ASSERT_LT(k, r.actions.size()) << "the other seat never shot";
  r.noise[static_cast<std::size_t>(other)].speed *= 2.0;
  const ReplayReport rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.action, k);  // the breaker's shots before it still replay
  EXPECT_EQ(rep.actions_identical, k);
  EXPECT_EQ(rep.where, action_path(k) + ".action.strike.speed");

  // The two seats' models swapped: both tournament here, so nothing changes...
  r = played_game();
  ASSERT_EQ(r.noise[0], r.noise[1]);
  std::swap(r.noise[0], r.noise[1]);
  EXPECT_TRUE(replay(r).identical);
  // ...but a seat without noise is caught at its first shot.
  r.noise[static_cast<std::size_t>(breaker)] = NoiseModel{};
  const ReplayReport none = replay(r);
  EXPECT_FALSE(none.identical);
  EXPECT_EQ(none.action, first_shot(r));
}

TEST(RecordReplay, TamperedStartIsNamed) {
  GameRecord r = played_game();
  r.start.position[5].x += 1e-12;
  ReplayReport rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_FALSE(rep.action.has_value());
  EXPECT_EQ(rep.actions_identical, 0u);
  EXPECT_EQ(rep.where, "start.position[5][0]");
  EXPECT_NE(rep.message.find("start"), std::string::npos) << rep.message;

  r = played_game();
  r.start.rack_seed += 1;  // another rack altogether
  rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.where.substr(0, 6), "start.") << rep.where;
}

TEST(RecordReplay, WrongPlayerIsNamed) {
  GameRecord r = played_game();
  const std::size_t k = a_shot(r);
  r.actions[k].player = 1 - r.actions[k].player;
  const ReplayReport rep = replay(r);
  EXPECT_EQ(rep.action, k);
  EXPECT_EQ(rep.where, action_path(k) + ".player");
}

TEST(RecordReplay, RefusedActionIsReportedNotThrown) {
  GameRecord r = played_game();
  const std::size_t k = first_shot(r);
  // A decision where a shot is due.
  r.actions[k].action = Decide{Choice::respot_eight};
  r.actions[k].intended.reset();
  ReplayReport rep;
  EXPECT_NO_THROW(rep = replay(r));
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.action, k);
  EXPECT_EQ(rep.where, action_path(k) + ".action");
  EXPECT_NE(rep.replayed.find("not allowed"), std::string::npos) << rep.replayed;
}

TEST(RecordReplay, ExtraActionAfterTheEndIsRefused) {
  GameRecord r = played_game();
  r.actions.push_back(r.actions.back());
  const ReplayReport rep = replay(r);
  EXPECT_FALSE(rep.identical);
  EXPECT_EQ(rep.action, r.actions.size() - 1);
}

TEST(RecordReplay, AForfeitEndsAGameTheRulesHadNotEnded) {
  GameRecord r = played_game();
  r.actions.resize(r.actions.size() / 2);
  r.ending = forfeit_of(1);
  const ReplayReport rep = replay(read_ok(write_record(r)));
  EXPECT_TRUE(rep.identical) << rep.message;
  EXPECT_NE(rep.final_state.phase, Phase::game_over);
  // A game the rules ended cannot also end by a forfeit.
  GameRecord over = played_game();
  over.ending = forfeit_of(1);
  const ReplayReport both = replay(over);
  EXPECT_FALSE(both.identical);
  EXPECT_EQ(both.where, "ending");
  EXPECT_EQ(both.actions_identical, over.actions.size());
  EXPECT_NE(both.replayed.find("the rules ended the game first"), std::string::npos)
      << both.replayed;
}

TEST(RecordReplay, ShortenedRecordIsIdenticalButNotOver) {
  GameRecord r = played_game();
  r.actions.resize(r.actions.size() / 2);
  const ReplayReport rep = replay(r);
  EXPECT_TRUE(rep.identical) << rep.message;
  EXPECT_NE(rep.final_state.phase, Phase::game_over);
}

}  // namespace

}  // namespace test_record

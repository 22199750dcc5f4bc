// Game records across physics changes (issue 22): version 1 records,
// written before the engine and the physics were recorded, read as played
// with the legacy physics and replay identical; version 2 records carry
// the engine and the physics and round-trip; records nobody can replay
// are refused with their version in the message; games played with other
// physics record it and replay on it. The version 1 files are in
// tests/data/records_v1 (its README says how they were made).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/version.hpp"

namespace test_record_versions {

namespace {

using namespace breakshot;
using ojson = nlohmann::ordered_json;

/// A file of tests/data/records_v1 (or of another folder of tests/data).
std::string data_file(const std::string& name, const std::string& folder = "records_v1") {
  const std::string path = std::string(BREAKSHOT_SOURCE_DIR) + "/tests/data/" + folder + "/" + name;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

GameRecord read_ok(const std::string& text) {
  auto parsed = read_record(text);
  if (const auto* err = std::get_if<RecordError>(&parsed)) {
    ADD_FAILURE() << err->path << ": " << err->reason;
    return {};
  }
  return std::get<GameRecord>(parsed);
}

RecordError read_error(const std::string& text) {
  auto parsed = read_record(text);
  if (const auto* err = std::get_if<RecordError>(&parsed)) return *err;
  ADD_FAILURE() << "accepted: " << text.substr(0, 300);
  return {};
}

/// The header lines version 2 adds for the legacy physics, as the writer
/// prints them.
const std::string kLegacyPhysicsLine =
    "  \"physics\": {\"cushion_model\":\"han_2005_v0\",\"ball_ball_model\":\"friction\","
    "\"ball_ball_friction\":{\"a\":0.009951,\"b\":0.108,\"c\":1.088}},\n";

/// A version 1 record's text as version 2 writes the same game made by
/// breakshot `engine` with the legacy physics: the version, then the
/// engine after it and the physics after the config; nothing else moves.
std::string as_version_2(std::string v1, const std::string& engine) {
  const std::string version = "  \"version\": 1,\n";
  const std::size_t at = v1.find(version);
  EXPECT_NE(at, std::string::npos);
  v1.replace(at, version.size(),
             "  \"version\": 2,\n  \"engine\": {\"version\":\"" + engine + "\"},\n");
  const std::size_t config = v1.find("  \"config\": ");
  const std::size_t after = v1.find('\n', config) + 1;
  v1.insert(after, kLegacyPhysicsLine);
  return v1;
}

/// A record's text with the words of its rulings and results left out
/// (read, emptied, written again): what a later version still writes byte
/// for byte, the words being put better since.
std::string without_words(const std::string& text) {
  GameRecord r = read_ok(text);
  for (RecordedAction& a : r.actions) {
    a.ruling.text.clear();
    a.after.result.clear();
  }
  return write_record(r);
}

const char* const kV1Files[] = {"nine_ball_club_seed1_game1.json",
                                "eight_ball_club_seed1_game1.json"};

// ---------------------------------------------------------------------------
// Version 1

TEST(RecordVersions, Version1RecordsReadAsLegacyPhysicsAndReplayIdentical) {
  for (const char* name : kV1Files) {
    const std::string text = data_file(name);
    ASSERT_NE(text.find("\"version\": 1,"), std::string::npos) << name;
    const GameRecord r = read_ok(text);
    EXPECT_EQ(r.engine, "0.1.0") << name;
    EXPECT_TRUE(r.config.physics == kLegacyGamePhysics) << name;
    EXPECT_EQ(r.config.physics.cushion_model, CushionModel::han_2005_v0);
    EXPECT_EQ(r.config.physics.ball_ball_model, BallBallModel::friction);
    EXPECT_TRUE(r.config.physics.ball_ball_friction_fit);
    EXPECT_TRUE(r.config.physics.ball_ball_friction_curve == kThrowFitTPA28);
    const ReplayReport rep = replay(r);
    EXPECT_TRUE(rep.identical) << name << ": " << rep.message;
    EXPECT_EQ(rep.actions_identical, r.actions.size()) << name;
    EXPECT_GT(r.actions.size(), 5u) << name;
  }
}

TEST(RecordVersions, Version1RecordIsRewrittenAsVersion2WithTheLegacyHeader) {
  for (const char* name : kV1Files) {
    const std::string v1 = data_file(name);
    const std::string v2 = write_record(read_ok(v1));
    EXPECT_EQ(v2, as_version_2(v1, "0.1.0")) << name;
    EXPECT_TRUE(read_ok(v2) == read_ok(v1)) << name;
  }
}

TEST(RecordVersions, LegacyGamesGiveTheRecordsTheyGaveBefore) {
  // The games of the version 1 files, played now with the legacy physics:
  // the same bytes apart from the version 2 header and the words.
  for (const GameType game : {GameType::nine_ball, GameType::eight_ball}) {
    MatchOptions opt;
    opt.game = game;
    opt.players = {"club", "club"};
    opt.games = 1;
    opt.seed = 1;
    opt.noise = parse_noise("none");
    opt.physics = kLegacyGamePhysics;
    auto p0 = make_player("club");
    auto p1 = make_player("club");
    std::vector<std::string> records;
    (void)play_match(opt, *p0, *p1,
                     [&](int, const GameRecord& r) { records.push_back(write_record(r)); });
    ASSERT_EQ(records.size(), 1u);
    const std::string name = std::string(to_string(game)) + "_club_seed1_game1.json";
    EXPECT_EQ(without_words(records[0]),
              without_words(as_version_2(data_file(name), std::string(kVersion))))
        << name;
    EXPECT_EQ(records[0].find("Foul ("), std::string::npos) << name;
  }
}

TEST(RecordVersions, LegacyPhysicsKeepsTheSummarysGames) {
  // The summary of `breakshot match --game nine_ball --players club,club
  // --games 3 --seed 1 --noise none` before record version 2. The default
  // physics has changed since; the legacy physics, named, gives these
  // games again, and the summary adds only the physics it names.
  MatchOptions opt;
  opt.physics = kLegacyGamePhysics;
  opt.game = GameType::nine_ball;
  opt.players = {"club", "club"};
  opt.games = 3;
  opt.seed = 1;
  opt.noise = parse_noise("none");
  auto p0 = make_player("club");
  auto p1 = make_player("club");
  nlohmann::ordered_json got = nlohmann::ordered_json::parse(match_summary_json(play_match(opt, *p0, *p1)));
  ASSERT_TRUE(got.contains("physics"));
  EXPECT_EQ(got["physics"]["cushion_model"], "han_2005_v0");
  got.erase("physics");
  EXPECT_EQ(got.dump(2) + "\n", data_file("nine_ball_club_seed1_summary.json"));
}

// ---------------------------------------------------------------------------
// Version 2 records written before the spinning friction was recorded
// (tests/data/records_v2/README.md): played with 0.044, which they do not
// name.

TEST(RecordVersions, RecordsWrittenBeforeTheSpinningFrictionReplayOnIt) {
  struct File {
    GameType game;
    const char* name;
  };
  for (const File& f : {File{GameType::nine_ball, "nine_ball_club_seed1_game1.json"},
                        File{GameType::three_cushion, "three_cushion_club_seed1_game1.json"}}) {
    const std::string text = data_file(f.name, "records_v2");
    ASSERT_EQ(text.find("spinning_friction"), std::string::npos) << f.name;
    const GameRecord r = read_ok(text);
    EXPECT_EQ(r.config.physics.spinning_friction, kLegacySpinningFriction) << f.name;
    GamePhysics then;  // the defaults of the time
    then.spinning_friction = kLegacySpinningFriction;
    EXPECT_TRUE(r.config.physics == then) << f.name;
    const ReplayReport rep = replay(r);
    EXPECT_TRUE(rep.identical) << f.name << ": " << rep.message;
    EXPECT_GT(r.actions.size(), 4u) << f.name;
    EXPECT_EQ(write_record(r), text) << f.name;

    // The same game played now on that physics, by name: the same bytes.
    MatchOptions opt;
    opt.game = f.game;
    opt.table_size = r.config.table_size;
    opt.carom = r.config.carom;
    opt.physics = then;
    opt.players = {"club", "club"};
    opt.seed = 1;
    opt.noise = parse_noise("tournament");
    auto p0 = make_player("club");
    auto p1 = make_player("club");
    std::vector<std::string> records;
    (void)play_match(opt, *p0, *p1,
                     [&](int, const GameRecord& g) { records.push_back(write_record(g)); });
    ASSERT_EQ(records.size(), 1u);
    EXPECT_EQ(records[0], text) << f.name;

    // On the measured spinning friction the recorded shots come out
    // otherwise: the record does depend on what it leaves out.
    GameRecord now = r;
    now.config.physics.spinning_friction = kSpinningFriction;
    EXPECT_FALSE(replay(now).identical) << f.name;
  }
}

// ---------------------------------------------------------------------------
// Version 2

GameRecord small_record() {
  GameConfig config;
  config.game = GameType::nine_ball;
  const Rules rules(config);
  GameRecord r;
  r.config = config;
  r.players = {"a", "b"};
  r.seed = 7;
  r.start = rules.start(11, 0);
  return r;
}

TEST(RecordVersions, Version2RoundTripKeepsTheEngineAndThePhysics) {
  GameRecord r = small_record();
  EXPECT_EQ(r.engine, std::string(kVersion));  // a new record: this build
  r.engine = "0.0.7";
  r.config.physics.cushion_model = CushionModel::mathavan_2010;
  r.config.physics.ball_ball_model = BallBallModel::mathavan_2014;
  r.config.physics.ball_ball_friction_curve = kThrowFitTPB3;
  const std::string text = write_record(r);
  EXPECT_NE(text.find("\n  \"version\": 2,\n  \"engine\": {\"version\":\"0.0.7\"},\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\n  \"physics\": {\"cushion_model\":\"mathavan_2010\","
                      "\"ball_ball_model\":\"mathavan_2014\","
                      "\"ball_ball_friction\":{\"a\":0.016,\"b\":0.219,\"c\":0.691},"
                      "\"airborne\":true,\"spinning_friction\":0.0117},\n"),
            std::string::npos)
      << text;
  const GameRecord back = read_ok(text);
  EXPECT_TRUE(back == r);
  EXPECT_EQ(back.engine, "0.0.7");
  EXPECT_TRUE(back.config.physics == r.config.physics);
  EXPECT_EQ(write_record(back), text);

  // A constant friction is a number.
  r.config.physics.ball_ball_friction_fit = false;
  r.config.physics.ball_ball_friction_curve = FrictionCurve{};
  r.config.physics.ball_ball_friction = 0.06;
  const std::string constant = write_record(r);
  EXPECT_NE(constant.find("\"ball_ball_friction\":0.06,\"airborne\":true,"), std::string::npos)
      << constant;
  EXPECT_TRUE(read_ok(constant) == r);
  EXPECT_EQ(write_record(read_ok(constant)), constant);

  // The spinning friction: written unless it is breakshot 0.1's 0.044, and
  // read as 0.044 when absent (the records written before it was recorded).
  r.config.physics.spinning_friction = kLegacySpinningFriction;
  const std::string old_spin = write_record(r);
  EXPECT_EQ(old_spin.find("spinning_friction"), std::string::npos) << old_spin;
  EXPECT_TRUE(read_ok(old_spin) == r);
  r.config.physics.spinning_friction = 0.02;
  EXPECT_TRUE(read_ok(write_record(r)) == r);
  for (const char* bad : {"0", "-0.01", "\"fast\""}) {
    std::string text_bad = write_record(r);
    const std::size_t at = text_bad.find("\"spinning_friction\":0.02");
    ASSERT_NE(at, std::string::npos);
    text_bad.replace(at, 24, std::string("\"spinning_friction\":") + bad);
    const auto parsed = read_record(text_bad);
    ASSERT_TRUE(std::holds_alternative<RecordError>(parsed)) << bad;
    EXPECT_EQ(std::get<RecordError>(parsed).path, "physics.spinning_friction") << bad;
  }
  r.config.physics.spinning_friction = kSpinningFriction;

  // The engine takes part in equality: a record says who made it.
  GameRecord other = r;
  other.engine = "0.0.8";
  EXPECT_FALSE(other == r);
}

TEST(RecordVersions, UnreplayableRecordsAreRefusedWithTheirVersion) {
  GameRecord r = small_record();
  r.engine = "0.1.0";
  const ojson good = ojson::parse(write_record(r));
  struct Case {
    const char* name;
    std::function<void(ojson&)> mutate;
    std::string path;
    std::vector<std::string> said;  // every one must be in the reason
  };
  const std::vector<Case> cases = {
      {"cushion model of a newer engine",
       [](ojson& j) {
         j["engine"]["version"] = "0.3.0";
         j["physics"]["cushion_model"] = "cushion_law_of_2099";
       },
       "physics.cushion_model",
       {"unknown cushion model \"cushion_law_of_2099\"", "version 2 record",
        "made by breakshot 0.3.0, a newer version",
        "this breakshot (" + std::string(kVersion) + ")"}},
      {"unknown cushion model",
       [](ojson& j) { j["physics"]["cushion_model"] = "han_2006"; },
       "physics.cushion_model",
       {"unknown cushion model \"han_2006\"", "made by breakshot 0.1.0", "version 2 record"}},
      {"ball-ball model of a newer engine",
       [](ojson& j) {
         j["engine"]["version"] = "1.0.0";
         j["physics"]["ball_ball_model"] = "hertz";
       },
       "physics.ball_ball_model",
       {"unknown ball-ball model \"hertz\"", "made by breakshot 1.0.0, a newer version"}},
      {"physics field of a newer engine",
       [](ojson& j) {
         j["engine"]["version"] = "0.2.0";
         j["physics"]["jump"] = true;
       },
       "physics.jump",
       {"unknown field", "made by breakshot 0.2.0, a newer version"}},
      {"friction that is no curve",
       [](ojson& j) { j["physics"]["ball_ball_friction"]["b"] = 2.0; },
       "physics.ball_ball_friction.b",
       {"must be in [0, 1]", "made by breakshot 0.1.0"}},
      {"negative constant friction",
       [](ojson& j) { j["physics"]["ball_ball_friction"] = -0.1; },
       "physics.ball_ball_friction",
       {"must be >= 0"}},
      {"record version of a newer engine",
       [](ojson& j) {
         j["version"] = 4;
         j["engine"]["version"] = "0.4.0";
       },
       "version",
       {"not version 4", "made by breakshot 0.4.0", "versions 1 to 3"}},
      {"version 0", [](ojson& j) { j["version"] = 0; }, "version", {"not version 0"}},
      {"version 2 without physics",
       [](ojson& j) { j.erase("physics"); },
       "physics",
       {"missing required field"}},
      {"version 2 without engine",
       [](ojson& j) { j.erase("engine"); },
       "engine",
       {"missing required field"}},
      {"empty engine",
       [](ojson& j) { j["engine"]["version"] = ""; },
       "engine.version",
       {"a library version"}},
      {"version 1 with physics", [](ojson& j) { j["version"] = 1; }, "engine", {"unknown field"}},
  };
  for (const Case& c : cases) {
    ojson doc = good;
    c.mutate(doc);
    const RecordError err = read_error(doc.dump());
    EXPECT_EQ(err.path, c.path) << c.name << ": " << err.reason;
    for (const std::string& s : c.said) {
      EXPECT_NE(err.reason.find(s), std::string::npos) << c.name << ": " << err.reason;
    }
  }
}

// ---------------------------------------------------------------------------
// Games with other physics

TEST(RecordVersions, RulesPlayTheGamesPhysics) {
  GameConfig config;
  config.physics.cushion_model = CushionModel::mathavan_2010;
  config.physics.ball_ball_model = BallBallModel::mathavan_2014;
  config.physics.ball_ball_friction_curve = kThrowFitTPB3;
  const Rules rules(config);
  const Scenario sc = rules.shot_scenario(rules.start(1, 0), CueStrike{});
  EXPECT_EQ(sc.table.cushion.model, CushionModel::mathavan_2010);
  // Mathavan et al. 2010's own constants, as a scenario's reader sets them.
  EXPECT_EQ(sc.table.cushion.nose_height, kMathavanNoseHeight);
  for (const BallSpec& b : sc.balls) EXPECT_EQ(b.wall_restitution, kMathavanRestitution);
  EXPECT_EQ(sc.physics.ball_ball_model, BallBallModel::mathavan_2014);
  EXPECT_TRUE(sc.physics.ball_ball_friction_fit);
  EXPECT_TRUE(sc.physics.ball_ball_friction_curve == kThrowFitTPB3);

  // The legacy physics: the scenario every game of breakshot 0.1 played.
  GameConfig old;
  old.physics = kLegacyGamePhysics;
  const Rules legacy(old);
  const Scenario ls = legacy.shot_scenario(legacy.start(1, 0), CueStrike{});
  EXPECT_EQ(ls.table.cushion.model, CushionModel::han_2005_v0);
  EXPECT_EQ(ls.table.cushion.nose_height, CushionParams{}.nose_height);
  for (const BallSpec& b : ls.balls) EXPECT_EQ(b.wall_restitution, 0.75);
  EXPECT_TRUE(ls.physics.ball_ball_friction_curve == kThrowFitTPA28);
  EXPECT_FALSE(ls.physics.airborne);
  // The default: han_2005 at 0.84, TP B-3, balls that may leave the cloth.
  const Rules now(GameConfig{});
  const Scenario ns = now.shot_scenario(now.start(1, 0), CueStrike{});
  EXPECT_EQ(ns.table.cushion.model, CushionModel::han_2005);
  for (const BallSpec& b : ns.balls) EXPECT_EQ(b.wall_restitution, 0.84);
  EXPECT_TRUE(ns.physics.ball_ball_friction_curve == kThrowFitTPB3);
  EXPECT_TRUE(ns.physics.airborne);

  GameConfig bad;
  bad.physics.ball_ball_friction_curve = {0.5, 0.9, 1.0};  // mu(0) = 1.4
  EXPECT_THROW((void)Rules(bad), std::invalid_argument);
  bad.physics.ball_ball_friction_fit = false;
  bad.physics.ball_ball_friction = -1.0;
  EXPECT_THROW((void)Rules(bad), std::invalid_argument);
}

GameRecord play_one(GameType game, const GamePhysics& physics, std::uint64_t seed) {
  GameConfig config;
  config.game = game;
  config.physics = physics;
  const Rules rules(config);
  auto p0 = make_player("club");
  auto p1 = make_player("club");
  return play_game(rules, *p0, *p1, 0, seed, parse_noise("tournament"));
}

TEST(RecordVersions, GamesWithOtherPhysicsRecordItAndReplayOnIt) {
  GamePhysics mathavan;
  mathavan.cushion_model = CushionModel::mathavan_2010;
  mathavan.ball_ball_friction_curve = kThrowFitTPB3;
  GamePhysics han;
  han.cushion_model = CushionModel::han_2005;
  han.ball_ball_model = BallBallModel::mathavan_2014;
  han.ball_ball_friction_fit = false;
  han.ball_ball_friction_curve = FrictionCurve{};
  han.ball_ball_friction = 0.06;
  for (const GamePhysics& physics : {mathavan, han}) {
    const GameRecord r = play_one(GameType::nine_ball, physics, 5);
    ASSERT_FALSE(r.actions.empty());
    EXPECT_TRUE(r.config.physics == physics);
    const std::string text = write_record(r);
    const GameRecord back = read_ok(text);
    EXPECT_TRUE(back == r);
    const ReplayReport rep = replay(back);
    EXPECT_TRUE(rep.identical) << rep.message;

    // The physics is what the game was played with: the same seed on the
    // legacy physics plays another game, and the record replayed on the
    // legacy physics differs, named at a shot.
    const GameRecord legacy = play_one(GameType::nine_ball, kLegacyGamePhysics, 5);
    EXPECT_FALSE(legacy == r);
    GameRecord relabelled = back;
    relabelled.config.physics = kLegacyGamePhysics;
    const ReplayReport other = replay(relabelled);
    EXPECT_FALSE(other.identical);
    ASSERT_TRUE(other.action.has_value());
    EXPECT_NE(other.where.find("actions["), std::string::npos) << other.message;
  }
}

// ---------------------------------------------------------------------------
// Summaries

TEST(RecordVersions, SummaryShowsThePhysicsOnlyWhenNotTheDefault) {
  MatchOptions opt;
  opt.game = GameType::nine_ball;
  opt.players = {"club", "club"};
  const std::array<NoiseModel, 2> noise{};
  const std::string plain = match_summary_json(empty_summary(opt, noise));
  EXPECT_EQ(plain.find("physics"), std::string::npos);

  opt.physics.cushion_model = CushionModel::mathavan_2010;
  opt.physics.ball_ball_friction_curve = kThrowFitTPB3;
  const MatchSummary s = empty_summary(opt, noise);
  const std::string text = match_summary_json(s);
  EXPECT_NE(text.find("\"table_size\": \"9ft\",\n  \"physics\": {\n    \"cushion_model\": "
                      "\"mathavan_2010\""),
            std::string::npos)
      << text;
  const MatchSummary back = read_match_summary(text);
  EXPECT_TRUE(back.physics == s.physics);
  EXPECT_EQ(match_summary_json(back), text);

  // Chunks of matches with different physics are different matches.
  MatchOptions legacy = opt;
  legacy.physics = kLegacyGamePhysics;
  MatchSummary into = empty_summary(legacy, noise);
  try {
    add_summary(into, s);
    ADD_FAILURE() << "added";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("physics"), std::string::npos) << e.what();
  }

  // The default physics is never written, so it is not read either.
  ojson doc = ojson::parse(text);
  doc["physics"] = ojson::parse(
      "{\"cushion_model\":\"han_2005\",\"ball_ball_model\":\"friction\","
      "\"ball_ball_friction\":{\"a\":0.016,\"b\":0.219,\"c\":0.691},\"airborne\":true,"
      "\"spinning_friction\":0.0117}");
  EXPECT_THROW((void)read_match_summary(doc.dump(2)), std::invalid_argument);
  // Without "spinning_friction" it is the legacy one's, not the default.
  doc["physics"].erase("spinning_friction");
  const MatchSummary old_spin = read_match_summary(doc.dump(2));
  EXPECT_EQ(old_spin.physics.spinning_friction, kLegacySpinningFriction);
}

TEST(RecordCorpus, EverySeedRecordReplays) {
  // The fuzzer's seed records (fuzz/record_corpus) are games this engine
  // plays: each reads and replays identical, versions 1, 2 and 3 alike.
  const std::filesystem::path folder =
      std::filesystem::path(BREAKSHOT_SOURCE_DIR) / "fuzz" / "record_corpus";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(folder)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 6u);
  std::array<int, 4> versions{};
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    auto parsed = read_record(text);
    if (const auto* err = std::get_if<RecordError>(&parsed)) {
      ADD_FAILURE() << file.filename() << ": " << err->path << ": " << err->reason;
      continue;
    }
    const GameRecord& r = std::get<GameRecord>(parsed);
    ++versions.at(static_cast<std::size_t>(r.version));
    EXPECT_FALSE(r.actions.empty()) << file.filename();
    const ReplayReport rep = replay(r);
    EXPECT_TRUE(rep.identical) << file.filename() << ": " << rep.message;
  }
  // Every version's reader keeps seeds of its own.
  EXPECT_GE(versions[1], 1);
  EXPECT_GE(versions[2], 1);
  EXPECT_GE(versions[3], 1);
}

TEST(RecordVersions, AReplayThatDiffersNamesTheVersionAndTheEngine) {
  const std::filesystem::path file = std::filesystem::path(BREAKSHOT_SOURCE_DIR) / "fuzz" /
                                     "record_corpus" / "nine_ball_3_actions.json";
  std::ifstream in(file, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  GameRecord v1 = read_ok(text);
  EXPECT_EQ(v1.version, 1);
  ASSERT_FALSE(v1.actions.empty());
  v1.actions[0].after.shots += 1;
  ReplayReport rep = replay(v1);
  EXPECT_FALSE(rep.identical);
  EXPECT_NE(rep.message.find("(a version 1 record made by breakshot 0.1.0"), std::string::npos)
      << rep.message;

  // A version 2 record of another engine, whose physics names this build
  // reads: the message says whose it is, never a plain "differs".
  GameRecord other = read_ok(write_record(v1));
  EXPECT_EQ(other.version, 2);
  other.engine = "0.0.9";
  rep = replay(other);
  EXPECT_FALSE(rep.identical);
  EXPECT_NE(rep.message.find("(a version 2 record made by breakshot 0.0.9; this is breakshot " +
                             std::string(kVersion) + ", another engine"),
            std::string::npos)
      << rep.message;
}

}  // namespace

}  // namespace test_record_versions

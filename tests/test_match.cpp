// Matches: games played to the end, recorded, replayable and summed up
// (include/breakshot/match.hpp), and the `match` and `replay` commands.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/record.hpp"
#include "breakshot/players.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/record_io.hpp"

namespace test_match {

namespace {

namespace fs = std::filesystem;
using namespace breakshot;
using nlohmann::json;
using ojson = nlohmann::ordered_json;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A fresh directory per test, removed afterwards.
fs::path fresh_dir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       ("breakshot-" + tag + "-" + std::to_string(::getpid()) + "-" +
                        info->test_suite_name() + "-" + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

GameRecord read_file(const fs::path& p) {
  auto parsed = read_record(slurp(p));
  if (const auto* err = std::get_if<RecordError>(&parsed)) {
    ADD_FAILURE() << p << ": " << err->path << ": " << err->reason;
    return {};
  }
  return std::get<GameRecord>(parsed);
}

MatchOptions options(GameType game, int games, std::uint64_t seed) {
  MatchOptions o;
  o.game = game;
  o.players = {"baseline", "baseline"};
  o.games = games;
  o.seed = seed;
  o.noise = parse_noise("tournament");
  return o;
}

/// Plays a short match writing the records, and checks everything that
/// must hold whatever the players do.
void check_short_match(GameType game) {
  const fs::path dir = fresh_dir("match");
  MatchOptions o = options(game, 4, 11);
  const std::string records = (dir / "records").string();
  const MatchSummary summary = play_match(o, record_files(records));  // creates the folder

  EXPECT_EQ(summary.games_played, 4);
  EXPECT_EQ(summary.players[0].games_won + summary.players[1].games_won + summary.draws, 4);
  MatchSummary again = empty_summary(o);
  int shots = 0;
  int innings = 0;
  int fouls = 0;
  for (int g = 0; g < 4; ++g) {
    const fs::path file = fs::path(records) / ("game-000" + std::to_string(g + 1) + ".json");
    ASSERT_TRUE(fs::exists(file)) << file;
    const GameRecord r = read_file(file);
    EXPECT_EQ(r.config.game, game);
    EXPECT_EQ(r.start.breaker, g % 2) << "breaks alternate";
    EXPECT_EQ(r.seed, mix_seed(o.seed, static_cast<std::uint64_t>(g)));
    // Baseline players have no noise of their own: both seats shoot with
    // the match's.
    EXPECT_EQ(r.noise[0], o.noise);
    EXPECT_EQ(r.noise[1], o.noise);
    ASSERT_FALSE(r.actions.empty());
    const GameState& end = r.actions.back().after;
    EXPECT_EQ(end.phase, Phase::game_over);
    for (std::size_t i = 0; i < r.actions.size(); ++i) {
      EXPECT_EQ(r.actions[i].noise_seed, mix_seed(r.seed, i));
      EXPECT_EQ(r.actions[i].intended.has_value(),
                std::holds_alternative<Shoot>(r.actions[i].action));
      fouls += static_cast<int>(r.actions[i].ruling.fouls.size());
    }
    const ReplayReport rep = replay(r);
    EXPECT_TRUE(rep.identical) << file << ": " << rep.message;
    shots += end.shots;
    innings += end.innings;
    add_game(again, r);
  }
  // The summary is a function of the records.
  EXPECT_EQ(match_summary_json(again), match_summary_json(summary));
  // Totals agree with the game states.
  const PlayerStats& a = summary.players[0];
  const PlayerStats& b = summary.players[1];
  EXPECT_EQ(a.shots + b.shots, shots);
  EXPECT_EQ(a.innings + b.innings, innings);
  EXPECT_GE(a.breaks, 2);  // each breaks twice, more after re-racks
  EXPECT_GE(b.breaks, 2);
  int counted = 0;
  for (const auto& [kind, n] : a.fouls) counted += n;
  for (const auto& [kind, n] : b.fouls) counted += n;
  EXPECT_EQ(counted, fouls);
  EXPECT_LE(a.break_and_runs, a.games_won);
  EXPECT_LE(b.break_and_runs, b.games_won);
  EXPECT_GT(a.balls_pocketed + b.balls_pocketed, 0);
  fs::remove_all(dir);
}

TEST(Match, ShortEightBallMatchRunsAndReplays) { check_short_match(GameType::eight_ball); }

TEST(Match, ShortNineBallMatchRunsAndReplays) { check_short_match(GameType::nine_ball); }

TEST(Match, ManyGamesRoundTripAndReplay) {
  // More games, in memory, for the rarer rulings (re-racks, the 8 on the
  // break, three fouls): every record reads back to the same bytes and
  // replays identical.
  for (const GameType game : {GameType::eight_ball, GameType::nine_ball}) {
    GameConfig config;
    config.game = game;
    const Rules rules(config);
    auto p0 = make_player("baseline");
    auto p1 = make_player("baseline");
    for (std::uint64_t g = 0; g < 24; ++g) {
      const GameRecord r = play_game(rules, *p0, *p1, static_cast<int>(g % 2), 1000 + g,
                                     parse_noise("tournament"));
      const std::string text = write_record(r);
      auto parsed = read_record(text);
      ASSERT_TRUE(std::holds_alternative<GameRecord>(parsed))
          << std::get<RecordError>(parsed).path << ": " << std::get<RecordError>(parsed).reason;
      const GameRecord& back = std::get<GameRecord>(parsed);
      EXPECT_TRUE(back == r) << g;
      EXPECT_EQ(write_record(back), text) << g;
      const ReplayReport rep = replay(back);
      EXPECT_TRUE(rep.identical) << to_string(game) << " game " << g << ": " << rep.message;
    }
  }
}

TEST(Match, SameSeedSameSummaryAndRecords) {
  const fs::path dir = fresh_dir("match");
  MatchOptions o = options(GameType::nine_ball, 2, 99);
  const std::string a = match_summary_json(play_match(o, record_files((dir / "a").string())));
  const std::string b = match_summary_json(play_match(o, record_files((dir / "b").string())));
  EXPECT_EQ(a, b);
  for (const char* name : {"game-0001.json", "game-0002.json"}) {
    EXPECT_EQ(slurp(dir / "a" / name), slurp(dir / "b" / name)) << name;
  }
  o.seed = 100;
  (void)play_match(o, record_files((dir / "c").string()));
  EXPECT_NE(slurp(dir / "a" / "game-0001.json"), slurp(dir / "c" / "game-0001.json"));
  fs::remove_all(dir);
}

TEST(Match, SummaryJsonHasEveryField) {
  MatchOptions o = options(GameType::eight_ball, 1, 5);
  const json j = json::parse(match_summary_json(play_match(o)));
  for (const char* key : {"game", "table_size", "seed", "noise", "games_played", "draws",
                          "players"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["game"], "eight_ball");
  EXPECT_EQ(j["seed"], "5");
  EXPECT_EQ(j["noise"], "tournament");
  ASSERT_EQ(j["players"].size(), 2u);
  for (const json& p : j["players"]) {
    for (const char* key : {"name", "noise", "games_won", "breaks", "break_and_runs", "innings",
                            "shots", "balls_pocketed", "balls_per_inning", "fouls"}) {
      EXPECT_TRUE(p.contains(key)) << key;
    }
    EXPECT_EQ(p["name"], "baseline");
    EXPECT_EQ(p["noise"], "tournament");  // the baseline has none of its own: the match's
    for (const char* foul : {"scratch", "no_contact", "wrong_ball_first", "no_rail",
                             "illegal_break", "behind_head_string"}) {
      EXPECT_TRUE(p["fouls"].contains(foul)) << foul;
    }
  }
}

TEST(Match, SummaryPlayerNoiseIsTheEffectiveNoise) {
  MatchOptions o = options(GameType::nine_ball, 1, 5);
  o.noise = parse_noise("2x");
  const MatchSummary s = empty_summary(o);
  EXPECT_EQ(s.noise, o.noise);
  EXPECT_EQ(s.players[0].noise, "2x");
  EXPECT_EQ(s.players[1].noise, "2x");
  // The key order of a player: its name, then its noise.
  const ojson j = ojson::parse(match_summary_json(s));
  EXPECT_EQ(j["noise"], "2x");
  auto key = j["players"][0].begin();
  EXPECT_EQ(key.key(), "name");
  ++key;
  EXPECT_EQ(key.key(), "noise");
  o.players[1] = "nobody";
  EXPECT_THROW((void)empty_summary(o), std::invalid_argument);
}

TEST(Match, StalemateLimitEndsInADraw) {
  GameConfig config;
  config.game = GameType::eight_ball;
  config.max_shots = 2;  // nobody wins 8-ball in two shots
  const Rules rules(config);
  auto p0 = make_player("baseline");
  auto p1 = make_player("baseline");
  const GameRecord r = play_game(rules, *p0, *p1, 1, 3, NoiseModel{});
  const GameState& end = r.actions.back().after;
  EXPECT_EQ(end.phase, Phase::game_over);
  EXPECT_EQ(end.winner, -1);
  EXPECT_EQ(end.shots, 2);
  EXPECT_EQ(r.start.breaker, 1);
  EXPECT_TRUE(replay(r).identical);
  MatchOptions o = options(GameType::eight_ball, 1, 0);
  MatchSummary s = empty_summary(o);
  add_game(s, r);
  EXPECT_EQ(s.draws, 1);
  EXPECT_EQ(s.players[0].games_won + s.players[1].games_won, 0);
  EXPECT_EQ(s.players[1].breaks, 1);
  EXPECT_EQ(s.players[0].break_and_runs + s.players[1].break_and_runs, 0);
}

TEST(Match, NoNoiseMeansExecutedIsIntended) {
  GameConfig config;
  config.game = GameType::nine_ball;
  config.max_shots = 6;
  const Rules rules(config);
  auto p0 = make_player("baseline");
  auto p1 = make_player("baseline");
  const GameRecord r = play_game(rules, *p0, *p1, 0, 8, NoiseModel{});
  for (const RecordedAction& ra : r.actions) {
    if (const auto* shot = std::get_if<Shoot>(&ra.action)) {
      ASSERT_TRUE(ra.intended.has_value());
      EXPECT_TRUE(identical(shot->strike, *ra.intended));
    }
  }
}

/// Always wants to decide, which the rules never allow on a break.
class Stubborn : public Player {
 public:
  std::string name() const override { return "stubborn"; }
  Action decide(const Rules&, const GameState&, std::uint64_t) override {
    return Decide{Choice::respot_eight};
  }
};

/// The baseline player's choices with a noise of its own.
class OwnNoise : public Player {
 public:
  explicit OwnNoise(NoiseModel noise) : noise_(noise) {}
  std::string name() const override { return "own-noise"; }
  Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) override {
    return inner_->decide(rules, state, seed);
  }
  std::optional<NoiseModel> noise() const override { return noise_; }

 private:
  std::unique_ptr<Player> inner_ = make_player("baseline");
  NoiseModel noise_;
};

TEST(Match, PlayerWithItsOwnNoiseShootsWithIt) {
  GameConfig config;
  config.game = GameType::nine_ball;
  const Rules rules(config);
  OwnNoise steady{NoiseModel{}};  // no noise at all, in a tournament-noise match
  auto baseline = make_player("baseline");
  const NoiseModel match_noise = parse_noise("tournament");
  for (const int seat : {0, 1}) {
    Player& p0 = seat == 0 ? static_cast<Player&>(steady) : *baseline;
    Player& p1 = seat == 0 ? *baseline : static_cast<Player&>(steady);
    const GameRecord r = play_game(rules, p0, p1, 0, 77, match_noise);
    const auto own = static_cast<std::size_t>(seat);
    EXPECT_EQ(r.noise[own], NoiseModel{}) << seat;
    EXPECT_EQ(r.noise[1 - own], match_noise) << seat;

    int own_shots = 0;
    int other_shots = 0;
    for (const RecordedAction& ra : r.actions) {
      const auto* shot = std::get_if<Shoot>(&ra.action);
      if (shot == nullptr) continue;
      ASSERT_TRUE(ra.intended.has_value());
      if (ra.player == seat) {
        ++own_shots;
        EXPECT_TRUE(identical(shot->strike, *ra.intended)) << "seat " << seat;
      } else {
        ++other_shots;
        EXPECT_FALSE(identical(shot->strike, *ra.intended)) << "seat " << seat;
      }
    }
    EXPECT_GT(own_shots, 0) << seat;
    EXPECT_GT(other_shots, 0) << seat;

    // The record replays identical, in memory and through the file.
    ReplayReport rep = replay(r);
    EXPECT_TRUE(rep.identical) << seat << ": " << rep.message;
    const std::string text = write_record(r);
    auto parsed = read_record(text);
    ASSERT_TRUE(std::holds_alternative<GameRecord>(parsed));
    EXPECT_TRUE(std::get<GameRecord>(parsed) == r);
    EXPECT_EQ(write_record(std::get<GameRecord>(parsed)), text);
    rep = replay(std::get<GameRecord>(parsed));
    EXPECT_TRUE(rep.identical) << seat << ": " << rep.message;

    // A record claiming the match's noise for that seat too does not.
    GameRecord tampered = r;
    tampered.noise[own] = match_noise;
    rep = replay(tampered);
    EXPECT_FALSE(rep.identical) << seat;
    ASSERT_TRUE(rep.action.has_value());
    EXPECT_EQ(r.actions[*rep.action].player, seat);
    EXPECT_TRUE(std::holds_alternative<Shoot>(r.actions[*rep.action].action));
    const std::string strike_path = "actions[" + std::to_string(*rep.action) + "].action.strike";
    EXPECT_EQ(rep.where.substr(0, strike_path.size()), strike_path) << rep.where;
  }
}

// A player named at a noise (NAME@NOISE): its name and noise are its own,
// an AI level plans with that noise, the plain name keeps the level's.
TEST(Match, PlayerNamedAtANoise) {
  const PlayerName read = read_player_name("champion@0.5x");
  EXPECT_EQ(read.base, "champion");
  EXPECT_EQ(read.noise_spec, "0.5x");
  ASSERT_TRUE(read.noise.has_value());
  EXPECT_EQ(*read.noise, parse_noise("0.5x"));
  EXPECT_FALSE(read_player_name("champion").noise.has_value());

  const auto champion = make_player("champion@0.5x");
  EXPECT_EQ(champion->name(), "champion@0.5x");
  EXPECT_EQ(champion->noise(), parse_noise("0.5x"));
  EXPECT_EQ(make_player("champion")->noise(), parse_noise("tournament"));
  const auto steady = make_player("baseline@none");
  EXPECT_EQ(steady->name(), "baseline@none");
  EXPECT_EQ(steady->noise(), NoiseModel{});
  EXPECT_FALSE(make_player("baseline")->noise().has_value());
  EXPECT_FALSE(check_player("expert@2x", GameType::snooker).has_value());

  // In a match: the summary and the records say the name and its noise.
  MatchOptions opt;
  opt.game = GameType::nine_ball;
  opt.players = {"beginner@none", "baseline@0.5x"};
  opt.games = 2;
  opt.seed = 4;
  opt.noise = parse_noise("tournament");
  std::vector<GameRecord> records;
  const MatchSummary s = play_match(opt, [&](int, const GameRecord& r) { records.push_back(r); });
  EXPECT_EQ(s.players[0].name, "beginner@none");
  EXPECT_EQ(s.players[0].noise, "none");
  EXPECT_EQ(s.players[1].noise, "0.5x");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].players[1], "baseline@0.5x");
  EXPECT_EQ(records[0].noise[1], parse_noise("0.5x"));
  EXPECT_TRUE(replay(records[1]).identical);

  // Bad names: what is wrong, named.
  const std::pair<const char*, const char*> bad[] = {
      {"club@", "no noise after the '@'"},
      {"@0.5x", "no player before the '@'"},
      {"club@0.5x@1x", "more than one '@'"},
      {"club@fast", "noise: unknown spec \"fast\""},
      {"club@-1x", "is not a finite number >= 0"},
  };
  for (const auto& [name, why] : bad) {
    EXPECT_THROW((void)make_player(name), std::invalid_argument) << name;
    const std::optional<std::string> msg = check_player(name, GameType::nine_ball);
    ASSERT_TRUE(msg.has_value()) << name;
    EXPECT_NE(msg->find(why), std::string::npos) << *msg;
    EXPECT_NE(msg->find(std::string("\"") + name + "\""), std::string::npos) << *msg;
  }
  EXPECT_NE(check_player("clubb@1x", GameType::nine_ball)->find("unknown player \"clubb\""),
            std::string::npos);
}

TEST(Match, RefusedActionStopsTheGameNamingThePlayer) {
  const Rules rules(GameConfig{});
  Stubborn stubborn;
  auto other = make_player("baseline");
  try {
    (void)play_game(rules, *other, stubborn, 1, 1, NoiseModel{});
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("player 1 (stubborn)"), std::string::npos) << what;
    EXPECT_NE(what.find("refuse"), std::string::npos) << what;
  }
}

TEST(Match, AddGameRefusesAnUnfinishedGame) {
  const Rules rules(GameConfig{});
  GameRecord r;
  r.start = rules.start(1, 0);
  MatchSummary s = empty_summary(options(GameType::eight_ball, 1, 0));
  EXPECT_THROW(add_game(s, r), std::invalid_argument);
}

TEST(Match, BadOptionsAndUnwritableRecords) {
  MatchOptions o = options(GameType::eight_ball, 0, 1);
  EXPECT_THROW((void)play_match(o), std::invalid_argument);
  o.games = 1;
  o.players[1] = "nobody";
  EXPECT_THROW((void)play_match(o), std::invalid_argument);
  o.players[1] = "baseline";
  o.table_size = "10ft";
  EXPECT_THROW((void)play_match(o), std::invalid_argument);

  const fs::path dir = fresh_dir("match");
  std::ofstream(dir / "file") << "in the way";
  o.table_size = "9ft";
  const std::string records = (dir / "file" / "records").string();
  try {
    (void)play_match(o, record_files(records));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(records), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace

// ---------------------------------------------------------------------------
// The command line

#ifdef BREAKSHOT_CLI

namespace {

class MatchCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = fresh_dir("cli"); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  struct Run {
    int status = -1;
    std::string out;
    std::string err;
  };

  static std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
      if (c == '\'') {
        q += "'\\''";
      } else {
        q += c;
      }
    }
    return q + "'";
  }

  Run run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt";
    const fs::path err = dir_ / "stderr.txt";
    const std::string cmd = quote(BREAKSHOT_CLI) + " " + args + " >" + quote(out.string()) +
                            " 2>" + quote(err.string());
    const int raw = std::system(cmd.c_str());
    Run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  /// One short 9-ball game with its record in dir_/records.
  Run play_one() const {
    return run("match --game nine_ball --players baseline,baseline --games 1 --seed 3 "
               "--noise tournament --records " + quote((dir_ / "records").string()));
  }

  fs::path dir_;
};

TEST_F(MatchCli, MatchPrintsTheSummary) {
  const Run r = run("match --game nine_ball --players baseline,baseline --games 2 --seed 12 "
                    "--noise 2x --table 7ft --records " + quote((dir_ / "records").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["game"], "nine_ball");
  EXPECT_EQ(j["table_size"], "7ft");
  EXPECT_EQ(j["seed"], "12");
  EXPECT_EQ(j["games_played"], 2);
  ASSERT_EQ(j["players"].size(), 2u);
  EXPECT_EQ(j["players"][0]["games_won"].get<int>() + j["players"][1]["games_won"].get<int>() +
                j["draws"].get<int>(),
            2);
  EXPECT_TRUE(fs::exists(dir_ / "records" / "game-0001.json"));
  EXPECT_TRUE(fs::exists(dir_ / "records" / "game-0002.json"));
  EXPECT_FALSE(fs::exists(dir_ / "records" / "game-0003.json"));
  EXPECT_EQ(read_file(dir_ / "records" / "game-0001.json").config.table_size, "7ft");
}

TEST_F(MatchCli, ThreeCushionSummaryAndReplay) {
  const Run r = run("match --game three_cushion --players baseline,baseline --games 2 --seed 5 "
                    "--noise tournament --target 6 --innings-limit 12 --equalizing-inning off "
                    "--records " + quote((dir_ / "records").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["game"], "three_cushion");
  EXPECT_EQ(j["table_size"], "10ft");
  EXPECT_EQ(j["carom"], json::parse(R"({"target": 6, "innings_limit": 12,
                                        "equalizing_inning": false})"));
  for (const json& p : j["players"]) {
    ASSERT_TRUE(p.contains("carom")) << r.out;
    const json& c = p["carom"];
    EXPECT_LE(c["points"].get<int>(), 12);
    EXPECT_DOUBLE_EQ(c["general_average"].get<double>(),
                     p["innings"].get<int>() > 0
                         ? c["points"].get<double>() / p["innings"].get<double>()
                         : 0.0);
    EXPECT_TRUE(p["fouls"].contains("push_through"));
    EXPECT_FALSE(p["fouls"].contains("scratch"));
  }
  const GameRecord rec = read_file(dir_ / "records" / "game-0001.json");
  EXPECT_EQ(rec.config.carom.target, 6);
  EXPECT_FALSE(rec.config.carom.equalizing_inning);
  const Run rep = run("replay " + quote((dir_ / "records" / "game-0002.json").string()));
  EXPECT_EQ(rep.status, 0) << rep.out << rep.err;
  EXPECT_NE(rep.out.find("actions: identical"), std::string::npos) << rep.out;
  // The other games' summaries have no carom part.
  const Run nine = run("match --game nine_ball --players baseline,baseline --games 1 --seed 5 "
                       "--noise tournament");
  ASSERT_EQ(nine.status, 0) << nine.err;
  EXPECT_EQ(nine.out.find("carom"), std::string::npos);
}

TEST_F(MatchCli, TimingAddsDecisionTimesOnlyWhenAsked) {
  const std::string args = "match --game nine_ball --players baseline,beginner --games 2 --seed 3 "
                           "--noise tournament";
  const Run plain = run(args);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_FALSE(json::parse(plain.out)["players"][0].contains("decision_seconds"));
  const Run timed = run(args + " --timing");
  ASSERT_EQ(timed.status, 0) << timed.err;
  const json j = json::parse(timed.out);
  for (const json& p : j["players"]) {
    ASSERT_TRUE(p.contains("decision_seconds")) << timed.out;
    const json& t = p["decision_seconds"];
    EXPECT_GT(t["decisions"].get<int>(), 0);
    EXPECT_LE(t["median"].get<double>(), t["p90"].get<double>());
    EXPECT_LE(t["p90"].get<double>(), t["max"].get<double>());
    EXPECT_GE(t["median"].get<double>(), 0.0);
  }
  // The games themselves do not change with timing on.
  json a = json::parse(plain.out), b = j;
  for (json& p : b["players"]) p.erase("decision_seconds");
  EXPECT_EQ(a, b);
}

TEST_F(MatchCli, ReplayOfAWrittenRecordIsIdentical) {
  ASSERT_EQ(play_one().status, 0);
  const Run r = run("replay " + quote((dir_ / "records" / "game-0001.json").string()));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("actions: identical"), std::string::npos) << r.out;
  EXPECT_TRUE(r.out.find("winner: Player ") != std::string::npos ||
              r.out.find("draw: ") != std::string::npos)
      << r.out;
}

TEST_F(MatchCli, ReplayOfATamperedRecordExitsFour) {
  ASSERT_EQ(play_one().status, 0);
  const fs::path file = dir_ / "records" / "game-0001.json";
  ojson doc = ojson::parse(slurp(file));
  doc["actions"][0]["ruling"]["spotted"] = ojson::array({5});
  std::ofstream(dir_ / "tampered.json", std::ios::binary) << doc.dump();
  const Run r = run("replay " + quote((dir_ / "tampered.json").string()));
  EXPECT_EQ(r.status, 4) << r.out << r.err;
  EXPECT_NE(r.out.find("actions[0].ruling.spotted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[5]"), std::string::npos) << r.out;
}

TEST_F(MatchCli, ReplayOfAForfeitSaysItsEnding) {
  ASSERT_EQ(play_one().status, 0);
  ojson doc = ojson::parse(slurp(dir_ / "records" / "game-0001.json"));
  doc["version"] = 3;
  doc["actions"].erase(doc["actions"].begin() + 1, doc["actions"].end());
  doc["ending"] = {{"kind", "forfeit"},
                   {"player", 0},
                   {"winner", 1},
                   {"text", "Player 1 left the table for 120 s and forfeits"}};
  std::ofstream(dir_ / "forfeit.json", std::ios::binary) << doc.dump();
  const Run r = run("replay " + quote((dir_ / "forfeit.json").string()));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("replayed 1 actions: identical\nforfeit: winner Player 2 ("),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("): Player 1 left the table for 120 s and forfeits\n"), std::string::npos)
      << r.out;
}

TEST_F(MatchCli, InvalidRecordExitsTwoNamingThePath) {
  ASSERT_EQ(play_one().status, 0);
  ojson doc = ojson::parse(slurp(dir_ / "records" / "game-0001.json"));
  doc["actions"][0].erase("player");
  std::ofstream(dir_ / "broken.json", std::ios::binary) << doc.dump();
  Run r = run("replay " + quote((dir_ / "broken.json").string()));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("invalid record: actions[0].player: missing required field"),
            std::string::npos)
      << r.err;

  std::ofstream(dir_ / "cut.json", std::ios::binary) << doc.dump().substr(0, 100);
  r = run("replay " + quote((dir_ / "cut.json").string()));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("invalid record: (document): "), std::string::npos) << r.err;

  r = run("replay " + quote((dir_ / "no-such-record.json").string()));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("no-such-record.json"), std::string::npos) << r.err;
}

TEST_F(MatchCli, BadArgumentsExitTwoNamingTheProblem) {
  struct Case {
    const char* args;
    const char* message;
  };
  const std::string base = "--noise tournament --seed 1 ";
  const Case cases[] = {
      {"--game bowls --players baseline,baseline --games 1", "--game: unknown game 'bowls'"},
      {"--game snooker --players baseline,baseline --games 1 --table 9ft",
       "--table: snooker is played on the 12ft table"},
      {"--game eight_ball --players baseline --games 1", "--players: "},
      {"--game eight_ball --players baseline,baseline,baseline --games 1", "--players: "},
      {"--game eight_ball --players baseline,nobody --games 1", "nobody"},
      {"--game eight_ball --players baseline,baseline --games 0", "--games: "},
      {"--game eight_ball --players baseline,baseline --games many", "--games: "},
      {"--game eight_ball --players baseline,baseline --games 1 --table 10ft", "--table: "},
      {"--game three_cushion --players baseline,baseline --games 1 --table 9ft",
       "--table: three_cushion is played on the 10ft carom table"},
      {"--game three_cushion --players baseline,baseline --games 1 --target 0", "--target: "},
      {"--game three_cushion --players baseline,baseline --games 1 --target x", "--target: "},
      {"--game three_cushion --players baseline,baseline --games 1 --innings-limit -1",
       "--innings-limit: "},
      {"--game three_cushion --players baseline,baseline --games 1 --equalizing-inning yes",
       "--equalizing-inning: expected on or off"},
      {"--game nine_ball --players baseline,baseline --games 1 --target 10",
       "--target: only three_cushion has this option"},
      {"--game snooker --players baseline,baseline --games 1 --innings-limit 10",
       "--innings-limit: only three_cushion has this option"},
  };
  for (const Case& c : cases) {
    const Run r = run("match " + base + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
  Run r = run("match --game nine_ball --players baseline,baseline --games 1 --seed 1 --noise loud");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--noise: "), std::string::npos) << r.err;
  r = run("match --game nine_ball --players baseline,baseline --games 1 --seed -4 --noise none");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--seed: "), std::string::npos) << r.err;
}

TEST_F(MatchCli, PhysicsOptionsAreRecordedAndShownOnlyWhenNotTheDefault) {
  const std::string args = "match --game nine_ball --players baseline,baseline --games 1 "
                           "--seed 3 --noise tournament";
  const Run plain = run(args);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.out.find("physics"), std::string::npos) << plain.out;
  // The defaults by their names give the same bytes.
  const Run named = run(args + " --cushion-model han_2005 --ball-ball-model friction "
                               "--ball-ball-friction tpb3 --airborne on");
  ASSERT_EQ(named.status, 0) << named.err;
  EXPECT_EQ(named.out, plain.out);
  // The legacy physics by its names is not the default: the summary says it.
  const Run legacy = run(args + " --cushion-model han_2005_v0 --ball-ball-friction tpa28 "
                                "--airborne off");
  ASSERT_EQ(legacy.status, 0) << legacy.err;
  const json lj = json::parse(legacy.out);
  EXPECT_EQ(lj["physics"]["cushion_model"], "han_2005_v0");
  EXPECT_FALSE(lj["physics"].contains("airborne"));

  const Run r = run(args + " --cushion-model mathavan_2010 --ball-ball-friction tpb3 --records " +
                    quote((dir_ / "records").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_TRUE(j.contains("physics")) << r.out;
  EXPECT_EQ(j["physics"]["cushion_model"], "mathavan_2010");
  EXPECT_EQ(j["physics"]["ball_ball_model"], "friction");
  EXPECT_EQ(j["physics"]["ball_ball_friction"], json::parse(R"({"a":0.016,"b":0.219,"c":0.691})"));
  const GameRecord rec = read_file(dir_ / "records" / "game-0001.json");
  EXPECT_EQ(rec.config.physics.cushion_model, CushionModel::mathavan_2010);
  EXPECT_TRUE(rec.config.physics.ball_ball_friction_curve == kThrowFitTPB3);
  const Run rep = run("replay " + quote((dir_ / "records" / "game-0001.json").string()));
  EXPECT_EQ(rep.status, 0) << rep.out << rep.err;

  const Run c = run(args + " --cushion-model han_2005 --ball-ball-model mathavan_2014 "
                           "--ball-ball-friction 0.06");
  ASSERT_EQ(c.status, 0) << c.err;
  const json k = json::parse(c.out);
  EXPECT_EQ(k["physics"]["cushion_model"], "han_2005");
  EXPECT_EQ(k["physics"]["ball_ball_model"], "mathavan_2014");
  EXPECT_EQ(k["physics"]["ball_ball_friction"], 0.06);
  const Run curve = run(args + " --ball-ball-friction 0.009951,0.108,1.088");
  ASSERT_EQ(curve.status, 0) << curve.err;
  EXPECT_EQ(json::parse(curve.out)["physics"]["ball_ball_friction"]["c"], 1.088);

  struct Case {
    const char* option;
    const char* message;
  };
  const Case bad[] = {
      {"--cushion-model han_2006", "--cushion-model: unknown cushion model 'han_2006'"},
      {"--ball-ball-model hertz", "--ball-ball-model: unknown ball-ball model 'hertz'"},
      {"--ball-ball-friction tpb4", "--ball-ball-friction: expected tpa28, tpb3"},
      {"--ball-ball-friction 1,2", "--ball-ball-friction: expected one number"},
      {"--ball-ball-friction 0.5,0.9,1", "--ball-ball-friction: b: "},
      {"--ball-ball-friction -0.1", "--ball-ball-friction: a constant friction must be >= 0"},
  };
  for (const Case& b : bad) {
    const Run e = run(args + " " + b.option);
    EXPECT_EQ(e.status, 2) << b.option << ": " << e.err;
    EXPECT_NE(e.err.find(b.message), std::string::npos) << b.option << ": " << e.err;
    EXPECT_TRUE(e.out.empty()) << b.option;
  }
}

TEST_F(MatchCli, RecordOfAnUnknownPhysicsExitsTwoNamingItsVersion) {
  ASSERT_EQ(play_one().status, 0);
  ojson doc = ojson::parse(slurp(dir_ / "records" / "game-0001.json"));
  doc["engine"]["version"] = "9.0.0";
  doc["physics"]["cushion_model"] = "cushion_law_of_2099";
  std::ofstream(dir_ / "future.json", std::ios::binary) << doc.dump();
  const Run r = run("replay " + quote((dir_ / "future.json").string()));
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("invalid record: physics.cushion_model: unknown cushion model "
                       "\"cushion_law_of_2099\""),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("version 2 record made by breakshot 9.0.0, a newer version"),
            std::string::npos)
      << r.err;
}

TEST_F(MatchCli, ThePhysicsPresetIsTheFourOptionsAndAnExplicitOptionWins) {
  const std::string args =
      "match --game nine_ball --players baseline,baseline --games 1 "
      "--seed 3 --noise tournament";
  const auto played = [&](const std::string& options, const std::string& folder) {
    const Run r = run(args + " " + options + " --records " + quote((dir_ / folder).string()));
    EXPECT_EQ(r.status, 0) << options << ": " << r.err;
    return r.out + slurp(dir_ / folder / "game-0001.json");
  };
  const std::string four = played(
      "--cushion-model han_2005_v0 --ball-ball-friction tpa28 --airborne off "
      "--spinning-friction legacy",
      "four");
  EXPECT_EQ(played("--physics legacy", "legacy"), four);
  EXPECT_EQ(played("--physics default", "default"), played("", "none"));
  // An option given with the preset wins over the preset's value for it.
  const std::string airborne = played(
      "--cushion-model han_2005_v0 --ball-ball-friction tpa28 --airborne on "
      "--spinning-friction legacy",
      "four-airborne");
  EXPECT_NE(airborne, four);
  EXPECT_EQ(played("--physics legacy --airborne on", "legacy-airborne"), airborne);
  EXPECT_EQ(played("--airborne on --physics legacy", "airborne-legacy"), airborne);

  const Run bad = run(args + " --physics modern");
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_NE(bad.err.find("--physics: unknown physics preset 'modern' (default or legacy)"),
            std::string::npos)
      << bad.err;
}

TEST_F(MatchCli, AReplayThatDiffersNamesTheRecordsVersionAndEngine) {
  ASSERT_EQ(play_one().status, 0);
  ojson doc = ojson::parse(slurp(dir_ / "records" / "game-0001.json"));
  // Another engine's record whose physics names this build still reads:
  // it reads, and where it does not replay the message says whose it is.
  doc["engine"]["version"] = "0.0.7";
  ojson& x = doc["actions"][0]["after"]["position"][1][0];
  x = x.get<double>() + 0.25;
  std::ofstream(dir_ / "other.json", std::ios::binary) << doc.dump();
  const Run r = run("replay " + quote((dir_ / "other.json").string()));
  EXPECT_EQ(r.status, 4) << r.out << r.err;
  EXPECT_NE(r.out.find("a version 2 record made by breakshot 0.0.7; this is breakshot " +
                       std::string(kVersion) + ", another engine"),
            std::string::npos)
      << r.out;
}

TEST_F(MatchCli, OtherFailuresExitOne) {
  std::ofstream(dir_ / "file") << "in the way";
  Run r = run("match --game nine_ball --players baseline,baseline --games 1 --seed 1 "
              "--noise none --records " + quote((dir_ / "file" / "records").string()));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find((dir_ / "file" / "records").string()), std::string::npos) << r.err;
  r = run("match --game nine_ball --players baseline,baseline --seed 1 --noise none");  // no --games
  EXPECT_EQ(r.status, 1) << r.err;
  r = run("replay");
  EXPECT_EQ(r.status, 1) << r.err;
}

TEST_F(MatchCli, HelpNamesTheSubcommands) {
  Run r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("match"), std::string::npos);
  EXPECT_NE(r.out.find("replay"), std::string::npos);
  r = run("match --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("Exit status"), std::string::npos);
  r = run("replay --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("Exit status"), std::string::npos);
}

}  // namespace

#endif  // BREAKSHOT_CLI

}  // namespace test_match

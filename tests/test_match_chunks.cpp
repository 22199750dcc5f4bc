// Chunks of a match (MatchOptions::first_game), summaries added together
// (add_summary) and read back (read_match_summary), and the `match
// --first-game` and `match-sum` commands.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record_io.hpp"

namespace test_match_chunks {

namespace {

namespace fs = std::filesystem;
using namespace breakshot;
using ojson = nlohmann::ordered_json;

MatchOptions options(GameType game, const char* p1, int first, int games) {
  MatchOptions o;
  o.game = game;
  o.players = {"baseline", p1};
  o.first_game = first;
  o.games = games;
  o.seed = 21;
  o.noise = parse_noise("tournament");
  return o;
}

/// Plays games first .. first + games - 1, keeping each record's text by index.
MatchSummary play(const MatchOptions& o, std::map<int, std::string>& records) {
  return play_match(o, [&records](int g, const GameRecord& r) {
    EXPECT_EQ(records.count(g), 0u) << "game " << g << " twice";
    records[g] = write_record(r);
  });
}

struct Chunk {
  int first;
  int games;
};

/// Chunks of uneven sizes covering games 0 .. N-1, summed in a shuffled
/// order one by one and also pairwise (a tree), give one match's summary
/// byte for byte; the chunks' records are that match's records.
void check_chunks_add_up(GameType game, const char* p1, int n, const std::vector<Chunk>& chunks,
                         const std::vector<std::size_t>& order) {
  std::map<int, std::string> whole_records;
  const MatchSummary whole = play(options(game, p1, 0, n), whole_records);
  const std::string expected = match_summary_json(whole);
  ASSERT_EQ(whole.games_played, n);

  std::vector<MatchSummary> parts;
  std::map<int, std::string> chunk_records;
  for (const Chunk& c : chunks) {
    parts.push_back(play(options(game, p1, c.first, c.games), chunk_records));
    EXPECT_EQ(parts.back().games_played, c.games);
    // A chunk not from 0 says where it starts, and reads back as written.
    const std::string text = match_summary_json(parts.back());
    if (c.first == 0) {
      EXPECT_EQ(text.find("first_game"), std::string::npos) << text;
    } else {
      EXPECT_EQ(ojson::parse(text)["first_game"], c.first);
    }
    EXPECT_EQ(match_summary_json(read_match_summary(text)), text);
  }
  EXPECT_EQ(chunk_records, whole_records);

  // One by one, in the shuffled order, from the first chunk's summary.
  MatchSummary sum = parts[order[0]];
  for (std::size_t i = 1; i < order.size(); ++i) add_summary(sum, parts[order[i]]);
  EXPECT_EQ(match_summary_json(sum), expected);

  // Pairwise, from an empty summary, through the JSON text each time.
  std::vector<MatchSummary> level;
  for (const std::size_t i : order) level.push_back(read_match_summary(match_summary_json(parts[i])));
  while (level.size() > 1) {
    std::vector<MatchSummary> next;
    for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
      MatchSummary s = level[i];
      add_summary(s, level[i + 1]);
      next.push_back(read_match_summary(match_summary_json(s)));
    }
    if (level.size() % 2 == 1) next.push_back(level.back());
    level = next;
  }
  MatchOptions o = options(game, p1, 0, n);
  MatchSummary from_empty = empty_summary(o);
  add_summary(from_empty, level[0]);
  EXPECT_EQ(match_summary_json(from_empty), expected);
}

TEST(MatchChunks, EightBallChunksAddUpToOneMatch) {
  check_chunks_add_up(GameType::eight_ball, "baseline", 11,
                      {{0, 3}, {3, 1}, {4, 5}, {9, 2}}, {2, 0, 3, 1});
}

TEST(MatchChunks, NineBallChunksAddUpToOneMatch) {
  check_chunks_add_up(GameType::nine_ball, "baseline", 10,
                      {{0, 1}, {1, 4}, {5, 2}, {7, 3}}, {3, 1, 2, 0});
}

TEST(MatchChunks, ChunksWithAnAiLevelAddUp) {
  check_chunks_add_up(GameType::nine_ball, "beginner", 4, {{0, 1}, {1, 2}, {3, 1}}, {2, 0, 1});
  check_chunks_add_up(GameType::eight_ball, "beginner", 3, {{0, 2}, {2, 1}}, {1, 0});
}

TEST(MatchChunks, AGapIsWrittenAsRangesAndReadBack) {
  std::map<int, std::string> records;
  MatchSummary a = play(options(GameType::eight_ball, "baseline", 0, 2), records);
  const MatchSummary b = play(options(GameType::eight_ball, "baseline", 5, 1), records);
  const MatchSummary c = play(options(GameType::eight_ball, "baseline", 9, 2), records);
  add_summary(a, c);
  add_summary(a, b);
  ASSERT_EQ(a.ranges, (std::vector<GameRange>{{0, 2}, {5, 1}, {9, 2}}));
  const std::string text = match_summary_json(a);
  const ojson j = ojson::parse(text);
  EXPECT_FALSE(j.contains("first_game"));
  EXPECT_EQ(j["game_ranges"], ojson::parse(R"([{"first_game": 0, "games": 2},
      {"first_game": 5, "games": 1}, {"first_game": 9, "games": 2}])"));
  EXPECT_EQ(j["games_played"], 5);
  EXPECT_EQ(match_summary_json(read_match_summary(text)), text);
  // Filling the gap gives one range again, written as first_game only.
  MatchSummary gap = play(options(GameType::eight_ball, "baseline", 2, 3), records);
  MatchSummary rest = play(options(GameType::eight_ball, "baseline", 6, 3), records);
  add_summary(a, gap);
  add_summary(a, rest);
  EXPECT_EQ(match_summary_json(a), match_summary_json(play(options(GameType::eight_ball,
                                                                    "baseline", 0, 11), records = {})));
}

TEST(MatchChunks, SumOfNoGamesStartsEmpty) {
  const MatchSummary e = empty_summary(options(GameType::nine_ball, "baseline", 0, 1));
  const std::string text = match_summary_json(e);
  EXPECT_EQ(match_summary_json(read_match_summary(text)), text);
  MatchSummary twice = e;
  add_summary(twice, e);
  EXPECT_EQ(match_summary_json(twice), text);
}

TEST(MatchChunks, AddingSummariesOfAnotherMatchThrowsNamingTheField) {
  std::map<int, std::string> records;
  const MatchOptions base = options(GameType::eight_ball, "baseline", 0, 1);
  const MatchSummary into = play(base, records);
  const std::string before = match_summary_json(into);
  struct Case {
    MatchSummary part;
    std::string field;
  };
  std::vector<Case> cases;
  MatchOptions o = base;
  o.first_game = 1;
  MatchSummary other = play(o, records = {});
  cases.push_back({other, "game"});
  cases.back().part.game = GameType::nine_ball;
  cases.push_back({other, "table_size"});
  cases.back().part.table_size = "7ft";
  cases.push_back({other, "seed"});
  cases.back().part.seed = 22;
  cases.push_back({other, "noise"});
  cases.back().part.noise = parse_noise("2x");
  cases.push_back({other, "players[1].name"});
  cases.back().part.players[1].name = "beginner";
  cases.push_back({other, "players[0].noise"});
  cases.back().part.players[0].noise = "none";
  cases.push_back({into, "first_game"});  // the same game twice
  for (const Case& c : cases) {
    MatchSummary s = into;
    try {
      add_summary(s, c.part);
      ADD_FAILURE() << c.field << ": no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(c.field + ": ", 0), 0u) << e.what();
    }
    EXPECT_EQ(match_summary_json(s), before) << c.field << ": changed by a refused add";
  }
  // An overlap inside a range is named by its games.
  MatchSummary wide = play(options(GameType::eight_ball, "baseline", 0, 3), records = {});
  const MatchSummary mid = play(options(GameType::eight_ball, "baseline", 1, 3), records = {});
  try {
    add_summary(wide, mid);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "first_game: the summaries overlap: both cover games 1 to 2");
  }
}

TEST(MatchChunks, FirstGameIsValidated) {
  MatchOptions o = options(GameType::eight_ball, "baseline", -1, 1);
  for (const auto& [first, games] : std::vector<std::pair<int, int>>{{-1, 1}, {INT_MAX, 1}, {INT_MAX - 2, 3}}) {
    o.first_game = first;
    o.games = games;
    try {
      (void)play_match(o);
      ADD_FAILURE() << first << " + " << games << ": no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("first_game: ", 0), 0u) << e.what();
    }
  }
}

/// A player that throws on every decision.
class Thrower : public Player {
 public:
  std::string name() const override { return "thrower"; }
  Action decide(const Rules&, const GameState&, std::uint64_t) override {
    throw std::runtime_error("boom");
  }
};

TEST(MatchChunks, AFailingGameIsNamedWithItsSeedWhenAsked) {
  auto baseline = make_player("baseline");
  Thrower thrower;
  MatchOptions o = options(GameType::nine_ball, "thrower", 7, 3);
  // Game 7 is broken by seat 1, the thrower.
  try {
    (void)play_match(o, *baseline, thrower);
    ADD_FAILURE() << "no exception";
  } catch (const MatchGameError&) {
    ADD_FAILURE() << "named without name_failing_game";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "boom");
  }
  o.name_failing_game = true;
  try {
    (void)play_match(o, *baseline, thrower);
    ADD_FAILURE() << "no exception";
  } catch (const MatchGameError& e) {
    const std::uint64_t seed = mix_seed(21, 7);
    EXPECT_EQ(std::string(e.what()), "game 7 (seed " + std::to_string(seed) + "): boom");
    EXPECT_EQ(e.game(), 7);
    EXPECT_EQ(e.game_seed(), seed);
    EXPECT_EQ(e.reason(), "boom");
  }
}

// Games played at once (MatchOptions::jobs) -------------------------------

/// Plays `o` with fresh players from their names, keeping each record's
/// text and the order the sink received the games in.
MatchSummary play_jobs(const MatchOptions& o, std::map<int, std::string>& records,
                       std::vector<int>& order) {
  const PlayerFactory make = [&o](int seat) {
    return make_player(o.players[static_cast<std::size_t>(seat)], 1);
  };
  return play_match(o, make, [&](int g, const GameRecord& r) {
    order.push_back(g);
    records[g] = write_record(r);
  });
}

/// The same match on 1 and on `jobs` game threads: the same summary text,
/// the same records, and the sink called in index order.
void check_jobs_match_one_thread(MatchOptions o, int jobs) {
  o.jobs = 1;
  std::map<int, std::string> one_records;
  std::vector<int> one_order;
  const std::string one = match_summary_json(play_jobs(o, one_records, one_order));
  o.jobs = jobs;
  std::map<int, std::string> many_records;
  std::vector<int> many_order;
  const MatchSummary many = play_jobs(o, many_records, many_order);
  EXPECT_EQ(match_summary_json(many), one);
  EXPECT_EQ(many_records, one_records);
  std::vector<int> expected(static_cast<std::size_t>(o.games));
  for (int i = 0; i < o.games; ++i) expected[static_cast<std::size_t>(i)] = o.first_game + i;
  EXPECT_EQ(many_order, expected);
  EXPECT_EQ(one_order, expected);
}

TEST(MatchJobs, SummariesAndRecordsAreThoseOfOneThread) {
  // More game threads than games and than cores, and a first game past 0.
  check_jobs_match_one_thread(options(GameType::eight_ball, "amateur", 3, 5), 3);
  check_jobs_match_one_thread(options(GameType::nine_ball, "baseline", 0, 7), 4);
  check_jobs_match_one_thread(options(GameType::nine_ball, "baseline", 0, 2), 8);
  MatchOptions snooker = options(GameType::snooker, "baseline", 1, 3);
  snooker.table_size = "12ft";
  check_jobs_match_one_thread(snooker, 2);
  MatchOptions carom = options(GameType::three_cushion, "baseline", 0, 3);
  carom.table_size = "10ft";
  carom.carom.target = 3;
  carom.carom.innings_limit = 10;
  check_jobs_match_one_thread(carom, 3);
}

TEST(MatchJobs, NamedPlayersMatchOnAnyNumberOfThreads) {
  MatchOptions o = options(GameType::nine_ball, "beginner", 0, 4);
  o.jobs = 1;
  const std::string one = match_summary_json(play_match(o));
  for (const int jobs : {0, 2, 4}) {
    o.jobs = jobs;
    EXPECT_EQ(match_summary_json(play_match(o)), one) << "jobs " << jobs;
  }
}

TEST(MatchJobs, TimingKeepsEveryDecision) {
  MatchOptions o = options(GameType::nine_ball, "baseline", 0, 4);
  o.timing = true;
  o.jobs = 1;
  const MatchSummary one = play_match(o);
  o.jobs = 3;
  const MatchSummary many = play_match(o);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_FALSE(one.players[p].decision_seconds.empty());
    EXPECT_EQ(many.players[p].decision_seconds.size(), one.players[p].decision_seconds.size());
  }
}

/// Breaks by throwing; plays every other shot as the baseline.
class BreakThrower : public Player {
 public:
  std::string name() const override { return "thrower"; }
  Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) override {
    if (state.phase == Phase::break_shot) throw std::runtime_error("no break");
    return baseline_->decide(rules, state, seed);
  }

 private:
  std::unique_ptr<Player> baseline_ = make_baseline_player();
};

TEST(MatchJobs, TheFirstFailingGameInOrderIsTheErrorAndEarlierGamesReachTheSink) {
  // Seat 1 breaks the odd games: games 6 and 8 play, 7 and 9 fail.
  MatchOptions o = options(GameType::nine_ball, "thrower", 6, 4);
  o.name_failing_game = true;
  for (const int jobs : {1, 2, 4}) {
    o.jobs = jobs;
    std::vector<int> sunk;
    const PlayerFactory make = [](int seat) -> std::unique_ptr<Player> {
      if (seat == 0) return make_baseline_player();
      return std::make_unique<BreakThrower>();
    };
    try {
      (void)play_match(o, make, [&sunk](int g, const GameRecord&) { sunk.push_back(g); });
      ADD_FAILURE() << "no exception, jobs " << jobs;
    } catch (const MatchGameError& e) {
      EXPECT_EQ(e.game(), 7) << "jobs " << jobs;
      EXPECT_EQ(e.reason(), "no break");
    }
    EXPECT_EQ(sunk, std::vector<int>{6}) << "jobs " << jobs;
  }
}

TEST(MatchJobs, ASinkErrorStopsTheMatchAfterTheGamesBeforeIt) {
  MatchOptions o = options(GameType::nine_ball, "baseline", 0, 6);
  o.jobs = 3;
  std::vector<int> sunk;
  const PlayerFactory make = [](int) { return make_baseline_player(); };
  EXPECT_THROW((void)play_match(o, make,
                                [&sunk](int g, const GameRecord&) {
                                  if (g == 2) throw std::runtime_error("disk full");
                                  sunk.push_back(g);
                                }),
               std::runtime_error);
  EXPECT_EQ(sunk, (std::vector<int>{0, 1}));
}

TEST(MatchJobs, BadJobsAndFactoriesAreRefused) {
  MatchOptions o = options(GameType::nine_ball, "baseline", 0, 2);
  o.jobs = -1;
  const PlayerFactory make = [](int) { return make_baseline_player(); };
  EXPECT_THROW((void)play_match(o, make), std::invalid_argument);
  EXPECT_THROW((void)play_match(o), std::invalid_argument);
  o.jobs = 2;
  const PlayerFactory none = [](int) { return std::unique_ptr<Player>(); };
  EXPECT_THROW((void)play_match(o, none), std::invalid_argument);
  EXPECT_THROW((void)make_player("champion", -1), std::invalid_argument);
  EXPECT_EQ(match_threads(1, 10), 1);
  EXPECT_EQ(match_threads(5, 3), 3);
  EXPECT_EQ(match_threads(4, 10), 4);
  EXPECT_GE(match_threads(0, 1000), 1);
  EXPECT_EQ(match_threads(0, 1), 1);
}

TEST(MatchChunks, RecordFileNames) {
  EXPECT_EQ(record_file_name(0), "game-0001.json");
  EXPECT_EQ(record_file_name(41), "game-0042.json");
  EXPECT_EQ(record_file_name(9999), "game-10000.json");
  EXPECT_EQ(record_file_name(INT_MAX), "game-2147483648.json");
}

/// The summary text of a short 8-ball match, changed by `edit`.
std::string edited(const std::function<void(ojson&)>& edit) {
  std::map<int, std::string> records;
  ojson j = ojson::parse(match_summary_json(play(options(GameType::eight_ball, "baseline", 3, 2), records)));
  edit(j);
  return j.dump(2) + "\n";
}

TEST(MatchChunks, ReadingABadSummaryNamesThePath) {
  struct Case {
    std::function<void(ojson&)> edit;
    std::string message;
  };
  const std::vector<Case> cases = {
      {[](ojson& j) { j.erase("seed"); }, "seed: missing required field"},
      {[](ojson& j) { j["extra"] = 1; }, "extra: unknown field"},
      {[](ojson& j) { j["game"] = "bowls"; }, "game: unknown game \"bowls\""},
      {[](ojson& j) { j["table_size"] = "10ft"; }, "table_size: unknown table size"},
      {[](ojson& j) { j["noise"] = "loud"; }, "noise: "},
      {[](ojson& j) { j["noise"] = "custom:phi=0.125,theta=0.1,speed=0.075,a=0.0005,b=0.0005"; },
       "noise: expected the noise as a summary writes it (\"tournament\")"},
      {[](ojson& j) { j["first_game"] = 0; }, "first_game: must be an integer in [1, "},
      {[](ojson& j) { j["first_game"] = -3; }, "first_game: "},
      {[](ojson& j) { j["games_played"] = 3; }, "games_played: must be the games won plus the draws (2)"},
      {[](ojson& j) { j["players"][1]["innings"] = "7"; }, "players[1].innings: expected an integer"},
      {[](ojson& j) { j["players"][0]["pot_rate"] = 0.123; }, "players[0].pot_rate: must be "},
      {[](ojson& j) { j["players"][0]["balls_per_inning"] = 99; }, "players[0].balls_per_inning: must be "},
      {[](ojson& j) { j["players"][0]["fouls"].erase("scratch"); }, "players[0].fouls.scratch: missing foul kind"},
      {[](ojson& j) { j["players"][1]["fouls"]["bad_break"] = 0; }, "players[1].fouls.bad_break: not a foul kind"},
      {[](ojson& j) {
         j["players"][0]["decision_seconds"] = {{"decisions", 1}, {"median", 0.1}, {"p90", 0.1}, {"max", 0.1}};
       },
       "players[0].decision_seconds: a summary with decision times (--timing) cannot be read"},
      {[](ojson& j) { j["players"].erase(1); }, "players: expected an array of 2"},
      {[](ojson& j) {
         j.erase("first_game");
         j["game_ranges"] = ojson::parse(R"([{"first_game": 0, "games": 1}, {"first_game": 1, "games": 1}])");
       },
       "game_ranges[1].first_game: the ranges must ascend with a gap between them"},
      {[](ojson& j) {
         j.erase("first_game");
         j["game_ranges"] = ojson::parse(R"([{"first_game": 0, "games": 1}, {"first_game": 4, "games": 2}])");
       },
       "game_ranges: the ranges hold 3 games, not games_played = 2"},
  };
  for (const Case& c : cases) {
    const std::string text = edited(c.edit);
    try {
      (void)read_match_summary(text);
      ADD_FAILURE() << c.message << ": no exception for\n" << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(c.message, 0), 0u) << e.what();
    }
  }
  EXPECT_THROW((void)read_match_summary("{\"game\": "), std::invalid_argument);
  EXPECT_THROW((void)read_match_summary("[]"), std::invalid_argument);
  // The unedited text reads.
  const std::string good = edited([](ojson&) {});
  EXPECT_EQ(match_summary_json(read_match_summary(good)), good);
}

}  // namespace

// ---------------------------------------------------------------------------
// The command line

#ifdef BREAKSHOT_CLI

namespace {

class MatchChunksCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("breakshot-chunks-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  struct Run {
    int status = -1;
    std::string out;
    std::string err;
  };

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  Run run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt";
    const fs::path err = dir_ / "stderr.txt";
    const std::string cmd = std::string(BREAKSHOT_CLI) + " " + args + " >" + out.string() +
                            " 2>" + err.string();
    const int raw = std::system(cmd.c_str());
    Run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  /// `match` with the common options and `extra`, its summary saved as `name`.
  Run chunk(const std::string& extra, const std::string& name) const {
    Run r = run("match --game nine_ball --players baseline,baseline --seed 5 --noise 2x --table 8ft " +
                extra);
    std::ofstream(dir_ / name, std::ios::binary) << r.out;
    return r;
  }

  std::string at(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(MatchChunksCli, TwoChunksSumToOneRunsBytes) {
  const Run whole = chunk("--games 5 --records " + at("whole"), "whole.json");
  ASSERT_EQ(whole.status, 0) << whole.err;
  const Run a = chunk("--games 2 --records " + at("chunks"), "a.json");
  const Run b = chunk("--games 3 --first-game 2 --records " + at("chunks"), "b.json");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(a.out.find("first_game"), std::string::npos);
  EXPECT_NE(b.out.find("\"first_game\": 2,"), std::string::npos) << b.out;
  // The chunks' records are the whole run's, under the same names.
  for (int g = 0; g < 5; ++g) {
    const std::string name = record_file_name(g);
    EXPECT_EQ(slurp(dir_ / "chunks" / name), slurp(dir_ / "whole" / name)) << name;
  }
  EXPECT_FALSE(fs::exists(dir_ / "chunks" / record_file_name(5)));
  for (const std::string& args : {at("b.json") + " " + at("a.json"), at("a.json") + " " + at("b.json"),
                                  "- " + at("a.json") + " < " + at("b.json")}) {
    const Run sum = run("match-sum " + args);
    ASSERT_EQ(sum.status, 0) << sum.err;
    EXPECT_EQ(sum.out, whole.out) << args;
  }
  // One summary alone prints itself.
  const Run one = run("match-sum " + at("b.json"));
  EXPECT_EQ(one.status, 0);
  EXPECT_EQ(one.out, b.out);
}

TEST_F(MatchChunksCli, BadSummariesExitTwoNamingTheFile) {
  ASSERT_EQ(chunk("--games 1", "a.json").status, 0);
  const Run other = run("match --game nine_ball --players baseline,baseline --seed 6 --noise 2x "
                        "--table 8ft --games 1 --first-game 1");
  ASSERT_EQ(other.status, 0) << other.err;
  std::ofstream(dir_ / "other.json", std::ios::binary) << other.out;
  std::ofstream(dir_ / "bad.json") << "{\"game\": \"nine_ball\"}";
  struct Case {
    std::string args;
    std::string message;
  };
  const Case cases[] = {
      {at("a.json") + " " + at("missing.json"), "cannot read " + at("missing.json")},
      {at("a.json") + " " + at("bad.json"), "invalid summary " + at("bad.json") + ": table_size: missing required field"},
      {at("a.json") + " " + at("a.json"), "cannot add " + at("a.json") + " to " + at("a.json") + ": first_game: the summaries overlap"},
      {at("a.json") + " " + at("other.json"), "cannot add " + at("other.json") + " to " + at("a.json") + ": seed: "},
  };
  for (const Case& c : cases) {
    const Run r = run("match-sum " + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("breakshot: " + c.message, 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
  EXPECT_EQ(run("match-sum").status, 1);  // a usage error
}

TEST_F(MatchChunksCli, BadFirstGameExitsTwoNamingTheOption) {
  for (const char* v : {"-1", "x", "1.5", "2147483647"}) {
    const Run r = chunk(std::string("--games 1 --first-game ") + v, "x.json");
    EXPECT_EQ(r.status, 2) << v << ": " << r.err;
    EXPECT_EQ(r.err.rfind("breakshot: --first-game: ", 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

TEST_F(MatchChunksCli, JobsGiveTheSameSummaryAndRecords) {
  const Run one = chunk("--games 5 --jobs 1 --records " + at("one"), "one.json");
  ASSERT_EQ(one.status, 0) << one.err;
  for (const char* jobs : {"2", "0", "7"}) {
    const std::string dir = at(std::string("jobs") + jobs);
    const Run r = chunk(std::string("--games 5 --jobs ") + jobs + " --records " + dir, "j.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, one.out) << "--jobs " << jobs;
    for (int g = 0; g < 5; ++g) {
      const std::string name = record_file_name(g);
      EXPECT_EQ(slurp(fs::path(dir) / name), slurp(dir_ / "one" / name)) << name;
    }
  }
  const Run dflt = chunk("--games 5", "d.json");  // every core
  EXPECT_EQ(dflt.out, one.out);
}

TEST_F(MatchChunksCli, BadJobsExitTwoNamingTheOption) {
  for (const char* v : {"-1", "x", "1.5"}) {
    const Run r = chunk(std::string("--games 1 --jobs ") + v, "x.json");
    EXPECT_EQ(r.status, 2) << v << ": " << r.err;
    EXPECT_EQ(r.err.rfind("breakshot: --jobs: ", 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

TEST_F(MatchChunksCli, HelpDescribesChunks) {
  Run r = run("--help");
  EXPECT_NE(r.out.find("match-sum"), std::string::npos);
  r = run("match --help");
  EXPECT_NE(r.out.find("--first-game"), std::string::npos);
  EXPECT_NE(r.out.find("--jobs"), std::string::npos);
  r = run("match-sum --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("Exit status"), std::string::npos);
}

}  // namespace

#endif  // BREAKSHOT_CLI

}  // namespace test_match_chunks

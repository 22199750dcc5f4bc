// The AI levels in three-cushion (docs/ai.md, "Three-cushion"): legal
// shots from hand-placed tables, the champion's points from a set-up
// position under tournament noise, decisions that do not depend on the
// thread count, and whole short games that end.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/players.hpp"

namespace test_ai_carom {

using namespace breakshot;

namespace {

const Rules& rules() {
  static const Rules r(three_cushion_config());
  return r;
}

/// A game in progress: player `player` to shoot, the balls where given.
GameState table(Vec2 white, Vec2 yellow, Vec2 red, int player = 0) {
  GameState s = rules().start(1, 0);
  s.position = {white, yellow, red};
  s.phase = Phase::shot;
  s.shots = 1;
  s.player = player;
  if (player == 1) {
    s.innings = 2;
    s.carom->innings = {1, 1};
  }
  return s;
}

/// Hand-placed tables: open, a ball on a rail, the balls close together,
/// the cue ball near a corner, and the break.
std::vector<GameState> tables() {
  return {table({0.5, 0.4}, {1.5, 1.0}, {2.3, 0.5}), table({2.0, 1.1}, {0.6, 0.2}, {1.4, 1.38}, 1),
          table({1.2, 0.7}, {1.9, 0.75}, {1.96, 0.80}),
          table({0.1, 0.1}, {2.5, 1.2}, {1.4, 0.7}, 1), rules().start(3, 0)};
}

/// A set-up one-ball-first shot: the red half-ball ahead of the cue ball,
/// the yellow in the far corner region its three-cushion path reaches.
GameState setup() { return table({0.70, 0.45}, {2.45, 1.15}, {1.10, 0.60}); }

bool point(const Outcome& o) { return o.ruling.carom && o.ruling.carom->point; }

}  // namespace

TEST(AiCarom, EveryLevelPlaysALegalShot) {
  for (const std::string& name : ai_level_names()) {
    AiLevel level = ai_level(name);
    level.threads = 2;
    const std::unique_ptr<Player> p = make_ai_player(level);
    int k = 0;
    for (const GameState& s : tables()) {
      const Action a = p->decide(rules(), s, 11 + static_cast<std::uint64_t>(k++));
      ASSERT_TRUE(std::holds_alternative<Shoot>(a)) << name;
      EXPECT_FALSE(rules().check(s, a)) << name << " table " << k << ": " << *rules().check(s, a);
      const Shoot& shot = std::get<Shoot>(a);
      EXPECT_GT(shot.strike.speed, 0.0) << name;
      EXPECT_FALSE(shot.cue_ball) << name;  // always its own ball
    }
  }
}

// The champion finds the set-up shot every time, and makes it under its
// own noise: 24 decisions with their own seeds, each played as chosen and
// with a noise draw of its own.
TEST(AiCarom, ChampionScoresASetUpShot) {
  AiLevel level = ai_level("champion");
  level.threads = 2;
  const std::unique_ptr<Player> p = make_ai_player(level);
  const GameState s = setup();
  constexpr int kTries = 24;
  int made = 0;
  int found = 0;
  for (int k = 0; k < kTries; ++k) {
    const Action a = p->decide(rules(), s, 1000 + static_cast<std::uint64_t>(k));
    ASSERT_TRUE(std::holds_alternative<Shoot>(a));
    Shoot played = std::get<Shoot>(a);
    if (point(rules().apply(s, Action{played}))) ++found;
    played.strike = perturb(played.strike, level.noise, kCaromBallRadius,
                            mix_seed(77, static_cast<std::uint64_t>(k)));
    if (point(rules().apply(s, Action{played}))) ++made;
  }
  EXPECT_EQ(found, kTries);
  // Under noise: 16 of the 24 with breakshot 0.1's spin decay (37.8
  // rad/s^2), 10 with the measured one (10 rad/s^2). Side spin that lasts
  // makes a three-cushion path more sensitive to the tip's noise, and the
  // champion's search has not been fitted to it yet (docs/ai.md); at least
  // a third, with room for small changes of the engine.
  EXPECT_GE(made, kTries / 3) << made << " of " << kTries;
}

// Same seed, same decision, for one thread or several.
TEST(AiCarom, DecisionsDoNotDependOnThreads) {
  for (const std::string& name : {std::string("club"), std::string("champion")}) {
    AiLevel one = ai_level(name);
    one.threads = 1;
    AiLevel many = ai_level(name);
    many.threads = 3;
    const std::unique_ptr<Player> a = make_ai_player(one);
    const std::unique_ptr<Player> b = make_ai_player(many);
    int k = 0;
    for (const GameState& s : tables()) {
      const std::uint64_t seed = 99 + static_cast<std::uint64_t>(k++);
      const Action x = a->decide(rules(), s, seed);
      const Action y = b->decide(rules(), s, seed);
      ASSERT_TRUE(std::holds_alternative<Shoot>(x));
      ASSERT_TRUE(std::holds_alternative<Shoot>(y));
      EXPECT_EQ(std::get<Shoot>(x).strike, std::get<Shoot>(y).strike) << name << " table " << k;
    }
  }
}

// Whole short games between neighbouring levels end.
TEST(AiCarom, ShortGamesEnd) {
  const std::vector<std::string> names = ai_level_names();
  for (std::size_t i = 0; i + 1 < names.size(); ++i) {
    MatchOptions opt;
    opt.game = GameType::three_cushion;
    opt.table_size = "10ft";
    opt.carom = CaromRules{2, 3, true};
    opt.players = {names[i], names[i + 1]};
    opt.games = 1;
    opt.seed = 5 + i;
    opt.noise = parse_noise("tournament");
    const MatchSummary m = play_match(opt);
    EXPECT_EQ(m.games_played, 1) << names[i];
  }
}

}  // namespace test_ai_carom

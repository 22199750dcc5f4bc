// A thousand whole games between baseline players (two hundred under the
// sanitizers), under every noise
// level: every game ends, and after every action the table is sound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "breakshot/players.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "sanitizers.hpp"

namespace test_games_long {

using namespace breakshot;

namespace {

// Invariants of a state between actions. Returns the first broken one.
std::string broken(const Rules& rules, const GameState& before, const RecordedAction& act) {
  const GameState& s = act.after;
  const double R = rules.config().ball_radius;
  const auto n = static_cast<std::size_t>(rules.ball_count());
  if (s.position.size() != n || s.on_table.size() != n) return "ball arrays resized";
  for (std::size_t i = 0; i < n; ++i) {
    if (!s.on_table[i]) continue;
    const Vec2 p = s.position[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return "ball " + std::to_string(i) + " at NaN";
    if (wall_clearance(rules.table(), p, R) < -1e-9) {
      return "ball " + std::to_string(i) + " off the table or in a cushion";
    }
    for (std::size_t j = i + 1; j < n; ++j) {
      if (s.on_table[j] && norm(s.position[j] - p) < 2.0 * R - 1e-9) {
        return "balls " + std::to_string(i) + " and " + std::to_string(j) + " overlap";
      }
    }
  }
  // An object ball that was down comes back only when spotted or re-racked.
  const bool reracked = s.racks != before.racks;
  for (std::size_t i = 1; i < n; ++i) {
    const bool spotted = std::count(act.ruling.spotted.begin(), act.ruling.spotted.end(),
                                    static_cast<int>(i)) > 0;
    if (!before.on_table[i] && s.on_table[i] && !spotted && !reracked) {
      return "ball " + std::to_string(i) + " came back without being spotted";
    }
  }
  if (s.player != 0 && s.player != 1) return "no player to act";
  if (s.phase == Phase::game_over) {
    if (s.winner != act.ruling.winner) return "winner differs between state and ruling";
    if (s.result.empty()) return "game over without a reason";
  } else if (s.winner != -1) {
    return "a winner before the game is over";
  }
  if (s.shots > rules.config().max_shots) return "more shots than the stalemate limit";
  return {};
}

void play_many(GameType game, int games, std::uint64_t seed) {
  GameConfig config;
  config.game = game;
  const Rules rules(config);
  const char* levels[] = {"none", "tournament", "5x"};
  auto p0 = make_player("baseline");
  auto p1 = make_player("baseline");
  int finished = 0, draws = 0;
  for (int g = 0; g < games; ++g) {
    const NoiseModel noise = parse_noise(levels[g % 3]);
    const GameRecord rec = play_game(rules, *p0, *p1, g % 2, mix_seed(seed, static_cast<std::uint64_t>(g)), noise);
    ASSERT_FALSE(rec.actions.empty());
    GameState before = rec.start;
    for (std::size_t k = 0; k < rec.actions.size(); ++k) {
      const std::string why = broken(rules, before, rec.actions[k]);
      ASSERT_TRUE(why.empty()) << to_string(game) << " game " << g << " action " << k << ": "
                               << why;
      before = rec.actions[k].after;
    }
    ASSERT_EQ(before.phase, Phase::game_over) << "game " << g << " did not end";
    ++finished;
    if (before.winner < 0) ++draws;
  }
  EXPECT_EQ(finished, games);
  // Baseline players finish most games; a draw is the stalemate limit.
  EXPECT_LT(draws, games / 10) << draws << " draws";
}

// Five hundred games of each; under the sanitizers the first hundred of
// them (what they add is memory and undefined behaviour, which the first
// hundred games cover as well as five hundred).
constexpr int kGames = kUnderSanitizers ? 100 : 500;

}  // namespace

TEST(GamesLong, FiveHundredEightBallGamesEndSoundly) {
  play_many(GameType::eight_ball, kGames, 8);
}

TEST(GamesLong, FiveHundredNineBallGamesEndSoundly) {
  play_many(GameType::nine_ball, kGames, 9);
}

}  // namespace test_games_long

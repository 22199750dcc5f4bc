// GameSession (include/breakshot/session.hpp): the one game step that the
// match runner, the browser's facade and replay share.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <variant>

#include "breakshot/match.hpp"
#include "breakshot/player.hpp"
#include "breakshot/record.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/session.hpp"

namespace test_session {

using namespace breakshot;

namespace {

Seats baseline_seats(const NoiseModel& noise) {
  return Seats{{"baseline", "baseline"}, {noise, noise}};
}

/// Plays a whole game through a session with baseline players.
GameSession play_through(const GameConfig& config, const NoiseModel& noise, std::uint64_t seed,
                         int breaker) {
  GameSession session(config, baseline_seats(noise), seed, breaker);
  const auto p = make_player("baseline");
  while (!session.over()) {
    session.play(p->decide(session.rules(), session.state(), session.next_player_seed()));
  }
  return session;
}

}  // namespace

TEST(Session, SeedStreamsAreApartAndFollowTheActionIndex) {
  const std::uint64_t s = 42;
  EXPECT_NE(GameSeeds::noise(s, 0), GameSeeds::noise(s, 1));
  EXPECT_NE(GameSeeds::player(s, 0), GameSeeds::noise(s, 0));
  EXPECT_NE(GameSeeds::rack(s), GameSeeds::noise(s, 0));
  EXPECT_NE(GameSeeds::rack(s), GameSeeds::player(s, 0));
  // The noise seed of action i is the one the record format documents.
  EXPECT_EQ(GameSeeds::noise(s, 5), mix_seed(s, 5));
}

TEST(Session, APlayedGameIsTheGamePlayGamePlays) {
  for (const GameType game : {GameType::eight_ball, GameType::nine_ball}) {
    GameConfig config;
    config.game = game;
    const NoiseModel noise = parse_noise("tournament");
    const GameSession session = play_through(config, noise, 9, 1);
    const auto p0 = make_player("baseline");
    const auto p1 = make_player("baseline");
    const GameRecord expected = play_game(Rules(config), *p0, *p1, 1, 9, noise);
    EXPECT_TRUE(session.record() == expected) << to_string(game);
    EXPECT_EQ(session.record().start.rack_seed, GameSeeds::rack(9));
    // Each action's noise seed follows its index, and a shot's executed
    // strike is its intended one with the seat's noise.
    for (std::size_t i = 0; i < session.record().actions.size(); ++i) {
      const RecordedAction& ra = session.record().actions[i];
      EXPECT_EQ(ra.noise_seed, GameSeeds::noise(9, i));
      if (const auto* shot = std::get_if<Shoot>(&ra.action)) {
        ASSERT_TRUE(ra.intended.has_value());
        EXPECT_TRUE(identical(shot->strike,
                              perturb(*ra.intended, noise, config.ball_radius, ra.noise_seed)));
      }
    }
    EXPECT_TRUE(replay(session.record()).identical);
  }
}

TEST(Session, RefusedActionLeavesTheGameUnchanged) {
  GameSession session(GameConfig{}, baseline_seats(NoiseModel{}), 3, 0);
  Shoot bad;
  bad.strike.speed = -1.0;  // not a strike the rules accept
  ASSERT_TRUE(session.check(bad).has_value());
  try {
    session.play(bad);
    FAIL() << "the session played a refused action";
  } catch (const GameSession::ExecutedRefused&) {
    FAIL() << "a refusal of the action as chosen was reported as after noise";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), *session.check(bad));
  }
  EXPECT_EQ(session.actions(), 0u);
  EXPECT_TRUE(session.state() == session.record().start);
}

TEST(Session, TakingBackAndPlayingAgainGivesTheSameGame) {
  GameConfig config;
  config.game = GameType::nine_ball;
  const GameSession whole = play_through(config, parse_noise("tournament"), 5, 0);
  const std::size_t n = whole.actions();
  ASSERT_GE(n, 3u);
  GameSession again = whole;
  again.take_back_to(n / 2);
  EXPECT_EQ(again.actions(), n / 2);
  EXPECT_TRUE(again.state() == whole.state_before(n / 2));
  for (std::size_t i = n / 2; i < n; ++i) {
    const RecordedAction& ra = whole.record().actions[i];
    Action chosen = ra.action;
    if (auto* shot = std::get_if<Shoot>(&chosen)) shot->strike = *ra.intended;
    again.play(chosen);
  }
  EXPECT_TRUE(again.record() == whole.record());
  EXPECT_THROW(again.take_back_to(n + 1), std::invalid_argument);
}

}  // namespace test_session

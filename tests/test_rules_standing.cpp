// Rules::standing, Rules::balls_on and Rules::ball_value: where a game
// stands for each side, read from the rules (docs/rules.md, "Standing"),
// checked by counting on hand-made tables.
#include <gtest/gtest.h>

#include <vector>

#include "breakshot/carom.hpp"
#include "rules_fixtures.hpp"
#include "snooker_fixtures.hpp"

namespace test_rules_standing {

using namespace breakshot;

namespace {

Rules rules_of(GameType game) {
  if (game == GameType::snooker) return Rules(snooker_config());
  if (game == GameType::three_cushion) return Rules(three_cushion_config());
  GameConfig c;
  c.game = game;
  return Rules(c);
}

}  // namespace

TEST(RulesStanding, EightBallCountsEachGroupsBallsLeftOnceTheGroupsAreSet) {
  const Rules rules = rules_fixtures::eight_ball_rules();
  GameState s = rules.start(3, 0);
  s.phase = Phase::shot;
  // Open table: nobody has balls to go yet.
  EXPECT_EQ(rules.standing(s), Standing{});
  s.group = {Group::stripes, Group::solids};
  // Take off the 2, 3 and 5 (solids), the 9 (a stripe) and leave the 8.
  for (int b : {2, 3, 5, 9}) s.on_table[static_cast<std::size_t>(b)] = 0;
  const Standing st = rules.standing(s);
  EXPECT_EQ(st.balls_to_go[0], 6);  // stripes 10-15
  EXPECT_EQ(st.balls_to_go[1], 4);  // solids 1, 4, 6, 7: the 8 is not one of them
  EXPECT_EQ(st.score[0], 0);
  EXPECT_EQ(st.points_left, -1);
  // The stripes all down: the shooter is on the 8, with none to go.
  for (int b = 10; b <= 15; ++b) s.on_table[static_cast<std::size_t>(b)] = 0;
  EXPECT_EQ(rules.standing(s).balls_to_go[0], 0);
  EXPECT_EQ(rules.balls_on(s), (std::vector<int>{8}));
  EXPECT_EQ(rules.ball_value(8), 1);
  EXPECT_EQ(rules.ball_value(0), 0);
  EXPECT_EQ(rules.ball_value(16), 0);
}

TEST(RulesStanding, RotationGamesHaveNoScoreAndTheLowestBallIsOn) {
  for (GameType g : {GameType::nine_ball, GameType::ten_ball}) {
    const Rules rules = rules_of(g);
    GameState s = rules.start(5, 1);
    s.phase = Phase::shot;
    s.on_table[1] = 0;
    s.on_table[2] = 0;
    EXPECT_EQ(rules.standing(s), Standing{}) << to_string(g);
    EXPECT_EQ(rules.balls_on(s), (std::vector<int>{3})) << to_string(g);
    EXPECT_EQ(rules.ball_value(rules.ball_count() - 1), 1) << to_string(g);
  }
}

TEST(RulesStanding, SnookerCountsTheScoreAndThePointsLeft) {
  const Rules& rules = snooker_fixtures::rules();
  GameState s = rules.start(9, 0);
  // A full table: 15 reds each with a black (8 x 15) and the colours
  // (2 + 3 + 4 + 5 + 6 + 7 = 27): the maximum break, 147.
  Standing st = rules.standing(s);
  EXPECT_EQ(st.points_left, 147);
  EXPECT_EQ(st.score, (std::array<int, 2>{0, 0}));
  EXPECT_EQ(st.balls_to_go, (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(rules.balls_on(s).size(), 15U);  // the reds
  // Player 1 leads 40-12 with three reds left and a red just potted: a
  // colour is on (7), then three reds with blacks (24) and the colours.
  s.phase = Phase::shot;
  s.player = 1;
  s.snooker->score = {12, 40};
  for (int b = 4; b <= 15; ++b) s.on_table[static_cast<std::size_t>(b)] = 0;
  s.snooker->colour_on = true;
  st = rules.standing(s);
  EXPECT_EQ(st.score, (std::array<int, 2>{12, 40}));
  EXPECT_EQ(st.points_left, 7 + 3 * 8 + 27);
  EXPECT_EQ(rules.balls_on(s), (std::vector<int>{16, 17, 18, 19, 20, 21}));
  const std::vector<int> values{1, 2, 3, 4, 5, 6, 7};
  for (int b = 15; b <= 21; ++b) EXPECT_EQ(rules.ball_value(b), values[static_cast<std::size_t>(b - 15)]);
  // The balls on are what snooker_balls_on says; a free ball widens the
  // targets, never the balls on.
  s.snooker->colour_on = false;
  s.snooker->free_ball = true;
  EXPECT_EQ(rules.balls_on(s), snooker_balls_on(s));
  EXPECT_GT(rules.targets(s).size(), rules.balls_on(s).size());
}

TEST(RulesStanding, ThreeCushionCountsPointsAndNoBallScoresByItself) {
  const Rules rules = rules_of(GameType::three_cushion);
  GameState s = rules.start(1, 0);
  s.carom->score = {7, 11};
  const Standing st = rules.standing(s);
  EXPECT_EQ(st.score, (std::array<int, 2>{7, 11}));
  EXPECT_EQ(st.points_left, -1);
  for (int b = 0; b < 3; ++b) EXPECT_EQ(rules.ball_value(b), 0);
}

}  // namespace test_rules_standing

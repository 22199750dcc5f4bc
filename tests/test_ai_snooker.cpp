// The AI levels at snooker (docs/ai.md, "Snooker") on hand-placed tables:
// a red over a pocket is potted with no nomination, a colour after a red
// is nominated and potted, the black is preferred to an equally easy
// yellow, a foul's choice goes to the side the table favours, a frame that
// needs snookers is conceded, the cue ball in hand is placed in the D, and
// whole frames between the levels end with every action legal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ai/evaluate.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/player.hpp"
#include "breakshot/players.hpp"
#include "breakshot/snooker.hpp"
#include "ai_fixtures.hpp"
#include "snooker_fixtures.hpp"
#include "sanitizers.hpp"

namespace test_ai_snooker {

using namespace breakshot;

namespace {

constexpr int kRed = 1;
constexpr int kYellow = 16;
constexpr int kBlack = 21;
constexpr double kR = kSnookerBallRadius;

using ai_fixtures::small_level;
using snooker_fixtures::put;
using snooker_fixtures::rules;

/// Only the cue ball on the table at `cue`, player 0 on a red at 0-0.
GameState bare(Vec2 cue) { return snooker_fixtures::bare(cue, 3); }

int pocket_index(const std::string& name) {
  const auto& pk = rules().table().pockets;
  for (std::size_t k = 0; k < pk.size(); ++k) {
    if (pk[k].name == name) return static_cast<int>(k);
  }
  ADD_FAILURE() << "no pocket " << name;
  return 0;
}

/// A ball `d` from the centre of `pocket` along the line toward the middle
/// of the table, and a cue ball `back` behind it on the same line.
struct StraightIn {
  Vec2 object;
  Vec2 cue;
};
StraightIn straight_in(int pocket, double d, double back) {
  const Vec2 c = rules().table().pockets[static_cast<std::size_t>(pocket)].centre;
  const Vec2 mid{0.5 * rules().table().length, 0.5 * rules().table().width};
  const Vec2 u = (mid - c) / norm(mid - c);
  return {c + u * d, c + u * (d + back)};
}

Action decide_legal(Player& p, const GameState& s, std::uint64_t seed = 1) {
  const Action a = p.decide(rules(), s, seed);
  const std::optional<std::string> why = rules().check(s, a);
  EXPECT_FALSE(why.has_value()) << why.value_or("");
  return a;
}

}  // namespace

TEST(AiSnooker, PotsARedOverAPocketWithoutNomination) {
  const StraightIn si = straight_in(pocket_index("top_right"), 0.25, 0.4);
  GameState s = bare(si.cue);
  put(s, kRed, si.object);
  put(s, kBlack, snooker_marks().black);
  for (const std::string level : {"beginner", "expert"}) {
    const auto player = make_ai_player(level == "beginner" ? ai_level(level) : small_level(level));
    const Action a = decide_legal(*player, s);
    ASSERT_TRUE(std::holds_alternative<Shoot>(a)) << level;
    EXPECT_FALSE(std::get<Shoot>(a).nominate.has_value()) << level;
    const Outcome out = rules().apply(s, a);  // as intended, without noise
    ASSERT_TRUE(out.ruling.snooker.has_value());
    EXPECT_EQ(out.ruling.snooker->points, 1) << level << ": " << out.ruling.text;
    EXPECT_TRUE(out.ruling.fouls.empty()) << level << ": " << out.ruling.text;
    EXPECT_TRUE(out.state.snooker->colour_on) << level;
  }
}

TEST(AiSnooker, NominatesTheColourItPotsAndPrefersTheBlack) {
  // After a red, the yellow and the black each hang over a corner pocket
  // with a straight shot of the same length: the black is worth 7, the
  // yellow 2, so the searching levels take the black.
  const int tr = pocket_index("top_right");
  const int br = pocket_index("bottom_right");
  const StraightIn b = straight_in(tr, 0.2, 0.5);
  const StraightIn y = straight_in(br, 0.2, 0.5);
  GameState s = bare(0.5 * (b.cue + y.cue));
  put(s, kBlack, b.object);
  put(s, kYellow, y.object);
  put(s, kRed + 1, {1.0, 0.5});  // reds remain: the potted colour comes back
  s.snooker->colour_on = true;
  for (const std::string level : {"club", "expert"}) {
    const auto player = make_ai_player(small_level(level));
    const Action a = decide_legal(*player, s);
    ASSERT_TRUE(std::holds_alternative<Shoot>(a)) << level;
    const Shoot& shot = std::get<Shoot>(a);
    ASSERT_TRUE(shot.nominate.has_value()) << level;
    EXPECT_EQ(*shot.nominate, kBlack) << level;
    const Outcome out = rules().apply(s, a);
    EXPECT_EQ(out.ruling.snooker->points, 7) << level << ": " << out.ruling.text;
  }
}

TEST(AiSnooker, ConcedesAFrameThatNeedsSnookers) {
  GameState s = bare({1.0, 0.9});
  put(s, kBlack, snooker_marks().black);  // the last ball: 7 left
  s.snooker->score = {20, 60};
  ASSERT_GT(snookers_required(s, 0), 0);
  const auto player = make_ai_player(small_level("club"));
  const Action a = decide_legal(*player, s);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::concede);
}

TEST(AiSnooker, PlacesTheCueBallInTheD) {
  // After an in-off: a red straight in from near the D.
  GameState s = bare({1.0, 0.9});
  s.on_table[0] = 0;
  s.ball_in_hand = BallInHand::d;
  const SnookerMarks m = snooker_marks();
  put(s, kRed, {m.baulk_x + 0.8, m.d_centre.y});
  put(s, kBlack, m.black);
  const auto player = make_ai_player(small_level("club"));
  const Action a = decide_legal(*player, s);
  ASSERT_TRUE(std::holds_alternative<PlaceCueBall>(a));
  const Vec2 p = std::get<PlaceCueBall>(a).position;
  EXPECT_LE(p.x, m.baulk_x + 1e-9);
  EXPECT_LE(norm(p - m.d_centre), m.d_radius + 1e-9);
}

TEST(AiSnooker, FoulChoiceTakesAnEasyPotAndLeavesAHardTable) {
  // After the opponent's foul the chooser plays on when a red hangs over a
  // pocket in front of the cue ball, and has the offender play again when
  // the only red is hidden behind the black (a snooker).
  const StraightIn si = straight_in(pocket_index("top_right"), 0.15, 0.3);
  GameState easy = bare(si.cue);
  put(easy, kRed, si.object);
  easy.phase = Phase::foul_choice;
  easy.snooker->score = {10, 10};
  const auto player = make_ai_player(small_level("club"));
  ASSERT_EQ(rules().legal_actions(easy).choices.empty(), false);
  Action a = decide_legal(*player, easy);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::play_on);

  const SnookerMarks m = snooker_marks();
  GameState hard = bare(m.blue);
  put(hard, kBlack, m.black);
  put(hard, kRed, {m.black.x + 2.0 * kR + 0.001, m.black.y});
  hard.phase = Phase::foul_choice;
  hard.snooker->score = {10, 10};
  a = decide_legal(*player, hard);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::offender_again);
}

TEST(AiSnooker, WholeFramesBetweenLevelsEndWithLegalActions) {
  // Two frames of the beginner against the amateur (one under the
  // sanitizers), played through the match runner (every action checked by
  // the rules), end with a winner and scores that add up to the points of
  // the rulings.
  const int frames = kUnderSanitizers ? 1 : 2;
  MatchOptions o;
  o.game = GameType::snooker;
  o.table_size = "12ft";
  o.games = frames;
  o.seed = 4;
  o.noise = parse_noise("tournament");
  o.players = {"beginner", "amateur"};
  std::vector<GameRecord> records;
  const MatchSummary sum = play_match(o, [&](int, const GameRecord& r) { records.push_back(r); });
  ASSERT_EQ(records.size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(sum.players[0].games_won + sum.players[1].games_won + sum.draws, frames);
  for (const GameRecord& r : records) {
    std::array<int, 2> points{0, 0};
    for (const RecordedAction& ra : r.actions) {
      if (!ra.ruling.snooker) continue;
      points[static_cast<std::size_t>(ra.player)] += ra.ruling.snooker->points;
      points[static_cast<std::size_t>(1 - ra.player)] += ra.ruling.snooker->penalty;
    }
    ASSERT_FALSE(r.actions.empty());
    const GameState& end = r.actions.back().after;
    ASSERT_TRUE(end.snooker.has_value());
    EXPECT_EQ(end.phase, Phase::game_over);
    EXPECT_EQ(end.snooker->score[0], points[0]);
    EXPECT_EQ(end.snooker->score[1], points[1]);
  }
}

// The break-off: every level plays a shot at the reds from the D, not a
// fallback. Played without noise it hits a red first and fouls nothing
// (the earlier break-off aimed straight up the table into the pink).
TEST(AiSnooker, BreakOffHitsARedCleanly) {
  const GameState start = rules().start(11, 0);
  ASSERT_EQ(start.phase, Phase::break_shot);
  for (const std::string level : {"beginner", "amateur", "champion"}) {
    const auto player =
        make_ai_player(level == "champion" ? small_level(level) : ai_level(level));
    GameState s = start;
    Action a = decide_legal(*player, s);
    if (std::holds_alternative<PlaceCueBall>(a)) {
      s = rules().apply(s, a).state;
      a = decide_legal(*player, s);
    }
    ASSERT_TRUE(std::holds_alternative<Shoot>(a)) << level;
    const Outcome out = rules().apply(s, a);
    EXPECT_TRUE(out.ruling.fouls.empty()) << level << ": " << out.ruling.text;
    ASSERT_FALSE(out.facts.first_hit < 0) << level;
    EXPECT_EQ(snooker_value(out.facts.first_hit), 1) << level << ": " << out.ruling.text;
  }
}

}  // namespace test_ai_snooker

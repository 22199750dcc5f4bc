// 10-ball's rules (src/game/rules_ten.cpp; docs/rules.md, "10-ball"),
// clause by clause. The shots are ruled from hand-made event lists
// (Rules::apply_events), so each clause is tested alone; whole games on
// the engine, with every level and the baseline, are at the end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"

namespace test_rules_ten {

using namespace breakshot;

namespace {

const Rules& rules() {
  static const Rules r([] {
    GameConfig c;
    c.game = GameType::ten_ball;
    return c;
  }());
  return r;
}

Event hit(int ball, double t = 0.1) {
  Event e;
  e.time = t;
  e.type = EventType::ball_ball;
  e.ball = 0;
  e.other = ball;
  return e;
}

Event pocket(int ball, int pocket_index, double t = 0.5) {
  Event e;
  e.time = t;
  e.type = EventType::ball_pocket;
  e.ball = ball;
  e.pocket = pocket_index;
  return e;
}

Event cushion(int ball, double t = 0.3) {
  Event e;
  e.time = t;
  e.type = EventType::ball_cushion;
  e.ball = ball;
  e.wall = 0;
  return e;
}

/// A shot from `s` ruled as if the engine had played these events, every
/// ball coming to rest where it stood.
Outcome rule(const GameState& s, const Shoot& shot, const std::vector<Event>& events) {
  return rules().apply_events(s, shot, events, s.position);
}

Shoot called(int ball, int pocket_index) {
  Shoot sh;
  sh.strike.speed = 2.0;
  sh.call = Call{ball, pocket_index};
  return sh;
}

Shoot safety() {
  Shoot sh;
  sh.strike.speed = 2.0;
  sh.safety = true;
  return sh;
}

Shoot break_shot() {
  Shoot sh;
  sh.strike.speed = 8.0;
  return sh;
}

/// After the break: player 0 to shoot, no ball in hand, all balls up.
GameState in_play() {
  GameState s = rules().start(5, 0);
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.shots = 1;
  s.push_out_allowed = false;
  return s;
}

bool on(const GameState& s, int b) { return s.on_table[static_cast<std::size_t>(b)] != 0; }

}  // namespace

TEST(RulesTenRack, TheOneOnTheFootSpotAndTheTenInTheMiddle) {
  const GameState s = rules().start(3, 0);
  ASSERT_EQ(s.position.size(), 11u);
  for (int b = 0; b <= 10; ++b) EXPECT_TRUE(on(s, b)) << b;
  const Vec2 foot = rules().table().foot_spot;
  EXPECT_LT(norm(s.position[1] - foot), 1e-9);  // the apex is not jittered
  // The 10 in the middle of the third row: on the long string, two rows
  // behind the apex (2 x sqrt(3) R apart, plus the racking gaps).
  EXPECT_NEAR(s.position[10].y, foot.y, 0.001);
  EXPECT_NEAR(s.position[10].x - foot.x, 2.0 * std::sqrt(3.0) * kPoolBallRadius, 0.002);
  // Ten object balls in rows of 1-2-3-4: the back row four balls wide.
  double back = 0.0;
  for (int b = 1; b <= 10; ++b) back = std::max(back, s.position[static_cast<std::size_t>(b)].x);
  EXPECT_NEAR(back - foot.x, 3.0 * std::sqrt(3.0) * kPoolBallRadius, 0.003);
  EXPECT_EQ(s.phase, Phase::break_shot);
  EXPECT_EQ(s.ball_in_hand, BallInHand::kitchen);
  // Other seeds place 2-9 otherwise; the 1 and the 10 stay.
  const GameState t = rules().start(4, 0);
  EXPECT_LT(norm(t.position[1] - foot), 1e-9);
  EXPECT_LT(norm(t.position[10] - s.position[10]), 0.002);
}

TEST(RulesTenCalls, EveryShotButTheBreakIsCalledOrASafety) {
  const GameState s = in_play();
  const LegalActions la = rules().legal_actions(s);
  EXPECT_TRUE(la.call);
  EXPECT_EQ(la.targets, std::vector<int>{1});
  Shoot bare;
  bare.strike.speed = 2.0;
  EXPECT_TRUE(rules().check(s, Action{bare}).has_value());
  EXPECT_NE(rules().check(s, Action{bare})->find("calls a ball and a pocket"), std::string::npos);
  EXPECT_FALSE(rules().check(s, Action{called(3, 2)}));  // any ball may be called
  EXPECT_FALSE(rules().check(s, Action{safety()}));
  Shoot both = called(1, 0);
  both.safety = true;
  EXPECT_TRUE(rules().check(s, Action{both}).has_value());
  EXPECT_TRUE(rules().check(s, Action{called(1, 9)}).has_value());  // no such pocket
  // The break is never called.
  const GameState b = rules().start(5, 0);
  GameState placed = rules().apply(b, Action{PlaceCueBall{rules().table().head_spot}}).state;
  EXPECT_FALSE(rules().check(placed, Action{break_shot()}));
  EXPECT_TRUE(rules().check(placed, Action{called(1, 0)}).has_value());
  EXPECT_FALSE(rules().legal_actions(placed).call);
}

TEST(RulesTenBreak, TheTenOnALegalBreakIsSpottedAndTheBreakerGoesOn) {
  GameState s = rules().start(5, 0);
  s = rules().apply(s, Action{PlaceCueBall{rules().table().head_spot}}).state;
  const Outcome o = rule(s, break_shot(), {hit(1), pocket(10, 3), pocket(4, 1)});
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_TRUE(on(o.state, 10));   // spotted
  EXPECT_FALSE(on(o.state, 4));  // stays down
  EXPECT_EQ(o.state.player, 0);
  EXPECT_TRUE(o.state.push_out_allowed);
  EXPECT_NE(o.state.phase, Phase::game_over);
  // The 10 alone is a pocketed ball: the break is legal, the breaker on.
  const Outcome alone = rule(s, break_shot(), {hit(1), pocket(10, 3)});
  EXPECT_TRUE(alone.ruling.legal_break);
  EXPECT_TRUE(on(alone.state, 10));
  EXPECT_EQ(alone.state.player, 0);
}

TEST(RulesTenBreak, TooSoftOrTheWrongBallIsAFoul) {
  GameState s = rules().start(5, 0);
  s = rules().apply(s, Action{PlaceCueBall{rules().table().head_spot}}).state;
  const Outcome soft = rule(s, break_shot(), {hit(1), cushion(2), cushion(3)});
  EXPECT_FALSE(soft.ruling.legal_break);
  EXPECT_FALSE(soft.ruling.fouls.empty());
  EXPECT_EQ(soft.state.player, 1);
  EXPECT_EQ(soft.state.ball_in_hand, BallInHand::anywhere);
  const Outcome wrong = rule(s, break_shot(), {hit(2), pocket(5, 0)});
  EXPECT_FALSE(wrong.ruling.fouls.empty());
  EXPECT_EQ(wrong.state.player, 1);
}

TEST(RulesTenShots, TheCallMadeContinuesAndTheCalledTenWins) {
  const GameState s = in_play();
  const Outcome made = rule(s, called(1, 2), {hit(1), pocket(1, 2)});
  EXPECT_TRUE(made.ruling.fouls.empty());
  EXPECT_TRUE(made.ruling.turn_continues);
  EXPECT_EQ(made.state.player, 0);
  EXPECT_TRUE(made.ruling.call_made);
  // A combination: the 1 first, the called 10 in its pocket.
  const Outcome win = rule(s, called(10, 4), {hit(1), pocket(10, 4)});
  EXPECT_EQ(win.state.phase, Phase::game_over);
  EXPECT_EQ(win.state.winner, 0);
  // The called ball made, the 10 down uncalled: spotted, the turn goes on.
  const Outcome extra = rule(s, called(1, 2), {hit(1), pocket(1, 2), pocket(10, 5)});
  EXPECT_TRUE(on(extra.state, 10));
  EXPECT_EQ(extra.state.player, 0);
  EXPECT_NE(extra.state.phase, Phase::game_over);
}

TEST(RulesTenShots, ABallPocketedWronglyLetsTheOpponentChoose) {
  const GameState s = in_play();
  // The called ball in another pocket.
  const Outcome wrong = rule(s, called(1, 2), {hit(1), pocket(1, 3)});
  EXPECT_TRUE(wrong.ruling.fouls.empty());
  EXPECT_FALSE(on(wrong.state, 1));  // it stays down
  EXPECT_EQ(wrong.state.phase, Phase::push_out_choice);
  EXPECT_EQ(wrong.state.player, 1);
  const LegalActions la = rules().legal_actions(wrong.state);
  EXPECT_EQ(la.choices, (std::vector<Choice>{Choice::shoot, Choice::pass_back}));
  // Handed back: the shooter of the wrong pot plays on from there.
  const Outcome back = rules().apply(wrong.state, Action{Decide{Choice::pass_back}});
  EXPECT_EQ(back.state.phase, Phase::shot);
  EXPECT_EQ(back.state.player, 0);
  EXPECT_EQ(back.state.ball_in_hand, BallInHand::none);
  const Outcome taken = rules().apply(wrong.state, Action{Decide{Choice::shoot}});
  EXPECT_EQ(taken.state.player, 1);
  EXPECT_EQ(taken.state.phase, Phase::shot);
  // Another ball than the one called, the 10 with it: the 10 is spotted.
  const Outcome other = rule(s, called(1, 2), {hit(1), pocket(3, 0), pocket(10, 1)});
  EXPECT_EQ(other.state.phase, Phase::push_out_choice);
  EXPECT_TRUE(on(other.state, 10));
  EXPECT_FALSE(on(other.state, 3));
  // Nothing down: the turn simply passes.
  const Outcome none = rule(s, called(1, 2), {hit(1), cushion(1)});
  EXPECT_EQ(none.state.phase, Phase::shot);
  EXPECT_EQ(none.state.player, 1);
}

TEST(RulesTenShots, ASafetyEndsTheInningWithItsBallsDown) {
  const GameState s = in_play();
  const Outcome o = rule(s, safety(), {hit(1), pocket(6, 0), pocket(10, 2), cushion(1)});
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(on(o.state, 6));
  EXPECT_TRUE(on(o.state, 10));
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
}

TEST(RulesTenFouls, TheTenOnAFoulIsSpottedAndThreeFoulsLose) {
  GameState s = in_play();
  const Outcome foul = rule(s, called(3, 0), {hit(3), pocket(10, 1)});
  EXPECT_FALSE(foul.ruling.fouls.empty());  // the 1 was not hit first
  EXPECT_TRUE(on(foul.state, 10));
  EXPECT_EQ(foul.state.player, 1);
  EXPECT_EQ(foul.state.ball_in_hand, BallInHand::anywhere);
  // Player 0 on two fouls fouls again: player 1 wins.
  s.fouls_in_a_row = {2, 0};
  const Outcome third = rule(s, called(1, 0), {hit(1)});  // no rail
  EXPECT_EQ(third.state.phase, Phase::game_over);
  EXPECT_EQ(third.state.winner, 1);
  // A legal shot clears the count.
  const Outcome legal = rule(s, called(1, 0), {hit(1), pocket(1, 0)});
  EXPECT_EQ(legal.state.fouls_in_a_row[0], 0);
}

TEST(RulesTenPushOut, AfterTheBreakTheOpponentChooses) {
  GameState s = in_play();
  s.push_out_allowed = true;
  Shoot push;
  push.strike.speed = 1.0;
  push.push_out = true;
  EXPECT_TRUE(rules().legal_actions(s).push_out);
  EXPECT_FALSE(rules().check(s, Action{push}));
  const Outcome o = rule(s, push, {});
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.state.phase, Phase::push_out_choice);
  EXPECT_EQ(o.state.player, 1);
  s.push_out_allowed = false;
  EXPECT_TRUE(rules().check(s, Action{push}).has_value());
}

// Whole games on the engine: every level and the baseline play 10-ball
// with no 10-ball code in the AI (its policy is 9-ball's rotation), every
// game ends, and every record replays identical.
TEST(RulesTenGames, EveryPlayerPlaysWholeGamesThatReplay) {
  for (const auto& [a, b] : {std::pair<const char*, const char*>{"baseline", "beginner"},
                             std::pair<const char*, const char*>{"amateur", "club"}}) {
    MatchOptions opt;
    opt.game = GameType::ten_ball;
    opt.players = {a, b};
    opt.games = 2;
    opt.seed = 12;
    opt.noise = parse_noise("tournament");
    std::vector<GameRecord> records;
    const MatchSummary sum = play_match(opt, [&](int, const GameRecord& r) { records.push_back(r); });
    EXPECT_EQ(sum.games_played, 2) << a;
    ASSERT_EQ(records.size(), 2u);
    for (const GameRecord& r : records) {
      ASSERT_FALSE(r.actions.empty());
      EXPECT_EQ(r.actions.back().after.phase, Phase::game_over) << a;
      const ReplayReport rep = replay(r);
      EXPECT_TRUE(rep.identical) << a << ": " << rep.message;
      const std::string text = write_record(r);
      EXPECT_NE(text.find("\"game\":\"ten_ball\""), std::string::npos);
      const auto back = read_record(text);
      ASSERT_TRUE(std::holds_alternative<GameRecord>(back));
      EXPECT_TRUE(std::get<GameRecord>(back) == r);
    }
  }
}

}  // namespace test_rules_ten

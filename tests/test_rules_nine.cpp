// 9-ball (WPA) rule by rule: each clause from a hand-placed table (or a
// seeded rack) and a shot that Rules::apply simulates.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "rules_fixtures.hpp"

namespace test_rules_nine {

using namespace breakshot;
using namespace rules_fixtures;

namespace {

constexpr double kBreakSpeed = 10.0;  // m/s

Outcome break_rack(const Rules& rules, std::uint64_t seed, double speed) {
  const GameState s = rules.start(seed, 0);
  return rules.apply(s, shot_at(s.position[0], rules.table().foot_spot, speed));
}

Vec2 diagonal_br() { return {2.54 - 0.5, 0.5}; }

}  // namespace

// ---------------------------------------------------------------------------
// The break

TEST(RulesNineBreak, PocketingABallContinuesAndAllowsAPushOut) {
  const Rules rules = nine_ball_rules();
  const Outcome o = break_rack(rules, 4, kBreakSpeed);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_FALSE(o.facts.pocketed.empty());
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  ASSERT_FALSE(includes(o.facts.pocketed, 9));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_TRUE(o.state.push_out_allowed);
  EXPECT_TRUE(rules.legal_actions(o.state).push_out);
  for (int b : o.facts.pocketed) EXPECT_FALSE(on(o.state, b)) << "ball " << b;
}

TEST(RulesNineBreak, TooSoftABreakIsAFoulWithBallInHandAnywhere) {
  const Rules rules = nine_ball_rules();
  const Outcome o = break_rack(rules, 1, 1.0);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_TRUE(o.facts.pocketed.empty());
  ASSERT_LT(o.facts.object_balls_to_cushion, 4);
  EXPECT_FALSE(o.ruling.legal_break);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::illegal_break});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.fouls_in_a_row[0], 1);
}

TEST(RulesNineBreak, HittingTheTwoFirstIsAFoulWithBallInHandAnywhere) {
  const Rules rules = nine_ball_rules();
  GameState s = rules.start(1, 0);
  put(s, 2, {1.3, 0.25});  // out of the rack, in the cue ball's way
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[2], 5.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 2);
  ASSERT_FALSE(includes(o.facts.pocketed, 9));
  EXPECT_TRUE(has_foul(o.ruling, Foul::wrong_ball_first));
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.fouls_in_a_row[0], 1);
  EXPECT_EQ(rules.legal_actions(o.state).place, BallInHand::anywhere);
  // The incoming player may still push out (docs/rules.md: also after a
  // foul on the break).
  EXPECT_TRUE(o.state.push_out_allowed);
  EXPECT_TRUE(rules.legal_actions(o.state).push_out);
}

TEST(RulesNineBreak, TheNineOnALegalBreakWins) {
  // A hand-made break: the 1 drives the 9 into the top-right corner.
  const Rules rules = nine_ball_rules();
  const int tr = pocket_index(rules, "top_right");
  const Vec2 head{0.6, 0.9};  // in the kitchen
  ASSERT_LE(head.x, rules.head_string());
  const Combination c = combination(rules, tr, head, 0.2, 0.0);
  GameState s = rules.start(2, 0);
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  put(s, 0, head);
  put(s, 9, c.target);
  put(s, 1, c.carrier);
  put(s, 2, {2.2, 0.3});
  put(s, 3, {2.0, 0.2});
  put(s, 4, {1.6, 0.15});
  ASSERT_EQ(s.phase, Phase::break_shot);
  const Outcome o = rules.apply(s, shot_at(head, c.carrier, 5.0, -0.3));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_EQ(pocket_of(o.facts, 9), tr);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_EQ(o.ruling.winner, 0);
  EXPECT_TRUE(o.ruling.spotted.empty());
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 0);
  EXPECT_FALSE(o.state.result.empty());
}

// ---------------------------------------------------------------------------
// Shots

TEST(RulesNineShots, TheNineOnAFoulIsSpotted) {
  // The 1 is on the table: pocketing the 9 directly is a foul.
  const Rules rules = nine_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, si.cue);
  put(s, 9, si.object);
  put(s, 1, {0.8, 1.0});
  const Outcome o = rules.apply(s, shot_at(si.cue, si.object, 2.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 9);
  ASSERT_EQ(pocket_of(o.facts, 9), br);
  EXPECT_TRUE(has_foul(o.ruling, Foul::wrong_ball_first));
  EXPECT_EQ(o.ruling.spotted, std::vector<int>{9});
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_EQ(o.state.winner, -1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  ASSERT_TRUE(on(o.state, 9));
  // Back on the foot spot, which nothing blocks here.
  EXPECT_EQ(o.state.position[9].x, rules.table().foot_spot.x);
  EXPECT_EQ(o.state.position[9].y, rules.table().foot_spot.y);
}

TEST(RulesNineShots, HittingAHigherBallFirstIsAFoul) {
  const Rules rules = nine_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 3, {1.27, 0.635});
  put(s, 1, {1.8, 1.0});
  put(s, 9, {0.6, 1.0});
  ASSERT_EQ(rules.legal_actions(s).targets, std::vector<int>{1});
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[3], 1.5));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 3);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::wrong_ball_first});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.fouls_in_a_row[0], 1);
}

TEST(RulesNineShots, AnyBallLegallyPocketedContinuesTheTurn) {
  // A combination: the 1 first, the 5 goes in.
  const Rules rules = nine_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const Combination c = combination(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, c.cue);
  put(s, 5, c.target);
  put(s, 1, c.carrier);
  put(s, 3, {0.8, 0.9});
  put(s, 9, {1.0, 1.0});
  const Outcome o = rules.apply(s, shot_at(c.cue, c.carrier, 3.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_EQ(pocket_of(o.facts, 5), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_FALSE(on(o.state, 5));
  EXPECT_FALSE(o.state.push_out_allowed);
  EXPECT_FALSE(o.ruling.call_made);  // no call

  // A 9-ball call is informational: the same shot called on the 5 in this
  // pocket gets the same ruling, marked as a pot made; called elsewhere,
  // the same ruling, not marked.
  Shoot called = shot_at(c.cue, c.carrier, 3.0);
  called.call = Call{5, br};
  const Outcome oc = rules.apply(s, called);
  EXPECT_EQ(oc.state, o.state);
  EXPECT_EQ(oc.ruling.fouls, o.ruling.fouls);
  EXPECT_EQ(oc.ruling.turn_continues, o.ruling.turn_continues);
  EXPECT_TRUE(oc.ruling.call_made);
  called.call = Call{5, (br + 1) % 6};
  const Outcome ow = rules.apply(s, called);
  EXPECT_EQ(ow.state, o.state);
  EXPECT_TRUE(ow.ruling.turn_continues);
  EXPECT_FALSE(ow.ruling.call_made);
}

TEST(RulesNineShots, TheNineLegallyPocketedOnACombinationWins) {
  const Rules rules = nine_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const Combination c = combination(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, c.cue);
  put(s, 9, c.target);
  put(s, 1, c.carrier);
  put(s, 3, {0.8, 0.9});
  const Outcome o = rules.apply(s, shot_at(c.cue, c.carrier, 3.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_EQ(pocket_of(o.facts, 9), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, 0);
  EXPECT_TRUE(o.ruling.spotted.empty());
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 0);
  EXPECT_FALSE(on(o.state, 9));
}

// ---------------------------------------------------------------------------
// Push-out

namespace {

// Player 1 to shoot right after a break that player 0 made: a push-out
// may be declared.
GameState push_out_layout(const Rules& rules) {
  GameState s = bare_table(rules, {0.8, 0.5}, 1);
  s.breaker = 0;
  s.push_out_allowed = true;
  put(s, 1, {1.9, 0.9});
  put(s, 4, {2.2, 0.4});
  put(s, 9, {1.5, 1.0});
  return s;
}

// A soft roll toward the bottom cushion that touches no ball.
Shoot soft_push(const GameState& s) {
  Shoot sh = shot_at(s.position[0], s.position[0] + Vec2{0.0, -1.0}, 0.4);
  sh.push_out = true;
  return sh;
}

}  // namespace

TEST(RulesNinePushOut, APushOutTouchingNoBallIsNoFoulAndTheOpponentChooses) {
  const Rules rules = nine_ball_rules();
  const GameState s = push_out_layout(rules);
  ASSERT_TRUE(rules.legal_actions(s).push_out);
  const Outcome o = rules.apply(s, soft_push(s));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, -1);
  ASSERT_TRUE(o.facts.pocketed.empty());
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::push_out_choice);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.fouls_in_a_row[1], 0);
  EXPECT_TRUE(o.state.after_push_out);
  EXPECT_FALSE(o.state.push_out_allowed);
  EXPECT_EQ(rules.legal_actions(o.state).choices,
            (std::vector<Choice>{Choice::shoot, Choice::pass_back}));
}

TEST(RulesNinePushOut, ShootTakesTheTableAsItIs) {
  const Rules rules = nine_ball_rules();
  const GameState s = push_out_layout(rules);
  const Outcome pushed = rules.apply(s, soft_push(s));
  ASSERT_EQ(pushed.state.phase, Phase::push_out_choice);
  const Outcome o = rules.apply(pushed.state, Decide{Choice::shoot});
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(o.state.position, pushed.state.position);
  EXPECT_TRUE(rules.legal_actions(o.state).shoot);
  EXPECT_FALSE(rules.legal_actions(o.state).push_out);
}

TEST(RulesNinePushOut, PassBackGivesTheShotToThePusher) {
  const Rules rules = nine_ball_rules();
  const GameState s = push_out_layout(rules);
  const Outcome pushed = rules.apply(s, soft_push(s));
  ASSERT_EQ(pushed.state.phase, Phase::push_out_choice);
  const Outcome o = rules.apply(pushed.state, Decide{Choice::pass_back});
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(o.state.position, pushed.state.position);
  EXPECT_FALSE(rules.legal_actions(o.state).push_out);
}

TEST(RulesNinePushOut, BallsPocketedOnAPushOutStayDown) {
  // The push-out may hit any ball first: the 5 goes straight in.
  const Rules rules = nine_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = push_out_layout(rules);
  s.position[0] = si.cue;
  put(s, 5, si.object);
  Shoot sh = shot_at(si.cue, si.object, 2.0);
  sh.push_out = true;
  const Outcome o = rules.apply(s, sh);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 5);
  ASSERT_EQ(pocket_of(o.facts, 5), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.spotted.empty());
  EXPECT_FALSE(on(o.state, 5));
  EXPECT_EQ(o.state.phase, Phase::push_out_choice);
  EXPECT_EQ(o.state.player, 0);
}

TEST(RulesNinePushOut, TheNinePocketedOnAPushOutIsSpotted) {
  const Rules rules = nine_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = push_out_layout(rules);
  s.position[0] = si.cue;
  s.position[9] = si.object;
  Shoot sh = shot_at(si.cue, si.object, 2.0);
  sh.push_out = true;
  const Outcome o = rules.apply(s, sh);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 9);
  ASSERT_EQ(pocket_of(o.facts, 9), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_EQ(o.ruling.spotted, std::vector<int>{9});
  ASSERT_TRUE(on(o.state, 9));
  EXPECT_EQ(o.state.position[9].y, rules.table().foot_spot.y);
  EXPECT_EQ(o.state.position[9].x, rules.table().foot_spot.x);
  EXPECT_EQ(o.state.phase, Phase::push_out_choice);
  EXPECT_EQ(o.state.winner, -1);
}

TEST(RulesNinePushOut, AScratchOnAPushOutIsStillAFoul) {
  const Rules rules = nine_ball_rules();
  GameState s = push_out_layout(rules);
  s.position[0] = {0.3, 0.3};
  Shoot sh = shot_at(s.position[0], pocket_centre(rules, pocket_index(rules, "bottom_left")), 1.5);
  sh.push_out = true;
  const Outcome o = rules.apply(s, sh);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.pocketed, std::vector<int>{0});
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::scratch});
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.fouls_in_a_row[1], 1);
  EXPECT_TRUE(rules.legal_actions(o.state).must_place);
}

TEST(RulesNinePushOut, IsAllowedOnlyOnTheShotAfterTheBreak) {
  const Rules rules = nine_ball_rules();
  // After a real break that passes the turn, the incoming player may push out.
  const Outcome broke = break_rack(rules, 2, kBreakSpeed);
  SCOPED_TRACE(describe(broke));
  ASSERT_TRUE(broke.ruling.fouls.empty());
  ASSERT_EQ(broke.state.player, 1);
  EXPECT_TRUE(broke.state.push_out_allowed);
  EXPECT_TRUE(rules.legal_actions(broke.state).push_out);
  Shoot declared = shot_at(broke.state.position[0], broke.state.position[1], 1.0);
  declared.push_out = true;
  EXPECT_EQ(rules.check(broke.state, declared), std::nullopt);

  // After a shot that was not a push-out, it is too late.
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = push_out_layout(rules);
  s.position[0] = si.cue;
  s.position[1] = si.object;
  const Outcome potted = rules.apply(s, shot_at(si.cue, si.object, 2.0));
  SCOPED_TRACE(describe(potted));
  ASSERT_EQ(pocket_of(potted.facts, 1), br);
  ASSERT_TRUE(potted.ruling.turn_continues);
  EXPECT_FALSE(potted.state.push_out_allowed);
  EXPECT_FALSE(rules.legal_actions(potted.state).push_out);
  Shoot late = shot_at(potted.state.position[0], potted.state.position[4], 1.0);
  late.push_out = true;
  const auto why = rules.check(potted.state, late);
  ASSERT_TRUE(why.has_value());
  EXPECT_FALSE(why->empty());
  EXPECT_THROW(rules.apply(potted.state, late), std::invalid_argument);

  // And after a push-out, the next shot is no push-out either.
  const Outcome pushed = rules.apply(push_out_layout(rules), soft_push(push_out_layout(rules)));
  const Outcome taken = rules.apply(pushed.state, Decide{Choice::shoot});
  Shoot again = shot_at(taken.state.position[0], taken.state.position[1], 1.0);
  again.push_out = true;
  EXPECT_TRUE(rules.check(taken.state, again).has_value());
}

// ---------------------------------------------------------------------------
// Three fouls in a row, ball in hand

namespace {

// The balls of the three-foul sequences, well away from the head rail.
GameState three_foul_layout(const Rules& rules) {
  GameState s = bare_table(rules, {0.3, 0.3}, 0);
  put(s, 1, {1.9, 0.9});
  put(s, 9, {2.3, 1.0});
  return s;
}

// From ball in hand: put the cue ball near the head rail and roll it softly
// into that rail, touching no ball (a no-contact foul).
Outcome miss_shot(const Rules& rules, const GameState& s, int expect_streak) {
  GameState t = s;
  if (t.ball_in_hand != BallInHand::none) {
    t = rules.apply(t, PlaceCueBall{{0.3, 0.3}}).state;
  }
  const Outcome o = rules.apply(t, shot_at(t.position[0], {0.0, t.position[0].y}, 0.5));
  EXPECT_EQ(o.facts.first_hit, -1) << describe(o);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_contact}) << describe(o);
  EXPECT_EQ(o.state.fouls_in_a_row[static_cast<std::size_t>(s.player)], expect_streak)
      << describe(o);
  return o;
}

GameState miss(const Rules& rules, const GameState& s, int expect_streak) {
  return miss_shot(rules, s, expect_streak).state;
}

}  // namespace

TEST(RulesNineFouls, ThreeFoulsInARowLose) {
  const Rules rules = nine_ball_rules();
  GameState s = three_foul_layout(rules);
  s = miss(rules, s, 1);  // player 0: first foul
  ASSERT_EQ(s.player, 1);
  s = miss(rules, s, 1);  // player 1 fouls too (that does not help player 0)
  ASSERT_EQ(s.player, 0);
  const Outcome second = miss_shot(rules, s, 2);  // player 0: second foul
  ASSERT_EQ(second.state.phase, Phase::shot);
  // The warning comes with the ruling.
  EXPECT_NE(second.ruling.text.find("two fouls"), std::string::npos) << second.ruling.text;
  s = miss(rules, second.state, 2);  // player 1
  ASSERT_EQ(s.player, 0);
  ASSERT_EQ(s.phase, Phase::shot);
  ASSERT_EQ(s.fouls_in_a_row[0], 2);

  // Player 0's third foul in a row.
  const GameState placed = rules.apply(s, PlaceCueBall{{0.3, 0.3}}).state;
  const Outcome o = rules.apply(placed, shot_at({0.3, 0.3}, {0.0, 0.3}, 0.5));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_contact});
  EXPECT_EQ(o.state.fouls_in_a_row[0], 3);
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
  EXPECT_FALSE(o.state.result.empty());
}

TEST(RulesNineFouls, ALegalShotInBetweenResetsTheCount) {
  const Rules rules = nine_ball_rules();
  GameState s = three_foul_layout(rules);
  s = miss(rules, s, 1);  // player 0
  s = miss(rules, s, 1);  // player 1
  s = miss(rules, s, 2);  // player 0: two in a row
  s = miss(rules, s, 2);  // player 1
  ASSERT_EQ(s.player, 0);
  ASSERT_EQ(s.fouls_in_a_row[0], 2);

  // Player 0 takes ball in hand and pockets the 1: a legal shot.
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  s.position[1] = si.object;  // hand-moved for a straight-in shot
  const GameState placed = rules.apply(s, PlaceCueBall{si.cue}).state;
  const Outcome legal = rules.apply(placed, shot_at(si.cue, si.object, 2.0));
  SCOPED_TRACE(describe(legal));
  ASSERT_EQ(pocket_of(legal.facts, 1), br);
  ASSERT_TRUE(legal.ruling.fouls.empty());
  EXPECT_TRUE(legal.ruling.turn_continues);
  EXPECT_EQ(legal.state.fouls_in_a_row[0], 0);
  EXPECT_EQ(legal.state.fouls_in_a_row[1], 2);  // player 1's streak is player 1's

  // A foul now is player 0's first again, not the third: from where the
  // cue ball stopped, a soft roll into the bottom cushion touches nothing.
  const Vec2 cue = legal.state.position[0];
  const Outcome o = rules.apply(legal.state, shot_at(cue, {cue.x, 0.0}, 0.4));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_contact});
  EXPECT_EQ(o.state.fouls_in_a_row[0], 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.winner, -1);
}

TEST(RulesNineFouls, BallInHandAnywhereAfterAFoul) {
  const Rules rules = nine_ball_rules();
  const GameState s = miss(rules, three_foul_layout(rules), 1);
  ASSERT_EQ(s.player, 1);
  ASSERT_EQ(s.ball_in_hand, BallInHand::anywhere);
  const LegalActions la = rules.legal_actions(s);
  EXPECT_EQ(la.place, BallInHand::anywhere);
  EXPECT_FALSE(la.must_place);  // no scratch: it may also be played where it lies

  // Anywhere: beyond the head string too.
  const Vec2 foot_half{2.0, 0.6};
  ASSERT_GT(foot_half.x, rules.head_string());
  EXPECT_EQ(rules.check(s, PlaceCueBall{foot_half}), std::nullopt);
  const Outcome placed = rules.apply(s, PlaceCueBall{foot_half});
  EXPECT_EQ(placed.state.position[0], foot_half);
  EXPECT_EQ(placed.state.phase, Phase::shot);
  EXPECT_EQ(placed.state.player, 1);
  EXPECT_EQ(placed.state.ball_in_hand, BallInHand::none);
  EXPECT_FALSE(placed.state.kitchen_shot);

  // Not on another ball.
  const PlaceCueBall on_one{s.position[1] + Vec2{kR, 0.0}};
  const auto overlap = rules.check(s, on_one);
  ASSERT_TRUE(overlap.has_value());
  EXPECT_NE(overlap->find("ball 1"), std::string::npos) << *overlap;
  EXPECT_THROW(rules.apply(s, on_one), std::invalid_argument);

  // Not off the playing surface, nor into a cushion.
  for (const Vec2 p : {Vec2{-0.2, 0.6}, Vec2{1.0, 0.5 * kR}, Vec2{3.0, 0.6}}) {
    const auto off = rules.check(s, PlaceCueBall{p});
    ASSERT_TRUE(off.has_value()) << p.x << ", " << p.y;
    EXPECT_NE(off->find("playing surface"), std::string::npos) << *off;
    EXPECT_THROW(rules.apply(s, PlaceCueBall{p}), std::invalid_argument);
  }
}

// ---------------------------------------------------------------------------
// Balls driven off the table (airborne physics; WPA 6.1, 6.5, 9-ball 2.6)

TEST(RulesNineOffTable, AnObjectBallOffTheTableIsAFoulAndIsNotSpotted) {
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.5, 0.5});
  put(s, 4, {1.9, 0.9});
  const Shoot shot = shot_at(s.position[0], s.position[1], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 1),
      ev(0.3, EventType::ball_ball, 1, 4),
      ev(0.49, EventType::ball_cushion, 4, -1, 2),  // on the nose, then over the rail
      ev(0.5, EventType::ball_off_table, 4, -1, 2),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_FALSE(on(o.state, 4));
  EXPECT_TRUE(o.ruling.spotted.empty());
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.fouls_in_a_row[0], 1);
}

TEST(RulesNineOffTable, TheNineOffTheTableIsSpotted) {
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 2, {1.5, 0.5});
  put(s, 9, {1.9, 0.9});
  const Shoot shot = shot_at(s.position[0], s.position[2], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 2),
      ev(0.3, EventType::ball_ball, 2, 9),
      ev(0.49, EventType::ball_cushion, 9, -1, 2),
      ev(0.5, EventType::ball_off_table, 9, -1, 2),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_EQ(o.ruling.spotted, std::vector<int>{9});
  EXPECT_TRUE(on(o.state, 9));
  EXPECT_EQ(o.state.position[9], rules.table().foot_spot);  // the foot spot is free
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.winner, -1);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.ruling.text,
            "Player 1 pockets nothing. The 9 leaves the table. Foul: a ball off the table. "
            "Player 2 has the cue ball in hand; the 9 is spotted.");
}

TEST(RulesNineOffTable, TheCueBallOffTheTableGivesBallInHand) {
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.5, 0.5});
  const int br = pocket_index(rules, "bottom_right");
  const Shoot shot = shot_at(s.position[0], s.position[1], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 1),
      ev(0.4, EventType::ball_pocket, 1, -1, -1, br),  // a pot, spoilt by the foul
      ev(0.5, EventType::ball_off_table, 0, -1, 3),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_FALSE(on(o.state, 0));
  EXPECT_FALSE(on(o.state, 1));
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_TRUE(rules.legal_actions(o.state).must_place);
}

TEST(RulesNineOffTable, ABallOffTheTableOnAPushOutIsAFoul) {
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  s.push_out_allowed = true;
  put(s, 1, {1.5, 0.5});
  put(s, 5, {1.0, 1.1});
  Shoot shot = shot_at(s.position[0], s.position[5], 6.0);
  shot.push_out = true;
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 5),
      ev(0.3, EventType::ball_off_table, 5, -1, 2),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.player, 1);
}

TEST(RulesNineOffTable, ALegalJumpShotIsNoFoul) {
  // The cue ball in flight over a blocker, then the lowest ball first and
  // a cushion: a legal shot.
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 5, {1.0, 0.5});
  put(s, 1, {1.5, 0.5});
  Shoot shot = shot_at(s.position[0], s.position[1], 4.0);
  shot.strike.theta = 45.0;
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),          slate(0.25, 0, MotionState::airborne),
      slate(0.3, 0, MotionState::sliding),        ev(0.35, EventType::ball_ball, 0, 1),
      ev(0.9, EventType::ball_cushion, 1, -1, 1),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(o.state.fouls_in_a_row[0], 0);
}

// The physics plays it: a hard elevated stroke lands the cue ball on the
// 9, which lies near the top rail; both bounce, and the 9 flies over the
// rail (found by scanning speed and elevation on the engine: at 6 m/s and
// 10 degrees the 9 leaves the table and the cue ball stays on it).
TEST(RulesNineOffTable, TheEngineDrivesTheNineOffTheTableAndItIsSpotted) {
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {1.0, 0.7});
  put(s, 9, {1.0, 1.15});
  Shoot shot = shot_at(s.position[0], s.position[9], 6.0);
  shot.strike.theta = 10.0;
  const Outcome o = rules.apply(s, shot);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 9);
  ASSERT_EQ(o.facts.off_table, std::vector<int>{9});
  bool flew = false;  // the cue ball left the cloth on its way
  for (const Event& e : o.events) flew = flew || (e.type == EventType::ball_slate && e.ball == 0);
  EXPECT_TRUE(flew);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_EQ(o.ruling.spotted, std::vector<int>{9});
  EXPECT_TRUE(on(o.state, 9));
  EXPECT_EQ(o.state.position[9], rules.spot_position(o.state, 9));
  EXPECT_TRUE(on(o.state, 0));
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  // On the cloth the same stroke keeps every ball on the table.
  const Outcome flat = nine_ball_rules().apply(s, shot);
  EXPECT_TRUE(flat.facts.off_table.empty());
  EXPECT_FALSE(has_foul(flat.ruling, Foul::ball_off_table));
}

TEST(RulesNineOffTable, FlyingOverARailIsNoCushionContact) {
  // The ball that leaves the table without touching a cushion does not
  // satisfy the rail requirement: both fouls are named.
  const Rules rules = airborne_rules(GameType::nine_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.5, 0.5});
  const Shoot shot = shot_at(s.position[0], s.position[1], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 1),
      ev(0.5, EventType::ball_off_table, 1, -1, 2),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, (std::vector<Foul>{Foul::ball_off_table, Foul::no_rail}));
  EXPECT_FALSE(on(o.state, 1));
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
}

}  // namespace test_rules_nine

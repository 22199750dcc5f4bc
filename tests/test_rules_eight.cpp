// 8-ball (WPA) rule by rule: each clause from a hand-placed table (or a
// seeded rack) and a shot that Rules::apply simulates.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "rules_fixtures.hpp"

namespace test_rules_eight {

using namespace breakshot;
using namespace rules_fixtures;

namespace {

constexpr double kBreakSpeed = 10.0;  // m/s, a firm break

// A full rack from `seed`, broken from the head spot straight at the apex.
Outcome break_rack(const Rules& rules, std::uint64_t seed, double speed, int breaker = 0) {
  const GameState s = rules.start(seed, breaker);
  return rules.apply(s, shot_at(s.position[0], rules.table().foot_spot, speed));
}

// Straight-in shots into the bottom-right corner along its diagonal.
Vec2 diagonal_br() { return {2.54 - 0.5, 0.5}; }

}  // namespace

// ---------------------------------------------------------------------------
// The break

TEST(RulesEightBreak, PocketingABallIsALegalBreakAndTheBreakerContinues) {
  const Rules rules = eight_ball_rules();
  const Outcome o = break_rack(rules, 1, kBreakSpeed);
  SCOPED_TRACE(describe(o));
  ASSERT_FALSE(o.facts.pocketed.empty());
  EXPECT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_FALSE(includes(o.facts.pocketed, 8));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.assigned, Group::none);
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(o.state.group[0], Group::none);  // the table stays open after the break
  EXPECT_EQ(o.state.group[1], Group::none);
  for (int b : o.facts.pocketed) EXPECT_FALSE(on(o.state, b)) << "ball " << b;
  EXPECT_EQ(o.state.shots, 1);
}

TEST(RulesEightBreak, FourBallsToACushionWithoutAPotIsLegalAndTheTurnPasses) {
  const Rules rules = eight_ball_rules();
  const Outcome o = break_rack(rules, 5, kBreakSpeed);
  SCOPED_TRACE(describe(o));
  ASSERT_TRUE(o.facts.pocketed.empty());
  ASSERT_GE(o.facts.object_balls_to_cushion, 4);
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(o.state.group[0], Group::none);
  EXPECT_EQ(o.state.group[1], Group::none);
}

TEST(RulesEightBreak, TooSoftABreakIsIllegalAndTheIncomingPlayerChooses) {
  const Rules rules = eight_ball_rules();
  const Outcome o = break_rack(rules, 1, 1.0);
  SCOPED_TRACE(describe(o));
  ASSERT_TRUE(o.facts.pocketed.empty());
  ASSERT_LT(o.facts.object_balls_to_cushion, 4);
  EXPECT_FALSE(o.ruling.legal_break);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::illegal_break});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::illegal_break_choice);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.breaker, 0);
  const LegalActions la = rules.legal_actions(o.state);
  EXPECT_FALSE(la.shoot);
  EXPECT_EQ(la.choices, (std::vector<Choice>{Choice::accept_table, Choice::rerack_and_break,
                                             Choice::rerack_opponent_breaks}));
}

TEST(RulesEightBreak, IllegalBreakAcceptTableShootsFromThePosition) {
  const Rules rules = eight_ball_rules();
  const GameState after = break_rack(rules, 1, 1.0).state;
  ASSERT_EQ(after.phase, Phase::illegal_break_choice);
  const Outcome o = rules.apply(after, Decide{Choice::accept_table});
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(o.state.position, after.position);
  EXPECT_EQ(o.state.on_table, after.on_table);
  EXPECT_EQ(o.state.racks, 1);
  EXPECT_TRUE(rules.legal_actions(o.state).shoot);
}

TEST(RulesEightBreak, IllegalBreakRerackAndBreakGivesTheIncomingPlayerAFreshRack) {
  const Rules rules = eight_ball_rules();
  const GameState after = break_rack(rules, 1, 1.0).state;
  ASSERT_EQ(after.phase, Phase::illegal_break_choice);
  const Outcome o = rules.apply(after, Decide{Choice::rerack_and_break});
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::break_shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.breaker, 1);
  EXPECT_EQ(o.state.racks, 2);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::kitchen);
  for (int b = 0; b < rules.ball_count(); ++b) EXPECT_TRUE(on(o.state, b)) << "ball " << b;
  EXPECT_EQ(o.state.position[0], rules.table().head_spot);
  // A fresh rack, not the broken balls put back.
  EXPECT_NE(o.state.rack_seed, after.rack_seed);
  const GameState fresh = rules.start(o.state.rack_seed, 1);
  EXPECT_EQ(o.state.position, fresh.position);
  EXPECT_NE(o.state.position, after.position);
}

TEST(RulesEightBreak, IllegalBreakRerackOpponentBreaksGivesTheBreakBack) {
  const Rules rules = eight_ball_rules();
  const GameState after = break_rack(rules, 1, 1.0).state;
  ASSERT_EQ(after.phase, Phase::illegal_break_choice);
  const Outcome o = rules.apply(after, Decide{Choice::rerack_opponent_breaks});
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::break_shot);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.breaker, 0);
  EXPECT_EQ(o.state.racks, 2);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::kitchen);
  for (int b = 0; b < rules.ball_count(); ++b) EXPECT_TRUE(on(o.state, b)) << "ball " << b;
  const GameState fresh = rules.start(o.state.rack_seed, 0);
  EXPECT_EQ(o.state.position, fresh.position);
}

TEST(RulesEightBreak, AnIllegalBreakWithAScratchLeavesTheCueBallInHandInTheKitchen) {
  // The breaker misses the rack and sends the cue ball into a corner.
  const Rules rules = eight_ball_rules();
  const GameState s = rules.start(1, 0);
  const int bl = pocket_index(rules, "bottom_left");
  const Outcome o = rules.apply(s, shot_at(s.position[0], pocket_centre(rules, bl), 2.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, -1);
  ASSERT_EQ(o.facts.pocketed, std::vector<int>{0});
  EXPECT_FALSE(o.ruling.legal_break);
  EXPECT_TRUE(has_foul(o.ruling, Foul::illegal_break));
  EXPECT_TRUE(has_foul(o.ruling, Foul::scratch));
  EXPECT_EQ(o.state.phase, Phase::illegal_break_choice);
  EXPECT_EQ(o.state.player, 1);
  // Accepting the table: the cue ball goes in hand behind the head string.
  const Outcome accept = rules.apply(o.state, Decide{Choice::accept_table});
  EXPECT_EQ(accept.state.phase, Phase::shot);
  EXPECT_EQ(accept.state.player, 1);
  EXPECT_EQ(accept.state.ball_in_hand, BallInHand::kitchen);
  const LegalActions la = rules.legal_actions(accept.state);
  EXPECT_TRUE(la.must_place);
  EXPECT_EQ(la.place, BallInHand::kitchen);
}

TEST(RulesEightBreak, ScratchOnALegalBreakGivesKitchenBallInHand) {
  const Rules rules = eight_ball_rules();
  const Outcome o = break_rack(rules, 25, kBreakSpeed);
  SCOPED_TRACE(describe(o));
  ASSERT_TRUE(includes(o.facts.pocketed, 0));
  ASSERT_FALSE(includes(o.facts.pocketed, 8));
  ASSERT_GE(o.facts.pocketed.size(), 2u);  // an object ball too
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::scratch});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::kitchen);
  EXPECT_FALSE(on(o.state, 0));
  EXPECT_EQ(o.state.group[0], Group::none);
  EXPECT_EQ(o.state.group[1], Group::none);
  for (int b : o.facts.pocketed) EXPECT_FALSE(on(o.state, b)) << "ball " << b;
  const LegalActions la = rules.legal_actions(o.state);
  EXPECT_TRUE(la.must_place);
  EXPECT_EQ(la.place, BallInHand::kitchen);
}

namespace {

// A hand-made "break": the 8 straight in to the top-right corner from the
// head spot, a few other balls out of the way.
GameState eight_break_layout(const Rules& rules) {
  GameState s = rules.start(3, 0);
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  const StraightIn si =
      straight_in(rules, pocket_index(rules, "top_right"), rules.table().head_spot, 0.5, 0.0);
  put(s, 0, rules.table().head_spot);
  put(s, 8, si.object);
  put(s, 1, {1.9, 0.25});
  put(s, 14, {2.2, 0.35});
  put(s, 5, {1.2, 0.2});
  s.phase = Phase::break_shot;
  s.ball_in_hand = BallInHand::kitchen;
  return s;
}

}  // namespace

TEST(RulesEightBreak, EightOnTheBreakIsNoLossAndTheBreakerChooses) {
  const Rules rules = eight_ball_rules();
  const GameState s = eight_break_layout(rules);
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[8], 6.0, -0.3));
  SCOPED_TRACE(describe(o));
  ASSERT_TRUE(includes(o.facts.pocketed, 8));
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_EQ(o.facts.first_hit, 8);
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::eight_on_break_choice);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.winner, -1);
  EXPECT_FALSE(on(o.state, 8));
  EXPECT_EQ(rules.legal_actions(o.state).choices,
            (std::vector<Choice>{Choice::respot_eight, Choice::rerack_and_break}));

  // Spot the 8 and play on.
  const Outcome spot = rules.apply(o.state, Decide{Choice::respot_eight});
  EXPECT_FALSE(spot.ruling.text.empty());
  EXPECT_EQ(spot.ruling.spotted, std::vector<int>{8});
  EXPECT_TRUE(on(spot.state, 8));
  // On the long string, on the foot spot when it is free (it is here).
  EXPECT_EQ(spot.state.position[8].y, rules.table().foot_spot.y);
  EXPECT_EQ(spot.state.position[8].x, rules.table().foot_spot.x);
  EXPECT_EQ(spot.state.phase, Phase::shot);
  EXPECT_EQ(spot.state.player, 0);
  EXPECT_EQ(spot.state.ball_in_hand, BallInHand::none);
  EXPECT_EQ(spot.state.group[0], Group::none);

  // Or re-rack and break again.
  const Outcome rerack = rules.apply(o.state, Decide{Choice::rerack_and_break});
  EXPECT_EQ(rerack.state.phase, Phase::break_shot);
  EXPECT_EQ(rerack.state.player, 0);
  EXPECT_EQ(rerack.state.breaker, 0);
  EXPECT_EQ(rerack.state.racks, s.racks + 1);
  for (int b = 0; b < rules.ball_count(); ++b) EXPECT_TRUE(on(rerack.state, b)) << "ball " << b;
}

TEST(RulesEightBreak, EightOnTheBreakSpotsOnTheLongStringWhenTheFootSpotIsTaken) {
  const Rules rules = eight_ball_rules();
  GameState s = eight_break_layout(rules);
  put(s, 2, rules.table().foot_spot);  // a ball on the foot spot
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[8], 6.0, -0.3));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.state.phase, Phase::eight_on_break_choice);
  ASSERT_TRUE(on(o.state, 2));
  const Outcome spot = rules.apply(o.state, Decide{Choice::respot_eight});
  const Vec2 p8 = spot.state.position[8];
  EXPECT_EQ(p8.y, rules.table().foot_spot.y);
  EXPECT_GT(p8.x, rules.table().foot_spot.x);  // behind the blocking ball, toward the foot rail
  for (int b = 0; b < rules.ball_count(); ++b) {
    if (b != 8 && on(spot.state, b)) {
      EXPECT_GE(norm(spot.state.position[b] - p8), 2.0 * kR) << "ball " << b;
    }
  }
}

TEST(RulesEightBreak, EightOnTheBreakWithAScratchTheOpponentChooses) {
  const Rules rules = eight_ball_rules();
  const GameState s = eight_break_layout(rules);
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[8], 6.0, 0.5));
  SCOPED_TRACE(describe(o));
  ASSERT_TRUE(includes(o.facts.pocketed, 8));
  ASSERT_TRUE(includes(o.facts.pocketed, 0));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::scratch});
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.phase, Phase::eight_on_break_choice);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.winner, -1);
  EXPECT_EQ(rules.legal_actions(o.state).choices,
            (std::vector<Choice>{Choice::respot_eight, Choice::rerack_and_break}));

  // Spot the 8: the opponent shoots with the cue ball in hand in the kitchen.
  const Outcome spot = rules.apply(o.state, Decide{Choice::respot_eight});
  EXPECT_EQ(spot.ruling.spotted, std::vector<int>{8});
  EXPECT_TRUE(on(spot.state, 8));
  EXPECT_EQ(spot.state.phase, Phase::shot);
  EXPECT_EQ(spot.state.player, 1);
  EXPECT_EQ(spot.state.ball_in_hand, BallInHand::kitchen);
  const LegalActions la = rules.legal_actions(spot.state);
  EXPECT_TRUE(la.must_place);
  EXPECT_EQ(la.place, BallInHand::kitchen);

  // Or re-rack: the opponent breaks.
  const Outcome rerack = rules.apply(o.state, Decide{Choice::rerack_and_break});
  EXPECT_EQ(rerack.state.phase, Phase::break_shot);
  EXPECT_EQ(rerack.state.player, 1);
  EXPECT_EQ(rerack.state.breaker, 1);
  EXPECT_EQ(rerack.state.racks, s.racks + 1);
}

// ---------------------------------------------------------------------------
// Open table

TEST(RulesEightOpenTable, SolidFirstThenTheCalledStripeAssignsStripes) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const Combination c = combination(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, c.cue);
  put(s, 10, c.target);
  put(s, 2, c.carrier);
  put(s, 6, {0.8, 0.9});
  put(s, 13, {1.0, 1.0});
  const Outcome o = rules.apply(s, with_call(shot_at(c.cue, c.carrier, 3.0), 10, br));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 2);
  ASSERT_EQ(pocket_of(o.facts, 10), br);
  EXPECT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.assigned, Group::stripes);
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.group[0], Group::stripes);
  EXPECT_EQ(o.state.group[1], Group::solids);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.phase, Phase::shot);
}

TEST(RulesEightOpenTable, HittingTheEightFirstIsAFoul) {
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 8, {1.27, 0.635});
  put(s, 3, {1.8, 1.0});
  put(s, 11, {0.6, 1.0});
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[8], 1.5));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 8);
  ASSERT_FALSE(includes(o.facts.pocketed, 8));
  EXPECT_TRUE(has_foul(o.ruling, Foul::wrong_ball_first));
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.group[0], Group::none);
  EXPECT_EQ(o.state.winner, -1);
}

TEST(RulesEightOpenTable, ADeclaredSafetyThatPocketsABallEndsTheTurn) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, si.cue);
  put(s, 4, si.object);
  put(s, 12, {1.0, 1.0});
  Shoot sh = shot_at(si.cue, si.object, 2.0);
  sh.safety = true;
  const Outcome o = rules.apply(s, sh);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 4), br);
  EXPECT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.assigned, Group::none);
  EXPECT_EQ(o.state.group[0], Group::none);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_FALSE(on(o.state, 4));  // it stays down
}

TEST(RulesEightOpenTable, AScratchAfterALegalPotIsAFoulAndThePotStaysDown) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, si.cue);
  put(s, 3, si.object);
  put(s, 12, {1.0, 1.0});
  const Outcome o = rules.apply(s, with_call(shot_at(si.cue, si.object, 2.0, 0.5), 3, br));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 3), br);
  ASSERT_TRUE(includes(o.facts.pocketed, 0));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::scratch});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.assigned, Group::none);  // no group on a foul
  EXPECT_EQ(o.state.group[0], Group::none);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_FALSE(on(o.state, 3));
  EXPECT_FALSE(on(o.state, 0));
  EXPECT_TRUE(rules.legal_actions(o.state).must_place);
}

// ---------------------------------------------------------------------------
// Groups assigned

namespace {

// Player 0 on the solids, player 1 on the stripes.
GameState with_groups(GameState s) {
  s.group = {Group::solids, Group::stripes};
  return s;
}

}  // namespace

TEST(RulesEightGroups, HittingAnOpponentsBallFirstIsAFoulWithBallInHandAnywhere) {
  const Rules rules = eight_ball_rules();
  GameState s = with_groups(bare_table(rules, {0.8, 0.5}));
  put(s, 12, {1.27, 0.635});
  put(s, 3, {1.8, 1.0});
  put(s, 8, {0.6, 1.0});
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[12], 1.5));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 12);
  EXPECT_TRUE(has_foul(o.ruling, Foul::wrong_ball_first));
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.group[0], Group::solids);
  EXPECT_EQ(o.state.group[1], Group::stripes);
  EXPECT_EQ(rules.legal_actions(o.state).place, BallInHand::anywhere);
}

TEST(RulesEightGroups, TheCalledBallInTheCalledPocketContinuesTheTurn) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, si.cue));
  put(s, 3, si.object);
  put(s, 5, {0.8, 0.9});
  put(s, 12, {1.0, 1.0});
  put(s, 8, {1.5, 1.0});
  const Outcome o = rules.apply(s, with_call(shot_at(si.cue, si.object, 2.0), 3, br));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 3), br);
  EXPECT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.assigned, Group::none);  // already assigned
  EXPECT_TRUE(o.ruling.call_made);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_FALSE(on(o.state, 3));
}

TEST(RulesEightGroups, TheCalledBallInAnotherPocketEndsTheTurnWithoutAFoul) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const int tl = pocket_index(rules, "top_left");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, si.cue));
  put(s, 3, si.object);
  put(s, 5, {0.8, 0.9});
  put(s, 12, {1.0, 1.0});
  put(s, 8, {1.5, 1.0});
  const Outcome o = rules.apply(s, with_call(shot_at(si.cue, si.object, 2.0), 3, tl));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 3), br);
  EXPECT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
  EXPECT_FALSE(on(o.state, 3));  // it stays down
}

TEST(RulesEightGroups, AnUncalledObviousShotCounts) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = bare_table(rules, si.cue);  // open table: the pot also picks the group
  put(s, 3, si.object);
  put(s, 5, {0.8, 0.9});
  put(s, 12, {1.0, 1.0});
  const Outcome o = rules.apply(s, shot_at(si.cue, si.object, 2.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 3);
  ASSERT_EQ(pocket_of(o.facts, 3), br);
  EXPECT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.assigned, Group::solids);
  EXPECT_EQ(o.state.group[0], Group::solids);
  EXPECT_EQ(o.state.group[1], Group::stripes);
  EXPECT_EQ(o.state.player, 0);
}

TEST(RulesEightGroups, NoRailAfterContactIsAFoul) {
  const Rules rules = eight_ball_rules();
  GameState s = with_groups(bare_table(rules, {1.27 - 0.15, 0.635}));
  put(s, 2, {1.27, 0.635});
  put(s, 12, {1.8, 1.0});
  put(s, 8, {0.6, 1.0});
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[2], 0.3));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 2);
  ASSERT_TRUE(o.facts.pocketed.empty());
  ASSERT_FALSE(o.facts.cushion_after_contact);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_rail});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
}

TEST(RulesEightGroups, ContactThenACushionIsNoFoul) {
  // The counterpart of the no-rail foul: the same tap harder sends the
  // object ball to a cushion, and the turn simply passes.
  const Rules rules = eight_ball_rules();
  GameState s = with_groups(bare_table(rules, {1.27 - 0.15, 0.635}));
  put(s, 2, {1.27, 0.635});
  put(s, 12, {1.8, 1.0});
  put(s, 8, {0.6, 1.0});
  const Outcome o = rules.apply(s, shot_at(s.position[0], s.position[2] + Vec2{0.0, 0.02}, 1.5));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 2);
  ASSERT_TRUE(o.facts.pocketed.empty());
  ASSERT_TRUE(o.facts.cushion_after_contact);
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
}

// ---------------------------------------------------------------------------
// The 8

TEST(RulesEightEight, CalledAndPocketedAfterClearingTheGroupWins) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, si.cue));
  put(s, 8, si.object);
  put(s, 12, {1.0, 1.0});
  put(s, 9, {0.6, 0.3});
  ASSERT_EQ(rules.legal_actions(s).targets, std::vector<int>{8});
  const Outcome o = rules.apply(s, with_call(shot_at(si.cue, si.object, 2.0), 8, br));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 8), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, 0);
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 0);
  EXPECT_FALSE(o.state.result.empty());
}

TEST(RulesEightEight, PocketedInAnUncalledPocketLoses) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const int tl = pocket_index(rules, "top_left");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, si.cue));
  put(s, 8, si.object);
  put(s, 12, {1.0, 1.0});
  const Outcome o = rules.apply(s, with_call(shot_at(si.cue, si.object, 2.0), 8, tl));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 8), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
  EXPECT_FALSE(o.state.result.empty());
}

TEST(RulesEightEight, PocketedBeforeTheGroupIsClearedLoses) {
  // A legal hit on the 1 that drives the 8 in (a combination).
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const Combination c = combination(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, c.cue));
  put(s, 8, c.target);
  put(s, 1, c.carrier);
  put(s, 6, {0.8, 0.9});
  put(s, 12, {1.0, 1.0});
  const Outcome o = rules.apply(s, shot_at(c.cue, c.carrier, 3.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_TRUE(includes(o.facts.pocketed, 8));
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
}

TEST(RulesEightEight, PocketedOnTheSameShotAsTheLastGroupBallLoses) {
  // The 1, the last solid, drives the 8 in and follows it.
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const Vec2 pc = pocket_centre(rules, br);
  const Vec2 u = unit(Vec2{2.54 - 0.8, 0.8} - pc);
  const Vec2 p8 = pc + u * 0.15;
  const Vec2 p1 = pc + u * (0.15 + 2.0 * kR + 0.5);
  const Vec2 cue = p1 + u * 0.25;
  GameState s = with_groups(bare_table(rules, cue));
  put(s, 8, p8);
  put(s, 1, p1);
  put(s, 12, {1.0, 1.0});
  ASSERT_EQ(rules.legal_actions(s).targets, std::vector<int>{1});
  const Outcome o = rules.apply(s, with_call(shot_at(cue, p1, 2.0, -0.3), 1, br));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 1);
  ASSERT_EQ(pocket_of(o.facts, 8), br);
  ASSERT_EQ(pocket_of(o.facts, 1), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
}

TEST(RulesEightEight, PocketedWithAScratchLoses) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, si.cue));
  put(s, 8, si.object);
  put(s, 12, {1.0, 1.0});
  const Outcome o = rules.apply(s, with_call(shot_at(si.cue, si.object, 2.0, 0.5), 8, br));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 8), br);
  ASSERT_TRUE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(has_foul(o.ruling, Foul::scratch));
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
}

TEST(RulesEightEight, PocketedWithoutACallLoses) {
  const Rules rules = eight_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, diagonal_br(), 0.25, 0.2);
  GameState s = with_groups(bare_table(rules, si.cue));
  put(s, 8, si.object);
  put(s, 12, {1.0, 1.0});
  const Outcome o = rules.apply(s, shot_at(si.cue, si.object, 2.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(pocket_of(o.facts, 8), br);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
}

// ---------------------------------------------------------------------------
// Cue ball in hand behind the head string

TEST(RulesEightKitchen, PlacingBeyondTheHeadStringIsRejected) {
  const Rules rules = eight_ball_rules();
  const GameState s = break_rack(rules, 25, kBreakSpeed).state;  // scratch on the break
  ASSERT_EQ(s.ball_in_hand, BallInHand::kitchen);
  ASSERT_EQ(s.player, 1);
  const PlaceCueBall beyond{{rules.head_string() + 0.2, 0.635}};
  const auto why = rules.check(s, beyond);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("head string"), std::string::npos) << *why;
  EXPECT_EQ(rules.check_placement(s, beyond.position), why);
  EXPECT_THROW(rules.apply(s, beyond), std::invalid_argument);

  const PlaceCueBall behind{{rules.head_string() - 0.2, 0.4}};
  ASSERT_EQ(rules.check(s, behind), std::nullopt);
  const Outcome o = rules.apply(s, behind);
  EXPECT_TRUE(on(o.state, 0));
  EXPECT_EQ(o.state.position[0], behind.position);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_TRUE(o.state.kitchen_shot);
  EXPECT_TRUE(rules.legal_actions(o.state).shoot);
}

namespace {

// Player 1 has the cue ball in hand behind the head string (as after a
// scratch on the break); the 3 lies in the kitchen, the 5 and 12 beyond.
GameState kitchen_layout(const Rules& rules) {
  GameState s = bare_table(rules, {0.3, 0.635}, 1);
  s.on_table[0] = 0;
  s.ball_in_hand = BallInHand::kitchen;
  put(s, 3, {0.35, 0.3});
  put(s, 5, {1.5, 0.9});
  put(s, 12, {1.8, 0.4});
  return s;
}

}  // namespace

TEST(RulesEightKitchen, FirstHittingABallBehindTheHeadStringIsAFoul) {
  const Rules rules = eight_ball_rules();
  const GameState s = kitchen_layout(rules);
  ASSERT_LE(s.position[3].x, rules.head_string());
  const Outcome placed = rules.apply(s, PlaceCueBall{{0.5, 0.635}});
  ASSERT_TRUE(placed.state.kitchen_shot);
  const Outcome o = rules.apply(placed.state, shot_at({0.5, 0.635}, s.position[3], 1.5));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 3);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  EXPECT_TRUE(has_foul(o.ruling, Foul::behind_head_string));
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_FALSE(o.state.kitchen_shot);
}

TEST(RulesEightKitchen, FirstHittingABallBeyondTheHeadStringIsNoFoul) {
  const Rules rules = eight_ball_rules();
  const GameState s = kitchen_layout(rules);
  const Outcome placed = rules.apply(s, PlaceCueBall{{0.5, 0.635}});
  const Outcome o = rules.apply(placed.state, shot_at({0.5, 0.635}, s.position[5], 2.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 5);
  ASSERT_FALSE(includes(o.facts.pocketed, 0));
  ASSERT_TRUE(o.facts.cushion_after_contact);
  EXPECT_TRUE(o.ruling.fouls.empty());
}

TEST(RulesEightKitchen, ABallBehindTheHeadStringIsFairOnceTheCueBallCrossedIt) {
  // WPA: from the kitchen, a ball behind the head string may be hit first
  // once the cue ball has crossed the head string. Here the cue ball goes
  // up to the foot cushion and comes back to the 3: no foul.
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.5, 0.3}, 1);
  s.on_table[0] = 0;
  s.ball_in_hand = BallInHand::kitchen;
  put(s, 3, {0.35, 0.9});
  put(s, 11, {2.0, 1.15});
  put(s, 6, {1.3, 1.1});
  const GameState placed = rules.apply(s, PlaceCueBall{{0.5, 0.3}}).state;
  ASSERT_TRUE(placed.kitchen_shot);
  Shoot bank;
  bank.strike.speed = 4.0;
  bank.strike.phi = 7.0;
  const Outcome o = rules.apply(placed, bank);
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, 3);
  ASSERT_LE(s.position[3].x, rules.head_string());
  ASSERT_TRUE(o.facts.pocketed.empty());
  ASSERT_TRUE(o.facts.cushion_after_contact);
  // Before touching the 3, the cue ball met a cushion beyond the head string.
  bool crossed = false;
  for (const Event& e : o.events) {
    if (e.type == EventType::ball_ball) break;
    if (e.type == EventType::ball_cushion && e.ball == 0) {
      const Wall& w = rules.table().walls[static_cast<std::size_t>(e.wall)];
      if (w.a.x > rules.head_string() && w.b.x > rules.head_string()) crossed = true;
    }
  }
  ASSERT_TRUE(crossed);
  EXPECT_TRUE(o.ruling.fouls.empty()) << describe(o);
  EXPECT_EQ(o.state.player, 0);  // nothing pocketed: the turn passes
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::none);
}

// ---------------------------------------------------------------------------
// Balls driven off the table (airborne physics; WPA 6.1, 6.5, 8-ball 3.3,
// 3.6, 3.8). The shots are hand-made event lists (Rules::apply_events),
// but for the last test, which the physics plays.

TEST(RulesEightOffTable, AnObjectBallOffTheTableIsAFoulAndStaysOff) {
  const Rules rules = airborne_rules(GameType::eight_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 3, {1.5, 0.5});
  put(s, 12, {1.9, 0.9});
  const Shoot shot = shot_at(s.position[0], s.position[3], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 3),
      ev(0.34, EventType::ball_cushion, 3, -1, 1),  // on the nose, then over the rail
      ev(0.35, EventType::ball_off_table, 3, -1, 1),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.facts.off_table, std::vector<int>{3});
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_FALSE(on(o.state, 3));  // no object ball but the 8 is ever spotted
  EXPECT_TRUE(o.ruling.spotted.empty());
  EXPECT_TRUE(on(o.state, 0));
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.ruling.text,
            "Player 1 pockets nothing. The 3 leaves the table. Foul: a ball off the table. "
            "Player 2 has the cue ball in hand.");
}

TEST(RulesEightOffTable, ABallOffTheTableSpoilsALegalPot) {
  // The called ball falls in the called pocket, but another ball leaves
  // the table: a foul, the pot stays down, no group is assigned.
  const Rules rules = airborne_rules(GameType::eight_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 3, {1.5, 0.5});
  put(s, 12, {1.9, 0.9});
  const int br = pocket_index(rules, "bottom_right");
  const Shoot shot = with_call(shot_at(s.position[0], s.position[3], 6.0), 3, br);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 3),
      ev(0.2, EventType::ball_ball, 0, 12),
      ev(0.4, EventType::ball_off_table, 12),
      ev(0.6, EventType::ball_pocket, 3, -1, -1, br),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_FALSE(o.ruling.call_made);
  EXPECT_EQ(o.ruling.assigned, Group::none);
  EXPECT_EQ(o.state.group[0], Group::none);
  EXPECT_FALSE(on(o.state, 3));
  EXPECT_FALSE(on(o.state, 12));
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
}

TEST(RulesEightOffTable, TheCueBallOffTheTableGivesBallInHand) {
  const Rules rules = airborne_rules(GameType::eight_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 3, {1.5, 0.5});
  const Shoot shot = shot_at(s.position[0], s.position[3], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 3),
      ev(0.3, EventType::ball_cushion, 3, -1, 3),
      ev(0.35, EventType::ball_off_table, 0, -1, 0),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_FALSE(on(o.state, 0));
  EXPECT_TRUE(on(o.state, 3));
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  const LegalActions la = rules.legal_actions(o.state);
  EXPECT_TRUE(la.must_place);
  EXPECT_FALSE(la.shoot);
  EXPECT_EQ(la.place, BallInHand::anywhere);
  EXPECT_NE(o.ruling.text.find("The cue ball leaves the table."), std::string::npos)
      << o.ruling.text;
}

TEST(RulesEightOffTable, TheEightOffTheTableLosesTheRack) {
  const Rules rules = airborne_rules(GameType::eight_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  s.group = {Group::solids, Group::stripes};
  put(s, 3, {1.5, 0.5});
  put(s, 8, {1.6, 0.62});
  const Shoot shot = shot_at(s.position[0], s.position[3], 6.0);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.15, EventType::ball_ball, 0, 3),  // a legal first contact
      ev(0.2, EventType::ball_ball, 3, 8),
      ev(0.39, EventType::ball_cushion, 8, -1, 1),
      ev(0.4, EventType::ball_off_table, 8, -1, 1),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_EQ(o.state.result, "Player 1 drove the 8 off the table");
  EXPECT_FALSE(on(o.state, 8));
}

TEST(RulesEightOffTable, TheEightOffTheTableOnTheBreakIsSpottedOrReracked) {
  // WPA 3.6: the 8 driven off the table on the break is spotted or the
  // balls are re-racked; leaving the table is a foul (6.5), so the
  // incoming player chooses and shoots from the kitchen.
  const Rules rules = airborne_rules(GameType::eight_ball);
  const GameState s = rules.start(1, 0);
  const Shoot shot = shot_at(s.position[0], rules.table().foot_spot, kBreakSpeed);
  std::vector<Event> events = {ev(0.0, EventType::cue_strike, 0),
                               ev(0.2, EventType::ball_ball, 0, 1)};
  for (int b : {2, 3, 9, 10}) events.push_back(ev(0.4, EventType::ball_cushion, b, -1, 1));
  events.push_back(ev(0.5, EventType::ball_off_table, 8, -1, 3));
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_EQ(o.state.phase, Phase::eight_on_break_choice);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_TRUE(o.state.scratch_on_break);
  EXPECT_FALSE(on(o.state, 8));
  EXPECT_FALSE(on(o.state, 0));  // the incoming player has it in hand
  const Outcome d = rules.apply(o.state, Decide{Choice::respot_eight});
  EXPECT_TRUE(on(d.state, 8));
  EXPECT_EQ(d.ruling.spotted, std::vector<int>{8});
  EXPECT_EQ(d.state.position[8], rules.spot_position(o.state, 8));
  EXPECT_EQ(d.state.ball_in_hand, BallInHand::kitchen);
  EXPECT_TRUE(rules.legal_actions(d.state).must_place);
}

TEST(RulesEightOffTable, AnObjectBallOffTheTableOnALegalBreakGivesKitchenBallInHand) {
  const Rules rules = airborne_rules(GameType::eight_ball);
  const GameState s = rules.start(1, 0);
  const Shoot shot = shot_at(s.position[0], rules.table().foot_spot, kBreakSpeed);
  const int tl = pocket_index(rules, "top_left");
  const std::vector<Event> events = {ev(0.0, EventType::cue_strike, 0),
                                     ev(0.2, EventType::ball_ball, 0, 1),
                                     ev(0.5, EventType::ball_pocket, 2, -1, -1, tl),
                                     ev(0.6, EventType::ball_off_table, 11, -1, 1)};
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_TRUE(o.ruling.legal_break);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::kitchen);
  EXPECT_TRUE(rules.legal_actions(o.state).must_place);
  EXPECT_FALSE(on(o.state, 2));
  EXPECT_FALSE(on(o.state, 11));
  EXPECT_TRUE(o.ruling.spotted.empty());
  EXPECT_EQ(o.ruling.text.find("Player 1 pockets 2. The 11 leaves the table. Foul on the break: "
                               "a ball off the table."),
            0u)
      << o.ruling.text;
}

TEST(RulesEightOffTable, ALegalJumpShotOverABlockerIsNoFoul) {
  // The cue ball leaves the cloth over a blocking ball and meets its own
  // group's ball first: a legal shot (WPA definitions: jump shot).
  const Rules rules = airborne_rules(GameType::eight_ball);
  GameState s = bare_table(rules, {0.8, 0.5});
  s.group = {Group::solids, Group::stripes};
  put(s, 12, {1.0, 0.5});  // the blocker, a stripe
  put(s, 3, {1.5, 0.5});
  const int br = pocket_index(rules, "bottom_right");
  Shoot shot = with_call(shot_at(s.position[0], s.position[3], 4.0), 3, br);
  shot.strike.theta = 45.0;
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      slate(0.25, 0, MotionState::airborne),
      ev(0.3, EventType::ball_ball, 0, 3),
      ev(0.8, EventType::ball_pocket, 3, -1, -1, br),
  };
  const Outcome o = rules.apply_events(s, shot, events, s.position);
  SCOPED_TRACE(describe(o));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.call_made);
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 0);
}

}  // namespace test_rules_eight

// Clauses both games share: no contact, what may be done when, strike
// validation, determinism, the facts read from events, the stalemate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/match.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/session.hpp"
#include "rules_fixtures.hpp"

namespace test_rules_common {

using namespace breakshot;
using namespace rules_fixtures;

namespace {

constexpr double kBreakSpeed = 10.0;  // m/s

Outcome break_rack(const Rules& rules, std::uint64_t seed, double speed) {
  const GameState s = rules.start(seed, 0);
  return rules.apply(s, shot_at(s.position[0], rules.table().foot_spot, speed));
}

// The reason check() gives, and apply() throwing std::invalid_argument
// with that same reason.
std::string rejected(const Rules& rules, const GameState& s, const Action& a) {
  const auto why = rules.check(s, a);
  if (!why) {
    ADD_FAILURE() << "the action was accepted";
    return {};
  }
  EXPECT_FALSE(why->empty());
  try {
    (void)rules.apply(s, a);
    ADD_FAILURE() << "apply did not throw (" << *why << ")";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), *why);
  }
  return *why;
}

Shoot strike(double speed, double phi, double theta = 0.0, double a = 0.0, double b = 0.0) {
  Shoot sh;
  sh.strike.speed = speed;
  sh.strike.phi = phi;
  sh.strike.theta = theta;
  sh.strike.a = a;
  sh.strike.b = b;
  return sh;
}

}  // namespace

// ---------------------------------------------------------------------------
// No contact

TEST(RulesCommonFouls, NoContactIsAFoulInEightBall) {
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  s.group = {Group::solids, Group::stripes};
  put(s, 3, {1.9, 0.9});
  put(s, 12, {2.2, 0.3});
  // Away from every ball, into the bottom cushion.
  const Outcome o = rules.apply(s, shot_at(s.position[0], {0.8, 0.0}, 1.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, -1);
  ASSERT_TRUE(o.facts.pocketed.empty());
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_contact});
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_FALSE(o.ruling.text.empty());
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
}

TEST(RulesCommonFouls, NoContactIsAFoulInNineBall) {
  const Rules rules = nine_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.9, 0.9});
  put(s, 9, {2.2, 0.3});
  const Outcome o = rules.apply(s, shot_at(s.position[0], {0.8, 0.0}, 1.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.facts.first_hit, -1);
  ASSERT_TRUE(o.facts.pocketed.empty());
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_contact});
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.fouls_in_a_row[0], 1);
}

TEST(RulesCommonFouls, AMiscueIsANoContactFoul) {
  // A tip offset beyond the miscue limit (half the radius) is not played.
  const Rules rules = nine_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.3, 0.5});
  put(s, 9, {2.2, 0.3});
  Shoot sh = shot_at(s.position[0], s.position[1], 2.0);
  sh.strike.a = 0.8;
  ASSERT_EQ(rules.check(s, sh), std::nullopt);
  const Outcome o = rules.apply(s, sh);
  SCOPED_TRACE(describe(o));
  ASSERT_TRUE(o.facts.miscue);
  EXPECT_EQ(o.facts.first_hit, -1);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::no_contact});
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::anywhere);
  EXPECT_EQ(o.state.position[1], s.position[1]);
}

// ---------------------------------------------------------------------------
// What may be done when

TEST(RulesCommonPhase, NoShotWhileADecisionIsDue) {
  const Rules eight = eight_ball_rules();
  const GameState choice = break_rack(eight, 1, 1.0).state;  // an illegal break
  ASSERT_EQ(choice.phase, Phase::illegal_break_choice);
  const std::string why =
      rejected(eight, choice, shot_at(choice.position[0], choice.position[1], 2.0));
  EXPECT_NE(why.find("decision"), std::string::npos) << why;
  // Nor a placement.
  rejected(eight, choice, PlaceCueBall{{0.3, 0.3}});
  // Nor a decision that is not on offer.
  rejected(eight, choice, Decide{Choice::shoot});
  rejected(eight, choice, Decide{Choice::respot_eight});

  // 9-ball after a push-out.
  const Rules nine = nine_ball_rules();
  GameState s = bare_table(nine, {0.8, 0.5}, 1);
  s.push_out_allowed = true;
  put(s, 1, {1.9, 0.9});
  put(s, 9, {1.5, 1.0});
  Shoot push = shot_at(s.position[0], {0.8, 0.0}, 0.4);
  push.push_out = true;
  const GameState pushed = nine.apply(s, push).state;
  ASSERT_EQ(pushed.phase, Phase::push_out_choice);
  rejected(nine, pushed, shot_at(pushed.position[0], pushed.position[1], 2.0));
  rejected(nine, pushed, Decide{Choice::accept_table});
}

TEST(RulesCommonPhase, NoDecisionDuringAShotPhase) {
  const Rules rules = eight_ball_rules();
  const GameState s = break_rack(rules, 1, kBreakSpeed).state;  // legal, breaker continues
  ASSERT_EQ(s.phase, Phase::shot);
  for (const Choice c : {Choice::shoot, Choice::pass_back, Choice::accept_table,
                         Choice::rerack_and_break, Choice::rerack_opponent_breaks,
                         Choice::respot_eight}) {
    const std::string why = rejected(rules, s, Decide{c});
    EXPECT_NE(why.find("no decision"), std::string::npos) << why;
  }
  // Nor on the break itself.
  rejected(rules, rules.start(1, 0), Decide{Choice::accept_table});
}

TEST(RulesCommonPhase, NoShotWhileTheCueBallMustBePlaced) {
  const Rules rules = eight_ball_rules();
  const Outcome scratched = break_rack(rules, 25, kBreakSpeed);
  ASSERT_TRUE(includes(scratched.facts.pocketed, 0));
  const GameState& s = scratched.state;
  ASSERT_TRUE(rules.legal_actions(s).must_place);
  EXPECT_FALSE(rules.legal_actions(s).shoot);
  const std::string why = rejected(rules, s, strike(2.0, 0.0));
  EXPECT_NE(why.find("place"), std::string::npos) << why;
}

TEST(RulesCommonPhase, NothingAfterGameOver) {
  const Rules rules = nine_ball_rules();
  const int br = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, br, {2.54 - 0.5, 0.5}, 0.25, 0.2);
  GameState s = bare_table(rules, si.cue);
  put(s, 9, si.object);  // the last ball: the 9 is the lowest
  const Outcome o = rules.apply(s, shot_at(si.cue, si.object, 2.0));
  SCOPED_TRACE(describe(o));
  ASSERT_EQ(o.state.phase, Phase::game_over);
  ASSERT_EQ(o.state.winner, 0);
  const GameState& over = o.state;
  const LegalActions la = rules.legal_actions(over);
  EXPECT_FALSE(la.shoot);
  EXPECT_TRUE(la.choices.empty());
  EXPECT_EQ(la.place, BallInHand::none);
  for (const Action& a : std::vector<Action>{strike(2.0, 0.0), PlaceCueBall{{1.0, 0.6}},
                                             Decide{Choice::shoot}}) {
    const std::string why = rejected(rules, over, a);
    EXPECT_NE(why.find("game is over"), std::string::npos) << why;
  }
}

TEST(RulesCommonPhase, CallsSafetiesAndPushOutsBelongToTheirGame) {
  const Rules nine = nine_ball_rules();
  GameState n = bare_table(nine, {0.8, 0.5});
  n.push_out_allowed = true;
  put(n, 1, {1.9, 0.9});
  // 9-ball calls are informational: allowed, ignored by the ruling, but
  // they must name a ball on the table and a pocket that exists, and a
  // push-out carries none.
  Shoot called = shot_at(n.position[0], n.position[1], 2.0);
  called.call = Call{1, 0};
  EXPECT_FALSE(nine.check(n, called).has_value());
  called.call = Call{1, 6};
  rejected(nine, n, called);
  called.call = Call{4, 0};  // the 4 is not on this table
  rejected(nine, n, called);
  called.call = Call{1, 0};
  called.push_out = true;
  rejected(nine, n, called);
  Shoot safe = shot_at(n.position[0], n.position[1], 2.0);
  safe.safety = true;
  rejected(nine, n, safe);

  const Rules eight = eight_ball_rules();
  GameState e = bare_table(eight, {0.8, 0.5});
  put(e, 3, {1.9, 0.9});
  Shoot push = shot_at(e.position[0], e.position[3], 2.0);
  push.push_out = true;
  rejected(eight, e, push);
  // A call must name a pocket that exists and a ball that may be hit.
  rejected(eight, e, with_call(shot_at(e.position[0], e.position[3], 2.0), 3, 6));
  rejected(eight, e, with_call(shot_at(e.position[0], e.position[3], 2.0), 8, 0));
  // The break is not called.
  const GameState b = eight.start(1, 0);
  rejected(eight, b, with_call(shot_at(b.position[0], eight.table().foot_spot, 10.0), 1, 0));
}

// ---------------------------------------------------------------------------
// Strikes

TEST(RulesCommonStrike, BadStrikesAreRejectedWithAReason) {
  const Rules rules = eight_ball_rules();
  const GameState s = rules.start(1, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(rejected(rules, s, strike(nan, 0.0)).find("speed"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(0.0, 0.0)).find("speed"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(-1.0, 0.0)).find("speed"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(inf, 0.0)).find("speed"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, nan)).find("phi"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, 0.0, 90.0)).find("theta"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, 0.0, -5.0)).find("theta"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, 0.0, nan)).find("theta"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, 0.0, 0.0, 1.5)).find("offset"), std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, 0.0, 0.0, 0.0, -1.01)).find("offset"),
            std::string::npos);
  EXPECT_NE(rejected(rules, s, strike(2.0, 0.0, 0.0, nan)).find("offset"), std::string::npos);
  // The limits themselves are fine.
  EXPECT_EQ(rules.check(s, strike(2.0, 0.0, 89.0, 1.0, -1.0)), std::nullopt);
}

TEST(RulesCommonStrike, ApplyThrowsForARejectedAction) {
  const Rules rules = nine_ball_rules();
  const GameState s = rules.start(1, 0);
  EXPECT_THROW(rules.apply(s, strike(0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(rules.apply(s, Decide{Choice::pass_back}), std::invalid_argument);
  EXPECT_THROW(rules.apply(s, PlaceCueBall{{2.0, 0.6}}), std::invalid_argument);  // kitchen
}

// ---------------------------------------------------------------------------
// Determinism

TEST(RulesCommonDeterminism, TheSameStateAndActionGiveTheSameOutcome) {
  for (const GameType g : {GameType::eight_ball, GameType::nine_ball}) {
    GameConfig c;
    c.game = g;
    const Rules rules(c);
    const GameState s = rules.start(11, 1);
    const Shoot sh = shot_at(s.position[0], rules.table().foot_spot + Vec2{0.0, 0.004},
                             kBreakSpeed, 0.2);
    const Outcome a = rules.apply(s, sh);
    const Outcome b = rules.apply(s, sh);
    ASSERT_FALSE(a.events.empty());
    EXPECT_TRUE(a.state == b.state);  // positions compare == (bit for bit)
    EXPECT_EQ(a.state.position, b.state.position);
    EXPECT_TRUE(a.events == b.events);
    EXPECT_TRUE(a.facts == b.facts);
    EXPECT_TRUE(a.ruling == b.ruling);
    // A second Rules object built from the same configuration agrees.
    const Rules again(c);
    const Outcome d = again.apply(s, sh);
    EXPECT_TRUE(a.state == d.state);
    EXPECT_TRUE(a.events == d.events);
  }
}

// ---------------------------------------------------------------------------
// Facts from hand-made event lists

TEST(RulesCommonFacts, EmptyEventsGiveNoFacts) {
  const Rules rules = eight_ball_rules();
  const ShotFacts f = rules.facts({});
  EXPECT_EQ(f.first_hit, -1);
  EXPECT_TRUE(f.pocketed.empty());
  EXPECT_TRUE(f.pocket_of.empty());
  EXPECT_FALSE(f.cushion_after_contact);
  EXPECT_EQ(f.object_balls_to_cushion, 0);
  EXPECT_FALSE(f.miscue);
}

TEST(RulesCommonFacts, FirstHitCushionsAndPockets) {
  const Rules rules = eight_ball_rules();
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.1, EventType::ball_cushion, 0, -1, 2),  // the cue ball, before any contact
      ev(0.2, EventType::ball_ball, 0, 3),         // first contact: the 3
      ev(0.3, EventType::ball_ball, 0, 7),
      ev(0.5, EventType::ball_cushion, 3, -1, 1),
      ev(0.6, EventType::ball_cushion, 3, -1, 0),  // the 3 again: counted once
      ev(0.7, EventType::ball_ball, 3, 5),
      ev(0.8, EventType::ball_cushion, 5, -1, 3),
      ev(0.9, EventType::ball_pocket, 5, -1, -1, 2),
      ev(1.0, EventType::ball_pocket, 0, -1, -1, 4),
  };
  const ShotFacts f = rules.facts(events);
  EXPECT_EQ(f.first_hit, 3);
  EXPECT_TRUE(f.cushion_after_contact);
  EXPECT_EQ(f.object_balls_to_cushion, 2);  // the 3 and the 5; the cue ball does not count
  EXPECT_EQ(f.pocketed, (std::vector<int>{5, 0}));
  EXPECT_EQ(f.pocket_of, (std::vector<int>{2, 4}));
}

TEST(RulesCommonFacts, ACushionBeforeContactIsNotACushionAfterContact) {
  const Rules rules = nine_ball_rules();
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.4, EventType::ball_cushion, 0, -1, 1),
      ev(0.9, EventType::ball_ball, 0, 2),
      ev(1.5, EventType::state_change, 2),
  };
  const ShotFacts f = rules.facts(events);
  EXPECT_EQ(f.first_hit, 2);
  EXPECT_FALSE(f.cushion_after_contact);
  EXPECT_EQ(f.object_balls_to_cushion, 0);
}

TEST(RulesCommonFacts, TheFirstHitIsTheCueBallsFirstContact) {
  // Object balls touching each other first (a ball already moving) do not
  // make a first hit; the cue ball's own first contact does, on either side
  // of the event.
  const Rules rules = eight_ball_rules();
  const std::vector<Event> events = {
      ev(0.1, EventType::ball_ball, 4, 6),
      ev(0.2, EventType::ball_cushion, 6, -1, 0),
      ev(0.3, EventType::ball_ball, 9, 0),
      ev(0.4, EventType::ball_ball, 0, 4),
  };
  const ShotFacts f = rules.facts(events);
  EXPECT_EQ(f.first_hit, 9);
  EXPECT_FALSE(f.cushion_after_contact);
  EXPECT_EQ(f.object_balls_to_cushion, 1);
  EXPECT_TRUE(f.pocketed.empty());
}

TEST(RulesCommonFacts, NoContactButBallsToCushions) {
  const Rules rules = eight_ball_rules();
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      ev(0.3, EventType::ball_cushion, 0, -1, 0),
      ev(0.6, EventType::ball_cushion, 0, -1, 1),
      ev(0.9, EventType::ball_pocket, 0, -1, -1, 1),
  };
  const ShotFacts f = rules.facts(events);
  EXPECT_EQ(f.first_hit, -1);
  EXPECT_FALSE(f.cushion_after_contact);
  EXPECT_EQ(f.object_balls_to_cushion, 0);
  EXPECT_EQ(f.pocketed, std::vector<int>{0});
  EXPECT_EQ(f.pocket_of, std::vector<int>{1});
}

TEST(RulesCommonFacts, AgreeWithASimulatedShot) {
  // Rules::apply's facts are facts(events) of the shot it simulated.
  const Rules rules = eight_ball_rules();
  const Outcome o = break_rack(rules, 4, kBreakSpeed);
  const ShotFacts f = rules.facts(o.events);
  EXPECT_EQ(f.first_hit, o.facts.first_hit);
  EXPECT_EQ(f.pocketed, o.facts.pocketed);
  EXPECT_EQ(f.pocket_of, o.facts.pocket_of);
  EXPECT_EQ(f.cushion_after_contact, o.facts.cushion_after_contact);
  EXPECT_EQ(f.object_balls_to_cushion, o.facts.object_balls_to_cushion);
}

// ---------------------------------------------------------------------------
// Stalemate

TEST(RulesCommonStalemate, TheGameIsDrawnAfterMaxShots) {
  const Rules rules = nine_ball_rules(2);
  const Outcome first = break_rack(rules, 4, kBreakSpeed);
  SCOPED_TRACE(describe(first));
  ASSERT_NE(first.state.phase, Phase::game_over);
  ASSERT_EQ(first.state.shots, 1);
  const GameState& s = first.state;
  const int lowest = rules.legal_actions(s).targets.front();
  const Outcome second = rules.apply(s, shot_at(s.position[0], s.position[lowest], 1.0));
  SCOPED_TRACE(describe(second));
  EXPECT_EQ(second.state.shots, 2);
  EXPECT_EQ(second.state.phase, Phase::game_over);
  EXPECT_EQ(second.state.winner, -1);
  EXPECT_EQ(second.ruling.winner, -1);
  EXPECT_FALSE(second.state.result.empty());
  EXPECT_FALSE(second.ruling.text.empty());
  EXPECT_TRUE(rules.check(second.state, strike(1.0, 0.0)).has_value());
}

TEST(RulesCommonStalemate, EightBallToo) {
  const Rules rules = eight_ball_rules(1);
  const Outcome o = break_rack(rules, 1, kBreakSpeed);  // a legal break: the breaker would continue
  SCOPED_TRACE(describe(o));
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, -1);
  EXPECT_EQ(o.ruling.winner, -1);
  EXPECT_FALSE(o.state.result.empty());
}

TEST(RulesCommonStalemate, NoLimitWithMaxShotsZero) {
  const Rules rules = eight_ball_rules(0);
  const Outcome o = break_rack(rules, 1, kBreakSpeed);
  EXPECT_EQ(o.state.phase, Phase::shot);
}

// ---------------------------------------------------------------------------
// Balls that leave the table (airborne physics)

TEST(RulesCommonFacts, BallsOffTheTableInOrderTheCueBallIncluded) {
  const Rules rules = airborne_rules(GameType::eight_ball);
  const std::vector<Event> events = {
      ev(0.0, EventType::cue_strike, 0),
      slate(0.1, 0, MotionState::airborne),  // a bounce is no fact of the rules
      ev(0.2, EventType::ball_ball, 0, 3),
      ev(0.3, EventType::ball_off_table, 3, -1, 1),  // over a rail
      ev(0.4, EventType::ball_pocket, 5, -1, -1, 2),
      ev(0.5, EventType::ball_off_table, 0),  // landed outside the table
  };
  const ShotFacts f = rules.facts(events);
  EXPECT_EQ(f.first_hit, 3);
  EXPECT_EQ(f.off_table, (std::vector<int>{3, 0}));
  EXPECT_EQ(f.pocketed, std::vector<int>{5});
  EXPECT_FALSE(f.cushion_after_contact);  // flying over a rail is no cushion contact
}

TEST(RulesCommonFouls, BallOffTableIsAFoulKindOnlyWithAirbornePhysics) {
  // Summaries list every foul kind of the game: the kind that cannot
  // happen on the cloth is not listed there, so their bytes stay.
  const std::vector<Foul> cloth = eight_ball_rules().foul_kinds();
  EXPECT_EQ(std::count(cloth.begin(), cloth.end(), Foul::ball_off_table), 0);
  EXPECT_EQ(cloth, nine_ball_rules().foul_kinds());
  for (const GameType g : {GameType::eight_ball, GameType::nine_ball}) {
    std::vector<Foul> air = airborne_rules(g).foul_kinds();
    ASSERT_EQ(air.size(), cloth.size() + 1);
    EXPECT_EQ(air.back(), Foul::ball_off_table);
    air.pop_back();
    EXPECT_EQ(air, cloth);
  }
  EXPECT_EQ(to_string(Foul::ball_off_table), "ball_off_table");
  EXPECT_EQ(parse_foul("ball_off_table"), Foul::ball_off_table);
}

TEST(RulesCommonEvents, ApplyEventsRulesAsApplyDoes) {
  // apply() is apply_events() with the simulated events and the balls'
  // resting places.
  const Rules rules = eight_ball_rules();
  const GameState s = rules.start(4, 0);
  const Shoot shot = shot_at(s.position[0], rules.table().foot_spot, kBreakSpeed);
  const Outcome o = rules.apply(s, shot);
  const Outcome e = rules.apply_events(s, shot, o.events, o.state.position, o.facts.miscue);
  EXPECT_EQ(e.facts, o.facts);
  EXPECT_EQ(e.ruling, o.ruling);
  EXPECT_EQ(e.state, o.state);
}

TEST(RulesCommonEvents, ABallThatLeavesKeepsItsPlaceAsInApply) {
  // apply() keeps a pocketed ball's position from before the shot, and
  // apply_events() does the same whatever `rest` gives it (the AI judges
  // its candidates through apply_events with the simulation's places).
  const Rules rules = nine_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.5, 0.5});
  put(s, 9, {2.0, 0.3});
  const Shoot shot = shot_at(s.position[0], s.position[1], 2.0);
  const std::vector<Event> events = {ev(0.0, EventType::cue_strike, 0),
                                     ev(0.2, EventType::ball_ball, 0, 1),
                                     ev(0.9, EventType::ball_pocket, 1, -1, -1, 0)};
  std::vector<Vec2> rest = s.position;
  rest[0] = {1.2, 0.5};
  rest[1] = rules.table().pockets[0].centre;
  const Outcome o = rules.apply_events(s, shot, events, rest);
  EXPECT_TRUE(o.ruling.fouls.empty()) << describe(o);
  EXPECT_FALSE(on(o.state, 1));
  EXPECT_TRUE(o.state.position[1] == s.position[1]);
  EXPECT_TRUE(o.state.position[0] == rest[0]);
  EXPECT_TRUE(o.state.position[9] == rest[9]);
}

TEST(RulesCommonEvents, ApplyEventsRefusesWhatCannotBe) {
  const Rules rules = nine_ball_rules();
  GameState s = bare_table(rules, {0.8, 0.5});
  put(s, 1, {1.5, 0.5});
  const Shoot shot = shot_at(s.position[0], s.position[1], 2.0);
  const std::vector<Event> events = {ev(0.0, EventType::cue_strike, 0),
                                     ev(0.2, EventType::ball_ball, 0, 1)};
  EXPECT_THROW((void)rules.apply_events(s, shot, events, std::vector<Vec2>(3)),
               std::invalid_argument);
  EXPECT_THROW(
      (void)rules.apply_events(s, shot, {ev(0.2, EventType::ball_ball, 0, 12)}, s.position),
      std::invalid_argument);
  std::vector<Vec2> bad = s.position;
  bad[1].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)rules.apply_events(s, shot, events, bad), std::invalid_argument);
  GameState over = s;
  over.phase = Phase::game_over;
  EXPECT_THROW((void)rules.apply_events(over, shot, events, s.position), std::invalid_argument);
}

TEST(RulesCommonEvents, AGameWithABallOffTheTableRecordsAndReplays) {
  // A real 9-ball game on airborne physics: the break, then hard elevated
  // strokes at the nearer long rail until a ball leaves the table. The
  // record names the foul, reads back to the same bytes and replays
  // identically.
  GameConfig config;
  config.game = GameType::nine_ball;
  config.physics = kLegacyGamePhysics;
  config.physics.airborne = true;
  GameSession game(config, Seats{{"a", "b"}, {}}, 11, 0);
  const GameState& s0 = game.state();
  (void)game.play(shot_at(s0.position[0], game.rules().table().foot_spot, kBreakSpeed));
  bool off = false;
  for (int shot = 0; shot < 6 && !off && !game.over(); ++shot) {
    const GameState& s = game.state();
    if (!s.on_table[0]) {
      (void)game.play(PlaceCueBall{{0.8, 0.635}});
      continue;
    }
    if (s.phase != Phase::shot) {
      (void)game.play(Decide{Choice::shoot});
      continue;
    }
    const Vec2 c = s.position[0];
    Shoot sh = strike(5.0, c.y < 0.635 ? -90.0 : 90.0, 30.0);
    const Outcome o = game.play(sh);
    off = !o.facts.off_table.empty();
    if (off) {
      EXPECT_TRUE(has_foul(o.ruling, Foul::ball_off_table));
      for (int b : o.facts.off_table) {
        EXPECT_EQ(on(o.state, b), b == 9) << "ball " << b;  // only the 9 comes back
      }
    }
  }
  ASSERT_TRUE(off) << "no ball left the table";
  const std::string text = write_record(game.record());
  EXPECT_NE(text.find("\"ball_off_table\""), std::string::npos);
  const auto read = read_record(text);
  ASSERT_TRUE(std::holds_alternative<GameRecord>(read)) << std::get<RecordError>(read).reason;
  EXPECT_EQ(write_record(std::get<GameRecord>(read)), text);
  const ReplayReport report = replay(std::get<GameRecord>(read));
  EXPECT_TRUE(report.identical) << report.message;
}

TEST(RulesCommonEvents, SummariesListBallOffTableOnlyWithAirbornePhysics) {
  MatchOptions options;
  options.game = GameType::nine_ball;
  options.players = {"baseline", "baseline"};
  options.physics.airborne = false;
  const std::string cloth = match_summary_json(empty_summary(options, {}));
  EXPECT_EQ(cloth.find("ball_off_table"), std::string::npos);
  options.physics.airborne = true;
  const std::string air = match_summary_json(empty_summary(options, {}));
  EXPECT_NE(air.find("\"ball_off_table\": 0"), std::string::npos) << air;
  // The reader expects the kinds of the summary's own physics.
  EXPECT_EQ(match_summary_json(read_match_summary(air)), air);
}

}  // namespace test_rules_common

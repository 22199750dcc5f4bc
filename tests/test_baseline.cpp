// The baseline player (include/breakshot/player.hpp) on hand-placed
// tables: it pots a straight-in ball in the pocket it calls, goes around a
// blocker, places the cue ball (behind the head string or anywhere) and
// then shoots, breaks, makes the decisions the rules offer, is
// deterministic, and over whole games never returns an action that
// Rules::check refuses. Every outcome comes from Rules::apply.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/players.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "rules_fixtures.hpp"

namespace test_baseline {

namespace {

using namespace rules_fixtures;

/// The player's action in `s`, which the rules must accept.
Action decide_legal(Player& player, const Rules& rules, const GameState& s,
                    std::uint64_t seed = 1) {
  const Action a = player.decide(rules, s, seed);
  const std::optional<std::string> why = rules.check(s, a);
  EXPECT_FALSE(why.has_value()) << why.value_or("");
  return a;
}

bool same_action(const Action& x, const Action& y) {
  if (x.index() != y.index()) return false;
  if (const auto* p = std::get_if<PlaceCueBall>(&x)) return *p == std::get<PlaceCueBall>(y);
  if (const auto* d = std::get_if<Decide>(&x)) return *d == std::get<Decide>(y);
  const Shoot& a = std::get<Shoot>(x);
  const Shoot& b = std::get<Shoot>(y);
  return a.strike.speed == b.strike.speed && a.strike.phi == b.strike.phi &&
         a.strike.theta == b.strike.theta && a.strike.a == b.strike.a && a.strike.b == b.strike.b &&
         a.call == b.call && a.safety == b.safety && a.push_out == b.push_out;
}

Vec2 rotate_deg(Vec2 v, double deg) {
  const double a = deg * kPi / 180.0;
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y};
}

Vec2 table_centre(const Rules& rules) {
  return {rules.table().length / 2.0, rules.table().width / 2.0};
}

/// balls[k] at 60 k degrees around `centre`, `gap` clear of it (-1 leaves
/// the place empty). Six balls 0.5 mm clear shut a ball in; with 3 mm
/// between them a ball has no way out but can be hit from an empty place.
void ring(GameState& s, Vec2 centre, const std::vector<int>& balls, double gap = 0.0005) {
  for (std::size_t k = 0; k < balls.size(); ++k) {
    if (balls[k] < 0) continue;
    const double a = static_cast<double>(k) * kPi / 3.0;
    put(s, balls[k], centre + Vec2{std::cos(a), std::sin(a)} * (2.0 * kR + gap));
  }
}

// ---------------------------------------------------------------------------

TEST(BaselinePlayer, MadeByName) {
  EXPECT_EQ(make_player("baseline")->name(), "baseline");
  EXPECT_EQ(make_baseline_player()->name(), "baseline");
  try {
    make_player("shark");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("shark"), std::string::npos) << msg;
    EXPECT_NE(msg.find("baseline"), std::string::npos) << msg;
  }
}

TEST(BaselinePlayer, PotsAStraightInBallInTheCalledPocket) {
  const Rules rules = eight_ball_rules();
  const int pocket = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, pocket, table_centre(rules), 0.45, 0.35);
  GameState s = bare_table(rules, si.cue);
  put(s, 3, si.object);
  put(s, 8, {0.5, 1.0});
  put(s, 12, {0.3, 0.9});
  const auto player = make_baseline_player();
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  ASSERT_TRUE(shot.call.has_value());
  EXPECT_EQ(*shot.call, (Call{3, pocket}));
  EXPECT_FALSE(shot.safety);
  // Straight at the ball, give or take the aim within the pocket mouth.
  EXPECT_NEAR(shot.strike.phi, aim_deg(si.cue, si.object), 1.5);
  EXPECT_EQ(shot.strike.a, 0.0);
  EXPECT_EQ(shot.strike.b, 0.0);
  EXPECT_EQ(shot.strike.theta, 0.0);

  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(pocket_of(out.facts, 3), pocket);
  EXPECT_TRUE(out.ruling.fouls.empty());
  EXPECT_TRUE(out.ruling.turn_continues) << out.ruling.text;
  EXPECT_EQ(out.ruling.assigned, Group::solids);
}

TEST(BaselinePlayer, PotsTheLowestBallIn9Ball) {
  const Rules rules = nine_ball_rules();
  const int pocket = pocket_index(rules, "side_top");
  const StraightIn si = straight_in(rules, pocket, {1.1, 0.3}, 0.5, 0.3);
  GameState s = bare_table(rules, si.cue);
  put(s, 2, si.object);
  put(s, 5, {2.2, 0.3});
  put(s, 9, {2.0, 1.0});
  const auto player = make_baseline_player();
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  EXPECT_FALSE(shot.call.has_value());
  EXPECT_FALSE(shot.push_out);
  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(out.facts.first_hit, 2);
  EXPECT_EQ(pocket_of(out.facts, 2), pocket);
  EXPECT_TRUE(out.ruling.turn_continues) << out.ruling.text;
}

TEST(BaselinePlayer, CutsABallIntoAPocket) {
  // A 30-degree cut: the aim has to allow for throw.
  const Rules rules = eight_ball_rules();
  const int pocket = pocket_index(rules, "top_left");
  const Vec2 c = pocket_centre(rules, pocket);
  const Vec2 object = c + unit(Vec2{1.0, -0.6}) * 0.8;
  const Vec2 line = unit(object - c);
  const Vec2 cue = object + rotate_deg(line, 30.0) * 0.6;
  GameState s = bare_table(rules, cue);
  put(s, 11, object);
  put(s, 8, {2.2, 0.2});
  const auto player = make_baseline_player();
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  ASSERT_TRUE(shot.call.has_value());
  EXPECT_EQ(*shot.call, (Call{11, pocket}));
  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(pocket_of(out.facts, 11), pocket);
  EXPECT_TRUE(out.ruling.turn_continues) << out.ruling.text;
}

TEST(BaselinePlayer, GoesAroundABlockedPocket) {
  const Rules rules = eight_ball_rules();
  const int pocket = pocket_index(rules, "bottom_right");
  const StraightIn si = straight_in(rules, pocket, table_centre(rules), 0.45, 0.35);
  GameState s = bare_table(rules, si.cue);
  put(s, 3, si.object);
  put(s, 12, {0.3, 0.9});
  const auto player = make_baseline_player();

  // The 8 halfway between the 3 and the pocket.
  GameState object_blocked = s;
  put(object_blocked, 8, (si.object + pocket_centre(rules, pocket)) * 0.5);
  const Action a = decide_legal(*player, rules, object_blocked);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  EXPECT_NE(shot.call, (std::optional<Call>{Call{3, pocket}}));
  EXPECT_NE(rules.apply(object_blocked, a).facts.first_hit, 8);

  // The 8 between the cue ball and the 3.
  GameState cue_blocked = s;
  put(cue_blocked, 8, (si.object + si.cue) * 0.5);
  const Action b = decide_legal(*player, rules, cue_blocked);
  ASSERT_TRUE(std::holds_alternative<Shoot>(b));
  EXPECT_NE(std::get<Shoot>(b).call, (std::optional<Call>{Call{3, pocket}}));
  const Outcome out = rules.apply(cue_blocked, b);
  EXPECT_NE(out.facts.first_hit, 8);
  EXPECT_TRUE(out.ruling.fouls.empty()) << out.ruling.text;
}

TEST(BaselinePlayer, PlaysASafetyWhenNothingIsMakeable) {
  // The only legal ball sits in a ring of others: no pot, but it can be
  // hit first and something sent to a cushion.
  const Rules rules = nine_ball_rules();
  GameState s = bare_table(rules, {0.6, 0.6});
  ring(s, {1.6, 0.6}, {2, 3, 4, -1, 5, 6}, 0.003);
  put(s, 1, {1.6, 0.6});
  put(s, 9, {2.3, 1.1});
  const auto player = make_baseline_player();
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(out.facts.first_hit, 1);
  EXPECT_TRUE(out.ruling.fouls.empty()) << out.ruling.text;

  // 8-ball: the same, declared as a safety, without a call.
  const Rules eight = eight_ball_rules();
  GameState e = bare_table(eight, {0.6, 0.6});
  e.group = {Group::solids, Group::stripes};
  ring(e, {1.6, 0.6}, {9, 10, 11, -1, 12, 13}, 0.003);
  put(e, 1, {1.6, 0.6});
  put(e, 8, {2.3, 1.1});
  const Action b = decide_legal(*player, eight, e);
  ASSERT_TRUE(std::holds_alternative<Shoot>(b));
  EXPECT_TRUE(std::get<Shoot>(b).safety);
  EXPECT_FALSE(std::get<Shoot>(b).call.has_value());
  const Outcome eo = eight.apply(e, b);
  EXPECT_EQ(eo.facts.first_hit, 1);
  EXPECT_TRUE(eo.ruling.fouls.empty()) << eo.ruling.text;
}

TEST(BaselinePlayer, BreaksStraightAtTheApex) {
  const auto player = make_baseline_player();
  for (const Rules& rules : {eight_ball_rules(), nine_ball_rules()}) {
    const GameState s = rules.start(5, 0);
    const Action a = decide_legal(*player, rules, s);
    ASSERT_TRUE(std::holds_alternative<Shoot>(a));
    const Shoot& shot = std::get<Shoot>(a);
    EXPECT_GE(shot.strike.speed, 7.5);
    EXPECT_LE(shot.strike.speed, 8.0);
    EXPECT_FALSE(shot.call.has_value());
    EXPECT_FALSE(shot.safety);
    // The apex is the 1 in 9-ball and the ball on the foot spot in 8-ball.
    int apex = 1;
    for (std::size_t b = 1; b < s.position.size(); ++b) {
      if (s.position[b].x < s.position[static_cast<std::size_t>(apex)].x) {
        apex = static_cast<int>(b);
      }
    }
    EXPECT_NEAR(shot.strike.phi, aim_deg(s.position[0], s.position[static_cast<std::size_t>(apex)]),
                1e-9);
    const Outcome out = rules.apply(s, a);
    EXPECT_EQ(out.facts.first_hit, apex);
  }
}

TEST(BaselinePlayer, PlacesBehindTheHeadStringAndShootsOutOfIt) {
  // After a scratch on the break: the cue ball in hand in the kitchen. The
  // easy 2 near the head rail may not be played first.
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.3, 0.6}, 1);
  s.on_table[0] = 0;
  s.ball_in_hand = BallInHand::kitchen;
  put(s, 2, {0.25, 0.15});
  put(s, 10, {1.7, 0.4});
  put(s, 5, {2.1, 0.9});
  put(s, 8, {1.9, 0.64});
  const auto player = make_baseline_player();

  const Action place = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<PlaceCueBall>(place));
  EXPECT_LE(std::get<PlaceCueBall>(place).position.x, rules.head_string());
  const GameState placed = rules.apply(s, place).state;
  EXPECT_EQ(placed.ball_in_hand, BallInHand::none);
  EXPECT_TRUE(placed.kitchen_shot);

  const Action a = decide_legal(*player, rules, placed);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  if (shot.call) {
    EXPECT_NE(shot.call->ball, 2);
  }
  const Outcome out = rules.apply(placed, a);
  EXPECT_NE(out.facts.first_hit, 2);
  EXPECT_FALSE(has_foul(out.ruling, Foul::behind_head_string));
  EXPECT_FALSE(has_foul(out.ruling, Foul::wrong_ball_first));
}

TEST(BaselinePlayer, PlacesAnywhereAndPots) {
  // Ball in hand after a foul, on tables left by real breaks: the player
  // places the cue ball, then shoots, and the pot goes in nearly always.
  const auto player = make_baseline_player();
  int tried = 0;
  int potted = 0;
  for (const Rules& rules : {eight_ball_rules(), nine_ball_rules()}) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      GameState s = rules.start(seed, 0);
      s = rules.apply(s, decide_legal(*player, rules, s)).state;
      if (s.phase != Phase::shot) continue;
      s.ball_in_hand = BallInHand::anywhere;
      s.on_table[0] = 0;

      const Action place = decide_legal(*player, rules, s);
      ASSERT_TRUE(std::holds_alternative<PlaceCueBall>(place));
      const GameState placed = rules.apply(s, place).state;
      EXPECT_FALSE(placed.kitchen_shot);
      const Action a = decide_legal(*player, rules, placed);
      ASSERT_TRUE(std::holds_alternative<Shoot>(a));
      const Shoot& shot = std::get<Shoot>(a);
      if (rules.config().game == GameType::eight_ball && !shot.call) continue;  // a safety
      ++tried;
      const Outcome out = rules.apply(placed, a);
      potted += out.ruling.turn_continues || out.state.winner == placed.player;
    }
  }
  EXPECT_GE(tried, 12);
  EXPECT_GE(potted, tried - 2) << potted << " of " << tried;
}

TEST(BaselinePlayer, MovesTheCueBallInHandOnlyForAnEasierShot) {
  // In hand anywhere with the cue ball already on the table behind an easy
  // straight-in: it shoots from there.
  const Rules rules = nine_ball_rules();
  const int pocket = pocket_index(rules, "bottom_left");
  const StraightIn si = straight_in(rules, pocket, table_centre(rules), 0.3, 0.08);
  GameState s = bare_table(rules, si.cue);
  put(s, 1, si.object);
  put(s, 9, {2.0, 1.0});
  s.ball_in_hand = BallInHand::anywhere;
  const auto player = make_baseline_player();
  const Action easy = decide_legal(*player, rules, s);
  EXPECT_TRUE(std::holds_alternative<Shoot>(easy));

  // Behind a wall of balls: it places.
  GameState hard = s;
  hard.position[0] = {2.3, 1.1};
  ring(hard, {2.3, 1.1}, {2, 3, 4, 5, 6, 7});
  const Action place = decide_legal(*player, rules, hard);
  EXPECT_TRUE(std::holds_alternative<PlaceCueBall>(place));
}

TEST(BaselinePlayer, MakesTheDecisionsOnOffer) {
  const auto player = make_baseline_player();

  // After a push-out: take the table with a pot on, else pass it back.
  const Rules nine = nine_ball_rules();
  const int pocket = pocket_index(nine, "top_right");
  const StraightIn si = straight_in(nine, pocket, table_centre(nine), 0.4, 0.3);
  GameState pushed = bare_table(nine, si.cue, 1);
  put(pushed, 1, si.object);
  put(pushed, 9, {0.5, 0.3});
  pushed.phase = Phase::push_out_choice;
  pushed.after_push_out = true;
  Action a = decide_legal(*player, nine, pushed);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::shoot);

  GameState hidden = pushed;
  ring(hidden, si.object, {2, 3, 4, 5, 6, 7});
  a = decide_legal(*player, nine, hidden);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::pass_back);

  // 8-ball: accept the table after an illegal break; spot the 8 after it
  // fell on the break.
  const Rules eight = eight_ball_rules();
  GameState illegal = eight.start(3, 0);
  illegal.phase = Phase::illegal_break_choice;
  illegal.player = 1;
  illegal.ball_in_hand = BallInHand::none;
  a = decide_legal(*player, eight, illegal);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::accept_table);

  GameState eight_down = eight.start(3, 0);
  eight_down.on_table[8] = 0;
  eight_down.phase = Phase::eight_on_break_choice;
  eight_down.ball_in_hand = BallInHand::none;
  a = decide_legal(*player, eight, eight_down);
  ASSERT_TRUE(std::holds_alternative<Decide>(a));
  EXPECT_EQ(std::get<Decide>(a).choice, Choice::respot_eight);
}

TEST(BaselinePlayer, IsDeterministic) {
  const Rules rules = eight_ball_rules();
  GameState s = rules.start(11, 0);
  const auto p1 = make_baseline_player();
  const auto p2 = make_baseline_player();
  s = rules.apply(s, decide_legal(*p1, rules, s)).state;
  for (int i = 0; i < 6 && s.phase != Phase::game_over; ++i) {
    const Action a = decide_legal(*p1, rules, s, 1);
    EXPECT_TRUE(same_action(a, p1->decide(rules, s, 1)));
    EXPECT_TRUE(same_action(a, p2->decide(rules, s, 987654321)));
    s = rules.apply(s, a).state;
  }
}

// Whole games between two baseline players, with and without execution
// noise: every action is legal and every game ends well before the shot
// limit.
TEST(BaselinePlayer, WholeGamesNeverBreakTheRules) {
  const NoiseModel noise = parse_noise("tournament");
  for (const Rules& rules : {eight_ball_rules(), nine_ball_rules()}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const bool noisy = seed > 2;
      const auto players = std::array{make_baseline_player(), make_baseline_player()};
      GameState s = rules.start(seed, static_cast<int>(seed % 2));
      int actions = 0;
      int pots = 0;
      while (s.phase != Phase::game_over && actions < 400) {
        Action a = decide_legal(*players[static_cast<std::size_t>(s.player)], rules, s, seed);
        if (auto* shot = std::get_if<Shoot>(&a); shot && noisy) {
          shot->strike = perturb(shot->strike, noise, rules.config().ball_radius,
                                 mix_seed(seed, static_cast<std::uint64_t>(actions)));
        }
        const Outcome out = rules.apply(s, a);
        if (std::holds_alternative<Shoot>(a) && out.ruling.turn_continues) ++pots;
        s = out.state;
        ++actions;
      }
      EXPECT_EQ(s.phase, Phase::game_over) << "seed " << seed;
      EXPECT_GE(s.winner, 0) << s.result;
      EXPECT_GT(pots, 2) << "seed " << seed;
    }
  }
}

}  // namespace

}  // namespace test_baseline

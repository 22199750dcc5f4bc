// Snooker by the WPBSA Official Rules of Snooker (docs/rules.md,
// "Snooker"): each clause from a hand-placed table and a shot. Rulings
// come from Rules::apply_events with hand-made event lists (what the
// physics reported is then exactly what the test says), a few from real
// shots on the 12 ft table, and whole frames between baseline players
// check that frames end and that scores and balls stay consistent with
// the rulings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/snooker.hpp"
#include "snooker_fixtures.hpp"
#include "io/game_json.hpp"
#include "sanitizers.hpp"

namespace test_rules_snooker {

using namespace breakshot;

namespace {

constexpr int kYellow = 16;
constexpr int kGreen = 17;
constexpr int kBrown = 18;
constexpr int kBlue = 19;
constexpr int kPink = 20;
constexpr int kBlack = 21;
constexpr double kR = kSnookerBallRadius;

using snooker_fixtures::put;
using snooker_fixtures::rules;

/// A frame in progress with only the cue ball on the table at `cue`.
GameState bare(Vec2 cue) { return snooker_fixtures::bare(cue, 5); }

bool on(const GameState& s, int ball) { return s.on_table[static_cast<std::size_t>(ball)] != 0; }

/// Every colour on its spot.
void colours_on_spots(GameState& s) {
  const SnookerMarks m = snooker_marks();
  put(s, kYellow, m.yellow);
  put(s, kGreen, m.green);
  put(s, kBrown, m.brown);
  put(s, kBlue, m.blue);
  put(s, kPink, m.pink);
  put(s, kBlack, m.black);
}

Event hit(double t, int a, int b) {
  Event e;
  e.time = t;
  e.type = EventType::ball_ball;
  e.ball = std::min(a, b);
  e.other = std::max(a, b);
  return e;
}

Event potted(double t, int ball, int pocket = 0) {
  Event e;
  e.time = t;
  e.type = EventType::ball_pocket;
  e.ball = ball;
  e.pocket = pocket;
  return e;
}

Shoot shoot(int nominate = -1) {
  Shoot sh;
  sh.strike.speed = 2.0;
  if (nominate > 0) sh.nominate = nominate;
  return sh;
}

/// Rules a shot from `s` whose events are `events` and after which every
/// ball still on the table rests where it was (or at `moved`).
Outcome rule(const GameState& s, const Shoot& sh, const std::vector<Event>& events,
             const std::vector<std::pair<int, Vec2>>& moved = {}) {
  std::vector<Vec2> rest = s.position;
  for (const auto& [b, p] : moved) rest[static_cast<std::size_t>(b)] = p;
  return rules().apply_events(s, sh, events, rest);
}

const SnookerState& sk(const GameState& s) { return *s.snooker; }

bool offered(const Rules& r, const GameState& s, Choice c) {
  const LegalActions la = r.legal_actions(s);
  return std::find(la.choices.begin(), la.choices.end(), c) != la.choices.end();
}

Vec2 mid() { return {0.5 * rules().table().length, 0.5 * rules().table().width}; }
/// A place for the cue ball clear of the spots.
Vec2 away() { return mid() + Vec2{-0.5, 0.3}; }

}  // namespace

// WPBSA Section 3, 2 (position of balls) and 4 (play from in-hand): the
// frame starts with every ball on its place and the cue ball in hand in
// the D.
TEST(Snooker, StartAndTheD) {
  const Rules& r = rules();
  const GameState s = r.start(11, 1);
  ASSERT_EQ(r.ball_count(), 22);
  EXPECT_EQ(s.phase, Phase::break_shot);
  EXPECT_EQ(s.player, 1);
  EXPECT_EQ(s.ball_in_hand, BallInHand::d);
  ASSERT_TRUE(s.snooker);
  EXPECT_EQ(sk(s).score[0], 0);
  for (int b = 0; b < 22; ++b) EXPECT_TRUE(on(s, b)) << b;
  const SnookerMarks m = snooker_marks();
  EXPECT_EQ(s.position[kBlack], m.black);
  EXPECT_EQ(s.position[kYellow], m.yellow);
  EXPECT_EQ(snooker_balls_on(s).size(), 15u);
  // The D: on the baulk line and within its radius of the brown spot.
  EXPECT_FALSE(r.check_placement(s, m.d_centre + Vec2{-0.1, 0.1}));
  EXPECT_FALSE(r.check_placement(s, {m.baulk_x, m.d_centre.y + 0.2}));
  EXPECT_TRUE(r.check_placement(s, {m.baulk_x + 0.01, m.d_centre.y + 0.1}));  // beyond the line
  EXPECT_TRUE(r.check_placement(s, m.d_centre + Vec2{-0.25, 0.2}));           // outside the arc
  // The opening stroke must first hit a red (3.3(c)).
  const LegalActions la = r.legal_actions(s);
  EXPECT_EQ(la.targets.size(), 15u);
  EXPECT_FALSE(la.must_nominate);
}

// 3.3(d)-(g), 3.6(a): a red, then a nominated colour, which is re-spotted
// while reds remain; the break adds up.
TEST(Snooker, RedThenNominatedColour) {
  GameState s = bare(away());
  colours_on_spots(s);
  put(s, 3, mid() + Vec2{0.3, 0.0});
  put(s, 4, mid() + Vec2{0.6, 0.3});
  const Outcome a = rule(s, shoot(), {hit(0.1, 0, 3), potted(0.5, 3)});
  EXPECT_TRUE(a.ruling.fouls.empty());
  ASSERT_TRUE(a.ruling.snooker);
  EXPECT_EQ(a.ruling.snooker->points, 1);
  EXPECT_TRUE(a.ruling.turn_continues);
  EXPECT_EQ(sk(a.state).score[0], 1);
  EXPECT_EQ(sk(a.state).break_points, 1);
  EXPECT_TRUE(sk(a.state).colour_on);
  EXPECT_EQ(snooker_balls_on(a.state), (std::vector<int>{16, 17, 18, 19, 20, 21}));
  // The colour must be nominated (the API asks it on every colour shot).
  EXPECT_TRUE(rules().legal_actions(a.state).must_nominate);
  EXPECT_TRUE(rules().check(a.state, shoot()));
  EXPECT_TRUE(rules().check(a.state, shoot(4)));  // a red is not a colour
  // A call is information only (a pot attempt for the statistics): a
  // ball on the table and a pocket that exists; the ball on is still the
  // nominated one.
  Shoot called = shoot(kBlue);
  called.call = Call{kBlue, 0};
  EXPECT_FALSE(rules().check(a.state, called));
  called.call = Call{kBlue, 6};
  EXPECT_TRUE(rules().check(a.state, called));  // no pocket 6
  called.call = Call{0, 0};
  EXPECT_TRUE(rules().check(a.state, called));  // the cue ball is no object ball
  const Outcome b = rule(a.state, shoot(kBlue), {hit(0.1, 0, kBlue), potted(0.6, kBlue, 2)});
  EXPECT_FALSE(b.ruling.call_made);
  called.call = Call{kBlue, 2};
  EXPECT_TRUE(rule(a.state, called, {hit(0.1, 0, kBlue), potted(0.6, kBlue, 2)}).ruling.call_made);
  called.call = Call{kBlue, 0};
  EXPECT_FALSE(rule(a.state, called, {hit(0.1, 0, kBlue), potted(0.6, kBlue, 2)}).ruling.call_made);
  EXPECT_TRUE(b.ruling.fouls.empty());
  EXPECT_EQ(b.ruling.snooker->points, 5);
  EXPECT_EQ(sk(b.state).score[0], 6);
  EXPECT_EQ(sk(b.state).break_points, 6);
  EXPECT_FALSE(sk(b.state).colour_on);
  EXPECT_TRUE(on(b.state, kBlue));
  EXPECT_EQ(b.state.position[kBlue], snooker_marks().blue);
  EXPECT_EQ(b.ruling.spotted, (std::vector<int>{kBlue}));
  EXPECT_TRUE(b.ruling.turn_continues);
  // Nothing potted: the break ends, the opponent is on a red.
  const Outcome c = rule(b.state, shoot(), {hit(0.1, 0, 4)});
  EXPECT_FALSE(c.ruling.turn_continues);
  EXPECT_EQ(c.state.player, 1);
  EXPECT_EQ(sk(c.state).break_points, 0);
  EXPECT_EQ(c.state.phase, Phase::shot);
}

// 3.3(d): every red potted in one stroke scores.
TEST(Snooker, SeveralRedsScore) {
  GameState s = bare(away());
  colours_on_spots(s);
  for (int b = 1; b <= 3; ++b) put(s, b, mid() + Vec2{0.3 + 0.06 * b, 0.1 * b});
  const Outcome o = rule(
      s, shoot(),
      {hit(0.1, 0, 1), hit(0.2, 1, 2), potted(0.5, 2, 1), potted(0.6, 3, 4), potted(0.7, 1, 5)});
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.snooker->points, 3);
  EXPECT_EQ(sk(o.state).score[0], 3);
}

// 3.11(b)(iv), (iii): the wrong colour first, or a colour not nominated
// potted: the value of the ball on or of the ball concerned, the higher.
TEST(Snooker, WrongColourFouls) {
  GameState s = bare(away());
  colours_on_spots(s);
  put(s, 5, mid() + Vec2{0.2, 0.4});
  s.snooker->colour_on = true;
  s.snooker->break_points = 1;
  s.snooker->score = {1, 0};
  // Nominated the green (3), hit the black (7) first: 7 away.
  const Outcome a = rule(s, shoot(kGreen), {hit(0.1, 0, kBlack)});
  EXPECT_EQ(a.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_first}));
  EXPECT_EQ(a.ruling.snooker->penalty, 7);
  EXPECT_EQ(sk(a.state).score[1], 7);
  EXPECT_EQ(a.state.phase, Phase::foul_choice);
  EXPECT_EQ(a.state.player, 1);
  EXPECT_FALSE(sk(a.state).colour_on);
  // Nominated the pink (6), hit the yellow first: 6, the ball on's value.
  const Outcome b = rule(s, shoot(kPink), {hit(0.1, 0, kYellow)});
  EXPECT_EQ(b.ruling.snooker->penalty, 6);
  // Nominated the yellow, hit it, potted the blue: 5, the blue re-spotted.
  const Outcome c = rule(s, shoot(kYellow),
                         {hit(0.1, 0, kYellow), hit(0.3, kYellow, kBlue), potted(0.8, kBlue, 3)});
  EXPECT_EQ(c.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_potted}));
  EXPECT_EQ(c.ruling.snooker->penalty, 5);
  EXPECT_EQ(c.ruling.snooker->points, 0);
  EXPECT_EQ(sk(c.state).score[0], 1);  // the break before the foul stands (3.10(a)(vi))
  EXPECT_TRUE(on(c.state, kBlue));
  EXPECT_EQ(c.state.position[kBlue], snooker_marks().blue);
}

// 3.11: at least 4; a red potted with a colour is a foul of the colour's
// value; the red stays down, the colour goes back.
TEST(Snooker, WrongBallPottedAndTheMinimum) {
  GameState s = bare(away());
  colours_on_spots(s);
  put(s, 7, mid() + Vec2{0.3, 0.2});
  put(s, 8, mid() + Vec2{0.5, -0.2});
  const Outcome a = rule(s, shoot(), {});
  EXPECT_EQ(a.ruling.fouls, (std::vector<Foul>{Foul::no_contact}));
  EXPECT_EQ(a.ruling.snooker->penalty, 4);
  const Outcome b = rule(
      s, shoot(), {hit(0.1, 0, 7), hit(0.2, 7, kPink), potted(0.5, 7, 1), potted(0.7, kPink, 4)});
  EXPECT_EQ(b.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_potted}));
  EXPECT_EQ(b.ruling.snooker->penalty, 6);
  EXPECT_FALSE(on(b.state, 7));
  EXPECT_TRUE(on(b.state, kPink));
  EXPECT_EQ(sk(b.state).score, (std::array<int, 2>{0, 6}));
}

// 3.11(a)(vi), 3.4, 3.10(c): an in-off gives the opponent the choice, and
// the cue ball in hand in the D.
TEST(Snooker, InOffAndTheD) {
  const Rules& r = rules();
  GameState s = bare(away());
  colours_on_spots(s);
  put(s, 2, mid() + Vec2{0.4, 0.0});
  const Outcome o = rule(s, shoot(), {hit(0.1, 0, 2), potted(0.9, 0, 2)});
  EXPECT_EQ(o.ruling.fouls, (std::vector<Foul>{Foul::in_off}));
  EXPECT_EQ(o.ruling.snooker->penalty, 4);
  EXPECT_EQ(o.state.phase, Phase::foul_choice);
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::d);
  EXPECT_FALSE(on(o.state, 0));
  EXPECT_FALSE(sk(o.state).free_ball);  // in hand: never snookered
  EXPECT_TRUE(offered(r, o.state, Choice::play_on));
  EXPECT_TRUE(offered(r, o.state, Choice::offender_again));
  EXPECT_FALSE(offered(r, o.state, Choice::replace_balls));
  const Outcome p = r.apply(o.state, Decide{Choice::play_on});
  EXPECT_EQ(p.state.player, 1);
  EXPECT_EQ(p.state.phase, Phase::shot);
  EXPECT_TRUE(r.legal_actions(p.state).must_place);
  const SnookerMarks m = snooker_marks();
  EXPECT_TRUE(r.check(p.state, PlaceCueBall{{m.baulk_x + 0.05, m.d_centre.y}}));
  const Outcome q = r.apply(p.state, PlaceCueBall{{m.baulk_x - 0.1, m.d_centre.y - 0.1}});
  EXPECT_EQ(q.state.ball_in_hand, BallInHand::none);
  // Or the offender plays again, from hand.
  const Outcome back = r.apply(o.state, Decide{Choice::offender_again});
  EXPECT_EQ(back.state.player, 0);
  EXPECT_EQ(back.state.ball_in_hand, BallInHand::d);
}

// Section 2 "Snookered", 3.9: after a foul that leaves the incoming player
// snookered, any ball may be nominated; potted, it scores as the ball on
// and is re-spotted.
TEST(Snooker, FreeBall) {
  const Rules& r = rules();
  GameState s = bare({1.0, 0.6});
  colours_on_spots(s);
  // The only red, straight behind the blue as seen from where the cue
  // ball comes to rest.
  const Vec2 blue = snooker_marks().blue;
  put(s, 9, blue + Vec2{0.5, 0.0});
  const Vec2 rest{blue.x - 0.6, blue.y};
  const Outcome foul = rule(s, shoot(), {hit(0.1, 0, kGreen)}, {{0, rest}});
  ASSERT_EQ(foul.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_first}));
  EXPECT_TRUE(r.snookered(foul.state));
  EXPECT_TRUE(sk(foul.state).free_ball);
  const Outcome play = r.apply(foul.state, Decide{Choice::play_on});
  EXPECT_TRUE(sk(play.state).free_ball);
  const LegalActions la = r.legal_actions(play.state);
  EXPECT_TRUE(std::count(la.targets.begin(), la.targets.end(), kBlue));
  EXPECT_TRUE(std::count(la.nominate.begin(), la.nominate.end(), kBlue));
  // The blue as a free ball, potted: one point (a red's), re-spotted, and
  // the striker is then on a colour.
  const Outcome fb = rule(play.state, shoot(kBlue), {hit(0.1, 0, kBlue), potted(0.5, kBlue, 2)});
  EXPECT_TRUE(fb.ruling.fouls.empty());
  EXPECT_TRUE(fb.ruling.snooker->free_ball);
  EXPECT_EQ(fb.ruling.snooker->points, 1);
  EXPECT_TRUE(on(fb.state, kBlue));
  EXPECT_TRUE(sk(fb.state).colour_on);
  EXPECT_FALSE(sk(fb.state).free_ball);
  // Hitting the red first on a free-ball shot that nominated the blue: a foul.
  const Outcome wrong = rule(play.state, shoot(kBlue), {hit(0.1, 0, 9)});
  EXPECT_EQ(wrong.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_first}));
  // The offender asked to play again gets no free ball.
  const Outcome again = r.apply(foul.state, Decide{Choice::offender_again});
  EXPECT_FALSE(sk(again.state).free_ball);
  EXPECT_TRUE(r.check(again.state, shoot(kBlue)));  // not on, no free ball
}

// 3.9(c), 3.11(a)(vii): the free ball must not leave the opponent
// snookered behind it.
TEST(Snooker, FreeBallMustNotSnooker) {
  GameState s = bare({1.0, 0.6});
  colours_on_spots(s);
  const Vec2 blue = snooker_marks().blue;
  put(s, 9, blue + Vec2{0.5, 0.0});
  s.snooker->free_ball = true;
  // The cue ball hits the blue (the free ball) and stops behind it.
  const Outcome o = rule(s, shoot(kBlue), {hit(0.1, 0, kBlue)}, {{0, blue - Vec2{0.3, 0.0}}});
  EXPECT_EQ(o.ruling.fouls, (std::vector<Foul>{Foul::free_ball_snooker}));
  EXPECT_EQ(o.ruling.snooker->penalty, 4);
  // Stopping with a clear view of the red is no foul.
  const Outcome ok = rule(s, shoot(kBlue), {hit(0.1, 0, kBlue)}, {{0, blue - Vec2{0.3, 0.3}}});
  EXPECT_TRUE(ok.ruling.fouls.empty());
}

// 3.6(c)-(e): a colour whose spot is taken goes to the highest-valued
// free spot; with every spot taken, as near its own spot as it can,
// toward the top cushion.
TEST(Snooker, RespottingOrder) {
  const SnookerMarks m = snooker_marks();
  const Rules& r = rules();
  GameState s = bare(mid() + Vec2{-0.5, 0.3});
  colours_on_spots(s);
  // Reds on the black and the pink spots: the black goes on the blue's.
  s.on_table[kBlack] = 0;
  s.on_table[kPink] = 0;
  s.on_table[kBlue] = 0;
  put(s, 10, m.black);
  put(s, 11, m.pink);
  EXPECT_EQ(r.spot_position(s, kBlack), m.blue);
  // Every spot taken: near its own spot, toward the top cushion (+x).
  GameState full = s;
  put(full, 12, m.blue);
  put(full, 13, m.brown);
  put(full, 14, m.green);
  put(full, 15, m.yellow);
  const Vec2 p = r.spot_position(full, kBlack);
  EXPECT_EQ(p.y, m.black.y);
  EXPECT_GT(p.x, m.black.x);
  EXPECT_GE(norm(p - m.black), 2.0 * kR);
  EXPECT_LT(norm(p - m.black), 2.0 * kR + kR / 32.0);
  const Vec2 y = r.spot_position(full, kYellow);
  EXPECT_EQ(y.y, m.yellow.y);
  EXPECT_GT(y.x, m.yellow.x);
  // A potted colour whose spot is taken, in a stroke: the black to the
  // highest free spot (here the pink's, its red gone).
  GameState t = s;
  t.on_table[11] = 0;
  put(t, kPink, m.pink + Vec2{-0.2, 0.3});
  put(t, kBlack, m.black + Vec2{-0.5, -0.3});
  t.snooker->colour_on = true;
  const Outcome o = rule(t, shoot(kBlack), {hit(0.1, 0, kBlack), potted(0.5, kBlack, 5)});
  ASSERT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(o.ruling.snooker->points, 7);
  EXPECT_EQ(o.state.position[kBlack], m.pink);
}

// 3.3(j), (k): the frame ends with the black; level scores re-spot it and
// the lot decides who plays from the D; the next score or foul ends it.
TEST(Snooker, RespottedBlackOnTie) {
  const Rules& r = rules();
  const SnookerMarks m = snooker_marks();
  GameState s = bare({1.5, 0.5});
  put(s, kBlack, m.black + Vec2{-0.3, 0.2});
  s.snooker->score = {40, 47};
  const Outcome o = rule(s, shoot(), {hit(0.1, 0, kBlack), potted(0.5, kBlack, 5)});
  ASSERT_TRUE(o.ruling.fouls.empty());
  EXPECT_EQ(sk(o.state).score, (std::array<int, 2>{47, 47}));
  EXPECT_NE(o.state.phase, Phase::game_over);
  EXPECT_TRUE(sk(o.state).respotted_black);
  EXPECT_TRUE(on(o.state, kBlack));
  EXPECT_EQ(o.state.position[kBlack], m.black);
  EXPECT_FALSE(on(o.state, 0));
  EXPECT_EQ(o.state.ball_in_hand, BallInHand::d);
  EXPECT_EQ(snooker_balls_on(o.state), (std::vector<int>{kBlack}));
  // The lot comes from the rack seed: the same frame, the same lot.
  const Outcome o2 = rule(s, shoot(), {hit(0.1, 0, kBlack), potted(0.5, kBlack, 5)});
  EXPECT_EQ(o2.state.player, o.state.player);
  const int lot = o.state.player;
  GameState placed = r.apply(o.state, PlaceCueBall{m.d_centre + Vec2{-0.1, 0.0}}).state;
  // A foul on the re-spotted black ends the frame for the opponent.
  const Outcome f = rule(placed, shoot(), {});
  EXPECT_EQ(f.state.phase, Phase::game_over);
  EXPECT_EQ(f.state.winner, 1 - lot);
  // Potting it wins.
  const Outcome w = rule(placed, shoot(), {hit(0.1, 0, kBlack), potted(0.5, kBlack, 5)});
  EXPECT_EQ(w.state.phase, Phase::game_over);
  EXPECT_EQ(w.state.winner, lot);
  EXPECT_EQ(w.ruling.winner, lot);
}

// 3.3(j): the last black potted ends the frame; a foul on it too.
TEST(Snooker, FrameEnd) {
  const SnookerMarks m = snooker_marks();
  GameState s = bare({1.5, 0.5});
  put(s, kBlack, m.black + Vec2{-0.3, 0.2});
  s.snooker->score = {60, 20};
  const Outcome o = rule(s, shoot(), {hit(0.1, 0, kBlack), potted(0.5, kBlack, 5)});
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 0);
  EXPECT_EQ(sk(o.state).score[0], 67);
  const Outcome f = rule(s, shoot(), {});
  EXPECT_EQ(f.state.phase, Phase::game_over);
  EXPECT_EQ(sk(f.state).score[1], 27);
  EXPECT_EQ(f.state.winner, 0);
  // The colours in order once the reds are gone (3.3(h)).
  GameState c = bare({1.5, 0.5});
  colours_on_spots(c);
  EXPECT_EQ(snooker_balls_on(c), (std::vector<int>{kYellow}));
  const Outcome g = rule(c, shoot(), {hit(0.1, 0, kGreen), potted(0.4, kGreen)});
  EXPECT_EQ(g.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_first, Foul::wrong_ball_potted}));
  EXPECT_TRUE(on(g.state, kGreen));  // a colour potted in a foul goes back
  const Outcome y = rule(c, shoot(), {hit(0.1, 0, kYellow), potted(0.4, kYellow)});
  EXPECT_EQ(y.ruling.snooker->points, 2);
  EXPECT_FALSE(on(y.state, kYellow));  // in order: stays down
  EXPECT_EQ(snooker_balls_on(y.state), (std::vector<int>{kGreen}));
}

// 3.14: a foul on which a ball on could be hit full is a miss; the
// incoming player may have the balls replaced and the offender play
// again; the third such miss loses the frame.
TEST(Snooker, MissWithTheBallsReplaced) {
  const Rules& r = rules();
  GameState s = bare({1.0, 0.5});
  colours_on_spots(s);
  put(s, 4, {2.0, 0.5});  // straight ahead, in the clear
  ASSERT_TRUE(r.full_ball_on(s));
  const Vec2 moved{1.7, 0.4};
  const Outcome m1 = rule(s, shoot(), {hit(0.1, 0, kBlue)}, {{0, moved}, {kBlue, {2.3, 0.6}}});
  ASSERT_EQ(m1.ruling.fouls, (std::vector<Foul>{Foul::wrong_ball_first}));
  EXPECT_TRUE(m1.ruling.snooker->miss);
  EXPECT_EQ(sk(m1.state).misses, 1);
  EXPECT_TRUE(offered(r, m1.state, Choice::replace_balls));
  const Outcome back = r.apply(m1.state, Decide{Choice::replace_balls});
  EXPECT_EQ(back.state.player, 0);
  EXPECT_EQ(back.state.position, s.position);
  EXPECT_EQ(back.state.on_table, s.on_table);
  EXPECT_EQ(sk(back.state).score[1], 5);  // the penalty stands
  EXPECT_TRUE(sk(back.state).replace_position.empty());
  const Outcome m2 = rule(back.state, shoot(), {}, {{0, moved}});
  EXPECT_TRUE(m2.ruling.snooker->miss);
  EXPECT_EQ(sk(m2.state).misses, 2);
  const Outcome back2 = r.apply(m2.state, Decide{Choice::replace_balls});
  const Outcome m3 = rule(back2.state, shoot(), {}, {{0, moved}});
  EXPECT_EQ(m3.state.phase, Phase::game_over);
  EXPECT_EQ(m3.state.winner, 1);
  // Playing on after a miss forgets the count.
  const Outcome on_ = r.apply(m1.state, Decide{Choice::play_on});
  EXPECT_EQ(sk(on_.state).misses, 0);
  EXPECT_FALSE(offered(r, on_.state, Choice::replace_balls));
}

TEST(Snooker, NoMissWithoutAFullBall) {
  const Rules& r = rules();
  // The only red hidden behind the blue: no full ball.
  GameState hid = bare({1.0, 0.9});
  colours_on_spots(hid);
  const Vec2 blue = snooker_marks().blue;
  hid.position[0] = blue - Vec2{0.5, 0.0};
  put(hid, 4, blue + Vec2{0.5, 0.0});
  EXPECT_FALSE(r.full_ball_on(hid));
  EXPECT_TRUE(r.snookered(hid));
  const Outcome o = rule(hid, shoot(), {hit(0.1, 0, kBlue)});
  EXPECT_FALSE(o.ruling.snooker->miss);
  EXPECT_FALSE(offered(r, o.state, Choice::replace_balls));
}

// 3.7: a cue ball touching a ball on may be played away from it; touching
// a ball not on, it must still hit a ball on.
TEST(Snooker, TouchingBall) {
  const Rules& r = rules();
  GameState s = bare({1.0, 0.9});
  colours_on_spots(s);
  put(s, 4, {1.0 + 2.0 * kR + 2e-5, 0.9});
  EXPECT_EQ(r.touching(s), (std::vector<int>{4}));
  const Outcome away = rule(s, shoot(), {}, {{0, {0.6, 0.9}}});
  EXPECT_TRUE(away.ruling.fouls.empty());
  GameState c = s;
  c.position[4] = {2.5, 1.2};
  put(c, kPink, {1.0, 0.9 + 2.0 * kR + 2e-5});
  ASSERT_EQ(r.touching(c), (std::vector<int>{kPink}));
  const Outcome no = rule(c, shoot(), {}, {{0, {0.6, 0.9}}});
  EXPECT_EQ(no.ruling.fouls, (std::vector<Foul>{Foul::no_contact}));
}

// Section 4 (conceding): the striker may concede; after a foul, the
// incoming player too.
TEST(Snooker, Concede) {
  const Rules& r = rules();
  GameState s = bare({1.0, 0.9});
  colours_on_spots(s);
  put(s, 4, {2.0, 0.9});
  s.snooker->score = {10, 50};
  EXPECT_TRUE(offered(r, s, Choice::concede));
  const Outcome o = r.apply(s, Decide{Choice::concede});
  EXPECT_EQ(o.state.phase, Phase::game_over);
  EXPECT_EQ(o.state.winner, 1);
  EXPECT_EQ(o.ruling.winner, 1);
  EXPECT_NE(o.ruling.text.find("concedes"), std::string::npos);
  const Outcome f = rule(s, shoot(), {});
  EXPECT_TRUE(offered(r, f.state, Choice::concede));
  EXPECT_EQ(r.apply(f.state, Decide{Choice::concede}).state.winner, 0);
}

// Points remaining and snookers required: 15 reds with blacks and the
// colours are 147; the colours alone 27.
TEST(Snooker, PointsRemainingAndSnookersRequired) {
  const GameState s = rules().start(3, 0);
  EXPECT_EQ(snooker_points_remaining(s), 147);
  GameState c = s;
  c.snooker->colour_on = true;
  c.on_table[1] = 0;
  EXPECT_EQ(snooker_points_remaining(c), 14 * 8 + 7 + 27);
  GameState colours = bare({1.0, 0.9});
  colours_on_spots(colours);
  EXPECT_EQ(snooker_points_remaining(colours), 27);
  colours.on_table[kYellow] = 0;
  EXPECT_EQ(snooker_points_remaining(colours), 25);
  GameState pb = bare({1.0, 0.9});
  put(pb, kPink, snooker_marks().pink);
  put(pb, kBlack, snooker_marks().black);
  pb.snooker->score = {0, 60};
  EXPECT_EQ(snooker_points_remaining(pb), 13);
  // 60 behind with 13 on the table: 47 to find, 6 a snooker on the pink.
  EXPECT_EQ(snookers_required(pb, 0), 8);
  EXPECT_EQ(snookers_required(pb, 1), 0);
  pb.snooker->score = {0, 13};
  EXPECT_EQ(snookers_required(pb, 0), 0);
  pb.snooker->score = {0, 14};
  EXPECT_EQ(snookers_required(pb, 0), 1);
  GameConfig nine;
  nine.game = GameType::nine_ball;
  EXPECT_THROW((void)snooker_points_remaining(Rules(nine).start(1, 0)), std::invalid_argument);
}

// Real shots on the 12 ft table: a red straight into a corner pocket
// scores; the cue ball rolled into a pocket past every ball is an in-off
// that missed all balls.
TEST(Snooker, RealShots) {
  const Rules& r = rules();
  const Table& t = r.table();
  // The corner pocket with the largest x + y (the top cushion's end).
  const Pocket* corner = &t.pockets.front();
  for (const Pocket& p : t.pockets) {
    if (p.centre.x + p.centre.y > corner->centre.x + corner->centre.y) corner = &p;
  }
  const Vec2 in = Vec2{-1.0, -1.0} / std::sqrt(2.0);  // from the pocket into the table
  GameState s = bare(corner->centre + in * 0.9);
  put(s, 5, corner->centre + in * 0.4);
  Shoot sh;
  sh.strike.speed = 2.0;
  sh.strike.phi = std::atan2(-in.y, -in.x) * 180.0 / 3.14159265358979323846;
  const Outcome o = r.apply(s, sh);
  EXPECT_TRUE(o.ruling.fouls.empty()) << o.ruling.text;
  EXPECT_FALSE(on(o.state, 5)) << o.ruling.text;
  EXPECT_EQ(o.ruling.snooker->points, 1);
  EXPECT_TRUE(sk(o.state).colour_on);

  GameState c = bare(corner->centre + in * 0.5);
  put(c, 5, mid());
  const Outcome io = r.apply(c, sh);
  EXPECT_EQ(io.ruling.fouls, (std::vector<Foul>{Foul::in_off, Foul::no_contact})) << io.ruling.text;
  EXPECT_EQ(io.ruling.snooker->penalty, 4);
  EXPECT_EQ(io.state.ball_in_hand, BallInHand::d);
}

namespace {

constexpr int kFrames = kUnderSanitizers ? 4 : 50;

/// The first broken invariant of an action of a snooker frame, or "".
std::string broken(const Rules& r, const GameState& before, const RecordedAction& act) {
  const GameState& s = act.after;
  const double R = r.config().ball_radius;
  if (!s.snooker || !before.snooker) return "snooker's part missing";
  for (int i = 0; i < 22; ++i) {
    if (!on(s, i)) continue;
    const Vec2 p = s.position[static_cast<std::size_t>(i)];
    if (wall_clearance(r.table(), p, R) < -1e-9)
      return "ball " + std::to_string(i) + " off the bed";
    for (int j = i + 1; j < 22; ++j) {
      if (on(s, j) && norm(s.position[static_cast<std::size_t>(j)] - p) < 2.0 * R - 1e-9) {
        return "balls " + std::to_string(i) + " and " + std::to_string(j) + " overlap";
      }
    }
  }
  const bool replaced = std::holds_alternative<Decide>(act.action) &&
                        std::get<Decide>(act.action).choice == Choice::replace_balls;
  for (int b = 1; b < 22; ++b) {
    if (on(before, b) || !on(s, b) || replaced) continue;
    if (b <= 15) return "red " + std::to_string(b) + " came back";
    if (!std::count(act.ruling.spotted.begin(), act.ruling.spotted.end(), b)) {
      return "colour " + std::to_string(b) + " came back unspotted";
    }
  }
  // The scores move only by the ruling's points and penalty.
  std::array<int, 2> expect = before.snooker->score;
  if (std::holds_alternative<Shoot>(act.action)) {
    if (!act.ruling.snooker) return "a shot without snooker's ruling";
    const auto me = static_cast<std::size_t>(act.player);
    expect[me] += act.ruling.snooker->points;
    expect[1 - me] += act.ruling.snooker->penalty;
    if (act.ruling.snooker->points > 0 && act.ruling.snooker->penalty > 0) {
      return "points and a penalty in one stroke";
    }
    if (act.ruling.fouls.empty() != (act.ruling.snooker->penalty == 0)) {
      return "a penalty without a foul, or a foul without one";
    }
  }
  if (s.snooker->score != expect) return "the score moved without the ruling";
  if (s.phase == Phase::game_over) {
    if (s.winner != act.ruling.winner || s.result.empty()) return "game over without a winner";
  }
  return {};
}

}  // namespace

// Whole frames between baseline players: every frame ends, the invariants
// hold after every action, the winner of a frame that ran its course has
// the higher score, and the records replay exactly.
TEST(Snooker, WholeFramesBetweenBaselinePlayers) {
  const Rules& r = rules();
  auto p0 = make_player("baseline");
  auto p1 = make_player("baseline");
  const char* levels[] = {"tournament", "none", "5x"};
  int stalemates = 0;
  for (int g = 0; g < kFrames; ++g) {
    const GameRecord rec =
        play_game(r, *p0, *p1, g % 2, mix_seed(23, static_cast<std::uint64_t>(g)),
                  parse_noise(levels[g % 3]));
    GameState before = rec.start;
    for (std::size_t k = 0; k < rec.actions.size(); ++k) {
      const std::string why = broken(r, before, rec.actions[k]);
      ASSERT_TRUE(why.empty()) << "frame " << g << " action " << k << ": " << why << " ("
                               << rec.actions[k].ruling.text << ")";
      before = rec.actions[k].after;
    }
    ASSERT_EQ(before.phase, Phase::game_over) << "frame " << g;
    if (before.winner < 0) {
      ++stalemates;
    } else if (before.result.find("won the frame") != std::string::npos) {
      const auto w = static_cast<std::size_t>(before.winner);
      EXPECT_GT(before.snooker->score[w], before.snooker->score[1 - w]) << "frame " << g;
    }
    if (g % 5 == 0) {
      const auto read = read_record(write_record(rec));
      ASSERT_TRUE(std::holds_alternative<GameRecord>(read));
      const ReplayReport rep = replay(std::get<GameRecord>(read));
      EXPECT_TRUE(rep.identical) << "frame " << g << ": " << rep.message;
      EXPECT_EQ(write_record(std::get<GameRecord>(read)), write_record(rec));
    }
  }
  EXPECT_LE(stalemates, kFrames / 10);
}

// The match summary: frames, points, breaks, fouls by snooker's kinds; its
// JSON reads back; the summed figures agree with the records.
TEST(Snooker, MatchSummary) {
  MatchOptions opt;
  opt.game = GameType::snooker;
  opt.table_size = "12ft";
  opt.players = {"baseline", "baseline"};
  opt.games = 2;
  opt.seed = 4;
  opt.noise = parse_noise("tournament");
  std::vector<GameRecord> records;
  const MatchSummary s =
      play_match(opt, [&](int, const GameRecord& rec) { records.push_back(rec); });
  ASSERT_EQ(records.size(), 2u);
  for (const PlayerStats& p : s.players) {
    ASSERT_TRUE(p.snooker);
    EXPECT_TRUE(p.fouls.count("in_off"));
    EXPECT_TRUE(p.fouls.count("wrong_ball_potted"));
    EXPECT_FALSE(p.fouls.count("scratch"));
    EXPECT_FALSE(p.fouls.count("no_rail"));
    EXPECT_GE(p.snooker->highest_break, 0);
    EXPECT_LE(p.snooker->break_points, p.snooker->points);
  }
  int points = 0;
  for (const GameRecord& rec : records) {
    const GameState& end = rec.actions.back().after;
    points += end.snooker->score[0] + end.snooker->score[1];
  }
  EXPECT_EQ(s.players[0].snooker->points + s.players[1].snooker->points, points);
  const std::string json = match_summary_json(s);
  EXPECT_NE(json.find("\"highest_break\""), std::string::npos);
  EXPECT_EQ(match_summary_json(read_match_summary(json)), json);
}

// The JSON of snooker's state and ruling: written in snooker only, read
// back equal, required in snooker and refused elsewhere.
TEST(Snooker, JsonOfStateAndRuling) {
  using json_io::json;
  GameState s = bare({1.0, 0.5});
  colours_on_spots(s);
  put(s, 4, {2.0, 0.5});
  const Outcome miss = rule(s, shoot(), {hit(0.1, 0, kBlue)}, {{0, {1.7, 0.4}}});
  ASSERT_FALSE(sk(miss.state).replace_position.empty());
  const auto read_state = [](const std::string& text, GameState& out) {
    json_io::GameReader reader;
    const bool ok = reader.state(json::parse(text), "state", out);
    return ok ? std::string() : reader.error->path + ": " + reader.error->reason;
  };
  GameState back;
  const std::string text = json_io::state_json(miss.state).dump();
  EXPECT_EQ(read_state(text, back), "");
  EXPECT_EQ(back, miss.state);
  // A snooker state without its part, a pool state with one: refused.
  json no_part = json::parse(text);
  no_part.erase("snooker");
  EXPECT_EQ(read_state(no_part.dump(), back), "state.snooker: missing required field");
  GameConfig nine;
  nine.game = GameType::nine_ball;
  json pool = json::parse(json_io::state_json(Rules(nine).start(1, 0)).dump());
  EXPECT_EQ(pool.find("snooker"), pool.end());
  pool["snooker"] = json::parse(text)["snooker"];
  EXPECT_NE(read_state(pool.dump(), back).find("state.snooker"), std::string::npos);
  // The ruling and the nominating shot.
  json_io::GameReader reader;
  Ruling r;
  ASSERT_TRUE(reader.ruling(json::parse(json_io::ruling_json(miss.ruling).dump()), "r", r));
  EXPECT_EQ(r, miss.ruling);
  Action a;
  ASSERT_TRUE(
      reader.action(json::parse(json_io::action_json(Action{shoot(kPink)}).dump()), "a", a));
  EXPECT_EQ(std::get<Shoot>(a).nominate, kPink);
  EXPECT_EQ(json_io::action_json(Action{shoot()}).dump().find("nominate"), std::string::npos);
}

}  // namespace test_rules_snooker

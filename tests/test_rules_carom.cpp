// Three-cushion billiards by the UMB rules (docs/rules.md,
// "Three-cushion"): each clause from a hand-placed table and a shot.
// Rulings come from Rules::apply_events with hand-made event lists (what
// the physics reported is then exactly what the test says), others from
// real shots on the carom table found by turning the aim, and whole games
// between baseline players check that games end, that the scores agree
// with the rulings and that records replay exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "io/game_json.hpp"

namespace test_rules_carom {

using namespace breakshot;

namespace {

constexpr int kWhite = 0;
constexpr int kYellow = 1;
constexpr int kRed = 2;
constexpr double kR = kCaromBallRadius;

const Rules& rules() {
  static const Rules r(three_cushion_config());
  return r;
}

Rules rules_with(CaromRules c) {
  GameConfig g = three_cushion_config();
  g.carom = c;
  return Rules(g);
}

/// A game in progress: player 0 (who broke, on the white) to shoot, the
/// balls where given.
GameState table(Vec2 white, Vec2 yellow, Vec2 red, int player = 0) {
  GameState s = rules().start(1, 0);
  s.position = {white, yellow, red};
  s.phase = Phase::shot;
  s.shots = 1;
  s.player = player;
  if (player == 1) {
    s.innings = 2;
    s.carom->innings = {1, 1};
  }
  return s;
}

GameState open_table(int player = 0) {
  return table({0.5, 0.4}, {1.5, 1.0}, {2.3, 0.5}, player);
}

Event hit(double t, int a, int b) {
  Event e;
  e.time = t;
  e.type = EventType::ball_ball;
  e.ball = std::min(a, b);
  e.other = std::max(a, b);
  return e;
}

Event rail(double t, int ball, int wall = 0) {
  Event e;
  e.time = t;
  e.type = EventType::ball_cushion;
  e.ball = ball;
  e.wall = wall;
  return e;
}

Event off(double t, int ball) {
  Event e;
  e.time = t;
  e.type = EventType::ball_off_table;
  e.ball = ball;
  return e;
}

Event strike(int ball) {
  Event e;
  e.time = 0.0;
  e.type = EventType::cue_strike;
  e.ball = ball;
  return e;
}

Shoot shoot(double phi = 0.0, double speed = 3.0) {
  Shoot sh;
  sh.strike.speed = speed;
  sh.strike.phi = phi;
  return sh;
}

/// The ruling of a hand-made shot, every ball coming to rest where it was
/// unless moved in `rest`.
Outcome rule(const GameState& s, std::vector<Event> ev, const Shoot& sh = shoot(),
             std::vector<Vec2> rest = {}, const Rules& r = rules()) {
  if (rest.empty()) rest = s.position;
  return r.apply_events(s, sh, std::move(ev), rest);
}

}  // namespace

TEST(ThreeCushion, StartsFromTheUmbPosition) {
  const Rules& r = rules();
  EXPECT_EQ(r.ball_count(), 3);
  EXPECT_EQ(r.table().shape, TableShape::carom);
  const CaromMarks m = carom_marks();
  for (int breaker = 0; breaker < 2; ++breaker) {
    const GameState s = r.start(7, breaker);
    EXPECT_EQ(s.phase, Phase::break_shot);
    EXPECT_EQ(s.player, breaker);
    EXPECT_EQ(s.breaker, breaker);
    EXPECT_EQ(s.ball_in_hand, BallInHand::none);
    EXPECT_EQ(s.position[kRed], m.top_spot);
    EXPECT_EQ(s.position[kYellow], m.bottom_spot);
    EXPECT_TRUE(s.position[kWhite] == m.starting_spots[0] ||
                s.position[kWhite] == m.starting_spots[1]);
    ASSERT_TRUE(s.carom);
    EXPECT_EQ(s.carom->score, (std::array<int, 2>{0, 0}));
    EXPECT_EQ(s.carom->innings[static_cast<std::size_t>(breaker)], 1);
    // The breaker plays the white, the other player the yellow.
    EXPECT_EQ(r.cue_ball(s), kWhite);
    GameState other = s;
    other.player = 1 - breaker;
    EXPECT_EQ(r.cue_ball(other), kYellow);
    const LegalActions la = r.legal_actions(s);
    EXPECT_TRUE(la.shoot);
    EXPECT_EQ(la.place, BallInHand::none);
    EXPECT_EQ(la.targets, std::vector<int>{kRed});
    EXPECT_TRUE(la.choices.empty());
  }
  EXPECT_EQ(r.foul_kinds(), (std::vector<Foul>{Foul::wrong_ball_first, Foul::wrong_cue_ball,
                                               Foul::push_through, Foul::ball_off_table}));
  GameConfig bad = three_cushion_config();
  bad.table_size = "9ft";
  EXPECT_THROW(Rules{bad}, std::invalid_argument);
  bad = three_cushion_config();
  bad.carom.target = 0;
  EXPECT_THROW(Rules{bad}, std::invalid_argument);
  bad = three_cushion_config();
  bad.carom.innings_limit = -1;
  EXPECT_THROW(Rules{bad}, std::invalid_argument);
}

TEST(ThreeCushion, APointWithThreeCushionsBeforeTheSecondBall) {
  const GameState s = open_table();
  // The white takes the red, then three cushions, then the yellow.
  const Outcome o = rule(s, {strike(kWhite), hit(0.5, kWhite, kRed), rail(0.9, kWhite),
                             rail(1.3, kWhite), rail(1.8, kWhite), hit(2.4, kWhite, kYellow)});
  ASSERT_TRUE(o.ruling.carom);
  EXPECT_TRUE(o.ruling.carom->point);
  EXPECT_EQ(o.ruling.carom->cushions, 3);
  EXPECT_EQ(o.ruling.carom->hit, (std::vector<int>{kRed, kYellow}));
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_TRUE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 0);
  EXPECT_EQ(o.state.carom->score, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(o.state.carom->run, 1);
  EXPECT_NE(o.ruling.text.find("A point"), std::string::npos) << o.ruling.text;
  // The same cushion counts again; cushions before the first ball count.
  const Outcome same = rule(s, {rail(0.2, kWhite, 2), rail(0.4, kWhite, 2), rail(0.6, kWhite, 2),
                                hit(0.9, kWhite, kYellow), hit(1.2, kWhite, kRed)});
  EXPECT_TRUE(same.ruling.carom->point);
  // Cushions after the second ball do not count.
  const Outcome late = rule(s, {hit(0.5, kWhite, kRed), rail(0.9, kWhite), rail(1.3, kWhite),
                                hit(1.6, kWhite, kYellow), rail(1.8, kWhite), rail(2.0, kWhite)});
  EXPECT_FALSE(late.ruling.carom->point);
  EXPECT_EQ(late.ruling.carom->cushions, 2);
}

TEST(ThreeCushion, AMissWithOnlyTwoCushionsEndsTheInning) {
  const GameState s = open_table();
  const Outcome o = rule(s, {hit(0.5, kWhite, kRed), rail(0.9, kWhite), rail(1.3, kWhite),
                             hit(2.0, kWhite, kYellow)});
  EXPECT_FALSE(o.ruling.carom->point);
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.carom->innings, (std::array<int, 2>{1, 1}));
  EXPECT_EQ(o.state.innings, 2);
  EXPECT_EQ(o.state.carom->score, (std::array<int, 2>{0, 0}));
  EXPECT_NE(o.ruling.text.find("Fewer than three cushions"), std::string::npos) << o.ruling.text;
  // The next player strikes the yellow.
  EXPECT_EQ(rules().cue_ball(o.state), kYellow);
}

TEST(ThreeCushion, CushionsBetweenTheBallsCount) {
  // One cushion, the red, two cushions, the yellow: three before the second.
  const GameState s = open_table();
  const Outcome o = rule(s, {rail(0.2, kWhite), hit(0.5, kWhite, kRed), rail(0.9, kWhite),
                             rail(1.3, kWhite), hit(2.0, kWhite, kYellow)});
  EXPECT_TRUE(o.ruling.carom->point);
  EXPECT_EQ(o.ruling.carom->cushions, 3);
}

TEST(ThreeCushion, KissesAndContactsAgain) {
  const GameState s = open_table();
  // The red kisses the yellow before the white comes: the white's own
  // contact with the yellow still scores.
  const Outcome kiss = rule(s, {hit(0.5, kWhite, kRed), hit(0.7, kRed, kYellow), rail(0.9, kWhite),
                                rail(1.3, kWhite), rail(1.6, kWhite), hit(2.0, kWhite, kYellow)});
  EXPECT_TRUE(kiss.ruling.carom->point);
  EXPECT_TRUE(kiss.ruling.carom->kiss);
  EXPECT_NE(kiss.ruling.text.find("kiss"), std::string::npos) << kiss.ruling.text;
  // A kiss that sends the second ball away: the white touches one ball.
  const Outcome away = rule(s, {hit(0.5, kWhite, kRed), hit(0.7, kRed, kYellow),
                                rail(0.9, kWhite), rail(1.3, kWhite), rail(1.6, kWhite)});
  EXPECT_FALSE(away.ruling.carom->point);
  EXPECT_EQ(away.ruling.carom->hit, std::vector<int>{kRed});
  // The first ball met twice is still one ball: the second comes later.
  const Outcome twice =
      rule(s, {hit(0.5, kWhite, kRed), rail(0.9, kWhite), hit(1.0, kWhite, kRed),
               rail(1.3, kWhite), rail(1.6, kWhite), hit(2.0, kWhite, kYellow)});
  EXPECT_TRUE(twice.ruling.carom->point);
  // An object ball coming back onto the white is a contact too.
  const Outcome back = rule(s, {rail(0.2, kWhite), rail(0.4, kWhite), rail(0.6, kWhite),
                                hit(0.9, kWhite, kRed), hit(1.5, kYellow, kWhite)});
  EXPECT_TRUE(back.ruling.carom->point);
}

// The count itself (carom_count): the rules' ruling and the page's count
// while a shot runs come from it, over all of a shot's events or over the
// first of them.
TEST(ThreeCushion, TheCountAsTheBallGoes) {
  const std::vector<Event> ev = {
      strike(kWhite),    rail(0.2, kWhite), hit(0.5, kWhite, kRed),    hit(0.6, kRed, kYellow),
      rail(0.9, kWhite), rail(1.3, kWhite), hit(2.0, kWhite, kYellow), rail(2.2, kWhite)};
  const std::vector<int> hits[] = {{},     {},     {kRed},          {kRed},
                                   {kRed}, {kRed}, {kRed, kYellow}, {kRed, kYellow}};
  const int cushions[] = {0, 1, 1, 1, 2, 3, 3, 3};
  for (std::size_t n = 0; n <= ev.size(); ++n) {
    const CaromCount c = carom_count(
        std::vector<Event>(ev.begin(), ev.begin() + static_cast<std::ptrdiff_t>(n)), kWhite);
    const std::size_t k = n == 0 ? 0 : n - 1;
    EXPECT_EQ(c.hit, n == 0 ? std::vector<int>{} : hits[k]) << n;
    EXPECT_EQ(c.cushions, n == 0 ? 0 : cushions[k]) << n;
    EXPECT_EQ(c.done(), n >= 7) << n;
    EXPECT_EQ(c.made(), n >= 7) << n;
    EXPECT_EQ(c.kiss, n >= 4) << n;
  }
  const CaromCount all = carom_count(ev, kWhite);
  EXPECT_EQ(all.first_contact, 0.5);
  // The ruling is the count's.
  const Outcome o = rule(open_table(), ev);
  EXPECT_EQ(o.ruling.carom->hit, all.hit);
  EXPECT_EQ(o.ruling.carom->cushions, all.cushions);
  EXPECT_EQ(o.ruling.carom->point, all.made());
  // Two cushions before the second ball: done, not made; the yellow's
  // count knows none of the white's.
  const CaromCount two = carom_count(
      {hit(0.5, kWhite, kRed), rail(0.9, kWhite), rail(1.3, kWhite), hit(2.0, kWhite, kYellow)},
      kWhite);
  EXPECT_TRUE(two.done());
  EXPECT_FALSE(two.made());
  EXPECT_EQ(carom_count(ev, kYellow).cushions, 0);
}

TEST(ThreeCushion, NoContactIsNoPointNotAFoul) {
  const GameState s = open_table();
  const Outcome o = rule(s, {rail(0.5, kWhite), rail(1.0, kWhite)});
  EXPECT_FALSE(o.ruling.carom->point);
  EXPECT_TRUE(o.ruling.fouls.empty());
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_NE(o.ruling.text.find("hits neither ball"), std::string::npos) << o.ruling.text;
}

TEST(ThreeCushion, FoulsEndTheInningWithoutAPoint) {
  const GameState s = open_table();
  const std::vector<Event> scoring{hit(0.5, kWhite, kRed), rail(0.9, kWhite), rail(1.3, kWhite),
                                   rail(1.8, kWhite), hit(2.4, kWhite, kYellow)};
  // A ball off the table: the point does not count; the red goes back on
  // the top spot.
  std::vector<Event> ev = scoring;
  ev.push_back(off(2.6, kRed));
  std::vector<Vec2> rest = s.position;
  rest[kRed] = {9.0, 9.0};  // unused: the ball left the table
  const Outcome o = rule(s, ev, shoot(), rest);
  EXPECT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::ball_off_table});
  EXPECT_FALSE(o.ruling.carom->point);
  EXPECT_FALSE(o.ruling.turn_continues);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.carom->score, (std::array<int, 2>{0, 0}));
  EXPECT_TRUE(o.state.on_table[kRed]);
  EXPECT_EQ(o.state.position[kRed], carom_marks().top_spot);
  EXPECT_EQ(o.ruling.spotted, std::vector<int>{kRed});
  // The offender's own ball off: it is the incoming player's object ball
  // now, on the centre spot; the incoming player's ball off goes to the
  // bottom spot.
  const Outcome own = rule(s, {hit(0.5, kWhite, kRed), off(0.8, kWhite)}, shoot(), rest);
  EXPECT_EQ(own.state.position[kWhite], carom_marks().centre_spot);
  const Outcome theirs = rule(s, {hit(0.5, kWhite, kYellow), off(0.8, kYellow)}, shoot(), rest);
  EXPECT_EQ(theirs.state.position[kYellow], carom_marks().bottom_spot);
  // A spot taken: the ball goes on the spot of the ball that takes it.
  GameState busy = s;
  busy.position[kYellow] = carom_marks().top_spot + Vec2{0.01, 0.0};
  std::vector<Vec2> rest2 = busy.position;
  const Outcome moved = rule(busy, {hit(0.5, kWhite, kRed), off(0.8, kRed)}, shoot(), rest2);
  EXPECT_EQ(moved.state.position[kRed], carom_marks().bottom_spot);

  // The wrong cue ball: the yellow struck by the player of the white.
  Shoot wrong = shoot();
  wrong.cue_ball = kYellow;
  const Outcome w = rule(s, {hit(0.5, kYellow, kRed), rail(0.9, kYellow), rail(1.3, kYellow),
                             rail(1.8, kYellow), hit(2.4, kYellow, kWhite)},
                         wrong);
  EXPECT_EQ(w.ruling.fouls, std::vector<Foul>{Foul::wrong_cue_ball});
  EXPECT_FALSE(w.ruling.carom->point);
  EXPECT_EQ(w.ruling.carom->cue_ball, kYellow);
  EXPECT_FALSE(w.ruling.turn_continues);

  // A push: the white meets the red while the tip could still be on it.
  const Outcome push = rule(s, {strike(kWhite), hit(0.0004, kWhite, kRed), rail(0.9, kWhite),
                                rail(1.3, kWhite), rail(1.8, kWhite), hit(2.4, kWhite, kYellow)});
  EXPECT_EQ(push.ruling.fouls, std::vector<Foul>{Foul::push_through});
  EXPECT_FALSE(push.ruling.carom->point);
  EXPECT_NE(push.ruling.text.find("Foul: a push-through. No point."), std::string::npos)
      << push.ruling.text;
}

TEST(ThreeCushion, TheBreakMustTakeTheRedDirectly) {
  const GameState s = rules().start(1, 0);
  const Outcome direct = rule(s, {hit(0.5, kWhite, kRed), rail(0.9, kWhite)});
  EXPECT_TRUE(direct.ruling.fouls.empty());
  const Outcome yellow = rule(s, {hit(0.1, kWhite, kYellow), rail(0.9, kWhite)});
  EXPECT_EQ(yellow.ruling.fouls, std::vector<Foul>{Foul::wrong_ball_first});
  const Outcome banked = rule(s, {rail(0.3, kWhite), hit(0.9, kWhite, kRed)});
  EXPECT_EQ(banked.ruling.fouls, std::vector<Foul>{Foul::wrong_ball_first});
  EXPECT_EQ(banked.state.player, 1);
  EXPECT_EQ(banked.state.phase, Phase::shot);
  // After the break either ball may come first.
  EXPECT_EQ(rules().legal_actions(open_table()).targets, (std::vector<int>{kYellow, kRed}));
  EXPECT_EQ(rules().legal_actions(open_table(1)).targets, (std::vector<int>{kWhite, kRed}));
}

TEST(ThreeCushion, ShotsTheGameRefuses) {
  const GameState s = open_table();
  Shoot sh = shoot();
  sh.call = Call{kRed, 0};
  EXPECT_TRUE(rules().check(s, sh));
  sh = shoot();
  sh.nominate = kRed;
  EXPECT_TRUE(rules().check(s, sh));
  sh = shoot();
  sh.cue_ball = 3;
  EXPECT_TRUE(rules().check(s, sh));
  EXPECT_TRUE(rules().check(s, Decide{Choice::play_on}));
  EXPECT_TRUE(rules().check(s, PlaceCueBall{{1.0, 0.5}}));
  // Naming the cue ball is three-cushion's only.
  const Rules pool(GameConfig{});
  Shoot named = shoot();
  named.cue_ball = 0;
  EXPECT_TRUE(pool.check(pool.start(1, 0), named));
}

TEST(ThreeCushion, BallsInContactAreSpotted) {
  // The white comes to rest against the red and the inning goes on: the
  // white goes to the bottom spot, the red to the top spot.
  const GameState s = open_table();
  std::vector<Vec2> rest = s.position;
  rest[kWhite] = {1.2, 0.7};
  rest[kRed] = {1.2 + 2.0 * kR + 0.5e-4, 0.7};
  const Outcome o = rule(s,
                         {hit(0.5, kWhite, kYellow), rail(0.9, kWhite), rail(1.3, kWhite),
                          rail(1.8, kWhite), hit(2.4, kWhite, kRed)},
                         shoot(), rest);
  EXPECT_TRUE(o.ruling.carom->point);
  EXPECT_EQ(o.state.position[kWhite], carom_marks().bottom_spot);
  EXPECT_EQ(o.state.position[kRed], carom_marks().top_spot);
  EXPECT_NE(o.ruling.text.find("touches the red"), std::string::npos) << o.ruling.text;
  // Against the other cue ball after a miss: the next player's yellow to
  // the bottom spot, the white to the centre spot.
  rest = s.position;
  rest[kYellow] = {2.0, 0.3};
  rest[kWhite] = {2.0, 0.3 + 2.0 * kR};
  const Outcome m = rule(s, {hit(0.5, kWhite, kYellow)}, shoot(), rest);
  EXPECT_EQ(m.state.player, 1);
  EXPECT_EQ(m.state.position[kYellow], carom_marks().bottom_spot);
  EXPECT_EQ(m.state.position[kWhite], carom_marks().centre_spot);
}

TEST(ThreeCushion, TheTargetAndTheEqualizingInning) {
  const std::vector<Event> scoring{hit(0.5, kWhite, kRed), rail(0.9, kWhite), rail(1.3, kWhite),
                                   rail(1.8, kWhite), hit(2.4, kWhite, kYellow)};
  std::vector<Event> scoring_yellow;
  for (Event e : scoring) {
    if (e.ball == kWhite && e.type == EventType::ball_cushion) e.ball = kYellow;
    if (e.type == EventType::ball_ball) {
      const int o = e.ball == kWhite ? e.other : e.ball;
      const int other = o == kYellow ? kWhite : o;
      e.ball = std::min(kYellow, other);
      e.other = std::max(kYellow, other);
    }
    scoring_yellow.push_back(e);
  }
  const std::vector<Event> miss{rail(0.5, kWhite)};
  const std::vector<Event> miss_yellow{rail(0.5, kYellow)};

  // The breaker reaches 40: the other player has the equalizing inning.
  GameState s = open_table();
  s.carom->score = {39, 36};
  s.carom->innings = {20, 19};
  Outcome o = rule(s, scoring);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.carom->score, (std::array<int, 2>{40, 36}));
  EXPECT_TRUE(o.state.carom->equalizing);
  EXPECT_EQ(o.state.player, 1);
  EXPECT_EQ(o.state.carom->innings, (std::array<int, 2>{20, 20}));
  EXPECT_NE(o.ruling.text.find("equalizing inning"), std::string::npos) << o.ruling.text;
  // ... who misses: the breaker wins.
  GameState eq = o.state;
  Outcome lost = rule(eq, miss_yellow);
  EXPECT_EQ(lost.state.phase, Phase::game_over);
  EXPECT_EQ(lost.state.winner, 0);
  EXPECT_EQ(lost.ruling.winner, 0);
  // ... or runs out to 40: a draw.
  eq.carom->score = {40, 39};
  Outcome draw = rule(eq, scoring_yellow);
  EXPECT_EQ(draw.state.phase, Phase::game_over);
  EXPECT_EQ(draw.state.winner, -1);
  EXPECT_EQ(draw.state.carom->score, (std::array<int, 2>{40, 40}));
  EXPECT_NE(draw.state.result.find("drawn"), std::string::npos) << draw.state.result;

  // Without the equalizing inning the breaker wins at once.
  const Rules plain = rules_with(CaromRules{40, 50, false});
  Outcome at_once = rule(s, scoring, shoot(), {}, plain);
  EXPECT_EQ(at_once.state.phase, Phase::game_over);
  EXPECT_EQ(at_once.state.winner, 0);

  // The other player reaching the target first wins at once.
  GameState y = open_table(1);
  y.carom->score = {30, 39};
  Outcome won = rule(y, scoring_yellow);
  EXPECT_EQ(won.state.phase, Phase::game_over);
  EXPECT_EQ(won.state.winner, 1);
  EXPECT_NE(won.state.result.find("Player 2 wins 40-30"), std::string::npos) << won.state.result;

  // Another target.
  const Rules short_game = rules_with(CaromRules{3, 0, false});
  GameState t = open_table();
  t.carom->score = {2, 0};
  EXPECT_EQ(rule(t, scoring, shoot(), {}, short_game).state.winner, 0);
}

TEST(ThreeCushion, TheInningsLimit) {
  const std::vector<Event> miss_yellow{rail(0.5, kYellow)};
  const std::vector<Event> miss{rail(0.5, kWhite)};
  // The breaker's 50th inning ends: the other player still has one.
  GameState s = open_table();
  s.carom->score = {12, 15};
  s.carom->innings = {50, 49};
  Outcome o = rule(s, miss);
  EXPECT_EQ(o.state.phase, Phase::shot);
  EXPECT_EQ(o.state.carom->innings, (std::array<int, 2>{50, 50}));
  // The other player's 50th ends the game: the higher score wins.
  Outcome end = rule(o.state, miss_yellow);
  EXPECT_EQ(end.state.phase, Phase::game_over);
  EXPECT_EQ(end.state.winner, 1);
  EXPECT_NE(end.ruling.text.find("innings limit (50)"), std::string::npos) << end.ruling.text;
  // Equal scores draw.
  GameState eq = o.state;
  eq.carom->score = {15, 15};
  EXPECT_EQ(rule(eq, miss_yellow).state.winner, -1);
  // No limit: the game goes on.
  const Rules open = rules_with(CaromRules{40, 0, true});
  EXPECT_EQ(rule(o.state, miss_yellow, shoot(), {}, open).state.phase, Phase::shot);
}

// Real shots on the carom table: turning the aim from a hand-placed table
// finds a shot for each clause, and the ruling agrees with the events.
TEST(ThreeCushion, RealShots) {
  const Rules& r = rules();
  const GameState s = table({0.6, 0.5}, {2.2, 1.0}, {1.6, 0.35});
  bool point = false;
  bool two_only = false;
  bool one_ball = false;
  bool kiss = false;
  for (int k = 0; k < 720 && !(point && two_only && one_ball && kiss); ++k) {
    const double phi = k * 0.5;
    for (const double speed : {3.0, 5.0}) {
      const Outcome o = r.apply(s, shoot(phi, speed));
      ASSERT_TRUE(o.ruling.carom);
      const CaromRuling& c = *o.ruling.carom;
      // The cushions counted from the events, independently.
      int rails = 0;
      std::vector<int> met;
      for (const Event& e : o.events) {
        if (met.size() < 2 && e.type == EventType::ball_cushion && e.ball == kWhite) ++rails;
        if (e.type == EventType::ball_ball && (e.ball == kWhite || e.other == kWhite)) {
          const int b = e.ball == kWhite ? e.other : e.ball;
          if (std::find(met.begin(), met.end(), b) == met.end()) met.push_back(b);
        }
      }
      EXPECT_EQ(c.hit, met);
      EXPECT_EQ(c.cushions, rails);
      EXPECT_EQ(c.point, o.ruling.fouls.empty() && met.size() == 2 && rails >= 3);
      EXPECT_EQ(o.ruling.turn_continues, c.point);
      EXPECT_EQ(o.state.carom->score[0], c.point ? 1 : 0);
      point = point || c.point;
      two_only = two_only || (met.size() == 2 && rails < 3);
      one_ball = one_ball || met.size() == 1;
      kiss = kiss || c.kiss;
    }
  }
  EXPECT_TRUE(point);
  EXPECT_TRUE(two_only);
  EXPECT_TRUE(one_ball);
  EXPECT_TRUE(kiss);
}

// Whole games between baseline players end (the innings limit, the
// target), the scores follow the rulings, and the records replay exactly.
TEST(ThreeCushion, WholeGamesBetweenBaselinePlayers) {
  auto p0 = make_player("baseline");
  auto p1 = make_player("baseline");
  const Rules limited = rules_with(CaromRules{40, 10, true});
  const Rules short_game = rules_with(CaromRules{2, 0, true});
  const char* levels[] = {"tournament", "none", "5x"};
  for (int g = 0; g < 6; ++g) {
    const Rules& r = g % 2 == 0 ? limited : short_game;
    const GameRecord rec = play_game(r, *p0, *p1, g % 2, mix_seed(31, static_cast<std::uint64_t>(g)),
                                     parse_noise(levels[g % 3]));
    ASSERT_FALSE(rec.actions.empty());
    const GameState& end = rec.actions.back().after;
    EXPECT_EQ(end.phase, Phase::game_over);
    std::array<int, 2> score{0, 0};
    for (const RecordedAction& ra : rec.actions) {
      ASSERT_TRUE(std::holds_alternative<Shoot>(ra.action));
      ASSERT_TRUE(ra.ruling.carom);
      if (ra.ruling.carom->point) score[static_cast<std::size_t>(ra.player)] += 1;
    }
    EXPECT_EQ(end.carom->score, score);
    if (g % 2 == 0) {
      EXPECT_LE(end.carom->innings[0], 10);
      EXPECT_LE(end.carom->innings[1], 10);
    } else {
      EXPECT_TRUE(score[0] >= 2 || score[1] >= 2);
    }
    const std::string text = write_record(rec);
    const auto read = read_record(text);
    ASSERT_TRUE(std::holds_alternative<GameRecord>(read));
    const ReplayReport rep = replay(std::get<GameRecord>(read));
    EXPECT_TRUE(rep.identical) << "game " << g << ": " << rep.message;
    EXPECT_EQ(write_record(std::get<GameRecord>(read)), text);
  }
}

// Every player plays the game: the baseline and the AI levels.
TEST(ThreeCushion, WhoPlaysIt) {
  EXPECT_EQ(player_names(GameType::three_cushion), player_names());
  for (const std::string& name : player_names()) {
    EXPECT_FALSE(check_player(name, GameType::three_cushion)) << name;
  }
}

// The match summary: points, general average, highest run, fouls by
// three-cushion's kinds; its JSON reads back and sums in chunks.
TEST(ThreeCushion, MatchSummary) {
  MatchOptions opt;
  opt.game = GameType::three_cushion;
  opt.table_size = "10ft";
  opt.carom = CaromRules{5, 8, true};
  opt.players = {"baseline", "baseline"};
  opt.games = 3;
  opt.seed = 4;
  opt.noise = parse_noise("tournament");
  std::vector<GameRecord> records;
  const MatchSummary s =
      play_match(opt, [&](int, const GameRecord& rec) { records.push_back(rec); });
  ASSERT_EQ(records.size(), 3u);
  std::array<int, 2> points{0, 0};
  for (const GameRecord& rec : records) {
    for (std::size_t p = 0; p < 2; ++p) points[p] += rec.actions.back().after.carom->score[p];
  }
  for (std::size_t p = 0; p < 2; ++p) {
    const PlayerStats& st = s.players[p];
    ASSERT_TRUE(st.carom);
    EXPECT_FALSE(st.snooker);
    EXPECT_EQ(st.carom->points, points[p]);
    EXPECT_EQ(st.balls_pocketed, 0);
    EXPECT_LE(st.carom->highest_run, 5);
    EXPECT_LE(st.carom->scoring_innings, st.innings);
    EXPECT_DOUBLE_EQ(st.general_average(),
                     st.innings > 0 ? static_cast<double>(points[p]) / st.innings : 0.0);
    EXPECT_TRUE(st.fouls.count("push_through"));
    EXPECT_TRUE(st.fouls.count("wrong_cue_ball"));
    EXPECT_FALSE(st.fouls.count("scratch"));
  }
  EXPECT_EQ(s.players[0].games_won + s.players[1].games_won + s.draws, 3);
  const std::string text = match_summary_json(s);
  EXPECT_NE(text.find("\"general_average\""), std::string::npos);
  EXPECT_NE(text.find("\"carom\": {\n    \"target\": 5"), std::string::npos) << text;
  const MatchSummary back = read_match_summary(text);
  EXPECT_EQ(match_summary_json(back), text);

  // Chunks add up to the whole match.
  MatchOptions a = opt;
  a.games = 1;
  MatchOptions b = opt;
  b.first_game = 1;
  b.games = 2;
  MatchSummary sum = play_match(a);
  add_summary(sum, play_match(b));
  EXPECT_EQ(match_summary_json(sum), text);
  // Another target is another match.
  MatchOptions c = b;
  c.carom.target = 6;
  MatchSummary other = play_match(a);
  EXPECT_THROW(add_summary(other, play_match(c)), std::invalid_argument);
}

// The innings of a record (carom_innings): a run goes on while the turn
// continues, and ends with a miss, a foul or the game.
TEST(ThreeCushion, TheInningsOfARecord) {
  GameRecord rec;
  const auto shot = [&](int player, bool point, bool more, bool over = false) {
    RecordedAction ra;
    ra.player = player;
    ra.action = Shoot{};
    ra.ruling.carom = CaromRuling{};
    ra.ruling.carom->point = point;
    ra.ruling.turn_continues = more;
    ra.after.phase = over ? Phase::game_over : Phase::shot;
    rec.actions.push_back(ra);
  };
  shot(0, true, true);
  shot(0, true, true);
  shot(0, false, false);  // a run of 2
  shot(1, false, false);  // nothing
  shot(0, true, true);
  shot(0, true, true);
  shot(0, true, true);        // 3, still going ...
  shot(0, true, true, true);  // ... and the game ends on a 4
  EXPECT_EQ(carom_innings(rec), (std::vector<CaromInning>{{0, 2}, {1, 0}, {0, 4}}));
  // An inning in progress is one too; a placement is no shot.
  rec.actions.resize(5);
  RecordedAction place;
  place.player = 0;
  place.action = PlaceCueBall{};
  rec.actions.push_back(place);
  EXPECT_EQ(carom_innings(rec), (std::vector<CaromInning>{{0, 2}, {1, 0}, {0, 1}}));
  EXPECT_TRUE(carom_innings(GameRecord{}).empty());
}

// The JSON of three-cushion's parts: written only in three-cushion, read
// back to the same values, refused in the other games.
TEST(ThreeCushion, JsonOfStateRulingAndAction) {
  const GameState s = open_table();
  Shoot wrong = shoot(12.5, 4.0);
  wrong.cue_ball = kRed;
  const Outcome o = rule(s, {hit(0.5, kRed, kYellow), rail(0.9, kRed)}, wrong);
  const json_io::ojson st = json_io::state_json(o.state);
  const json_io::ojson ru = json_io::ruling_json(o.ruling);
  const json_io::ojson ac = json_io::action_json(wrong);
  EXPECT_EQ(st["carom"]["innings"], json_io::ojson::array({1, 1}));
  EXPECT_EQ(ru["carom"]["cue_ball"], kRed);
  EXPECT_EQ(ac["cue_ball"], kRed);
  EXPECT_FALSE(json_io::state_json(GameState{}).contains("carom"));
  EXPECT_FALSE(json_io::action_json(shoot()).contains("cue_ball"));
  json_io::GameReader reader;
  reader.game_context = GameType::three_cushion;
  GameState s2;
  Ruling r2;
  Action a2;
  ASSERT_TRUE(reader.state(nlohmann::json::parse(st.dump()), "s", s2)) << reader.error->reason;
  ASSERT_TRUE(reader.ruling(nlohmann::json::parse(ru.dump()), "r", r2)) << reader.error->reason;
  ASSERT_TRUE(reader.action(nlohmann::json::parse(ac.dump()), "a", a2)) << reader.error->reason;
  EXPECT_EQ(s2, o.state);
  EXPECT_EQ(r2, o.ruling);
  EXPECT_EQ(std::get<Shoot>(a2), wrong);
  json_io::GameReader pool;
  pool.game_context = GameType::nine_ball;
  Ruling r3;
  EXPECT_FALSE(pool.ruling(nlohmann::json::parse(ru.dump()), "r", r3));
  EXPECT_NE(pool.error->reason.find("only three-cushion rulings"), std::string::npos);
}

}  // namespace test_rules_carom

// The AI player (include/breakshot/ai.hpp) on hand-placed tables and in
// whole games: its actions are always legal, it pots what is there (a
// ball along a rail, one hanging in the jaws), finds a bank when every
// direct pot is blocked, plays safe when nothing is makeable, places the
// cue ball legally, and decides the same for a seed and a simulation
// budget whatever the number of threads. Small levels
// and budgets keep each test to a few seconds even under the sanitizers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "ai/evaluate.hpp"
#include "breakshot/players.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "ai_fixtures.hpp"
#include "rules_fixtures.hpp"

namespace test_ai {

namespace {

using namespace rules_fixtures;

using ai_fixtures::small_level;

Action decide_legal(Player& player, const Rules& rules, const GameState& s,
                    std::uint64_t seed = 1) {
  const Action a = player.decide(rules, s, seed);
  const std::optional<std::string> why = rules.check(s, a);
  EXPECT_FALSE(why.has_value()) << why.value_or("");
  return a;
}

int pocket_of(const ShotFacts& f, int ball) {
  for (std::size_t i = 0; i < f.pocketed.size(); ++i) {
    if (f.pocketed[i] == ball) return f.pocket_of[i];
  }
  return -1;
}

Vec2 at(Vec2 centre, double deg, double dist) {
  const double a = deg * kPi / 180.0;
  return centre + Vec2{std::cos(a), std::sin(a)} * dist;
}

// ---------------------------------------------------------------------------

TEST(AiLevels, EveryNameResolvesAndMakePlayerAcceptsIt) {
  const std::vector<std::string> names = ai_level_names();
  ASSERT_EQ(names, (std::vector<std::string>{"beginner", "amateur", "club", "expert", "champion"}));
  for (const std::string& n : names) {
    const AiLevel l = ai_level(n);
    EXPECT_EQ(l.name, n);
    const auto p = make_player(n);
    EXPECT_EQ(p->name(), n);
    ASSERT_TRUE(p->noise().has_value());
    EXPECT_EQ(*p->noise(), l.noise);
    EXPECT_EQ(make_ai_player(l)->name(), n);
  }
  EXPECT_EQ(ai_level("beginner").noise, parse_noise("4x"));
  EXPECT_EQ(ai_level("champion").noise, parse_noise("tournament"));
  EXPECT_TRUE(ai_level("champion").lookahead);
  EXPECT_FALSE(make_player("baseline")->noise().has_value());
}

TEST(AiLevels, UnknownNamesAreRefusedWithTheKnownOnes) {
  try {
    ai_level("shark");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("shark"), std::string::npos) << msg;
    EXPECT_NE(msg.find("champion"), std::string::npos) << msg;
  }
  try {
    make_player("shark");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("baseline"), std::string::npos) << msg;
    EXPECT_NE(msg.find("beginner"), std::string::npos) << msg;
    EXPECT_NE(msg.find("champion"), std::string::npos) << msg;
  }
}

TEST(AiShotKind, Names) {
  EXPECT_EQ(to_string(ShotKind::direct), "direct");
  EXPECT_EQ(to_string(ShotKind::bank), "bank");
  EXPECT_EQ(to_string(ShotKind::kick), "kick");
  EXPECT_EQ(to_string(ShotKind::combination), "combination");
  EXPECT_EQ(to_string(ShotKind::safety), "safety");
  EXPECT_EQ(to_string(ShotKind::break_shot), "break_shot");
  EXPECT_EQ(to_string(ShotKind::jump), "jump");
}

TEST(AiPlayer, PotsAStraightInBall) {
  const Rules rules = eight_ball_rules();
  const int pocket = pocket_index(rules, "bottom_right");
  const StraightIn si =
      straight_in(rules, pocket, {rules.table().length / 2, rules.table().width / 2}, 0.45, 0.35);
  GameState s = bare_table(rules, si.cue);
  put(s, 3, si.object);
  put(s, 8, {0.5, 1.0});
  put(s, 12, {0.3, 0.9});
  for (const std::string level : {"beginner", "expert"}) {
    AiLevel l = level == "beginner" ? ai_level(level) : small_level(level);
    const auto player = make_ai_player(l);
    const Action a = decide_legal(*player, rules, s);
    ASSERT_TRUE(std::holds_alternative<Shoot>(a)) << level;
    const Shoot& shot = std::get<Shoot>(a);
    ASSERT_TRUE(shot.call.has_value()) << level;
    EXPECT_EQ(shot.call->ball, 3) << level;
    const Outcome out = rules.apply(s, a);  // as intended, without noise
    EXPECT_GE(pocket_of(out.facts, 3), 0) << level;
    EXPECT_TRUE(out.ruling.fouls.empty()) << level << ": " << out.ruling.text;
    EXPECT_TRUE(out.ruling.turn_continues) << level << ": " << out.ruling.text;
  }
}

TEST(AiPlayer, NineBallPotsCarryAnInformationalCall) {
  // 9-ball: the rules ignore a call, but the AI makes one on its pots so
  // that the match can count its pot attempts.
  const Rules rules = nine_ball_rules();
  const int pocket = pocket_index(rules, "bottom_right");
  const StraightIn si =
      straight_in(rules, pocket, {rules.table().length / 2, rules.table().width / 2}, 0.45, 0.35);
  GameState s = bare_table(rules, si.cue);
  put(s, 1, si.object);
  put(s, 9, {0.5, 1.0});
  const auto player = make_ai_player(small_level());
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  ASSERT_TRUE(shot.call.has_value());
  EXPECT_EQ(shot.call->ball, 1);
  EXPECT_EQ(shot.call->pocket, pocket);
  const Outcome out = rules.apply(s, a);
  EXPECT_TRUE(out.ruling.call_made) << out.ruling.text;
}

TEST(AiExpectedPot, HalfTheSamplesMustPotTheSameBallInTheSamePocket) {
  using ai_detail::expected_pot;
  const Call a{1, 2};
  const Call b{1, 3};
  const Call c{4, 2};
  // 5 of 10 plays pot the 1 in pocket 2: that is the pot expected.
  EXPECT_EQ(expected_pot({b, a, a, c, a, a, a}, 10), a);
  // 4 of 10: not enough, though it is the most common.
  EXPECT_EQ(expected_pot({a, a, a, a, b, c}, 10), std::nullopt);
  // The same ball in different pockets does not add up.
  EXPECT_EQ(expected_pot({a, a, a, b, b, b}, 10), std::nullopt);
  EXPECT_EQ(expected_pot({}, 10), std::nullopt);
  EXPECT_EQ(expected_pot({a}, 0), std::nullopt);
  EXPECT_EQ(expected_pot({c, c, c}, 3), c);
}

TEST(AiCentreAim, AStraightInPotAlongTheBisectorIsAimedStraight) {
  // A corner pot straight down the pocket's bisector, centre ball: the
  // corner is its own mirror image about that line, so the aims that pot
  // the ball lie symmetrically about the straight aim. An aim a quarter
  // of a degree off it that still pots is brought back to it.
  const Rules rules = eight_ball_rules();
  const int pocket = pocket_index(rules, "bottom_right");
  const Vec2 c = pocket_centre(rules, pocket);
  const StraightIn si = straight_in(rules, pocket, c + Vec2{-1.0, 1.0}, 0.5, 0.4);
  GameState s = bare_table(rules, si.cue);
  put(s, 3, si.object);
  put(s, 12, {0.4, 0.9});
  const double straight = std::atan2(si.object.y - si.cue.y, si.object.x - si.cue.x) * 180.0 / kPi;
  Shoot shot;
  shot.strike.speed = 2.0;
  shot.strike.phi = straight + 0.25;
  shot.call = Call{3, pocket};
  ASSERT_TRUE(rules.apply(s, Action{shot}).ruling.call_made);
  const Shoot centred = ai_detail::centre_aim(rules, s, shot);
  EXPECT_NEAR(centred.strike.phi, straight, 0.03);
  EXPECT_TRUE(rules.apply(s, Action{centred}).ruling.call_made);
  // Only the aim moves.
  Shoot same = centred;
  same.strike.phi = shot.strike.phi;
  EXPECT_EQ(same, shot);
  // A shot that does not pot, or has no call, is left alone.
  Shoot wide = shot;
  wide.strike.phi = straight + 20.0;
  ASSERT_FALSE(rules.apply(s, Action{wide}).ruling.call_made);
  EXPECT_EQ(ai_detail::centre_aim(rules, s, wide), wide);
  Shoot uncalled = shot;
  uncalled.call.reset();
  EXPECT_EQ(ai_detail::centre_aim(rules, s, uncalled), uncalled);
}

TEST(AiPlayer, FindsTheBankWhenEveryDirectPotIsBlocked) {
  // 9-ball: the 1 with a blocker on its line to every pocket (hitting a
  // blocker first is a foul, so no combination either); the way out is
  // off the top rail.
  const Rules rules = nine_ball_rules();
  const Vec2 one{1.6, 0.9};
  GameState s = bare_table(rules, at(one, 240.0, 0.12));
  put(s, 1, one);
  int blocker = 2;
  for (const Pocket& pk : rules.table().pockets) {
    put(s, blocker++, one + unit(pk.centre - one) * 0.3);
  }
  // No direct pot exists.
  for (const CandidateShot& c : generate_shots(rules, s, ShotGenOptions{})) {
    EXPECT_NE(c.kind, ShotKind::direct);
  }
  const auto player = make_ai_player(small_level());
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(out.facts.first_hit, 1);
  EXPECT_GE(pocket_of(out.facts, 1), 0) << out.ruling.text;
  EXPECT_TRUE(out.ruling.turn_continues) << out.ruling.text;
}

// The table was laid out on breakshot 0.1's physics with balls that may
// leave the cloth (rules_fixtures.hpp says why the fixtures keep it).
Rules nine_ball_airborne(bool airborne) {
  GameConfig c;
  c.game = GameType::nine_ball;
  c.physics = kLegacyGamePhysics;
  c.physics.airborne = airborne;
  return Rules(c);
}

/// 9-ball: the 1 0.35 m out of the bottom-right corner, the cue ball
/// 0.7 m from its ghost ball for a 15 degree cut, and the 2 on the cue
/// ball's path 0.25 m in front of it; with `blocker` false the 2 is left
/// off and the line is open.
GameState jump_table(const Rules& rules, bool blocker) {
  const int pocket = pocket_index(rules, "bottom_right");
  const Vec2 c = pocket_centre(rules, pocket);
  const Vec2 out = unit(Vec2{rules.table().length / 2.0, rules.table().width / 2.0} - c);
  const Vec2 one = c + out * 0.35;
  const Vec2 ghost = one + out * (2.0 * kR);
  const Vec2 cue = ghost + at({0.0, 0.0}, std::atan2(out.y, out.x) * 180.0 / kPi - 15.0, 0.7);
  GameState s = bare_table(rules, cue);
  put(s, 1, one);
  if (blocker) put(s, 2, cue + unit(ghost - cue) * 0.25);
  put(s, 9, {0.4, 1.0});
  return s;
}

/// The top level with a smaller search (jumps on, as in the level).
AiLevel small_champion() {
  AiLevel l = ai_level("champion");
  l.candidates = 8;
  l.samples = 16;
  l.lookahead = false;
  l.centre_aim = false;
  l.threads = 1;
  return l;
}

TEST(AiJump, TheTopLevelJumpsTheBallInFrontOfTheCueBall) {
  // The direct pot of the 1 is blocked by the 2 just in front of the cue
  // ball (kicks off a rail are left, none of them easy). With balls that
  // may leave the cloth the champion jumps the 2: an elevated stroke
  // that, played without noise, flies, hits the 1 first and pots it with
  // no foul.
  const Rules rules = nine_ball_airborne(true);
  const GameState s = jump_table(rules, true);
  const auto player = make_ai_player(small_champion());
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Shoot& shot = std::get<Shoot>(a);
  EXPECT_GT(shot.strike.theta, 20.0);
  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(out.facts.first_hit, 1) << describe(out);
  EXPECT_EQ(pocket_of(out.facts, 1), pocket_index(rules, "bottom_right")) << describe(out);
  EXPECT_TRUE(out.ruling.fouls.empty()) << out.ruling.text;
  bool flew = false;
  for (const Event& e : out.events) flew = flew || (e.type == EventType::ball_slate && e.ball == 0);
  EXPECT_TRUE(flew) << describe(out);
}

TEST(AiJump, NoJumpOnTheClothOrBelowTheLevelsThatMayJump) {
  // The same table with balls on the cloth, or a level that does not
  // jump (club): a level stroke, and a legal action.
  for (const bool airborne : {false, true}) {
    const Rules rules = nine_ball_airborne(airborne);
    const GameState s = jump_table(rules, true);
    const auto player = make_ai_player(airborne ? small_level("club") : small_champion());
    const Action a = decide_legal(*player, rules, s);
    ASSERT_TRUE(std::holds_alternative<Shoot>(a)) << airborne;
    EXPECT_EQ(std::get<Shoot>(a).strike.theta, 0.0) << airborne;
  }
  EXPECT_FALSE(ai_level("club").generation.jumps);
  EXPECT_TRUE(ai_level("champion").generation.jumps);
}

TEST(AiJump, AnOpenLineIsPlayedStraight) {
  // Without the 2 the straight pot is open: the champion plays it level,
  // and it pots.
  const Rules rules = nine_ball_airborne(true);
  const GameState s = jump_table(rules, false);
  const auto player = make_ai_player(small_champion());
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  EXPECT_EQ(std::get<Shoot>(a).strike.theta, 0.0);
  const Outcome out = rules.apply(s, a);
  EXPECT_GE(pocket_of(out.facts, 1), 0) << describe(out);
  EXPECT_TRUE(out.ruling.fouls.empty()) << out.ruling.text;
}

TEST(AiPlayer, PlaysASafetyWhenNothingIsMakeable) {
  // The 1 in a ring of others, open only toward the cue ball: no pot.
  const Rules rules = nine_ball_rules();
  const Vec2 one{1.6, 0.6};
  GameState s = bare_table(rules, {0.6, 0.6});
  put(s, 1, one);
  for (int k = 0; k < 6; ++k) {
    if (k == 3) continue;  // the side facing the cue ball
    put(s, 2 + (k > 3 ? k - 1 : k), at(one, 60.0 * k, 2.0 * kR + 0.003));
  }
  put(s, 9, {2.3, 1.1});
  const auto player = make_ai_player(small_level());
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<Shoot>(a));
  const Outcome out = rules.apply(s, a);
  EXPECT_EQ(out.facts.first_hit, 1);
  EXPECT_TRUE(out.ruling.fouls.empty()) << out.ruling.text;
  EXPECT_FALSE(out.ruling.turn_continues) << out.ruling.text;
  // The opponent is left without an easy pot.
  ASSERT_EQ(out.state.player, 1);
  EXPECT_LT(ai_detail::best_pot_estimate(rules, out.state, 0.125), 0.6);
}

// The fast estimate of a table counts a pot only where shot generation
// finds an open line for the object ball past the cushions and jaws. A
// ball 2 cm off the long rail, 0.25 m from the side pocket, cannot go
// straight into that pocket (its line runs into the jaw): none is
// planned, and no aim of a sweep at three speeds pots it there without a
// cushion. A ball 7 cm off the foot rail, 0.38 m from the corner, goes
// into the corner along that rail: its open lines lie to one side of the
// pocket's centre (until 2026-11-23 the planner tried only lines near the
// centre and found none); it is planned and pots under tournament noise.
// Where there is a pot, the chance the estimate gives is the engine's
// chance of the best direct candidate for the ball and pocket it picks,
// sampled under tournament noise, to within 0.2. The estimate is fitted
// to such samples on the tables of recorded games (docs/ai.md), where it
// is right on average; on these open cuts of a bare table it reads 0.11
// to 0.19 below the engine.
TEST(AiEstimate, CountsOnlyPotsWithAnOpenLineAndAgreesWithTheEngine) {
  const Rules rules = nine_ball_rules();
  const NoiseModel noise = parse_noise("tournament");
  {
    const int side = pocket_index(rules, "side_bottom");
    const Vec2 jawed{rules.table().length / 2.0 + 0.25, kR + 0.02};
    GameState s = bare_table(rules, {jawed.x + 0.35, jawed.y + 0.3});
    put(s, 1, jawed);
    for (const CandidateShot& c : generate_shots(rules, s, ShotGenOptions{})) {
      if (c.kind == ShotKind::direct) {
        EXPECT_NE(c.pocket, side) << "a direct pot into the jawed side pocket was planned";
      }
    }
    int hits = 0;
    for (double speed : {1.0, 2.0, 3.5}) {
      for (int k = 0; k < 3600; ++k) {
        Shoot sh;
        sh.strike.speed = speed;
        sh.strike.phi = 0.1 * k;
        const Outcome o = rules.apply(s, Action{sh});
        if (o.facts.first_hit != 1) continue;
        ++hits;
        EXPECT_FALSE(pocket_of(o.facts, 1) == side && o.facts.object_balls_to_cushion == 0)
            << "the engine pots the jawed ball straight into the side at phi " << sh.strike.phi;
      }
    }
    EXPECT_GT(hits, 100);  // the sweep did hit the ball
  }
  {
    const int corner = pocket_index(rules, "top_right");
    const Vec2 railed{rules.table().length - 0.073, rules.table().width - 0.375};
    GameState s = bare_table(rules, {railed.x - 0.108, railed.y - 0.379});
    put(s, 1, railed);
    int planned = 0;
    for (const CandidateShot& c : generate_shots(rules, s, ShotGenOptions{})) {
      if (c.kind != ShotKind::direct || c.pocket != corner) continue;
      ++planned;
      int in = 0;
      for (int k = 0; k < 100; ++k) {
        Shoot sh = c.shot;
        sh.strike = perturb(c.shot.strike, noise, rules.config().ball_radius,
                            mix_seed(5, static_cast<std::uint64_t>(k)));
        in += pocket_of(rules.apply(s, Action{sh}).facts, 1) == corner ? 1 : 0;
      }
      EXPECT_GE(in, 80) << "phi " << c.shot.strike.phi << " speed " << c.shot.strike.speed;
    }
    EXPECT_GT(planned, 0) << "no direct pot along the rail into the corner was planned";
    int best_ball = -1;
    int best_pocket = -1;
    const double p = ai_detail::best_pot_estimate_from(rules, s, s.position[0], false, 0.125,
                                                       &best_ball, &best_pocket);
    EXPECT_GT(p, 0.0);
    EXPECT_EQ(best_pocket, corner);
  }

  // Open cuts at a few distances: the estimate against the engine.
  for (const Vec2 cue : {Vec2{1.2, 0.5}, Vec2{0.7, 0.3}, Vec2{1.6, 0.35}}) {
    GameState t = bare_table(rules, cue);
    put(t, 1, {1.9, 0.9});
    int best_ball = -1;
    int best_pocket = -1;
    const double p = ai_detail::best_pot_estimate_from(rules, t, cue, false, 0.125, &best_ball,
                                                       &best_pocket);
    ASSERT_EQ(best_ball, 1);
    ASSERT_GE(best_pocket, 0);
    double made = 0.0;
    for (const CandidateShot& c : generate_shots(rules, t, ShotGenOptions{})) {
      if (c.kind != ShotKind::direct || c.pocket != best_pocket) continue;
      int in = 0;
      constexpr int kSamples = 100;
      for (int k = 0; k < kSamples; ++k) {
        Shoot sh = c.shot;
        sh.strike = perturb(c.shot.strike, noise, rules.config().ball_radius,
                            mix_seed(5, static_cast<std::uint64_t>(k)));
        const Outcome o = rules.apply(t, Action{sh});
        in += o.ruling.fouls.empty() && pocket_of(o.facts, 1) == best_pocket ? 1 : 0;
      }
      made = std::max(made, static_cast<double>(in) / kSamples);
    }
    EXPECT_NEAR(p, made, 0.2) << "cue at " << cue.x << ", " << cue.y << " pocket " << best_pocket;
  }
}

/// Plays of `c` under tournament noise (100, fixed seeds) that drop
/// `ball` in `pocket` with no foul.
int made_of_100(const Rules& rules, const GameState& s, const CandidateShot& c, int ball,
                int pocket) {
  const NoiseModel noise = parse_noise("tournament");
  int in = 0;
  for (int k = 0; k < 100; ++k) {
    Shoot sh = c.shot;
    sh.strike = perturb(c.shot.strike, noise, rules.config().ball_radius,
                        mix_seed(5, static_cast<std::uint64_t>(k)));
    const Outcome o = rules.apply(s, Action{sh});
    in += o.ruling.fouls.empty() && pocket_of(o.facts, ball) == pocket ? 1 : 0;
  }
  return in;
}

// A ball a centimetre off the long rail, 0.8 m from the corner: every line
// across the corner's mouth meets the cushion on the way, yet the engine
// runs the ball along the rail and drops it, as on a real table (docs/experiments.md,
// "rail runs into the corners"). Shot generation plans that run and
// the plans go in under tournament noise.
TEST(AiShotGeneration, RunsABallAlongTheRailIntoTheCorner) {
  const Rules rules = nine_ball_rules();
  const int corner = pocket_index(rules, "bottom_left");
  for (const Vec2 ball : {Vec2{0.85, kR + 0.01}, Vec2{1.05, kR + 0.002}, Vec2{0.6, kR + 0.05}}) {
    GameState s = bare_table(rules, {ball.x + 0.35, ball.y + 0.18});
    put(s, 1, ball);
    int planned = 0;
    int best = 0;
    for (const CandidateShot& c : generate_shots(rules, s, ShotGenOptions{})) {
      if (c.kind != ShotKind::direct || c.pocket != corner) continue;
      ++planned;
      // Every speed and spin variant goes in most of the time (the worst,
      // the hardest strokes, 74 of 100 when written), the best nearly always.
      const int made = made_of_100(rules, s, c, 1, corner);
      best = std::max(best, made);
      EXPECT_GE(made, 70) << "ball at " << ball.x << ", " << ball.y << ": phi "
                          << c.shot.strike.phi << " speed " << c.shot.strike.speed;
    }
    EXPECT_GT(planned, 0) << "no run along the rail planned for the ball at " << ball.x << ", "
                          << ball.y;
    EXPECT_GE(best, 95) << "ball at " << ball.x << ", " << ball.y;
  }
}

// A ball hanging in a corner's jaws, past the end of the cushion: the line
// to the pocket's centre would need the cue ball inside the short rail's
// cushion, so the pot is planned along the long rail instead, and it goes.
TEST(AiShotGeneration, PotsABallHangingInTheJawsFromWhereTheCueBallFits) {
  const Rules rules = nine_ball_rules();
  const int corner = pocket_index(rules, "top_left");
  const Vec2 ball{-0.0014, rules.table().width - 0.0222};
  GameState s = bare_table(rules, {0.345, rules.table().width - 0.054});
  put(s, 1, ball);
  int planned = 0;
  for (const CandidateShot& c : generate_shots(rules, s, ShotGenOptions{})) {
    if (c.kind != ShotKind::direct || c.pocket != corner) continue;
    ++planned;
    EXPECT_GE(made_of_100(rules, s, c, 1, corner), 90) << "phi " << c.shot.strike.phi;
  }
  EXPECT_GT(planned, 0) << "no pot of the hanging ball planned";
}

TEST(AiPlayer, PlacesTheCueBallAnywhereThenShoots) {
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.5, 0.5});
  s.on_table[0] = 0;
  s.ball_in_hand = BallInHand::anywhere;
  put(s, 2, {1.8, 0.4});
  put(s, 5, {0.9, 1.0});
  put(s, 8, {1.3, 0.7});
  put(s, 13, {2.0, 0.9});
  const auto player = make_ai_player(small_level());
  const Action a = decide_legal(*player, rules, s);
  ASSERT_TRUE(std::holds_alternative<PlaceCueBall>(a));
  const GameState placed = rules.apply(s, a).state;
  const Action b = decide_legal(*player, rules, placed, 2);
  ASSERT_TRUE(std::holds_alternative<Shoot>(b));
  const Outcome out = rules.apply(placed, b);
  EXPECT_TRUE(out.ruling.fouls.empty()) << out.ruling.text;
  EXPECT_TRUE(out.ruling.turn_continues) << out.ruling.text;  // ball in hand: an easy pot
}

TEST(AiPlayer, PlacesTheCueBallBehindTheHeadString) {
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.5, 0.5});
  s.on_table[0] = 0;
  s.ball_in_hand = BallInHand::kitchen;
  put(s, 2, {1.8, 0.4});
  put(s, 4, {0.3, 0.9});  // behind the head string: not a fair first ball
  put(s, 11, {2.2, 1.0});
  for (const std::string level : {"beginner", "expert"}) {
    const auto player = make_ai_player(level == "beginner" ? ai_level(level) : small_level());
    const Action a = decide_legal(*player, rules, s);
    ASSERT_TRUE(std::holds_alternative<PlaceCueBall>(a)) << level;
    EXPECT_LE(std::get<PlaceCueBall>(a).position.x, rules.head_string()) << level;
    const GameState placed = rules.apply(s, a).state;
    const Action b = decide_legal(*player, rules, placed, 2);
    ASSERT_TRUE(std::holds_alternative<Shoot>(b)) << level;
    const Outcome out = rules.apply(placed, b);
    EXPECT_NE(out.facts.first_hit, 4) << level;
  }
}

// The strongest level's break spends its samples in rounds that halve
// the options (src/ai/break_shot.cpp): the call that places the cue ball
// and the call that then finds it there read the same rounds and agree,
// whatever the decision seed and the threads.
TEST(AiBreak, TheChampionPlacesTheCueBallThenShootsTheBreakItChose) {
  const Rules rules = eight_ball_rules();
  const GameState s = rules.start(11, 0);
  AiLevel l = ai_level("champion");
  l.samples = 24;  // 12 an option on average (the level: 32), still in rounds
  l.threads = 1;
  const Action a = make_ai_player(l)->decide(rules, s, 1);
  ASSERT_TRUE(std::holds_alternative<PlaceCueBall>(a));
  EXPECT_DOUBLE_EQ(std::get<PlaceCueBall>(a).position.x, rules.head_string());
  const GameState placed = rules.apply(s, a).state;
  const Action b = make_ai_player(l)->decide(rules, placed, 2);
  ASSERT_TRUE(std::holds_alternative<Shoot>(b));
  EXPECT_GE(std::get<Shoot>(b).strike.speed, 9.9);  // a power break, 10 or 11 m/s
  l.threads = 2;
  EXPECT_TRUE(make_ai_player(l)->decide(rules, placed, 7) == b);
}

/// An open 8-ball table in play: two solids, a stripe and the 8.
GameState four_balls(const Rules& rules) {
  GameState s = bare_table(rules, {0.7, 0.5});
  put(s, 1, {1.5, 0.4});
  put(s, 3, {1.9, 1.0});
  put(s, 9, {1.2, 0.9});
  put(s, 8, {2.2, 0.3});
  return s;
}

TEST(AiPlayer, SameSeedAndBudgetSameActionOnOneAndTwoThreads) {
  const Rules rules = eight_ball_rules();
  const GameState s = four_balls(rules);
  AiLevel l = small_level("champion");
  l.candidates = 5;
  l.samples = 6;
  l.simulation_budget = 40;
  for (std::uint64_t seed : {1u, 2u}) {
    l.threads = 1;
    const Action one = make_ai_player(l)->decide(rules, s, seed);
    l.threads = 2;
    const Action two = make_ai_player(l)->decide(rules, s, seed);
    EXPECT_TRUE(one == two) << "seed " << seed;
  }
}

// The 9-ball lookahead depth applies to 9-ball alone: on an 8-ball table
// whose decision does depend on the depth (seeds 2 and 4), setting it
// changes nothing; in 9-ball it replaces the 8-ball depth where set.
// (No small 9-ball table was found whose decision depends on the depth at
// test budgets, so the 9-ball side is checked on the rule itself.)
TEST(AiPlayer, NineBallLookaheadDepthAppliesToNineBallOnly) {
  AiLevel shallow = small_level("champion");
  shallow.candidates = 5;
  shallow.samples = 6;
  shallow.lookahead_candidates = 1;
  shallow.lookahead_states = 1;
  shallow.lookahead_candidates_nine = 0;  // unset (the champion sets them)
  shallow.lookahead_states_nine = 0;
  shallow.centre_aim = false;  // the seeds below were found without it
  AiLevel wide = shallow;
  wide.lookahead_candidates = 5;
  wide.lookahead_states = 6;
  AiLevel deep_nine = shallow;
  deep_nine.lookahead_candidates_nine = 5;
  deep_nine.lookahead_states_nine = 6;

  const Rules eight = eight_ball_rules();
  const GameState e = four_balls(eight);
  for (std::uint64_t seed : {2u, 4u}) {
    const Action a = make_ai_player(shallow)->decide(eight, e, seed);
    ASSERT_FALSE(a == make_ai_player(wide)->decide(eight, e, seed)) << "seed " << seed;
    EXPECT_TRUE(a == make_ai_player(deep_nine)->decide(eight, e, seed)) << "seed " << seed;
  }

  const LookaheadDepth d8 = lookahead_depth(deep_nine, GameType::eight_ball);
  const LookaheadDepth d9 = lookahead_depth(deep_nine, GameType::nine_ball);
  EXPECT_EQ(d8.candidates, 1);
  EXPECT_EQ(d8.states, 1);
  EXPECT_EQ(d9.candidates, 5);
  EXPECT_EQ(d9.states, 6);
  const LookaheadDepth unset = lookahead_depth(wide, GameType::nine_ball);
  EXPECT_EQ(unset.candidates, 5);
  EXPECT_EQ(unset.states, 6);
  const AiLevel champion = ai_level("champion");
  EXPECT_EQ(lookahead_depth(champion, GameType::eight_ball).states, 8);  // unset: 128 samples
  EXPECT_GT(lookahead_depth(champion, GameType::nine_ball).candidates,
            lookahead_depth(champion, GameType::eight_ball).candidates);
}

TEST(AiPlayer, WholeGamesAreLegal) {
  // play_game throws if any action is refused.
  for (const GameType g : {GameType::eight_ball, GameType::nine_ball}) {
    GameConfig c;
    c.game = g;
    c.max_shots = 60;
    const Rules rules(c);
    AiLevel l = small_level("club");
    l.candidates = 3;
    l.samples = 2;
    l.generation.max_candidates = 12;
    const auto ai = make_ai_player(l);
    const auto beginner = make_ai_player(ai_level("beginner"));
    const auto baseline = make_baseline_player();
    for (int breaker : {0, 1}) {
      const GameRecord r = play_game(rules, *ai, breaker ? *beginner : *baseline, breaker,
                                     static_cast<std::uint64_t>(11 + breaker),
                                     parse_noise("tournament"));
      EXPECT_EQ(r.actions.back().after.phase, Phase::game_over);
    }
  }
}

}  // namespace

}  // namespace test_ai

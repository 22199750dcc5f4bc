// Pot maps (include/breakshot/pot_map.hpp): a ball in the jaws of a pocket
// with the cue ball straight behind it drops nearly always, in 8-ball,
// 9-ball, 10-ball and snooker; a ball boxed in by others cannot be potted;
// what counts as a pot is the game's ruling (the 8 before its time in
// 8-ball, a colour while the ball on is a red in snooker, are none); a cue
// ball on another ball, over a pocket or off the table is no place, and
// its cell is 0, never NaN; a grid gives the same numbers on one thread
// and on two, and each cell is pot_chance with the cell's seed; shot
// generation limited to one ball and pocket gives exactly the unlimited
// generation's shots for them; bad arguments are refused naming what is
// wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/pot_map.hpp"
#include "rules_fixtures.hpp"
#include "snooker_fixtures.hpp"

namespace test_pot_map {

namespace {

using namespace rules_fixtures;

/// 9-ball: the 1 in the jaws of the top-right pocket (its centre 8 cm from
/// the pocket's centre), the 9 out of the way.
struct Jaws {
  Rules rules = nine_ball_rules();
  int pocket = pocket_index(rules, "top_right");
  StraightIn si = straight_in(rules, pocket, {1.2, 0.5}, 0.08, 0.5);
  GameState state;
  Jaws() {
    state = bare_table(rules, {0.3, 0.3});
    put(state, 1, si.object);
    put(state, 9, {0.5, 0.9});
  }
};

Vec2 rotate_deg(Vec2 v, double deg) {
  const double a = deg * kPi / 180.0;
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y};
}

bool same_strike(const CueStrike& a, const CueStrike& b) {
  return a.phi == b.phi && a.theta == b.theta && a.speed == b.speed && a.a == b.a && a.b == b.b;
}

bool same_cell(const PotChance& a, const PotChance& b) {
  return a.probability == b.probability && a.placeable == b.placeable &&
         a.unplaceable == b.unplaceable && a.shots == b.shots && a.plays == b.plays &&
         a.kind == b.kind && same_strike(a.aim, b.aim) && a.simulations == b.simulations;
}

Rules ten_ball_rules() {
  GameConfig c;
  c.game = GameType::ten_ball;
  c.physics = kLegacyGamePhysics;
  return Rules(c);
}

/// A game's table with only the cue ball on it (at `cue`): player 0 to
/// shoot, no ball in hand; snooker on a red, 0-0.
GameState bare(const Rules& rules, Vec2 cue) {
  if (rules.config().game == GameType::snooker) return snooker_fixtures::bare(cue, 7);
  return bare_table(rules, cue);
}

/// One game's straight pot: `ball` in the jaws of the top-right pocket
/// (8 cm from its centre on the pocket's diagonal), the cue ball 0.5 m
/// straight behind it, and `other` (a ball of the game that is no legal
/// first target, or -1) out of the way at (0.5, 0.9).
struct Straight {
  Rules rules;
  int ball;
  int pocket;
  StraightIn si;
  GameState state;
  Straight(Rules r, int b, int other = -1)
      : rules(std::move(r)),
        ball(b),
        pocket(pocket_index(rules, "top_right")),
        si(straight_in(rules, pocket, pocket_centre(rules, pocket) - Vec2{1.0, 1.0}, 0.08, 0.5)),
        state(bare(rules, {0.3, 0.3})) {
    put(state, ball, si.object);
    if (other >= 0) put(state, other, {0.5, 0.9});
  }
  double R() const { return rules.config().ball_radius; }
  /// Six balls (`ring`) around the ball, 0.5 mm apart from it: nothing
  /// reaches it and it has nowhere to go.
  void box_in(const std::vector<int>& ring) {
    const Vec2 centre{rules.table().length / 2.0, rules.table().width / 2.0};
    put(state, ball, centre);
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const double a = static_cast<double>(k) * kPi / 3.0;
      put(state, ring[k], centre + Vec2{std::cos(a), std::sin(a)} * (2.0 * R() + 0.0005));
    }
  }
};

/// The four games with pockets, each with a ball it may pot first and
/// six balls to box it in with.
struct GameCase {
  std::string name;
  Straight straight;
  std::vector<int> ring;
};

std::vector<GameCase> every_game() {
  return {
      {"eight_ball", Straight(eight_ball_rules(), 3, 8), {1, 2, 4, 5, 6, 7}},
      {"nine_ball", Straight(nine_ball_rules(), 1, 9), {2, 3, 4, 5, 6, 7}},
      {"ten_ball", Straight(ten_ball_rules(), 1, 10), {2, 3, 4, 5, 6, 7}},
      // Snooker: a red, the black out of the way.
      {"snooker", Straight(snooker_fixtures::rules(), 1, 21), {2, 3, 4, 5, 6, 7}},
  };
}

PotMapOptions few(int samples, int candidates, std::uint64_t seed = 5) {
  PotMapOptions o;
  o.samples = samples;
  o.candidates = candidates;
  o.seed = seed;
  return o;
}

TEST(PotMap, BallInTheJawsWithTheCueBallStraightBehindDrops) {
  const Jaws j;
  // Club and above: their generation has draw, which keeps the cue ball
  // out of the pocket after the full hit.
  for (const std::string name : {"club", "expert", "champion"}) {
    PotMapOptions o;
    o.samples = 24;
    o.candidates = 4;
    o.seed = 5;
    const PotChance c = pot_chance(j.rules, j.state, j.si.cue, 1, j.pocket, ai_level(name), o);
    EXPECT_TRUE(c.placeable) << name;
    EXPECT_GT(c.shots, 0) << name;
    EXPECT_EQ(c.plays, 24) << name;
    EXPECT_EQ(c.kind, ShotKind::direct) << name;
    // The aim is about the straight line from the cue ball to the pocket.
    const double line = aim_deg(j.si.cue, pocket_centre(j.rules, j.pocket));
    EXPECT_NEAR(c.aim.phi, line, 1.0) << name;
    EXPECT_LT(c.aim.b, 0.0) << name;  // draw
    // Tournament noise times 1.6 (0.2 degrees of aim) cannot miss from 8 cm.
    EXPECT_EQ(c.probability, 1.0) << name;
  }
  // The beginner and the amateur hit the ball centre only: a full hit
  // from 0.5 m follows the 1 into the pocket, so no shot of theirs makes
  // it without a scratch and the map says 0.
  for (const std::string name : {"beginner", "amateur"}) {
    const PotChance c = pot_chance(j.rules, j.state, j.si.cue, 1, j.pocket, ai_level(name));
    EXPECT_TRUE(c.placeable) << name;
    EXPECT_EQ(c.shots, 0) << name;
    EXPECT_EQ(c.probability, 0.0) << name;
  }
}

TEST(PotMap, BallInTheJawsOnAThirtyDegreeCutDropsForEveryLevel) {
  const Jaws j;
  // The cue ball 0.5 m from the 1 on a line turned 30 degrees from the
  // pocket's: the cue ball leaves the pocket's line after the hit.
  const Vec2 from_pocket = unit(j.si.object - pocket_centre(j.rules, j.pocket));
  const Vec2 cue = j.si.object + rotate_deg(from_pocket, 30.0) * 0.5;
  for (const std::string& name : ai_level_names()) {
    PotMapOptions o;
    o.samples = 24;
    o.candidates = 4;
    const PotChance c = pot_chance(j.rules, j.state, cue, 1, j.pocket, ai_level(name), o);
    EXPECT_GT(c.shots, 0) << name;
    // Tournament noise up to 2.5 times cannot miss from 8 cm. The
    // beginner's four times (0.5 degrees of aim, 0.3 m/s of speed, 2 mm of
    // tip) loses one play in 24 here.
    EXPECT_GE(c.probability, name == "beginner" ? 0.9 : 1.0) << name;
  }
}

TEST(PotMap, BoxedInBallCannotBePotted) {
  Jaws j;
  // Six balls in a ring touching-close around the 1 in mid-table: the cue
  // ball cannot reach it and it has nowhere to go.
  const Vec2 centre{j.rules.table().length / 2.0, j.rules.table().width / 2.0};
  put(j.state, 1, centre);
  for (int k = 0; k < 6; ++k) {
    const double a = k * kPi / 3.0;
    put(j.state, 2 + k, centre + Vec2{std::cos(a), std::sin(a)} * (2.0 * kR + 0.0005));
  }
  PotMapOptions o;
  o.samples = 8;
  for (int pocket = 0; pocket < 6; ++pocket) {
    const PotChance c = pot_chance(j.rules, j.state, {0.4, 0.4}, 1, pocket, ai_level("club"), o);
    EXPECT_TRUE(c.placeable);
    EXPECT_EQ(c.shots, 0) << "pocket " << pocket;
    EXPECT_EQ(c.probability, 0.0) << "pocket " << pocket;
    EXPECT_EQ(c.plays, 0);
  }
}

TEST(PotMap, NoPlaceForTheCueBallIsZeroWithTheReason) {
  const Jaws j;
  const struct {
    Vec2 cue;
    std::string why;
  } cases[] = {
      {j.si.object + Vec2{0.03, 0.0}, "overlap ball 1"},
      {Vec2{-0.1, 0.5}, "playing surface"},
      {Vec2{0.01, 0.5}, "clear of the cushions"},
  };
  for (const auto& c : cases) {
    const PotChance p = pot_chance(j.rules, j.state, c.cue, 1, j.pocket, ai_level("club"));
    EXPECT_FALSE(p.placeable);
    EXPECT_NE(p.unplaceable.find(c.why), std::string::npos) << p.unplaceable;
    EXPECT_EQ(p.probability, 0.0);
    EXPECT_EQ(p.shots, 0);
    EXPECT_EQ(p.plays, 0);
    EXPECT_EQ(p.simulations, 0);
  }
  const PotChance p = pot_chance(j.rules, j.state, j.si.cue, 1, j.pocket, ai_level("club"));
  EXPECT_TRUE(p.placeable);
  EXPECT_TRUE(p.unplaceable.empty());
}

TEST(PotMap, StraightPotInEveryGameAndABoxedBallInNone) {
  for (GameCase& g : every_game()) {
    Straight& t = g.straight;
    const PotChance c =
        pot_chance(t.rules, t.state, t.si.cue, t.ball, t.pocket, ai_level("champion"), few(16, 2));
    EXPECT_TRUE(c.placeable) << g.name;
    EXPECT_GT(c.shots, 0) << g.name;
    EXPECT_EQ(c.plays, 16) << g.name;
    EXPECT_EQ(c.kind, ShotKind::direct) << g.name;
    EXPECT_NEAR(c.aim.phi, aim_deg(t.si.cue, pocket_centre(t.rules, t.pocket)), 1.0) << g.name;
    // The champion's aim noise cannot make the ball miss a pocket from 8
    // cm, pool's or snooker's. In snooker the soft straight draw it
    // chooses may still let the cue ball follow the red in-off, a foul
    // (1 play in 16 here).
    EXPECT_GE(c.probability, g.name == "snooker" ? 0.9 : 1.0) << g.name;

    t.box_in(g.ring);
    for (int pocket = 0; pocket < 6; ++pocket) {
      const PotChance b =
          pot_chance(t.rules, t.state, {0.4, 0.4}, t.ball, pocket, ai_level("club"), few(8, 0));
      EXPECT_TRUE(b.placeable) << g.name;
      EXPECT_EQ(b.shots, 0) << g.name << " pocket " << pocket;
      EXPECT_EQ(b.probability, 0.0) << g.name << " pocket " << pocket;
      EXPECT_EQ(b.plays, 0) << g.name;
    }
  }
}

TEST(PotMap, TheEightBeforeItsTimeIsNoPot) {
  // 8-ball, player 0 on the solids with the 3 still up: the 8 in the
  // jaws, the cue ball straight behind it. The rules lose the game for
  // the 8 now, so no play of it is a pot; with the 3 gone the 8 is the
  // ball on and the same shot is one.
  Straight t(eight_ball_rules(), 8, 3);
  t.state.group = {Group::solids, Group::stripes};
  const AiLevel champion = ai_level("champion");
  const PotChance early = pot_chance(t.rules, t.state, t.si.cue, 8, t.pocket, champion, few(16, 2));
  EXPECT_TRUE(early.placeable);
  EXPECT_EQ(early.shots, 0);
  EXPECT_EQ(early.probability, 0.0);
  GameState on_eight = t.state;
  on_eight.on_table[3] = 0;
  const PotChance due = pot_chance(t.rules, on_eight, t.si.cue, 8, t.pocket, champion, few(16, 2));
  EXPECT_GT(due.shots, 0);
  EXPECT_EQ(due.probability, 1.0);

  // The judge itself, on rulings from hand-made events: the 3 hit first
  // (a legal contact) and the 8 pocketed is no foul but a lost game, so
  // no pot; the 3 pocketed the same way is one.
  const auto events = [&](int dropped) {
    return std::vector<Event>{ev(0.0, EventType::cue_strike, 0),
                              ev(0.1, EventType::ball_ball, 0, 3),
                              ev(0.5, EventType::ball_pocket, dropped, -1, -1, t.pocket)};
  };
  Shoot shot = with_call(shot_at(t.si.cue, t.state.position[3], 2.0), 3, t.pocket);
  const Outcome lost = t.rules.apply_events(t.state, shot, events(8), t.state.position);
  ASSERT_TRUE(lost.ruling.fouls.empty());
  ASSERT_EQ(lost.state.phase, Phase::game_over);
  ASSERT_EQ(lost.state.winner, 1);
  EXPECT_FALSE(counts_as_pot(t.state, lost, 8, t.pocket));
  const Outcome made = t.rules.apply_events(t.state, shot, events(3), t.state.position);
  ASSERT_TRUE(made.ruling.fouls.empty());
  EXPECT_TRUE(counts_as_pot(t.state, made, 3, t.pocket));
  EXPECT_FALSE(counts_as_pot(t.state, made, 3, (t.pocket + 1) % 6));
  // The 8 in the called pocket when it is due wins: a pot.
  shot.call = Call{8, t.pocket};
  const auto on8 =
      std::vector<Event>{ev(0.0, EventType::cue_strike, 0), ev(0.1, EventType::ball_ball, 0, 8),
                         ev(0.5, EventType::ball_pocket, 8, -1, -1, t.pocket)};
  const Outcome won = t.rules.apply_events(on_eight, shot, on8, on_eight.position);
  ASSERT_EQ(won.state.winner, 0);
  EXPECT_TRUE(counts_as_pot(on_eight, won, 8, t.pocket));
}

TEST(PotMap, SnookerColourWhileTheBallOnIsARedIsNoPot) {
  // The blue (19) in the jaws, the cue ball straight behind it, a red up
  // the table. On a red, potting the blue is a foul: no play counts.
  // After a red (a colour on, nominated) the same shot is a pot.
  Straight t(snooker_fixtures::rules(), 19, 1);
  const AiLevel champion = ai_level("champion");
  ASSERT_FALSE(t.state.snooker->colour_on);
  const PotChance on_red =
      pot_chance(t.rules, t.state, t.si.cue, 19, t.pocket, champion, few(16, 2));
  EXPECT_TRUE(on_red.placeable);
  EXPECT_EQ(on_red.shots, 0);
  EXPECT_EQ(on_red.probability, 0.0);
  GameState colour = t.state;
  colour.snooker->colour_on = true;
  const PotChance on_colour =
      pot_chance(t.rules, colour, t.si.cue, 19, t.pocket, champion, few(16, 2));
  EXPECT_GT(on_colour.shots, 0);
  EXPECT_GE(on_colour.probability, 0.9);  // an in-off may spoil one (see above)

  // The judge on the engine's own play of that shot on a red: the blue
  // drops, and the ruling's foul makes it no pot; nominated after a red,
  // it is one.
  Shoot shot = shot_at(t.si.cue, t.si.object, 2.0, -0.4);
  GameState placed = t.state;
  put(placed, 0, t.si.cue);
  const Outcome foul = t.rules.apply(placed, shot);
  ASSERT_EQ(foul.facts.pocketed, std::vector<int>{19});
  ASSERT_FALSE(foul.ruling.fouls.empty());
  EXPECT_FALSE(counts_as_pot(placed, foul, 19, t.pocket));
  GameState placed_colour = colour;
  put(placed_colour, 0, t.si.cue);
  shot.nominate = 19;
  const Outcome pot = t.rules.apply(placed_colour, shot);
  ASSERT_EQ(pot.facts.pocketed, std::vector<int>{19});
  EXPECT_TRUE(counts_as_pot(placed_colour, pot, 19, t.pocket));
}

TEST(PotMap, NoNaNInAnyCellOfAGridWithCellsWhereTheCueBallCannotGo) {
  for (GameCase& g : every_game()) {
    const Straight& t = g.straight;
    const Vec2 pocket = pocket_centre(t.rules, t.pocket);
    // Columns: on the ball, over the pocket, off the table, the cue
    // ball's own place (placeable), mid-table (placeable).
    const std::vector<double> xs = {t.si.object.x, pocket.x, -0.2, t.si.cue.x,
                                    t.rules.table().length / 2.0};
    const std::vector<double> ys = {t.si.object.y, pocket.y, t.si.cue.y};
    const PotMap map =
        pot_map(t.rules, t.state, t.ball, t.pocket, ai_level("club"), xs, ys, few(4, 2, 9));
    int placeable = 0;
    for (std::size_t k = 0; k < map.cells.size(); ++k) {
      const PotChance& c = map.cells[k];
      EXPECT_TRUE(std::isfinite(c.probability)) << g.name << " cell " << k;
      EXPECT_GE(c.probability, 0.0);
      EXPECT_LE(c.probability, 1.0);
      for (double v : {c.aim.phi, c.aim.theta, c.aim.speed, c.aim.a, c.aim.b}) {
        EXPECT_TRUE(std::isfinite(v)) << g.name << " cell " << k;
      }
      EXPECT_EQ(c.placeable, c.unplaceable.empty()) << g.name << " cell " << k;
      if (!c.placeable) {
        EXPECT_EQ(c.probability, 0.0);
        EXPECT_EQ(c.shots, 0);
        EXPECT_EQ(c.plays, 0);
      }
      placeable += c.placeable ? 1 : 0;
    }
    const auto cell = [&](std::size_t i, std::size_t j) { return map.cells[j * xs.size() + i]; };
    EXPECT_NE(cell(0, 0).unplaceable.find("overlap ball " + std::to_string(t.ball)),
              std::string::npos)
        << g.name << ": " << cell(0, 0).unplaceable;
    EXPECT_NE(cell(1, 1).unplaceable.find("inside pocket top_right"), std::string::npos)
        << g.name << ": " << cell(1, 1).unplaceable;
    for (std::size_t j = 0; j < ys.size(); ++j) EXPECT_FALSE(cell(2, j).placeable) << g.name;
    EXPECT_TRUE(cell(3, 2).placeable) << g.name;
    EXPECT_GT(cell(3, 2).probability, 0.0) << g.name;
    EXPECT_GE(placeable, 4) << g.name;
  }
}

TEST(PotMap, GamesWithoutPocketsAndStatesOfAnotherGameAreRefused) {
  const Rules carom(three_cushion_config());
  GameState s = carom.start(1, 0);
  s.phase = Phase::shot;
  try {
    pot_chance(carom, s, {0.5, 0.5}, 2, 0, ai_level("club"));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("three_cushion has none"), std::string::npos) << e.what();
  }
  const Jaws j;
  const Straight snooker(snooker_fixtures::rules(), 1);
  try {
    pot_chance(j.rules, snooker.state, {0.5, 0.5}, 1, 0, ai_level("club"));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("snooker state"), std::string::npos) << e.what();
  }
}

/// pot_map over xs by ys on one thread and on two: the same cells, each
/// its own pot_chance with the cell's seed; another seed gives another
/// map. Returns the one-thread map.
PotMap check_threads(const Rules& rules, const GameState& state, int ball, int pocket,
                     const std::vector<double>& xs, const std::vector<double>& ys) {
  PotMapOptions o = few(6, 3, 11);
  o.threads = 1;
  const AiLevel level = ai_level("club");
  const PotMap one = pot_map(rules, state, ball, pocket, level, xs, ys, o);
  o.threads = 2;
  const PotMap two = pot_map(rules, state, ball, pocket, level, xs, ys, o);
  EXPECT_EQ(one.cells.size(), xs.size() * ys.size());
  EXPECT_EQ(two.cells.size(), one.cells.size());
  for (std::size_t k = 0; k < std::min(one.cells.size(), two.cells.size()); ++k) {
    EXPECT_TRUE(same_cell(one.cells[k], two.cells[k])) << "cell " << k;
    PotMapOptions alone = o;
    alone.seed = mix_seed(11, k);
    const PotChance c = pot_chance(rules, state, {xs[k % xs.size()], ys[k / xs.size()]}, ball,
                                   pocket, level, alone);
    EXPECT_TRUE(same_cell(c, one.cells[k])) << "cell " << k;
  }
  // Another seed draws other noise.
  o.seed = 12;
  const PotMap other = pot_map(rules, state, ball, pocket, level, xs, ys, o);
  bool differs = false;
  for (std::size_t k = 0; k < other.cells.size(); ++k) {
    differs = differs || !same_cell(other.cells[k], one.cells[k]);
  }
  EXPECT_TRUE(differs);
  return one;
}

int placeable_cells(const PotMap& map) {
  return static_cast<int>(std::count_if(map.cells.begin(), map.cells.end(),
                                        [](const PotChance& c) { return c.placeable; }));
}

TEST(PotMap, SameGridForOneAndTwoThreadsAndCellsAreTheirOwnPotChance) {
  const Jaws j;
  const PotMap one = check_threads(j.rules, j.state, 1, j.pocket, {0.5, 1.0, 1.4, 1.8}, {0.3, 0.9});
  ASSERT_EQ(one.cells.size(), 8u);
  // Cell (0.5, 0.9) is the 9's own place.
  EXPECT_FALSE(one.cells[4].placeable);
  EXPECT_EQ(placeable_cells(one), 7);
}

TEST(PotMap, SnookerGridIsTheSameForOneAndTwoThreads) {
  // A red in the jaws, the black out of the way at (0.5, 0.9); cells on
  // both sides of the baulk line (the map is not held to the D).
  const Straight t(snooker_fixtures::rules(), 1, 21);
  const PotMap one = check_threads(t.rules, t.state, 1, t.pocket, {0.5, 0.6, 1.5, 2.6}, {0.3, 0.9});
  ASSERT_EQ(one.cells.size(), 8u);
  EXPECT_FALSE(one.cells[4].placeable);  // the black's place
  EXPECT_EQ(placeable_cells(one), 7);
  int potted = 0;
  for (const PotChance& c : one.cells) potted += c.probability > 0.0 ? 1 : 0;
  EXPECT_GT(potted, 0);
}

TEST(PotMap, LimitedGenerationGivesTheSameShotsForTheBallAndPocket) {
  const Rules rules = eight_ball_rules();
  GameState s = bare_table(rules, {0.5, 0.4});
  put(s, 3, {1.3, 0.7});
  put(s, 12, {1.8, 0.3});
  put(s, 5, {0.9, 0.9});
  ShotGenOptions all;
  all.safeties = false;
  all.max_candidates = 1000;
  const std::vector<CandidateShot> every = generate_shots(rules, s, all);
  int checked = 0;
  for (int ball : {3, 12, 5}) {
    for (int pocket = 0; pocket < 6; ++pocket) {
      ShotGenOptions one = all;
      one.only_ball = ball;
      one.only_pocket = pocket;
      const std::vector<CandidateShot> got = generate_shots(rules, s, one);
      std::vector<CandidateShot> want;
      std::copy_if(every.begin(), every.end(), std::back_inserter(want),
                   [&](const CandidateShot& c) { return c.target == ball && c.pocket == pocket; });
      ASSERT_EQ(got.size(), want.size()) << "ball " << ball << " pocket " << pocket;
      for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_TRUE(got[i].shot == want[i].shot && got[i].prior == want[i].prior);
      }
      checked += static_cast<int>(got.size());
    }
  }
  EXPECT_GT(checked, 10);
}

TEST(PotMap, BadArgumentsAreRefusedByName) {
  const Jaws j;
  const AiLevel level = ai_level("club");
  const auto message = [&](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no exception)";
  };
  EXPECT_NE(message([&] { pot_chance(j.rules, j.state, j.si.cue, 10, j.pocket, level); })
                .find("ball 10"),
            std::string::npos);
  EXPECT_NE(message([&] { pot_chance(j.rules, j.state, j.si.cue, 4, j.pocket, level); })
                .find("ball 4 is not on the table"),
            std::string::npos);
  EXPECT_NE(message([&] { pot_chance(j.rules, j.state, j.si.cue, 1, 6, level); }).find("pocket 6"),
            std::string::npos);
  EXPECT_NE(message([&] { pot_chance(j.rules, j.state, j.si.cue, 1, -1, level); }).find("pocket -1"),
            std::string::npos);
  GameState broken = j.state;
  broken.phase = Phase::break_shot;
  EXPECT_NE(message([&] { pot_chance(j.rules, broken, j.si.cue, 1, j.pocket, level); })
                .find("phase shot"),
            std::string::npos);
  EXPECT_NE(message([&] { pot_map(j.rules, j.state, 1, j.pocket, level, {}, {0.5}); })
                .find("empty"),
            std::string::npos);
  EXPECT_NE(message([&] {
              pot_map(j.rules, j.state, 1, j.pocket, level, {0.5, std::nan("")}, {0.5});
            }).find("xs"),
            std::string::npos);
  PotMapOptions o;
  o.samples = -1;
  EXPECT_NE(message([&] { pot_chance(j.rules, j.state, j.si.cue, 1, j.pocket, level, o); })
                .find("samples"),
            std::string::npos);
}

}  // namespace

}  // namespace test_pot_map

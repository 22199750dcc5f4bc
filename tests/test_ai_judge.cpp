// The AI's judgement of a shot ties to the rules: for random mid-game
// states of 8-ball, 9-ball, 10-ball and snooker, the judge shot
// generation rules its candidates with (src/ai/judge.hpp), run on a
// simulation set up as shot generation sets it up, gives what
// Rules::apply gives for the same shot: the facts, the fouls, and the
// state after it field by field (next player, phase, winner, scores,
// balls on the table and where they lie, bit for bit, ball in hand).
// The shots are candidates of generate_shots and random strikes (calls,
// safeties, nominations, tip offsets up to miscues, elevated cues).
// Fixed seed. Under the sanitizers a tenth of the states.
//
// Three-cushion is not here: its search (src/ai/carom_ai.cpp) plays
// every shot it weighs through Rules::apply itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ai/judge.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"
#include "sanitizers.hpp"

namespace test_ai_judge {

using namespace breakshot;

namespace {

constexpr int kStates = kUnderSanitizers ? 25 : 250;
constexpr int kRandomStrikes = 4;
constexpr std::size_t kCandidates = 6;  // of each state's generated candidates

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
int below(std::mt19937_64& g, int n) { return static_cast<int>(g() % static_cast<std::uint64_t>(n)); }
bool coin(std::mt19937_64& g) { return (g() & 1) != 0; }

/// A free place for a ball: on the cloth away from the cushions and jaws,
/// clear of every ball on the table.
Vec2 free_place(const Rules& rules, const GameState& s, std::mt19937_64& g, double x_max = -1.0) {
  const Table& t = rules.table();
  const double R = rules.config().ball_radius;
  const double hi_x = x_max > 0.0 ? x_max : t.length - R;
  for (;;) {
    const Vec2 p{R + (hi_x - R) * unit(g), R + (t.width - 2.0 * R) * unit(g)};
    if (wall_clearance(t, p, R) < 1e-3) continue;
    bool clear = true;
    for (std::size_t b = 0; b < s.on_table.size() && clear; ++b) {
      clear = !s.on_table[b] || norm(s.position[b] - p) > 2.0 * R + 1e-3;
    }
    if (clear) return p;
  }
}

/// Puts `balls` (and the cue ball) on an empty table at random places.
void place(const Rules& rules, GameState& s, const std::vector<int>& balls, std::mt19937_64& g) {
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  for (int b : balls) {
    s.position[static_cast<std::size_t>(b)] = free_place(rules, s, g);
    s.on_table[static_cast<std::size_t>(b)] = 1;
  }
}

/// A random state of a pool game with a shot to play: a random subset of
/// the object balls (the game ball always among them) at random places,
/// either player to shoot; 8-ball's groups open or taken, the cue ball
/// sometimes just placed in the kitchen; 9-ball's and 10-ball's fouls in
/// a row and push-out; now and then the shot the stalemate limit ends.
GameState pool_state(const Rules& rules, std::mt19937_64& g) {
  const GameType game = rules.config().game;
  GameState s = rules.start(g(), below(g, 2));
  const int n = rules.ball_count();
  const int game_ball = game == GameType::eight_ball ? 8 : game == GameType::nine_ball ? 9 : 10;
  std::vector<int> balls{game_ball};
  const int keep = 1 + below(g, n - 1);
  for (int b = 1; b < n; ++b) {
    if (b != game_ball && below(g, n - 1) < keep) balls.push_back(b);
  }
  const bool kitchen = game == GameType::eight_ball && below(g, 8) == 0;
  place(rules, s, balls, g);
  s.position[0] = free_place(rules, s, g, kitchen ? rules.head_string() : -1.0);
  s.on_table[0] = 1;
  s.kitchen_shot = kitchen;
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.player = below(g, 2);
  s.shots = below(g, 10) == 0 ? rules.config().max_shots - 1 : 1 + below(g, 40);
  s.innings = s.shots;
  if (game == GameType::eight_ball) {
    if (coin(g)) {
      const Group mine = coin(g) ? Group::solids : Group::stripes;
      s.group[static_cast<std::size_t>(s.player)] = mine;
      s.group[static_cast<std::size_t>(1 - s.player)] =
          mine == Group::solids ? Group::stripes : Group::solids;
    }
  } else {
    s.fouls_in_a_row = {below(g, 3), below(g, 3)};
    s.push_out_allowed = below(g, 4) == 0;
  }
  return s;
}

/// A random snooker state with a shot to play: some reds (with all the
/// colours), or none and the colours from one up, at random places; the
/// scores and the break; a colour on after a red; a free ball where the
/// striker is snookered; the re-spotted black; and now and then the
/// break-off from a place in the D.
GameState snooker_state(const Rules& rules, std::mt19937_64& g) {
  GameState s = rules.start(g(), below(g, 2));
  if (below(g, 8) == 0) {
    const SnookerMarks m = snooker_marks();
    for (;;) {
      const Vec2 p{m.baulk_x - m.d_radius * unit(g),
                   m.d_centre.y + (2.0 * unit(g) - 1.0) * m.d_radius};
      if (!rules.check_placement(s, p)) return rules.apply(s, PlaceCueBall{p}).state;
    }
  }
  const int reds = below(g, 16);
  const int lowest = reds > 0 ? 2 : 2 + below(g, 6);
  std::vector<int> balls;
  for (int b = 1; b <= 15; ++b) {
    if (below(g, 15) < reds) balls.push_back(b);
  }
  for (int b = 16; b <= 21; ++b) {
    if (snooker_value(b) >= lowest) balls.push_back(b);
  }
  place(rules, s, balls, g);
  s.position[0] = free_place(rules, s, g);
  s.on_table[0] = 1;
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.player = below(g, 2);
  s.shots = 1 + below(g, 60);
  SnookerState& k = *s.snooker;
  k.score = {below(g, 70), below(g, 70)};
  k.break_points = std::min(k.score[static_cast<std::size_t>(s.player)], below(g, 20));
  const bool any_red = std::any_of(balls.begin(), balls.end(), [](int b) { return b <= 15; });
  k.colour_on = (any_red || lowest == 2) && below(g, 3) == 0;
  if (lowest == 7 && coin(g)) {
    k.respotted_black = true;
    k.score[1] = k.score[0];
    k.break_points = 0;
  }
  if (!k.colour_on && !k.respotted_black && rules.snookered(s)) k.free_ball = coin(g);
  return s;
}

/// A random strike, with the call, declaration or nomination the state
/// allows; nullopt when the rules refuse every version of it.
std::optional<Shoot> random_shot(const Rules& rules, const GameState& s, std::mt19937_64& g) {
  const LegalActions la = rules.legal_actions(s);
  Shoot shot;
  shot.strike.speed = 0.3 + 6.7 * unit(g);
  shot.strike.phi = 360.0 * unit(g);
  const double tip = below(g, 6) == 0 ? 0.85 : 0.5;  // past the miscue limit now and then
  shot.strike.a = tip * (2.0 * unit(g) - 1.0);
  shot.strike.b = tip * (2.0 * unit(g) - 1.0);
  if (below(g, 5) == 0) shot.strike.theta = 40.0 * unit(g);
  if (!la.nominate.empty() && (la.must_nominate || coin(g))) {
    shot.nominate = la.nominate[static_cast<std::size_t>(below(g, static_cast<int>(la.nominate.size())))];
  }
  if (!la.targets.empty() && coin(g)) {
    const int ball = la.targets[static_cast<std::size_t>(below(g, static_cast<int>(la.targets.size())))];
    shot.call = Call{ball, below(g, static_cast<int>(rules.table().pockets.size()))};
  } else if (la.call) {
    shot.safety = true;
  }
  if (la.push_out && below(g, 4) == 0) {
    shot.push_out = true;
    shot.call.reset();
    shot.safety = false;
  }
  if (!rules.check(s, Action{shot})) return shot;
  Shoot plain = shot;  // without the call or declaration
  plain.call.reset();
  plain.safety = false;
  plain.push_out = false;
  if (!rules.check(s, Action{plain})) return plain;
  plain.safety = true;
  if (!rules.check(s, Action{plain})) return plain;
  return std::nullopt;
}

/// The balls whose positions differ, with both positions.
std::string moved(const GameState& a, const GameState& b) {
  std::ostringstream out;
  out.precision(17);
  for (std::size_t k = 0; k < a.position.size(); ++k) {
    if (a.position[k] == b.position[k]) continue;
    out << " ball " << k << (a.on_table[k] ? "" : " (off)") << " at (" << a.position[k].x
        << ", " << a.position[k].y << ") against (" << b.position[k].x << ", "
        << b.position[k].y << ");";
  }
  return out.str();
}

/// The first field in which two states differ, in words ("" if none).
std::string first_difference(const GameState& a, const GameState& b) {
  if (a.phase != b.phase) return "phase";
  if (a.player != b.player) return "player";
  if (a.winner != b.winner) return "winner";
  if (a.ball_in_hand != b.ball_in_hand) return "ball_in_hand";
  if (a.on_table != b.on_table) return "on_table";
  if (a.position != b.position) return "position:" + moved(a, b);
  if (a.snooker != b.snooker) return "snooker";
  if (a.group != b.group) return "group";
  if (a.fouls_in_a_row != b.fouls_in_a_row) return "fouls_in_a_row";
  if (a.result != b.result) return "result: " + a.result + " against " + b.result;
  if (!(a == b)) return "another field";
  return "";
}

/// What the judges compared, for checking that the shots covered what
/// they should.
struct Tally {
  int shots = 0;
  int candidates = 0;
  int fouls = 0;
  int pots = 0;       ///< shots that pocketed an object ball with no foul
  int kept = 0;       ///< the shooter to play again
  int over = 0;       ///< the game (frame) ended
  int stepped = 0;    ///< judged from a run stepped part of the way first
};

/// Judges `shot` from `s` as shot generation does and checks it against
/// Rules::apply. `sim` is reused from shot to shot (re-armed, as shot
/// generation re-arms its runs); `step` events are taken one at a time
/// first, as the aim's refinement takes them.
void expect_tied(const Rules& rules, const GameState& s, const Shoot& shot,
                 std::optional<Simulation>& sim, int step, Tally& tally, const std::string& where) {
  std::vector<int> numbers;
  Scenario sc = rules.shot_scenario(s, CueStrike{}, &numbers);
  sc.cue->strike = shot.strike;
  if (sim) {
    sim->reset(sc);
  } else {
    sim.emplace(sc);
  }
  for (int k = 0; k < step; ++k) {
    const double t = sim->next_event_time();
    if (!std::isfinite(t)) break;
    sim->advance_to(t);
  }
  const ai_detail::Judged j = ai_detail::judge(rules, s, shot, *sim, numbers);
  const Outcome o = rules.apply(s, Action{shot});

  EXPECT_EQ(j.fouls, o.ruling.fouls) << where;
  EXPECT_EQ(j.first_hit, o.facts.first_hit) << where;
  EXPECT_EQ(j.pocketed, o.facts.pocketed) << where;
  EXPECT_EQ(j.pocket_of, o.facts.pocket_of) << where;
  EXPECT_EQ(first_difference(j.next, o.state), "") << where;
  EXPECT_TRUE(j.next == o.state) << where;
  EXPECT_TRUE(j.after.pos == o.state.position) << where;
  EXPECT_TRUE(j.after.on == o.state.on_table) << where;
  const bool over = o.state.phase == Phase::game_over;
  const bool wins = over && o.state.winner == s.player;
  EXPECT_EQ(j.wins, wins) << where;
  EXPECT_EQ(j.legal, o.ruling.fouls.empty() && (!over || wins)) << where;

  ++tally.shots;
  tally.stepped += step > 0 ? 1 : 0;
  tally.fouls += o.ruling.fouls.empty() ? 0 : 1;
  tally.pots += o.ruling.fouls.empty() && std::any_of(o.facts.pocketed.begin(),
                                                       o.facts.pocketed.end(),
                                                       [](int b) { return b > 0; });
  tally.kept += !over && o.state.player == s.player ? 1 : 0;
  tally.over += over ? 1 : 0;
}

/// Shot generation's options for these tables: every kind of candidate,
/// few variants, so that many states fit in the time.
ShotGenOptions options() {
  ShotGenOptions o;
  o.jumps = true;
  o.speed_factors = {1.0, 1.8};
  o.spins = {-0.3, 0.3};
  o.sides = {0.3};
  o.refine_iterations = 2;
  o.max_candidates = 16;
  return o;
}

Tally tie(const Rules& rules, GameState (*make_state)(const Rules&, std::mt19937_64&),
          std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::optional<Simulation> sim;
  Tally tally;
  const ShotGenOptions opt = options();
  for (int n = 0; n < kStates; ++n) {
    const GameState s = make_state(rules, g);
    const std::string state = "state " + std::to_string(n) + " of seed " + std::to_string(seed);
    const std::vector<CandidateShot> cands = generate_shots(rules, s, opt);
    // The best few and the last few: pots and safeties alike.
    for (std::size_t i = 0; i < cands.size(); ++i) {
      if (i >= kCandidates / 2 && i + kCandidates / 2 < cands.size()) continue;
      expect_tied(rules, s, cands[i].shot, sim, below(g, 3) == 0 ? below(g, 12) : 0, tally,
                  state + ", candidate " + std::to_string(i));
      ++tally.candidates;
    }
    for (int k = 0; k < kRandomStrikes; ++k) {
      const std::optional<Shoot> shot = random_shot(rules, s, g);
      if (!shot) continue;
      expect_tied(rules, s, *shot, sim, below(g, 3) == 0 ? below(g, 12) : 0, tally,
                  state + ", random strike " + std::to_string(k));
    }
  }
  return tally;
}

Rules rules_of(GameType game) {
  if (game == GameType::snooker) return Rules(snooker_config());
  GameConfig c;
  c.game = game;
  return Rules(c);
}

/// The shots covered candidates and strikes that foul, pot, keep the
/// turn and end the game, and runs judged after stepping.
void expect_covered(const Tally& t) {
  EXPECT_GE(t.shots, kStates * 3);
  EXPECT_GT(t.candidates, kStates);
  EXPECT_GT(t.fouls, 0);
  EXPECT_GT(t.pots, 0);
  EXPECT_GT(t.kept, 0);
  EXPECT_GT(t.stepped, 0);
}

}  // namespace

TEST(AiJudge, EightBallRulingsAreTheRules) {
  const Tally t = tie(rules_of(GameType::eight_ball), pool_state, 81);
  expect_covered(t);
  EXPECT_GT(t.over, 0);
}

TEST(AiJudge, NineBallRulingsAreTheRules) {
  const Tally t = tie(rules_of(GameType::nine_ball), pool_state, 91);
  expect_covered(t);
  EXPECT_GT(t.over, 0);
}

TEST(AiJudge, TenBallRulingsAreTheRules) {
  const Tally t = tie(rules_of(GameType::ten_ball), pool_state, 101);
  expect_covered(t);
  EXPECT_GT(t.over, 0);
}

TEST(AiJudge, SnookerRulingsAreTheRules) {
  const Tally t = tie(rules_of(GameType::snooker), snooker_state, 147);
  expect_covered(t);
}

}  // namespace test_ai_judge

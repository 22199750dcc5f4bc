// Pot maps (include/breakshot/pot_map.hpp): a level's chance of potting one
// ball in one pocket, with its own shot generation, shortlist, centred
// aims and noise, as its AI player (ai_player.cpp) plays a pot. What
// counts as a pot is the game's ruling of each play (counts_as_pot), so
// the same code serves every game with pockets.
//
// Determinism: every play is a unit whose seed comes from the position's
// seed and the play's index; parallel_map returns results in index order
// and they are combined in that order, so the numbers do not depend on
// the thread count.
#include "breakshot/pot_map.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/noise.hpp"
#include "evaluate.hpp"

namespace breakshot {

namespace {

using ai_detail::parallel_map;
using ai_detail::parallel_map_ws;

// Seed streams (ASCII of their names): the plays that choose the best
// shot and the fresh plays that measure it.
constexpr std::uint64_t kChooseStream = 0x63686f6f7365ULL;   // "choose"
constexpr std::uint64_t kMeasureStream = 0x6d656173757265ULL;  // "measure"

// Samples for a level that does not sample (the beginner).
constexpr int kDefaultSamples = 16;

void check_arguments(const Rules& rules, const GameState& state, int ball, int pocket,
                     const PotMapOptions& options) {
  const std::string game(to_string(rules.config().game));
  if (rules.table().pockets.empty()) {
    throw std::invalid_argument("pot maps need a table with pockets; " + game + " has none");
  }
  if (state.game != rules.config().game) {
    throw std::invalid_argument("the state is a " + std::string(to_string(state.game)) +
                                " state; the rules are " + game + "'s");
  }
  if (state.phase != Phase::shot) {
    throw std::invalid_argument("pot maps need a state with a shot to play (phase shot), not " +
                                std::string(to_string(state.phase)));
  }
  const int n = rules.ball_count();
  if (static_cast<int>(state.position.size()) != n || static_cast<int>(state.on_table.size()) != n) {
    throw std::invalid_argument("the state has " + std::to_string(state.position.size()) +
                                " ball positions; " + game + " has " + std::to_string(n) +
                                " balls");
  }
  if (ball < 1 || ball >= n) {
    throw std::invalid_argument("ball " + std::to_string(ball) + " is not an object ball of " +
                                game + " (1 to " + std::to_string(n - 1) + ")");
  }
  if (!state.on_table[static_cast<std::size_t>(ball)]) {
    throw std::invalid_argument("ball " + std::to_string(ball) + " is not on the table");
  }
  const int pockets = static_cast<int>(rules.table().pockets.size());
  if (pocket < 0 || pocket >= pockets) {
    throw std::invalid_argument("pocket " + std::to_string(pocket) + " is out of range (the table has " +
                                std::to_string(pockets) + " pockets, 0 to " +
                                std::to_string(pockets - 1) + ")");
  }
  if (options.samples < 0) throw std::invalid_argument("samples must be >= 0 (0: the level's own)");
  if (options.candidates < 0) {
    throw std::invalid_argument("candidates must be >= 0 (0: the level's own)");
  }
  if (options.threads < 0) throw std::invalid_argument("threads must be >= 0 (0: all cores)");
}

/// Plays `shot` from `state` with the strike perturbed under `seed`: did
/// `ball` drop in `pocket` as the game counts a pot?
bool pots(const Rules& rules, const GameState& state, const Shoot& shot, const NoiseModel& noise,
          std::uint64_t seed, int ball, int pocket, ShotWorkspace& work) {
  Shoot played = shot;
  played.strike = perturb(shot.strike, noise, rules.config().ball_radius, seed);
  return counts_as_pot(state, rules.apply(state, played, work), ball, pocket);
}

/// The shortlist, as the level makes it for pots: the best variant of
/// each line (kind, first ball) by prior before any second variant.
std::vector<CandidateShot> shortlist(std::vector<CandidateShot> cands, std::size_t n) {
  std::stable_sort(cands.begin(), cands.end(),
                   [](const CandidateShot& a, const CandidateShot& b) { return a.prior > b.prior; });
  if (cands.size() <= n) return cands;
  std::vector<CandidateShot> firsts;
  std::vector<CandidateShot> rest;
  for (const CandidateShot& c : cands) {
    const bool seen = std::any_of(firsts.begin(), firsts.end(), [&](const CandidateShot& f) {
      return f.kind == c.kind && f.first == c.first;
    });
    (seen ? rest : firsts).push_back(c);
  }
  firsts.insert(firsts.end(), rest.begin(), rest.end());
  firsts.resize(n);
  return firsts;
}

}  // namespace

bool counts_as_pot(const GameState& before, const Outcome& outcome, int ball, int pocket) {
  if (!outcome.ruling.fouls.empty()) return false;
  // A shot that ends the game is a pot only if the shooter won it.
  if (outcome.state.phase == Phase::game_over && outcome.state.winner != before.player) {
    return false;
  }
  const ShotFacts& f = outcome.facts;
  for (std::size_t i = 0; i < f.pocketed.size(); ++i) {
    if (f.pocketed[i] == ball && f.pocket_of[i] == pocket) return true;
  }
  return false;
}

PotChance pot_chance(const Rules& rules, const GameState& state, Vec2 cue, int ball, int pocket,
                     const AiLevel& level, const PotMapOptions& options) {
  check_arguments(rules, state, ball, pocket, options);
  PotChance res;

  // The cue ball where asked, placed as the rules place a ball in hand
  // anywhere (every game's check for that: the surface, the cushions, the
  // balls; snooker's D binds only BallInHand::d). Placed, the state has
  // no ball in hand and no kitchen shot.
  GameState in_hand = state;
  in_hand.on_table[0] = 0;
  in_hand.ball_in_hand = BallInHand::anywhere;
  in_hand.kitchen_shot = false;
  if (std::optional<std::string> why = rules.check_placement(in_hand, cue)) {
    res.unplaceable = std::move(*why);
    return res;
  }
  // The placement check lets a ball lie over the mouth of a pocket; a
  // ball whose centre is within a pocket's radius of its centre has
  // fallen in (the physics' test, and validate()'s for a scenario).
  for (const Pocket& p : rules.table().pockets) {
    if (norm(cue - p.centre) <= p.radius) {
      res.unplaceable = "the cue ball would lie inside pocket " + p.name;
      return res;
    }
  }
  res.placeable = true;
  const GameState s = rules.apply(in_hand, PlaceCueBall{cue}).state;

  ShotGenOptions gen = level.generation;
  gen.safeties = false;
  gen.only_ball = ball;
  gen.only_pocket = pocket;
  gen.leave_sigma_deg = ai_detail::estimate_sigma(level.noise);
  std::vector<CandidateShot> cands = generate_shots(rules, s, gen);
  std::erase_if(cands, [&](const CandidateShot& c) {
    return c.target != ball || c.pocket != pocket || rules.check(s, c.shot).has_value();
  });
  res.shots = static_cast<int>(cands.size());
  if (cands.empty()) return res;

  const int samples = options.samples > 0 ? options.samples
                      : level.samples > 0 ? level.samples
                                          : kDefaultSamples;
  const int wanted = options.candidates > 0 ? options.candidates : std::max(1, level.candidates);
  cands = shortlist(std::move(cands), static_cast<std::size_t>(wanted));
  if (level.centre_aim) {
    // Every candidate here is a pot of `ball` (target >= 0).
    ai_detail::add_centred_aims(rules, s, cands, options.threads);
  }

  // Choose: as the level samples, half the plays for every candidate,
  // then the rest for the best third (at least three), with common random
  // numbers; the best is the one that potted most often (ties: the first).
  const std::size_t n = cands.size();
  std::vector<int> hits(n, 0);
  std::vector<int> count(n, 0);
  const std::uint64_t choose_seed = mix_seed(options.seed, kChooseStream);
  const auto run = [&](const std::vector<std::size_t>& which, int from, int to) {
    const auto per = static_cast<std::size_t>(std::max(0, to - from));
    if (per == 0 || which.empty()) return;
    const std::vector<char> got =
        parallel_map_ws<char>(which.size() * per, options.threads, [&](std::size_t u, ShotWorkspace& ws) {
          const std::size_t c = which[u / per];
          const auto k = static_cast<std::uint64_t>(from) + u % per;
          return static_cast<char>(pots(rules, s, cands[c].shot, level.noise,
                                        mix_seed(choose_seed, k), ball, pocket, ws));
        });
    for (std::size_t u = 0; u < got.size(); ++u) {
      hits[which[u / per]] += got[u];
      count[which[u / per]] += 1;
    }
    res.simulations += static_cast<std::int64_t>(got.size());
  };
  const auto rate = [&](std::size_t c) {
    return count[c] > 0 ? static_cast<double>(hits[c]) / count[c] : -1.0;
  };
  std::size_t best = 0;
  if (n > 1) {
    std::vector<std::size_t> all(n);
    std::iota(all.begin(), all.end(), std::size_t{0});
    const int first = std::max(1, (samples + 1) / 2);
    run(all, 0, first);
    if (samples > first) {
      std::vector<std::size_t> top = all;
      std::stable_sort(top.begin(), top.end(),
                       [&](std::size_t a, std::size_t b) { return rate(a) > rate(b); });
      top.resize(std::min(n, std::max<std::size_t>(3, (n + 2) / 3)));
      std::sort(top.begin(), top.end());
      run(top, first, samples);
    }
    for (std::size_t c = 1; c < n; ++c) {
      if (rate(c) > rate(best)) best = c;
    }
  }

  // Measure the chosen shot on fresh draws.
  const std::uint64_t measure_seed = mix_seed(options.seed, kMeasureStream);
  const Shoot chosen = cands[best].shot;
  const std::vector<char> got =
      parallel_map_ws<char>(static_cast<std::size_t>(samples), options.threads, [&](std::size_t k, ShotWorkspace& ws) {
        return static_cast<char>(
            pots(rules, s, chosen, level.noise, mix_seed(measure_seed, k), ball, pocket, ws));
      });
  const int made = static_cast<int>(std::count(got.begin(), got.end(), char{1}));
  res.simulations += samples;
  res.plays = samples;
  res.probability = static_cast<double>(made) / samples;
  res.aim = chosen.strike;
  res.kind = cands[best].kind;
  return res;
}

PotMap pot_map(const Rules& rules, const GameState& state, int ball, int pocket,
               const AiLevel& level, const std::vector<double>& xs, const std::vector<double>& ys,
               const PotMapOptions& options) {
  check_arguments(rules, state, ball, pocket, options);
  if (xs.empty() || ys.empty()) {
    throw std::invalid_argument("the grid is empty (" + std::to_string(xs.size()) + " x " +
                                std::to_string(ys.size()) + " points)");
  }
  for (const std::vector<double>* v : {&xs, &ys}) {
    for (double c : *v) {
      if (!std::isfinite(c)) {
        throw std::invalid_argument(std::string(v == &xs ? "xs" : "ys") +
                                    " holds a coordinate that is not a finite number");
      }
    }
  }
  PotMap map;
  map.xs = xs;
  map.ys = ys;
  PotMapOptions cell = options;
  cell.threads = 1;
  map.cells = parallel_map<PotChance>(xs.size() * ys.size(), options.threads, [&](std::size_t k) {
    PotMapOptions o = cell;
    o.seed = mix_seed(options.seed, static_cast<std::uint64_t>(k));
    return pot_chance(rules, state, Vec2{xs[k % xs.size()], ys[k / xs.size()]}, ball, pocket,
                      level, o);
  });
  return map;
}

}  // namespace breakshot

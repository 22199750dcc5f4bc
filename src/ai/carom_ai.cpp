// The AI levels' three-cushion decisions (carom_ai.hpp; docs/ai.md,
// "Three-cushion").
//
// 1. Starting aims from geometry. In the unfolded table of ball centres
//    (the mirror construction, baseline_carom.hpp) every straight line is
//    a frictionless path without spin, and the paths the diamond systems
//    describe are such lines: a ball-first shot departs from the first
//    object ball F toward an image of the second, S, three to five
//    cushions away (around the table, reverse, umbrella, double-the-rail
//    are images in different directions); a cushion-first shot ("bank")
//    reaches an image of F after one to three cushions and departs from
//    it toward an image of S, so that the cushions before F and after it
//    add up to three or more. For each image the contacts on F from which
//    a rolling cue ball departs along the line give an aim; its speed is
//    the least that brings the cue ball to S with some pace left. The
//    aims are ranked easiest first (short paths, few cushions, cuts near
//    half-ball) and near-duplicates dropped.
// 2. Refinement on the engine: the best starting aims are each played
//    without noise (Rules::apply) at a few speeds and side spins, the aim
//    swept in fine steps around the starting one. Consecutive aims that
//    score form an interval; its edges are bisected and its middle is the
//    aim, so that an aim error has the most room on both sides. Wider
//    intervals rank higher.
// 3. Evaluation under noise: the best intervals are played `samples`
//    times with the strike perturbed by the player's own noise, every
//    candidate with the same seeds (common random numbers). A sample that
//    scores is worth 1 (the inning goes on); at the top level also the
//    leave: the geometric ease of the next shot for the shooter, and
//    after a miss minus the ease of the opponent's shot (defence). The
//    best mean wins.
//
// Determinism: the simulations are units of a parallel map with seeds from
// the decision seed and the sample index only, combined in index order.
// A simulation budget (AiLevel::simulation_budget) shrinks the search
// before it starts (fewer starting aims, then fewer samples); a time
// budget is not read.
#include "carom_ai.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "baseline_carom.hpp"
#include "physics/detmath.hpp"
#include "breakshot/noise.hpp"
#include "evaluate.hpp"
#include "geometry.hpp"

namespace breakshot::ai_detail {

namespace {

using ai::kDeg;
using ai::kGravity;
using ai::kRollingFriction;

constexpr std::uint64_t kCaromStream = 0x6361726f6dULL;  // "carom"

/// Speed kept per cushion, pace wanted at the second ball (m/s) and the
/// cue ball's speed per unit of cue speed: the baseline's speed estimate.
constexpr double kCushionKeep = 0.8;
constexpr double kArrival = 0.5;
constexpr double kLaunch = 2.0 / (1.0 + 0.210 / 0.567);
constexpr double kMaxSpeed = 10.0;

/// The top level's leave terms: what the next shot's ease adds to a point
/// and what the opponent's ease takes from a miss.
constexpr double kLeaveWeight = 0.3;
constexpr double kDefenceWeight = 0.3;

/// One level's search.
struct CaromSearch {
  int max_rails = 4;           ///< most cushions of a path
  bool cushion_first = false;  ///< bank shots too
  int starts = 6;              ///< starting aims refined
  std::vector<double> speed_scales{1.0};
  std::vector<double> sides{0.0};  ///< side spin (a, fraction of R)
  double follow = 0.0;             ///< tip height (b)
  double half_width = 2.0;         ///< degrees swept either side
  double step = 0.4;               ///< degrees
  int bisections = 0;              ///< of each interval's edges
  int sampled = 0;                 ///< candidates sampled (0: the widest interval)
  int samples = 0;
  bool position = false;  ///< leave and defence terms
};

CaromSearch search_of(const AiLevel& level) {
  CaromSearch s;
  if (level.name == "beginner") {
    return s;
  }
  if (level.name == "amateur") {
    s.starts = 8;
    s.speed_scales = {1.0, 1.3};
    s.half_width = 2.5;
    s.step = 0.3;
    s.bisections = 2;
    s.sampled = 4;
    s.samples = 8;
    return s;
  }
  if (level.name == "club") {
    s.cushion_first = true;
    s.starts = 10;
    s.speed_scales = {0.9, 1.25};
    s.sides = {0.0, 0.3};
    s.half_width = 2.5;
    s.step = 0.25;
    s.bisections = 3;
    s.sampled = 6;
    s.samples = 12;
    return s;
  }
  if (level.name == "expert") {
    s.max_rails = 5;
    s.cushion_first = true;
    s.starts = 14;
    s.speed_scales = {0.85, 1.1, 1.4};
    s.sides = {-0.3, 0.0, 0.3};
    s.half_width = 3.0;
    s.step = 0.25;
    s.bisections = 4;
    s.sampled = 8;
    s.samples = 20;
    return s;
  }
  // champion, and any other level built from ai_level's fields.
  s.max_rails = 5;
  s.cushion_first = true;
  s.starts = 18;
  s.speed_scales = {0.85, 1.1, 1.4};
  s.sides = {-0.3, 0.0, 0.3};
  s.half_width = 3.0;
  s.step = 0.2;
  s.bisections = 4;
  s.sampled = 10;
  s.samples = 32;
  s.position = true;
  return s;
}

/// Shrinks `s` until its refinement sweep and its samples fit `budget`
/// simulations (the bisections are few and not counted): fewer starting
/// aims first, then fewer samples.
void fit_budget(CaromSearch& s, std::int64_t budget) {
  const auto offsets = [&] { return 2 * std::lround(s.half_width / s.step) + 1; };
  const auto sweep = [&] {
    return static_cast<std::int64_t>(s.starts) * static_cast<std::int64_t>(s.speed_scales.size()) *
           static_cast<std::int64_t>(s.sides.size()) * offsets();
  };
  const auto sampling = [&] { return static_cast<std::int64_t>(s.sampled) * s.samples; };
  while (s.starts > 1 && sweep() + sampling() > budget) --s.starts;
  while (s.samples > 1 && sweep() + sampling() > budget) --s.samples;
}

double phi_of(Vec2 d) { return dm::atan2(d.y, d.x) / kDeg; }

struct Start {
  double phi = 0.0;    // degrees
  double speed = 0.0;  // cue speed, m/s
  double cost = 0.0;   // lower is easier
};

/// The starting aims for the player to act in `state`, easiest first.
std::vector<Start> starting_aims(const Rules& rules, const GameState& state, int max_rails,
                                 bool cushion_first, int steps) {
  const Table& table = rules.table();
  const double R = rules.config().ball_radius;
  const int own = rules.cue_ball(state);
  const Vec2 C = state.position[static_cast<std::size_t>(own)];
  const Vec2 lo{R, R};
  const Vec2 hi{table.length - R, table.width - R};
  std::vector<int> objects;
  for (int b = 0; b < rules.ball_count(); ++b) {
    if (b != own) objects.push_back(b);
  }
  std::vector<Start> out;
  for (const int f : rules.targets(state)) {
    const int s = objects[0] == f ? objects[1] : objects[0];
    const Vec2 F = state.position[static_cast<std::size_t>(f)];
    const Vec2 S = state.position[static_cast<std::size_t>(s)];
    const int first_most = cushion_first ? 3 : 0;
    for (int i1 = -first_most; i1 <= first_most; ++i1) {
      for (int j1 = -first_most; j1 <= first_most; ++j1) {
        const int before = std::abs(i1) + std::abs(j1);
        if (before > first_most) continue;
        const Vec2 Fi = ai::carom_image(F, lo, hi, i1, j1);
        for (int i = i1 - max_rails; i <= i1 + max_rails; ++i) {
          for (int j = j1 - max_rails; j <= j1 + max_rails; ++j) {
            const int after = std::abs(i - i1) + std::abs(j - j1);
            const int rails = before + after;
            if (rails < 3 || rails > max_rails) continue;
            const Vec2 target = ai::carom_image(S, lo, hi, i, j);
            for (const double a : ai::carom_contact_angles(C, Fi, target, R, steps)) {
              Vec2 n{0.0, 0.0};
              dm::sincos(a, n.y, n.x);
              const Vec2 G = Fi - n * (2.0 * R);
              if (before == 0) {
                if (G.x < lo.x || G.x > hi.x || G.y < lo.y || G.y > hi.y) continue;
                if (segment_distance(S, C, G) < 2.0 * R + ai::kBallMargin) continue;
              }
              const double l1 = norm(G - C);
              if (l1 < 1e-6) continue;
              const Vec2 u = (G - C) / l1;
              const double full = dot(u, n);
              if (full > 0.97) continue;  // the cue ball would stop on F
              const double keep = norm(ai::carom_departure(u, n));
              const double l2 = norm(target - G);
              double need = std::sqrt(kArrival * kArrival + 2.0 * kRollingFriction * kGravity * l2);
              for (int r = 0; r < after; ++r) need /= kCushionKeep;
              double at_contact = need / keep;
              double launch2 = at_contact * at_contact + 2.0 * kRollingFriction * kGravity * l1;
              for (int r = 0; r < before; ++r) launch2 /= kCushionKeep * kCushionKeep;
              const double launch = std::sqrt(launch2) / (5.0 / 7.0);
              Start st;
              st.phi = phi_of(G - C);
              st.speed = std::clamp(launch / kLaunch, 1.5, 8.0);
              st.cost = l1 + l2 + 0.5 * (rails - 3) + 2.0 * std::abs(full - 0.5) + 0.3 * before;
              out.push_back(st);
            }
          }
        }
      }
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Start& x, const Start& y) { return x.cost < y.cost; });
  return out;
}

/// How easy the next shot of the player to act in `state` looks, in
/// [0, 1]: the easiest ball-first starting aim's cost read on a scale
/// where a short half-ball three-cushion path is about 1.
double ease(const Rules& rules, const GameState& state) {
  if (state.phase == Phase::game_over) return 0.0;
  const std::vector<Start> s = starting_aims(rules, state, 4, false, 90);
  if (s.empty()) return 0.0;
  return std::clamp(dm::exp(-(s.front().cost - 3.0) / 1.5), 0.0, 1.0);
}

Shoot make_shot(double phi, double speed, double side, double follow) {
  Shoot s;
  s.strike.phi = phi;
  s.strike.speed = std::min(speed, kMaxSpeed);
  s.strike.a = side;
  s.strike.b = follow;
  return s;
}

bool scores(const Rules& rules, const GameState& state, const Shoot& shot) {
  const Outcome o = rules.apply(state, Action{shot});
  return o.ruling.carom && o.ruling.carom->point && o.ruling.fouls.empty();
}

/// A way to score found on the engine: an interval of aims at one speed
/// and spin.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  double speed = 0.0;
  double side = 0.0;
  double width() const { return hi - lo; }
};

}  // namespace

Action carom_action(const AiLevel& level, const Rules& rules, const GameState& state,
                    std::uint64_t seed) {
  CaromSearch search = search_of(level);
  if (level.simulation_budget > 0) fit_budget(search, level.simulation_budget);
  const int threads = level.threads;
  std::vector<Start> starts =
      starting_aims(rules, state, search.max_rails, search.cushion_first, 360);
  if (starts.empty()) {
    // Nothing geometric: straight at the first legal ball.
    const int own = rules.cue_ball(state);
    const int f = rules.targets(state).front();
    return make_shot(phi_of(state.position[static_cast<std::size_t>(f)] -
                            state.position[static_cast<std::size_t>(own)]),
                     3.0, 0.0, search.follow);
  }
  // Drop near-duplicates (aims the sweep of an earlier one covers).
  std::vector<Start> kept;
  for (const Start& s : starts) {
    if (static_cast<int>(kept.size()) >= search.starts) break;
    const bool near = std::any_of(kept.begin(), kept.end(), [&](const Start& k) {
      return std::abs(k.phi - s.phi) < search.half_width && std::abs(k.speed - s.speed) < 0.5;
    });
    if (!near) kept.push_back(s);
  }

  // Refinement: every start x speed x side x aim offset, without noise.
  const int offsets = 2 * static_cast<int>(std::lround(search.half_width / search.step)) + 1;
  const std::size_t speeds = search.speed_scales.size();
  const std::size_t sides = search.sides.size();
  const std::size_t configs = kept.size() * speeds * sides;
  const auto config_shot = [&](std::size_t c, double phi) {
    const Start& st = kept[c / (speeds * sides)];
    const double scale = search.speed_scales[(c / sides) % speeds];
    const double side = search.sides[c % sides];
    return make_shot(phi, st.speed * scale, side, search.follow);
  };
  const auto aim_of = [&](std::size_t c, int k) {
    const Start& st = kept[c / (speeds * sides)];
    return st.phi + (k - offsets / 2) * search.step;
  };
  const std::vector<char> hit =
      parallel_map<char>(configs * static_cast<std::size_t>(offsets), threads, [&](std::size_t u) {
        const std::size_t c = u / static_cast<std::size_t>(offsets);
        const int k = static_cast<int>(u % static_cast<std::size_t>(offsets));
        return static_cast<char>(scores(rules, state, config_shot(c, aim_of(c, k))));
      });
  // Intervals: runs of scoring aims.
  std::vector<Interval> found;
  std::vector<std::size_t> found_config;
  for (std::size_t c = 0; c < configs; ++c) {
    int k = 0;
    while (k < offsets) {
      if (!hit[c * static_cast<std::size_t>(offsets) + static_cast<std::size_t>(k)]) {
        ++k;
        continue;
      }
      int e = k;
      while (e + 1 < offsets &&
             hit[c * static_cast<std::size_t>(offsets) + static_cast<std::size_t>(e + 1)])
        ++e;
      Interval iv;
      iv.lo = aim_of(c, k);
      iv.hi = aim_of(c, e);
      const Shoot probe = config_shot(c, 0.0);
      iv.speed = probe.strike.speed;
      iv.side = probe.strike.a;
      found.push_back(iv);
      found_config.push_back(c);
      k = e + 1;
    }
  }
  // Edges bisected between the last aim that scores and the next that
  // does not (or the sweep's end).
  if (search.bisections > 0 && !found.empty()) {
    const std::size_t n = found.size();
    found = parallel_map<Interval>(n, threads, [&](std::size_t i) {
      Interval iv = found[i];
      for (int side = 0; side < 2; ++side) {
        double in = side == 0 ? iv.lo : iv.hi;
        double out = in + (side == 0 ? -search.step : search.step);
        for (int b = 0; b < search.bisections; ++b) {
          const double mid = 0.5 * (in + out);
          if (scores(rules, state, make_shot(mid, iv.speed, iv.side, search.follow))) {
            in = mid;
          } else {
            out = mid;
          }
        }
        (side == 0 ? iv.lo : iv.hi) = in;
      }
      return iv;
    });
  }
  std::vector<std::size_t> order(found.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return found[x].width() > found[y].width();
  });

  std::vector<Shoot> cands;
  for (const std::size_t i : order) {
    const Interval& iv = found[i];
    cands.push_back(make_shot(0.5 * (iv.lo + iv.hi), iv.speed, iv.side, search.follow));
  }
  if (search.sampled <= 0 || search.samples <= 0) {
    if (!cands.empty()) return cands.front();
    return make_shot(kept.front().phi, kept.front().speed, 0.0, search.follow);
  }
  // Too few ways to score: the easiest geometric aims fill the list (they
  // may score now and then, and at the top level they are read for the
  // table they hand over).
  for (std::size_t k = 0; k < kept.size() && static_cast<int>(cands.size()) < search.sampled; ++k) {
    cands.push_back(make_shot(kept[k].phi, kept[k].speed, 0.0, search.follow));
  }
  if (static_cast<int>(cands.size()) > search.sampled) {
    cands.resize(static_cast<std::size_t>(search.sampled));
  }

  // Evaluation under the player's noise, common random numbers.
  const std::uint64_t base = mix_seed(seed, kCaromStream);
  const std::size_t m = static_cast<std::size_t>(search.samples);
  const double R = rules.config().ball_radius;
  const std::vector<double> values =
      parallel_map_ws<double>(cands.size() * m, threads, [&](std::size_t u, ShotWorkspace& ws) {
        const std::size_t c = u / m;
        const std::size_t j = u % m;
        Shoot played = cands[c];
        played.strike = perturb(cands[c].strike, level.noise, R, mix_seed(base, j));
        const Outcome o = rules.apply(state, Action{played}, ws);
        const bool point = o.ruling.carom && o.ruling.carom->point && o.ruling.fouls.empty();
        if (!search.position) return point ? 1.0 : 0.0;
        if (point) return 1.0 + kLeaveWeight * ease(rules, o.state);
        return -kDefenceWeight * ease(rules, o.state);
      });
  std::size_t best = 0;
  double best_value = -1e300;
  for (std::size_t c = 0; c < cands.size(); ++c) {
    double sum = 0.0;
    for (std::size_t j = 0; j < m; ++j) sum += values[c * m + j];
    if (sum > best_value) {
      best_value = sum;
      best = c;
    }
  }
  return cands[best];
}

}  // namespace breakshot::ai_detail

// The break (ai_player.hpp): the pool games' break, placements in the
// kitchen, aims at the head ball and speeds, sampled with seeds from the
// rack; and snooker's break-off, the place in the D chosen from a fixed
// set.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "ai_player.hpp"
#include "breakshot/snooker.hpp"

namespace breakshot::ai_detail {

namespace {

constexpr double kBreakSpeedSoft = 8.5;  // m/s
constexpr double kBreakSpeedHard = 11.0;
constexpr double kBreakSpeedMedium = 10.0;
constexpr double kBreakSpeedNine = 12.0;
constexpr double kBreakDraw = -0.2;  // a little draw keeps the cue ball near the centre

}  // namespace

/// The break: for a few placements in the kitchen, aims at the head
/// ball (full and slightly to either side) and two speeds, the option
/// whose samples are worth most. The cue ball is placed first when it is
/// not already there; the next call finds it there and shoots. The
/// samples' seeds come from the rack, not the decision seed, and the
/// options from the table and the rack, not the cue ball's position, so
/// that both calls see the same evaluation and agree.
Action AiPlayer::break_action(const Rules& rules, const GameState& state, const LegalActions& la,
                              Budget& budget) const {
  const Table& table = rules.table();
  // The head ball: the 1 in 9-ball (the only legal first ball), else
  // the object ball nearest the head rail.
  int apex = -1;
  if (ai_detail::game_policy(state.game).rotation && !la.targets.empty()) {
    apex = la.targets.front();
  } else {
    for (std::size_t b = 1; b < state.on_table.size(); ++b) {
      if (state.on_table[b] &&
          (apex < 0 || state.position[b].x < state.position[static_cast<std::size_t>(apex)].x)) {
        apex = static_cast<int>(b);
      }
    }
  }
  const Vec2 target = apex > 0 ? state.position[static_cast<std::size_t>(apex)] : table.foot_spot;
  const double R = rules.config().ball_radius;

  struct Option {
    Vec2 place;
    Shoot shot;
  };
  std::vector<Option> options;
  std::vector<double> offsets{0.0};
  std::vector<double> speeds{kBreakSpeedHard};
  std::vector<double> spread{0.0};
  std::vector<double> draws{kBreakDraw};
  if (searches()) {
    offsets = {0.0, -0.2, 0.2};
    speeds = {kBreakSpeedSoft, kBreakSpeedHard};
    spread = level_.candidates >= 8 ? std::vector<double>{0.0, -0.25, 0.25, -0.45, 0.45}
                                    : std::vector<double>{0.0, -0.3, 0.3};
  }
  if (level_.lookahead) {
    // The strongest level searches the break finely: from the side of
    // the kitchen, a fraction of a ball off the head ball's centre, at
    // about 10-11 m/s with a centre hit keeps the cue ball and drops a
    // ball most often (about 0.85 of 8-ball racks under tournament
    // noise, measured on the engine, against 0.7 at the head spot).
    offsets = {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3};
    // 9-ball's diamond wants a little more pace (11-12 m/s).
    speeds = ai_detail::game_policy(state.game).rotation
                 ? std::vector<double>{kBreakSpeedHard, kBreakSpeedNine}
                 : std::vector<double>{kBreakSpeedMedium, kBreakSpeedHard};
    spread = {0.0, -0.45, 0.45, -0.25, 0.25};
    draws = {0.0, kBreakDraw};
  }
  GameState probe = state;
  probe.on_table[0] = 0;  // the cue ball's current place must not block a placement
  for (double dy : spread) {
    const Vec2 p{rules.head_string(), table.head_spot.y + dy};
    if (rules.check_placement(probe, p)) continue;
    for (double off : offsets) {
      // Aim a fraction of a ball to one side of the head ball's centre.
      const Vec2 d = (target - p) / norm(target - p);
      const Vec2 aim = target + perp(d) * (off * R);
      for (double v : speeds) {
        for (double b : draws) options.push_back(Option{p, make_shoot(aim_deg(p, aim), v, b)});
      }
    }
  }
  if (options.empty()) {
    // Nowhere on the head string is free: play from where it lies, or
    // put it on the first free point of the kitchen.
    if (!la.must_place) return make_shoot(aim_deg(state.position[0], target), kBreakSpeedHard);
    const std::vector<Vec2> free = placements(rules, state, la);
    return PlaceCueBall{free.empty() ? table.head_spot : free.front()};
  }

  std::size_t best = 0;
  if (options.size() > 1) {
    // At most 32 each on average: the strongest level has over a hundred
    // options. The other levels sample each option alike; the strongest
    // spends its samples in rounds that halve the options (successive
    // halving): every option gets eight samples, the better half six
    // more, the better quarter thirteen, and so on, so that the option
    // chosen is read from about six hundred samples instead of being the
    // luckiest of 140 at 32 each. On 300 racks (bench/run_probe --break-only) its 8-ball break
    // kept the table 233 times against 217, its 9-ball break 231 against
    // 215 (docs/ai.md). Sample k of every option shares its noise seed
    // (common random numbers).
    const int samples = std::clamp(level_.samples / 2, 4, 32);
    const std::int64_t want = static_cast<std::int64_t>(options.size()) * samples;
    std::int64_t left = budget.take(want);
    const std::uint64_t break_seed =
        mix_seed(mix_seed(state.rack_seed, kBreakStream), static_cast<std::uint64_t>(state.racks));
    std::vector<std::size_t> alive(options.size());
    for (std::size_t i = 0; i < alive.size(); ++i) alive[i] = i;
    std::vector<double> sum(options.size(), 0.0);
    std::size_t taken = 0;  // samples each survivor has had
    int rounds = 1;
    if (level_.lookahead) {
      rounds = 0;
      for (std::size_t n = options.size(); n > 1; n = (n + 1) / 2) ++rounds;
    }
    const std::int64_t first =
        rounds == 1
            ? want
            : std::max<std::int64_t>(
                  want / rounds, static_cast<std::int64_t>(options.size()) * std::min(samples, 8));
    for (int round = 0; alive.size() > 1 && left >= static_cast<std::int64_t>(alive.size());
         ++round) {
      const std::int64_t share =
          round == 0 ? std::min(first, left)
                     : std::min(left, (left + rounds - round - 1) / std::max(1, rounds - round));
      const std::size_t per = static_cast<std::size_t>(
          std::max<std::int64_t>(1, share / static_cast<std::int64_t>(alive.size())));
      left -= static_cast<std::int64_t>(per * alive.size());
      const std::vector<double> res = parallel_map_ws<double>(
          alive.size() * per, level_.threads, [&](std::size_t u, ShotWorkspace& ws) {
            const Option& o = options[alive[u / per]];
            GameState placed = state;
            placed.position[0] = o.place;
            placed.on_table[0] = 1;
            return sample_shot(rules, placed, o.shot, level_.noise,
                               mix_seed(break_seed, static_cast<std::uint64_t>(taken + u % per)),
                               sigma_, nullptr, nullptr, &ws);
          });
      for (std::size_t j = 0; j < alive.size(); ++j) {
        for (std::size_t k = 0; k < per; ++k) sum[alive[j]] += res[j * per + k];
      }
      taken += per;
      // The better half goes on (ties to the earlier option); with one
      // round, the best.
      std::stable_sort(alive.begin(), alive.end(),
                       [&](std::size_t x, std::size_t y) { return sum[x] > sum[y]; });
      alive.resize(rounds == 1 ? 1 : (alive.size() + 1) / 2);
    }
    if (taken > 0) best = alive.front();
  }
  const Option& o = options[best];
  if (state.on_table[0] && state.position[0] == o.place) return o.shot;
  return PlaceCueBall{o.place};
}

/// Snooker's break-off: the cue ball may be placed in the D again and
/// again until the stroke, so the place is chosen from a fixed set (six
/// points of the baulk line, the break-off spot first) with seeds from
/// the rack, never from the decision or the cue ball's position: the
/// call that places the cue ball and the call that then finds it there
/// choose the same place, and the second shoots. Each place is searched
/// with half the effort of a shot decision; the shot itself is then
/// chosen as any shot.
Action AiPlayer::break_off(const Rules& rules, const GameState& state, const LegalActions& la,
                           std::uint64_t seed, Budget& budget) const {
  const SnookerMarks m = snooker_marks();
  std::vector<Vec2> spots;
  for (const double f : {-0.5, 0.5, -0.25, 0.25, -0.75, 0.75}) {
    const Vec2 p{m.baulk_x, m.d_centre.y + f * m.d_radius};
    if (!rules.check_placement(state, p)) spots.push_back(p);
  }
  if (spots.empty()) return shot_action(rules, state, la, seed, budget);
  std::size_t best = 0;
  if (searches()) {
    const std::uint64_t place_seed = mix_seed(state.rack_seed, kBreakOffStream);
    double best_value = kNoValue;
    for (std::size_t i = 0; i < spots.size(); ++i) {
      const GameState placed = rules.apply(state, PlaceCueBall{spots[i]}).state;
      const double v = best_shot(rules, placed, mix_seed(place_seed, i), 0.5, budget).value;
      if (v > best_value) {
        best_value = v;
        best = i;
      }
    }
  }
  if (state.on_table[0] && norm(state.position[0] - spots[best]) < 1e-9) {
    return shot_action(rules, state, la, seed, budget);
  }
  return PlaceCueBall{spots[best]};
}

}  // namespace breakshot::ai_detail

// Cue ball in hand (ai_player.hpp): the placements tried, ranked by the
// geometric estimate of the best pot from each, the best few searched in
// full against shooting from where the ball lies.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "ai_player.hpp"
#include "breakshot/snooker.hpp"

namespace breakshot::ai_detail {

namespace {

// A placement or a candidate needs to beat staying put by this much, so
// that the placement decision settles.
constexpr double kStayMargin = 0.02;

using ai::kDeg;

Vec2 rotate(Vec2 v, double rad) {
  double s = 0.0;
  double c = 0.0;
  dm::sincos(rad, s, c);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

}  // namespace

/// Places the cue ball where the best shot is best, or shoots from where
/// it lies when that is as good. Placing ends the ball in hand (the
/// rules), so the next call chooses the shot from the placed ball.
Action AiPlayer::placement_or_shot(const Rules& rules, const GameState& state,
                                   const LegalActions& la, std::uint64_t seed,
                                   Budget& budget) const {
  const bool kitchen = la.place == BallInHand::kitchen;
  struct Spot {
    Vec2 p;
    double score;
    bool here;
  };
  std::vector<Spot> spots;
  for (const Vec2 p : placements(rules, state, la)) {
    spots.push_back(Spot{p, best_pot_estimate_from(rules, state, p, kitchen, sigma_), false});
  }
  if (!la.must_place) {
    spots.push_back(Spot{state.position[0], best_pot_estimate(rules, state, sigma_), true});
  }
  std::stable_sort(spots.begin(), spots.end(),
                   [](const Spot& a, const Spot& b) { return a.score > b.score; });
  if (spots.empty()) return PlaceCueBall{rules.table().head_spot};  // check() will say why
  // The best few, kept apart so that they are different tables.
  const std::size_t want = searches() ? (level_.lookahead ? 4 : 3) : 1;
  std::vector<Spot> pick;
  for (const Spot& s : spots) {
    if (pick.size() >= want) break;
    const bool near = std::any_of(pick.begin(), pick.end(),
                                  [&](const Spot& q) { return norm(q.p - s.p) < 0.06; });
    if (!near) pick.push_back(s);
  }
  const auto here_it = std::find_if(spots.begin(), spots.end(), [](const Spot& s) { return s.here; });
  if (!searches()) {
    if (here_it != spots.end() && here_it->score + kStayMargin >= pick.front().score) {
      return shot_action(rules, state, la, seed, budget);
    }
    return PlaceCueBall{pick.front().p};
  }
  if (here_it != spots.end() &&
      std::none_of(pick.begin(), pick.end(), [](const Spot& s) { return s.here; })) {
    pick.push_back(*here_it);  // staying put is always compared
  }
  // Each placement searched with half the effort of a shot decision.
  double best_value = kNoValue;
  std::size_t best = 0;
  for (std::size_t i = 0; i < pick.size(); ++i) {
    if (i > 0 && budget.past(0.5)) break;
    GameState placed = state;
    if (!pick[i].here) placed = rules.apply(state, PlaceCueBall{pick[i].p}).state;
    const Evaluated c = best_shot(rules, placed, mix_seed(mix_seed(seed, kPlaceStream), i), 0.5, budget);
    const double v = c.value + (pick[i].here ? kStayMargin : 0.0);
    if (v > best_value) {
      best_value = v;
      best = i;
    }
  }
  if (pick[best].here) return shot_action(rules, state, la, seed, budget);
  return PlaceCueBall{pick[best].p};
}

/// Where the cue ball may go: behind each legal ball on its line to each
/// pocket (straight and at slight cuts, near and farther back), and a
/// 10 cm grid, all checked with Rules::check_placement.
std::vector<Vec2> AiPlayer::placements(const Rules& rules, const GameState& state,
                                       const LegalActions& la) {
  const double R = rules.config().ball_radius;
  const bool kitchen = la.place == BallInHand::kitchen;
  const double head = rules.head_string();
  std::vector<Vec2> out;
  const auto add = [&](Vec2 p) {
    if (!rules.check_placement(state, p)) out.push_back(p);
  };
  for (int t : la.targets) {
    const Vec2 b = state.position[static_cast<std::size_t>(t)];
    if (kitchen && b.x <= head) continue;
    for (const Pocket& pk : rules.table().pockets) {
      const Vec2 u = (pk.centre - b) / norm(pk.centre - b);
      const Vec2 ghost = b - u * (2.0 * R);
      for (double angle : {0.0, 15.0, -15.0}) {
        const Vec2 back = rotate(u, angle * kDeg);
        for (double dist : {0.1, 0.22, 0.4}) add(ghost - back * dist);
      }
    }
  }
  const Table& table = rules.table();
  if (la.place == BallInHand::d) {
    // Snooker's D: a 4 cm grid over it (check_placement keeps what lies
    // inside).
    const SnookerMarks m = snooker_marks();
    for (double x = m.baulk_x - m.d_radius; x <= m.baulk_x + 1e-9; x += 0.04) {
      for (double y = m.d_centre.y - m.d_radius; y <= m.d_centre.y + m.d_radius + 1e-9; y += 0.04) {
        add({x, y});
      }
    }
    add({m.baulk_x, m.d_centre.y - 0.5 * m.d_radius});  // the break-off spot
    return out;
  }
  for (double x = 0.05; x < table.length; x += 0.1) {
    if (kitchen && x > head) break;
    for (double y = 0.05; y < table.width; y += 0.1) add({x, y});
  }
  return out;
}

}  // namespace breakshot::ai_detail

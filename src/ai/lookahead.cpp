// The lookahead (ai_player.hpp; champion): the tables the best
// candidates' samples left, read a shot deeper, correct their values.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "ai_player.hpp"

namespace breakshot::ai_detail {

namespace {

/// Options for shots searched inside another search (the lookahead): pots
/// only, few variants, so that a table can be read in a few milliseconds.
ShotGenOptions lookahead_generation(const ShotGenOptions& base) {
  ShotGenOptions o = base;
  o.banks = false;
  o.kicks = false;
  o.combinations = false;
  o.safeties = false;
  o.jumps = false;
  o.speed_factors = {1.0, 1.7};
  o.spins = {-0.3, 0.0, 0.3};
  o.sides = {};
  o.refine_iterations = std::min(base.refine_iterations, 2);
  o.max_candidates = 24;
  return o;
}

}  // namespace

/// Corrects value[c] for each c in `top`: for up to kStates of the
/// tables its samples left with a shot to play from where the cue ball
/// lies (the player's own next shot, or the opponent's after a miss or
/// a safety), the shooter's best few pots there are sampled, with the
/// static value of playing safe (the table with no pot) as a floor. The
/// mean difference between that and the static value of those tables,
/// times the share of samples that left such a table, is added. So the
/// cue ball's leave (position play) and what a safety really leaves the
/// opponent are both read by sampling rather than by the quick estimate.
void AiPlayer::lookahead(const Rules& rules, const GameState& state, std::uint64_t seed,
                         const std::vector<std::size_t>& top,
                         const std::vector<std::vector<GameState>>& left,
                         const std::vector<int>& count, std::vector<double>& value,
                         Budget& budget) const {
  const std::size_t kStates = static_cast<std::size_t>(lookahead_depth(level_, state.game).states);
  constexpr std::size_t kNext = 3;
  const int next_samples = std::max(4, level_.samples / 6);
  const int me = state.player;
  struct Unit {
    std::size_t cand;
    const GameState* table;
  };
  std::vector<Unit> units;
  std::vector<int> readable(value.size(), 0);
  for (std::size_t c : top) {
    std::size_t taken = 0;
    for (const GameState& g : left[c]) {
      const bool shot = g.phase == Phase::shot && g.ball_in_hand == BallInHand::none &&
                        g.on_table[0];
      if (!shot) continue;
      ++readable[c];
      if (taken < kStates) {
        units.push_back(Unit{c, &g});
        ++taken;
      }
    }
  }
  if (units.empty()) return;
  const std::int64_t want = static_cast<std::int64_t>(units.size() * kNext) * next_samples;
  if (budget.take(want) < want) return;  // all or nothing: a partial correction would be uneven
  const ShotGenOptions gen = lookahead_generation(generation(state.game));
  const std::uint64_t look_seed = mix_seed(seed, kLookStream);
  const std::vector<double> delta = parallel_map_ws<double>(units.size(), level_.threads, [&](std::size_t u, ShotWorkspace& ws) {
    const GameState& g = *units[u].table;
    const int shooter = g.player;
    const double stat = position_value(rules, g, shooter, sigma_);
    // Playing safe: the static value without the pot.
    const double safe =
        ai_detail::game_policy(g.game).frame_scoring
            ? ai_detail::snooker_position_value(rules, g, shooter, sigma_, true)
            : stat - ai_detail::kShooterGain * best_pot_estimate(rules, g, sigma_);
    // The shooter's best pots there by promise (speed and spin variants
    // ranked by the leave they play for), one variant per line first.
    std::vector<CandidateShot> all = generate_shots(rules, g, gen);
    std::stable_sort(all.begin(), all.end(), [](const CandidateShot& a, const CandidateShot& b) {
      return promise(a) > promise(b);
    });
    std::vector<CandidateShot> next;
    for (int pass = 0; pass < 2 && next.size() < kNext; ++pass) {
      for (const CandidateShot& c : all) {
        if (next.size() >= kNext) break;
        const bool seen = std::any_of(next.begin(), next.end(), [&](const CandidateShot& x) {
          return x.kind == c.kind && x.target == c.target && x.pocket == c.pocket;
        });
        const bool same = std::any_of(next.begin(), next.end(), [&](const CandidateShot& x) {
          return x.shot == c.shot;
        });
        if (same || (pass == 0 && seen)) continue;
        next.push_back(c);
      }
    }
    double q = kNoValue;
    for (const CandidateShot& c : next) {
      double s = 0.0;
      for (int k = 0; k < next_samples; ++k) {
        s += sample_shot(rules, g, c.shot, level_.noise,
                         mix_seed(look_seed, static_cast<std::uint64_t>(k)), sigma_, nullptr,
                         nullptr, &ws);
      }
      q = std::max(q, s / next_samples);
    }
    // Nothing to pot found: the static value (a safety) stands.
    if (q == kNoValue) return 0.0;
    q = std::max(q, safe);
    const double d = q - stat;
    return shooter == me ? d : -d;
  });
  std::vector<double> dsum(value.size(), 0.0);
  std::vector<int> dn(value.size(), 0);
  for (std::size_t u = 0; u < units.size(); ++u) {
    dsum[units[u].cand] += delta[u];
    dn[units[u].cand] += 1;
  }
  for (std::size_t c : top) {
    if (dn[c] == 0 || count[c] == 0) continue;
    value[c] += (dsum[c] / dn[c]) * readable[c] / static_cast<double>(count[c]);
  }
}

}  // namespace breakshot::ai_detail

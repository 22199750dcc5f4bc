// The best shot (ai_player.hpp): the candidates of shot generation, the
// shortlist (shortlist.cpp), each pot also at its centred aim (champion),
// every candidate sampled under the level's own noise with common random
// numbers in two rounds, a pot charged for its sampled miss rate
// (champion), the lookahead's correction (lookahead.cpp), and the best
// mean value chosen.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "ai_player.hpp"

namespace breakshot::ai_detail {

namespace {

// What a pot's value loses per unit of its sampled miss rate (above).
constexpr double kMissPenalty = 0.4;
// Without sampling, a pot is preferred to a safety from this prior up.
constexpr double kFairPot = 0.2;

/// A legal hit when no candidate exists: straight at the nearest legal
/// ball (a declared safety in 8-ball).
Shoot fallback_shot(const Rules& rules, const GameState& state) {
  const LegalActions la = rules.legal_actions(state);
  const Vec2 cue = state.position[0];
  int nearest = -1;
  for (int t : la.targets) {
    const Vec2 p = state.position[static_cast<std::size_t>(t)];
    if (nearest < 0 || norm(p - cue) < norm(state.position[static_cast<std::size_t>(nearest)] - cue)) {
      nearest = t;
    }
  }
  Shoot s = make_shoot(nearest > 0 ? aim_deg(cue, state.position[static_cast<std::size_t>(nearest)]) : 0.0, 3.0);
  s.safety = la.call;
  if (la.must_nominate && nearest > 0) s.nominate = nearest;  // snooker: the colour it hits
  if (rules.check(state, s)) s.safety = false;
  return s;
}

}  // namespace

/// The best shot in `state` (phase shot, cue ball on the table) and its
/// value; `scale` shrinks the search (for searches inside searches).
Evaluated AiPlayer::best_shot(const Rules& rules, const GameState& state, std::uint64_t seed,
                              double scale, Budget& budget) const {
  std::vector<CandidateShot> cands = generate_shots(rules, state, generation(state.game));
  // Defensive: only what the rules accept (generate_shots promises it).
  std::erase_if(cands, [&](const CandidateShot& c) { return rules.check(state, c.shot).has_value(); });
  std::stable_sort(cands.begin(), cands.end(),
                   [](const CandidateShot& a, const CandidateShot& b) { return a.prior > b.prior; });
  if (cands.empty()) return Evaluated{fallback_shot(rules, state), shooter_value(0.0) - 0.5};
  if (!searches()) {
    // No sampling: the best pot by prior when it is a fair chance, else
    // the best candidate of any kind (a safety's prior is how little it
    // leaves, on another scale).
    const auto pot = std::find_if(cands.begin(), cands.end(), [](const CandidateShot& c) {
      return c.kind != ShotKind::safety && c.target >= 0;
    });
    const CandidateShot& c = pot != cands.end() && pot->prior >= kFairPot ? *pot : cands.front();
    return Evaluated{c.shot, shooter_value(c.prior)};
  }

  cands = shortlist(std::move(cands), static_cast<std::size_t>(std::max(
                                          1, static_cast<int>(std::lround(level_.candidates * scale)))));
  // 8-ball: each declared safety also unannounced. Without a call the
  // shot counts only if the first ball hit drops (docs/rules.md), so it
  // plays out like the safety except that such a ball keeps the turn
  // instead of ending it; the samples say which is worth more.
  if (ai_detail::game_policy(state.game).unannounced_safeties && level_.samples >= 12) {
    const std::size_t n0 = cands.size();
    for (std::size_t i = 0; i < n0; ++i) {
      if (!cands[i].shot.safety) continue;
      CandidateShot open = cands[i];
      open.shot.safety = false;
      if (!rules.check(state, open.shot)) cands.push_back(open);
    }
  }
  if (level_.centre_aim) {
    // Each pot also aimed at the middle of the aims that make it
    // (evaluate.hpp), as a second candidate: the move turns the cue
    // ball's path after the contact, so the original aim may leave the
    // better position; the samples decide.
    ai_detail::add_centred_aims(rules, state, cands, level_.threads);
  }
  const std::size_t n = cands.size();
  const int total = std::max(1, static_cast<int>(std::lround(level_.samples * scale)));
  const int first = std::max(1, (total + 1) / 2);
  const std::uint64_t sample_seed = mix_seed(seed, kSampleStream);

  // Per candidate: the sum of sample values, how many, and the tables
  // the samples left (for the lookahead).
  std::vector<double> sum(n, 0.0);
  std::vector<int> count(n, 0);
  std::vector<int> kept(n, 0);
  std::vector<std::vector<GameState>> left(n);
  // 9-ball: the ball and pocket of each sample that potted (below).
  std::vector<std::vector<Call>> potted(n);
  const bool nine = ai_detail::game_policy(state.game).rotation;
  const bool keep = level_.lookahead;

  // Samples [from, to) of the candidates in `which`: one unit each.
  const auto run = [&](const std::vector<std::size_t>& which, int from, int to) {
    const std::size_t per = static_cast<std::size_t>(std::max(0, to - from));
    if (per == 0 || which.empty()) return;
    struct Result {
      double value = 0.0;
      bool kept = false;  ///< the shooter still at the table, or won
      GameState after;
      Call potted;
    };
    const std::vector<Result> res = parallel_map_ws<Result>(
        which.size() * per, level_.threads, [&](std::size_t u, ShotWorkspace& ws) {
          const std::size_t c = which[u / per];
          const int s = from + static_cast<int>(u % per);
          Result r;
          r.value = sample_shot(rules, state, cands[c].shot, level_.noise,
                                mix_seed(sample_seed, static_cast<std::uint64_t>(s)), sigma_,
                                &r.after, nine ? &r.potted : nullptr, &ws);
          r.kept = r.after.phase == Phase::game_over ? r.after.winner == state.player
                                                     : r.after.player == state.player;
          if (!keep) r.after = GameState{};
          return r;
        });
    for (std::size_t u = 0; u < res.size(); ++u) {
      const std::size_t c = which[u / per];
      sum[c] += res[u].value;
      count[c] += 1;
      kept[c] += res[u].kept ? 1 : 0;
      if (keep) left[c].push_back(res[u].after);
      if (res[u].potted.ball > 0) potted[c].push_back(res[u].potted);
    }
  };

  // Round 1: every candidate, half the samples (fewer if the budget
  // says so).
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t{0});
  const int first_granted = static_cast<int>(
      budget.take(static_cast<std::int64_t>(n) * first) / static_cast<std::int64_t>(n));
  run(all, 0, std::max(1, first_granted));

  // A pot is charged for the share of its samples that miss: beyond
  // what the miss's table is worth, a missed pot hands the opponent the
  // table, which the static values read too kindly (risk aversion; the
  // strongest level only).
  // Snooker's values are frame chances from the score, where a missed
  // pot already costs what the opponent's visit promises: no charge.
  const double risk =
      level_.lookahead && !ai_detail::game_policy(state.game).frame_scoring ? kMissPenalty : 0.0;
  const auto mean = [&](std::size_t c) {
    if (!count[c]) return kNoValue;
    double m = sum[c] / count[c];
    if (cands[c].target >= 0) m -= risk * (1.0 - static_cast<double>(kept[c]) / count[c]);
    return m;
  };
  const auto ranked = [&]() {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return mean(a) > mean(b); });
    return order;
  };

  // Round 2: the rest of the samples for the best third (at least three).
  if (total > first && n > 1 && !budget.past(0.5)) {
    std::vector<std::size_t> top = ranked();
    top.resize(std::min(n, std::max<std::size_t>(3, (n + 2) / 3)));
    std::sort(top.begin(), top.end());  // index order: the same units for any ranking ties
    const std::int64_t want = static_cast<std::int64_t>(top.size()) * (total - first);
    const int more = static_cast<int>(budget.take(want) / static_cast<std::int64_t>(top.size()));
    const int from = std::max(1, first_granted);
    run(top, from, from + more);
  }

  std::vector<std::size_t> order = ranked();
  std::vector<double> value(n);
  for (std::size_t c = 0; c < n; ++c) value[c] = mean(c);

  // Round 3 (lookahead): read the best few candidates' tables a shot
  // deeper and choose among them only, their values being corrected
  // alike.
  const int look_cands = lookahead_depth(level_, state.game).candidates;
  if (level_.lookahead && look_cands > 0 && !budget.past(0.6)) {
    const std::size_t nl = std::min<std::size_t>(n, static_cast<std::size_t>(look_cands));
    order.resize(nl);
    lookahead(rules, state, seed, order, left, count, value, budget);
  }

  std::size_t best = order.front();
  for (std::size_t c : order) {
    if (value[c] > value[best] || (value[c] == value[best] && c < best)) best = c;
  }
  // A rotation game whose shots need no call (9-ball: the call is
  // information only, a pot attempt for the statistics): a safety or
  // kick whose samples mostly pocket one ball in one pocket is called
  // for it, as the pot it is expected to be. Where the rules want every
  // shot called or declared safe (10-ball), the safety stays declared.
  Shoot chosen = cands[best].shot;
  if (nine && !chosen.call && !chosen.safety) {
    Shoot called = chosen;
    called.call = expected_pot(potted[best], count[best]);
    if (called.call && !rules.check(state, Action{called})) chosen = called;
  }
  return Evaluated{chosen, value[best]};
}

}  // namespace breakshot::ai_detail

// The AI player (include/breakshot/ai.hpp), built the way the
// computational pool tournament winners were (PickPocket, CueCard):
//
// 1. Shot generation: generate_shots() lists candidate shots with their
//    aim refined on the engine and a geometric prior.
// 2. Monte Carlo evaluation: the best `candidates` by prior are each
//    played `samples` times through Rules::apply with the strike perturbed
//    by the player's own noise. A sample is worth what the table it leaves
//    is worth (evaluate.hpp): a win 1, a loss -1, a continued turn the
//    quality of the next pot, a miss or safety minus the opponent's, a
//    foul minus the opponent's ball in hand. The evaluation runs in two
//    rounds: half the samples for every candidate, then the rest for the
//    best third, so that samples go where the decision is close.
//    The strongest level also samples each pot a second time with its
//    aim in the middle of the aims that make it (centre_aim), and
//    charges a pot for its sampled miss rate
//    (kMissPenalty), so that a doubtful pot loses to a safety that is
//    nearly as good; in 8-ball each declared safety is also tried
//    unannounced (a first ball that drops then keeps the turn). In
//    9-ball a chosen safety or kick whose samples mostly pot one ball in
//    one pocket is called for it (expected_pot), so that the statistics
//    count it as a pot attempt.
// 3. Lookahead (champion): for the best `lookahead_candidates`, a few of
//    the tables their samples leave with a shot to play (the player's
//    next shot, or the opponent's after a miss or a safety) are searched
//    one shot deeper (the shooter's best pots, sampled, with playing safe
//    as a floor), and the difference between that and the static value of
//    those tables corrects the candidate's value. 9-ball reads more
//    candidates and more of their tables (lookahead_candidates_nine,
//    lookahead_states_nine): the rotation fixes the next ball, so the
//    leave for it decides more there.
//
// The decisions the rules ask for get their own small searches: the break
// (placements in the kitchen, aims and speeds, sampled), cue ball in hand
// (placements behind balls on their pocket lines and a grid, ranked by the
// geometric estimate, the best few searched in full), the 9-ball push-out
// and the reply to one, and the 8-ball choices after the break.
//
// Determinism: every simulation is a unit with a seed derived from the
// decision seed and its indices, never from the thread that runs it;
// results are gathered in index order and combined in a fixed order, and
// every choice of what to evaluate next depends only on earlier results.
// So a decision is a function of the seed and the simulation budget, for
// any number of threads. Only a time budget (which cuts rounds short)
// makes it depend on the machine. The samples of all candidates share
// their seeds (common random numbers): each candidate meets the same
// noise draws, so differences between candidates are not differences of
// luck.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/detmath.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/snooker.hpp"
#include "carom_ai.hpp"
#include "evaluate.hpp"
#include "policy.hpp"

namespace breakshot {

std::string_view to_string(ShotKind k) {
  switch (k) {
    case ShotKind::direct:
      return "direct";
    case ShotKind::bank:
      return "bank";
    case ShotKind::kick:
      return "kick";
    case ShotKind::combination:
      return "combination";
    case ShotKind::safety:
      return "safety";
    case ShotKind::break_shot:
      return "break_shot";
    case ShotKind::jump:
      return "jump";
  }
  return "unknown";
}

namespace {

using ai_detail::best_pot_estimate;
using ai_detail::best_pot_estimate_from;
using ai_detail::expected_pot;
using ai_detail::parallel_map;
using ai_detail::parallel_map_ws;
using ai_detail::position_value;
using ai_detail::sample_shot;
using ai_detail::shooter_value;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kNoValue = -std::numeric_limits<double>::infinity();

// Stream tags keep the seeds of the different searches apart (ASCII of
// their names; arbitrary constants).
constexpr std::uint64_t kSampleStream = 0x73616d706c65ULL;    // "sample"
constexpr std::uint64_t kLookStream = 0x6c6f6f6bULL;          // "look"
constexpr std::uint64_t kBreakStream = 0x627265616bULL;       // "break"
constexpr std::uint64_t kPushStream = 0x70757368ULL;          // "push"
constexpr std::uint64_t kPlaceStream = 0x706c616365ULL;       // "place"
constexpr std::uint64_t kBreakOffStream = 0x626f6666ULL;      // "boff"
constexpr std::uint64_t kChoiceStream = 0x63686f696365ULL;    // "choice"

// A push-out is considered when the best shot is worth less than this,
// and the table is taken after the opponent's push-out when it is worth
// more than this to the taker.
constexpr double kPushThreshold = 0.0;
constexpr double kTakeThreshold = 0.0;
// An illegal break's table is accepted when it is worth at least what
// breaking a fresh rack is (position_value gives a break 0.1).
constexpr double kAcceptThreshold = 0.1;
// A placement or a candidate needs to beat staying put by this much, so
// that the placement decision settles.
constexpr double kStayMargin = 0.02;
// What a pot's value loses per unit of its sampled miss rate (above).
constexpr double kMissPenalty = 0.4;
// What a missed pot is taken to cost when candidates are ranked before
// sampling: the opponent at an average table (shooter_value(0.5)).
constexpr double kMissCost = 0.325;
// Without sampling, a pot is preferred to a safety from this prior up.
constexpr double kFairPot = 0.2;

constexpr double kBreakSpeedSoft = 8.5;  // m/s
constexpr double kBreakSpeedHard = 11.0;
constexpr double kBreakSpeedMedium = 10.0;
constexpr double kBreakSpeedNine = 12.0;
constexpr double kBreakDraw = -0.2;  // a little draw keeps the cue ball near the centre

/// A decision's remaining allowance: simulations (deterministic) and wall
/// time (not).
class Budget {
 public:
  Budget(std::int64_t simulations, double seconds)
      : left_(simulations > 0 ? simulations : -1),
        seconds_(seconds),
        start_(std::chrono::steady_clock::now()) {}

  /// Up to n simulations (all of them without a simulation budget).
  std::int64_t take(std::int64_t n) {
    if (left_ < 0) return n;
    const std::int64_t got = std::min(n, left_);
    left_ -= got;
    return got;
  }
  std::int64_t left() const { return left_ < 0 ? std::numeric_limits<std::int64_t>::max() : left_; }
  /// True once `fraction` of the time budget is spent (never without one).
  bool past(double fraction) const {
    if (seconds_ <= 0.0) return false;
    const std::chrono::duration<double> used = std::chrono::steady_clock::now() - start_;
    return used.count() >= fraction * seconds_;
  }

 private:
  std::int64_t left_;
  double seconds_;
  std::chrono::steady_clock::time_point start_;
};

/// A shot chosen with what it is estimated to be worth to the shooter.
struct Evaluated {
  Shoot shot;
  double value = kNoValue;
};

Shoot make_shoot(double phi, double speed, double b = 0.0) {
  Shoot s;
  s.strike.phi = phi;
  s.strike.speed = speed;
  s.strike.b = b;
  return s;
}

double aim_deg(Vec2 from, Vec2 to) { return dm::atan2(to.y - from.y, to.x - from.x) / kDeg; }

Vec2 rotate(Vec2 v, double rad) {
  double s = 0.0;
  double c = 0.0;
  dm::sincos(rad, s, c);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

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

/// What a pot's noiseless play promises, for ranking candidates before
/// they are sampled: the chance that it drops times the value of its
/// leave, against a miss that hands over an average table. Other shots:
/// their prior.
double promise(const CandidateShot& c) {
  if (c.target < 0 || c.leave < 0.0) return c.prior;
  return c.prior * shooter_value(c.leave) - (1.0 - c.prior) * kMissCost;
}

class AiPlayer final : public Player {
 public:
  explicit AiPlayer(AiLevel level)
      : level_(std::move(level)), sigma_(ai_detail::estimate_sigma(level_.noise)) {
    level_.generation.leave_sigma_deg = sigma_;
    if (level_.snooker_generation) level_.snooker_generation->leave_sigma_deg = sigma_;
  }

  std::string name() const override { return level_.name; }
  std::optional<NoiseModel> noise() const override { return level_.noise; }

  Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) override {
    const ai_detail::GamePolicy& policy = ai_detail::game_policy(state.game);
    if (policy.search == ai_detail::GamePolicy::Search::carom) {
      return ai_detail::carom_action(level_, rules, state, seed);
    }
    Budget budget(level_.simulation_budget, level_.time_budget);
    const LegalActions la = rules.legal_actions(state);
    if (policy.search == ai_detail::GamePolicy::Search::snooker) {
      return snooker_action(rules, state, la, seed, budget);
    }
    if (!la.choices.empty()) return Decide{choose(rules, state, la, seed, budget)};
    if (state.phase == Phase::break_shot) return break_action(rules, state, la, budget);
    if (la.place != BallInHand::none) return placement_or_shot(rules, state, la, seed, budget);
    return shot_action(rules, state, la, seed, budget);
  }

 private:
  bool searches() const { return level_.samples > 0 && level_.candidates > 0; }
  /// The shot generation for `game` (snooker's own where the level has one).
  const ShotGenOptions& generation(GameType game) const {
    return ai_detail::game_policy(game).snooker_generation && level_.snooker_generation
               ? *level_.snooker_generation
               : level_.generation;
  }

  // -------------------------------------------------------------------------
  // Snooker

  /// Snooker: the decision after the opponent's foul, conceding a frame
  /// that needs snookers, the break-off and shots from the D (a shot with
  /// the cue ball in hand), and the shots.
  Action snooker_action(const Rules& rules, const GameState& state, const LegalActions& la,
                        std::uint64_t seed, Budget& budget) const {
    const int me = state.player;
    const auto offered = [&](Choice c) {
      return std::find(la.choices.begin(), la.choices.end(), c) != la.choices.end();
    };
    if (offered(Choice::concede) && snookers_required(state, me) > 0) {
      return Decide{Choice::concede};
    }
    if (state.phase == Phase::foul_choice) {
      // The choice whose table is worth most: played on, the offender to
      // play again, or the balls replaced after a miss.
      Choice best = Choice::play_on;
      double best_value = kNoValue;
      for (const Choice c : {Choice::play_on, Choice::offender_again, Choice::replace_balls}) {
        if (!offered(c)) continue;
        const GameState next = rules.apply(state, Decide{c}).state;
        const double v = position_value(rules, next, me, sigma_);
        if (v > best_value) {
          best_value = v;
          best = c;
        }
      }
      return Decide{best};
    }
    if (state.phase == Phase::break_shot) return break_off(rules, state, la, seed, budget);
    if (la.place != BallInHand::none) return placement_or_shot(rules, state, la, seed, budget);
    return shot_action(rules, state, la, seed, budget);
  }

  /// Snooker's break-off: the cue ball may be placed in the D again and
  /// again until the stroke, so the place is chosen from a fixed set (six
  /// points of the baulk line, the break-off spot first) with seeds from
  /// the rack, never from the decision or the cue ball's position: the
  /// call that places the cue ball and the call that then finds it there
  /// choose the same place, and the second shoots. Each place is searched
  /// with half the effort of a shot decision; the shot itself is then
  /// chosen as any shot.
  Action break_off(const Rules& rules, const GameState& state, const LegalActions& la,
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
        const double v =
            best_shot(rules, placed, mix_seed(place_seed, i), 0.5, budget).value;
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

  // -------------------------------------------------------------------------
  // Shots

  /// The shot to play (a push-out when that is worth more).
  Action shot_action(const Rules& rules, const GameState& state, const LegalActions& la,
                     std::uint64_t seed, Budget& budget) const {
    Evaluated best = best_shot(rules, state, seed, 1.0, budget);
    if (la.push_out && searches() && best.value < kPushThreshold && !budget.past(0.8)) {
      const Evaluated push = best_push(rules, state, seed, budget);
      if (push.value > best.value) return push.shot;
    }
    return best.shot;
  }

  /// The best shot in `state` (phase shot, cue ball on the table) and its
  /// value; `scale` shrinks the search (for searches inside searches).
  Evaluated best_shot(const Rules& rules, const GameState& state, std::uint64_t seed, double scale,
                    Budget& budget) const {
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
      const std::size_t n0 = cands.size();
      const std::vector<Shoot> centred =
          parallel_map<Shoot>(n0, level_.threads, [&](std::size_t i) {
            return cands[i].target >= 0 ? ai_detail::centre_aim(rules, state, cands[i].shot)
                                        : cands[i].shot;
          });
      for (std::size_t i = 0; i < n0; ++i) {
        if (centred[i] == cands[i].shot) continue;
        CandidateShot c = cands[i];
        c.shot = centred[i];
        cands.push_back(c);
      }
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

  /// The candidates worth sampling, from `cands` sorted by prior: the
  /// priors of safeties (how little they leave) and of pots (how likely
  /// they drop) are not on one scale, and each line comes in several
  /// speed and spin variants with nearly equal priors, so a plain cut by
  /// prior could hold only safeties, or one line. So three quarters of the
  /// places go to pots and a quarter to safeties (either filling in for
  /// the other when short). Pots are ranked by their promise (the prior
  /// times the value of the leave of their noiseless play), safeties by
  /// prior, and the first pass takes the best variant of each line (kind,
  /// balls, pocket) before any second variant.
  static std::vector<CandidateShot> shortlist(std::vector<CandidateShot> cands, std::size_t n) {
    if (cands.size() <= n) return cands;
    std::vector<std::size_t> pots;
    std::vector<std::size_t> safes;
    for (std::size_t i = 0; i < cands.size(); ++i) {
      (cands[i].kind == ShotKind::safety || cands[i].target < 0 ? safes : pots).push_back(i);
    }
    const auto same_line = [&](std::size_t a, std::size_t b) {
      const CandidateShot& x = cands[a];
      const CandidateShot& y = cands[b];
      return x.kind == y.kind && x.first == y.first && x.target == y.target && x.pocket == y.pocket;
    };
    // Lines first, then the other variants, each in prior order.
    const auto spread = [&](const std::vector<std::size_t>& in) {
      std::vector<std::size_t> firsts;
      std::vector<std::size_t> rest;
      for (std::size_t i : in) {
        const bool seen = std::any_of(firsts.begin(), firsts.end(),
                                      [&](std::size_t f) { return same_line(f, i); });
        (seen ? rest : firsts).push_back(i);
      }
      firsts.insert(firsts.end(), rest.begin(), rest.end());
      return firsts;
    };
    // Pots by what their noiseless play promises: the chance that they
    // drop times the value of the leave, against a miss that hands over
    // an average table. So the variants of a line that leave the cue ball
    // well are the ones sampled.
    std::stable_sort(pots.begin(), pots.end(), [&](std::size_t a, std::size_t b) {
      return promise(cands[a]) > promise(cands[b]);
    });
    pots = spread(pots);
    safes = spread(safes);
    std::size_t n_safe = std::min(safes.size(), std::max<std::size_t>(1, n / 4));
    std::size_t n_pot = std::min(pots.size(), n - n_safe);
    n_safe = std::min(safes.size(), n - n_pot);
    std::vector<std::size_t> keep(pots.begin(), pots.begin() + static_cast<std::ptrdiff_t>(n_pot));
    keep.insert(keep.end(), safes.begin(), safes.begin() + static_cast<std::ptrdiff_t>(n_safe));
    std::vector<CandidateShot> out;
    out.reserve(keep.size());
    for (std::size_t i : keep) out.push_back(cands[i]);
    return out;
  }

  /// Corrects value[c] for each c in `top`: for up to kStates of the
  /// tables its samples left with a shot to play from where the cue ball
  /// lies (the player's own next shot, or the opponent's after a miss or
  /// a safety), the shooter's best few pots there are sampled, with the
  /// static value of playing safe (the table with no pot) as a floor. The
  /// mean difference between that and the static value of those tables,
  /// times the share of samples that left such a table, is added. So the
  /// cue ball's leave (position play) and what a safety really leaves the
  /// opponent are both read by sampling rather than by the quick estimate.
  void lookahead(const Rules& rules, const GameState& state, std::uint64_t seed,
                 const std::vector<std::size_t>& top,
                 const std::vector<std::vector<GameState>>& left, const std::vector<int>& count,
                 std::vector<double>& value, Budget& budget) const {
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

  /// A legal hit when no candidate exists: straight at the nearest legal
  /// ball (a declared safety in 8-ball).
  static Shoot fallback_shot(const Rules& rules, const GameState& state) {
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

  /// 9-ball push-out: soft rolls in twelve directions at two speeds, each
  /// sampled; the opponent then takes the better of shooting and passing
  /// back (position_value), so the best push leaves a table worth little
  /// to either side.
  Evaluated best_push(const Rules& rules, const GameState& state, std::uint64_t seed,
                    Budget& budget) const {
    std::vector<Shoot> pushes;
    for (int k = 0; k < 12; ++k) {
      for (double speed : {0.8, 1.5}) {
        Shoot s = make_shoot(30.0 * k, speed);
        s.push_out = true;
        if (!rules.check(state, s)) pushes.push_back(s);
      }
    }
    const int samples = std::max(2, level_.samples / 4);
    const std::int64_t want = static_cast<std::int64_t>(pushes.size()) * samples;
    if (pushes.empty() || budget.take(want) < want) return Evaluated{};
    const std::uint64_t push_seed = mix_seed(seed, kPushStream);
    const std::size_t per = static_cast<std::size_t>(samples);
    const std::vector<double> res = parallel_map_ws<double>(pushes.size() * per, level_.threads, [&](std::size_t u, ShotWorkspace& ws) {
      return sample_shot(rules, state, pushes[u / per], level_.noise,
                         mix_seed(push_seed, static_cast<std::uint64_t>(u % per)), sigma_, nullptr,
                         nullptr, &ws);
    });
    Evaluated best;
    for (std::size_t i = 0; i < pushes.size(); ++i) {
      double s = 0.0;
      for (std::size_t k = 0; k < per; ++k) s += res[i * per + k];
      const double v = s / samples;
      if (v > best.value) best = Evaluated{pushes[i], v};
    }
    return best;
  }

  // -------------------------------------------------------------------------
  // Cue ball in hand

  /// Places the cue ball where the best shot is best, or shoots from where
  /// it lies when that is as good. Placing ends the ball in hand (the
  /// rules), so the next call chooses the shot from the placed ball.
  Action placement_or_shot(const Rules& rules, const GameState& state, const LegalActions& la,
                           std::uint64_t seed, Budget& budget) const {
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
  static std::vector<Vec2> placements(const Rules& rules, const GameState& state,
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

  // -------------------------------------------------------------------------
  // The break

  /// The break: for a few placements in the kitchen, aims at the head
  /// ball (full and slightly to either side) and two speeds, the option
  /// whose samples are worth most. The cue ball is placed first when it is
  /// not already there; the next call finds it there and shoots. The
  /// samples' seeds come from the rack, not the decision seed, and the
  /// options from the table and the rack, not the cue ball's position, so
  /// that both calls see the same evaluation and agree.
  Action break_action(const Rules& rules, const GameState& state, const LegalActions& la,
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
      // At most 32 each: the strongest level has over a hundred options.
      const int samples = std::clamp(level_.samples / 2, 4, 32);
      const std::int64_t want = static_cast<std::int64_t>(options.size()) * samples;
      const int granted = static_cast<int>(budget.take(want) / static_cast<std::int64_t>(options.size()));
      if (granted > 0) {
        const std::uint64_t break_seed =
            mix_seed(mix_seed(state.rack_seed, kBreakStream), static_cast<std::uint64_t>(state.racks));
        const std::size_t per = static_cast<std::size_t>(granted);
        const std::vector<double> res =
            parallel_map_ws<double>(options.size() * per, level_.threads, [&](std::size_t u, ShotWorkspace& ws) {
              const Option& o = options[u / per];
              GameState placed = state;
              placed.position[0] = o.place;
              placed.on_table[0] = 1;
              return sample_shot(rules, placed, o.shot, level_.noise,
                                 mix_seed(break_seed, static_cast<std::uint64_t>(u % per)), sigma_,
                                 nullptr, nullptr, &ws);
            });
        double best_value = kNoValue;
        for (std::size_t i = 0; i < options.size(); ++i) {
          double s = 0.0;
          for (std::size_t k = 0; k < per; ++k) s += res[i * per + k];
          if (s > best_value) {
            best_value = s;
            best = i;
          }
        }
      }
    }
    const Option& o = options[best];
    if (state.on_table[0] && state.position[0] == o.place) return o.shot;
    return PlaceCueBall{o.place};
  }

  // -------------------------------------------------------------------------
  // Decisions

  Choice choose(const Rules& rules, const GameState& state, const LegalActions& la,
                std::uint64_t seed, Budget& budget) const {
    const auto offered = [&](Choice c) {
      return std::find(la.choices.begin(), la.choices.end(), c) != la.choices.end();
    };
    const int me = state.player;
    if (state.phase == Phase::push_out_choice && offered(Choice::shoot) && offered(Choice::pass_back)) {
      // Take the table when shooting from it is worth more than the
      // threshold; passing back gives the same table to the opponent.
      const GameState taken = rules.apply(state, Decide{Choice::shoot}).state;
      double v = 0.0;
      if (searches() && taken.on_table[0] && taken.ball_in_hand == BallInHand::none) {
        v = best_shot(rules, taken, mix_seed(seed, kChoiceStream), 0.5, budget).value;
      } else {
        v = position_value(rules, taken, me, sigma_);
      }
      return v > kTakeThreshold ? Choice::shoot : Choice::pass_back;
    }
    if (state.phase == Phase::illegal_break_choice && offered(Choice::accept_table)) {
      const GameState accepted = rules.apply(state, Decide{Choice::accept_table}).state;
      if (position_value(rules, accepted, me, sigma_) >= kAcceptThreshold ||
          !offered(Choice::rerack_and_break)) {
        return Choice::accept_table;
      }
      return Choice::rerack_and_break;
    }
    // After the 8 on the break: spotting it keeps the balls that fell
    // down and the table open, which is worth more than a new rack.
    for (Choice c : {Choice::respot_eight, Choice::accept_table, Choice::shoot}) {
      if (offered(c)) return c;
    }
    return la.choices.front();
  }

  AiLevel level_;
  double sigma_;
};

/// The five levels: each shoots with less noise and searches more than the
/// one below it.
AiLevel make_level(std::string_view name) {
  AiLevel l;
  l.name = std::string(name);
  if (name == "beginner") {
    // Four times tournament noise, no sampling: the best prior, at once.
    l.noise = parse_noise("4x");
    l.generation.banks = false;
    l.generation.combinations = false;
    l.generation.speed_factors = {1.6};
    l.generation.spins = {0.0};
    l.generation.refine_iterations = 1;
    l.generation.max_candidates = 30;
    l.candidates = 1;
    l.samples = 0;
    l.threads = 1;
  } else if (name == "amateur") {
    l.noise = parse_noise("2.5x");
    l.generation.combinations = false;
    l.generation.speed_factors = {1.2, 2.0};
    l.generation.spins = {0.0};
    l.generation.refine_iterations = 2;
    l.generation.max_candidates = 40;
    l.candidates = 6;
    l.samples = 6;
  } else if (name == "club") {
    l.noise = parse_noise("1.6x");
    l.generation.refine_iterations = 3;
    l.generation.max_candidates = 60;
    l.candidates = 12;
    l.samples = 12;
  } else if (name == "expert") {
    // A little more noise than the champion's, so that the two differ in
    // more than the depth of their search (with the same noise the
    // champion won only 55 of 100 9-ball games).
    l.noise = parse_noise("1.25x");
    l.generation.jumps = true;
    l.candidates = 24;
    l.samples = 24;
  } else if (name == "champion") {
    l.noise = parse_noise("tournament");
    // Twice the samples of the first version and twice the candidates
    // read a shot deeper. Five speeds, five tip heights and two side
    // offsets per line: the shortlist ranks them by the leave of their
    // noiseless play, so the variants sampled are the ones that play
    // position (docs/ai.md).
    l.generation.speed_factors = {1.0, 1.35, 1.8, 2.4, 3.2};
    l.generation.spins = {-0.45, -0.25, 0.0, 0.25, 0.45};
    l.generation.sides = {-0.35, 0.35};
    l.generation.max_candidates = 400;
    l.generation.safety_turns = {0.0, 12.0, 25.0, 38.0, 50.0, 62.0};
    l.generation.safety_speeds = {0.8, 1.2, 1.7, 2.4, 3.4};
    l.generation.safety_spins = {-0.4, 0.0, 0.4};
    l.generation.jumps = true;
    // Snooker: eight speeds, eight tip heights and four side offsets per
    // line, and room for them all in the shortlist. On 80 open tables
    // (bench/snooker_probe) the mean break rose from 14.6 to 17.9 and the
    // pots made from 79 % to 83 % of those attempted (docs/ai.md).
    ShotGenOptions sn = l.generation;
    sn.speed_factors = {1.0, 1.2, 1.4, 1.7, 2.0, 2.4, 2.9, 3.5};
    sn.spins = {-0.55, -0.4, -0.25, -0.1, 0.0, 0.15, 0.3, 0.45};
    sn.sides = {-0.35, -0.2, 0.2, 0.35};
    sn.max_candidates = 1000;
    l.snooker_generation = sn;
    l.candidates = 60;
    l.samples = 128;
    l.lookahead = true;
    l.lookahead_candidates = 10;
    l.lookahead_candidates_nine = 16;
    l.lookahead_states_nine = 12;
    l.centre_aim = true;
  }
  return l;
}

constexpr std::array<std::string_view, 5> kLevelNames{"beginner", "amateur", "club", "expert",
                                                      "champion"};

}  // namespace

LookaheadDepth lookahead_depth(const AiLevel& level, GameType game) {
  const bool nine = ai_detail::game_policy(game).rotation;
  LookaheadDepth d;
  d.candidates = nine && level.lookahead_candidates_nine > 0 ? level.lookahead_candidates_nine
                                                             : level.lookahead_candidates;
  d.states = nine && level.lookahead_states_nine > 0 ? level.lookahead_states_nine
                                                     : level.lookahead_states;
  if (d.states <= 0) d.states = level.samples >= 48 ? 8 : 4;
  return d;
}

AiLevel ai_level(std::string_view name) {
  if (std::find(kLevelNames.begin(), kLevelNames.end(), name) == kLevelNames.end()) {
    std::string known;
    for (std::string_view n : kLevelNames) known += (known.empty() ? "" : ", ") + std::string(n);
    throw std::invalid_argument("unknown AI level \"" + std::string(name) +
                                "\" (known levels: " + known + ")");
  }
  return make_level(name);
}

std::vector<std::string> ai_level_names() {
  return std::vector<std::string>(kLevelNames.begin(), kLevelNames.end());
}

std::unique_ptr<Player> make_ai_player(const AiLevel& level) {
  return std::make_unique<AiPlayer>(level);
}

}  // namespace breakshot

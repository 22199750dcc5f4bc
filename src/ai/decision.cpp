// Choosing among actions (ai_player.hpp): a shot or a 9-ball push-out,
// the incoming player's choices (the push-out reply, an illegal break's
// table, 8-ball's choices after the break), and snooker's: conceding a
// frame that needs snookers, the choice after the opponent's foul.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "ai_player.hpp"

namespace breakshot::ai_detail {

namespace {

// A push-out is considered when the best shot is worth less than this,
// and the table is taken after the opponent's push-out when it is worth
// more than this to the taker.
constexpr double kPushThreshold = 0.0;
constexpr double kTakeThreshold = 0.0;
// An illegal break's table is accepted when it is worth at least what
// breaking a fresh rack is (position_value gives a break 0.1).
constexpr double kAcceptThreshold = 0.1;

}  // namespace

/// Snooker: the decision after the opponent's foul, conceding a frame
/// that needs snookers, the break-off and shots from the D (a shot with
/// the cue ball in hand), and the shots.
Action AiPlayer::snooker_action(const Rules& rules, const GameState& state, const LegalActions& la,
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

/// The shot to play (a push-out when that is worth more).
Action AiPlayer::shot_action(const Rules& rules, const GameState& state, const LegalActions& la,
                             std::uint64_t seed, Budget& budget) const {
  Evaluated best = best_shot(rules, state, seed, 1.0, budget);
  if (la.push_out && searches() && best.value < kPushThreshold && !budget.past(0.8)) {
    const Evaluated push = best_push(rules, state, seed, budget);
    if (push.value > best.value) return push.shot;
  }
  return best.shot;
}

/// 9-ball push-out: soft rolls in twelve directions at two speeds, each
/// sampled; the opponent then takes the better of shooting and passing
/// back (position_value), so the best push leaves a table worth little
/// to either side.
Evaluated AiPlayer::best_push(const Rules& rules, const GameState& state, std::uint64_t seed,
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

Choice AiPlayer::choose(const Rules& rules, const GameState& state, const LegalActions& la,
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

}  // namespace breakshot::ai_detail

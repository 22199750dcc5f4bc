// The AI player (include/breakshot/ai.hpp; ai_player.hpp maps its
// files), built the way the computational pool tournament winners were
// (PickPocket, CueCard):
//
// 1. Shot generation: generate_shots() lists candidate shots with their
//    aim refined on the engine and a geometric prior (shot_generator.hpp).
// 2. Monte Carlo evaluation (sampling.cpp): the best `candidates` by prior
//    (shortlist.cpp) are each played `samples` times through Rules::apply
//    with the strike perturbed by the player's own noise. A sample is
//    worth what the table it leaves is worth (evaluate.hpp): a win 1, a
//    loss -1, a continued turn the quality of the next pot, a miss or
//    safety minus the opponent's, a foul minus the opponent's ball in
//    hand. The evaluation runs in two rounds: half the samples for every
//    candidate, then the rest for the best third, so that samples go where
//    the decision is close. The strongest level also samples each pot a
//    second time with its aim in the middle of the aims that make it
//    (centre_aim), and charges a pot for its sampled miss rate
//    (kMissPenalty), so that a doubtful pot loses to a safety that is
//    nearly as good; in 8-ball each declared safety is also tried
//    unannounced (a first ball that drops then keeps the turn). In 9-ball
//    a chosen safety or kick whose samples mostly pot one ball in one
//    pocket is called for it (expected_pot), so that the statistics count
//    it as a pot attempt.
// 3. Lookahead (champion; lookahead.cpp): for the best
//    `lookahead_candidates`, a few of the tables their samples leave with
//    a shot to play (the player's next shot, or the opponent's after a
//    miss or a safety) are searched one shot deeper (the shooter's best
//    pots, sampled, with playing safe as a floor), and the difference
//    between that and the static value of those tables corrects the
//    candidate's value. 9-ball reads more candidates and more of their
//    tables (lookahead_candidates_nine, lookahead_states_nine): the
//    rotation fixes the next ball, so the leave for it decides more there.
//
// The decisions the rules ask for get their own small searches: the break
// (break_shot.cpp: placements in the kitchen, aims and speeds, sampled),
// cue ball in hand (ball_in_hand.cpp: placements behind balls on their
// pocket lines and a grid, ranked by the geometric estimate, the best few
// searched in full), the 9-ball push-out and the reply to one, and the
// 8-ball choices after the break (decision.cpp).
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
#include "ai_player.hpp"

#include <memory>
#include <utility>

#include "carom_ai.hpp"

namespace breakshot {

namespace ai_detail {

AiPlayer::AiPlayer(AiLevel level) : level_(std::move(level)), sigma_(estimate_sigma(level_.noise)) {
  level_.generation.leave_sigma_deg = sigma_;
  if (level_.snooker_generation) level_.snooker_generation->leave_sigma_deg = sigma_;
}

Action AiPlayer::decide(const Rules& rules, const GameState& state, std::uint64_t seed) {
  const GamePolicy& policy = game_policy(state.game);
  if (policy.search == GamePolicy::Search::carom) {
    return carom_action(level_, rules, state, seed);
  }
  Budget budget(level_.simulation_budget, level_.time_budget);
  const LegalActions la = rules.legal_actions(state);
  if (policy.search == GamePolicy::Search::snooker) {
    return snooker_action(rules, state, la, seed, budget);
  }
  if (!la.choices.empty()) return Decide{choose(rules, state, la, seed, budget)};
  if (state.phase == Phase::break_shot) return break_action(rules, state, la, budget);
  if (la.place != BallInHand::none) return placement_or_shot(rules, state, la, seed, budget);
  return shot_action(rules, state, la, seed, budget);
}

}  // namespace ai_detail

std::unique_ptr<Player> make_ai_player(const AiLevel& level) {
  return std::make_unique<ai_detail::AiPlayer>(level);
}

}  // namespace breakshot

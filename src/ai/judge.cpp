// The judge (judge.hpp): a simulated run renumbered to ball numbers and
// ruled by Rules::apply_events.
#include "judge.hpp"

#include <cstddef>
#include <utility>

namespace breakshot::ai_detail {

Judged judge(const Rules& rules, const GameState& state, const Shoot& shot, Simulation& sim,
             const std::vector<int>& numbers) {
  Judged j;
  if (sim.advance_to_rest() != StopReason::reached || !sim.at_rest()) return j;
  if (rules.check(state, Action{shot})) return j;
  std::vector<Event> events = sim.events();
  for (Event& e : events) {
    if (e.ball >= 0) e.ball = numbers[static_cast<std::size_t>(e.ball)];
    if (e.other >= 0) e.other = numbers[static_cast<std::size_t>(e.other)];
  }
  std::vector<Vec2> rest = state.position;
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    rest[static_cast<std::size_t>(numbers[k])] = sim.ball(k).position;
  }
  const bool miscue = sim.cue_result() && sim.cue_result()->miscue;
  Outcome o = rules.apply_events(state, shot, std::move(events), rest, miscue);
  j.first_hit = o.facts.first_hit;
  j.pocketed = o.facts.pocketed;
  j.pocket_of = o.facts.pocket_of;
  j.after.pos = o.state.position;
  j.after.on = o.state.on_table;
  const bool over = o.state.phase == Phase::game_over;
  j.wins = over && o.state.winner == state.player;
  j.legal = o.ruling.fouls.empty() && (!over || j.wins);
  j.fouls = std::move(o.ruling.fouls);
  j.next = std::move(o.state);
  return j;
}

int pocket_of(const Judged& j, int ball) {
  for (std::size_t k = 0; k < j.pocketed.size(); ++k) {
    if (j.pocketed[k] == ball) return j.pocket_of[k];
  }
  return -1;
}

}  // namespace breakshot::ai_detail

// 8-ball by the WPA rules: groups, calls, the 8, the break and its
// choices, shots from the kitchen. docs/rules.md lists the clauses.
#include <algorithm>
#include <memory>
#include <string>

#include "breakshot/simulation.hpp"
#include "ruleset.hpp"

namespace breakshot::detail {

namespace {

Group group_of(int ball) { return ball < 8 ? Group::solids : Group::stripes; }

Group other(Group g) { return g == Group::solids ? Group::stripes : Group::solids; }

// From the kitchen, a ball behind the head string may be hit first only
// after the cue ball has crossed the head string (WPA): did the cue ball's
// centre pass x > head string before its first contact? The shot is run
// again event by event up to that contact, and each piece of the cue
// ball's path (a parabola between events) is checked at its ends and at
// its turning point.
bool crossed_head_string(const Scenario& scenario, const std::vector<Event>& events) {
  double contact = -1.0;
  for (const Event& e : events) {
    if (e.type == EventType::ball_ball && (e.ball == 0 || e.other == 0)) {
      contact = e.time;
      break;
    }
  }
  if (contact < 0.0) return false;
  const double line = scenario.table.head_spot.x;
  Simulation sim(scenario);
  for (std::size_t guard = 0; guard <= events.size() + 1; ++guard) {
    const Simulation::Trajectory& tr = sim.trajectory(0);
    const double from = sim.time();
    const double to = std::min({sim.next_event_time(), contact, tr.t_end});
    const auto x_at = [&](double t) {
      const double dt = t - tr.t0;
      return tr.p0.x + tr.v0.x * dt + 0.5 * tr.acc.x * dt * dt;
    };
    double most = std::max(x_at(from), x_at(to));
    if (tr.acc.x != 0.0) {
      const double turn = tr.t0 - tr.v0.x / tr.acc.x;
      if (turn > from && turn < to) most = std::max(most, x_at(turn));
    }
    if (most > line) return true;
    if (to >= contact) return false;
    sim.advance_to(to);
  }
  return false;
}

class EightBall final : public Ruleset {
 public:
  int ball_count() const override { return 16; }

  std::vector<Foul> foul_kinds() const override { return pool_foul_kinds(); }

  Standing standing(const GameState& s) const override {
    // Once the groups are set, each side's balls left before the 8.
    Standing st;
    for (std::size_t p = 0; p < 2; ++p) {
      const Group g = s.group[p];
      if (g == Group::none) continue;
      int left = 0;
      for (int b = 1; b < static_cast<int>(s.on_table.size()); ++b) {
        if (b != 8 && group_of(b) == g && s.on_table[static_cast<std::size_t>(b)]) ++left;
      }
      st.balls_to_go[p] = left;
    }
    return st;
  }

  std::vector<int> targets(const GameState& s) const override {
    std::vector<int> out;
    const auto n = static_cast<int>(s.on_table.size());
    if (s.phase == Phase::break_shot) {
      for (int b = 1; b < n; ++b) {
        if (s.on_table[static_cast<std::size_t>(b)]) out.push_back(b);
      }
      return out;
    }
    const Group g = s.group[static_cast<std::size_t>(s.player)];
    for (int b = 1; b < n; ++b) {
      if (b == 8 || !s.on_table[static_cast<std::size_t>(b)]) continue;
      if (g == Group::none || group_of(b) == g) out.push_back(b);
    }
    // The 8 is the target once the shooter's group is cleared (never on an
    // open table: WPA 8-ball, open table).
    if (out.empty() && g != Group::none && s.on_table[8]) out.push_back(8);
    return out;
  }

  std::vector<Choice> choices(Phase phase) const override {
    switch (phase) {
      case Phase::illegal_break_choice:
        return {Choice::accept_table, Choice::rerack_and_break, Choice::rerack_opponent_breaks};
      case Phase::eight_on_break_choice:
        return {Choice::respot_eight, Choice::rerack_and_break};
      default:
        return {};
    }
  }

  void legal_shot(const GameState& s, LegalActions& la) const override {
    la.call = s.phase == Phase::shot;
  }

  std::optional<std::string> check_shot(const Rules& rules, const GameState& s,
                                        const Shoot& shot) const override {
    if (shot.push_out) return "8-ball has no push-out";
    if (shot.nominate) return "8-ball has no nominated ball (nominate is snooker's)";
    if (s.phase == Phase::break_shot) {
      if (shot.call || shot.safety) return "the break is neither called nor a safety";
      return std::nullopt;
    }
    if (shot.call && shot.safety) return "a declared safety has no call";
    if (shot.call) {
      const Call& call = *shot.call;
      if (auto why = check_called_pocket(rules, call)) return why;
      if (!has(targets(s), call.ball)) {
        return "called ball " + std::to_string(call.ball) + " is not a legal target";
      }
    }
    return std::nullopt;
  }

  void decide(DecisionRuling& d, Choice choice) const override {
    GameState& s = d.s;
    const GameState& state = d.before;
    Ruling& r = d.r;
    const std::string& who = d.who;
    switch (choice) {
      case Choice::accept_table:
        s.phase = Phase::shot;
        s.ball_in_hand = state.scratch_on_break ? BallInHand::kitchen : BallInHand::none;
        s.scratch_on_break = false;
        r.text = who + " accepts the table.";
        break;
      case Choice::rerack_and_break:
        d.rerack(d.shooter);
        r.text = who + " has the balls re-racked and breaks.";
        break;
      case Choice::rerack_opponent_breaks:
        d.rerack(d.opp);
        r.turn_continues = false;
        r.text = who + " has the balls re-racked; " + player_name(d.opp) + " breaks again.";
        break;
      case Choice::respot_eight:
        s.position[8] = d.rules.spot_position(state, 8);
        s.on_table[8] = 1;
        r.spotted.push_back(8);
        s.phase = Phase::shot;
        s.ball_in_hand = state.scratch_on_break ? BallInHand::kitchen : BallInHand::none;
        s.scratch_on_break = false;
        r.text = who + " has the 8 spotted and plays on.";
        break;
      default:
        break;  // not on offer in 8-ball: check() refuses them
    }
  }

  void rule_shot(ShotRuling& x) const override {
    if (x.is_break) {
      rule_break(x);
    } else {
      rule_play(x);
    }
  }

 private:
  static void rule_break(ShotRuling& x) {
    GameState& s = x.s;
    Ruling& r = x.r;
    const ShotFacts& f = x.f;
    const std::string& who = x.who;
    const std::string& what = x.what;
    const bool eight_in = has(f.pocketed, 8);
    const bool eight_off = has(x.objects_off, 8);
    // The fouls so far (a scratch, a ball off the table): the incoming
    // player has the cue ball in hand behind the head string.
    const bool fouled = !r.fouls.empty();
    if (fouled) s.on_table[0] = 0;
    r.legal_break = !x.objects.empty() || f.object_balls_to_cushion >= 4;
    if (eight_in || eight_off) {
      // The 8 pocketed or driven off the table on the break (WPA 8-ball
      // 3.3, 3.6): no loss; a choice.
      s.phase = Phase::eight_on_break_choice;
      s.scratch_on_break = fouled;
      s.ball_in_hand = BallInHand::none;
      if (fouled) {
        x.pass_turn();
        const bool only_scratch = r.fouls.size() == 1 && r.fouls.front() == Foul::scratch;
        r.text =
            what + (eight_off ? "The 8 left the table on the break" : "The 8 fell on the break") +
            (only_scratch ? " with a scratch" : " with a foul (" + fouls_in_words(r.fouls) + ")") +
            ": " + player_name(x.opp) +
            " chooses to spot the 8 and shoot from the kitchen, or to "
            "re-rack and break.";
      } else {
        r.turn_continues = true;
        r.text = what + "The 8 fell on the break: " + who +
                 " chooses to spot the 8 and play on, or to re-rack and break "
                 "again.";
      }
    } else if (!r.legal_break) {
      x.foul(Foul::illegal_break);
      s.phase = Phase::illegal_break_choice;
      s.scratch_on_break = fouled;
      s.ball_in_hand = BallInHand::none;
      x.pass_turn();
      r.text = what + "Illegal break (nothing pocketed, " +
               std::to_string(f.object_balls_to_cushion) +
               " object balls to a cushion): " + player_name(x.opp) +
               " accepts the table or has the balls re-racked.";
    } else if (fouled) {
      x.ball_in_hand_for_opponent(BallInHand::kitchen);
      r.text = what + "Foul on the break: " + fouls_in_words(r.fouls) + ". " + player_name(x.opp) +
               " has the cue ball in hand behind the head string; the table is "
               "open.";
    } else if (!x.objects.empty()) {
      s.phase = Phase::shot;
      s.ball_in_hand = BallInHand::none;
      r.turn_continues = true;
      r.text = what + "Legal break; the table is open and " + who + " shoots again.";
    } else {
      s.phase = Phase::shot;
      s.ball_in_hand = BallInHand::none;
      x.pass_turn();
      r.text = what + "Legal break; " + player_name(x.opp) + " to shoot on an open table.";
    }
  }

  static void rule_play(ShotRuling& x) {
    GameState& s = x.s;
    Ruling& r = x.r;
    const ShotFacts& f = x.f;
    const GameState& state = x.before;
    const Shoot& shot = x.shot;
    const std::string& who = x.who;
    const std::string& what = x.what;
    const int shooter = x.shooter;
    const int opp = x.opp;
    const std::vector<Foul>& fouls = r.fouls;
    const bool eight_in = has(f.pocketed, 8);
    if (f.first_hit < 0) {
      x.foul(Foul::no_contact);
    } else if (!has(x.targets, f.first_hit)) {
      x.foul(Foul::wrong_ball_first);
    } else if (state.kitchen_shot &&
               state.position[static_cast<std::size_t>(f.first_hit)].x <= x.rules.head_string() &&
               !crossed_head_string(x.rules.shot_scenario(state, shot.strike), x.events)) {
      x.foul(Foul::behind_head_string);
    }
    if (f.first_hit >= 0 && x.objects.empty() && !f.cushion_after_contact) x.foul(Foul::no_rail);
    const bool was_on_eight = has(x.targets, 8);
    if (has(x.objects_off, 8)) {
      // The 8 driven off the table loses the rack (WPA 8-ball 3.8).
      x.game_over(opp, who + " drove the 8 off the table");
      r.text = what + "Foul: " + fouls_in_words(fouls) + ". " + s.result + ": " +
               player_name(s.winner) + " wins.";
    } else if (eight_in) {
      const bool called_eight = shot.call && shot.call->ball == 8;
      const bool right_pocket = called_eight && x.pocket_of(8) == shot.call->pocket;
      if (!fouls.empty()) {
        x.game_over(opp, who + " pocketed the 8 on a foul (" + fouls_in_words(fouls) + ")");
      } else if (!was_on_eight) {
        x.game_over(opp, who + " pocketed the 8 before clearing the group");
      } else if (!called_eight) {
        x.game_over(opp, who + " pocketed the 8 without calling it");
      } else if (!right_pocket) {
        x.game_over(
            opp, who + " pocketed the 8 in an uncalled pocket (" +
                     x.rules.table().pockets[static_cast<std::size_t>(x.pocket_of(8))].name + ")");
      } else {
        x.game_over(shooter, who + " pocketed the 8 in the called pocket");
      }
      // On a foul the result names it.
      r.text = what + s.result + ": " + player_name(s.winner) + " wins.";
    } else if (!fouls.empty()) {
      x.ball_in_hand_for_opponent(BallInHand::anywhere);
      r.text = what + "Foul: " + fouls_in_words(fouls) + ". " + player_name(opp) +
               " has the cue ball in hand.";
    } else {
      // Did the shot count? A called ball in its called pocket; an
      // uncalled shot counts if the first ball hit went in (the obvious
      // shot); a safety never does.
      int made = -1;
      if (shot.safety) {
        made = -1;
      } else if (shot.call) {
        if (x.pocket_of(shot.call->ball) == shot.call->pocket) made = shot.call->ball;
      } else if (has(x.objects, f.first_hit)) {
        made = f.first_hit;
      }
      if (made > 0) {
        if (state.group[static_cast<std::size_t>(shooter)] == Group::none) {
          s.group[static_cast<std::size_t>(shooter)] = group_of(made);
          s.group[static_cast<std::size_t>(opp)] = other(group_of(made));
          r.assigned = group_of(made);
        }
        s.phase = Phase::shot;
        s.ball_in_hand = BallInHand::none;
        r.turn_continues = true;
        r.text = what +
                 (r.assigned != Group::none
                      ? who + " takes the " + std::string(to_string(r.assigned)) + " and "
                      : who + " ") +
                 "shoots again.";
      } else {
        s.phase = Phase::shot;
        s.ball_in_hand = BallInHand::none;
        x.pass_turn();
        const char* why = shot.safety         ? "Safety. "
                          : x.objects.empty() ? ""
                          : shot.call         ? "The called ball did not go in the called pocket. "
                                              : "No called or obvious ball went in. ";
        r.text = what + why + player_name(opp) + " to shoot.";
      }
    }
  }
};

}  // namespace

std::shared_ptr<const Ruleset> make_eight_ball_ruleset() { return std::make_shared<EightBall>(); }

}  // namespace breakshot::detail

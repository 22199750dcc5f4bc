// 9-ball by the WPA rules: the lowest ball first, the 9 wins, the push-out
// after the break, three fouls in a row. docs/rules.md lists the clauses.
#include <memory>
#include <string>

#include "ruleset.hpp"

namespace breakshot::detail {

namespace {

class NineBall final : public Ruleset {
 public:
  int ball_count() const override { return 10; }

  std::vector<Foul> foul_kinds() const override {
    // As 8-ball lists them: behind_head_string never occurs in 9-ball
    // and stays at 0.
    return pool_foul_kinds();
  }

  std::vector<int> targets(const GameState& s) const override { return lowest_ball(s); }

  std::vector<Choice> choices(Phase phase) const override {
    if (phase == Phase::push_out_choice) return {Choice::shoot, Choice::pass_back};
    return {};
  }

  void legal_shot(const GameState& s, LegalActions& la) const override {
    la.push_out = s.phase == Phase::shot && s.push_out_allowed;
  }

  std::optional<std::string> check_shot(const Rules& rules, const GameState& s,
                                        const Shoot& shot) const override {
    if (shot.safety) return "9-ball has no declared safety";
    if (shot.nominate) return "9-ball has no nominated ball (nominate is snooker's)";
    if (shot.call) {
      // Informational only: a valid pocket and an object ball on the table.
      if (auto why = check_call(rules, s, *shot.call, ball_count())) return why;
      if (shot.push_out) return "a push-out is not a pot attempt: it has no call";
    }
    if (shot.push_out && !(s.phase == Phase::shot && s.push_out_allowed)) {
      return "a push-out is only allowed on the shot right after the break";
    }
    return std::nullopt;
  }

  void decide(DecisionRuling& d, Choice choice) const override {
    rotation_reply(d, choice, "takes the table after the push-out", "passes the shot back to");
  }

  void rule_shot(ShotRuling& x) const override {
    GameState& s = x.s;
    Ruling& r = x.r;
    const ShotFacts& f = x.f;
    const Shoot& shot = x.shot;
    const std::string& who = x.who;
    const std::string& what = x.what;
    const std::vector<Foul>& fouls = r.fouls;
    const bool is_break = x.is_break;
    const bool nine_in = has(f.pocketed, 9);
    // The 9 driven off the table is spotted (WPA 9-ball 2.6); no other
    // object ball is. Leaving the table is a foul, so only a foul can
    // send the 9 there.
    const bool nine_off = has(x.objects_off, 9);
    const int lowest = x.targets.empty() ? -1 : x.targets.front();
    if (is_break) {
      r.legal_break = !x.objects.empty() || f.object_balls_to_cushion >= 4;
      if (f.first_hit < 0)
        x.foul(Foul::no_contact);
      else if (f.first_hit != lowest)
        x.foul(Foul::wrong_ball_first);
      if (!r.legal_break) x.foul(Foul::illegal_break);
    } else if (shot.push_out) {
      // Push-out: only the other fouls apply (WPA 9-ball).
    } else {
      if (f.first_hit < 0)
        x.foul(Foul::no_contact);
      else if (f.first_hit != lowest)
        x.foul(Foul::wrong_ball_first);
      if (f.first_hit >= 0 && x.objects.empty() && !f.cushion_after_contact) {
        x.foul(Foul::no_rail);
      }
    }
    auto& streak = s.fouls_in_a_row[static_cast<std::size_t>(x.shooter)];
    s.push_out_allowed = is_break;  // the shot after the break may be a push-out
    if (!fouls.empty()) {
      rotation_foul(x, 9, nine_in || nine_off);
    } else if (shot.push_out) {
      streak = 0;
      if (nine_in) x.spot(9);
      s.phase = Phase::push_out_choice;
      s.after_push_out = true;
      s.ball_in_hand = BallInHand::none;
      x.pass_turn();
      r.text = what + "Push-out" + (nine_in ? "; the 9 is spotted" : "") + ": " +
               player_name(x.opp) + " shoots from here or passes the shot back.";
    } else {
      streak = 0;
      s.phase = Phase::shot;
      s.ball_in_hand = BallInHand::none;
      if (nine_in) {
        x.game_over(x.shooter,
                    who + (is_break ? " pocketed the 9 on the break" : " pocketed the 9 legally"));
        r.text = what + s.result + ": " + who + " wins.";
      } else if (!x.objects.empty()) {
        r.turn_continues = true;
        r.text = what + (is_break ? "Legal break; " : "") + who + " shoots again" +
                 (is_break ? " and may push out." : ".");
      } else {
        x.pass_turn();
        r.text = what + (is_break ? "Legal break; " : "") + player_name(x.opp) + " to shoot" +
                 (is_break ? " and may push out." : ".");
      }
    }
  }
};

}  // namespace

std::shared_ptr<const Ruleset> make_nine_ball_ruleset() { return std::make_shared<NineBall>(); }

}  // namespace breakshot::detail

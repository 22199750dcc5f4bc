// 10-ball by the WPA rules (2009 and later, as decisions.md reads them):
// the lowest ball first; every shot but the break calls one ball and one
// pocket (or declares a safety); the 10 pocketed on a legal break is
// spotted and the breaker goes on; a push-out on the shot after the
// break; a ball pocketed wrongly (not the one called, or in another
// pocket) ends the inning and the incoming player chooses who shoots
// next, the 10 spotted if it went down so; the called 10 made legally
// wins; three fouls in a row lose the rack. docs/rules.md lists the
// clauses.
#include <memory>
#include <string>

#include "ruleset.hpp"

namespace breakshot::detail {

namespace {

constexpr int kTen = 10;

class TenBall final : public Ruleset {
 public:
  int ball_count() const override { return 11; }

  std::vector<Foul> foul_kinds() const override { return pool_foul_kinds(); }

  std::vector<int> targets(const GameState& s) const override { return lowest_ball(s); }

  std::vector<Choice> choices(Phase phase) const override {
    // After a push-out, and after a ball pocketed wrongly: the incoming
    // player shoots from here or hands the shot back.
    if (phase == Phase::push_out_choice) return {Choice::shoot, Choice::pass_back};
    return {};
  }

  void legal_shot(const GameState& s, LegalActions& la) const override {
    la.push_out = s.phase == Phase::shot && s.push_out_allowed;
    la.call = s.phase == Phase::shot;  // every shot but the break is called
  }

  std::optional<std::string> check_shot(const Rules& rules, const GameState& s,
                                        const Shoot& shot) const override {
    if (shot.nominate) return "10-ball has no nominated ball (nominate is snooker's)";
    if (s.phase == Phase::break_shot) {
      if (shot.call || shot.safety || shot.push_out) {
        return "the break is neither called, a safety nor a push-out";
      }
      return std::nullopt;
    }
    if (shot.push_out) {
      if (!s.push_out_allowed) return "a push-out is only allowed on the shot right after the break";
      if (shot.call || shot.safety) return "a push-out has no call and is no safety";
      return std::nullopt;
    }
    if (shot.call && shot.safety) return "a declared safety has no call";
    if (!shot.call && !shot.safety) {
      return "10-ball: every shot but the break calls a ball and a pocket, or is a safety";
    }
    if (shot.call) {
      if (auto why = check_call(rules, s, *shot.call, ball_count())) return why;
    }
    return std::nullopt;
  }

  void decide(DecisionRuling& d, Choice choice) const override {
    rotation_reply(d, choice, "takes the table", "hands the shot back to");
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
    const bool ten_in = has(f.pocketed, kTen);
    // The 10 driven off the table is spotted, as in 9-ball; leaving the
    // table is a foul.
    const bool ten_off = has(x.objects_off, kTen);
    const int lowest = x.targets.empty() ? -1 : x.targets.front();
    if (shot.push_out) {
      // Push-out: only the other fouls apply.
    } else {
      if (f.first_hit < 0) {
        x.foul(Foul::no_contact);
      } else if (f.first_hit != lowest) {
        x.foul(Foul::wrong_ball_first);
      }
      if (is_break) {
        r.legal_break = !x.objects.empty() || f.object_balls_to_cushion >= 4;
        if (!r.legal_break) x.foul(Foul::illegal_break);
      } else if (f.first_hit >= 0 && x.objects.empty() && !f.cushion_after_contact) {
        x.foul(Foul::no_rail);
      }
    }
    auto& streak = s.fouls_in_a_row[static_cast<std::size_t>(x.shooter)];
    s.push_out_allowed = is_break;  // the shot after the break may be a push-out
    if (!fouls.empty()) {
      rotation_foul(x, kTen, ten_in || ten_off);
      return;
    }
    streak = 0;
    if (shot.push_out) {
      if (ten_in) x.spot(kTen);
      s.phase = Phase::push_out_choice;
      s.after_push_out = true;
      s.ball_in_hand = BallInHand::none;
      x.pass_turn();
      r.text = what + "Push-out" + (ten_in ? "; the 10 is spotted" : "") + ": " +
               player_name(x.opp) + " shoots from here or hands the shot back.";
      return;
    }
    s.phase = Phase::shot;
    s.ball_in_hand = BallInHand::none;
    if (is_break) {
      // A legal break: the 10 is spotted, balls pocketed stay down, and a
      // pocketed ball keeps the breaker at the table.
      if (ten_in) x.spot(kTen);
      const std::string spotted = ten_in ? "the 10 is spotted; " : "";
      if (!x.objects.empty()) {
        r.turn_continues = true;
        r.text = what + "Legal break; " + spotted + who + " shoots again and may push out.";
      } else {
        x.pass_turn();
        r.text = what + "Legal break; " + spotted + player_name(x.opp) +
                 " to shoot and may push out.";
      }
      return;
    }
    if (shot.safety) {
      // A declared safety: the balls it pockets stay down (the 10 is
      // spotted) and the inning ends.
      if (ten_in) x.spot(kTen);
      x.pass_turn();
      r.text = what + "Safety" + (ten_in ? "; the 10 is spotted" : "") + ": " +
               player_name(x.opp) + " to shoot.";
      return;
    }
    const Call& call = *shot.call;
    const bool made = x.pocket_of(call.ball) == call.pocket;
    if (made && call.ball == kTen) {
      x.game_over(x.shooter, who + " pocketed the called 10");
      r.text = what + s.result + ": " + who + " wins.";
      return;
    }
    if (ten_in) x.spot(kTen);
    const std::string spotted = ten_in ? "; the 10 is spotted" : "";
    if (made) {
      r.turn_continues = true;
      r.text = what + "The call is made" + spotted + ": " + who + " shoots again.";
      return;
    }
    x.pass_turn();
    if (x.objects.empty()) {
      r.text = what + player_name(x.opp) + " to shoot.";
      return;
    }
    // A ball pocketed wrongly: the incoming player chooses who shoots.
    s.phase = Phase::push_out_choice;
    r.text = what + "Not the call" + spotted + ": " + player_name(x.opp) +
             " shoots from here or hands the shot back.";
  }
};

}  // namespace

std::shared_ptr<const Ruleset> make_ten_ball_ruleset() { return std::make_shared<TenBall>(); }

}  // namespace breakshot::detail

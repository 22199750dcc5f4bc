// Three-cushion billiards by the UMB rules (docs/rules.md, "Three-cushion",
// which cites each clause): the starting position, the point (the ball
// struck touches both object balls, and three cushions before its first
// contact with the second), the inning that goes on after a point, the
// fouls that end it, balls off the table and balls in contact spotted
// again, and the end of the game at the target score, with the equalizing
// inning and the innings limit.
#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/rack.hpp"
#include "ruleset.hpp"

namespace breakshot {

namespace detail {
namespace {

constexpr int kWhite = 0;
constexpr int kYellow = 1;
constexpr int kRed = 2;
constexpr int kBalls = 3;

std::string ball_name(int b) {
  switch (b) {
    case kWhite:
      return "the white";
    case kYellow:
      return "the yellow";
    case kRed:
      return "the red";
    default:
      return "ball " + std::to_string(b);
  }
}

/// The cue ball of `player`: the breaker plays the white, the other the
/// yellow (UMB: the player who begins plays the white).
int own_ball(const GameState& s, int player) { return player == s.breaker ? kWhite : kYellow; }

std::string score_text(const CaromState& k) {
  return std::to_string(k.score[0]) + "-" + std::to_string(k.score[1]);
}

std::string cushions_text(int n) { return std::to_string(n) + (n == 1 ? " cushion" : " cushions"); }

}  // namespace
}  // namespace detail

CaromCount carom_count(const std::vector<Event>& events, int struck) {
  CaromCount c;
  for (const Event& e : events) {
    switch (e.type) {
      case EventType::cue_strike:
        if (e.ball == struck) c.strike = e.time;
        break;
      case EventType::ball_cushion:
        if (e.ball == struck && !c.done()) c.cushions += 1;
        break;
      case EventType::ball_ball: {
        if (e.ball != struck && e.other != struck) {
          c.kiss = true;
          break;
        }
        const int o = e.ball == struck ? e.other : e.ball;
        if (c.first_contact < 0.0) c.first_contact = e.time;
        if (!c.done() && std::find(c.hit.begin(), c.hit.end(), o) == c.hit.end()) {
          c.hit.push_back(o);
        }
        break;
      }
      case EventType::ball_pocket:
      case EventType::ball_off_table:
      case EventType::state_change:
      case EventType::ball_slate:
        break;
    }
  }
  return c;
}

namespace detail {
namespace {

class ThreeCushionRuleset final : public Ruleset {
 public:
  int ball_count() const override { return kBalls; }

  int cue_ball(const GameState& s) const override { return own_ball(s, s.player); }

  std::vector<Foul> foul_kinds() const override {
    return {Foul::wrong_ball_first, Foul::wrong_cue_ball, Foul::push_through};
  }

  int ball_value(int /*ball*/) const override { return 0; }  // points come from caroms, not pots

  Standing standing(const GameState& s) const override {
    Standing st;
    if (s.carom) st.score = s.carom->score;
    return st;
  }

  std::vector<int> targets(const GameState& s) const override {
    // The break must hit the red directly (UMB 3.3); after it either
    // object ball may come first.
    if (s.phase == Phase::break_shot) return {kRed};
    const int own = own_ball(s, s.player);
    return {own == kWhite ? kYellow : kWhite, kRed};
  }

  std::vector<Choice> choices(Phase /*phase*/) const override { return {}; }

  void legal_shot(const GameState& /*s*/, LegalActions& /*la*/) const override {}

  std::optional<std::string> check_shot(const Rules& /*rules*/, const GameState& /*s*/,
                                        const Shoot& shot) const override {
    if (shot.call) return "three-cushion has no called shots";
    if (shot.safety) return "three-cushion has no declared safety";
    if (shot.push_out) return "three-cushion has no push-out";
    if (shot.nominate) return "three-cushion has no nominated ball (nominate is snooker's)";
    return std::nullopt;
  }

  void decide(DecisionRuling& /*d*/, Choice /*choice*/) const override {
    throw std::logic_error("three-cushion has no decisions");
  }

  bool start(const Rules& rules, std::uint64_t rack_seed, int breaker,
             GameState& s) const override {
    for (const RackedBall& b :
         make_rack("three_cushion", rules.table(), rules.config().ball_radius, rack_seed)) {
      const int n = b.id == "white" ? kWhite : b.id == "yellow" ? kYellow : kRed;
      s.position[static_cast<std::size_t>(n)] = b.position;
      s.on_table[static_cast<std::size_t>(n)] = 1;
    }
    s.phase = Phase::break_shot;
    s.player = breaker;
    s.breaker = breaker;
    s.ball_in_hand = BallInHand::none;
    s.rack_seed = rack_seed;
    s.innings = 1;
    CaromState k;
    k.innings[static_cast<std::size_t>(breaker)] = 1;
    s.carom = k;
    return true;
  }

  void rule_shot(ShotRuling& x) const override {
    GameState& s = x.s;
    Ruling& r = x.r;
    CaromState& k = *s.carom;
    const CaromRules& opts = x.rules.config().carom;
    const int own = own_ball(x.before, x.shooter);
    const int cue = x.shot.cue_ball.value_or(own);
    const CaromCount path = carom_count(x.events, cue);

    // Fouls: the common part has added ball_off_table.
    if (cue != own) x.foul(Foul::wrong_cue_ball);
    if (path.first_contact >= 0.0 && path.first_contact - path.strike < kCaromTipContact) {
      x.foul(Foul::push_through);
    }
    // The break must meet the red first and directly: no cushion before.
    if (x.is_break && !x.f.miscue &&
        (path.hit.empty() || path.hit.front() != kRed ||
         cushions_before_first(x.events, cue) > 0)) {
      x.foul(Foul::wrong_ball_first);
    }

    CaromRuling c;
    c.cue_ball = cue;
    c.hit = path.hit;
    c.cushions = path.cushions;
    c.kiss = path.kiss;
    const bool both = path.done();
    c.point = r.fouls.empty() && path.made();

    // The shot in words.
    std::string text = x.who;
    if (x.f.miscue) {
      text += " miscues: the cue ball does not move";
    } else if (path.hit.empty()) {
      text += " hits neither ball (" + cushions_text(path.cushions) + ")";
    } else if (path.hit.size() == 1) {
      text += " hits only " + ball_name(path.hit[0]) + " (" + cushions_text(path.cushions) + ")";
    } else {
      text += " hits " + ball_name(path.hit[0]) + ", then " + ball_name(path.hit[1]) + " after " +
              cushions_text(path.cushions);
    }
    if (cue != own) text += ", playing " + ball_name(cue) + " instead of " + ball_name(own);
    if (path.kiss) text += "; the object balls kiss";
    text += ". ";
    if (!x.f.off_table.empty()) {
      std::string balls;
      for (std::size_t i = 0; i < x.f.off_table.size(); ++i) {
        if (i > 0) balls += i + 1 == x.f.off_table.size() ? " and " : ", ";
        balls += ball_name(x.f.off_table[i]);
      }
      balls[0] = 'T';
      text += balls + (x.f.off_table.size() == 1 ? " leaves" : " leave") + " the table. ";
    }
    if (!r.fouls.empty()) {
      text += "Foul: " + fouls_in_words(r.fouls) + ". No point. ";
    } else if (c.point) {
      text += "A point. ";
    } else if (both) {
      text += "Fewer than three cushions before the second ball: no point. ";
    } else {
      text += "No point. ";
    }

    // Balls off the table come back before anything else is decided.
    const int scorer = x.shooter;
    bool inning_ends = !c.point;
    if (c.point) {
      k.score[static_cast<std::size_t>(scorer)] += 1;
      k.run += 1;
    }
    r.carom = c;

    // The end of the game.
    const int target = opts.target;
    const bool reached = k.score[static_cast<std::size_t>(scorer)] >= target;
    const bool breaker_shoots = scorer == x.before.breaker;
    std::string ending;
    int winner = -2;  // -2: the game goes on; -1: a draw
    if (reached && !breaker_shoots) {
      // The other player reaches the target: first (a win), or in the
      // equalizing inning (a draw: both reached it in as many innings).
      winner = k.equalizing ? -1 : scorer;
    } else if (reached) {
      if (opts.equalizing_inning) {
        ending = x.who + " reaches " + std::to_string(target) + ": " + player_name(x.opp) +
                 " has the equalizing inning. ";
        k.equalizing = true;
        inning_ends = true;
      } else {
        winner = scorer;
      }
    } else if (inning_ends && k.equalizing) {
      winner = x.opp;  // the equalizing inning ends short of the target
    } else if (inning_ends && !breaker_shoots && opts.innings_limit > 0 &&
               k.innings[static_cast<std::size_t>(scorer)] >= opts.innings_limit) {
      const int a = k.score[0];
      const int b = k.score[1];
      winner = a == b ? -1 : (a > b ? 0 : 1);
      ending = "The innings limit (" + std::to_string(opts.innings_limit) + ") is reached. ";
    }

    if (winner != -2) {
      text += ending;
      const int innings = k.innings[static_cast<std::size_t>(x.before.breaker)];
      const std::string why =
          winner < 0 ? "drawn at " + score_text(k) + " in " + std::to_string(innings) + " innings"
                     : player_name(winner) + " wins " +
                           std::to_string(k.score[static_cast<std::size_t>(winner)]) + "-" +
                           std::to_string(k.score[static_cast<std::size_t>(1 - winner)]) + " in " +
                           std::to_string(innings) + " innings";
      x.game_over(winner, why);
      k.run = 0;
      text += (winner < 0 ? "The game is " : "") + why + ".";
      respot_off_table(x, text, x.shooter);
      r.text = text;
      return;
    }

    s.phase = Phase::shot;
    s.ball_in_hand = BallInHand::none;
    if (inning_ends) {
      k.run = 0;
      x.pass_turn();
      k.innings[static_cast<std::size_t>(s.player)] += 1;
      r.turn_continues = false;
      text += ending + "Score " + score_text(k) + "; " + player_name(s.player) + " plays inning " +
              std::to_string(k.innings[static_cast<std::size_t>(s.player)]) +
              (k.equalizing ? " (the equalizing inning)" : "") + ".";
    } else {
      r.turn_continues = true;
      text += "Score " + score_text(k) + ", a run of " + std::to_string(k.run) + "; " + x.who +
              " plays on.";
    }
    respot_off_table(x, text, s.player);
    respot_touching(x, text, s.player);
    r.text = text;
  }

 private:
  static int cushions_before_first(const std::vector<Event>& events, int cue) {
    int n = 0;
    for (const Event& e : events) {
      if (e.type == EventType::ball_ball && (e.ball == cue || e.other == cue)) return n;
      if (e.type == EventType::ball_cushion && e.ball == cue) n += 1;
    }
    return n;
  }

  /// The spot a ball goes back to (UMB 3.8, 3.7): the red to the top
  /// spot, the cue ball of the player to act next to the bottom spot, the
  /// other cue ball to the centre spot.
  static Vec2 home(int ball, int next_own) {
    const CaromMarks m = carom_marks();
    if (ball == kRed) return m.top_spot;
    return ball == next_own ? m.bottom_spot : m.centre_spot;
  }

  /// Puts `ball` on its home spot or, when another ball stands in the way,
  /// on that ball's home spot, else on the third spot.
  static void place(ShotRuling& x, int ball, int next_own) {
    GameState& s = x.s;
    const double R = x.rules.config().ball_radius;
    const auto blocker = [&](Vec2 p) {
      for (int b = 0; b < kBalls; ++b) {
        if (b != ball && s.on_table[static_cast<std::size_t>(b)] &&
            norm(s.position[static_cast<std::size_t>(b)] - p) < 2.0 * R) {
          return b;
        }
      }
      return -1;
    };
    std::vector<Vec2> tries{home(ball, next_own)};
    if (const int b = blocker(tries[0]); b >= 0) tries.push_back(home(b, next_own));
    for (int b = 0; b < kBalls; ++b) tries.push_back(home(b, next_own));
    for (const Vec2 p : tries) {
      if (blocker(p) < 0) {
        s.position[static_cast<std::size_t>(ball)] = p;
        s.on_table[static_cast<std::size_t>(ball)] = 1;
        if (std::find(x.r.spotted.begin(), x.r.spotted.end(), ball) == x.r.spotted.end()) {
          x.r.spotted.push_back(ball);
        }
        return;
      }
    }
    throw std::logic_error("no free spot for " + ball_name(ball));
  }

  static std::string spot_name(Vec2 p) {
    const CaromMarks m = carom_marks();
    if (p == m.top_spot) return "the top spot";
    if (p == m.bottom_spot) return "the bottom spot";
    return "the centre spot";
  }

  /// Balls that left the table go back on their spots for the next shot,
  /// in the order red, then the cue balls (the next player's first).
  static void respot_off_table(ShotRuling& x, std::string& text, int next_player) {
    if (x.f.off_table.empty()) return;
    const int next_own = own_ball(x.s, next_player);
    for (const int b : {kRed, next_own, next_own == kWhite ? kYellow : kWhite}) {
      if (std::find(x.f.off_table.begin(), x.f.off_table.end(), b) == x.f.off_table.end()) {
        continue;
      }
      x.s.on_table[static_cast<std::size_t>(b)] = 0;
      place(x, b, next_own);
      std::string name = ball_name(b);
      name[0] = 'T';
      text += " " + name + " is spotted on " +
              spot_name(x.s.position[static_cast<std::size_t>(b)]) + ".";
    }
  }

  /// When the next player's cue ball touches another ball, the balls in
  /// contact are spotted again (UMB 3.7): the cue ball on the bottom
  /// spot, the red on the top spot, the other cue ball on the centre spot.
  static void respot_touching(ShotRuling& x, std::string& text, int next_player) {
    if (x.s.phase == Phase::game_over) return;
    GameState& s = x.s;
    const int next_own = own_ball(s, next_player);
    const double R = x.rules.config().ball_radius;
    std::vector<int> touching;
    for (int b = 0; b < kBalls; ++b) {
      if (b == next_own) continue;
      const double gap = norm(s.position[static_cast<std::size_t>(b)] -
                              s.position[static_cast<std::size_t>(next_own)]) -
                         2.0 * R;
      if (gap <= kCaromTouching) touching.push_back(b);
    }
    if (touching.empty()) return;
    std::vector<int> moved{next_own};
    moved.insert(moved.end(), touching.begin(), touching.end());
    for (const int b : moved) s.on_table[static_cast<std::size_t>(b)] = 0;
    std::string names;
    for (const int b : touching) names += (names.empty() ? "" : " and ") + ball_name(b);
    std::string own = ball_name(next_own);
    own[0] = 'T';
    text += " " + own + " touches " + names + ": the balls in contact are spotted (";
    for (std::size_t i = 0; i < moved.size(); ++i) {
      place(x, moved[i], next_own);
      text += (i > 0 ? ", " : "") + ball_name(moved[i]) + " on " +
              spot_name(s.position[static_cast<std::size_t>(moved[i])]);
    }
    text += ").";
  }
};

}  // namespace

std::shared_ptr<const Ruleset> make_three_cushion_ruleset() {
  return std::make_shared<ThreeCushionRuleset>();
}

}  // namespace detail

GameConfig three_cushion_config() {
  GameConfig c;
  c.game = GameType::three_cushion;
  c.table_size = "10ft";
  c.ball_radius = kCaromBallRadius;
  c.ball_mass = kCaromBallMass;
  return c;
}

GameConfig default_game_config(GameType game) {
  if (game == GameType::snooker) return snooker_config();
  if (game == GameType::three_cushion) return three_cushion_config();
  GameConfig c;
  c.game = game;
  return c;
}

}  // namespace breakshot

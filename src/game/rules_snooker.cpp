// Snooker by the WPBSA Official Rules of Snooker: the ball on (a red, then
// a nominated colour, then the colours in order), scoring and the break,
// fouls and their penalties, the choice after a foul, the free ball, the
// foul and a miss with the balls replaced, colours re-spotted, the cue
// ball in hand in the D, touching ball, the end of the frame with the
// re-spotted black, conceding. docs/rules.md lists the clauses by their
// WPBSA numbers and what is simplified.
//
// Balls: 0 the cue ball, 1-15 the reds, 16-21 the yellow, green, brown,
// blue, pink and black (values 2-7).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/snooker.hpp"
#include "ruleset.hpp"

namespace breakshot {

namespace {

constexpr int kBalls = 22;
constexpr int kYellow = 16;
constexpr int kPink = 20;
constexpr int kBlack = 21;
/// The stream of mix_seed(rack seed, .) that draws the lots on a tie
/// after the black (WPBSA 3.3(k)(ii)).
constexpr std::uint64_t kLotStream = 0x6c6f7473;  // "lots"

constexpr std::array<const char*, 6> kColourNames{"yellow", "green", "brown",
                                                  "blue",   "pink",  "black"};

bool is_red(int b) { return b >= 1 && b <= 15; }
bool is_colour(int b) { return b >= kYellow && b <= kBlack; }

const SnookerState& part(const GameState& s) {
  if (s.game != GameType::snooker || !s.snooker ||
      s.on_table.size() != static_cast<std::size_t>(kBalls) ||
      s.position.size() != static_cast<std::size_t>(kBalls)) {
    throw std::invalid_argument("not a snooker state (22 balls and snooker's part needed)");
  }
  return *s.snooker;
}

bool on(const GameState& s, int b) { return s.on_table[static_cast<std::size_t>(b)] != 0; }
Vec2 pos(const GameState& s, int b) { return s.position[static_cast<std::size_t>(b)]; }

int reds_left(const GameState& s) {
  int n = 0;
  for (int b = 1; b <= 15; ++b) n += on(s, b) ? 1 : 0;
  return n;
}

/// Only the black is left of the object balls.
bool black_alone(const GameState& s) {
  for (int b = 1; b < kBlack; ++b) {
    if (on(s, b)) return false;
  }
  return on(s, kBlack);
}

/// Only the pink and the black are left (WPBSA 3.9(c)).
bool pink_and_black_alone(const GameState& s) {
  for (int b = 1; b < kPink; ++b) {
    if (on(s, b)) return false;
  }
  return on(s, kPink) && on(s, kBlack);
}

std::string name(int b) {
  if (b == 0) return "cue ball";
  if (is_red(b)) return "red";
  if (is_colour(b)) return kColourNames[static_cast<std::size_t>(b - kYellow)];
  return "ball " + std::to_string(b);
}

/// "a red", "3 reds and the pink", "the cue ball".
std::string describe(const std::vector<int>& balls) {
  std::vector<std::string> parts;
  const auto reds = std::count_if(balls.begin(), balls.end(), is_red);
  if (reds == 1) parts.push_back("a red");
  if (reds > 1) parts.push_back(std::to_string(reds) + " reds");
  for (int b : balls) {
    if (!is_red(b)) parts.push_back("the " + name(b));
  }
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) out += i + 1 == parts.size() ? " and " : ", ";
    out += parts[i];
  }
  return out;
}

bool fouled_with(const std::vector<Foul>& fouls, Foul f) {
  return std::find(fouls.begin(), fouls.end(), f) != fouls.end();
}

std::string points_text(int n) { return std::to_string(n) + (n == 1 ? " point" : " points"); }

std::string score_text(const SnookerState& k) {
  return "Score " + std::to_string(k.score[0]) + "-" + std::to_string(k.score[1]) + ".";
}

/// What the player to act is on, in words.
std::string on_text(const GameState& s) {
  const SnookerState& k = part(s);
  if (k.colour_on) return "a colour";
  if (!k.respotted_black && reds_left(s) > 0) return "a red";
  const std::vector<int> balls = snooker_balls_on(s);
  return balls.empty() ? "nothing" : "the " + name(balls.front());
}

/// The ball at `b` can be hit along the straight segment from `from` to
/// `to` (the cue ball's centre) without the cue ball coming within 2R of
/// a ball for which `obstacle` is true.
template <class Obstacle>
bool path_clear(const GameState& s, Vec2 from, Vec2 to, double R, Obstacle obstacle) {
  for (int b = 1; b < kBalls; ++b) {
    if (!on(s, b) || !obstacle(b)) continue;
    if (segment_distance(pos(s, b), from, to) < 2.0 * R) return false;
  }
  return true;
}

/// Both extreme edges of ball `b` can be hit from the cue ball along
/// straight paths clear of the balls for which `obstacle` is true. The
/// grazing paths pass a millionth of 2R inside the edge.
template <class Obstacle>
bool edges_clear(const GameState& s, int b, double R, Obstacle obstacle) {
  const Vec2 c = pos(s, 0);
  const Vec2 to = pos(s, b) - c;
  const double d = norm(to);
  if (d <= 2.0 * R + kSnookerTouching) return true;  // touching: played away from (3.7)
  const Vec2 u = to / d;
  const Vec2 w = perp(u);
  const double sin_a = 2.0 * R * (1.0 - 1e-6) / d;
  const double cos_a = std::sqrt(1.0 - sin_a * sin_a);
  const double run = d * cos_a;  // to where the cue ball's centre passes closest
  for (const double side : {1.0, -1.0}) {
    const Vec2 dir = u * cos_a + w * (side * sin_a);
    if (!path_clear(s, c, c + dir * run, R, obstacle)) return false;
  }
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------
// Public helpers (game.hpp)

GameConfig snooker_config() {
  GameConfig c;
  c.game = GameType::snooker;
  c.table_size = "12ft";
  c.ball_radius = kSnookerBallRadius;
  c.ball_mass = kSnookerBallMass;
  return c;
}

int snooker_value(int ball) {
  if (is_red(ball)) return 1;
  if (is_colour(ball)) return ball - 14;
  return 0;
}

std::vector<int> snooker_balls_on(const GameState& s) {
  const SnookerState& k = part(s);
  std::vector<int> out;
  if (k.respotted_black) {
    if (on(s, kBlack)) out.push_back(kBlack);
    return out;
  }
  if (k.colour_on) {
    for (int b = kYellow; b <= kBlack; ++b) {
      if (on(s, b)) out.push_back(b);
    }
    return out;
  }
  for (int b = 1; b <= 15; ++b) {
    if (on(s, b)) out.push_back(b);
  }
  if (!out.empty()) return out;
  for (int b = kYellow; b <= kBlack; ++b) {
    if (on(s, b)) return {b};
  }
  return out;
}

int snooker_points_remaining(const GameState& s) {
  const SnookerState& k = part(s);
  if (k.respotted_black) return on(s, kBlack) ? 7 : 0;
  const int reds = reds_left(s);
  int colours = 0;
  for (int b = kYellow; b <= kBlack; ++b) colours += on(s, b) ? snooker_value(b) : 0;
  if (reds > 0 || k.colour_on) return 8 * reds + (k.colour_on ? 7 : 0) + colours;
  return colours;
}

int snookers_required(const GameState& s, int player) {
  if (player != 0 && player != 1) throw std::invalid_argument("player must be 0 or 1");
  const SnookerState& k = part(s);
  const auto p = static_cast<std::size_t>(player);
  const int deficit = k.score[1 - p] - k.score[p];
  const int beyond = deficit - snooker_points_remaining(s);
  if (beyond <= 0) return 0;
  int per = 4;
  if (reds_left(s) == 0 && !k.colour_on) {
    for (int b = kYellow; b <= kBlack; ++b) {
      if (on(s, b)) {
        per = std::max(4, snooker_value(b));
        break;
      }
    }
  }
  return (beyond + per - 1) / per;
}

std::vector<int> Rules::touching(const GameState& s) const {
  (void)part(s);
  std::vector<int> out;
  if (!on(s, 0)) return out;
  const double R = config_.ball_radius;
  for (int b = 1; b < kBalls; ++b) {
    if (on(s, b) && norm(pos(s, b) - pos(s, 0)) <= 2.0 * R + kSnookerTouching) out.push_back(b);
  }
  return out;
}

bool Rules::snookered(const GameState& s) const {
  (void)part(s);
  if (!on(s, 0)) return false;
  const std::vector<int> balls = snooker_balls_on(s);
  const double R = config_.ball_radius;
  const auto not_on = [&](int b) { return !detail::has(balls, b); };
  for (int b : balls) {
    if (edges_clear(s, b, R, not_on)) return false;
  }
  return !balls.empty();
}

bool Rules::full_ball_on(const GameState& s) const {
  (void)part(s);
  if (!on(s, 0)) return false;
  const double R = config_.ball_radius;
  const Vec2 c = pos(s, 0);
  for (int b : snooker_balls_on(s)) {
    const Vec2 to = pos(s, b) - c;
    const double d = norm(to);
    if (d <= 2.0 * R + kSnookerTouching) continue;
    const Vec2 contact = pos(s, b) - to / d * (2.0 * R);
    if (path_clear(s, c, contact, R, [&](int o) { return o != b; })) return true;
  }
  return false;
}

namespace detail {

namespace {

class Snooker final : public Ruleset {
 public:
  Snooker() : m_(snooker_marks()) {}

  int ball_count() const override { return kBalls; }

  std::vector<Foul> foul_kinds() const override {
    return {Foul::in_off, Foul::no_contact, Foul::wrong_ball_first, Foul::wrong_ball_potted,
            Foul::free_ball_snooker};
  }

  std::vector<int> balls_on(const GameState& s) const override { return snooker_balls_on(s); }

  int ball_value(int ball) const override { return snooker_value(ball); }

  Standing standing(const GameState& s) const override {
    Standing st;
    st.score = part(s).score;
    st.points_left = snooker_points_remaining(s);
    return st;
  }

  std::vector<int> targets(const GameState& s) const override {
    std::vector<int> out = snooker_balls_on(s);
    if (part(s).free_ball) {
      for (int b = 1; b < kBalls; ++b) {
        if (on(s, b) && !has(out, b)) out.push_back(b);
      }
      std::sort(out.begin(), out.end());
    }
    return out;
  }

  std::vector<Choice> choices(Phase phase) const override {
    if (phase == Phase::foul_choice) return {Choice::play_on, Choice::offender_again};
    return {};
  }

  std::vector<Choice> state_choices(const GameState& s) const override {
    if (s.phase != Phase::foul_choice) return {};
    std::vector<Choice> out = choices(s.phase);
    if (!part(s).replace_position.empty()) out.push_back(Choice::replace_balls);
    out.push_back(Choice::concede);
    return out;
  }

  void legal_shot(const GameState& s, LegalActions& la) const override {
    const SnookerState& k = part(s);
    la.choices = {Choice::concede};  // WPBSA 4.6: only the striker concedes
    la.must_nominate = k.colour_on;
    la.nominate = targets(s);
  }

  std::optional<std::string> check_shot(const Rules& rules, const GameState& s,
                                        const Shoot& shot) const override {
    const SnookerState& k = part(s);
    if (shot.call) {
      // Informational only, as in 9-ball: it marks a pot attempt for the
      // statistics. A valid pocket and a ball on the table; the ball on
      // is still named by nominate.
      const Call& call = *shot.call;
      if (auto why = check_called_pocket(rules, call)) return why;
      if (call.ball < 1 || call.ball >= kBalls || !on(s, call.ball)) {
        return "called ball " + std::to_string(call.ball) + " is not on the table";
      }
    }
    if (shot.safety) return "snooker has no declared safety";
    if (shot.push_out) return "snooker has no push-out";
    if (shot.nominate) {
      const int b = *shot.nominate;
      if (b < 1 || b >= kBalls || !on(s, b)) {
        return "nominated ball " + std::to_string(b) + " is not on the table";
      }
      if (k.colour_on && !is_colour(b)) {
        return "after a red the nominated ball must be a colour (16 yellow ... 21 black), not " +
               std::to_string(b);
      }
      const std::vector<int> balls = snooker_balls_on(s);
      if (!k.colour_on && !k.free_ball && !has(balls, b)) {
        return "nominated ball " + std::to_string(b) + " (" + name(b) +
               ") is not on: " + on_text(s) + " is";
      }
    } else if (k.colour_on) {
      return "after a red the shot must nominate a colour (16 yellow ... 21 black)";
    }
    return std::nullopt;
  }

  std::optional<std::string> check_place(const Rules& /*rules*/, const GameState& s,
                                         Vec2 p) const override {
    if (s.ball_in_hand != BallInHand::d) return std::nullopt;
    // The D: behind the baulk line (on it included), within its radius.
    constexpr double kEdge = 1e-12;
    if (p.x > m_.baulk_x + kEdge || norm(p - m_.d_centre) > m_.d_radius + kEdge) {
      return "the cue ball must be placed in the D (x <= " + std::to_string(m_.baulk_x) +
             " m and at most " + std::to_string(m_.d_radius) + " m from (" +
             std::to_string(m_.d_centre.x) + ", " + std::to_string(m_.d_centre.y) + "))";
    }
    return std::nullopt;
  }

  std::optional<Vec2> spot_position(const Rules& rules, const GameState& s,
                                    int ball) const override {
    if (!is_colour(ball)) return std::nullopt;
    GameState t = s;
    t.on_table[static_cast<std::size_t>(ball)] = 0;
    return spot_place(rules, t, ball, true);
  }

  bool start(const Rules& rules, std::uint64_t rack_seed, int breaker,
             GameState& s) const override {
    const std::vector<RackedBall> rack =
        make_rack("snooker", rules.table(), rules.config().ball_radius, rack_seed);
    for (const RackedBall& b : rack) {
      int n = -1;
      if (b.id.rfind("red", 0) == 0) {
        n = std::stoi(b.id.substr(3));
      } else {
        for (std::size_t c = 0; c < kColourNames.size(); ++c) {
          if (b.id == kColourNames[c]) n = kYellow + static_cast<int>(c);
        }
      }
      if (n < 1 || n >= kBalls) throw std::logic_error("snooker rack: unknown ball " + b.id);
      s.position[static_cast<std::size_t>(n)] = b.position;
      s.on_table[static_cast<std::size_t>(n)] = 1;
    }
    s.position[0] = snooker_break_off_spot();
    s.on_table[0] = 1;
    s.phase = Phase::break_shot;
    s.player = breaker;
    s.breaker = breaker;
    s.ball_in_hand = BallInHand::d;
    s.rack_seed = rack_seed;
    s.innings = 1;
    s.snooker = SnookerState{};
    return true;
  }

  void decide(DecisionRuling& d, Choice choice) const override {
    GameState& s = d.s;
    SnookerState& k = *s.snooker;
    Ruling& r = d.r;
    const std::string& who = d.who;
    const auto clear_replace = [&] {
      k.replace_position.clear();
      k.replace_on_table.clear();
      k.replace_colour_on = false;
      k.replace_free_ball = false;
    };
    switch (choice) {
      case Choice::concede:
        s.phase = Phase::game_over;
        s.winner = d.opp;
        s.result = who + " conceded the frame";
        r.winner = d.opp;
        r.turn_continues = false;
        clear_replace();
        r.text = who + " concedes the frame at " + std::to_string(k.score[0]) + "-" +
                 std::to_string(k.score[1]) + ": " + player_name(d.opp) + " wins.";
        break;
      case Choice::play_on:
        s.phase = Phase::shot;
        k.misses = 0;
        clear_replace();
        r.text = who + " plays on" + (k.free_ball ? " with a free ball" : "") +
                 (s.on_table[0] ? "" : " from the D") + ".";
        break;
      case Choice::offender_again:
        s.phase = Phase::shot;
        k.free_ball = false;  // WPBSA 3.9: no free ball for the offender
        k.misses = 0;
        clear_replace();
        d.pass_turn();
        r.turn_continues = false;
        r.text = who + " has " + player_name(d.opp) + " play again" +
                 (s.on_table[0] ? " from where the balls lie." : " from the D.");
        break;
      case Choice::replace_balls:
        s.phase = Phase::shot;
        s.position = k.replace_position;
        s.on_table = k.replace_on_table;
        s.ball_in_hand = BallInHand::none;
        k.colour_on = k.replace_colour_on;
        k.free_ball = k.replace_free_ball;
        clear_replace();
        d.pass_turn();
        r.turn_continues = false;
        r.text = who + " has the balls replaced: " + player_name(d.opp) +
                 " plays again from the position of the miss" +
                 (k.misses >= 2 ? "; a third miss from it loses the frame." : ".");
        break;
      default:
        break;  // not on offer in snooker: check() refuses them
    }
  }

  void rule_shot(ShotRuling& x) const override {
    const Rules& rules = x.rules;
    const GameState& before = x.before;
    GameState& s = x.s;
    Ruling& r = x.r;
    const ShotFacts& f = x.f;
    const SnookerState& kb = part(before);
    SnookerState& k = *s.snooker;
    const auto shooter = static_cast<std::size_t>(x.shooter);
    const auto opp = static_cast<std::size_t>(x.opp);
    r.fouls.clear();  // snooker names its own fouls
    r.legal_break = true;
    SnookerRuling sr;

    // The ball on for this stroke (WPBSA 3.3), the balls the cue ball may
    // hit first and pot, and the value of the ball on.
    const std::vector<int> balls_on = snooker_balls_on(before);
    const int nominated = x.shot.nominate.value_or(-1);
    const bool free_ball = kb.free_ball && nominated > 0 && !has(balls_on, nominated);
    const bool reds_phase = !kb.colour_on && !kb.respotted_black && reds_left(before) > 0;
    const bool last_black = !kb.colour_on && black_alone(before);
    sr.free_ball = free_ball;
    sr.nominated = nominated;
    std::vector<int> first = kb.colour_on ? std::vector<int>{nominated} : balls_on;
    std::vector<int> pottable = first;
    const int value_on = kb.colour_on ? snooker_value(nominated)
                                      : (balls_on.empty() ? 0 : snooker_value(balls_on.front()));
    if (free_ball) {
      // WPBSA 3.9: the free ball is the ball on; hitting it first is required.
      first = {nominated};
      pottable.push_back(nominated);
    }

    // Touching ball (3.7): playing away from a touching ball on counts as
    // hitting it. The simulator shows a push only as a contact.
    bool touching_on = false;
    for (int t : rules.touching(before)) touching_on = touching_on || has(first, t);

    // Fouls (3.10, 3.11): the penalty is the value of the ball on or of a
    // ball concerned, the highest, at least 4.
    int penalty = std::max(4, value_on);
    const auto concern = [&](int b) { penalty = std::max(penalty, snooker_value(b)); };
    if (x.cue_in) x.foul(Foul::in_off);
    if (x.cue_off || !x.objects_off.empty()) x.foul(Foul::ball_off_table);
    for (int b : x.objects_off) concern(b);
    if (f.first_hit < 0) {
      if (!touching_on) x.foul(Foul::no_contact);
    } else if (!has(first, f.first_hit)) {
      x.foul(Foul::wrong_ball_first);
      concern(f.first_hit);
    }
    for (int b : x.objects) {
      if (!has(pottable, b)) {
        x.foul(Foul::wrong_ball_potted);
        concern(b);
      }
    }
    // A free ball must not leave the opponent snookered behind it (3.9(c)).
    if (r.fouls.empty() && free_ball && x.objects.empty() && on(s, 0) && on(s, nominated) &&
        !pink_and_black_alone(before)) {
      GameState next = s;
      next.snooker->colour_on = false;
      next.snooker->free_ball = false;
      GameState without = next;
      without.on_table[static_cast<std::size_t>(nominated)] = 0;
      if (rules.snookered(next) && !rules.snookered(without)) x.foul(Foul::free_ball_snooker);
    }
    const bool fouled = !r.fouls.empty();

    // The ruling's text begins with what happened.
    std::string what = x.who;
    if (free_ball) what = "Free ball (the " + name(nominated) + "): " + what;
    what += x.objects.empty() ? " pots nothing" : " pots " + describe(x.objects);
    if (x.cue_in) what += " and goes in-off";
    const std::string pots = what;  // for a scoring stroke: "...: 1 point, break 1."
    what += ". ";
    if (!f.off_table.empty()) {
      std::vector<int> objects_off = x.objects_off;
      what += (x.cue_off ? std::string("The cue ball") + (objects_off.empty() ? "" : " and ")
                         : std::string()) +
              (objects_off.empty()
                   ? ""
                   : (x.cue_off ? describe(objects_off) : capitalised(describe(objects_off)))) +
              (f.off_table.size() == 1 ? " leaves" : " leave") + " the table. ";
    }

    k.free_ball = false;
    clear_replace(k);

    if (fouled) {
      sr.penalty = penalty;
      sr.miss = (fouled_with(r.fouls, Foul::no_contact) ||
                 fouled_with(r.fouls, Foul::wrong_ball_first)) &&
                rules.full_ball_on(before);
      k.score[opp] += penalty;
      k.break_points = 0;
      k.colour_on = false;
      const std::string foul_text = std::string(sr.miss ? "Foul and a miss: " : "Foul: ") +
                                    fouls_in_words(r.fouls) + ". " + points_text(penalty) + " to " +
                                    player_name(x.opp) + ". ";
      if (last_black) {
        // The first score or foul on the last black ends the frame (3.3(j)).
        r.snooker = sr;
        end_frame(x, what + foul_text + score_text(k) + " ");
        return;
      }
      std::vector<int> spot;
      for (int b : x.objects) {
        if (is_colour(b)) spot.push_back(b);
      }
      for (int b : x.objects_off) {
        if (is_colour(b)) spot.push_back(b);
      }
      spot_colours(rules, s, spot, r.spotted);
      if (x.cue_gone()) s.on_table[0] = 0;
      s.ball_in_hand = x.cue_gone() ? BallInHand::d : BallInHand::none;
      if (sr.miss && kb.misses + 1 >= 3) {
        // Three misses from the same position with a full ball on: the
        // frame is awarded to the opponent (3.14(c)).
        r.snooker = sr;
        x.game_over(x.opp, x.who + " missed three times with a full ball on");
        r.text = what + foul_text + score_text(k) + " The third miss: the frame is awarded to " +
                 player_name(x.opp) + ".";
        return;
      }
      k.misses = sr.miss ? kb.misses + 1 : 0;
      if (sr.miss) {
        k.replace_position = before.position;
        k.replace_on_table = before.on_table;
        k.replace_colour_on = kb.colour_on;
        k.replace_free_ball = kb.free_ball;
      }
      s.phase = Phase::foul_choice;
      x.pass_turn();
      // The incoming player may be snookered: a free ball (3.9).
      k.free_ball = rules.snookered(s);
      r.text = what + foul_text + score_text(k) + " " + player_name(x.opp) + " may play on" +
               (k.free_ball ? " with a free ball" : "") +
               (sr.miss ? ", have " + x.who + " play again or have the balls replaced."
                        : " or have " + x.who + " play again.");
      if (sr.miss && k.misses == 2)
        r.text += " A third miss from the same position loses the frame.";
      r.snooker = sr;
      return;
    }

    // No foul: what the stroke scored (3.3, 3.9(d)-(f)).
    k.misses = 0;
    int points = 0;
    std::vector<int> spot;
    const bool free_in = free_ball && has(x.objects, nominated);
    if (free_in) spot.push_back(nominated);
    if (reds_phase) {
      for (int b : x.objects) points += is_red(b) ? 1 : 0;
      if (free_in) points += 1;  // the free ball counts as a red
    } else if (kb.colour_on) {
      if (has(x.objects, nominated)) {
        points = snooker_value(nominated);
        spot.push_back(nominated);  // colours go back while reds remain, and after the last red
      }
    } else {
      const int ball_on = balls_on.empty() ? -1 : balls_on.front();
      if (has(x.objects, ball_on) || free_in) points = value_on;
    }
    spot_colours(rules, s, spot, r.spotted);
    s.ball_in_hand = BallInHand::none;
    sr.points = points;
    r.snooker = sr;
    if (points > 0) {
      k.score[shooter] += points;
      k.break_points += points;
      k.colour_on = reds_phase;
      const std::string scored =
          pots + ": " + points_text(points) + ", break " + std::to_string(k.break_points) + ". ";
      if (last_black) {
        end_frame(x, scored + score_text(k) + " ");
        return;
      }
      s.phase = Phase::shot;
      r.turn_continues = true;
      r.text = scored + score_text(k) + " " + x.who + " is on " + on_text(s) + ".";
      return;
    }
    k.colour_on = false;
    k.break_points = 0;
    s.phase = Phase::shot;
    x.pass_turn();
    r.text = what + score_text(k) + " " + player_name(x.opp) + " to play, on " + on_text(s) + ".";
  }

 private:
  static std::string capitalised(std::string s) {
    if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
    return s;
  }

  static void clear_replace(SnookerState& k) {
    k.replace_position.clear();
    k.replace_on_table.clear();
    k.replace_colour_on = false;
    k.replace_free_ball = false;
  }

  Vec2 own_spot(int colour) const {
    switch (colour) {
      case kYellow:
        return m_.yellow;
      case kYellow + 1:
        return m_.green;
      case kYellow + 2:
        return m_.brown;
      case kYellow + 3:
        return m_.blue;
      case kPink:
        return m_.pink;
      default:
        return m_.black;
    }
  }

  /// Where `colour` goes (WPBSA 3.6): its own spot; else (`any_spot`) the
  /// highest-valued free spot; else the nearest free place from its own
  /// spot along the table's length toward the top cushion, else toward
  /// the bottom cushion (WPBSA gives the pink and the black this second
  /// way, 3.6(f); the others are given it too, for a place always to
  /// exist). Free: clear of the cushions and at least 2R from every ball
  /// on the table.
  Vec2 spot_place(const Rules& rules, const GameState& s, int colour, bool any_spot) const {
    const double R = rules.config().ball_radius;
    const Table& table = rules.table();
    const auto free = [&](Vec2 p) {
      if (wall_clearance(table, p, R) < 0.0) return false;
      for (int b = 0; b < kBalls; ++b) {
        if (on(s, b) && norm(pos(s, b) - p) < 2.0 * R) return false;
      }
      return true;
    };
    const Vec2 own = own_spot(colour);
    if (free(own)) return own;
    if (any_spot) {
      for (int c = kBlack; c >= kYellow; --c) {
        if (free(own_spot(c))) return own_spot(c);
      }
    }
    // Steps of R/64, as the pool games' spotting.
    const double step = R / 64.0;
    for (double x = own.x + step; x <= table.length - R; x += step) {
      if (free({x, own.y})) return {x, own.y};
    }
    for (double x = own.x - step; x >= R; x -= step) {
      if (free({x, own.y})) return {x, own.y};
    }
    throw std::logic_error("no free place to spot the " + name(colour));
  }

  /// Puts `colours` (off the table) back (3.6): first every one whose own
  /// spot is free, then the rest, highest value first, each on the
  /// highest-valued free spot or near its own (3.6(c)-(e)).
  void spot_colours(const Rules& rules, GameState& s, std::vector<int> colours,
                    std::vector<int>& spotted) const {
    std::sort(colours.begin(), colours.end(), [](int a, int b) { return a > b; });
    colours.erase(std::unique(colours.begin(), colours.end()), colours.end());
    std::vector<int> rest;
    const double R = rules.config().ball_radius;
    for (int c : colours) {
      const Vec2 own = own_spot(c);
      bool free = wall_clearance(rules.table(), own, R) >= 0.0;
      for (int b = 0; b < kBalls && free; ++b) {
        free = !(on(s, b) && norm(pos(s, b) - own) < 2.0 * R);
      }
      if (free) {
        place(s, c, own, spotted);
      } else {
        rest.push_back(c);
      }
    }
    for (int c : rest) place(s, c, spot_place(rules, s, c, true), spotted);
  }

  static void place(GameState& s, int b, Vec2 p, std::vector<int>& spotted) {
    s.position[static_cast<std::size_t>(b)] = p;
    s.on_table[static_cast<std::size_t>(b)] = 1;
    spotted.push_back(b);
  }

  /// The frame is over after the last black, potted or fouled: the
  /// higher score wins; on equal scores the black is re-spotted, lots are
  /// drawn and the winner of the lot plays from the D (3.3(j), (k)).
  void end_frame(ShotRuling& x, const std::string& lead) const {
    GameState& s = x.s;
    SnookerState& k = *s.snooker;
    Ruling& r = x.r;
    const std::string score = std::to_string(k.score[0]) + "-" + std::to_string(k.score[1]);
    if (k.score[0] != k.score[1]) {
      const int winner = k.score[0] > k.score[1] ? 0 : 1;
      x.game_over(winner, player_name(winner) + " won the frame " + score);
      r.text = lead + player_name(winner) + " wins the frame " + score + ".";
      return;
    }
    // Lots: from the rack seed, so that a frame stays a function of its seeds.
    const int lot = static_cast<int>(mix_seed(s.rack_seed, kLotStream) & 1U);
    s.on_table[kBlack] = 0;
    spot_colours(x.rules, s, {kBlack}, r.spotted);
    s.on_table[0] = 0;
    s.ball_in_hand = BallInHand::d;
    s.phase = Phase::shot;
    s.player = lot;
    s.innings += 1;
    k.respotted_black = true;
    k.colour_on = false;
    k.free_ball = false;
    k.break_points = 0;
    k.misses = 0;
    clear_replace(k);
    r.turn_continues = false;
    r.text = lead + "The scores are level at " + score + ": the black is re-spotted and " +
             player_name(lot) + ", drawn by lot, plays from the D.";
  }

  SnookerMarks m_;
};

}  // namespace

std::shared_ptr<const Ruleset> make_snooker_ruleset() { return std::make_shared<Snooker>(); }

}  // namespace detail

}  // namespace breakshot

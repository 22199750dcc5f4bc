// Every ruling in words (Ruling::text, and GameState::result, which rulings
// quote): no foul named by its identifier (no '_' anywhere), no sentence
// said twice. Walks every foul kind of every game: hand-made event lists
// (Rules::apply_events) on the states of games played by the baseline,
// every decision after them, and the played games' own rulings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/snooker.hpp"

namespace test_ruling_words {

using namespace breakshot;

namespace {

constexpr Foul kAllFouls[] = {
    Foul::scratch,           Foul::no_contact,         Foul::wrong_ball_first, Foul::no_rail,
    Foul::illegal_break,     Foul::behind_head_string, Foul::ball_off_table,   Foul::in_off,
    Foul::wrong_ball_potted, Foul::free_ball_snooker,  Foul::wrong_cue_ball,   Foul::push_through};

GameConfig config_of(GameType game) {
  GameConfig c = game == GameType::snooker         ? snooker_config()
                 : game == GameType::three_cushion ? three_cushion_config()
                                                   : GameConfig{};
  c.game = game;
  c.physics.airborne = true;  // so that ball_off_table is one of the kinds
  c.max_shots = 150;
  return c;
}

/// The sentences of `text`: the pieces between ". " (and before a final ".").
std::vector<std::string> sentences(const std::string& text) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (from < text.size()) {
    std::size_t end = text.find(". ", from);
    if (end == std::string::npos) end = text.size();
    std::string s = text.substr(from, end - from);
    if (!s.empty() && s.back() == '.') s.pop_back();
    if (!s.empty()) out.push_back(s);
    from = end + 2;
  }
  return out;
}

/// Checks one text: no identifier, no sentence said twice.
void check_words(const std::string& where, const std::string& text) {
  EXPECT_EQ(text.find('_'), std::string::npos) << where << ": an identifier in \"" << text << "\"";
  const std::vector<std::string> parts = sentences(text);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      EXPECT_NE(parts[i], parts[j]) << where << ": a sentence said twice in \"" << text << "\"";
    }
  }
}

TEST(RulingWords, SentencesSplitAtFullStops) {
  EXPECT_EQ(sentences("A b. C d. A b."), (std::vector<std::string>{"A b", "C d", "A b"}));
  EXPECT_EQ(sentences("One"), std::vector<std::string>{"One"});
}

TEST(RulingWords, EveryFoulHasWordsOfItsOwn) {
  std::set<std::string> seen;
  for (const Foul f : kAllFouls) {
    const std::string words(foul_words(f));
    SCOPED_TRACE(std::string(to_string(f)));
    EXPECT_FALSE(words.empty());
    EXPECT_EQ(words.find('_'), std::string::npos) << words;
    EXPECT_NE(words, std::string(to_string(f)));
    EXPECT_TRUE(seen.insert(words).second) << "said of two fouls: " << words;
  }
}

/// Walks the rulings of one game: every ruling met is checked, and the
/// foul kinds met are counted.
class Walk {
 public:
  explicit Walk(GameType game) : rules_(config_of(game)) {}

  const Rules& rules() const { return rules_; }
  const std::set<Foul>& fouls() const { return fouls_; }
  std::size_t rulings() const { return rulings_; }

  void check(const std::string& where, const Outcome& o) {
    ++rulings_;
    check_words(where, o.ruling.text);
    check_words(where + " (result)", o.state.result);
    for (const Foul f : o.ruling.fouls) fouls_.insert(f);
    // The decisions the ruling leaves, one level deep.
    if (o.state.phase == Phase::break_shot || o.state.phase == Phase::shot ||
        o.state.phase == Phase::game_over) {
      return;
    }
    for (const Choice c : rules_.legal_actions(o.state).choices) {
      const Outcome d = rules_.apply(o.state, Decide{c});
      ++rulings_;
      check_words(where + ", then " + std::string(to_string(c)), d.ruling.text);
      check_words(where + ", then " + std::string(to_string(c)) + " (result)", d.state.result);
    }
  }

  /// The shots the rules accept from `s` for a first hit on `first`
  /// (-1: none): with a call or a nomination where one is due, without,
  /// as a safety, as a push-out.
  std::vector<Shoot> shots(const GameState& s, int first) const {
    const LegalActions la = rules_.legal_actions(s);
    std::vector<Shoot> out;
    Shoot base;
    base.strike.speed = 3.0;
    base.strike.phi = 90.0;  // along the head string: from the kitchen, it is never crossed
    const int on = first > 0 ? first : la.targets.empty() ? -1 : la.targets.front();
    std::vector<Shoot> tries;
    tries.push_back(base);
    if (on > 0) {
      Shoot called = base;
      called.call = Call{on, 0};
      tries.push_back(called);
    }
    Shoot safety = base;
    safety.safety = true;
    tries.push_back(safety);
    if (la.push_out) {
      Shoot push = base;
      push.push_out = true;
      tries.push_back(push);
    }
    if (!la.nominate.empty()) {
      const bool hit_is_on = std::count(la.nominate.begin(), la.nominate.end(), first) > 0;
      Shoot nominated = base;
      nominated.nominate = hit_is_on ? first : la.nominate.front();
      tries.push_back(nominated);
    }
    for (const Shoot& sh : tries) {
      if (!rules_.check(s, Action{sh})) out.push_back(sh);
    }
    return out;
  }

  /// Every recipe of hand-made events from `s`: the first ball hit (none,
  /// a ball on, a ball not on), then balls pocketed, a cushion or none,
  /// balls off the table.
  void walk_pool(const std::string& where, const GameState& s) {
    const LegalActions la = rules_.legal_actions(s);
    std::vector<int> firsts{-1};
    for (int b : la.targets) {
      if (firsts.size() < 3) firsts.push_back(b);
    }
    for (int b = rules_.ball_count() - 1, others = 0; b > 0 && others < 2; --b) {
      if (s.on_table[static_cast<std::size_t>(b)] &&
          !std::count(la.targets.begin(), la.targets.end(), b)) {
        firsts.push_back(b);
        ++others;
      }
    }
    for (const int first : firsts) {
      for (const Shoot& sh : shots(s, first)) {
        for (int pot = 0; pot < 4; ++pot) {       // nothing, cue ball, first ball, both
          for (int rail = 0; rail < 2; ++rail) {  // no cushion, a cushion
            for (int off = 0; off < 3; ++off) {   // nothing, cue ball, first ball off
              std::vector<Event> ev;
              double t = 0.1;
              const auto add = [&](EventType type, int ball, int other, int pocket) {
                Event e;
                e.time = t;
                t += 0.1;
                e.type = type;
                e.ball = ball;
                e.other = other;
                e.pocket = pocket;
                ev.push_back(e);
              };
              add(EventType::cue_strike, 0, -1, -1);
              if (first > 0) add(EventType::ball_ball, 0, first, -1);
              if (rail) add(EventType::ball_cushion, first > 0 ? first : 0, -1, -1);
              const bool pot_cue = pot == 1 || pot == 3;
              const bool pot_first = (pot == 2 || pot == 3) && first > 0;
              if (pot_first) add(EventType::ball_pocket, first, -1, 0);
              if (pot_cue) add(EventType::ball_pocket, 0, -1, 1);
              if (off == 1 && !pot_cue) add(EventType::ball_off_table, 0, -1, -1);
              if (off == 2 && first > 0 && !pot_first) {
                add(EventType::ball_off_table, first, -1, -1);
              }
              const Outcome o = rules_.apply_events(s, sh, ev, s.position);
              check(where + ": first " + std::to_string(first) + ", pot " + std::to_string(pot) +
                        ", rail " + std::to_string(rail) + ", off " + std::to_string(off),
                    o);
            }
          }
        }
      }
    }
  }

  /// Three-cushion: the struck ball (its own or the other cue ball), a
  /// first contact early enough to be a push or not, cushions, the second
  /// ball, a ball off the table.
  void walk_carom(const std::string& where, const GameState& s) {
    const int own = rules_.cue_ball(s);
    for (const int striker : {own, 1 - own}) {
      for (const int first : {-1, 0, 1, 2}) {
        if (first == striker) continue;
        const int second = first < 0 ? -1 : 3 - striker - first;
        for (const double at : {0.0004, 0.5}) {
          for (int cushions = 0; cushions <= 3; cushions += 3) {
            for (int both = 0; both < 2; ++both) {
              for (int off = 0; off < 2; ++off) {
                std::vector<Event> ev;
                const auto add = [&](double t, EventType type, int ball, int other) {
                  Event e;
                  e.time = t;
                  e.type = type;
                  e.ball = other >= 0 ? std::min(ball, other) : ball;
                  e.other = other >= 0 ? std::max(ball, other) : -1;
                  ev.push_back(e);
                };
                add(0.0, EventType::cue_strike, striker, -1);
                if (first >= 0) add(at, EventType::ball_ball, striker, first);
                for (int k = 0; k < cushions; ++k)
                  add(1.0 + k, EventType::ball_cushion, striker, -1);
                if (both && second >= 0) add(5.0, EventType::ball_ball, striker, second);
                if (off) add(6.0, EventType::ball_off_table, first >= 0 ? first : striker, -1);
                Shoot sh;
                sh.strike.speed = 3.0;
                if (striker != own) sh.cue_ball = striker;
                const Outcome o = rules_.apply_events(s, sh, ev, s.position);
                check(where + ": striker " + std::to_string(striker) + ", first " +
                          std::to_string(first) + ", at " + std::to_string(at) + ", cushions " +
                          std::to_string(cushions) + ", both " + std::to_string(both) + ", off " +
                          std::to_string(off),
                      o);
              }
            }
          }
        }
      }
    }
  }

  void walk(const std::string& where, const GameState& s) {
    if (s.phase != Phase::break_shot && s.phase != Phase::shot) return;
    if (!s.on_table[static_cast<std::size_t>(rules_.cue_ball(s))]) return;
    if (rules_.config().game == GameType::three_cushion) {
      walk_carom(where, s);
    } else {
      walk_pool(where, s);
    }
  }

 private:
  Rules rules_;
  std::set<Foul> fouls_;
  std::size_t rulings_ = 0;
};

/// States where a shot is due, from a game the baseline plays with noise.
std::vector<GameState> played_states(Walk& w, std::uint64_t seed) {
  const auto p0 = make_baseline_player();
  const auto p1 = make_baseline_player();
  const GameRecord record = play_game(w.rules(), *p0, *p1, 0, seed, parse_noise("2x"));
  std::vector<GameState> states{record.start};
  for (std::size_t i = 0; i < record.actions.size(); ++i) {
    const RecordedAction& a = record.actions[i];
    check_words("played action " + std::to_string(i), a.ruling.text);
    check_words("played action " + std::to_string(i) + " (result)", a.after.result);
    states.push_back(a.after);
  }
  // Every fifth state keeps the walk short and still reaches the middle
  // and the end of the game.
  std::vector<GameState> out;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (i < 4 || i % 5 == 0 || i + 1 == states.size()) out.push_back(states[i]);
  }
  return out;
}

void walk_states(Walk& w, const std::vector<GameState>& states) {
  for (std::size_t i = 0; i < states.size(); ++i) {
    w.walk("state " + std::to_string(i), states[i]);
  }
}

/// The foul kinds a game can rule: its list, but behind_head_string,
/// which 9-ball and 10-ball list and never rule (rules_nine.cpp).
std::set<Foul> expected_fouls(const Rules& rules) {
  const std::vector<Foul> kinds = rules.foul_kinds();
  std::set<Foul> out(kinds.begin(), kinds.end());
  const GameType g = rules.config().game;
  if (g == GameType::nine_ball || g == GameType::ten_ball) out.erase(Foul::behind_head_string);
  return out;
}

void expect_every_foul(const Walk& w) {
  for (const Foul f : expected_fouls(w.rules())) {
    EXPECT_TRUE(w.fouls().contains(f)) << "no ruling of " << to_string(w.rules().config().game)
                                       << " with the foul " << to_string(f);
  }
}

TEST(RulingWords, EightBall) {
  Walk w(GameType::eight_ball);
  std::vector<GameState> states = played_states(w, 11);
  // On the 8: the shooter's group cleared.
  GameState on_eight = states[states.size() / 2];
  on_eight.phase = Phase::shot;
  on_eight.ball_in_hand = BallInHand::none;
  on_eight.on_table[0] = 1;
  on_eight.group = {Group::solids, Group::stripes};
  for (int b = 1; b < 8; ++b) on_eight.on_table[static_cast<std::size_t>(b)] = 0;
  on_eight.on_table[8] = 1;
  on_eight.player = 0;
  states.push_back(on_eight);
  // From the kitchen, with an object ball behind the head string.
  GameState kitchen = on_eight;
  kitchen.group = {Group::none, Group::none};
  kitchen.kitchen_shot = true;
  kitchen.position[0] = {0.3, 0.3};
  kitchen.position[2] = {0.4, 0.9};
  kitchen.on_table[2] = 1;
  states.push_back(kitchen);
  walk_states(w, states);
  expect_every_foul(w);
  EXPECT_GT(w.rulings(), 1000u);
}

TEST(RulingWords, NineBall) {
  Walk w(GameType::nine_ball);
  std::vector<GameState> states = played_states(w, 12);
  GameState two_fouls = states[states.size() / 2];
  two_fouls.fouls_in_a_row[static_cast<std::size_t>(two_fouls.player)] = 2;
  states.push_back(two_fouls);
  walk_states(w, states);
  expect_every_foul(w);
}

TEST(RulingWords, TenBall) {
  Walk w(GameType::ten_ball);
  std::vector<GameState> states = played_states(w, 13);
  GameState two_fouls = states[states.size() / 2];
  two_fouls.fouls_in_a_row[static_cast<std::size_t>(two_fouls.player)] = 2;
  states.push_back(two_fouls);
  walk_states(w, states);
  expect_every_foul(w);
}

TEST(RulingWords, Snooker) {
  Walk w(GameType::snooker);
  walk_states(w, played_states(w, 14));
  // A free ball that leaves the cue ball snookered behind it (WPBSA
  // 3.9(c)): the blue nominated, hit, and the cue ball at rest behind it.
  GameState s = w.rules().start(7, 0);
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  const SnookerMarks marks = snooker_marks();
  s.on_table[0] = 1;
  s.position[0] = {1.0, 0.6};
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.shots = 1;
  const int kBlue = 19;
  const int kRed = 9;
  for (const int colour : {16, 17, 18, 19, 20, 21})
    s.on_table[static_cast<std::size_t>(colour)] = 1;
  s.position[16] = marks.yellow;
  s.position[17] = marks.green;
  s.position[18] = marks.brown;
  s.position[19] = marks.blue;
  s.position[20] = marks.pink;
  s.position[21] = marks.black;
  s.on_table[kRed] = 1;
  s.position[kRed] = marks.blue + Vec2{0.5, 0.0};
  s.snooker->free_ball = true;
  Shoot sh;
  sh.strike.speed = 3.0;
  sh.nominate = kBlue;
  Event hit;
  hit.time = 0.1;
  hit.type = EventType::ball_ball;
  hit.ball = 0;
  hit.other = kBlue;
  std::vector<Vec2> rest = s.position;
  rest[0] = marks.blue - Vec2{0.3, 0.0};
  const Outcome o = w.rules().apply_events(s, sh, {hit}, rest);
  ASSERT_EQ(o.ruling.fouls, std::vector<Foul>{Foul::free_ball_snooker}) << o.ruling.text;
  w.check("free ball", o);
  expect_every_foul(w);
}

TEST(RulingWords, ThreeCushion) {
  Walk w(GameType::three_cushion);
  walk_states(w, played_states(w, 15));
  expect_every_foul(w);
}

TEST(RulingWords, SayTheFoulOnce) {
  // One example in full, as the page's log shows it.
  Walk w(GameType::nine_ball);
  GameState s = w.rules().start(3, 0);
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.shots = 1;
  Event hit;
  hit.time = 0.1;
  hit.type = EventType::ball_ball;
  hit.ball = 0;
  hit.other = 9;
  Shoot sh;
  sh.strike.speed = 3.0;
  const Outcome o = w.rules().apply_events(s, sh, {hit}, s.position);
  EXPECT_EQ(o.ruling.text,
            "Player 1 pockets nothing. Foul: the wrong ball hit first and no ball to a cushion "
            "after the contact. Player 2 has the cue ball in hand.");
}

}  // namespace

}  // namespace test_ruling_words

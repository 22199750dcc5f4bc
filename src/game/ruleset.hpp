// The family of rulesets behind Rules (include/breakshot/game.hpp).
//
// Rules is the one shape every game has: a plain GameState, legal actions,
// check, and apply returning the next state with the shot's events and the
// ruling read from them. What is common to the games on a pool table
// (placing the cue ball, simulating a shot, reading its facts, spotting,
// the stalemate limit) is written once in rules.cpp; what one game decides
// is a Ruleset, one file a game (rules_eight.cpp, rules_nine.cpp,
// rules_snooker.cpp, rules_carom.cpp). A new game is a new Ruleset and an entry in
// make_ruleset.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "breakshot/event.hpp"
#include "breakshot/game.hpp"

namespace breakshot::detail {

bool has(const std::vector<int>& v, int x);
std::string player_name(int p);
std::string join_balls(const std::vector<int>& balls);
/// The fouls in words (foul_words), joined: "a scratch and no ball hit".
std::string fouls_in_words(const std::vector<Foul>& fouls);

/// A decision being ruled: the state before it, the state and ruling
/// being built, and the moves the games' decisions share.
struct DecisionRuling {
  const Rules& rules;
  const GameState& before;
  GameState& s;
  Ruling& r;
  int shooter;
  int opp;
  std::string who;  ///< "Player N" of the shooter

  /// The table is racked again (a new rack seed from the old one), the
  /// shots and innings of the game carried over, `breaker` to break.
  void rerack(int breaker);
  /// The turn passes to the opponent (a new inning begins).
  void pass_turn();
};

/// A shot being ruled: what the common part read from the simulation and
/// the moves the games' rulings share.
struct ShotRuling {
  const Rules& rules;
  const GameState& before;
  const Shoot& shot;
  const std::vector<Event>& events;  ///< ball fields are ball numbers
  const ShotFacts& f;
  GameState& s;
  Ruling& r;
  int shooter;
  int opp;
  std::string who;   ///< "Player N" of the shooter
  std::string what;  ///< "Player N pockets ... ." and a space
  bool is_break = false;
  bool cue_in = false;           ///< the cue ball fell
  std::vector<int> objects;      ///< object balls pocketed, in order
  std::vector<int> targets;      ///< the legal first targets before the shot
  bool cue_off = false;          ///< the cue ball left the table
  std::vector<int> objects_off;  ///< object balls that left the table, in order

  /// The cue ball is off the cloth for good (pocketed or off the table):
  /// the next player has it in hand.
  bool cue_gone() const { return cue_in || cue_off; }

  /// Adds a foul once.
  void foul(Foul x);
  void game_over(int winner, const std::string& why);
  /// The opponent shoots next with the cue ball in hand at `where`.
  void ball_in_hand_for_opponent(BallInHand where);
  void pass_turn();
  /// Puts `ball` back on the table (Rules::spot_position) and says so.
  void spot(int ball);
  /// The pocket `ball` fell in, -1 if it did not.
  int pocket_of(int ball) const;
};

class Ruleset {
 public:
  virtual ~Ruleset() = default;
  /// Balls including the cue ball.
  virtual int ball_count() const = 0;
  /// The ball the player to act strikes (Rules::cue_ball).
  virtual int cue_ball(const GameState& /*s*/) const { return 0; }
  /// The foul kinds this game knows, in the order summaries list them.
  virtual std::vector<Foul> foul_kinds() const = 0;
  /// Balls the shooter may legally hit first.
  virtual std::vector<int> targets(const GameState& s) const = 0;
  /// The decisions on offer in a decision phase (empty: none).
  virtual std::vector<Choice> choices(Phase phase) const = 0;
  /// The game's part of LegalActions for a shot (push_out, call).
  virtual void legal_shot(const GameState& s, LegalActions& la) const = 0;
  /// Why the game refuses this shot (the strike itself is checked already).
  virtual std::optional<std::string> check_shot(const Rules& rules, const GameState& s,
                                                const Shoot& shot) const = 0;
  /// Plays a decision already checked to be on offer.
  virtual void decide(DecisionRuling& d, Choice choice) const = 0;
  /// Rules a shot: fouls, whose turn, the next phase, the ruling's text.
  virtual void rule_shot(ShotRuling& shot) const = 0;

  /// Rules::balls_on: the targets unless the game names balls on.
  virtual std::vector<int> balls_on(const GameState& s) const { return targets(s); }
  /// Rules::ball_value for an object ball of the game (1 <= ball <
  /// ball_count()): a pool ball is one ball.
  virtual int ball_value(int /*ball*/) const { return 1; }
  /// Rules::standing: no points, no balls to go, unless the game counts
  /// them.
  virtual Standing standing(const GameState& /*s*/) const { return {}; }

  // What a game on another table than the pool table's changes (snooker);
  // the defaults are the pool games'.

  /// The decisions on offer in `s` (a decision phase, or the shot phase
  /// when the game offers one there): choices(s.phase) unless the game
  /// says otherwise.
  virtual std::vector<Choice> state_choices(const GameState& s) const { return choices(s.phase); }
  /// Sets up a new game's balls, phase and game state (Rules::start);
  /// false: the pool games' rack and start.
  virtual bool start(const Rules& /*rules*/, std::uint64_t /*rack_seed*/, int /*breaker*/,
                     GameState& /*s*/) const {
    return false;
  }
  /// Why the cue ball may not be placed at p for the game's own kind of
  /// ball in hand (BallInHand::d), or nullopt.
  virtual std::optional<std::string> check_place(const Rules& /*rules*/, const GameState& /*s*/,
                                                 Vec2 /*p*/) const {
    return std::nullopt;
  }
  /// Where `ball` is spotted; nullopt: the pool games' long string.
  virtual std::optional<Vec2> spot_position(const Rules& /*rules*/, const GameState& /*s*/,
                                            int /*ball*/) const {
    return std::nullopt;
  }
};

/// The rotation games' (9-ball, 10-ball) legal first ball: the
/// lowest-numbered object ball on the table.
std::vector<int> lowest_ball(const GameState& s);

/// The rotation games' reply to a push-out (and 10-ball's to a ball
/// pocketed wrongly), Choice::shoot or Choice::pass_back, with the words
/// of each game: `taken` ("takes the table after the push-out") and
/// `handed` ("passes the shot back to") follow the player's name.
void rotation_reply(DecisionRuling& d, Choice choice, const std::string& taken,
                    const std::string& handed);

/// A foul in a rotation game: the game ball spotted if it went down or
/// left the table (`spot_game_ball`), the shooter's foul count raised, and
/// either the rack lost on the third foul in a row or the cue ball in hand
/// anywhere for the opponent, with the ruling's words.
void rotation_foul(ShotRuling& x, int game_ball, bool spot_game_ball);

/// Why `call` (a pocket and an object ball of the `ball_count` balls) is
/// not one on this table and state, or nullopt.
std::optional<std::string> check_call(const Rules& rules, const GameState& s, const Call& call,
                                      int ball_count);

/// Why a call's pocket does not exist on the rules' table, or nullopt.
std::optional<std::string> check_called_pocket(const Rules& rules, const Call& call);

/// The foul kinds of the games on a pool table, in the order summaries
/// list them (8-ball and 9-ball both list them all), but ball_off_table,
/// which Rules::foul_kinds adds when the physics is airborne.
std::vector<Foul> pool_foul_kinds();

std::shared_ptr<const Ruleset> make_eight_ball_ruleset();
std::shared_ptr<const Ruleset> make_nine_ball_ruleset();
std::shared_ptr<const Ruleset> make_snooker_ruleset();
std::shared_ptr<const Ruleset> make_three_cushion_ruleset();
std::shared_ptr<const Ruleset> make_ten_ball_ruleset();

}  // namespace breakshot::detail

// Game records: every action of one game with its ruling and the state
// after it, enough to replay the game and check it bit for bit.
//
// A record holds the seeds and each seat's noise model as well as the
// strikes: the executed strike of a shot is perturb(intended, noise of the
// acting seat, radius, noise_seed), so replay() can check that the noise
// was applied as claimed, and then that the rules, given the same
// actions, rule the same and leave the same balls in the same places.
// Writing, reading and replaying records: record_io.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/version.hpp"

namespace breakshot {

/// One action as it was played.
struct RecordedAction {
  int player = 0;  ///< who acted (0 or 1)
  /// As executed: for a shot, the strike after noise.
  Action action;
  /// Shots: the strike the player chose, before noise. nullopt otherwise.
  std::optional<CueStrike> intended;
  /// Seed of the shot's noise (play_game gives every action one, shots or
  /// not, so that the seeds follow the action index).
  std::uint64_t noise_seed = 0;
  Ruling ruling;
  GameState after;

  /// Exact equality: doubles are compared by their bits (-0 is not +0).
  bool operator==(const RecordedAction& o) const;
};

/// How a game ended that the rules did not end: online play's forfeit of
/// a player who left for good (src/web/rooms.cpp), or the game abandoned
/// when both did. The actions stop there; the last state is not over.
struct GameEnding {
  enum class Kind : std::uint8_t {
    forfeit,    ///< `player` left for good and forfeits: `winner` is the other seat
    abandoned,  ///< both players left: no winner (player and winner -1)
  };
  Kind kind = Kind::forfeit;
  int player = -1;   ///< the seat that forfeited (0 or 1); -1 when abandoned
  int winner = -1;   ///< 1 - player for a forfeit; -1 when abandoned
  std::string text;  ///< in words: "Player 1 left the table for 120 s and forfeits"
  bool operator==(const GameEnding&) const = default;
};
std::string_view to_string(GameEnding::Kind k);
std::optional<GameEnding::Kind> parse_ending_kind(std::string_view s);

struct GameRecord {
  static constexpr std::string_view kFormat = "breakshot-game-record";
  /// Version 2 adds the engine and the
  /// physics (GameConfig::physics) to the header; version 1 records have
  /// neither and were played with kLegacyGamePhysics. Version 3 adds the
  /// ending (`ending`): a record is written as version 3 only when it has
  /// one, else as version 2, so that the games the rules end keep their
  /// bytes and a breakshot that knows no ending refuses the record by its
  /// version.
  static constexpr int kVersion = 3;
  /// The version of a record without an ending.
  static constexpr int kVersionWithoutEnding = 2;

  /// The version of the library that played the game (version.hpp's
  /// kVersion): this build's for a new record; "0.1.0" for a version 1
  /// record, the only library version that wrote them.
  std::string engine = std::string(::breakshot::kVersion);
  /// The format version the record was read from (1 or 2; kVersion for a
  /// new record). write_record always writes kVersion; replay names it
  /// with the engine when the record does not replay. Not compared by ==.
  int version = kVersion;

  GameConfig config;
  std::array<std::string, 2> players;  ///< names, by seat
  std::uint64_t seed = 0;              ///< the game's seed (match.hpp derives the rest from it)
  /// The noise each seat's shots were played with, by seat (a player's
  /// own, or the match's for a player without one).
  std::array<NoiseModel, 2> noise;
  GameState
      start;  ///< the initial rack and whose break: Rules::start(start.rack_seed, start.breaker)
  std::vector<RecordedAction> actions;
  /// How the game ended when the rules did not end it (a forfeit); nullopt
  /// for a game the rules ended or that is still going on.
  std::optional<GameEnding> ending;

  /// Exact equality, as RecordedAction's.
  bool operator==(const GameRecord& o) const;
};

/// Three-cushion: one inning of a game, the points its player made in a
/// row (its run).
struct CaromInning {
  int player = 0;
  int points = 0;
  bool operator==(const CaromInning&) const = default;
};

/// Three-cushion: the innings of a record, in order, the last one in
/// progress included. An inning ends with a shot after which the turn
/// does not continue, or with the game; shots without a carom ruling
/// (other games) are not counted. The match summary's runs
/// (CaromStats) and the page's highest runs both come from it.
std::vector<CaromInning> carom_innings(const GameRecord& record);

/// Bit-for-bit equality of strikes and actions (CueStrike has no
/// operator==; a record needs the exact comparison anyway).
bool identical(const CueStrike& a, const CueStrike& b);
bool identical(const Action& a, const Action& b);

/// Bit-for-bit equality of game states (doubles by their bits).
bool identical(const GameState& a, const GameState& b);

}  // namespace breakshot

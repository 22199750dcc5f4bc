// One game in progress: the rules, the record and the seed streams.
//
// Every place that plays a game (the match runner, the browser's facade,
// replay) goes through a GameSession, so that a game step is written once:
// check the action, apply the acting seat's noise to a shot, let the rules
// play it, append the action, its ruling and the state after it to the
// record.
//
// Seeds: a game's seed gives three streams (GameSeeds). The rack comes from
// GameSeeds::rack(seed); the noise of action i from GameSeeds::noise(seed,
// i), which the record stores beside the action; the player deciding action
// i gets GameSeeds::player(seed, i). The stream tags keep the three apart,
// and because every seed follows the action index, a game is a pure
// function of its seed, its seats' noise and the players' choices.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/record.hpp"

namespace breakshot {

/// The seed streams of a game, from its seed.
struct GameSeeds {
  /// Seed of the first rack.
  static std::uint64_t rack(std::uint64_t game_seed);
  /// Seed of action i's noise (every action has one, shots or not).
  static std::uint64_t noise(std::uint64_t game_seed, std::size_t action);
  /// Seed given to the player deciding action i.
  static std::uint64_t player(std::uint64_t game_seed, std::size_t action);
};

/// Who sits at the table: the names written into the record and the noise
/// each seat's shots are played with.
struct Seats {
  std::array<std::string, 2> names;
  std::array<NoiseModel, 2> noise;
};

class GameSession {
 public:
  /// A new game: the rules of `config` (std::invalid_argument if they
  /// cannot be built), the rack from GameSeeds::rack(game_seed), `breaker`
  /// (0 or 1; std::invalid_argument otherwise) to break.
  GameSession(const GameConfig& config, const Seats& seats, std::uint64_t game_seed, int breaker);
  /// A game whose first rack has the seed `rack_seed` (a record's start);
  /// otherwise as above.
  GameSession(const GameConfig& config, const Seats& seats, std::uint64_t game_seed,
              std::uint64_t rack_seed, int breaker);

  const Rules& rules() const { return rules_; }
  /// The record so far: config, seats, seed, start and every action played.
  const GameRecord& record() const { return record_; }
  /// The state now (after the last action).
  const GameState& state() const;
  /// The state before action i (i <= actions()).
  const GameState& state_before(std::size_t i) const;
  std::size_t actions() const { return record_.actions.size(); }
  bool over() const { return state().phase == Phase::game_over; }

  /// Seeds of the next action.
  std::uint64_t next_noise_seed() const;
  std::uint64_t next_player_seed() const;

  /// The strike a seat's shot is executed with: `intended` perturbed by the
  /// seat's noise with `noise_seed` (perturb, noise.hpp).
  CueStrike executed(const CueStrike& intended, int seat, std::uint64_t noise_seed) const;

  /// Why `action` may not be played now, or nullopt.
  std::optional<std::string> check(const Action& action) const;

  /// Plays `chosen` for the seat to act: a shot's strike is perturbed by
  /// that seat's noise with next_noise_seed(), then the rules play it and
  /// the record grows by one action. Throws std::invalid_argument with
  /// check()'s reason when the rules refuse the action as chosen, and
  /// ExecutedRefused when they refuse it as executed (after noise). Returns
  /// the outcome (its events and facts are not kept in the record).
  Outcome play(const Action& chosen);

  /// Plays an action exactly as executed (no noise is applied), recording
  /// `intended` and `noise_seed` beside it: how a recorded game is played
  /// again. Throws std::invalid_argument when the rules refuse it, and
  /// whatever the rules throw when a shot cannot be played.
  Outcome play_executed(const Action& executed, const std::optional<CueStrike>& intended,
                        std::uint64_t noise_seed);

  /// Keeps the first n actions (n <= actions()) and takes back the rest:
  /// the game continues from the state after action n - 1.
  void take_back_to(std::size_t n);

  /// Thrown by play() when noise made an allowed action illegal.
  struct ExecutedRefused : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
  };

 private:
  Rules rules_;
  GameRecord record_;
};

}  // namespace breakshot

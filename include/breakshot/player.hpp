// A player maps a game state to an action. The computer players and the
// registry that makes them by name are in players.hpp (the AI layer).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"

namespace breakshot {

class Player {
 public:
  virtual ~Player() = default;
  virtual std::string name() const = 0;
  /// A legal action for the player to act in `state` (never a game over
  /// state). `seed` is for any randomness the player uses.
  virtual Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) = 0;
  /// The noise this player's shots are played with when it has its own
  /// (the AI levels, docs/ai.md); nullopt: the match's noise.
  virtual std::optional<NoiseModel> noise() const { return std::nullopt; }
};

}  // namespace breakshot

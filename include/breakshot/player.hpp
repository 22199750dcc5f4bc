// Computer players. A player maps a game state to an action.
#pragma once

#include <cstdint>
#include <memory>
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

/// The baseline player: ghost-ball aim at every legal ball and pocket,
/// the easiest unblocked shot (docs/rules.md, "Baseline player"). Its
/// aim uses libm (atan2, sin, cos), so its choices are reproducible on
/// one maths library; records store the executed actions, so a replay
/// never depends on that.
std::unique_ptr<Player> make_baseline_player();

/// A player by name ("baseline"); throws std::invalid_argument for an
/// unknown name, listing the known ones.
std::unique_ptr<Player> make_player(std::string_view name);

}  // namespace breakshot

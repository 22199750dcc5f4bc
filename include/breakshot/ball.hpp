// Balls: their fixed properties and their kinematic state.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "breakshot/vec.hpp"

namespace breakshot {

/// How a ball is moving. `moving` and `stationary` are the states of the
/// ideal and friction models; the pool model uses the others. `airborne`
/// (off the cloth, in flight) and `off_table` (it left the table over a
/// rail; out of play, like `pocketed`) need physics.airborne.
enum class MotionState : std::uint8_t {
  stationary,
  moving,
  sliding,
  rolling,
  spinning,
  pocketed,
  airborne,
  off_table,
};

std::string_view to_string(MotionState s);

/// The default ball: a pool ball (WPA: 2.25 in diameter, 5.5-6 oz).
inline constexpr double kPoolBallRadius = 0.028575;  ///< m
inline constexpr double kPoolBallMass = 0.170;       ///< kg

/// What does not change during a simulation.
struct BallSpec {
  std::string id;
  double radius = kPoolBallRadius;  ///< m
  double mass = kPoolBallMass;      ///< kg
  double wall_restitution = 1.0; ///< against every wall of the table
};

/// Where a ball is and how it moves at one instant.
struct BallState {
  Vec2 position;
  Vec2 velocity;
  Vec3 spin;  ///< rad/s (pool model; zero otherwise)
  MotionState state = MotionState::stationary;
  /// Height of the centre above its resting height (m) and vertical
  /// velocity (m/s, up positive): nonzero only for an airborne ball, and
  /// for a ball whose scenario velocity has a vertical component.
  double z = 0.0;
  double vz = 0.0;
};

}  // namespace breakshot

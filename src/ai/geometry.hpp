// Path geometry shared by the computer players (internal): distances
// between straight paths and from a path to the table's walls, and the
// constants both players estimate with.
#pragma once

#include <limits>

#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"

namespace breakshot::ai {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The pool model's defaults (docs/physics.md), for the players' speed
// estimates only: their simulations use the scenario's own values.
inline constexpr double kGravity = 9.81;
inline constexpr double kSlidingFriction = 0.2;
inline constexpr double kRollingFriction = 0.01;
inline constexpr double kBallBallRestitution = 0.95;

/// True if the segments p0-p1 and q0-q1 cross at a point inside both.
bool segments_cross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// Distance between the segments p0-p1 and q0-q1 (0 if they cross).
double segments_distance(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// Distance from the segment a-b to a wall piece; an arc counts as its
/// whole circle, which errs on the side of caution.
double wall_distance(const Wall& w, Vec2 a, Vec2 b);

}  // namespace breakshot::ai

// The physics models and their parameters.
#pragma once

#include <cstdint>
#include <string_view>

namespace breakshot {

/// Which equations of motion and collision laws the engine uses.
enum class Model : std::uint8_t {
  ideal,     ///< frictionless disks: constant velocity between collisions
  friction,  ///< constant deceleration along minus the velocity until rest
  pool,      ///< sliding, rolling and spinning spheres, cue, cushions, pockets
};

std::string_view to_string(Model m);

/// Every physics parameter, with the defaults documented in
/// docs/scenario.md. Units are SI.
struct PhysicsParams {
  Model model = Model::ideal;
  /// Restitution of a ball-ball collision unless a pair overrides it.
  double ball_ball_restitution = 1.0;
  /// Ball-ball friction coefficient (pool model only; ideal and friction
  /// collisions are frictionless by definition).
  double ball_ball_friction = 0.0;
  /// Pool model: use the speed-dependent fit mu(v) = a + b exp(-c v)
  /// (pooltool's default, after Alciatore) instead of the constant
  /// ball_ball_friction. The reader sets it when the field is not given.
  bool ball_ball_friction_fit = false;
  double gravity = 9.81;
  /// Deceleration of every moving ball in the friction model (m/s^2).
  /// The scenario reader defaults it to rolling_friction * gravity.
  double deceleration = 0.0981;
  double sliding_friction = 0.2;
  double rolling_friction = 0.01;
  double spinning_friction = 0.044;
  /// Closing speed (m/s) below which a ball-ball collision is treated as
  /// elastic, and the separating speed a pair in pushing contact leaves
  /// with. This is the rule that keeps inelastic clusters from
  /// collapsing (docs/physics-core.md, "Inelastic collapse").
  double collapse_speed = 1e-5;
  /// A ball striking a cluster (balls within half a millimetre of each
  /// other) resolves the impact on the whole cluster at once with Hertz
  /// contacts instead of pair by pair (docs/physics-core.md, "Clusters").
  /// Off by default; the games' scenarios (make_break_scenario) turn it
  /// on so that a break spreads the rack.
  bool ball_clusters = false;
};

/// The pool model's default collapse_speed (m/s): larger, because balls
/// pushing a cluster stay pressed together for a long time and every
/// re-contact is an event.
inline constexpr double kPoolCollapseSpeed = 1e-3;

/// The pool model's default ball-ball restitution: the middle of
/// Alciatore's measured 0.92-0.98 for phenolic pool balls.
inline constexpr double kPoolBallBallRestitution = 0.95;

/// The physics of `model` when nothing else is given (docs/scenario.md,
/// "Defaults"), in one place, after Box2D's b2DefaultWorldDef: the
/// scenario reader starts from it, and so do the racks and the games, the
/// AI's estimates, the benchmarks and, through the web facade
/// (bs_defaults), the page. PhysicsParams{} is default_physics(ideal).
/// The pool model: restitution 0.95, the measured speed-dependent
/// ball-ball friction (ball_ball_friction_fit), kPoolCollapseSpeed; the
/// games also turn ball_clusters on.
constexpr PhysicsParams default_physics(Model model) {
  PhysicsParams p;
  p.model = model;
  // A ball of the friction model slows as a rolling ball does on cloth.
  p.deceleration = p.rolling_friction * p.gravity;
  if (model == Model::pool) {
    p.ball_ball_restitution = kPoolBallBallRestitution;
    p.ball_ball_friction_fit = true;
    p.collapse_speed = kPoolCollapseSpeed;
  }
  return p;
}

}  // namespace breakshot

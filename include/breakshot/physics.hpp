// The physics models and their parameters.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace breakshot {

/// Which equations of motion and collision laws the engine uses.
enum class Model : std::uint8_t {
  ideal,     ///< frictionless disks: constant velocity between collisions
  friction,  ///< constant deceleration along minus the velocity until rest
  pool,      ///< sliding, rolling and spinning spheres, cue, cushions, pockets
};

std::string_view to_string(Model m);

/// The law of a pool ball-ball impact (`physics.ball_ball_model`,
/// docs/physics.md, "Ball-ball impact"). The pool model only.
enum class BallBallModel : std::uint8_t {
  /// One instantaneous impulse: restitution along the line of centres and
  /// Coulomb friction at the contact, mu evaluated at the slip at the start
  /// (Alciatore TP A-14). The default, and the law of breakshot 0.1.
  friction,
  /// Mathavan, Jackson, Parkin 2014 (Sports Eng. 17): the impact integrated
  /// over the normal impulse, with slip at the contact and at the cloth.
  mathavan_2014,
};

std::string_view to_string(BallBallModel m);
/// The model of a name ("friction", "mathavan_2014"); false for an
/// unknown name.
bool parse_ball_ball_model(std::string_view name, BallBallModel& out);

/// A ball-ball friction coefficient that falls with the slip speed v of
/// the contact points (m/s): mu(v) = a + b exp(-c v).
struct FrictionCurve {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  friend constexpr bool operator==(const FrictionCurve&, const FrictionCurve&) = default;
};

/// What is wrong with `curve` as a friction law, if anything: the member
/// ('a', 'b' or 'c') to blame and why. A curve is one when a, b and c are
/// finite, c >= 0 (mu then runs monotonically from a + b at zero slip to a
/// at high slip) and both a and a + b are in [0, 1]: so mu(v) stays in
/// [0, 1] for every v >= 0.
struct FrictionCurveProblem {
  char member = 'a';
  std::string reason;
};
std::optional<FrictionCurveProblem> check_friction_curve(const FrictionCurve& curve);

/// Alciatore's fit to Marlow's friction data (TP A-28, "Throw plots for
/// all types of shots": mu = 0.11, 0.06, 0.01 at v = 0.1, 1, 10 times
/// sin(45 deg) m/s). pooltool's default and breakshot 0.1's, now the
/// legacy curve (kLegacyGamePhysics, `--ball-ball-friction tpa28`): the
/// throw it gives is 2-3 times below the measured (docs/physics.md). Not
/// the pool model's default (kThrowFitTPB3 is); it stays the initial value
/// of PhysicsParams::ball_ball_friction_curve (unused outside the pool
/// model) and of BallFriction, so that what starts from them keeps its
/// results.
inline constexpr FrictionCurve kThrowFitTPA28{0.009951, 0.108, 1.088};

/// Alciatore's refit of the same curve to Colin Colenso's measured throw
/// (TP B-3, "Throw calibration and contour plots": 30 and 45 degree cuts at
/// 4, 8 and 12 km/h), a = 0.016, b = 0.219, c = 0.691. The pool model's
/// default (default_physics(Model::pool), so every pool scenario that
/// gives no physics.ball_ball_friction, and the games): the measured
/// table wins over the clean-ball theory.
inline constexpr FrictionCurve kThrowFitTPB3{0.016, 0.219, 0.691};

/// The default spinning friction mu_sp: a pool ball's spin about the
/// vertical then decays at 5 mu_sp g / (2R) = 10.0 rad/s^2, the middle of
/// the measured 5-15 rad/s^2 of Alciatore's "pool physics property
/// constants" (docs/physics.md, "Spin about the vertical"). One
/// coefficient for every ball: a snooker ball's spin decays at 10.9
/// rad/s^2, a carom ball's at 9.3.
inline constexpr double kSpinningFriction = 0.0117;

/// breakshot 0.1's spinning friction (FastFiz's figure): 37.7 rad/s^2 for
/// a pool ball, three times the measured. Part of the legacy physics
/// (kLegacyGamePhysics); a game record or link without a
/// "spinning_friction" was played with it.
inline constexpr double kLegacySpinningFriction = 0.044;

/// Every physics parameter, with the defaults documented in
/// docs/scenario.md. Units are SI.
struct PhysicsParams {
  Model model = Model::ideal;
  /// Restitution of a ball-ball collision unless a pair overrides it.
  double ball_ball_restitution = 1.0;
  /// Ball-ball friction coefficient (pool model only; ideal and friction
  /// collisions are frictionless by definition).
  double ball_ball_friction = 0.0;
  /// Pool model: use the speed-dependent curve ball_ball_friction_curve
  /// instead of the constant ball_ball_friction. The reader sets it when
  /// the field is not given or is given as {"a", "b", "c"}.
  bool ball_ball_friction_fit = false;
  /// mu(v) = a + b exp(-c v) of the slip speed v when
  /// ball_ball_friction_fit is set. The struct's initial value is the
  /// legacy TP A-28 curve, which no model's defaults use (the ideal and
  /// friction models have no ball-ball friction); default_physics(pool),
  /// where the engine's pool scenarios start, sets TP B-3 (kThrowFitTPB3).
  FrictionCurve ball_ball_friction_curve = kThrowFitTPA28;
  /// The pool model's ball-ball impact law.
  BallBallModel ball_ball_model = BallBallModel::friction;
  double gravity = 9.81;
  /// Deceleration of every moving ball in the friction model (m/s^2).
  /// The scenario reader defaults it to rolling_friction * gravity.
  double deceleration = 0.0981;
  double sliding_friction = 0.2;
  double rolling_friction = 0.01;
  /// mu_sp: spin about the vertical decays at 5 mu_sp g / (2R) in every
  /// state (kSpinningFriction, from the measured spin deceleration).
  double spinning_friction = kSpinningFriction;
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
  /// Pool model: balls may leave the cloth (docs/physics.md, "Airborne
  /// balls"). A cue strike's downward part then goes into the slate,
  /// which throws the ball back up with slate_restitution (a jump when
  /// the cue is raised enough); balls fly, land and bounce, meet other
  /// balls in three dimensions, hop off a cushion nose and can leave the
  /// table. Off, the vertical parts of every impulse are dropped, as in
  /// breakshot 0.1. On in the pool model's defaults (default_physics).
  bool airborne = false;
  /// Restitution of a ball landing on the slate (through the cloth):
  /// Alciatore's "ball-table coefficient of restitution", 0.5. In [0, 1).
  double slate_restitution = 0.5;
  /// A bounce off the slate lower than this (m, the height the ball's
  /// bottom would reach) ends the flight: the ball stays on the cloth.
  /// About the cloth's thickness. Positive.
  double min_bounce_height = 0.001;
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
/// ball-ball friction (ball_ball_friction_fit, kThrowFitTPB3),
/// kPoolCollapseSpeed, balls that may leave the cloth (airborne); the
/// games also turn ball_clusters on.
constexpr PhysicsParams default_physics(Model model) {
  PhysicsParams p;
  p.model = model;
  // A ball of the friction model slows as a rolling ball does on cloth.
  p.deceleration = p.rolling_friction * p.gravity;
  if (model == Model::pool) {
    p.ball_ball_restitution = kPoolBallBallRestitution;
    p.ball_ball_friction_fit = true;
    p.ball_ball_friction_curve = kThrowFitTPB3;
    p.collapse_speed = kPoolCollapseSpeed;
    p.airborne = true;
  }
  return p;
}

}  // namespace breakshot
